// Composed stencils that repeat. Past the first levels nearly every composed stencil is one of a
// few hundred shapes: an outer stencil with a pooled mask over inner stencils that are themselves
// of a known class. Such a stencil's weights are a function of the outer mask, the inner
// stencils' weights and which of the inner entries name the same source (they collapse into one
// output entry): the memo keeps, per class, that collapse pattern and the weights it gave, and a
// later stencil with the same key and the same pattern takes them as they are. Its output sources
// come from its own inner stencils through the pattern, so a hit is bitwise what the scatter row
// would compute: the same terms, added in the same order (far/compose_stencils.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "far/internal/same_sources.h"

namespace quadtri {
inline namespace v0 {

class CompositionMemo {
public:
    static constexpr int kNoClass = -1;
    // Class ids are serial << kLocalBits | local: every memo of one composition numbers its own.
    static constexpr int kLocalBits = 20, kMaxSerial = (1 << (31 - kLocalBits)) - 1;

    CompositionMemo(int serial, int numSources) : serial_(serial), stamp_(std::size_t(numSources), 0u), heads_(1024, -1) {}

    // Whether to look stencils up at all: not once most lookups miss (shapes that hardly repeat,
    // where the checks and the records would only add to the scatter row's work).
    bool usable() const {
        return serial_ <= kMaxSerial && (lookups_ < kTrialLookups || 4 * hits_ >= 3 * lookups_);
    }

    // The stencil about to be composed: its outer mask, then per outer entry its inner
    // stencil's class and sources.
    void begin(int mask) {
        mask_ = mask;
        classes_.clear();
        products_ = 0;
    }
    void addInner(int cls, const int* sources, int n) {
        classes_.push_back(cls);
        if (productSources_.size() < std::size_t(products_ + n)) grow(products_ + n);
        std::memcpy(productSources_.data() + products_, sources, sizeof(int) * std::size_t(n));
        products_ += n;
    }

    // The class of a stencil with the current key whose sources collapse as one already seen
    // (its output sources then in sources()), or kNoClass.
    int find() {
        n_ = int(classes_.size());
        std::uint64_t h = std::uint64_t(std::uint32_t(mask_)) * 0x9E3779B97F4A7C15ull ^ std::uint64_t(n_);
        for (int c : classes_) h = (h ^ std::uint32_t(c)) * 0x100000001B3ull;
        hash_ = std::uint32_t(h ^ (h >> 32));
        ++lookups_;
        patternsTried_ = 0;
        for (int e = heads_[hash_ & (heads_.size() - 1)]; e >= 0; e = entries_[std::size_t(e)].next) {
            const Entry& entry = entries_[std::size_t(e)];
            if (entry.hash == hash_ && entry.mask == mask_ && entry.n == n_ && products_ == entry.products &&
                std::memcmp(keys_.data() + entry.keyAt, classes_.data(), sizeof(int) * std::size_t(n_)) == 0) {
                if (collapsesAs(entry)) {
                    ++hits_;
                    return classOf(e);
                }
                if (++patternsTried_ == kMaxPatterns) return kNoClass;
            }
        }
        return kNoClass;
    }

    // After find() missed: records the stencil just composed (`size` entries, `weights`; entryOf(source) its entry
    // for each source) as a new class of the current key; kNoClass once the memo is full.
    template <class EntryOf>
    int add(int size, const double* weights, EntryOf entryOf) {
        const int local = int(entries_.size());
        if (local >= (1 << kLocalBits) || pattern_.size() + std::size_t(products_) > kMaxProducts ||
            patternsTried_ == kMaxPatterns)
            return kNoClass;
        Entry entry{hash_, mask_, n_, int(keys_.size()), int(pattern_.size()), products_,
                    int(first_.size()), size, int(weights_.size()), -1};
        keys_.insert(keys_.end(), classes_.begin(), classes_.end());
        first_.resize(first_.size() + std::size_t(size), -1);
        int* first = first_.data() + entry.firstAt;
        for (int p = 0; p < products_; ++p) {
            const int at = entryOf(productSources_[std::size_t(p)]);
            pattern_.push_back(at);
            if (first[at] < 0) first[at] = p;
        }
        weights_.insert(weights_.end(), weights, weights + size);
        floats_.insert(floats_.end(), weights, weights + size);
        const std::size_t bucket = hash_ & (heads_.size() - 1);
        entry.next = heads_[bucket];
        heads_[bucket] = local;
        entries_.push_back(entry);
        if (entries_.size() > heads_.size() / 2) rehash();
        return classOf(local);
    }

    // After a hit: the stencil's sources; and any class's size and weights.
    const int* sources() const { return sources_.data(); }
    int size(int cls) const { return entries_[std::size_t(localOf(cls))].size; }
    const double* weights(int cls) const { return weights_.data() + entries_[std::size_t(localOf(cls))].weightsAt; }
    const float* floatWeights(int cls) const { return floats_.data() + entries_[std::size_t(localOf(cls))].weightsAt; }
    int serial() const { return serial_; }
    static int serialOf(int cls) { return cls >> kLocalBits; }
    static int localOf(int cls) { return cls & ((1 << kLocalBits) - 1); }

private:
    // Products recorded over all classes: bounds the memo's memory (4 bytes a product).
    static constexpr std::size_t kMaxProducts = std::size_t(1) << 23;
    // Patterns kept per key (a key with more is composed by the row past them), and lookups
    // before the hit rate decides whether the memo stays on.
    static constexpr int kMaxPatterns = 4, kTrialLookups = 256;

    struct Entry {
        std::uint32_t hash;
        int mask, n, keyAt, patternAt, products, firstAt, size, weightsAt, next;
    };

    int classOf(int local) const { return serial_ << kLocalBits | local; }

    // Whether the current products collapse as the entry's: each product's source is that of
    // its output entry's first product, and the output entries' sources are distinct. (The
    // inner stencils' sizes are the entry's: their classes are.)
    bool collapsesAs(const Entry& entry) {
        if (sources_.size() < std::size_t(entry.size)) grow(entry.size);
        int* sources = sources_.data();
        if (!sameSources(productSources_.data(), products_, first_.data() + entry.firstAt, entry.size,
                         pattern_.data() + entry.patternAt, sources))
            return false;
        if (++generation_ == 0) {
            std::fill(stamp_.begin(), stamp_.end(), 0u);
            generation_ = 1;
        }
        for (int s = 0; s < entry.size; ++s) {
            if (stamp_[std::size_t(sources[s])] == generation_) return false;
            stamp_[std::size_t(sources[s])] = generation_;
        }
        return true;
    }

    // Room for n products and n output entries (a stencil has no more entries than products).
    void grow(int n) {
        const std::size_t to = 2 * std::size_t(n);
        if (productSources_.size() < to) productSources_.resize(to);
        if (sources_.size() < to) sources_.resize(to);
    }

    void rehash() {
        heads_.assign(heads_.size() * 2, -1);
        for (int e = 0; e < int(entries_.size()); ++e) {
            const std::size_t bucket = entries_[std::size_t(e)].hash & (heads_.size() - 1);
            entries_[std::size_t(e)].next = heads_[bucket];
            heads_[bucket] = e;
        }
    }

    int serial_;
    std::vector<std::uint32_t> stamp_;  // per source: the generation of the check that last saw it
    std::uint32_t generation_ = 0;
    std::vector<int> heads_;  // per bucket: the last entry of its chain, -1 when empty
    std::vector<Entry> entries_;
    // Per entry: its inner classes, the output entry of each product, and the first product of
    // each output entry.
    std::vector<int> keys_, pattern_, first_;
    std::vector<double> weights_;
    std::vector<float> floats_;
    // The stencil being looked up.
    int mask_ = 0, n_ = 0, products_ = 0, patternsTried_ = 0;
    long lookups_ = 0, hits_ = 0;
    std::uint32_t hash_ = 0;
    std::vector<int> classes_, productSources_, sources_;  // sources_: the output entries' sources
};

}  // namespace v0
}  // namespace quadtri
