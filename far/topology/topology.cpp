// Connectivity from face-vertex lists: edges, incidences and boundary / non-manifold / seam flags.
#include <quadtri/far/topology.h>

#include "far/topology/face_loops.h"
#include "far/internal/for_each.h"
#include "far/schemes/scheme.h"
#include "far/topology/topology_builder.h"

#include <algorithm>
#include <string>
#include <utility>

namespace quadtri {
inline namespace v0 {

using namespace internal;

const char* toString(BoundaryInterpolation boundary) {
    switch (boundary) {
    case BoundaryInterpolation::EdgeOnly: return "edge-only";
    case BoundaryInterpolation::EdgeAndCorner: return "edge-and-corner";
    case BoundaryInterpolation::None: return "none";
    }
    return "?";
}

const char* toString(CreaseMethod method) {
    switch (method) {
    case CreaseMethod::Uniform: return "uniform";
    case CreaseMethod::Chaikin: return "chaikin";
    }
    return "?";
}

std::string TopologyDiagnostic::message() const {
    static const char* const names[] = {"", "face", "crease", "corner", "hole"};
    std::string text;
    if (component != Component::None) text = std::string(names[int(component)]) + " " + std::to_string(index) + ": ";
    if (vertex >= 0) text += "vertex " + std::to_string(vertex) + " ";
    return text + problem;
}

MemoryBudgetError::MemoryBudgetError(std::string subject, std::size_t needed, std::size_t held, std::size_t budget)
    : TopologyError(subject + " needs at least " + std::to_string(needed) + " bytes with the " + std::to_string(held) +
                    " the Refiner holds, over the budget of " + std::to_string(budget) +
                    " bytes (Options::memoryBudgetBytes)"),
      subject_(std::move(subject)), needed_(needed), held_(held), budget_(budget) {}

std::size_t bytesOf(const Topology& t) {
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return bytes(t.faceOffsets) + bytes(t.faceVerts) + bytes(t.faceEdges) + bytes(t.faceHole) + bytes(t.edgeVerts) +
           bytes(t.edgeFaceOffsets) + bytes(t.edgeFaces) + bytes(t.edgeSharpness) + bytes(t.edgeFlags) +
           bytes(t.vertFaceOffsets) + bytes(t.vertFaces) + bytes(t.vertEdgeOffsets) + bytes(t.vertEdges) +
           bytes(t.vertSharpness) + bytes(t.vertFlags);
}

VertexFaceCounts countVertexFaces(const Topology& t, int v) {
    VertexFaceCounts counts;
    for (int f : t.facesOfVertex(v)) {
        if (t.faceSize(f) == 3)
            ++counts.triangles;
        else
            ++counts.quads;
    }
    return counts;
}

namespace {

// Prefix sums turning per-item counts (stored at [i+1]) into CSR offsets.
void countsToOffsets(std::vector<int>& offsets) {
    for (size_t i = 1; i < offsets.size(); ++i) offsets[i] += offsets[i - 1];
}

// Edges keyed by their lower vertex: corners are bucketed by min(a, b) with a counting sort,
// and within a bucket each upper vertex remembers its edge (a pole's bucket holds thousands, so
// no linear search there). No hashing, no maps. A collapsed edge (a corner followed by the same
// vertex, kept by schemes that read faces as OpenSubdiv does) is an edge of its own in every
// face, as OpenSubdiv makes it: it joins nothing.
void buildEdges(Topology& t) {
    const int nv = t.numVertices;
    const int nc = t.numFaceVertices();
    std::vector<int> cornerNext;
    cornerNext.resize(std::size_t(nc));
    for (int f = 0; f < t.numFaces(); ++f) {
        const int b = t.faceOffsets[f], n = t.faceSize(f);
        for (int i = 0; i < n; ++i) cornerNext[b + i] = t.faceVerts[i + 1 == n ? b : b + i + 1];
    }
    std::vector<int> bucketOffsets;
    bucketOffsets.assign(std::size_t(nv) + 1, 0);
    for (int c = 0; c < nc; ++c) ++bucketOffsets[std::min(t.faceVerts[c], cornerNext[c]) + 1];
    countsToOffsets(bucketOffsets);
    std::vector<int> bucket;
    bucket.resize(std::size_t(nc));
    {
        std::vector<int> fill(bucketOffsets.begin(), bucketOffsets.end() - 1);
        for (int c = 0; c < nc; ++c) bucket[fill[std::min(t.faceVerts[c], cornerNext[c])]++] = c;
    }
    t.faceEdges.assign(std::size_t(nc), -1);
    t.edgeVerts.clear();
    t.edgeVerts.reserve(std::size_t(nc));  // about nc/2 edges for closed meshes, nc for open ones
    std::vector<int> edgeToHi;
    edgeToHi.assign(std::size_t(nv), -1);  // edge (lo, hi) of the current bucket lo, or one of an earlier bucket
    for (int lo = 0; lo < nv; ++lo) {
        const int firstEdge = t.numEdges();
        for (int k = bucketOffsets[lo]; k < bucketOffsets[lo + 1]; ++k) {
            const int c = bucket[k];
            const int hi = std::max(t.faceVerts[c], cornerNext[c]);
            if (hi == lo) {
                t.faceEdges[c] = t.numEdges();
                t.edgeVerts.push_back(lo);
                t.edgeVerts.push_back(hi);
                continue;
            }
            int& e = edgeToHi[hi];
            if (e < firstEdge) {
                e = t.numEdges();
                t.edgeVerts.push_back(lo);
                t.edgeVerts.push_back(hi);
            }
            t.faceEdges[c] = e;
        }
    }
}

// Face f's edge from v to its next corner.
int edgeFrom(const Topology& t, int f, int v) { return t.edgeOfCorner(f, t.cornerOfVertex(f, v)); }

// Whether face f runs along edge e from its first vertex to its second. Found by the edge, not by
// the vertex: a face with a collapsed edge holds a vertex twice.
bool runsForward(const Topology& t, int f, int e) { return t.verticesOfFace(f)[t.cornerOfEdge(f, e)] == t.edgeVerts[2 * e]; }

void flagEdges(Topology& t) {
    const int ne = t.numEdges();
    t.edgeFlags.assign(std::size_t(ne), 0);
    forEach(ne, [&t](int e) {
        const IndexSpan faces = t.facesOfEdge(e);
        const int nf = faces.size();
        if (t.edgeVerts[2 * e] == t.edgeVerts[2 * e + 1]) {
            t.edgeFlags[e] |= kEdgeBoundary | kEdgeNonManifold;  // a collapsed edge, as OpenSubdiv tags it
        } else if (nf == 1) {
            t.edgeFlags[e] |= kEdgeBoundary;
        } else if (nf > 2) {
            t.edgeFlags[e] |= kEdgeNonManifold;
        } else {
            // Two faces crossing the edge the same way disagree on orientation: not a manifold pair.
            const bool sameWay = runsForward(t, faces[0], e) == runsForward(t, faces[1], e);
            if (sameWay || faces[0] == faces[1]) {
                t.edgeFlags[e] |= kEdgeNonManifold;
            } else if ((t.faceSize(faces[0]) == 3) != (t.faceSize(faces[1]) == 3)) {
                t.edgeFlags[e] |= kEdgeSeam;
            }
        }
    });
}

// The faces of a manifold vertex form one fan: walk it face to face across manifold edges.
bool isSingleFan(const Topology& t, int v, int boundaryEdges) {
    const IndexSpan faces = t.facesOfVertex(v);
    const int nf = faces.size();
    if (nf == 0) return true;
    auto outgoing = [&](int f) { return edgeFrom(t, f, v); };
    auto incoming = [&](int f) { return t.edgeOfCorner(f, t.cornerOfVertex(f, v) - 1); };
    int start = faces[0];
    if (boundaryEdges == 2) {  // start at the face whose incoming edge is on the boundary
        for (int i = 0; i < nf; ++i)
            if (t.edgeFlags[incoming(faces[i])] & kEdgeBoundary) start = faces[i];
    }
    int f = start, visited = 0;
    while (visited <= nf) {
        ++visited;
        const int e = outgoing(f);
        if (t.edgeFlags[e] & kEdgeBoundary) break;
        const IndexSpan ef = t.facesOfEdge(e);
        f = ef[0] == f ? ef[1] : ef[0];
        if (f == start) break;
    }
    return visited == nf;
}

void flagVertices(Topology& t) {
    const int nv = t.numVertices;
    t.vertFlags.assign(std::size_t(nv), 0);
    forEach(nv, [&t](int v) {
        int boundary = 0;
        uint8_t flags = 0;
        for (int e : t.edgesOfVertex(v)) {
            const uint8_t ef = t.edgeFlags[e];
            boundary += (ef & kEdgeBoundary) ? 1 : 0;
            if (ef & kEdgeNonManifold) flags |= kVertexNonManifold;
            if (ef & kEdgeSeam) flags |= kVertexSeam;
        }
        if (boundary > 0) flags |= kVertexBoundary;
        const int nf = t.vertexFaceCount(v), ne = t.vertexEdgeCount(v);
        if (!(flags & kVertexNonManifold)) {
            const bool counts = boundary == 0 ? ne == nf : (boundary == 2 && ne == nf + 1);
            if (!counts || !isSingleFan(t, v, boundary)) flags |= kVertexNonManifold;
        }
        if (nf == 1 && ne == 2) flags |= kVertexCorner;
        t.vertFlags[v] = flags;
    });
}

}  // namespace

void internal::buildIncidences(Topology& t) {
    const int nv = t.numVertices, ne = t.numEdges(), nf = t.numFaces();
    t.edgeFaceOffsets.assign(std::size_t(ne) + 1, 0);
    for (int e : t.faceEdges) ++t.edgeFaceOffsets[e + 1];
    countsToOffsets(t.edgeFaceOffsets);
    t.edgeFaces.resize(t.faceEdges.size());
    t.vertFaceOffsets.assign(std::size_t(nv) + 1, 0);
    for (int v : t.faceVerts) ++t.vertFaceOffsets[v + 1];
    countsToOffsets(t.vertFaceOffsets);
    t.vertFaces.resize(t.faceVerts.size());
    {
        std::vector<int> edgeFill(t.edgeFaceOffsets.begin(), t.edgeFaceOffsets.end() - 1);
        std::vector<int> vertFill(t.vertFaceOffsets.begin(), t.vertFaceOffsets.end() - 1);
        for (int f = 0; f < nf; ++f)
            for (int c = t.faceOffsets[f]; c < t.faceOffsets[f + 1]; ++c) {
                t.edgeFaces[edgeFill[t.faceEdges[c]]++] = f;
                t.vertFaces[vertFill[t.faceVerts[c]]++] = f;
            }
    }
    t.vertEdgeOffsets.assign(std::size_t(nv) + 1, 0);
    for (int v : t.edgeVerts) ++t.vertEdgeOffsets[v + 1];
    countsToOffsets(t.vertEdgeOffsets);
    t.vertEdges.resize(t.edgeVerts.size());
    std::vector<int> fill(t.vertEdgeOffsets.begin(), t.vertEdgeOffsets.end() - 1);
    for (int e = 0; e < ne; ++e) {
        t.vertEdges[fill[t.edgeVerts[2 * e]]++] = e;
        t.vertEdges[fill[t.edgeVerts[2 * e + 1]]++] = e;
    }
}

void internal::completeTopology(Topology& t) {
    buildEdges(t);
    completeTopologyFromEdges(t);
}

int findEdge(const Topology& t, int a, int b) {
    if (t.vertexEdgeCount(a) > t.vertexEdgeCount(b)) std::swap(a, b);  // scan the shorter list
    for (int e : t.edgesOfVertex(a))
        if (t.otherVertex(e, a) == b) return e;
    return -1;
}

namespace {

std::string describeLoops(const FaceLoops& loops) {
    if (loops.repeated < 0) return "has fewer than 3 distinct corners: no area, left out";
    std::string text = "appears again further on: the face pinches there";
    if (loops.loops == 0) return text + " into pieces of fewer than 3 corners; no area, left out";
    text += " and is read as " + std::to_string(loops.loops) + (loops.loops == 1 ? " face" : " faces");
    if (loops.leftOut > 0) text += " (" + std::to_string(loops.leftOut) + " piece of fewer than 3 corners left out)";
    return text;
}

}  // namespace

float internal::ruledEdgeSharpness(const Topology& t, int e, float sharpness) {
    return (t.edgeFlags[e] & (kEdgeBoundary | kEdgeNonManifold)) ? kInfiniteSharpness : sharpness;
}

float internal::ruledVertexSharpness(const Topology& t, int v, const Options& options, float sharpness) {
    const uint8_t flags = t.vertFlags[v];
    if ((flags & kVertexCorner) && options.boundary == BoundaryInterpolation::EdgeAndCorner) {
        sharpness = kInfiniteSharpness;
    } else if (flags & kVertexNonManifold) {
        // A non-manifold crease (two opposing non-manifold edges carrying extra fins, no
        // boundary) stays a crease; every other non-manifold vertex becomes a corner.
        int nonManifoldEdges = 0;
        for (int e : t.edgesOfVertex(v)) nonManifoldEdges += (t.edgeFlags[e] & kEdgeNonManifold) ? 1 : 0;
        const bool nonManifoldCrease =
            nonManifoldEdges == 2 && !(flags & kVertexBoundary) && t.vertexFaceCount(v) > t.vertexEdgeCount(v);
        if (!nonManifoldCrease) sharpness = kInfiniteSharpness;
    }
    if (t.vertexFaceCount(v) == 0) sharpness = kInfiniteSharpness;  // isolated: stays put
    return sharpness;
}

bool internal::ruledHole(const Topology& t, int f, const Options& options, bool given) {
    if (given || options.boundary != BoundaryInterpolation::None) return given;
    for (int v : t.verticesOfFace(f))
        if ((t.vertFlags[v] & kVertexBoundary) && t.vertSharpness[v] < kInfiniteSharpness) return true;
    return false;
}

void internal::applyBoundaryRules(Topology& t, const Options& options) {
    // Boundary and non-manifold edges are infinitely sharp.
    forEach(t.numEdges(), [&t](int e) { t.edgeSharpness[e] = ruledEdgeSharpness(t, e, t.edgeSharpness[e]); });
    forEach(t.numVertices, [&t, &options](int v) { t.vertSharpness[v] = ruledVertexSharpness(t, v, options, t.vertSharpness[v]); });
    if (options.boundary == BoundaryInterpolation::None) {
        for (int v = 0; v < t.numVertices; ++v) {
            if (!(t.vertFlags[v] & kVertexBoundary) || t.vertSharpness[v] >= kInfiniteSharpness) continue;
            for (int f : t.facesOfVertex(v)) t.faceHole[f] = 1;
        }
    }
}

void internal::completeTopologyFromEdges(Topology& t) {
    buildIncidences(t);
    flagEdges(t);
    flagVertices(t);
    t.edgeSharpness.assign(std::size_t(t.numEdges()), 0.0f);
    t.vertSharpness.assign(std::size_t(t.numVertices), 0.0f);
    t.faceHole.resize(std::size_t(t.numFaces()));
}

Topology internal::buildBaseTopology(const TopologyDescriptor& desc, const Options& options,
                                     std::vector<TopologyDiagnostic>* warnings, std::vector<uint8_t>* givenHoles) {
    validateDescriptor(desc);
    // Level 0 and its scratch: per vertex its incidence offsets, flags, sharpness and edge
    // buckets; per corner its face, edge and incidence entries and at most one edge. Checked
    // before anything is allocated: a descriptor's counts need not match what its arrays hold.
    std::size_t corners = 0;
    for (int f = 0; f < desc.numFaces; ++f) corners += std::size_t(desc.numVertsPerFace[f]);
    const std::size_t estimate = std::size_t(desc.numVertices) * 32 + corners * 64 + std::size_t(desc.numFaces) * 16;
    if (estimate > options.memoryBudgetBytes) throw MemoryBudgetError("level 0", estimate, 0, options.memoryBudgetBytes);
    const SchemeRules& rules = rulesOf(options.scheme);
    // As the descriptor has it, before collapsed corners are merged: OpenSubdiv refuses `1 2 3 3`
    // under Loop too.
    if (!rules.acceptsNonTriangles()) {
        for (int f = 0; f < desc.numFaces; ++f)
            if (desc.numVertsPerFace[f] != 3)
                throw TopologyError({TopologyDiagnostic::Component::Face, f, -1,
                                     "has " + std::to_string(desc.numVertsPerFace[f]) + " corners; the " +
                                         rules.name() + " scheme takes triangles only"});
    }
    if (options.smoothTriangles && !rules.acceptsSmoothTriangles())
        throw TopologyError(std::string("smooth triangles (Options::smoothTriangles) are a catmull-clark rule; ") +
                            rules.name() + " has none");
    Topology t;
    t.numVertices = desc.numVertices;
    // Faces become the simple loops they walk around (face_loops.h); firstFace maps each face of
    // the descriptor to its loops, for holes.
    // A face's loops keep at most its corners, and most faces are one loop: sized once, the arrays
    // are not copied as they grow (a million-face cage's faceVerts would be, about twenty times).
    std::vector<int> sizes, firstFace;
    firstFace.assign(size_t(desc.numFaces) + 1, 0);
    sizes.reserve(size_t(desc.numFaces));
    t.faceVerts.reserve(corners);
    FaceLoopSplitter splitter(desc.numVertices, rules.collapsedEdges());
    const int* verts = desc.faceVertIndices;
    for (int f = 0; f < desc.numFaces; ++f) {
        const int n = desc.numVertsPerFace[f];
        const FaceLoops loops = splitter.split(verts, n, t.faceVerts, sizes);
        verts += n;
        firstFace[size_t(f) + 1] = int(sizes.size());
        if (warnings && (loops.repeated >= 0 || loops.loops == 0))
            warnings->push_back({TopologyDiagnostic::Component::Face, f, loops.repeated,
                                 describeLoops(loops)});
    }
    t.faceOffsets.assign(sizes.size() + 1, 0);
    for (std::size_t f = 0; f < sizes.size(); ++f) t.faceOffsets[f + 1] = t.faceOffsets[f] + sizes[f];
    if (options.leftHanded) {  // store counter-clockwise: keep the first corner, reverse the rest
        for (int f = 0; f < t.numFaces(); ++f)
            std::reverse(t.faceVerts.begin() + t.faceOffsets[f] + 1, t.faceVerts.begin() + t.faceOffsets[f + 1]);
    }
    completeTopology(t);

    for (int i = 0; i < desc.numCreases; ++i) {
        const int a = desc.creaseVertexPairs[2 * i], b = desc.creaseVertexPairs[2 * i + 1];
        const int e = findEdge(t, a, b);
        if (e < 0) {  // as OpenSubdiv: said, and ignored
            if (warnings)
                warnings->push_back({TopologyDiagnostic::Component::Crease, i, -1,
                                     "vertices " + std::to_string(a) + ", " + std::to_string(b) +
                                         " are not an edge of the mesh; crease ignored"});
            continue;
        }
        t.edgeSharpness[e] = desc.creaseWeights[i];
    }
    for (int i = 0; i < desc.numCorners; ++i) t.vertSharpness[desc.cornerVertexIndices[i]] = desc.cornerWeights[i];
    for (int i = 0; i < desc.numHoles; ++i) {
        const int f = desc.holeIndices[i];
        std::fill(t.faceHole.begin() + firstFace[size_t(f)], t.faceHole.begin() + firstFace[size_t(f) + 1], uint8_t(1));
    }

    if (givenHoles) *givenHoles = t.faceHole;
    applyBoundaryRules(t, options);
    return t;
}

}  // namespace v0
}  // namespace quadtri
