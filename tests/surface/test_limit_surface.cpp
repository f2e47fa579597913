// LimitSurface (far/limit_surface.h): the patch bases' closed forms, every scheme's point at a
// dyadic (u, v) against the uniform limit of the matching vertex, OpenSubdiv's Bfr at deep
// approximation under catmull-clark and loop, continuity across edges, and the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include <quadtri/far/limit_surface.h>
#include "far/surface/local_mesh.h"
#include "far/surface/patch_basis.h"
#include "far/surface/regular_patch.h"
#include "tests/limit/limit_support.h"
#include "tests/osd_reference.h"
#include "tests/sanitized.h"
#include "tests/surface/surface_support.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

// ---- bases ---------------------------------------------------------------------------------

TEST(PatchBasis, BSplineIsAPartitionOfUnityThatReproducesLines) {
    for (double s : {0.0, 0.3, 0.5, 1.0})
        for (double t : {0.0, 0.7, 1.0}) {
            double w[16], ws[16], wt[16];
            bSplineWeights(s, t, w, ws, wt);
            double sum = 0, ds = 0, x = 0, y = 0, dx = 0, dy = 0;
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i) {
                    sum += w[4 * j + i];
                    ds += ws[4 * j + i];
                    x += w[4 * j + i] * (i - 1);  // grid point (i, j) at (i - 1, j - 1)
                    y += w[4 * j + i] * (j - 1);
                    dx += ws[4 * j + i] * (i - 1);
                    dy += wt[4 * j + i] * (j - 1);
                }
            EXPECT_NEAR(sum, 1, 1e-15);
            EXPECT_NEAR(ds, 0, 1e-15);
            EXPECT_NEAR(x, s, 1e-15);
            EXPECT_NEAR(y, t, 1e-15);
            EXPECT_NEAR(dx, 1, 1e-15);
            EXPECT_NEAR(dy, 1, 1e-15);
        }
}

TEST(PatchBasis, BoxSplineIsAPartitionOfUnityThatReproducesLinesOnItsLattice) {
    const int lattice[12][2] = {{0, -1}, {1, -1}, {2, -1}, {-1, 0}, {0, 0}, {1, 0},
                                {2, 0},  {-1, 1}, {0, 1},  {1, 1},  {-1, 2}, {0, 2}};
    for (double s : {0.0, 0.25, 0.5, 1.0})
        for (double t : {0.0, 0.25, 0.5}) {
            if (s + t > 1) continue;
            double w[12], ws[12], wt[12];
            boxSplineWeights(s, t, w, ws, wt);
            double sum = 0, a = 0, b = 0, as = 0, bt = 0, bs = 0;
            for (int i = 0; i < 12; ++i) {
                EXPECT_GE(w[i], -1e-15) << "box-spline weights are non-negative";
                sum += w[i];
                a += w[i] * lattice[i][0];
                b += w[i] * lattice[i][1];
                as += ws[i] * lattice[i][0];
                bs += ws[i] * lattice[i][1];
                bt += wt[i] * lattice[i][1];
            }
            EXPECT_NEAR(sum, 1, 1e-14);
            EXPECT_NEAR(a, s, 1e-14);
            EXPECT_NEAR(b, t, 1e-14);
            EXPECT_NEAR(as, 1, 1e-14);
            EXPECT_NEAR(bs, 0, 1e-14);
            EXPECT_NEAR(bt, 1, 1e-14);
        }
}

TEST(PatchBasis, BoxSplineAtACornerIsLoopsLimitMask) {
    // Loop's limit mask at a valence-6 vertex: 1/2 the vertex, 1/12 each neighbour.
    double w[12], ws[12], wt[12];
    boxSplineWeights(0, 0, w, ws, wt);
    EXPECT_NEAR(w[4], 0.5, 1e-15);
    for (int i : {0, 1, 3, 5, 7, 8}) EXPECT_NEAR(w[i], 1.0 / 12, 1e-15) << i;
}

TEST(PatchBasis, QuadraticsInterpolateTheirNodes) {
    double w[9], ws[9], wt[9];
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            quadraticQuadWeights(0.5 * i, 0.5 * j, w, ws, wt);
            for (int k = 0; k < 9; ++k) EXPECT_NEAR(w[k], k == 3 * j + i ? 1 : 0, 1e-15);
        }
    const double nodes[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
    for (int n = 0; n < 6; ++n) {
        quadraticTriangleWeights(nodes[n][0], nodes[n][1], w, ws, wt);
        for (int k = 0; k < 6; ++k) EXPECT_NEAR(w[k], k == n ? 1 : 0, 1e-15);
    }
}

// ---- local refinement ------------------------------------------------------------------------

// Follows `path` (a child per level) from base face `face` and checks that every vertex of the
// followed face's one-ring, positioned by its rows, is a vertex of the uniform level.
double worstLocalVertex(const std::string& mesh, Scheme scheme, int face, const std::vector<int>& path) {
    Options options;
    options.scheme = scheme;
    const RefinedMesh r = refineMesh(mesh, int(path.size()), options);
    Options local = r.refiner->options();
    local.leftHanded = false;
    const int rings = rulesOf(scheme).surfaceRings();
    WalkScratch scratch;
    std::vector<int> columns;
    LocalMesh m = cutBase(r.refiner->level(0), face, rings, local, scratch, columns);
    for (int child : path) m = refineTowards(m, child, rings, local, scratch);
    const std::vector<float>& level = r.positions[path.size()];
    const double diagonal = boundingBoxDiagonal(r.positions[0]);
    double worst = 0;
    for (int v : m.topology.verticesOfFace(m.face))
        for (int g : m.topology.facesOfVertex(v))
            for (int x : m.topology.verticesOfFace(g)) {
                Vec3 p{0, 0, 0};
                const SparseRow row = m.row(x);
                for (int k = 0; k < row.size; ++k)
                    for (int c = 0; c < 3; ++c)
                        p[c] += row.weights[k] * r.positions[0][3 * std::size_t(columns[std::size_t(row.columns[k])]) + c];
                double nearest = 1e300;
                for (std::size_t k = 0; k < level.size() / 3; ++k) nearest = std::min(nearest, distance(p, vec3(&level[3 * k])));
                worst = std::max(worst, nearest / diagonal);
            }
    return worst;
}

// Each vertex's ring ordered once and shared by its faces finds the patches face by face does,
// in any order of the faces, on every mesh and level 0 and 1 of every scheme.
TEST(RegularPatches, AreThePatchesFoundFaceByFace) {
    std::mt19937 random(5);
    forEachMeshAndScheme(1, [&](const std::string& mesh, Scheme scheme, RefinedMesh& r) {
        Options o = r.options;
        o.leftHanded = false;  // every level is counter-clockwise
        for (int l = 0; l <= 1; ++l) {
            const Topology& level = r.refiner->level(l);
            std::vector<int> faces(std::size_t(level.numFaces()));
            for (int f = 0; f < level.numFaces(); ++f) faces[std::size_t(f)] = f;
            std::shuffle(faces.begin(), faces.end(), random);
            RegularPatches shared(level, o);
            std::vector<int> alone, found;
            int regular = 0;
            for (int f : faces) {
                const PatchKind kind = regularPatch(level, f, o, alone);
                ASSERT_EQ(shared.of(f, found), kind)
                    << mesh << " " << toString(scheme) << " level " << l << " face " << f;
                if (kind == PatchKind::None) continue;
                ASSERT_EQ(found, alone) << mesh << " level " << l << " face " << f;
                ++regular;
            }
            if (mesh == "mixed/mixed_torus.obj" && l == 1) {
                EXPECT_GT(regular, 0) << toString(scheme);
            }
        }
    });
}

TEST(LocalRefinement, KeepsTheMeshsOwnVerticesAroundTheFollowedFace) {
    for (const std::string mesh : {"osd/catmark_inf_crease0.obj", "osd/catmark_torus_creases0.obj", "mixed/mixed_torus.obj"})
        for (Scheme scheme : schemesTakingQuads())
            for (const std::vector<int>& path : {std::vector<int>{2, 0, 0}, {1, 3, 2}})
                EXPECT_LT(worstLocalVertex(mesh, scheme, 9, path), 1e-6) << mesh << " " << toString(scheme);
}

// Each cut keeps the scheme's own rings (1 around the followed child where masks read one ring,
// 3 or 2 for the mixed schemes; 7 for their limit masks): the points are bit for bit those of
// wider cuts (the old 2 and 7 everywhere), at maxDepth 2 (most points reach the limit step) and
// at the default, on every mesh and scheme, random points and points next to corners.
TEST(LocalRefinement, WiderCutsChangeNoBit) {
    std::mt19937 random(11);
    forEachMeshAndScheme(0, [&](const std::string& mesh, Scheme scheme, RefinedMesh& r) {
        for (int maxDepth : {2, 10}) {
            const auto [narrow, wider] = narrowAndWiderCuts(scheme, maxDepth);
            const LimitSurface a(*r.refiner, narrow), b(*r.refiner, wider);
            const int step = std::max(1, a.numFaces() / (kSanitized ? 2 : 6));
            LimitPointStencil sa, sb;
            for (int f = 0; f < a.numFaces(); f += step) {
                if (a.isHole(f)) continue;
                const FaceParameterization p = a.parameterization(f);
                std::vector<std::pair<double, double>> points;
                for (int k = 0; k < 2; ++k) points.push_back(randomPointOf(p, k, random));
                double u, v;
                p.cornerCoord(0, u, v);
                const bool sub = p.type == FaceParameterization::Type::QuadSubFaces;  // corner 0's sub-face
                const double cu = sub ? std::floor(u) + 0.5 : 0.25, cv = sub ? std::floor(v) + 0.5 : 0.25;
                points.emplace_back(u + (cu - u) * 1e-3, v + (cv - v) * 1e-3);  // deep, next to corner 0
                for (const auto& [pu, pv] : points) {
                    a.stencil(f, pu, pv, sa);
                    b.stencil(f, pu, pv, sb);
                    ASSERT_TRUE(sameWeights(sa, sb)) << mesh << " " << toString(scheme) << " maxDepth " << maxDepth
                                                     << " face " << f << " (" << pu << ", " << pv << ")";
                }
            }
        }
    });
}

// ---- dyadic points against the uniform limit ----------------------------------------------

struct Dyadic {
    double worstPosition = 0;  // over the bounding-box diagonal
    double worstNormal = 0;    // radians
    int points = 0;
    int inexactReference = 0;  // points whose uniform limit is not exact (skipped)
};

Dyadic compareWithUniformLimit(const std::string& mesh, Scheme scheme, int L, int maxFaces, LimitSurfaceOptions so = {}) {
    Options options;
    options.scheme = scheme;
    const RefinedMesh r = refineMesh(mesh, L, options);
    r.refiner->refineUniform(L, TopologyDetail::Full);
    const Topology& level = r.refiner->level(L);
    const LimitData limit = applyLimit(r.refiner->limitStencils(L), r.positions[L]);
    const LimitSurface surface(*r.refiner, so);
    const double diagonal = boundingBoxDiagonal(r.positions[0]);
    Dyadic d;
    const int faces = surface.numFaces(), step = std::max(1, faces / maxFaces);
    for (int f = 0; f < faces; f += step) {
        if (surface.isHole(f)) continue;
        forEachDescendantCorner(*r.refiner, f, L, [&](int levelFace, int corner, double u, double v) {
            const int vertex = r.refiner->faces(L).verticesOfFace(levelFace)[corner];
            if (!exactUniformLimit(level, vertex)) {
                ++d.inexactReference;
                return;
            }
            float p[3], du[3], dv[3];
            surface.evaluate(f, u, v, r.positions[0].data(), 3, 3, p, du, dv);
            const double e = distance(vec3(p), limit.position[vertex]) / diagonal;
            d.worstPosition = std::max(d.worstPosition, e);
            const Vec3 normal = cross(vec3(du), vec3(dv)), want = cross(limit.du[vertex], limit.dv[vertex]);
            if (norm(normal) > 1e-12 && norm(want) > 1e-12)
                d.worstNormal = std::max(d.worstNormal, angleBetween(normal, want));
            ++d.points;
        });
    }
    return d;
}

class DyadicAgreement : public testing::TestWithParam<std::tuple<std::string, Scheme>> {};

TEST_P(DyadicAgreement, EqualsTheUniformLimitOfTheMatchingVertex) {
    const auto& [mesh, scheme] = GetParam();
    Dyadic d;
    try {
        d = compareWithUniformLimit(mesh, scheme, 2, kSanitized ? 2 : 24);
    } catch (const TopologyError& e) {
        GTEST_SKIP() << e.what();  // a mesh the scheme refuses (loop on quads)
    }
    EXPECT_GT(d.points, 0);
    EXPECT_LT(d.worstPosition, 2e-6) << mesh << " " << toString(scheme) << " (" << d.points << " points)";
    RecordProperty("worst_position", std::to_string(d.worstPosition));
    RecordProperty("worst_normal", std::to_string(d.worstNormal));
    std::printf("%s %s: %d points (%d skipped), position %.3g of the diagonal, normal %.3g rad\n", mesh.c_str(), toString(scheme),
                d.points, d.inexactReference, d.worstPosition, d.worstNormal);
}

INSTANTIATE_TEST_SUITE_P(AllMeshes, DyadicAgreement, testing::Combine(testing::ValuesIn(allMeshes()), testing::ValuesIn(allSchemes())),
                         [](const auto& info) {
                             return testNameOf(std::get<0>(info.param) + "_" + toString(std::get<1>(info.param)));
                         });

// ---- OpenSubdiv's Bfr ----------------------------------------------------------------------

struct BfrComparison {
    double worstPosition = 0, worstNormal = 0;
    int points = 0;
};

// Random (u, v) on every face (those with a collapsed edge too), against Bfr with both
// approximation levels at 10.
BfrComparison compareWithBfr(const std::string& meshName, Scheme scheme, int perFace) {
    Options options;
    options.scheme = scheme;
    const RefinedMesh r = refineMesh(meshName, 0, options);
    const LimitSurface surface(*r.refiner);
    std::mt19937 random(7);
    std::vector<int> faces;
    std::vector<double> uv;
    for (int f = 0; f < surface.numFaces(); ++f) {
        if (surface.isHole(f)) continue;
        const FaceParameterization p = surface.parameterization(f);
        for (int k = 0; k < perFace; ++k) {
            const auto [u, v] = randomPointOf(p, k, random);
            faces.push_back(f);
            uv.insert(uv.end(), {u, v});
        }
    }
    const OsdScheme osdScheme = scheme == Scheme::Loop ? OsdScheme::Loop : OsdScheme::Catmark;
    const OsdSurfacePoints bfr = osdSurfacePoints(r.mesh, osdScheme, r.options.boundary, r.options.creaseMethod, 10,
                                                  faces, uv, r.options.leftHanded);
    const double diagonal = boundingBoxDiagonal(r.positions[0]);
    BfrComparison c;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        if (!bfr.evaluated[i]) continue;
        float p[3], du[3], dv[3];
        surface.evaluate(faces[i], uv[2 * i], uv[2 * i + 1], r.positions[0].data(), 3, 3, p, du, dv);
        c.worstPosition = std::max(c.worstPosition, distance(vec3(p), vec3(&bfr.position[3 * i])) / diagonal);
        c.worstNormal = std::max(c.worstNormal, angleBetween(cross(vec3(du), vec3(dv)),
                                                             cross(vec3(&bfr.du[3 * i]), vec3(&bfr.dv[3 * i]))));
        ++c.points;
    }
    return c;
}

std::vector<std::string> osdMeshes(const char* prefix) {
    std::vector<std::string> out;
    for (const std::string& m : allMeshes())
        if (m.rfind(prefix, 0) == 0) out.push_back(m);
    return out;
}

class BfrAgreement : public testing::TestWithParam<std::string> {};

TEST_P(BfrAgreement, EqualsBfrAtApproximationLevel10) {
    const std::string mesh = GetParam();
    const Scheme scheme = mesh.rfind("osd/loop_", 0) == 0 ? Scheme::Loop : Scheme::CatmullClark;
    const BfrComparison c = compareWithBfr(mesh, scheme, kSanitized ? 1 : 8);
    std::printf("%s %s: %d points, position %.3g of the diagonal, normal %.3g rad\n", mesh.c_str(), toString(scheme),
                c.points, c.worstPosition, c.worstNormal);
    EXPECT_GT(c.points, 0);
    EXPECT_LT(c.worstPosition, 1e-6) << mesh;
    EXPECT_LT(c.worstNormal, 1e-4) << mesh;
}

std::vector<std::string> bfrMeshes() {
    std::vector<std::string> out = osdMeshes("osd/catmark_");
    for (const std::string& m : osdMeshes("osd/loop_")) out.push_back(m);
    return out;
}

INSTANTIATE_TEST_SUITE_P(OpenSubdivShapes, BfrAgreement, testing::ValuesIn(bfrMeshes()),
                         [](const auto& info) { return testNameOf(info.param); });

// ---- continuity and errors -------------------------------------------------------------------

TEST(LimitSurface, IsContinuousAcrossEveryEdgeWithContinuousNormals) {
    for (Scheme scheme : schemesWhere([](const SchemeRules& r) { return r.acceptsNonTriangles() && !r.surfacePatches().bilinear; })) {
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineMesh("mixed/mixed_torus.obj", 0, options);
        const Topology& t = r.refiner->level(0);
        const LimitSurface surface(*r.refiner);
        const double diagonal = boundingBoxDiagonal(r.positions[0]);
        double worstGap = 0, worstNormal = 0;
        for (int e = 0; e < t.numEdges(); e += kSanitized ? 7 : 1) {
            if (t.edgeFaceCount(e) != 2) continue;
            Vec3 p[2], n[2];
            for (int side = 0; side < 2; ++side) {
                const int f = t.facesOfEdge(e)[side], i = t.cornerOfEdge(f, e);
                // t runs from corner i to i + 1: from the edge's first end on one side, its other on the other.
                const bool forward = t.verticesOfFace(f)[i] == t.edgeVerts[2 * e];
                double u, v;
                surface.parameterization(f).edgeCoord(i, forward ? 0.3 : 0.7, u, v);
                float x[3], du[3], dv[3];
                surface.evaluate(f, u, v, r.positions[0].data(), 3, 3, x, du, dv);
                p[side] = vec3(x);
                n[side] = cross(vec3(du), vec3(dv));
            }
            worstGap = std::max(worstGap, distance(p[0], p[1]) / diagonal);
            worstNormal = std::max(worstNormal, angleBetween(n[0], n[1]));
        }
        EXPECT_LT(worstGap, 1e-6) << toString(scheme);
        EXPECT_LT(worstNormal, 1e-3) << toString(scheme);
        std::printf("%s: gap %.3g, normal jump %.3g rad\n", toString(scheme), worstGap, worstNormal);
    }
}

// An n-gon's (u, v) is in sub-face i where it lies in i's half-unit square at (i % w, i / w),
// within the tolerance: on each square's edges and just past them, in the gaps between squares,
// outside the grid, at NaN and infinity.
TEST(FaceParameterization, FindsTheSubFaceWhoseSquareHoldsThePoint) {
    const double tolerance = 1e-9, inf = std::numeric_limits<double>::infinity();
    for (int n : {3, 5, 6, 7, 8, 9, 10, 17}) {  // a quad is a unit square of its own
        const FaceParameterization p = FaceParameterization::of(Scheme::CatmullClark, n);
        ASSERT_EQ(p.type, FaceParameterization::Type::QuadSubFaces) << n;
        std::vector<double> coords{-0.3, std::nan(""), inf, -inf};
        for (int k = -1; k <= 2 * (p.gridWidth + 1); ++k)
            for (double d : {-2 * tolerance, -tolerance / 2, 0.0, tolerance / 2, 2 * tolerance, 0.1, 0.3})
                coords.push_back(0.5 * k + d);
        for (double u : coords)
            for (double v : coords) {
                int expected = -1;
                for (int i = 0; i < n && expected < 0; ++i) {
                    const double x = i % p.gridWidth, y = i / p.gridWidth;
                    if (u >= x - tolerance && u <= x + 0.5 + tolerance && v >= y - tolerance && v <= y + 0.5 + tolerance)
                        expected = i;
                }
                ASSERT_EQ(p.subFaceAt(u, v, tolerance), expected) << n << "-gon (" << u << ", " << v << ")";
                ASSERT_EQ(p.contains(u, v, tolerance), expected >= 0) << n << "-gon (" << u << ", " << v << ")";
            }
    }
}

TEST(LimitSurface, RefusesPointsItHasNoSurfaceFor) {
    const RefinedMesh r = refineMesh("osd/catmark_hole_test1.obj", 0);
    const LimitSurface surface(*r.refiner);
    float p[3];
    EXPECT_THROW(surface.evaluate(-1, 0.5, 0.5, r.positions[0].data(), 3, 3, p), SurfaceError);
    EXPECT_THROW(surface.evaluate(surface.numFaces(), 0.5, 0.5, r.positions[0].data(), 3, 3, p), SurfaceError);
    EXPECT_THROW(surface.evaluate(0, 1.5, 0.5, r.positions[0].data(), 3, 3, p), SurfaceError);
    EXPECT_THROW(surface.evaluate(0, std::nan(""), 0.5, r.positions[0].data(), 3, 3, p), SurfaceError);
    int hole = -1;
    for (int f = 0; f < surface.numFaces() && hole < 0; ++f)
        if (surface.isHole(f)) hole = f;
    ASSERT_GE(hole, 0);
    try {
        surface.evaluate(hole, 0.5, 0.5, r.positions[0].data(), 3, 3, p);
        FAIL() << "a hole evaluated";
    } catch (const SurfaceError& e) {
        EXPECT_NE(std::string(e.what()).find("face " + std::to_string(hole) + " is a hole"), std::string::npos) << e.what();
    }
}

// Built from the mesh's arrays without a Refiner, the surface is the Refiner's: the same stencils,
// UVs included, and the Refiner's errors for a bad mesh.
TEST(LimitSurface, FromTheMeshArraysIsTheRefinersSurface) {
    for (const char* mesh : {"uv/cylinder_capped_creased_uv.obj", "osd/catmark_hole_test1.obj"}) {
        const io::ObjMesh obj = io::readObj(meshPath(mesh));
        FVarChannel uvChannel;
        const TopologyDescriptor desc = obj.descriptor(uvChannel);
        for (Scheme scheme : {Scheme::SchaeferWarren, Scheme::CatmullClark}) {
            Options options;
            options.scheme = scheme;
            options = obj.applyTags(options);
            const Refiner refiner(desc, options);
            const LimitSurface viaRefiner(refiner), direct(desc, options);
            ASSERT_EQ(direct.numFaces(), viaRefiner.numFaces());
            ASSERT_EQ(direct.numFVarChannels(), viaRefiner.numFVarChannels());
            std::mt19937 random(5);
            LimitPointStencil a, b;
            for (int f = 0; f < direct.numFaces(); f += 3) {
                ASSERT_EQ(direct.isHole(f), viaRefiner.isHole(f));
                if (direct.isHole(f)) continue;
                const auto [u, v] = randomPointOf(direct.parameterization(f), f, random);
                direct.stencil(f, u, v, a);
                viaRefiner.stencil(f, u, v, b);
                ASSERT_TRUE(a.indices == b.indices && a.position == b.position && a.du == b.du && a.dv == b.dv)
                    << mesh << " face " << f;
                for (int c = 0; c < direct.numFVarChannels(); ++c) {
                    direct.fvarStencil(c, f, u, v, a);
                    viaRefiner.fvarStencil(c, f, u, v, b);
                    ASSERT_TRUE(a.indices == b.indices && a.position == b.position) << mesh << " UVs, face " << f;
                }
            }
        }
    }
    const int sizes[] = {4}, verts[] = {0, 1, 2, 7};
    TopologyDescriptor bad;
    bad.numVertices = 4;
    bad.numFaces = 1;
    bad.numVertsPerFace = sizes;
    bad.faceVertIndices = verts;
    EXPECT_THROW(LimitSurface(bad, Options{}), TopologyError);
}

TEST(LimitSurface, StencilsArePartitionsOfUnityWithDerivativesSummingToZero) {
    for (Scheme scheme : schemesTakingQuads()) {
        Options options;
        options.scheme = scheme;
        const RefinedMesh r = refineMesh("mixed/cylinder_capped_creased.obj", 0, options);
        const LimitSurface surface(*r.refiner);
        LimitPointStencil s;
        for (int f = 0; f < surface.numFaces(); f += 3) {
            const FaceParameterization p = surface.parameterization(f);
            double u, v;
            p.edgeCoord(0, 0.37, u, v);
            surface.stencil(f, u, v, s);
            double sum = 0, du = 0, dv = 0;
            for (int k = 0; k < s.size(); ++k) {
                sum += s.position[k];
                du += s.du[k];
                dv += s.dv[k];
            }
            EXPECT_NEAR(sum, 1, 1e-12) << toString(scheme) << " face " << f;
            EXPECT_NEAR(du, 0, 1e-9) << toString(scheme) << " face " << f;
            EXPECT_NEAR(dv, 0, 1e-9) << toString(scheme) << " face " << f;
        }
    }
}

}  // namespace
}  // namespace quadtri::test
