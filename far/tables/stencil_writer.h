// Writes the masks of one level into a stencil table, one mask at a time or one finished part
// (the stencils of the children that follow) at a time. Used by buildLevelStencils (rules.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>


#include "far/internal/sparse_accumulator.h"
#include <quadtri/far/stencil_table.h>
#include "far/tables/weight_pool.h"
#include "far/internal/stencil_table_double.h"
#include "far/internal/parallel.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// Appends each accumulated mask to the table being built. The float table interns the mask's
// weights in the level's pool, so identical masks share one copy; the double table (analysis
// and composition) stores them per entry.
template <typename Table>
class StencilWriter;

template <>
class StencilWriter<StencilTableD> {
public:
    StencilWriter(StencilTableD& table, int numStencils, std::size_t maxEntries) : table_(table) {
        table_.sizes.reserve(numStencils);
        table_.offsets.reserve(numStencils);
        table_.indices.reserve(maxEntries);
        table_.weights.reserve(maxEntries);
    }
    void append(SparseAccumulator& acc) {
        table_.offsets.push_back(int(table_.indices.size()));
        table_.sizes.push_back(acc.flush(table_.indices, table_.weights));
    }
    void appendEmpty() {
        table_.offsets.push_back(int(table_.indices.size()));
        table_.sizes.push_back(0);
    }
    // Appends the stencils of tables built for the children that follow, in order.
    void append(const std::vector<StencilTableD>& parts) {
        for (const StencilTableD& part : parts) append(part);
    }
    void append(const StencilTableD& part) {
        const int base = int(table_.indices.size());
        for (int offset : part.offsets) table_.offsets.push_back(base + offset);
        table_.sizes.insert(table_.sizes.end(), part.sizes.begin(), part.sizes.end());
        table_.indices.insert(table_.indices.end(), part.indices.begin(), part.indices.end());
        table_.weights.insert(table_.weights.end(), part.weights.begin(), part.weights.end());
    }
    void finish() {}

private:
    StencilTableD& table_;
};

template <>
class StencilWriter<StencilTable> {
public:
    // Offsets and weight offsets are sized up front and written by position; indices grow in
    // blocks through a cursor. vector::push_back and resize are not inlined here, and a call
    // per stencil was a fifth of the build.
    StencilWriter(StencilTable& table, int numStencils, std::size_t maxEntries) : table_(table) {
        table_.offsets.assign(std::size_t(numStencils) + 1, 0);
        table_.weightOffsets.assign(numStencils, 0);
        table_.indices.reserve(maxEntries);
    }
    void append(SparseAccumulator& acc) {
        const int n = acc.size();
        if (int(maskWeights_.size()) < n) maskWeights_.resize(n);
        acc.flushTo(extendIndices(n), maskWeights_.data());
        // Neighbouring children are mostly of one kind and regular: most masks repeat the one
        // before, which a bitwise comparison confirms without hashing.
        if (!sameAsPrevious(n)) {
            previousOffset_ = pool_.intern(maskWeights_.data(), n);
            previousSize_ = n;
        }
        table_.weightOffsets[stencils_] = previousOffset_;
        table_.offsets[++stencils_] = int(entries_);
    }
    // A stencil of no entries (a child whose mask is not wanted).
    void appendEmpty() {
        if (emptyOffset_ < 0) emptyOffset_ = pool_.intern(maskWeights_.data(), 0);
        table_.weightOffsets[stencils_] = emptyOffset_;
        table_.offsets[++stencils_] = int(entries_);
    }
    // Room for n indices after the last stencil, for the next stencil to be gathered in place
    // (RegularMasks): no copy per stencil. What is written there counts only once appended.
    int* nextIndices(int n) {
        if (entries_ + n > table_.indices.size())
            table_.indices.resize(std::max(table_.indices.size() + kIndexBlock, entries_ + n));
        return table_.indices.data() + entries_;
    }
    // Appends the stencil of the n indices written at nextIndices(), whose weights are already in
    // the pool.
    void appendGathered(int n, int weightOffset) {
        entries_ += n;
        table_.weightOffsets[stencils_] = weightOffset;
        table_.offsets[++stencils_] = int(entries_);
    }
    // Whether the last stencil appended has exactly these indices, and where its weights are.
    bool lastHasIndices(const int* indices, int n) const {
        const int first = table_.offsets[stencils_ - 1];
        return int(entries_) - first == n && std::equal(indices, indices + n, table_.indices.data() + first);
    }
    int lastWeightOffset() const { return table_.weightOffsets[stencils_ - 1]; }
    // Appends the stencils of finished tables built for the children that follow, in order,
    // interning each pool's sequences in first-use order: the result equals a serial build's
    // exactly. Only the interning is serial (a handful of sequences on a smooth level); the
    // offsets, weight offsets and indices are copied in parallel.
    void append(const std::vector<StencilTable>& parts) {
        struct Placed {
            std::vector<int> remap;  // the part's pool offsets -> this pool's
            std::size_t entry;       // where its entries start in the table
            int stencil;             // where its stencils start
        };
        std::vector<Placed> placed(parts.size());
        std::size_t entries = entries_;
        int stencils = stencils_;
        for (std::size_t k = 0; k < parts.size(); ++k) {
            const StencilTable& part = parts[k];
            Placed& p = placed[k];
            p.remap.assign(part.weights.size() + 1, -1);  // + 1: an empty sequence may sit at the end
            for (int i = 0; i < part.numStencils(); ++i) {
                int& global = p.remap[part.weightOffsets[i]];
                if (global < 0) global = pool_.intern(part.weightsOf(i), part.size(i));
            }
            p.entry = entries;
            p.stencil = stencils;
            entries += part.indices.size();
            stencils += part.numStencils();
        }
        extendIndices(entries - entries_);
        stencils_ = stencils;
        for (std::size_t k = 0; k < parts.size(); ++k) {
            const StencilTable& part = parts[k];
            const Placed& p = placed[k];
            parallel::forEachRange(0, part.numStencils(), kCopyGrain, [&](int begin, int end) {
                for (int i = begin; i != end; ++i) {
                    table_.weightOffsets[p.stencil + i] = p.remap[part.weightOffsets[i]];
                    table_.offsets[p.stencil + i + 1] = int(p.entry) + part.offsets[i + 1];
                }
                const int* first = part.indices.data() + part.offsets[begin];
                const int* last = part.indices.data() + part.offsets[end];
                std::copy(first, last, table_.indices.data() + p.entry + part.offsets[begin]);
            });
        }
    }
    void finish() {
        // Offsets were sized for the stencils announced: fewer written would leave a wrong table.
        if (stencils_ != table_.numStencils())
            throw std::logic_error("StencilWriter: " + std::to_string(stencils_) + " stencils written, " +
                                   std::to_string(table_.numStencils()) + " announced");
        table_.indices.resize(entries_);
        table_.weights = pool_.take();
    }

private:
    static constexpr std::size_t kIndexBlock = 16384;
    static constexpr int kCopyGrain = 16384;  // stencils per task of a part's copy

    int* extendIndices(std::size_t n) {
        int* out = nextIndices(int(n));
        entries_ += n;
        return out;
    }

    StencilTable& table_;
    int stencils_ = 0;         // stencils written
    std::size_t entries_ = 0;  // indices written (table_.indices runs ahead by up to a block)
    WeightPool pool_;
    std::vector<float> maskWeights_;  // the current mask's weights before interning
    int previousOffset_ = -1;         // where the last mask's weights sit in the pool
    int previousSize_ = 0;
    int emptyOffset_ = -1;  // the empty sequence's place in the pool, once interned

    bool sameAsPrevious(int n) const {
        if (previousOffset_ < 0 || n != previousSize_) return false;
        const float* previous = pool_.values().data() + previousOffset_;
        for (int k = 0; k < n; ++k)
            if (bitsOf(maskWeights_[k]) != bitsOf(previous[k])) return false;
        return true;
    }
    static std::uint32_t bitsOf(float w) {
        std::uint32_t bits;
        std::memcpy(&bits, &w, sizeof bits);
        return bits;
    }
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
