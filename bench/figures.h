// What the bench measures per case, and for the whole run; written out by report.cpp (the JSON
// that bench/performance_section.py turns into docs/performance.md and README's headline table).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bench/frame_figures.h"
#include "bench/measure/timing.h"

namespace quadtri::bench {

// Memory of one side of a case: the bytes its tables and vertex buffers hold by count, and the
// most memory resident above what was resident when its untimed first run (build, buffers, one
// evaluation each way) began, read from Linux's peak resident set (bench/measure/peak_memory.h; absent
// where the kernel cannot reset that peak).
struct MemoryFigures {
    std::size_t tableBytes = 0;
    std::size_t bufferBytes = 0;
    std::optional<std::size_t> peakResidentBytes;
};

struct QuadtriFigures {
    Timing build1Ms;                      // Refiner construction + refineUniform(level), oneTBB limited to 1 thread
    Timing buildMs;                       // the same on all threads
    // The same build and then factorizedStencils(level), on 1 thread and on all (absent where the
    // memory budget refuses the factorized table, and where OpenSubdiv has no case beside it).
    std::optional<Timing> buildFactorized1Ms, buildFactorizedMs;
    std::size_t tableBytes = 0;           // sum of the per-level tables' bytes()
    Timing evalSerialMs;                  // CpuEvaluator, level by level, 3 floats a vertex
    Timing evalThreadedMs;                // TbbEvaluator, the same, all threads
    Timing evalSerial4Ms;                 // the same two with positions padded to 4 floats
    Timing evalThreaded4Ms;
    std::optional<Timing> evalVulkanMs;   // VulkanEvaluator over every level, submit to fence (no device: absent)
    std::optional<Timing> uploadVulkanMs; // the per-level tables and the control positions
    // Table arrays read + distinct source vertices read + output vertices written, all levels,
    // 12 bytes a vertex (16 for compulsoryBytes4).
    double compulsoryBytes = 0;
    double compulsoryBytes4 = 0;
    MemoryFigures memory;
};

// One way OpenSubdiv evaluates the case's last level.
struct OsdEvaluation {
    std::string table;      // "per_level" (level by level) or "factorized" (control vertices to the last level)
    // "cpu" (Osd::CpuEvaluator, serial), "omp" (Osd::OmpEvaluator, all threads) or "far"
    // (Far::StencilTable::UpdateValues, serial, compiled into the bench over a Width-float vertex)
    std::string evaluator;
    int width = 3;          // floats a vertex: 3, or 4 (xyz padded, its SIMD path for Osd::CpuEvaluator)
    Timing ms;
};

struct OsdFigures {
    Timing buildPerLevelMs;    // refiner + RefineUniform + StencilTableFactory (intermediate levels), serial
    Timing buildFactorizedMs;  // the same, last level factorized over the control vertices
    std::size_t tableBytes = 0;  // per-level table: sizes, offsets, indices, weights
    std::size_t tableBytesFactorized = 0;
    std::vector<OsdEvaluation> evaluations;  // every table x evaluator x width
    MemoryFigures memory;                    // both tables, the buffers of every evaluation
};

// Per-frame limit positions and unit normals of the last level's vertices.
// The factorized figures are absent where the memory budget refuses that table (the chain,
// whose tables are far smaller, still runs).
struct LimitFigures {
    std::optional<std::size_t> tableBytes;  // the factorized LimitStencilTable
    std::size_t chainTableBytes = 0;        // the per-level tables and the limit table over level N
    std::optional<Timing> limitSerialMs;    // CpuEvaluator::EvalLimitStencils, factorized (control -> limit)
    std::optional<Timing> limitThreadedMs;  // TbbEvaluator, the same
    Timing levelsThenLimitSerialMs;         // per-level tables to level N, then the limit table over level N
    Timing levelsThenLimitThreadedMs;
    Timing meshNormalsSerialMs;             // EvalMeshNormals of level N (its positions given)
    Timing meshNormalsThreadedMs;
    std::optional<Timing> limitVulkanMs;    // VulkanLimitEvaluator, factorized, submit to fence
    MemoryFigures memory;
};

struct OsdLimitFigures {
    std::size_t tableBytes = 0;  // Far::LimitStencilTable: sizes, offsets, indices, three weight arrays
    Timing evalCpuMs;            // Osd::CpuEvaluator::EvalStencils with du, dv + the normal loop
    Timing evalOmpMs;            // Osd::OmpEvaluator, the same
    Timing evalFarMs;            // Far's UpdateValues + UpdateDerivs compiled into the bench, the same normals
    MemoryFigures memory;
};

struct LimitCaseResult {
    std::string mesh;
    std::string scheme;
    int level = 0;
    int points = 0;
    LimitFigures quadtri;
    std::optional<OsdLimitFigures> osd;
};

// One way of evaluating a surface case's points (position, du, dv, then the unit normal), serial.
struct SurfaceWay {
    std::string library;  // "quadtri" or "opensubdiv"
    // quadtri: "face_surface" (FaceSurfaceFactory); OpenSubdiv: "bfr_default" (Bfr::Surface at its
    // approximation levels 2 smooth / 6 sharp), "bfr_approx10" (both at 10) or "patch_table_cpu"
    // (Far::PatchTable, adaptive to level 2, Gregory end caps, Osd::CpuEvaluator::EvalPatches)
    std::string way;
    Timing factoryMs;               // from the mesh's arrays to a factory (refiner, analysis, patch table)
    Timing pointsMs;                // every point, a new factory's caches empty (PatchTable: its local points too)
    std::optional<Timing> warmMs;   // every point again, the factory's caches full (Bfr, quadtri)
    // The farthest point from Bfr at level 10 evaluated in double, / the bounding-box diagonal
    std::optional<double> positionError;
    std::optional<double> normalError;    // the largest angle between the two normals, radians
};

// Points at random (u, v) on every face of a cage, grouped by face, evaluated by each way.
struct SurfaceCaseResult {
    std::string mesh;
    std::string scheme;
    int faces = 0;
    int points = 0;
    std::vector<SurfaceWay> ways;
};

// memcpy bandwidth in GB/s (bytes read + written), on one thread and on all.
struct MemcpyFigures {
    std::size_t bytes = 0;  // bytes copied (the copy touches twice as many)
    double gbps1 = 0, gbpsAll = 0;
};

struct CaseResult {
    std::string mesh;
    std::string scheme;
    int level = 0;
    int refinedVertices = 0;  // vertices of the last level
    QuadtriFigures quadtri;
    std::optional<OsdFigures> osd;
    // A copy whose source and destination together are the size of the 3-float evaluation's
    // compulsory bytes, so that it runs from the same level of the memory hierarchy.
    MemcpyFigures memcpyWorkingSet;
};

// One way to tessellate a whole cage at a uniform rate: points, unit normals and triangles,
// serial (bench/quadtri/tessellation_case.h).
struct TessellationWay {
    std::string library;  // "quadtri" or "opensubdiv"
    // quadtri: "tessellation" (Tessellation + LimitSurface::stencilTable + EvalLimitStencils);
    // OpenSubdiv: "bfr_tessellation" (per face Bfr::Surface at its default approximation levels,
    // Bfr::Tessellation, Surface::Evaluate at each coordinate; every face its own boundary points)
    std::string way;
    int points = 0;     // points evaluated (Bfr: a shared edge's points once per face)
    int triangles = 0;
    Timing firstMs;     // from the mesh's arrays to points, normals and the index buffer
    Timing frameMs;     // the same triangles, the cage moved: points and normals again
    double area = 0;    // the triangles' total area (both sides tessellate the same surface)
};

struct TessellationCaseResult {
    std::string mesh;
    std::string scheme;
    int faces = 0;
    int rate = 0;
    std::vector<TessellationWay> ways;
};

// One edit of a cage's tags (bench/edit_case.h): applied in place against the same tables built
// again, and OpenSubdiv's rebuild of its tables for the edited cage.
struct EditCaseResult {
    std::string mesh;
    std::string scheme;
    int level = 0;
    std::string edit;          // "edge", "edge_loop" (ten edges), "corner", "hole"
    int points = 0;            // stencils of the factorized limit table (level N's vertices)
    int stencilsWritten = 0;   // of that table, by the update (the last repetition's)
    Timing updateMs;           // Refiner::applyEdits + LimitTableUpdate::update, all threads
    Timing rebuildMs;          // Refiner + refineUniform(N) + factorizedLimitStencils(N), all threads
    // The largest distance between a limit point of the updated table and the rebuilt one's on the
    // cage, over the bounding-box diagonal.
    double maxDifference = 0;
    // OpenSubdiv (Catmark or Loop on the same cage, where it has the scheme: its rebuild is what a
    // user of it pays for any scheme): refiner + RefineUniform(N) + factorized StencilTable, and
    // refiner + RefineAdaptive(2) + LimitStencilTable at the level's points, serial.
    std::optional<Timing> osdRebuildMs;
    std::string osdScheme;
};

struct BenchResult {
    std::string date;           // UTC, ISO 8601
    std::string cpu;            // /proc/cpuinfo's model name
    std::string command;        // the bench's own command line
    int threads = 0;            // oneTBB's concurrency: the threaded figures' "all threads"
    std::string vulkanDevice;   // empty: no Vulkan figures
    int repetitions = 0;        // timed runs per figure, after one warm-up
    MemcpyFigures memcpyLarge;  // 256 MiB
    std::vector<CaseResult> cases;
    std::vector<LimitCaseResult> limitCases;
    std::vector<FrameCaseResult> frameCases;
    std::vector<SurfaceCaseResult> surfaceCases;
    std::vector<TessellationCaseResult> tessellationCases;
    std::vector<EditCaseResult> editCases;
};

}  // namespace quadtri::bench
