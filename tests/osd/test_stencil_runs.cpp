// StencilRuns (osd/stencil_runs.h): its runs and chunks cover the table in order, the chunks'
// groups list each stencil once, all agree with the table's per-stencil arrays, and evaluating
// through them gives the table's own bits on CpuEvaluator and TbbEvaluator, for every width,
// padded layouts and ranges that start and end inside runs and chunks.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/meshes/torus.h"
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/stencil_runs.h>
#include <quadtri/osd/tbb_evaluator.h>
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

struct Case {
    const char* name;
    bench::TorusFaces faces;
    Scheme scheme;
};
// Catmull-Clark and Loop tables are a few long runs after a level; Schaefer-Warren's of a mixed
// mesh have many short ones, which become chunks of stretches.
const Case kCases[] = {{"quads", bench::TorusFaces::Quads, Scheme::StamLoop},
                       {"triangles", bench::TorusFaces::Triangles, Scheme::StamLoop},
                       {"mixed", bench::TorusFaces::Mixed, Scheme::SchaeferWarren}};
constexpr int kLevels = 3;

std::unique_ptr<Refiner> refinedTorus(const Case& c) {
    const bench::ControlMesh m = bench::makeTorus(20, c.faces);
    Options options;
    options.scheme = c.scheme;
    auto refiner = std::make_unique<Refiner>(descriptorOf(m.numVertices, m.faceSizes, m.faceVerts), options);
    refiner->refineUniform(kLevels);
    return refiner;
}

TEST(StencilRuns, CoverTheTableAndAgreeWithItsArrays) {
    for (const Case& c : kCases) {
        const std::unique_ptr<Refiner> refiner = refinedTorus(c);
        for (int L = 1; L <= kLevels; ++L) {
            const StencilTable& t = refiner->levelStencils(L);
            const StencilRuns runs(t);
            ASSERT_EQ(runs.numStencils(), t.numStencils());
            const std::string where = std::string(c.name) + " level " + std::to_string(L);
            int next = 0, inRuns = 0;
            std::vector<int> listed(t.numStencils(), 0);
            for (std::size_t k = 0; k < runs.runs().size(); ++k) {
                const StencilRun& r = runs.runs()[k];
                ASSERT_EQ(r.firstStencil, next) << where << " run " << k;
                ASSERT_GT(r.numStencils, 0) << where << " run " << k;
                next += r.numStencils;
                if (r.firstGroup >= 0) {  // a chunk: its groups list each of its stencils once, by mask
                    EXPECT_LE(r.numStencils, StencilRuns::kChunk) << where << " run " << k;
                    EXPECT_EQ(r.size, 0) << where << " run " << k;
                    EXPECT_EQ(r.weightOffset, -1) << where << " run " << k;
                    for (int g = r.firstGroup, done = 0; done < r.numStencils; done += runs.groups()[g].count, ++g) {
                        ASSERT_LT(g, int(runs.groups().size())) << where << " run " << k;
                        const StencilGroup& group = runs.groups()[g];
                        ASSERT_GT(group.count, 0) << where << " group " << g;
                        for (int q = group.first; q < group.first + group.count; ++q) {
                            const int i = runs.order()[q];
                            ASSERT_TRUE(i >= r.firstStencil && i < next) << where << " group " << g;
                            ++listed[i];
                            ASSERT_EQ(t.size(i), group.size) << where << " stencil " << i;
                            ASSERT_EQ(t.weightOffsets[i], group.weightOffset) << where << " stencil " << i;
                        }
                    }
                    continue;
                }
                EXPECT_GE(r.numStencils, StencilRuns::kMinRun) << where << " run " << k;
                inRuns += r.numStencils;
                for (int i = r.firstStencil; i < next; ++i) {
                    ++listed[i];
                    ASSERT_EQ(t.size(i), r.size) << where << " stencil " << i;
                    ASSERT_EQ(t.weightOffsets[i], r.weightOffset) << where << " stencil " << i;
                }
            }
            for (int i = 0; i < t.numStencils(); ++i) ASSERT_EQ(listed[i], 1) << where << " stencil " << i;
            EXPECT_EQ(next, t.numStencils()) << where;
            // After a level, nearly every quad and triangle stencil is in a run.
            if (c.scheme == Scheme::StamLoop && L >= 2) {
                EXPECT_GT(inRuns, 0.9 * t.numStencils()) << where;
            }
        }
    }
}

// Distinct values in every component, with the padding and the floats before element 0 filled.
std::vector<float> source(const BufferDescriptor& d, int count) {
    std::vector<float> src(std::size_t(d.offset) + std::size_t(count) * d.stride, -5.5f);
    for (int v = 0; v < count; ++v)
        for (int c = 0; c < d.length; ++c)
            src[d.offset + std::size_t(v) * d.stride + c] = float(std::sin(0.37 * v + 1.1 * c) + 0.01 * (v % 89));
    return src;
}

using Eval = void (*)(const float*, const BufferDescriptor&, float*, const BufferDescriptor&, const StencilRuns&, int,
                      int);

// Through the runs (CpuEvaluator or TbbEvaluator) against CpuEvaluator on the table itself, whole
// and in pieces whose ends fall inside runs; untouched floats stay untouched.
void expectTheTablesBits(const StencilTable& t, Eval eval, const std::string& where) {
    const StencilRuns runs(t);
    const int n = t.numStencils();
    for (int width : {1, 3, 4, 7}) {
        const BufferDescriptor s(2, width, width + 1), d(3, width, width + 2);
        const std::vector<float> src = source(s, t.numSourceVertices);
        std::vector<float> expected(std::size_t(d.offset) + std::size_t(n) * d.stride, -9.0f);
        std::vector<float> whole = expected, pieces = expected;
        CpuEvaluator::EvalStencils(src.data(), s, expected.data(), d, t);
        eval(src.data(), s, whole.data(), d, runs, 0, -1);
        for (int b = 0; b < n;) {
            const int e = std::min(n, b + 1 + (b * 7919) % 5003);  // pieces of 1 to 5003 stencils
            eval(src.data(), s, pieces.data(), d, runs, b, e);
            b = e;
        }
        const std::size_t bytes = expected.size() * sizeof(float);
        EXPECT_EQ(std::memcmp(whole.data(), expected.data(), bytes), 0) << where << " width " << width;
        EXPECT_EQ(std::memcmp(pieces.data(), expected.data(), bytes), 0) << where << " width " << width << " in pieces";
    }
}

TEST(StencilRuns, CpuEvaluatorGivesTheTablesBits) {
    for (const Case& c : kCases) {
        const std::unique_ptr<Refiner> refiner = refinedTorus(c);
        for (int L = 1; L <= kLevels; ++L)
            expectTheTablesBits(refiner->levelStencils(L), CpuEvaluator::EvalStencilRuns,
                                std::string(c.name) + " level " + std::to_string(L));
    }
}

TEST(StencilRuns, TbbEvaluatorGivesTheTablesBits) {
    for (const Case& c : kCases) {
        const std::unique_ptr<Refiner> refiner = refinedTorus(c);
        for (int threads : {1, 2}) {
            tbb::task_arena arena(threads);
            arena.execute([&] {
                for (int L = 1; L <= kLevels; ++L)
                    expectTheTablesBits(refiner->levelStencils(L), TbbEvaluator::EvalStencilRuns,
                                        std::string(c.name) + " level " + std::to_string(L) + ", " +
                                            std::to_string(threads) + " threads");
            });
        }
    }
}

TEST(StencilRuns, RejectATableThatChangedAndBadRanges) {
    StencilTable t = handCheckedTable();
    const StencilRuns runs(t);
    std::vector<float> src(64, 1.0f), dst(64);
    const BufferDescriptor d(0, 3, 3);
    EXPECT_THROW(CpuEvaluator::EvalStencilRuns(src.data(), d, dst.data(), d, runs, 0, 4), std::invalid_argument);
    EXPECT_THROW(TbbEvaluator::EvalStencilRuns(src.data(), d, dst.data(), d, runs, 2, 1), std::invalid_argument);
    t.indices.push_back(0);  // one more stencil of one entry
    t.offsets.push_back(int(t.indices.size()));
    t.weightOffsets.push_back(0);
    EXPECT_THROW(CpuEvaluator::EvalStencilRuns(src.data(), d, dst.data(), d, runs), std::invalid_argument);
    EXPECT_THROW(TbbEvaluator::EvalStencilRuns(src.data(), d, dst.data(), d, runs), std::invalid_argument);
}

}  // namespace
}  // namespace quadtri::test
