#include "far/unzip.h"

#include "far/crease.h"

namespace quadtri {

bool isNetworkEdge(const Topology& t, int e) { return (t.edgeFlags[e] & kEdgeSeam) && !isInfinite(t.edgeSharpness[e]); }

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
        for (int i = t.vertEdgeOffsets[v]; i < t.vertEdgeOffsets[v + 1]; ++i) {
            const int e = t.vertEdges[i];
            if (!isNetworkEdge(t, e)) continue;
            table.indices.push_back(t.otherVertex(e, v));
            table.weights.push_back(sign / 48.0);
            table.weights[centre] -= sign / 48.0;
        }
        table.sizes.push_back(int(table.indices.size()) - table.offsets.back());
    }
    return table;
}

}  // namespace quadtri
