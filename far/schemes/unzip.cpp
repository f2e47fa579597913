#include "far/schemes/unzip.h"

#include <algorithm>

#include "far/schemes/crease.h"
#include "far/internal/for_each.h"
#include "far/topology/level_estimate.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

bool isNetworkEdge(const Topology& t, int e) { return (t.edgeFlags[e] & kEdgeSeam) && !isInfinite(t.edgeSharpness[e]); }

namespace {

// A crease or corner whose creases are semi-sharp keeps its own position: its child follows the
// crease rule from the original points, and copies displaced off the crease would tilt the faces
// beside it a little more each level (the rook's crease corners folded so, 105° to 150° over
// levels 1-5). Where every crease is infinitely sharp (boundaries) the seam's end is unzipped as
// before: no test mesh folds there, and quadratic precision at the seam is tested with it.
bool keepsOnePosition(const Topology& t, int v) {
    int sharp = 0;
    bool semiSharp = false;
    for (int e : t.edgesOfVertex(v)) {
        const float s = t.edgeSharpness[e];
        sharp += isSharp(s) ? 1 : 0;
        semiSharp = semiSharp || isSemiSharp(s);
    }
    return sharp >= 2 && semiSharp;
}

// Writes row `row` (sized already): vertex v, then the far ends of its network edges in incidence
// order, with each piece's weights.
void writeRow(const Topology& t, int v, int row, UnzippedCopies& u) {
    const std::size_t first = std::size_t(u.offsets[row]);
    int* indices = u.indices.data() + first;
    double* triangle = u.triangleWeights.data() + first;
    double* quad = u.quadWeights.data() + first;
    indices[0] = v;
    triangle[0] = quad[0] = 1.0;
    int k = 1;
    for (int e : t.edgesOfVertex(v)) {
        if (!isNetworkEdge(t, e)) continue;
        indices[k] = t.otherVertex(e, v);
        triangle[k] = 1.0 / 48.0;
        quad[k++] = -1.0 / 48.0;
        triangle[0] -= 1.0 / 48.0;
        quad[0] += 1.0 / 48.0;
    }
}

std::size_t countNetworkEdges(const Topology& t) {
    std::size_t count = 0;
    for (int e = 0; e < t.numEdges(); ++e) count += isNetworkEdge(t, e) ? 1 : 0;
    return count;
}

}  // namespace

UnzippedCopies unzipCopies(const Topology& t) {
    UnzippedCopies u;
    if (countNetworkEdges(t) == 0) return u;  // a pure level: nothing splits
    // Each vertex's network edges counted by its own task (a vertex that keeps one position has
    // none that count), then the rows numbered and sized in vertex order, then written on the
    // threads: arrays of their exact size, no growth.
    u.rowOf.resize(std::size_t(t.numVertices));
    forEach(t.numVertices, [&](int v) {
        int count = 0;
        if (!keepsOnePosition(t, v))
            for (int e : t.edgesOfVertex(v)) count += isNetworkEdge(t, e) ? 1 : 0;
        u.rowOf[v] = count;
    });
    u.splitting.assign(std::size_t(t.numVertices), 0);
    u.offsets.push_back(0);
    for (int v = 0; v < t.numVertices; ++v) {
        const int count = u.rowOf[v];
        if (count == 0) {
            u.rowOf[v] = -1;
            continue;
        }
        u.splitting[v] = 1;
        u.rowOf[v] = int(u.offsets.size()) - 1;
        u.offsets.push_back(u.offsets.back() + 1 + count);
    }
    const std::size_t entries = std::size_t(u.offsets.back());
    u.indices.resize(entries);
    u.triangleWeights.resize(entries);
    u.quadWeights.resize(entries);
    forEach(t.numVertices, [&](int v) {
        if (u.splitting[v]) writeRow(t, v, u.rowOf[v], u);
    });
    return u;
}

UnzippedCopies unzipCopies(const Topology& t, const std::vector<int>& vertices) {
    UnzippedCopies u;
    std::vector<int> counts;
    for (int v : vertices) {
        int count = 0;
        if (!keepsOnePosition(t, v))
            for (int e : t.edgesOfVertex(v)) count += isNetworkEdge(t, e) ? 1 : 0;
        counts.push_back(count);
    }
    if (std::all_of(counts.begin(), counts.end(), [](int c) { return c == 0; })) return u;
    u.rowOf.assign(std::size_t(t.numVertices), -1);
    u.splitting.assign(std::size_t(t.numVertices), 0);
    u.offsets.push_back(0);
    for (std::size_t k = 0; k < vertices.size(); ++k) {
        if (counts[k] == 0) continue;
        u.splitting[std::size_t(vertices[k])] = 1;
        u.rowOf[std::size_t(vertices[k])] = int(u.offsets.size()) - 1;
        u.offsets.push_back(u.offsets.back() + 1 + counts[k]);
    }
    const std::size_t entries = std::size_t(u.offsets.back());
    u.indices.resize(entries);
    u.triangleWeights.resize(entries);
    u.quadWeights.resize(entries);
    for (int v : vertices)
        if (u.splitting[std::size_t(v)]) writeRow(t, v, u.rowOf[std::size_t(v)], u);
    return u;
}

std::size_t unzipBytesBound(const Topology& t) {
    // Each network edge puts an entry in the rows of both its ends; a splitting vertex has one.
    const std::size_t edges = t.edgeFlags.empty() ? edgeCountBound(t) : countNetworkEdges(t);
    if (edges == 0) return 0;
    const std::size_t rows = std::min<std::size_t>(std::size_t(t.numVertices), 2 * edges);
    const std::size_t entries = rows + 2 * edges;
    return std::size_t(t.numVertices) * (1 + sizeof(int)) + (rows + 1) * sizeof(int) +
           entries * (sizeof(int) + 2 * sizeof(double));
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
