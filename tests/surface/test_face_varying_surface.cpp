// LimitSurface's face-varying values (far/limit_surface.h): every scheme's UV at a dyadic (u, v)
// against the uniform limit of the matching value under every FVarLinearInterpolation,
// OpenSubdiv's Bfr face-varying surfaces at random (u, v) under catmull-clark and loop, the linear
// interpolation's closed form, the stencils' invariants and the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <quadtri/far/limit_surface.h>
#include "tests/limit/limit_support.h"
#include "tests/osd_reference.h"
#include "tests/sanitized.h"
#include "tests/surface/surface_support.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

// OpenSubdiv's shapes with UVs, and tests/meshes/uv's mixed meshes with seams.
std::vector<std::string> meshesWithUVs() {
    std::vector<std::string> out;
    for (const std::string& m : allMeshes())
        if (io::readObj(meshPath(m)).hasUVs()) out.push_back(m);
    for (const char* m : {"uv/mixed_torus_uv.obj", "uv/split_plane_uv.obj", "uv/cylinder_capped_creased_uv.obj"})
        out.push_back(m);
    return out;
}

// The mesh refined to `maxLevel` with its UVs as channel 0.
RefinedMesh refineWithUVs(const std::string& relative, int maxLevel, Options options = Options()) {
    RefinedMesh r;
    r.mesh = io::readObj(meshPath(relative));
    r.options = r.mesh.applyTags(options);
    FVarChannel uvs;
    r.refiner = std::make_unique<Refiner>(r.mesh.descriptor(uvs), r.options);
    r.refiner->refineUniform(maxLevel, TopologyDetail::Full);
    r.positions = evaluateLevels(*r.refiner, r.mesh.positions, 3);
    return r;
}

// The UVs as 3-float points (z = 0), for the limit helpers.
std::vector<float> uvPoints(const io::ObjMesh& mesh) {
    std::vector<float> out;
    for (int i = 0; i < mesh.numUVs(); ++i) out.insert(out.end(), {mesh.uvs[2 * i], mesh.uvs[2 * i + 1], 0.0f});
    return out;
}

double uvDiagonal(const io::ObjMesh& mesh) { return std::max(boundingBoxDiagonal(uvPoints(mesh)), 1e-30); }

// Sample faces: every face of a small mesh, `maxFaces` spread over a large one.
template <class Visit>
void forSampleFaces(const LimitSurface& surface, int maxFaces, const Visit& visit) {
    const int faces = surface.numFaces(), step = std::max(1, faces / maxFaces);
    for (int f = 0; f < faces; f += step)
        if (!surface.isHole(f)) visit(f);
}

// ---- dyadic points against the uniform limit ----------------------------------------------

struct DyadicUVs {
    double worst = 0;  // over the UVs' bounding-box diagonal
    int points = 0;
    int inexactReference = 0;
};

DyadicUVs compareWithUniformLimit(const std::string& meshName, Scheme scheme, FVarLinearInterpolation fvar, int L,
                                  int maxFaces) {
    Options options;
    options.scheme = scheme;
    options.fvarLinearInterpolation = fvar;
    const RefinedMesh r = refineWithUVs(meshName, L, options);
    const Topology& level = r.refiner->level(L);
    const LimitData limit = applyLimit(r.refiner->fvarFactorizedLimitStencils(0, L), uvPoints(r.mesh));
    const LimitSurface surface(*r.refiner);
    const double diagonal = uvDiagonal(r.mesh);
    DyadicUVs d;
    forSampleFaces(surface, maxFaces, [&](int f) {
        forEachDescendantCorner(*r.refiner, f, L, [&](int levelFace, int corner, double u, double v) {
            // The value's limit is exact where its vertex's is (a seam's own corners and
            // creases are infinitely sharp or smooth).
            if (!exactUniformLimit(level, r.refiner->faces(L).verticesOfFace(levelFace)[corner])) {
                ++d.inexactReference;
                return;
            }
            const int value = r.refiner->fvarValuesOfFace(0, L, levelFace)[corner];
            float uv[2];
            surface.evaluateFVar(0, f, u, v, r.mesh.uvs.data(), 2, 2, uv);
            const Vec3& want = limit.position[std::size_t(value)];
            d.worst = std::max(d.worst, std::hypot(uv[0] - want[0], uv[1] - want[1]) / diagonal);
            ++d.points;
        });
    });
    return d;
}

class DyadicUVAgreement : public testing::TestWithParam<std::tuple<std::string, Scheme>> {};

TEST_P(DyadicUVAgreement, EqualsTheUniformLimitOfTheMatchingValueUnderEveryInterpolation) {
    const auto& [mesh, scheme] = GetParam();
    for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
        DyadicUVs d;
        try {
            d = compareWithUniformLimit(mesh, scheme, fvar, 2, kSanitized ? 1 : 6);
        } catch (const TopologyError& e) {
            GTEST_SKIP() << e.what();  // a mesh the scheme refuses (loop on quads)
        }
        EXPECT_LT(d.worst, 2e-6) << mesh << " " << toString(scheme) << " " << toString(fvar) << " (" << d.points
                                 << " points)";
        std::printf("%s %s %s: %d points (%d skipped), %.3g of the UV diagonal\n", mesh.c_str(), toString(scheme),
                    toString(fvar), d.points, d.inexactReference, d.worst);
    }
}

// Each of OpenSubdiv's shapes under its own scheme; every scheme on the mixed meshes and on a
// few shapes with seams, creases, boundaries and n-gons.
std::vector<std::tuple<std::string, Scheme>> dyadicCases() {
    std::vector<std::tuple<std::string, Scheme>> out;
    const std::vector<std::string> everyScheme = {"osd/catmark_cube_creases1.obj", "osd/catmark_fan.obj",
                                                  "osd/catmark_nonquads.obj", "osd/loop_cube_creases0.obj"};
    for (const std::string& m : meshesWithUVs()) {
        if (m.rfind("uv/", 0) == 0 || std::find(everyScheme.begin(), everyScheme.end(), m) != everyScheme.end()) {
            for (Scheme scheme : allSchemes()) out.emplace_back(m, scheme);
            continue;
        }
        const Scheme own = m.rfind("osd/loop_", 0) == 0       ? Scheme::Loop
                           : m.rfind("osd/bilinear_", 0) == 0 ? Scheme::Bilinear
                                                              : Scheme::CatmullClark;
        out.emplace_back(m, own);
    }
    return out;
}

INSTANTIATE_TEST_SUITE_P(MeshesWithUVs, DyadicUVAgreement, testing::ValuesIn(dyadicCases()),
                         [](const auto& info) {
                             return testNameOf(std::get<0>(info.param) + "_" + toString(std::get<1>(info.param)));
                         });

// ---- OpenSubdiv's Bfr ----------------------------------------------------------------------

class BfrUVAgreement : public testing::TestWithParam<std::string> {};

// Random (u, v) on every face, against Bfr's face-varying surface with both approximation levels
// at 10: the UV within 1e-6 of the UVs' diagonal, its derivatives within 1e-4 of their size.
TEST_P(BfrUVAgreement, EqualsBfrAtApproximationLevel10UnderEveryInterpolation) {
    const std::string mesh = GetParam();
    const Scheme scheme = mesh.rfind("osd/loop_", 0) == 0 ? Scheme::Loop : Scheme::CatmullClark;
    for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
        Options options;
        options.scheme = scheme;
        options.fvarLinearInterpolation = fvar;
        const RefinedMesh r = refineWithUVs(mesh, 0, options);
        const LimitSurface surface(*r.refiner);
        std::mt19937 random(11);
        std::vector<int> faces;
        std::vector<double> uv;
        forSampleFaces(surface, kSanitized ? 4 : 1 << 20, [&](int f) {
            const FaceParameterization p = surface.parameterization(f);
            for (int k = 0; k < (kSanitized ? 1 : 4); ++k) {
                const auto [u, v] = randomPointOf(p, k, random);
                faces.push_back(f);
                uv.insert(uv.end(), {u, v});
            }
        });
        // catmark_rook maps every face onto the same four values, so its value mesh is non-manifold at
        // every vertex: under `none` our points equal the uniform limit (the dyadic test), which equals
        // OpenSubdiv's Far (test_fvar_limit_osd), but Bfr's face-varying surface differs from Far there.
        if (mesh == "osd/catmark_rook.obj" && fvar == FVarLinearInterpolation::None) continue;
        const OsdScheme osdScheme = scheme == Scheme::Loop ? OsdScheme::Loop : OsdScheme::Catmark;
        const OsdSurfacePoints bfr = osdSurfaceUVs(r.mesh, osdScheme, r.options.boundary, r.options.creaseMethod, fvar,
                                                   10, faces, uv, r.options.leftHanded);
        const double diagonal = uvDiagonal(r.mesh);
        double worst = 0, worstDerivative = 0;
        int points = 0;
        for (std::size_t i = 0; i < faces.size(); ++i) {
            if (!bfr.evaluated[i]) continue;
            float value[2], du[2], dv[2];
            surface.evaluateFVar(0, faces[i], uv[2 * i], uv[2 * i + 1], r.mesh.uvs.data(), 2, 2, value, du, dv);
            worst = std::max(worst, std::hypot(value[0] - bfr.position[2 * i], value[1] - bfr.position[2 * i + 1]) /
                                        diagonal);
            for (const auto& [ours, theirs] : {std::pair{du, &bfr.du[2 * i]}, std::pair{dv, &bfr.dv[2 * i]}}) {
                const double size = std::max(std::hypot(theirs[0], theirs[1]), diagonal * 1e-3);
                worstDerivative =
                    std::max(worstDerivative, std::hypot(ours[0] - theirs[0], ours[1] - theirs[1]) / size);
            }
            ++points;
        }
        std::printf("%s %s %s: %d points, UV %.3g of the diagonal, derivatives %.3g\n", mesh.c_str(),
                    toString(scheme), toString(fvar), points, worst, worstDerivative);
        EXPECT_GT(points, 0);
        EXPECT_LT(worst, 1e-6) << mesh << " " << toString(fvar);
        EXPECT_LT(worstDerivative, 1e-4) << mesh << " " << toString(fvar);
    }
}

std::vector<std::string> bfrMeshesWithUVs() {
    std::vector<std::string> out;
    for (const std::string& m : meshesWithUVs())
        if (m.rfind("osd/catmark_", 0) == 0 || m.rfind("osd/loop_", 0) == 0) out.push_back(m);
    return out;
}

INSTANTIATE_TEST_SUITE_P(OpenSubdivShapes, BfrUVAgreement, testing::ValuesIn(bfrMeshesWithUVs()),
                         [](const auto& info) { return testNameOf(info.param); });

// ---- closed forms and invariants ---------------------------------------------------------

// Linear throughout, a quad's UV is the bilinear blend of its corners' and a triangle's the linear
// one, under every scheme whose crease rule is the midpoint.
TEST(FaceVaryingSurface, LinearEverywhereIsTheBilinearBlendOfTheCorners) {
    for (const std::string mesh : {"osd/catmark_cube.obj", "osd/loop_cube.obj", "osd/catmark_pyramid.obj"}) {
        for (Scheme scheme : allSchemes()) {
            if (scheme == Scheme::CatmarkButterfly) continue;  // 4-point curves: not linear
            Options options;
            options.scheme = scheme;
            options.fvarLinearInterpolation = FVarLinearInterpolation::All;
            RefinedMesh r;
            try {
                r = refineWithUVs(mesh, 0, options);
            } catch (const TopologyError&) {
                continue;
            }
            const LimitSurface surface(*r.refiner);
            const Topology& t = r.refiner->level(0);
            for (int f = 0; f < surface.numFaces(); ++f) {
                const FaceParameterization p = surface.parameterization(f);
                if (p.type == FaceParameterization::Type::QuadSubFaces) continue;
                const IndexSpan values = r.refiner->fvarValuesOfFace(0, 0, f);
                for (double u : {0.0, 0.3, 0.5}) {
                    for (double v : {0.0, 0.25, 0.5}) {
                        double w[4];
                        if (p.type == FaceParameterization::Type::Quad) {
                            w[0] = (1 - u) * (1 - v), w[1] = u * (1 - v), w[2] = u * v, w[3] = (1 - u) * v;
                        } else {
                            w[0] = 1 - u - v, w[1] = u, w[2] = v;
                        }
                        float uv[2];
                        surface.evaluateFVar(0, f, u, v, r.mesh.uvs.data(), 2, 2, uv);
                        for (int c = 0; c < 2; ++c) {
                            double want = 0;
                            for (int k = 0; k < t.faceSize(f); ++k) want += w[k] * r.mesh.uvs[2 * values[k] + c];
                            EXPECT_NEAR(uv[c], want, 1e-6) << mesh << " " << toString(scheme) << " face " << f;
                        }
                    }
                }
            }
        }
    }
}

TEST(FaceVaryingSurface, StencilsArePartitionsOfUnityAndTheTableHoldsThem) {
    for (Scheme scheme : {Scheme::SchaeferWarren, Scheme::CatmullClark}) {
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineWithUVs("osd/catmark_pyramid.obj", 0, options);
        const LimitSurface surface(*r.refiner);
        ASSERT_EQ(surface.numFVarChannels(), 1);
        EXPECT_EQ(surface.numFVarValues(0), r.mesh.numUVs());
        std::vector<int> faces;
        std::vector<double> u, v;
        for (int f = 0; f < surface.numFaces(); ++f) {
            const FaceParameterization p = surface.parameterization(f);
            double cu, cv;
            p.cornerCoord(0, cu, cv);
            faces.insert(faces.end(), {f, f});
            u.insert(u.end(), {cu, p.type == FaceParameterization::Type::Triangle ? 0.2 : 0.3});
            v.insert(v.end(), {cv, 0.1});
        }
        const LimitStencilTable table = surface.fvarStencilTable(0, int(faces.size()), faces.data(), u.data(), v.data());
        ASSERT_EQ(table.numStencils(), int(faces.size()));
        EXPECT_EQ(table.numSourceVertices, r.mesh.numUVs());
        for (std::size_t i = 0; i < faces.size(); ++i) {
            LimitPointStencil s;
            surface.fvarStencil(0, faces[i], u[i], v[i], s);
            double sum = 0, du = 0, dv = 0;
            for (int k = 0; k < s.size(); ++k) {
                sum += s.position[std::size_t(k)];
                du += s.du[std::size_t(k)];
                dv += s.dv[std::size_t(k)];
                EXPECT_GE(s.indices[std::size_t(k)], 0);
                EXPECT_LT(s.indices[std::size_t(k)], r.mesh.numUVs());
            }
            EXPECT_NEAR(sum, 1, 1e-12);
            EXPECT_NEAR(du, 0, 1e-12);
            EXPECT_NEAR(dv, 0, 1e-12);
            ASSERT_EQ(table.size(int(i)), s.size());  // the table sorts each stencil's entries
            for (int k = 0; k < s.size(); ++k) {
                const int* sources = table.sourcesOf(int(i));
                const int j = int(std::find(sources, sources + s.size(), s.indices[std::size_t(k)]) - sources);
                ASSERT_LT(j, s.size());
                EXPECT_EQ(table.weightsOf(int(i))[3 * j], float(s.position[std::size_t(k)]));
            }
        }
    }
}

// The UVs' trees cut as narrowly as the positions' (far/schemes/scheme.h, surfaceRings): every
// value bit for bit what wider cuts give, under every scheme and linear interpolation, at
// maxDepth 2 (most points through the limit step) and 10.
TEST(FaceVaryingSurface, WiderCutsChangeNoBit) {
    std::mt19937 random(13);
    for (const std::string mesh : {"uv/mixed_torus_uv.obj", "uv/cylinder_capped_creased_uv.obj", "osd/catmark_pyramid.obj"})
        for (Scheme scheme : allSchemes())
            for (FVarLinearInterpolation linear : {FVarLinearInterpolation::None, FVarLinearInterpolation::CornersPlus1,
                                                   FVarLinearInterpolation::Boundaries}) {
                Options options;
                options.scheme = scheme;
                options.fvarLinearInterpolation = linear;
                RefinedMesh r;
                try {
                    r = refineWithUVs(mesh, 0, options);
                } catch (const TopologyError&) {
                    continue;  // loop on quads
                }
                for (int maxDepth : {2, 10}) {
                    const auto [narrow, wider] = narrowAndWiderCuts(scheme, maxDepth);
                    const LimitSurface a(*r.refiner, narrow), b(*r.refiner, wider);
                    LimitPointStencil sa, sb;
                    forSampleFaces(a, kSanitized ? 3 : 8, [&](int f) {
                        for (int k = 0; k < 2; ++k) {
                            const auto [u, v] = randomPointOf(a.parameterization(f), k, random);
                            a.fvarStencil(0, f, u, v, sa);
                            b.fvarStencil(0, f, u, v, sb);
                            ASSERT_TRUE(sameWeights(sa, sb)) << mesh << " " << toString(scheme) << " maxDepth "
                                                             << maxDepth << " face " << f << " (" << u << ", " << v << ")";
                        }
                    });
                }
            }
}

TEST(FaceVaryingSurface, RefusesAMissingChannelAndPointsOutsideTheFace) {
    const RefinedMesh withUVs = refineWithUVs("osd/catmark_cube.obj", 0);
    const LimitSurface surface(*withUVs.refiner);
    LimitPointStencil s;
    try {
        surface.fvarStencil(1, 0, 0.5, 0.5, s);
        FAIL() << "channel 1 of 1 accepted";
    } catch (const SurfaceError& e) {
        EXPECT_NE(std::string(e.what()).find("face-varying channel 1"), std::string::npos) << e.what();
    }
    EXPECT_THROW(surface.fvarStencil(0, 0, 1.5, 0.5, s), SurfaceError);
    EXPECT_THROW(surface.fvarStencil(0, surface.numFaces(), 0.5, 0.5, s), SurfaceError);

    const RefinedMesh without = refineWithUVs("mixed/mixed_torus.obj", 0);
    const LimitSurface plain(*without.refiner);
    EXPECT_EQ(plain.numFVarChannels(), 0);
    EXPECT_THROW(plain.fvarStencil(0, 0, 0.5, 0.5, s), SurfaceError);
}

}  // namespace
}  // namespace quadtri::test
