// `quadtri render IN.obj -o out.png`: the mesh refined by the chosen evaluator on the renderer's
// own device and drawn offscreen (docs/rendering.md), one labelled panel per scheme of --compare.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "tools/commands.h"
#include "tools/render/gpu_device.h"
#include "tools/render/legend.h"
#include "tools/render/level_surface.h"
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

// One panel's level, evaluated: on the renderer's device (Vulkan) or in host memory.
struct Panel {
    std::optional<Scheme> scheme;  // labelled when set
    Refiner refiner;
    std::vector<float> uvs;  // per value of face-varying channel 0 at the level
    std::optional<render::DeviceSurface> onDevice;
    Surface host;                  // CPU / oneTBB; with Vulkan only for the mean curvature
    std::vector<float> curvature;  // mean-curvature shading only
};

Panel preparePanel(const RenderArgs& args, const io::ObjMesh& mesh, std::optional<Scheme> scheme, VulkanContext& ctx,
                   bool curvature) {
    MeshArgs meshArgs = args.mesh;
    if (scheme) meshArgs.scheme = scheme;
    Panel p{scheme, makeRefiner(mesh, makeOptions(meshArgs, mesh)), {}, std::nullopt, {}, {}};
    p.refiner.refineUniform(args.level);
    // The UVs on the CPU: they do not move.
    if (p.refiner.numFVarChannels() > 0)
        p.uvs = std::move(evaluateLevels(EvaluatorKind::Cpu, {fvarLevels(p.refiner, 0, args.level, mesh.uvs, 2)})[0]);
    if (args.evaluator == EvaluatorKind::Vulkan) {
        p.onDevice.emplace(ctx, p.refiner, args.level, mesh.positions, args.limit);
        if (curvature) {  // computed on the CPU: only then are the positions read back
            p.host.positions = p.onDevice->readPositions();
            p.host.normals = p.onDevice->readNormals();
        }
    } else {
        p.host = evaluateSurface(args.evaluator, p.refiner, args.level,
                                 evaluateLevels(args.evaluator, p.refiner, args.level, mesh.positions), args.limit,
                                 NormalKind::Limit);
    }
    if (curvature)
        p.curvature =
            render::meanCurvature(p.refiner.faces(args.level), p.host.positions.data(), p.host.normals.data());
    return p;
}

// `legend`: with the cage, the sharpness colour code along the bottom.
Image drawPanel(const RenderArgs& args, const io::ObjMesh& mesh, const Panel& p, render::OffscreenTarget& target,
                render::Renderer& renderer, const render::ViewSettings& view, bool legend) {
    render::showLevel(renderer, p.refiner, args.level, p.uvs.empty() ? nullptr : p.uvs.data());
    if (p.onDevice)
        renderer.useVertexBuffers(p.onDevice->positions(), p.onDevice->normals());
    else
        renderer.uploadVertices(p.host.positions.data(), p.host.normals.data(),
                                p.refiner.faces(args.level).numVertices());
    if (!p.curvature.empty()) renderer.uploadCurvature(p.curvature);
    renderer.setCage(render::cageOf(p.refiner.level(0), mesh.positions.data()));
    Image image = render::downsample(
        target.render({0.13f, 0.14f, 0.16f, 1.0f},
                      [&](VkCommandBuffer cmd, VkExtent2D extent) { renderer.record(cmd, extent, view); }),
        args.supersample);
    std::string label = p.scheme ? toString(*p.scheme) : "";
    if (!args.label.empty()) label += (label.empty() ? "" : ", ") + args.label;
    if (!label.empty()) render::drawLabel(image, 8, 8, label, 2, {255, 255, 255});
    if (args.cage && legend) render::drawSharpnessLegend(image);
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
    const int k = args.supersample;
    render::OffscreenTarget target(ctx, uint32_t(k * args.width), uint32_t(k * args.height));
    render::Renderer renderer(ctx, target.renderPass());
    if (texture) renderer.setTexture(&*texture);

    render::ViewSettings view;
    view.shading = shading;
    view.showSurface = !args.hideSurface;
    view.showCage = args.cage;
    view.showPoints = args.points;
    view.stripes = args.stripes;
    view.edgeWidthPixels *= float(k);
    view.pointSizePixels *= float(k);
    view.camera.yawDegrees = args.yaw;
    view.camera.pitchDegrees = args.pitch;
    const render::BoundingSphere sphere = render::boundingSphere(mesh.positions.data(), mesh.numVertices());
    view.camera.frame(sphere, float(args.width) / float(args.height));
    view.sceneRadius = sphere.radius;
    view.light.direction = glm::vec3(args.lightDirection[0], args.lightDirection[1], args.lightDirection[2]);
    view.light.color = glm::vec3(args.lightColor[0], args.lightColor[1], args.lightColor[2]);

    const bool curvature = shading == render::Shading::MeanCurvature;
    std::vector<Panel> prepared;
    if (args.compare.empty()) prepared.push_back(preparePanel(args, mesh, std::nullopt, ctx, curvature));
    for (Scheme scheme : args.compare) prepared.push_back(preparePanel(args, mesh, scheme, ctx, curvature));
    // One colour range for every panel, so that they compare.
    view.curvatureRange = 0.0f;
    for (const Panel& p : prepared)
        view.curvatureRange = std::max(view.curvatureRange, render::curvatureRange(p.curvature));
    if (args.curvatureRange) view.curvatureRange = *args.curvatureRange;
    std::vector<Image> panels;
    for (const Panel& p : prepared) panels.push_back(drawPanel(args, mesh, p, target, renderer, view, panels.empty()));
    const Image image = panels.size() == 1 ? std::move(panels[0]) : render::sideBySide(panels);
    const std::vector<uint8_t> png = render::encodePng(image);
    io::writeReplacing(args.output, [&png](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
    });
    if (gpu->validationMessageCount() > 0)
        std::fprintf(stderr, "quadtri: the Vulkan validation layer reported %d problems\n",
                     gpu->validationMessageCount());
    std::printf("%s: level %d, %s shading, %dx%d -> %s (Vulkan device %s)\n", args.mesh.input.c_str(), args.level,
                args.shading.c_str(), image.width, image.height, args.output.c_str(), gpu->deviceName().c_str());
    return 0;
}

}  // namespace quadtri::cli
