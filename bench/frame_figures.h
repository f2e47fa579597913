// What a frame case measures: the real-time loop's whole frame (the cage posed by the two-bone
// skin, then level N's positions and normals) on each side, per way of running it; written out by
// bench/frame_report.cpp.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bench/measure/timing.h"

namespace quadtri::bench {

// One way of running the frame, timed over the case's frames (each at its own bend angle): each
// phase and the whole frame (their sum), in ms. The phases are realtime::PhaseTimes': deform (the
// skin, and the cage handed to the evaluator: Vulkan's upload), evaluate, normals (0 where the
// evaluation pass computes them).
struct FrameTiming {
    // quadtri: "cpu" (CpuEvaluator), "tbb" (TbbEvaluator, all threads), "vulkan";
    // OpenSubdiv: "cpu" (Osd::CpuEvaluator), "omp" (Osd::OmpEvaluator, all threads), "far" (Far's
    // UpdateValues + UpdateDerivs, serial).
    std::string evaluator;
    // What the frame computes and how. Limit positions + limit normals: "factorized_limit"
    // (quadtri's factorized limit table, one pass from the cage), "levels_then_limit" (the
    // per-level tables, then the limit table over level N), "limit_stencils" (OpenSubdiv's
    // Far::LimitStencilTable with du, dv, then normalize(du x dv)). Refined positions + mesh
    // normals: "levels_then_mesh_normals" (the per-level tables to level N, then its mesh normals).
    std::string route;
    Timing deformMs, evaluateMs, normalsMs, frameMs;
};

struct FrameCaseResult {
    std::string mesh;
    std::string scheme;  // quadtri's, "/catmark" or "/loop" where OpenSubdiv runs the cage too
    int level = 0;
    int controlVertices = 0;
    int faces = 0;       // the cage's
    int points = 0;      // level N's vertices: what a frame outputs
    int frames = 0;      // timed frames per way, after a warm-up frame
    std::optional<std::size_t> limitTableBytes;  // the factorized limit table (absent: the budget refused it)
    std::size_t chainTableBytes = 0;             // the per-level tables and the limit table over level N
    std::vector<FrameTiming> quadtri;
    std::vector<FrameTiming> osd;                // empty: OpenSubdiv has no scheme for the cage
};

}  // namespace quadtri::bench
