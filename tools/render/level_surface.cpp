#include "tools/render/level_surface.h"

#include <quadtri/far/draw_buffers.h>
#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/osd/vulkan_limit_evaluator.h>
#include <quadtri/osd/vulkan_limit_tables.h>

namespace quadtri::render {

void showLevel(Renderer& renderer, const Refiner& refiner, int level, const float* uvValues,
               const std::vector<int>* elementOfVertex) {
    const LevelFaces faces = refiner.faces(level);
    const bool uvs = uvValues && refiner.numFVarChannels() > 0;
    DrawBuffers draw =
        uvs ? buildDrawBuffers(faces, {refiner.fvarValues(0, level).begin()}, {refiner.numFVarValues(0, level)})
            : buildDrawBuffers(faces);
    if (elementOfVertex)
        for (int& v : draw.vertexOf) v = (*elementOfVertex)[std::size_t(v)];
    renderer.setSurface(draw, uvs ? uvValues : nullptr,
                        triangleOrigins(faces, refiner.faces(0), rootFaces(refiner, level), draw));
}

DeviceSurface::DeviceSurface(VulkanContext& ctx, const Refiner& refiner, int level, const std::vector<float>& control,
                             bool limit) {
    const int numControl = int(control.size() / 3);
    std::vector<VulkanStencilTable> tables;
    tables.reserve(std::size_t(level));
    for (int L = 1; L <= level; ++L) tables.emplace_back(ctx, refiner.levelStencils(L));
    std::vector<const VulkanStencilTable*> pointers;
    for (const VulkanStencilTable& t : tables) pointers.push_back(&t);
    const std::vector<int> first =
        level > 0 ? VulkanEvaluator::levelFirstElements(pointers) : std::vector<int>{0, numControl};
    levels_ = VulkanVertexBuffer::create(ctx, first.back(), 3);
    levels_->updateData(control.data(), 0, numControl);
    if (level > 0) VulkanEvaluator(ctx).EvalLevelsAndWait(*levels_, BufferDescriptor(0, 3, 3), pointers);
    numVertices_ = refiner.faces(level).numVertices();
    firstVertex_ = first[std::size_t(level)];

    const BufferDescriptor levelDesc(3 * firstVertex_, 3, 3), packed(0, 3, 3);
    VulkanLimitEvaluator evaluator(ctx);
    const VulkanMeshNormalTable fallback(ctx, buildMeshNormalTable(refiner.faces(level)));
    const VulkanLimitStencilTable table(ctx, refiner.limitStencils(level));
    normals_ = VulkanVertexBuffer::create(ctx, numVertices_, 3);
    if (limit) limitPositions_ = VulkanVertexBuffer::create(ctx, numVertices_, 3);
    evaluator.EvalLimitStencilsAndWait(*levels_, levelDesc, limit ? &*limitPositions_ : nullptr, packed, nullptr,
                                       packed, nullptr, packed, &*normals_, packed, table, &fallback);
    positionRef_ = limit ? VulkanBufferRef{limitPositions_->buffer(), 0}
                         : VulkanBufferRef{levels_->buffer(), VkDeviceSize(firstVertex_) * 3 * sizeof(float)};
}

namespace {

std::vector<float> readElements(const VulkanVertexBuffer& buffer, int first, int count) {
    std::vector<float> all(buffer.numFloats());
    buffer.readBack(all.data());
    return {all.begin() + 3 * std::ptrdiff_t(first), all.begin() + 3 * std::ptrdiff_t(first + count)};
}

}  // namespace

std::vector<float> DeviceSurface::readPositions() const {
    return limitPositions_ ? readElements(*limitPositions_, 0, numVertices_)
                           : readElements(*levels_, firstVertex_, numVertices_);
}

std::vector<float> DeviceSurface::readNormals() const { return readElements(*normals_, 0, numVertices_); }

}  // namespace quadtri::render
