// Limit stencils: for every vertex of a level, where it lands on the limit surface and two tangents
// there, each a weighted sum over one shared set of source vertices (docs/limit.md).
#pragma once

#include <cstddef>
#include <vector>

namespace quadtri {
inline namespace v0 {

// Stencil i reads the sources indices[offsets[i] .. offsets[i+1]) once and weighs each with three
// weights, interleaved: entry k's (position, dU, dV) weights are weightsOf(i)[3k], [3k+1], [3k+2].
// So one pass over the sources gives
//   position_i = Σ_k w[3k]   · src[indices[offsets[i] + k]]   (position weights sum to 1)
//   dU_i       = Σ_k w[3k+1] · src[...]                        (tangent weights sum to 0)
//   dV_i       = Σ_k w[3k+2] · src[...]
// The weight triples live in a pool in which identical sequences are stored once, as in
// StencilTable: after a level or two nearly every stencil is one of a few regular masks.
//
// Orientation: dU × dV points to the side the faces' winding makes the outside (faces listed
// counter-clockwise seen from outside, or clockwise under Options::leftHanded), so a normal is
// normalize(dU × dV) with no sign fix. Only the tangents' directions are promised, not their
// lengths (they scale with the local edge lengths, by a factor that depends on the vertex's
// configuration). Where the limit surface has no tangent plane (a corner) the pair still spans
// the plane of the first face's two edges at the vertex, so the normal stays defined; it can
// vanish only on degenerate input geometry.
struct LimitStencilTable {
    int numSourceVertices = 0;       // size of the vertex set the indices point into
    std::vector<int> offsets{0};     // numStencils() + 1
    std::vector<int> indices;        // source vertex of each entry
    std::vector<int> weightOffsets;  // per stencil: its 3 · size(i) weights start at weights[weightOffsets[i]]
    std::vector<float> weights;      // the pool of interleaved (position, dU, dV) triples

    int numStencils() const { return int(weightOffsets.size()); }
    int size(int i) const { return offsets[i + 1] - offsets[i]; }
    const float* weightsOf(int i) const { return weights.data() + weightOffsets[i]; }
    std::size_t numEntries() const { return indices.size(); }
    // Bytes of the four arrays.
    std::size_t bytes() const {
        return (offsets.size() + indices.size() + weightOffsets.size()) * sizeof(int) + weights.size() * sizeof(float);
    }
};

}  // namespace v0
}  // namespace quadtri
