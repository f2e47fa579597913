// One frame case on OpenSubdiv's side: its fastest way to the frame's output, level N's limit
// positions and unit normals (bench/opensubdiv/osd_limit_case.h: a Far::LimitStencilTable with du, dv at the
// level's vertices, then normalize(du x dv)), applied to the cage as posed every frame by the same
// realtime::DeformingSurface and two-bone skin as quadtri's side, and timed the same way
// (bench/quadtri/frame_case.h's timeFrames), on Osd::CpuEvaluator, Osd::OmpEvaluator (all threads) and
// Far's UpdateValues + UpdateDerivs.
#pragma once

#include <memory>
#include <vector>

#include "bench/frame_figures.h"
#include "bench/opensubdiv/osd_limit_case.h"
#include "tools/realtime/deforming_surface.h"

namespace quadtri::bench {

class OsdFrameCase {
public:
    // `mesh` as OsdLimitCase takes it; it must outlive the case.
    OsdFrameCase(const ControlMesh& mesh, OsdScheme scheme, int level);
    ~OsdFrameCase();

    // Builds and checks the limit table (OsdLimitCase::prepare), then runs one frame at `radians`
    // on each evaluator: OmpEvaluator and Far's templates must give CpuEvaluator's floats bitwise
    // (std::runtime_error if not).
    void prepare(float radians);

    // CpuEvaluator's limit positions and unit normals at prepare()'s angle.
    const std::vector<float>& positions() const { return positions_; }
    const std::vector<float>& normals() const { return normals_; }

    // Every evaluator, `frames` frames each.
    std::vector<FrameTiming> measure(int frames);

private:
    OsdLimitCase limit_;
    realtime::DeformingSurface surface_;
    std::vector<std::unique_ptr<realtime::FrameEvaluator>> evaluators_;
    std::vector<float> positions_, normals_;
};

}  // namespace quadtri::bench
