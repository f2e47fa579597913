// What a scheme's limit masks read and write (docs/limit.md): one vertex of a level with its
// neighbourhood in rotational order, and the three weight sets (position, dU, dV) over one support.
#pragma once

#include <vector>

#include "far/schemes/crease.h"
#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

// A vertex's faces and edges in rotational order, counter-clockwise seen from outside (Topology
// stores every face so, left-handed input reversed): face i lies between
// edges[i] (the edge that leaves the vertex in face i's winding) and edges[i + 1] (the edge that
// enters it; edges[0] again for an interior vertex).
//   - interior manifold vertex: faces.size() == edges.size(); where the ring starts is chosen as
//     OpenSubdiv chooses it (far/limit/limit_ring.h), which decides the side a crease's normal
//     is taken on and a corner's tangents;
//   - boundary manifold vertex: edges.size() == faces.size() + 1, edges[0] and edges.back() the
//     boundary edges;
//   - non-manifold vertex (manifold == false): faces and edges in Topology's incidence order,
//     with no rotational meaning.
// neighbours[i] is edges[i]'s other end, opposite[i] face i's corner two after the vertex (a
// quad's diagonal corner): the two vertex lists OpenSubdiv's limit masks weigh.
struct VertexRing {
    int vertex = -1;
    bool manifold = true;
    bool boundary = false;
    std::vector<int> faces;
    std::vector<int> edges;
    std::vector<int> neighbours;
    std::vector<int> opposite;
    std::vector<float> edgeSharpness;  // per edges[i], at this level
};

// Position, dU and dV weights over one support; add() merges a vertex that appears twice.
class LimitMask {
public:
    void clear() {
        indices.clear();
        position.clear();
        du.clear();
        dv.clear();
    }
    void add(int vertex, double p, double u, double v) {
        for (std::size_t k = 0; k < indices.size(); ++k)
            if (indices[k] == vertex) {
                position[k] += p;
                du[k] += u;
                dv[k] += v;
                return;
            }
        indices.push_back(vertex);
        position.push_back(p);
        du.push_back(u);
        dv.push_back(v);
    }
    int size() const { return int(indices.size()); }

    // The closed forms' layout, every weight 0: the vertex, then ring.neighbours, then
    // ring.opposite (slots 0, 1 + i, 1 + edges + i), to be written by slot.
    void startRing(const VertexRing& ring) {
        clear();
        indices.push_back(ring.vertex);
        indices.insert(indices.end(), ring.neighbours.begin(), ring.neighbours.end());
        indices.insert(indices.end(), ring.opposite.begin(), ring.opposite.end());
        position.assign(indices.size(), 0.0);
        du.assign(indices.size(), 0.0);
        dv.assign(indices.size(), 0.0);
    }
    // After startRing: merges the slots of a vertex that appears twice and drops slots that weigh
    // nothing, keeping the first-appearance order.
    void finishRing() {
        int kept = 0;
        for (int k = 0; k < size(); ++k) {
            int j = 0;
            while (j < kept && indices[j] != indices[k]) ++j;
            if (j < kept) {
                position[j] += position[k];
                du[j] += du[k];
                dv[j] += dv[k];
            } else if (k == 0 || position[k] != 0.0 || du[k] != 0.0 || dv[k] != 0.0) {
                indices[kept] = indices[k];
                position[kept] = position[k];
                du[kept] = du[k];
                dv[kept] = dv[k];
                ++kept;
            }
        }
        indices.resize(kept);
        position.resize(kept);
        du.resize(kept);
        dv.resize(kept);
    }

    std::vector<int> indices;
    std::vector<double> position, du, dv;
};

// What a scheme's limit hook reads: the level, its options, the vertex's ordered ring and rule.
struct LimitVertex {
    const Topology& level;
    const Options& options;
    const VertexRing& ring;
    VertexRule rule;
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
