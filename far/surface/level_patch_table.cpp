// LevelPatchTable (quadtri/far/level_patch_table.h): which level-K faces are regular patches,
// the level-L vertices each one writes at which grid cell, and the limit stencils of the rest
// composed down to level K (docs/patches.md).
#include <quadtri/far/level_patch_table.h>

#include <algorithm>
#include <string>
#include <utility>

#include <quadtri/far/refiner.h>
#include "far/surface/level_patch_builder.h"
#include "far/surface/patch_basis.h"
#include "far/surface/regular_patch.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

using Basis = LevelPatchTable::Basis;

// The cubic B-spline's weights at every grid line and the box spline's at every cell, also as
// runs over the grid lines.
void fillWeights(LevelPatchTable& t) {
    const int n = t.rate();
    for (int i = 0; i <= n; ++i) {
        const double s = double(i) / n, r = 1 - s;
        const double w[8] = {r * r * r / 6, (3 * s * s * s - 6 * s * s + 4) / 6, (-3 * s * s * s + 3 * s * s + 3 * s + 1) / 6,
                             s * s * s / 6, -r * r / 2, (3 * s * s - 4 * s) / 2, (-3 * s * s + 2 * s + 1) / 2, s * s / 2};
        for (double x : w) t.curveWeights.push_back(float(x));
    }
    t.boxSplineWeights.assign(std::size_t((n + 1) * (n + 1) * 36), 0.0f);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i + j <= n; ++i) {
            double w[12], ws[12], wt[12];
            boxSplineWeights(double(i) / n, double(j) / n, w, ws, wt);
            float* cell = t.boxSplineWeights.data() + std::size_t((j * (n + 1) + i) * 36);
            for (int k = 0; k < 12; ++k) {
                cell[3 * k] = float(w[k]);
                cell[3 * k + 1] = float(ws[k]);
                cell[3 * k + 2] = float(wt[k]);
            }
        }
    const std::size_t width = std::size_t(t.lineWidth());
    t.curveWeightLines.assign(8 * width, 0.0f);
    for (int i = 0; i <= n; ++i)
        for (int k = 0; k < 8; ++k) t.curveWeightLines[std::size_t(k) * width + std::size_t(i)] = t.curveWeights[std::size_t(8 * i + k)];
    t.boxSplineWeightLines.assign(std::size_t(36 * (n + 1)) * width, 0.0f);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            for (int k = 0; k < 36; ++k)
                t.boxSplineWeightLines[std::size_t(36 * j + k) * width + std::size_t(i)] =
                    t.boxSplineWeights[std::size_t((j * (n + 1) + i) * 36 + k)];
}

}  // namespace

LevelPatchTable buildLevelPatchTable(const Refiner& refiner, int L, int K) {
    if (K < 0 || K >= L || L > refiner.maxLevel() || L - K > 7)
        throw TopologyError("level patches: level " + std::to_string(L) + " from patch level " + std::to_string(K) +
                            " asked for; it needs 0 <= patch level < level <= " + std::to_string(refiner.maxLevel()) +
                            " (the refined levels), at most 7 levels apart");
    for (int l = K + 1; l <= L; ++l)
        if (!refiner.hasLevelStencils(l))
            throw TopologyError("level patches: level " + std::to_string(l) +
                                " has no per-level table (refined with LevelTables::None)");
    const Topology& patchLevel = refiner.level(K);
    Options options = refiner.options();
    options.leftHanded = false;  // every refined level is counter-clockwise already

    LevelPatchTable t;
    t.level = L;
    t.patchLevel = K;
    t.numSourceVertices = patchLevel.numVertices;
    t.numPoints = refiner.faces(L).numVertices();
    fillWeights(t);

    // Each level-K face's level-L vertices with their grid cells; regular faces first, so that a
    // vertex shared with an irregular face is written by the patch.
    const DescendantCorners corners(refiner, K, L);
    std::vector<std::uint8_t> written(std::size_t(t.numPoints), 0);
    std::vector<int> points;
    std::vector<int> irregularFaces;
    RegularPatches patches(patchLevel, options);
    std::vector<std::pair<int, int>> order;  // (cell, vertex)
    for (int f = 0; f < patchLevel.numFaces(); ++f) {
        if (patchLevel.faceHole[std::size_t(f)]) continue;
        const PatchKind kind = patches.of(f, points);
        if (kind != PatchKind::BSpline && kind != PatchKind::BoxSpline) {
            irregularFaces.push_back(f);
            continue;
        }
        t.patchBasis.push_back(kind == PatchKind::BSpline ? Basis::BSpline : Basis::BoxSpline);
        t.patchPoints.insert(t.patchPoints.end(), points.begin(), points.end());
        t.pointOffsets.push_back(int(t.patchPoints.size()));
        corners.forEach(f, [&](int vertex, int i, int j) {
            if (written[std::size_t(vertex)]) return;
            written[std::size_t(vertex)] = 1;
            t.outputVertices.push_back(vertex);
            t.outputCells.push_back(std::uint16_t(i + 256 * j));
        });
        // By cell, row after row: the kernel computes a row at a time.
        const int begin = t.outputOffsets.back(), end = int(t.outputVertices.size());
        order.resize(std::size_t(end - begin));
        for (int k = 0; k < end - begin; ++k) order[std::size_t(k)] = {t.outputCells[std::size_t(begin + k)], t.outputVertices[std::size_t(begin + k)]};
        std::sort(order.begin(), order.end());
        for (int k = 0; k < end - begin; ++k) {
            t.outputCells[std::size_t(begin + k)] = std::uint16_t(order[std::size_t(k)].first);
            t.outputVertices[std::size_t(begin + k)] = order[std::size_t(k)].second;
        }
        t.outputOffsets.push_back(end);
    }
    for (int f : irregularFaces)
        corners.forEach(f, [&](int vertex, int, int) {
            if (written[std::size_t(vertex)]) return;
            written[std::size_t(vertex)] = 1;
            t.stencilVertices.push_back(vertex);
        });
    // Vertices of holes only, or of no face: their limit still, so that every point is written.
    for (int v = 0; v < t.numPoints; ++v)
        if (!written[std::size_t(v)]) t.stencilVertices.push_back(v);
    t.stencils = composeLimitRowsDown(refiner, L, K, t.stencilVertices);
    return t;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
