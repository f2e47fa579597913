// A patch around one vertex, cut out of its level and refined one level (far/limit/
// limit_deeper.h): the patch keeps the level's faces, holes, edge and vertex sharpness, so that
// inside its rim the refinement is the mesh's own.
#include "far/limit/limit_deeper.h"

#include <algorithm>
#include <cstring>

#include "far/schemes/crease.h"
#include "far/topology/refine_topology.h"
#include "far/tables/level_stencils.h"
#include "far/schemes/scheme.h"
#include "far/topology/topology_builder.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

void cutPatch(const Topology& t, IndexSpan seeds, int rings, WalkScratch& scratch, PatchCut& cut) {
    for (std::vector<int>* a :
         {&cut.source, &cut.faceSource, &cut.sizes, &cut.corners, &cut.creasePairs, &cut.holes, &cut.cornerVerts})
        a->clear();
    cut.creaseWeights.clear();
    cut.cornerWeights.clear();
    StampedMarks& local = scratch.vertices;  // value: the vertex's number in the patch
    StampedMarks& inside = scratch.faces;
    std::vector<int>& faces = scratch.faceList;
    local.clear(t.numVertices);
    inside.clear(t.numFaces());
    faces.clear();
    auto addVertex = [&](int v) {
        if (local.mark(v, int(cut.source.size()))) cut.source.push_back(v);
    };
    for (int v : seeds) addVertex(v);
    size_t reached = 0;
    for (int ring = 0; ring < rings; ++ring) {
        const size_t end = cut.source.size(), firstNew = faces.size();
        for (; reached < end; ++reached)
            for (int f : t.facesOfVertex(cut.source[reached]))
                if (inside.mark(f)) faces.push_back(f);
        for (size_t i = firstNew; i < faces.size(); ++i)  // the older faces' corners are in already
            for (int u : t.verticesOfFace(faces[i])) addVertex(u);
    }
    std::vector<int>& sharpEdges = scratch.sharpEdges;
    sharpEdges.clear();
    cut.sizes.resize(faces.size());
    std::size_t corners = 0;
    for (size_t i = 0; i < faces.size(); ++i) corners += cut.sizes[i] = t.faceSize(faces[i]);
    cut.corners.resize(corners);
    int* corner = cut.corners.data();
    for (size_t i = 0; i < faces.size(); ++i) {
        const int f = faces[i];
        for (int u : t.verticesOfFace(f)) *corner++ = local.value(u);
        if (t.faceHole[f]) cut.holes.push_back(int(i));
        for (int e : t.edgesOfFace(f))
            if (isSharp(t.edgeSharpness[e]) && !(t.edgeFlags[e] & kEdgeBoundary)) sharpEdges.push_back(e);
    }
    cut.faceSource.assign(faces.begin(), faces.end());
    std::sort(sharpEdges.begin(), sharpEdges.end());
    sharpEdges.erase(std::unique(sharpEdges.begin(), sharpEdges.end()), sharpEdges.end());
    for (int e : sharpEdges) {
        cut.creasePairs.push_back(local.value(t.edgeVerts[2 * e]));
        cut.creasePairs.push_back(local.value(t.edgeVerts[2 * e + 1]));
        cut.creaseWeights.push_back(t.edgeSharpness[e]);
    }
    for (size_t i = 0; i < cut.source.size(); ++i)
        if (isSharp(t.vertSharpness[cut.source[i]])) {
            cut.cornerVerts.push_back(int(i));
            cut.cornerWeights.push_back(t.vertSharpness[cut.source[i]]);
        }
}

void PatchCut::key(const Options& options, std::vector<int>& k) const {
    k.assign({int(source.size()), int(options.scheme), int(options.boundary), int(options.creaseMethod),
              options.smoothTriangles ? 1 : 0, options.leftHanded ? 1 : 0});
    auto ints = [&](const std::vector<int>& a) {
        k.push_back(int(a.size()));
        k.insert(k.end(), a.begin(), a.end());
    };
    auto floats = [&](const std::vector<float>& a) {
        k.push_back(int(a.size()));
        for (float x : a) {
            int bits;
            std::memcpy(&bits, &x, sizeof bits);
            k.push_back(bits);
        }
    };
    ints(sizes);
    ints(corners);
    ints(creasePairs);
    ints(holes);
    ints(cornerVerts);
    floats(creaseWeights);
    floats(cornerWeights);
}

Topology cutTopology(const PatchCut& cut, const Options& options) {
    TopologyDescriptor d;
    d.numVertices = int(cut.source.size());
    d.numFaces = int(cut.sizes.size());
    d.numVertsPerFace = cut.sizes.data();
    d.faceVertIndices = cut.corners.data();
    d.numCreases = int(cut.creaseWeights.size());
    d.creaseVertexPairs = cut.creasePairs.empty() ? nullptr : cut.creasePairs.data();
    d.creaseWeights = cut.creaseWeights.empty() ? nullptr : cut.creaseWeights.data();
    d.numCorners = int(cut.cornerVerts.size());
    d.cornerVertexIndices = cut.cornerVerts.empty() ? nullptr : cut.cornerVerts.data();
    d.cornerWeights = cut.cornerWeights.empty() ? nullptr : cut.cornerWeights.data();
    d.numHoles = int(cut.holes.size());
    d.holeIndices = cut.holes.empty() ? nullptr : cut.holes.data();
    return buildBaseTopology(d, options);
}

PatchStep refineCut(const PatchCut& cut, const Options& options) {
    PatchStep step;
    step.source = cut.source;
    const Topology patch = cutTopology(cut, options);
    const ChildNumbering num = numberChildren(patch, rulesOf(options.scheme).triangleSplit());
    step.table = buildLevelStencils<StencilTableD>(patch, num, options);
    step.child = refineTopology(patch, num, options.creaseMethod, TopologyDetail::Full);
    step.descendant = num.vertexPoint(0);
    return step;
}

PatchStep refinePatch(const Topology& t, int vertex, const Options& options, WalkScratch& scratch) {
    PatchCut cut;
    cutPatch(t, vertex, scratch, cut);
    return refineCut(cut, options);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
