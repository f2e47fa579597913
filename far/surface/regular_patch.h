// Whether a sub-face is a regular patch of the scheme's limit surface, and its points
// (docs/surface.md, "Regular patches").
#pragma once

#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>

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

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
