// Loop subdivision exactly as OpenSubdiv's Loop scheme (docs/schemes/loop.md), on meshes of
// triangles only (any other face is refused before refinement):
//   edge point:   ⅜ each end + ⅛ each opposite corner.
//   vertex point: (1 − nβ) v + β Σ neighbours, β = (⅝ − (⅜ + ¼ cos 2π/n)²)/n, n = incident faces
//                 (β = 1/16 at the regular valence 6).
// Creases, corners and their blends are the shared rules (scheme.h, rules.cpp).
#include <cmath>

#include "far/limit/limit_closed_forms.h"
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

double loopBeta(int n) {
    if (n == 6) return 1.0 / 16.0;
    const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * M_PI / n);
    return (5.0 / 8.0 - c * c) / n;
}

class LoopMasks : public SchemeMasks {
public:
    using SchemeMasks::SchemeMasks;

    void smoothEdgePoint(int e, double scale) override {
        const int a = t_.edgeVerts[2 * e], b = t_.edgeVerts[2 * e + 1];
        const IndexSpan faces = t_.facesOfEdge(e);
        acc_.add(a, scale * 0.375);
        acc_.add(b, scale * 0.375);
        const double opposite = scale * 0.125 * 2.0 / faces.size();
        for (int f : faces)
            for (int c : t_.verticesOfFace(f))
                if (c != a && c != b) acc_.add(c, opposite);
    }

protected:
    void smoothVertexPoint(int v, double scale) override {
        const int n = t_.vertexFaceCount(v);
        const double beta = loopBeta(n);
        acc_.add(v, scale * (1.0 - n * beta));
        for (int e : t_.edgesOfVertex(v)) acc_.add(t_.otherVertex(e, v), scale * beta);
    }
};

class LoopRules : public SchemeRules {
public:
    SurfacePatches surfacePatches() const override { return {false, false, true, false}; }
    int surfaceRings() const override { return 1; }
    const char* name() const override { return "loop"; }
    const char* description() const override { return "OpenSubdiv's Loop exactly: triangles only"; }
    bool acceptsNonTriangles() const override { return false; }
    bool regularMasksApply() const override { return true; }
    std::unique_ptr<SchemeMasks> makeMasks(const Topology& parent, const Options&, const SchemeLevel*,
                                           SparseAccumulator& accumulator) const override {
        return std::make_unique<LoopMasks>(parent, accumulator);
    }
    void limitMask(const LimitVertex& vertex, LimitMaskCache&, LimitMask& out) const override { loopLimit(vertex, out); }
};

}  // namespace

const SchemeRules& loopRules() {
    static const LoopRules rules;
    return rules;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
