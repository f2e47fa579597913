#include "tools/realtime/deforming_surface.h"

#include <chrono>

namespace quadtri::realtime {

PhaseTimes DeformingSurface::frame(FrameEvaluator& evaluator, float radians) {
    using Clock = std::chrono::steady_clock;
    PhaseTimes times;
    const Clock::time_point start = Clock::now();
    skin_.pose(radians, cage_.data());
    evaluator.setCage(cage_.data());
    times.deformMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    evaluator.evaluate(times);
    return times;
}

}  // namespace quadtri::realtime
