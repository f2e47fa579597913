// One frame case on quadtri's side: the real-time loop's whole frame (tools/realtime/,
// docs/realtime_loop.md). Every frame realtime::DeformingSurface poses the cage with the two-bone
// skin, then level N's limit positions and unit normals are evaluated through the table routes
// (the factorized limit table; the per-level tables followed by the limit table over level N;
// the per-level tables to level N - 3 followed by the regular patches, docs/patches.md) on
// CpuEvaluator, TbbEvaluator (all threads) and, given a device, Vulkan (the route
// fastestSurfaceTables takes); and, as a second figure, the per-level tables to level N followed
// by level N's mesh normals.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/frame_figures.h"
#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>
#include "tools/realtime/deforming_surface.h"
#include "tools/realtime/frame_evaluator.h"
#include "tools/realtime/surface_tables.h"

namespace quadtri {
inline namespace v0 {
class VulkanContext;
}  // namespace v0
}  // namespace quadtri

namespace quadtri::bench {

// `frames` timed frames through `evaluator` after one warm-up frame at the rest pose, along the
// demo's motion (realtime::bendAngle) from just past the rest pose to the full bend, so that
// every frame poses the cage anew; each phase summarized, `route` and the evaluator's name kept.
FrameTiming timeFrames(realtime::DeformingSurface& surface, realtime::FrameEvaluator& evaluator,
                       const std::string& route, int frames);

class FrameCase {
public:
    // Refines the cage (`descriptor` need only live during the call; `rest` its positions, 3
    // floats a vertex) to `level` and builds the tables: the factorized limit table where the
    // memory budget allows it (else that route is left out) and the per-level chain. `name`
    // names the case in errors.
    FrameCase(std::string name, const TopologyDescriptor& descriptor, const Options& options, std::vector<float> rest,
              int level, VulkanContext* vulkan);
    ~FrameCase();

    // One frame at `radians` every way, checked before anything is timed (std::runtime_error if
    // not): TbbEvaluator's frames bitwise CpuEvaluator's, the chain's limit within 1e-5 of the
    // bounding box diagonal of the factorized one (normals within 1e-3 doubled per level past
    // the first: float rounding), Vulkan's within 1e-5 of the diagonal and 1e-3, the mesh normals
    // of unit length. Where a point's tangents differ in length by a ratio r, its normals may
    // differ by 64 float epsilons times r (the skin pinches the surface there).
    void prepare(float radians);

    // CpuEvaluator's limit positions and unit normals of level N at prepare()'s angle, through
    // the factorized table where there is one (else the chain).
    const std::vector<float>& positions() const { return positions_; }
    const std::vector<float>& normals() const { return normals_; }
    double diagonal() const { return diagonal_; }
    int numPoints() const;
    std::optional<std::size_t> limitTableBytes() const;
    std::size_t chainTableBytes() const;

    // Every way, `frames` frames each.
    std::vector<FrameTiming> measure(int frames);

private:
    struct Way {
        std::string route;
        std::unique_ptr<realtime::FrameEvaluator> evaluator;
    };

    std::vector<double> tangentRatios() const;

    std::string name_;
    int level_;
    double diagonal_;
    std::unique_ptr<Refiner> refiner_;
    std::unique_ptr<realtime::SurfaceTables> factorized_, chain_, patches_;
    realtime::DeformingSurface surface_;
    std::vector<Way> ways_;  // the limit ways first, then the mesh-normal ways
    std::vector<float> positions_, normals_;
};

}  // namespace quadtri::bench
