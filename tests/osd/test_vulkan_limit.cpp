// VulkanLimitEvaluator (lavapipe in CI) against CpuEvaluator: mesh normals of refined bench tori
// (quads, triangles, mixed), limit positions, tangents and normals of random tables for widths 3 and 7 and
// every output subset, the degenerate fallback, ranges and omitted outputs left untouched, and the
// argument checks with CpuEvaluator's messages. The Khronos validation layer must stay silent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include <quadtri/far/limit_table_update.h>
#include <quadtri/far/refiner.h>
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/vulkan_limit_evaluator.h>
#include "bench/meshes/torus.h"
#include "tests/far/edit_support.h"
#include "tests/limit/limit_test_tables.h"
#include "tests/test_support.h"
#include "tests/osd/vulkan_test_support.h"

namespace quadtri::test {
namespace {

constexpr float kUntouched = -777.5f;
constexpr double kTolerance = 1e-5;  // relative to max(1, |value|)
const BufferDescriptor kPacked(0, 3, 3);

VulkanVertexBuffer upload(VulkanContext& ctx, const std::vector<float>& data, int stride) {
    return uploadPadded(ctx, data, stride, kUntouched);
}

// Within kTolerance, times conditioning(f) where given: a unit normal's float rounding grows with
// the condition number of its tangents (the host's 3-float loop may use fused multiply-adds, the
// shader need not, so their roundings differ), see normalConditioning.
void expectClose(const std::vector<float>& gpu, const std::vector<float>& cpu, const std::string& what,
                 const std::function<double(std::size_t)>& conditioning = nullptr) {
    ASSERT_EQ(gpu.size(), cpu.size()) << what;
    for (std::size_t f = 0; f < cpu.size(); ++f) {
        if (cpu[f] == kUntouched) {
            ASSERT_EQ(gpu[f], kUntouched) << what << " float " << f << " should be untouched";
            continue;
        }
        const double scale = conditioning ? conditioning(f) : 1.0;
        ASSERT_NEAR(gpu[f], cpu[f], scale * kTolerance * std::max(1.0f, std::fabs(cpu[f]))) << what << " float " << f;
    }
}

// Per stencil: max(1, kappa / 100), kappa the condition number of its normal in float, (|dU|'s
// rounding bound / |dU| + |dV|'s / |dV|) / sine(dU, dV), the bounds sum_k |w_k| |s_k - s_0|
// (double, 3 floats of source).
std::vector<double> normalConditioning(const LimitStencilTable& table, const std::vector<float>& src,
                                       const BufferDescriptor& srcDesc) {
    const int n = table.numStencils();
    std::vector<double> scale(n, 1.0);
    auto at = [&](int v, int c) { return double(src[srcDesc.offset + std::size_t(v) * srcDesc.stride + c]); };
    for (int i = 0; i < n; ++i) {
        double u[3] = {0, 0, 0}, v[3] = {0, 0, 0}, bu = 0, bv = 0;
        const int* idx = &table.indices[table.offsets[i]];
        for (int k = 0; k < table.size(i); ++k) {
            const float* w = table.weightsOf(i) + 3 * k;
            double d2 = 0;
            for (int c = 0; c < 3; ++c) {
                const double d = at(idx[k], c) - at(idx[0], c);
                u[c] += w[1] * d, v[c] += w[2] * d, d2 += d * d;
            }
            bu += std::fabs(w[1]) * std::sqrt(d2), bv += std::fabs(w[2]) * std::sqrt(d2);
        }
        const double cr[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        const double lv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        const double sine = std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]) / (lu * lv);
        if (lu > 0 && lv > 0 && sine > 0) scale[i] = std::max(1.0, (bu / lu + bv / lv) / sine / 100.0);
    }
    return scale;
}

// One host buffer per output, uploaded, evaluated, read back and compared with the CPU's.
void compareLimit(VulkanContext& ctx, VulkanLimitEvaluator& eval, const LimitStencilTable& table,
                  const std::vector<float>& src, const BufferDescriptor& srcDesc, int width, const bool want[4],
                  const MeshNormalTable* fallback, int start, int end, const std::string& what) {
    const int n = table.numStencils();
    const BufferDescriptor descs[4] = {BufferDescriptor(1, width, width + 1), BufferDescriptor(0, width, width + 2),
                                       BufferDescriptor(3, width, width), BufferDescriptor(2, 3, 5)};
    std::vector<float> cpu[4];
    float* cpuPtr[4];
    for (int k = 0; k < 4; ++k) {
        cpu[k].assign(std::size_t(descs[k].offset) + std::size_t(n) * descs[k].stride, kUntouched);
        cpuPtr[k] = want[k] ? cpu[k].data() : nullptr;
    }
    CpuEvaluator::EvalLimitStencils(src.data(), srcDesc, cpuPtr[0], descs[0], cpuPtr[1], descs[1], cpuPtr[2], descs[2],
                                    cpuPtr[3], descs[3], table, fallback, start, end);
    const VulkanLimitStencilTable gpuTable(ctx, table);
    std::unique_ptr<VulkanMeshNormalTable> gpuFallback;
    if (fallback) gpuFallback = std::make_unique<VulkanMeshNormalTable>(ctx, *fallback);
    const VulkanVertexBuffer s = upload(ctx, src, srcDesc.stride);
    std::vector<VulkanVertexBuffer> outs;
    for (int k = 0; k < 4; ++k) outs.push_back(upload(ctx, std::vector<float>(cpu[k].size(), kUntouched), descs[k].stride));
    const VulkanVertexBuffer* ptr[4];
    for (int k = 0; k < 4; ++k) ptr[k] = want[k] ? &outs[k] : nullptr;
    eval.EvalLimitStencilsAndWait(s, srcDesc, ptr[0], descs[0], ptr[1], descs[1], ptr[2], descs[2], ptr[3], descs[3],
                                  gpuTable, gpuFallback.get(), start, end);
    const char* names[4] = {"position", "dU", "dV", "normal"};
    for (int k = 0; k < 3; ++k) expectClose(downloadFloats(outs[k], cpu[k].size()), cpu[k], what + " " + names[k]);
    if (!want[3]) return;
    const std::vector<double> scale = normalConditioning(table, src, srcDesc);
    const BufferDescriptor& d = descs[3];
    expectClose(downloadFloats(outs[3], cpu[3].size()), cpu[3], what + " normal",
                [&](std::size_t f) { return scale[(f - std::size_t(d.offset)) / d.stride]; });
}

// The device's normals of vertices [start, end) against CpuEvaluator's (the whole level: its
// face-by-face pass; a range: its per-vertex gather), through padded descriptors.
void compareMeshNormals(VulkanContext& ctx, VulkanLimitEvaluator& eval, const MeshNormalTable& table,
                        const std::vector<float>& xyz, int start, int end, const std::string& what) {
    const BufferDescriptor src(1, 3, 4), dst(2, 3, 5);
    const int n = table.numVertices;
    std::vector<float> host(std::size_t(src.offset) + std::size_t(n) * src.stride, kUntouched);
    for (int v = 0; v < n; ++v) std::copy_n(&xyz[3 * std::size_t(v)], 3, &host[src.offset + std::size_t(v) * src.stride]);
    const std::size_t outFloats = std::size_t(dst.offset) + std::size_t(n) * dst.stride;
    std::vector<float> cpu(outFloats, kUntouched);
    CpuEvaluator::EvalMeshNormals(host.data(), src, cpu.data(), dst, table, start, end);
    const VulkanMeshNormalTable gpuTable(ctx, table);
    const VulkanVertexBuffer s = upload(ctx, host, src.stride);
    const VulkanVertexBuffer d = upload(ctx, std::vector<float>(outFloats, kUntouched), dst.stride);
    eval.EvalMeshNormalsAndWait(s, src, d, dst, gpuTable, start, end);
    expectClose(downloadFloats(d, outFloats), cpu, what);
}

TEST_F(VulkanTest, MeshNormalsMatchCpu) {
    VulkanLimitEvaluator eval(*ctx);
    for (bench::TorusFaces faces : {bench::TorusFaces::Quads, bench::TorusFaces::Triangles, bench::TorusFaces::Mixed}) {
        const bench::ControlMesh m = bench::makeTorus(16, faces);
        Refiner refiner(m.descriptor(), Options());
        refiner.refineUniform(3);
        const std::vector<float> xyz = evaluateLevels(refiner, m.positions, 3)[3];
        const MeshNormalTable table = buildMeshNormalTable(refiner.faces(3));
        compareMeshNormals(*ctx, eval, table, xyz, 0, -1, "mesh normals of " + m.name);
        compareMeshNormals(*ctx, eval, table, xyz, 10, table.numVertices - 10, "mesh normals of " + m.name + ", a range");
    }
    // Faces of 5 and 6 corners (a fan of quads closed by a triangle, and one without): a roof of a
    // pentagon and a hexagon over a bent strip, no two faces coplanar.
    const std::vector<int> sizes = {5, 6, 3, 4};
    const std::vector<int> verts = {0, 1, 2, 3, 4, 1, 5, 6, 7, 8, 2, 2, 8, 9, 3, 2, 9, 10};
    const std::vector<float> xyz = {0, 0, 0,  1, 0, 0.1f,  1.2f, 1, 0.3f,  0.5f, 1.6f, 0.2f,  -0.3f, 0.9f, 0.1f,
                                    2, -0.2f, 0.4f,  2.8f, 0.3f, 0.9f,  2.9f, 1.2f, 1.1f,  2.1f, 1.7f, 0.6f,
                                    1.4f, 2.3f, 0.8f,  0.9f, 1.5f, 1.4f};
    const Refiner polygons(descriptorOf(11, sizes, verts), Options());
    compareMeshNormals(*ctx, eval, buildMeshNormalTable(polygons.faces(0)), xyz, 0, -1, "mesh normals of polygons");
}

TEST_F(VulkanTest, LimitStencilsMatchCpu) {
    VulkanLimitEvaluator eval(*ctx);
    const LimitStencilTable table = randomLimitTable(5000, 700, 29);
    for (int width : {3, 7}) {
        const BufferDescriptor srcDesc(2, width, width + 1);
        std::vector<float> src(std::size_t(srcDesc.offset) + 700u * srcDesc.stride, kUntouched);
        for (int v = 0; v < 700; ++v)
            for (int c = 0; c < width; ++c)
                src[srcDesc.offset + std::size_t(v) * srcDesc.stride + c] = float(std::sin(0.37 * v + 1.1 * c));
        for (int subset = 1; subset < 16; ++subset) {
            const bool want[4] = {(subset & 1) != 0, (subset & 2) != 0, (subset & 4) != 0, (subset & 8) != 0};
            if (want[3] && width != 3) continue;
            compareLimit(*ctx, eval, table, src, srcDesc, width, want, nullptr, subset == 15 ? 100 : 0,
                         subset == 15 ? 4000 : -1, "width " + std::to_string(width) + " subset " + std::to_string(subset));
        }
    }
}

TEST_F(VulkanTest, RefinerLimitTablesMatchCpu) {
    VulkanLimitEvaluator eval(*ctx);
    const bool all[4] = {true, true, true, true};
    for (auto [faces, scheme] : {std::pair{bench::TorusFaces::Quads, Scheme::CatmullClark},
                                 std::pair{bench::TorusFaces::Triangles, Scheme::Loop}}) {
        const bench::ControlMesh m = bench::makeTorus(12, faces);
        Options options;
        options.scheme = scheme;
        Refiner refiner(descriptorOf(m.numVertices, m.faceSizes, m.faceVerts), options);
        refiner.refineUniform(2);
        compareLimit(*ctx, eval, refiner.factorizedLimitStencils(2), m.positions, kPacked, 3, all, nullptr, 0, -1,
                     m.name + " factorized");
        const MeshNormalTable level2 = buildMeshNormalTable(refiner.faces(2));
        compareLimit(*ctx, eval, refiner.limitStencils(2), evaluateLevels(refiner, m.positions, 3)[2], kPacked, 3, all,
                     &level2, 0, -1, m.name + " over level 2");
    }
}

TEST_F(VulkanTest, LimitFallbackMatchesCpu) {
    VulkanLimitEvaluator eval(*ctx);
    const CornerLevel L = cornerLevel(2);
    const bool all[4] = {true, true, true, true};
    compareLimit(*ctx, eval, L.table, L.positions, kPacked, 3, all, &L.meshNormals, 0, -1, "corner level, fallback");
    compareLimit(*ctx, eval, L.table, L.positions, kPacked, 3, all, nullptr, 0, -1, "corner level, no fallback");
}

// Recorded into the caller's command buffer, with all four outputs in one buffer at byte offsets
// that need not meet minStorageBufferOffsetAlignment.
TEST_F(VulkanTest, LimitRecordedIntoOneSharedBuffer) {
    VulkanLimitEvaluator eval(*ctx);
    const CornerLevel L = cornerLevel(2);
    const int n = L.table.numStencils();
    const VulkanLimitStencilTable table(*ctx, L.table);
    const VulkanMeshNormalTable fallback(*ctx, L.meshNormals);
    const VulkanVertexBuffer src = upload(*ctx, L.positions, 3);
    const VulkanVertexBuffer all = upload(*ctx, std::vector<float>(std::size_t(12) * n + 16, kUntouched), 4);
    const VkDeviceSize region = VkDeviceSize(3) * n * sizeof(float);
    std::vector<float> expected(std::size_t(12) * n + 16, kUntouched);
    float* out[4];
    VulkanBufferRef refs[4];
    for (int k = 0; k < 4; ++k) {
        const VkDeviceSize at = sizeof(float) * (1 + k) + region * k;  // 4-byte aligned only
        refs[k] = {all.buffer(), at};
        out[k] = expected.data() + at / sizeof(float);
    }
    CpuEvaluator::EvalLimitStencils(L.positions.data(), kPacked, out[0], kPacked, out[1], kPacked, out[2], kPacked, out[3],
                                    kPacked, L.table, &L.meshNormals);
    ctx->submitAndWait([&](VkCommandBuffer cmd) {
        eval.EvalLimitStencils(cmd, {src.buffer(), 0}, kPacked, refs[0], kPacked, refs[1], kPacked, refs[2], kPacked,
                               refs[3], kPacked, table, &fallback);
    });
    eval.resetDescriptorSets();
    expectClose(downloadFloats(all, expected.size()), expected, "one shared buffer");
}

// The device reads whatever the table's arrays say: a table whose arrays disagree, or whose run
// or weights reach past their pool, is refused on upload.
// A table kept up to date with edits (LimitTableUpdate) and its device copy updated by range
// (VulkanLimitStencilTable::update): the device evaluates what a fresh copy of the host table
// evaluates, bit for bit, after every tenth of 40 random edits; a copy without room for updates,
// or after the pools were laid out again, is refused an update and left as it was.
TEST_F(VulkanTest, ALimitTableUpdatedByRangeEqualsAFreshCopy) {
    const io::ObjMesh mesh = io::readObj(meshPath("mixed/mixed_torus.obj"));
    Options options;
    options.scheme = Scheme::SchaeferWarren;
    std::unique_ptr<Refiner> refiner = build(mesh, options, 2);
    LimitStencilTable table = refiner->factorizedLimitStencils(2);
    LimitTableUpdate update(*refiner, 2, LimitTableUpdate::Sources::Control);
    VulkanLimitStencilTable device(*ctx, table, true), fixed(*ctx, table);
    const VulkanVertexBuffer cage = upload(*ctx, mesh.positions, 3);
    auto evaluate = [&](const VulkanLimitStencilTable& t) {
        const VulkanVertexBuffer out = upload(*ctx, std::vector<float>(3 * std::size_t(table.numStencils()), 0.0f), 3);
        VulkanLimitEvaluator eval(*ctx);
        eval.EvalLimitStencilsAndWait(cage, kPacked, &out, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, t);
        return downloadFloats(out, 3 * std::size_t(table.numStencils()));
    };
    std::mt19937 random(17);
    int byRange = 0;
    for (int k = 1; k <= 40; ++k) {
        const LimitTableChange change = update.update(refiner->applyEdits(randomEdits(refiner->level(0), random, true)), table);
        if (device.update(*ctx, table, change)) {
            ++byRange;
        } else {
            device = VulkanLimitStencilTable(*ctx, table, true);
        }
        if (change.poolsLaidOut) {
            EXPECT_FALSE(fixed.update(*ctx, table, change));
        }
        if (k % 10 == 0) {
            EXPECT_EQ(evaluate(device), evaluate(VulkanLimitStencilTable(*ctx, table))) << "edit " << k;
        }
    }
    EXPECT_GT(byRange, 30);
    // A copy without room: refused once its pools would grow, and still what it was.
    const std::vector<float> before = evaluate(fixed);
    LimitStencilTable grown = table;
    grown.indices.push_back(0);
    EXPECT_FALSE(fixed.update(*ctx, grown, LimitTableChange{}));
    EXPECT_EQ(evaluate(fixed), before);
}

TEST_F(VulkanTest, InconsistentLimitTablesAreRefused) {
    const LimitStencilTable good = randomLimitTable(10, 8, 1);
    std::vector<LimitStencilTable> bad(4, good);
    bad[0].sizes.pop_back();
    bad[1].offsets.push_back(0);
    bad[2].offsets[3] = int(good.indices.size()) - good.sizes[3] + 1;
    bad[3].weightOffsets[5] = int(good.weights.size()) - 3 * good.sizes[5] + 1;
    for (const LimitStencilTable& t : bad)
        EXPECT_EQ(messageOf([&] { const VulkanLimitStencilTable uploaded(*ctx, t); }),
                  "VulkanLimitStencilTable: inconsistent LimitStencilTable arrays");
    EXPECT_EQ(messageOf([&] { const VulkanLimitStencilTable uploaded(*ctx, good); }), "(no exception)");
}

TEST_F(VulkanTest, LimitArgumentChecksMatchCpu) {
    VulkanLimitEvaluator eval(*ctx);
    const LimitStencilTable table = randomLimitTable(10, 8, 1);
    const VulkanLimitStencilTable gpuTable(*ctx, table);
    const CornerLevel L = cornerLevel(1);
    const VulkanMeshNormalTable gpuNormals(*ctx, L.meshNormals);
    std::vector<float> host(64, 1.0f);
    const VulkanVertexBuffer buf = VulkanVertexBuffer::create(*ctx, 64, 4);
    const BufferDescriptor bad(0, 3, 2), four(0, 4, 4);
    const float* h = host.data();
    float* o = host.data();
    const VulkanVertexBuffer* b = &buf;
    struct Case {
        std::function<void()> cpu, gpu;
    };
    const Case cases[] = {
        {[&] { CpuEvaluator::EvalLimitStencils(h, bad, o, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, table); },
         [&] { eval.EvalLimitStencilsAndWait(buf, bad, b, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, gpuTable); }},
        {[&] { CpuEvaluator::EvalLimitStencils(h, kPacked, o, four, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, table); },
         [&] { eval.EvalLimitStencilsAndWait(buf, kPacked, b, four, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, gpuTable); }},
        {[&] { CpuEvaluator::EvalLimitStencils(h, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, table); },
         [&] { eval.EvalLimitStencilsAndWait(buf, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, gpuTable); }},
        {[&] { CpuEvaluator::EvalLimitStencils(h, four, o, four, nullptr, four, nullptr, four, o, kPacked, table); },
         [&] { eval.EvalLimitStencilsAndWait(buf, four, b, four, nullptr, four, nullptr, four, b, kPacked, gpuTable); }},
        {[&] { CpuEvaluator::EvalLimitStencils(h, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, o, kPacked, table, &L.meshNormals); },
         [&] { eval.EvalLimitStencilsAndWait(buf, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, b, kPacked, gpuTable, &gpuNormals); }},
        {[&] { CpuEvaluator::EvalLimitStencils(h, kPacked, o, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, table, nullptr, 3, 12); },
         [&] { eval.EvalLimitStencilsAndWait(buf, kPacked, b, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr, kPacked, gpuTable, nullptr, 3, 12); }},
        {[&] { CpuEvaluator::EvalMeshNormals(h, four, o, kPacked, L.meshNormals); },
         [&] { eval.EvalMeshNormalsAndWait(buf, four, buf, kPacked, gpuNormals); }},
        {[&] { CpuEvaluator::EvalMeshNormals(h, kPacked, o, kPacked, L.meshNormals, 0, 1 << 20); },
         [&] { eval.EvalMeshNormalsAndWait(buf, kPacked, buf, kPacked, gpuNormals, 0, 1 << 20); }},
    };
    for (const Case& c : cases) {
        const std::string cpu = messageOf(c.cpu), gpu = messageOf(c.gpu);
        EXPECT_NE(cpu, "(no exception)");
        EXPECT_EQ(cpu, gpu);
    }
    // Recording: a null output VkBuffer is omitted; a missing source is refused as on the CPU.
    EXPECT_EQ(messageOf([&] {
                  ctx->submitAndWait([&](VkCommandBuffer cmd) {
                      eval.EvalLimitStencils(cmd, {}, kPacked, {buf.buffer(), 0}, kPacked, {}, kPacked, {}, kPacked, {},
                                             kPacked, gpuTable);
                  });
              }),
              "EvalLimitStencils: null source buffer");
    // The buffer sizes of the waiting call: 64 elements of stride 4 hold 85 packed 3-float ones.
    const LimitStencilTable big = randomLimitTable(100, 8, 2);
    const VulkanLimitStencilTable gpuBig(*ctx, big);
    EXPECT_EQ(messageOf([&] {
                  eval.EvalLimitStencilsAndWait(buf, kPacked, b, kPacked, nullptr, kPacked, nullptr, kPacked, nullptr,
                                                kPacked, gpuBig);
              }),
              "EvalLimitStencils: position buffer of 256 floats too small for 100 elements");
}

}  // namespace
}  // namespace quadtri::test
