// Batches of a regular face's points built with AVX2 (far/surface/patch_points.cpp picks them at
// run time where the CPU has it).
#include "far/surface/patch_points_loops.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

void bSplinePointsAvx2(const int* sources, const float* control, int stride, const PatchPoints& points) {
    bSplineBatch(sources, control, stride, points);
}

void boxSplinePointsAvx2(const int* sources, const float* control, int stride, const PatchPoints& points) {
    boxSplineBatch(sources, control, stride, points);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
