#include <quadtri/far/mesh_normal_table.h>

namespace quadtri {
inline namespace v0 {

namespace {

// Calls add(v, a, b, c) for every triple of face `f` (corners c, size n), in corner order.
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

}  // namespace

MeshNormalTable buildMeshNormalTable(const LevelFaces& faces) {
    MeshNormalTable t;
    t.numVertices = faces.numVertices();
    // Counting sort by vertex: each vertex's triples in face order.
    std::vector<int> count(std::size_t(t.numVertices) + 1, 0);
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        const IndexSpan c = faces.verticesOfFace(f);
        forEachTriple(c.begin(), faces.faceSize(f), [&](int v, int, int, int) { ++count[std::size_t(v) + 1]; });
    }
    t.offsets.assign(count.begin(), count.end());
    for (std::size_t v = 1; v < t.offsets.size(); ++v) t.offsets[v] += t.offsets[v - 1];
    t.corners.resize(3 * std::size_t(t.offsets.back()));
    std::vector<int> next(t.offsets.begin(), t.offsets.end() - 1);
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        const IndexSpan c = faces.verticesOfFace(f);
        forEachTriple(c.begin(), faces.faceSize(f), [&](int v, int a, int b, int d) {
            int* out = &t.corners[3 * std::size_t(next[v]++)];
            out[0] = a, out[1] = b, out[2] = d;
        });
    }
    return t;
}

}  // namespace v0
}  // namespace quadtri
