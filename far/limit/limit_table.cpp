// Limit stencil tables (docs/limit.md): one mask per vertex from the scheme's hook, composition
// over the control vertices, the float table with its runs of sources and its weight triples
// pooled. The Refiner's tables are made straight in float, in parts on the threads interned in
// stencil order (floatTableInParts); the double masks feed the composition, and the double
// composition is the reference the float one is tested against. None depends on the thread count.
#include "far/limit/limit_table.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>


#include "far/limit/limit_eigen.h"
#include "far/limit/limit_ring.h"
#include "far/schemes/scheme.h"
#include "far/tables/weight_pool.h"
#include "far/internal/parallel.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// Vertex v's limit mask into `mask`, its weights interleaved (position, dU, dV) onto `weights`.
void limitMaskOf(const Topology& level, const Options& options, const SchemeRules& rules, const RingStarts* starts,
                 int v, VertexRing& ring, LimitMaskCache& cache, LimitMask& mask, std::vector<double>& weights) {
    orderVertexRing(level, v, starts ? starts->startFace(v) : -1, ring);
    mask.clear();
    rules.limitMask(LimitVertex{level, options, ring, limitRule(level, ring)}, cache, mask);
    for (int k = 0; k < mask.size(); ++k) weights.insert(weights.end(), {mask.position[k], mask.du[k], mask.dv[k]});
}

void append(const LimitStencilTableD& part, LimitStencilTableD& table) {
    const int base = int(table.indices.size());
    for (int offset : part.offsets) table.offsets.push_back(base + offset);
    table.sizes.insert(table.sizes.end(), part.sizes.begin(), part.sizes.end());
    table.indices.insert(table.indices.end(), part.indices.begin(), part.indices.end());
    table.weights.insert(table.weights.end(), part.weights.begin(), part.weights.end());
}

// Room in `table` for `stencils` and `entries`, reserved once: a limit table of a few hundred
// thousand vertices is hundreds of MB, and growing it by doubling would copy it several times.
void reserveFor(std::size_t stencils, std::size_t entries, LimitStencilTableD& table) {
    table.sizes.reserve(stencils);
    table.offsets.reserve(stencils);
    table.indices.reserve(entries);
    table.weights.reserve(3 * entries);
}

// The parts in order, as one table. The first part was reserved for all of them (pages untouched
// past what it wrote cost nothing), so it is kept and the others are appended to it: only their
// entries are copied. Joining into a new table copied the
// first part as well, which, new pages and all, was a fifth of a factorized limit table's build on
// two parts.
LimitStencilTableD joined(std::vector<LimitStencilTableD>& parts) {
    std::size_t stencils = 0, entries = 0;
    for (const LimitStencilTableD& part : parts) {
        stencils += part.sizes.size();
        entries += part.indices.size();
    }
    LimitStencilTableD table = std::move(parts[0]);
    reserveFor(stencils, entries, table);  // nothing to do unless the first part's estimate fell short
    for (std::size_t k = 1; k < parts.size(); ++k) {
        append(parts[k], table);
        parts[k] = LimitStencilTableD();
    }
    return table;
}

// Vertices per part below which a level is not split.
constexpr int kMinVerticesPerPart = 16384;

}  // namespace

LimitStencilTableD buildLimitStencils(const Topology& level, const Options& options, const RingStarts* starts) {
    const SchemeRules& rules = rulesOf(options.scheme);
    const int n = level.numVertices;
    const int parts = std::max(1, std::min(parallel::arenaThreads(), n / kMinVerticesPerPart));
    auto split = [&](int k) { return int(std::int64_t(n) * k / parts); };
    std::vector<LimitStencilTableD> built(parts);
    parallel::forEachPart(0, parts, [&](int k) {
        VertexRing ring;
        LimitMask mask;
        LimitMaskCache cache;
        LimitStencilTableD& part = built[k];
        const int first = split(k), last = split(k + 1);
        // At most the vertex, its edge neighbours and its faces' opposite corners per stencil; the
        // first part reserves room for every part (joined).
        const int until = k == 0 ? n : last;
        const std::size_t bound = std::size_t(until - first) + (level.vertEdgeOffsets[until] - level.vertEdgeOffsets[first]) +
                                  (level.vertFaceOffsets[until] - level.vertFaceOffsets[first]);
        reserveFor(std::size_t(until - first), bound, part);
        for (int v = first; v < last; ++v) {
            part.offsets.push_back(int(part.indices.size()));
            limitMaskOf(level, options, rules, starts, v, ring, cache, mask, part.weights);
            part.sizes.push_back(mask.size());
            part.indices.insert(part.indices.end(), mask.indices.begin(), mask.indices.end());
        }
    });
    LimitStencilTableD table = joined(built);
    table.numSourceVertices = n;
    return table;
}

LimitStencilTableD buildLimitStencilsOf(const Topology& level, const Options& options, const RingStarts* starts,
                                        const std::vector<int>& vertices, LimitMaskCache& cache) {
    const SchemeRules& rules = rulesOf(options.scheme);
    LimitStencilTableD table;
    table.numSourceVertices = level.numVertices;
    VertexRing ring;
    LimitMask mask;
    for (int v : vertices) {
        table.offsets.push_back(int(table.indices.size()));
        limitMaskOf(level, options, rules, starts, v, ring, cache, mask, table.weights);
        table.sizes.push_back(mask.size());
        table.indices.insert(table.indices.end(), mask.indices.begin(), mask.indices.end());
    }
    return table;
}

namespace {

// Stencil i of limit ∘ inner appended to `indices` and `weights` (three per entry): each limit
// entry's inner stencil scaled by its weight triple, in entry order, a source's sums in the slot
// where it was first reached (`slot`: per inner source, -1 or its place past `base`; left all -1).
template <class Indices, class Weights>
void composeOneLimit(const LimitStencilTableD& limit, const StencilTableD& inner, int i, std::vector<int>& slot,
                     Indices& indices, Weights& weights) {
    const std::size_t start = indices.size();
    for (int k = 0; k < limit.sizes[i]; ++k) {
        const int entry = limit.offsets[i] + k, s = limit.indices[entry];
        const double* w = limit.weights.data() + 3 * std::size_t(entry);
        for (int j = 0; j < inner.sizes[s]; ++j) {
            const int c = inner.indices[inner.offsets[s] + j];
            const double x = inner.weights[inner.offsets[s] + j];
            if (slot[c] < 0) {
                slot[c] = int(indices.size() - start);
                indices.push_back(c);
                weights.insert(weights.end(), {0.0, 0.0, 0.0});
            }
            double* o = weights.data() + 3 * (start + std::size_t(slot[c]));
            o[0] += w[0] * x;
            o[1] += w[1] * x;
            o[2] += w[2] * x;
        }
    }
    for (std::size_t k = start; k < indices.size(); ++k) slot[indices[k]] = -1;
}

}  // namespace

LimitStencilTableD composeLimitStencils(const LimitStencilTableD& limit, const StencilTableD& inner) {
    LimitStencilTableD out;
    out.numSourceVertices = inner.numSourceVertices;
    std::vector<int> slot(std::size_t(inner.numSourceVertices), -1);
    for (int i = 0; i < limit.numStencils(); ++i) {
        const std::size_t start = out.indices.size();
        out.offsets.push_back(int(start));
        composeOneLimit(limit, inner, i, slot, out.indices, out.weights);
        out.sizes.push_back(int(out.indices.size() - start));
    }
    return out;
}

namespace {

// A stencil's `size` entries (`sources`, three `weights` each) in ascending source order, appended:
// its sources to `run`, their weight triples rounded to float to `triples`. The sort is by
// (source, position in the stencil), so ties (a source listed twice) keep their order and become
// one entry, weights added in double.
void sortedEntries(int size, const int* sources, const double* weights, std::vector<int>& order,
                   std::vector<int>& run, std::vector<float>& triples) {
    order.resize(size);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return sources[a] < sources[b] || (sources[a] == sources[b] && a < b); });
    for (int k = 0; k < size;) {
        const int source = sources[order[k]];
        const double* w = weights + 3 * order[k];
        double sum[3] = {w[0], w[1], w[2]};
        for (++k; k < size && sources[order[k]] == source; ++k)
            for (int c = 0; c < 3; ++c) sum[c] += weights[3 * order[k] + c];
        run.push_back(source);
        triples.insert(triples.end(), {float(sum[0]), float(sum[1]), float(sum[2])});
    }
}

}  // namespace

namespace {

// Stencils per part of a float table built in parts, and parts per thread in a wave: enough to
// balance, few enough that a wave's buffers stay small.
constexpr int kPartStencils = 2048, kPartsPerThread = 4;

// A part's stencils as the float table will hold them: each one's size, and their sorted runs of
// sources and rounded weight triples back to back.
struct LimitPart {
    std::vector<int> sizes, runs;
    std::vector<float> triples;
};

// The float table of n stencils over `numSources` sources: fill(i, scratch, runs, triples) appends
// stencil i's sorted run and rounded triples (sortedEntries), in parts of consecutive stencils on
// oneTBB's threads, each thread with its own scratch (makeScratch()); the parts are then interned
// on one thread in stencil order, so the pools, and the table, do not depend on the threads.
// Throws std::length_error once the entries, counted as if none were pooled, pass maxEntries.
template <class MakeScratch, class Fill>
LimitStencilTable floatTableInParts(int n, int numSources, std::size_t maxEntries, MakeScratch makeScratch, Fill fill) {
    LimitStencilTable out;
    out.numSourceVertices = numSources;
    out.sizes.resize(std::size_t(n));
    out.offsets.resize(std::size_t(n));
    out.weightOffsets.resize(std::size_t(n));
    IndexPool runs;
    WeightPool pool;
    const int numParts = (n + kPartStencils - 1) / kPartStencils;
    const int wave = std::max(1, std::min(numParts, kPartsPerThread * parallel::arenaThreads()));
    std::vector<LimitPart> parts(static_cast<std::size_t>(wave));
    parallel::ThreadLocal<decltype(makeScratch())> scratch(makeScratch);
    std::size_t placed = 0;  // entries interned so far
    for (int first = 0; first < numParts; first += wave) {
        const int count = std::min(wave, numParts - first);
        parallel::forEachPart(0, count, [&](int p) {
            LimitPart& part = parts[std::size_t(p)];
            part.sizes.clear();
            part.runs.clear();
            part.triples.clear();
            auto& s = scratch.local();
            const int begin = (first + p) * kPartStencils, end = std::min(n, begin + kPartStencils);
            for (int i = begin; i < end; ++i) {
                const std::size_t before = part.runs.size();
                fill(i, s, part.runs, part.triples);
                part.sizes.push_back(int(part.runs.size() - before));
            }
        });
        for (int p = 0; p < count; ++p) {
            const LimitPart& part = parts[std::size_t(p)];
            const int* run = part.runs.data();
            const float* triple = part.triples.data();
            int i = (first + p) * kPartStencils;
            for (int size : part.sizes) {
                placed += std::size_t(size);
                if (placed > maxEntries) throw std::length_error("limit stencils pass their budget");
                out.sizes[std::size_t(i)] = size;
                out.offsets[std::size_t(i)] = runs.intern(run, size);
                out.weightOffsets[std::size_t(i)] = pool.intern(triple, 3 * size);
                run += size;
                triple += 3 * size;
                ++i;
            }
        }
    }
    out.indices = runs.take();
    out.weights = pool.take();
    return out;
}

// Entries a float table of n stencils may hold within maxBytes, each counted as if unpooled (an
// index and three floats; three ints per stencil).
std::size_t floatEntryLimit(int n, std::size_t maxBytes) {
    const std::size_t fixed = std::size_t(n) * 3 * sizeof(int);
    if (fixed > maxBytes) throw std::length_error("limit stencils pass their budget");
    return (maxBytes - fixed) / (sizeof(int) + 3 * sizeof(float));
}

// One thread's working space for the sort alone.
struct SortScratch {
    std::vector<int> order;
};

// One thread's working space for the composition: a slot per inner source (all -1 between
// stencils), the stencil being composed, and the sort's order.
struct ComposeScratch {
    std::vector<int> slot, indices, order;
    std::vector<double> weights;
};

// One thread's working space for the masks: the ring, the mask, the cache of analysed
// configurations (its answers do not depend on what it holds), the mask's weights interleaved.
struct MaskScratch {
    VertexRing ring;
    LimitMask mask;
    LimitMaskCache cache;
    std::vector<double> weights;
    std::vector<int> order;
};

}  // namespace

LimitStencilTable toFloatTable(const LimitStencilTableD& table) {
    return floatTableInParts(
        table.numStencils(), table.numSourceVertices, ~std::size_t(0), [] { return SortScratch(); },
        [&](int i, SortScratch& s, std::vector<int>& run, std::vector<float>& triples) {
            sortedEntries(table.sizes[i], table.indices.data() + table.offsets[i],
                          table.weights.data() + 3 * std::size_t(table.offsets[i]), s.order, run, triples);
        });
}

LimitStencilTable composeLimitStencilsToFloat(const LimitStencilTableD& limit, const StencilTableD& inner,
                                              std::size_t maxBytes) {
    const int n = limit.numStencils();
    return floatTableInParts(
        n, inner.numSourceVertices, floatEntryLimit(n, maxBytes),
        [&] {
            ComposeScratch s;
            s.slot.assign(std::size_t(inner.numSourceVertices), -1);
            return s;
        },
        [&](int i, ComposeScratch& s, std::vector<int>& run, std::vector<float>& triples) {
            s.indices.clear();
            s.weights.clear();
            composeOneLimit(limit, inner, i, s.slot, s.indices, s.weights);
            sortedEntries(int(s.indices.size()), s.indices.data(), s.weights.data(), s.order, run, triples);
        });
}

LimitStencilTable buildLimitStencilsToFloat(const Topology& level, const Options& options, const RingStarts* starts,
                                            std::size_t maxBytes) {
    const SchemeRules& rules = rulesOf(options.scheme);
    const int n = level.numVertices;
    return floatTableInParts(
        n, n, floatEntryLimit(n, maxBytes), [] { return MaskScratch(); },
        [&](int v, MaskScratch& s, std::vector<int>& run, std::vector<float>& triples) {
            s.weights.clear();
            limitMaskOf(level, options, rules, starts, v, s.ring, s.cache, s.mask, s.weights);
            sortedEntries(s.mask.size(), s.mask.indices.data(), s.weights.data(), s.order, run, triples);
        });
}

std::size_t bytesOf(const LimitStencilTableD& table) {
    return (table.sizes.size() + table.offsets.size() + table.indices.size()) * sizeof(int) +
           table.weights.size() * sizeof(double);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
