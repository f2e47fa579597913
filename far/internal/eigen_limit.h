// Limit position and tangents of a vertex from the eigen-structure of its local subdivision
// matrix (docs/limit_eigen.md): computed once per configuration and cached, then laid over the
// vertex's ring neighbourhood in any level.
#pragma once

#include <optional>
#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>
#include "far/internal/local_matrix.h"

namespace quadtri {
inline namespace v0 {

// How a configuration's tangents were found.
enum class TangentSource {
    Eigen,     // a clean subdominant pair: the exact tangent plane
    Estimate,  // no clean pair: the layout's linear function taken six levels down (docs/limit_eigen.md)
};

// The analysis of one configuration: masks over its ring neighbourhood N, in ring-relative order.
struct ConfigurationLimit {
    int rings = 0;  // N is this many face rings
    std::vector<double> position, tangent1, tangent2;
    std::vector<int> signature;  // of the configuration's mesh, rings + 1 face rings deep
    TangentSource tangents = TangentSource::Eigen;
    bool exactPosition = true;  // false: eigenvalue 1 not simple; the position is the vertex itself
    double lambda1 = 0, lambda2 = 0, lambda3 = 0, imaginary = 0;  // moduli; |Im| of the pair
    int iterations = 0;
    double seconds = 0;  // time the analysis took
};

// The analysis of a configuration, uncached; nullopt where no ring neighbourhood up to
// kMaxLocalRings is closed under the scheme's masks.
std::optional<ConfigurationLimit> analyseConfiguration(const VertexConfiguration& configuration, const Options& options);

// The same from the process-wide cache (one analysis per configuration and option set; safe to
// call from several threads at once). The pointer stays valid for the life of the process.
const ConfigurationLimit* cachedLimit(const VertexConfiguration& configuration, const Options& options);

// A vertex's limit masks over the vertices of its level. `settled` says that the neighbourhood,
// one ring beyond N, is the configuration's own, so the masks are exactly the limit of the
// scheme; otherwise the vertex is still near another irregularity and they are an estimate that
// one more level of refinement makes exact.
struct VertexLimitMasks {
    std::vector<int> vertices;  // the level's vertices the masks read
    std::vector<double> position, tangent1, tangent2;
    const ConfigurationLimit* analysis = nullptr;
    bool settled = false;
};
// Nullopt where the vertex has no configuration (fanOf), its configuration no closed
// neighbourhood, or the level too few vertices around it.
std::optional<VertexLimitMasks> eigenLimitMasks(const Topology& topology, int vertex, const Options& options);

}  // namespace v0
}  // namespace quadtri
