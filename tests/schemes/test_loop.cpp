// loop (OpenSubdiv's Loop) in closed form: β at valence 3, 4 and 6, the edge mask, and the
// refusal of any face that is not a triangle, named in the descriptor's and the file's
// numbering. Agreement with OpenSubdiv on its shapes: test_osd_agreement.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "far/topology/refine_topology.h"
#include <quadtri/far/refiner.h>
#include "far/tables/level_stencils.h"
#include "far/internal/stencil_table_double.h"
#include "far/schemes/scheme.h"
#include "tests/local_meshes.h"
#include "tests/schemes/rule_oracles.h"
#include "tests/test_support.h"
#include "tools/obj_io.h"

namespace {

using namespace quadtri;
using namespace quadtri::test;

Options loop() {
    Options o;
    o.scheme = Scheme::Loop;
    return o;
}

// Loop splits triangles in four: no face points; edges, then vertices.
int edgePointOf(const Topology&, int e) { return e; }
int vertexPointOf(const Topology& t, int v) { return t.numEdges() + v; }

// The vertex point of the centre of a ring of n triangles: (1 − nβ) c + β Σ p_i.
void expectCentreBeta(int n, double beta) {
    SCOPED_TRACE("valence " + std::to_string(n));
    const RingMesh ring = buildRingMesh(std::string(size_t(n), 'T'));
    Refiner refiner(ring.mesh.descriptor(), loop());
    refiner.refineUniform(1);
    const Topology& t = refiner.level(0);
    const std::vector<double> w = denseStencil(refiner.levelStencils(1), vertexPointOf(t, ring.center));
    EXPECT_NEAR(w[ring.center], 1.0 - n * beta, kWeightTol);
    for (int p : ring.p) EXPECT_NEAR(w[p], beta, kWeightTol);
    EXPECT_NEAR(w[ring.apex], 0.0, kWeightTol);
}

// β = (⅝ − (⅜ + ¼ cos 2π/n)²)/n: 3/16 at n = 3 (cos = −½), 31/256 at n = 4 (cos = 0), 1/16 at n = 6
// (cos = ½).
TEST(Loop, BetaInClosedForm) {
    expectCentreBeta(3, 3.0 / 16.0);
    expectCentreBeta(4, 31.0 / 256.0);
    expectCentreBeta(6, 1.0 / 16.0);
}

// ⅜ each end, ⅛ each opposite corner.
TEST(Loop, EdgeMask) {
    const RingMesh ring = buildRingMesh("TTTTT");
    Refiner refiner(ring.mesh.descriptor(), loop());
    refiner.refineUniform(2);
    const Topology& t = refiner.level(0);
    EXPECT_EQ(refiner.level(1).numFaces(), 4 * t.numFaces());
    for (int i = 0; i < 5; ++i) {
        const int e = edgeBetween(t, ring.center, ring.p[i]);
        Dense edge(ring.mesh.numVertices);
        edge.add(ring.center, 0.375);
        edge.add(ring.p[i], 0.375);
        edge.add(ring.p[(i + 1) % 5], 0.125);
        edge.add(ring.p[(i + 4) % 5], 0.125);
        EXPECT_LE(maxAbsDifference(denseStencil(refiner.levelStencils(1), edgePointOf(t, e)), edge.w), kWeightTol)
            << "edge c-p" << i;
    }
}

TEST(Loop, RefusesAQuadNamingIt) {
    LocalMesh m;
    m.numVertices = 5;
    m.addFace({0, 1, 2});
    m.addFace({0, 2, 3, 4});
    try {
        Refiner refiner(m.descriptor(), loop());
        FAIL() << "loop accepted a quad";
    } catch (const TopologyError& e) {
        EXPECT_EQ(e.component(), TopologyDiagnostic::Component::Face);
        EXPECT_EQ(e.index(), 1);
        EXPECT_EQ(std::string(e.what()), "face 1: has 4 corners; the loop scheme takes triangles only");
    }
    // The same file's face in its own numbering: line and 1-based face.
    std::istringstream obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 2 0\nf 1 2 3\n# a quad\nf 1 3 4 5\n");
    const io::ObjMesh mesh = io::parseObj(obj, "q.obj");
    try {
        Refiner refiner(mesh.descriptor(), mesh.applyTags(loop()));
        FAIL() << "loop accepted a quad";
    } catch (const TopologyError& e) {
        EXPECT_EQ(mesh.describe(e.diagnostic()), "q.obj:8: face 2: has 4 corners; the loop scheme takes triangles only");
    }
    // Every other scheme takes it.
    EXPECT_NO_THROW(Refiner(m.descriptor(), Options()));
}

TEST(Loop, RegularShortCutEqualsTheRules) {
    for (const char* name : {"osd/loop_icosahedron.obj", "osd/loop_cube.obj", "osd/loop_xord_interior.obj"})
        expectShortCutEqualsTheRules(name, loop());
}

}  // namespace
