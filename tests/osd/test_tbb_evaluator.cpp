// TbbEvaluator against CpuEvaluator: bit-identical output on every test mesh (per-level and
// factorized tables), for several widths, strides, offsets and ranges, in task arenas of 1 and 2
// threads; and the same argument checking.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

// Fills the padding, the floats before element 0 and rows that must stay untouched.
constexpr float kUntouched = -12345.5f;
constexpr int kWidths[] = {1, 3, 4, 7};
constexpr int kThreads[] = {1, 2};


// Layouts with padding after every element and floats before element 0 (different on each side).
BufferDescriptor srcLayout(int width) { return BufferDescriptor(3, width, width + 2); }
BufferDescriptor dstLayout(int width) { return BufferDescriptor(5, width, width + 2); }

size_t bufferSize(const BufferDescriptor& d, int count) { return size_t(d.offset) + size_t(count) * size_t(d.stride); }

// Per-vertex source data: `xyz` (3 floats per vertex) when given, else generated values.
std::vector<float> makeSource(int width, int count, const std::vector<float>* xyz = nullptr) {
    const BufferDescriptor d = srcLayout(width);
    std::vector<float> src(bufferSize(d, count), kUntouched);
    for (int v = 0; v < count; ++v)
        for (int c = 0; c < width; ++c)
            src[d.offset + size_t(v) * d.stride + c] =
                xyz ? (*xyz)[3 * size_t(v) + c] : float(std::sin(0.731 * v + 1.37 * c + 0.2) * (1 + c));
    return src;
}

// Runs `fn` inside a task arena of `threads` threads.
template <class Fn>
void inArena(int threads, Fn&& fn) {
    tbb::task_arena arena(threads);
    arena.execute([&] {
        EXPECT_EQ(tbb::this_task_arena::max_concurrency(), threads);
        fn();
    });
}

// "" when a and b hold the same bits, else where they first differ.
std::string difference(const std::vector<float>& a, const std::vector<float>& b) {
    if (a.size() != b.size()) return "sizes " + std::to_string(a.size()) + " and " + std::to_string(b.size());
    if (std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0) return "";
    for (size_t i = 0; i < a.size(); ++i)
        if (std::memcmp(&a[i], &b[i], sizeof(float)) != 0) {
            std::ostringstream out;
            out.precision(9);
            out << "float " << i << ": " << a[i] << " vs " << b[i];
            return out.str();
        }
    return "";
}

// The padding and the floats before element 0 of a destination buffer still hold kUntouched.
bool paddingUntouched(const std::vector<float>& dst, int width, int count) {
    const BufferDescriptor d = dstLayout(width);
    for (int i = 0; i < d.offset; ++i)
        if (dst[i] != kUntouched) return false;
    for (int v = 0; v < count; ++v)
        for (int c = width; c < d.stride; ++c)
            if (dst[d.offset + size_t(v) * d.stride + c] != kUntouched) return false;
    return true;
}

// All stencils of `table` through both evaluators, for every width, in arenas of 1 and 2 threads.
// `xyz` (positions of the table's source vertices) is the width-3 data.
void expectSameAsCpu(const StencilTable& table, const std::vector<float>& xyz, const std::string& what) {
    const int n = table.numStencils();
    for (int width : kWidths) {
        const std::vector<float> src = makeSource(width, table.numSourceVertices, width == 3 ? &xyz : nullptr);
        std::vector<float> expected(bufferSize(dstLayout(width), n), kUntouched);
        CpuEvaluator::EvalStencils(src.data(), srcLayout(width), expected.data(), dstLayout(width), table);
        for (int threads : kThreads) {
            std::vector<float> got(expected.size(), kUntouched);
            inArena(threads, [&] {
                TbbEvaluator::EvalStencils(src.data(), srcLayout(width), got.data(), dstLayout(width), table);
            });
            const std::string diff = difference(expected, got);
            EXPECT_EQ(diff, "") << what << ", width " << width << ", " << threads << " thread(s)";
            EXPECT_TRUE(paddingUntouched(got, width, n)) << what << ", width " << width << ", " << threads << " thread(s)";
        }
    }
}

class TbbEvaluatorMeshes : public ::testing::TestWithParam<std::string> {};

TEST_P(TbbEvaluatorMeshes, BitIdenticalToCpuEvaluator) {
    const io::ObjMesh probe = io::readObj(meshPath(GetParam()));
    const int maxLevel = probe.numFaces() > 500 ? 2 : 3;
    const RefinedMesh r = refineMesh(GetParam(), maxLevel);
    for (int L = 1; L <= maxLevel; ++L) {
        const StencilTable& perLevel = r.refiner->levelStencils(L);
        expectSameAsCpu(perLevel, r.positions[L - 1], "level " + std::to_string(L) + " per-level table");
        const StencilTable factorized = r.refiner->factorizedStencils(L);
        expectSameAsCpu(factorized, r.positions[0], "level " + std::to_string(L) + " factorized table");
    }
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) { return testNameOf(info.param); }

INSTANTIATE_TEST_SUITE_P(AllMeshes, TbbEvaluatorMeshes, ::testing::ValuesIn(allMeshes()), testName);

// A table large enough to be split into many blocks: stencils of 1..24 random entries, each
// with weights of its own in the pool.
StencilTable randomTable(int numStencils, int numSources) {
    std::mt19937 rng(12345);
    std::uniform_int_distribution<int> size(1, 24), vertex(0, numSources - 1);
    std::uniform_real_distribution<float> weight(-0.5f, 1.0f);
    StencilTable t;
    t.numSourceVertices = numSources;
    for (int i = 0; i < numStencils; ++i) {
        t.weightOffsets.push_back(int(t.weights.size()));
        const int n = size(rng);
        for (int k = 0; k < n; ++k) {
            t.indices.push_back(vertex(rng));
            t.weights.push_back(weight(rng));
        }
        t.offsets.push_back(int(t.indices.size()));
    }
    return t;
}

TEST(TbbEvaluator, LargeTableBitIdenticalToCpuEvaluator) {
    const StencilTable t = randomTable(40000, 5000);
    for (int width : kWidths) {
        const std::vector<float> src = makeSource(width, t.numSourceVertices);
        std::vector<float> expected(bufferSize(dstLayout(width), t.numStencils()), kUntouched);
        CpuEvaluator::EvalStencils(src.data(), srcLayout(width), expected.data(), dstLayout(width), t);
        for (int threads : kThreads) {
            std::vector<float> got(expected.size(), kUntouched);
            inArena(threads, [&] { TbbEvaluator::EvalStencils(src.data(), srcLayout(width), got.data(), dstLayout(width), t); });
            EXPECT_EQ(difference(expected, got), "") << "width " << width << ", " << threads << " thread(s)";
            EXPECT_TRUE(paddingUntouched(got, width, t.numStencils()));
        }
    }
}

TEST(TbbEvaluator, RangeWritesExactlyItsRows) {
    const StencilTable t = randomTable(20000, 3000);
    const int n = t.numStencils();
    // Empty ranges (at both ends and inside), single stencils, ranges around power-of-two sizes
    // (where a threaded evaluator switches between serial and split), unaligned and whole ranges.
    const std::vector<std::pair<int, int>> ranges = {
        {0, 0},       {n, n},       {777, 777},   {0, 1},       {n - 1, n},   {4321, 4322}, {1, 4096},
        {3, 4100},    {5, 8197},    {100, 8291},  {0, 2047},    {0, 2048},    {0, 2049},    {1, 4097},
        {999, 16999}, {1, n - 1},   {0, n},       {12345, n},   {0, -1},      {n / 2, -1},
    };
    for (int width : kWidths) {
        const BufferDescriptor dd = dstLayout(width);
        const std::vector<float> src = makeSource(width, t.numSourceVertices);
        std::vector<float> all(bufferSize(dd, n), kUntouched);
        CpuEvaluator::EvalStencils(src.data(), srcLayout(width), all.data(), dd, t);
        for (auto [start, end] : ranges) {
            // Rows [start, end) of the full evaluation, everything else untouched.
            const int last = end < 0 ? n : end;
            std::vector<float> expected(all.size(), kUntouched);
            for (int i = start; i < last; ++i)
                std::copy_n(all.begin() + dd.offset + size_t(i) * dd.stride, width,
                            expected.begin() + dd.offset + size_t(i) * dd.stride);
            std::vector<float> cpu(all.size(), kUntouched);
            CpuEvaluator::EvalStencils(src.data(), srcLayout(width), cpu.data(), dd, t, start, end);
            ASSERT_EQ(difference(expected, cpu), "") << "CpuEvaluator range [" << start << ", " << end << ")";
            for (int threads : kThreads) {
                std::vector<float> got(all.size(), kUntouched);
                inArena(threads, [&] { TbbEvaluator::EvalStencils(src.data(), srcLayout(width), got.data(), dd, t, start, end); });
                EXPECT_EQ(difference(expected, got), "")
                    << "range [" << start << ", " << end << "), width " << width << ", " << threads << " thread(s)";
            }
        }
    }
}

TEST(TbbEvaluator, RangeOnSmallTable) {
    // The hand-checked table of test_cpu_evaluator.cpp: 0.5 s0 + 0.5 s1, s3, 0.25 (s0 + s1 + s2 + s3).
    const StencilTable t = handCheckedTable();
    std::vector<float> src(12);
    for (int v = 0; v < 4; ++v)
        for (int c = 0; c < 3; ++c) src[3 * v + c] = float(10 * v + c + 1);
    for (int threads : kThreads) {
        std::vector<float> dst(9, -1.0f);
        inArena(threads, [&] {
            TbbEvaluator::EvalStencils(src.data(), BufferDescriptor(0, 3, 3), dst.data(), BufferDescriptor(0, 3, 3), t, 1, 2);
        });
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(dst[c], -1.0f);
            EXPECT_EQ(dst[3 + c], src[9 + c]);
            EXPECT_EQ(dst[6 + c], -1.0f);
        }
        inArena(threads, [&] {
            TbbEvaluator::EvalStencils(src.data(), BufferDescriptor(0, 3, 3), dst.data(), BufferDescriptor(0, 3, 3), t);
        });
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(dst[c], 0.5f * (src[c] + src[3 + c]));
            EXPECT_EQ(dst[6 + c], 0.25f * (src[c] + src[3 + c] + src[6 + c] + src[9 + c]));
        }
    }
}

TEST(TbbEvaluator, RejectsBadArgumentsLikeCpuEvaluator) {
    const StencilTable t = handCheckedTable();
    std::vector<float> src(16), dst(16);
    auto tbbEval = [&](BufferDescriptor s, BufferDescriptor d, int start, int end) {
        TbbEvaluator::EvalStencils(src.data(), s, dst.data(), d, t, start, end);
    };
    auto cpuEval = [&](BufferDescriptor s, BufferDescriptor d, int start, int end) {
        CpuEvaluator::EvalStencils(src.data(), s, dst.data(), d, t, start, end);
    };
    for (const auto& eval : {std::function<void(BufferDescriptor, BufferDescriptor, int, int)>(tbbEval),
                             std::function<void(BufferDescriptor, BufferDescriptor, int, int)>(cpuEval)}) {
        EXPECT_THROW(eval({0, 3, 2}, {0, 3, 3}, 0, -1), std::invalid_argument);   // stride < length
        EXPECT_THROW(eval({0, 3, 3}, {0, 4, 4}, 0, -1), std::invalid_argument);   // length mismatch
        EXPECT_THROW(eval({-1, 3, 3}, {0, 3, 3}, 0, -1), std::invalid_argument);  // negative offset
        EXPECT_THROW(eval({0, 3, 3}, {0, 3, 3}, 2, 1), std::invalid_argument);    // start > end
        EXPECT_THROW(eval({0, 3, 3}, {0, 3, 3}, 0, 4), std::invalid_argument);    // past the table
        EXPECT_THROW(eval({0, 3, 3}, {0, 3, -1}, 0, -1), std::invalid_argument);  // negative stride
        EXPECT_THROW(eval({0, 0, 0}, {0, 0, 0}, 0, -1), std::invalid_argument);   // zero length
        EXPECT_THROW(eval({0, 3, 3}, {0, 3, 3}, -1, 2), std::invalid_argument);   // negative start
        EXPECT_NO_THROW(eval({0, 3, 3}, {0, 3, 3}, 3, 3));                         // empty range at the end
    }
    // Null buffers: rejected unless there is nothing to evaluate.
    EXPECT_THROW(TbbEvaluator::EvalStencils(nullptr, {0, 3, 3}, dst.data(), {0, 3, 3}, t), std::invalid_argument);
    EXPECT_THROW(TbbEvaluator::EvalStencils(src.data(), {0, 3, 3}, nullptr, {0, 3, 3}, t), std::invalid_argument);
    EXPECT_NO_THROW(TbbEvaluator::EvalStencils(nullptr, {0, 3, 3}, nullptr, {0, 3, 3}, t, 1, 1));
    EXPECT_THROW(CpuEvaluator::EvalStencils(nullptr, {0, 3, 3}, dst.data(), {0, 3, 3}, t), std::invalid_argument);
    EXPECT_NO_THROW(CpuEvaluator::EvalStencils(nullptr, {0, 3, 3}, nullptr, {0, 3, 3}, t, 1, 1));
}

}  // namespace
}  // namespace quadtri::test
