#include <quadtri/far/mesh_normal_table.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace quadtri {
inline namespace v0 {

namespace {

// Chunks of at least 4096 faces, at most 16 of them: enough for 16 threads, few seam vertices.
int facesPerChunk(int faces) { return std::max(4096, (faces + 15) / 16); }

// Each vertex's faces in face order (a counting sort by vertex of the faces' corners).
void sortFacesByVertex(MeshNormalTable& t) {
    std::vector<int>& offsets = t.vertexFaceOffsets;
    offsets.assign(std::size_t(t.numVertices) + 1, 0);
    for (int c : t.faceCorners) ++offsets[std::size_t(c) + 1];
    for (std::size_t v = 1; v < offsets.size(); ++v) offsets[v] += offsets[v - 1];
    t.vertexFaces.resize(std::size_t(offsets.back()));
    std::vector<int> next(offsets.begin(), offsets.end() - 1);
    for (int f = 0; f < t.numFaces(); ++f)
        for (int k = t.faceOffsets[f]; k < t.faceOffsets[f + 1]; ++k) t.vertexFaces[next[t.faceCorners[k]]++] = f;
}

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
    sortFacesByVertex(t);
    t.facesPerChunk = facesPerChunk(t.numFaces());
    flagSeams(t);
    return t;
}

}  // namespace v0
}  // namespace quadtri
