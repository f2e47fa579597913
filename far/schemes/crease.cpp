#include "far/schemes/crease.h"

#include <algorithm>

namespace quadtri {
inline namespace v0 {
namespace internal {

bool hasSharpness(const Topology& t) {
    return std::any_of(t.edgeSharpness.begin(), t.edgeSharpness.end(), isSharp) ||
           std::any_of(t.vertSharpness.begin(), t.vertSharpness.end(), isSharp);
}

void childEdgeSharpnessAtVertex(const Topology& t, int v, CreaseMethod method, float* out) {
    const IndexSpan edges = t.edgesOfVertex(v);
    const int n = edges.size();
    float semiSharpSum = 0.0f;
    int semiSharpCount = 0;
    for (int e : edges) {
        const float s = t.edgeSharpness[e];
        if (isSemiSharp(s)) {
            semiSharpSum += s;
            ++semiSharpCount;
        }
    }
    for (int i = 0; i < n; ++i) {
        const float s = t.edgeSharpness[edges[i]];
        if (method == CreaseMethod::Uniform || semiSharpCount < 2 || !isSemiSharp(s)) {
            out[i] = decrementSharpness(s);
        } else {
            // Chaikin: 3/4 of the edge's own sharpness plus 1/4 of the mean of the other
            // semi-sharp edges at this vertex, then - 1.
            const float others = (semiSharpSum - s) / float(semiSharpCount - 1);
            const float child = (0.75f * s + 0.25f * others) - 1.0f;
            out[i] = child > 0.0f ? child : 0.0f;
        }
    }
}

float transitionWeight(float parentVertexSharpness, float childVertexSharpness, int edgeCount,
                       const float* parentEdgeSharpness, const float* childEdgeSharpness) {
    int count = 0;
    float sum = 0.0f;
    if (isSharp(parentVertexSharpness) && !isSharp(childVertexSharpness)) {
        count = 1;
        sum = parentVertexSharpness;
    }
    for (int i = 0; i < edgeCount; ++i) {
        if (isSharp(parentEdgeSharpness[i]) && !isSharp(childEdgeSharpness[i])) {
            sum += parentEdgeSharpness[i];
            ++count;
        }
    }
    if (count == 0) return 0.0f;
    const float w = sum / float(count);
    return w > 1.0f ? 1.0f : w;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
