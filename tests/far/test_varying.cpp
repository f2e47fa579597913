// Varying stencils (Refiner::varyingStencils, factorizedVaryingStencils; docs/varying.md): equal to
// OpenSubdiv's PrimvarRefiner::InterpolateVarying on its shapes (catmark_* under catmull-clark,
// loop_* under loop, levels 1-3, vertices matched by their refined positions); under the
// bilinear scheme, the same tables as its vertex stencils (built by the scheme's masks, an
// independent path); on every mesh and scheme: one stencil per child in the vertex tables'
// order, weights summing to 1, vertex points that keep their vertex, sharpness ignored, a
// factorized table equal to the per-level ones composed, and level errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <quadtri/far/refiner.h>
#include <quadtri/osd/cpu_evaluator.h>
#include "tests/osd_reference.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

constexpr int kMaxLevel = 3;

std::vector<float> evaluated(const StencilTable& table, const std::vector<float>& src) {
    std::vector<float> out(3 * std::size_t(table.numStencils()));
    const BufferDescriptor xyz(0, 3, 3);
    CpuEvaluator::EvalStencils(src.data(), xyz, out.data(), xyz, table);
    return out;
}

// The control positions carried to level L through the per-level varying tables.
std::vector<std::vector<float>> varyingLevels(const Refiner& refiner, const std::vector<float>& control, int maxLevel) {
    std::vector<std::vector<float>> levels{control};
    for (int L = 1; L <= maxLevel; ++L) levels.push_back(evaluated(refiner.varyingStencils(L), levels.back()));
    return levels;
}

std::string nameOf(const std::string& mesh) { return mesh.substr(mesh.find('/') + 1); }
bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

TEST(VaryingStencils, EqualOpenSubdivsInterpolateVarying) {
    int cases = 0;
    for (const std::string& mesh : allMeshes()) {
        const std::string name = nameOf(mesh);
        Options options;
        OsdScheme reference;
        if (startsWith(name, "catmark_")) {
            options.scheme = Scheme::CatmullClark, reference = OsdScheme::Catmark;
        } else if (startsWith(name, "loop_")) {
            options.scheme = Scheme::Loop, reference = OsdScheme::Loop;
        } else {
            continue;
        }
        const RefinedMesh r = refineMesh(mesh, kMaxLevel, options);
        const double diagonal = boundingBoxDiagonal(r.mesh.positions);
        const std::vector<std::vector<float>> ours = varyingLevels(*r.refiner, r.mesh.positions, kMaxLevel);
        for (int L = 1; L <= kMaxLevel; ++L) {
            const OsdVarying osd = osdVarying(r.mesh, reference, r.options.boundary, r.options.creaseMethod, L,
                                              r.options.smoothTriangles);
            const PositionMatch match = matchPositions(r.positions[L], osd.refined, diagonal, 1e-5);
            ASSERT_TRUE(match.countsEqual) << mesh << " level " << L;
            ASSERT_LE(match.maxRelative(), 1e-5) << mesh << " level " << L << ": refined vertices do not match";
            double worst = 0;
            for (int v = 0; v < match.numOurs; ++v)
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::fabs(ours[L][3 * v + c] - osd.varying[3 * match.ourToReference[v] + c]));
            EXPECT_LE(worst / diagonal, 1e-6) << mesh << " level " << L;
            ++cases;
        }
    }
    EXPECT_GE(cases, 3 * 40);  // every catmark_* and loop_* shape at three levels
}

// Bilinear's vertex stencils are built by its SchemeMasks with the shared crease code; the varying
// table by far/tables/varying_table.cpp: the same linear rules, so the same tables.
TEST(VaryingStencils, EqualTheBilinearSchemesVertexStencils) {
    for (const std::string& mesh : allMeshes()) {
        Options options;
        options.scheme = Scheme::Bilinear;
        const RefinedMesh r = refineMesh(mesh, 2, options);
        for (int L = 1; L <= 2; ++L) {
            const StencilTable varying = r.refiner->varyingStencils(L), vertex = r.refiner->levelStencils(L);
            ASSERT_EQ(varying.numStencils(), vertex.numStencils()) << mesh << " level " << L;
            const std::vector<float> a = evaluated(varying, r.positions[L - 1]), b = evaluated(vertex, r.positions[L - 1]);
            for (std::size_t f = 0; f < a.size(); ++f) ASSERT_NEAR(a[f], b[f], 1e-6) << mesh << " level " << L;
        }
    }
}

TEST(VaryingStencils, InvariantsOnEveryMeshAndScheme) {
    int checked = 0;
    for (const std::string& mesh : allMeshes()) {
        for (Scheme scheme : allSchemes()) {
            Options options;
            options.scheme = scheme;
            RefinedMesh r;
            try {
                r = refineMesh(mesh, 2, options);
            } catch (const TopologyError&) {
                continue;  // a scheme that refuses the mesh (loop on quads, ...)
            }
            const std::vector<std::vector<float>> levels = varyingLevels(*r.refiner, r.mesh.positions, 2);
            for (int L = 1; L <= 2; ++L) {
                const StencilTable table = r.refiner->varyingStencils(L);
                ASSERT_EQ(table.numStencils(), r.refiner->levelStencils(L).numStencils()) << mesh;
                ASSERT_EQ(table.numSourceVertices, r.refiner->levelStencils(L).numSourceVertices) << mesh;
                for (int i = 0; i < table.numStencils(); ++i) ASSERT_NEAR(stencilWeightSum(table, i), 1.0, 1e-6) << mesh;
                // Vertex points come last, one per parent vertex, in its order: they keep it.
                const int parents = table.numSourceVertices, first = table.numStencils() - parents;
                for (int v = 0; v < parents; ++v) {
                    ASSERT_EQ(table.size(first + v), 1) << mesh;
                    ASSERT_EQ(table.indices[table.offsets[first + v]], v) << mesh;
                }
                // Composed over the control vertices, the same values.
                const std::vector<float> direct = evaluated(r.refiner->factorizedVaryingStencils(L), r.mesh.positions);
                for (std::size_t f = 0; f < direct.size(); ++f) ASSERT_NEAR(direct[f], levels[L][f], 1e-5) << mesh;
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 100);
}

TEST(VaryingStencils, IgnoreSharpness) {
    // The same cube with and without creases and a corner: varying data is never sharpened.
    const std::vector<int> sizes(6, 4);
    const std::vector<int> verts = {0, 1, 3, 2, 2, 3, 5, 4, 4, 5, 7, 6, 6, 7, 1, 0, 1, 7, 5, 3, 6, 0, 2, 4};
    TopologyDescriptor plain = descriptorOf(8, sizes, verts), sharp = plain;
    const std::vector<int> pairs = {0, 1, 1, 3};
    const std::vector<float> weights = {2.5f, kInfiniteSharpness};
    const std::vector<int> corner = {5};
    const std::vector<float> cornerWeight = {3.0f};
    sharp.numCreases = 2, sharp.creaseVertexPairs = pairs.data(), sharp.creaseWeights = weights.data();
    sharp.numCorners = 1, sharp.cornerVertexIndices = corner.data(), sharp.cornerWeights = cornerWeight.data();
    for (Scheme scheme : {Scheme::CatmullClark, Scheme::SchaeferWarren, Scheme::StamLoop}) {
        Options options;
        options.scheme = scheme;
        Refiner a(plain, options), b(sharp, options);
        a.refineUniform(3);
        b.refineUniform(3);
        for (int L = 1; L <= 3; ++L) {
            const StencilTable x = a.varyingStencils(L), y = b.varyingStencils(L);
            EXPECT_EQ(x.offsets, y.offsets);
            EXPECT_EQ(x.indices, y.indices);
            EXPECT_EQ(x.weights, y.weights);
        }
        EXPECT_NE(a.levelStencils(2).weights, b.levelStencils(2).weights);  // the creases do act on positions
    }
}

TEST(VaryingStencils, LevelsOutOfRangeAreRefused) {
    const RefinedMesh r = refineMesh("osd/catmark_cube.obj", 2);
    for (int L : {0, -1, 3}) {
        EXPECT_THROW(r.refiner->varyingStencils(L), TopologyError) << L;
        EXPECT_THROW(r.refiner->factorizedVaryingStencils(L), TopologyError) << L;
    }
    try {
        r.refiner->varyingStencils(3);
    } catch (const TopologyError& e) {
        EXPECT_EQ(std::string(e.what()), "varying stencils asked for level 3; refined levels are 1..2");
    }
}

}  // namespace
}  // namespace quadtri::test
