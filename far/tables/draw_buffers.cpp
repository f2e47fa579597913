// Draw buffers (docs/draw_buffers.md): one pass over the faces' corners welds equal
// (vertex, values) combinations through a short list per vertex (a vertex has one draw vertex
// away from seams and a few on them), then the faces are cut into triangles.
#include <quadtri/far/draw_buffers.h>

#include <string>

#include <quadtri/far/options.h>

namespace quadtri {
inline namespace v0 {

namespace {

// The draw vertex of corner `c` (vertex v), made if its combination is new. Draw vertices of v
// are chained from first[v] through next[].
int drawVertexOf(int v, int c, const std::vector<const int*>& cornerValues, std::vector<int>& first,
                 std::vector<int>& next, DrawBuffers& out) {
    const std::size_t channels = cornerValues.size();
    for (int d = first[v]; d >= 0; d = next[d]) {
        std::size_t k = 0;
        while (k < channels && out.valueOf[k][d] == cornerValues[k][c]) ++k;
        if (k == channels) return d;
    }
    const int d = out.numVertices();
    out.vertexOf.push_back(v);
    for (std::size_t k = 0; k < channels; ++k) out.valueOf[k].push_back(cornerValues[k][c]);
    next.push_back(first[v]);
    first[v] = d;
    return d;
}

}  // namespace

DrawBuffers buildDrawBuffers(const LevelFaces& faces, const std::vector<const int*>& cornerValues,
                             const std::vector<int>& numValues) {
    if (numValues.size() != cornerValues.size())
        throw TopologyError("draw buffers: " + std::to_string(numValues.size()) + " value counts for " +
                            std::to_string(cornerValues.size()) + " channels");
    DrawBuffers out;
    out.valueOf.resize(cornerValues.size());
    out.numLevelVertices = faces.numVertices();
    out.numChannelValues = numValues;
    std::vector<int> first(faces.numVertices(), -1), next;
    std::vector<int> drawn;  // the current face's draw vertices
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        const int start = faces.offsets()[f], n = faces.faceSize(f);
        drawn.clear();
        for (int i = 0; i < n; ++i) {
            const int c = start + i;
            for (std::size_t k = 0; k < cornerValues.size(); ++k)
                if (cornerValues[k][c] < 0 || cornerValues[k][c] >= numValues[k])
                    throw TopologyError(TopologyDiagnostic{TopologyDiagnostic::Component::Face, f, -1,
                                                           "channel " + std::to_string(k) + " value " +
                                                               std::to_string(cornerValues[k][c]) +
                                                               " is out of range [0, " + std::to_string(numValues[k]) + ")"});
            drawn.push_back(drawVertexOf(faces.vertices()[c], c, cornerValues, first, next, out));
        }
        for (int i = 2; i < n; ++i)
            out.triangles.insert(out.triangles.end(), {std::uint32_t(drawn[0]), std::uint32_t(drawn[i - 1]),
                                                       std::uint32_t(drawn[i])});
    }
    return out;
}

StencilTable DrawBuffers::gatherStencils(int channel) const {
    if (channel < -1 || channel >= int(valueOf.size()))
        throw TopologyError("draw buffers: no channel " + std::to_string(channel) + " (there are " +
                            std::to_string(valueOf.size()) + ")");
    const std::vector<int>& source = channel < 0 ? vertexOf : valueOf[channel];
    StencilTable t;
    t.numSourceVertices = channel < 0 ? numLevelVertices : numChannelValues[channel];
    t.indices = source;
    t.offsets.resize(source.size() + 1);
    for (std::size_t i = 0; i <= source.size(); ++i) t.offsets[i] = int(i);
    t.weightOffsets.assign(source.size(), 0);  // every stencil reads the one pooled weight
    t.weights = {1.0f};
    return t;
}

}  // namespace v0
}  // namespace quadtri
