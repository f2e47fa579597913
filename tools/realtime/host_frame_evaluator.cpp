#include "tools/realtime/host_frame_evaluator.h"

#include <chrono>
#include <stdexcept>

#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>

namespace quadtri::realtime {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

HostFrameEvaluator::HostFrameEvaluator(const SurfaceTables& tables, bool threaded)
    : tables_(tables), threaded_(threaded), positions_(3 * std::size_t(tables.numPoints)),
      normals_(3 * std::size_t(tables.numPoints)) {
    for (const StencilTable& level : tables.levels) {
        runs_.emplace_back(level);
        levels_.emplace_back(3 * std::size_t(level.numStencils()));
    }
}

void HostFrameEvaluator::evaluate(PhaseTimes& times) {
    if (!cage_) throw std::logic_error("HostFrameEvaluator::evaluate: no cage set");
    const BufferDescriptor xyz(0, 3, 3);
    auto stencils = threaded_ ? TbbEvaluator::EvalStencilRuns : CpuEvaluator::EvalStencilRuns;
    auto limit = threaded_ ? TbbEvaluator::EvalLimitStencils : CpuEvaluator::EvalLimitStencils;

    Clock::time_point start = Clock::now();
    const float* source = cage_;
    for (std::size_t L = 0; L < levels_.size(); ++L) {
        stencils(source, xyz, levels_[L].data(), xyz, runs_[L], 0, -1);
        source = levels_[L].data();
    }
    if (tables_.patches) {
        auto patches = threaded_ ? TbbEvaluator::EvalLevelPatches : CpuEvaluator::EvalLevelPatches;
        times.evaluateMs = msSince(start);
        start = Clock::now();
        patches(source, xyz, positions_.data(), xyz, normals_.data(), xyz, *tables_.patches);
        times.normalsMs = msSince(start);
        return;
    }
    const bool onePass = tables_.route == TableRoute::FactorizedLimit;
    if (!onePass) {
        times.evaluateMs = msSince(start);
        start = Clock::now();
    }
    limit(source, xyz, positions_.data(), xyz, nullptr, xyz, nullptr, xyz, normals_.data(), xyz, tables_.limit,
          onePass ? nullptr : &tables_.fallback, 0, -1);
    (onePass ? times.evaluateMs : times.normalsMs) = msSince(start);
    if (onePass) times.normalsMs = 0;
}

void HostFrameEvaluator::readBack(std::vector<float>& positions, std::vector<float>& normals) {
    positions = positions_;
    normals = normals_;
    if (!tables_.patches) return;
    // The patch table's points, back in level order.
    for (int k = 0; k < tables_.numPoints; ++k) {
        const std::size_t v = std::size_t(tables_.patches->vertexOf(k));
        for (int c = 0; c < 3; ++c) {
            positions[3 * v + std::size_t(c)] = positions_[3 * std::size_t(k) + std::size_t(c)];
            normals[3 * v + std::size_t(c)] = normals_[3 * std::size_t(k) + std::size_t(c)];
        }
    }
}

}  // namespace quadtri::realtime
