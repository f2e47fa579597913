// FaceSurface's batch loops as the library's baseline build has them, for test_face_surface: a
// CPU with AVX2 runs the library's AVX2 build instead, so the test calls these directly.
#include "far/surface/patch_points_loops.h"

namespace quadtri::test {

void baselinePatchPoints(bool boxSpline, const int* sources, const float* control, int stride,
                         const internal::PatchPoints& points) {
    if (boxSpline)
        internal::boxSplineBatch(sources, control, stride, points);
    else
        internal::bSplineBatch(sources, control, stride, points);
}

}  // namespace quadtri::test
