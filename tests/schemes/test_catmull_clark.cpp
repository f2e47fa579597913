// catmull-clark (OpenSubdiv's Catmark) in closed form: triangles split into three quads around
// their centroid, the face, edge and vertex masks next to triangles, the smooth-triangle edge
// weights, a face with a collapsed edge kept as OpenSubdiv keeps it, and the option's and the
// OBJ tag's reach. Agreement with OpenSubdiv on its shapes: test_osd_agreement.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
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

Options catmullClark(bool smoothTriangles = false) {
    Options o;
    o.scheme = Scheme::CatmullClark;
    o.smoothTriangles = smoothTriangles;
    return o;
}

// Under catmull-clark every face of level L has a face point: child f, then edges, then vertices.
int facePointOf(const Topology&, int f) { return f; }
int edgePointOf(const Topology& t, int e) { return t.numFaces() + e; }
int vertexPointOf(const Topology& t, int v) { return t.numFaces() + t.numEdges() + v; }

// A ring of n faces around the centre c (RingMesh), refined once; its faces as lists.
struct RefinedRing {
    RingMesh ring;
    std::unique_ptr<Refiner> refiner;
    std::vector<std::vector<int>> faces;  // level 0
};

RefinedRing refineRing(const std::string& kinds, bool smoothTriangles) {
    RefinedRing r;
    r.ring = buildRingMesh(kinds);
    r.refiner = std::make_unique<Refiner>(r.ring.mesh.descriptor(), catmullClark(smoothTriangles));
    r.refiner->refineUniform(1, TopologyDetail::Full);
    const Topology& t = r.refiner->level(0);
    for (int f = 0; f < t.numFaces(); ++f)
        r.faces.emplace_back(t.faceVerts.begin() + t.faceOffsets[f], t.faceVerts.begin() + t.faceOffsets[f + 1]);
    return r;
}

// Adds x times the centroid of `face` to d.
void addCentroid(Dense& d, const std::vector<int>& face, double x) {
    for (int v : face) d.add(v, x / double(face.size()));
}

TEST(CatmullClark, TrianglesSplitIntoThreeQuads) {
    const RefinedRing r = refineRing("TTTTT", false);
    const Topology& t0 = r.refiner->level(0);
    const Topology& t1 = r.refiner->level(1);
    // Every face of level 0 is a triangle: 3 quads and a face point each.
    EXPECT_EQ(t1.numFaces(), 3 * t0.numFaces());
    EXPECT_EQ(t1.numVertices, t0.numFaces() + t0.numEdges() + t0.numVertices);
    for (int f = 0; f < t1.numFaces(); ++f) EXPECT_EQ(t1.faceSize(f), 4) << "child face " << f;
    // The child of corner i of face 0 is (vertex, next edge point, face point, previous edge point).
    const int b = t1.faceOffsets[0];
    EXPECT_EQ(t1.faceVerts[b], vertexPointOf(t0, t0.faceVerts[0]));
    EXPECT_EQ(t1.faceVerts[b + 2], facePointOf(t0, 0));
}

// Catmark's masks beside triangles: face point = centroid, edge point = ¼ ends + ¼ face points,
// vertex point = (n − 2)/n c + 1/n² Σ p + 1/n² Σ face points; in closed form around a ring of n
// triangles: c weighs (n − 2)/n + 1/(3n), each p_i 5/(3n²).
TEST(CatmullClark, TriangleMasksInClosedForm) {
    for (int n = 3; n <= 7; ++n) {
        SCOPED_TRACE("valence " + std::to_string(n));
        const RefinedRing r = refineRing(std::string(size_t(n), 'T'), false);
        const Topology& t = r.refiner->level(0);
        const StencilTable& table = r.refiner->levelStencils(1);
        const int V = r.ring.mesh.numVertices, c = r.ring.center;
        for (int i = 0; i < n; ++i) {
            Dense face(V);
            addCentroid(face, r.faces[i], 1.0);
            EXPECT_LE(maxAbsDifference(denseStencil(table, facePointOf(t, i)), face.w), kWeightTol) << "face " << i;
            EXPECT_NEAR(denseStencil(table, facePointOf(t, i))[c], 1.0 / 3.0, kWeightTol);

            Dense edge(V);
            edge.add(c, 0.25);
            edge.add(r.ring.p[i], 0.25);
            addCentroid(edge, r.faces[i], 0.25);
            addCentroid(edge, r.faces[(i + n - 1) % n], 0.25);
            const int e = edgeBetween(t, c, r.ring.p[i]);
            EXPECT_LE(maxAbsDifference(denseStencil(table, edgePointOf(t, e)), edge.w), kWeightTol) << "edge c-p" << i;
            // ¼ + 2 · ¼ · ⅓ on each end, 1/12 on each far corner.
            EXPECT_NEAR(denseStencil(table, edgePointOf(t, e))[c], 0.25 + 1.0 / 6.0, kWeightTol);
        }
        const std::vector<double> centre = denseStencil(table, vertexPointOf(t, c));
        EXPECT_NEAR(centre[c], double(n - 2) / n + 1.0 / (3 * n), kWeightTol);
        for (int i = 0; i < n; ++i) EXPECT_NEAR(centre[r.ring.p[i]], 5.0 / (3.0 * n * n), kWeightTol);
        EXPECT_NEAR(centre[r.ring.apex], 0.0, kWeightTol);
    }
}

// Mixed ring: the vertex rule reads quads' and triangles' centroids alike.
TEST(CatmullClark, MixedVertexMask) {
    const RefinedRing r = refineRing("QTQTT", false);
    const Topology& t = r.refiner->level(0);
    const int n = 5, c = r.ring.center;
    Dense vertex(r.ring.mesh.numVertices);
    vertex.add(c, double(n - 2) / n);
    for (int i = 0; i < n; ++i) {
        vertex.add(r.ring.p[i], 1.0 / (n * n));
        addCentroid(vertex, r.faces[i], 1.0 / (n * n));
    }
    EXPECT_LE(maxAbsDifference(denseStencil(r.refiner->levelStencils(1), vertexPointOf(t, c)), vertex.w), kWeightTol);
}

// The smooth-triangle rule: an edge beside a triangle weighs each face point w = (w0 + w1)/2
// (w = 0.47 for a triangle, ¼ for a quad) and each end (1 − 2w)/2. Two triangles: 0.47 and
// 0.03; a triangle and a quad: 0.36 and 0.14; two quads: ¼ and ¼ as without the rule.
TEST(CatmullClark, SmoothTriangleEdgeWeights) {
    const RefinedRing r = refineRing("TTQQT", true);
    const Topology& t = r.refiner->level(0);
    const StencilTable& table = r.refiner->levelStencils(1);
    const int n = 5, c = r.ring.center;
    const double faceWeight[] = {0.47, 0.47, 0.36, 0.25, 0.36};  // edge c-p_i lies between faces i-1 and i
    for (int i = 0; i < n; ++i) {
        SCOPED_TRACE("edge c-p" + std::to_string(i));
        const double w = faceWeight[i], end = (1.0 - 2.0 * w) / 2.0;
        Dense edge(r.ring.mesh.numVertices);
        edge.add(c, end);
        edge.add(r.ring.p[i], end);
        addCentroid(edge, r.faces[i], w);
        addCentroid(edge, r.faces[(i + n - 1) % n], w);
        const int e = edgeBetween(t, c, r.ring.p[i]);
        EXPECT_LE(maxAbsDifference(denseStencil(table, edgePointOf(t, e)), edge.w), kWeightTol)
            << describe(denseStencil(table, edgePointOf(t, e)));
    }
    EXPECT_NEAR(0.5 * (0.47 + 0.25), 0.36, 1e-15);
    // The vertex rule does not change.
    const RefinedRing plain = refineRing("TTQQT", false);
    EXPECT_LE(maxAbsDifference(denseStencil(table, vertexPointOf(t, c)),
                               denseStencil(plain.refiner->levelStencils(1), vertexPointOf(t, c))),
              kWeightTol);
    // Level 1 has no triangle left: its edges are plain Catmark again.
    Refiner deeper(r.ring.mesh.descriptor(), catmullClark(true));
    Refiner reference(r.ring.mesh.descriptor(), catmullClark(false));
    deeper.refineUniform(2);
    reference.refineUniform(2);
    const StencilTable& a = deeper.levelStencils(2);
    const StencilTable& b = reference.levelStencils(2);
    ASSERT_EQ(a.numStencils(), b.numStencils());
    for (int i = 0; i < a.numStencils(); ++i)
        ASSERT_LE(maxAbsDifference(denseStencil(a, i), denseStencil(b, i)), 0.0) << "level 2 stencil " << i;
}

TEST(CatmullClark, SmoothTrianglesAreACatmullClarkRuleOnly) {
    const RingMesh ring = buildRingMesh("TTTT");
    for (Scheme s : allSchemes()) {
        if (s == Scheme::CatmullClark) continue;  // below
        Options o;
        o.scheme = s;
        o.smoothTriangles = true;
        EXPECT_FALSE(takesSmoothTriangles(s)) << toString(s);
        try {
            Refiner refiner(ring.mesh.descriptor(), o);
            ADD_FAILURE() << toString(s) << " accepted smoothTriangles";
        } catch (const TopologyError& e) {
            EXPECT_NE(std::string(e.what()).find("catmull-clark"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(toString(s)), std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(takesSmoothTriangles(Scheme::CatmullClark));
}

// `f 4 3 5 5`: kept as a quad with an edge from 5 to 5 of its own, as OpenSubdiv reads it; the
// collapsed edge is boundary and non-manifold, so infinitely sharp, and so is the pole at its end.
TEST(CatmullClark, CollapsedEdgeKeptAsOpenSubdivKeepsIt) {
    const io::ObjMesh mesh = io::readObj(meshPath("osd/catmark_nonman_quadpole8.obj"));
    Refiner refiner(mesh.descriptor(), mesh.applyTags(catmullClark()));
    refiner.refineUniform(2, TopologyDetail::Full);
    const Topology& t = refiner.level(0);
    ASSERT_EQ(t.numFaces(), 16);
    const int pole = 4;  // `5` in the file
    int collapsed = 0;
    for (int e = 0; e < t.numEdges(); ++e) {
        if (t.edgeVerts[2 * e] != t.edgeVerts[2 * e + 1]) continue;
        ++collapsed;
        EXPECT_EQ(t.edgeVerts[2 * e], pole);
        EXPECT_EQ(t.edgeFaceCount(e), 1);  // one per face: never shared
        EXPECT_EQ(t.edgeFlags[e] & (kEdgeBoundary | kEdgeNonManifold), kEdgeBoundary | kEdgeNonManifold);
        EXPECT_GE(t.edgeSharpness[e], kInfiniteSharpness);
    }
    EXPECT_EQ(collapsed, 8);
    for (int f = 1; f < 16; f += 2) EXPECT_EQ(t.faceSize(f), 4) << "face " << f + 1 << " stays a quad";
    EXPECT_GE(t.vertSharpness[pole], kInfiniteSharpness);
    // The other edges of the collapsed quads are manifold: their vertices stay smooth.
    EXPECT_EQ(t.vertFlags[2] & kVertexNonManifold, 0);
    EXPECT_EQ(t.vertFlags[3] & kVertexNonManifold, 0);
    EXPECT_EQ(t.vertSharpness[2], 0.0f);

    const StencilTable& table = refiner.levelStencils(1);
    // Face point of `4 3 5 5`: (v4 + v3 + 2 v5) / 4.
    const std::vector<double> face = denseStencil(table, facePointOf(t, 1));
    EXPECT_NEAR(face[3], 0.25, kWeightTol);
    EXPECT_NEAR(face[2], 0.25, kWeightTol);
    EXPECT_NEAR(face[pole], 0.5, kWeightTol);
    // The pole stays; so does the point of each collapsed edge.
    EXPECT_NEAR(denseStencil(table, vertexPointOf(t, pole))[pole], 1.0, kWeightTol);
    for (int e = 0; e < t.numEdges(); ++e) {
        if (t.edgeVerts[2 * e] != t.edgeVerts[2 * e + 1]) continue;
        EXPECT_NEAR(denseStencil(table, edgePointOf(t, e))[pole], 1.0, kWeightTol);
    }
    // Level 1: only quads, none repeating a vertex; each collapsed edge became two edges between
    // its point and the pole's, one face each.
    const Topology& t1 = refiner.level(1);
    EXPECT_EQ(t1.numFaces(), 64);
    for (int f = 0; f < t1.numFaces(); ++f) {
        std::vector<int> v(t1.faceVerts.begin() + t1.faceOffsets[f], t1.faceVerts.begin() + t1.faceOffsets[f + 1]);
        std::sort(v.begin(), v.end());
        EXPECT_EQ(std::adjacent_find(v.begin(), v.end()), v.end()) << "child face " << f;
    }
    for (int e = 0; e < t.numEdges(); ++e) {
        if (t.edgeVerts[2 * e] != t.edgeVerts[2 * e + 1]) continue;
        for (int half : {2 * e, 2 * e + 1}) {
            EXPECT_EQ(t1.edgeFaceCount(half), 1) << "half " << half;
            EXPECT_GE(t1.edgeSharpness[half], kInfiniteSharpness);
        }
        EXPECT_NE(t1.edgeFaces[t1.edgeFaceOffsets[2 * e]], t1.edgeFaces[t1.edgeFaceOffsets[2 * e + 1]]);
    }

    // Every other scheme still reads `4 3 5 5` as the triangle `4 3 5`.
    Refiner mixed(mesh.descriptor(), mesh.applyTags(Options()));
    EXPECT_EQ(mixed.level(0).faceSize(1), 3);
}

TEST(CatmullClark, ObjTagSmoothTriangles) {
    const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";
    std::istringstream smooth(quad + "t smoothtriangles 0/0/1 smooth\n");
    const io::ObjMesh m = io::parseObj(smooth, "s.obj");
    ASSERT_TRUE(m.smoothTriangles.has_value());
    EXPECT_TRUE(*m.smoothTriangles);
    EXPECT_TRUE(m.warnings.empty());
    EXPECT_TRUE(m.applyTags(catmullClark()).smoothTriangles);
    EXPECT_FALSE(m.applyTags(Options()).smoothTriangles) << "the tag is for catmull-clark, as in OpenSubdiv's harness";

    std::istringstream catmark(quad + "t smoothtriangles 0/0/1 catmark\n");
    const io::ObjMesh c = io::parseObj(catmark, "c.obj");
    ASSERT_TRUE(c.smoothTriangles.has_value());
    EXPECT_FALSE(c.applyTags(catmullClark(true)).smoothTriangles) << "the file's catmark turns the rule off";

    std::istringstream bad(quad + "t smoothtriangles 0/0/1 always\n");
    try {
        io::parseObj(bad, "b.obj");
        ADD_FAILURE() << "accepted 'always'";
    } catch (const io::ObjError& e) {
        EXPECT_EQ(std::string(e.what()), "b.obj:7: smoothtriangles 'always' is not smooth or catmark");
    }
}

TEST(CatmullClark, RegularShortCutEqualsTheRules) {
    for (const char* name : {"osd/catmark_cube.obj", "osd/catmark_torus.obj", "osd/catmark_pyramid.obj",
                             "mixed/mixed_torus.obj"})
        for (bool smooth : {false, true}) {
            SCOPED_TRACE(smooth ? "smooth triangles" : "catmark triangles");
            expectShortCutEqualsTheRules(name, catmullClark(smooth));
        }
}

}  // namespace
