// What the MeshNormals evaluators read: for every vertex of one refined level, the faces around
// it. The normal of vertex v is the normalised sum of the vector areas of its faces
// (area-weighted face normals; docs/limit_evaluation.md). Holes are left out, as they are not
// drawn. The Refiner stores every level's faces counter-clockwise (it reverses clockwise input
// under Options::leftHanded), so the normals point to the outside of either kind of input.
#pragma once

#include <cstddef>
#include <vector>

#include <quadtri/far/level_faces.h>

namespace quadtri {
inline namespace v0 {

// Two forms of the same sums (docs/limit_evaluation.md, "MeshNormals"):
// - facets, for the host evaluators: a facet (p, q, r, s) has the vector area (r - p) x (s - q),
//   twice the area of a quad (p, q, r, s); a triangle (p, q, r) is the facet (p, q, r, r), and a
//   larger face a fan of quads (and a last triangle) from its first corner. Vertex v's normal sums
//   the facets of its faces, so each facet's area can be computed once and shared by its corners.
// - corner triples, for the Vulkan shaders: a triple (a, b, c) of vertex v adds
//   (p_b - p_v) x (p_c - p_a): a quad (v, a, b, c) or, written (a, c, c), a triangle (v, a, c); a
//   larger face gives v one triple per triangle of its fan from v.
struct MeshNormalTable {
    int numVertices = 0;
    std::vector<int> facets;              // 4 corners per facet
    std::vector<int> facetOffsets{0};     // numVertices + 1: vertex v's facets are
    std::vector<int> vertexFacets;        //   vertexFacets[facetOffsets[v] .. facetOffsets[v+1])
    std::vector<int> offsets{0};          // numVertices + 1: vertex v's triples are [offsets[v], offsets[v+1])
    std::vector<int> corners;             // 3 per triple

    int numFacets() const { return int(facets.size() / 4); }
    int numTriples() const { return int(corners.size() / 3); }
    std::size_t bytes() const {
        return (facets.size() + facetOffsets.size() + vertexFacets.size() + offsets.size() + corners.size()) *
               sizeof(int);
    }
};

// Room for the facets' vector areas (3 floats each) of one EvalMeshNormals call at a time, owned
// by the caller so that a frame loop allocates it once: the call grows it to the table's facets
// when it is smaller. One scratch per concurrent call.
struct MeshNormalScratch {
    std::vector<float> facetAreas;
};

// The table of one level's faces (refiner.faces(L)).
MeshNormalTable buildMeshNormalTable(const LevelFaces& faces);

}  // namespace v0
}  // namespace quadtri
