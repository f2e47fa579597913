// Limit stencils of face-varying channels (docs/face_varying.md, "Limit UVs"): a seamless
// channel's limit is the mesh's (a linear map of the positions gives that map of the limit
// positions and tangents, under every scheme), position weights sum to 1 and tangent weights to 0,
// the factorized tables give what the per-level ones give, bilinear values stay, and the
// refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <quadtri/osd/cpu_evaluator.h>

#include "tests/test_support.h"

namespace quadtri::test {
namespace {

constexpr int kMaxLevel = 3;
constexpr int kSeamLevels = 2;  // every option and scheme on seamed shapes: two levels compose


// One of a limit table's three outputs (0 position, 1 dU, 2 dV) of `width`-float data, in double.
std::vector<double> limitOutput(const LimitStencilTable& table, const std::vector<float>& src, int width, int output) {
    std::vector<double> dst(std::size_t(table.numStencils()) * width, 0.0);
    for (int i = 0; i < table.numStencils(); ++i) {
        const int* sources = table.sourcesOf(i);
        const float* w = table.weightsOf(i);
        for (int k = 0; k < table.size(i); ++k)
            for (int c = 0; c < width; ++c)
                dst[std::size_t(i) * width + c] += double(w[3 * k + output]) * src[std::size_t(sources[k]) * width + c];
    }
    return dst;
}

std::vector<Scheme> schemesFor(const io::ObjMesh& mesh) {
    const bool triangles = std::all_of(mesh.faceSizes.begin(), mesh.faceSizes.end(), [](int n) { return n == 3; });
    std::vector<Scheme> schemes;
    for (Scheme s : allSchemes())
        if (s != Scheme::Loop || triangles) schemes.push_back(s);
    return schemes;
}

// The linear map u = A x + b of test_fvar, applied to a point (withOffset) or a tangent.
void linearMap(const double* x, bool withOffset, double* uv) {
    uv[0] = 0.5 * x[0] - 0.25 * x[1] + 0.125 * x[2] + (withOffset ? 2.0 : 0.0);
    uv[1] = -0.375 * x[0] + 0.75 * x[2] - (withOffset ? 1.0 : 0.0);
}

std::vector<float> linearUVs(const std::vector<float>& xyz) {
    std::vector<float> uv;
    for (std::size_t v = 0; v < xyz.size(); v += 3) {
        const double x[3] = {xyz[v], xyz[v + 1], xyz[v + 2]};
        double u[2];
        linearMap(x, true, u);
        uv.insert(uv.end(), {float(u[0]), float(u[1])});
    }
    return uv;
}

// A channel with one value per vertex has no seam: where every value matches its vertex (every
// option but All on a closed mesh, None anywhere) the value mesh is the mesh, so the limit UVs
// are the linear map of the limit positions and the UV tangents the map of the tangents, corner by
// corner, at every level from 0.
class FVarLimitWithoutSeams : public testing::TestWithParam<std::string> {};

TEST_P(FVarLimitWithoutSeams, LinearMapOfTheLimit) {
    const std::string& name = GetParam();
    const io::ObjMesh mesh = io::readObj(meshPath(name));
    bool closed = true;
    {
        Refiner probe(mesh.descriptor(), mesh.applyTags(Options()));
        for (uint8_t flags : probe.level(0).vertFlags) closed = closed && !(flags & kVertexBoundary);
    }
    const FVarChannel channel{mesh.numVertices(), mesh.faceVerts.data()};
    const std::vector<float> control = linearUVs(mesh.positions);
    double scale = 1;
    for (float x : control) scale = std::max(scale, double(std::fabs(x)));
    for (Scheme scheme : schemesFor(mesh))
        for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
            // On a closed seamless mesh every option but All tags nothing: two of them suffice.
            if (fvar != FVarLinearInterpolation::None && (!closed || fvar != FVarLinearInterpolation::Boundaries)) continue;
            SCOPED_TRACE(name + " " + toString(scheme) + " " + toString(fvar));
            Options options;
            options.scheme = scheme;
            options.fvarLinearInterpolation = fvar;
            options = mesh.applyTags(options);
            TopologyDescriptor desc = mesh.descriptor();
            desc.numFVarChannels = 1;
            desc.fvarChannels = &channel;
            Refiner refiner(desc, options);
            refiner.refineUniform(kMaxLevel);
            const auto positions = evaluateLevels(refiner, mesh.positions, 3);
            const auto uvs = evaluateChannelLevels(refiner, 0, control, 2);
            for (int L = 0; L <= kMaxLevel; ++L) {
                const LimitStencilTable meshLimit = refiner.limitStencils(L);
                const LimitStencilTable uvLimit = refiner.fvarLimitStencils(0, L);
                double worst[3] = {0, 0, 0}, size[3] = {scale, 0, 0};
                for (int output = 0; output < 3; ++output) {
                    const std::vector<double> x = limitOutput(meshLimit, positions[std::size_t(L)], 3, output);
                    const std::vector<double> u = limitOutput(uvLimit, uvs[std::size_t(L)], 2, output);
                    const LevelFaces faces = refiner.faces(L);
                    const IndexSpan values = refiner.fvarValues(0, L);
                    for (int k = 0; k < faces.numCorners(); ++k) {
                        double expected[2];
                        linearMap(&x[3 * std::size_t(faces.vertices()[k])], output == 0, expected);
                        for (int a = 0; a < 2; ++a) {
                            worst[output] = std::max(worst[output], std::fabs(u[2 * std::size_t(values[k]) + a] - expected[a]));
                            size[output] = std::max(size[output], std::fabs(expected[a]));
                        }
                    }
                }
                EXPECT_LE(worst[0], 1e-5 * scale) << "level " << L;
                EXPECT_LE(worst[1], 1e-5 * (size[1] + scale)) << "level " << L;
                EXPECT_LE(worst[2], 1e-5 * (size[2] + scale)) << "level " << L;
            }
        }
}

// Seams everywhere (OpenSubdiv's shapes' own UVs) under every scheme and option: the position
// weights of every stencil sum to 1, the tangent weights to 0, and the factorized table applied to
// the control UVs gives what the per-level table gives applied to the refined ones.
class FVarLimitWithSeams : public testing::TestWithParam<std::string> {};

TEST_P(FVarLimitWithSeams, PartitionOfUnityAndFactorization) {
    const std::string& name = GetParam();
    const io::ObjMesh mesh = io::readObj(meshPath(name));
    ASSERT_TRUE(mesh.hasUVs());
    for (Scheme scheme : schemesFor(mesh))
        for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
            SCOPED_TRACE(name + " " + toString(scheme) + " " + toString(fvar));
            Options options;
            options.scheme = scheme;
            options.fvarLinearInterpolation = fvar;
            FVarChannel channel;
            Refiner refiner(mesh.descriptor(channel), mesh.applyTags(options));
            refiner.refineUniform(kSeamLevels);
            const auto uvs = evaluateChannelLevels(refiner, 0, mesh.uvs, 2);
            for (int L = 0; L <= kSeamLevels; ++L) {
                const LimitStencilTable table = refiner.fvarLimitStencils(0, L);
                const LimitStencilTable factorized = refiner.fvarFactorizedLimitStencils(0, L);
                ASSERT_EQ(table.numStencils(), refiner.numFVarValues(0, L));
                ASSERT_EQ(factorized.numStencils(), table.numStencils());
                EXPECT_EQ(table.numSourceVertices, refiner.numFVarValues(0, L));
                EXPECT_EQ(factorized.numSourceVertices, mesh.numUVs());
                double worstSum[3] = {0, 0, 0};
                for (const LimitStencilTable* t : {&table, &factorized})
                    for (int i = 0; i < t->numStencils(); ++i)
                        for (int output = 0; output < 3; ++output) {
                            double sum = 0, magnitude = 0;
                            for (int k = 0; k < t->size(i); ++k) {
                                sum += t->weightsOf(i)[3 * k + output];
                                magnitude += std::fabs(t->weightsOf(i)[3 * k + output]);
                            }
                            const double expected = output == 0 ? 1.0 : 0.0;
                            worstSum[output] = std::max(worstSum[output], std::fabs(sum - expected) / std::max(1.0, magnitude));
                        }
                EXPECT_LE(worstSum[0], 1e-6) << "level " << L;
                EXPECT_LE(worstSum[1], 1e-6) << "level " << L;
                EXPECT_LE(worstSum[2], 1e-6) << "level " << L;
                double worst = 0;
                for (int output = 0; output < 3; ++output) {
                    const std::vector<double> direct = limitOutput(factorized, mesh.uvs, 2, output);
                    const std::vector<double> perLevel = limitOutput(table, uvs[std::size_t(L)], 2, output);
                    for (std::size_t i = 0; i < direct.size(); ++i)
                        worst = std::max(worst, std::fabs(direct[i] - perLevel[i]) / (1.0 + std::fabs(perLevel[i])));
                }
                EXPECT_LE(worst, 1e-5) << "level " << L;
            }
        }
}

std::string meshName(const testing::TestParamInfo<std::string>& info) { return testNameOf(info.param); }

INSTANTIATE_TEST_SUITE_P(Meshes, FVarLimitWithoutSeams,
                         testing::Values("mixed/mixed_torus.obj", "mixed/checker_cube.obj", "mixed/cylinder_capped.obj",
                                         "osd/loop_icosahedron.obj", "mixed/split_plane.obj", "osd/catmark_tent.obj",
                                         "osd/catmark_nonman_quadpole8.obj"),
                         meshName);
INSTANTIATE_TEST_SUITE_P(Meshes, FVarLimitWithSeams,
                         testing::Values("osd/catmark_fan.obj", "osd/catmark_nonquads.obj", "osd/catmark_cube_creases1.obj",
                                         "osd/loop_cubes_semisharp.obj", "osd/catmark_torus.obj"),
                         meshName);

// Bilinear refinement never moves a value: its limit is every value itself, seams or not.
TEST(FVarLimit, BilinearValuesStay) {
    const io::ObjMesh mesh = io::readObj(meshPath("osd/catmark_fan.obj"));
    for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
        SCOPED_TRACE(toString(fvar));
        Options options;
        options.scheme = Scheme::Bilinear;
        options.fvarLinearInterpolation = fvar;
        FVarChannel channel;
        Refiner refiner(mesh.descriptor(channel), options);
        refiner.refineUniform(2);
        for (int L = 0; L <= 2; ++L) {
            const LimitStencilTable table = refiner.fvarLimitStencils(0, L);
            for (int i = 0; i < table.numStencils(); ++i)
                for (int k = 0; k < table.size(i); ++k)
                    ASSERT_EQ(table.weightsOf(i)[3 * k], table.sourcesOf(i)[k] == i ? 1.0f : 0.0f)
                        << "level " << L << " value " << i;
        }
    }
}

TEST(FVarLimit, RefusesChannelsAndLevelsOutOfRangeAndPastTheBudget) {
    const io::ObjMesh mesh = io::readObj(meshPath("osd/catmark_cube.obj"));
    ASSERT_TRUE(mesh.hasUVs());
    FVarChannel channel;
    Refiner refiner(mesh.descriptor(channel), Options());
    refiner.refineUniform(2);
    EXPECT_NO_THROW(refiner.fvarLimitStencils(0, 2));
    for (int c : {-1, 1}) {
        EXPECT_THROW(refiner.fvarLimitStencils(c, 0), TopologyError);
        EXPECT_THROW(refiner.fvarFactorizedLimitStencils(c, 1), TopologyError);
    }
    for (int L : {-1, 3}) {
        EXPECT_THROW(refiner.fvarLimitStencils(0, L), TopologyError);
        EXPECT_THROW(refiner.fvarFactorizedLimitStencils(0, L), TopologyError);
    }
    try {
        refiner.fvarLimitStencils(0, 3);
    } catch (const TopologyError& e) {
        EXPECT_STREQ(e.what(), "face-varying limit stencils asked for level 3; refined levels are 0..2");
    }

    // The smallest budget level 4 is refined under leaves too little for the channel's factorized
    // limit.
    Options tight;
    std::size_t lo = 0, hi = std::size_t(1) << 26;
    while (hi - lo > 1) {
        tight.memoryBudgetBytes = (lo + hi) / 2;
        try {
            Refiner(mesh.descriptor(channel), tight).refineUniform(4);
            hi = tight.memoryBudgetBytes;
        } catch (const MemoryBudgetError&) {
            lo = tight.memoryBudgetBytes;
        }
    }
    tight.memoryBudgetBytes = hi;
    Refiner small(mesh.descriptor(channel), tight);
    small.refineUniform(4);
    try {
        small.fvarFactorizedLimitStencils(0, 4);
        FAIL() << "the factorized limit stencils of level 4 fit in " << tight.memoryBudgetBytes << " bytes";
    } catch (const MemoryBudgetError& e) {
        EXPECT_EQ(e.subject(), "the factorized limit stencils of face-varying channel 0 at level 4");
        EXPECT_GT(e.needed(), e.budget());
    }
}

}  // namespace
}  // namespace quadtri::test
