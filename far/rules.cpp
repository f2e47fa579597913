// Stam-Loop quad/triangle rules (DESIGN.md §2, §2.1, §3) with DeRose creases (§6), written as
// one-pass masks over the parent level. Each mask below is the two-pass form (linear split,
// averaging with α = 1/(1 + nE/2 + nQ/4), β = α/2, γ = α/4, then the η correction) expanded
// over parent vertices:
//   face point:   centroid.
//   edge point:   α(1 + T/4) per endpoint, α/2 per triangle's opposite vertex, α per quad-like
//                 face's centroid; α = 1/(2 + T + Q). Using the centroid for an n-gon's diagonal
//                 corners gives Catmull-Clark's edge rule next to n-gons.
//   vertex point: (1+η)(α(1 + nE/4) v + α/4 Σ neighbours + α/4 Σ quad-like centroids) − η v.
// Schaefer-Warren replaces the smooth masks next to the tri/quad network (schaefer_warren.cpp);
// sharp masks and everything away from the network are shared.
#include "far/rules.h"

#include <cmath>
#include <optional>

#include "far/crease.h"
#include "far/schaefer_warren.h"
#include "far/sparse_accumulator.h"

namespace quadtri {

double stamLoopEta(int nE, int nQ, int nT) {
    const double n = nE;
    if (nT == 0) return (4.0 - n) * (n + 1.0) / (n * n);  // Catmull-Clark
    if (nQ == 0) {                                        // Loop, with Loop's original β
        const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * M_PI / n);
        const double beta = (5.0 / 8.0 - c * c) / n;
        return 2.0 * (n + 2.0) * beta - 1.0;
    }
    if (nE == 2 && nQ == 1) return -0.20505;
    if (nE == 3 && nQ == 1) return 54.0 / 67.0;
    if (nE == 3 && nQ == 2) return 8.0 / 13.0;
    if (nE == 4 && nQ == 1) return 0.34792;
    if (nE == 4 && nQ == 2) return 0.21380;
    if (nE == 4 && nQ == 3) return 0.10550;
    return 0.0;
}

namespace {

struct Level {
    const Topology& t;
    SparseAccumulator& acc;
    SchaeferWarrenMasks* unzipped;  // the smooth path of Schaefer-Warren, null for Stam-Loop

    void facePoint(int f) {
        if (unzipped && unzipped->touchesFace(f))
            unzipped->facePoint(f, 1.0);
        else
            centroid(f, 1.0);
    }

    void centroid(int f, double scale) {
        const int b = t.faceOffsets[f], n = t.faceSize(f);
        for (int i = 0; i < n; ++i) acc.add(t.faceVerts[b + i], scale / n);
    }

    void edgeSharp(int e, double scale) {
        acc.add(t.edgeVerts[2 * e], 0.5 * scale);
        acc.add(t.edgeVerts[2 * e + 1], 0.5 * scale);
    }

    void edgeSmooth(int e, double scale) {
        if (unzipped && unzipped->touchesEdge(e)) return unzipped->edgePoint(e, scale);
        const int a = t.edgeVerts[2 * e], b = t.edgeVerts[2 * e + 1];
        int tris = 0, quads = 0;
        for (int i = t.edgeFaceOffsets[e]; i < t.edgeFaceOffsets[e + 1]; ++i)
            (t.faceSize(t.edgeFaces[i]) == 3 ? tris : quads)++;
        const double alpha = 1.0 / (2 + tris + quads);
        acc.add(a, scale * alpha * (1.0 + 0.25 * tris));
        acc.add(b, scale * alpha * (1.0 + 0.25 * tris));
        for (int i = t.edgeFaceOffsets[e]; i < t.edgeFaceOffsets[e + 1]; ++i) {
            const int f = t.edgeFaces[i];
            if (t.faceSize(f) != 3) {
                centroid(f, scale * alpha);
                continue;
            }
            for (int c = t.faceOffsets[f]; c < t.faceOffsets[f + 1]; ++c)
                if (t.faceVerts[c] != a && t.faceVerts[c] != b) acc.add(t.faceVerts[c], scale * alpha * 0.5);
        }
    }

    void vertexSmooth(int v, double scale) {
        if (unzipped && unzipped->touchesVertex(v)) return unzipped->vertexPoint(v, scale);
        const int nE = t.vertexEdgeCount(v);
        const VertexFaceCounts counts = countVertexFaces(t, v);
        const double alpha = 1.0 / (1.0 + 0.5 * nE + 0.25 * counts.quads);
        const double eta = stamLoopEta(nE, counts.quads, counts.triangles);
        const double k = scale * (1.0 + eta);
        acc.add(v, k * alpha * (1.0 + 0.25 * nE) - scale * eta);
        for (int i = t.vertEdgeOffsets[v]; i < t.vertEdgeOffsets[v + 1]; ++i)
            acc.add(t.otherVertex(t.vertEdges[i], v), k * alpha * 0.25);
        for (int i = t.vertFaceOffsets[v]; i < t.vertFaceOffsets[v + 1]; ++i)
            if (t.faceSize(t.vertFaces[i]) != 3) centroid(t.vertFaces[i], k * alpha * 0.25);
    }

    // ¾ v + ⅛ at the far ends of the two sharp edges (edgeSharpness in vertEdges order).
    void vertexCrease(int v, const float* edgeSharpness, double scale) {
        acc.add(v, 0.75 * scale);
        const int begin = t.vertEdgeOffsets[v];
        for (int i = 0; i < t.vertexEdgeCount(v); ++i)
            if (isSharp(edgeSharpness[i])) acc.add(t.otherVertex(t.vertEdges[begin + i], v), 0.125 * scale);
    }

    void vertexRule(int v, VertexRule rule, const float* edgeSharpness, double scale) {
        switch (rule) {
        case VertexRule::Smooth:
        case VertexRule::Dart: vertexSmooth(v, scale); break;
        case VertexRule::Crease: vertexCrease(v, edgeSharpness, scale); break;
        case VertexRule::Corner: acc.add(v, scale); break;
        }
    }
};

int countSharp(const float* s, int n) {
    int k = 0;
    for (int i = 0; i < n; ++i) k += isSharp(s[i]) ? 1 : 0;
    return k;
}

// Child sharpness of edge e at its end v, from the per-vertex child sharpness table.
float childSharpnessAt(const Topology& t, const std::vector<float>& childEdgeSharpness, int v, int e) {
    for (int i = t.vertEdgeOffsets[v]; i < t.vertEdgeOffsets[v + 1]; ++i)
        if (t.vertEdges[i] == e) return childEdgeSharpness[i];
    return 0.0f;
}

}  // namespace

template <typename Table>
Table buildLevelStencils(const Topology& t, const ChildNumbering& num, const Options& options) {
    const int numChildren = num.numFacePoints + t.numEdges() + t.numVertices;
    Table table;
    table.numSourceVertices = t.numVertices;
    table.sizes.reserve(numChildren);
    table.offsets.reserve(numChildren);
    // Reserve an upper bound of the entries: untouched reserved pages cost nothing, while
    // growing by doubling would copy and touch the arrays several times over.
    std::size_t bound = 4 * std::size_t(t.numEdges()) + t.numVertices;
    for (int f = 0; f < t.numFaces(); ++f) bound += std::size_t(t.faceSize(f)) * (1 + 2 * t.faceSize(f));
    table.indices.reserve(bound);
    table.weights.reserve(bound);
    SparseAccumulator acc(t.numVertices);
    std::optional<SchaeferWarrenMasks> unzipped;
    if (options.scheme == Scheme::SchaeferWarren) unzipped.emplace(t, acc);
    Level level{t, acc, unzipped ? &*unzipped : nullptr};
    const bool linear = options.scheme == Scheme::Bilinear;
    auto emit = [&]() {
        table.offsets.push_back(int(table.indices.size()));
        table.sizes.push_back(acc.flush(table.indices, table.weights));
    };

    for (int f = 0; f < t.numFaces(); ++f) {
        if (num.facePoint[f] < 0) continue;
        level.facePoint(f);
        emit();
    }

    // Child sharpness of every (vertex, incident edge) pair, parallel to t.vertEdges.
    std::vector<float> childEdgeSharpness(t.vertEdges.size());
    for (int v = 0; v < t.numVertices; ++v)
        childEdgeSharpnessAtVertex(t, v, options.creaseMethod, &childEdgeSharpness[t.vertEdgeOffsets[v]]);

    for (int e = 0; e < t.numEdges(); ++e) {
        // The edge point is a crease point when both child halves stay sharp. Uniform decay keeps
        // them sharp exactly when s > 1 (s = 1 blends with weight 1, the same point); Chaikin can
        // smooth the children of an edge with s > 1 next to weaker creases, and the blend then
        // uses s unclamped, as OpenSubdiv does.
        const float s = t.edgeSharpness[e];
        bool sharp = linear || isInfinite(s) || t.edgeFaceCount(e) != 2;
        if (!sharp && isSharp(s)) {
            sharp = options.creaseMethod == CreaseMethod::Uniform
                        ? s >= 1.0f
                        : childSharpnessAt(t, childEdgeSharpness, t.edgeVerts[2 * e], e) > 0.0f &&
                              childSharpnessAt(t, childEdgeSharpness, t.edgeVerts[2 * e + 1], e) > 0.0f;
        }
        if (sharp) {
            level.edgeSharp(e, 1.0);
        } else if (!isSharp(s)) {
            level.edgeSmooth(e, 1.0);
        } else {  // semi-sharp edge whose children are smooth: blend by the parent sharpness
            level.edgeSharp(e, s);
            level.edgeSmooth(e, 1.0 - s);
        }
        emit();
    }

    std::vector<float> parentEdgeSharpness;
    for (int v = 0; v < t.numVertices; ++v) {
        if (linear) {
            acc.add(v, 1.0);
            emit();
            continue;
        }
        const int n = t.vertexEdgeCount(v), begin = t.vertEdgeOffsets[v];
        parentEdgeSharpness.resize(n);
        for (int i = 0; i < n; ++i) parentEdgeSharpness[i] = t.edgeSharpness[t.vertEdges[begin + i]];
        const float* childSharpness = &childEdgeSharpness[begin];
        const float pVertex = t.vertSharpness[v], cVertex = decrementSharpness(pVertex);
        const VertexRule pRule = vertexRule(pVertex, countSharp(parentEdgeSharpness.data(), n));
        const VertexRule cRule = vertexRule(cVertex, countSharp(childSharpness, n));
        if (pRule == VertexRule::Smooth || pRule == VertexRule::Dart || pRule == cRule) {
            level.vertexRule(v, pRule, parentEdgeSharpness.data(), 1.0);
        } else {  // the rule relaxes this level: blend the parent's and the child's masks
            const double w = transitionWeight(pVertex, cVertex, n, parentEdgeSharpness.data(), childSharpness);
            level.vertexRule(v, pRule, parentEdgeSharpness.data(), w);
            level.vertexRule(v, cRule, childSharpness, 1.0 - w);
        }
        emit();
    }
    return table;
}

template StencilTable buildLevelStencils<StencilTable>(const Topology&, const ChildNumbering&, const Options&);
template StencilTableD buildLevelStencils<StencilTableD>(const Topology&, const ChildNumbering&, const Options&);

}  // namespace quadtri
