// One-pass oracles for the refinement masks at boundaries (edge-only and edge-and-corner), for
// left-handed input and unused vertices, for semi-sharp crease edge points, and the partition of
// unity of every stencil. Interior rules: test_rules.cpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <quadtri/far/refiner.h>
#include "tests/local_meshes.h"
#include "tests/schemes/rule_oracles.h"
#include "tests/test_support.h"

namespace {

using namespace quadtri;
using namespace quadtri::test;

// ---- (e) Boundaries -----------------------------------------------------------------------

TEST(BoundaryRules, GridsUnderEdgeOnlyAndEdgeAndCorner) {
    for (auto b : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
        for (bool triangles : {false, true}) {
            const std::string name = std::string(triangles ? "triangle" : "quad") + " grid, " + toString(b);
            const LocalMesh grid = buildGrid(3, 3, triangles);
            const OracleCounts c = checkOracles(grid, stamLoop(b), 2, name);
            EXPECT_EQ(c.skipped, 0) << name;
        }
    }
}

// The same facts spelled out on the 3x3 quad grid (vertex (i, j) = 4 j + i).
TEST(BoundaryRules, ExplicitQuadGrid) {
    const LocalMesh grid = buildGrid(3, 3, false);
    for (auto b : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
        SCOPED_TRACE(toString(b));
        Refiner refiner(grid.descriptor(), stamLoop(b));
        refiner.refineUniform(1);
        const Topology& t = refiner.level(0);
        const StencilTable& table = refiner.levelStencils(1);
        // Boundary edge 1-2: midpoint.
        std::vector<double> w = denseStencil(table, childOfEdge(t, edgeBetween(t, 1, 2)));
        EXPECT_NEAR(w[1], 0.5, kWeightTol);
        EXPECT_NEAR(w[2], 0.5, kWeightTol);
        EXPECT_NEAR(w[5], 0.0, kWeightTol);
        // Smooth boundary vertex 1 (two faces): 3/4 v + 1/8 (0 + 2), nothing from the interior.
        w = denseStencil(table, childOfVertex(t, 1));
        EXPECT_NEAR(w[1], 0.75, kWeightTol);
        EXPECT_NEAR(w[0], 0.125, kWeightTol);
        EXPECT_NEAR(w[2], 0.125, kWeightTol);
        EXPECT_NEAR(w[5], 0.0, kWeightTol);
        // Corner vertex 0 (one face).
        w = denseStencil(table, childOfVertex(t, 0));
        if (b == BoundaryInterpolation::EdgeAndCorner) {
            EXPECT_NEAR(w[0], 1.0, kWeightTol);
            EXPECT_NEAR(w[1], 0.0, kWeightTol);
            EXPECT_NEAR(w[4], 0.0, kWeightTol);
        } else {
            EXPECT_NEAR(w[0], 0.75, kWeightTol);
            EXPECT_NEAR(w[1], 0.125, kWeightTol);
            EXPECT_NEAR(w[4], 0.125, kWeightTol);
        }
        EXPECT_NEAR(w[5], 0.0, kWeightTol);
        // Interior vertex 5 next to the boundary: regular Catmull-Clark 9/16, 3/32, 1/64.
        w = denseStencil(table, childOfVertex(t, 5));
        EXPECT_NEAR(w[5], 9.0 / 16, kWeightTol);
        for (int p : {1, 4, 6, 9})
            EXPECT_NEAR(w[p], 3.0 / 32, kWeightTol);
        for (int q : {0, 2, 8, 10})
            EXPECT_NEAR(w[q], 1.0 / 64, kWeightTol);
    }
}

// Triangle grid: corner (3,0) = vertex 3 has one triangle; corner (0,0) has two triangles
// (three edges) and follows the crease rule even under EdgeAndCorner.
TEST(BoundaryRules, ExplicitTriangleGridCorners) {
    const LocalMesh grid = buildGrid(3, 3, true);
    for (auto b : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
        SCOPED_TRACE(toString(b));
        Refiner refiner(grid.descriptor(), stamLoop(b));
        refiner.refineUniform(1);
        const Topology& t = refiner.level(0);
        const StencilTable& table = refiner.levelStencils(1);
        std::vector<double> w = denseStencil(table, childOfVertex(t, 3));
        if (b == BoundaryInterpolation::EdgeAndCorner) {
            EXPECT_NEAR(w[3], 1.0, kWeightTol);
        } else {
            EXPECT_NEAR(w[3], 0.75, kWeightTol);
            EXPECT_NEAR(w[2], 0.125, kWeightTol);
            EXPECT_NEAR(w[7], 0.125, kWeightTol);
        }
        w = denseStencil(table, childOfVertex(t, 0));
        EXPECT_NEAR(w[0], 0.75, kWeightTol);
        EXPECT_NEAR(w[1], 0.125, kWeightTol);
        EXPECT_NEAR(w[4], 0.125, kWeightTol);
        EXPECT_NEAR(w[5], 0.0, kWeightTol);
    }
}

// ---- Orientation ----------------------------------------------------------------------------

// Options::leftHanded only changes the orientation of faces, no weight: clockwise input with
// leftHanded = true gives the same level-1 stencils as counter-clockwise input (edges matched by
// their endpoints, since edge numbering may follow the traversal).
TEST(Rules, LeftHandedInputGivesTheSameWeights) {
    const std::vector<std::pair<std::string, LocalMesh>> meshes = {
        {"ring QQTT", buildRingMesh("QQTT").mesh}, {"ring QTT", buildRingMesh("QTT").mesh}, {"prism 5", buildPrism(5)},
        {"triangle grid", buildGrid(3, 2, true)},  {"quad grid", buildGrid(2, 3, false)},
    };
    for (const auto& [name, mesh] : meshes) {
        LocalMesh flipped = mesh;
        int offset = 0;
        for (int n : flipped.faceSizes) {
            std::reverse(flipped.faceVerts.begin() + offset, flipped.faceVerts.begin() + offset + n);
            offset += n;
        }
        for (auto b : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
            Options right = stamLoop(b), left = stamLoop(b);
            left.leftHanded = true;
            Refiner r(mesh.descriptor(), right), l(flipped.descriptor(), left);
            r.refineUniform(1);
            l.refineUniform(1);
            const Topology &tr = r.level(0), &tl = l.level(0);
            ASSERT_EQ(tr.numEdges(), tl.numEdges()) << name;
            ASSERT_EQ(r.levelStencils(1).numStencils(), l.levelStencils(1).numStencils()) << name;
            double worst = 0;
            for (int f = 0; f < mesh.numFaces(); ++f)
                if (mesh.faceSizes[f] != 3)
                    worst = std::max(worst, maxAbsDifference(denseStencil(r.levelStencils(1), childOfFace(tr, f)),
                                                             denseStencil(l.levelStencils(1), childOfFace(tl, f))));
            for (int e = 0; e < tr.numEdges(); ++e) {
                const int el = edgeBetween(tl, tr.edgeVerts[2 * e], tr.edgeVerts[2 * e + 1]);
                ASSERT_GE(el, 0) << name;
                worst = std::max(worst, maxAbsDifference(denseStencil(r.levelStencils(1), childOfEdge(tr, e)),
                                                         denseStencil(l.levelStencils(1), childOfEdge(tl, el))));
            }
            for (int v = 0; v < mesh.numVertices; ++v)
                worst = std::max(worst, maxAbsDifference(denseStencil(r.levelStencils(1), childOfVertex(tr, v)),
                                                         denseStencil(l.levelStencils(1), childOfVertex(tl, v))));
            EXPECT_LE(worst, 1e-7) << name << ", " << toString(b);
        }
    }
}

// A vertex no face uses is accepted and stays where it is; the rest of the mesh is unaffected.
TEST(Rules, UnusedVertexStaysPut) {
    LocalMesh mesh = buildPrism(4);
    const int unused = mesh.numVertices++;
    const OracleCounts c = checkOracles(mesh, stamLoop(), 1, "cube + unused vertex");
    EXPECT_EQ(c.skipped, 0);
    Refiner refiner(mesh.descriptor(), stamLoop());
    refiner.refineUniform(1);
    const std::vector<double> w = denseStencil(refiner.levelStencils(1), childOfVertex(refiner.level(0), unused));
    Dense expected(mesh.numVertices);
    expected.add(unused, 1.0);
    EXPECT_LE(maxAbsDifference(w, expected.w), kWeightTol) << describe(w);
}

// ---- Semi-sharp edges (docs/schemes/creases.md, §2) -------------------------------------------

// 4 x 4 quad grid; the middle row's edges (1,2)-(2,2), (2,2)-(3,2), (3,2)-(4,2) get sharpness
// side, s, side. The edge point of (2,2)-(3,2) is the crease midpoint while both of its child
// halves stay sharp, else s * midpoint + (1 - s) * smooth (s not clamped, as OpenSubdiv does).
struct SemiSharpCase {
    CreaseMethod method;
    float s, side;
    bool childSharp;  // derived by hand below
};

TEST(CreaseRules, SemiSharpEdgePoint) {
    // Child sharpness of the middle edge at (2,2) (and, by symmetry, at (3,2)):
    //   Uniform: s - 1.  Chaikin: the other semi-sharp edge there has `side`, so
    //   max(0, 3/4 s + 1/4 side - 1).
    const SemiSharpCase cases[] = {
        {CreaseMethod::Uniform, 0.4f, 0.0f, false},  // 0.4 - 1 < 0: blend 0.4 / 0.6
        {CreaseMethod::Uniform, 1.2f, 0.1f, true},   // 0.2 > 0: midpoint
        {CreaseMethod::Chaikin, 0.8f, 3.0f, true},   // 0.6 + 0.75 - 1 = 0.35 > 0: midpoint
        {CreaseMethod::Chaikin, 1.2f, 0.1f, false},  // 0.9 + 0.025 - 1 < 0: blend 1.2 / -0.2
        {CreaseMethod::Chaikin, 1.05f, 0.0f, true},  // no other semi-sharp edge: uniform, 0.05 > 0
    };
    for (const SemiSharpCase& c : cases) {
        SCOPED_TRACE(std::string(toString(c.method)) + " s = " + std::to_string(c.s) + ", side " +
                     std::to_string(c.side));
        LocalMesh grid = buildGrid(4, 4, false);
        auto V = [](int i, int j) { return 5 * j + i; };
        grid.creasePairs = {V(1, 2), V(2, 2), V(2, 2), V(3, 2), V(3, 2), V(4, 2)};
        grid.creaseWeights = {c.side, c.s, c.side};
        Options o = stamLoop();
        o.creaseMethod = c.method;
        Refiner refiner(grid.descriptor(), o);
        refiner.refineUniform(1);
        const Topology& t = refiner.level(0);
        const int a = V(2, 2), b = V(3, 2);
        const int e = edgeBetween(t, a, b);
        ASSERT_GE(e, 0);
        Dense expected(grid.numVertices);
        const double w = c.childSharp ? 1.0 : double(c.s);
        expected.add(a, 0.5 * w);
        expected.add(b, 0.5 * w);
        if (!c.childSharp) {  // (1 - s) * Catmull-Clark edge point
            const double k = 1.0 - double(c.s);
            expected.add(a, 0.25 * k);
            expected.add(b, 0.25 * k);
            for (int v : {V(2, 1), V(3, 1), V(3, 2), V(2, 2), V(2, 2), V(3, 2), V(3, 3), V(2, 3)})
                expected.add(v, 0.25 * k / 4);
        }
        const std::vector<double> actual = denseStencil(refiner.levelStencils(1), childOfEdge(t, e));
        EXPECT_LE(maxAbsDifference(actual, expected.w), kWeightTol)
            << "expected:" << describe(expected.w) << "\nactual:  " << describe(actual);
    }
}

// ---- (f) Partition of unity ---------------------------------------------------------------

TEST(Rules, PartitionOfUnity) {
    std::vector<std::pair<std::string, LocalMesh>> meshes;
    for (int n = 3; n <= 8; ++n) {
        meshes.push_back({"quad ring " + std::to_string(n), buildRingMesh(std::string(size_t(n), 'Q')).mesh});
        meshes.push_back({"bipyramid " + std::to_string(n), buildRingMesh(std::string(size_t(n), 'T')).mesh});
        meshes.push_back({"prism " + std::to_string(n), buildPrism(n)});
    }
    for (const std::string ring : {"QT", "QTT", "QQT", "QQTT", "QTQT", "QQQT", "QTQTT"})
        meshes.push_back({ringName(ring), buildRingMesh(ring).mesh});
    meshes.push_back({"quad grid", buildGrid(3, 3, false)});
    meshes.push_back({"triangle grid", buildGrid(3, 3, true)});
    for (const auto& [name, mesh] : meshes) {
        for (Scheme s : {Scheme::StamLoop, Scheme::Bilinear}) {
            for (auto b : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
                Options o;
                o.scheme = s;
                o.boundary = b;
                Refiner refiner(mesh.descriptor(), o);
                refiner.refineUniform(3);
                for (int L = 1; L <= 3; ++L) {
                    const StencilTable& table = refiner.levelStencils(L);
                    const StencilTable factorized = refiner.factorizedStencils(L);
                    ASSERT_EQ(table.numStencils(), refiner.faces(L).numVertices()) << name;
                    ASSERT_EQ(factorized.numStencils(), refiner.faces(L).numVertices()) << name;
                    EXPECT_EQ(factorized.numSourceVertices, mesh.numVertices) << name;
                    double worst = 0, worstFactorized = 0;
                    for (int i = 0; i < table.numStencils(); ++i) {
                        worst = std::max(worst, std::fabs(stencilWeightSum(table, i) - 1.0));
                        worstFactorized = std::max(worstFactorized, std::fabs(stencilWeightSum(factorized, i) - 1.0));
                    }
                    EXPECT_LE(worst, 1e-6) << name << " " << toString(s) << " level " << L;
                    EXPECT_LE(worstFactorized, 1e-6) << name << " " << toString(s) << " factorized level " << L;
                }
            }
        }
    }
}

}  // namespace
