// The generic limit masks (docs/limit.md, "Configurations without a closed form"): from the
// eigen-structure of the local subdivision matrix built from the scheme's own masks, for the
// vertices no closed form covers (mixed quad/triangle neighbourhoods, seams, Butterfly's
// triangles). Computed once per configuration and cached.
#pragma once

#include <map>
#include <vector>

#include "far/internal/limit_mask.h"

namespace quadtri {
inline namespace v0 {

class SchemeRules;

// One configuration's masks, relative to the local neighbourhood in the order the generic path
// lists it (its own convention), ready to be mapped onto a vertex's actual indices.
struct LocalLimitMask {
    std::vector<double> position, du, dv;
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

}  // namespace v0
}  // namespace quadtri
