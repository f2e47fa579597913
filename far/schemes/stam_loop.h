// Stam-Loop quad/triangle rules (docs/schemes/stam_loop.md): Catmull-Clark on quads, Loop on
// triangles, corrected mixed vertices. Each mask is the two-pass form (linear split, averaging
// with α = 1/(1 + nE/2 + nQ/4), β = α/2, γ = α/4, then the η correction) expanded over the parent
// vertices:
//   face point:   centroid.
//   edge point:   α(1 + T/4) per endpoint, α/2 per triangle's opposite vertex, α per quad-like
//                 face's centroid; α = 1/(2 + T + Q). Using the centroid for an n-gon's diagonal
//                 corners gives Catmull-Clark's edge rule next to n-gons.
//   vertex point: (1+η)(α(1 + nE/4) v + α/4 Σ neighbours + α/4 Σ quad-like centroids) − η v.
// Sharp masks are the shared DeRose ones (scheme.h). Schaefer-Warren and catmark-butterfly
// derive from these masks and replace the ones they change.
#pragma once

#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// η of the Stam-Loop correction v2 = v1 + η (v1 - v0) for a smooth vertex with nE incident
// edges, nQ quad-like and nT triangular faces (docs/schemes/stam_loop.md, §3).
double stamLoopEta(int nE, int nQ, int nT);

class StamLoopMasks : public SchemeMasks {
public:
    using SchemeMasks::SchemeMasks;
    void smoothEdgePoint(int edge, double scale) override;

protected:
    void smoothVertexPoint(int vertex, double scale) override;
};

const SchemeRules& stamLoopRules();

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
