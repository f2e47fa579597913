#include "bench/quadtri/limit_case.h"

#include <cstring>
#include <sstream>
#include <stdexcept>

#include "bench/compare.h"
#include "bench/measure/peak_memory.h"
#include "bench/measure/timing.h"
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#ifdef QUADTRI_BENCH_VULKAN
#include <quadtri/osd/vulkan_limit_evaluator.h>
#endif

namespace quadtri::bench {

namespace {

const BufferDescriptor kXyz(0, 3, 3);

template <class Evaluator>
void evalLimit(const float* src, const LimitStencilTable& t, std::vector<float>& position, std::vector<float>& normal) {
    Evaluator::EvalLimitStencils(src, kXyz, position.data(), kXyz, nullptr, kXyz, nullptr, kXyz, normal.data(), kXyz, t);
}

void expectClose(const std::vector<float>& a, const std::vector<float>& b, double tolerance, const std::string& what) {
    const double d = maxAbsDifference(a, b);
    if (d > tolerance) {
        std::ostringstream m;
        m << what << " differ by " << d << " (tolerance " << tolerance << ")";
        throw std::runtime_error(m.str());
    }
}

}  // namespace

LimitCase::LimitCase(const ControlMesh& mesh, Scheme scheme, int level) : mesh_(mesh), level_(level) {
    options_.scheme = scheme;
}

LimitCase::~LimitCase() = default;

void LimitCase::limitFactorized(bool threaded, std::vector<float>& position, std::vector<float>& normal) {
    if (threaded) evalLimit<TbbEvaluator>(mesh_.positions.data(), limit_, position, normal);
    else evalLimit<CpuEvaluator>(mesh_.positions.data(), limit_, position, normal);
}

void LimitCase::levelsThenLimit(bool threaded, std::vector<float>& position, std::vector<float>& normal) {
    for (int L = 1; L <= level_; ++L) {
        if (threaded) TbbEvaluator::EvalStencils(levels_[L - 1].data(), kXyz, levels_[L].data(), kXyz, refiner_->levelStencils(L));
        else CpuEvaluator::EvalStencils(levels_[L - 1].data(), kXyz, levels_[L].data(), kXyz, refiner_->levelStencils(L));
    }
    if (threaded) evalLimit<TbbEvaluator>(levels_[level_].data(), limitOverLevel_, position, normal);
    else evalLimit<CpuEvaluator>(levels_[level_].data(), limitOverLevel_, position, normal);
}

void LimitCase::meshNormals(bool threaded, std::vector<float>& normal) {
    if (threaded) TbbEvaluator::EvalMeshNormals(levels_[level_].data(), kXyz, normal.data(), kXyz, meshTable_);
    else CpuEvaluator::EvalMeshNormals(levels_[level_].data(), kXyz, normal.data(), kXyz, meshTable_);
}

void LimitCase::prepare() {
    const PeakMemory peak;
    refiner_ = std::make_unique<Refiner>(mesh_.descriptor(), options_);
    refiner_->refineUniform(level_);
    limitOverLevel_ = refiner_->limitStencils(level_);
    try {
        limit_ = refiner_->factorizedLimitStencils(level_);
    } catch (const MemoryBudgetError& e) {  // dense near the seams: the chain alone is timed
        factorizedRefused_ = e.what();
    }
    meshTable_ = buildMeshNormalTable(refiner_->faces(level_));
    levels_.assign(std::size_t(level_) + 1, {});
    levels_[0] = mesh_.positions;
    for (int L = 1; L <= level_; ++L) levels_[L].assign(3 * std::size_t(refiner_->levelStencils(L).numStencils()), 0.0f);

    const std::size_t n = 3 * std::size_t(limitOverLevel_.numStencils());
    position_.assign(n, 0.0f);
    normal_ = position_;
    memory_.tableBytes = limitOverLevel_.bytes() + limit_.bytes() + meshTable_.bytes();
    for (int L = 1; L <= level_; ++L) memory_.tableBytes += refiner_->levelStencils(L).bytes();
    memory_.bufferBytes = 2 * n * sizeof(float);
    for (const std::vector<float>& level : levels_) memory_.bufferBytes += level.size() * sizeof(float);
    memory_.peakResidentBytes = peak.peakAboveStart();
    std::vector<float> p(n), q(n);
    if (!factorizedRefused_.empty()) {
        levelsThenLimit(false, position_, normal_);
        levelsThenLimit(true, p, q);
        if (std::memcmp(p.data(), position_.data(), n * sizeof(float)) ||
            std::memcmp(q.data(), normal_.data(), n * sizeof(float)))
            throw std::runtime_error(mesh_.name + ": TbbEvaluator's chained limit differs from CpuEvaluator's");
        return;
    }
    limitFactorized(false, position_, normal_);
    limitFactorized(true, p, q);
    if (std::memcmp(p.data(), position_.data(), n * sizeof(float)) || std::memcmp(q.data(), normal_.data(), n * sizeof(float)))
        throw std::runtime_error(mesh_.name + ": TbbEvaluator's limit differs from CpuEvaluator's");
    levelsThenLimit(false, p, q);
    const std::string where = mesh_.name + " level " + std::to_string(level_);
    expectClose(p, position_, 1e-5 * mesh_.boundingBoxDiagonal(), where + ": chained and factorized limit positions");
    // Tangents shrink with the level's edges while the positions they are gathered from do not:
    // at level 4 float rounding moves the chained normals by ~1e-4.
    expectClose(q, normal_, 1e-3, where + ": chained and factorized limit normals");
}

LimitFigures LimitCase::measure(int reps, [[maybe_unused]] VulkanContext* vulkan) {
    LimitFigures f;
    f.memory = memory_;
    f.chainTableBytes = limitOverLevel_.bytes();
    for (int L = 1; L <= level_; ++L) f.chainTableBytes += refiner_->levelStencils(L).bytes();
    std::vector<float> p(position_.size()), q(position_.size());
    const bool factorized = factorizedRefused_.empty();
    if (factorized) {
        f.tableBytes = limit_.bytes();
        f.limitSerialMs = timeMs(reps, [&] { limitFactorized(false, p, q); });
        f.limitThreadedMs = timeMs(reps, [&] { limitFactorized(true, p, q); });
    }
    f.levelsThenLimitSerialMs = timeMs(reps, [&] { levelsThenLimit(false, p, q); });
    f.levelsThenLimitThreadedMs = timeMs(reps, [&] { levelsThenLimit(true, p, q); });
    f.meshNormalsSerialMs = timeMs(reps, [&] { meshNormals(false, q); });
    f.meshNormalsThreadedMs = timeMs(reps, [&] { meshNormals(true, q); });
#ifdef QUADTRI_BENCH_VULKAN
    if (vulkan && factorized) {
        const int n = limit_.numStencils();
        const VulkanLimitStencilTable table(*vulkan, limit_);
        VulkanVertexBuffer src = VulkanVertexBuffer::create(*vulkan, mesh_.numVertices, 3);
        src.updateData(mesh_.positions.data(), 0, mesh_.numVertices);
        const VulkanVertexBuffer position = VulkanVertexBuffer::create(*vulkan, n, 3);
        const VulkanVertexBuffer normal = VulkanVertexBuffer::create(*vulkan, n, 3);
        VulkanLimitEvaluator eval(*vulkan);
        auto run = [&] {
            eval.EvalLimitStencilsAndWait(src, kXyz, &position, kXyz, nullptr, kXyz, nullptr, kXyz, &normal, kXyz, table);
        };
        run();
        std::vector<float> gpu(position_.size());
        position.readBack(gpu.data());
        expectClose(gpu, position_, 1e-5 * mesh_.boundingBoxDiagonal(), mesh_.name + ": Vulkan limit positions");
        normal.readBack(gpu.data());
        expectClose(gpu, normal_, 1e-3, mesh_.name + ": Vulkan limit normals");
        f.limitVulkanMs = timeMs(reps, run);
    }
#endif
    return f;
}

}  // namespace quadtri::bench
