// The real-time loop on the host: CpuEvaluator (one thread) or TbbEvaluator (oneTBB's threads, in
// the caller's task arena), bitwise the same results.
#pragma once

#include <vector>

#include <quadtri/osd/stencil_runs.h>
#include "tools/realtime/frame_evaluator.h"
#include "tools/realtime/surface_tables.h"

namespace quadtri::realtime {

class HostFrameEvaluator : public FrameEvaluator {
public:
    // `tables` must outlive the evaluator.
    HostFrameEvaluator(const SurfaceTables& tables, bool threaded);

    std::string name() const override { return threaded_ ? "tbb" : "cpu"; }
    void setCage(const float* cage) override { cage_ = cage; }
    void evaluate(PhaseTimes& times) override;
    void readBack(std::vector<float>& positions, std::vector<float>& normals) override;

    // The outputs in place, 3 floats per level-N vertex (per point of the patch table, in its
    // order, under TableRoute::Patches; readBack gives level order).
    const std::vector<float>& positions() const { return positions_; }
    const std::vector<float>& normals() const { return normals_; }

private:
    const SurfaceTables& tables_;
    bool threaded_;
    const float* cage_ = nullptr;
    std::vector<StencilRuns> runs_;           // of tables_.levels, what the frame loop evaluates
    std::vector<std::vector<float>> levels_;  // LevelsThenLimit: levels 1..N; Patches: 1..K
    std::vector<float> positions_, normals_;
};

}  // namespace quadtri::realtime
