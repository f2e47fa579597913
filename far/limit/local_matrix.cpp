// The local subdivision matrix of a configuration (docs/limit_eigen.md, "The local matrix"): a
// mesh of regular sectors around one vertex (a quad sector a grid, a triangle sector a
// triangular lattice), refined one level by the scheme's own masks; S is the children of the
// ring neighbourhood N over N, its rows checked to read nothing outside N.
#include <cmath>
#include <map>
#include <tuple>

#include "far/limit/local_matrix.h"
#include "far/topology/refine_topology.h"
#include "far/tables/level_stencils.h"
#include "far/schemes/scheme.h"
#include "far/topology/topology_builder.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// A configuration's sectors, `radius` edges along each ray. Vertex (s, a, b) of sector s lies at
// a steps along ray s and b along ray s + 1; (s, 0, b) and (s + 1, b, 0) are one vertex.
class FanMesh {
public:
    FanMesh(const VertexConfiguration& c, int radius) : c_(c), radius_(radius) {
        const int sectors = int(c.faceSizes.size());
        vertex(0, 0, 0);
        for (int s = 0; s < sectors; ++s) {
            const bool quad = c.faceSizes[s] == 4;
            for (int i = 0; i < radius; ++i)
                for (int j = 0; j < radius; ++j) {
                    if (quad) {
                        cells_[{s, i, j}] = int(sizes_.size());
                        addFace({vertex(s, i, j), vertex(s, i + 1, j), vertex(s, i + 1, j + 1), vertex(s, i, j + 1)});
                    } else if (i + j < radius) {
                        addFace({vertex(s, i, j), vertex(s, i + 1, j), vertex(s, i, j + 1)});
                        if (i + j + 1 < radius)
                            addFace({vertex(s, i + 1, j), vertex(s, i + 1, j + 1), vertex(s, i, j + 1)});
                    }
                }
        }
        for (int r = 0; r < c.numRays(); ++r) {
            if (!c.sharpRays[r]) continue;
            for (int a = 0; a < radius; ++a) {
                creasePairs_.push_back(vertex(r, a, 0));
                creasePairs_.push_back(vertex(r, a + 1, 0));
                creaseWeights_.push_back(kInfiniteSharpness);
            }
        }
        // Sector angles as in a regular layout (π/2 a quad, π/3 a triangle), scaled to close the
        // fan, or to at most 3π/2 when it is open.
        double total = 0;
        for (uint8_t n : c.faceSizes) total += n == 4 ? kPi / 2 : kPi / 3;
        const double scale = c.open ? std::min(1.0, 1.5 * kPi / total) : 2 * kPi / total;
        double angle = 0;
        for (int r = 0; r <= sectors; ++r) {
            rayAngles_.push_back(angle);
            if (r < sectors) angle += scale * (c.faceSizes[r] == 4 ? kPi / 2 : kPi / 3);
        }
    }

    TopologyDescriptor descriptor() const {
        TopologyDescriptor d;
        d.numVertices = int(coords_.size());
        d.numFaces = int(sizes_.size());
        d.numVertsPerFace = sizes_.data();
        d.faceVertIndices = verts_.data();
        d.numCreases = int(creaseWeights_.size());
        d.creaseVertexPairs = creasePairs_.empty() ? nullptr : creasePairs_.data();
        d.creaseWeights = creaseWeights_.empty() ? nullptr : creaseWeights_.data();
        d.numCorners = c_.corner ? 1 : 0;
        d.cornerVertexIndices = c_.corner ? &kCentre : nullptr;
        d.cornerWeights = c_.corner ? &kInfinite : nullptr;
        return d;
    }

    // The vertex at (s, a, b), created on first use.
    int vertex(int s, int a, int b) {
        const auto key = canonical(s, a, b);
        const auto it = ids_.find(key);
        if (it != ids_.end()) return it->second;
        const int id = int(coords_.size());
        ids_[key] = id;
        coords_.push_back(key);
        return id;
    }
    int find(int s, int a, int b) const { return ids_.at(canonical(s, a, b)); }
    std::tuple<int, int, int> coordinates(int id) const { return coords_[id]; }
    bool isQuad(int s) const { return c_.faceSizes[s] == 4; }
    int cell(int s, int i, int j) const { return cells_.at({s, i, j}); }
    int startFace() const { return 0; }  // sector 0's cell at the centre
    // The vertex's position in the plane layout.
    void place(int id, double* xy) const {
        const auto [s, a, b] = coords_[id];
        xy[0] = a * std::cos(rayAngles_[s]) + b * std::cos(rayAngles_[s + 1]);
        xy[1] = a * std::sin(rayAngles_[s]) + b * std::sin(rayAngles_[s + 1]);
    }

private:
    static constexpr double kPi = 3.14159265358979323846;
    static constexpr int kCentre = 0;
    static constexpr float kInfinite = kInfiniteSharpness;

    std::tuple<int, int, int> canonical(int s, int a, int b) const {
        const int sectors = int(c_.faceSizes.size());
        if (a == 0 && b == 0) return {0, 0, 0};
        if (a == 0 && (s + 1 < sectors || !c_.open)) return {(s + 1) % sectors, b, 0};
        return {s, a, b};
    }
    void addFace(std::initializer_list<int> corners) {
        sizes_.push_back(int(corners.size()));
        verts_.insert(verts_.end(), corners.begin(), corners.end());
    }

    const VertexConfiguration& c_;
    int radius_;
    std::map<std::tuple<int, int, int>, int> ids_, cells_;
    std::vector<std::tuple<int, int, int>> coords_;
    std::vector<int> sizes_, verts_, creasePairs_;
    std::vector<float> creaseWeights_;
    std::vector<double> rayAngles_;
};

// The level-1 vertex at coordinates (a, b) of sector s of the child lattice: the vertex point
// of (a/2, b/2), the edge point of the edge through the midpoint, or a quad's face point.
int childAt(const FanMesh& m, const Topology& t, const ChildNumbering& num, int s, int a, int b) {
    if (a % 2 == 0 && b % 2 == 0) return num.vertexPoint(m.find(s, a / 2, b / 2));
    if (a % 2 == 1 && b % 2 == 1 && m.isQuad(s)) return num.facePoint[m.cell(s, a / 2, b / 2)];
    int u, w;
    if (a % 2 == 1 && b % 2 == 1) {  // a triangle's diagonal
        u = m.find(s, (a + 1) / 2, (b - 1) / 2);
        w = m.find(s, (a - 1) / 2, (b + 1) / 2);
    } else if (a % 2 == 1) {
        u = m.find(s, a / 2, b / 2);
        w = m.find(s, a / 2 + 1, b / 2);
    } else {
        u = m.find(s, a / 2, b / 2);
        w = m.find(s, a / 2, b / 2 + 1);
    }
    return num.edgePoint(findEdge(t, u, w));
}

}  // namespace

std::optional<LocalMatrix> buildLocalMatrix(const VertexConfiguration& c, const Options& options) {
    Options o = options;
    o.scheme = c.scheme;
    o.boundary = c.boundary;
    o.leftHanded = false;  // the fan is built counter-clockwise
    for (int rings = 1; rings <= kMaxLocalRings; ++rings) {
        // The masks of N's children read a few rings beyond N at most; the fan's own boundary
        // lies well past that.
        FanMesh mesh(c, 2 * rings + 4);
        const Topology t = buildBaseTopology(mesh.descriptor(), o);
        const ChildNumbering num = numberChildren(t, rulesOf(c.scheme).triangleSplit());
        const StencilTableD table = buildLevelStencils<StencilTableD>(t, num, o);
        const Neighbourhood n = gatherNeighbourhood(t, 0, mesh.startFace(), rings);
        const int size = int(n.vertices.size());
        std::vector<int> local(size_t(t.numVertices), -1);
        for (int i = 0; i < size; ++i) local[n.vertices[i]] = i;
        LocalMatrix m;
        m.rings = rings;
        m.size = size;
        m.S.assign(size_t(size) * size, 0.0);
        m.layout.resize(2 * size_t(size));
        bool closed = true;
        for (int i = 0; i < size && closed; ++i) {
            mesh.place(n.vertices[i], &m.layout[2 * i]);
            const auto [s, a, b] = mesh.coordinates(n.vertices[i]);
            const int child = childAt(mesh, t, num, s, a, b);
            for (int k = table.offsets[child]; k < table.offsets[child] + table.sizes[child]; ++k) {
                const int col = local[table.indices[k]];
                if (col < 0 && std::fabs(table.weights[k]) > 1e-12) closed = false;
                if (col >= 0) m.S[size_t(i) * size + col] += table.weights[k];
            }
        }
        if (!closed) continue;
        m.signature = n.signature;
        return m;
    }
    return std::nullopt;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
