// LevelPatchTable (far/level_patch_table.h, Refiner::levelPatches): level L's limit from level K's
// regular patches equals the factorized limit route within float rounding on every scheme, every
// level-L vertex is one point of the table, the serial and threaded evaluators agree bit for bit,
// the portable loops (CPUs without SSE2) and the baseline build's agree with them, and the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include <quadtri/far/level_patch_table.h>
#define QUADTRI_PORTABLE_PATCH_LOOPS  // the loops CPUs without SSE2 run, checked here too
#include "kernels/patch_kernel_loops.h"
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#include "tests/limit/limit_support.h"
#include "tests/sanitized.h"
#include "tests/test_support.h"

namespace quadtri::test {

// tests/surface/baseline_patch_loops.cpp
void baselinePatchLoop(const float* src, const kernels::LevelPatchArrays& a, float* position, float* normal,
                       int numPatches);

namespace {

struct Case {
    std::string mesh;
    Scheme scheme;
    int level, patchLevel;
};

std::vector<Case> cases() {
    std::vector<Case> out;
    const std::vector<std::pair<std::string, std::vector<Scheme>>> meshes = {
        {"mixed/mixed_torus.obj",
         {Scheme::SchaeferWarren, Scheme::StamLoop, Scheme::CatmarkButterfly, Scheme::CatmullClark, Scheme::Bilinear}},
        {"mixed/cylinder_capped_creased.obj", {Scheme::SchaeferWarren, Scheme::CatmullClark}},
        {"mixed/split_plane.obj", {Scheme::SchaeferWarren, Scheme::StamLoop}},
        {"mixed/book_nonmanifold.obj", {Scheme::SchaeferWarren}},
        {"osd/catmark_torus.obj", {Scheme::CatmullClark}},
        {"osd/catmark_hole_test1.obj", {Scheme::CatmullClark}},
        {"osd/catmark_nonquads.obj", {Scheme::CatmullClark, Scheme::SchaeferWarren}},
        {"osd/loop_cube.obj", {Scheme::Loop}},
        {"osd/loop_xord_interior.obj", {Scheme::Loop}},
    };
    for (const auto& [mesh, schemes] : meshes)
        for (Scheme scheme : schemes)
            for (const auto& [L, K] : {std::pair{2, 0}, std::pair{2, 1}, std::pair{3, 1}}) out.push_back({mesh, scheme, L, K});
    return out;
}

class LevelPatches : public testing::TestWithParam<Case> {};

TEST_P(LevelPatches, EqualTheFactorizedLimitAndWriteEveryVertexOnce) {
    const Case& c = GetParam();
    Options options;
    options.scheme = c.scheme;
    const RefinedMesh r = refineMesh(c.mesh, c.level, options);
    const LevelPatchTable table = r.refiner->levelPatches(c.level, c.patchLevel);
    const int n = r.refiner->faces(c.level).numVertices();
    ASSERT_EQ(table.numPoints, n);
    ASSERT_EQ(table.numSourceVertices, r.refiner->faces(c.patchLevel).numVertices());

    std::vector<int> writes(std::size_t(n), 0);
    for (int k = 0; k < n; ++k) ++writes[std::size_t(table.vertexOf(k))];
    EXPECT_TRUE(std::all_of(writes.begin(), writes.end(), [](int w) { return w == 1; }));
    const std::vector<int> pointOf = table.pointOfVertex();
    for (int v = 0; v < n; v += 7) EXPECT_EQ(table.vertexOf(pointOf[std::size_t(v)]), v);

    const BufferDescriptor xyz(0, 3, 3);
    std::vector<float> position(3 * std::size_t(n)), normal(3 * std::size_t(n));
    CpuEvaluator::EvalLevelPatches(r.positions[std::size_t(c.patchLevel)].data(), xyz, position.data(), xyz,
                                   normal.data(), xyz, table);
    std::vector<float> wantPosition(3 * std::size_t(n)), wantNormal(3 * std::size_t(n));
    CpuEvaluator::EvalLimitStencils(r.positions[0].data(), xyz, wantPosition.data(), xyz, nullptr, {}, nullptr, {},
                                    wantNormal.data(), xyz, r.refiner->factorizedLimitStencils(c.level));
    const double diagonal = boundingBoxDiagonal(r.positions[0]);
    double worstPosition = 0, worstNormal = 0;
    for (int k = 0; k < n; ++k) {
        const std::size_t v = std::size_t(table.vertexOf(k));
        worstPosition = std::max(worstPosition, distance(vec3(&position[3 * std::size_t(k)]), vec3(&wantPosition[3 * v])) /
                                                    diagonal);
        const Vec3 a = vec3(&normal[3 * std::size_t(k)]), b = vec3(&wantNormal[3 * v]);
        if (norm(b) > 0.5 && norm(a) > 0.5) worstNormal = std::max(worstNormal, angleBetween(a, b));
    }
    std::printf("%s %s level %d from %d: %d of %d points from %d patches, position %.3g, normal %.3g rad\n",
                c.mesh.c_str(), toString(c.scheme), c.level, c.patchLevel, table.numPatchOutputs(), n,
                table.numPatches(), worstPosition, worstNormal);
    EXPECT_LT(worstPosition, 1e-6);
    EXPECT_LT(worstNormal, 1e-4);

    // The portable loops (what a CPU without SSE2 runs) on the same patches.
    const kernels::LevelPatchArrays arrays{table.rate(),
                                           reinterpret_cast<const std::uint8_t*>(table.patchBasis.data()),
                                           table.pointOffsets.data(),
                                           table.patchPoints.data(),
                                           table.outputOffsets.data(),
                                           table.outputCells.data(),
                                           table.curveWeights.data(),
                                           table.boxSplineWeights.data(),
                                           table.lineWidth(),
                                           table.curveWeightLines.data(),
                                           table.boxSplineWeightLines.data()};
    // And the baseline build's loops, which a CPU with AVX2 does not run.
    for (bool portable : {true, false}) {
        SCOPED_TRACE(portable ? "portable loops" : "baseline loops");
        std::vector<float> otherPosition(position.size()), otherNormal(normal.size());
        const float* source = r.positions[std::size_t(c.patchLevel)].data();
        if (portable)
            kernels::levelPatchLoop(source, 3, arrays, otherPosition.data(), 3, otherNormal.data(), 3, 0,
                                    table.numPatches());
        else
            baselinePatchLoop(source, arrays, otherPosition.data(), otherNormal.data(), table.numPatches());
        float worstOther = 0, worstOtherNormal = 0;
        for (std::size_t k = 0; k < 3 * std::size_t(table.numPatchOutputs()); ++k) {
            worstOther = std::max(worstOther, std::fabs(otherPosition[k] - position[k]));
            worstOtherNormal = std::max(worstOtherNormal, std::fabs(otherNormal[k] - normal[k]));
        }
        EXPECT_LT(worstOther, 1e-6 * diagonal);
        EXPECT_LT(worstOtherNormal, 1e-5f);
    }

    std::vector<float> tbbPosition(position.size()), tbbNormal(normal.size());
    TbbEvaluator::EvalLevelPatches(r.positions[std::size_t(c.patchLevel)].data(), xyz, tbbPosition.data(), xyz,
                                   tbbNormal.data(), xyz, table);
    EXPECT_EQ(tbbPosition, position);
    EXPECT_EQ(tbbNormal, normal);
}

INSTANTIATE_TEST_SUITE_P(Meshes, LevelPatches, testing::ValuesIn(cases()), [](const auto& info) {
    const Case& c = info.param;
    return testNameOf(c.mesh + "_" + toString(c.scheme) + "_" + std::to_string(c.level) + "_from_" +
                      std::to_string(c.patchLevel));
});

// A closed regular quad mesh is all patches from level 0; a regular triangle mesh all box splines.
TEST(LevelPatches, AreAllPatchesOnRegularMeshes) {
    Options options;
    options.scheme = Scheme::CatmullClark;
    const RefinedMesh torus = refineMesh("osd/catmark_torus.obj", 2, options);
    const LevelPatchTable quads = torus.refiner->levelPatches(2, 1);
    EXPECT_EQ(quads.stencils.numStencils(), 0);
    EXPECT_EQ(quads.numPatches(), torus.refiner->faces(1).numFaces());
    for (LevelPatchTable::Basis b : quads.patchBasis) EXPECT_EQ(b, LevelPatchTable::Basis::BSpline);
}

// The host loops write a row of a patch 8 cells at a time: at rates past 8 (rows of several
// chunks), into interleaved outputs (each item's 4-float store must not reach the next), and with
// a patch's outputs in an order whose rows are not runs of grid lines (taken one at a time), each
// point is the one the plain layout gives, bit for bit.
TEST(LevelPatches, HostLoopsTakeAnyRateOutputLayoutAndOrder) {
    for (const auto& [mesh, scheme, L] : {std::tuple{"osd/catmark_torus.obj", Scheme::CatmullClark, 4},
                                          std::tuple{"mixed/mixed_torus.obj", Scheme::SchaeferWarren, 4}}) {
        SCOPED_TRACE(mesh);
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineMesh(mesh, L, options);
        const LevelPatchTable table = r.refiner->levelPatches(L, 0);
        ASSERT_EQ(table.rate(), 16);
        const std::size_t n = std::size_t(table.numPoints);
        const BufferDescriptor xyz(0, 3, 3);
        std::vector<float> position(3 * n), normal(3 * n);
        CpuEvaluator::EvalLevelPatches(r.positions[0].data(), xyz, position.data(), xyz, normal.data(), xyz, table);

        std::vector<float> interleaved(6 * n + 1, -7.0f);
        CpuEvaluator::EvalLevelPatches(r.positions[0].data(), xyz, interleaved.data(), BufferDescriptor(0, 3, 6),
                                       interleaved.data(), BufferDescriptor(3, 3, 6), table);
        for (std::size_t k = 0; k < n; ++k)
            for (std::size_t c = 0; c < 3; ++c) {
                ASSERT_EQ(interleaved[6 * k + c], position[3 * k + c]) << "point " << k;
                ASSERT_EQ(interleaved[6 * k + 3 + c], normal[3 * k + c]) << "point " << k;
            }
        EXPECT_EQ(interleaved.back(), -7.0f);

        // Patch 0's first two outputs swapped: its first row is no run of grid lines now.
        LevelPatchTable shuffled = table;
        const int first = shuffled.outputOffsets[0], other = first + 1;
        ASSERT_EQ(shuffled.outputCells[std::size_t(first)] >> 8, shuffled.outputCells[std::size_t(other)] >> 8);
        std::swap(shuffled.outputCells[std::size_t(first)], shuffled.outputCells[std::size_t(other)]);
        std::swap(shuffled.outputVertices[std::size_t(first)], shuffled.outputVertices[std::size_t(other)]);
        std::vector<float> p2(3 * n), n2(3 * n);
        CpuEvaluator::EvalLevelPatches(r.positions[0].data(), xyz, p2.data(), xyz, n2.data(), xyz, shuffled);
        const std::vector<int> before = table.pointOfVertex(), after = shuffled.pointOfVertex();
        for (std::size_t v = 0; v < n; ++v)
            for (std::size_t c = 0; c < 3; ++c) {
                ASSERT_EQ(p2[3 * std::size_t(after[v]) + c], position[3 * std::size_t(before[v]) + c]) << "vertex " << v;
                ASSERT_EQ(n2[3 * std::size_t(after[v]) + c], normal[3 * std::size_t(before[v]) + c]) << "vertex " << v;
            }
    }
}

TEST(LevelPatches, RefusesLevelsOutOfRangeAndLevelsWithoutTables) {
    const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 2);
    EXPECT_THROW(r.refiner->levelPatches(2, 2), TopologyError);
    EXPECT_THROW(r.refiner->levelPatches(3, 1), TopologyError);
    EXPECT_THROW(r.refiner->levelPatches(2, -1), TopologyError);
    const io::ObjMesh mesh = io::readObj(meshPath("mixed/mixed_torus.obj"));
    Refiner bare(mesh.descriptor(), Options());
    bare.refineUniform(2, TopologyDetail::FacesOnly, LevelTables::None);
    try {
        bare.levelPatches(2, 0);
        FAIL() << "levels without tables accepted";
    } catch (const TopologyError& e) {
        EXPECT_NE(std::string(e.what()).find("has no per-level table"), std::string::npos) << e.what();
    }
    const LevelPatchTable table = r.refiner->levelPatches(2, 0);
    std::vector<float> out(3 * std::size_t(table.numPoints));
    const BufferDescriptor xyz(0, 3, 3), xy(0, 2, 3);
    EXPECT_THROW(CpuEvaluator::EvalLevelPatches(r.positions[0].data(), xy, out.data(), xyz, nullptr, {}, table),
                 std::invalid_argument);
    EXPECT_THROW(CpuEvaluator::EvalLevelPatches(r.positions[0].data(), xyz, nullptr, {}, nullptr, {}, table),
                 std::invalid_argument);
}

}  // namespace
}  // namespace quadtri::test
