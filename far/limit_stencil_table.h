// Limit stencils: for every vertex of a level, where it lands on the limit surface and two tangents
// there, each a weighted sum over one shared set of source vertices (docs/limit.md).
#pragma once

#include <cstddef>
#include <vector>

namespace quadtri {
inline namespace v0 {

// Stencil i reads its size(i) sources sourcesOf(i) = indices[offsets[i] .. offsets[i] + sizes[i])
// once and weighs each with three weights, interleaved: entry k's (position, dU, dV) weights are
// weightsOf(i)[3k], [3k+1], [3k+2]. So one pass over the sources gives
//   position_i = Σ_k w[3k]   · src[sourcesOf(i)[k]]   (position weights sum to 1)
//   dU_i       = Σ_k w[3k+1] · src[...]              (tangent weights sum to 0)
//   dV_i       = Σ_k w[3k+2] · src[...]
// Both arrays the stencils point into are pools in which identical sequences are stored once, as
// StencilTable's weights are: the weight triples, since after a level or two nearly every stencil
// is one of a few regular masks, and the runs of sources, since in a regular region every limit
// point inside one control face reads that face's same neighbourhood (its 4x4 B-spline block for
// Catmull-Clark, 12 vertices for Loop), and every point on one control edge another. So offsets
// are not monotonic, and a stencil's run may be another's; in the tables the Refiner builds, each
// run is strictly ascending (a source appears once per stencil). The evaluators need neither.
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
    std::vector<int> sizes;          // per stencil: how many sources it reads
    std::vector<int> offsets;        // per stencil: where its run of sources starts in `indices`
    std::vector<int> indices;        // the pool of runs of source indices
    std::vector<int> weightOffsets;  // per stencil: its 3 · size(i) weights start at weights[weightOffsets[i]]
    std::vector<float> weights;      // the pool of interleaved (position, dU, dV) triples

    int numStencils() const { return int(sizes.size()); }
    int size(int i) const { return sizes[i]; }
    const int* sourcesOf(int i) const { return indices.data() + offsets[i]; }
    const float* weightsOf(int i) const { return weights.data() + weightOffsets[i]; }
    // Entries an evaluation reads, the sum of the sizes (O(numStencils)); indices.size() counts
    // only the pooled runs.
    std::size_t numEntries() const {
        std::size_t n = 0;
        for (int s : sizes) n += std::size_t(s);
        return n;
    }
    // Bytes of the five arrays.
    std::size_t bytes() const {
        return (sizes.size() + offsets.size() + indices.size() + weightOffsets.size()) * sizeof(int) +
               weights.size() * sizeof(float);
    }
};

}  // namespace v0
}  // namespace quadtri
