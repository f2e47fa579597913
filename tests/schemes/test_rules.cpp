// One-pass oracles for the interior refinement masks: every refined vertex of small hand-built
// meshes is compared, as a dense weight vector over the parent level, with the classical
// closed-form rule (Catmull-Clark, Loop, n-gons, the Stam-Loop seam edge, bilinear). Boundaries,
// orientation, creases and partition of unity: test_boundary_rules.cpp.

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include <tbb/task_arena.h>

#include "far/topology/refine_topology.h"
#include <quadtri/far/refiner.h>
#include "far/tables/level_stencils.h"
#include "tests/local_meshes.h"
#include "tests/schemes/rule_oracles.h"
#include "tests/test_support.h"
#include "far/internal/stencil_table_double.h"

namespace {

using namespace quadtri;
using namespace quadtri::test;

// ---- (a) Catmull-Clark ------------------------------------------------------------------

// n = 2 (two quads glued along two edges) is included: the same closed form holds.
TEST(CatmullClarkRules, QuadRingCentreEdgesAndFaces) {
    for (int n = 2; n <= 8; ++n) {
        SCOPED_TRACE("valence " + std::to_string(n));
        const RingMesh ring = buildRingMesh(std::string(size_t(n), 'Q'));
        Refiner refiner(ring.mesh.descriptor(), stamLoop());
        refiner.refineUniform(1);
        const Topology& t = refiner.level(0);
        const StencilTable& table = refiner.levelStencils(1);
        const int V = ring.mesh.numVertices;
        auto F = [&](Dense& d, int i, double x) {  // face point of quad i, expanded
            for (int v : {ring.center, ring.p[i], ring.q[i], ring.p[(i + 1) % n]})
                d.add(v, x / 4);
        };
        // Vertex point: (n-2)/n c + 1/n^2 sum p_i + 1/n^2 sum F_i.
        Dense vertex(V);
        vertex.add(ring.center, double(n - 2) / n);
        for (int i = 0; i < n; ++i) {
            vertex.add(ring.p[i], 1.0 / (n * n));
            F(vertex, i, 1.0 / (n * n));
        }
        EXPECT_LE(maxAbsDifference(denseStencil(table, childOfVertex(t, ring.center)), vertex.w), kWeightTol)
            << describe(denseStencil(table, childOfVertex(t, ring.center)));
        // In closed form: c gets (n-2)/n + 1/(4n), each p 3/(2n^2), each q 1/(4n^2).
        const std::vector<double> centre = denseStencil(table, childOfVertex(t, ring.center));
        EXPECT_NEAR(centre[ring.center], double(n - 2) / n + 1.0 / (4 * n), kWeightTol);
        EXPECT_NEAR(centre[ring.p[0]], 1.5 / (n * n), kWeightTol);
        EXPECT_NEAR(centre[ring.q[0]], 0.25 / (n * n), kWeightTol);
        EXPECT_NEAR(centre[ring.apex], 0.0, kWeightTol);
        for (int i = 0; i < n; ++i) {
            // Edge point of c-p_i: 1/4 c + 1/4 p_i + 1/4 F_{i-1} + 1/4 F_i.
            Dense edge(V);
            edge.add(ring.center, 0.25);
            edge.add(ring.p[i], 0.25);
            F(edge, i, 0.25);
            F(edge, (i + n - 1) % n, 0.25);
            const int e = edgeBetween(t, ring.center, ring.p[i]);
            ASSERT_GE(e, 0);
            EXPECT_LE(maxAbsDifference(denseStencil(table, childOfEdge(t, e)), edge.w), kWeightTol)
                << "edge c-p" << i << ":" << describe(denseStencil(table, childOfEdge(t, e)));
            // Face point of quad i: its centroid.
            Dense face(V);
            F(face, i, 1.0);
            EXPECT_LE(maxAbsDifference(denseStencil(table, childOfFace(t, i)), face.w), kWeightTol) << "face " << i;
        }
        // Every other vertex, edge and face with an oracle, two levels deep.
        const OracleCounts c = checkOracles(ring.mesh, stamLoop(), 2, ringName(ring.ring));
        EXPECT_GT(c.vertices, 0);
    }
}

// All-quad closed meshes with vertices of valence 3, 4 and n: a prism over an n-gon, split once
// topologically (the n-gon centres get valence n).
TEST(CatmullClarkRules, QuadrangulatedPrisms) {
    for (int n = 3; n <= 8; ++n) {
        const LocalMesh mesh = quadrangulate(buildPrism(n));
        const OracleCounts c = checkOracles(mesh, stamLoop(), 2, "quadrangulated prism " + std::to_string(n));
        EXPECT_EQ(c.skipped, 0);  // all-quad: every vertex has an oracle
        EXPECT_GE(c.vertices, mesh.numVertices);
    }
}

// ---- (b) Loop -----------------------------------------------------------------------------

// The all-triangle ring mesh is a bipyramid: apexes of valence n, equator vertices of valence 4.
TEST(LoopRules, Bipyramids) {
    for (int n = 3; n <= 8; ++n) {
        SCOPED_TRACE("valence " + std::to_string(n));
        const RingMesh ring = buildRingMesh(std::string(size_t(n), 'T'));
        Refiner refiner(ring.mesh.descriptor(), stamLoop());
        refiner.refineUniform(1);
        const Topology& t = refiner.level(0);
        const StencilTable& table = refiner.levelStencils(1);
        EXPECT_EQ(countNonTriangleFaces(t), 0);
        const int V = ring.mesh.numVertices;
        const double beta = loopBeta(n);
        Dense vertex(V);  // (1 - n beta) c + beta sum p_i
        vertex.add(ring.center, 1.0 - n * beta);
        for (int i = 0; i < n; ++i)
            vertex.add(ring.p[i], beta);
        EXPECT_LE(maxAbsDifference(denseStencil(table, childOfVertex(t, ring.center)), vertex.w), kWeightTol)
            << describe(denseStencil(table, childOfVertex(t, ring.center)));
        for (int i = 0; i < n; ++i) {  // 3/8 c + 3/8 p_i + 1/8 p_{i-1} + 1/8 p_{i+1}
            Dense edge(V);
            edge.add(ring.center, 3.0 / 8);
            edge.add(ring.p[i], 3.0 / 8);
            edge.add(ring.p[(i + 1) % n], 1.0 / 8);
            edge.add(ring.p[(i + n - 1) % n], 1.0 / 8);
            const int e = edgeBetween(t, ring.center, ring.p[i]);
            ASSERT_GE(e, 0);
            EXPECT_LE(maxAbsDifference(denseStencil(table, childOfEdge(t, e)), edge.w), kWeightTol)
                << "edge c-p" << i << ":" << describe(denseStencil(table, childOfEdge(t, e)));
        }
        const OracleCounts c = checkOracles(ring.mesh, stamLoop(), 2, ringName(ring.ring));
        EXPECT_EQ(c.skipped, 0);
        EXPECT_EQ(c.faces, 0);
    }
}

// Loop's beta for n = 6 is the regular 1/16; n = 3 gives 3/16 (not Warren's 3/(8n) = 1/8).
TEST(LoopRules, BetaClosedFormSanity) {
    EXPECT_NEAR(loopBeta(6), 1.0 / 16, 1e-15);
    EXPECT_NEAR(loopBeta(3), 3.0 / 16, 1e-15);
}

// ---- (c) n-gons next to quads and the quad/triangle seam edge -------------------------------

// Prism over an n-gon: every vertex has the n-gon and two quads, every cap edge is an
// n-gon/quad edge. Catmull-Clark's rules with true centroids must hold exactly at level 1.
TEST(NgonRules, PrismsMatchCatmullClark) {
    for (int n = 4; n <= 8; ++n) {
        const LocalMesh mesh = buildPrism(n);
        Refiner refiner(mesh.descriptor(), stamLoop());
        refiner.refineUniform(1);
        const Topology& t = refiner.level(0);
        const StencilTable& table = refiner.levelStencils(1);
        // Explicitly: the edge between bottom vertices 0 and 1 (n-gon face 0, side quad 2).
        Dense edge(mesh.numVertices);
        edge.add(0, 0.25);
        edge.add(1, 0.25);
        for (int i = 0; i < n; ++i)
            edge.add(i, 0.25 / n);  // bottom n-gon centroid
        for (int v : {0, 1, n + 1, n})
            edge.add(v, 0.25 / 4);  // side quad centroid
        const int e = edgeBetween(t, 0, 1);
        ASSERT_GE(e, 0);
        EXPECT_LE(maxAbsDifference(denseStencil(table, childOfEdge(t, e)), edge.w), kWeightTol)
            << "n = " << n << ":" << describe(denseStencil(table, childOfEdge(t, e)));
        // The n-gon's face point: its centroid.
        Dense face(mesh.numVertices);
        for (int i = 0; i < n; ++i)
            face.add(i, 1.0 / n);
        EXPECT_LE(maxAbsDifference(denseStencil(table, childOfFace(t, 0)), face.w), kWeightTol) << "n = " << n;
        // Vertex 0, valence 3: 1/3 v + 1/9 (sum of 3 neighbours) + 1/9 (n-gon + 2 quad centroids).
        Dense vertex(mesh.numVertices);
        vertex.add(0, 1.0 / 3);
        for (int w : {1, n - 1, n})
            vertex.add(w, 1.0 / 9);
        for (int i = 0; i < n; ++i)
            vertex.add(i, 1.0 / (9.0 * n));
        for (int v : {0, 1, n + 1, n})
            vertex.add(v, 1.0 / 36);  // side quad 0
        for (int v : {n - 1, 0, n, 2 * n - 1})
            vertex.add(v, 1.0 / 36);  // side quad n-1
        EXPECT_LE(maxAbsDifference(denseStencil(table, childOfVertex(t, 0)), vertex.w), kWeightTol)
            << "n = " << n << ":" << describe(denseStencil(table, childOfVertex(t, 0)));

        const OracleCounts c = checkOracles(mesh, stamLoop(), 2, "prism " + std::to_string(n));
        EXPECT_EQ(c.skipped, 0);
    }
}

// Mixed rings: every edge at the centre is quad/quad, triangle/triangle or a quad/triangle seam
// edge (Stam-Loop: 3/8, 3/8 at the ends, 1/8 at the triangle's opposite vertex, 1/16 at the
// quad's two far corners); every face point is a centroid.
TEST(SeamRules, MixedRings) {
    for (const std::string ring : {"QT", "QTT", "QQT", "QQTT", "QTQT", "QQQT", "QTQTT", "QTTTTT", "QQQQQT"}) {
        const RingMesh r = buildRingMesh(ring);
        Refiner refiner(r.mesh.descriptor(), stamLoop());
        refiner.refineUniform(1);
        const Topology& t = refiner.level(0);
        const StencilTable& table = refiner.levelStencils(1);
        const int n = int(ring.size());
        int seams = 0;
        for (int i = 0; i < n; ++i) {
            const int before = (i + n - 1) % n;  // face between p_{i-1} and p_i
            if ((ring[i] == 'Q') == (ring[before] == 'Q'))
                continue;
            const int quad = ring[i] == 'Q' ? i : before;
            const int tri = ring[i] == 'Q' ? before : i;
            const int triOpposite = tri == i ? r.p[(i + 1) % n] : r.p[(i + n - 1) % n];
            const int quadNeighbour = quad == i ? r.p[(i + 1) % n] : r.p[(i + n - 1) % n];
            Dense edge(r.mesh.numVertices);
            edge.add(r.center, 3.0 / 8);
            edge.add(r.p[i], 3.0 / 8);
            edge.add(triOpposite, 1.0 / 8);
            edge.add(quadNeighbour, 1.0 / 16);
            edge.add(r.q[quad], 1.0 / 16);
            const int e = edgeBetween(t, r.center, r.p[i]);
            ASSERT_GE(e, 0);
            EXPECT_LE(maxAbsDifference(denseStencil(table, childOfEdge(t, e)), edge.w), kWeightTol)
                << ring << " seam edge c-p" << i << ":" << describe(denseStencil(table, childOfEdge(t, e)));
            ++seams;
        }
        EXPECT_GT(seams, 0) << ring;
        const OracleCounts c = checkOracles(r.mesh, stamLoop(), 2, ringName(ring));
        EXPECT_GT(c.edges, 0);
    }
}

// ---- (d) Bilinear -------------------------------------------------------------------------

TEST(BilinearRules, CornersMidpointsCentroids) {
    Options o;
    o.scheme = Scheme::Bilinear;
    const std::vector<std::pair<std::string, LocalMesh>> meshes = {
        {"prism 5", buildPrism(5)},
        {"prism 3", buildPrism(3)},
        {"ring QQTT", buildRingMesh("QQTT").mesh},
        {"quad grid", buildGrid(3, 2, false)},
        {"triangle grid", buildGrid(2, 3, true)},
        {"quadrangulated prism 6", quadrangulate(buildPrism(6))},
    };
    for (const auto& [name, mesh] : meshes) {
        const OracleCounts c = checkOracles(mesh, o, 2, name);
        EXPECT_EQ(c.skipped, 0) << name;
        EXPECT_GT(c.vertices, 0) << name;
    }
    // One explicit case: the pentagon of prism 5 gets a face point at its centroid, its corner
    // 0 stays, the edge 0-1 gets the midpoint.
    const LocalMesh prism = buildPrism(5);
    Refiner refiner(prism.descriptor(), o);
    refiner.refineUniform(1);
    const Topology& t = refiner.level(0);
    const std::vector<double> vertex = denseStencil(refiner.levelStencils(1), childOfVertex(t, 0));
    EXPECT_NEAR(vertex[0], 1.0, kWeightTol);
    const std::vector<double> edge = denseStencil(refiner.levelStencils(1), childOfEdge(t, edgeBetween(t, 0, 1)));
    EXPECT_NEAR(edge[0], 0.5, kWeightTol);
    EXPECT_NEAR(edge[1], 0.5, kWeightTol);
    const std::vector<double> face = denseStencil(refiner.levelStencils(1), childOfFace(t, 0));
    for (int i = 0; i < 5; ++i)
        EXPECT_NEAR(face[i], 0.2, kWeightTol);
}

// Large levels are built in parts, one per thread, joined in child order: the joined table must
// equal the one-part build exactly (same entries, same pool, same offsets), whatever the number
// of parts, for every scheme hook and with creases.
TEST(LevelStencils, PartsJoinToTheSerialTable) {
    const struct {
        const char* mesh;
        Scheme scheme;
        int parentLevel;
    } cases[] = {{"mixed/mixed_torus.obj", Scheme::SchaeferWarren, 4},
                 {"mixed/mixed_torus.obj", Scheme::CatmarkButterfly, 4},
                 {"mixed/cylinder_capped_creased.obj", Scheme::StamLoop, 5}};
    for (const auto& c : cases) {
        const io::ObjMesh mesh = io::readObj(meshPath(c.mesh));
        Options options;
        options.scheme = c.scheme;
        options.creaseMethod = CreaseMethod::Chaikin;
        Refiner refiner(mesh.descriptor(), mesh.applyTags(options));
        refiner.refineUniform(c.parentLevel, TopologyDetail::Full);
        const Topology& parent = refiner.level(c.parentLevel);
        const ChildNumbering numbering = numberChildren(parent);
        const std::string where = std::string(c.mesh) + " " + toString(c.scheme);
        const int children = numbering.numFacePoints + parent.numEdges() + parent.numVertices;
        ASSERT_GE(children, 65536) << where << ": too small to be split";

        auto build = [&](int threads) {
            tbb::task_arena arena(threads);
            std::pair<StencilTable, StencilTableD> tables;
            arena.execute([&] {
                tables.first = buildLevelStencils<StencilTable>(parent, numbering, refiner.options());
                tables.second = buildLevelStencils<StencilTableD>(parent, numbering, refiner.options());
            });
            return tables;
        };
        const auto serial = build(1), split = build(4);
        EXPECT_EQ(serial.first.numStencils(), children) << where;
        EXPECT_EQ(serial.first.offsets, split.first.offsets) << where;
        EXPECT_EQ(serial.first.indices, split.first.indices) << where;
        EXPECT_EQ(serial.first.weightOffsets, split.first.weightOffsets) << where;
        EXPECT_EQ(serial.first.weights, split.first.weights) << where;
        EXPECT_EQ(serial.second.offsets, split.second.offsets) << where;
        EXPECT_EQ(serial.second.sizes, split.second.sizes) << where;
        EXPECT_EQ(serial.second.indices, split.second.indices) << where;
        EXPECT_EQ(serial.second.weights, split.second.weights) << where;
    }
}

// Float tables of smooth levels take the regular masks' short cut (far/schemes/regular_masks.h): the
// table must be exactly the one the rules build (the double table, rounded and interned), on
// closed pure meshes where nearly every mask is regular, and on a mixed one where only part is.
TEST(LevelStencils, RegularShortCutEqualsTheRules) {
    for (const char* name : {"osd/loop_icosahedron.obj", "osd/catmark_cube.obj", "osd/catmark_torus.obj", "osd/loop_cube.obj",
                             "mixed/mixed_torus.obj"}) {
        for (Scheme scheme : {Scheme::StamLoop, Scheme::SchaeferWarren, Scheme::CatmullClark}) {
            Options options;
            options.scheme = scheme;
            expectShortCutEqualsTheRules(name, options);
        }
    }
}

}  // namespace
