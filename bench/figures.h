// What the bench measures per case, and for the whole run; written out by report.cpp.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace quadtri::bench {

struct QuadtriFigures {
    double buildMs = 0;                     // Refiner construction + refineUniform(level)
    std::size_t tableBytes = 0;             // sum of the per-level tables' bytes()
    double evalSerialMs = 0;                // CpuEvaluator, level by level
    std::optional<double> evalThreadedMs;   // TbbEvaluator, level by level
    std::optional<double> evalVulkanMs;     // VulkanEvaluator over every level, submit to fence (no device: absent)
    std::optional<double> uploadVulkanMs;   // the per-level tables and the control positions
    // Table arrays read + distinct source vertices read + output vertices written, all levels.
    double compulsoryBytes = 0;
};

struct OsdFigures {
    double buildMsPerLevel = 0;      // refiner + RefineUniform + StencilTableFactory (intermediate levels)
    double buildMsFactorized = 0;    // the same, last level factorized over the control vertices
    double evalCpuPerLevelMs = 0;    // Osd::CpuEvaluator on the per-level table (one call)
    double evalCpuFactorizedMs = 0;  // Osd::CpuEvaluator on the factorized table
    double evalOmpMs = 0;            // Osd::OmpEvaluator on the per-level table, level by level
    std::size_t tableBytes = 0;      // per-level table: sizes, offsets, indices, weights
    std::size_t tableBytesFactorized = 0;
    double bestEvalMs() const { return std::min({evalCpuPerLevelMs, evalCpuFactorizedMs, evalOmpMs}); }
};

// Per-frame limit positions and unit normals of the last level's vertices.
// The factorized figures are absent where the memory budget refuses that table (the chain,
// whose tables are far smaller, still runs).
struct LimitFigures {
    std::optional<std::size_t> tableBytes;  // the factorized LimitStencilTable
    std::size_t chainTableBytes = 0;        // the per-level tables and the limit table over level N
    std::optional<double> limitSerialMs;    // CpuEvaluator::EvalLimitStencils, factorized (control -> limit)
    std::optional<double> limitThreadedMs;  // TbbEvaluator, the same
    double levelsThenLimitSerialMs = 0;     // per-level tables to level N, then the limit table over level N
    double levelsThenLimitThreadedMs = 0;
    double meshNormalsSerialMs = 0;         // EvalMeshNormals of level N (its positions given)
    double meshNormalsThreadedMs = 0;
    std::optional<double> limitVulkanMs;    // VulkanLimitEvaluator, factorized, submit to fence
    double bestSerialMs() const { return std::min(limitSerialMs.value_or(levelsThenLimitSerialMs), levelsThenLimitSerialMs); }
    double bestThreadedMs() const {
        return std::min(limitThreadedMs.value_or(levelsThenLimitThreadedMs), levelsThenLimitThreadedMs);
    }
};

struct OsdLimitFigures {
    std::size_t tableBytes = 0;  // Far::LimitStencilTable: sizes, offsets, indices, three weight arrays
    double evalCpuMs = 0;        // Osd::CpuEvaluator::EvalStencils with du, dv + the normal loop
    double evalOmpMs = 0;        // Osd::OmpEvaluator, the same
    double bestMs() const { return std::min(evalCpuMs, evalOmpMs); }
};

struct LimitCaseResult {
    std::string mesh;
    std::string scheme;
    int level = 0;
    int points = 0;
    LimitFigures quadtri;
    std::optional<OsdLimitFigures> osd;
};

struct CaseResult {
    std::string mesh;
    std::string scheme;
    int level = 0;
    int refinedVertices = 0;  // vertices of the last level
    QuadtriFigures quadtri;
    std::optional<OsdFigures> osd;
};

struct BenchResult {
    std::size_t memcpyBytes = 0;  // buffer size of the memcpy runs
    double memcpyGbps1 = 0;
    double memcpyGbps2 = 0;
    std::vector<CaseResult> cases;
    std::vector<LimitCaseResult> limitCases;
};

}  // namespace quadtri::bench
