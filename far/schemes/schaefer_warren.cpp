#include <algorithm>

#include "far/limit/limit_closed_forms.h"
#include "far/schemes/schaefer_warren.h"

#include "far/internal/for_each.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

std::vector<int> verticesOf(const Topology& t, const std::vector<int>& faces) {
    std::vector<int> vertices;
    for (int f : faces)
        for (int v : t.verticesOfFace(f)) vertices.push_back(v);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    return vertices;
}

}  // namespace

UnzippedLevel::UnzippedLevel(const Topology& t, const std::vector<int>* faces)
    : copies(faces ? unzipCopies(t, verticesOf(t, *faces)) : unzipCopies(t)) {
    if (copies.splitting.empty()) return;
    faceTouches.assign(std::size_t(t.numFaces()), 0);
    auto touch = [&](int f) {
        for (int v : t.verticesOfFace(f))
            if (copies.splits(v)) {
                faceTouches[f] = 1;
                return;
            }
    };
    if (faces)
        for (int f : *faces) touch(f);
    else
        forEach(t.numFaces(), touch);
}

SchaeferWarrenMasks::SchaeferWarrenMasks(const Topology& topology, const UnzippedLevel& unzipped,
                                         SparseAccumulator& accumulator)
    : StamLoopMasks(topology, accumulator), u_(unzipped) {}

bool SchaeferWarrenMasks::touchesEdge(int e) const {
    for (int f : t_.facesOfEdge(e))
        if (touchesFace(f)) return true;
    return false;
}

bool SchaeferWarrenMasks::touchesVertex(int v) const {
    for (int f : t_.facesOfVertex(v))
        if (touchesFace(f)) return true;
    return false;
}

void SchaeferWarrenMasks::addCopy(int v, bool quad, double scale) {
    if (!u_.copies.splits(v)) quad = false;  // both copies are v itself: one term
    for (Copy& c : copies_)
        if (c.vertex == v && c.quad == quad) {
            c.weight += scale;
            return;
        }
    copies_.push_back({v, quad, scale});
}

void SchaeferWarrenMasks::flushCopies() {
    for (const Copy& c : copies_) {
        if (!u_.copies.splits(c.vertex)) {  // the copy is the vertex with weight 1
            acc_.add(c.vertex, c.weight);
            continue;
        }
        // The copy's bounds read once: the accumulator's int stores could otherwise change them.
        const int row = u_.copies.rowOf[c.vertex];
        const int first = u_.copies.offsets[row], last = u_.copies.offsets[row + 1];
        const int* indices = u_.copies.indices.data();
        const double* weights = u_.copies.weightsOf(c.quad ? Piece::Quad : Piece::Triangle).data();
        for (int k = first; k < last; ++k) acc_.add(indices[k], c.weight * weights[k]);
    }
    copies_.clear();
}

void SchaeferWarrenMasks::addPoint(Point p, bool quad, double scale) {
    switch (p.kind) {
    case Point::Vertex: addCopy(p.index, quad, scale); break;
    case Point::Edge:
        addCopy(t_.edgeVerts[2 * p.index], quad, 0.5 * scale);
        addCopy(t_.edgeVerts[2 * p.index + 1], quad, 0.5 * scale);
        break;
    case Point::Face: {  // only quads and n-gons have centres
        const IndexSpan corners = t_.verticesOfFace(p.index);
        for (int v : corners) addCopy(v, true, scale / corners.size());
        break;
    }
    }
}

void SchaeferWarrenMasks::addCentroid(const Point* c, int count, double scale) {
    if (count == 4) {
        for (int i = 0; i < 4; ++i) addPoint(c[i], true, 0.25 * scale);
    } else {
        addPoint(c[0], false, 0.25 * scale);
        addPoint(c[1], false, 0.375 * scale);
        addPoint(c[2], false, 0.375 * scale);
    }
}

// The n child quads around the centre, each weighing ½ (s = n/2). Faces without a vertex on the
// network keep the centroid.
void SchaeferWarrenMasks::facePoint(int f, double scale) {
    if (!touchesFace(f)) return centroid(f, scale);
    const IndexSpan corners = t_.verticesOfFace(f);
    const int n = corners.size();
    const Point centre{Point::Face, f};
    for (int i = 0; i < n; ++i) {
        const Point quad[4] = {centre, {Point::Edge, t_.edgeOfCorner(f, i - 1)}, {Point::Vertex, corners[i]},
                               {Point::Edge, t_.edgeOfCorner(f, i)}};
        addCentroid(quad, 4, scale / n);
    }
    flushCopies();
}

// Each quad-like face gives two child quads (½ each), each triangle three child triangles (⅓
// each): s = number of faces. Next to an n-gon the child quad's corner diagonal to the midpoint
// is replaced by the n-gon's centre, which gives Catmull-Clark's edge rule there.
void SchaeferWarrenMasks::smoothEdgePoint(int e, double scale) {
    if (!touchesEdge(e)) return StamLoopMasks::smoothEdgePoint(e, scale);
    const double s = t_.edgeFaceCount(e);
    const Point mid{Point::Edge, e};
    for (int f : t_.facesOfEdge(e)) {
        const IndexSpan corners = t_.verticesOfFace(f);
        const int n = corners.size(), i = t_.cornerOfEdge(f, e);
        const Point here{Point::Vertex, corners[i]}, next{Point::Vertex, corners[(i + 1) % n]};
        const Point prevEdge{Point::Edge, t_.edgeOfCorner(f, i - 1)}, nextEdge{Point::Edge, t_.edgeOfCorner(f, i + 1)};
        if (n == 3) {
            const Point a[3] = {mid, here, prevEdge}, c[3] = {mid, next, nextEdge}, centre[3] = {mid, nextEdge, prevEdge};
            for (const Point* tri : {a, c, centre}) addCentroid(tri, 3, scale / (3 * s));
        } else {
            const Point centre{Point::Face, f};
            const Point a[4] = {mid, here, n == 4 ? prevEdge : centre, centre};
            const Point c[4] = {mid, next, n == 4 ? nextEdge : centre, centre};
            addCentroid(a, 4, scale / (2 * s));
            addCentroid(c, 4, scale / (2 * s));
        }
    }
    flushCopies();
}

// avg over the child faces at v, then v2 = v0 + (1 + η) 2sα (avg − v0) with α = 1/(1 + nE/2 + nQ/4).
void SchaeferWarrenMasks::smoothVertexPoint(int v, double scale) {
    if (!touchesVertex(v)) return StamLoopMasks::smoothVertexPoint(v, scale);
    const VertexFaceCounts counts = countVertexFaces(t_, v);
    const int nE = t_.vertexEdgeCount(v);
    const double s = 0.5 * counts.quads + counts.triangles / 3.0;
    const double alpha = 1.0 / (1.0 + 0.5 * nE + 0.25 * counts.quads);
    const double k = (1.0 + stamLoopEta(nE, counts.quads, counts.triangles)) * 2.0 * s * alpha;
    const Point vertex{Point::Vertex, v};
    for (int f : t_.facesOfVertex(v)) {
        const int i = t_.cornerOfVertex(f, v);
        const Point next{Point::Edge, t_.edgeOfCorner(f, i)}, prev{Point::Edge, t_.edgeOfCorner(f, i - 1)};
        if (t_.faceSize(f) == 3) {
            const Point tri[3] = {vertex, next, prev};
            addCentroid(tri, 3, scale * k / (3 * s));
        } else {
            const Point quad[4] = {vertex, next, {Point::Face, f}, prev};
            addCentroid(quad, 4, scale * k / (2 * s));
        }
    }
    flushCopies();
    acc_.add(v, scale * (1.0 - k));
}

namespace {

class SchaeferWarrenRules : public SchemeRules {
public:
    SurfacePatches surfacePatches() const override { return {false, true, true, true}; }
    int surfaceRings() const override { return 3; }
    int surfaceLimitRings() const override { return 7; }
    const char* name() const override { return "schaefer-warren"; }
    const char* description() const override {
        return "Stam-Loop plus unzipping of the tri/quad network: C2 across the ordinary seam";
    }
    bool regularMasksApply() const override { return true; }
    std::unique_ptr<SchemeLevel> prepareLevel(const Topology& parent, const Options&,
                                              const std::vector<int>* faces) const override {
        return std::make_unique<UnzippedLevel>(parent, faces);
    }
    std::unique_ptr<SchemeMasks> makeMasks(const Topology& parent, const Options&, const SchemeLevel* prepared,
                                           SparseAccumulator& accumulator) const override {
        return std::make_unique<SchaeferWarrenMasks>(parent, static_cast<const UnzippedLevel&>(*prepared), accumulator);
    }
    // Off the network its masks are Stam-Loop's: the closed forms where the neighbourhood is pure.
    void limitMask(const LimitVertex& vertex, LimitMaskCache& cache, LimitMask& out) const override {
        if (!pureClosedForm(vertex, true, out)) limitFromLocalMatrix(*this, vertex, cache, out);
    }
    // The copies of the vertices that split, and a flag per face where any does.
    std::size_t extraLevelBytes(const Topology& parent) const override {
        const std::size_t copies = unzipBytesBound(parent);
        return copies ? copies + std::size_t(parent.numFaces()) : 0;
    }
};

}  // namespace

const SchemeRules& schaeferWarrenRules() {
    static const SchaeferWarrenRules rules;
    return rules;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
