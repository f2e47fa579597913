// Surface rules of catmark-butterfly (see butterfly.h). Every weight below is either Butterfly's
// or Zorin's, or was derived by docs/catmark_butterfly/derive_seam_rules.py.
#include "far/limit/limit_closed_forms.h"
#include "far/schemes/butterfly.h"

#include <algorithm>
#include <cmath>

#include "far/topology/level_estimate.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

bool edgeHasQuad(const Topology& t, int e) {
    for (int f : t.facesOfEdge(e))
        if (t.faceSize(f) != 3) return true;
    return false;
}

// Valence of a vertex whose faces close a manifold fan around it, else 0 (Zorin's rule needs the
// whole ring).
int closedFanValence(const Topology& t, int v) {
    if (t.vertFlags[v] & (kVertexBoundary | kVertexNonManifold)) return 0;
    return t.vertexEdgeCount(v);
}

// Whether an interior end of this valence takes Zorin's rule. His weights hold for K >= 3 only:
// at K = 2 (two triangles back to back, the only closed fan below 3) the cos 4πj/K terms stop
// cancelling and the mask would sum to 1.5. Such an end is refined as a regular one, by the
// plain Butterfly, whose weights sum to 1 whatever its wings are.
bool takesZorinRule(int valence) { return valence >= 3 && valence != 6; }

}  // namespace

CatmarkButterflyMasks::CatmarkButterflyMasks(const Topology& topology, SparseAccumulator& accumulator)
    : StamLoopMasks(topology, accumulator), kind_(size_t(topology.numVertices)), sharpEdges_(size_t(topology.numVertices)) {
    for (int v = 0; v < t_.numVertices; ++v) kind_[size_t(v)] = classify(v);
    for (int e = 0; e < t_.numEdges(); ++e) {
        if (!isSharp(t_.edgeSharpness[e])) continue;
        for (int end = 0; end < 2; ++end) {
            uint8_t& count = sharpEdges_[size_t(t_.edgeVerts[2 * e + end])];
            count = count < 3 ? count + 1 : 3;
        }
    }
}

CatmarkButterflyMasks::Kind CatmarkButterflyMasks::classify(int v) const {
    int quads = 0, triangles = 0, ngons = 0, seamEdges = 0;
    for (int f : t_.facesOfVertex(v)) {
        const int n = t_.faceSize(f);
        (n == 3 ? triangles : n == 4 ? quads : ngons)++;
    }
    if (triangles == 0) return Kind::QuadOnly;
    if (quads + ngons == 0) return Kind::TriangleOnly;
    for (int e : t_.edgesOfVertex(v)) seamEdges += (t_.edgeFlags[e] & kEdgeSeam) ? 1 : 0;
    const bool regular = closedFanValence(t_, v) == 5 && quads == 2 && ngons == 0 && triangles == 3 && seamEdges == 2;
    return regular ? Kind::RegularSeam : Kind::Seam;
}

// Interpolated vertices never move; crease vertices on the seam follow the curve rules, smooth
// ones of the regular seam eq. 13. Corners and irregular smooth seam vertices keep the shared
// rules (a fixed corner, Stam-Loop's mixed vertex rule).
bool CatmarkButterflyMasks::touchesVertex(int v, VertexRule rule) const {
    switch (kind_[v]) {
    case Kind::QuadOnly: return false;
    case Kind::TriangleOnly: return true;
    case Kind::Seam: return rule == VertexRule::Crease;
    case Kind::RegularSeam: return rule != VertexRule::Corner;
    }
    return false;
}

bool CatmarkButterflyMasks::touchesEdge(int e) const {
    for (int f : t_.facesOfEdge(e))
        if (t_.faceSize(f) == 3) return true;
    return false;
}

// A sharp edge with a quad keeps the crease midpoint: both its ends are approximated (they touch
// the quad), and the midpoint is the cubic B-spline's rule there.
bool CatmarkButterflyMasks::touchesSharpEdge(int e) const {
    return t_.edgeFaceCount(e) > 0 && !edgeHasQuad(t_, e);
}

void CatmarkButterflyMasks::vertexPoint(int v, VertexRule rule, const float* edgeSharpness, double scale) {
    if (!touchesVertex(v, rule)) return StamLoopMasks::vertexPoint(v, rule, edgeSharpness, scale);
    if (interpolated(v)) return acc_.add(v, scale);
    if (rule == VertexRule::Crease) return creaseVertex(v, edgeSharpness, scale);
    seamVertex(v, scale);
}

// Eq. 13 by weight class: 9/112 per neighbour along an edge with a quad (the quad-side and the
// two seam neighbours), 3/56 per neighbour along a triangle-only edge, 3/224 per quad's far
// corner, 5/8 at the vertex.
void CatmarkButterflyMasks::seamVertex(int v, double scale) {
    acc_.add(v, scale * 5.0 / 8.0);
    for (int e : t_.edgesOfVertex(v))
        acc_.add(t_.otherVertex(e, v), scale * (edgeHasQuad(t_, e) ? 9.0 / 112.0 : 3.0 / 56.0));
    for (int f : t_.facesOfVertex(v)) {
        if (t_.faceSize(f) != 4) continue;
        acc_.add(t_.verticesOfFace(f)[(t_.cornerOfVertex(f, v) + 2) % 4], scale * 3.0 / 224.0);
    }
}

void CatmarkButterflyMasks::smoothEdgePoint(int e, double scale) {
    if (!touchesEdge(e)) return StamLoopMasks::smoothEdgePoint(e, scale);
    const int f0 = t_.facesOfEdge(e)[0], f1 = t_.facesOfEdge(e)[1];
    if (t_.faceSize(f0) == 3 && t_.faceSize(f1) == 3)
        butterflyEdge(e, scale);
    else
        seamEdge(e, scale);
}

// Eq. 14: 11/28 per endpoint, 3/56 per far corner of the quad (3/28 shared by an n-gon's far
// corners), 13/112 at the triangle's opposite vertex, −1/224 per wing.
void CatmarkButterflyMasks::seamEdge(int e, double scale) {
    const int a = t_.edgeVerts[2 * e], b = t_.edgeVerts[2 * e + 1];
    acc_.add(a, scale * 11.0 / 28.0);
    acc_.add(b, scale * 11.0 / 28.0);
    for (int f : t_.facesOfEdge(e)) {
        const int n = t_.faceSize(f);
        if (n == 3) {
            const int c = thirdVertex(f, a, b);
            acc_.add(c, scale * 13.0 / 112.0);
            addWing(f, a, c, b, -scale / 224.0);
            addWing(f, b, c, a, -scale / 224.0);
            continue;
        }
        for (int c : t_.verticesOfFace(f))
            if (c != a && c != b) acc_.add(c, scale * 3.0 / 28.0 / (n - 2));
    }
}

// An edge between two triangles. Both ends interpolated: Zorin at extraordinary interior ends,
// else Butterfly, or the half Butterfly away from the seam when the plain rule's weights on seam
// vertices do not cancel (column 1 → column 2). One end on a regular seam vertex: eqs. 11/12.
// Every other edge with an end on the seam (irregular seams only): Butterfly, missing wings
// reflected (the docs measure why not Zorin's rule of the interpolated end nor eqs. 11/12).
void CatmarkButterflyMasks::butterflyEdge(int e, double scale) {
    const int a = t_.edgeVerts[2 * e], b = t_.edgeVerts[2 * e + 1];
    const int f0 = t_.facesOfEdge(e)[0], f1 = t_.facesOfEdge(e)[1];
    if (interpolated(a) && interpolated(b)) {
        const bool extraordinaryA = takesZorinRule(closedFanValence(t_, a));
        const bool extraordinaryB = takesZorinRule(closedFanValence(t_, b));
        if (extraordinaryA && extraordinaryB) {
            zorinEdge(a, e, 0.5 * scale);
            zorinEdge(b, e, 0.5 * scale);
        } else if (extraordinaryA || extraordinaryB) {
            zorinEdge(extraordinaryA ? a : b, e, scale);
        } else if (seamWeightOfSide(f0, a, b) == 0.0 && seamWeightOfSide(f1, a, b) == 0.0) {
            butterfly(a, b, f0, f1, scale);
        } else if (cleanSide(f1, a, b)) {
            halfButterfly(a, b, f1, scale);
        } else if (cleanSide(f0, a, b)) {
            halfButterfly(a, b, f0, scale);
        } else {
            butterfly(a, b, f0, f1, scale);
        }
        return;
    }
    const int s = interpolated(a) ? b : a;
    if (interpolated(a) != interpolated(b) && kind_[s] == Kind::RegularSeam) {
        const bool seam0 = t_.edgeFlags[edgeOfFace(f0, s, thirdVertex(f0, a, b))] & kEdgeSeam;
        return seamDiagonal(s, s == a ? b : a, seam0 ? f0 : f1, seam0 ? f1 : f0, scale);
    }
    butterfly(a, b, f0, f1, scale);
}

void CatmarkButterflyMasks::butterfly(int a, int b, int f0, int f1, double scale) {
    acc_.add(a, 0.5 * scale);
    acc_.add(b, 0.5 * scale);
    for (int f : {f0, f1}) {
        const int c = thirdVertex(f, a, b);
        acc_.add(c, 0.125 * scale);
        addWing(f, a, c, b, -0.0625 * scale);
        addWing(f, b, c, a, -0.0625 * scale);
    }
}

// ½ a + ½ b + ¼ d − ⅛ (wings across a–d and b–d), d opposite in `f`: quadratic interpolation on
// the regular triangle lattice that reads one side of the edge only.
void CatmarkButterflyMasks::halfButterfly(int a, int b, int f, double scale) {
    const int d = thirdVertex(f, a, b);
    acc_.add(a, 0.5 * scale);
    acc_.add(b, 0.5 * scale);
    acc_.add(d, 0.25 * scale);
    addWing(f, a, d, b, -0.125 * scale);
    addWing(f, b, d, a, -0.125 * scale);
}

// Eqs. 11/12: seam vertex s, interpolated vertex t, the triangle towards the seam (opposite c, a
// seam neighbour of s) and the one away from it (opposite d). The wing across t–c has weight 0.
void CatmarkButterflyMasks::seamDiagonal(int s, int t, int towardsSeam, int away, double scale) {
    const int c = thirdVertex(towardsSeam, s, t), d = thirdVertex(away, s, t);
    acc_.add(s, scale * 31.0 / 80.0);
    acc_.add(t, scale * 17.0 / 40.0);
    acc_.add(c, scale * 3.0 / 32.0);
    acc_.add(d, scale * 7.0 / 40.0);
    addWing(away, s, d, t, -scale / 32.0);
    addWing(away, t, d, s, -scale / 20.0);
}

// Zorin's modified Butterfly seen from `centre` along edge e, the ring starting at e's other end:
// ¾ at the centre, K = 3: (5/12, −1/12, −1/12), K = 4: (3/8, 0, −1/8, 0), else
// (¼ + cos 2πj/K + ½ cos 4πj/K)/K. A mask costs its K + 1 entries: the weights are computed once
// per valence, and a ring longer than a few steps is walked once per centre (a vertex's edges
// mostly come one after another; short rings, walked per edge, do not evict it).
void CatmarkButterflyMasks::zorinEdge(int centre, int e, double scale) {
    const int other = t_.otherVertex(e, centre), firstFace = t_.facesOfEdge(e)[0];
    const int k = t_.vertexEdgeCount(centre);
    std::vector<int>* ring = &shortRing_;
    if (k > kShortRing) {
        ring = &longRing_;
        if (longRingCentre_ != centre) walkRing(centre, other, firstFace, longRing_);
        longRingCentre_ = centre;
    } else {
        walkRing(centre, other, firstFace, shortRing_);
    }
    const std::vector<double>& weights = zorinWeights(int(ring->size()));
    // The ring is read from `other` on, first into e's first face: the order (and so every bit
    // of the table) does not depend on which edge the ring was walked from.
    const int n = int(ring->size());
    int start = 0;
    while ((*ring)[size_t(start)] != other) ++start;
    const int step = (*ring)[size_t((start + 1) % n)] == thirdVertex(firstFace, centre, other) ? 1 : n - 1;
    acc_.add(centre, 0.75 * scale);
    for (int j = 0, i = start; j < n; ++j, i = (i + step) % n) acc_.add((*ring)[size_t(i)], weights[size_t(j)] * scale);
}

const std::vector<double>& CatmarkButterflyMasks::zorinWeights(int k) {
    if (int(weightsByValence_.size()) <= k) weightsByValence_.resize(size_t(k) + 1);
    std::vector<double>& weights = weightsByValence_[size_t(k)];
    if (weights.empty()) {
        weights.resize(size_t(k));
        for (int j = 0; j < k; ++j) {
            if (k == 3)
                weights[size_t(j)] = j == 0 ? 5.0 / 12.0 : -1.0 / 12.0;
            else if (k == 4)
                weights[size_t(j)] = j == 0 ? 0.375 : j == 2 ? -0.125 : 0.0;
            else
                weights[size_t(j)] = (0.25 + std::cos(2.0 * M_PI * j / k) + 0.5 * std::cos(4.0 * M_PI * j / k)) / k;
        }
    }
    return weights;
}

// The centre's neighbours in fan order from `other`, through `face` first: each step crosses the
// face's other edge at the centre, found among the face's corners.
void CatmarkButterflyMasks::walkRing(int centre, int other, int face, std::vector<int>& ring) const {
    const int valence = t_.vertexEdgeCount(centre);
    ring.assign(1, other);
    while (int(ring.size()) < valence && face >= 0) {
        ring.push_back(thirdVertex(face, centre, ring.back()));
        face = otherFace(edgeOfFace(face, centre, ring.back()), face);
    }
}

int CatmarkButterflyMasks::thirdVertex(int f, int a, int b) const {
    for (int c : t_.verticesOfFace(f))
        if (c != a && c != b) return c;
    return -1;
}

int CatmarkButterflyMasks::otherFace(int e, int f) const {
    if (e < 0 || t_.edgeFaceCount(e) != 2) return -1;
    const IndexSpan faces = t_.facesOfEdge(e);
    return faces[0] == f ? faces[1] : faces[0];
}

int CatmarkButterflyMasks::edgeOfFace(int f, int x, int y) const {
    const IndexSpan corners = t_.verticesOfFace(f);
    const int n = corners.size();
    for (int i = 0; i < n; ++i) {
        const int u = corners[i], w = corners[i + 1 == n ? 0 : i + 1];
        if ((u == x && w == y) || (u == y && w == x)) return t_.edgesOfFace(f)[i];
    }
    return -1;
}

int CatmarkButterflyMasks::wing(int f, int x, int y) const {
    const int g = otherFace(edgeOfFace(f, x, y), f);
    return g >= 0 && t_.faceSize(g) == 3 ? thirdVertex(g, x, y) : -1;
}

// Across a crease the wing lies on the crease's other side, which must not pull this side's
// points (the crease is refined from its own points only): it is reflected too, in the share the
// crease edge's own point takes the crease rule (all of it from sharpness 1, s below), so that the
// surface moves continuously with the sharpness.
void CatmarkButterflyMasks::addWing(int f, int x, int y, int z, double weight) {
    const int w = wing(f, x, y);
    const double reflected = w < 0 ? 1.0 : std::min(1.0, double(t_.edgeSharpness[edgeOfFace(f, x, y)]));
    if (reflected < 1.0) acc_.add(w, weight * (1.0 - reflected));
    if (reflected == 0.0) return;
    acc_.add(x, weight * reflected);
    acc_.add(y, weight * reflected);
    acc_.add(z, -weight * reflected);
}

bool CatmarkButterflyMasks::cleanSide(int f, int a, int b) const {
    const int d = thirdVertex(f, a, b), wa = wing(f, a, d), wb = wing(f, b, d);
    return interpolated(d) && wa >= 0 && interpolated(wa) && wb >= 0 && interpolated(wb);
}

// The plain Butterfly's weight on seam vertices from one side (opposite vertex and wings, with
// missing wings reflected); with both sides at 0 the seam's Q⁻ correction cancels.
double CatmarkButterflyMasks::seamWeightOfSide(int f, int a, int b) const {
    const int d = thirdVertex(f, a, b);
    double sum = interpolated(d) ? 0.0 : 0.125;
    for (int x : {a, b}) {
        const int w = wing(f, x, d);
        if (w >= 0 && !interpolated(w)) sum -= 0.0625;
        if (w < 0 && !interpolated(d)) sum -= 0.0625;  // the reflection x + d − y reads d
    }
    return sum;
}

namespace {

class CatmarkButterflyRules : public SchemeRules {
public:
    // Butterfly interpolates: its triangles are no polynomial patch.
    SurfacePatches surfacePatches() const override { return {false, true, false, true, false}; }
    int surfaceRings() const override { return 3; }
    int surfaceLimitRings() const override { return 7; }
    const char* name() const override { return "catmark-butterfly"; }
    const char* description() const override {
        return "Catmull-Clark on quads, interpolating Butterfly on triangles";
    }
    std::unique_ptr<SchemeMasks> makeMasks(const Topology& parent, const Options&, const SchemeLevel*,
                                           SparseAccumulator& accumulator) const override {
        return std::make_unique<CatmarkButterflyMasks>(parent, accumulator);
    }
    // Catmull-Clark's closed form among quads only; triangles interpolate (the generic path).
    void limitMask(const LimitVertex& vertex, LimitMaskCache& cache, LimitMask& out) const override {
        if (!pureClosedForm(vertex, false, out)) limitFromLocalMatrix(*this, vertex, cache, out);
    }
    std::size_t extraLevelBytes(const Topology& parent) const override;
};

// Zorin's edge masks read the whole ring of an extraordinary vertex with triangles only: each of
// its K edges' masks has up to K + 1 more entries than the shared estimate counts.
std::size_t CatmarkButterflyRules::extraLevelBytes(const Topology& p) const {
    std::vector<std::size_t> corners(std::size_t(p.numVertices), 0);
    std::vector<uint8_t> touchesQuad(std::size_t(p.numVertices), 0);
    for (int f = 0; f < p.numFaces(); ++f)
        for (int v : p.verticesOfFace(f)) {
            ++corners[std::size_t(v)];
            touchesQuad[std::size_t(v)] |= p.faceSize(f) != 3;
        }
    auto extraordinary = [&](int v, std::size_t k) { return !touchesQuad[std::size_t(v)] && k >= 3 && k != 6; };
    std::size_t entries = 0;
    if (p.vertEdgeOffsets.size() == std::size_t(p.numVertices) + 1) {
        // Zorin's rule applies where both ends have triangles only, at an end whose faces close
        // a manifold fan.
        for (int e = 0; e < p.numEdges(); ++e) {
            const int a = p.edgeVerts[2 * e], b = p.edgeVerts[2 * e + 1];
            if (touchesQuad[std::size_t(a)] || touchesQuad[std::size_t(b)]) continue;
            for (int v : {a, b}) {
                const std::size_t k = std::size_t(p.vertexEdgeCount(v));
                if (!(p.vertFlags[std::size_t(v)] & (kVertexBoundary | kVertexNonManifold)) && extraordinary(v, k))
                    entries += k + 1;
            }
        }
    } else {
        // Faces only: a vertex has at most one edge more than it has corners.
        for (int v = 0; v < p.numVertices; ++v) {
            const std::size_t k = corners[std::size_t(v)] + 1;
            if (extraordinary(v, k)) entries += k * (k + 1);
        }
    }
    return tableEntryBytes(entries);
}

}  // namespace

const SchemeRules& catmarkButterflyRules() {
    static const CatmarkButterflyRules rules;
    return rules;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
