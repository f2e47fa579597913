// Argument checking shared by every evaluator's EvalStencils, EvalMeshNormals and
// EvalLimitStencils (CpuEvaluator, TbbEvaluator, the Vulkan evaluators), so that all of them accept
// and reject exactly the same calls with the same messages.
#pragma once

#include <quadtri/export.h>
#include <quadtri/far/level_patch_table.h>
#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/far/stencil_table.h>
#include "kernels/limit_kernel.h"
#include "kernels/patch_kernel.h"
#include "kernels/mesh_normal_kernel.h"
#include "kernels/stencil_kernel.h"
#include <quadtri/osd/buffer_descriptor.h>
#include <quadtri/osd/stencil_runs.h>

namespace quadtri {
inline namespace v0 {
namespace detail {

// Checks the arguments of an EvalStencils call over a table of `numStencils` stencils and
// resolves end < 0 to numStencils. srcPresent / dstPresent say whether the caller passed a
// buffer (a non-null pointer on the host, a non-null VkBuffer on a device). Throws
// std::invalid_argument on an invalid descriptor, differing source and destination lengths, a
// range outside [0, numStencils] or start > end, and (only when the range is not empty) a
// missing buffer. Returns false when [start, end) is empty: nothing to evaluate.
QUADTRI_API bool checkEvalArguments(bool srcPresent, const BufferDescriptor& srcDesc, bool dstPresent,
                        const BufferDescriptor& dstDesc, int numStencils, int start, int& end);

// EvalMeshNormals over a table of `numVertices` vertices: valid descriptors of length 3 on both
// sides, the range, and (only when the range is not empty) both buffers; end < 0 resolved.
// Returns false when there is nothing to evaluate.
QUADTRI_API bool checkMeshNormalArguments(bool srcPresent, const BufferDescriptor& srcDesc, bool dstPresent,
                              const BufferDescriptor& dstDesc, int numVertices, int start, int& end);

// One optional output of EvalLimitStencils: absent (a null pointer or VkBuffer) means not
// written, and its descriptor is not looked at.
struct LimitOutputArgument {
    bool present;
    const BufferDescriptor& desc;
};

// EvalLimitStencils: a valid source descriptor and a valid descriptor for every present output,
// position, dU and dV of the source's length, normals only for 3-float data (normal length 3), at
// least one output, a fallback table (fallbackVertices >= 0; -1 for none) over the limit table's
// own sources and stencils, the range, and the source buffer when the range is not empty.
// Returns false when there is nothing to evaluate.
QUADTRI_API bool checkLimitArguments(bool srcPresent, const BufferDescriptor& srcDesc, const LimitOutputArgument& position,
                         const LimitOutputArgument& du, const LimitOutputArgument& dv,
                         const LimitOutputArgument& normal, int numStencils, int numSources, int fallbackVertices,
                         int start, int& end);

// The host evaluators' EvalLimitStencils arguments checked (the table's per-stencil arrays of
// one length, then checkLimitArguments) and turned into what kernels::evalLimitStencils reads
// (outputs.fallback points into the struct itself, so it is filled in place); returns false when
// the range is empty.
struct HostLimitCall {
    const float* src;
    kernels::LimitStencilArrays arrays;
    kernels::MeshNormalArrays fallbackArrays;
    kernels::LimitOutputs outputs;
};
QUADTRI_API bool hostLimitCall(HostLimitCall& call, const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                   const BufferDescriptor& positionDesc, float* dstDu, const BufferDescriptor& duDesc, float* dstDv,
                   const BufferDescriptor& dvDesc, float* dstNormal, const BufferDescriptor& normalDesc,
                   const LimitStencilTable& table, const MeshNormalTable* fallback, int start, int& end);

// The table's arrays as the kernel reads them.
inline kernels::StencilArrays stencilArrays(const StencilTable& table) {
    return kernels::StencilArrays{table.offsets.data(), table.indices.data(), table.weightOffsets.data(),
                                  table.weights.data()};
}

// A StencilRuns' arrays as the kernel reads them; throws std::invalid_argument where its table's
// stencil count changed since the runs were built (they would no longer cover it).
QUADTRI_API kernels::StencilRunArrays stencilRunArrays(const StencilRuns& runs);

inline kernels::LimitStencilArrays limitArrays(const LimitStencilTable& table) {
    return kernels::LimitStencilArrays{table.sizes.data(), table.offsets.data(), table.indices.data(),
                                       table.weightOffsets.data(), table.weights.data()};
}

inline kernels::MeshNormalArrays meshNormalArrays(const MeshNormalTable& table) {
    return kernels::MeshNormalArrays{table.faceOffsets.data(), table.faceCorners.data(),
                                     table.vertexFaceOffsets.data(), table.vertexFaces.data()};
}

// EvalLevelPatches: the source buffer, valid descriptors of length 3 for the source and each
// output given, at least one output. Throws std::invalid_argument.
QUADTRI_API void checkLevelPatchArguments(bool srcPresent, const BufferDescriptor& srcDesc, bool positionPresent,
                                          const BufferDescriptor& positionDesc, bool normalPresent,
                                          const BufferDescriptor& normalDesc);

// The host's EvalLevelPatches: checkLevelPatchArguments, the table's array lengths; the patches' arrays and the stencils' as the kernels read them, with the outputs
// offset. Throws std::invalid_argument.
struct HostLevelPatchCall {
    const float* src;
    int srcStride;
    kernels::LevelPatchArrays patches;
    float* position;
    int positionStride;
    float* normal;
    int normalStride;
    kernels::LimitStencilArrays stencils;
    kernels::LimitOutputs stencilOutputs;  // from element numPatchOutputs on
};
QUADTRI_API HostLevelPatchCall levelPatchCall(const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                                              const BufferDescriptor& positionDesc, float* dstNormal,
                                              const BufferDescriptor& normalDesc, const LevelPatchTable& table);

}  // namespace detail
}  // namespace v0
}  // namespace quadtri
