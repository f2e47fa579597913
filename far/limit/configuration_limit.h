// The limit masks of one vertex configuration from the eigen-structure of its local subdivision
// matrix (docs/limit_eigen.md), over the configuration's ring neighbourhood.
#pragma once

#include <optional>

#include <quadtri/far/options.h>
#include "far/limit/limit_eigen.h"
#include "far/limit/local_matrix.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// The analysis of a configuration; nullopt where no ring neighbourhood up to kMaxLocalRings is
// closed under the scheme's masks. dU × dV turns the way the configuration's faces are listed.
std::optional<LocalLimitMask> analyseConfiguration(const VertexConfiguration& configuration, const Options& options);

// The analysis from `cache` (one per configuration and option set), analysed on a miss; a mask
// with rings == 0 where there is none.
const LocalLimitMask& cachedLimit(const VertexConfiguration& configuration, const Options& options, LimitMaskCache& cache);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
