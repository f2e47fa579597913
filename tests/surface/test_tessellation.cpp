// Tessellation (far/tessellation.h): counts in closed form, watertight and consistently oriented
// index buffers at uniform and per-edge rates, and at rate 2^L the points of uniform level L.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <utility>

#include <quadtri/far/tessellation.h>
#include "tests/limit/limit_support.h"
#include "tests/sanitized.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

// The meshes every scheme that takes them is tessellated on here.
std::vector<std::string> tessellatedMeshes() {
    return {"mixed/cylinder_capped.obj", "mixed/mixed_torus.obj", "mixed/split_plane.obj", "mixed/book_nonmanifold.obj",
            "osd/catmark_nonquads.obj",  "osd/catmark_hole_test1.obj", "osd/catmark_fan.obj", "osd/loop_cube.obj",
            "osd/loop_triangle_edgecorner.obj"};
}

struct Case {
    std::string mesh;
    Scheme scheme;
};

std::vector<Case> tessellatedCases() {
    std::vector<Case> cases;
    for (const std::string& mesh : tessellatedMeshes())
        for (Scheme scheme : allSchemes()) {
            if (!rulesOf(scheme).acceptsNonTriangles() && mesh.find("loop_") == std::string::npos) continue;
            cases.push_back({mesh, scheme});
        }
    return cases;
}

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// Every triangle edge: how many triangles use it either way, and whether one way is used twice.
// An edge inside a face is used twice, once each way; a segment of base edge e by e's faces.
void expectWatertight(const Tessellation& tess, const Topology& t, const std::string& what) {
    std::map<std::pair<int, int>, int> directed;
    const std::vector<int>& tri = tess.triangles();
    for (int k = 0; k < tess.numTriangles(); ++k) {
        const int* c = &tri[std::size_t(3 * k)];
        ASSERT_TRUE(c[0] != c[1] && c[1] != c[2] && c[2] != c[0]) << what << ": triangle " << k << " repeats a point";
        for (int i = 0; i < 3; ++i) ++directed[{c[i], c[(i + 1) % 3]}];
    }
    std::map<std::pair<int, int>, int> onBaseEdge;  // segment -> faces of its base edge (holes left out)
    for (int e = 0; e < t.numEdges(); ++e) {
        int faces = 0;
        for (int f : t.facesOfEdge(e)) faces += t.faceHole[std::size_t(f)] ? 0 : 1;
        if (faces == 0) continue;
        std::vector<int> chain{tess.vertexPoint(t.edgeVerts[std::size_t(2 * e)])};
        for (int j = 1; j < tess.edgeRate(e); ++j) chain.push_back(tess.firstEdgePoint(e) + j - 1);
        chain.push_back(tess.vertexPoint(t.edgeVerts[std::size_t(2 * e + 1)]));
        for (std::size_t j = 0; j + 1 < chain.size(); ++j)
            onBaseEdge[{std::min(chain[j], chain[j + 1]), std::max(chain[j], chain[j + 1])}] += faces;
    }
    std::map<std::pair<int, int>, int> uses;
    for (const auto& [edge, count] : directed) uses[{std::min(edge.first, edge.second), std::max(edge.first, edge.second)}] += count;
    int wrong = 0;
    for (const auto& [edge, count] : uses) {
        const auto base = onBaseEdge.find(edge);
        const int expected = base == onBaseEdge.end() ? 2 : base->second;
        if (count != expected && ++wrong <= 3)
            ADD_FAILURE() << what << ": segment " << edge.first << "-" << edge.second << " used by " << count
                          << " triangles, expected " << expected;
        if (base == onBaseEdge.end() && directed[{edge.first, edge.second}] != 1 && ++wrong <= 3)
            ADD_FAILURE() << what << ": inner segment " << edge.first << "-" << edge.second
                          << " is not used once each way (the triangles around it disagree in orientation)";
    }
    for (const auto& [segment, faces] : onBaseEdge)
        if (!uses.count(segment) && ++wrong <= 3)
            ADD_FAILURE() << what << ": base edge segment " << segment.first << "-" << segment.second << " is in no triangle";
    EXPECT_EQ(wrong, 0) << what;
    std::vector<bool> used(std::size_t(tess.numPoints()), false);
    for (int p : tri) used[std::size_t(p)] = true;
    EXPECT_EQ(std::count(used.begin(), used.end(), false), 0) << what << ": points in no triangle";
}

// The case's mesh refined to level 0 under its scheme, and its limit surface.
struct CaseSurface {
    RefinedMesh refined;
    LimitSurface surface;
    explicit CaseSurface(const Case& c) : refined(refineWith(c)), surface(*refined.refiner) {}
    static RefinedMesh refineWith(const Case& c) {
        Options options;
        options.scheme = c.scheme;
        return refineMesh(c.mesh, 0, options);
    }
};

class Tessellated : public testing::TestWithParam<Case> {};

TEST_P(Tessellated, IsWatertightAtUniformAndPerEdgeRates) {
    const std::string& mesh = GetParam().mesh;
    const CaseSurface c(GetParam());
    const LimitSurface& surface = c.surface;
    const Topology& t = surface.topology();
    for (int rate : {1, 2, 3, 5}) {
        const Tessellation tess(surface, rate);
        expectWatertight(tess, t, mesh + " rate " + std::to_string(rate));
        for (int e = 0; e < t.numEdges(); ++e) EXPECT_GE(tess.edgeRate(e), rate);
    }
    std::mt19937 random(11);
    for (int trial = 0; trial < 3; ++trial) {
        std::vector<int> rates(std::size_t(t.numEdges()));
        for (int& rate : rates) rate = 1 + int(random() % 6);
        const Tessellation tess(surface, rates);
        expectWatertight(tess, t, mesh + " random rates " + std::to_string(trial));
        for (int e = 0; e < t.numEdges(); ++e) {
            const int asked = rates[std::size_t(e)], got = tess.edgeRate(e);
            EXPECT_TRUE(got == asked || (got == asked + 1 && got % 2 == 0)) << mesh << " edge " << e;
        }
    }
}

// Each triangle's normal agrees with the limit normal at its corners: no triangle is folded over.
TEST_P(Tessellated, FacesTheWayTheSurfaceDoes) {
    const auto& [mesh, scheme] = GetParam();
    const CaseSurface c(GetParam());
    const LimitSurface& surface = c.surface;
    const RefinedMesh& r = c.refined;
    std::vector<int> rates(std::size_t(surface.topology().numEdges()));
    std::mt19937 random(5);
    for (int& rate : rates) rate = kSanitized ? 2 + int(random() % 2) : 3 + int(random() % 5);
    const Tessellation tess(surface, rates);
    const LimitData limit =
        applyLimit(surface.stencilTable(tess.numPoints(), tess.faces(), tess.u(), tess.v()), r.positions[0]);
    // A point on a non-manifold edge is shared by pages that face different ways; it carries the
    // normal of one of them, so the triangles touching it are left out here.
    const Topology& t = surface.topology();
    std::vector<bool> manyPages(std::size_t(tess.numPoints()), false);
    for (int e = 0; e < t.numEdges(); ++e) {
        if (t.edgeFaceCount(e) <= 2) continue;
        for (int end = 0; end < 2; ++end) manyPages[std::size_t(tess.vertexPoint(t.edgeVerts[std::size_t(2 * e + end)]))] = true;
        for (int j = 1; j < tess.edgeRate(e); ++j) manyPages[std::size_t(tess.firstEdgePoint(e) + j - 1)] = true;
    }
    int folded = 0;
    for (int k = 0; k < tess.numTriangles(); ++k) {
        const int* c = &tess.triangles()[std::size_t(3 * k)];
        if (manyPages[std::size_t(c[0])] || manyPages[std::size_t(c[1])] || manyPages[std::size_t(c[2])]) continue;
        const Vec3 n = cross(minus(limit.position[c[1]], limit.position[c[0]]), minus(limit.position[c[2]], limit.position[c[0]]));
        double facing = 0;
        for (int i = 0; i < 3; ++i) {
            const Vec3 normal = cross(limit.du[c[i]], limit.dv[c[i]]);
            if (norm(normal) > 0) facing += dot(n, normal) / norm(normal);
        }
        if (facing <= 0) ++folded;
    }
    // Corners where the surface itself folds (a cone's apex, a crease's sharp turn) may hold one
    // odd triangle each; a wrong layout turns whole strips.
    EXPECT_LE(folded, tess.numTriangles() / 200) << mesh << " " << toString(scheme) << ": " << folded << " of "
                                                 << tess.numTriangles() << " triangles face away";
}

INSTANTIATE_TEST_SUITE_P(Meshes, Tessellated, testing::ValuesIn(tessellatedCases()), [](const auto& info) {
    return testNameOf(info.param.mesh + "_" + toString(info.param.scheme));
});

// At rate 2^L every edge is halved L times, as uniform refinement halves it: the points are level
// L's vertices, each on its limit position, and every face makes twice its level-L quads'
// triangles (its triangles' as many).
TEST(Tessellation, AtRateTwoToTheLIsUniformLevelL) {
    struct Mesh {
        const char* name;
        Scheme scheme;
    };
    for (const Mesh& m : {Mesh{"mixed/cylinder_capped.obj", Scheme::SchaeferWarren}, Mesh{"mixed/mixed_torus.obj", Scheme::StamLoop},
                          Mesh{"osd/catmark_nonquads.obj", Scheme::CatmullClark}, Mesh{"osd/loop_cube.obj", Scheme::Loop},
                          Mesh{"mixed/cylinder_capped.obj", Scheme::CatmullClark}}) {
        for (int L = 1; L <= 2; ++L) {
            Options options;
            options.scheme = m.scheme;
            const RefinedMesh r = refineMesh(m.name, L, options);
            r.refiner->refineUniform(L, TopologyDetail::Full);
            const Topology& level = r.refiner->level(L);
            const LimitData reference = applyLimit(r.refiner->limitStencils(L), r.positions[L]);
            const LimitSurface surface(*r.refiner);
            const Tessellation tess(surface, 1 << L);
            const std::string what = std::string(m.name) + " " + toString(m.scheme) + " level " + std::to_string(L);
            ASSERT_EQ(tess.numPoints(), level.numVertices) << what;
            int triangles = 0;
            for (int f = 0; f < level.numFaces(); ++f) triangles += level.faceHole[std::size_t(f)] ? 0 : level.faceSize(f) - 2;
            EXPECT_EQ(tess.numTriangles(), triangles) << what;
            const LimitData limit =
                applyLimit(surface.stencilTable(tess.numPoints(), tess.faces(), tess.u(), tess.v()), r.positions[0]);
            const double diagonal = boundingBoxDiagonal(r.positions[0]);
            std::vector<bool> taken(std::size_t(level.numVertices), false);
            double worst = 0;
            for (int i = 0; i < tess.numPoints(); ++i) {
                int nearest = -1;
                double best = 1e300;
                for (int v = 0; v < level.numVertices; ++v) {
                    const double d = distance(limit.position[i], reference.position[v]);
                    if (d < best) {
                        best = d;
                        nearest = v;
                    }
                }
                EXPECT_FALSE(taken[std::size_t(nearest)]) << what << ": two points on vertex " << nearest;
                taken[std::size_t(nearest)] = true;
                worst = std::max(worst, best / diagonal);
            }
            EXPECT_LT(worst, 2e-6) << what;
        }
    }
}

// UVs: at rate 2^L each (point, value) is a corner of uniform level L as (limit position, limit
// UV), one per value of the level: a point on a UV seam carries both sides' UVs.
TEST(Tessellation, UVsAtRateTwoToTheLAreUniformLevelLsLimitCorners) {
    for (const char* mesh : {"uv/mixed_torus_uv.obj", "uv/split_plane_uv.obj", "osd/catmark_cube.obj"}) {
        for (Scheme scheme : {Scheme::SchaeferWarren, Scheme::CatmullClark}) {
            for (int L = 1; L <= (kSanitized ? 1 : 2); ++L) {
                Options options;
                options.scheme = scheme;
                const io::ObjMesh obj = io::readObj(meshPath(mesh));
                FVarChannel channel;
                Refiner refiner(obj.descriptor(channel), obj.applyTags(options));
                refiner.refineUniform(L, TopologyDetail::Full);
                const LimitSurface surface(refiner);
                const Tessellation tess(surface, 1 << L);
                const Tessellation::FVarPoints values = tess.fvarPoints(surface, 0);
                const std::string what = std::string(mesh) + " " + toString(scheme) + " level " + std::to_string(L);
                ASSERT_EQ(values.numValues(), refiner.numFVarValues(0, L)) << what;
                ASSERT_EQ(values.cornerValues.size(), tess.triangles().size()) << what;

                auto uvPoints = [](const std::vector<float>& uv) {
                    std::vector<float> out;
                    for (std::size_t i = 0; i < uv.size(); i += 2) out.insert(out.end(), {uv[i], uv[i + 1], 0.0f});
                    return out;
                };
                const LimitData position =
                    applyLimit(surface.stencilTable(tess.numPoints(), tess.faces(), tess.u(), tess.v()), obj.positions);
                const LimitData uv = applyLimit(surface.fvarStencilTable(0, values.numValues(), values.faces.data(),
                                                                         values.u.data(), values.v.data()),
                                                uvPoints(obj.uvs));
                using Corner = std::array<double, 5>;
                std::vector<Corner> ours(std::size_t(values.numValues()));
                for (std::size_t c = 0; c < values.cornerValues.size(); ++c) {
                    const Vec3 &p = position.position[std::size_t(tess.triangles()[c])],
                               &t = uv.position[std::size_t(values.cornerValues[c])];
                    ours[std::size_t(values.cornerValues[c])] = {p[0], p[1], p[2], t[0], t[1]};
                }
                const std::vector<std::vector<float>> levels = evaluateLevels(refiner, obj.positions, 3);
                const LimitData levelPosition = applyLimit(refiner.limitStencils(L), levels[std::size_t(L)]);
                const LimitData levelUV = applyLimit(refiner.fvarFactorizedLimitStencils(0, L), uvPoints(obj.uvs));
                std::vector<Corner> reference;
                const LevelFaces faces = refiner.faces(L);
                const int* verts = faces.vertices();
                const IndexSpan corners = refiner.fvarValues(0, L);
                for (int k = 0; k < corners.size(); ++k) {
                    const Vec3 &p = levelPosition.position[std::size_t(verts[k])],
                               &t = levelUV.position[std::size_t(corners[k])];
                    reference.push_back({p[0], p[1], p[2], t[0], t[1]});
                }
                double worst = 0;
                for (const Corner& a : ours) {
                    double best = 1e300;
                    for (const Corner& b : reference) {
                        double d = 0;
                        for (int i = 0; i < 5; ++i) d = std::max(d, std::abs(a[std::size_t(i)] - b[std::size_t(i)]));
                        best = std::min(best, d);
                    }
                    worst = std::max(worst, best);
                }
                EXPECT_LT(worst, 1e-5) << what;
            }
        }
    }
}

TEST(Tessellation, CountsPointsAndTrianglesInClosedForm) {
    Options options;
    options.scheme = Scheme::CatmullClark;
    const RefinedMesh quads = refineMesh("osd/catmark_cube.obj", 0, options);
    options.scheme = Scheme::Loop;
    const RefinedMesh triangles = refineMesh("osd/loop_cube.obj", 0, options);
    for (int n : {1, 2, 3, 7}) {
        const LimitSurface q(*quads.refiner), t(*triangles.refiner);
        const Tessellation a(q, n), b(t, n);
        const Topology &tq = q.topology(), &tt = t.topology();
        EXPECT_EQ(a.numPoints(), tq.numVertices + tq.numEdges() * (n - 1) + tq.numFaces() * (n - 1) * (n - 1));
        EXPECT_EQ(a.numTriangles(), 2 * tq.numFaces() * n * n);
        EXPECT_EQ(b.numPoints(), tt.numVertices + tt.numEdges() * (n - 1) + tt.numFaces() * (n - 1) * (n - 2) / 2);
        EXPECT_EQ(b.numTriangles(), tt.numFaces() * n * n);
    }
}

TEST(Tessellation, RefusesRatesItCannotMake) {
    const RefinedMesh r = refineMesh("mixed/cylinder_capped.obj", 0);
    const LimitSurface surface(*r.refiner);
    EXPECT_THROW(Tessellation(surface, 0), SurfaceError);
    EXPECT_THROW(Tessellation(surface, Tessellation::kMaxRate + 1), SurfaceError);
    EXPECT_THROW(Tessellation(surface, std::vector<int>(3, 2)), SurfaceError);
    std::vector<int> rates(std::size_t(surface.topology().numEdges()), 2);
    rates[5] = -3;
    try {
        Tessellation tess(surface, rates);
        FAIL() << "a negative rate was taken";
    } catch (const SurfaceError& e) {
        EXPECT_NE(std::string(e.what()).find("edge 5's rate -3"), std::string::npos) << e.what();
    }
    const RefinedMesh limb = refineMesh("../../data/mixed_limb.obj", 0);
    const LimitSurface big(*limb.refiner);
    EXPECT_THROW(Tessellation(big, Tessellation::kMaxRate), SurfaceError);  // refused before it allocates
}

}  // namespace
}  // namespace quadtri::test
