// The closed-form limit masks (docs/limit.md): Catmull-Clark and Loop as OpenSubdiv's
// PrimvarRefiner::Limit applies them (smooth, dart, crease, corner), and the bilinear choice.
// Each appends to `out` (empty) position, dU and dV weights over the vertex's ring.
#pragma once

#include "far/limit/limit_mask.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

void catmullClarkLimit(const LimitVertex& vertex, LimitMask& out);
void loopLimit(const LimitVertex& vertex, LimitMask& out);
// The vertex itself; tangents those of Loop's rules over the edge neighbours (docs/limit.md).
void bilinearLimit(const LimitVertex& vertex, LimitMask& out);

// Whether every face around the vertex has `corners` corners.
bool ringFacesHave(const LimitVertex& vertex, int corners);

// For the mixed schemes: Catmull-Clark's closed form where every face around the vertex is a
// quad, or (`loopOnTriangles`) Loop's where every one is a triangle, and no corner of those faces
// is on a tri/quad seam, so that the scheme's masks there and on every later level are those
// schemes' own (docs/limit.md). Returns false, writing nothing, elsewhere.
bool pureClosedForm(const LimitVertex& vertex, bool loopOnTriangles, LimitMask& out);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
