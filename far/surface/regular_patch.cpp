// Regular patches (far/surface/regular_patch.h): the corners' rings, ordered from the face, give
// the patch's points by their lattice directions.
#include "far/surface/regular_patch.h"

#include "far/limit/limit_mask.h"
#include "far/limit/limit_ring.h"
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// A corner a regular patch may have: interior, manifold, `valence` faces of `size` corners, none a
// hole, no sharpness on it or its edges.
bool regularCorner(const Topology& t, int v, int size, int valence) {
    if ((t.vertFlags[v] & (kVertexBoundary | kVertexNonManifold)) != 0 || t.vertSharpness[v] != 0.0f) return false;
    if (t.vertexFaceCount(v) != valence || t.vertexEdgeCount(v) != valence) return false;
    for (int f : t.facesOfVertex(v))
        if (t.faceSize(f) != size || t.faceHole[f]) return false;
    for (int e : t.edgesOfVertex(v))
        if (t.edgeSharpness[e] != 0.0f) return false;
    return true;
}

bool onlyFacesOfSize(const Topology& t, int v, int size) {
    for (int f : t.facesOfVertex(v))
        if (t.faceSize(f) != size) return false;
    return true;
}

// The 16 points of a regular quad: corner i at grid (1,1), (2,1), (2,2), (1,2); its ring,
// started at the face, runs a, b, -a, -b with a towards corner i + 1 and b towards corner i - 1.
void quadPoints(const Topology& t, int face, std::vector<int>& points) {
    static constexpr int kCorner[4][2] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
    static constexpr int kA[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    points.assign(16, -1);
    VertexRing ring;
    const IndexSpan corners = t.verticesOfFace(face);
    for (int i = 0; i < 4; ++i) {
        orderVertexRing(t, corners[i], face, ring);
        const int ax = kA[i][0], ay = kA[i][1], bx = -ay, by = ax;  // b is a turned a quarter
        const int dx[4] = {ax, bx, -ax, -bx}, dy[4] = {ay, by, -ay, -by};
        const int x = kCorner[i][0], y = kCorner[i][1];
        points[4 * y + x] = corners[i];
        for (int k = 0; k < 4; ++k) {
            points[4 * (y + dy[k]) + x + dx[k]] = ring.neighbours[k];
            const int n = (k + 1) % 4;
            points[4 * (y + dy[k] + dy[n]) + x + dx[k] + dx[n]] = ring.opposite[k];
        }
    }
}

// The 12 points of a regular triangle, by lattice coordinates (patch_basis.h); corner i's ring,
// started at the face, turns counter-clockwise through the six directions from the one towards
// corner i + 1.
void trianglePoints(const Topology& t, int face, std::vector<int>& points) {
    static constexpr int kDirections[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
    static constexpr int kCorner[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    static constexpr int kFirst[3] = {0, 2, 4};  // direction from corner i to corner i + 1
    auto slot = [](int a, int b) {
        static constexpr int kSlot[4][4] = {// [b + 1][a + 1]
                                            {-1, 0, 1, 2},
                                            {3, 4, 5, 6},
                                            {7, 8, 9, -1},
                                            {10, 11, -1, -1}};
        return kSlot[b + 1][a + 1];
    };
    points.assign(12, -1);
    VertexRing ring;
    const IndexSpan corners = t.verticesOfFace(face);
    for (int i = 0; i < 3; ++i) {
        orderVertexRing(t, corners[i], face, ring);
        const int a = kCorner[i][0], b = kCorner[i][1];
        points[slot(a, b)] = corners[i];
        for (int k = 0; k < 6; ++k) {
            const int* d = kDirections[(kFirst[i] + k) % 6];
            points[slot(a + d[0], b + d[1])] = ring.neighbours[k];
        }
    }
}

}  // namespace

PatchKind regularPatch(const Topology& t, int face, const Options& options, std::vector<int>& points) {
    const SurfacePatches kinds = rulesOf(options.scheme).surfacePatches();
    const IndexSpan corners = t.verticesOfFace(face);
    const int n = corners.size();
    points.clear();
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < i; ++j)
            if (corners[i] == corners[j]) return PatchKind::None;
    if (kinds.bilinear && (n == 3 || n == 4)) {
        points.assign(corners.begin(), corners.end());
        return n == 4 ? PatchKind::Bilinear : PatchKind::Linear;
    }
    const bool quad = n == 4 && kinds.bSplineQuads, triangle = n == 3 && kinds.boxSplineTriangles;
    if (!quad && !triangle) return PatchKind::None;
    for (int v : corners)
        if (!regularCorner(t, v, n, quad ? 4 : 6)) return PatchKind::None;
    if (quad)
        quadPoints(t, face, points);
    else
        trianglePoints(t, face, points);
    // A face with a collapsed edge (catmull-clark keeps `4 3 5 5`) or a folded neighbourhood
    // repeats a point: not the patch.
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (points[i] == points[j]) return PatchKind::None;
    if (kinds.pureNeighbourhood)
        for (int v : points)
            if (!onlyFacesOfSize(t, v, n)) return PatchKind::None;
    return quad ? PatchKind::BSpline : PatchKind::BoxSpline;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
