// VulkanLimitEvaluator::EvalLevelPatches (shaders/level_patches.comp, lavapipe in CI) against
// CpuEvaluator::EvalLevelPatches: every scheme's level L from level K's patches and stencils,
// rates 2 to 32 (several patches to a workgroup at the low ones), padded and shared buffers, one
// output alone (the other left untouched), recorded into the caller's command buffer, the argument checks with the host's messages, and tables the
// device must not read refused on upload. The Khronos validation layer must stay silent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <quadtri/far/level_patch_table.h>
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/vulkan_limit_evaluator.h>
#include "bench/meshes/torus.h"
#include "tests/limit/limit_support.h"
#include "tests/osd/vulkan_test_support.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

constexpr float kUntouched = -777.5f;
const BufferDescriptor kPacked(0, 3, 3);

VulkanVertexBuffer upload(VulkanContext& ctx, const std::vector<float>& data, int stride) {
    return uploadPadded(ctx, data, stride, kUntouched);
}

// `xyz` (3 floats an element) laid out by `d`, kUntouched elsewhere.
std::vector<float> laidOut(const std::vector<float>& xyz, const BufferDescriptor& d) {
    const std::size_t n = xyz.size() / 3;
    std::vector<float> out(layoutFloats(d, int(n)), kUntouched);
    for (std::size_t v = 0; v < n; ++v) std::copy_n(&xyz[3 * v], 3, &out[std::size_t(d.offset) + v * std::size_t(d.stride)]);
    return out;
}

// The largest distance between the device's and the host's element k (positions: over the
// diagonal; normals: the angle, where both are unit vectors), after checking that every float
// the host left untouched the device left untouched, and that both found the same degenerate
// normals.
struct Difference {
    double position = 0, normal = 0;
};

void compareOutput(const std::vector<float>& gpu, const std::vector<float>& cpu, const BufferDescriptor& d, int n,
                   bool isNormal, double scale, double& worst, const std::string& what) {
    ASSERT_EQ(gpu.size(), cpu.size()) << what;
    for (std::size_t f = 0; f < cpu.size(); ++f)
        if (cpu[f] == kUntouched) {
            ASSERT_EQ(gpu[f], kUntouched) << what << ": float " << f << " should be untouched";
        }
    for (int k = 0; k < n; ++k) {
        const std::size_t at = std::size_t(d.offset) + std::size_t(k) * std::size_t(d.stride);
        const Vec3 a = vec3(&gpu[at]), b = vec3(&cpu[at]);
        if (!isNormal) {
            worst = std::max(worst, distance(a, b) / scale);
            continue;
        }
        ASSERT_EQ(norm(a) > 0.5, norm(b) > 0.5) << what << ": point " << k << " degenerate on one side only";
        if (norm(b) > 0.5) worst = std::max(worst, angleBetween(a, b));
    }
}

struct Case {
    std::string mesh;
    Scheme scheme;
    int level, patchLevel;
};

void PrintTo(const Case& c, std::ostream* os) {
    *os << c.mesh << " " << toString(c.scheme) << " level " << c.level << " from " << c.patchLevel;
}

class VulkanLevelPatches : public VulkanTest, public testing::WithParamInterface<Case> {};

// Level L from level K (positions[K]), through padded descriptors (source offset 1 stride 4,
// positions offset 2 stride 5, normals packed), against the host's loops.
void compareWithCpu(VulkanContext& ctx, const Refiner& refiner, const std::vector<std::vector<float>>& positions,
                    int level, int patchLevel, const std::string& what) {
    const LevelPatchTable table = refiner.levelPatches(level, patchLevel);
    const int n = table.numPoints;
    const BufferDescriptor srcDesc(1, 3, 4), positionDesc(2, 3, 5);
    const std::vector<float> src = laidOut(positions[std::size_t(patchLevel)], srcDesc);
    std::vector<float> cpuPosition(layoutFloats(positionDesc, n), kUntouched), cpuNormal(layoutFloats(kPacked, n), kUntouched);
    CpuEvaluator::EvalLevelPatches(src.data(), srcDesc, cpuPosition.data(), positionDesc, cpuNormal.data(), kPacked, table);

    VulkanLimitEvaluator eval(ctx);
    const VulkanLevelPatchTable gpuTable(ctx, table);
    EXPECT_EQ(gpuTable.numPatches(), table.numPatches());
    EXPECT_EQ(gpuTable.numPatchOutputs(), table.numPatchOutputs());
    EXPECT_EQ(gpuTable.stencils().numStencils(), table.stencils.numStencils());
    const VulkanVertexBuffer s = upload(ctx, src, srcDesc.stride);
    const VulkanVertexBuffer p = upload(ctx, std::vector<float>(cpuPosition.size(), kUntouched), positionDesc.stride);
    const VulkanVertexBuffer nb = upload(ctx, std::vector<float>(cpuNormal.size(), kUntouched), 3);
    eval.EvalLevelPatchesAndWait(s, srcDesc, &p, positionDesc, &nb, kPacked, gpuTable);

    const double diagonal = boundingBoxDiagonal(positions[0]);
    Difference worst;
    compareOutput(downloadFloats(p, cpuPosition.size()), cpuPosition, positionDesc, n, false, diagonal, worst.position,
                  what + " position");
    compareOutput(downloadFloats(nb, cpuNormal.size()), cpuNormal, kPacked, n, true, 1, worst.normal, what + " normal");
    int boxSplines = 0;
    for (LevelPatchTable::Basis b : table.patchBasis) boxSplines += b == LevelPatchTable::Basis::BoxSpline;
    std::printf("%s level %d from %d (%d patches, %d box splines, %d stencils): position %.3g, normal %.3g rad\n",
                what.c_str(), level, patchLevel, table.numPatches(), boxSplines, table.stencils.numStencils(),
                worst.position, worst.normal);
    EXPECT_LT(worst.position, 1e-6) << what;
    EXPECT_LT(worst.normal, 1e-5) << what;
}

TEST_P(VulkanLevelPatches, MatchCpu) {
    const Case& c = GetParam();
    Options options;
    options.scheme = c.scheme;
    const RefinedMesh r = refineMesh(c.mesh, c.level, options);
    compareWithCpu(*ctx, *r.refiner, r.positions, c.level, c.patchLevel, c.mesh + " " + toString(c.scheme));
}

// Regular tori: every face a patch, all B-splines (quads) or all box splines (triangles under
// loop and schaefer-warren), up to rate 16.
TEST_F(VulkanTest, LevelPatchesOfRegularToriMatchCpu) {
    for (auto [faces, scheme] : {std::pair{bench::TorusFaces::Quads, Scheme::CatmullClark},
                                 std::pair{bench::TorusFaces::Triangles, Scheme::Loop},
                                 std::pair{bench::TorusFaces::Triangles, Scheme::SchaeferWarren}}) {
        const bench::ControlMesh m = bench::makeTorus(8, faces);
        Options options;
        options.scheme = scheme;
        Refiner refiner(descriptorOf(m.numVertices, m.faceSizes, m.faceVerts), options);
        refiner.refineUniform(4);
        compareWithCpu(*ctx, refiner, evaluateLevels(refiner, m.positions, 3), 4, 0,
                       m.name + " " + toString(scheme));
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, VulkanLevelPatches,
                         testing::Values(Case{"mixed/mixed_torus.obj", Scheme::SchaeferWarren, 3, 1},
                                         Case{"mixed/split_plane.obj", Scheme::StamLoop, 2, 1},
                                         Case{"mixed/mixed_torus.obj", Scheme::StamLoop, 2, 0},
                                         Case{"mixed/mixed_torus.obj", Scheme::CatmarkButterfly, 3, 1},
                                         Case{"mixed/mixed_torus.obj", Scheme::Bilinear, 2, 0},
                                         Case{"mixed/cylinder_capped_creased.obj", Scheme::CatmullClark, 3, 1},
                                         Case{"osd/catmark_torus.obj", Scheme::CatmullClark, 5, 0},
                                         Case{"osd/loop_xord_interior.obj", Scheme::Loop, 4, 1}),
                         [](const auto& info) {
                             const Case& c = info.param;
                             return testNameOf(c.mesh + "_" + toString(c.scheme) + "_" + std::to_string(c.level) +
                                               "_from_" + std::to_string(c.patchLevel));
                         });

// Positions alone, then normals alone, both recorded into the caller's command buffer and written
// into one buffer at byte offsets that need not meet minStorageBufferOffsetAlignment: the output
// not asked for stays untouched.
TEST_F(VulkanTest, LevelPatchesRecordedIntoOneSharedBuffer) {
    Options options;
    options.scheme = Scheme::SchaeferWarren;
    const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 2, options);
    const LevelPatchTable table = r.refiner->levelPatches(2, 0);
    const int n = table.numPoints;
    const std::vector<float>& src = r.positions[0];
    VulkanLimitEvaluator eval(*ctx);
    const VulkanLevelPatchTable gpuTable(*ctx, table);
    const VulkanVertexBuffer s = upload(*ctx, src, 3);
    const std::size_t floats = std::size_t(6) * std::size_t(n) + 8;
    for (bool positions : {true, false}) {
        const VulkanVertexBuffer all = upload(*ctx, std::vector<float>(floats, kUntouched), 4);
        std::vector<float> expected(floats, kUntouched);
        const VkDeviceSize first = sizeof(float), second = sizeof(float) * (3 + 3 * std::size_t(n));
        float* out = expected.data() + (positions ? first : second) / sizeof(float);
        CpuEvaluator::EvalLevelPatches(src.data(), kPacked, positions ? out : nullptr, kPacked, positions ? nullptr : out,
                                       kPacked, table);
        const VulkanBufferRef ref{all.buffer(), positions ? first : second};
        ctx->submitAndWait([&](VkCommandBuffer cmd) {
            eval.EvalLevelPatches(cmd, {s.buffer(), 0}, kPacked, positions ? ref : VulkanBufferRef{}, kPacked,
                                  positions ? VulkanBufferRef{} : ref, kPacked, gpuTable);
        });
        eval.resetDescriptorSets();
        const std::vector<float> got = downloadFloats(all, floats);
        for (std::size_t f = 0; f < floats; ++f) {
            if (expected[f] == kUntouched) {
                ASSERT_EQ(got[f], kUntouched) << "float " << f;
                continue;
            }
            ASSERT_NEAR(got[f], expected[f], 1e-5 * std::max(1.0f, std::fabs(expected[f]))) << "float " << f;
        }
    }
}

TEST_F(VulkanTest, LevelPatchArgumentChecksMatchCpu) {
    const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 2);
    const LevelPatchTable table = r.refiner->levelPatches(2, 1);
    VulkanLimitEvaluator eval(*ctx);
    const VulkanLevelPatchTable gpuTable(*ctx, table);
    const int n = table.numPoints;
    std::vector<float> host(std::size_t(4) * std::size_t(n), 1.0f);
    const VulkanVertexBuffer buf = VulkanVertexBuffer::create(*ctx, n, 4);
    const BufferDescriptor bad(0, 3, 2), four(0, 4, 4);
    const float* h = host.data();
    float* o = host.data();
    const VulkanVertexBuffer* b = &buf;
    struct Call {
        std::function<void()> cpu, gpu;
    };
    const Call calls[] = {
        {[&] { CpuEvaluator::EvalLevelPatches(h, bad, o, kPacked, nullptr, kPacked, table); },
         [&] { eval.EvalLevelPatchesAndWait(buf, bad, b, kPacked, nullptr, kPacked, gpuTable); }},
        {[&] { CpuEvaluator::EvalLevelPatches(h, four, o, kPacked, nullptr, kPacked, table); },
         [&] { eval.EvalLevelPatchesAndWait(buf, four, b, kPacked, nullptr, kPacked, gpuTable); }},
        {[&] { CpuEvaluator::EvalLevelPatches(h, kPacked, nullptr, kPacked, nullptr, kPacked, table); },
         [&] { eval.EvalLevelPatchesAndWait(buf, kPacked, nullptr, kPacked, nullptr, kPacked, gpuTable); }},
        {[&] { CpuEvaluator::EvalLevelPatches(h, kPacked, o, four, nullptr, kPacked, table); },
         [&] { eval.EvalLevelPatchesAndWait(buf, kPacked, b, four, nullptr, kPacked, gpuTable); }},
        {[&] { CpuEvaluator::EvalLevelPatches(h, kPacked, nullptr, kPacked, o, bad, table); },
         [&] { eval.EvalLevelPatchesAndWait(buf, kPacked, nullptr, kPacked, b, bad, gpuTable); }},
    };
    for (const Call& c : calls) {
        const std::string cpu = messageOf(c.cpu), gpu = messageOf(c.gpu);
        EXPECT_NE(cpu, "(no exception)");
        EXPECT_EQ(cpu, gpu);
    }
    // A buffer too small for the table's points.
    const VulkanVertexBuffer small = VulkanVertexBuffer::create(*ctx, n - 1, 3);
    EXPECT_NE(messageOf([&] { eval.EvalLevelPatchesAndWait(buf, kPacked, &small, kPacked, nullptr, kPacked, gpuTable); })
                  .find("too small"),
              std::string::npos);
    EXPECT_EQ(messageOf([&] { eval.EvalLevelPatches(VK_NULL_HANDLE, {buf.buffer(), 0}, kPacked, {buf.buffer(), 0},
                                                    kPacked, {}, kPacked, gpuTable); }),
              "EvalLevelPatches: null command buffer");
}

// The device reads whatever the table's arrays say: a table that would make it read or write
// past an array is refused on upload, naming what is wrong.
TEST_F(VulkanTest, InconsistentLevelPatchTablesAreRefused) {
    const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 2);
    const LevelPatchTable good = r.refiner->levelPatches(2, 0);
    ASSERT_GT(good.numPatches(), 1);
    ASSERT_GT(good.stencils.numStencils(), 0);
    std::vector<std::pair<LevelPatchTable, std::string>> bad(7, {good, ""});
    bad[0].first.pointOffsets.pop_back();
    bad[0].second = "array lengths";
    bad[1].first.patchBasis[1] = LevelPatchTable::Basis(7);
    bad[1].second = "patch 1's basis";
    bad[2].first.patchBasis[0] = good.patchBasis[0] == LevelPatchTable::Basis::BSpline ? LevelPatchTable::Basis::BoxSpline
                                                                                         : LevelPatchTable::Basis::BSpline;
    bad[2].second = "patch 0's point count";
    bad[3].first.patchPoints[5] = good.numSourceVertices;
    bad[3].second = "patch point " + std::to_string(good.numSourceVertices) + " outside level 0";
    bad[4].first.outputCells[3] = std::uint16_t(good.rate() + 1);
    bad[4].second = "grid cell " + std::to_string(good.rate() + 1);
    bad[5].first.numPoints += 1;
    bad[5].second = "array lengths";
    bad[6].first.level = good.patchLevel + 8;
    bad[6].second = "level " + std::to_string(good.patchLevel + 8) + " from " + std::to_string(good.patchLevel);
    for (const auto& [table, why] : bad)
        EXPECT_EQ(messageOf([&] { const VulkanLevelPatchTable uploaded(*ctx, table); }),
                  "VulkanLevelPatchTable: inconsistent LevelPatchTable (" + why + ")");
    EXPECT_EQ(messageOf([&] { const VulkanLevelPatchTable uploaded(*ctx, good); }), "(no exception)");
}

}  // namespace
}  // namespace quadtri::test
