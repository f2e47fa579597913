// FaceSurface (far/limit_surface.h): a face's tree grown by many points in any order gives each
// point exactly the stencil LimitSurface gives it alone, for every mesh and scheme (and again when
// the factory meets the face a second time); evaluate
// applies it; face-varying surfaces the same; and the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <quadtri/far/limit_surface.h>
#include "far/surface/patch_points.h"
#include "tests/sanitized.h"
#include "tests/surface/surface_support.h"
#include "tests/test_support.h"

namespace quadtri::test {

// baseline_patch_points.cpp
void baselinePatchPoints(bool boxSpline, const int* sources, const float* control, int stride,
                         const internal::PatchPoints& points);

namespace {

// Points of face f: random ones, its corners and points on its edges (where the tree goes
// deepest next to a boundary, a crease or the seam), in a shuffled order.
std::vector<std::pair<double, double>> pointsOf(const FaceParameterization& p, std::mt19937& random) {
    std::vector<std::pair<double, double>> points;
    for (int k = 0; k < 3 * p.faceSize; ++k) points.push_back(randomPointOf(p, k, random));
    for (int i = 0; i < p.faceSize; ++i) {
        double u, v;
        p.cornerCoord(i, u, v);
        points.emplace_back(u, v);
        for (double t : {0.25, 0.6}) {
            p.edgeCoord(i, t, u, v);
            points.emplace_back(u, v);
        }
    }
    std::shuffle(points.begin(), points.end(), random);
    return points;
}

bool sameStencil(const LimitPointStencil& a, const LimitPointStencil& b) {
    return a.indices == b.indices && a.position == b.position && a.du == b.du && a.dv == b.dv;
}

// The mesh's level 0 under `scheme` into r, or why the scheme refuses the mesh (loop on quads).
std::string refineUnder(const std::string& mesh, Scheme scheme, RefinedMesh& r) {
    Options options;
    options.scheme = scheme;
    try {
        r = refineMesh(mesh, 0, options);
    } catch (const TopologyError& e) {
        return e.what();
    }
    return {};
}

class FaceSurfaceAgreement : public testing::TestWithParam<std::tuple<std::string, Scheme>> {};

TEST_P(FaceSurfaceAgreement, GivesEachPointTheStencilItHasAlone) {
    const auto& [mesh, scheme] = GetParam();
    RefinedMesh r;
    if (const std::string refused = refineUnder(mesh, scheme, r); !refused.empty()) GTEST_SKIP() << refused;
    const LimitSurface surface(*r.refiner);
    const std::vector<float>& control = r.positions[0];
    std::mt19937 random(7);
    const int step = std::max(1, surface.numFaces() / (kSanitized ? 4 : 24));
    int points = 0;
    FaceSurfaceFactory factory(surface);
    struct Checked {
        int face;
        double u, v;
        LimitPointStencil stencil;
    };
    std::vector<Checked> checked;
    for (int f = 0; f < surface.numFaces(); f += step) {
        if (surface.isHole(f)) continue;
        FaceSurface face = factory.faceSurface(f);
        ASSERT_EQ(face.face(), f);
        LimitPointStencil alone, grown;
        for (const auto& [u, v] : pointsOf(surface.parameterization(f), random)) {
            surface.stencil(f, u, v, alone);
            face.stencil(u, v, grown);
            ASSERT_TRUE(sameStencil(alone, grown)) << mesh << " face " << f << " (" << u << ", " << v << ")";
            checked.push_back({f, u, v, alone});
            // evaluate applies that stencil (LimitSurface::evaluate's point, without its search again).
            double p[3] = {}, du[3] = {}, dv[3] = {};
            for (int k = 0; k < alone.size(); ++k)
                for (int c = 0; c < 3; ++c) {
                    const double x = control[3 * std::size_t(alone.indices[std::size_t(k)]) + std::size_t(c)];
                    p[c] += alone.position[std::size_t(k)] * x;
                    du[c] += alone.du[std::size_t(k)] * x;
                    dv[c] += alone.dv[std::size_t(k)] * x;
                }
            float q[3], qu[3], qv[3];
            face.evaluate(u, v, control.data(), 3, 3, q, qu, qv);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(q[c], p[c], 1e-5 * (1 + std::abs(p[c]))) << mesh << " face " << f;
                EXPECT_NEAR(qu[c], du[c], 1e-4 * (1 + std::abs(du[c]))) << mesh << " face " << f;
                EXPECT_NEAR(qv[c], dv[c], 1e-4 * (1 + std::abs(dv[c]))) << mesh << " face " << f;
            }
            ++points;
        }
    }
    EXPECT_GT(points, 0);
    // The same points again through one reused FaceSurface: what the factory kept of each face
    // (its tree and neighbourhood) gives the same stencils.
    FaceSurface reused;
    LimitPointStencil again;
    for (const Checked& c : checked) {
        factory.faceSurface(c.face, reused);
        ASSERT_EQ(reused.face(), c.face);
        reused.stencil(c.u, c.v, again);
        ASSERT_TRUE(sameStencil(c.stencil, again)) << mesh << " face " << c.face << " again (" << c.u << ", " << c.v << ")";
    }
}

INSTANTIATE_TEST_SUITE_P(AllMeshes, FaceSurfaceAgreement,
                         testing::Combine(testing::ValuesIn(allMeshes()), testing::ValuesIn(allSchemes())),
                         [](const auto& info) {
                             return testNameOf(std::get<0>(info.param) + "_" + toString(std::get<1>(info.param)));
                         });

// A batch gives what the points give one at a time: bit for bit on bicubic patches and the
// trees (the same sums in the same order), within rounding on box splines (their batch sums the
// polynomial's monomials).
class FaceSurfaceBatches : public testing::TestWithParam<std::tuple<std::string, Scheme>> {};

TEST_P(FaceSurfaceBatches, AreThePointsOneAtATime) {
    const auto& [mesh, scheme] = GetParam();
    RefinedMesh r;
    if (const std::string refused = refineUnder(mesh, scheme, r); !refused.empty()) GTEST_SKIP() << refused;
    const LimitSurface surface(*r.refiner);
    const bool exact = !rulesOf(scheme).surfacePatches().boxSplineTriangles;
    // 5 floats a vertex, 6 apart: x y z, x + y, 1 (a partition of unity: value 1, derivatives 0).
    const int n = surface.numControlVertices();
    std::vector<float> control(std::size_t(n) * 6, 1e30f);
    for (int i = 0; i < n; ++i) {
        const float* p = &r.positions[0][3 * std::size_t(i)];
        const float values[5] = {p[0], p[1], p[2], p[0] + p[1], 1.0f};
        std::copy(values, values + 5, &control[6 * std::size_t(i)]);
    }
    std::mt19937 random(11);
    FaceSurfaceFactory factory(surface);
    FaceSurface face;
    const int step = std::max(1, surface.numFaces() / (kSanitized ? 6 : 40));
    for (int f = 0; f < surface.numFaces(); f += step) {
        if (surface.isHole(f)) continue;
        factory.faceSurface(f, face);
        std::vector<double> u, v;
        for (const auto& [a, b] : pointsOf(surface.parameterization(f), random)) {
            u.push_back(a);
            v.push_back(b);
        }
        const int count = int(u.size()), stride = 7;  // the batch's outputs 7 floats apart
        std::vector<float> p(std::size_t(count) * stride, -7.0f), du = p, dv = p;
        face.evaluate(count, u.data(), v.data(), control.data(), 5, 6, p.data(), du.data(), dv.data(), stride);
        std::vector<float> q(std::size_t(count) * stride, -7.0f);
        face.evaluate(count, u.data(), v.data(), control.data(), 5, 6, q.data(), nullptr, nullptr, stride);
        for (int i = 0; i < count; ++i) {
            float a[5], au[5], av[5];
            face.evaluate(u[std::size_t(i)], v[std::size_t(i)], control.data(), 5, 6, a, au, av);
            const std::size_t at = std::size_t(i) * stride;
            for (int c = 0; c < 5; ++c) {
                const float values[3] = {p[at + std::size_t(c)], du[at + std::size_t(c)], dv[at + std::size_t(c)]};
                const float alone[3] = {a[c], au[c], av[c]};
                for (int k = 0; k < 3; ++k) {
                    if (exact)
                        ASSERT_EQ(values[k], alone[k]) << mesh << " face " << f << " point " << i << " component " << c;
                    else
                        ASSERT_NEAR(values[k], alone[k], 2e-6 * (1 + std::abs(alone[k])))
                            << mesh << " face " << f << " point " << i << " component " << c;
                }
                ASSERT_EQ(q[at + std::size_t(c)], p[at + std::size_t(c)]);
            }
            for (std::size_t c = 5; c < stride; ++c) ASSERT_EQ(p[at + c], -7.0f) << "written between points";
            EXPECT_NEAR(p[at + 4], 1.0f, 1e-6f);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(SomeMeshes, FaceSurfaceBatches,
                         testing::Combine(testing::Values("mixed/mixed_torus.obj", "mixed/checker_cube.obj",
                                                          "osd/catmark_torus_creases0.obj",
                                                          "osd/loop_xord_interior.obj", "osd/catmark_fan.obj"),
                                          testing::ValuesIn(allSchemes())),
                         [](const auto& info) {
                             return testNameOf(std::get<0>(info.param) + "_" + toString(std::get<1>(info.param)));
                         });

// The batch loops' AVX2 build (where the CPU runs it) sums as the baseline build does, bit for bit:
// it is built without fused multiply-adds.
TEST(FaceSurface, BatchLoopsAreTheBaselineLoopsBitForBit) {
    std::mt19937 random(13);
    std::uniform_real_distribution<float> value(-10.0f, 10.0f);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int width : {1, 2, 3, 4, 5, 7, 9}) {
        const int stride = width + 2, numControl = 40;
        std::vector<float> control(std::size_t(numControl * stride));
        for (float& x : control) x = value(random);
        int sources[16];
        for (int& k : sources) k = int(unit(random) * numControl) % numControl;
        for (int count : {1, 5, 8, 13, 40}) {
            std::vector<double> u(static_cast<std::size_t>(count)), v(u);
            for (int i = 0; i < count; ++i) {
                u[std::size_t(i)] = unit(random);
                v[std::size_t(i)] = unit(random) * (1 - u[std::size_t(i)]);
            }
            for (bool box : {false, true}) {
                const std::size_t size = std::size_t(count * width);
                std::vector<float> p(size), du(size), dv(size), q(size), dq(size), eq(size);
                const internal::PatchPoints library{count, u.data(), v.data(), width, p.data(), du.data(), dv.data(), width};
                const internal::PatchPoints baseline{count, u.data(), v.data(), width, q.data(), dq.data(), eq.data(), width};
                if (box)
                    internal::boxSplinePoints(sources, control.data(), stride, library);
                else
                    internal::bSplinePoints(sources, control.data(), stride, library);
                baselinePatchPoints(box, sources, control.data(), stride, baseline);
                EXPECT_EQ(p, q) << "width " << width << " count " << count << (box ? " box spline" : " B-spline");
                EXPECT_EQ(du, dq) << "width " << width << " count " << count;
                EXPECT_EQ(dv, eq) << "width " << width << " count " << count;
            }
        }
    }
}

// More points than one chunk of the tree path's scratch, on faces whose points go through their
// trees (a triangle under catmull-clark: three sub-faces) and on a regular quad.
TEST(FaceSurface, LongBatchesAreThePointsOneAtATime) {
    Options options;
    options.scheme = Scheme::CatmullClark;
    const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 0, options);
    const LimitSurface surface(*r.refiner);
    FaceSurfaceFactory factory(surface);
    std::mt19937 random(17);
    int triangles = 0;
    for (int f = 0; f < surface.numFaces() && triangles < 2; ++f) {
        const FaceParameterization param = surface.parameterization(f);
        if (param.faceSize != 3 && f != 0) continue;
        triangles += param.faceSize == 3;
        FaceSurface face = factory.faceSurface(f);
        std::vector<double> u, v;
        for (int k = 0; k < 700; ++k) {
            const auto [a, b] = randomPointOf(param, k, random);
            u.push_back(a);
            v.push_back(b);
        }
        const std::size_t size = 3 * u.size();
        std::vector<float> p(size), du(size), dv(size);
        face.evaluate(int(u.size()), u.data(), v.data(), r.positions[0].data(), 3, 3, p.data(), du.data(), dv.data());
        for (std::size_t i = 0; i < u.size(); ++i) {
            float a[3], au[3], av[3];
            face.evaluate(u[i], v[i], r.positions[0].data(), 3, 3, a, au, av);
            for (std::size_t c = 0; c < 3; ++c) {
                ASSERT_EQ(p[3 * i + c], a[c]) << "face " << f << " point " << i;
                ASSERT_EQ(du[3 * i + c], au[c]) << "face " << f << " point " << i;
                ASSERT_EQ(dv[3 * i + c], av[c]) << "face " << f << " point " << i;
            }
        }
    }
    EXPECT_EQ(triangles, 2);
}

TEST(FaceSurface, RefusesABatchWithAPointOutsideBeforeWritingAny) {
    const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 0);
    const LimitSurface surface(*r.refiner);
    FaceSurfaceFactory factory(surface);
    for (int f : {0, 1, 2, 3}) {
        FaceSurface face = factory.faceSurface(f);
        const double u[3] = {0.2, 0.3, 1.5}, v[3] = {0.2, 0.1, 0.5};
        float p[9];
        std::fill(p, p + 9, -7.0f);
        try {
            face.evaluate(3, u, v, r.positions[0].data(), 3, 3, p);
            FAIL() << "no error for face " << f;
        } catch (const SurfaceError& e) {
            EXPECT_NE(std::string(e.what()).find("point 2"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("face " + std::to_string(f)), std::string::npos) << e.what();
        }
        EXPECT_TRUE(std::all_of(p, p + 9, [](float x) { return x == -7.0f; }));
    }
    FaceSurface face = factory.faceSurface(0);
    float p[3];
    const double u = 0.5, v = 0.5;
    EXPECT_THROW(face.evaluate(-1, &u, &v, r.positions[0].data(), 3, 3, p), SurfaceError);
    EXPECT_THROW(face.evaluate(1, &u, &v, r.positions[0].data(), 3, 3, p, nullptr, nullptr, 2), SurfaceError);
    face.evaluate(0, &u, &v, r.positions[0].data(), 3, 3, p);  // nothing to do
    FaceSurface empty;
    EXPECT_THROW(empty.evaluate(0, &u, &v, r.positions[0].data(), 3, 3, p), SurfaceError);
}

TEST(FaceSurface, FaceVaryingValuesAreThoseOfTheLimitSurface) {
    for (FVarLinearInterpolation fvar : {FVarLinearInterpolation::None, FVarLinearInterpolation::CornersOnly,
                                         FVarLinearInterpolation::Boundaries, FVarLinearInterpolation::All}) {
        for (const char* mesh : {"uv/mixed_torus_uv.obj", "uv/cylinder_capped_creased_uv.obj"}) {
            Options options;
            options.fvarLinearInterpolation = fvar;
            const io::ObjMesh obj = io::readObj(meshPath(mesh));
            FVarChannel uvChannel;
            const Refiner refiner(obj.descriptor(uvChannel), obj.applyTags(options));
            const LimitSurface surface(refiner);
            ASSERT_EQ(surface.numFVarChannels(), 1);
            std::mt19937 random(3);
            const int step = kSanitized ? 9 : 2;
            FaceSurfaceFactory factory(surface, 0);
            for (int f = 0; f < surface.numFaces(); f += step) {
                FaceSurface face = factory.faceSurface(f);
                LimitPointStencil alone, grown;
                for (const auto& [u, v] : pointsOf(surface.parameterization(f), random)) {
                    surface.fvarStencil(0, f, u, v, alone);
                    face.stencil(u, v, grown);
                    ASSERT_TRUE(sameStencil(alone, grown)) << mesh << " face " << f;
                    float a[2], b[2];
                    surface.evaluateFVar(0, f, u, v, obj.uvs.data(), 2, 2, a);
                    face.evaluate(u, v, obj.uvs.data(), 2, 2, b);
                    EXPECT_NEAR(a[0], b[0], 1e-6) << mesh << " face " << f;
                    EXPECT_NEAR(a[1], b[1], 1e-6) << mesh << " face " << f;
                }
            }
        }
    }
}

TEST(FaceSurface, EvaluatesWideDataComponentByComponent) {
    const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 0);
    const LimitSurface surface(*r.refiner);
    // 7 floats per vertex, 9 apart: x y z, then 2 x, 3 - y, z + x, 0.5, two floats never read.
    const int n = surface.numControlVertices();
    std::vector<float> wide(std::size_t(n) * 9, -1e30f);
    for (int i = 0; i < n; ++i) {
        const float* p = &r.positions[0][3 * std::size_t(i)];
        float* w = &wide[9 * std::size_t(i)];
        const float values[7] = {p[0], p[1], p[2], 2 * p[0], 3 - p[1], p[2] + p[0], 0.5f};
        std::copy(values, values + 7, w);
    }
    FaceSurfaceFactory factory(surface);
    FaceSurface face = factory.faceSurface(5);
    float p[3], q[7], dq[7];
    face.evaluate(0.3, 0.8, r.positions[0].data(), 3, 3, p);
    face.evaluate(0.3, 0.8, wide.data(), 7, 9, q, dq);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(q[c], p[c], 1e-5);
    EXPECT_NEAR(q[3], 2 * p[0], 1e-5);
    EXPECT_NEAR(q[4], 3 - p[1], 1e-5);
    EXPECT_NEAR(q[5], p[2] + p[0], 1e-5);
    EXPECT_NEAR(q[6], 0.5, 1e-6);  // a partition of unity
    EXPECT_NEAR(dq[6], 0.0, 1e-5);
}

TEST(FaceSurface, RefusesWhatTheLimitSurfaceRefuses) {
    const RefinedMesh r = refineMesh("osd/catmark_hole_test1.obj", 0);
    const LimitSurface surface(*r.refiner);
    FaceSurfaceFactory factory(surface);
    EXPECT_THROW(factory.faceSurface(-1), SurfaceError);
    EXPECT_THROW(factory.faceSurface(surface.numFaces()), SurfaceError);
    EXPECT_THROW(FaceSurfaceFactory(surface, 0), SurfaceError);  // no channel
    EXPECT_THROW(FaceSurfaceFactory(surface, -2), SurfaceError);
    int hole = -1, solid = -1;
    for (int f = 0; f < surface.numFaces(); ++f) (surface.isHole(f) ? hole : solid) = f;
    ASSERT_GE(hole, 0);
    EXPECT_THROW(factory.faceSurface(hole), SurfaceError);
    FaceSurface face = factory.faceSurface(solid);
    LimitPointStencil s;
    EXPECT_THROW(face.stencil(1.5, 0.5, s), SurfaceError);
    EXPECT_THROW(face.stencil(std::nan(""), 0.5, s), SurfaceError);
    FaceSurface empty;
    EXPECT_EQ(empty.face(), -1);
    EXPECT_THROW(empty.stencil(0.5, 0.5, s), SurfaceError);
}

}  // namespace
}  // namespace quadtri::test
