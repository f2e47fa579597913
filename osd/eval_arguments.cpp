#include "osd/internal/eval_arguments.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace quadtri {
inline namespace v0 {
namespace detail {

bool checkEvalArguments(bool srcPresent, const BufferDescriptor& srcDesc, bool dstPresent,
                        const BufferDescriptor& dstDesc, int numStencils, int start, int& end) {
    if (end < 0) end = numStencils;
    if (!srcDesc.isValid() || !dstDesc.isValid())
        throw std::invalid_argument("EvalStencils: invalid BufferDescriptor (need length > 0, stride >= length, offset >= 0)");
    if (srcDesc.length != dstDesc.length)
        throw std::invalid_argument("EvalStencils: source length " + std::to_string(srcDesc.length) +
                                    " differs from destination length " + std::to_string(dstDesc.length));
    if (start < 0 || start > end || end > numStencils)
        throw std::invalid_argument("EvalStencils: range [" + std::to_string(start) + ", " + std::to_string(end) +
                                    ") outside the table's " + std::to_string(numStencils) + " stencils");
    if (start == end) return false;
    if (!srcPresent || !dstPresent) throw std::invalid_argument("EvalStencils: null buffer");
    return true;
}

kernels::StencilRunArrays stencilRunArrays(const StencilRuns& runs) {
    if (runs.table().numStencils() != runs.numStencils())
        throw std::invalid_argument("EvalStencils: the table has " + std::to_string(runs.table().numStencils()) +
                                    " stencils, its StencilRuns were built for " +
                                    std::to_string(runs.numStencils()) + ": build them again");
    return kernels::StencilRunArrays{stencilArrays(runs.table()), runs.runs().data(), int(runs.runs().size()),
                                     runs.groups().data(), runs.order().data()};
}

namespace {

const char* const kInvalidDescriptor = "invalid BufferDescriptor (need length > 0, stride >= length, offset >= 0)";

void checkRange(const char* call, const char* what, int count, int start, int end) {
    if (start < 0 || start > end || end > count)
        throw std::invalid_argument(std::string(call) + ": range [" + std::to_string(start) + ", " +
                                    std::to_string(end) + ") outside the table's " + std::to_string(count) + " " + what);
}

}  // namespace

bool checkMeshNormalArguments(bool srcPresent, const BufferDescriptor& srcDesc, bool dstPresent,
                              const BufferDescriptor& dstDesc, int numVertices, int start, int& end) {
    if (end < 0) end = numVertices;
    if (!srcDesc.isValid() || !dstDesc.isValid())
        throw std::invalid_argument(std::string("EvalMeshNormals: ") + kInvalidDescriptor);
    if (srcDesc.length != 3 || dstDesc.length != 3)
        throw std::invalid_argument("EvalMeshNormals: positions and normals are 3 floats (source length " +
                                    std::to_string(srcDesc.length) + ", destination length " +
                                    std::to_string(dstDesc.length) + ")");
    checkRange("EvalMeshNormals", "vertices", numVertices, start, end);
    if (start == end) return false;
    if (!srcPresent || !dstPresent) throw std::invalid_argument("EvalMeshNormals: null buffer");
    return true;
}

bool checkLimitArguments(bool srcPresent, const BufferDescriptor& srcDesc, const LimitOutputArgument& position,
                         const LimitOutputArgument& du, const LimitOutputArgument& dv,
                         const LimitOutputArgument& normal, int numStencils, int numSources, int fallbackVertices,
                         int start, int& end) {
    if (end < 0) end = numStencils;
    const std::string call = "EvalLimitStencils: ";
    if (!srcDesc.isValid()) throw std::invalid_argument(call + "source " + kInvalidDescriptor);
    const std::pair<const char*, const LimitOutputArgument*> outputs[] = {
        {"position", &position}, {"dU", &du}, {"dV", &dv}, {"normal", &normal}};
    bool any = false;
    for (const auto& [name, out] : outputs) {
        if (!out->present) continue;
        any = true;
        if (!out->desc.isValid()) throw std::invalid_argument(call + name + " " + kInvalidDescriptor);
        if (out != &normal && out->desc.length != srcDesc.length)
            throw std::invalid_argument(call + "source length " + std::to_string(srcDesc.length) + " differs from " +
                                        name + " length " + std::to_string(out->desc.length));
    }
    if (!any) throw std::invalid_argument(call + "no output (position, dU, dV and normal all null)");
    if (normal.present && (srcDesc.length != 3 || normal.desc.length != 3))
        throw std::invalid_argument(call + "normals need 3-float positions and normals (source length " +
                                    std::to_string(srcDesc.length) + ", normal length " +
                                    std::to_string(normal.desc.length) + ")");
    if (fallbackVertices >= 0 && (fallbackVertices != numSources || fallbackVertices != numStencils))
        throw std::invalid_argument(call + "the fallback MeshNormalTable has " + std::to_string(fallbackVertices) +
                                    " vertices, the limit table " + std::to_string(numStencils) + " stencils over " +
                                    std::to_string(numSources) +
                                    " sources (a fallback needs the table over its level's own vertices)");
    checkRange("EvalLimitStencils", "stencils", numStencils, start, end);
    if (start == end) return false;
    if (!srcPresent) throw std::invalid_argument(call + "null source buffer");
    return true;
}

bool hostLimitCall(HostLimitCall& call, const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                   const BufferDescriptor& positionDesc, float* dstDu, const BufferDescriptor& duDesc, float* dstDv,
                   const BufferDescriptor& dvDesc, float* dstNormal, const BufferDescriptor& normalDesc,
                   const LimitStencilTable& table, const MeshNormalTable* fallback, int start, int& end) {
    // O(1): the per-stencil arrays agree in length (what each stencil's run holds is not looked
    // at per call; VulkanLimitStencilTable checks it once, on upload).
    if (table.offsets.size() != table.sizes.size() || table.weightOffsets.size() != table.sizes.size())
        throw std::invalid_argument("EvalLimitStencils: inconsistent LimitStencilTable arrays (" +
                                    std::to_string(table.sizes.size()) + " sizes, " +
                                    std::to_string(table.offsets.size()) + " offsets, " +
                                    std::to_string(table.weightOffsets.size()) + " weight offsets)");
    if (!checkLimitArguments(src != nullptr, srcDesc, {dstPosition != nullptr, positionDesc},
                                      {dstDu != nullptr, duDesc}, {dstDv != nullptr, dvDesc},
                                      {dstNormal != nullptr, normalDesc}, table.numStencils(),
                                      table.numSourceVertices, fallback ? fallback->numVertices : -1, start, end))
        return false;
    auto output = [](float* data, const BufferDescriptor& d) {
        return kernels::LimitOutput{data ? data + d.offset : nullptr, data ? d.stride : 0};
    };
    call.src = src + srcDesc.offset;
    call.arrays = limitArrays(table);
    if (fallback) call.fallbackArrays = meshNormalArrays(*fallback);
    call.outputs = {output(dstPosition, positionDesc), output(dstDu, duDesc), output(dstDv, dvDesc),
                    output(dstNormal, normalDesc), fallback ? &call.fallbackArrays : nullptr};
    return true;
}

static_assert(kernels::kMaxRate == LevelPatchTable::kMaxRate, "the kernel's grid-line bytes follow the table's");

void checkLevelPatchArguments(bool srcPresent, const BufferDescriptor& srcDesc, bool positionPresent,
                              const BufferDescriptor& positionDesc, bool normalPresent,
                              const BufferDescriptor& normalDesc) {
    auto check = [](bool ok, const std::string& what) {
        if (!ok) throw std::invalid_argument("EvalLevelPatches: " + what);
    };
    check(srcPresent, "no source buffer");
    check(srcDesc.isValid() && srcDesc.length == 3, "the source descriptor must be valid, of length 3");
    check(positionPresent || normalPresent, "neither positions nor normals asked for");
    check(!positionPresent || (positionDesc.isValid() && positionDesc.length == 3),
          "the position descriptor must be valid, of length 3");
    check(!normalPresent || (normalDesc.isValid() && normalDesc.length == 3),
          "the normal descriptor must be valid, of length 3");
}

HostLevelPatchCall levelPatchCall(const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                                  const BufferDescriptor& positionDesc, float* dstNormal,
                                  const BufferDescriptor& normalDesc, const LevelPatchTable& t) {
    checkLevelPatchArguments(src != nullptr, srcDesc, dstPosition != nullptr, positionDesc, dstNormal != nullptr,
                             normalDesc);
    auto check = [](bool ok, const std::string& what) {
        if (!ok) throw std::invalid_argument("EvalLevelPatches: " + what);
    };
    check(t.pointOffsets.size() == t.patchBasis.size() + 1 && t.outputOffsets.size() == t.patchBasis.size() + 1 &&
              t.outputCells.size() == t.outputVertices.size() &&
              t.stencilVertices.size() == std::size_t(t.stencils.numStencils()) &&
              t.stencils.offsets.size() == t.stencils.sizes.size() &&
              t.stencils.weightOffsets.size() == t.stencils.sizes.size() && t.rate() <= LevelPatchTable::kMaxRate &&
              t.curveWeights.size() == 8 * std::size_t(t.rate() + 1) &&
              t.boxSplineWeights.size() == 36 * std::size_t((t.rate() + 1) * (t.rate() + 1)) &&
              t.curveWeightLines.size() == 8 * std::size_t(t.lineWidth()) &&
              t.boxSplineWeightLines.size() == 36 * std::size_t((t.rate() + 1) * t.lineWidth()),
          "inconsistent LevelPatchTable arrays");
    HostLevelPatchCall c{};
    c.src = src + srcDesc.offset;
    c.srcStride = srcDesc.stride;
    c.patches = {t.rate(),
                 reinterpret_cast<const std::uint8_t*>(t.patchBasis.data()),
                 t.pointOffsets.data(),
                 t.patchPoints.data(),
                 t.outputOffsets.data(),
                 t.outputCells.data(),
                 t.curveWeights.data(),
                 t.boxSplineWeights.data(),
                 t.lineWidth(),
                 t.curveWeightLines.data(),
                 t.boxSplineWeightLines.data()};
    c.position = dstPosition ? dstPosition + positionDesc.offset : nullptr;
    c.positionStride = positionDesc.stride;
    c.normal = dstNormal ? dstNormal + normalDesc.offset : nullptr;
    c.normalStride = normalDesc.stride;
    c.stencils = limitArrays(t.stencils);
    const long first = t.numPatchOutputs();
    c.stencilOutputs = {{c.position ? c.position + first * c.positionStride : nullptr, c.positionStride},
                        {nullptr, 0},
                        {nullptr, 0},
                        {c.normal ? c.normal + first * c.normalStride : nullptr, c.normalStride},
                        nullptr};
    return c;
}

}  // namespace detail
}  // namespace v0
}  // namespace quadtri
