// Batches of a regular face's points built with AVX2 (far/surface/patch_points.cpp picks them at
// run time where the CPU has it).
#include "far/surface/patch_points_loops.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

void bSplinePointsAvx2(const int* sources, const float* control, int stride, const PatchPoints& points) {
    byGroups(points, [&](auto n, int c) { bSplineLanes<decltype(n)::value>(sources, control, stride, c, points); });
}

void boxSplinePointsAvx2(const int* sources, const float* control, int stride, const PatchPoints& points) {
    byGroups(points, [&](auto n, int c) { boxSplineLanes<decltype(n)::value>(sources, control, stride, c, points); });
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
