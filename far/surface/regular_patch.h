// Whether a sub-face is a regular patch of the scheme's limit surface, and its points
// (docs/surface.md, "Regular patches").
#pragma once

#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>
#include "far/limit/limit_ring.h"
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

enum class PatchKind {
    None,       // not regular: refine further
    BSpline,    // 16 points, patch_basis.h's grid order
    BoxSpline,  // 12 points, patch_basis.h's lattice order
    Bilinear,   // the quad's 4 corners
    Linear,     // the triangle's 3 corners
};

// The kind of patch `face` of `level` is under `options.scheme`, its points into `points`.
PatchKind regularPatch(const Topology& level, int face, const Options& options, std::vector<int>& points);

// The same for many faces of one topology: each vertex's ring is ordered once, the first time a
// face asks for it, and read by the faces around it after. One thread at a time.
class RegularPatches {
public:
    RegularPatches(const Topology& level, const Options& options);
    PatchKind of(int face, std::vector<int>& points);

private:
    static constexpr int kUnknown = -2, kIrregular = -1;
    const Topology& t_;
    SurfacePatches kinds_;
    std::vector<int> ringAt_;     // per vertex: kUnknown, kIrregular, or where its ring starts in rings_
    std::vector<int> rings_;      // a regular corner's faces, neighbours and opposite corners in ring order
    std::vector<int> sizeOf_;     // per vertex: the size of all its faces, 0 if they differ, -1 unknown
    std::vector<unsigned> seen_;  // per vertex: the stamp of the last patch that had it
    unsigned stamp_ = 0;
    VertexRing ring_;
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
