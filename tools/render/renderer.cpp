#include "tools/render/renderer.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

namespace quadtri {
inline namespace v0 {
namespace shaders {
extern const uint32_t surface_vert[], surface_frag[], cage_edges_vert[], cage_points_vert[], color_frag[];
extern const std::size_t surface_vert_words, surface_frag_words, cage_edges_vert_words, cage_points_vert_words,
    color_frag_words;
}  // namespace shaders
}  // namespace v0
}  // namespace quadtri

namespace quadtri::render {

using detail::vkStruct;

namespace {

constexpr uint32_t kSurfaceBuffers = 7;  // positions, normals, triangles, vertexOf, uvs, curvature, origins
constexpr uint32_t kCageBuffers = 4;     // positions, edges, edge colours, point colours
constexpr VkMemoryPropertyFlags kHostMemory = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
constexpr int32_t kHasUVs = 1, kHasTexture = 2;

// The push constants of shaders/surface.* and shaders/cage_*.vert.
struct SurfaceConstants {
    float viewProjection[16];
    float eye[4];
    float lightDir[4];
    float lightColor[4];
    int32_t params[4];
};
static_assert(sizeof(SurfaceConstants) == 128, "the guaranteed push-constant size");
struct CageConstants {
    float viewProjection[16];
    float viewport[4];
    float eye[4];
};

VkShaderModule createModule(VkDevice device, const uint32_t* code, std::size_t words) {
    auto info = vkStruct<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    info.codeSize = words * sizeof(uint32_t);
    info.pCode = code;
    VkShaderModule module = VK_NULL_HANDLE;
    vkCheck(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
    return module;
}

VkDescriptorSetLayout createSetLayout(VkDevice device, uint32_t buffers, bool withSampler) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (uint32_t b = 0; b < buffers; ++b)
        bindings.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr});
    if (withSampler)
        bindings.push_back({buffers, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
    auto info = vkStruct<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    vkCheck(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout), "vkCreateDescriptorSetLayout");
    return layout;
}

VkPipelineLayout createPipelineLayout(VkDevice device, VkDescriptorSetLayout set, VkShaderStageFlags stages,
                                      uint32_t pushBytes) {
    VkPushConstantRange push{stages, 0, pushBytes};
    auto info = vkStruct<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    info.setLayoutCount = 1;
    info.pSetLayouts = &set;
    info.pushConstantRangeCount = 1;
    info.pPushConstantRanges = &push;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    vkCheck(vkCreatePipelineLayout(device, &info, nullptr, &layout), "vkCreatePipelineLayout");
    return layout;
}

// A triangle-list pipeline without vertex input (the shaders pull their data), depth tested,
// both faces drawn, viewport and scissor set at record time.
VkPipeline createPipeline(VkDevice device, VkRenderPass renderPass, VkSampleCountFlagBits samples,
                          VkPipelineLayout layout, VkShaderModule vertex, VkShaderModule fragment) {
    VkPipelineShaderStageCreateInfo stages[2];
    for (int i = 0; i < 2; ++i) {
        stages[i] = vkStruct<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
        stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
        stages[i].module = i == 0 ? vertex : fragment;
        stages[i].pName = "main";
    }
    auto vertexInput = vkStruct<VkPipelineVertexInputStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
    auto assembly = vkStruct<VkPipelineInputAssemblyStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    auto viewport = vkStruct<VkPipelineViewportStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    auto raster = vkStruct<VkPipelineRasterizationStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    auto multisample = vkStruct<VkPipelineMultisampleStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
    multisample.rasterizationSamples = samples;
    auto depth = vkStruct<VkPipelineDepthStencilStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
    depth.depthTestEnable = VK_TRUE;
    depth.depthWriteEnable = VK_TRUE;
    depth.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    VkPipelineColorBlendAttachmentState blendAttachment{};
    blendAttachment.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    auto blend = vkStruct<VkPipelineColorBlendStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
    blend.attachmentCount = 1;
    blend.pAttachments = &blendAttachment;
    const VkDynamicState dynamicStates[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    auto dynamic = vkStruct<VkPipelineDynamicStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamicStates;

    auto info = vkStruct<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = layout;
    info.renderPass = renderPass;
    info.subpass = 0;
    VkPipeline pipeline = VK_NULL_HANDLE;
    vkCheck(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline), "vkCreateGraphicsPipelines");
    return pipeline;
}

}  // namespace

// A sampled RGBA8 image, uploaded once.
struct Renderer::Texture {
    VkDevice device = VK_NULL_HANDLE;
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;

    Texture(VulkanContext& ctx, const Image& source) : device(ctx.device()) {
        try {
            create(ctx, source);
        } catch (...) {
            release();
            throw;
        }
    }
    ~Texture() { release(); }
    Texture(const Texture&) = delete;
    Texture& operator=(const Texture&) = delete;

    void create(VulkanContext& ctx, const Image& source) {
        const uint32_t w = uint32_t(source.width), h = uint32_t(source.height);
        auto ii = vkStruct<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
        ii.imageType = VK_IMAGE_TYPE_2D;
        ii.format = VK_FORMAT_R8G8B8A8_UNORM;
        ii.extent = {w, h, 1};
        ii.mipLevels = 1;
        ii.arrayLayers = 1;
        ii.samples = VK_SAMPLE_COUNT_1_BIT;
        ii.tiling = VK_IMAGE_TILING_OPTIMAL;
        ii.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        vkCheck(vkCreateImage(device, &ii, nullptr, &image), "vkCreateImage");
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device, image, &req);
        auto ai = vkStruct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        ai.allocationSize = req.size;
        ai.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        vkCheck(vkAllocateMemory(device, &ai, nullptr, &memory), "vkAllocateMemory");
        vkCheck(vkBindImageMemory(device, image, memory, 0), "vkBindImageMemory");
        auto vi = vkStruct<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        vi.image = image;
        vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vi.format = ii.format;
        vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCheck(vkCreateImageView(device, &vi, nullptr, &view), "vkCreateImageView");

        detail::DeviceBuffer staging(ctx, source.rgba.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, kHostMemory);
        std::memcpy(staging.map(), source.rgba.data(), source.rgba.size());
        ctx.submitAndWait([&](VkCommandBuffer cmd) {
            auto barrier = vkStruct<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
            barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.image = image;
            barrier.subresourceRange = vi.subresourceRange;
            barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
            barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                                 nullptr, 1, &barrier);
            VkBufferImageCopy copy{};
            copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            copy.imageExtent = ii.extent;
            vkCmdCopyBufferToImage(cmd, staging.buffer(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
            barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            barrier.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
            barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0,
                                 nullptr, 0, nullptr, 1, &barrier);
        });
    }

    void release() noexcept {
        if (view) vkDestroyImageView(device, view, nullptr);
        if (image) vkDestroyImage(device, image, nullptr);
        if (memory) vkFreeMemory(device, memory, nullptr);
        view = VK_NULL_HANDLE, image = VK_NULL_HANDLE, memory = VK_NULL_HANDLE;
    }
};

Renderer::Renderer(VulkanContext& ctx, VkRenderPass renderPass, VkSampleCountFlagBits samples) : ctx_(ctx) {
    VkDevice device = ctx_.device();
    try {
        createLayouts();
        createPipelines(renderPass, samples);
        empty_ = detail::DeviceBuffer(ctx_, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, kHostMemory);
        std::memset(empty_.map(), 0, 16);
        auto si = vkStruct<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
        si.magFilter = si.minFilter = VK_FILTER_LINEAR;
        si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
        vkCheck(vkCreateSampler(device, &si, nullptr, &sampler_), "vkCreateSampler");
        checker_ = std::make_unique<Texture>(ctx_, Image{1, 1, {255, 255, 255, 255}});
        createDescriptors();
    } catch (...) {
        destroy();
        throw;
    }
}

Renderer::~Renderer() { destroy(); }

void Renderer::destroy() noexcept {
    VkDevice device = ctx_.device();
    texture_.reset();
    checker_.reset();
    if (sampler_) vkDestroySampler(device, sampler_, nullptr);
    if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr);
    for (VkPipeline p : {surfacePipeline_, edgePipeline_, pointPipeline_})
        if (p) vkDestroyPipeline(device, p, nullptr);
    for (VkPipelineLayout l : {surfacePipelineLayout_, cagePipelineLayout_})
        if (l) vkDestroyPipelineLayout(device, l, nullptr);
    for (VkDescriptorSetLayout l : {surfaceLayout_, cageLayout_})
        if (l) vkDestroyDescriptorSetLayout(device, l, nullptr);
    sampler_ = VK_NULL_HANDLE, pool_ = VK_NULL_HANDLE;
    surfacePipeline_ = edgePipeline_ = pointPipeline_ = VK_NULL_HANDLE;
    surfacePipelineLayout_ = cagePipelineLayout_ = VK_NULL_HANDLE;
    surfaceLayout_ = cageLayout_ = VK_NULL_HANDLE;
}

void Renderer::createLayouts() {
    VkDevice device = ctx_.device();
    surfaceLayout_ = createSetLayout(device, kSurfaceBuffers, true);
    cageLayout_ = createSetLayout(device, kCageBuffers, false);
    surfacePipelineLayout_ = createPipelineLayout(device, surfaceLayout_,
                                                  VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                                                  sizeof(SurfaceConstants));
    cagePipelineLayout_ = createPipelineLayout(device, cageLayout_, VK_SHADER_STAGE_VERTEX_BIT, sizeof(CageConstants));
}

void Renderer::createPipelines(VkRenderPass renderPass, VkSampleCountFlagBits samples) {
    VkDevice device = ctx_.device();
    VkShaderModule modules[5] = {};
    try {
        modules[0] = createModule(device, shaders::surface_vert, shaders::surface_vert_words);
        modules[1] = createModule(device, shaders::surface_frag, shaders::surface_frag_words);
        modules[2] = createModule(device, shaders::cage_edges_vert, shaders::cage_edges_vert_words);
        modules[3] = createModule(device, shaders::cage_points_vert, shaders::cage_points_vert_words);
        modules[4] = createModule(device, shaders::color_frag, shaders::color_frag_words);
        surfacePipeline_ = createPipeline(device, renderPass, samples, surfacePipelineLayout_, modules[0], modules[1]);
        edgePipeline_ = createPipeline(device, renderPass, samples, cagePipelineLayout_, modules[2], modules[4]);
        pointPipeline_ = createPipeline(device, renderPass, samples, cagePipelineLayout_, modules[3], modules[4]);
    } catch (...) {
        for (VkShaderModule m : modules)
            if (m) vkDestroyShaderModule(device, m, nullptr);
        throw;
    }
    for (VkShaderModule m : modules) vkDestroyShaderModule(device, m, nullptr);
}

void Renderer::createDescriptors() {
    VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kSurfaceBuffers + kCageBuffers},
                                     {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
    auto pi = vkStruct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    pi.maxSets = 2;
    pi.poolSizeCount = 2;
    pi.pPoolSizes = sizes;
    vkCheck(vkCreateDescriptorPool(ctx_.device(), &pi, nullptr, &pool_), "vkCreateDescriptorPool");
    const VkDescriptorSetLayout layouts[2] = {surfaceLayout_, cageLayout_};
    auto ai = vkStruct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    ai.descriptorPool = pool_;
    ai.descriptorSetCount = 2;
    ai.pSetLayouts = layouts;
    VkDescriptorSet sets[2];
    vkCheck(vkAllocateDescriptorSets(ctx_.device(), &ai, sets), "vkAllocateDescriptorSets");
    surfaceSet_ = sets[0], cageSet_ = sets[1];
    writeSurfaceSet();
    writeCageSet();
}

namespace {

// Writes `buffers` (null handles: `fallback`) to bindings 0.. of `set`, whole ranges.
void writeBuffers(VkDevice device, VkDescriptorSet set, const std::vector<VkBuffer>& buffers, VkBuffer fallback) {
    std::vector<VkDescriptorBufferInfo> infos;
    for (VkBuffer b : buffers) infos.push_back({b ? b : fallback, 0, VK_WHOLE_SIZE});
    std::vector<VkWriteDescriptorSet> writes;
    for (std::size_t b = 0; b < infos.size(); ++b) {
        auto w = vkStruct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        w.dstSet = set;
        w.dstBinding = uint32_t(b);
        w.descriptorCount = 1;
        w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        w.pBufferInfo = &infos[b];
        writes.push_back(w);
    }
    vkUpdateDescriptorSets(device, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace

void Renderer::writeSurfaceSet() {
    writeBuffers(ctx_.device(), surfaceSet_,
                 {positions_.buffer, normals_.buffer, triangles_.buffer(), vertexOf_.buffer(), uvs_.buffer(),
                  curvature_.buffer(), origins_.buffer()},
                 empty_.buffer());
    VkDescriptorImageInfo image{sampler_, (texture_ ? texture_ : checker_)->view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    auto w = vkStruct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    w.dstSet = surfaceSet_;
    w.dstBinding = kSurfaceBuffers;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &image;
    vkUpdateDescriptorSets(ctx_.device(), 1, &w, 0, nullptr);
}

void Renderer::writeCageSet() {
    writeBuffers(ctx_.device(), cageSet_,
                 {cagePositions_.buffer(), cageEdges_.buffer(), edgeColors_.buffer(), pointColors_.buffer()},
                 empty_.buffer());
}

detail::DeviceBuffer Renderer::hostBuffer(const void* data, std::size_t bytes) const {
    detail::DeviceBuffer buffer(ctx_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, kHostMemory);
    if (bytes && data) std::memcpy(buffer.map(), data, bytes);
    return buffer;
}

void Renderer::setSurface(const DrawBuffers& draw, const float* uvValues, const std::vector<uint32_t>& triangleOrigins) {
    if (int(triangleOrigins.size()) != draw.numTriangles())
        throw std::invalid_argument("Renderer::setSurface: one origin per triangle expected");
    triangles_ = hostBuffer(draw.triangles.data(), draw.triangles.size() * sizeof(uint32_t));
    vertexOf_ = hostBuffer(draw.vertexOf.data(), draw.vertexOf.size() * sizeof(int));
    origins_ = hostBuffer(triangleOrigins.data(), triangleOrigins.size() * sizeof(uint32_t));
    hasUVs_ = uvValues && !draw.valueOf.empty();
    if (hasUVs_) {
        std::vector<float> uvs(2 * std::size_t(draw.numVertices()));
        for (std::size_t d = 0; d < std::size_t(draw.numVertices()); ++d) {
            const std::size_t value = std::size_t(draw.valueOf[0][d]);
            uvs[2 * d] = uvValues[2 * value], uvs[2 * d + 1] = uvValues[2 * value + 1];
        }
        uvs_ = hostBuffer(uvs.data(), uvs.size() * sizeof(float));
    } else {
        uvs_.reset();
    }
    numTriangles_ = draw.numTriangles();
    writeSurfaceSet();
}

void Renderer::useVertexBuffers(const VulkanBufferRef& positions, const VulkanBufferRef& normals) {
    if (positions.byteOffset % 4 || normals.byteOffset % 4)
        throw std::invalid_argument("Renderer::useVertexBuffers: byte offsets must be multiples of 4");
    positions_ = positions, normals_ = normals;
    ownPositions_.reset(), ownNormals_.reset();
    writeSurfaceSet();
}

void Renderer::uploadVertices(const float* positions, const float* normals, int numVertices) {
    const std::size_t bytes = 3 * std::size_t(numVertices) * sizeof(float);
    if (ownPositions_.size() != std::max<std::size_t>(bytes, 4)) {
        ownPositions_ = hostBuffer(positions, bytes);
        ownNormals_ = hostBuffer(nullptr, bytes);  // zero until given: flat shading needs none
        std::memset(ownNormals_.map(), 0, bytes);
        if (normals) std::memcpy(ownNormals_.map(), normals, bytes);
        positions_ = {ownPositions_.buffer(), 0}, normals_ = {ownNormals_.buffer(), 0};
        writeSurfaceSet();
        return;
    }
    std::memcpy(ownPositions_.map(), positions, bytes);
    if (normals) std::memcpy(ownNormals_.map(), normals, bytes);
}

void Renderer::uploadCurvature(const std::vector<float>& curvature) {
    curvature_ = hostBuffer(curvature.data(), curvature.size() * sizeof(float));
    writeSurfaceSet();
}

void Renderer::setCage(const Cage& cage) {
    cagePositions_ = hostBuffer(cage.positions.data(), cage.positions.size() * sizeof(float));
    cageEdges_ = hostBuffer(cage.edges.data(), cage.edges.size() * sizeof(uint32_t));
    edgeColors_ = hostBuffer(cage.edgeColors.data(), cage.edgeColors.size() * sizeof(glm::vec4));
    pointColors_ = hostBuffer(cage.pointColors.data(), cage.pointColors.size() * sizeof(glm::vec4));
    numEdges_ = int(cage.edges.size() / 2);
    numPoints_ = int(cage.positions.size() / 3);
    writeCageSet();
}

void Renderer::setTexture(const Image* image) {
    texture_ = image ? std::make_unique<Texture>(ctx_, *image) : nullptr;
    writeSurfaceSet();
}

void Renderer::record(VkCommandBuffer cmd, VkExtent2D extent, const ViewSettings& view, VkOffset2D origin) {
    const float aspect = float(extent.width) / float(std::max(extent.height, 1u));
    const glm::mat4 viewMatrix = view.camera.view();
    const glm::mat4 viewProjection = view.camera.projection(aspect, view.sceneRadius) * viewMatrix;
    const glm::vec3 eye = view.camera.eye();
    const VkViewport viewport{float(origin.x), float(origin.y), float(extent.width), float(extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{origin, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);

    if (view.showSurface && numTriangles_ > 0 && positions_.buffer) {
        SurfaceConstants c{};
        std::memcpy(c.viewProjection, glm::value_ptr(viewProjection), sizeof c.viewProjection);
        // The light is given in view space: it turns with the camera.
        const glm::vec3 light = glm::transpose(glm::mat3(viewMatrix)) * view.light.direction;
        const float eye4[4] = {eye.x, eye.y, eye.z, view.stripes};
        const float light4[4] = {light.x, light.y, light.z, view.curvatureRange};
        const float color4[4] = {view.light.color.r, view.light.color.g, view.light.color.b, 1.0f};
        std::memcpy(c.eye, eye4, sizeof eye4);
        std::memcpy(c.lightDir, light4, sizeof light4);
        std::memcpy(c.lightColor, color4, sizeof color4);
        const int32_t flags = (hasUVs_ ? kHasUVs : 0) | (texture_ ? kHasTexture : 0);
        c.params[0] = int32_t(view.shading);
        c.params[1] = int32_t(positions_.byteOffset / 4);
        c.params[2] = int32_t(normals_.byteOffset / 4);
        c.params[3] = flags;
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, surfacePipeline_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, surfacePipelineLayout_, 0, 1, &surfaceSet_, 0, nullptr);
        vkCmdPushConstants(cmd, surfacePipelineLayout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof c, &c);
        vkCmdDraw(cmd, uint32_t(3 * numTriangles_), 1, 0, 0);
    }

    const bool edges = view.showCage && numEdges_ > 0, points = view.showPoints && numPoints_ > 0;
    if (!edges && !points) return;
    CageConstants c{};
    std::memcpy(c.viewProjection, glm::value_ptr(viewProjection), sizeof c.viewProjection);
    const float viewport4[4] = {float(extent.width), float(extent.height), 0.5f * view.edgeWidthPixels,
                                0.5f * view.pointSizePixels};
    // Pulled towards the eye by a fraction of the scene, so that a cage lying on the surface
    // (an interpolating scheme's) shows.
    const float eye4[4] = {eye.x, eye.y, eye.z, 0.004f * view.sceneRadius};
    std::memcpy(c.viewport, viewport4, sizeof viewport4);
    std::memcpy(c.eye, eye4, sizeof eye4);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, cagePipelineLayout_, 0, 1, &cageSet_, 0, nullptr);
    vkCmdPushConstants(cmd, cagePipelineLayout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof c, &c);
    if (edges) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, edgePipeline_);
        vkCmdDraw(cmd, uint32_t(6 * numEdges_), 1, 0, 0);
    }
    if (points) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pointPipeline_);
        vkCmdDraw(cmd, uint32_t(6 * numPoints_), 1, 0, 0);
    }
}

}  // namespace quadtri::render
