// What the MeshNormals evaluators read: for every vertex of one refined level, the faces around
// it, so that each vertex gathers its own normal (no atomics, no second pass). The normal of
// vertex v is the normalised sum of the vector areas of its faces (area-weighted face normals;
// docs/limit_evaluation.md). Holes are left out, as they are not drawn. The Refiner stores every
// level's faces counter-clockwise (it reverses clockwise input under Options::leftHanded), so the
// normals point to the outside of either kind of input.
#pragma once

#include <cstddef>
#include <vector>

#include <quadtri/far/level_faces.h>

namespace quadtri {
inline namespace v0 {

struct MeshNormalTable {
    int numVertices = 0;
    // Faces around vertex v: faceOffsets-indexed faces vertexFaces[vertexOffsets[v] .. vertexOffsets[v+1]).
    std::vector<int> vertexOffsets{0};  // numVertices + 1
    std::vector<int> vertexFaces;       // per incidence: a face of the arrays below
    // The level's non-hole faces: face f's corners are faceVerts[faceOffsets[f] .. faceOffsets[f+1]).
    std::vector<int> faceOffsets{0};
    std::vector<int> faceVerts;

    int numFaces() const { return int(faceOffsets.size()) - 1; }
    std::size_t bytes() const {
        return (vertexOffsets.size() + vertexFaces.size() + faceOffsets.size() + faceVerts.size()) * sizeof(int);
    }
};

// The table of one level's faces (refiner.faces(L)).
MeshNormalTable buildMeshNormalTable(const LevelFaces& faces);

}  // namespace v0
}  // namespace quadtri
