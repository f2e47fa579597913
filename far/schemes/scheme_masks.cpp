// The masks every scheme shares unless it overrides them: DeRose's sharp rules (midpoint, the
// crease's ¾ ⅛, a fixed corner; docs/schemes/creases.md) and the dispatch by vertex rule.
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

void SchemeMasks::sharpEdgePoint(int e, double scale) {
    acc_.add(t_.edgeVerts[2 * e], 0.5 * scale);
    acc_.add(t_.edgeVerts[2 * e + 1], 0.5 * scale);
}

void SchemeMasks::vertexPoint(int v, VertexRule rule, const float* edgeSharpness, double scale) {
    switch (rule) {
    case VertexRule::Smooth:
    case VertexRule::Dart: smoothVertexPoint(v, scale); break;
    case VertexRule::Crease: creaseVertexPoint(v, edgeSharpness, scale); break;
    case VertexRule::Corner: cornerVertexPoint(v, scale); break;
    }
}

void SchemeMasks::creaseVertexPoint(int v, const float* edgeSharpness, double scale) {
    acc_.add(v, 0.75 * scale);
    const IndexSpan edges = t_.edgesOfVertex(v);
    for (int i = 0; i < edges.size(); ++i)
        if (isSharp(edgeSharpness[i])) acc_.add(t_.otherVertex(edges[i], v), 0.125 * scale);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
