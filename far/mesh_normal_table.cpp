#include <quadtri/far/mesh_normal_table.h>

namespace quadtri {
inline namespace v0 {

namespace {

// Calls add(v, a, b, c) for every corner triple of face `f` (corners c, size n), in corner order.
template <class Add>
void forEachTriple(const int* c, int n, Add&& add) {
    for (int k = 0; k < n; ++k) {
        const int v = c[k];
        auto at = [&](int step) { return c[(k + step) % n]; };
        if (n == 3) {
            add(v, at(1), at(2), at(2));
        } else if (n == 4) {
            add(v, at(1), at(2), at(3));
        } else {
            for (int j = 1; j + 1 < n; ++j) add(v, at(j), at(j + 1), at(j + 1));
        }
    }
}

// Calls add(p, q, r, s) for every facet of a face (corners c, size n): itself when it has 3 or 4
// corners (a triangle as (c0, c1, c2, c2)), else the fan of quads (c0, ck, ck+1, ck+2) from its
// first corner, closed by a triangle when n is odd.
template <class Add>
void forEachFacet(const int* c, int n, Add&& add) {
    if (n == 3) {
        add(c[0], c[1], c[2], c[2]);
        return;
    }
    int k = 1;
    for (; k + 2 < n; k += 2) add(c[0], c[k], c[k + 1], c[k + 2]);
    if (k + 1 < n) add(c[0], c[k], c[k + 1], c[k + 1]);
}

int facetsOfFace(int n) { return n == 3 ? 1 : (n - 1) / 2; }

// Counting sort by vertex: offsets (numVertices + 1) from the per-vertex counts `count(f, emit)`
// reports for each drawn face; `entries` sized to `width` ints per entry; then fill(f, next)
// writes each vertex's entries in face order.
template <class Count, class Fill>
std::vector<int> sortByVertex(const LevelFaces& faces, int numVertices, Count&& count, std::vector<int>& entries,
                              int width, Fill&& fill) {
    std::vector<int> offsets(std::size_t(numVertices) + 1, 0);
    for (int f = 0; f < faces.numFaces(); ++f)
        if (!faces.isHole(f)) count(f, [&](int v, int n) { offsets[std::size_t(v) + 1] += n; });
    for (std::size_t v = 1; v < offsets.size(); ++v) offsets[v] += offsets[v - 1];
    entries.resize(std::size_t(width) * std::size_t(offsets.back()));
    std::vector<int> next(offsets.begin(), offsets.end() - 1);
    for (int f = 0; f < faces.numFaces(); ++f)
        if (!faces.isHole(f)) fill(f, next);
    return offsets;
}

}  // namespace

MeshNormalTable buildMeshNormalTable(const LevelFaces& faces) {
    MeshNormalTable t;
    t.numVertices = faces.numVertices();

    // Facets face by face; firstFacet[f] is face f's first.
    std::vector<int> firstFacet(std::size_t(faces.numFaces()) + 1, 0);
    for (int f = 0; f < faces.numFaces(); ++f)
        firstFacet[std::size_t(f) + 1] = firstFacet[f] + (faces.isHole(f) ? 0 : facetsOfFace(faces.faceSize(f)));
    t.facets.reserve(4 * std::size_t(firstFacet.back()));
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        forEachFacet(faces.verticesOfFace(f).begin(), faces.faceSize(f),
                     [&](int p, int q, int r, int s) { t.facets.insert(t.facets.end(), {p, q, r, s}); });
    }

    // Every corner of a face lists all the face's facets.
    t.facetOffsets = sortByVertex(
        faces, t.numVertices,
        [&](int f, auto&& emit) {
            const IndexSpan c = faces.verticesOfFace(f);
            for (int k = 0; k < faces.faceSize(f); ++k) emit(c.begin()[k], firstFacet[f + 1] - firstFacet[f]);
        },
        t.vertexFacets, 1,
        [&](int f, std::vector<int>& next) {
            const IndexSpan c = faces.verticesOfFace(f);
            for (int k = 0; k < faces.faceSize(f); ++k)
                for (int i = firstFacet[f]; i < firstFacet[f + 1]; ++i) t.vertexFacets[next[c.begin()[k]]++] = i;
        });

    t.offsets = sortByVertex(
        faces, t.numVertices,
        [&](int f, auto&& emit) {
            forEachTriple(faces.verticesOfFace(f).begin(), faces.faceSize(f), [&](int v, int, int, int) { emit(v, 1); });
        },
        t.corners, 3,
        [&](int f, std::vector<int>& next) {
            forEachTriple(faces.verticesOfFace(f).begin(), faces.faceSize(f), [&](int v, int a, int b, int d) {
                int* out = &t.corners[3 * std::size_t(next[v]++)];
                out[0] = a, out[1] = b, out[2] = d;
            });
        });
    return t;
}

}  // namespace v0
}  // namespace quadtri
