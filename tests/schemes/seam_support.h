// Shared by the Schaefer-Warren tests: scheme options and double-precision evaluation of the
// analyzer's own double tables.
#pragma once

#include <queue>
#include <vector>

#include "far/topology/refine_topology.h"
#include <quadtri/far/refiner.h>
#include "far/tables/level_stencils.h"
#include "far/schemes/scheme.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri::test {

using namespace quadtri::internal;

inline Options schemeOptions(Scheme scheme) {
    Options o;
    o.scheme = scheme;
    return o;
}

inline std::vector<double> applyTable(const StencilTableD& table, const std::vector<double>& src, int width) {
    std::vector<double> out(table.sizes.size() * size_t(width), 0.0);
    for (size_t i = 0; i < table.sizes.size(); ++i)
        for (int k = 0; k < table.sizes[i]; ++k) {
            const int j = table.offsets[i] + k;
            const double w = table.weights[size_t(j)];
            const size_t s = size_t(table.indices[size_t(j)]) * size_t(width);
            for (int c = 0; c < width; ++c) out[i * size_t(width) + size_t(c)] += w * src[s + size_t(c)];
        }
    return out;
}

// Level L (>= 1) of the refiner's topology as a double table built by the analyzer's builder.
inline StencilTableD doubleLevelTable(const Refiner& refiner, int L) {
    const Topology& parent = refiner.level(L - 1);
    const ChildNumbering numbering = numberChildren(parent, rulesOf(refiner.options().scheme).triangleSplit());
    return buildLevelStencils<StencilTableD>(parent, numbering, refiner.options());
}

// Graph distance of every vertex from a seed set, over the edges of `t`.
inline std::vector<int> bfsDistance(const Topology& t, const std::vector<int>& seeds) {
    std::vector<int> d(size_t(t.numVertices), -1);
    std::queue<int> queue;
    for (int s : seeds)
        if (d[size_t(s)] < 0) {
            d[size_t(s)] = 0;
            queue.push(s);
        }
    while (!queue.empty()) {
        const int v = queue.front();
        queue.pop();
        for (int i = t.vertEdgeOffsets[v]; i < t.vertEdgeOffsets[v + 1]; ++i) {
            const int w = t.otherVertex(t.vertEdges[i], v);
            if (d[size_t(w)] < 0) {
                d[size_t(w)] = d[size_t(v)] + 1;
                queue.push(w);
            }
        }
    }
    return d;
}

}  // namespace quadtri::test
