// How a face of the input becomes faces of level 0. Modelling tools and OpenSubdiv's own shapes
// have faces that repeat a vertex; each is read as the simple loops it walks around:
//   - a corner equal to the one before it (cyclically) is a collapsed edge and is dropped, so the
//     quad `4 3 5 5` left at poles is the triangle `4 3 5`;
//   - a vertex met again further on closes a loop there: `1 2 3 1 4 5` (a bow tie) is the two
//     triangles `1 2 3` and `1 4 5`;
//   - a loop with fewer than 3 corners (`1 1 2 2`, or the pieces of `1 2 1 3`) has no area and is
//     left out.
// The loops keep the face's orientation, so neighbours still agree on their shared edges.
// Each corner kept comes from one corner of the input (what a face-varying channel's values follow,
// docs/face_varying.md): where a collapsed edge merges corners, the first of them going around the
// face; at a vertex where a bow tie closes a loop, the corner at which the walk leaves it for each
// loop (the first corner for the loop that starts there, the closing corner for the one after).
// Schemes that must equal OpenSubdiv read a face whose only repeats are collapsed edges as
// OpenSubdiv does: kept as it is, each collapsed edge an edge of its own (CollapsedEdges::Keep).
#pragma once

#include <cstddef>
#include <vector>

namespace quadtri {
inline namespace v0 {
namespace internal {

// What splitting one face did, for the warning that names it.
struct FaceLoops {
    int loops = 0;          // loops kept (faces of level 0)
    int leftOut = 0;        // loops of fewer than 3 corners
    int repeated = -1;      // the first vertex met again further on, or -1
};

// What becomes of a face whose only repeated corners are collapsed edges (`4 3 5 5`).
enum class CollapsedEdges {
    Drop,  // the corners are merged: `4 3 5 5` is the triangle `4 3 5`
    Keep,  // the face stays as it is, with an edge from 5 to 5 (docs/schemes/catmull_clark.md)
};

// Splits faces into simple loops; `numVertices` bounds the indices (validated beforehand).
class FaceLoopSplitter {
public:
    explicit FaceLoopSplitter(int numVertices, CollapsedEdges collapsed = CollapsedEdges::Drop)
        : position_(std::size_t(numVertices), -1), collapsed_(collapsed) {}

    // Appends the loops of face `verts[0 .. n)` to `faceVerts`, one size per loop to `faceSizes`,
    // and, when `corners` is given, the input corner (0 .. n) each kept corner comes from.
    // Linear in n.
    FaceLoops split(const int* verts, int n, std::vector<int>& faceVerts, std::vector<int>& faceSizes,
                    std::vector<int>* corners = nullptr);

private:
    std::vector<int> position_;  // per vertex: its index on the walk, or -1 (reset after each face)
    std::vector<int> walk_;
    std::vector<int> walkCorner_;  // per vertex on the walk: the input corner it stands for
    CollapsedEdges collapsed_;
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
