// One evaluator's side of a frame of the real-time loop: the deformed cage in, level N's limit
// positions and unit normals out, each phase timed (docs/realtime_loop.md, "A frame").
#pragma once

#include <string>
#include <vector>

namespace quadtri::realtime {

// Milliseconds per phase of one frame. With TableRoute::FactorizedLimit the positions and the
// normals come out of one pass, all counted as `evaluate`, and `normals` is 0; with
// LevelsThenLimit `evaluate` is the per-level tables and `normals` the limit pass over level N
// (which also moves the points onto the limit surface); with Patches `evaluate` is the per-level
// tables to the patch level and `normals` the patch pass (positions and normals).
struct PhaseTimes {
    double deformMs = 0;    // skinning the cage, and putting it where the evaluator reads it
    double evaluateMs = 0;
    double normalsMs = 0;
    double frameMs() const { return deformMs + evaluateMs + normalsMs; }
};

class FrameEvaluator {
public:
    virtual ~FrameEvaluator() = default;
    // "cpu", "tbb", "vulkan".
    virtual std::string name() const = 0;
    // Hands over the deformed cage (3 floats per control vertex), which must stay valid until
    // evaluate() returns: a host evaluator reads it in place, a device evaluator uploads it.
    virtual void setCage(const float* cage) = 0;
    // Evaluates the surface of the cage last set; fills times.evaluateMs and times.normalsMs.
    virtual void evaluate(PhaseTimes& times) = 0;
    // Level N's limit positions and unit normals of the last evaluation, 3 floats per vertex, in
    // host memory (a device evaluator reads them back: not part of a frame).
    virtual void readBack(std::vector<float>& positions, std::vector<float>& normals) = 0;
};

}  // namespace quadtri::realtime
