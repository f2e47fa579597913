// Regular patches (far/surface/regular_patch.h): the corners' rings, ordered from the face, give
// the patch's points by their lattice directions.
#include "far/surface/regular_patch.h"

#include <algorithm>

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

// A corner's ring, started at the face asking: neighbour k (along the ring's edge k) and the
// corner opposite it in face k, k from 0.
struct StartedRing {
    const int* neighbours;
    const int* opposite;
    int start, valence;
    // k in [0, valence)
    int at(int k) const { return start + k < valence ? start + k : start + k - valence; }
    int neighbour(int k) const { return neighbours[at(k)]; }
    int across(int k) const { return opposite[at(k)]; }
};

// The 16 points of a regular quad: corner i at grid (1,1), (2,1), (2,2), (1,2); its ring,
// started at the face, runs a, b, -a, -b with a towards corner i + 1 and b towards corner i - 1.
template <class RingOf>
void quadPoints(const Topology& t, int face, RingOf&& ringOf, std::vector<int>& points) {
    static constexpr int kCorner[4][2] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
    static constexpr int kA[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    points.assign(16, -1);
    const IndexSpan corners = t.verticesOfFace(face);
    for (int i = 0; i < 4; ++i) {
        const StartedRing ring = ringOf(corners[i]);
        const int ax = kA[i][0], ay = kA[i][1], bx = -ay, by = ax;  // b is a turned a quarter
        const int dx[4] = {ax, bx, -ax, -bx}, dy[4] = {ay, by, -ay, -by};
        const int x = kCorner[i][0], y = kCorner[i][1];
        points[4 * y + x] = corners[i];
        for (int k = 0; k < 4; ++k) {
            points[4 * (y + dy[k]) + x + dx[k]] = ring.neighbour(k);
            const int n = (k + 1) % 4;
            points[4 * (y + dy[k] + dy[n]) + x + dx[k] + dx[n]] = ring.across(k);
        }
    }
}

// The 12 points of a regular triangle, by lattice coordinates (patch_basis.h); corner i's ring,
// started at the face, turns counter-clockwise through the six directions from the one towards
// corner i + 1.
template <class RingOf>
void trianglePoints(const Topology& t, int face, RingOf&& ringOf, std::vector<int>& points) {
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
    const IndexSpan corners = t.verticesOfFace(face);
    for (int i = 0; i < 3; ++i) {
        const StartedRing ring = ringOf(corners[i]);
        const int a = kCorner[i][0], b = kCorner[i][1];
        points[slot(a, b)] = corners[i];
        for (int k = 0; k < 6; ++k) {
            const int* d = kDirections[(kFirst[i] + k) % 6];
            points[slot(a + d[0], b + d[1])] = ring.neighbour(k);
        }
    }
}

bool distinctPairwise(const std::vector<int>& points) {
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (points[i] == points[j]) return false;
    return true;
}

// The patch of `face` (regularPatch): whether v may be its corner from corner(v), a corner's ring
// started at the face from ringOf(v), "v has only faces of size n" from pure(v, n), whether no
// point repeats from distinct(points).
template <class Corner, class RingOf, class Pure, class Distinct>
PatchKind patchOf(const Topology& t, int face, const SurfacePatches& kinds, Corner&& corner, RingOf&& ringOf,
                  Pure&& pure, Distinct&& distinct, std::vector<int>& points) {
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
        if (!corner(v)) return PatchKind::None;
    if (quad)
        quadPoints(t, face, ringOf, points);
    else
        trianglePoints(t, face, ringOf, points);
    // A face with a collapsed edge (catmull-clark keeps `4 3 5 5`) or a folded neighbourhood
    // repeats a point: not the patch.
    if (!distinct(points)) return PatchKind::None;
    if (kinds.pureNeighbourhood)
        for (int v : points)
            if (!pure(v, n)) return PatchKind::None;
    return quad ? PatchKind::BSpline : PatchKind::BoxSpline;
}

}  // namespace

PatchKind regularPatch(const Topology& t, int face, const Options& options, std::vector<int>& points) {
    thread_local VertexRing ring;  // its lists keep their memory from call to call
    const int valence = t.faceSize(face) == 4 ? 4 : 6;
    auto corner = [&](int v) { return regularCorner(t, v, t.faceSize(face), valence); };
    auto ringOf = [&](int v) {
        orderVertexRing(t, v, face, ring);
        return StartedRing{ring.neighbours.data(), ring.opposite.data(), 0, valence};
    };
    auto pure = [&](int v, int n) { return onlyFacesOfSize(t, v, n); };
    return patchOf(t, face, rulesOf(options.scheme).surfacePatches(), corner, ringOf, pure, distinctPairwise,
                   points);
}

RegularPatches::RegularPatches(const Topology& t, const Options& options)
    : t_(t),
      kinds_(rulesOf(options.scheme).surfacePatches()),
      ringAt_(std::size_t(t.numVertices), kUnknown),
      sizeOf_(std::size_t(t.numVertices), -1),
      seen_(std::size_t(t.numVertices), 0) {}

PatchKind RegularPatches::of(int face, std::vector<int>& points) {
    // A regular corner's faces all have the asking face's size: its valence follows.
    const int valence = t_.faceSize(face) == 4 ? 4 : 6;
    auto corner = [&](int v) {
        int& at = ringAt_[std::size_t(v)];
        if (at == kUnknown) {
            at = kIrregular;
            if (regularCorner(t_, v, t_.faceSize(face), valence)) {
                orderVertexRing(t_, v, face, ring_);
                at = int(rings_.size());
                rings_.insert(rings_.end(), ring_.faces.begin(), ring_.faces.end());
                rings_.insert(rings_.end(), ring_.neighbours.begin(), ring_.neighbours.end());
                rings_.insert(rings_.end(), ring_.opposite.begin(), ring_.opposite.end());
            }
        }
        return at != kIrregular;
    };
    auto ringOf = [&](int v) {
        const int* faces = rings_.data() + ringAt_[std::size_t(v)];
        const int start = int(std::find(faces, faces + valence, face) - faces);
        return StartedRing{faces + valence, faces + 2 * valence, start, valence};
    };
    auto pure = [&](int v, int n) {
        int& size = sizeOf_[std::size_t(v)];
        if (size < 0) size = onlyFacesOfSize(t_, v, n) ? n : 0;  // v is in a face of size n: it asks
        return size == n;
    };
    auto distinct = [&](const std::vector<int>& points) {
        if (++stamp_ == 0) {  // wrapped: every vertex unseen again
            std::fill(seen_.begin(), seen_.end(), 0u);
            stamp_ = 1;
        }
        for (int v : points) {
            if (seen_[std::size_t(v)] == stamp_) return false;
            seen_[std::size_t(v)] = stamp_;
        }
        return true;
    };
    return patchOf(t_, face, kinds_, corner, ringOf, pure, distinct, points);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
