// Limit stencil tables (docs/limit.md): one mask per vertex from the scheme's hook, built in
// parallel parts (one ring, mask and cache per part, joined in vertex order, so the table does
// not depend on the thread count), composition over the control vertices, the float table with
// its runs of sources and its weight triples pooled.
#include "far/internal/limit_table.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <stdexcept>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "far/internal/fresh_pages.h"
#include "far/internal/limit_eigen.h"
#include "far/internal/limit_ring.h"
#include "far/internal/scheme.h"
#include "far/internal/weight_pool.h"

namespace quadtri {
inline namespace v0 {

namespace {

void appendMask(const LimitMask& mask, LimitStencilTableD& table) {
    table.offsets.push_back(int(table.indices.size()));
    table.sizes.push_back(mask.size());
    for (int k = 0; k < mask.size(); ++k) {
        table.indices.push_back(mask.indices[k]);
        table.weights.push_back(mask.position[k]);
        table.weights.push_back(mask.du[k]);
        table.weights.push_back(mask.dv[k]);
    }
}

void append(const LimitStencilTableD& part, LimitStencilTableD& table) {
    const int base = int(table.indices.size());
    for (int offset : part.offsets) table.offsets.push_back(base + offset);
    table.sizes.insert(table.sizes.end(), part.sizes.begin(), part.sizes.end());
    table.indices.insert(table.indices.end(), part.indices.begin(), part.indices.end());
    table.weights.insert(table.weights.end(), part.weights.begin(), part.weights.end());
}

// Room in `table` for `stencils` and `entries`, on fresh huge pages where the arrays are large
// (far/internal/fresh_pages.h): a limit table of a few hundred thousand vertices is hundreds of
// MB, and its first touch in 4 KiB faults took longer than its masks.
void reserveFor(std::size_t stencils, std::size_t entries, LimitStencilTableD& table) {
    reserveFresh(table.sizes, stencils);
    reserveFresh(table.offsets, stencils);
    reserveFresh(table.indices, entries);
    reserveFresh(table.weights, 3 * entries);
}

// Room for every part at once: no copy of what was joined so far.
void reserveFor(const std::vector<LimitStencilTableD>& parts, LimitStencilTableD& table) {
    std::size_t stencils = 0, entries = 0;
    for (const LimitStencilTableD& part : parts) {
        stencils += part.sizes.size();
        entries += part.indices.size();
    }
    reserveFor(stencils, entries, table);
}

// Vertices per part below which a level is not split.
constexpr int kMinVerticesPerPart = 16384;

}  // namespace

LimitStencilTableD buildLimitStencils(const Topology& level, const Options& options, const RingStarts* starts) {
    const SchemeRules& rules = rulesOf(options.scheme);
    const int n = level.numVertices;
    const int parts = std::max(1, std::min(tbb::this_task_arena::max_concurrency(), n / kMinVerticesPerPart));
    auto split = [&](int k) { return int(std::int64_t(n) * k / parts); };
    std::vector<LimitStencilTableD> built(parts);
    tbb::parallel_for(0, parts, [&](int k) {
        VertexRing ring;
        LimitMask mask;
        LimitMaskCache cache;
        LimitStencilTableD& part = built[k];
        const int first = split(k), last = split(k + 1);
        // At most the vertex, its edge neighbours and its faces' opposite corners per stencil.
        const std::size_t bound = std::size_t(last - first) + (level.vertEdgeOffsets[last] - level.vertEdgeOffsets[first]) +
                                  (level.vertFaceOffsets[last] - level.vertFaceOffsets[first]);
        reserveFor(std::size_t(last - first), bound, part);
        for (int v = first; v < last; ++v) {
            orderVertexRing(level, v, starts ? starts->startFace(v) : -1, ring);
            mask.clear();
            rules.limitMask(LimitVertex{level, options, ring, limitRule(level, ring)}, cache, mask);
            appendMask(mask, part);
        }
    });
    LimitStencilTableD table;
    if (parts == 1) {
        table = std::move(built[0]);
    } else {
        reserveFor(built, table);
        for (const LimitStencilTableD& part : built) append(part, table);
    }
    table.numSourceVertices = n;
    return table;
}

namespace {

// Stencils [first, last) of limit ∘ inner into `out`; `entries` counts every part's entries so
// that all of them together stop at `maxEntries`. The arrays are reserved for the inner table's
// entries per stencil and a quarter more (a limit stencil reads its vertex's ring, whose composed
// stencils overlap: the demo's limb at level 3 has 14.4 entries a composed limit stencil over
// 12.6 an inner one), and grow by half before a stencil that might not fit, onto fresh pages
// each time: growing by doubling behind push_back copied the arrays and faulted each new block
// in 4 KiB at a time, most of the composition's time.
void composeRange(const LimitStencilTableD& limit, const StencilTableD& inner, int first, int last,
                  std::atomic<std::size_t>& entries, std::size_t maxEntries, LimitStencilTableD& out) {
    std::vector<int> slot(inner.numSourceVertices, -1);  // where a source sits in the current stencil
    const double perStencil = inner.sizes.empty() ? 0.0 : double(inner.indices.size()) / double(inner.sizes.size());
    reserveFor(std::size_t(last - first),
               std::min(maxEntries, std::size_t(1.25 * perStencil * double(last - first)) + 16), out);
    for (int i = first; i < last; ++i) {
        const std::size_t start = out.indices.size();
        std::size_t most = 0;  // entries stencil i can have: its entries' inner stencils added up
        for (int k = 0; k < limit.sizes[i]; ++k) most += std::size_t(inner.sizes[limit.indices[limit.offsets[i] + k]]);
        if (start + most > out.indices.capacity()) {
            const std::size_t grown = start + most + (start + most) / 2;
            reserveFresh(out.indices, grown);
            reserveFresh(out.weights, 3 * grown);
        }
        out.offsets.push_back(int(start));
        for (int k = 0; k < limit.sizes[i]; ++k) {
            const int entry = limit.offsets[i] + k, s = limit.indices[entry];
            const double* w = limit.weights.data() + 3 * std::size_t(entry);
            for (int j = 0; j < inner.sizes[s]; ++j) {
                const int c = inner.indices[inner.offsets[s] + j];
                const double x = inner.weights[inner.offsets[s] + j];
                if (slot[c] < 0) {
                    slot[c] = int(out.indices.size());
                    out.indices.push_back(c);
                    out.weights.insert(out.weights.end(), {0.0, 0.0, 0.0});
                }
                double* o = out.weights.data() + 3 * std::size_t(slot[c]);
                o[0] += w[0] * x;
                o[1] += w[1] * x;
                o[2] += w[2] * x;
            }
        }
        for (std::size_t k = start; k < out.indices.size(); ++k) slot[out.indices[k]] = -1;
        const int size = int(out.indices.size() - start);
        out.sizes.push_back(size);
        if (entries.fetch_add(size) + size > maxEntries) throw std::length_error("composed limit stencils pass their budget");
    }
}

}  // namespace

LimitStencilTableD composeLimitStencils(const LimitStencilTableD& limit, const StencilTableD& inner,
                                        std::size_t maxBytes) {
    const int n = limit.numStencils();
    const int parts = std::max(1, std::min(tbb::this_task_arena::max_concurrency(), n / kMinVerticesPerPart));
    // Bytes per entry (an index, three weights), twice over while parts are joined.
    const std::size_t perEntry = (parts > 1 ? 2 : 1) * (sizeof(int) + 3 * sizeof(double));
    const std::size_t fixed = std::size_t(n) * 2 * sizeof(int);
    if (fixed > maxBytes) throw std::length_error("composed limit stencils pass their budget");
    const std::size_t maxEntries = std::min<std::size_t>((maxBytes - fixed) / perEntry, INT32_MAX);
    auto split = [&](int k) { return int(std::int64_t(n) * k / parts); };
    std::atomic<std::size_t> entries{0};
    std::vector<LimitStencilTableD> built(parts);
    tbb::parallel_for(0, parts, [&](int k) { composeRange(limit, inner, split(k), split(k + 1), entries, maxEntries, built[k]); });
    LimitStencilTableD out;
    if (parts == 1) {
        out = std::move(built[0]);
    } else {
        reserveFor(built, out);
        for (const LimitStencilTableD& part : built) append(part, out);
    }
    out.numSourceVertices = inner.numSourceVertices;
    return out;
}

namespace {

// Stencil i's entries in ascending source order: its sources into `run`, their weight triples
// rounded to float into `triples`. The sort is by (source, position in the stencil), so ties
// (a source listed twice) keep their order and become one entry, weights added in double.
void sortedEntries(const LimitStencilTableD& table, int i, std::vector<int>& order, std::vector<int>& run,
                   std::vector<float>& triples) {
    const int size = table.sizes[i];
    const int* sources = table.indices.data() + table.offsets[i];
    const double* weights = table.weights.data() + 3 * std::size_t(table.offsets[i]);
    order.resize(size);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return sources[a] < sources[b] || (sources[a] == sources[b] && a < b); });
    run.clear();
    triples.clear();
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

LimitStencilTable toFloatTable(const LimitStencilTableD& table) {
    LimitStencilTable out;
    out.numSourceVertices = table.numSourceVertices;
    const int n = table.numStencils();
    out.sizes.resize(n);
    out.offsets.resize(n);
    out.weightOffsets.resize(n);
    IndexPool runs;
    WeightPool pool;
    std::vector<int> order, run;
    std::vector<float> triples;
    for (int i = 0; i < n; ++i) {
        sortedEntries(table, i, order, run, triples);
        const int size = int(run.size());
        out.sizes[i] = size;
        out.offsets[i] = runs.intern(run.data(), size);
        out.weightOffsets[i] = pool.intern(triples.data(), 3 * size);
    }
    out.indices = runs.take();
    out.weights = pool.take();
    return out;
}

std::size_t bytesOf(const LimitStencilTableD& table) {
    return (table.sizes.size() + table.offsets.size() + table.indices.size()) * sizeof(int) +
           table.weights.size() * sizeof(double);
}

}  // namespace v0
}  // namespace quadtri
