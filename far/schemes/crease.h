// DeRose semi-sharp creases as OpenSubdiv applies them: sharpness decay and vertex rules
// (docs/schemes/creases.md). Sharpness is float, as in OpenSubdiv, so decayed values match it
// bit for bit.
#pragma once

#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

inline bool isSharp(float s) { return s > 0.0f; }
inline bool isInfinite(float s) { return s >= kInfiniteSharpness; }
inline bool isSemiSharp(float s) { return s > 0.0f && s < kInfiniteSharpness; }

// Uniform decay: infinite stays, otherwise s - 1 clamped at 0. Vertex sharpness always decays so.
inline float decrementSharpness(float s) {
    if (s <= 0.0f) return 0.0f;
    if (isInfinite(s)) return kInfiniteSharpness;
    return s > 1.0f ? s - 1.0f : 0.0f;
}

// Whether any edge or vertex of the level has sharpness > 0: without, no crease rule applies and
// no sharpness passes to the children.
bool hasSharpness(const Topology& topology);

enum class VertexRule { Smooth, Dart, Crease, Corner };

// Rule of a vertex from its own sharpness and the number of incident edges with sharpness > 0.
inline VertexRule vertexRule(float vertexSharpness, int sharpEdgeCount) {
    if (isSharp(vertexSharpness)) return VertexRule::Corner;
    if (sharpEdgeCount == 0) return VertexRule::Smooth;
    if (sharpEdgeCount == 1) return VertexRule::Dart;
    if (sharpEdgeCount == 2) return VertexRule::Crease;
    return VertexRule::Corner;
}

// Sharpness of the child of every edge incident to vertex v (in vertEdges order) at v's end.
// `out` has topology.vertexEdgeCount(v) entries.
void childEdgeSharpnessAtVertex(const Topology& topology, int v, CreaseMethod method, float* out);

// The fraction of the parent rule's mask kept when the rule changes from parent to child: the
// mean of the sharpness values (vertex and incident edges) that decay to zero, at most 1.
float transitionWeight(float parentVertexSharpness, float childVertexSharpness, int edgeCount,
                       const float* parentEdgeSharpness, const float* childEdgeSharpness);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
