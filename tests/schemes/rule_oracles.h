// Closed-form oracles for the refinement masks, shared by test_rules (interior rules) and
// test_boundary_rules (boundaries, orientation, creases, partition of unity). Expected weights
// are computed here from the mesh's own face lists, never from the analyzer.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <quadtri/far/refiner.h>
#include "tests/local_meshes.h"

namespace quadtri::test {

// Weights are stored as float: a weight of magnitude <= 1 is exact to ~6e-8.
inline constexpr double kWeightTol = 1e-6;
inline const double kPi = std::acos(-1.0);

inline double loopBeta(int n) {
    const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * kPi / n);
    return (5.0 / 8.0 - c * c) / n;
}

using Key = std::pair<int, int>;
inline Key edgeKey(int a, int b) {
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
inline int oppositeVertex(const std::vector<int>& tri, int a, int b) {
    for (int v : tri)
        if (v != a && v != b)
            return v;
    return -1;
}

inline std::string describe(const std::vector<double>& w) {
    std::ostringstream s;
    for (size_t i = 0; i < w.size(); ++i)
        if (std::fabs(w[i]) > 1e-9)
            s << " [" << i << "]=" << w[i];
    return s.str();
}

// ---- Oracles -----------------------------------------------------------------------------

inline std::optional<std::vector<double>> expectedFacePoint(const Adjacency& adj, int f) {
    Dense d(adj.numVertices);
    d.addCentroid(adj.faces[f], 1.0);
    return d.w;
}

inline std::optional<std::vector<double>> expectedEdgePoint(const Adjacency& adj, const Options& o, int a, int b) {
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
inline std::optional<std::vector<double>> expectedVertexPoint(const Adjacency& adj, const Options& o, int v) {
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
inline OracleCounts checkOracles(const LocalMesh& mesh, const Options& options, int levels, const std::string& name) {
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

inline std::string ringName(const std::string& ring) {
    return "ring " + ring;
}

inline Options stamLoop(BoundaryInterpolation b = BoundaryInterpolation::EdgeOnly) {
    Options o;
    o.scheme = Scheme::StamLoop;
    o.boundary = b;
    return o;
}

}  // namespace quadtri::test
