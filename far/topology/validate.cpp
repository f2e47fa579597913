// Input validation: every index and value the analyzer will trust is checked here first.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <quadtri/far/topology.h>
#include "far/topology/topology_builder.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

using Component = TopologyError::Component;

[[noreturn]] void fail(const std::string& what) { throw TopologyError(what); }
[[noreturn]] void fail(Component component, int index, int vertex, const std::string& problem) {
    throw TopologyError({component, index, vertex, problem});
}

void checkArray(int count, const void* array, const char* countName, const char* arrayName) {
    if (count < 0) fail(std::string(countName) + " is negative (" + std::to_string(count) + ")");
    if (count > 0 && array == nullptr)
        fail(std::string(arrayName) + " is null but " + countName + " is " + std::to_string(count));
}

void checkSharpness(float s, const std::string& what, Component component, int index) {
    if (!std::isfinite(s)) fail(component, index, -1, what + "sharpness is not a finite number");
    if (s < 0) {
        char value[32];
        std::snprintf(value, sizeof value, "%g", double(s));
        fail(component, index, -1, what + "negative sharpness " + value);
    }
}

}  // namespace

void validateDescriptor(const TopologyDescriptor& d) {
    if (d.numVertices < 0) fail("numVertices is negative (" + std::to_string(d.numVertices) + ")");
    checkArray(d.numFaces, d.numVertsPerFace, "numFaces", "numVertsPerFace");
    checkArray(d.numFaces, d.faceVertIndices, "numFaces", "faceVertIndices");
    checkArray(d.numCreases, d.creaseVertexPairs, "numCreases", "creaseVertexPairs");
    checkArray(d.numCreases, d.creaseWeights, "numCreases", "creaseWeights");
    checkArray(d.numCorners, d.cornerVertexIndices, "numCorners", "cornerVertexIndices");
    checkArray(d.numCorners, d.cornerWeights, "numCorners", "cornerWeights");
    checkArray(d.numHoles, d.holeIndices, "numHoles", "holeIndices");

    long long total = 0;
    for (int f = 0; f < d.numFaces; ++f) {
        const int n = d.numVertsPerFace[f];
        if (n < 3) fail(Component::Face, f, -1, "has " + std::to_string(n) + " vertices; a face needs at least 3");
        const int* verts = d.faceVertIndices + total;
        total += n;
        if (total > (1LL << 31) - 1) fail(Component::Face, f, -1, "more than 2^31 face-vertex indices in total");
        for (int i = 0; i < n; ++i)
            if (verts[i] < 0 || verts[i] >= d.numVertices)
                fail(Component::Face, f, -1,
                     "vertex index " + std::to_string(verts[i]) + " is out of range [0, " + std::to_string(d.numVertices) + ")");
        // Repeated vertices are not an error: the face is read as the loops it walks around
        // (face_loops.h).
    }
    checkArray(d.numFVarChannels, d.fvarChannels, "numFVarChannels", "fvarChannels");
    for (int c = 0; c < d.numFVarChannels; ++c) {
        const FVarChannel& channel = d.fvarChannels[c];
        const std::string name = "face-varying channel " + std::to_string(c);
        if (channel.numValues < 0) fail(name + ": numValues is negative (" + std::to_string(channel.numValues) + ")");
        if (total > 0 && channel.valueIndices == nullptr) fail(name + ": valueIndices is null");
        const int* values = channel.valueIndices;
        for (int f = 0; f < d.numFaces; ++f)
            for (int i = 0; i < d.numVertsPerFace[f]; ++i, ++values)
                if (*values < 0 || *values >= channel.numValues)
                    fail(Component::Face, f, -1,
                         name + ": value index " + std::to_string(*values) + " is out of range [0, " +
                             std::to_string(channel.numValues) + ")");
    }
    for (int i = 0; i < d.numCreases; ++i) {
        const int a = d.creaseVertexPairs[2 * i], b = d.creaseVertexPairs[2 * i + 1];
        const std::string what = "vertices " + std::to_string(a) + ", " + std::to_string(b) + ": ";
        if (a < 0 || a >= d.numVertices || b < 0 || b >= d.numVertices)
            fail(Component::Crease, i, -1, what + "vertex index out of range [0, " + std::to_string(d.numVertices) + ")");
        if (a == b) fail(Component::Crease, i, -1, what + "both ends are the same vertex");
        checkSharpness(d.creaseWeights[i], what, Component::Crease, i);
    }
    for (int i = 0; i < d.numCorners; ++i) {
        const int v = d.cornerVertexIndices[i];
        if (v < 0 || v >= d.numVertices)
            fail(Component::Corner, i, -1,
                 "vertex " + std::to_string(v) + " is out of range [0, " + std::to_string(d.numVertices) + ")");
        checkSharpness(d.cornerWeights[i], "vertex " + std::to_string(v) + ": ", Component::Corner, i);
    }
    for (int i = 0; i < d.numHoles; ++i) {
        const int f = d.holeIndices[i];
        if (f < 0 || f >= d.numFaces)
            fail(Component::Hole, i, -1,
                 "face index " + std::to_string(f) + " is out of range [0, " + std::to_string(d.numFaces) + ")");
    }
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
