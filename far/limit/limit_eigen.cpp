// The generic limit masks (docs/limit_eigen.md): a vertex's configuration is analysed once (its
// local subdivision matrix's eigen-structure, far/limit/configuration_limit.cpp) and its masks laid over
// the vertex's ring neighbourhood. Where that neighbourhood is not yet the configuration's own (another
// irregularity within a ring or two, a semi-sharp crease still decaying, a face that is not a
// triangle or quad), a patch around the vertex is refined locally until it is, and the
// descendant's masks are brought back through the patch tables: the same limit, exactly.
#include "far/limit/limit_eigen.h"

#include <algorithm>
#include <array>
#include <map>

#include "far/limit/configuration_limit.h"
#include "far/schemes/crease.h"
#include "far/limit/limit_deeper.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// Levels refined locally at most: enough for a crease of sharpness up to this to decay and for
// any irregularity near the vertex to fall behind its neighbourhood.
constexpr int kMaxDeeperLevels = 10;

// A mask as three weights per vertex of some level.
using SparseMask = std::map<int, std::array<double, 3>>;  // ordered: the same table on every run
// The same as a list, each vertex once, in no particular order (sorted into a SparseMask's order
// before it becomes a LimitMask): what the common paths build, without a node per vertex.
using MaskEntries = std::vector<std::pair<int, std::array<double, 3>>>;

// Where there is no limit to analyse (a non-manifold vertex, one without faces or beside a hole)
// or none needed (a fixed corner): the vertex itself, and the two edges of `face` at it (-1: its first face in
// Topology's order) as the tangent pair.
void ownPositionAndFaceEdges(const Topology& t, int v, int face, SparseMask& m) {
    m[v][0] += 1.0;
    if (face < 0) {
        if (t.vertexFaceCount(v) == 0) return;
        face = t.facesOfVertex(v)[0];
    }
    const IndexSpan c = t.verticesOfFace(face);
    const int i = t.cornerOfVertex(face, v), n = c.size();
    m[c[(i + 1) % n]][1] += 1.0;
    m[v][1] -= 1.0;
    m[c[(i + n - 1) % n]][2] += 1.0;
    m[v][2] -= 1.0;
}

// A corner whose sharpness never decays: every level keeps it in place, so it is its own limit
// at any level, and its tangents are its first face's edges there.
bool isFixedCorner(const Topology& t, int v, const Options& options) {
    if (isInfinite(t.vertSharpness[v])) return true;
    int sharp = 0;
    for (int e : t.edgesOfVertex(v)) sharp += isInfinite(t.edgeSharpness[e]) || t.edgeFaceCount(e) == 1 ? 1 : 0;
    const bool loneFace = (t.vertFlags[v] & kVertexCorner) && options.boundary == BoundaryInterpolation::EdgeAndCorner;
    return sharp > 2 || loneFace;
}

bool touchesHole(const Topology& t, int v) {
    for (int f : t.facesOfVertex(v))
        if (t.faceHole[f]) return true;
    return false;
}

struct Found {
    const LocalLimitMask* analysis = nullptr;
    bool settled = false;
};

// The configuration's masks at v of level t, appended to `m`, if its neighbourhood there is the
// configuration's own (or, with `acceptUnsettled`, at least as large).
Found laidOver(const Topology& t, int v, const Options& options, LimitMaskCache& cache, bool acceptUnsettled,
               MaskEntries& m) {
    Found found;
    const std::optional<VertexFan> fan = fanOf(t, v, options);
    if (!fan) return found;
    const LocalLimitMask& limit = cachedLimit(fan->configuration, options, cache);
    if (limit.rings == 0) return found;
    Neighbourhood& ring = cache.scratch().ring;
    // Unless an unsettled one will do, the walk stops where the neighbourhood departs from the
    // configuration's: most vertices of a seam-dense level do, early.
    const bool alike = gatherNeighbourhood(t, v, fan->faces[0], limit.rings, cache.scratch().walk, ring,
                                           acceptUnsettled ? nullptr : &limit.signature);
    if (!alike || ring.vertices.size() != limit.position.size()) return found;
    found.settled = ring.signature == limit.signature;
    if (!found.settled && !acceptUnsettled) return found;
    found.analysis = &limit;
    for (size_t k = 0; k < ring.vertices.size(); ++k) {
        std::array<double, 3> w{};  // zero plus the weight, as a sum would start (a -0.0 weight turns +0.0)
        w[0] += limit.position[k];
        w[1] += limit.du[k];
        w[2] += limit.dv[k];
        m.push_back({ring.vertices[k], w});
    }
    return found;
}

// `m` over a patch's child vertices brought back over the vertices the patch was cut from, or
// (`ownNumbering`) over the patch's own vertices.
SparseMask throughPatch(const PatchStep& step, const SparseMask& m, bool ownNumbering) {
    SparseMask out;
    for (const auto& [child, w] : m) {
        const StencilTableD& t = step.table;
        for (int k = t.offsets[child]; k < t.offsets[child] + t.sizes[child]; ++k) {
            auto& o = out[ownNumbering ? t.indices[k] : step.source[t.indices[k]]];
            for (int c = 0; c < 3; ++c) o[c] += t.weights[k] * w[c];
        }
    }
    return out;
}

// A vertex whose neighbourhood has not settled, followed down the patch `cut` until it does (or
// kMaxDeeperLevels): its masks over the cut's vertices.
FollowedDown followDown(const PatchCut& cut, const Options& options, LimitMaskCache& cache) {
    FollowedDown result;
    std::vector<PatchStep> steps;
    steps.push_back(refineCut(cut, options));
    MaskEntries deepest;  // the masks where the neighbourhood settled, over the last patch
    for (int depth = 1; depth <= kMaxDeeperLevels; ++depth) {
        const Found found = laidOver(steps.back().child, steps.back().descendant, options, cache,
                                     depth == kMaxDeeperLevels, deepest);
        if (found.analysis) {
            result.analysis = found.analysis;
            result.settled = found.settled;
            result.deeperLevels = depth;
            break;
        }
        if (depth < kMaxDeeperLevels)
            steps.push_back(refinePatch(steps.back().child, steps.back().descendant, options, cache.scratch().walk));
    }
    if (!result.analysis) return result;
    SparseMask m(deepest.begin(), deepest.end());
    for (auto step = steps.rbegin(); step != steps.rend(); ++step) m = throughPatch(*step, m, step + 1 == steps.rend());
    result.mask.assign(m.begin(), m.end());
    return result;
}

}  // namespace

EigenLimitReport eigenLimit(const Topology& level, int vertex, const Options& options, int firstFace,
                            LimitMaskCache& cache, LimitMask& out) {
    EigenLimitReport report;
    MaskEntries& m = cache.scratch().entries;
    m.clear();
    // Nothing to analyse at a non-manifold or isolated vertex or one beside a hole (its fan never
    // closes into a configuration); nothing needed at a fixed corner.
    const bool ownLimit = (level.vertFlags[vertex] & kVertexNonManifold) || level.vertexFaceCount(vertex) == 0 ||
                          touchesHole(level, vertex) || isFixedCorner(level, vertex, options);
    if (!ownLimit) {
        const Found found = laidOver(level, vertex, options, cache, false, m);
        report.analysis = found.analysis;
        report.settled = found.settled;
        if (!found.analysis) {
            // The patch decides everything below, so a vertex with the same patch as one seen
            // before has that one's masks, to the bit.
            LimitScratch& scratch = cache.scratch();
            const PatchCut& cut = scratch.cut;
            cutPatch(level, vertex, scratch.walk, scratch.cut);
            cut.key(options, scratch.key);
            const FollowedDown* known = cache.findFollowed(scratch.key);
            FollowedDown computed;
            if (!known) {
                computed = followDown(cut, options, cache);
                known = &computed;
            }
            report.analysis = known->analysis;
            report.settled = known->settled;
            report.deeperLevels = known->deeperLevels;
            for (const auto& [u, w] : known->mask) m.push_back({cut.source[u], w});
            if (known == &computed) cache.insertFollowed(scratch.key, std::move(computed));
        }
    }
    if (!report.analysis) {
        SparseMask own;
        ownPositionAndFaceEdges(level, vertex, firstFace, own);
        m.assign(own.begin(), own.end());
        report.settled = isFixedCorner(level, vertex, options);  // exact there
    }
    // Each vertex is in m once: in vertex order, as a SparseMask lists them.
    std::sort(m.begin(), m.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    // Topology stores faces counter-clockwise seen from outside (left-handed input reversed), the
    // way the fan is read: dU × dV points outside.
    for (const auto& [u, w] : m) out.add(u, w[0], w[1], w[2]);
    return report;
}

void limitFromLocalMatrix(const SchemeRules&, const LimitVertex& vertex, LimitMaskCache& cache, LimitMask& out) {
    eigenLimit(vertex.level, vertex.ring.vertex, vertex.options, vertex.ring.faces.empty() ? -1 : vertex.ring.faces[0],
               cache, out);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
