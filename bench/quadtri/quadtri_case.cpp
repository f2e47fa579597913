#include "bench/quadtri/quadtri_case.h"

#include <tbb/global_control.h>

#include <cstring>
#include <sstream>
#include <stdexcept>

#include "bench/compare.h"
#include "bench/measure/peak_memory.h"
#include "bench/measure/timing.h"
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>

namespace quadtri::bench {

namespace {

// Source vertices a table reads at least once.
std::size_t distinctSources(const StencilTable& table) {
    std::vector<char> seen(table.numSourceVertices, 0);
    std::size_t count = 0;
    for (int index : table.indices)
        if (!seen[index]) {
            seen[index] = 1;
            ++count;
        }
    return count;
}

std::vector<float> padded(const std::vector<float>& xyz) {
    std::vector<float> out(xyz.size() / 3 * 4, 0.0f);
    for (std::size_t v = 0; v < xyz.size() / 3; ++v) std::memcpy(&out[4 * v], &xyz[3 * v], 3 * sizeof(float));
    return out;
}

std::size_t bytesOf(const std::vector<std::vector<float>>& levels) {
    std::size_t bytes = 0;
    for (const std::vector<float>& level : levels) bytes += level.size() * sizeof(float);
    return bytes;
}

}  // namespace

QuadtriCase::QuadtriCase(const ControlMesh& mesh, Scheme scheme, int level, bool factorized)
    : mesh_(mesh), level_(level), factorized_(factorized) {
    options_.scheme = scheme;
    // The big cage's level 2 (16 million vertices) needs about 5 GB, past the library's default
    // budget of 4 GiB; the bench's machine is given more.
    options_.memoryBudgetBytes = std::size_t(16) << 30;
}

QuadtriCase::~QuadtriCase() = default;

std::unique_ptr<Refiner> QuadtriCase::build(LevelTables tables) const {
    auto refiner = std::make_unique<Refiner>(mesh_.descriptor(), options_);
    refiner->refineUniform(level_, TopologyDetail::FacesOnly, tables);
    return refiner;
}

QuadtriCase::FactorizedBuild QuadtriCase::buildFactorized() const {
    FactorizedBuild b{build(LevelTables::None), {}};
    b.table = b.refiner->factorizedStencils(level_);
    return b;
}

template <class Evaluator>
void QuadtriCase::eval(std::vector<std::vector<float>>& levels, int width, bool throughTables) {
    const BufferDescriptor desc(0, width, width);
    for (int L = 1; L <= level_; ++L)
        if (throughTables)
            Evaluator::EvalStencils(levels[L - 1].data(), desc, levels[L].data(), desc, refiner_->levelStencils(L));
        else
            Evaluator::EvalStencilRuns(levels[L - 1].data(), desc, levels[L].data(), desc, runs_[L - 1]);
}

void QuadtriCase::prepare() {
    const PeakMemory peak;
    refiner_ = build();
    serial_.assign(level_ + 1, {});
    serial_[0] = mesh_.positions;
    for (int L = 1; L <= level_; ++L) serial_[L].assign(3 * size_t(refiner_->levelStencils(L).numStencils()), 0.0f);
    eval<CpuEvaluator>(serial_, 3, true);
    // The case's memory: the tables and one set of 3-float level buffers, as an application
    // holds them; the bench's other buffers come after.
    memory_.tableBytes = 0;
    for (int L = 1; L <= level_; ++L) memory_.tableBytes += refiner_->levelStencils(L).bytes();
    memory_.bufferBytes = bytesOf(serial_);
    memory_.peakResidentBytes = peak.peakAboveStart();

    // Also the factorized build's warm-up.
    try {
        if (factorized_) buildFactorized();
        factorizedFits_ = factorized_;
    } catch (const MemoryBudgetError&) {
        factorizedFits_ = false;
    }

    runs_.clear();
    for (int L = 1; L <= level_; ++L) runs_.emplace_back(refiner_->levelStencils(L));
    std::vector<std::vector<float>> serialRuns = serial_;
    eval<CpuEvaluator>(serialRuns, 3);
    threaded_ = serial_;
    for (int L = 1; L <= level_; ++L) std::fill(threaded_[L].begin(), threaded_[L].end(), 0.0f);
    padded_.clear();
    for (const std::vector<float>& level : threaded_) padded_.push_back(padded(level));
    std::vector<std::vector<float>> paddedThreaded = padded_;
    eval<TbbEvaluator>(threaded_, 3);
    eval<CpuEvaluator>(padded_, 4);
    eval<TbbEvaluator>(paddedThreaded, 4);
    // The same arithmetic in the same order: every way gives the same floats.
    const std::vector<float>& last = serial_.back();
    const std::string where = mesh_.name + " level " + std::to_string(level_) + ": ";
    if (std::memcmp(serialRuns.back().data(), last.data(), last.size() * sizeof(float)))
        throw std::runtime_error(where + "the evaluation through StencilRuns differs from the tables'");
    if (std::memcmp(threaded_.back().data(), last.data(), last.size() * sizeof(float)))
        throw std::runtime_error(where + "TbbEvaluator differs from CpuEvaluator");
    if (padded_.back() != paddedThreaded.back() || padded_.back() != padded(last))
        throw std::runtime_error(where + "the evaluation of 4-float positions differs from the 3-float one");
}

QuadtriFigures QuadtriCase::measure(int reps) {
    QuadtriFigures f;
    auto timeBuilds = [&] {
        std::vector<double> builds;
        for (int r = 0; r < reps; ++r) {
            Stopwatch watch;
            std::unique_ptr<Refiner> refiner = build();
            builds.push_back(watch.elapsedMs());
        }  // each refiner is destroyed outside its timed span
        return summarize(builds);
    };
    auto timeFactorizedBuilds = [&]() -> std::optional<Timing> {
        if (!factorizedFits_) return std::nullopt;
        std::vector<double> builds;
        for (int r = 0; r < reps; ++r) {
            Stopwatch watch;
            const FactorizedBuild b = buildFactorized();
            builds.push_back(watch.elapsedMs());
        }  // as above
        return summarize(builds);
    };
    {
        const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
        f.build1Ms = timeBuilds();
        f.buildFactorized1Ms = timeFactorizedBuilds();
    }
    f.buildMs = timeBuilds();
    f.buildFactorizedMs = timeFactorizedBuilds();

    for (int L = 1; L <= level_; ++L) {
        const StencilTable& t = refiner_->levelStencils(L);
        f.tableBytes += t.bytes();
        const double vertices = double(distinctSources(t)) + double(t.numStencils());
        f.compulsoryBytes += double(t.bytes()) + 12.0 * vertices;
        f.compulsoryBytes4 += double(t.bytes()) + 16.0 * vertices;
    }
    f.evalSerialMs = timeMs(reps, [this] { eval<CpuEvaluator>(serial_, 3); });
    f.evalThreadedMs = timeMs(reps, [this] { eval<TbbEvaluator>(threaded_, 3); });
    f.evalSerial4Ms = timeMs(reps, [this] { eval<CpuEvaluator>(padded_, 4); });
    f.evalThreaded4Ms = timeMs(reps, [this] { eval<TbbEvaluator>(padded_, 4); });
    f.memory = memory_;
    return f;
}

}  // namespace quadtri::bench
