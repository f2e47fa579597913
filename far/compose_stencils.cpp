// Composition of stencil tables: a table over another table's stencils expanded over that
// table's sources, in double, one stencil at a time through a dense scatter row. The outer table
// is read as it is stored (a float table's weights widen to double exactly), and the last
// composition of a factorized table can go straight to the stored float table.
//
// Stencils are composed in waves of parts on oneTBB's threads, each part a run of consecutive
// stencils into buffers reused from wave to wave; the parts are then appended in stencil order,
// on one thread, which also interns the float weights: the table is the same on any number of
// threads. A stencil whose shape was composed before (far/internal/composition_memo.h) takes its
// weights from the memo instead of the scatter row, and in a float table its pooled weights too.
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "far/internal/composition_memo.h"
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
    int mask(int) const { return CompositionMemo::kNoClass; }  // weights not pooled: not memoized
};

struct FloatOuter {
    const StencilTable& t;
    int numStencils() const { return t.numStencils(); }
    int begin(int i) const { return t.offsets[i]; }
    int end(int i) const { return t.offsets[i + 1]; }
    double weight(int i, int k) const { return double(t.weights[std::size_t(t.weightOffsets[i] + k - t.offsets[i])]); }
    const int* parents() const { return t.indices.data(); }
    int mask(int i) const { return t.weightOffsets[i]; }  // with the stencil's size, its weights
};

// The classes of the inner table's stencils: the composition's own where it made the table, else
// one per distinct weight sequence (bitwise), into `own`.
const int* innerClasses(const StencilTableD& inner, std::vector<int>& own) {
    if (inner.classes.size() == inner.sizes.size()) return inner.classes.data();
    own.resize(inner.sizes.size());
    std::unordered_multimap<std::uint64_t, int> seen;  // hash of a sequence -> stencils that start a class
    int classes = 0;
    for (std::size_t i = 0; i < inner.sizes.size(); ++i) {
        const double* w = inner.weights.data() + inner.offsets[i];
        const int n = inner.sizes[i];
        std::uint64_t h = std::uint64_t(n);
        for (int k = 0; k < n; ++k) {
            std::uint64_t bits;
            std::memcpy(&bits, w + k, sizeof bits);
            h = (h ^ bits) * 0x100000001B3ull;
        }
        own[i] = -1;
        for (auto [at, last] = seen.equal_range(h); at != last; ++at) {
            const std::size_t j = std::size_t(at->second);
            if (inner.sizes[j] == n && std::memcmp(inner.weights.data() + inner.offsets[j], w, sizeof(double) * std::size_t(n)) == 0) {
                own[i] = own[j];
                break;
            }
        }
        if (own[i] < 0) {
            own[i] = classes++;
            seen.emplace(h, int(i));
        }
    }
    return own.data();
}

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

// A composed stencil: its class (CompositionMemo::kNoClass when not memoized) and its entries.
struct Composed {
    int cls, size;
    const int* indices;
    const double* weights;
};

// What a thread composes with: the scatter row and its memo.
struct Worker {
    ScatterRow row;
    CompositionMemo memo;
};

// Stencil i of outer ∘ inner: from the memo where its shape was seen, else through the row:
// each outer entry's inner stencil, scaled by its weight, in entry order, so every sum is added
// up in the same order whatever the row's layout. The caller clears the row after reading it.
template <class Outer>
Composed composeOne(const Outer& outer, const StencilTableD& inner, const int* classes, int i, Worker& worker) {
    const int begin = outer.begin(i), end = outer.end(i);
    const int* parents = outer.parents();
    const int *sizes = inner.sizes.data(), *offsets = inner.offsets.data();
    CompositionMemo& memo = worker.memo;
    bool memoize = outer.mask(i) >= 0 && memo.usable();
    if (memoize) {
        memo.begin(outer.mask(i));
        for (int k = begin; k < end && memoize; ++k) {
            const int j = parents[k];
            memoize = classes[j] >= 0;
            memo.addInner(classes[j], inner.indices.data() + offsets[j], sizes[j]);
        }
        if (memoize) {
            const int cls = memo.find();
            if (cls >= 0) return {cls, memo.size(cls), memo.sources(), memo.weights(cls)};
        }
    }
    ScatterRow& row = worker.row;
    int terms = 0;
    for (int k = begin; k < end; ++k) terms += sizes[parents[k]];
    row.reserve(terms);
    for (int k = begin; k < end; ++k) {
        const int j = parents[k];
        row.addScaled(inner.indices.data() + offsets[j], inner.weights.data() + offsets[j], sizes[j], outer.weight(i, k));
    }
    const int cls = memoize ? memo.add(row.size(), row.weights(), [&](int source) { return row.entryOf(source); })
                            : CompositionMemo::kNoClass;
    return {cls, row.size(), row.indices(), row.weights()};
}

// A run of composed stencils: their sizes and classes, and their entries back to back, the
// weights as the result stores them (double, or rounded to float). A float part keeps the
// weights of unclassed stencils only: the others are the memo's.
template <class Weight>
struct Part {
    std::vector<int> sizes, classes;
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
// append(part, memos), memos[serial] the memo of the classes with that serial. Throws
// std::length_error once the entries composed pass maxEntries.
template <class Weight, class Outer, class Append>
void composeParts(const Outer& outer, const StencilTableD& inner, std::size_t maxEntries, Append append) {
    const int n = outer.numStencils();
    const int numParts = (n + kPartStencils - 1) / kPartStencils;
    const int wave = std::max(1, std::min(numParts, kPartsPerThread * tbb::this_task_arena::max_concurrency()));
    std::vector<Part<Weight>> parts(static_cast<std::size_t>(wave));
    std::vector<int> ownClasses;
    const int* classes = innerClasses(inner, ownClasses);
    std::atomic<int> serials{0};
    tbb::enumerable_thread_specific<Worker> workers(
        [&] { return Worker{ScatterRow(inner.numSourceVertices), CompositionMemo(serials++, inner.numSourceVertices)}; });
    std::vector<const CompositionMemo*> memos;
    std::atomic<std::size_t> entries{0};  // composed so far, over every part of every wave
    for (int first = 0; first < numParts; first += wave) {
        const int count = std::min(wave, numParts - first);
        tbb::parallel_for(0, count, [&](int p) {
            Part<Weight>& part = parts[std::size_t(p)];
            part.sizes.clear();
            part.classes.clear();
            part.indices.clear();
            part.weights.clear();
            Worker& worker = workers.local();
            const int begin = (first + p) * kPartStencils, end = std::min(n, begin + kPartStencils);
            for (int i = begin; i < end; ++i) {
                const Composed c = composeOne(outer, inner, classes, i, worker);
                if (entries.fetch_add(std::size_t(c.size)) + std::size_t(c.size) > maxEntries) {
                    worker.row.clear();
                    throw std::length_error("stencil table over its memory budget");
                }
                part.sizes.push_back(c.size);
                part.classes.push_back(c.cls);
                part.indices.insert(part.indices.end(), c.indices, c.indices + c.size);
                if (std::is_same_v<Weight, double> || c.cls < 0) part.weights.insert(part.weights.end(), c.weights, c.weights + c.size);
                worker.row.clear();
            }
        });
        memos.assign(std::size_t(serials.load()), nullptr);
        for (const Worker& worker : workers) memos[std::size_t(worker.memo.serial())] = &worker.memo;
        for (int p = 0; p < count; ++p) append(parts[std::size_t(p)], memos);
    }
}

template <class Outer>
StencilTableD composeDouble(const Outer& outer, const StencilTableD& inner, std::size_t maxBytes) {
    StencilTableD result;
    result.numSourceVertices = inner.numSourceVertices;
    const int n = outer.numStencils();
    const std::size_t maxEntries = entryLimit(n, maxBytes);
    result.sizes.reserve(n);
    result.offsets.reserve(n);
    const std::size_t expected = expectedEntries(n, inner, maxEntries);
    result.indices.reserve(expected);
    result.weights.reserve(expected);
    result.classes.reserve(n);
    composeParts<double>(outer, inner, maxEntries, [&](const Part<double>& part, const std::vector<const CompositionMemo*>&) {
        const std::size_t needed = result.indices.size() + part.indices.size();
        reserveFor(result.indices, needed, maxEntries);
        reserveFor(result.weights, needed, maxEntries);
        for (int size : part.sizes) {
            result.offsets.push_back(result.offsets.empty() ? 0 : result.offsets.back() + result.sizes.back());
            result.sizes.push_back(size);
        }
        result.indices.insert(result.indices.end(), part.indices.begin(), part.indices.end());
        result.weights.insert(result.weights.end(), part.weights.begin(), part.weights.end());
        result.classes.insert(result.classes.end(), part.classes.begin(), part.classes.end());
    });
    return result;
}

template <class Outer>
StencilTable composeFloat(const Outer& outer, const StencilTableD& inner, std::size_t maxBytes) {
    StencilTable result;
    result.numSourceVertices = inner.numSourceVertices;
    const int n = outer.numStencils();
    const std::size_t maxEntries = entryLimit(n, maxBytes);
    result.offsets.reserve(std::size_t(n) + 1);
    result.weightOffsets.reserve(n);
    result.indices.reserve(expectedEntries(n, inner, maxEntries));
    WeightPool pool;
    // Per memo serial, per class: its weights' pool offset, -1 until a stencil of it is appended.
    // Interning a class's weights once is as interning them for each of its stencils: the pool
    // only grows at the first of a sequence.
    std::vector<std::vector<int>> pooled;
    composeParts<float>(outer, inner, maxEntries, [&](const Part<float>& part, const std::vector<const CompositionMemo*>& memos) {
        reserveFor(result.indices, result.indices.size() + part.indices.size(), maxEntries);
        pooled.resize(memos.size());
        const float* weights = part.weights.data();
        for (std::size_t s = 0; s < part.sizes.size(); ++s) {
            const int size = part.sizes[s], cls = part.classes[s];
            result.offsets.push_back(result.offsets.back() + size);
            if (cls < 0) {
                result.weightOffsets.push_back(pool.intern(weights, size));
                weights += size;
                continue;
            }
            std::vector<int>& offsets = pooled[std::size_t(CompositionMemo::serialOf(cls))];
            const std::size_t local = std::size_t(CompositionMemo::localOf(cls));
            if (offsets.size() <= local) offsets.resize(local + 1, -1);
            if (offsets[local] < 0) offsets[local] = pool.intern(memos[std::size_t(CompositionMemo::serialOf(cls))]->floatWeights(cls), size);
            result.weightOffsets.push_back(offsets[local]);
        }
        result.indices.insert(result.indices.end(), part.indices.begin(), part.indices.end());
    });
    result.weights = pool.take();
    return result;
}

}  // namespace

StencilTableD composeStencils(const StencilTableD& outer, const StencilTableD& inner, std::size_t maxBytes) {
    return composeDouble(DoubleOuter{outer}, inner, maxBytes);
}

StencilTableD composeStencils(const StencilTable& outer, const StencilTableD& inner, std::size_t maxBytes) {
    return composeDouble(FloatOuter{outer}, inner, maxBytes);
}

StencilTable composeStencilsToFloat(const StencilTableD& outer, const StencilTableD& inner, std::size_t maxBytes) {
    return composeFloat(DoubleOuter{outer}, inner, maxBytes);
}

StencilTable composeStencilsToFloat(const StencilTable& outer, const StencilTableD& inner, std::size_t maxBytes) {
    return composeFloat(FloatOuter{outer}, inner, maxBytes);
}

}  // namespace v0
}  // namespace quadtri
