// Placeholder for the generic limit masks (far/internal/limit_eigen.h): until the eigen-analysis
// lands, a vertex without a closed form is refused with a clear error.
#include "far/internal/limit_eigen.h"

#include <stdexcept>
#include <string>

namespace quadtri {
inline namespace v0 {

void limitFromLocalMatrix(const SchemeRules&, const LimitVertex& vertex, LimitMaskCache&, LimitMask&) {
    throw std::logic_error("limit masks: vertex " + std::to_string(vertex.ring.vertex) +
                           " has no closed form under scheme " + toString(vertex.options.scheme) +
                           " (generic limit masks not built yet)");
}

}  // namespace v0
}  // namespace quadtri
