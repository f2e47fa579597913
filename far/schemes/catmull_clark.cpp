// Catmull-Clark exactly as OpenSubdiv's Catmark scheme (docs/schemes/catmull_clark.md): every
// face, triangles included, gets its centroid as face point and splits into quads around it.
//   edge point:   ¼ each end + ¼ each face point; with Options::smoothTriangles, an edge beside
//                 a triangle weighs the face points w = (w0 + w1)/2 each (w = 0.47 for a
//                 triangle, ¼ otherwise) and the ends (1 − 2w)/2 each.
//   vertex point: (n − 2)/n v + 1/n² Σ neighbours + 1/n² Σ face points, n = incident faces.
// Creases, corners and their blends are the shared rules (scheme.h, rules.cpp). A face with a
// collapsed edge (`4 3 5 5`) is kept as it is, as OpenSubdiv keeps it.
#include "far/limit/limit_closed_forms.h"
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// The face-point weight of a triangle beside a smooth edge under the smooth-triangle option.
constexpr double kSmoothTriangleWeight = 0.47;

class CatmullClarkMasks : public SchemeMasks {
public:
    CatmullClarkMasks(const Topology& topology, SparseAccumulator& accumulator, bool smoothTriangles)
        : SchemeMasks(topology, accumulator), smoothTriangles_(smoothTriangles) {}

    void smoothEdgePoint(int e, double scale) override {
        const IndexSpan faces = t_.facesOfEdge(e);
        double faceWeight = 0.25, endWeight = 0.25;
        if (faces.size() != 2) {
            faceWeight = 0.5 / faces.size();
        } else if (smoothTriangles_ && (t_.faceSize(faces[0]) == 3 || t_.faceSize(faces[1]) == 3)) {
            auto weightOf = [&](int f) { return t_.faceSize(f) == 3 ? kSmoothTriangleWeight : 0.25; };
            faceWeight = 0.5 * (weightOf(faces[0]) + weightOf(faces[1]));
            endWeight = 0.5 * (1.0 - 2.0 * faceWeight);
        }
        acc_.add(t_.edgeVerts[2 * e], scale * endWeight);
        acc_.add(t_.edgeVerts[2 * e + 1], scale * endWeight);
        for (int f : faces) centroid(f, scale * faceWeight);
    }

protected:
    void smoothVertexPoint(int v, double scale) override {
        const double n = t_.vertexFaceCount(v);
        const double ring = scale / (n * n);
        acc_.add(v, scale * (n - 2.0) / n);
        for (int e : t_.edgesOfVertex(v)) acc_.add(t_.otherVertex(e, v), ring);
        for (int f : t_.facesOfVertex(v)) centroid(f, ring);
    }

private:
    bool smoothTriangles_;
};

class CatmullClarkRules : public SchemeRules {
public:
    SurfacePatches surfacePatches() const override { return {false, true, false, false}; }
    int surfaceRings() const override { return 1; }
    const char* name() const override { return "catmull-clark"; }
    const char* description() const override {
        return "OpenSubdiv's Catmark exactly: every face, triangles too, split into quads";
    }
    TriangleSplit triangleSplit() const override { return TriangleSplit::ThreeQuads; }
    CollapsedEdges collapsedEdges() const override { return CollapsedEdges::Keep; }
    bool acceptsSmoothTriangles() const override { return true; }
    bool regularMasksApply() const override { return true; }
    std::unique_ptr<SchemeMasks> makeMasks(const Topology& parent, const Options& options, const SchemeLevel*,
                                           SparseAccumulator& accumulator) const override {
        return std::make_unique<CatmullClarkMasks>(parent, accumulator, options.smoothTriangles);
    }
    // OpenSubdiv's closed forms everywhere, faces of any size included (docs/limit.md).
    void limitMask(const LimitVertex& vertex, LimitMaskCache&, LimitMask& out) const override {
        catmullClarkLimit(vertex, out);
    }
};

}  // namespace

const SchemeRules& catmullClarkRules() {
    static const CatmullClarkRules rules;
    return rules;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
