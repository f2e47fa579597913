#include <quadtri/osd/vulkan_limit_tables.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "osd/vulkan/vulkan_memory.h"

namespace quadtri {
inline namespace v0 {

namespace {

constexpr VkBufferUsageFlags kUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkMemoryPropertyFlags kLocal = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;

// Arrays (data, bytes) into device buffers of their own, one staging copy.
template <std::size_t N>
void uploadAll(VulkanContext& ctx, detail::DeviceBuffer (&to)[N], const void* const (&data)[N],
               const std::size_t (&bytes)[N], VkBufferUsageFlags extraUsage = 0) {
    std::vector<detail::CopyRegion> regions;
    for (std::size_t k = 0; k < N; ++k) {
        to[k] = detail::DeviceBuffer(ctx, bytes[k], kUsage | extraUsage, kLocal);
        if (bytes[k]) regions.push_back({to[k].buffer(), 0, data[k], nullptr, bytes[k]});
    }
    detail::upload(ctx, regions);
}

// Why the shader would read or write outside `t`'s arrays, or "" where it would not.
std::string inconsistency(const LevelPatchTable& t) {
    const std::size_t patches = t.patchBasis.size();
    const int levels = t.level - t.patchLevel;
    if (levels < 1 || levels > 30 || (1 << levels) > LevelPatchTable::kMaxRate)
        return "level " + std::to_string(t.level) + " from " + std::to_string(t.patchLevel);
    const std::size_t lines = std::size_t(t.rate()) + 1;
    if (t.pointOffsets.size() != patches + 1 || t.outputOffsets.size() != patches + 1 || t.pointOffsets[0] != 0 ||
        t.outputOffsets[0] != 0 || std::size_t(t.pointOffsets.back()) != t.patchPoints.size() ||
        std::size_t(t.outputOffsets.back()) != t.outputCells.size() || t.outputCells.size() != t.outputVertices.size() ||
        t.curveWeights.size() != 8 * lines || t.boxSplineWeights.size() != 36 * lines * lines ||
        t.stencilVertices.size() != std::size_t(t.stencils.numStencils()) ||
        t.stencils.numSourceVertices != t.numSourceVertices ||
        std::int64_t(t.outputVertices.size()) + t.stencils.numStencils() != t.numPoints)
        return "array lengths";
    for (std::size_t p = 0; p < patches; ++p) {
        const bool bSpline = t.patchBasis[p] == LevelPatchTable::Basis::BSpline;
        if (!bSpline && t.patchBasis[p] != LevelPatchTable::Basis::BoxSpline) return "patch " + std::to_string(p) + "'s basis";
        if (t.pointOffsets[p + 1] - t.pointOffsets[p] != (bSpline ? 16 : 12))
            return "patch " + std::to_string(p) + "'s point count";
        if (t.outputOffsets[p + 1] < t.outputOffsets[p]) return "patch " + std::to_string(p) + "'s outputs";
    }
    for (int v : t.patchPoints)
        if (v < 0 || v >= t.numSourceVertices) return "patch point " + std::to_string(v) + " outside level " + std::to_string(t.patchLevel);
    for (std::uint16_t cell : t.outputCells)
        if (std::size_t(cell & 0xff) >= lines || std::size_t(cell >> 8) >= lines) return "grid cell " + std::to_string(cell);
    return "";
}

}  // namespace

struct VulkanMeshNormalTable::Arrays {
    detail::DeviceBuffer buffers[4];
};

VulkanMeshNormalTable::VulkanMeshNormalTable(VulkanContext& ctx, const MeshNormalTable& t)
    : device_(ctx.device()), numVertices_(t.numVertices), arrays_(std::make_unique<Arrays>()) {
    if (t.faceOffsets.empty() || std::size_t(t.faceOffsets.back()) != t.faceCorners.size() ||
        t.vertexFaceOffsets.size() != std::size_t(t.numVertices) + 1 ||
        std::size_t(t.vertexFaceOffsets.back()) != t.vertexFaces.size())
        throw std::invalid_argument("VulkanMeshNormalTable: inconsistent MeshNormalTable arrays");
    const std::vector<int>* arrays[4] = {&t.faceOffsets, &t.faceCorners, &t.vertexFaceOffsets, &t.vertexFaces};
    uploadAll(ctx, arrays_->buffers, {arrays[0]->data(), arrays[1]->data(), arrays[2]->data(), arrays[3]->data()},
              {arrays[0]->size() * sizeof(int), arrays[1]->size() * sizeof(int), arrays[2]->size() * sizeof(int),
               arrays[3]->size() * sizeof(int)});
    for (int k = 0; k < 4; ++k) handles_[k] = arrays_->buffers[k].buffer();
}

VulkanMeshNormalTable::~VulkanMeshNormalTable() = default;
VulkanMeshNormalTable::VulkanMeshNormalTable(VulkanMeshNormalTable&&) noexcept = default;
VulkanMeshNormalTable& VulkanMeshNormalTable::operator=(VulkanMeshNormalTable&&) noexcept = default;

struct VulkanLevelPatchTable::Arrays {
    detail::DeviceBuffer buffers[6];
    detail::TexelView texels[3];
};

namespace {

// Checks `t` before anything is uploaded.
VkDevice checkedDevice(VulkanContext& ctx, const LevelPatchTable& t) {
    const std::string why = inconsistency(t);
    if (!why.empty()) throw std::invalid_argument("VulkanLevelPatchTable: inconsistent LevelPatchTable (" + why + ")");
    return ctx.device();
}

}  // namespace

VulkanLevelPatchTable::VulkanLevelPatchTable(VulkanContext& ctx, const LevelPatchTable& t)
    : device_(checkedDevice(ctx, t)), numPoints_(t.numPoints), numSourceVertices_(t.numSourceVertices),
      numPatches_(t.numPatches()), numPatchOutputs_(t.numPatchOutputs()), rate_(t.rate()),
      arrays_(std::make_unique<Arrays>()), stencils_(ctx, t.stencils) {
    std::vector<int> basis(t.patchBasis.size());
    for (std::size_t p = 0; p < basis.size(); ++p) basis[p] = t.patchBasis[p] == LevelPatchTable::Basis::BSpline ? 0 : 1;
    // The cells padded to whole words: the shader reads output o from word o / 2.
    std::vector<std::uint16_t> cells(t.outputCells);
    cells.resize(cells.size() + cells.size() % 2, 0);
    auto bytesOf = [](const auto& v) { return v.size() * sizeof(v[0]); };
    uploadAll(ctx, arrays_->buffers,
              {basis.data(), t.pointOffsets.data(), t.patchPoints.data(), t.outputOffsets.data(), cells.data(),
               t.boxSplineWeights.data()},
              {bytesOf(basis), bytesOf(t.pointOffsets), bytesOf(t.patchPoints), bytesOf(t.outputOffsets), bytesOf(cells),
               bytesOf(t.boxSplineWeights)},
              VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
    for (int k = 0; k < 6; ++k) handles_[k] = arrays_->buffers[k].buffer();
    // Texel views only where the device's limit allows them: the shader reads the storage
    // buffers otherwise.
    const std::size_t limit = ctx.texelBufferLimit();
    if (t.patchPoints.size() <= limit && cells.size() / 2 <= limit && t.boxSplineWeights.size() <= limit) {
        arrays_->texels[0] = detail::TexelView(ctx, arrays_->buffers[2], VK_FORMAT_R32_SINT);
        arrays_->texels[1] = detail::TexelView(ctx, arrays_->buffers[4], VK_FORMAT_R32_UINT);
        arrays_->texels[2] = detail::TexelView(ctx, arrays_->buffers[5], VK_FORMAT_R32_SFLOAT);
        for (int k = 0; k < 3; ++k) texelHandles_[k] = arrays_->texels[k].view();
    }
}

VulkanLevelPatchTable::~VulkanLevelPatchTable() = default;
VulkanLevelPatchTable::VulkanLevelPatchTable(VulkanLevelPatchTable&&) noexcept = default;
VulkanLevelPatchTable& VulkanLevelPatchTable::operator=(VulkanLevelPatchTable&&) noexcept = default;

}  // namespace v0
}  // namespace quadtri
