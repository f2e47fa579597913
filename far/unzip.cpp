#include "far/internal/unzip.h"

#include "far/internal/crease.h"
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

}  // namespace

StencilTableD unzipStencils(const Topology& t, Piece piece) {
    const double sign = piece == Piece::Triangle ? 1.0 : -1.0;
    StencilTableD table;
    table.numSourceVertices = t.numVertices;
    table.sizes.reserve(t.numVertices);
    table.offsets.reserve(t.numVertices);
    for (int v = 0; v < t.numVertices; ++v) {
        table.offsets.push_back(int(table.indices.size()));
        table.indices.push_back(v);
        table.weights.push_back(1.0);
        const int centre = int(table.weights.size()) - 1;
        if (keepsOnePosition(t, v)) {
            table.sizes.push_back(1);
            continue;
        }
        for (int e : t.edgesOfVertex(v)) {
            if (!isNetworkEdge(t, e)) continue;
            table.indices.push_back(t.otherVertex(e, v));
            table.weights.push_back(sign / 48.0);
            table.weights[centre] -= sign / 48.0;
        }
        table.sizes.push_back(int(table.indices.size()) - table.offsets.back());
    }
    return table;
}

}  // namespace v0
}  // namespace quadtri
