// Bilinear subdivision: corners stay, edge points are midpoints, face points centroids.
// Sharpness changes none of these masks, so every level is built as smooth.
#include "far/limit/limit_closed_forms.h"
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

class BilinearMasks : public SchemeMasks {
public:
    using SchemeMasks::SchemeMasks;
    void smoothEdgePoint(int edge, double scale) override { sharpEdgePoint(edge, scale); }

protected:
    void smoothVertexPoint(int vertex, double scale) override { acc_.add(vertex, scale); }
};

class BilinearRules : public SchemeRules {
public:
    SurfacePatches surfacePatches() const override { return {true, false, false, false}; }
    int surfaceRings() const override { return 1; }
    const char* name() const override { return "bilinear"; }
    const char* description() const override {
        return "linear subdivision only: corners stay, edge midpoints, face centroids";
    }
    bool usesSharpness() const override { return false; }
    void limitMask(const LimitVertex& vertex, LimitMaskCache&, LimitMask& out) const override {
        bilinearLimit(vertex, out);
    }
    std::unique_ptr<SchemeMasks> makeMasks(const Topology& parent, const Options&, const SchemeLevel*,
                                           SparseAccumulator& accumulator) const override {
        return std::make_unique<BilinearMasks>(parent, accumulator);
    }
};

}  // namespace

const SchemeRules& bilinearRules() {
    static const BilinearRules rules;
    return rules;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
