// The closed-form limit masks (docs/limit.md): Catmull-Clark and Loop as OpenSubdiv's
// PrimvarRefiner::Limit applies them, by the vertex's rule at the level asked for, over its ring
// (far/limit/limit_mask.h: neighbours[i] the far end of edge i, opposite[i] face i's corner two
// after the vertex). Every tangent pair is oriented so that dU × dV points outside.
#include "far/limit/limit_closed_forms.h"

#include <cmath>

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// The first and last sharp edge in ring order: the crease's two edges when the rule is Crease.
struct CreaseEnds {
    int first = 0, last = 0;
};
CreaseEnds creaseEnds(const VertexRing& ring) {
    CreaseEnds ends;
    const int n = int(ring.edges.size());
    ends.first = 0;
    while (ends.first < n - 1 && !isSharp(ring.edgeSharpness[ends.first])) ++ends.first;
    ends.last = n - 1;
    while (ends.last > 0 && !isSharp(ring.edgeSharpness[ends.last])) --ends.last;
    return ends;
}

// The weights of one mask by ring slot, written straight into the mask: the vertex, edge
// neighbour i, face i's opposite corner (LimitMask::startRing's layout).
struct RingWeights {
    double* edge[3];  // per output (position, dU, dV), per ring edge
    double* face[3];  // per output, per ring face
    double& vertex(int k) { return (*channels_[k])[0]; }

    RingWeights(const VertexRing& ring, LimitMask& out) : channels_{&out.position, &out.du, &out.dv} {
        out.startRing(ring);
        for (int k = 0; k < 3; ++k) {
            edge[k] = channels_[k]->data() + 1;
            face[k] = edge[k] + ring.edges.size();
        }
    }

private:
    std::vector<double>* channels_[3];
};

constexpr int kPosition = 0, kU = 1, kV = 2;

// cos and sin of i/n of a turn, exact where the angle is a multiple of 30 degrees (the regular
// valences' masks then hold exact zeros and halves, as their tabulated forms do).
double cosTurn(int i, int n) {
    static const double kTwelfths[12] = {1.0, 0.5 * std::sqrt(3.0), 0.5, 0.0, -0.5, -0.5 * std::sqrt(3.0),
                                         -1.0, -0.5 * std::sqrt(3.0), -0.5, 0.0, 0.5, 0.5 * std::sqrt(3.0)};
    i = (i % n + n) % n;
    if ((12 * i) % n == 0) return kTwelfths[12 * i / n];
    return std::cos(2.0 * M_PI * i / n);
}
double sinTurn(int i, int n) { return cosTurn(4 * i - n, 4 * n); }  // sin x = cos(x - quarter turn)

// A corner: the vertex itself; the tangents along its first two edges (the first face's sides),
// scaled by `scale`.
void cornerMasks(const VertexRing& ring, double scale, RingWeights& w) {
    w.vertex(kPosition) = 1.0;
    if (ring.edges.size() < 2) return;  // an isolated vertex: no tangent
    w.vertex(kU) = w.vertex(kV) = -scale;
    w.edge[kU][0] = scale;
    w.edge[kV][1] = scale;
}

// The crease's limit point: the cubic B-spline of its crease curve, (1, 4, 1)/6.
void creasePosition(const CreaseEnds& ends, RingWeights& w) {
    w.vertex(kPosition) = 4.0 / 6.0;
    w.edge[kPosition][ends.first] += 1.0 / 6.0;
    w.edge[kPosition][ends.last] += 1.0 / 6.0;
}

void catmullClarkSmooth(const VertexRing& ring, RingWeights& w) {
    const int n = int(ring.faces.size());
    const double f = 1.0 / (n * (n + 5.0)), e = 4.0 * f;
    w.vertex(kPosition) = 1.0 - n * (e + f);
    const double cosTheta = cosTurn(1, n);
    const double lambda = 5.0 / 16.0 + (cosTheta + cosTurn(1, 2 * n) * std::sqrt(2.0 * (9.0 + cosTheta))) / 16.0;
    const double faceScale = 1.0 / (4.0 * lambda - 1.0);
    for (int i = 0; i < n; ++i) {
        w.edge[kPosition][i] = e;
        w.face[kPosition][i] = f;
        // dV is dU turned by one slot, a quarter turn at the regular valence.
        const int next = (i + 1) % n;
        const double ci = cosTurn(i, n), ci1 = cosTurn(i + 1, n);
        w.edge[kU][i] = 4.0 * ci;
        w.face[kU][i] = faceScale * (ci + ci1);
        w.edge[kV][next] = 4.0 * ci;
        w.face[kV][next] = faceScale * (ci + ci1);
    }
}

// Across the crease, into the faces between its first and last edge (Biermann et al.'s boundary
// tangent where the vertex is irregular, the uniform cubic B-spline's where it is regular).
void catmullClarkCrease(const VertexRing& ring, RingWeights& w) {
    const CreaseEnds ends = creaseEnds(ring);
    creasePosition(ends, w);
    w.edge[kU][ends.first] = 0.5;
    w.edge[kU][ends.last] = -0.5;
    const int interior = ends.last - ends.first - 1;
    auto& edge = w.edge[kV];
    auto& face = w.face[kV];
    if (interior == 0) {  // one face: the mean of the crease's two edges
        w.vertex(kV) = -6.0;
        edge[ends.first] += 3.0;
        edge[ends.last] += 3.0;
    } else if (interior == 1) {
        w.vertex(kV) = -4.0 / 6.0;
        edge[ends.first] = -1.0 / 6.0;
        edge[ends.first + 1] = 4.0 / 6.0;
        edge[ends.last] = -1.0 / 6.0;
        face[ends.first] = 1.0 / 6.0;
        face[ends.first + 1] = 1.0 / 6.0;
    } else {
        const int k = interior + 1;
        const double cosTheta = cosTurn(1, 2 * k), sinTheta = sinTurn(1, 2 * k);  // θ = π/k
        const double d = 1.0 / (k * (3.0 + cosTheta)), r = (cosTheta + 1.0) / sinTheta;
        w.vertex(kV) = 4.0 * r * (cosTheta - 1.0) * d;
        edge[ends.first] = -r * (1.0 + 2.0 * cosTheta) * d;
        edge[ends.last] = -r * (1.0 + 2.0 * cosTheta) * d;
        face[ends.first] = sinTheta * d;
        for (int i = 1; i < k; ++i) {
            edge[ends.first + i] = 4.0 * sinTurn(i, 2 * k) * d;
            face[ends.first + i] = (sinTurn(i, 2 * k) + sinTurn(i + 1, 2 * k)) * d;
        }
    }
}

// Loop's tangents: cos and sin of the edges' angles around an interior vertex.
void loopSmoothTangents(const VertexRing& ring, RingWeights& w) {
    const int n = int(ring.edges.size());
    for (int i = 0; i < n; ++i) {
        w.edge[kU][i] = cosTurn(i, n);
        w.edge[kV][i] = sinTurn(i, n);
    }
}

void loopSmooth(const VertexRing& ring, RingWeights& w) {
    const int n = int(ring.faces.size());
    double e = 1.0 / 12.0;
    if (n != 6) {
        const double beta = 0.25 * cosTurn(1, n) + 0.375;
        const double gamma = (0.625 - beta * beta) / n;
        e = 1.0 / (n + 3.0 / (8.0 * gamma));
    }
    w.vertex(kPosition) = 1.0 - n * e;
    for (std::size_t i = 0; i < ring.edges.size(); ++i) w.edge[kPosition][i] = e;
    loopSmoothTangents(ring, w);
}

// Loop's tangents at a crease: along it, (3/2)(first − last); across it, into the faces between
// its first and last edge, scaled to match the interior tangents' lengths on a regular mesh.
void loopCreaseTangents(const CreaseEnds& ends, RingWeights& w) {
    w.edge[kU][ends.first] = 1.5;
    w.edge[kU][ends.last] = -1.5;
    const int interior = ends.last - ends.first - 1;
    auto& edge = w.edge[kV];
    if (interior == 0) {
        w.vertex(kV) = -6.0;
        edge[ends.first] += 3.0;
        edge[ends.last] += 3.0;
    } else if (interior == 1) {
        w.vertex(kV) = -3.0;
        edge[ends.first + 1] = 3.0;
    } else if (interior == 2) {
        const double root3 = std::sqrt(3.0);
        w.vertex(kV) = -root3;
        edge[ends.first] = -root3 / 2;
        edge[ends.last] = -root3 / 2;
        edge[ends.first + 1] = root3;
        edge[ends.first + 2] = root3;
    } else {
        const int k = 2 * (interior + 1);  // θ = π/(interior + 1): sin iθ = sinTurn(i, k)
        edge[ends.first] = -3.0 * sinTurn(1, k);
        edge[ends.last] = -3.0 * sinTurn(1, k);
        for (int i = 1; i <= interior; ++i) edge[ends.first + i] = -6.0 * (cosTurn(1, k) - 1.0) * sinTurn(i, k);
    }
}

bool hasRing(const VertexRing& ring) { return !ring.faces.empty() && ring.edges.size() >= 2; }

}  // namespace

void catmullClarkLimit(const LimitVertex& vertex, LimitMask& out) {
    const VertexRing& ring = vertex.ring;
    RingWeights w(ring, out);
    const bool smooth = vertex.rule == VertexRule::Smooth || vertex.rule == VertexRule::Dart;
    if (!hasRing(ring) || vertex.rule == VertexRule::Corner || (smooth && ring.faces.size() == 2))
        cornerMasks(ring, 1.0, w);
    else if (smooth && ring.faces.size() == ring.edges.size())
        catmullClarkSmooth(ring, w);
    else if (smooth)
        cornerMasks(ring, 1.0, w);  // a smooth rule without a closed fan (non-manifold): stays put
    else
        catmullClarkCrease(ring, w);
    out.finishRing();
}

void loopLimit(const LimitVertex& vertex, LimitMask& out) {
    const VertexRing& ring = vertex.ring;
    RingWeights w(ring, out);
    const bool smooth = vertex.rule == VertexRule::Smooth || vertex.rule == VertexRule::Dart;
    if (!hasRing(ring) || vertex.rule == VertexRule::Corner || (smooth && ring.faces.size() != ring.edges.size())) {
        cornerMasks(ring, 3.0, w);
    } else if (smooth) {
        loopSmooth(ring, w);
    } else {
        const CreaseEnds ends = creaseEnds(ring);
        creasePosition(ends, w);
        loopCreaseTangents(ends, w);
    }
    out.finishRing();
}

void bilinearLimit(const LimitVertex& vertex, LimitMask& out) {
    const VertexRing& ring = vertex.ring;
    RingWeights w(ring, out);
    w.vertex(kPosition) = 1.0;
    if (!hasRing(ring) || vertex.rule == VertexRule::Corner) {
        cornerMasks(ring, 1.0, w);
    } else if (vertex.rule == VertexRule::Crease) {
        loopCreaseTangents(creaseEnds(ring), w);
    } else if (ring.faces.size() == ring.edges.size()) {
        loopSmoothTangents(ring, w);
    } else {
        cornerMasks(ring, 1.0, w);
    }
    out.finishRing();
}

bool ringFacesHave(const LimitVertex& vertex, int corners) {
    for (int f : vertex.ring.faces)
        if (vertex.level.faceSize(f) != corners) return false;
    return !vertex.ring.faces.empty();
}

bool pureClosedForm(const LimitVertex& vertex, bool loopOnTriangles, LimitMask& out) {
    if (vertex.ring.faces.empty()) {  // an isolated vertex stays where it is, whatever the scheme
        catmullClarkLimit(vertex, out);
        return true;
    }
    const bool quads = ringFacesHave(vertex, 4), triangles = loopOnTriangles && ringFacesHave(vertex, 3);
    if (!quads && !triangles) return false;
    for (int f : vertex.ring.faces)
        for (int c : vertex.level.verticesOfFace(f))
            if (vertex.level.vertFlags[c] & kVertexSeam) return false;
    if (quads)
        catmullClarkLimit(vertex, out);
    else
        loopLimit(vertex, out);
    return true;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
