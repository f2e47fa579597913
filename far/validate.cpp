// Input validation: every index and value the analyzer will trust is checked here first.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "far/topology.h"

namespace quadtri {

namespace {

[[noreturn]] void fail(const std::string& what) { throw TopologyError(what); }

std::string face(int f) { return "face " + std::to_string(f); }

void checkArray(int count, const void* array, const char* countName, const char* arrayName) {
    if (count < 0) fail(std::string(countName) + " is negative (" + std::to_string(count) + ")");
    if (count > 0 && array == nullptr)
        fail(std::string(arrayName) + " is null but " + countName + " is " + std::to_string(count));
}

void checkSharpness(float s, const std::string& what) {
    if (!std::isfinite(s)) fail(what + ": sharpness is not a finite number");
    if (s < 0) fail(what + ": negative sharpness " + std::to_string(s));
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
    std::vector<int> sorted;
    for (int f = 0; f < d.numFaces; ++f) {
        const int n = d.numVertsPerFace[f];
        if (n < 3) fail(face(f) + " has " + std::to_string(n) + " vertices; a face needs at least 3");
        const int* verts = d.faceVertIndices + total;
        total += n;
        if (total > (1LL << 31) - 1) fail(face(f) + ": more than 2^31 face-vertex indices in total");
        for (int i = 0; i < n; ++i)
            if (verts[i] < 0 || verts[i] >= d.numVertices)
                fail(face(f) + ": vertex index " + std::to_string(verts[i]) + " is out of range [0, " +
                     std::to_string(d.numVertices) + ")");
        sorted.assign(verts, verts + n);
        std::sort(sorted.begin(), sorted.end());
        const auto dup = std::adjacent_find(sorted.begin(), sorted.end());
        if (dup != sorted.end()) fail(face(f) + ": vertex " + std::to_string(*dup) + " appears more than once");
    }
    for (int i = 0; i < d.numCreases; ++i) {
        const int a = d.creaseVertexPairs[2 * i], b = d.creaseVertexPairs[2 * i + 1];
        const std::string what = "crease " + std::to_string(i) + " (vertices " + std::to_string(a) + ", " +
                                 std::to_string(b) + ")";
        if (a < 0 || a >= d.numVertices || b < 0 || b >= d.numVertices) fail(what + ": vertex index out of range");
        if (a == b) fail(what + ": both ends are the same vertex");
        checkSharpness(d.creaseWeights[i], what);
    }
    for (int i = 0; i < d.numCorners; ++i) {
        const int v = d.cornerVertexIndices[i];
        const std::string what = "corner " + std::to_string(i) + " (vertex " + std::to_string(v) + ")";
        if (v < 0 || v >= d.numVertices) fail(what + ": vertex index out of range");
        checkSharpness(d.cornerWeights[i], what);
    }
    for (int i = 0; i < d.numHoles; ++i) {
        const int f = d.holeIndices[i];
        if (f < 0 || f >= d.numFaces)
            fail("hole " + std::to_string(i) + ": face index " + std::to_string(f) + " is out of range [0, " +
                 std::to_string(d.numFaces) + ")");
    }
}

}  // namespace quadtri
