// Masks whose weights depend on a small key only, on a level without sharpness: the face point
// of a triangle or a quad (the centroid: ⅓ or ¼ each corner), the edge point of an edge between
// two triangles (Loop: 3/8, 3/8, 1/8, 1/8), the vertex point of a vertex whose n faces are all
// triangles (Loop, weights by n), and the same for quads (Catmull-Clark: an edge between two
// quads; a vertex whose n faces are all quads). After a level or two nearly every child of a
// pure or mostly pure mesh is one of these. The first mask of each key is built by the scheme's
// rules (rules.cpp); if they listed exactly the vertices gathered here, in the same order, its
// pooled weights serve every later mask of the key, which then only gathers its vertices: the
// table is the one the rules build, without their arithmetic.
#pragma once

#include <cstdint>
#include <vector>

#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

class RegularMasks {
public:
    static constexpr int kMaxValence = 16;
    static constexpr int kUnknown = -1;  // weights of the key not seen yet
    static constexpr int kNever = -2;    // the rules ordered the key's vertices otherwise

    explicit RegularMasks(const Topology& t) : t_(t), weights_(kKeys, kUnknown) {}

    // Gathers the vertices of a regular face, edge or vertex mask into `out` (room for
    // 2 * kMaxValence + 1) and returns their count, with `key` set; 0 when not regular.
    int face(int f, int* out, int& key) const {
        const IndexSpan corners = t_.verticesOfFace(f);
        const int n = corners.size();
        if (n != 3 && n != 4) return 0;
        // Repeated corners would merge entries: left to the rules.
        if (n == 3 ? !copyDistinct<3>(corners.begin(), out) : !copyDistinct<4>(corners.begin(), out)) return 0;
        key = kFaceKeys + (n == 3 ? 0 : 1);
        return n;
    }

    int edge(int e, int* out, int& key) const {
        if (t_.edgeFaceCount(e) != 2) return 0;
        const int a = t_.edgeVerts[2 * e], b = t_.edgeVerts[2 * e + 1];
        const int f0 = t_.facesOfEdge(e)[0], f1 = t_.facesOfEdge(e)[1];
        const int n = t_.faceSize(f0);
        if (n != t_.faceSize(f1) || (n != 3 && n != 4) || f0 == f1) return 0;
        const int* q0 = t_.verticesOfFace(f0).begin();
        const int* q1 = t_.verticesOfFace(f1).begin();
        const int count = n == 3 ? edgeOf<3>(a, b, q0, q1, out) : edgeOf<4>(a, b, q0, q1, out);
        if (count == 0) return 0;
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
        Seen seen;
        for (int e : t_.edgesOfVertex(v)) {
            const int neighbour = t_.otherVertex(e, v);
            seen.add(neighbour);
            out[count++] = neighbour;
        }
        if (size == 4) {  // then each quad's corner opposite v, in face order
            for (int f : faces) {
                // v's first corner in the quad, found without a branch per corner (where it sits
                // varies from face to face).
                const int* q = t_.verticesOfFace(f).begin();
                const int corner = q[0] == v ? 0 : q[1] == v ? 1 : q[2] == v ? 2 : 3;
                const int diagonal = q[(corner + 2) & 3];
                // A diagonal that is also a neighbour or another face's diagonal would merge.
                if (seen.mayHold(diagonal) && contains(out + 1, count - 1, diagonal)) return 0;
                seen.add(diagonal);
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
    // Keys: edges between two triangles / two quads (0, 1), vertices by face size and valence,
    // then faces of 3 and 4 corners.
    static constexpr int kFaceKeys = 2 + 2 * (kMaxValence + 1);
    static constexpr int kKeys = kFaceKeys + 2;

    // The vertices gathered so far, as one bit each of 64: a clear bit proves a vertex new, so
    // the search for a repeat runs only on a shared bit.
    class Seen {
    public:
        void add(int v) { bits_ |= bit(v); }
        bool mayHold(int v) const { return (bits_ & bit(v)) != 0; }

    private:
        // The top bits of a multiplicative hash: neighbouring indices, common in a ring, land
        // on different bits.
        static std::uint64_t bit(int v) { return std::uint64_t(1) << ((unsigned(v) * 0x9E3779B1u) >> 26); }
        std::uint64_t bits_ = 0;
    };
    // The N corners of q into out; false if one repeats.
    template <int N>
    static bool copyDistinct(const int* q, int* out) {
        bool repeat = false;  // without a branch per pair: repeats are rare
        for (int i = 0; i < N; ++i) {
            out[i] = q[i];
            for (int j = 0; j < i; ++j) repeat |= q[i] == q[j];
        }
        return !repeat;
    }
    // An edge (a, b) between faces q0 and q1 of N corners: a, b, then each face's other corners
    // in corner order; 0 if the faces share more than the edge (their entries would merge: left to
    // the rules).
    template <int N>
    static int edgeOf(int a, int b, const int* q0, const int* q1, int* out) {
        out[0] = a;
        out[1] = b;
        int count = 2;
        for (const int* q : {q0, q1})
            for (int i = 0; i < N; ++i) {  // without a branch: where a and b sit varies
                out[count] = q[i];
                count += int(q[i] != a) & int(q[i] != b);
            }
        bool repeat = false;
        for (int i = N; i < count; ++i)
            for (int j = 2; j < N; ++j) repeat |= out[i] == out[j];
        return repeat ? 0 : count;
    }
    static bool contains(const int* list, int n, int v) {
        for (int i = 0; i < n; ++i)
            if (list[i] == v) return true;
        return false;
    }

    const Topology& t_;
    std::vector<int> weights_;  // per key
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
