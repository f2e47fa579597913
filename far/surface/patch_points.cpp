// Batches of a regular face's points (far/surface/patch_points.h) for the baseline CPU, or
// handed to their AVX2 build.
#include "far/surface/patch_points.h"

#include "far/surface/patch_points_loops.h"
#include "kernels/cpu_features.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

void bSplinePoints(const int* sources, const float* control, int stride, const PatchPoints& points) {
    if (kernels::cpuRunsAvx2Kernels()) return bSplinePointsAvx2(sources, control, stride, points);
    bSplineBatch(sources, control, stride, points);
}

void boxSplinePoints(const int* sources, const float* control, int stride, const PatchPoints& points) {
    if (kernels::cpuRunsAvx2Kernels()) return boxSplinePointsAvx2(sources, control, stride, points);
    boxSplineBatch(sources, control, stride, points);
}

#if !defined(QUADTRI_HAVE_AVX2_KERNELS)
void bSplinePointsAvx2(const int* sources, const float* control, int stride, const PatchPoints& points) {
    bSplineBatch(sources, control, stride, points);
}
void boxSplinePointsAvx2(const int* sources, const float* control, int stride, const PatchPoints& points) {
    boxSplineBatch(sources, control, stride, points);
}
#endif

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
