// A patch around one vertex, cut out of its level and refined one level (far/internal/
// limit_deeper.h): the patch keeps the level's faces, holes, edge and vertex sharpness, so that
// inside its rim the refinement is the mesh's own.
#include "far/internal/limit_deeper.h"

#include <algorithm>
#include <unordered_map>

#include "far/internal/crease.h"
#include "far/internal/refine_topology.h"
#include "far/internal/rules.h"
#include "far/internal/scheme.h"
#include "far/internal/topology_builder.h"

namespace quadtri {
inline namespace v0 {

PatchStep refinePatch(const Topology& t, int vertex, const Options& options) {
    PatchStep step;
    std::unordered_map<int, int> local;
    std::vector<int> faces;
    std::vector<uint8_t> inPatch(size_t(t.numFaces()), 0);
    auto addVertex = [&](int v) {
        if (local.emplace(v, int(step.source.size())).second) step.source.push_back(v);
    };
    addVertex(vertex);
    size_t reached = 0;
    for (int ring = 0; ring < kPatchRings; ++ring) {
        const size_t end = step.source.size();
        for (; reached < end; ++reached)
            for (int f : t.facesOfVertex(step.source[reached]))
                if (!inPatch[f]) {
                    inPatch[f] = 1;
                    faces.push_back(f);
                }
        for (size_t i = 0; i < faces.size(); ++i)
            for (int u : t.verticesOfFace(faces[i])) addVertex(u);
    }
    std::vector<int> sizes, corners, creasePairs, holes, cornerVerts;
    std::vector<float> creaseWeights, cornerWeights;
    std::vector<int> sharpEdges;
    for (size_t i = 0; i < faces.size(); ++i) {
        const int f = faces[i];
        sizes.push_back(t.faceSize(f));
        for (int u : t.verticesOfFace(f)) corners.push_back(local.at(u));
        if (t.faceHole[f]) holes.push_back(int(i));
        for (int e : t.edgesOfFace(f))
            if (isSharp(t.edgeSharpness[e])) sharpEdges.push_back(e);
    }
    std::sort(sharpEdges.begin(), sharpEdges.end());
    sharpEdges.erase(std::unique(sharpEdges.begin(), sharpEdges.end()), sharpEdges.end());
    for (int e : sharpEdges) {
        creasePairs.push_back(local.at(t.edgeVerts[2 * e]));
        creasePairs.push_back(local.at(t.edgeVerts[2 * e + 1]));
        creaseWeights.push_back(t.edgeSharpness[e]);
    }
    for (size_t i = 0; i < step.source.size(); ++i)
        if (isSharp(t.vertSharpness[step.source[i]])) {
            cornerVerts.push_back(int(i));
            cornerWeights.push_back(t.vertSharpness[step.source[i]]);
        }
    TopologyDescriptor d;
    d.numVertices = int(step.source.size());
    d.numFaces = int(sizes.size());
    d.numVertsPerFace = sizes.data();
    d.faceVertIndices = corners.data();
    d.numCreases = int(creaseWeights.size());
    d.creaseVertexPairs = creasePairs.empty() ? nullptr : creasePairs.data();
    d.creaseWeights = creaseWeights.empty() ? nullptr : creaseWeights.data();
    d.numCorners = int(cornerVerts.size());
    d.cornerVertexIndices = cornerVerts.empty() ? nullptr : cornerVerts.data();
    d.cornerWeights = cornerWeights.empty() ? nullptr : cornerWeights.data();
    d.numHoles = int(holes.size());
    d.holeIndices = holes.empty() ? nullptr : holes.data();
    const Topology patch = buildBaseTopology(d, options);
    const ChildNumbering num = numberChildren(patch, rulesOf(options.scheme).triangleSplit());
    step.table = buildLevelStencils<StencilTableD>(patch, num, options);
    step.child = refineTopology(patch, num, options.creaseMethod, TopologyDetail::Full);
    step.descendant = num.vertexPoint(0);
    return step;
}

}  // namespace v0
}  // namespace quadtri
