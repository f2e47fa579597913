// Refined levels are built by construction (far/topology/refine_topology.cpp); here they are checked
// against the generic builder (completeTopology) run on the same child faces.
#include <gtest/gtest.h>

#include <algorithm>

#include "far/topology/refine_topology.h"
#include "tests/test_support.h"
#include "far/internal/stencil_table_double.h"
#include "far/topology/topology_builder.h"

namespace quadtri::test {
namespace {

std::vector<int> range(const std::vector<int>& values, int begin, int end) {
    return std::vector<int>(values.begin() + begin, values.begin() + end);
}

void expectSameConnectivity(const Topology& direct, const std::string& where) {
    Topology generic;
    generic.numVertices = direct.numVertices;
    generic.faceOffsets = direct.faceOffsets;
    generic.faceVerts = direct.faceVerts;
    completeTopology(generic);

    ASSERT_EQ(direct.numEdges(), generic.numEdges()) << where;
    // Each face's edges join its consecutive corners.
    for (int f = 0; f < direct.numFaces(); ++f) {
        const int b = direct.faceOffsets[f], n = direct.faceSize(f);
        for (int i = 0; i < n; ++i) {
            const int e = direct.faceEdges[b + i], u = direct.faceVerts[b + i], w = direct.faceVerts[b + (i + 1) % n];
            ASSERT_TRUE((direct.edgeVerts[2 * e] == u && direct.edgeVerts[2 * e + 1] == w) ||
                        (direct.edgeVerts[2 * e] == w && direct.edgeVerts[2 * e + 1] == u))
                << where << " face " << f << " corner " << i;
        }
    }
    // Same edges with the same faces (in the same, ascending order) and flags.
    for (int e = 0; e < direct.numEdges(); ++e) {
        const int g = findEdge(generic, direct.edgeVerts[2 * e], direct.edgeVerts[2 * e + 1]);
        ASSERT_GE(g, 0) << where << " edge " << e;
        EXPECT_EQ(range(direct.edgeFaces, direct.edgeFaceOffsets[e], direct.edgeFaceOffsets[e + 1]),
                  range(generic.edgeFaces, generic.edgeFaceOffsets[g], generic.edgeFaceOffsets[g + 1]))
            << where << " edge " << e;
        EXPECT_EQ(direct.edgeFlags[e], generic.edgeFlags[g]) << where << " edge " << e;
    }
    for (int v = 0; v < direct.numVertices; ++v) {
        EXPECT_EQ(range(direct.vertFaces, direct.vertFaceOffsets[v], direct.vertFaceOffsets[v + 1]),
                  range(generic.vertFaces, generic.vertFaceOffsets[v], generic.vertFaceOffsets[v + 1]))
            << where << " vertex " << v;
        // Edge numbers differ between the builders: each listed edge ends at v, ascending, and
        // the lists have the same length.
        EXPECT_EQ(direct.vertexEdgeCount(v), generic.vertexEdgeCount(v)) << where << " vertex " << v;
        const std::vector<int> edges = range(direct.vertEdges, direct.vertEdgeOffsets[v], direct.vertEdgeOffsets[v + 1]);
        EXPECT_TRUE(std::is_sorted(edges.begin(), edges.end())) << where << " vertex " << v;
        for (int e : edges)
            EXPECT_TRUE(direct.edgeVerts[2 * e] == v || direct.edgeVerts[2 * e + 1] == v) << where << " vertex " << v;
        EXPECT_EQ(direct.vertFlags[v], generic.vertFlags[v]) << where << " vertex " << v;
    }
}

TEST(RefineTopology, ChildLevelsEqualTheGenericBuilder) {
    for (const std::string& name : allMeshes()) {
        const io::ObjMesh mesh = io::readObj(meshPath(name));
        const int levels = mesh.numFaces() > 500 ? 1 : 2;
        Refiner refiner(mesh.descriptor(), mesh.applyTags(Options()));
        refiner.refineUniform(levels, TopologyDetail::Full);
        for (int L = 1; L <= levels; ++L) expectSameConnectivity(refiner.level(L), name + " level " + std::to_string(L));
    }
}

// Levels 1 and 2 under catmull-clark (its triangle split, its sharpness and flags). A collapsed
// edge's two halves join the same two vertices, which the generic builder would merge into one
// edge: that shape's halves are checked in test_catmull_clark instead.
TEST(RefineTopology, CatmullClarkLevelsEqualTheGenericBuilder) {
    Options catmullClark;
    catmullClark.scheme = Scheme::CatmullClark;
    for (const std::string& name : allMeshes()) {
        if (name == "osd/catmark_nonman_quadpole8.obj") continue;
        const io::ObjMesh mesh = io::readObj(meshPath(name));
        const int levels = mesh.numFaces() > 500 ? 1 : 2;
        Refiner refiner(mesh.descriptor(), mesh.applyTags(catmullClark));
        refiner.refineUniform(levels, TopologyDetail::Full);
        for (int f = 0; f < refiner.level(1).numFaces(); ++f) ASSERT_EQ(refiner.level(1).faceSize(f), 4) << name;
        for (int L = 1; L <= levels; ++L) expectSameConnectivity(refiner.level(L), name + " level " + std::to_string(L));
    }
}

// A scheme may split triangles into three quads around a face point (TriangleSplit::ThreeQuads,
// as Catmull-Clark does): every face then has a face point and every child is a quad, and the
// child level built by construction still equals the generic builder's.
TEST(RefineTopology, TrianglesSplitIntoThreeQuadsEqualTheGenericBuilder) {
    for (const std::string& name : allMeshes()) {
        const io::ObjMesh mesh = io::readObj(meshPath(name));
        Refiner refiner(mesh.descriptor(), mesh.applyTags(Options()));
        const Topology& p = refiner.level(0);
        const ChildNumbering num = numberChildren(p, TriangleSplit::ThreeQuads);
        ASSERT_EQ(num.numFacePoints, p.numFaces()) << name;
        const Topology c = refineTopology(p, num, CreaseMethod::Uniform);
        int corners = 0;
        for (int f = 0; f < p.numFaces(); ++f) corners += p.faceSize(f);
        ASSERT_EQ(c.numFaces(), corners) << name;
        for (int f = 0; f < c.numFaces(); ++f) ASSERT_EQ(c.faceSize(f), 4) << name << " child face " << f;
        expectSameConnectivity(c, name + " split into quads");
    }
}

// The halves of parent edge e are child edges 2e (at edgeVerts[2e]) and 2e+1, carrying the
// decayed sharpness of their end.
TEST(RefineTopology, HalvesOfParentEdgesCarryTheirSharpness) {
    const RefinedMesh r = refineMesh("osd/catmark_chaikin0.obj", 1);
    const Topology& p = r.refiner->level(0);
    const Topology& c = r.refiner->level(1);
    const ChildNumbering num = numberChildren(p);
    int sharpHalves = 0;
    for (int e = 0; e < p.numEdges(); ++e)
        for (int side = 0; side < 2; ++side) {
            const int v = p.edgeVerts[2 * e + side];
            EXPECT_EQ(findEdge(c, num.vertexPoint(v), num.edgePoint(e)), 2 * e + side);
            sharpHalves += c.edgeSharpness[2 * e + side] > 0;
            if (p.edgeSharpness[e] <= 0) {
                EXPECT_EQ(c.edgeSharpness[2 * e + side], 0.0f);
            }
        }
    EXPECT_GT(sharpHalves, 0);
    for (int e = 2 * p.numEdges(); e < c.numEdges(); ++e) EXPECT_EQ(c.edgeSharpness[e], 0.0f);
}

// The last level is faces only by default (as OpenSubdiv's fullTopologyInLastLevel = false);
// its faces equal the full build's, and refining further or asking for Full completes it.
TEST(RefineTopology, FacesOnlyLastLevelCompletesOnDemand) {
    for (const std::string name : {"osd/catmark_chaikin0.obj", "mixed/cylinder_capped_creased.obj"}) {
        const io::ObjMesh mesh = io::readObj(meshPath(name));
        const Options options = mesh.applyTags(Options());
        Refiner full(mesh.descriptor(), options), lazy(mesh.descriptor(), options);
        full.refineUniform(2, TopologyDetail::Full);
        lazy.refineUniform(1);
        const LevelFaces minimal = lazy.faces(1);
        EXPECT_EQ(cornersOf(minimal), cornersOf(full.faces(1))) << name;
        EXPECT_EQ(offsetsOf(minimal), offsetsOf(full.faces(1))) << name;
        EXPECT_EQ(holesOf(minimal), holesOf(full.faces(1))) << name;
        EXPECT_EQ(minimal.numVertices(), full.faces(1).numVertices()) << name;
        // Its edges and incidences are not built, and level() says so rather than hand out empty arrays.
        EXPECT_EQ(lazy.detail(1), TopologyDetail::FacesOnly) << name;
        EXPECT_THROW(lazy.level(1), std::logic_error) << name;
        EXPECT_EQ(full.detail(1), TopologyDetail::Full) << name;

        lazy.refineUniform(2);  // level 1 becomes a parent: it is completed first
        expectSameConnectivity(lazy.level(1), name + " level 1 completed");
        EXPECT_EQ(lazy.level(1).edgeSharpness, full.level(1).edgeSharpness) << name;
        EXPECT_EQ(toDoubleTable(lazy.levelStencils(2)).weights, toDoubleTable(full.levelStencils(2)).weights) << name;
        lazy.refineUniform(2, TopologyDetail::Full);
        expectSameConnectivity(lazy.level(2), name + " level 2 completed");
        EXPECT_EQ(lazy.level(2).vertSharpness, full.level(2).vertSharpness) << name;
    }
}

}  // namespace
}  // namespace quadtri::test
