#include "far/limit/limit_closed_forms.h"
#include "far/schemes/stam_loop.h"

#include <array>
#include <cmath>

namespace quadtri {
inline namespace v0 {
namespace internal {

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

void StamLoopMasks::smoothEdgePoint(int e, double scale) {
    const int a = t_.edgeVerts[2 * e], b = t_.edgeVerts[2 * e + 1];
    const IndexSpan faces = t_.facesOfEdge(e);
    int tris = 0, quads = 0;
    for (int f : faces) (t_.faceSize(f) == 3 ? tris : quads)++;
    const double alpha = 1.0 / (2 + tris + quads);
    acc_.add(a, scale * alpha * (1.0 + 0.25 * tris));
    acc_.add(b, scale * alpha * (1.0 + 0.25 * tris));
    for (int f : faces) {
        if (t_.faceSize(f) != 3) {
            centroid(f, scale * alpha);
            continue;
        }
        for (int c : t_.verticesOfFace(f))
            if (c != a && c != b) acc_.add(c, scale * alpha * 0.5);
    }
}

void StamLoopMasks::smoothVertexPoint(int v, double scale) {
    const int nE = t_.vertexEdgeCount(v);
    const VertexFaceCounts counts = countVertexFaces(t_, v);
    const double alpha = 1.0 / (1.0 + 0.5 * nE + 0.25 * counts.quads);
    const double eta = stamLoopEta(nE, counts.quads, counts.triangles);
    const double k = scale * (1.0 + eta);
    acc_.add(v, k * alpha * (1.0 + 0.25 * nE) - scale * eta);
    for (int e : t_.edgesOfVertex(v)) acc_.add(t_.otherVertex(e, v), k * alpha * 0.25);
    for (int f : t_.facesOfVertex(v))
        if (t_.faceSize(f) != 3) centroid(f, k * alpha * 0.25);
}

namespace {

class StamLoopRules : public SchemeRules {
public:
    SurfacePatches surfacePatches() const override { return {false, true, true, true}; }
    int surfaceRings() const override { return 2; }
    int surfaceLimitRings() const override { return 7; }
    const char* name() const override { return "stam-loop"; }
    const char* description() const override {
        return "Catmull-Clark on quads, Loop on triangles, corrected mixed vertices (Stam-Loop)";
    }
    bool regularMasksApply() const override { return true; }
    std::unique_ptr<SchemeMasks> makeMasks(const Topology& parent, const Options&, const SchemeLevel*,
                                           SparseAccumulator& accumulator) const override {
        return std::make_unique<StamLoopMasks>(parent, accumulator);
    }
    // Catmull-Clark's or Loop's closed form where the neighbourhood is pure (docs/limit.md).
    void limitMask(const LimitVertex& vertex, LimitMaskCache& cache, LimitMask& out) const override {
        if (!pureClosedForm(vertex, true, out)) limitFromLocalMatrix(*this, vertex, cache, out);
    }
};

}  // namespace

const SchemeRules& stamLoopRules() {
    static const StamLoopRules rules;
    return rules;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
