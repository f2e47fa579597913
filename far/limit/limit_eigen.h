// The generic limit masks (docs/limit.md, "Configurations without a closed form"): from the
// eigen-structure of the local subdivision matrix built from the scheme's own masks, for the
// vertices no closed form covers (mixed quad/triangle neighbourhoods, seams, Butterfly's
// triangles). Computed once per configuration and cached.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "far/limit/limit_deeper.h"
#include "far/limit/limit_mask.h"
#include "far/limit/limit_scratch.h"
#include "far/limit/local_matrix.h"
#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

class SchemeRules;

// How a configuration's tangents were found (docs/limit_eigen.md).
enum class TangentSource {
    Eigen,     // a clean subdominant pair: the exact tangent plane
    Estimate,  // no clean pair: the layout's coordinate functions taken six levels down
};

// One configuration's masks, relative to the local neighbourhood in the order the generic path
// lists it (gatherNeighbourhood's labels, far/limit/local_matrix.h), ready to be mapped onto a
// vertex's actual indices; with what the analysis found.
struct LocalLimitMask {
    std::vector<double> position, du, dv;
    int rings = 0;               // the neighbourhood is this many face rings; 0: none is closed
    std::vector<int> signature;  // gatherNeighbourhood's on the configuration's mesh
    TangentSource tangents = TangentSource::Eigen;
    bool exactPosition = true;   // false: eigenvalue 1 is not simple; the position is the vertex's own
    double lambda1 = 0, lambda2 = 0, lambda3 = 0, imaginary = 0;  // moduli; |Im| of the pair
    int iterations = 0;          // of the subspace iteration
    double seconds = 0;          // time the analysis took
};

// A vertex followed down a locally refined patch (docs/limit_eigen.md): its masks over the patch's
// own vertex numbering (PatchCut), in that numbering's order, and what the analysis found.
struct FollowedDown {
    std::vector<std::pair<int, std::array<double, 3>>> mask;  // (patch vertex, position / dU / dV weights)
    const LocalLimitMask* analysis = nullptr;                 // null: no configuration was reached
    int deeperLevels = 0;
    bool settled = false;
};

// What eigenLimit reuses from one vertex to the next (far/limit/limit_scratch.h).
struct LimitScratch {
    WalkScratch walk;       // the neighbourhood's and the patch's marks
    Neighbourhood ring;     // the vertex's neighbourhood, as laidOver reads it
    PatchCut cut;           // the vertex's patch
    std::vector<int> key;   // cut's key
    std::vector<int> configurationKey;  // cachedLimit's
    std::vector<std::pair<int, std::array<double, 3>>> entries;  // the vertex's masks, before they are sorted
};

// Masks per configuration (the key encodes what decides the mask: the cyclic face sizes around
// the vertex, its rule and sharp edges, the scheme's state near it; the generic path defines it).
// Not shared between threads: each builder of a limit table holds its own, with the working
// space of its vertices.
class LimitMaskCache {
public:
    const LocalLimitMask* find(const std::vector<int>& key) const {
        const auto it = masks_.find(key);
        return it == masks_.end() ? nullptr : &it->second;
    }
    const LocalLimitMask& insert(std::vector<int> key, LocalLimitMask mask) {
        return masks_.emplace(std::move(key), std::move(mask)).first->second;
    }

    // Followed-down masks by the patch they were cut from (PatchCut::key): on a repetitive mesh
    // most such vertices share their patch with another one. Kept up to a fixed count, so that
    // a mesh of distinct patches does not hold every one.
    const FollowedDown* findFollowed(const std::vector<int>& patchKey) const {
        const auto it = followed_.find(patchKey);
        return it == followed_.end() ? nullptr : &it->second;
    }
    void insertFollowed(std::vector<int> patchKey, FollowedDown f) {
        if (followed_.size() < kMaxFollowed) followed_.emplace(std::move(patchKey), std::move(f));
    }

    LimitScratch& scratch() { return scratch_; }

private:
    // Every int of the key mixed in (keys differ anywhere, often only far along), in four
    // independent lanes: a patch's key is a thousand ints or so.
    struct KeyHash {
        std::size_t operator()(const std::vector<int>& key) const {
            std::uint64_t lane[4] = {key.size(), 1, 2, 3};
            const std::size_t n = key.size();
            std::size_t i = 0;
            for (; i + 4 <= n; i += 4)
                for (int j = 0; j < 4; ++j) lane[j] = mix(lane[j] + std::uint32_t(key[i + j]));
            for (; i < n; ++i) lane[0] = mix(lane[0] + std::uint32_t(key[i]));
            return std::size_t(mix(lane[0] ^ mix(lane[1] ^ mix(lane[2] ^ mix(lane[3])))));
        }
        static std::uint64_t mix(std::uint64_t h) {
            h *= 0x9E3779B97F4A7C15ull;
            return h ^ (h >> 32);
        }
    };
    static constexpr std::size_t kMaxFollowed = 4096;
    // Node-based: a mask's address stays put as others are added (FollowedDown::analysis).
    std::unordered_map<std::vector<int>, LocalLimitMask, KeyHash> masks_;
    std::unordered_map<std::vector<int>, FollowedDown, KeyHash> followed_;
    LimitScratch scratch_;
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

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
