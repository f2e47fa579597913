// VulkanEvaluator (on lavapipe in CI) against CpuEvaluator on every test mesh: per-level tables
// through one buffer holding all levels, factorized tables, widths 3 and 4 and a width-7 primvar
// with stride 8; ranges; argument checks, the same as CpuEvaluator's and TbbEvaluator's. The Khronos validation layer must stay silent.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#include <quadtri/osd/vulkan_evaluator.h>
#include "tests/far/edit_support.h"
#include "tests/test_support.h"
#include "tests/osd/vulkan_test_support.h"

namespace quadtri::test {
namespace {

constexpr float kUntouched = -4242.5f;
constexpr double kRelativeTolerance = 1e-5;  // of the control mesh's bounding-box diagonal

// Width 3 packed, width 4 after one float, width 7 with stride 8 after three floats.
const BufferDescriptor kLayouts[] = {BufferDescriptor(0, 3, 3), BufferDescriptor(1, 4, 4), BufferDescriptor(3, 7, 8)};


std::string testName(const testing::TestParamInfo<std::string>& info) {
    return testNameOf(info.param.substr(0, info.param.size() - 4));  // without ".obj"
}

class VulkanMeshTest : public VulkanTest, public testing::WithParamInterface<std::string> {};

TEST_P(VulkanMeshTest, MatchesCpuEvaluator) {
    const io::ObjMesh probe = io::readObj(meshPath(GetParam()));
    const int maxLevel = probe.numFaces() > 500 ? 2 : 3;
    const RefinedMesh r = refineMesh(GetParam(), maxLevel);
    const Refiner& refiner = *r.refiner;
    const double tol = kRelativeTolerance * boundingBoxDiagonal(r.mesh.positions);
    const int numControl = r.mesh.numVertices();

    std::vector<VulkanStencilTable> levelTables, factorized;
    std::vector<StencilTable> factorizedHost;
    for (int L = 1; L <= maxLevel; ++L) {
        levelTables.emplace_back(*ctx, refiner.levelStencils(L));
        factorizedHost.push_back(refiner.factorizedStencils(L));
        factorized.emplace_back(*ctx, factorizedHost.back());
    }
    std::vector<const VulkanStencilTable*> levelPointers;
    for (const auto& t : levelTables) levelPointers.push_back(&t);
    const std::vector<int> first = VulkanEvaluator::levelFirstElements(levelPointers);
    VulkanEvaluator evaluator(*ctx);

    for (const BufferDescriptor& d : kLayouts) {
        const std::string where = GetParam() + " width " + std::to_string(d.length) + " stride " + std::to_string(d.stride);
        const std::vector<float> control = primvar(r.mesh.positions, d.length);

        // Per level: every level in one buffer, CPU level by level on the same layout.
        std::vector<float> expected = layout(control, d, first.back(), kUntouched);
        for (int L = 1; L <= maxLevel; ++L) {
            const BufferDescriptor src(d.offset + first[L - 1] * d.stride, d.length, d.stride);
            const BufferDescriptor dst(d.offset + first[L] * d.stride, d.length, d.stride);
            CpuEvaluator::EvalStencils(expected.data(), src, expected.data(), dst, refiner.levelStencils(L));
        }
        const int elements = int((expected.size() + d.stride - 1) / d.stride);
        std::vector<float> host(std::size_t(elements) * d.stride, kUntouched);
        std::copy(expected.begin(), expected.begin() + layoutFloats(d, numControl), host.begin());
        expected.resize(host.size(), kUntouched);
        VulkanVertexBuffer all = VulkanVertexBuffer::create(*ctx, elements, d.stride);
        all.updateData(host.data(), 0, elements);
        evaluator.EvalLevelsAndWait(all, d, levelPointers);
        all.readBack(host.data());
        expectSameLayout(host, expected, d, tol, where + " per level");

        // Factorized: level L straight from the control vertices, one dispatch.
        const BufferDescriptor srcDesc(d.offset, d.length, d.stride);
        const std::vector<float> controlLaid = layout(control, srcDesc, numControl, kUntouched);
        VulkanVertexBuffer src = VulkanVertexBuffer::create(*ctx, numControl + 1, d.stride);
        std::vector<float> padded(src.numFloats(), kUntouched);
        std::copy(controlLaid.begin(), controlLaid.end(), padded.begin());
        src.updateData(padded.data(), 0, src.numElements());
        for (int L = 1; L <= maxLevel; ++L) {
            const StencilTable& table = factorizedHost[L - 1];
            const int n = table.numStencils();
            std::vector<float> want(std::size_t(n + 1) * d.stride, kUntouched);
            CpuEvaluator::EvalStencils(padded.data(), srcDesc, want.data(), srcDesc, table);
            VulkanVertexBuffer dst = VulkanVertexBuffer::create(*ctx, n + 1, d.stride);
            dst.updateData(std::vector<float>(dst.numFloats(), kUntouched).data(), 0, n + 1);
            evaluator.EvalStencilsAndWait(src, srcDesc, dst, srcDesc, factorized[L - 1]);
            std::vector<float> got(dst.numFloats());
            dst.readBack(got.data());
            expectSameLayout(got, want, srcDesc, tol, where + " factorized level " + std::to_string(L));
        }
    }
}

INSTANTIATE_TEST_SUITE_P(AllMeshes, VulkanMeshTest, testing::ValuesIn(allMeshes()), testName);

// Ranges [start, end) write exactly their rows, recorded into one command buffer of the
// caller's (more evaluations than one descriptor pool holds).
TEST_F(VulkanTest, RangesWriteOnlyTheirRows) {
    const RefinedMesh r = refineMesh("osd/catmark_torus.obj", 2);
    const StencilTable table = r.refiner->factorizedStencils(2);
    const int n = table.numStencils();
    const BufferDescriptor d(2, 3, 5);
    const std::vector<float> control = layout(r.mesh.positions, d, r.mesh.numVertices(), kUntouched);
    std::vector<float> full(layoutFloats(d, n), kUntouched);
    CpuEvaluator::EvalStencils(control.data(), d, full.data(), d, table);

    VulkanStencilTable gpuTable(*ctx, table);
    VulkanEvaluator evaluator(*ctx);
    VulkanVertexBuffer src = VulkanVertexBuffer::create(*ctx, int((control.size() + d.stride - 1) / d.stride), d.stride);
    std::vector<float> paddedControl(src.numFloats(), kUntouched);
    std::copy(control.begin(), control.end(), paddedControl.begin());
    src.updateData(paddedControl.data(), 0, src.numElements());
    const int elements = int((full.size() + d.stride - 1) / d.stride);
    const std::vector<std::pair<int, int>> ranges = {{0, 0}, {5, 17}, {n - 3, n}, {n, n}, {0, 1}, {100, 164}};
    for (const auto& [start, end] : ranges) {
        VulkanVertexBuffer dst = VulkanVertexBuffer::create(*ctx, elements, d.stride);
        std::vector<float> got(dst.numFloats(), kUntouched), want(dst.numFloats(), kUntouched);
        dst.updateData(got.data(), 0, elements);
        CpuEvaluator::EvalStencils(control.data(), d, want.data(), d, table, start, end);
        // 70 one-stencil evaluations in the same command buffer: more sets than one pool holds.
        ctx->submitAndWait([&](VkCommandBuffer cmd) {
            for (int i = 0; i < 70; ++i) evaluator.EvalStencils(cmd, src, d, dst, d, gpuTable, start, end);
        });
        evaluator.resetDescriptorSets();
        dst.readBack(got.data());
        const std::string what = "range [" + std::to_string(start) + ", " + std::to_string(end) + ")";
        expectSameLayout(got, want, d, 1e-5 * boundingBoxDiagonal(r.mesh.positions), what);
    }
}

TEST_F(VulkanTest, RejectsBadArguments) {
    const StencilTable t = handCheckedTable();
    VulkanStencilTable table(*ctx, t);
    VulkanEvaluator evaluator(*ctx);
    VulkanVertexBuffer src = VulkanVertexBuffer::create(*ctx, 4, 4), dst = VulkanVertexBuffer::create(*ctx, 3, 4);
    auto eval = [&](BufferDescriptor s, BufferDescriptor d, int start, int end) {
        evaluator.EvalStencilsAndWait(src, s, dst, d, table, start, end);
    };
    EXPECT_THROW(eval({0, 3, 2}, {0, 3, 3}, 0, -1), std::invalid_argument);   // stride < length
    EXPECT_THROW(eval({0, 3, 3}, {0, 4, 4}, 0, -1), std::invalid_argument);   // length mismatch
    EXPECT_THROW(eval({-1, 3, 3}, {0, 3, 3}, 0, -1), std::invalid_argument);  // negative offset
    EXPECT_THROW(eval({0, 3, 3}, {0, 3, 3}, 2, 1), std::invalid_argument);    // start > end
    EXPECT_THROW(eval({0, 3, 3}, {0, 3, 3}, 0, 4), std::invalid_argument);    // past the table
    EXPECT_THROW(eval({0, 3, 4}, {2, 3, 4}, 0, -1), std::invalid_argument);   // dst too small
    EXPECT_THROW(eval({5, 3, 4}, {0, 3, 4}, 0, -1), std::invalid_argument);   // src too small
    EXPECT_NO_THROW(eval({0, 3, 4}, {0, 3, 4}, 1, 1));                        // empty range
    ctx->submitAndWait([&](VkCommandBuffer cmd) {
        EXPECT_THROW(evaluator.EvalStencils(cmd, VulkanBufferRef{}, {0, 3, 3}, {dst.buffer(), 0}, {0, 3, 3}, table),
                     std::invalid_argument);  // null buffer
        EXPECT_THROW(evaluator.EvalStencils(cmd, {src.buffer(), 2}, {0, 3, 3}, {dst.buffer(), 0}, {0, 3, 3}, table),
                     std::invalid_argument);  // byte offset not a multiple of 4
    });
    EXPECT_NO_THROW(eval({0, 3, 4}, {0, 3, 4}, 0, -1));
    std::vector<float> out(dst.numFloats());
    dst.readBack(out.data());
    EXPECT_EQ(out[0], 0.0f);  // create() zero-fills; sources are zero
}

// One EvalStencils call on the 3-stencil hand-checked table, and whether it must be accepted.
struct Call {
    const char* what;
    BufferDescriptor src, dst;
    int start, end;
    bool nullSrc, nullDst, accepted;
};

const Call kCalls[] = {
    {"stride < length", {0, 3, 2}, {0, 3, 3}, 0, -1, false, false, false},
    {"negative offset", {0, 3, 3}, {-1, 3, 3}, 0, -1, false, false, false},
    {"zero length", {0, 0, 0}, {0, 0, 0}, 0, -1, false, false, false},
    {"negative stride", {0, 3, 3}, {0, 3, -1}, 0, -1, false, false, false},
    {"length mismatch", {0, 3, 3}, {0, 4, 4}, 0, -1, false, false, false},
    {"start > end", {0, 3, 3}, {0, 3, 3}, 2, 1, false, false, false},
    {"end past the table", {0, 3, 3}, {0, 3, 3}, 0, 4, false, false, false},
    {"negative start", {0, 3, 3}, {0, 3, 3}, -1, 2, false, false, false},
    {"null source", {0, 3, 3}, {0, 3, 3}, 0, -1, true, false, false},
    {"null destination", {0, 3, 4}, {1, 3, 4}, 1, 2, false, true, false},
    {"null buffer, invalid descriptor", {0, 3, 2}, {0, 3, 3}, 0, -1, true, false, false},
    {"null buffer, range past the table", {0, 3, 3}, {0, 3, 3}, 0, 4, false, true, false},
    {"null buffers, empty range", {0, 3, 3}, {0, 3, 3}, 1, 1, true, true, true},
    {"empty range at the end (end < 0)", {0, 3, 3}, {0, 3, 3}, 3, -1, false, false, true},
    {"every stencil", {1, 4, 4}, {2, 4, 5}, 0, -1, false, false, true},
    {"a range", {0, 3, 3}, {0, 3, 3}, 1, 3, false, false, true},
};

// "accepted", or the std::invalid_argument's message.
template <class Eval>
std::string outcome(Eval&& eval) {
    try {
        eval();
        return "accepted";
    } catch (const std::invalid_argument& e) {
        return std::string("rejected: ") + e.what();
    }
}

// The device reads whatever the table says: offsets that do not span the indices, or a stencil
// whose weights reach past the pool, are refused on upload.
// Per-level tables kept up to date with edits (Refiner::applyEdits) and their device copies
// updated by range where the entries stayed put (VulkanStencilTable::update): after every tenth of
// 40 random edits the device evaluates each level as a fresh copy of the host table does, bit for
// bit; a copy whose entries moved is refused the update.
TEST_F(VulkanTest, PerLevelTablesUpdatedByRangeEqualFreshCopies) {
    const io::ObjMesh mesh = io::readObj(meshPath("mixed/mixed_torus.obj"));
    Options options;
    options.scheme = Scheme::SchaeferWarren;
    std::unique_ptr<Refiner> refiner = build(mesh, options, 3);
    std::vector<VulkanStencilTable> device;
    for (int L = 1; L <= 3; ++L) device.emplace_back(*ctx, refiner->levelStencils(L), true);
    const BufferDescriptor d(0, 3, 3);
    auto evaluate = [&](const VulkanStencilTable& table, int L) {
        // Any data will do, as long as it differs from vertex to vertex.
        std::vector<float> source(3 * std::size_t(refiner->faces(L - 1).numVertices()));
        for (std::size_t i = 0; i < source.size(); ++i) source[i] = float(i % 97) * 0.01f + float(i % 5);
        VulkanVertexBuffer src = VulkanVertexBuffer::create(*ctx, int(source.size() / 3), 3);
        src.updateData(source.data(), 0, src.numElements());
        VulkanVertexBuffer dst = VulkanVertexBuffer::create(*ctx, table.numStencils(), 3);
        VulkanEvaluator evaluator(*ctx);
        evaluator.EvalStencilsAndWait(src, d, dst, d, table);
        std::vector<float> out(dst.numFloats());
        dst.readBack(out.data());
        return out;
    };
    std::mt19937 random(29);
    int byRange = 0, copied = 0;
    for (int k = 1; k <= 40; ++k) {
        const EditReport report = refiner->applyEdits(randomEdits(refiner->level(0), random, false));
        for (int L = 1; L <= 3; ++L) {
            const EditedLevel& edited = report.levels[std::size_t(L)];
            if (edited.stencils.empty()) continue;
            VulkanStencilTable& copy = device[std::size_t(L) - 1];
            if (copy.update(*ctx, refiner->levelStencils(L), edited.stencils, edited.tableResized, edited.poolLaidOut)) {
                ++byRange;
            } else {
                EXPECT_TRUE(edited.tableResized || edited.poolLaidOut) << "edit " << k << ", level " << L;
                copy = VulkanStencilTable(*ctx, refiner->levelStencils(L), true);
                ++copied;
            }
        }
        if (k % 10 != 0) continue;
        for (int L = 1; L <= 3; ++L)
            EXPECT_EQ(evaluate(device[std::size_t(L) - 1], L), evaluate(VulkanStencilTable(*ctx, refiner->levelStencils(L)), L))
                << "edit " << k << ", level " << L;
    }
    EXPECT_GT(byRange, 10);
    EXPECT_GT(copied, 0);  // creases that start or end change a stencil's size
}

TEST_F(VulkanTest, InconsistentStencilTablesAreRefused) {
    const StencilTable good = handCheckedTable();
    StencilTable shortIndices = good, pastThePool = good;
    shortIndices.indices.pop_back();
    pastThePool.weightOffsets.back() = int(good.weights.size()) - good.size(good.numStencils() - 1) + 1;
    for (const StencilTable& t : {shortIndices, pastThePool})
        EXPECT_EQ(outcome([&] { const VulkanStencilTable uploaded(*ctx, t); }),
                  "rejected: VulkanStencilTable: inconsistent StencilTable arrays");
    EXPECT_EQ(outcome([&] { const VulkanStencilTable uploaded(*ctx, good); }), "accepted");
}

TEST_F(VulkanTest, SameArgumentChecksAsHostEvaluators) {
    const StencilTable t = handCheckedTable();
    VulkanStencilTable table(*ctx, t);
    VulkanEvaluator evaluator(*ctx);
    VulkanVertexBuffer src = VulkanVertexBuffer::create(*ctx, 16, 4), dst = VulkanVertexBuffer::create(*ctx, 16, 4);
    std::vector<float> hostSrc(src.numFloats()), hostDst(dst.numFloats());
    std::vector<std::string> onDevice;
    ctx->submitAndWait([&](VkCommandBuffer cmd) {
        for (const Call& c : kCalls) {
            const VulkanBufferRef s{c.nullSrc ? VK_NULL_HANDLE : src.buffer(), 0};
            const VulkanBufferRef d{c.nullDst ? VK_NULL_HANDLE : dst.buffer(), 0};
            onDevice.push_back(outcome([&] { evaluator.EvalStencils(cmd, s, c.src, d, c.dst, table, c.start, c.end); }));
        }
    });
    evaluator.resetDescriptorSets();
    for (std::size_t i = 0; i < std::size(kCalls); ++i) {
        const Call& c = kCalls[i];
        const float* s = c.nullSrc ? nullptr : hostSrc.data();
        float* d = c.nullDst ? nullptr : hostDst.data();
        const std::string cpu = outcome([&] { CpuEvaluator::EvalStencils(s, c.src, d, c.dst, t, c.start, c.end); });
        const std::string tbb = outcome([&] { TbbEvaluator::EvalStencils(s, c.src, d, c.dst, t, c.start, c.end); });
        EXPECT_EQ(cpu == "accepted", c.accepted) << c.what << ": " << cpu;
        EXPECT_EQ(tbb, cpu) << c.what;
        EXPECT_EQ(onDevice[i], cpu) << c.what;
        // The VulkanVertexBuffer overloads take no null buffer; the rest must match too.
        if (c.nullSrc || c.nullDst) continue;
        EXPECT_EQ(outcome([&] { evaluator.EvalStencilsAndWait(src, c.src, dst, c.dst, table, c.start, c.end); }), cpu)
            << c.what;
    }
}

}  // namespace
}  // namespace quadtri::test
