// The real-time loop's frame: pose the cage with the two-bone skin at a time, hand it to an
// evaluator, evaluate level N's limit positions and normals; each phase timed. The demo
// (`quadtri demo`) and the viewer run the same frame (docs/realtime_loop.md).
#pragma once

#include <vector>

#include "tools/realtime/frame_evaluator.h"
#include "tools/realtime/two_bone_skin.h"

namespace quadtri::realtime {

class DeformingSurface {
public:
    explicit DeformingSurface(TwoBoneSkin skin) : skin_(std::move(skin)), cage_(skin_.rest().size()) {}

    // One frame at `radians` of bend (bendAngle(t) for the demo's motion) through `evaluator`,
    // whose tables must be of this cage. The posed cage stays in cage() until the next frame.
    PhaseTimes frame(FrameEvaluator& evaluator, float radians);

    const TwoBoneSkin& skin() const { return skin_; }
    const std::vector<float>& cage() const { return cage_; }

private:
    TwoBoneSkin skin_;
    std::vector<float> cage_;
};

}  // namespace quadtri::realtime
