#include "far/refine_topology.h"

#include "far/crease.h"

namespace quadtri {

ChildNumbering numberChildren(const Topology& parent) {
    ChildNumbering n;
    n.facePoint.assign(parent.numFaces(), -1);
    for (int f = 0; f < parent.numFaces(); ++f)
        if (parent.faceSize(f) != 3) n.facePoint[f] = n.numFacePoints++;
    n.numEdges = parent.numEdges();
    return n;
}

namespace {

void addChildFaces(const Topology& p, const ChildNumbering& num, Topology& c) {
    int childFaces = 0, childCorners = 0;
    for (int f = 0; f < p.numFaces(); ++f) {
        const int n = p.faceSize(f);
        childFaces += n == 3 ? 4 : n;
        childCorners += n == 3 ? 12 : 4 * n;
    }
    c.faceOffsets.assign(1, 0);
    c.faceOffsets.reserve(childFaces + 1);
    c.faceVerts.clear();
    c.faceVerts.reserve(childCorners);
    c.faceHole.clear();
    c.faceHole.reserve(childFaces);
    auto close = [&](uint8_t hole) {
        c.faceOffsets.push_back(int(c.faceVerts.size()));
        c.faceHole.push_back(hole);
    };
    for (int f = 0; f < p.numFaces(); ++f) {
        const int b = p.faceOffsets[f], n = p.faceSize(f);
        const uint8_t hole = p.faceHole[f];
        // Corner i's child keeps the parent's orientation: vertex i, edge i (towards corner i+1),
        // [centroid], edge i-1 (from corner i-1).
        for (int i = 0; i < n; ++i) {
            const int prev = (i + n - 1) % n;
            c.faceVerts.push_back(num.vertexPoint(p.faceVerts[b + i]));
            c.faceVerts.push_back(num.edgePoint(p.faceEdges[b + i]));
            if (n != 3) c.faceVerts.push_back(num.facePoint[f]);
            c.faceVerts.push_back(num.edgePoint(p.faceEdges[b + prev]));
            close(hole);
        }
        if (n == 3) {
            for (int i = 0; i < 3; ++i) c.faceVerts.push_back(num.edgePoint(p.faceEdges[b + i]));
            close(hole);
        }
    }
}

// Child edges of parent edges inherit decayed sharpness (Chaikin per end); edges inside faces
// are smooth. Child vertices of parent vertices inherit uniformly decayed vertex sharpness.
void inheritSharpness(const Topology& p, const ChildNumbering& num, CreaseMethod method, Topology& c) {
    std::vector<float> childSharpness;
    for (int v = 0; v < p.numVertices; ++v) {
        c.vertSharpness[num.vertexPoint(v)] = decrementSharpness(p.vertSharpness[v]);
        const int n = p.vertexEdgeCount(v);
        childSharpness.resize(n);
        childEdgeSharpnessAtVertex(p, v, method, childSharpness.data());
        for (int i = 0; i < n; ++i) {
            if (childSharpness[i] <= 0.0f) continue;
            const int e = p.vertEdges[p.vertEdgeOffsets[v] + i];
            c.edgeSharpness[findEdge(c, num.vertexPoint(v), num.edgePoint(e))] = childSharpness[i];
        }
    }
}

}  // namespace

Topology refineTopology(const Topology& parent, const ChildNumbering& numbering, CreaseMethod creaseMethod) {
    Topology child;
    child.numVertices = numbering.numFacePoints + parent.numEdges() + parent.numVertices;
    addChildFaces(parent, numbering, child);
    std::vector<uint8_t> holes = std::move(child.faceHole);
    completeTopology(child);
    child.faceHole = std::move(holes);
    inheritSharpness(parent, numbering, creaseMethod, child);
    return child;
}

}  // namespace quadtri
