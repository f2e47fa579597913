// Small hand-built meshes and stencil helpers shared by test_rules, test_eigen and test_validation.
// Every mesh here is pure topology (the rules tests compare weights, not positions).
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <quadtri/far/refiner.h>

namespace quadtri::test {

struct LocalMesh {
    int numVertices = 0;
    std::vector<int> faceSizes;
    std::vector<int> faceVerts;
    std::vector<int> creasePairs;
    std::vector<float> creaseWeights;
    std::vector<int> corners;
    std::vector<float> cornerWeights;

    void addFace(std::initializer_list<int> verts) {
        faceSizes.push_back(int(verts.size()));
        faceVerts.insert(faceVerts.end(), verts.begin(), verts.end());
    }
    void addFace(const std::vector<int>& verts) {
        faceSizes.push_back(int(verts.size()));
        faceVerts.insert(faceVerts.end(), verts.begin(), verts.end());
    }
    int numFaces() const { return int(faceSizes.size()); }

    TopologyDescriptor descriptor() const {
        TopologyDescriptor d;
        d.numVertices = numVertices;
        d.numFaces = numFaces();
        d.numVertsPerFace = faceSizes.data();
        d.faceVertIndices = faceVerts.data();
        d.numCreases = int(creaseWeights.size());
        d.creaseVertexPairs = creasePairs.empty() ? nullptr : creasePairs.data();
        d.creaseWeights = creaseWeights.empty() ? nullptr : creaseWeights.data();
        d.numCorners = int(corners.size());
        d.cornerVertexIndices = corners.empty() ? nullptr : corners.data();
        d.cornerWeights = cornerWeights.empty() ? nullptr : cornerWeights.data();
        return d;
    }
};

// A closed mesh around one interior vertex. `ring` lists the faces around the centre in
// counter-clockwise order: 'Q' for a quad, 'T' for a triangle. Vertex 0 is the centre c,
// vertices 1..n its edge neighbours p_0..p_{n-1} (face i lies between p_i and p_{i+1 mod n}),
// then one opposite corner q_i per quad (in ring order), then the apex z of a triangle cone
// that closes the disk's boundary loop, so that c's 1-ring is interior and no edge at c is sharp.
struct RingMesh {
    LocalMesh mesh;
    std::string ring;
    int center = 0;
    std::vector<int> p;       // edge neighbours, p[i] = 1 + i
    std::vector<int> q;       // per face i: its opposite corner (quads) or -1 (triangles)
    std::vector<int> quadOf;  // quads in ring order: the face index i of each
    int apex = -1;
};

inline RingMesh buildRingMesh(const std::string& ring) {
    RingMesh r;
    r.ring = ring;
    const int n = int(ring.size());
    if (n < 2)
        throw std::invalid_argument("ring needs at least two faces");
    int next = 1 + n;
    for (int i = 0; i < n; ++i)
        r.p.push_back(1 + i);
    r.q.assign(n, -1);
    for (int i = 0; i < n; ++i)
        if (ring[i] == 'Q') {
            r.q[i] = next++;
            r.quadOf.push_back(i);
        }
    r.apex = next++;
    r.mesh.numVertices = next;
    // Disk faces and the directed edges of its boundary loop.
    std::vector<std::pair<int, int>> boundary;
    for (int i = 0; i < n; ++i) {
        const int a = r.p[i], b = r.p[(i + 1) % n];
        if (ring[i] == 'Q') {
            r.mesh.addFace({r.center, a, r.q[i], b});
            boundary.push_back({a, r.q[i]});
            boundary.push_back({r.q[i], b});
        } else {
            r.mesh.addFace({r.center, a, b});
            boundary.push_back({a, b});
        }
    }
    // Cone: the boundary edge a->b of the disk is traversed b->a by its cone triangle.
    for (auto [a, b] : boundary)
        r.mesh.addFace({b, a, r.apex});
    return r;
}

// Closed prism over an n-gon: bottom face 0 (vertices 0..n-1), top face 1 (n..2n-1), then n
// side quads (face 2 + i joins bottom i, i+1 and top i+1, i).
inline LocalMesh buildPrism(int n) {
    LocalMesh m;
    m.numVertices = 2 * n;
    std::vector<int> bottom, top;
    for (int i = 0; i < n; ++i)
        bottom.push_back(n - 1 - i);  // facing down
    for (int i = 0; i < n; ++i)
        top.push_back(n + i);
    m.addFace(bottom);
    m.addFace(top);
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        m.addFace({i, j, n + j, n + i});
    }
    return m;
}

// Open planar grid of w x h cells, vertex (i, j) = j * (w + 1) + i. Quads, or each cell split
// into two triangles along its (i,j)-(i+1,j+1) diagonal.
inline LocalMesh buildGrid(int w, int h, bool triangles) {
    LocalMesh m;
    m.numVertices = (w + 1) * (h + 1);
    auto V = [w](int i, int j) { return j * (w + 1) + i; };
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const int a = V(i, j), b = V(i + 1, j), c = V(i + 1, j + 1), d = V(i, j + 1);
            if (triangles) {
                m.addFace({a, b, c});
                m.addFace({a, c, d});
            } else {
                m.addFace({a, b, c, d});
            }
        }
    return m;
}

// Topological Catmull-Clark split (my own, no weights): a face of k corners becomes k quads
// around a new face-centre vertex. Vertices: the old ones, then one per edge (first seen
// order), then one per face. The centre of a k-gon gets valence k.
inline LocalMesh quadrangulate(const LocalMesh& m) {
    LocalMesh out;
    std::vector<std::pair<std::pair<int, int>, int>> edgeIds;  // small meshes: linear search
    int next = m.numVertices;
    auto edgeVertex = [&](int a, int b) {
        const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
        for (auto& [k, id] : edgeIds)
            if (k == key)
                return id;
        edgeIds.push_back({key, next});
        return next++;
    };
    std::vector<std::vector<int>> mids(size_t(m.numFaces()));
    int offset = 0;
    for (int f = 0; f < m.numFaces(); ++f) {
        const int k = m.faceSizes[f];
        for (int i = 0; i < k; ++i)
            mids[f].push_back(edgeVertex(m.faceVerts[offset + i], m.faceVerts[offset + (i + 1) % k]));
        offset += k;
    }
    offset = 0;
    for (int f = 0; f < m.numFaces(); ++f) {
        const int k = m.faceSizes[f];
        const int centre = next++;
        for (int i = 0; i < k; ++i)
            out.addFace({m.faceVerts[offset + i], mids[f][i], centre, mids[f][(i + k - 1) % k]});
        offset += k;
    }
    out.numVertices = next;
    return out;
}

// The faces of a refined level as a LocalMesh (to run the same oracles one level further).
inline LocalMesh fromTopology(const Topology& t) {
    LocalMesh m;
    m.numVertices = t.numVertices;
    for (int f = 0; f < t.numFaces(); ++f)
        m.addFace(std::vector<int>(t.faceVerts.begin() + t.faceOffsets[f], t.faceVerts.begin() + t.faceOffsets[f + 1]));
    return m;
}

// ---- Index helpers following the documented vertex order of level L (face points of the
// non-triangle faces of level L-1, then edge points, then vertex points). ----

inline int edgeBetween(const Topology& t, int a, int b) {
    for (int e = 0; e < t.numEdges(); ++e) {
        const int u = t.edgeVerts[2 * e], v = t.edgeVerts[2 * e + 1];
        if ((u == a && v == b) || (u == b && v == a))
            return e;
    }
    return -1;
}

inline int countNonTriangleFaces(const Topology& t) {
    int count = 0;
    for (int f = 0; f < t.numFaces(); ++f)
        if (t.faceSize(f) != 3)
            ++count;
    return count;
}

// Index in level L+1 of the point of face f (not a triangle) of level L.
inline int childOfFace(const Topology& t, int f) {
    if (t.faceSize(f) == 3)
        throw std::invalid_argument("triangles have no face point");
    int rank = 0;
    for (int g = 0; g < f; ++g)
        if (t.faceSize(g) != 3)
            ++rank;
    return rank;
}
inline int childOfEdge(const Topology& t, int e) {
    return countNonTriangleFaces(t) + e;
}
inline int childOfVertex(const Topology& t, int v) {
    return countNonTriangleFaces(t) + t.numEdges() + v;
}

// Stencil i of `table` as dense weights over its source vertices (repeated indices summed).
inline std::vector<double> denseStencil(const StencilTable& table, int i) {
    std::vector<double> w(size_t(table.numSourceVertices), 0.0);
    for (int k = 0; k < table.size(i); ++k) w.at(size_t(table.indices[table.offsets[i] + k])) += table.weightsOf(i)[k];
    return w;
}

inline double maxAbsDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i)
        d = std::max(d, std::fabs(a[i] - b[i]));
    if (a.size() != b.size())
        d = INFINITY;
    return d;
}

}  // namespace quadtri::test
