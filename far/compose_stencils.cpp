// Composition of stencil tables: a table over another table's stencils expanded over that
// table's sources, in double, one stencil at a time through a dense scatter row. The outer table
// is read as it is stored (a float table's weights widen to double exactly), and the last
// composition of a factorized table can go straight to the stored float table.
//
// Stencils are composed in waves of parts on oneTBB's threads, each part a run of consecutive
// stencils into buffers reused from wave to wave; the parts are then appended in stencil order,
// on one thread, which also interns the float weights: the table is the same on any number of
// threads.
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <vector>

#include "far/internal/regular_patches.h"
#include "far/internal/scatter_row.h"
#include "far/internal/stencil_table_double.h"
#include "far/internal/weight_pool.h"

namespace quadtri {
inline namespace v0 {

namespace {

// Bytes of the double result: an index and a weight per entry, a size and an offset per stencil.
constexpr std::size_t kEntryBytes = sizeof(int) + sizeof(double), kStencilBytes = 2 * sizeof(int);
// Stencils per part, and parts per thread in a wave: enough to balance, few enough that a wave's
// buffers stay a small fraction of the result.
constexpr int kPartStencils = 2048, kPartsPerThread = 4;

// The outer table's stencil i: entries [begin(i), end(i)), entry k's parent and weight.
struct DoubleOuter {
    const StencilTableD& t;
    int numStencils() const { return int(t.sizes.size()); }
    int begin(int i) const { return t.offsets[i]; }
    int end(int i) const { return t.offsets[i] + t.sizes[i]; }
    double weight(int, int k) const { return t.weights[k]; }
    const int* parents() const { return t.indices.data(); }
};

struct FloatOuter {
    const StencilTable& t;
    int numStencils() const { return t.numStencils(); }
    int begin(int i) const { return t.offsets[i]; }
    int end(int i) const { return t.offsets[i + 1]; }
    double weight(int i, int k) const { return double(t.weights[std::size_t(t.weightOffsets[i] + k - t.offsets[i])]); }
    const int* parents() const { return t.indices.data(); }
};

// Entries a double result of n stencils may hold within maxBytes, and within its int offsets.
std::size_t entryLimit(int n, std::size_t maxBytes) {
    const std::size_t perStencil = std::size_t(n) * kStencilBytes;
    if (perStencil > maxBytes) throw std::length_error("stencil table over its memory budget");
    return std::min<std::size_t>((maxBytes - perStencil) / kEntryBytes, (1u << 31) - 1);
}

// Entries to reserve for the result: the inner table's entries per stencil, a quarter more (a
// composed stencil grows by a tenth to a quarter a level once past the first levels), within
// `limit`. Past it the arrays grow by half.
std::size_t expectedEntries(int n, const StencilTableD& inner, std::size_t limit) {
    const double perStencil = inner.sizes.empty() ? 0.0 : double(inner.indices.size()) / double(inner.sizes.size());
    return std::min<std::size_t>(limit, std::size_t(1.25 * perStencil * n) + 16);
}

// Stencil i of outer ∘ inner into `row`: each outer entry's inner stencil, scaled by its weight,
// in entry order, so every sum is added up in the same order whatever the row's layout.
template <class Outer>
void composeOne(const Outer& outer, const StencilTableD& inner, int i, ScatterRow& row) {
    const int begin = outer.begin(i), end = outer.end(i);
    const int* parents = outer.parents();
    const int *sizes = inner.sizes.data(), *offsets = inner.offsets.data();
    int terms = 0;
    for (int k = begin; k < end; ++k) terms += sizes[parents[k]];
    row.reserve(terms);
    for (int k = begin; k < end; ++k) {
        const int j = parents[k];
        row.addScaled(inner.indices.data() + offsets[j], inner.weights.data() + offsets[j], sizes[j], outer.weight(i, k));
    }
}

// A run of composed stencils: their sizes, and their entries back to back, the weights as the
// result stores them (double, or rounded to float).
template <class Weight>
struct Part {
    std::vector<int> sizes;
    std::vector<int> indices;
    std::vector<Weight> weights;
};

// Grows `v` to hold `needed` (half as much again), never past `limit` elements, so that a
// refusal comes before the allocation that would pass the budget.
template <class V>
void reserveFor(V& v, std::size_t needed, std::size_t limit) {
    if (needed > v.capacity()) v.reserve(std::min(limit, needed + needed / 2));
}

// Composes every stencil of outer ∘ inner into parts and hands each part, in stencil order, to
// append(part); those `known` has (if not null) are copied from it. Throws std::length_error
// once the entries composed pass maxEntries.
template <class Weight, class Outer, class Append>
void composeParts(const Outer& outer, const StencilTableD& inner, std::size_t maxEntries, const KnownStencils* known,
                  Append append) {
    const int n = outer.numStencils();
    const int numParts = (n + kPartStencils - 1) / kPartStencils;
    const int wave = std::max(1, std::min(numParts, kPartsPerThread * tbb::this_task_arena::max_concurrency()));
    std::vector<Part<Weight>> parts(static_cast<std::size_t>(wave));
    tbb::enumerable_thread_specific<ScatterRow> rows([&] { return ScatterRow(inner.numSourceVertices); });
    std::atomic<std::size_t> entries{0};  // composed so far, over every part of every wave
    for (int first = 0; first < numParts; first += wave) {
        const int count = std::min(wave, numParts - first);
        tbb::parallel_for(0, count, [&](int p) {
            Part<Weight>& part = parts[std::size_t(p)];
            part.sizes.clear();
            part.indices.clear();
            part.weights.clear();
            ScatterRow& row = rows.local();
            const int begin = (first + p) * kPartStencils, end = std::min(n, begin + kPartStencils);
            for (int i = begin; i < end; ++i) {
                const bool copied = known && known->has(i);
                if (!copied) composeOne(outer, inner, i, row);
                const int size = copied ? known->size(i) : row.size();
                if (entries.fetch_add(std::size_t(size)) + std::size_t(size) > maxEntries) {
                    row.clear();
                    throw std::length_error("stencil table over its memory budget");
                }
                part.sizes.push_back(size);
                if (copied) {
                    const std::size_t at = part.indices.size();
                    part.indices.resize(at + std::size_t(size));
                    part.weights.resize(at + std::size_t(size));
                    known->write(i, part.indices.data() + at, part.weights.data() + at);
                    continue;
                }
                part.indices.insert(part.indices.end(), row.indices(), row.indices() + size);
                part.weights.insert(part.weights.end(), row.weights(), row.weights() + size);
                row.clear();
            }
        });
        for (int p = 0; p < count; ++p) append(parts[std::size_t(p)]);
    }
}

template <class Outer>
StencilTableD composeDouble(const Outer& outer, const StencilTableD& inner, std::size_t maxBytes,
                            const KnownStencils* known) {
    StencilTableD result;
    result.numSourceVertices = inner.numSourceVertices;
    const int n = outer.numStencils();
    const std::size_t maxEntries = entryLimit(n, maxBytes);
    result.sizes.reserve(n);
    result.offsets.reserve(n);
    const std::size_t expected = expectedEntries(n, inner, maxEntries);
    result.indices.reserve(expected);
    result.weights.reserve(expected);
    composeParts<double>(outer, inner, maxEntries, known, [&](const Part<double>& part) {
        const std::size_t needed = result.indices.size() + part.indices.size();
        reserveFor(result.indices, needed, maxEntries);
        reserveFor(result.weights, needed, maxEntries);
        for (int size : part.sizes) {
            result.offsets.push_back(result.offsets.empty() ? 0 : result.offsets.back() + result.sizes.back());
            result.sizes.push_back(size);
        }
        result.indices.insert(result.indices.end(), part.indices.begin(), part.indices.end());
        result.weights.insert(result.weights.end(), part.weights.begin(), part.weights.end());
    });
    return result;
}

template <class Outer>
StencilTable composeFloat(const Outer& outer, const StencilTableD& inner, std::size_t maxBytes, const KnownStencils* known) {
    StencilTable result;
    result.numSourceVertices = inner.numSourceVertices;
    const int n = outer.numStencils();
    const std::size_t maxEntries = entryLimit(n, maxBytes);
    result.offsets.reserve(std::size_t(n) + 1);
    result.weightOffsets.reserve(n);
    result.indices.reserve(expectedEntries(n, inner, maxEntries));
    WeightPool pool;
    // A known stencil's weights are its template's: interned once per template, not per stencil.
    std::vector<int> pooled[2];
    if (known) {
        std::vector<float> rounded;
        for (int kind = 0; kind < 2; ++kind)
            for (int p = 0; p < known->numTemplates[kind]; ++p) {
                const int begin = known->offsets[kind][p], end = known->offsets[kind][p + 1];
                rounded.assign(known->weights[kind] + begin, known->weights[kind] + end);
                pooled[kind].push_back(pool.intern(rounded.data(), end - begin));
            }
    }
    int i = 0;  // the stencil appended next
    composeParts<float>(outer, inner, maxEntries, known, [&](const Part<float>& part) {
        reserveFor(result.indices, result.indices.size() + part.indices.size(), maxEntries);
        const float* weights = part.weights.data();
        for (int size : part.sizes) {
            result.offsets.push_back(result.offsets.back() + size);
            const bool copied = known && known->has(i);
            result.weightOffsets.push_back(copied ? pooled[known->kind(i)][std::size_t(known->position[i])]
                                                  : pool.intern(weights, size));
            weights += size;
            ++i;
        }
        result.indices.insert(result.indices.end(), part.indices.begin(), part.indices.end());
    });
    result.weights = pool.take();
    return result;
}

}  // namespace

StencilTableD composeStencils(const StencilTableD& outer, const StencilTableD& inner, std::size_t maxBytes,
    const KnownStencils* known) {
    return composeDouble(DoubleOuter{outer}, inner, maxBytes, known);
}

StencilTableD composeStencils(const StencilTable& outer, const StencilTableD& inner, std::size_t maxBytes,
    const KnownStencils* known) {
    return composeDouble(FloatOuter{outer}, inner, maxBytes, known);
}

StencilTable composeStencilsToFloat(const StencilTableD& outer, const StencilTableD& inner, std::size_t maxBytes,
    const KnownStencils* known) {
    return composeFloat(DoubleOuter{outer}, inner, maxBytes, known);
}

StencilTable composeStencilsToFloat(const StencilTable& outer, const StencilTableD& inner, std::size_t maxBytes,
    const KnownStencils* known) {
    return composeFloat(FloatOuter{outer}, inner, maxBytes, known);
}

}  // namespace v0
}  // namespace quadtri
