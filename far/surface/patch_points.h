// A regular face's points in batches (FaceSurface::evaluate of many points): the face's control
// points read once, the points' sums run across the batch, with AVX2 where the CPU has it.
#pragma once

#include <algorithm>
#include <type_traits>

namespace quadtri {
inline namespace v0 {
namespace internal {

// `count` points (u[i], v[i]) of `width` components: point i's values at position[i * outStride]
// (dPdu, dPdv likewise, where not null).
struct PatchPoints {
    int count;
    const double* u;
    const double* v;
    int width;
    float* position;
    float* dPdu;
    float* dPdv;
    int outStride;
};

// The points of a regular quad's bicubic B-spline patch (its 16 points at control[sources[k] *
// stride]) and of a regular triangle's quartic box spline (its 12 points), as patch_basis.h orders them.
void bSplinePoints(const int* sources, const float* control, int stride, const PatchPoints& points);
void boxSplinePoints(const int* sources, const float* control, int stride, const PatchPoints& points);
// The same built with AVX2 (patch_points_avx2.cpp); called by the above where the CPU has it.
void bSplinePointsAvx2(const int* sources, const float* control, int stride, const PatchPoints& points);
void boxSplinePointsAvx2(const int* sources, const float* control, int stride, const PatchPoints& points);

// Calls each(std::integral_constant<int, N>, c) for the components [c, c + N) of a width-wide
// value, N = 4 but for a last shorter group: the sums are unrolled for each N.
template <class Each>
void byComponentGroups(int width, Each&& each) {
    for (int c = 0; c < width; c += 4) {
        switch (std::min(4, width - c)) {
        case 1: each(std::integral_constant<int, 1>{}, c); break;
        case 2: each(std::integral_constant<int, 2>{}, c); break;
        case 3: each(std::integral_constant<int, 3>{}, c); break;
        default: each(std::integral_constant<int, 4>{}, c); break;
        }
    }
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
