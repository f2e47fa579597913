// Stam-Loop quad/triangle rules (docs/schemes/stam_loop.md) with DeRose creases
// (docs/schemes/creases.md), written as
// one-pass masks over the parent level. Each mask below is the two-pass form (linear split,
// averaging with α = 1/(1 + nE/2 + nQ/4), β = α/2, γ = α/4, then the η correction) expanded
// over parent vertices:
//   face point:   centroid.
//   edge point:   α(1 + T/4) per endpoint, α/2 per triangle's opposite vertex, α per quad-like
//                 face's centroid; α = 1/(2 + T + Q). Using the centroid for an n-gon's diagonal
//                 corners gives Catmull-Clark's edge rule next to n-gons.
//   vertex point: (1+η)(α(1 + nE/4) v + α/4 Σ neighbours + α/4 Σ quad-like centroids) − η v.
// Schaefer-Warren replaces the smooth masks next to the tri/quad network (schaefer_warren.cpp);
// sharp masks and everything away from the network are shared. Catmark-butterfly replaces every
// mask that touches a triangle (butterfly.cpp) except at irregular smooth seam vertices, and keeps
// the rest: Catmull-Clark, and Stam-Loop's mixed vertex rule there.
#include "far/internal/rules.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <type_traits>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "far/internal/butterfly.h"
#include "far/internal/crease.h"
#include "far/internal/regular_masks.h"
#include "far/internal/schaefer_warren.h"
#include "far/internal/sparse_accumulator.h"
#include "far/internal/stencil_writer.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {

double stamLoopEta(int nE, int nQ, int nT) {
    const double n = nE;
    if (nT == 0) return (4.0 - n) * (n + 1.0) / (n * n);  // Catmull-Clark
    if (nQ == 0) {  // Loop, with Loop's original β; tabulated, as every vertex asks for it
        auto loopEta = [](double valence) {
            const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * M_PI / valence);
            const double beta = (5.0 / 8.0 - c * c) / valence;
            return 2.0 * (valence + 2.0) * beta - 1.0;
        };
        constexpr int kTabulated = 32;
        static const std::array<double, kTabulated> table = [&] {
            std::array<double, kTabulated> values{};
            for (int k = 1; k < kTabulated; ++k) values[k] = loopEta(k);
            return values;
        }();
        return nE > 0 && nE < kTabulated ? table[nE] : loopEta(n);
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
    CatmarkButterflyMasks* butterfly;  // every mask of catmark-butterfly that touches a triangle, or null

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
        if (butterfly && butterfly->touchesSharpEdge(e)) return butterfly->sharpEdgePoint(e, scale);
        acc.add(t.edgeVerts[2 * e], 0.5 * scale);
        acc.add(t.edgeVerts[2 * e + 1], 0.5 * scale);
    }

    void edgeSmooth(int e, double scale) {
        if (unzipped && unzipped->touchesEdge(e)) return unzipped->edgePoint(e, scale);
        if (butterfly && butterfly->touchesEdge(e)) return butterfly->smoothEdgePoint(e, scale);
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
        if (butterfly && butterfly->touchesVertex(v, rule)) return butterfly->vertexPoint(v, rule, edgeSharpness, scale);
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

// What every worker of a level reads.
struct LevelInputs {
    const Topology& t;
    const ChildNumbering& num;
    const Options& options;
    std::vector<int> faceOfPoint;           // parent face of each face point
    std::vector<float> childEdgeSharpness;  // per (vertex, incident edge), parallel to t.vertEdges
    std::vector<float> childSharpnessAtEnds;  // the same per edge: 2e at edgeVerts[2e], 2e + 1 at the other end
    bool smooth;  // no sharp edge or vertex in the level (closed, uncreased): no crease rule applies
    std::optional<UnzippedLevel> unzipped;  // Schaefer-Warren's copies, built once per level
};

// One worker's state: the accumulator and the scheme hooks hold per-mask scratch, so each
// worker has its own.
struct Worker {
    SparseAccumulator acc;
    std::optional<SchaeferWarrenMasks> unzipped;
    std::optional<CatmarkButterflyMasks> butterfly;
    Level level;
    std::vector<float> parentEdgeSharpness;  // per incident edge of the current vertex

    explicit Worker(const LevelInputs& in) : acc(in.t.numVertices), level{in.t, acc, nullptr, nullptr} {
        if (in.unzipped) level.unzipped = &unzipped.emplace(in.t, *in.unzipped, acc);
        if (in.options.scheme == Scheme::CatmarkButterfly) level.butterfly = &butterfly.emplace(in.t, acc);
    }
};

void edgeMask(const LevelInputs& in, Worker& w, int e) {
    const Topology& t = in.t;
    if (in.smooth) return w.level.edgeSmooth(e, 1.0);
    // The edge point is a crease point when both child halves stay sharp. Uniform decay keeps
    // them sharp exactly when s > 1 (s = 1 blends with weight 1, the same point); Chaikin can
    // smooth the children of an edge with s > 1 next to weaker creases, and the blend then
    // uses s unclamped, as OpenSubdiv does.
    const float s = t.edgeSharpness[e];
    bool sharp = in.options.scheme == Scheme::Bilinear || isInfinite(s) || t.edgeFaceCount(e) != 2;
    if (!sharp && isSharp(s)) {
        sharp = in.options.creaseMethod == CreaseMethod::Uniform
                    ? s >= 1.0f
                    : in.childSharpnessAtEnds[2 * e] > 0.0f && in.childSharpnessAtEnds[2 * e + 1] > 0.0f;
    }
    if (sharp) {
        w.level.edgeSharp(e, 1.0);
    } else if (!isSharp(s)) {
        w.level.edgeSmooth(e, 1.0);
    } else {  // semi-sharp edge whose children are smooth: blend by the parent sharpness
        w.level.edgeSharp(e, s);
        w.level.edgeSmooth(e, 1.0 - s);
    }
}

void vertexMask(const LevelInputs& in, Worker& w, int v) {
    const Topology& t = in.t;
    if (in.options.scheme == Scheme::Bilinear) return w.acc.add(v, 1.0);
    if (in.smooth) return w.level.vertexRule(v, VertexRule::Smooth, nullptr, 1.0);
    const int n = t.vertexEdgeCount(v), begin = t.vertEdgeOffsets[v];
    std::vector<float>& parentSharpness = w.parentEdgeSharpness;
    parentSharpness.resize(n);
    for (int i = 0; i < n; ++i) parentSharpness[i] = t.edgeSharpness[t.vertEdges[begin + i]];
    const float* childSharpness = in.childEdgeSharpness.data() + begin;
    const float pVertex = t.vertSharpness[v], cVertex = decrementSharpness(pVertex);
    const VertexRule pRule = vertexRule(pVertex, countSharp(parentSharpness.data(), n));
    const VertexRule cRule = vertexRule(cVertex, countSharp(childSharpness, n));
    if (pRule == VertexRule::Smooth || pRule == VertexRule::Dart || pRule == cRule) {
        w.level.vertexRule(v, pRule, parentSharpness.data(), 1.0);
    } else {  // the rule relaxes this level: blend the parent's and the child's masks
        const double weight = transitionWeight(pVertex, cVertex, n, parentSharpness.data(), childSharpness);
        w.level.vertexRule(v, pRule, parentSharpness.data(), weight);
        w.level.vertexRule(v, cRule, childSharpness, 1.0 - weight);
    }
}

// Masks of children [first, last) in child order (face points, edge points, vertex points).
// Float tables of smooth Stam-Loop and Schaefer-Warren levels take the regular masks' short cut
// (regular_masks.h) wherever Schaefer-Warren leaves the Stam-Loop masks alone.
template <typename Table>
void buildRange(const LevelInputs& in, StencilWriter<Table>& writer, int first, int last) {
    Worker w(in);
    const int edgePoints = in.num.numFacePoints, vertexPoints = edgePoints + in.t.numEdges();
    constexpr bool kFloat = std::is_same_v<Table, StencilTable>;
    const bool shortCut = kFloat && in.smooth &&
                          (in.options.scheme == Scheme::StamLoop || in.options.scheme == Scheme::SchaeferWarren);
    RegularMasks regular(in.t);
    int gathered[2 * RegularMasks::kMaxValence + 1];
    for (int c = first; c < last; ++c) {
        int n = 0, key = 0;
        if (shortCut && c >= edgePoints) {
            const SchaeferWarrenMasks* unzipped = w.level.unzipped;
            if (c < vertexPoints) {
                const int e = c - edgePoints;
                if (!unzipped || !unzipped->touchesEdge(e)) n = regular.edge(e, gathered, key);
            } else {
                const int v = c - vertexPoints;
                if (!unzipped || !unzipped->touchesVertex(v)) n = regular.vertex(v, gathered, key);
            }
        }
        if constexpr (kFloat) {
            if (n > 0 && regular.weights(key) >= 0) {
                writer.append(gathered, n, regular.weights(key));
                continue;
            }
        }
        if (c < edgePoints)
            w.level.facePoint(in.faceOfPoint[c]);
        else if (c < vertexPoints)
            edgeMask(in, w, c - edgePoints);
        else
            vertexMask(in, w, c - vertexPoints);
        writer.append(w.acc);
        if constexpr (kFloat) {
            if (n > 0 && regular.weights(key) == RegularMasks::kUnknown)
                regular.setWeights(key, writer.lastHasIndices(gathered, n) ? writer.lastWeightOffset()
                                                                           : RegularMasks::kNever);
        }
    }
}

// Children per part below which a level is not split: a part's worker setup and the copy that
// joins it must stay small next to its masks.
constexpr int kMinChildrenPerPart = 32768;

}  // namespace

// The children are split into one contiguous part per thread; the first part writes straight
// into the table, the others into their own tables, appended in order afterwards.
template <typename Table>
Table buildLevelStencils(const Topology& t, const ChildNumbering& num, const Options& options) {
    const int numChildren = num.numFacePoints + t.numEdges() + t.numVertices;
    const bool smooth = options.scheme != Scheme::Bilinear && !hasSharpness(t);
    LevelInputs in{t, num, options, std::vector<int>(num.numFacePoints), {}, {}, smooth, std::nullopt};
    if (options.scheme == Scheme::SchaeferWarren) in.unzipped.emplace(t);
    for (int f = 0; f < t.numFaces(); ++f)
        if (num.facePoint[f] >= 0) in.faceOfPoint[num.facePoint[f]] = f;
    if (!smooth) {
        in.childEdgeSharpness.resize(t.vertEdges.size());
        const bool chaikin = options.creaseMethod == CreaseMethod::Chaikin;  // edge points read both ends
        if (chaikin) in.childSharpnessAtEnds.resize(t.edgeVerts.size());
        for (int v = 0; v < t.numVertices; ++v) {
            childEdgeSharpnessAtVertex(t, v, options.creaseMethod, in.childEdgeSharpness.data() + t.vertEdgeOffsets[v]);
            for (int i = t.vertEdgeOffsets[v]; chaikin && i < t.vertEdgeOffsets[v + 1]; ++i) {
                const int e = t.vertEdges[i];
                in.childSharpnessAtEnds[2 * e + (t.edgeVerts[2 * e] == v ? 0 : 1)] = in.childEdgeSharpness[i];
            }
        }
    }

    // Reserve an upper bound of the entries: untouched reserved pages cost nothing, while
    // growing by doubling would copy and touch the arrays several times over.
    std::size_t bound = 4 * std::size_t(t.numEdges()) + t.numVertices;
    for (int f = 0; f < t.numFaces(); ++f) bound += std::size_t(t.faceSize(f)) * (1 + 2 * t.faceSize(f));
    const int parts =
        std::max(1, std::min(tbb::this_task_arena::max_concurrency(), numChildren / kMinChildrenPerPart));
    auto split = [&](int k) { return int(std::int64_t(numChildren) * k / parts); };
    auto partBound = [&](int k) {
        return std::size_t(double(bound) * (split(k + 1) - split(k)) / std::max(1, numChildren)) + 64;
    };

    Table table;
    table.numSourceVertices = t.numVertices;
    StencilWriter<Table> writer(table, numChildren, bound);
    std::vector<Table> rest(parts - 1);
    tbb::parallel_for(0, parts, [&](int k) {
        if (k == 0) return buildRange(in, writer, 0, split(1));
        Table& part = rest[k - 1];
        part.numSourceVertices = t.numVertices;
        StencilWriter<Table> partWriter(part, split(k + 1) - split(k), partBound(k));
        buildRange(in, partWriter, split(k), split(k + 1));
        partWriter.finish();
    });
    for (const Table& part : rest) writer.append(part);
    writer.finish();
    return table;
}

template StencilTable buildLevelStencils<StencilTable>(const Topology&, const ChildNumbering&, const Options&);
template StencilTableD buildLevelStencils<StencilTableD>(const Topology&, const ChildNumbering&, const Options&);

}  // namespace v0
}  // namespace quadtri
