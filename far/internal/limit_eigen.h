// The generic limit masks (docs/limit.md, "Configurations without a closed form"): from the
// eigen-structure of the local subdivision matrix built from the scheme's own masks, for the
// vertices no closed form covers (mixed quad/triangle neighbourhoods, seams, Butterfly's
// triangles). Computed once per configuration and cached.
#pragma once

#include <map>
#include <vector>

#include "far/internal/limit_mask.h"
#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {

class SchemeRules;

// How a configuration's tangents were found (docs/limit_eigen.md).
enum class TangentSource {
    Eigen,     // a clean subdominant pair: the exact tangent plane
    Estimate,  // no clean pair: the layout's coordinate functions taken six levels down
};

// One configuration's masks, relative to the local neighbourhood in the order the generic path
// lists it (gatherNeighbourhood's labels, far/internal/local_matrix.h), ready to be mapped onto a
// vertex's actual indices; with what the analysis found.
struct LocalLimitMask {
    std::vector<double> position, du, dv;
    int rings = 0;               // the neighbourhood is this many face rings; 0: none is closed
    std::vector<int> signature;  // of the configuration's mesh, rings + 1 face rings deep
    TangentSource tangents = TangentSource::Eigen;
    bool exactPosition = true;   // false: eigenvalue 1 is not simple; the position is the vertex's own
    double lambda1 = 0, lambda2 = 0, lambda3 = 0, imaginary = 0;  // moduli; |Im| of the pair
    int iterations = 0;          // of the subspace iteration
    double seconds = 0;          // time the analysis took
};

// Masks per configuration (the key encodes what decides the mask: the cyclic face sizes around
// the vertex, its rule and sharp edges, the scheme's state near it; the generic path defines it).
// Not shared between threads: each builder of a limit table holds its own.
class LimitMaskCache {
public:
    const LocalLimitMask* find(const std::vector<int>& key) const {
        const auto it = masks_.find(key);
        return it == masks_.end() ? nullptr : &it->second;
    }
    const LocalLimitMask& insert(std::vector<int> key, LocalLimitMask mask) {
        return masks_.emplace(std::move(key), std::move(mask)).first->second;
    }

private:
    std::map<std::vector<int>, LocalLimitMask> masks_;
};

// Appends to `out` (cleared by the caller) the limit masks of `vertex` under `rules`, over the
// vertices of vertex.level, from the left eigenvectors of the local subdivision matrix
// (eigenvalue 1: position; the subdominant pair: dU, dV, oriented as LimitStencilTable says).
// SchemeRules::limitMask calls it wherever the scheme has no closed form.
void limitFromLocalMatrix(const SchemeRules& rules, const LimitVertex& vertex, LimitMaskCache& cache,
                          LimitMask& out);

// The same with what it found, for tests and diagnostics. `firstFace` is the face whose two edges
// give a corner's tangents (-1: the first of the vertex's fan).
struct EigenLimitReport {
    const LocalLimitMask* analysis = nullptr;  // of the configuration the masks came from; null if none
    int deeperLevels = 0;   // levels refined locally before the neighbourhood settled (0: it had)
    bool settled = false;   // the masks are the scheme's exact limit (false: an estimate, docs/limit_eigen.md)
};
EigenLimitReport eigenLimit(const Topology& level, int vertex, const Options& options, int firstFace,
                            LimitMaskCache& cache, LimitMask& out);

}  // namespace v0
}  // namespace quadtri
