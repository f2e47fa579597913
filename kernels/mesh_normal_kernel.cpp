// The facet pass of kernels/mesh_normal_kernel.h.
#include "kernels/mesh_normal_kernel.h"

namespace quadtri {
inline namespace v0 {
namespace kernels {

void evalFacetAreas(const float* src, int srcStride, const int* facets, int begin, int end, float* areas) {
    for (int f = begin; f < end; ++f) facetArea(src, srcStride, facets + 4 * static_cast<long>(f), areas + 3 * static_cast<long>(f));
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
