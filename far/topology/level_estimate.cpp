#include "far/topology/level_estimate.h"
#include "far/internal/parallel.h"


namespace quadtri {
inline namespace v0 {
namespace internal {

std::size_t edgeCountBound(const Topology& p) {
    return p.edgeVerts.empty() ? p.faceVerts.size() : std::size_t(p.numEdges());
}

std::size_t estimateLevelBytes(const Topology& p, const SchemeRules& rules) {
    const bool triangleInFour = rules.triangleSplit() == TriangleSplit::FourTriangles;
    std::size_t faces = 0, corners = 0, entries = 0, facePoints = 0;
    for (int f = 0; f < p.numFaces(); ++f) {
        const std::size_t n = p.faceSize(f);
        const bool inFour = n == 3 && triangleInFour;
        faces += inFour ? 4 : n;
        corners += inFour ? 12 : 4 * n;
        facePoints += inFour ? 0 : 1;
        // Each face contributes its corners to its face point and to the masks of its edges'
        // and vertices' points.
        entries += n + 2 * n * n;
    }
    const std::size_t parentEdges = edgeCountBound(p);
    const std::size_t edges = 2 * parentEdges + corners / 4;
    const std::size_t vertices = facePoints + parentEdges + p.numVertices;
    entries += 4 * parentEdges + p.numVertices;
    const std::size_t topologyBytes = corners * 16 + edges * 25 + vertices * 22 + faces * 5;
    // An index per entry and two offsets per stencil (weights are pooled), twice over: the parts
    // built by other threads are copied into the table (buildLevelStencils).
    const std::size_t tableBytes = tableEntryBytes(entries) + 2 * vertices * 8;
    const std::size_t outputBytes = vertices * 3 * sizeof(float);
    // Per thread, a sparse accumulator over the parent's vertices.
    const std::size_t threads = std::size_t(parallel::arenaThreads());
    const std::size_t scratchBytes = threads * std::size_t(p.numVertices) * 16;
    return topologyBytes + tableBytes + outputBytes + scratchBytes + rules.extraLevelBytes(p);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
