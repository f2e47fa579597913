// `quadtri info`'s face-varying report: where a channel is cut at level 0.
#include <algorithm>
#include <vector>

#include <quadtri/far/refiner.h>
#include "tools/commands.h"

namespace quadtri::cli {

FVarSeams countFVarSeams(const Refiner& refiner, int channel) {
    const Topology& t = refiner.level(0);
    auto valueAt = [&](int f, int v) { return refiner.fvarValuesOfFace(channel, 0, f)[t.cornerOfVertex(f, v)]; };
    FVarSeams seams;
    for (int e = 0; e < t.numEdges(); ++e) {
        const IndexSpan faces = t.facesOfEdge(e);
        const int a = t.edgeVerts[2 * std::size_t(e)], b = t.edgeVerts[2 * std::size_t(e) + 1];
        const bool cut = std::any_of(faces.begin(), faces.end(), [&](int f) {
            return valueAt(f, a) != valueAt(faces[0], a) || valueAt(f, b) != valueAt(faces[0], b);
        });
        seams.edges += cut;
    }
    std::vector<int> values;
    for (int v = 0; v < t.numVertices; ++v) {
        values.clear();
        for (int f : t.facesOfVertex(v)) values.push_back(valueAt(f, v));
        std::sort(values.begin(), values.end());
        seams.vertices += std::unique(values.begin(), values.end()) - values.begin() > 1;
    }
    return seams;
}

}  // namespace quadtri::cli
