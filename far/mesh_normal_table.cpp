#include <quadtri/far/mesh_normal_table.h>

namespace quadtri {
inline namespace v0 {

MeshNormalTable buildMeshNormalTable(const LevelFaces& faces) {
    MeshNormalTable t;
    t.numVertices = faces.numVertices();
    // The drawn faces, renumbered (a level's faces are simple loops: no corner repeats).
    std::vector<int> counts(std::size_t(t.numVertices) + 1, 0);
    t.faceOffsets.reserve(std::size_t(faces.numFaces()) + 1);
    t.faceVerts.reserve(std::size_t(faces.numCorners()));
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        for (int v : faces.verticesOfFace(f)) {
            t.faceVerts.push_back(v);
            ++counts[std::size_t(v) + 1];
        }
        t.faceOffsets.push_back(int(t.faceVerts.size()));
    }
    t.vertexOffsets.assign(counts.begin(), counts.end());
    for (std::size_t v = 1; v < t.vertexOffsets.size(); ++v) t.vertexOffsets[v] += t.vertexOffsets[v - 1];
    // Counting sort by vertex: each vertex's faces in face order.
    t.vertexFaces.resize(t.faceVerts.size());
    std::vector<int> next(t.vertexOffsets.begin(), t.vertexOffsets.end() - 1);
    for (int f = 0; f < t.numFaces(); ++f)
        for (int k = t.faceOffsets[f]; k < t.faceOffsets[f + 1]; ++k) t.vertexFaces[next[t.faceVerts[k]]++] = f;
    return t;
}

}  // namespace v0
}  // namespace quadtri
