// Reading a vertex of a level as a configuration (its fan, counter-clockwise) and labelling its
// ring neighbourhood in an order two equal configurations share (docs/limit_eigen.md).
#include <algorithm>
#include <utility>

#include "far/schemes/crease.h"
#include "far/limit/local_matrix.h"
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

std::string VertexConfiguration::key() const {
    std::string k;
    k += char('A' + int(scheme));
    k += char('a' + int(boundary));
    k += open ? 'o' : 'c';
    k += corner ? 'x' : '-';
    for (size_t i = 0; i < faceSizes.size(); ++i) k += faceSizes[i] == 3 ? 'T' : 'Q';
    k += ':';
    for (uint8_t s : sharpRays) k += s ? '1' : '0';
    return k;
}

namespace {

bool schemeHasConfigurations(Scheme scheme) {
    switch (scheme) {
    case Scheme::StamLoop:
    case Scheme::SchaeferWarren:
    case Scheme::CatmarkButterfly:
    case Scheme::CatmullClark:
    case Scheme::Loop: return true;
    case Scheme::Bilinear: return false;
    }
    return false;
}

bool isBoundaryEdge(const Topology& t, int e) { return t.edgeFaceCount(e) == 1; }

// The other face on edge e, or -1.
int acrossEdge(const Topology& t, int e, int face) {
    for (int g : t.facesOfEdge(e))
        if (g != face) return g;
    return -1;
}

// The rotation of a closed fan that lists it smallest (face size, ray sharpness) first.
int canonicalRotation(const VertexConfiguration& c) {
    const int n = int(c.faceSizes.size());
    auto less = [&](int r, int s) {
        for (int i = 0; i < n; ++i) {
            const auto a = std::make_pair(c.faceSizes[(r + i) % n], c.sharpRays[(r + i) % n]);
            const auto b = std::make_pair(c.faceSizes[(s + i) % n], c.sharpRays[(s + i) % n]);
            if (a != b) return a < b;
        }
        return false;
    };
    int best = 0;
    for (int r = 1; r < n; ++r)
        if (less(r, best)) best = r;
    return best;
}

}  // namespace

std::optional<VertexFan> fanOf(const Topology& t, int v, const Options& options) {
    if (!schemeHasConfigurations(options.scheme) || (t.vertFlags[v] & kVertexNonManifold)) return std::nullopt;
    const bool quadSplit = rulesOf(options.scheme).triangleSplit() == TriangleSplit::ThreeQuads;
    const IndexSpan around = t.facesOfVertex(v);
    if (around.size() == 0) return std::nullopt;
    for (int f : around) {
        const int n = t.faceSize(f);
        if ((n != 3 && n != 4) || t.faceHole[f] || (n == 3 && quadSplit)) return std::nullopt;
    }
    const bool open = (t.vertFlags[v] & kVertexBoundary) != 0;
    int start = around[0];
    if (open) {
        start = -1;
        for (int f : around)
            if (isBoundaryEdge(t, t.edgeOfCorner(f, t.cornerOfVertex(f, v)))) start = f;
        if (start < 0) return std::nullopt;
    }
    VertexFan fan;
    VertexConfiguration& c = fan.configuration;
    c.scheme = options.scheme;
    c.boundary = options.boundary;
    c.open = open;
    c.corner = isSharp(t.vertSharpness[v]);
    // Counter-clockwise: the next face shares this face's edge coming into v.
    for (int f = start;;) {
        const int corner = t.cornerOfVertex(f, v);
        fan.faces.push_back(f);
        fan.rays.push_back(t.edgeOfCorner(f, corner));
        const int incoming = t.edgeOfCorner(f, corner - 1);
        if (isBoundaryEdge(t, incoming)) {
            if (!open) return std::nullopt;
            fan.rays.push_back(incoming);
            break;
        }
        f = acrossEdge(t, incoming, f);
        if (f == start || int(fan.faces.size()) > around.size()) break;
    }
    if (int(fan.faces.size()) != around.size()) return std::nullopt;
    for (int f : fan.faces) c.faceSizes.push_back(uint8_t(t.faceSize(f)));
    for (int e : fan.rays) c.sharpRays.push_back(isSharp(t.edgeSharpness[e]) || isBoundaryEdge(t, e) ? 1 : 0);
    if (!open) {
        const int r = canonicalRotation(c);
        std::rotate(fan.faces.begin(), fan.faces.begin() + r, fan.faces.end());
        std::rotate(fan.rays.begin(), fan.rays.begin() + r, fan.rays.end());
        std::rotate(c.faceSizes.begin(), c.faceSizes.begin() + r, c.faceSizes.end());
        std::rotate(c.sharpRays.begin(), c.sharpRays.begin() + r, c.sharpRays.end());
    }
    return fan;
}

namespace {

int sharpnessClass(float s) { return isInfinite(s) ? 2 : isSharp(s) ? 1 : 0; }

// Marks in `scratch` the faces of `rings` face rings around v (the region) and their corners,
// those of the first `inner` rings with value 1.
void markRegion(const Topology& t, int v, int rings, int inner, WalkScratch& scratch) {
    std::vector<int>& vertices = scratch.vertexList;
    std::vector<int>& faces = scratch.faceList;
    StampedMarks &reachedVertices = scratch.vertices, &region = scratch.faces;
    vertices.assign(1, v);
    faces.clear();
    reachedVertices.clear(t.numVertices);
    region.clear(t.numFaces());
    reachedVertices.mark(v, 1);
    size_t reached = 0;  // vertices before this index have had their faces added
    for (int ring = 0; ring < rings; ++ring) {
        const size_t end = vertices.size(), firstNew = faces.size();
        for (; reached < end; ++reached)
            for (int f : t.facesOfVertex(vertices[reached]))
                if (region.mark(f)) faces.push_back(f);
        for (size_t i = firstNew; i < faces.size(); ++i)
            for (int u : t.verticesOfFace(faces[i]))
                if (reachedVertices.mark(u, ring < inner ? 1 : 0)) vertices.push_back(u);
    }
}

}  // namespace

// Breadth first over the faces of rings + 1 face rings; each face is entered at a known corner
// (the start face at v, a neighbour at the end of the edge it was reached across), and its
// corners and edges are read counter-clockwise from there, so the labels depend on the faces
// only. The signature numbers every vertex met; `vertices` keeps those of the first `rings`.
bool gatherNeighbourhood(const Topology& t, int v, int startFace, int rings, WalkScratch& scratch,
                         Neighbourhood& n, const std::vector<int>* expected) {
    markRegion(t, v, rings + 1, rings, scratch);
    n.vertices.clear();
    n.signature.clear();
    bool differs = false;  // from `expected`, somewhere in the signature so far
    auto see = [&](int x) {
        const size_t at = n.signature.size();
        n.signature.push_back(x);
        if (expected && (at >= expected->size() || (*expected)[at] != x)) differs = true;
    };
    scratch.labels.clear(t.numVertices);
    int labelled = 0;
    auto label = [&](int u) {
        if (scratch.labels.mark(u, labelled)) {
            ++labelled;
            if (scratch.vertices.marked(u) && scratch.vertices.value(u) == 1) n.vertices.push_back(u);
            see(sharpnessClass(t.vertSharpness[u]));
        }
        return scratch.labels.value(u);
    };
    label(v);
    StampedMarks& region = scratch.faces;
    region.setValue(startFace, 1);
    std::vector<std::pair<int, int>>& queue = scratch.queue;  // first in, first out from `head`
    queue.assign(1, {startFace, t.cornerOfVertex(startFace, v)});
    for (size_t head = 0; head < queue.size(); ++head) {
        const auto [f, entry] = queue[head];
        const IndexSpan corners = t.verticesOfFace(f);
        const int size = corners.size();
        see(-size);
        for (int i = 0; i < size; ++i) see(label(corners[(entry + i) % size]));
        for (int i = 0; i < size; ++i) {
            const int e = t.edgeOfCorner(f, entry + i);
            see(sharpnessClass(t.edgeSharpness[e]) * 4 + std::min(t.edgeFaceCount(e), 3));
            for (int g : t.facesOfEdge(e)) {
                if (g == f || !region.marked(g) || region.value(g) == 1) continue;
                region.setValue(g, 1);
                queue.push_back({g, t.cornerOfVertex(g, corners[(entry + i + 1) % size])});
            }
        }
        if (differs) return false;
    }
    return true;
}

Neighbourhood gatherNeighbourhood(const Topology& t, int v, int startFace, int rings) {
    WalkScratch scratch;
    Neighbourhood n;
    gatherNeighbourhood(t, v, startFace, rings, scratch, n);
    return n;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
