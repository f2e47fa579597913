// The part of every level's masks that all schemes share (docs/architecture.md, "Building one
// level"): DeRose creases (docs/schemes/creases.md) decide per child whether the scheme's sharp,
// smooth or blended mask applies, and the vertex rule with its transition blend; the scheme's
// masks (scheme.h) supply the weights. The children are built in parallel parts, one worker each.
#include "far/tables/level_stencils.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <type_traits>


#include "far/schemes/crease.h"
#include "far/schemes/regular_masks.h"
#include "far/schemes/scheme.h"
#include "far/internal/sparse_accumulator.h"
#include "far/tables/stencil_writer.h"
#include "far/internal/parallel.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

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
    const SchemeRules& rules;
    std::vector<int> faceOfPoint;           // parent face of each face point
    std::vector<float> childEdgeSharpness;  // per (vertex, incident edge), parallel to t.vertEdges
    std::vector<float> childSharpnessAtEnds;  // the same per edge: 2e at edgeVerts[2e], 2e + 1 at the other end
    // No crease rule applies: no sharp edge or vertex in the level (closed, uncreased), or a
    // scheme whose masks sharpness does not change.
    bool smooth;
    std::unique_ptr<SchemeLevel> prepared;  // what the scheme builds once per level, or null
    const std::uint8_t* wanted;             // per child: whether its mask is built (null: all)
};

// One worker's state: the accumulator and the scheme's masks hold per-mask scratch, so each
// worker has its own.
struct Worker {
    SparseAccumulator acc;
    std::unique_ptr<SchemeMasks> masks;
    std::vector<float> parentEdgeSharpness;  // per incident edge of the current vertex

    explicit Worker(const LevelInputs& in)
        : acc(in.t.numVertices), masks(in.rules.makeMasks(in.t, in.options, in.prepared.get(), acc)) {}
};

void edgeMask(const LevelInputs& in, Worker& w, int e) {
    const Topology& t = in.t;
    SchemeMasks& masks = *w.masks;
    if (in.smooth) return masks.smoothEdgePoint(e, 1.0);
    // The edge point is a crease point when both child halves stay sharp. Uniform decay keeps
    // them sharp exactly when s > 1 (s = 1 blends with weight 1, the same point); Chaikin can
    // smooth the children of an edge with s > 1 next to weaker creases, and the blend then
    // uses s unclamped, as OpenSubdiv does.
    const float s = t.edgeSharpness[e];
    bool sharp = isInfinite(s) || t.edgeFaceCount(e) != 2;
    if (!sharp && isSharp(s)) {
        sharp = in.options.creaseMethod == CreaseMethod::Uniform
                    ? s >= 1.0f
                    : in.childSharpnessAtEnds[2 * e] > 0.0f && in.childSharpnessAtEnds[2 * e + 1] > 0.0f;
    }
    if (sharp) {
        masks.sharpEdgePoint(e, 1.0);
    } else if (!isSharp(s)) {
        masks.smoothEdgePoint(e, 1.0);
    } else {  // semi-sharp edge whose children are smooth: blend by the parent sharpness
        masks.sharpEdgePoint(e, s);
        masks.smoothEdgePoint(e, 1.0 - s);
    }
}

void vertexMask(const LevelInputs& in, Worker& w, int v) {
    const Topology& t = in.t;
    SchemeMasks& masks = *w.masks;
    if (in.smooth) return masks.vertexPoint(v, VertexRule::Smooth, nullptr, 1.0);
    const IndexSpan edges = t.edgesOfVertex(v);
    const int n = edges.size();
    std::vector<float>& parentSharpness = w.parentEdgeSharpness;
    parentSharpness.resize(n);
    for (int i = 0; i < n; ++i) parentSharpness[i] = t.edgeSharpness[edges[i]];
    const float* childSharpness = in.childEdgeSharpness.data() + t.vertEdgeOffsets[v];
    const float pVertex = t.vertSharpness[v], cVertex = decrementSharpness(pVertex);
    const VertexRule pRule = vertexRule(pVertex, countSharp(parentSharpness.data(), n));
    const VertexRule cRule = vertexRule(cVertex, countSharp(childSharpness, n));
    if (pRule == VertexRule::Smooth || pRule == VertexRule::Dart || pRule == cRule) {
        masks.vertexPoint(v, pRule, parentSharpness.data(), 1.0);
    } else {  // the rule relaxes this level: blend the parent's and the child's masks
        const double weight = transitionWeight(pVertex, cVertex, n, parentSharpness.data(), childSharpness);
        masks.vertexPoint(v, pRule, parentSharpness.data(), weight);
        masks.vertexPoint(v, cRule, childSharpness, 1.0 - weight);
    }
}

// Builds the masks of one worker's children, one call of build(c) per child, appended in the
// order of the calls. Float tables of smooth levels take the regular masks' short cut
// (regular_masks.h) where the scheme allows it (SchemeRules::regularMasksApply,
// SchemeMasks::regularFace / regularEdge / regularVertex).
template <typename Table>
class MaskBuilder {
public:
    MaskBuilder(const LevelInputs& in, StencilWriter<Table>& writer) : in_(in), writer_(writer), w_(in), regular_(in.t) {}

    void build(int c) {
        int n = 0, key = 0;
        if constexpr (kFloat) {
            // Gathered straight into the table, kept there when the key's weights are known.
            if (shortCut_) {
                int* out = writer_.nextIndices(kMaxGathered);
                if (c < edgePoints_) {
                    const int f = in_.faceOfPoint[c];
                    if (w_.masks->regularFace(f)) n = regular_.face(f, out, key);
                } else if (c < vertexPoints_) {
                    const int e = c - edgePoints_;
                    if (w_.masks->regularEdge(e)) n = regular_.edge(e, out, key);
                } else {
                    const int v = c - vertexPoints_;
                    if (w_.masks->regularVertex(v)) n = regular_.vertex(v, out, key);
                }
                if (n > 0 && regular_.weights(key) >= 0) {
                    writer_.appendGathered(n, regular_.weights(key));
                    return;
                }
                if (n > 0) std::copy(out, out + n, gathered_);
            }
        }
        if (c < edgePoints_)
            w_.masks->facePoint(in_.faceOfPoint[c], 1.0);
        else if (c < vertexPoints_)
            edgeMask(in_, w_, c - edgePoints_);
        else
            vertexMask(in_, w_, c - vertexPoints_);
        writer_.append(w_.acc);
        if constexpr (kFloat) {
            if (n > 0 && regular_.weights(key) == RegularMasks::kUnknown)
                regular_.setWeights(key, writer_.lastHasIndices(gathered_, n) ? writer_.lastWeightOffset()
                                                                              : RegularMasks::kNever);
        }
    }

private:
    static constexpr bool kFloat = std::is_same_v<Table, StencilTable>;
    static constexpr int kMaxGathered = 2 * RegularMasks::kMaxValence + 1;

    const LevelInputs& in_;
    StencilWriter<Table>& writer_;
    Worker w_;
    RegularMasks regular_;
    const int edgePoints_ = in_.num.numFacePoints, vertexPoints_ = edgePoints_ + in_.t.numEdges();
    const bool shortCut_ = kFloat && in_.smooth && in_.rules.regularMasksApply();
    int gathered_[kMaxGathered];  // the first mask of a key's vertices, compared with the rules'
};

// Masks of children [first, last) in child order (face points, edge points, vertex points).
template <typename Table>
void buildRange(const LevelInputs& in, StencilWriter<Table>& writer, int first, int last) {
    MaskBuilder<Table> builder(in, writer);
    for (int c = first; c < last; ++c) {
        if (in.wanted && !in.wanted[c])
            writer.appendEmpty();
        else
            builder.build(c);
    }
}

// Children per part below which a level is not split: a part's worker setup and the copy that
// joins it must stay small next to its masks.
constexpr int kMinChildrenPerPart = 32768;

// The child sharpness the masks read: per vertex's edges, and per edge end under Chaikin; at
// every vertex, or at those the masks of `children` read.
void prepareSharpness(LevelInputs& in, const std::vector<float>* childEdgeSharpness, const std::vector<int>* children) {
    if (in.smooth) return;
    const Topology& t = in.t;
    in.childEdgeSharpness.resize(t.vertEdges.size());
    if (childEdgeSharpness) in.childEdgeSharpness = *childEdgeSharpness;
    const bool chaikin = in.options.creaseMethod == CreaseMethod::Chaikin;  // edge points read both ends
    if (chaikin) in.childSharpnessAtEnds.resize(t.edgeVerts.size());
    auto prepare = [&](int v) {
        if (!childEdgeSharpness)
            childEdgeSharpnessAtVertex(t, v, in.options.creaseMethod, in.childEdgeSharpness.data() + t.vertEdgeOffsets[v]);
        const IndexSpan edges = t.edgesOfVertex(v);
        for (int i = 0; chaikin && i < edges.size(); ++i) {
            const int e = edges[i];
            in.childSharpnessAtEnds[2 * e + (t.edgeVerts[2 * e] == v ? 0 : 1)] = in.childEdgeSharpness[t.vertEdgeOffsets[v] + i];
        }
    };
    if (!children) {
        for (int v = 0; v < t.numVertices; ++v) prepare(v);
        return;
    }
    const int edgePoints = in.num.numFacePoints, vertexPoints = edgePoints + t.numEdges();
    std::vector<int> vertices;
    for (int c : *children) {
        if (c >= vertexPoints) {
            vertices.push_back(c - vertexPoints);
        } else if (c >= edgePoints && chaikin) {
            vertices.push_back(t.edgeVerts[2 * (c - edgePoints)]);
            vertices.push_back(t.edgeVerts[2 * (c - edgePoints) + 1]);
        }
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    for (int v : vertices) prepare(v);
}

// `children` and `faces`, when given: only the masks of those children are built, and the
// scheme prepares only the level's `faces` (SchemeRules::prepareLevel).
LevelInputs makeInputs(const Topology& t, const ChildNumbering& num, const Options& options,
                       const std::vector<float>* childEdgeSharpness, const std::uint8_t* wanted,
                       const std::vector<int>* children = nullptr, const std::vector<int>* faces = nullptr) {
    const SchemeRules& rules = rulesOf(options.scheme);
    const bool smooth = !rules.usesSharpness() || !hasSharpness(t);
    LevelInputs in{t, num, options, rules, std::vector<int>(num.numFacePoints), {}, {}, smooth,
                   rules.prepareLevel(t, options, faces), wanted};
    for (int f = 0; f < t.numFaces(); ++f)
        if (num.facePoint[f] >= 0) in.faceOfPoint[num.facePoint[f]] = f;
    prepareSharpness(in, childEdgeSharpness, children);
    return in;
}

}  // namespace

// The children are split into one contiguous part per thread; the first part writes straight
// into the table, the others into their own tables, appended in order afterwards.
template <typename Table>
Table buildLevelStencils(const Topology& t, const ChildNumbering& num, const Options& options,
                         const std::vector<float>* childEdgeSharpness, const std::vector<std::uint8_t>* wanted) {
    const int numChildren = num.numFacePoints + t.numEdges() + t.numVertices;
    const LevelInputs in = makeInputs(t, num, options, childEdgeSharpness, wanted ? wanted->data() : nullptr);

    // Reserve an upper bound of the entries: untouched reserved pages cost nothing, while
    // growing by doubling would copy and touch the arrays several times over.
    std::size_t bound = 4 * std::size_t(t.numEdges()) + t.numVertices;
    for (int f = 0; f < t.numFaces(); ++f) bound += std::size_t(t.faceSize(f)) * (1 + 2 * t.faceSize(f));
    // The threads that can run: the arena's, unless a tbb::global_control allows fewer (a part
    // per thread that cannot run would only add its join).
    const int threads = parallel::allowedThreads();
    const int parts = std::max(1, std::min(threads, numChildren / kMinChildrenPerPart));
    auto split = [&](int k) { return int(std::int64_t(numChildren) * k / parts); };
    auto partBound = [&](int k) {
        return std::size_t(double(bound) * (split(k + 1) - split(k)) / std::max(1, numChildren)) + 64;
    };

    Table table;
    table.numSourceVertices = t.numVertices;
    StencilWriter<Table> writer(table, numChildren, bound);
    std::vector<Table> rest(parts - 1);
    parallel::forEachPart(0, parts, [&](int k) {
        if (k == 0) return buildRange(in, writer, 0, split(1));
        Table& part = rest[k - 1];
        part.numSourceVertices = t.numVertices;
        StencilWriter<Table> partWriter(part, split(k + 1) - split(k), partBound(k));
        buildRange(in, partWriter, split(k), split(k + 1));
        partWriter.finish();
    });
    writer.append(rest);
    writer.finish();
    return table;
}

template <typename Table>
Table buildChildStencils(const Topology& t, const ChildNumbering& num, const Options& options,
                         const std::vector<int>& children, const std::vector<int>& faces) {
    const LevelInputs in = makeInputs(t, num, options, nullptr, nullptr, &children, &faces);
    Table table;
    table.numSourceVertices = t.numVertices;
    StencilWriter<Table> writer(table, int(children.size()), 16 * children.size());
    MaskBuilder<Table> builder(in, writer);
    for (int c : children) builder.build(c);
    writer.finish();
    return table;
}

template StencilTable buildChildStencils<StencilTable>(const Topology&, const ChildNumbering&, const Options&,
                                                       const std::vector<int>&, const std::vector<int>&);
template StencilTableD buildChildStencils<StencilTableD>(const Topology&, const ChildNumbering&, const Options&,
                                                         const std::vector<int>&, const std::vector<int>&);
template StencilTable buildLevelStencils<StencilTable>(const Topology&, const ChildNumbering&, const Options&,
                                                       const std::vector<float>*, const std::vector<std::uint8_t>*);
template StencilTableD buildLevelStencils<StencilTableD>(const Topology&, const ChildNumbering&, const Options&,
                                                         const std::vector<float>*, const std::vector<std::uint8_t>*);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
