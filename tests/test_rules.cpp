// One-pass oracles for the refinement masks: every refined vertex of small hand-built meshes is
// compared, as a dense weight vector over the parent level, with the classical closed-form rule
// (Catmull-Clark, Loop, the Stam-Loop seam edge, bilinear, boundary creases and corners).
// Expected weights are computed here from the mesh's own face lists, never from the analyzer.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "far/refiner.h"
#include "tests/local_meshes.h"
#include "tests/test_support.h"

namespace {

using namespace quadtri;
using namespace quadtri::test;

// Weights are stored as float: a weight of magnitude <= 1 is exact to ~6e-8.
constexpr double kWeightTol = 1e-6;
const double kPi = std::acos(-1.0);

double loopBeta(int n) {
    const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * kPi / n);
    return (5.0 / 8.0 - c * c) / n;
}

using Key = std::pair<int, int>;
Key edgeKey(int a, int b) {
    return {std::min(a, b), std::max(a, b)};
}

// Adjacency computed by the test from the face lists.
struct Adjacency {
    int numVertices = 0;
    std::vector<std::vector<int>> faces;
    std::map<Key, std::vector<int>> edgeFaces;
    std::vector<std::vector<int>> vertexFaces;
    std::vector<std::set<int>> neighbours;

    explicit Adjacency(const LocalMesh& m) : numVertices(m.numVertices) {
        vertexFaces.resize(size_t(numVertices));
        neighbours.resize(size_t(numVertices));
        int offset = 0;
        for (int f = 0; f < m.numFaces(); ++f) {
            const int k = m.faceSizes[f];
            std::vector<int> face(m.faceVerts.begin() + offset, m.faceVerts.begin() + offset + k);
            offset += k;
            for (int i = 0; i < k; ++i) {
                const int a = face[i], b = face[(i + 1) % k];
                edgeFaces[edgeKey(a, b)].push_back(f);
                neighbours[a].insert(b);
                neighbours[b].insert(a);
                vertexFaces[a].push_back(f);
            }
            faces.push_back(face);
        }
    }
    bool isTriangle(int f) const { return faces[f].size() == 3; }
    int boundaryEdgeCount(int v) const {
        int k = 0;
        for (int w : neighbours[v])
            if (edgeFaces.at(edgeKey(v, w)).size() == 1)
                ++k;
        return k;
    }
};

struct Dense {
    std::vector<double> w;
    explicit Dense(int n) : w(size_t(n), 0.0) {}
    void add(int v, double x) { w.at(size_t(v)) += x; }
    void addCentroid(const std::vector<int>& face, double x) {
        for (int v : face)
            add(v, x / double(face.size()));
    }
};

// The vertex of triangle f that is not on edge (a, b).
int oppositeVertex(const std::vector<int>& tri, int a, int b) {
    for (int v : tri)
        if (v != a && v != b)
            return v;
    return -1;
}

std::string describe(const std::vector<double>& w) {
    std::ostringstream s;
    for (size_t i = 0; i < w.size(); ++i)
        if (std::fabs(w[i]) > 1e-9)
            s << " [" << i << "]=" << w[i];
    return s.str();
}

// ---- Oracles -----------------------------------------------------------------------------

std::optional<std::vector<double>> expectedFacePoint(const Adjacency& adj, int f) {
    Dense d(adj.numVertices);
    d.addCentroid(adj.faces[f], 1.0);
    return d.w;
}

std::optional<std::vector<double>> expectedEdgePoint(const Adjacency& adj, const Options& o, int a, int b) {
    Dense d(adj.numVertices);
    const std::vector<int>& faces = adj.edgeFaces.at(edgeKey(a, b));
    if (o.scheme == Scheme::Bilinear || faces.size() != 2) {  // linear, boundary or non-manifold
        d.add(a, 0.5);
        d.add(b, 0.5);
        return d.w;
    }
    // Smooth edge: 1/4 of each endpoint plus each side's half of its own scheme's mask:
    // a quad-like side adds 1/4 of its face point (Catmull-Clark: 1/4 a + 1/4 b + 1/4 F1 + 1/4 F2),
    // a triangle side adds 1/16 a + 1/16 b + 1/8 opposite (Loop: 3/8, 3/8, 1/8, 1/8).
    d.add(a, 0.25);
    d.add(b, 0.25);
    for (int f : faces) {
        if (adj.isTriangle(f)) {
            d.add(a, 1.0 / 16);
            d.add(b, 1.0 / 16);
            d.add(oppositeVertex(adj.faces[f], a, b), 1.0 / 8);
        } else {
            d.addCentroid(adj.faces[f], 0.25);
        }
    }
    return d.w;
}

// Empty for configurations without a one-pass oracle here (mixed interior vertices: test_eigen).
std::optional<std::vector<double>> expectedVertexPoint(const Adjacency& adj, const Options& o, int v) {
    Dense d(adj.numVertices);
    if (o.scheme == Scheme::Bilinear) {
        d.add(v, 1.0);
        return d.w;
    }
    if (adj.vertexFaces[v].empty()) {  // unused vertex: stays
        d.add(v, 1.0);
        return d.w;
    }
    const int k = adj.boundaryEdgeCount(v);
    if (k > 0) {
        if (k != 2)
            return std::nullopt;
        if (adj.vertexFaces[v].size() == 1 && o.boundary == BoundaryInterpolation::EdgeAndCorner) {
            d.add(v, 1.0);  // corner: fixed
            return d.w;
        }
        d.add(v, 0.75);  // crease rule over the two boundary neighbours
        for (int w : adj.neighbours[v])
            if (adj.edgeFaces.at(edgeKey(v, w)).size() == 1)
                d.add(w, 0.125);
        return d.w;
    }
    int tris = 0, others = 0;
    for (int f : adj.vertexFaces[v])
        (adj.isTriangle(f) ? tris : others)++;
    const int n = int(adj.neighbours[v].size());
    if (tris == 0) {  // Catmull-Clark: (n-2)/n v + sum p / n^2 + sum F / n^2
        d.add(v, double(n - 2) / n);
        for (int w : adj.neighbours[v])
            d.add(w, 1.0 / (n * n));
        for (int f : adj.vertexFaces[v])
            d.addCentroid(adj.faces[f], 1.0 / (n * n));
        return d.w;
    }
    if (others == 0) {  // Loop: (1 - n beta) v + beta sum p
        const double beta = loopBeta(n);
        d.add(v, 1.0 - n * beta);
        for (int w : adj.neighbours[v])
            d.add(w, beta);
        return d.w;
    }
    return std::nullopt;
}

struct OracleCounts {
    int vertices = 0, edges = 0, faces = 0, skipped = 0;
};

// Refines `mesh` to `levels` and compares every refined vertex of every level that has an oracle.
OracleCounts checkOracles(const LocalMesh& mesh, const Options& options, int levels, const std::string& name) {
    OracleCounts counts;
    Refiner refiner(mesh.descriptor(), options);
    refiner.refineUniform(levels);
    for (int L = 1; L <= levels; ++L) {
        const LocalMesh parent = L == 1 ? mesh : fromTopology(refiner.level(L - 1));
        const Adjacency adj(parent);
        const Topology& t = refiner.level(L - 1);
        const StencilTable& table = refiner.levelStencils(L);
        const std::string where = name + " level " + std::to_string(L);
        int nonTriangles = 0;
        for (int f = 0; f < int(adj.faces.size()); ++f)
            if (!adj.isTriangle(f))
                ++nonTriangles;
        EXPECT_EQ(table.numSourceVertices, parent.numVertices) << where;
        EXPECT_EQ(t.numVertices, parent.numVertices) << where;
        EXPECT_EQ(t.numFaces(), parent.numFaces()) << where;
        EXPECT_EQ(t.numEdges(), int(adj.edgeFaces.size())) << where;
        EXPECT_EQ(table.numStencils(), parent.numVertices + int(adj.edgeFaces.size()) + nonTriangles) << where;
        if (table.numStencils() != parent.numVertices + int(adj.edgeFaces.size()) + nonTriangles ||
            t.numEdges() != int(adj.edgeFaces.size()))
            return counts;
        std::map<Key, int> edgeIndex;
        for (int e = 0; e < t.numEdges(); ++e)
            edgeIndex[edgeKey(t.edgeVerts[2 * e], t.edgeVerts[2 * e + 1])] = e;

        auto compare = [&](int child, const std::vector<double>& expected, const std::string& what) {
            const std::vector<double> actual = denseStencil(table, child);
            const double diff = maxAbsDifference(actual, expected);
            EXPECT_LE(diff, kWeightTol) << where << ", " << what << " (child " << child
                                        << ")\n  expected:" << describe(expected)
                                        << "\n  actual:  " << describe(actual);
        };
        for (int f = 0; f < int(adj.faces.size()); ++f) {
            if (adj.isTriangle(f))
                continue;
            compare(childOfFace(t, f), *expectedFacePoint(adj, f), "face " + std::to_string(f));
            ++counts.faces;
        }
        for (const auto& [key, faces] : adj.edgeFaces) {
            auto it = edgeIndex.find(key);
            EXPECT_NE(it, edgeIndex.end()) << where << ": no edge " << key.first << "-" << key.second;
            if (it == edgeIndex.end())
                continue;
            compare(childOfEdge(t, it->second), *expectedEdgePoint(adj, options, key.first, key.second),
                    "edge " + std::to_string(key.first) + "-" + std::to_string(key.second));
            ++counts.edges;
        }
        for (int v = 0; v < parent.numVertices; ++v) {
            const auto expected = expectedVertexPoint(adj, options, v);
            if (!expected) {
                ++counts.skipped;
                continue;
            }
            compare(childOfVertex(t, v), *expected, "vertex " + std::to_string(v));
            ++counts.vertices;
        }
    }
    return counts;
}

std::string ringName(const std::string& ring) {
    return "ring " + ring;
}

Options stamLoop(BoundaryInterpolation b = BoundaryInterpolation::EdgeOnly) {
    Options o;
    o.scheme = Scheme::StamLoop;
    o.boundary = b;
    return o;
}

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

// ---- Semi-sharp edges (DESIGN.md 6) -----------------------------------------------------------

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
                    ASSERT_EQ(table.numStencils(), refiner.level(L).numVertices) << name;
                    ASSERT_EQ(factorized.numStencils(), refiner.level(L).numVertices) << name;
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
