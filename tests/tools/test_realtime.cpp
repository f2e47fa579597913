// The real-time loop (tools/realtime/): the two-bone skin by its invariants, and a frame's
// limit positions and normals against the evaluators' own results, bitwise between CpuEvaluator
// and TbbEvaluator, across the two table routes, and under a rigid motion of the bent cage.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include <quadtri/osd/cpu_evaluator.h>
#include "tests/tools/realtime_support.h"
#include "tools/realtime/deforming_surface.h"
#include "tools/realtime/host_frame_evaluator.h"

namespace quadtri::test {
namespace {

using realtime::DeformingSurface;
using realtime::HostFrameEvaluator;
using realtime::SurfaceTables;
using realtime::TableRoute;
using realtime::TwoBoneSkin;

constexpr float kBend = 1.2f;  // radians, a frame well into the bend

// One level-1 cage shared by the tests: loading and the tables take a while under sanitizers.
const DemoCage& cage() {
    static const DemoCage c = loadDemoCage(1);
    return c;
}

const SurfaceTables& tables(TableRoute route) {
    static const SurfaceTables factorized(*cage().refiner, 1, TableRoute::FactorizedLimit);
    static const SurfaceTables levels(*cage().refiner, 1, TableRoute::LevelsThenLimit);
    static const SurfaceTables patches(*cage().refiner, 1, TableRoute::Patches);
    return route == TableRoute::FactorizedLimit ? factorized : route == TableRoute::LevelsThenLimit ? levels : patches;
}

struct Frame {
    std::vector<float> positions, normals;
};

Frame evaluate(const SurfaceTables& t, const std::vector<float>& cagePositions, bool threaded) {
    HostFrameEvaluator evaluator(t, threaded);
    evaluator.setCage(cagePositions.data());
    realtime::PhaseTimes times;
    evaluator.evaluate(times);
    Frame frame;
    evaluator.readBack(frame.positions, frame.normals);  // level order, whatever the route's
    return frame;
}

std::vector<float> posed(float radians) {
    const TwoBoneSkin skin(cage().mesh.positions);
    std::vector<float> out(skin.rest().size());
    skin.pose(radians, out.data());
    return out;
}

TEST(TwoBoneSkin, RestPoseAtAngleZeroIsTheCageBitwise) {
    const std::vector<float> rest = posed(0.0f);
    ASSERT_EQ(rest.size(), cage().mesh.positions.size());
    EXPECT_EQ(0, std::memcmp(rest.data(), cage().mesh.positions.data(), rest.size() * sizeof(float)));
}

TEST(TwoBoneSkin, BonesAlongTheLongestSideJoinedAtItsMiddle) {
    const TwoBoneSkin skin(cage().mesh.positions);
    EXPECT_EQ(skin.longAxis(), 0);  // the limb runs along x, is wider in y than in z
    EXPECT_EQ(skin.bendAxis(), 1);
    float lo = 1e30f, hi = -1e30f;
    for (std::size_t i = 0; i < skin.rest().size(); i += 3) {
        lo = std::min(lo, skin.rest()[i]);
        hi = std::max(hi, skin.rest()[i]);
    }
    EXPECT_FLOAT_EQ(skin.joint()[0], 0.5f * (lo + hi));
    // The weights: a smoothstep of x over the middle 20 % of the length, computed here in double.
    for (int v = 0; v < skin.numVertices(); ++v) {
        const double s = std::clamp((skin.rest()[3 * v] - (skin.joint()[0] - 0.1 * (hi - lo))) / (0.2 * (hi - lo)), 0.0, 1.0);
        ASSERT_NEAR(skin.weights()[v], s * s * (3 - 2 * s), 1e-5) << "vertex " << v;
    }
}

TEST(TwoBoneSkin, FirstBoneStaysSecondTurnsRigidly) {
    const TwoBoneSkin skin(cage().mesh.positions);
    const std::vector<float> bent = posed(kBend);
    const auto& c = skin.joint();
    const double cs = std::cos(double(kBend)), sn = std::sin(double(kBend));
    int still = 0, turned = 0, blended = 0;
    for (int v = 0; v < skin.numVertices(); ++v) {
        const float* p = &skin.rest()[3 * v];
        const float* q = &bent[3 * v];
        const float w = skin.weights()[v];
        EXPECT_EQ(q[1], p[1]) << "vertex " << v << " moved along the bend axis";
        if (w == 0.0f) {
            ++still;
            ASSERT_TRUE(q[0] == p[0] && q[2] == p[2]) << "vertex " << v << " on the first bone moved";
        } else if (w == 1.0f) {
            ++turned;  // R(p - c) + c, the turn about y taking z to x
            const double dz = p[2] - c[2], dx = p[0] - c[0];
            ASSERT_NEAR(q[2], c[2] + cs * dz - sn * dx, 1e-5) << "vertex " << v;
            ASSERT_NEAR(q[0], c[0] + sn * dz + cs * dx, 1e-5) << "vertex " << v;
        } else {
            ++blended;
        }
    }
    // The blend region is a fifth of the length; the rest splits between the bones.
    EXPECT_GT(still, skin.numVertices() / 4);
    EXPECT_GT(turned, skin.numVertices() / 4);
    EXPECT_GT(blended, skin.numVertices() / 10);
}

TEST(TwoBoneSkin, BendAngleFromRestToTheMaximumAndBack) {
    EXPECT_EQ(realtime::bendAngle(0.0), 0.0f);
    EXPECT_FLOAT_EQ(realtime::bendAngle(1.0, 1.5f, 2.0), 1.5f);
    EXPECT_NEAR(realtime::bendAngle(2.0, 1.5f, 2.0), 0.0f, 1e-6);
    EXPECT_FLOAT_EQ(realtime::bendAngle(0.5, 1.5f, 2.0), 0.75f);
}

TEST(TwoBoneSkin, RefusesCagesWithoutExtent) {
    EXPECT_THROW(TwoBoneSkin(std::vector<float>{}), std::invalid_argument);
    EXPECT_THROW(TwoBoneSkin(std::vector<float>{1, 2}), std::invalid_argument);
    EXPECT_THROW(TwoBoneSkin(std::vector<float>{1, 2, 3, 1, 2, 3}), std::invalid_argument);
    EXPECT_THROW(TwoBoneSkin(std::vector<float>{0, 0, 0, 1, 0, 0}, 0.0f), std::invalid_argument);
}

TEST(RealtimeLoop, FactorizedFrameIsTheEvaluatorsOwnResult) {
    const std::vector<float> bent = posed(kBend);
    const LimitStencilTable limit = cage().refiner->factorizedLimitStencils(1);
    const int n = limit.numStencils();
    std::vector<float> positions(3 * std::size_t(n)), normals(3 * std::size_t(n));
    const BufferDescriptor xyz(0, 3, 3);
    CpuEvaluator::EvalLimitStencils(bent.data(), xyz, positions.data(), xyz, nullptr, xyz, nullptr, xyz,
                                    normals.data(), xyz, limit);

    HostFrameEvaluator evaluator(tables(TableRoute::FactorizedLimit), false);
    DeformingSurface surface{TwoBoneSkin(cage().mesh.positions)};
    const realtime::PhaseTimes times = surface.frame(evaluator, kBend);
    EXPECT_EQ(surface.cage(), bent);
    EXPECT_EQ(evaluator.positions(), positions);
    EXPECT_EQ(evaluator.normals(), normals);
    EXPECT_EQ(times.normalsMs, 0.0);  // one pass: all of it counted as evaluation
    EXPECT_GE(times.evaluateMs, 0.0);
}

TEST(RealtimeLoop, PerLevelFrameIsTheEvaluatorsOwnResult) {
    const std::vector<float> bent = posed(kBend);
    const Refiner& refiner = *cage().refiner;
    const BufferDescriptor xyz(0, 3, 3);
    std::vector<float> level1(3 * std::size_t(refiner.levelStencils(1).numStencils()));
    CpuEvaluator::EvalStencils(bent.data(), xyz, level1.data(), xyz, refiner.levelStencils(1));
    const LimitStencilTable limit = refiner.limitStencils(1);
    const MeshNormalTable fallback = buildMeshNormalTable(refiner.faces(1));
    std::vector<float> positions(level1.size()), normals(level1.size());
    CpuEvaluator::EvalLimitStencils(level1.data(), xyz, positions.data(), xyz, nullptr, xyz, nullptr, xyz,
                                    normals.data(), xyz, limit, &fallback);

    const Frame frame = evaluate(tables(TableRoute::LevelsThenLimit), bent, false);
    EXPECT_EQ(frame.positions, positions);
    EXPECT_EQ(frame.normals, normals);
}

TEST(RealtimeLoop, CpuAndTbbBitwiseEqualOnEveryRoute) {
    const std::vector<float> bent = posed(kBend);
    for (TableRoute route : {TableRoute::FactorizedLimit, TableRoute::LevelsThenLimit, TableRoute::Patches}) {
        const Frame serial = evaluate(tables(route), bent, false);
        const Frame threaded = evaluate(tables(route), bent, true);
        EXPECT_EQ(serial.positions, threaded.positions) << realtime::toString(route);
        EXPECT_EQ(serial.normals, threaded.normals) << realtime::toString(route);
    }
}

// Normals are differences of nearby points normalised: the per-level route rounds each level's
// positions (coordinates up to 6) to float before the limit pass takes differences over edges
// a hundredth of that, so its normals carry 1e-5-scale rounding (measured 2.2e-5 here); 1e-4 is
// still far below any wrong mask's error.
constexpr float kNormalRounding = 1e-4f;

TEST(RealtimeLoop, RoutesAgreeWithinRounding) {
    const std::vector<float> bent = posed(kBend);
    const Frame factorized = evaluate(tables(TableRoute::FactorizedLimit), bent, false);
    const Frame levels = evaluate(tables(TableRoute::LevelsThenLimit), bent, false);
    EXPECT_LT(maxDifference(factorized.positions, levels.positions), 1e-5f);
    EXPECT_LT(maxDifference(factorized.normals, levels.normals), kNormalRounding);
    const Frame patches = evaluate(tables(TableRoute::Patches), bent, false);
    EXPECT_LT(maxDifference(factorized.positions, patches.positions), 1e-5f);
    EXPECT_LT(maxDifference(factorized.normals, patches.normals), kNormalRounding);
}

// A rigid motion x -> Q x + t of the bent cage moves the limit surface the same way and turns its
// normals by Q: the stencils' position weights sum to 1 and their tangent weights to 0.
TEST(RealtimeLoop, RigidMotionOfTheBentCageMovesTheSurfaceRigidly) {
    const std::vector<float> bent = posed(kBend);
    // Q: a turn by 0.7 rad about (1, 2, 3) / |(1, 2, 3)| (Rodrigues' formula), t: a shift.
    const double a[3] = {1 / std::sqrt(14.0), 2 / std::sqrt(14.0), 3 / std::sqrt(14.0)};
    const double c = std::cos(0.7), s = std::sin(0.7);
    double Q[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Q[i][j] = (i == j ? c : 0.0) + (1 - c) * a[i] * a[j];
    Q[0][1] -= s * a[2], Q[0][2] += s * a[1], Q[1][0] += s * a[2], Q[1][2] -= s * a[0], Q[2][0] -= s * a[1],
        Q[2][1] += s * a[0];
    const double t[3] = {0.3, -0.2, 0.5};
    auto move = [&](const std::vector<float>& x, bool shift) {
        std::vector<float> y(x.size());
        for (std::size_t v = 0; v < x.size(); v += 3)
            for (int i = 0; i < 3; ++i)
                y[v + i] = float(Q[i][0] * x[v] + Q[i][1] * x[v + 1] + Q[i][2] * x[v + 2] + (shift ? t[i] : 0.0));
        return y;
    };
    for (TableRoute route : {TableRoute::FactorizedLimit, TableRoute::LevelsThenLimit, TableRoute::Patches}) {
        const Frame frame = evaluate(tables(route), bent, true);
        const Frame moved = evaluate(tables(route), move(bent, true), true);
        EXPECT_LT(maxDifference(moved.positions, move(frame.positions, true)), 1e-5f) << realtime::toString(route);
        EXPECT_LT(maxDifference(moved.normals, move(frame.normals, false)), kNormalRounding) << realtime::toString(route);
    }
}

TEST(RealtimeLoop, FastestTablesAreFactorizedWithinTheBudget) {
    const SurfaceTables fastest = realtime::fastestSurfaceTables(*cage().refiner, 1);
    EXPECT_EQ(fastest.route, TableRoute::FactorizedLimit);
    EXPECT_EQ(fastest.numPoints, cage().refiner->faces(1).numVertices());
    EXPECT_EQ(fastest.numControl, cage().refiner->faces(0).numVertices());
    EXPECT_TRUE(fastest.levels.empty());
}

// Level 0: the cage's own limit surface, the same through both routes (no level table).
TEST(RealtimeLoop, LevelZeroIsTheCagesLimitSurface) {
    const std::vector<float> bent = posed(kBend);
    const LimitStencilTable limit = cage().refiner->limitStencils(0);
    const MeshNormalTable fallback = buildMeshNormalTable(cage().refiner->faces(0));
    const int n = limit.numStencils();
    std::vector<float> positions(3 * std::size_t(n)), normals(3 * std::size_t(n));
    const BufferDescriptor xyz(0, 3, 3);
    CpuEvaluator::EvalLimitStencils(bent.data(), xyz, positions.data(), xyz, nullptr, xyz, nullptr, xyz,
                                    normals.data(), xyz, limit, &fallback);
    for (TableRoute route : {TableRoute::FactorizedLimit, TableRoute::LevelsThenLimit}) {
        const SurfaceTables t(*cage().refiner, 0, route);
        EXPECT_EQ(t.numPoints, t.numControl);
        const Frame frame = evaluate(t, bent, false);
        EXPECT_EQ(frame.positions, positions) << realtime::toString(route);
        EXPECT_LT(maxDifference(frame.normals, normals), 1e-6f) << realtime::toString(route);  // fallback or not
    }
}

TEST(RealtimeLoop, TablesOnlyForRefinedLevels) {
    EXPECT_THROW(SurfaceTables(*cage().refiner, -1, TableRoute::FactorizedLimit), std::invalid_argument);
    EXPECT_THROW(SurfaceTables(*cage().refiner, 2, TableRoute::LevelsThenLimit), std::invalid_argument);
    HostFrameEvaluator evaluator(tables(TableRoute::FactorizedLimit), false);
    realtime::PhaseTimes times;
    EXPECT_THROW(evaluator.evaluate(times), std::logic_error);  // no cage set
}

}  // namespace
}  // namespace quadtri::test
