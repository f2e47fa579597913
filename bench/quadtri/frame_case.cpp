#include "bench/quadtri/frame_case.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "bench/compare.h"
#include "tools/realtime/host_frame_evaluator.h"
#include <quadtri/far/refiner.h>
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#ifdef QUADTRI_BENCH_VULKAN
#include "tools/realtime/vulkan_frame_evaluator.h"
#endif

namespace quadtri::bench {

namespace {

// The second figure's frame: refined positions and mesh normals. The per-level tables of the
// chain to level N, then EvalMeshNormals of level N through the chain's MeshNormalTable, on
// CpuEvaluator or TbbEvaluator.
class MeshNormalFrameEvaluator : public realtime::FrameEvaluator {
public:
    MeshNormalFrameEvaluator(const realtime::SurfaceTables& chain, bool threaded)
        : chain_(chain), threaded_(threaded), normals_(3 * std::size_t(chain.numPoints)) {
        for (const StencilTable& level : chain.levels) levels_.emplace_back(3 * std::size_t(level.numStencils()));
    }

    std::string name() const override { return threaded_ ? "tbb" : "cpu"; }
    void setCage(const float* cage) override { cage_ = cage; }

    void evaluate(realtime::PhaseTimes& times) override {
        const BufferDescriptor xyz(0, 3, 3);
        Stopwatch levels;
        const float* source = cage_;
        for (std::size_t L = 0; L < levels_.size(); ++L) {
            if (threaded_) TbbEvaluator::EvalStencils(source, xyz, levels_[L].data(), xyz, chain_.levels[L]);
            else CpuEvaluator::EvalStencils(source, xyz, levels_[L].data(), xyz, chain_.levels[L]);
            source = levels_[L].data();
        }
        times.evaluateMs = levels.elapsedMs();
        Stopwatch normals;
        if (threaded_) TbbEvaluator::EvalMeshNormals(source, xyz, normals_.data(), xyz, chain_.fallback);
        else CpuEvaluator::EvalMeshNormals(source, xyz, normals_.data(), xyz, chain_.fallback);
        times.normalsMs = normals.elapsedMs();
    }

    void readBack(std::vector<float>& positions, std::vector<float>& normals) override {
        positions = levels_.back();
        normals = normals_;
    }

private:
    const realtime::SurfaceTables& chain_;
    bool threaded_;
    const float* cage_ = nullptr;
    std::vector<std::vector<float>> levels_;
    std::vector<float> normals_;
};

const char* routeName(realtime::TableRoute route) {
    switch (route) {
        case realtime::TableRoute::FactorizedLimit: return "factorized_limit";
        case realtime::TableRoute::LevelsThenLimit: return "levels_then_limit";
        case realtime::TableRoute::Patches: return "patches";
    }
    return "?";
}

double boxDiagonal(const std::vector<float>& xyz) {
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (std::size_t i = 0; i < xyz.size(); ++i) {
        lo[i % 3] = std::min(lo[i % 3], double(xyz[i]));
        hi[i % 3] = std::max(hi[i % 3], double(xyz[i]));
    }
    double d2 = 0;
    for (int c = 0; c < 3; ++c) d2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    return std::sqrt(d2);
}

}  // namespace

FrameTiming timeFrames(realtime::DeformingSurface& surface, realtime::FrameEvaluator& evaluator, const std::string& route,
                       int frames) {
    surface.frame(evaluator, 0.0f);
    std::vector<double> deform, evaluate, normals, frame;
    for (int k = 1; k <= frames; ++k) {
        // t from 1/frames s to 1 s: half the demo's 2 s period, up to the full bend.
        const realtime::PhaseTimes times = surface.frame(evaluator, realtime::bendAngle(double(k) / frames));
        deform.push_back(times.deformMs);
        evaluate.push_back(times.evaluateMs);
        normals.push_back(times.normalsMs);
        frame.push_back(times.frameMs());
    }
    return {evaluator.name(), route, summarize(deform), summarize(evaluate), summarize(normals), summarize(frame)};
}

FrameCase::FrameCase(std::string name, const TopologyDescriptor& descriptor, const Options& options,
                     std::vector<float> rest, int level, [[maybe_unused]] VulkanContext* vulkan)
    : name_(std::move(name)), level_(level), diagonal_(boxDiagonal(rest)),
      refiner_(std::make_unique<Refiner>(descriptor, options)), surface_(realtime::TwoBoneSkin(std::move(rest))) {
    refiner_->refineUniform(level);
    try {
        factorized_ = std::make_unique<realtime::SurfaceTables>(*refiner_, level, realtime::TableRoute::FactorizedLimit);
    } catch (const MemoryBudgetError&) {  // the chain alone, as fastestSurfaceTables falls back to
    }
    chain_ = std::make_unique<realtime::SurfaceTables>(*refiner_, level, realtime::TableRoute::LevelsThenLimit);
    if (level > 0) patches_ = std::make_unique<realtime::SurfaceTables>(*refiner_, level, realtime::TableRoute::Patches);
    for (const realtime::SurfaceTables* tables : {factorized_.get(), chain_.get(), patches_.get()}) {
        if (!tables) continue;
        for (bool threaded : {false, true})
            ways_.push_back({routeName(tables->route), std::make_unique<realtime::HostFrameEvaluator>(*tables, threaded)});
    }
#ifdef QUADTRI_BENCH_VULKAN
    if (vulkan) {
        const realtime::SurfaceTables& fastest = factorized_ ? *factorized_ : *chain_;
        ways_.push_back({routeName(fastest.route), std::make_unique<realtime::VulkanFrameEvaluator>(*vulkan, fastest)});
        if (patches_)
            ways_.push_back({routeName(patches_->route), std::make_unique<realtime::VulkanFrameEvaluator>(*vulkan, *patches_)});
    }
#endif
    for (bool threaded : {false, true})
        ways_.push_back({"levels_then_mesh_normals", std::make_unique<MeshNormalFrameEvaluator>(*chain_, threaded)});
}

FrameCase::~FrameCase() = default;

int FrameCase::numPoints() const { return chain_->numPoints; }

std::optional<std::size_t> FrameCase::limitTableBytes() const {
    if (!factorized_) return std::nullopt;
    return factorized_->limit.bytes();
}

std::size_t FrameCase::chainTableBytes() const {
    std::size_t bytes = chain_->limit.bytes();
    for (const StencilTable& level : chain_->levels) bytes += level.bytes();
    return bytes;
}

// Per point of level N at the posed cage: how much larger its longer limit tangent is than its
// shorter one (the chain's limit table). A normal's float rounding grows with it: where the
// skin pinches the surface (the bent torus's inner side, 2 800 at 1.2 rad), two ways' normals
// differ by 1e-3 however carefully each sums.
std::vector<double> FrameCase::tangentRatios() const {
    const BufferDescriptor xyz(0, 3, 3);
    std::vector<float> source = surface_.cage(), next;
    for (const StencilTable& level : chain_->levels) {
        next.assign(3 * std::size_t(level.numStencils()), 0.0f);
        CpuEvaluator::EvalStencils(source.data(), xyz, next.data(), xyz, level);
        source.swap(next);
    }
    const std::size_t n = std::size_t(chain_->numPoints);
    std::vector<float> p(3 * n), du(3 * n), dv(3 * n);
    CpuEvaluator::EvalLimitStencils(source.data(), xyz, p.data(), xyz, du.data(), xyz, dv.data(), xyz, nullptr, xyz,
                                    chain_->limit);
    std::vector<double> ratio(n);
    for (std::size_t v = 0; v < n; ++v) {
        double u2 = 0, v2 = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            u2 += double(du[3 * v + c]) * du[3 * v + c];
            v2 += double(dv[3 * v + c]) * dv[3 * v + c];
        }
        const double lo = std::sqrt(std::min(u2, v2)), hi = std::sqrt(std::max(u2, v2));
        ratio[v] = lo > 0 ? hi / lo : HUGE_VAL;
    }
    return ratio;
}

void FrameCase::prepare(float radians) {
    const std::string where = name_ + " level " + std::to_string(level_) + ": the frame ";
    const double tolerance = 1e-5 * diagonal_;
    // The chain's tangents are differences of level N's float positions over edges that halve
    // every level, so their rounding doubles per level: on the bent quad torus its normals lie
    // 5.9e-4, 1.4e-3 and 4.9e-3 from the factorized table's at levels 2-4, whose own agree with
    // OpenSubdiv's within 2e-4 rad (checked by the caller).
    const double chainNormals = std::ldexp(1e-3, std::max(1, level_ - 1));
    std::map<std::string, std::pair<std::vector<float>, std::vector<float>>> serial;  // CpuEvaluator's, per route
    std::vector<float> p, n;
    std::vector<double> ratio;
    for (Way& w : ways_) {
        surface_.frame(*w.evaluator, radians);
        if (ratio.empty()) ratio = tangentRatios();
        w.evaluator->readBack(p, n);
        const std::string evaluator = w.evaluator->name();
        const std::string what = where + w.route + " on " + evaluator;
        // Normals within normalTolerance, or, where the tangents' lengths differ by a large ratio,
        // within 64 float epsilons of it; 0: bitwise.
        auto differs = [&](const std::vector<float>& p0, const std::vector<float>& n0, double positionTolerance,
                           double normalTolerance, const std::string& than) {
            const double dp = maxAbsDifference(p, p0);
            double dn = n.size() == n0.size() ? 0.0 : HUGE_VAL, excess = dn;
            for (std::size_t i = 0; i < n.size() && i < n0.size(); ++i) {
                const double d = std::fabs(double(n[i]) - double(n0[i]));
                const double allowed = normalTolerance > 0 ? std::max(normalTolerance, 64 * 0x1p-23 * ratio[i / 3]) : 0.0;
                dn = std::max(dn, d);
                excess = std::max(excess, d - allowed);
            }
            if (dp <= positionTolerance && excess <= 0) return;
            std::ostringstream m;
            m << what << " differs from " << than << ": positions by " << dp << ", normals by " << dn;
            throw std::runtime_error(m.str());
        };
        if (evaluator == "cpu") {
            if (serial.empty()) {  // the first route: the reference
                positions_ = p;
                normals_ = n;
            } else if (w.route != "levels_then_mesh_normals") {
                differs(positions_, normals_, tolerance, chainNormals, "CpuEvaluator's on " + ways_[0].route);
            } else {
                for (std::size_t v = 0; v < n.size(); v += 3) {
                    const double length = std::sqrt(double(n[v]) * n[v] + double(n[v + 1]) * n[v + 1] +
                                                    double(n[v + 2]) * n[v + 2]);
                    if (!(std::fabs(length - 1.0) < 1e-5))
                        throw std::runtime_error(what + ": vertex " + std::to_string(v / 3) +
                                                 "'s mesh normal has length " + std::to_string(length));
                }
            }
            serial[w.route] = {p, n};
            continue;
        }
        const auto& [p0, n0] = serial.at(w.route);
        // TbbEvaluator runs CpuEvaluator's kernels over ranges of the same tables: bitwise.
        if (evaluator == "tbb") differs(p0, n0, 0.0, 0.0, "CpuEvaluator's");
        else differs(p0, n0, tolerance, 1e-3, "CpuEvaluator's");
    }
}

std::vector<FrameTiming> FrameCase::measure(int frames) {
    std::vector<FrameTiming> timings;
    for (Way& w : ways_) timings.push_back(timeFrames(surface_, *w.evaluator, w.route, frames));
    return timings;
}

}  // namespace quadtri::bench
