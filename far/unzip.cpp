#include "far/internal/unzip.h"

#include <algorithm>

#include "far/internal/crease.h"
#include "far/internal/for_each.h"
#include "far/internal/fresh_pages.h"
#include "far/internal/level_estimate.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {

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

// Appends vertex v's copy for `piece`: v first, then its network neighbours in incidence order.
void appendCopy(const Topology& t, int v, Piece piece, StencilTableD& table) {
    const double sign = piece == Piece::Triangle ? 1.0 : -1.0;
    table.offsets.push_back(int(table.indices.size()));
    table.indices.push_back(v);
    table.weights.push_back(1.0);
    const std::size_t centre = table.weights.size() - 1;
    for (int e : t.edgesOfVertex(v)) {
        if (!isNetworkEdge(t, e)) continue;
        table.indices.push_back(t.otherVertex(e, v));
        table.weights.push_back(sign / 48.0);
        table.weights[centre] -= sign / 48.0;
    }
    table.sizes.push_back(int(table.indices.size()) - table.offsets.back());
}

bool anyNetworkEdge(const Topology& t) {
    for (int e = 0; e < t.numEdges(); ++e)
        if (isNetworkEdge(t, e)) return true;
    return false;
}

std::size_t countNetworkEdges(const Topology& t) {
    std::size_t count = 0;
    for (int e = 0; e < t.numEdges(); ++e) count += isNetworkEdge(t, e) ? 1 : 0;
    return count;
}

}  // namespace

UnzippedCopies unzipCopies(const Topology& t) {
    UnzippedCopies u;
    if (!anyNetworkEdge(t)) return u;  // a pure level: nothing splits
    // Which vertices split, each flagged by its own task; then their rows numbered in vertex order.
    assignFresh(u.splitting, std::size_t(t.numVertices), 0);
    forEach(t.numVertices, [&](int v) {
        if (keepsOnePosition(t, v)) return;
        for (int e : t.edgesOfVertex(v))
            if (isNetworkEdge(t, e)) {
                u.splitting[v] = 1;
                return;
            }
    });
    resizeFresh(u.rowOf, std::size_t(t.numVertices));
    int rows = 0;
    for (int v = 0; v < t.numVertices; ++v) u.rowOf[v] = u.splitting[v] ? rows++ : -1;
    for (Piece piece : {Piece::Triangle, Piece::Quad}) {
        StencilTableD& table = piece == Piece::Triangle ? u.triangle : u.quad;
        table.numSourceVertices = t.numVertices;
        table.sizes.reserve(rows);
        table.offsets.reserve(rows);
        for (int v = 0; v < t.numVertices; ++v)
            if (u.splitting[v]) appendCopy(t, v, piece, table);
    }
    return u;
}

std::size_t unzipBytesBound(const Topology& t) {
    // Each network edge puts an entry in the rows of both its ends; a splitting vertex has one.
    const std::size_t edges = t.edgeFlags.empty() ? edgeCountBound(t) : countNetworkEdges(t);
    if (edges == 0) return 0;
    const std::size_t rows = std::min<std::size_t>(std::size_t(t.numVertices), 2 * edges);
    const std::size_t entries = rows + 2 * edges;
    return std::size_t(t.numVertices) * (1 + sizeof(int)) + 2 * (rows * 2 * sizeof(int) + entries * (sizeof(int) + sizeof(double)));
}

}  // namespace v0
}  // namespace quadtri
