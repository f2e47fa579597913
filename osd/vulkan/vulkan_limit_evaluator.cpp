#include <quadtri/osd/vulkan_limit_evaluator.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "osd/internal/eval_arguments.h"
#include "osd/vulkan/vulkan_kernel.h"
#include "osd/vulkan/vulkan_memory.h"

namespace quadtri {
inline namespace v0 {

namespace shaders {
extern const uint32_t limit_eval_comp[];
extern const std::size_t limit_eval_comp_words;
extern const uint32_t mesh_normals_comp[];
extern const std::size_t mesh_normals_comp_words;
extern const uint32_t level_patches_comp[];
extern const std::size_t level_patches_comp_words;
}  // namespace shaders

namespace {

constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kTexels = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
// table (5: sizes, offsets, the index pool, weight offsets, the weight pool), source, 4 outputs,
// fallback table (4), then the two pools and the source again as texel buffers
// (shaders/limit_eval.comp).
constexpr std::size_t kFirstTexelBinding = 14;
const std::vector<VkDescriptorType> kLimitBindings = {kStorage, kStorage, kStorage, kStorage, kStorage, kStorage,
                                                      kStorage, kStorage, kStorage, kStorage, kStorage, kStorage,
                                                      kStorage, kStorage, kTexels,  kTexels,  kTexels};
constexpr uint32_t kLimitPushWords = 7;  // 5 float offsets, start, end
const std::vector<VkDescriptorType> kNormalBindings(6, kStorage);  // table (4), source, destination
constexpr uint32_t kNormalPushWords = 4;
// the patch table (6), source, position, normal, then the source and three of the table's arrays
// as texel buffers (shaders/level_patches.comp)
const std::vector<VkDescriptorType> kPatchBindings = {kStorage, kStorage, kStorage, kStorage, kStorage,
                                                      kStorage, kStorage, kStorage, kStorage, kTexels,
                                                      kTexels,  kTexels,  kTexels};
constexpr std::size_t kFirstPatchTexelBinding = 9;  // the source, then the table's three
constexpr uint32_t kPatchPushWords = 8;  // 3 float offsets, rate, patches per workgroup, patches, start, end

// Floats needed to hold `count` elements of `d` (0 when count is 0).
std::size_t floatsNeeded(const BufferDescriptor& d, int count) {
    return count <= 0 ? 0 : std::size_t(d.offset) + std::size_t(count - 1) * std::size_t(d.stride) + std::size_t(d.length);
}

void checkFits(const char* call, const char* which, const VulkanVertexBuffer* b, const BufferDescriptor& d, int count) {
    if (b && floatsNeeded(d, count) > b->numFloats())
        throw std::invalid_argument(std::string(call) + ": " + which + " buffer of " + std::to_string(b->numFloats()) +
                                    " floats too small for " + std::to_string(count) + " elements");
}

VulkanBufferRef refOf(const VulkanVertexBuffer* b) { return {b ? b->buffer() : VK_NULL_HANDLE, 0}; }

// What a shader's push constants and bindings get from the outputs given: each output's binding
// (`unused` where absent), float offset and stride (0 where absent); returns the mask of those
// present (bit k: output k).
template <std::size_t N>
int32_t bindOutputs(const VulkanContext& ctx, VkBuffer unused, const VulkanBufferRef (&outputs)[N],
                    const BufferDescriptor* const (&descs)[N], const char* call,
                    std::vector<VkDescriptorBufferInfo>& infos, std::vector<uint32_t>& words,
                    std::vector<int32_t>& constants) {
    int32_t mask = 0;
    for (std::size_t k = 0; k < N; ++k) {
        if (outputs[k].buffer == VK_NULL_HANDLE) {
            infos.push_back({unused, 0, VK_WHOLE_SIZE});
            words.push_back(0);
            constants.push_back(0);
            continue;
        }
        const detail::BoundBuffer out = detail::bindAligned(ctx, outputs[k].buffer, outputs[k].byteOffset, *descs[k], call);
        infos.push_back(out.info);
        words.push_back(out.floatOffset);
        constants.push_back(descs[k]->stride);
        mask |= int32_t(1) << k;
    }
    return mask;
}

// A source bound as a storage buffer and, where the caller gave a view, read through it instead:
// the view starts at the buffer's byte 0, the storage binding at `bound.info`; `offset` is the
// shader's float offset for the one it reads.
struct SourceBinding {
    detail::BoundBuffer bound;
    bool texels;
    uint32_t offset;
};

SourceBinding bindSource(const VulkanContext& ctx, const VulkanBufferRef& src, const BufferDescriptor& srcDesc,
                         const char* call) {
    const detail::BoundBuffer bound = detail::bindAligned(ctx, src.buffer, src.byteOffset, srcDesc, call);
    const std::size_t texelOffset = src.byteOffset / 4 + std::size_t(srcDesc.offset);
    const bool texels = src.texels != VK_NULL_HANDLE && texelOffset <= std::size_t(INT32_MAX);
    return {bound, texels, texels ? uint32_t(texelOffset) : bound.floatOffset};
}

}  // namespace

struct VulkanLimitEvaluator::Kernels {
    explicit Kernels(VulkanContext& ctx)
        : limit(ctx, shaders::limit_eval_comp, shaders::limit_eval_comp_words, kLimitBindings, kLimitPushWords),
          normals(ctx, shaders::mesh_normals_comp, shaders::mesh_normals_comp_words, kNormalBindings, kNormalPushWords),
          patches(ctx, shaders::level_patches_comp, shaders::level_patches_comp_words, kPatchBindings, kPatchPushWords),
          unused(ctx, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {}
    detail::VulkanKernel limit, normals, patches;
    detail::UnusedBindings unused;  // bound where an output, the fallback or a texel view is absent
};

VulkanLimitEvaluator::VulkanLimitEvaluator(VulkanContext& ctx) : ctx_(ctx), kernels_(std::make_unique<Kernels>(ctx)) {}

VulkanLimitEvaluator::~VulkanLimitEvaluator() = default;

void VulkanLimitEvaluator::resetDescriptorSets() {
    kernels_->limit.resetSets(detail::Arena::Recorded);
    kernels_->normals.resetSets(detail::Arena::Recorded);
    kernels_->patches.resetSets(detail::Arena::Recorded);
}

void VulkanLimitEvaluator::resetWaited() {
    kernels_->limit.resetSets(detail::Arena::Waited);
    kernels_->normals.resetSets(detail::Arena::Waited);
    kernels_->patches.resetSets(detail::Arena::Waited);
}

void VulkanLimitEvaluator::recordLimit(VkCommandBuffer cmd, bool waited, const VulkanBufferRef& src,
                                       const BufferDescriptor& srcDesc, const VulkanBufferRef (&outputs)[4],
                                       const BufferDescriptor* const (&descs)[4], const VulkanLimitStencilTable& table,
                                       const VulkanMeshNormalTable* fallback, int start, int end) {
    bool present[4];
    for (int k = 0; k < 4; ++k) present[k] = outputs[k].buffer != VK_NULL_HANDLE;
    if (!detail::checkLimitArguments(src.buffer != VK_NULL_HANDLE, srcDesc, {present[0], *descs[0]},
                                     {present[1], *descs[1]}, {present[2], *descs[2]}, {present[3], *descs[3]},
                                     table.numStencils(), table.numSourceVertices(),
                                     fallback ? fallback->numVertices() : -1, start, end))
        return;
    const char* call = "EvalLimitStencils";
    if (!cmd) throw std::invalid_argument("EvalLimitStencils: null command buffer");
    if (table.device() != ctx_.device() || (fallback && fallback->device() != ctx_.device()))
        throw std::invalid_argument("EvalLimitStencils: the table belongs to another VkDevice");

    const SourceBinding source = bindSource(ctx_, src, srcDesc, call);
    std::vector<VkDescriptorBufferInfo> infos = {
        {table.sizes(), 0, VK_WHOLE_SIZE},         {table.offsets(), 0, VK_WHOLE_SIZE},
        {table.indices(), 0, VK_WHOLE_SIZE},       {table.weightOffsets(), 0, VK_WHOLE_SIZE},
        {table.weights(), 0, VK_WHOLE_SIZE},       source.bound.info};
    std::vector<uint32_t> words{source.offset};
    std::vector<int32_t> constants{srcDesc.length, srcDesc.stride};
    int32_t mask = bindOutputs(ctx_, kernels_->unused.buffer.buffer(), outputs, descs, call, infos, words, constants);
    const bool useFallback = fallback && present[3];
    if (useFallback) {
        mask |= 16;
        for (VkBuffer b : fallback->buffers()) infos.push_back({b, 0, VK_WHOLE_SIZE});
    } else {
        for (int k = 0; k < 4; ++k) infos.push_back({kernels_->unused.buffer.buffer(), 0, VK_WHOLE_SIZE});
    }
    constants.push_back(mask);
    const bool poolTexels = table.indexTexels() != VK_NULL_HANDLE;
    constants.push_back(poolTexels);
    constants.push_back(source.texels);
    std::vector<VkBufferView> texels(kLimitBindings.size(), VK_NULL_HANDLE);
    texels[kFirstTexelBinding] = poolTexels ? table.indexTexels() : kernels_->unused.indexTexels.view();
    texels[kFirstTexelBinding + 1] = poolTexels ? table.weightTexels() : kernels_->unused.floatTexels.view();
    texels[kFirstTexelBinding + 2] = source.texels ? src.texels : kernels_->unused.floatTexels.view();
    kernels_->limit.record(cmd, waited ? detail::Arena::Waited : detail::Arena::Recorded, infos, constants, words, start, end,
                   texels);
}

void VulkanLimitEvaluator::EvalLimitStencils(VkCommandBuffer cmd, const VulkanBufferRef& src,
                                             const BufferDescriptor& srcDesc, const VulkanBufferRef& position,
                                             const BufferDescriptor& positionDesc, const VulkanBufferRef& du,
                                             const BufferDescriptor& duDesc, const VulkanBufferRef& dv,
                                             const BufferDescriptor& dvDesc, const VulkanBufferRef& normal,
                                             const BufferDescriptor& normalDesc, const VulkanLimitStencilTable& table,
                                             const VulkanMeshNormalTable* fallback, int start, int end) {
    const VulkanBufferRef outputs[4] = {position, du, dv, normal};
    const BufferDescriptor* const descs[4] = {&positionDesc, &duDesc, &dvDesc, &normalDesc};
    recordLimit(cmd, false, src, srcDesc, outputs, descs, table, fallback, start, end);
}

void VulkanLimitEvaluator::EvalLimitStencilsAndWait(
    const VulkanVertexBuffer& src, const BufferDescriptor& srcDesc, const VulkanVertexBuffer* position,
    const BufferDescriptor& positionDesc, const VulkanVertexBuffer* du, const BufferDescriptor& duDesc,
    const VulkanVertexBuffer* dv, const BufferDescriptor& dvDesc, const VulkanVertexBuffer* normal,
    const BufferDescriptor& normalDesc, const VulkanLimitStencilTable& table, const VulkanMeshNormalTable* fallback,
    int start, int end) {
    int last = end;
    if (!detail::checkLimitArguments(true, srcDesc, {position != nullptr, positionDesc}, {du != nullptr, duDesc},
                                     {dv != nullptr, dvDesc}, {normal != nullptr, normalDesc}, table.numStencils(),
                                     table.numSourceVertices(), fallback ? fallback->numVertices() : -1, start, last))
        return;
    const char* call = "EvalLimitStencils";
    checkFits(call, "source", &src, srcDesc, table.numSourceVertices());
    checkFits(call, "position", position, positionDesc, last);
    checkFits(call, "dU", du, duDesc, last);
    checkFits(call, "dV", dv, dvDesc, last);
    checkFits(call, "normal", normal, normalDesc, last);
    const VulkanBufferRef outputs[4] = {refOf(position), refOf(du), refOf(dv), refOf(normal)};
    const BufferDescriptor* const descs[4] = {&positionDesc, &duDesc, &dvDesc, &normalDesc};
    try {
        ctx_.submitAndWait([&](VkCommandBuffer cmd) {
            recordLimit(cmd, true, {src.buffer(), 0, src.texels()}, srcDesc, outputs, descs, table, fallback, start, end);
        });
    } catch (...) {
        resetWaited();
        throw;
    }
    resetWaited();
}

void VulkanLimitEvaluator::recordNormals(VkCommandBuffer cmd, bool waited, const VulkanBufferRef& src,
                                         const BufferDescriptor& srcDesc, const VulkanBufferRef& dst,
                                         const BufferDescriptor& dstDesc, const VulkanMeshNormalTable& table, int start,
                                         int end) {
    if (!detail::checkMeshNormalArguments(src.buffer != VK_NULL_HANDLE, srcDesc, dst.buffer != VK_NULL_HANDLE, dstDesc,
                                          table.numVertices(), start, end))
        return;
    const char* call = "EvalMeshNormals";
    if (!cmd) throw std::invalid_argument("EvalMeshNormals: null command buffer");
    if (table.device() != ctx_.device())
        throw std::invalid_argument("EvalMeshNormals: the table belongs to another VkDevice");
    const detail::BoundBuffer s = detail::bindAligned(ctx_, src.buffer, src.byteOffset, srcDesc, call);
    const detail::BoundBuffer d = detail::bindAligned(ctx_, dst.buffer, dst.byteOffset, dstDesc, call);
    std::vector<VkDescriptorBufferInfo> infos;
    for (VkBuffer b : table.buffers()) infos.push_back({b, 0, VK_WHOLE_SIZE});
    infos.push_back(s.info);
    infos.push_back(d.info);
    const std::vector<int32_t> constants{srcDesc.stride, dstDesc.stride};
    kernels_->normals.record(cmd, waited ? detail::Arena::Waited : detail::Arena::Recorded, infos, constants,
                     {s.floatOffset, d.floatOffset}, start, end);
}

void VulkanLimitEvaluator::EvalMeshNormals(VkCommandBuffer cmd, const VulkanBufferRef& src,
                                           const BufferDescriptor& srcDesc, const VulkanBufferRef& dst,
                                           const BufferDescriptor& dstDesc, const VulkanMeshNormalTable& table,
                                           int start, int end) {
    recordNormals(cmd, false, src, srcDesc, dst, dstDesc, table, start, end);
}

void VulkanLimitEvaluator::EvalMeshNormalsAndWait(const VulkanVertexBuffer& src, const BufferDescriptor& srcDesc,
                                                  const VulkanVertexBuffer& dst, const BufferDescriptor& dstDesc,
                                                  const VulkanMeshNormalTable& table, int start, int end) {
    int last = end;
    if (!detail::checkMeshNormalArguments(true, srcDesc, true, dstDesc, table.numVertices(), start, last)) return;
    checkFits("EvalMeshNormals", "source", &src, srcDesc, table.numVertices());
    checkFits("EvalMeshNormals", "destination", &dst, dstDesc, last);
    try {
        ctx_.submitAndWait([&](VkCommandBuffer cmd) {
            recordNormals(cmd, true, {src.buffer(), 0}, srcDesc, {dst.buffer(), 0}, dstDesc, table, start, end);
        });
    } catch (...) {
        resetWaited();
        throw;
    }
    resetWaited();
}

void VulkanLimitEvaluator::recordPatches(VkCommandBuffer cmd, bool waited, const VulkanBufferRef& src,
                                         const BufferDescriptor& srcDesc, const VulkanBufferRef& position,
                                         const BufferDescriptor& positionDesc, const VulkanBufferRef& normal,
                                         const BufferDescriptor& normalDesc, const VulkanLevelPatchTable& table) {
    const bool hasPosition = position.buffer != VK_NULL_HANDLE, hasNormal = normal.buffer != VK_NULL_HANDLE;
    detail::checkLevelPatchArguments(src.buffer != VK_NULL_HANDLE, srcDesc, hasPosition, positionDesc, hasNormal,
                                     normalDesc);
    const char* call = "EvalLevelPatches";
    if (!cmd) throw std::invalid_argument("EvalLevelPatches: null command buffer");
    if (table.device() != ctx_.device())
        throw std::invalid_argument("EvalLevelPatches: the table belongs to another VkDevice");
    const detail::Arena arena = waited ? detail::Arena::Waited : detail::Arena::Recorded;
    // Patches share a workgroup where their grids are smaller than it (shaders/level_patches.comp).
    const uint32_t group = ctx_.workgroupSize();
    const std::int64_t cells = std::int64_t(table.rate() + 1) * (table.rate() + 1);
    const std::int64_t perGroup = std::max<std::int64_t>(1, group / cells);
    const std::int64_t invocations = (table.numPatches() + perGroup - 1) / perGroup * group;
    if (invocations > INT32_MAX) throw std::invalid_argument("EvalLevelPatches: more than 2^31 invocations");
    if (invocations > 0) {
        const SourceBinding source = bindSource(ctx_, src, srcDesc, call);
        std::vector<VkDescriptorBufferInfo> infos;
        for (VkBuffer b : table.buffers()) infos.push_back({b, 0, VK_WHOLE_SIZE});
        infos.push_back(source.bound.info);
        std::vector<uint32_t> words{source.offset};
        std::vector<int32_t> constants{srcDesc.stride};
        const VulkanBufferRef outputs[2] = {position, normal};
        const BufferDescriptor* const descs[2] = {&positionDesc, &normalDesc};
        const int32_t mask =
            bindOutputs(ctx_, kernels_->unused.buffer.buffer(), outputs, descs, call, infos, words, constants);
        constants.push_back(mask);
        const bool tableTexels = table.texels()[0] != VK_NULL_HANDLE;
        constants.push_back(source.texels);
        constants.push_back(tableTexels);
        words.push_back(uint32_t(table.rate()));
        words.push_back(uint32_t(perGroup));
        words.push_back(uint32_t(table.numPatches()));
        std::vector<VkBufferView> texels(kPatchBindings.size(), VK_NULL_HANDLE);
        texels[kFirstPatchTexelBinding] = source.texels ? src.texels : kernels_->unused.floatTexels.view();
        texels[kFirstPatchTexelBinding + 1] = tableTexels ? table.texels()[0] : kernels_->unused.indexTexels.view();
        texels[kFirstPatchTexelBinding + 2] = tableTexels ? table.texels()[1] : kernels_->unused.uintTexels.view();
        texels[kFirstPatchTexelBinding + 3] = tableTexels ? table.texels()[2] : kernels_->unused.floatTexels.view();
        kernels_->patches.record(cmd, arena, infos, constants, words, 0, int(invocations), texels);
    }
    if (table.stencils().numStencils() == 0) return;
    // The stencils write from element numPatchOutputs on.
    auto shifted = [&](const BufferDescriptor& d, bool present) {
        if (!present) return d;
        const std::int64_t offset = d.offset + std::int64_t(table.numPatchOutputs()) * d.stride;
        if (offset > INT32_MAX) throw std::invalid_argument("EvalLevelPatches: an output's offset passes 2^31 floats");
        return BufferDescriptor(int(offset), d.length, d.stride);
    };
    const BufferDescriptor positionAfter = shifted(positionDesc, hasPosition), normalAfter = shifted(normalDesc, hasNormal);
    const VulkanBufferRef outputs[4] = {position, {}, {}, normal};
    const BufferDescriptor* const descs[4] = {&positionAfter, &positionAfter, &positionAfter, &normalAfter};
    recordLimit(cmd, waited, src, srcDesc, outputs, descs, table.stencils(), nullptr, 0, -1);
}

void VulkanLimitEvaluator::EvalLevelPatches(VkCommandBuffer cmd, const VulkanBufferRef& src,
                                            const BufferDescriptor& srcDesc, const VulkanBufferRef& position,
                                            const BufferDescriptor& positionDesc, const VulkanBufferRef& normal,
                                            const BufferDescriptor& normalDesc, const VulkanLevelPatchTable& table) {
    recordPatches(cmd, false, src, srcDesc, position, positionDesc, normal, normalDesc, table);
}

void VulkanLimitEvaluator::EvalLevelPatchesAndWait(const VulkanVertexBuffer& src, const BufferDescriptor& srcDesc,
                                                   const VulkanVertexBuffer* position,
                                                   const BufferDescriptor& positionDesc,
                                                   const VulkanVertexBuffer* normal, const BufferDescriptor& normalDesc,
                                                   const VulkanLevelPatchTable& table) {
    detail::checkLevelPatchArguments(true, srcDesc, position != nullptr, positionDesc, normal != nullptr, normalDesc);
    const char* call = "EvalLevelPatches";
    checkFits(call, "source", &src, srcDesc, table.numSourceVertices());
    checkFits(call, "position", position, positionDesc, table.numPoints());
    checkFits(call, "normal", normal, normalDesc, table.numPoints());
    try {
        ctx_.submitAndWait([&](VkCommandBuffer cmd) {
            recordPatches(cmd, true, {src.buffer(), 0, src.texels()}, srcDesc, refOf(position), positionDesc,
                          refOf(normal), normalDesc, table);
        });
    } catch (...) {
        resetWaited();
        throw;
    }
    resetWaited();
}

}  // namespace v0
}  // namespace quadtri
