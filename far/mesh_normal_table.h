// What the MeshNormals evaluators read: for every vertex of one refined level, one triple of
// corners per face around it, so that each vertex gathers its own normal (no atomics, no second
// pass). The normal of vertex v is the normalised sum of the vector areas of its faces
// (area-weighted face normals; docs/limit_evaluation.md). Holes are left out, as they are not
// drawn. The Refiner stores every level's faces counter-clockwise (it reverses clockwise input
// under Options::leftHanded), so the normals point to the outside of either kind of input.
#pragma once

#include <cstddef>
#include <vector>

#include <quadtri/far/level_faces.h>

namespace quadtri {
inline namespace v0 {

// A triple (a, b, c) of vertex v adds (p_b - p_v) x (p_c - p_a): twice the vector area of a quad
// (v, a, b, c) or, written (a, c, c), of a triangle (v, a, c). A larger face gives v one triple
// per triangle of its fan from v, which sum to its vector area.
struct MeshNormalTable {
    int numVertices = 0;
    std::vector<int> offsets{0};  // numVertices + 1: vertex v's triples are [offsets[v], offsets[v+1])
    std::vector<int> corners;     // 3 per triple

    int numTriples() const { return int(corners.size() / 3); }
    std::size_t bytes() const { return (offsets.size() + corners.size()) * sizeof(int); }
};

// The table of one level's faces (refiner.faces(L)).
MeshNormalTable buildMeshNormalTable(const LevelFaces& faces);

}  // namespace v0
}  // namespace quadtri
