// Per-level and factorized tables describe the same refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "tests/test_support.h"

namespace quadtri::test {
namespace {


// Evaluation in double, so that the comparison sees the tables and not float rounding of the data.
std::vector<double> evaluateDouble(const StencilTable& t, const std::vector<double>& src) {
    std::vector<double> out(size_t(t.numStencils()) * 3, 0.0);
    for (int i = 0; i < t.numStencils(); ++i)
        for (int k = t.offsets[i]; k < t.offsets[i] + t.sizes[i]; ++k)
            for (int c = 0; c < 3; ++c) out[3 * i + c] += double(t.weights[k]) * src[3 * size_t(t.indices[k]) + c];
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
        size_t expectedOffset = 0;
        for (int i = 0; i < t.numStencils(); ++i) {
            ASSERT_EQ(size_t(t.offsets[i]), expectedOffset);
            expectedOffset += t.sizes[i];
            for (int k = t.offsets[i]; k < t.offsets[i] + t.sizes[i]; ++k) {
                ASSERT_GE(t.indices[k], 0);
                ASSERT_LT(t.indices[k], t.numSourceVertices);
                ASSERT_TRUE(std::isfinite(t.weights[k]));
            }
            ASSERT_NEAR(stencilWeightSum(t, i), 1.0, 1e-6) << "stencil " << i << " level " << L;
        }
        EXPECT_EQ(expectedOffset, t.numEntries());
        EXPECT_EQ(t.bytes(), (2 * t.sizes.size() + t.indices.size()) * sizeof(int) + t.weights.size() * sizeof(float));
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

}  // namespace
}  // namespace quadtri::test
