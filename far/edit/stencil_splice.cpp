#include "far/edit/stencil_splice.h"

#include <algorithm>
#include <cstring>

#include "far/tables/weight_pool.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

bool sameStencil(const StencilTable& a, int i, const StencilTable& b, int k) {
    const int n = a.size(i);
    if (n != b.size(k)) return false;
    const int* ai = a.indices.data() + a.offsets[i];
    const int* bi = b.indices.data() + b.offsets[k];
    return std::equal(ai, ai + n, bi) &&
           std::memcmp(a.weightsOf(i), b.weightsOf(k), sizeof(float) * std::size_t(n)) == 0;
}

}  // namespace

void compactWeights(StencilTable& table) {
    WeightPool pool;
    int previous = -1, previousSize = -1, placed = -1;
    for (int i = 0; i < table.numStencils(); ++i) {
        const int n = table.size(i);
        if (table.weightOffsets[i] != previous || n != previousSize) {
            previous = table.weightOffsets[i], previousSize = n;
            placed = pool.intern(table.weights.data() + previous, n);
        }
        table.weightOffsets[i] = placed;
    }
    table.weights = pool.take();
}

namespace {

bool sameLimitStencil(const LimitStencilTable& a, int i, const LimitStencilTable& b, int k) {
    const int n = a.size(i);
    return n == b.size(k) && std::equal(a.sourcesOf(i), a.sourcesOf(i) + n, b.sourcesOf(k)) &&
           std::memcmp(a.weightsOf(i), b.weightsOf(k), sizeof(float) * 3 * std::size_t(n)) == 0;
}

}  // namespace

void compactPools(LimitStencilTable& table) {
    IndexPool runs;
    WeightPool weights;
    for (int i = 0; i < table.numStencils(); ++i) {
        const int n = table.size(i);
        const int run = runs.intern(table.sourcesOf(i), n), triples = weights.intern(table.weightsOf(i), 3 * n);
        table.offsets[std::size_t(i)] = run;
        table.weightOffsets[std::size_t(i)] = triples;
    }
    table.indices = runs.take();
    table.weights = weights.take();
}

std::vector<int> spliceLimitStencils(LimitStencilTable& table, const std::vector<int>& rows,
                                     const LimitStencilTable& fresh, LimitPoolMarks& marks, bool* laidOut) {
    if (laidOut) *laidOut = false;
    if (marks.indices == 0 && marks.weights == 0) marks = {table.indices.size(), table.weights.size()};
    std::vector<int> changed;
    IndexPool runs;
    WeightPool weights;
    std::vector<int> run, triples;  // per changed row, its place in `runs` and `weights`
    for (std::size_t k = 0; k < rows.size(); ++k) {
        if (sameLimitStencil(table, rows[k], fresh, int(k))) continue;
        changed.push_back(rows[k]);
        const int n = fresh.size(int(k));
        run.push_back(runs.intern(fresh.sourcesOf(int(k)), n));
        triples.push_back(weights.intern(fresh.weightsOf(int(k)), 3 * n));
        table.sizes[std::size_t(rows[k])] = n;
    }
    const int indexBase = int(table.indices.size()), weightBase = int(table.weights.size());
    table.indices.insert(table.indices.end(), runs.values().begin(), runs.values().end());
    table.weights.insert(table.weights.end(), weights.values().begin(), weights.values().end());
    for (std::size_t j = 0; j < changed.size(); ++j) {
        table.offsets[std::size_t(changed[j])] = indexBase + run[j];
        table.weightOffsets[std::size_t(changed[j])] = weightBase + triples[j];
    }
    if (table.indices.size() > 2 * marks.indices + 4096 || table.weights.size() > 2 * marks.weights + 4096) {
        compactPools(table);
        marks = {table.indices.size(), table.weights.size()};
        if (laidOut) *laidOut = true;
    }
    return changed;
}

Splice spliceStencils(StencilTable& table, const std::vector<int>& rows, const StencilTable& fresh,
                      std::size_t& poolMark) {
    Splice out;
    std::vector<int> from;  // per changed row, its stencil in `fresh`
    for (std::size_t k = 0; k < rows.size(); ++k) {
        if (sameStencil(table, rows[k], fresh, int(k))) continue;
        out.changed.push_back(rows[k]);
        from.push_back(int(k));
        out.resized = out.resized || table.size(rows[k]) != fresh.size(int(k));
    }
    if (out.changed.empty()) return out;

    // New weights after the pool's end, each distinct sequence once.
    WeightPool added;
    std::vector<int> weightOffset(out.changed.size());
    const int base = int(table.weights.size());
    for (std::size_t j = 0; j < out.changed.size(); ++j)
        weightOffset[j] = base + added.intern(fresh.weightsOf(from[j]), fresh.size(from[j]));
    const std::vector<float>& values = added.values();
    table.weights.insert(table.weights.end(), values.begin(), values.end());
    for (std::size_t j = 0; j < out.changed.size(); ++j)
        table.weightOffsets[std::size_t(out.changed[j])] = weightOffset[j];

    if (!out.resized) {
        for (std::size_t j = 0; j < out.changed.size(); ++j) {
            const int k = from[j];
            std::copy_n(fresh.indices.data() + fresh.offsets[k], fresh.size(k),
                        table.indices.data() + table.offsets[out.changed[j]]);
        }
    } else {
        // The entries from the first changed row on, moved by what the changed rows grow or shrink.
        const int first = out.changed.front(), numStencils = table.numStencils();
        std::vector<int> tail(table.indices.begin() + table.offsets[first], table.indices.end());
        const int tailBase = table.offsets[first];
        std::vector<int> oldOffsets(table.offsets.begin() + first, table.offsets.end());
        auto oldOffset = [&](int i) { return oldOffsets[std::size_t(i - first)]; };
        table.indices.resize(std::size_t(tailBase));
        std::size_t j = 0;
        for (int i = first; i < numStencils;) {
            if (j < out.changed.size() && out.changed[j] == i) {
                const int k = from[j++];
                table.indices.insert(table.indices.end(), fresh.indices.begin() + fresh.offsets[k],
                                     fresh.indices.begin() + fresh.offsets[k + 1]);
                table.offsets[std::size_t(i) + 1] = int(table.indices.size());
                ++i;
                continue;
            }
            // The unchanged run up to the next changed row, copied at once.
            const int end = j < out.changed.size() ? out.changed[j] : numStencils;
            const int shift = int(table.indices.size()) - oldOffset(i);
            table.indices.insert(table.indices.end(), tail.begin() + (oldOffset(i) - tailBase),
                                 tail.begin() + (oldOffset(end) - tailBase));
            for (int r = i; r < end; ++r) table.offsets[std::size_t(r) + 1] = oldOffset(r + 1) + shift;
            i = end;
        }
    }
    if (table.weights.size() > 2 * poolMark + 4096) {
        compactWeights(table);
        poolMark = table.weights.size();
        out.poolLaidOut = true;
    }
    return out;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
