// Per-level and factorized tables describe the same refinement; the float tables' weight pool
// shares exactly the bitwise-equal masks and evaluates as the plain CSR layout would.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>

#include "bench/meshes/sphere.h"
#include "bench/meshes/torus.h"
#include "far/tables/level_stencils.h"
#include "far/schemes/scheme.h"
#include "far/tables/weight_pool.h"
#include "kernels/stencil_kernel.h"
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#include "tests/test_support.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri::test {
namespace {


// Evaluation in double, so that the comparison sees the tables and not float rounding of the data.
std::vector<double> evaluateDouble(const StencilTable& t, const std::vector<double>& src) {
    std::vector<double> out(size_t(t.numStencils()) * 3, 0.0);
    for (int i = 0; i < t.numStencils(); ++i)
        for (int k = 0; k < t.size(i); ++k)
            for (int c = 0; c < 3; ++c)
                out[3 * i + c] += double(t.weightsOf(i)[k]) * src[3 * size_t(t.indices[t.offsets[i] + k]) + c];
    return out;
}

class StencilTables : public ::testing::TestWithParam<std::string> {};

TEST_P(StencilTables, FactorizedEqualsPerLevel) {
    const io::ObjMesh probe = io::readObj(meshPath(GetParam()));
    const int maxLevel = probe.numFaces() > 500 ? 2 : 3;
    for (Scheme scheme : {Scheme::StamLoop, Scheme::Bilinear}) {
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineMesh(GetParam(), maxLevel, options);
        const double diagonal = boundingBoxDiagonal(r.mesh.positions);
        for (int L = 1; L <= maxLevel; ++L) {
            const StencilTable factorized = r.refiner->factorizedStencils(L);
            ASSERT_EQ(factorized.numStencils(), r.refiner->level(L).numVertices);
            ASSERT_EQ(factorized.numSourceVertices, r.mesh.numVertices());
            const std::vector<double> control(r.mesh.positions.begin(), r.mesh.positions.end());
            std::vector<double> cascade = control;
            for (int l = 1; l <= L; ++l) cascade = evaluateDouble(r.refiner->levelStencils(l), cascade);
            const std::vector<double> direct = evaluateDouble(factorized, control);
            double worst = 0;
            for (size_t i = 0; i < direct.size(); ++i) worst = std::max(worst, std::abs(direct[i] - cascade[i]));
            EXPECT_LE(worst, 1e-6 * diagonal) << toString(scheme) << " level " << L;
            for (int i = 0; i < factorized.numStencils(); ++i)
                ASSERT_NEAR(stencilWeightSum(factorized, i), 1.0, 1e-6) << "stencil " << i << " level " << L;
        }
    }
}

TEST_P(StencilTables, PerLevelTablesAreConsistent) {
    const RefinedMesh r = refineMesh(GetParam(), 2);
    for (int L = 1; L <= 2; ++L) {
        const StencilTable& t = r.refiner->levelStencils(L);
        ASSERT_EQ(t.numSourceVertices, r.refiner->level(L - 1).numVertices);
        ASSERT_EQ(t.numStencils(), r.refiner->level(L).numVertices);
        ASSERT_EQ(t.offsets.size(), size_t(t.numStencils()) + 1);
        ASSERT_EQ(t.offsets[0], 0);
        for (int i = 0; i < t.numStencils(); ++i) {
            ASSERT_GT(t.size(i), 0) << "stencil " << i << " level " << L;
            ASSERT_GE(t.weightOffsets[i], 0);
            ASSERT_LE(size_t(t.weightOffsets[i]) + size_t(t.size(i)), t.weights.size());
            for (int k = t.offsets[i]; k < t.offsets[i + 1]; ++k) {
                ASSERT_GE(t.indices[k], 0);
                ASSERT_LT(t.indices[k], t.numSourceVertices);
            }
            ASSERT_NEAR(stencilWeightSum(t, i), 1.0, 1e-6) << "stencil " << i << " level " << L;
        }
        EXPECT_EQ(size_t(t.offsets.back()), t.numEntries());
        for (float w : t.weights) ASSERT_TRUE(std::isfinite(w));
        EXPECT_EQ(t.bytes(), (t.offsets.size() + t.indices.size() + t.weightOffsets.size()) * sizeof(int) +
                                 t.weights.size() * sizeof(float));
    }
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) { return testNameOf(info.param); }

INSTANTIATE_TEST_SUITE_P(AllMeshes, StencilTables, ::testing::ValuesIn(allMeshes()), testName);

TEST(StencilTableGuard, RefusesLevelsOverBudgetBeforeAllocating) {
    Options options;
    options.memoryBudgetBytes = 200000;
    const io::ObjMesh mesh = io::readObj(meshPath("osd/catmark_cube.obj"));
    Refiner refiner(mesh.descriptor(), options);
    try {
        refiner.refineUniform(8);
        FAIL() << "level 8 of a cube fits 200 kB?";
    } catch (const TopologyError& e) {
        EXPECT_NE(std::string(e.what()).find("bytes"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("budget"), std::string::npos) << e.what();
    }
    // The levels under budget were built and stay usable.
    EXPECT_GE(refiner.maxLevel(), 3);
    EXPECT_LE(refiner.estimateLevelBytes(refiner.maxLevel()), options.memoryBudgetBytes);
}

// The bench's meshes as descriptors (bench/meshes/torus.h, bench/meshes/sphere.h).
TopologyDescriptor descriptorOf(const bench::ControlMesh& mesh) {
    return test::descriptorOf(mesh.numVertices, mesh.faceSizes, mesh.faceVerts);
}

// A UV sphere with triangle fans at its poles: its factorized stencils near the poles span the
// whole pole ring, so they grow far faster than the per-level tables.
TEST(StencilTableGuard, FactorizedTablesAreBudgeted) {
    const bench::ControlMesh sphere = bench::makeUvSphere(400, 6, bench::SpherePoles::TriangleFans);
    Options options;
    options.memoryBudgetBytes = 64 << 20;
    Refiner refiner(descriptorOf(sphere), options);
    ASSERT_NO_THROW(refiner.refineUniform(3));  // per level, 3 levels fit in 64 MiB
    EXPECT_NO_THROW(refiner.factorizedStencils(1));
    try {
        refiner.factorizedStencils(3);  // over 8 M entries, about 100 MB in double
        FAIL() << "level 3's factorized stencils fit 64 MiB?";
    } catch (const TopologyError& e) {
        EXPECT_NE(std::string(e.what()).find("factorized stencils of level 3"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("budget"), std::string::npos) << e.what();
    }
    // Under the default budget it fits, and composes what the per-level tables give.
    Refiner roomy(descriptorOf(sphere), Options());
    roomy.refineUniform(2);
    const StencilTable factorized = roomy.factorizedStencils(2);
    EXPECT_EQ(factorized.numStencils(), roomy.faces(2).numVertices());
    EXPECT_LE(factorized.bytes() + roomy.bytes(), Options().memoryBudgetBytes);
}

// `pages` triangles sharing the edge 0-1, each with its own third vertex.
struct LocalBook {
    std::vector<int> sizes, verts;
    int numVertices;
    explicit LocalBook(int pages) : sizes(size_t(pages), 3), numVertices(pages + 2) {
        for (int i = 0; i < pages; ++i) verts.insert(verts.end(), {0, 1, i + 2});
    }
    TopologyDescriptor descriptor() const { return test::descriptorOf(numVertices, sizes, verts); }
};

// Nor may it overshoot by far, or it refuses what fits: catmark-butterfly's Zorin masks read
// whole rings only at manifold, triangle-only ends, so a book of 2000 triangles on one edge (its
// spine ends have valence 2001 but are non-manifold) must not be charged K² entries.
TEST(StencilTableGuard, EstimateStaysNearTheLevel) {
    LocalBook book(2000);
    for (Scheme scheme : {Scheme::StamLoop, Scheme::SchaeferWarren, Scheme::CatmarkButterfly}) {
        Options options;
        options.scheme = scheme;
        Refiner refiner(book.descriptor(), options);
        const std::size_t estimate = refiner.estimateLevelBytes(1);
        refiner.refineUniform(1, TopologyDetail::Full);
        const std::size_t real = refiner.bytes() - bytesOf(refiner.level(0));
        EXPECT_GE(estimate, real) << toString(scheme);
        EXPECT_LE(estimate, 8 * real) << toString(scheme);
    }
}

// The descriptor's counts are checked against the budget before level 0 is allocated: a count
// of 2^31 - 1 vertices would be tens of GB of incidence arrays.
TEST(StencilTableGuard, BaseLevelIsBudgeted) {
    const bench::ControlMesh sphere = bench::makeUvSphere(8, 3, bench::SpherePoles::TriangleFans);
    TopologyDescriptor d = descriptorOf(sphere);
    d.numVertices = 2147483647;
    try {
        Refiner refiner(d, Options());
        FAIL() << "2^31 - 1 vertices fit the default budget?";
    } catch (const TopologyError& e) {
        EXPECT_NE(std::string(e.what()).find("level 0"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("budget"), std::string::npos) << e.what();
    }
}

TEST(StencilTableGuard, EstimateBoundsTheLevel) {
    // The estimate must not undershoot what a level really holds.
    const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 3);
    for (int L = 1; L <= 3; ++L) {
        const Topology& t = r.refiner->level(L);
        const size_t real = r.refiner->levelStencils(L).bytes() + t.faceVerts.size() * 8 + t.edgeVerts.size() * 8 +
                            size_t(t.numVertices) * 12;
        EXPECT_GE(r.refiner->estimateLevelBytes(L), real) << "level " << L;
    }
}

// ---------------------------------------------------------------------------------------------
// The weight pool.

// The bench's closed n x n tori (bench/meshes/torus.h): quads, or every quad split along the same
// diagonal, so that every vertex is regular (valence 4 or 6) and every level has one mask per
// kind of point.
TEST(WeightSharing, RegularTorusPoolsOneSequencePerMask) {
    struct Case {
        bool triangles;
        int masks;
        const char* what;
    };
    for (const Case& c : {Case{false, 3, "quads: face, edge and vertex points"},
                          Case{true, 2, "triangles: edge and vertex points"}}) {
        // Level 3 has 65536 children, enough for the analyzer to build it in parts when it has
        // two threads: the parts' pools must merge without a duplicate.
        const bench::ControlMesh torus =
            bench::makeTorus(32, c.triangles ? bench::TorusFaces::Triangles : bench::TorusFaces::Quads);
        Refiner refiner(descriptorOf(torus), Options());
        refiner.refineUniform(3);
        for (int L = 1; L <= 3; ++L) {
            const StencilTable& t = refiner.levelStencils(L);
            std::map<int, int> sequenceSizes;  // pool offset -> length of the sequence there
            for (int i = 0; i < t.numStencils(); ++i) {
                const auto [at, fresh] = sequenceSizes.emplace(t.weightOffsets[i], t.size(i));
                ASSERT_TRUE(fresh || at->second == t.size(i)) << "two lengths at one pool offset";
            }
            EXPECT_EQ(int(sequenceSizes.size()), c.masks) << c.what << ", level " << L;
            std::size_t pooled = 0;
            for (const auto& entry : sequenceSizes) pooled += std::size_t(entry.second);
            EXPECT_EQ(t.weights.size(), pooled) << c.what << ", level " << L << ": the pool holds more than the masks";
            // OpenSubdiv's per-level layout: sizes and offsets per stencil, index and weight per entry.
            const double osdBytes = 8.0 * t.numStencils() + 8.0 * double(t.numEntries());
            EXPECT_LT(double(t.bytes()), 0.7 * osdBytes) << c.what << ", level " << L;
        }
        // And into exactly the table of a build on one thread.
        tbb::task_arena oneThread(1);
        oneThread.execute([&] {
            Refiner serial(descriptorOf(torus), Options());
            serial.refineUniform(3);
            for (int L = 1; L <= 3; ++L) {
                const StencilTable &a = refiner.levelStencils(L), &b = serial.levelStencils(L);
                EXPECT_EQ(a.offsets, b.offsets) << c.what << ", level " << L;
                EXPECT_EQ(a.indices, b.indices) << c.what << ", level " << L;
                EXPECT_EQ(a.weightOffsets, b.weightOffsets) << c.what << ", level " << L;
                EXPECT_EQ(a.weights, b.weights) << c.what << ", level " << L;
            }
        });
    }
}

// Level L of a refined mesh built as a double table by the analyzer's own builder.
StencilTableD doubleLevelTable(const Refiner& refiner, int L) {
    const Topology& parent = refiner.level(L - 1);
    const ChildNumbering numbering = numberChildren(parent, rulesOf(refiner.options().scheme).triangleSplit());
    return buildLevelStencils<StencilTableD>(parent, numbering, refiner.options());
}

TEST(WeightSharing, FloatTableRoundTripsThroughDouble) {
    for (const char* name : {"mixed/mixed_torus.obj", "mixed/cylinder_capped_creased.obj", "osd/catmark_pole8.obj",
                             "osd/loop_xord_interior.obj"}) {
        const RefinedMesh r = refineMesh(name, 2);
        for (int L = 1; L <= 2; ++L) {
            const std::string where = std::string(name) + " level " + std::to_string(L);
            const StencilTableD d = doubleLevelTable(*r.refiner, L);
            const StencilTable f = toFloatTable(d);
            const StencilTableD back = toDoubleTable(f);
            ASSERT_EQ(back.numSourceVertices, d.numSourceVertices) << where;
            ASSERT_EQ(back.sizes, d.sizes) << where;
            for (std::size_t i = 0; i < d.sizes.size(); ++i)
                for (int k = 0; k < d.sizes[i]; ++k) {
                    const auto from = std::size_t(d.offsets[i] + k), to = std::size_t(back.offsets[i] + k);
                    ASSERT_EQ(back.indices[to], d.indices[from]) << where << ", stencil " << i;
                    ASSERT_EQ(back.weights[to], double(float(d.weights[from]))) << where << ", stencil " << i;
                }
            // The analyzer interns while it builds; that must give exactly the converted table.
            const StencilTable& built = r.refiner->levelStencils(L);
            EXPECT_EQ(built.offsets, f.offsets) << where;
            EXPECT_EQ(built.indices, f.indices) << where;
            EXPECT_EQ(built.weightOffsets, f.weightOffsets) << where;
            EXPECT_EQ(built.weights, f.weights) << where;
            // And the way back and forth again changes nothing.
            const StencilTable again = toFloatTable(toDoubleTable(built));
            EXPECT_EQ(again.weightOffsets, built.weightOffsets) << where;
            EXPECT_EQ(again.weights, built.weights) << where;
        }
    }
}

TEST(WeightSharing, OnlyBitwiseEqualWeightsShare) {
    const float mask[] = {0.375f, 0.375f, 0.125f, 0.125f};
    float oneUlp[4], copy[4];
    std::memcpy(oneUlp, mask, sizeof mask);
    std::memcpy(copy, mask, sizeof mask);
    oneUlp[2] = std::nextafter(oneUlp[2], 1.0f);
    const float zero[] = {0.0f}, negativeZero[] = {-0.0f};

    WeightPool pool;
    const int first = pool.intern(mask, 4);
    EXPECT_EQ(pool.intern(copy, 4), first) << "an equal sequence elsewhere in memory";
    const int apart = pool.intern(oneUlp, 4);
    EXPECT_NE(apart, first) << "one ulp apart";
    EXPECT_EQ(pool.values()[std::size_t(apart) + 2], oneUlp[2]);
    EXPECT_NE(pool.intern(negativeZero, 1), pool.intern(zero, 1)) << "-0.0 == 0.0, but not bitwise";
    EXPECT_EQ(pool.values().size(), 4u + 4u + 1u + 1u);

    // In a table: weights rounded to float first, so doubles that round alike do share.
    StencilTableD d;
    d.numSourceVertices = 3;
    d.sizes = {2, 2, 2, 2};
    d.offsets = {0, 2, 4, 6};
    d.indices = {0, 1, 1, 2, 2, 0, 0, 2};
    const double up = double(std::nextafter(0.75f, 1.0f));
    d.weights = {0.25, 0.75, 0.25, up, 0.25, 0.75 + 1e-12, 0.25, 0.75};
    const StencilTable t = toFloatTable(d);
    EXPECT_NE(t.weightOffsets[1], t.weightOffsets[0]);
    EXPECT_EQ(t.weightOffsets[2], t.weightOffsets[0]);
    EXPECT_EQ(t.weightOffsets[3], t.weightOffsets[0]);
    EXPECT_EQ(t.weights.size(), 4u);
    EXPECT_EQ(t.weightsOf(1)[1], float(up));
}

TEST(WeightPool, GrowingKeepsEveryOffset) {
    WeightPool pool;
    std::vector<std::vector<float>> sequences;
    std::vector<int> offsets;
    // Far more sequences than the initial slots, of lengths 1..9: the table grows many times.
    for (int s = 0; s < 5000; ++s) {
        std::vector<float> w(std::size_t(1 + s % 9));
        for (std::size_t k = 0; k < w.size(); ++k) w[k] = float(s) + 0.125f * float(k);
        offsets.push_back(pool.intern(w.data(), int(w.size())));
        sequences.push_back(std::move(w));
    }
    std::size_t total = 0;
    for (std::size_t s = 0; s < sequences.size(); ++s) {
        const std::vector<float>& w = sequences[s];
        ASSERT_LE(std::size_t(offsets[s]) + w.size(), pool.values().size()) << "sequence " << s;
        ASSERT_TRUE(std::equal(w.begin(), w.end(), pool.values().begin() + offsets[s])) << "sequence " << s;
        ASSERT_EQ(pool.intern(w.data(), int(w.size())), offsets[s]) << "sequence " << s;
        total += w.size();
    }
    EXPECT_EQ(pool.values().size(), total) << "a sequence was stored twice";

    const std::vector<float> taken = pool.take();
    EXPECT_EQ(taken.size(), total);
    EXPECT_TRUE(pool.values().empty());
    EXPECT_EQ(pool.intern(sequences[7].data(), int(sequences[7].size())), 0) << "the emptied pool starts afresh";
}

// The plain CSR loop that the pooled layout replaces, in float with the kernel's order of
// operations, written out here from what kernels/stencil_kernel.h documents: one running sum per
// component with entries in order (the portable loops), or, where evalStencils takes the AVX2 +
// FMA loop (widths 3 and 4), a fused multiply-add per entry into two partial sums, the even and
// the odd entries, added at the end. Evaluators must match it bit for bit.
std::vector<float> evaluatePlain(const StencilTableD& plain, const std::vector<float>& src, int width) {
    const bool fused = (width == 3 || width == 4) && kernels::stencilKernelUsesAvx2();
    std::vector<float> out(plain.sizes.size() * std::size_t(width));
    for (std::size_t i = 0; i < plain.sizes.size(); ++i)
        for (int c = 0; c < width; ++c) {
            float sum = 0.0f, even = 0.0f, odd = 0.0f;
            for (int k = 0; k < plain.sizes[i]; ++k) {
                const std::size_t at = std::size_t(plain.offsets[i] + k);
                const float w = float(plain.weights[at]), s = src[std::size_t(plain.indices[at]) * width + c];
                if (!fused)
                    sum += w * s;
                else if (k % 2 == 0)
                    even = std::fma(w, s, even);
                else
                    odd = std::fma(w, s, odd);
            }
            out[i * std::size_t(width) + std::size_t(c)] = fused ? even + odd : sum;
        }
    return out;
}

TEST(WeightSharing, EvaluatorsMatchThePlainLayout) {
    const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 3);
    for (int L = 1; L <= 3; ++L) {
        for (bool factorized : {false, true}) {
            const StencilTable table = factorized ? r.refiner->factorizedStencils(L) : r.refiner->levelStencils(L);
            const StencilTableD plain = toDoubleTable(table);
            for (int width : {1, 3, 4, 7}) {
                std::vector<float> src(std::size_t(table.numSourceVertices) * width);
                for (std::size_t k = 0; k < src.size(); ++k)
                    src[k] = std::sin(0.37f * float(k)) + 0.001f * float(k % 97);
                const std::vector<float> expected = evaluatePlain(plain, src, width);
                const BufferDescriptor desc(0, width, width);
                std::vector<float> cpu(expected.size(), -1.0f), tbb(expected.size(), -1.0f);
                CpuEvaluator::EvalStencils(src.data(), desc, cpu.data(), desc, table);
                TbbEvaluator::EvalStencils(src.data(), desc, tbb.data(), desc, table);
                const std::string where = "level " + std::to_string(L) + (factorized ? " factorized" : " per level") +
                                          ", width " + std::to_string(width);
                const std::size_t bytes = expected.size() * sizeof(float);
                EXPECT_EQ(std::memcmp(cpu.data(), expected.data(), bytes), 0) << "CpuEvaluator, " << where;
                EXPECT_EQ(std::memcmp(tbb.data(), expected.data(), bytes), 0) << "TbbEvaluator, " << where;
            }
        }
    }
}

}  // namespace
}  // namespace quadtri::test
