// Composition of stencil tables: a table over another table's stencils expanded over that
// table's sources, in double, one stencil at a time through a dense scatter row. The outer table
// is read as it is stored (a float table's weights widen to double exactly), and the last
// composition of a factorized table can go straight to the stored float table.
//
// Stencils are composed in waves of parts on oneTBB's threads, each part a run of consecutive
// stencils into buffers reused from wave to wave; the parts are then placed in stencil order, on
// one thread, which also interns the float weights, and written into the result on the threads:
// the table is the same on any number of threads. Stencils that templates give
// (far/tables/regular_patches.h) are written straight into the result, and read from their
// templates by the composition of the level below.

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "far/tables/regular_patches.h"
#include "far/tables/scatter_row.h"
#include "far/internal/stencil_table_double.h"
#include "far/tables/weight_pool.h"
#include "far/internal/parallel.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

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

// The inner table's stencil j: its entries' sources and weights. A float table's weights widen
// to double exactly, so composing over it is composing over its toDoubleTable() bitwise, without
// making that copy (level 1's, under level 2 of every factorized table).
struct DoubleInner {
    const StencilTableD& t;
    int numSources() const { return t.numSourceVertices; }
    int numStencils() const { return int(t.sizes.size()); }
    std::size_t numEntries() const { return t.indices.size(); }
    int size(int j) const { return t.sizes[j]; }
    const int* indices(int j) const { return t.indices.data() + t.offsets[j]; }
    const double* weights(int j) const { return t.weights.data() + t.offsets[j]; }
};

struct FloatInner {
    const StencilTable& t;
    int numSources() const { return t.numSourceVertices; }
    int numStencils() const { return t.numStencils(); }
    std::size_t numEntries() const { return t.numEntries(); }
    int size(int j) const { return t.offsets[j + 1] - t.offsets[j]; }
    const int* indices(int j) const { return t.indices.data() + t.offsets[j]; }
    const float* weights(int j) const { return t.weights.data() + t.weightOffsets[j]; }
};

// Entries a double result of n stencils may hold within maxBytes, and within its int offsets.
std::size_t entryLimit(int n, std::size_t maxBytes) {
    const std::size_t perStencil = std::size_t(n) * kStencilBytes;
    if (perStencil > maxBytes) throw std::length_error("stencil table over its memory budget");
    return std::min<std::size_t>((maxBytes - perStencil) / kEntryBytes, (1u << 31) - 1);
}

// Entries to reserve for the result: the templated stencils' own sizes (none where they are
// left out), and for each of the others the inner table's entries per stored stencil and a
// quarter more (a composed stencil grows by a tenth to a quarter a level once past the first
// levels), within `limit`. Past it the arrays grow by half.
template <class Inner>
std::size_t expectedEntries(int n, const Inner& inner, const TemplatedStencils& templated, std::size_t limit) {
    std::size_t stored = std::size_t(inner.numStencils());
    if (templated.inner)
        for (int j = 0; j < inner.numStencils(); ++j) stored -= templated.inner->has(j) ? 1 : 0;
    const double perStencil = stored == 0 ? 0.0 : double(inner.numEntries()) / double(stored);
    std::size_t knownEntries = 0;
    int composed = n;
    if (const KnownStencils* known = templated.result)
        for (int i = 0; i < n; ++i)
            if (known->has(i)) {
                if (!templated.leaveOut) knownEntries += std::size_t(known->size(i));
                --composed;
            }
    return std::min<std::size_t>(limit, knownEntries + std::size_t(1.25 * perStencil * composed) + 16);
}

// Stencil i of outer ∘ inner into `row`: each outer entry's inner stencil (from its template
// where `innerKnown` has it), scaled by its weight, in entry order, so every sum is added up in
// the same order whatever the row's layout. A templated inner stencil's entries come in the order
// the table would have held them (KnownStencils::write).
template <class Outer, class Inner>
void composeOne(const Outer& outer, const Inner& inner, const KnownStencils* innerKnown, int i, ScatterRow& row) {
    const int begin = outer.begin(i), end = outer.end(i);
    const int* parents = outer.parents();
    auto templated = [&](int j) { return innerKnown && innerKnown->has(j); };
    int terms = 0;
    for (int k = begin; k < end; ++k) {
        const int j = parents[k];
        terms += templated(j) ? innerKnown->size(j) : inner.size(j);
    }
    row.reserve(terms);
    for (int k = begin; k < end; ++k) {
        const int j = parents[k];
        if (templated(j)) {
            const KnownStencils::Entries t = innerKnown->entries(j);
            row.addScaled(t.patch, t.corners, t.weights, t.size, outer.weight(i, k));
        } else {
            row.addScaled(inner.indices(j), inner.weights(j), inner.size(j), outer.weight(i, k));
        }
    }
}

// A run of consecutive stencils: every stencil's size, and the entries of those composed (not
// known) back to back, the weights as the result stores them (double, or rounded to float);
// `at`, where the run's entries start in the result.
template <class Weight>
struct Part {
    std::vector<int> sizes;
    std::vector<int> indices;
    std::vector<Weight> weights;
    std::size_t at = 0;
};

// Grows `v` to hold `needed` (half as much again), never past `limit` elements, so that a
// refusal comes before the allocation that would pass the budget.
template <class V>
void reserveFor(V& v, std::size_t needed, std::size_t limit) {
    if (needed > v.capacity()) v.reserve(std::min(limit, needed + needed / 2));
}

// Composes every stencil of outer ∘ inner into the result that `sink` keeps. Waves of parts are
// composed on the threads; sink.append(part), on one thread and in stencil order, takes each
// part's stencils, grows the result to hold their entries and returns where they start; then the
// parts' entries are written there on the threads: a composed stencil's from its part, a
// templated one's straight from its template, so that it is written once (or left out).
// sink.indices() and sink.weights() point at the result's entries (weights null where the
// result keeps none per entry). Throws std::length_error once the entries pass maxEntries.
template <class Weight, class Outer, class Inner, class Sink>
void composeParts(const Outer& outer, const Inner& inner, std::size_t maxEntries,
                  const TemplatedStencils& templated, Sink& sink) {
    const int n = outer.numStencils();
    const int numParts = (n + kPartStencils - 1) / kPartStencils;
    const int wave = std::max(1, std::min(numParts, kPartsPerThread * parallel::arenaThreads()));
    std::vector<Part<Weight>> parts(static_cast<std::size_t>(wave));
    parallel::ThreadLocal<ScatterRow> rows([&] { return ScatterRow(inner.numSources()); });
    std::size_t placed = 0;  // entries of the parts placed so far, over every wave
    const KnownStencils* known = templated.result;
    auto isKnown = [&](int i) { return known && known->has(i); };
    for (int first = 0; first < numParts; first += wave) {
        const int count = std::min(wave, numParts - first);
        auto range = [&](int p) { return std::make_pair((first + p) * kPartStencils, std::min(n, (first + p + 1) * kPartStencils)); };
        parallel::forEachPart(0, count, [&](int p) {
            Part<Weight>& part = parts[std::size_t(p)];
            part.sizes.clear();
            part.indices.clear();
            part.weights.clear();
            ScatterRow& row = rows.local();
            const auto [begin, end] = range(p);
            // The part alone past the budget stops here; the wave's parts together are checked as
            // they are placed. No count shared between threads: an atomic add per stencil made two
            // threads slower than one.
            std::size_t partEntries = 0;
            for (int i = begin; i < end; ++i) {
                const bool copied = isKnown(i);
                if (!copied) composeOne(outer, inner, templated.inner, i, row);
                const int size = copied ? (templated.leaveOut ? 0 : known->size(i)) : row.size();
                partEntries += std::size_t(size);
                if (placed + partEntries > maxEntries) {
                    row.clear();
                    throw std::length_error("stencil table over its memory budget");
                }
                part.sizes.push_back(size);
                if (copied) continue;
                part.indices.insert(part.indices.end(), row.indices(), row.indices() + size);
                part.weights.insert(part.weights.end(), row.weights(), row.weights() + size);
                row.clear();
            }
        });
        for (int p = 0; p < count; ++p) {
            Part<Weight>& part = parts[std::size_t(p)];
            for (int size : part.sizes) placed += std::size_t(size);
            if (placed > maxEntries) throw std::length_error("stencil table over its memory budget");
            part.at = sink.append(part, range(p).first);
        }
        parallel::forEachPart(0, count, [&](int p) {
            const Part<Weight>& part = parts[std::size_t(p)];
            int* indices = sink.indices() + part.at;
            Weight* weights = sink.weights() ? sink.weights() + part.at : nullptr;
            const int* composedIndices = part.indices.data();
            const Weight* composedWeights = part.weights.data();
            const auto [begin, end] = range(p);
            for (int i = begin; i < end; ++i) {
                const int size = part.sizes[std::size_t(i - begin)];
                if (isKnown(i)) {
                    if (size > 0) known->write(i, indices, weights);
                } else {
                    std::copy_n(composedIndices, size, indices);
                    composedIndices += size;
                    if (weights) std::copy_n(composedWeights, size, weights);
                    composedWeights += size;
                }
                indices += size;
                if (weights) weights += size;
            }
        });
    }
}

// The double result: entries appended part by part.
struct DoubleSink {
    StencilTableD& result;
    std::size_t maxEntries;
    std::size_t append(const Part<double>& part, int) {
        const std::size_t at = result.indices.size();
        std::size_t size = 0;
        for (int s : part.sizes) {
            result.offsets.push_back(int(at + size));
            result.sizes.push_back(s);
            size += std::size_t(s);
        }
        reserveFor(result.indices, at + size, maxEntries);
        reserveFor(result.weights, at + size, maxEntries);
        result.indices.resize(at + size);
        result.weights.resize(at + size);
        return at;
    }
    int* indices() { return result.indices.data(); }
    double* weights() { return result.weights.data(); }
};

template <class Outer, class Inner>
StencilTableD composeDouble(const Outer& outer, const Inner& inner, std::size_t maxBytes,
                            const TemplatedStencils& templated) {
    StencilTableD result;
    result.numSourceVertices = inner.numSources();
    const int n = outer.numStencils();
    const std::size_t maxEntries = entryLimit(n, maxBytes);
    result.sizes.reserve(std::size_t(n));
    result.offsets.reserve(std::size_t(n));
    const std::size_t expected = expectedEntries(n, inner, templated, maxEntries);
    result.indices.reserve(expected);
    result.weights.reserve(expected);
    DoubleSink sink{result, maxEntries};
    composeParts<double>(outer, inner, maxEntries, templated, sink);
    return result;
}

// The float result: offsets and interned weights appended part by part (a known stencil's weights
// are its template's, interned once per template), the indices after them.
struct FloatSink {
    StencilTable& result;
    WeightPool& pool;
    const KnownStencils* known;
    const std::vector<int>* pooled;  // per kind: each template's weights in the pool
    std::size_t maxEntries;
    std::size_t append(const Part<float>& part, int first) {
        const std::size_t at = result.indices.size();
        const float* weights = part.weights.data();
        int i = first;
        for (int size : part.sizes) {
            result.offsets.push_back(result.offsets.back() + size);
            if (known && known->has(i)) {
                result.weightOffsets.push_back(pooled[known->kind(i)][std::size_t(known->position[i])]);
            } else {
                result.weightOffsets.push_back(pool.intern(weights, size));
                weights += size;
            }
            ++i;
        }
        const std::size_t end = std::size_t(result.offsets.back());
        reserveFor(result.indices, end, maxEntries);
        result.indices.resize(end);
        return at;
    }
    int* indices() { return result.indices.data(); }
    float* weights() { return nullptr; }
};

template <class Outer, class Inner>
StencilTable composeFloat(const Outer& outer, const Inner& inner, std::size_t maxBytes,
                          TemplatedStencils templated) {
    templated.leaveOut = false;
    const KnownStencils* known = templated.result;
    StencilTable result;
    result.numSourceVertices = inner.numSources();
    const int n = outer.numStencils();
    const std::size_t maxEntries = entryLimit(n, maxBytes);
    result.offsets.reserve(std::size_t(n) + 1);
    result.weightOffsets.reserve(std::size_t(n));
    result.indices.reserve(expectedEntries(n, inner, templated, maxEntries));
    WeightPool pool;
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
    FloatSink sink{result, pool, known, pooled, maxEntries};
    composeParts<float>(outer, inner, maxEntries, templated, sink);
    result.weights = pool.take();
    return result;
}

}  // namespace

StencilTableD composeStencils(const StencilTableD& outer, const StencilTableD& inner, std::size_t maxBytes,
                              const TemplatedStencils& templated) {
    return composeDouble(DoubleOuter{outer}, DoubleInner{inner}, maxBytes, templated);
}

StencilTableD composeStencils(const StencilTable& outer, const StencilTableD& inner, std::size_t maxBytes,
                              const TemplatedStencils& templated) {
    return composeDouble(FloatOuter{outer}, DoubleInner{inner}, maxBytes, templated);
}

StencilTableD composeStencils(const StencilTable& outer, const StencilTable& inner, std::size_t maxBytes,
                              const TemplatedStencils& templated) {
    return composeDouble(FloatOuter{outer}, FloatInner{inner}, maxBytes, templated);
}

StencilTable composeStencilsToFloat(const StencilTableD& outer, const StencilTableD& inner, std::size_t maxBytes,
                                    const TemplatedStencils& templated) {
    return composeFloat(DoubleOuter{outer}, DoubleInner{inner}, maxBytes, templated);
}

StencilTable composeStencilsToFloat(const StencilTable& outer, const StencilTableD& inner, std::size_t maxBytes,
                                    const TemplatedStencils& templated) {
    return composeFloat(FloatOuter{outer}, DoubleInner{inner}, maxBytes, templated);
}

StencilTable composeStencilsToFloat(const StencilTable& outer, const StencilTable& inner, std::size_t maxBytes,
                                    const TemplatedStencils& templated) {
    return composeFloat(FloatOuter{outer}, FloatInner{inner}, maxBytes, templated);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
