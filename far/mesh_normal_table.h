// What the MeshNormals evaluators read: one refined level's faces and, for every vertex, the faces
// around it. The normal of vertex v is the normalised sum of the vector areas of its faces
// (area-weighted face normals; docs/limit_evaluation.md). Holes are left out, as they are not
// drawn. The Refiner stores every level's faces counter-clockwise (it reverses clockwise input
// under Options::leftHanded), so the normals point to the outside of either kind of input.
#pragma once

#include <cstddef>
#include <vector>

#include <quadtri/export.h>
#include <quadtri/far/level_faces.h>

namespace quadtri {
inline namespace v0 {

// The level's drawn faces and each vertex's faces in face order (docs/limit_evaluation.md,
// "MeshNormals"). The host evaluators add each face's area into its corners' rows in face order
// (serially, or in parallel one chunk of facesPerChunk faces each); a vertex whose faces lie in
// more than one chunk (a seam vertex) is left out by the parallel chunks and gathers its faces
// itself (vertexFaces), in the same order; its corners carry kSeamCorner above the vertex index
// (kCornerIndexMask). The Vulkan shaders and ranges shorter than the level gather per vertex.
struct MeshNormalTable {
    static constexpr int kCornerIndexMask = (1 << 30) - 1;
    static constexpr int kSeamCorner = 1 << 30;

    int numVertices = 0;
    int facesPerChunk = 1;                  // at most 16 chunks, each >= 4096 faces
    std::vector<int> faceOffsets{0};        // drawn faces + 1
    std::vector<int> faceCorners;           // flagged vertex indices, faceOffsets.back() of them
    std::vector<int> vertexFaceOffsets{0};  // numVertices + 1: vertex v's faces are
    std::vector<int> vertexFaces;           //   vertexFaces[vertexFaceOffsets[v] .. [v+1]), in face order
    std::vector<int> seamVertices;          // ascending

    int numFaces() const { return int(faceOffsets.size()) - 1; }
    int numChunks() const { return (numFaces() + facesPerChunk - 1) / facesPerChunk; }
    std::size_t bytes() const {
        return (faceOffsets.size() + faceCorners.size() + vertexFaceOffsets.size() + vertexFaces.size() +
                seamVertices.size()) *
               sizeof(int);
    }
};

// The table of one level's faces (refiner.faces(L)). Throws std::invalid_argument for a level of
// more vertices than kCornerIndexMask.
QUADTRI_API MeshNormalTable buildMeshNormalTable(const LevelFaces& faces);

}  // namespace v0
}  // namespace quadtri
