// The offscreen renderer on lavapipe (or any device) with the Khronos validation layer on, which
// must stay silent: images checked against what the CPU computes from the same mesh and camera
// (silhouette coverage, where a crease may change the picture), and the shading modes' own
// properties (two-toned stripes, checker colours, face origins, curvature of a sphere).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include <quadtri/far/draw_buffers.h>
#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/vulkan_evaluator.h>
#include <quadtri/osd/vulkan_limit_evaluator.h>
#include <quadtri/osd/vulkan_limit_tables.h>
#include "tests/test_support.h"
#include "tests/osd/vulkan_test_support.h"
#include "tools/render/gpu_device.h"
#include "tools/render/level_surface.h"
#include "tools/render/offscreen_target.h"
#include "tools/render/renderer.h"

namespace quadtri::test {
namespace {

using render::Image;

constexpr int kSize = 256;
const std::array<float, 4> kBackground{1.0f, 0.0f, 1.0f, 1.0f};  // magenta: no shading makes it

bool isBackground(const uint8_t* p) { return p[0] == 255 && p[1] == 0 && p[2] == 255; }

// A mesh refined on the CPU: level `level`'s positions and limit normals.
struct Scene {
    io::ObjMesh mesh;
    std::unique_ptr<Refiner> refiner;
    int level = 0;
    std::vector<float> positions, normals, uvs;
};

Scene makeScene(io::ObjMesh mesh, int level, Options base = Options()) {
    Scene s;
    s.mesh = std::move(mesh);
    s.level = level;
    FVarChannel channel;
    s.refiner = std::make_unique<Refiner>(s.mesh.descriptor(channel), s.mesh.applyTags(base));
    s.refiner->refineUniform(level);
    s.positions = evaluateLevels(*s.refiner, s.mesh.positions, 3)[std::size_t(level)];
    s.normals.assign(s.positions.size(), 0.0f);
    const BufferDescriptor d(0, 3, 3);
    const MeshNormalTable fallback = buildMeshNormalTable(s.refiner->faces(level));
    CpuEvaluator::EvalLimitStencils(s.positions.data(), d, nullptr, d, nullptr, d, nullptr, d, s.normals.data(), d,
                                    s.refiner->limitStencils(level), &fallback);
    if (s.refiner->numFVarChannels() > 0)
        s.uvs = evaluateChannelLevels(*s.refiner, 0, s.mesh.uvs, 2)[std::size_t(level)];
    return s;
}

Scene sceneOf(const std::string& relativePath, int level, Options base = Options()) {
    return makeScene(io::readObj(meshPath(relativePath)), level, base);
}

render::ViewSettings viewOf(const Scene& s, render::Shading shading, float yaw = 30.0f, float pitch = 20.0f) {
    render::ViewSettings view;
    view.shading = shading;
    view.showCage = false;
    view.camera.yawDegrees = yaw;
    view.camera.pitchDegrees = pitch;
    const render::BoundingSphere sphere = render::boundingSphere(s.mesh.positions.data(), s.mesh.numVertices());
    view.camera.frame(sphere, 1.0f);
    view.sceneRadius = sphere.radius;
    return view;
}

// Pixel coordinates (x right, y down, pixel centres at +0.5) of level vertices under the view.
std::vector<glm::vec2> project(const std::vector<float>& xyz, const render::ViewSettings& view, int w, int h) {
    const glm::mat4 m = view.camera.projection(float(w) / float(h), view.sceneRadius) * view.camera.view();
    std::vector<glm::vec2> out;
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
        const glm::vec4 c = m * glm::vec4(xyz[i], xyz[i + 1], xyz[i + 2], 1.0f);
        out.emplace_back((c.x / c.w + 1.0f) * 0.5f * float(w), (c.y / c.w + 1.0f) * 0.5f * float(h));
    }
    return out;
}

// Pixels whose centre lies in a projected triangle of the scene's level (edges included).
int silhouettePixels(const Scene& s, const render::ViewSettings& view, int w, int h) {
    const std::vector<glm::vec2> p = project(s.positions, view, w, h);
    std::vector<uint8_t> covered(std::size_t(w) * std::size_t(h), 0);
    const DrawBuffers draw = buildDrawBuffers(s.refiner->faces(s.level));
    auto edge = [](glm::vec2 a, glm::vec2 b, glm::vec2 q) {
        return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
    };
    for (int t = 0; t < draw.numTriangles(); ++t) {
        glm::vec2 v[3];
        for (int k = 0; k < 3; ++k)
            v[k] = p[std::size_t(draw.vertexOf[draw.triangles[3 * std::size_t(t) + std::size_t(k)]])];
        const int x0 = std::max(0, int(std::floor(std::min({v[0].x, v[1].x, v[2].x}))));
        const int x1 = std::min(w - 1, int(std::ceil(std::max({v[0].x, v[1].x, v[2].x}))));
        const int y0 = std::max(0, int(std::floor(std::min({v[0].y, v[1].y, v[2].y}))));
        const int y1 = std::min(h - 1, int(std::ceil(std::max({v[0].y, v[1].y, v[2].y}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 q(float(x) + 0.5f, float(y) + 0.5f);
                const float e0 = edge(v[0], v[1], q), e1 = edge(v[1], v[2], q), e2 = edge(v[2], v[0], q);
                if ((e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0))
                    covered[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 1;
            }
    }
    return int(std::count(covered.begin(), covered.end(), uint8_t(1)));
}

int surfacePixels(const Image& image) {
    int n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) n += isBackground(image.pixel(x, y)) ? 0 : 1;
    return n;
}

class RenderTest : public ::testing::Test {
protected:
    void SetUp() override {
        enableValidation();
        try {
            gpu = std::make_unique<render::GpuDevice>();
        } catch (const VulkanError& e) {
            if (vulkanRequired()) FAIL() << "QUADTRI_REQUIRE_VULKAN is set but Vulkan is unusable: " << e.what();
            GTEST_SKIP() << "no Vulkan device (" << e.what() << "); set QUADTRI_REQUIRE_VULKAN=1 to fail instead";
        }
        pinVulkanLibraries();
        std::printf("Vulkan device: %s, validation layer %s\n", gpu->deviceName().c_str(),
                    gpu->validationEnabled() ? "on" : "off");
        if (vulkanRequired()) {
            EXPECT_TRUE(gpu->validationEnabled()) << "the Khronos validation layer is not installed";
        }
        target = std::make_unique<render::OffscreenTarget>(gpu->context(), kSize, kSize);
        renderer = std::make_unique<render::Renderer>(gpu->context(), target->renderPass());
    }
    void TearDown() override {
        if (!gpu) return;
        renderer.reset();
        target.reset();
        gpu.reset();
        EXPECT_EQ(render::GpuDevice::totalValidationMessageCount(), 0)
            << "the validation layer reported problems (above)";
    }

    // The scene's level drawn with its CPU positions and normals.
    Image draw(const Scene& s, const render::ViewSettings& view) {
        render::showLevel(*renderer, *s.refiner, s.level, s.uvs.empty() ? nullptr : s.uvs.data());
        renderer->uploadVertices(s.positions.data(), s.normals.data(), int(s.positions.size() / 3));
        renderer->setCage(render::cageOf(s.refiner->level(0), s.mesh.positions.data()));
        return target->render(kBackground,
                              [&](VkCommandBuffer cmd, VkExtent2D extent) { renderer->record(cmd, extent, view); });
    }

    std::unique_ptr<render::GpuDevice> gpu;
    std::unique_ptr<render::OffscreenTarget> target;
    std::unique_ptr<render::Renderer> renderer;
};

TEST_F(RenderTest, CornersAreBackgroundAndCoverageMatchesTheProjectedSilhouette) {
    for (const char* path : {"mixed/mixed_torus.obj", "osd/catmark_cube.obj", "mixed/cylinder_capped.obj"}) {
        for (render::Shading shading : {render::Shading::Smooth, render::Shading::Flat}) {
            const Scene s = sceneOf(path, 2);
            const render::ViewSettings view = viewOf(s, shading, 35.0f, 25.0f);
            const Image image = draw(s, view);
            ASSERT_EQ(image.width, kSize);
            ASSERT_EQ(image.height, kSize);
            for (auto [x, y] : {std::pair{0, 0}, {kSize - 1, 0}, {0, kSize - 1}, {kSize - 1, kSize - 1}})
                EXPECT_TRUE(isBackground(image.pixel(x, y))) << path << ": corner " << x << "," << y;
            const int expected = silhouettePixels(s, view, kSize, kSize);
            const int drawn = surfacePixels(image);
            EXPECT_GT(expected, kSize * kSize / 10) << path << ": the mesh should fill a good part of the view";
            EXPECT_NEAR(drawn, expected, 0.02 * expected) << path << " shading " << int(shading);
        }
    }
}

TEST_F(RenderTest, ARectangleOfTheFramebufferHoldsItsOwnView) {
    // The left half only, e.g. one of two schemes side by side in a window.
    const Scene s = sceneOf("mixed/mixed_torus.obj", 2);
    render::ViewSettings view = viewOf(s, render::Shading::Smooth);
    view.camera.frame(render::boundingSphere(s.mesh.positions.data(), s.mesh.numVertices()), 0.5f);
    render::showLevel(*renderer, *s.refiner, s.level, nullptr);
    renderer->uploadVertices(s.positions.data(), s.normals.data(), int(s.positions.size() / 3));
    const VkRect2D left{{0, 0}, {kSize / 2, kSize}};
    const Image image =
        target->render(kBackground, [&](VkCommandBuffer cmd, VkExtent2D) { renderer->record(cmd, left, view); });
    int inRight = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = kSize / 2; x < kSize; ++x) inRight += isBackground(image.pixel(x, y)) ? 0 : 1;
    EXPECT_EQ(inRight, 0) << "pixels drawn outside the rectangle";
    const int expected = silhouettePixels(s, view, kSize / 2, kSize);
    EXPECT_GT(expected, kSize * kSize / 20);
    EXPECT_NEAR(surfacePixels(image), expected, 0.02 * expected);
}

TEST_F(RenderTest, TheVulkanEvaluatorsBuffersDrawTheSameImage) {
    const Scene s = sceneOf("mixed/mixed_torus.obj", 3);
    const render::ViewSettings view = viewOf(s, render::Shading::Smooth);
    // With --limit the CPU draws the limit positions it evaluates from the level's.
    std::vector<float> limit(s.positions.size());
    const BufferDescriptor d(0, 3, 3);
    CpuEvaluator::EvalLimitStencils(s.positions.data(), d, limit.data(), d, nullptr, d, nullptr, d, nullptr, d,
                                    s.refiner->limitStencils(s.level));
    for (bool onLimit : {false, true}) {
        render::showLevel(*renderer, *s.refiner, s.level, nullptr);
        renderer->uploadVertices(onLimit ? limit.data() : s.positions.data(), s.normals.data(),
                                 int(s.positions.size() / 3));
        auto record = [&](VkCommandBuffer cmd, VkExtent2D extent) { renderer->record(cmd, extent, view); };
        const Image cpu = target->render(kBackground, record);
        const render::DeviceSurface onDevice(gpu->context(), *s.refiner, s.level, s.mesh.positions, onLimit);
        renderer->useVertexBuffers(onDevice.positions(), onDevice.normals());
        const Image vulkan = target->render(kBackground, record);
        int different = 0;
        for (std::size_t i = 0; i < cpu.rgba.size(); i += 4)
            different +=
                std::abs(int(cpu.rgba[i]) - int(vulkan.rgba[i])) > 2 || cpu.rgba[i + 1] != vulkan.rgba[i + 1] ? 1 : 0;
        EXPECT_LT(different, kSize * kSize / 1000)
            << "pixels that differ between the CPU and Vulkan evaluators' buffers" << (onLimit ? ", on the limit" : "");
        EXPECT_GT(surfacePixels(vulkan), kSize * kSize / 10);
    }
}

TEST_F(RenderTest, OneSubmissionEvaluatesAndDrawsAFrame) {
    // The real-time loop's frame: the factorized table applied to the control points, the limit
    // normals from the result, the draw of both buffers, all in one command buffer.
    const Scene s = sceneOf("mixed/mixed_torus.obj", 3);
    const render::ViewSettings view = viewOf(s, render::Shading::Smooth);
    const Image expected = draw(s, view);
    VulkanContext& ctx = gpu->context();
    const VulkanStencilTable table(ctx, s.refiner->factorizedStencils(s.level));
    const VulkanLimitStencilTable limit(ctx, s.refiner->limitStencils(s.level));
    const VulkanMeshNormalTable fallback(ctx, buildMeshNormalTable(s.refiner->faces(s.level)));
    const int n = int(s.positions.size() / 3);
    VulkanVertexBuffer control = VulkanVertexBuffer::create(ctx, s.mesh.numVertices(), 3);
    control.updateData(s.mesh.positions.data(), 0, s.mesh.numVertices());
    VulkanVertexBuffer positions = VulkanVertexBuffer::create(ctx, n, 3);
    VulkanVertexBuffer normals = VulkanVertexBuffer::create(ctx, n, 3);
    VulkanEvaluator evaluator(ctx);
    VulkanLimitEvaluator limitEvaluator(ctx);
    render::showLevel(*renderer, *s.refiner, s.level, nullptr);
    renderer->useVertexBuffers({positions.buffer(), 0}, {normals.buffer(), 0});
    const BufferDescriptor d(0, 3, 3);
    const Image frame = target->render(
        kBackground, [&](VkCommandBuffer cmd, VkExtent2D extent) { renderer->record(cmd, extent, view); },
        [&](VkCommandBuffer cmd) {
            evaluator.EvalStencils(cmd, control, d, positions, d, table);
            limitEvaluator.EvalLimitStencils(cmd, {positions.buffer(), 0}, d, {}, d, {}, d, {}, d,
                                             {normals.buffer(), 0}, d, limit, &fallback);
            render::barrierBeforeDraw(cmd);
        });
    evaluator.resetDescriptorSets();
    limitEvaluator.resetDescriptorSets();
    int different = 0;
    for (std::size_t i = 0; i < frame.rgba.size(); i += 4)
        different += std::abs(int(frame.rgba[i]) - int(expected.rgba[i])) > 2 ? 1 : 0;
    EXPECT_LT(different, kSize * kSize / 1000) << "pixels that differ from the CPU's frame";
    EXPECT_GT(surfacePixels(frame), kSize * kSize / 10);
}

// A capped tube along y: `rings` + 1 rings of 8 vertices (y from -2 to 2, radius 1) joined by
// quads, each end closed by a triangle fan; the bottom rim's edges creased at `sharpness` (none
// when 0).
io::ObjMesh tube(int rings, float sharpness) {
    std::ostringstream obj;
    for (int j = 0; j <= rings; ++j)
        for (int k = 0; k < 8; ++k) {
            const double a = 2.0 * M_PI * k / 8.0;
            obj << "v " << std::cos(a) << " " << (-2.0 + 4.0 * j / rings) << " " << std::sin(a) << "\n";
        }
    const int bottom = 8 * (rings + 1) + 1, top = bottom + 1;  // 1-based
    obj << "v 0 -2 0\nv 0 2 0\n";
    auto at = [](int j, int k) { return 8 * j + (k % 8) + 1; };
    for (int j = 0; j < rings; ++j)
        for (int k = 0; k < 8; ++k)
            obj << "f " << at(j, k) << " " << at(j + 1, k) << " " << at(j + 1, k + 1) << " " << at(j, k + 1) << "\n";
    for (int k = 0; k < 8; ++k) {
        obj << "f " << bottom << " " << at(0, k) << " " << at(0, k + 1) << "\n";
        obj << "f " << top << " " << at(rings, k + 1) << " " << at(rings, k) << "\n";
    }
    if (sharpness > 0)
        for (int k = 0; k < 8; ++k)
            obj << "t crease 2/1/0 " << at(0, k) - 1 << " " << at(0, k + 1) - 1 << " " << sharpness << "\n";
    std::istringstream in(obj.str());
    return io::parseObj(in, "tube.obj");
}

// Distance from q to the closed polyline `loop`.
float distanceToLoop(glm::vec2 q, const std::vector<glm::vec2>& loop) {
    float best = 1e30f;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const glm::vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
        const float t = std::clamp(glm::dot(q - a, b - a) / std::max(glm::dot(b - a, b - a), 1e-12f), 0.0f, 1.0f);
        best = std::min(best, glm::length(q - (a + t * (b - a))));
    }
    return best;
}

TEST_F(RenderTest, ACreaseChangesThePictureNearItAndNowhereFarFromIt) {
    constexpr int kRings = 10;
    for (Scheme scheme : {Scheme::CatmullClark, Scheme::SchaeferWarren}) {
        Options options;
        options.scheme = scheme;
        const Scene smooth = makeScene(tube(kRings, 0.0f), 3, options);
        const Scene creased = makeScene(tube(kRings, 10.0f), 3, options);
        // Level with the tube's middle: the rim and the rings above it project as flat ellipses
        // stacked one above the other, none crossing another.
        const render::ViewSettings view = viewOf(smooth, render::Shading::Smooth, 30.0f, 0.0f);
        const Image a = draw(smooth, view), b = draw(creased, view);
        // The crease: the bottom rim, on screen. The support of the rim's vertices reaches two
        // rings of faces up the tube; ring 5 (half way) is well beyond it.
        const std::vector<glm::vec2> control = project(smooth.mesh.positions, view, kSize, kSize);
        const std::vector<glm::vec2> rim(control.begin(), control.begin() + 8);
        float far = 1e30f;
        for (int k = 0; k < 8; ++k) far = std::min(far, distanceToLoop(control[std::size_t(8 * 5 + k)], rim));
        constexpr float kNear = 10.0f;
        int near = 0, farAway = 0, total = 0, farSurface = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
                const float d = distanceToLoop(glm::vec2(float(x) + 0.5f, float(y) + 0.5f), rim);
                farSurface += d > far && !isBackground(p) ? 1 : 0;
                if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) continue;
                ++total;
                near += d <= kNear ? 1 : 0;
                farAway += d > far ? 1 : 0;
            }
        ASSERT_GT(far, 3 * kNear) << "the view separates the rim from the tube's middle";
        EXPECT_GT(farSurface, 2000) << "the tube's upper half is in view";
        EXPECT_GT(near, 100) << toString(scheme) << ": pixels changed within " << kNear << " px of the crease";
        EXPECT_EQ(farAway, 0) << toString(scheme) << ": pixels changed beyond " << far << " px of the crease, of "
                              << total;
    }
}

TEST_F(RenderTest, ReflectionLinesAreTwoTonedStripes) {
    for (Scheme scheme : {Scheme::SchaeferWarren, Scheme::CatmullClark}) {
        Options options;
        options.scheme = scheme;
        const Scene s = sceneOf("mixed/mixed_torus.obj", 3, options);
        render::ViewSettings view = viewOf(s, render::Shading::ReflectionLines);
        view.stripes = 12.0f;
        const Image image = draw(s, view);
        std::map<uint32_t, int> colors;
        int surface = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const uint8_t* p = image.pixel(x, y);
                if (isBackground(p)) continue;
                ++surface;
                ++colors[uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]];
            }
        std::vector<std::pair<int, uint32_t>> byCount;
        for (auto [color, count] : colors) byCount.emplace_back(count, color);
        std::sort(byCount.rbegin(), byCount.rend());
        ASSERT_GE(byCount.size(), 2u);
        EXPECT_GE(byCount[0].first + byCount[1].first, 0.98 * surface) << toString(scheme) << ": two tones";
        const uint32_t dark = std::min(byCount[0].second, byCount[1].second);
        const uint32_t light = std::max(byCount[0].second, byCount[1].second);
        EXPECT_GT((light & 0xff) - (dark & 0xff), 150u) << "the tones contrast";
        // Stripes: the tone changes several times along scan lines across the surface.
        for (int y : {kSize / 4, kSize / 2, 3 * kSize / 4}) {
            int transitions = 0;
            uint32_t previous = 0;
            for (int x = 0; x < kSize; ++x) {
                const uint8_t* p = image.pixel(x, y);
                const uint32_t c = uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2];
                if (c != dark && c != light) continue;
                if (previous && c != previous) ++transitions;
                previous = c;
            }
            EXPECT_GE(transitions, 4) << toString(scheme) << ": stripes along row " << y;
        }
    }
}

TEST_F(RenderTest, FaceTypeShowsTheTriangleAndQuadHalvesOfTheTorus) {
    // mixed_torus: quads on one half, triangles on the other; orange (red > blue) for faces from
    // triangles, blue (blue > red) for faces from quads, nothing green.
    const Scene s = sceneOf("mixed/mixed_torus.obj", 2);
    const Image image = draw(s, viewOf(s, render::Shading::FaceType));
    int orange = 0, blue = 0, other = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        if (isBackground(&image.rgba[i])) continue;
        const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
        if (r > b + 20 && r >= g) {
            ++orange;
        } else if (b > r + 20 && b >= g) {
            ++blue;
        } else {
            ++other;
        }
    }
    EXPECT_GT(orange, 3000);
    EXPECT_GT(blue, 3000);
    EXPECT_LT(other, (orange + blue) / 50) << "pixels neither orange nor blue (highlights)";
}

TEST_F(RenderTest, TexturedShadingShowsTheCheckerThroughTheUVs) {
    const Scene s = sceneOf("osd/catmark_cube.obj", 2);
    ASSERT_FALSE(s.uvs.empty()) << "catmark_cube has UVs";
    const Image checker = draw(s, viewOf(s, render::Shading::Textured));
    int reddish = 0, pale = 0;
    for (std::size_t i = 0; i < checker.rgba.size(); i += 4) {
        const int r = checker.rgba[i], g = checker.rgba[i + 1], b = checker.rgba[i + 2];
        if (isBackground(&checker.rgba[i])) continue;
        reddish += r > 2 * g && r > 2 * b ? 1 : 0;
        pale += std::abs(r - g) < 20 && std::abs(g - b) < 30 && r > 60 ? 1 : 0;
    }
    EXPECT_GT(reddish, 500);
    EXPECT_GT(pale, 500);
    // A texture of one colour replaces the checker.
    Image green{2, 2, std::vector<uint8_t>(16, 0)};
    for (int i = 0; i < 4; ++i) green.rgba[std::size_t(4 * i + 1)] = green.rgba[std::size_t(4 * i + 3)] = 255;
    renderer->setTexture(&green);
    const Image textured = draw(s, viewOf(s, render::Shading::Textured));
    int notGreen = 0;
    for (std::size_t i = 0; i < textured.rgba.size(); i += 4)
        if (!isBackground(&textured.rgba[i])) notGreen += textured.rgba[i + 1] < textured.rgba[i] + 40 ? 1 : 0;
    EXPECT_EQ(notGreen, 0) << "surface pixels not green under a green texture";
}

TEST_F(RenderTest, TheCageIsDrawnInItsSharpnessColours) {
    const Scene s = makeScene(tube(4, 10.0f), 2);
    render::ViewSettings view = viewOf(s, render::Shading::Smooth, 30.0f, 25.0f);
    view.showSurface = false;
    view.showCage = true;
    const Image image = draw(s, view);
    const glm::vec3 infinite = render::sharpnessColor(10.0f) * 255.0f, smooth = render::sharpnessColor(0.0f) * 255.0f;
    int infinitePixels = 0, smoothPixels = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const uint8_t* p = image.pixel(x, y);
            auto is = [p](glm::vec3 c) {
                return std::abs(p[0] - c.r) < 2 && std::abs(p[1] - c.g) < 2 && std::abs(p[2] - c.b) < 2;
            };
            infinitePixels += is(infinite) ? 1 : 0;
            smoothPixels += is(smooth) ? 1 : 0;
        }
    EXPECT_GT(infinitePixels, 100) << "the creased rim";
    EXPECT_GT(smoothPixels, 4 * infinitePixels) << "the other edges";
}

TEST(RenderData, RootFacesFollowTheSplits) {
    for (Scheme scheme : {Scheme::SchaeferWarren, Scheme::CatmullClark}) {
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 3, options);
        const std::vector<int> roots = render::rootFaces(*r.refiner, 3);
        const LevelFaces control = r.refiner->faces(0);
        ASSERT_EQ(int(roots.size()), r.refiner->faces(3).numFaces());
        std::vector<int> children(std::size_t(control.numFaces()), 0);
        for (int f : roots) ++children[std::size_t(f)];
        for (int f = 0; f < control.numFaces(); ++f) {
            // Three levels of four children each, except catmull-clark's first split of a
            // triangle, into three quads.
            const int expected = control.faceSize(f) == 3 && scheme == Scheme::CatmullClark ? 3 * 16 : 64;
            EXPECT_EQ(children[std::size_t(f)], expected) << toString(scheme) << " face " << f;
        }
    }
}

TEST(RenderData, MeanCurvatureOfASphereIsOneOverItsRadius) {
    // A latitude-longitude sphere of radius 2: quads, and triangle fans at the poles.
    constexpr int kRings = 40, kSegments = 80;
    constexpr double kRadius = 2.0;
    std::vector<float> xyz{0.0f, float(kRadius), 0.0f};
    for (int i = 1; i < kRings; ++i)
        for (int k = 0; k < kSegments; ++k) {
            const double theta = M_PI * i / kRings, phi = 2.0 * M_PI * k / kSegments;
            xyz.insert(xyz.end(), {float(kRadius * std::sin(theta) * std::cos(phi)), float(kRadius * std::cos(theta)),
                                   float(kRadius * std::sin(theta) * std::sin(phi))});
        }
    xyz.insert(xyz.end(), {0.0f, float(-kRadius), 0.0f});
    const int south = int(xyz.size() / 3) - 1;
    auto at = [](int i, int k) { return 1 + (i - 1) * kSegments + k % kSegments; };
    std::vector<int> sizes, verts;
    for (int k = 0; k < kSegments; ++k) {
        sizes.push_back(3), verts.insert(verts.end(), {0, at(1, k + 1), at(1, k)});
        sizes.push_back(3), verts.insert(verts.end(), {south, at(kRings - 1, k), at(kRings - 1, k + 1)});
    }
    for (int i = 1; i + 1 < kRings; ++i)
        for (int k = 0; k < kSegments; ++k) {
            sizes.push_back(4);
            verts.insert(verts.end(), {at(i, k), at(i, k + 1), at(i + 1, k + 1), at(i + 1, k)});
        }
    const Refiner sphere(descriptorOf(int(xyz.size() / 3), sizes, verts), Options());
    std::vector<float> normals(xyz.size());
    for (std::size_t i = 0; i < xyz.size(); ++i) normals[i] = xyz[i] / float(kRadius);
    const std::vector<float> h = render::meanCurvature(sphere.faces(0), xyz.data(), normals.data());
    for (int i = 2; i < kRings - 2; ++i)
        for (int k = 0; k < kSegments; k += 7)
            EXPECT_NEAR(h[std::size_t(at(i, k))], 1.0 / kRadius, 0.02) << i << "," << k;
    // Turned inside out (normals inwards), the sign flips.
    for (float& n : normals) n = -n;
    EXPECT_NEAR(render::meanCurvature(sphere.faces(0), xyz.data(), normals.data())[std::size_t(at(kRings / 2, 0))],
                -1.0 / kRadius, 0.02);
}

}  // namespace
}  // namespace quadtri::test
