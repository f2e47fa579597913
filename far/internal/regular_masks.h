// Masks whose weights depend on a small key only, on a level without sharpness: the edge point
// of an edge between two triangles (Loop: 3/8, 3/8, 1/8, 1/8), the vertex point of a vertex
// whose n faces are all triangles (Loop, weights by n), and the same for quads (Catmull-Clark:
// an edge between two quads; a vertex whose n faces are all quads). After a level or two nearly
// every child of a pure or mostly pure mesh is one of these. The first mask of each key is built
// by the scheme's rules (rules.cpp); if they listed exactly the vertices gathered here, in the same
// order, its pooled weights serve every later mask of the key, which then only gathers its
// vertices: the table is the one the rules build, without their arithmetic.
#pragma once

#include <vector>

#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {

class RegularMasks {
public:
    static constexpr int kMaxValence = 16;
    static constexpr int kUnknown = -1;  // weights of the key not seen yet
    static constexpr int kNever = -2;    // the rules ordered the key's vertices otherwise

    explicit RegularMasks(const Topology& t) : t_(t), weights_(2 + 2 * (kMaxValence + 1), kUnknown) {}

    // Gathers the vertices of a regular edge or vertex mask into `out` (room for
    // 2 * kMaxValence + 1) and returns their count, with `key` set; 0 when not regular.
    int edge(int e, int* out, int& key) const {
        if (t_.edgeFaceCount(e) != 2) return 0;
        const int a = t_.edgeVerts[2 * e], b = t_.edgeVerts[2 * e + 1];
        const int f0 = t_.facesOfEdge(e)[0], f1 = t_.facesOfEdge(e)[1];
        const int n = t_.faceSize(f0);
        if (n != t_.faceSize(f1) || (n != 3 && n != 4) || f0 == f1) return 0;
        out[0] = a;
        out[1] = b;
        int count = 2;
        for (int f : {f0, f1})
            for (int c : t_.verticesOfFace(f))
                if (c != a && c != b) out[count++] = c;
        // Two faces sharing more than the edge would merge entries: left to the rules.
        for (int i = 2 + n - 2; i < count; ++i)
            for (int j = 2; j < 2 + n - 2; ++j)
                if (out[i] == out[j]) return 0;
        key = n == 3 ? 0 : 1;
        return count;
    }

    int vertex(int v, int* out, int& key) const {
        const int n = t_.vertexEdgeCount(v);
        if (n < 3 || n > kMaxValence || t_.vertexFaceCount(v) != n) return 0;
        const IndexSpan faces = t_.facesOfVertex(v);
        const int size = t_.faceSize(faces[0]);
        if (size != 3 && size != 4) return 0;
        for (int f : faces)
            if (t_.faceSize(f) != size) return 0;
        int count = 0;
        out[count++] = v;
        for (int e : t_.edgesOfVertex(v)) out[count++] = t_.otherVertex(e, v);
        if (size == 4) {  // then each quad's corner opposite v, in face order
            for (int f : faces) {
                const int diagonal = t_.verticesOfFace(f)[(t_.cornerOfVertex(f, v) + 2) % 4];
                // A diagonal that is also a neighbour or another face's diagonal would merge.
                for (int j = 1; j < count; ++j)
                    if (out[j] == diagonal) return 0;
                out[count++] = diagonal;
            }
        }
        key = 2 + (size == 3 ? 0 : kMaxValence + 1) + n;
        return count;
    }

    // Pool offset of the key's weights, kUnknown or kNever.
    int weights(int key) const { return weights_[key]; }
    void setWeights(int key, int offset) { weights_[key] = offset; }

private:
    const Topology& t_;
    std::vector<int> weights_;  // per key
};

}  // namespace v0
}  // namespace quadtri
