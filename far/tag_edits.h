// Edits of a refined mesh's tags: edge (crease) and vertex (corner) sharpness and holes, applied
// in place by Refiner::applyEdits to what the Refiner holds (docs/edits.md). An edit changes
// only the stencils within a few rings of what it touches; the report says which, level by
// level, so that tables built from the Refiner's (and their device copies) can be updated by
// range instead of rebuilt.
#pragma once

#include <cstdint>
#include <vector>

#include <quadtri/export.h>

namespace quadtri {
inline namespace v0 {

// What one edit sets, in level 0's numbering (Refiner::faces(0): the descriptor's vertices, and
// its faces where no face repeats a vertex). Sharpness as TopologyDescriptor takes it: 0 smooth,
// kInfiniteSharpness (10) or more infinitely sharp. The last setting of an item wins.
class QUADTRI_API TagEdits {
public:
    void setCrease(int a, int b, float sharpness);  // the edge between vertices a and b
    void setCorner(int vertex, float sharpness);
    void setHole(int face, bool hole);

    bool empty() const { return creaseWeights.empty() && cornerWeights.empty() && holeFlags.empty(); }
    void clear();

    std::vector<int> creaseVertexPairs;  // 2 per crease
    std::vector<float> creaseWeights;
    std::vector<int> cornerVertices;
    std::vector<float> cornerWeights;
    std::vector<int> holeFaces;
    std::vector<std::uint8_t> holeFlags;
};

// What an edit changed in one level (all lists sorted).
struct EditedLevel {
    std::vector<int> edges;     // edges whose sharpness changed
    std::vector<int> vertices;  // vertices whose sharpness changed
    std::vector<int> faces;     // faces whose hole flag changed
    // Levels L >= 1 with a per-level table: the stencils of levelStencils(L) recomputed (the
    // children within the scheme's reach of a changed tag of level L - 1), and of those the
    // ones that changed.
    int recomputedStencils = 0;
    std::vector<int> stencils;
    // Whether a changed stencil changed its size: the table's arrays were rewritten from that
    // stencil on (else only the changed stencils' indices, weight offsets and new weights at the
    // pool's end were written).
    bool tableResized = false;
    // Whether the table's weight pool was laid out again (it grows at its end otherwise): every
    // stencil's weight offset may have changed.
    bool poolLaidOut = false;
};

struct EditReport {
    std::vector<EditedLevel> levels;  // one per level 0 .. Refiner::maxLevel()
    // Face-varying channels are refined again from level 0 (not yet updated in place).
    bool faceVaryingRebuilt = false;
    // Whether the edit changed any tag.
    bool changed() const {
        return !levels.empty() && (!levels[0].edges.empty() || !levels[0].vertices.empty() || !levels[0].faces.empty());
    }
};

}  // namespace v0
}  // namespace quadtri
