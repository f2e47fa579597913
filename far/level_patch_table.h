// Level L's limit positions and normals from the patches of a coarser level K: the "patches"
// route of the frame (docs/patches.md). Built by Refiner::levelPatches; applied to level K's
// data by the evaluators' EvalLevelPatches.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <quadtri/far/limit_stencil_table.h>

namespace quadtri {
inline namespace v0 {

// Every face of level K that is a regular patch of the scheme (a bicubic B-spline quad, a
// quartic box-spline triangle) gives the level-L vertices inside it through one fixed basis, at
// the grid of rate 2^(L-K) over the face, from its 16 (12) level-K vertices: no stencil and no index per point beyond the point's own. The level-L
// vertices of the other faces (extraordinary vertices, creases, boundaries, the tri/quad seam)
// have limit stencils over level K's vertices, as do all of them under `bilinear` (whose limit
// normal at a vertex is not one face's). Each level-L vertex is one point of the table, given by
// the first regular face that holds it, else by a stencil.
//
// The points come in the table's own order, patch by patch, so that each patch writes one run:
// point k is level-L vertex vertexOf(k) (the patches' outputVertices, then stencilVertices).
// Remap an index buffer of level L once with pointOfVertex() to draw the points as they come.
struct LevelPatchTable {
    enum class Basis : std::uint8_t { BSpline, BoxSpline };

    int level = 0;              // L: the points are level L's vertices
    int patchLevel = 0;         // K: the sources are level K's vertices
    int numPoints = 0;          // level L's vertices
    int numSourceVertices = 0;  // level K's vertices
    int rate() const { return 1 << (level - patchLevel); }

    // At most 2^7 segments per level-K edge: a grid line's index fits a byte.
    static constexpr int kMaxRate = 128;

    // Patch p: its basis, its points (level-K vertices) patchPoints[pointOffsets[p] ..
    // pointOffsets[p + 1]) in the basis's order, and its outputs [outputOffsets[p],
    // outputOffsets[p + 1]): output k is level-L vertex outputVertices[k] at grid cell
    // outputCells[k] = i + 256 j, i.e. at (i, j) / rate of the face's (s, t).
    std::vector<Basis> patchBasis;
    std::vector<int> pointOffsets{0};
    std::vector<int> patchPoints;
    std::vector<int> outputOffsets{0};
    std::vector<int> outputVertices;
    std::vector<std::uint16_t> outputCells;

    // The B-spline patch is a tensor product: per grid line i (rate + 1 of them), the cubic
    // B-spline's 4 weights at i / rate and then their 4 derivatives.
    std::vector<float> curveWeights;
    // The box spline's per cell j (rate + 1) + i, per patch point: the weights of the position and
    // of d/ds, d/dt, interleaved (36 floats a cell; zero outside the triangle).
    std::vector<float> boxSplineWeights;
    // The same weights as runs over the grid lines i, for hosts that evaluate 8 cells of a row at
    // once: lineWidth() floats a run, zero past the rate. curveWeightLines[k lineWidth() + i] is
    // curveWeights[8 i + k]; boxSplineWeightLines[(36 j + 3 p + d) lineWidth() + i] is
    // boxSplineWeights[36 (j (rate + 1) + i) + 3 p + d].
    std::vector<float> curveWeightLines;
    std::vector<float> boxSplineWeightLines;
    int lineWidth() const { return (rate() + 15) / 8 * 8; }  // rate + 1 lines and 7 more, in 8s

    // The rest: stencil i gives point numPatchOutputs() + i, level-L vertex stencilVertices[i],
    // from level K's vertices.
    LimitStencilTable stencils;
    std::vector<int> stencilVertices;

    int numPatches() const { return int(patchBasis.size()); }
    int vertexOf(int point) const {
        const int n = numPatchOutputs();
        return point < n ? outputVertices[std::size_t(point)] : stencilVertices[std::size_t(point - n)];
    }
    // Per level-L vertex, its point.
    std::vector<int> pointOfVertex() const {
        std::vector<int> out(std::size_t(numPoints), -1);
        for (int k = 0; k < numPoints; ++k) out[std::size_t(vertexOf(k))] = k;
        return out;
    }
    int numPatchOutputs() const { return int(outputVertices.size()); }
    static int pointsOf(Basis b) { return b == Basis::BSpline ? 16 : 12; }
    std::size_t bytes() const {
        auto bytesOf = [](const auto& v) { return v.size() * sizeof(v[0]); };
        std::size_t total = bytesOf(patchBasis) + bytesOf(pointOffsets) + bytesOf(patchPoints) +
                            bytesOf(outputOffsets) + bytesOf(outputVertices) + bytesOf(outputCells) +
                            bytesOf(stencilVertices) + bytesOf(curveWeights) + bytesOf(boxSplineWeights) + bytesOf(curveWeightLines) +
                            bytesOf(boxSplineWeightLines) + stencils.bytes();
        return total;
    }
};

}  // namespace v0
}  // namespace quadtri
