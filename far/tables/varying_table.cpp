// Varying stencils (docs/varying.md): the same children as the scheme's level, in the same
// order, each a linear interpolation of its parents, so per-vertex data that must not be
// smoothed (colours, skinning weights, ids blended linearly) follows the refined mesh.
#include "far/tables/varying_table.h"

#include <array>
#include <vector>

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// One stencil: the mean of `parents`.
template <class Range>
void appendMean(StencilTableD& t, const Range& parents) {
    t.offsets.push_back(int(t.indices.size()));
    t.sizes.push_back(int(parents.size()));
    for (int v : parents) {
        t.indices.push_back(v);
        t.weights.push_back(1.0 / double(parents.size()));
    }
}

}  // namespace

StencilTableD buildVaryingStencils(const Topology& parent, const ChildNumbering& numbering) {
    StencilTableD t;
    t.numSourceVertices = parent.numVertices;
    const int numChildren = numbering.numFacePoints + parent.numEdges() + parent.numVertices;
    t.sizes.reserve(numChildren);
    t.offsets.reserve(numChildren);
    // Face points come first, in the order numbering gives them (face order, skipping the faces
    // that have none).
    std::vector<int> faceOfPoint(numbering.numFacePoints, -1);
    for (int f = 0; f < parent.numFaces(); ++f)
        if (numbering.facePoint[f] >= 0) faceOfPoint[numbering.facePoint[f]] = f;
    for (int f : faceOfPoint) appendMean(t, parent.verticesOfFace(f));
    for (int e = 0; e < parent.numEdges(); ++e)
        appendMean(t, std::array<int, 2>{parent.edgeVerts[2 * e], parent.edgeVerts[2 * e + 1]});
    for (int v = 0; v < parent.numVertices; ++v) appendMean(t, std::array<int, 1>{v});
    return t;
}

std::size_t varyingStencilBytes(const Topology& parent, const ChildNumbering& numbering) {
    const std::size_t stencils = std::size_t(numbering.numFacePoints) + parent.numEdges() + parent.numVertices;
    const std::size_t entries = parent.faceVerts.size() + 2 * std::size_t(parent.numEdges()) + parent.numVertices;
    return stencils * 2 * sizeof(int) + entries * (sizeof(int) + sizeof(double));
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
