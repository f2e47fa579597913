// `quadtri render IN.obj -o out.png`: the mesh refined by the chosen evaluator on the renderer's
// own device and drawn offscreen (docs/rendering.md), one labelled panel per scheme of --compare.
#include <cmath>
#include <cstdio>
#include <optional>
#include <ostream>
#include <stdexcept>

#include <quadtri/far/draw_buffers.h>
#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/osd/vulkan_evaluator.h>
#include <quadtri/osd/vulkan_limit_evaluator.h>
#include <quadtri/osd/vulkan_limit_tables.h>
#include "tools/commands.h"
#include "tools/render/gpu_device.h"
#include "tools/render/offscreen_target.h"
#include "tools/render/renderer.h"

namespace quadtri::cli {

namespace {

using render::Image;

render::Shading shadingNamed(const std::string& name) {
    const std::vector<std::string>& names = renderShadings();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return render::Shading(int(i));
    throw std::invalid_argument("unknown shading '" + name + "'");
}

// The refined level on the device: the evaluators' output buffers the draw reads, kept alive
// while it does.
struct DeviceSurface {
    std::optional<VulkanVertexBuffer> levels, limitPositions, normals;
    VulkanBufferRef positionRef, normalRef;
};

// Positions (all levels in one buffer, one dispatch per level), then the limit normals (and,
// with `limit`, positions) of the last level, all on the renderer's device.
DeviceSurface evaluateOnDevice(VulkanContext& ctx, const Refiner& refiner, int level, const std::vector<float>& control,
                               bool limit) {
    DeviceSurface s;
    const int numControl = int(control.size() / 3);
    std::vector<VulkanStencilTable> tables;
    tables.reserve(std::size_t(level));
    for (int L = 1; L <= level; ++L) tables.emplace_back(ctx, refiner.levelStencils(L));
    std::vector<const VulkanStencilTable*> pointers;
    for (const VulkanStencilTable& t : tables) pointers.push_back(&t);
    const std::vector<int> first = level > 0 ? VulkanEvaluator::levelFirstElements(pointers) : std::vector<int>{0, numControl};
    s.levels = VulkanVertexBuffer::create(ctx, first.back(), 3);
    s.levels->updateData(control.data(), 0, numControl);
    if (level > 0) VulkanEvaluator(ctx).EvalLevelsAndWait(*s.levels, BufferDescriptor(0, 3, 3), pointers);

    const int n = refiner.faces(level).numVertices();
    const BufferDescriptor levelDesc(3 * first[std::size_t(level)], 3, 3), packed(0, 3, 3);
    VulkanLimitEvaluator evaluator(ctx);
    const VulkanMeshNormalTable fallback(ctx, buildMeshNormalTable(refiner.faces(level)));
    const VulkanLimitStencilTable table(ctx, refiner.limitStencils(level));
    s.normals = VulkanVertexBuffer::create(ctx, n, 3);
    if (limit) s.limitPositions = VulkanVertexBuffer::create(ctx, n, 3);
    evaluator.EvalLimitStencilsAndWait(*s.levels, levelDesc, limit ? &*s.limitPositions : nullptr, packed, nullptr,
                                       packed, nullptr, packed, &*s.normals, packed, table, &fallback);
    s.positionRef = limit ? VulkanBufferRef{s.limitPositions->buffer(), 0}
                          : VulkanBufferRef{s.levels->buffer(), VkDeviceSize(first[std::size_t(level)]) * 12};
    s.normalRef = {s.normals->buffer(), 0};
    return s;
}

// The elements [first, first + count) of a device buffer of 3-float elements, in host memory.
std::vector<float> readElements(const VulkanVertexBuffer& buffer, int first, int count) {
    std::vector<float> all(buffer.numFloats());
    buffer.readBack(all.data());
    return {all.begin() + 3 * std::ptrdiff_t(first), all.begin() + 3 * std::ptrdiff_t(first + count)};
}

// One panel: `scheme`'s level drawn with `view`.
Image renderPanel(const RenderArgs& args, const io::ObjMesh& mesh, std::optional<Scheme> scheme,
                  VulkanContext& ctx, render::OffscreenTarget& target, render::Renderer& renderer,
                  render::ViewSettings view) {
    MeshArgs meshArgs = args.mesh;
    if (scheme) meshArgs.scheme = scheme;
    const Options options = makeOptions(meshArgs, mesh);
    Refiner refiner = makeRefiner(mesh, options);
    refiner.refineUniform(args.level);
    const LevelFaces faces = refiner.faces(args.level);

    // UVs (face-varying channel 0) per value of the level, on the CPU: they do not move.
    std::vector<float> uvs;
    DrawBuffers draw;
    if (refiner.numFVarChannels() > 0) {
        uvs = std::move(evaluateLevels(EvaluatorKind::Cpu, {fvarLevels(refiner, 0, args.level, mesh.uvs, 2)})[0]);
        draw = buildDrawBuffers(faces, {refiner.fvarValues(0, args.level).begin()}, {refiner.numFVarValues(0, args.level)});
    } else {
        draw = buildDrawBuffers(faces);
    }
    renderer.setSurface(draw, uvs.empty() ? nullptr : uvs.data(),
                        render::triangleOrigins(faces, refiner.faces(0), render::rootFaces(refiner, args.level), draw));

    std::optional<DeviceSurface> onDevice;
    Surface host;
    const bool curvature = view.shading == render::Shading::MeanCurvature;
    if (args.evaluator == EvaluatorKind::Vulkan) {
        onDevice = evaluateOnDevice(ctx, refiner, args.level, mesh.positions, args.limit);
        renderer.useVertexBuffers(onDevice->positionRef, onDevice->normalRef);
        if (curvature) {  // the curvature is computed on the CPU: only then are positions read back
            const int n = faces.numVertices();
            host.positions = onDevice->limitPositions
                                 ? readElements(*onDevice->limitPositions, 0, n)
                                 : readElements(*onDevice->levels, int(onDevice->positionRef.byteOffset / 12), n);
            host.normals = readElements(*onDevice->normals, 0, n);
        }
    } else {
        host = evaluateSurface(args.evaluator, refiner, args.level,
                               evaluateLevels(args.evaluator, refiner, args.level, mesh.positions), args.limit,
                               NormalKind::Limit);
        renderer.uploadVertices(host.positions.data(), host.normals.data(), faces.numVertices());
    }
    if (curvature) {
        const std::vector<float> h = render::meanCurvature(faces, host.positions.data(), host.normals.data());
        renderer.uploadCurvature(h);
        view.curvatureRange = args.curvatureRange.value_or(render::curvatureRange(h));
    }
    renderer.setCage(render::cageOf(refiner.level(0), mesh.positions.data()));
    Image image = target.render({0.13f, 0.14f, 0.16f, 1.0f}, [&](VkCommandBuffer cmd, VkExtent2D extent) {
        renderer.record(cmd, extent, view);
    });
    if (scheme) render::drawLabel(image, 8, 8, toString(*scheme), 2, {255, 255, 255});
    return image;
}

}  // namespace

int runRender(const RenderArgs& args) {
    if (args.output.empty()) throw io::ObjError("-o: the output file name is empty");
    io::ObjMesh mesh = loadMesh(args.mesh);
    if (args.creaseSharpness)
        for (float& s : mesh.creaseSharpness) s = *args.creaseSharpness;
    std::optional<Image> texture;
    if (!args.texture.empty()) texture = render::readImage(args.texture);
    const render::Shading shading = shadingNamed(args.shading);
    if (shading == render::Shading::Textured && !mesh.hasUVs())
        std::fprintf(stderr, "quadtri: warning: %s has no UVs (vt): textured shading shows it smooth\n",
                     args.mesh.input.c_str());

    std::optional<render::GpuDevice> gpu;
    try {
        gpu.emplace();
    } catch (const VulkanError& e) {
        throw std::runtime_error(std::string("render needs a Vulkan device: ") + e.what());
    }
    VulkanContext& ctx = gpu->context();
    render::OffscreenTarget target(ctx, uint32_t(args.width), uint32_t(args.height));
    render::Renderer renderer(ctx, target.renderPass());
    if (texture) renderer.setTexture(&*texture);

    render::ViewSettings view;
    view.shading = shading;
    view.showSurface = !args.hideSurface;
    view.showCage = args.cage;
    view.showPoints = args.points;
    view.stripes = args.stripes;
    view.camera.yawDegrees = args.yaw;
    view.camera.pitchDegrees = args.pitch;
    const render::BoundingSphere sphere = render::boundingSphere(mesh.positions.data(), mesh.numVertices());
    view.camera.frame(sphere, float(args.width) / float(args.height));
    view.sceneRadius = sphere.radius;
    view.light.direction = glm::vec3(args.lightDirection[0], args.lightDirection[1], args.lightDirection[2]);
    view.light.color = glm::vec3(args.lightColor[0], args.lightColor[1], args.lightColor[2]);

    std::vector<Image> panels;
    if (args.compare.empty())
        panels.push_back(renderPanel(args, mesh, std::nullopt, ctx, target, renderer, view));
    for (Scheme scheme : args.compare) panels.push_back(renderPanel(args, mesh, scheme, ctx, target, renderer, view));
    const Image image = panels.size() == 1 ? std::move(panels[0]) : render::sideBySide(panels);
    const std::vector<uint8_t> png = render::encodePng(image);
    io::writeReplacing(args.output, [&png](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
    });
    if (gpu->validationMessageCount() > 0)
        std::fprintf(stderr, "quadtri: the Vulkan validation layer reported %d problems\n", gpu->validationMessageCount());
    std::printf("%s: level %d, %s shading, %dx%d -> %s (Vulkan device %s)\n", args.mesh.input.c_str(), args.level,
                args.shading.c_str(), image.width, image.height, args.output.c_str(), gpu->deviceName().c_str());
    return 0;
}

}  // namespace quadtri::cli
