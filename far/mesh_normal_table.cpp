#include <quadtri/far/mesh_normal_table.h>

#include <algorithm>
#include <stdexcept>
#include <string>

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

// Counting sort by vertex: the offsets (numVertices + 1) of the entries count(emit) reports per
// vertex (emit(v) once per entry), `entries` sized to `width` ints per entry, then fill(next)
// writing each vertex's entries in the order count reported them.
template <class Count, class Fill>
std::vector<int> sortByVertex(int numVertices, Count&& count, std::vector<int>& entries, int width, Fill&& fill) {
    std::vector<int> offsets(std::size_t(numVertices) + 1, 0);
    count([&](int v) { ++offsets[std::size_t(v) + 1]; });
    for (std::size_t v = 1; v < offsets.size(); ++v) offsets[v] += offsets[v - 1];
    entries.resize(std::size_t(width) * std::size_t(offsets.back()));
    std::vector<int> next(offsets.begin(), offsets.end() - 1);
    fill(next);
    return offsets;
}

// Chunks of at least 4096 faces, at most 16 of them: enough for 16 threads, few seam vertices.
int facesPerChunk(int faces) { return std::max(4096, (faces + 15) / 16); }

// Flags the corners of the seam vertices (MeshNormalTable's comment): those whose faces lie in
// more than one chunk.
void flagSeams(MeshNormalTable& t) {
    std::vector<char> seam(std::size_t(t.numVertices), 0);
    for (int v = 0; v < t.numVertices; ++v) {
        const int first = t.vertexFaceOffsets[v], last = t.vertexFaceOffsets[v + 1] - 1;
        seam[v] = last > first && t.vertexFaces[first] / t.facesPerChunk != t.vertexFaces[last] / t.facesPerChunk;
        if (seam[v]) t.seamVertices.push_back(v);
    }
    for (int& c : t.faceCorners)
        if (seam[c]) c |= MeshNormalTable::kSeamCorner;
}

}  // namespace

MeshNormalTable buildMeshNormalTable(const LevelFaces& faces) {
    MeshNormalTable t;
    t.numVertices = faces.numVertices();
    if (t.numVertices > MeshNormalTable::kCornerIndexMask)
        throw std::invalid_argument("buildMeshNormalTable: " + std::to_string(t.numVertices) +
                                    " vertices, more than the table's " +
                                    std::to_string(MeshNormalTable::kCornerIndexMask));
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        const IndexSpan c = faces.verticesOfFace(f);
        t.faceCorners.insert(t.faceCorners.end(), c.begin(), c.begin() + faces.faceSize(f));
        t.faceOffsets.push_back(int(t.faceCorners.size()));
    }
    const int drawn = t.numFaces();

    t.vertexFaceOffsets = sortByVertex(
        t.numVertices,
        [&](auto&& emit) {
            for (int c : t.faceCorners) emit(c);
        },
        t.vertexFaces, 1,
        [&](std::vector<int>& next) {
            for (int f = 0; f < drawn; ++f)
                for (int k = t.faceOffsets[f]; k < t.faceOffsets[f + 1]; ++k)
                    t.vertexFaces[next[t.faceCorners[k]]++] = f;
        });
    t.facesPerChunk = facesPerChunk(drawn);
    flagSeams(t);

    auto eachDrawnFace = [&](auto&& body) {
        for (int f = 0; f < faces.numFaces(); ++f)
            if (!faces.isHole(f)) body(faces.verticesOfFace(f).begin(), faces.faceSize(f));
    };
    t.offsets = sortByVertex(
        t.numVertices,
        [&](auto&& emit) {
            eachDrawnFace([&](const int* c, int n) { forEachTriple(c, n, [&](int v, int, int, int) { emit(v); }); });
        },
        t.corners, 3,
        [&](std::vector<int>& next) {
            eachDrawnFace([&](const int* c, int n) {
                forEachTriple(c, n, [&](int v, int a, int b, int d) {
                    int* out = &t.corners[3 * std::size_t(next[v]++)];
                    out[0] = a, out[1] = b, out[2] = d;
                });
            });
        });
    return t;
}

}  // namespace v0
}  // namespace quadtri
