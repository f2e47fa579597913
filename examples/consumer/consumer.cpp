// The program both consumer projects build (examples/consumer/add_subdirectory/ and
// find_package/): it sees quadtri only through <quadtri/...> and the quadtri:: targets. It
// refines a cube with one face split into two triangles to level 2, evaluates the factorized
// table with the CPU, oneTBB and (when quadtri::vulkan is linked: QUADTRI_CONSUMER_VULKAN)
// Vulkan evaluators, and exits 1 unless the results agree and hold what the mesh implies.
// QUADTRI_REQUIRE_VULKAN=1 makes a missing Vulkan evaluator or device a failure, as in the tests.
#include <quadtri/quadtri.h>
#ifdef QUADTRI_CONSUMER_VULKAN
#include <quadtri/osd/vulkan_evaluator.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

bool vulkanRequired() {
    const char* v = std::getenv("QUADTRI_REQUIRE_VULKAN");
    return v && *v && std::strcmp(v, "0") != 0;
}

int failures = 0;
void check(bool ok, const char* what) {
    std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what);
    if (!ok) ++failures;
}

// No Vulkan evaluator to run: a failure under QUADTRI_REQUIRE_VULKAN, else a skip with the reason.
void withoutVulkan(const char* why) {
    if (vulkanRequired()) check(false, why);
    else std::printf("skip: %s (QUADTRI_REQUIRE_VULKAN=1 makes this a failure)\n", why);
}

#ifdef QUADTRI_CONSUMER_VULKAN
double largestDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::fabs(double(a[i]) - double(b[i])));
    return d;
}

// The Vulkan result, or an empty vector when there is no device (a failure if one is required).
std::vector<float> evaluateOnVulkan(const std::vector<float>& control, const quadtri::StencilTable& table) {
    setenv("QUADTRI_VK_VALIDATION", "1", /*overwrite=*/0);  // when the layer is installed
    try {
        quadtri::VulkanContext ctx;
        std::printf("Vulkan device: %s\n", ctx.deviceName().c_str());
        const quadtri::BufferDescriptor xyz(0, 3, 3);
        quadtri::VulkanStencilTable gpuTable(ctx, table);
        auto src = quadtri::VulkanVertexBuffer::create(ctx, table.numSourceVertices, 3);
        auto dst = quadtri::VulkanVertexBuffer::create(ctx, table.numStencils(), 3);
        src.updateData(control.data(), 0, table.numSourceVertices);
        quadtri::VulkanEvaluator(ctx).EvalStencilsAndWait(src, xyz, dst, xyz, gpuTable);
        std::vector<float> out(dst.numFloats());
        dst.readBack(out.data());
        check(quadtri::VulkanContext::totalValidationMessageCount() == 0, "the validation layer reported nothing");
        return out;
    } catch (const quadtri::VulkanError& e) {
        std::printf("%s\n", e.what());
        withoutVulkan("no Vulkan device");
        return {};
    }
}
#endif

int run() {
    // A unit cube; its top face (4 5 6 7) is split along 4-6 into two triangles.
    const std::vector<float> control = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    const std::vector<int> sizes = {4, 4, 4, 4, 4, 3, 3};
    const std::vector<int> verts = {0, 3, 2, 1, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7, 4, 5, 6, 4, 6, 7};
    quadtri::TopologyDescriptor desc;
    desc.numVertices = 8;
    desc.numFaces = int(sizes.size());
    desc.numVertsPerFace = sizes.data();
    desc.faceVertIndices = verts.data();

    quadtri::Refiner refiner(desc, quadtri::Options{});
    refiner.refineUniform(2);
    const quadtri::StencilTable table = refiner.factorizedStencils(2);
    std::printf("quadtri %s: level 2 has %d vertices\n", QUADTRI_VERSION_STRING, table.numStencils());
    // Level 1: 5 face points (quads only) + 13 edge points + 8 vertex points = 26 vertices, 52
    // edges (2 per old edge, 4 inside each quad, 3 inside each triangle), 20 quads and 8 triangles.
    // Level 2: 20 + 52 + 26 vertices, 80 quads and 32 triangles.
    const quadtri::LevelFaces faces = refiner.faces(2);
    check(table.numStencils() == 98 && faces.numVertices() == 98, "98 vertices at level 2");
    int quads = 0, triangles = 0;
    for (int f = 0; f < faces.numFaces(); ++f) (faces.faceSize(f) == 4 ? quads : triangles) += 1;
    check(quads == 80 && triangles == 32, "80 quads and 32 triangles at level 2");

    const quadtri::BufferDescriptor xyz(0, 3, 3);
    std::vector<float> cpu(3 * std::size_t(table.numStencils())), tbb(cpu.size());
    quadtri::CpuEvaluator::EvalStencils(control.data(), xyz, cpu.data(), xyz, table);
    quadtri::TbbEvaluator::EvalStencils(control.data(), xyz, tbb.data(), xyz, table);
    check(cpu == tbb, "oneTBB equals the CPU evaluator bit for bit");

    // A closed, smooth surface shrinks inside its control cube (here to about [0.05, 0.95]).
    bool inside = true;
    for (float c : cpu) inside = inside && c >= 0 && c <= 1;
    check(inside, "every refined vertex inside the control cube's bounding box");

#ifdef QUADTRI_CONSUMER_VULKAN
    const std::vector<float> gpu = evaluateOnVulkan(control, table);
    if (!gpu.empty()) check(gpu.size() == cpu.size() && largestDifference(gpu, cpu) <= 1e-5, "Vulkan within 1e-5 of the CPU");
#else
    withoutVulkan("built without quadtri::vulkan");
#endif
    return failures == 0 ? 0 : 1;
}

}  // namespace

int main() {
    try {
        return run();
    } catch (const std::exception& e) {  // quadtri::TopologyError, std::bad_alloc, ...
        std::printf("FAIL: %s\n", e.what());
        return 1;
    }
}
