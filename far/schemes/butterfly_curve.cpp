// Curve rules of catmark-butterfly: boundaries and creases whose faces are triangles, and crease
// vertices on the seam. A boundary or crease is refined from its own points only (so that two
// surfaces sharing it join without a crack), as a univariate scheme: the 4-point rule between
// interpolated points (triangle side), the cubic B-spline between approximated ones (quad side
// and seam), and in between the rule that reproduces cubics under the curve quasi-interpolant
// (Q⁻f = f − f''/6 at approximated points, Q⁺f = f at interpolated ones): the method of the
// paper's §3.2 (docs/catmark_butterfly/README.md, §3), solved here on the points at hand
// (docs/catmark_butterfly/derive_seam_rules.py prints the same systems in exact rationals and
// checks that every pattern of point kinds is solvable).
#include <cmath>
#include <utility>

#include "far/schemes/butterfly.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

struct CurvePoint {
    int vertex;
    double parameter;  // along the curve, the parent spacing being 1
    bool approximated;
};

// x^k minus its second derivative times c: Q f for f = x^k (c = h²/6 at approximated points).
double quasiInterpolated(int k, double x, double c) {
    double value = 1.0, second = 0.0;
    for (int i = 0; i < k; ++i) value *= x;
    if (k >= 2) {
        second = k * (k - 1);
        for (int i = 0; i < k - 2; ++i) second *= x;
    }
    return value - c * second;
}

// Adds the mask on `count` (2 to 4) points that maps Q x^k to the refined Q x^k at `target` for
// k < count: row k of the system is Σ_j w_j Q_j x^k(p_j) = Q x^k(target) at half the spacing.
void addCurveMask(const CurvePoint* points, int count, double target, bool approximatedTarget,
                  SparseAccumulator& acc, double scale) {
    double m[4][5];
    for (int k = 0; k < count; ++k) {
        for (int j = 0; j < count; ++j)
            m[k][j] = quasiInterpolated(k, points[j].parameter, points[j].approximated ? 1.0 / 6.0 : 0.0);
        m[k][count] = quasiInterpolated(k, target, approximatedTarget ? 1.0 / 24.0 : 0.0);
    }
    for (int c = 0; c < count; ++c) {  // Gauss-Jordan with partial pivoting
        int pivot = c;
        for (int r = c + 1; r < count; ++r)
            if (std::fabs(m[r][c]) > std::fabs(m[pivot][c])) pivot = r;
        for (int j = 0; j <= count; ++j) std::swap(m[c][j], m[pivot][j]);
        for (int r = 0; r < count; ++r) {
            if (r == c) continue;
            const double factor = m[r][c] / m[c][c];
            for (int j = c; j <= count; ++j) m[r][j] -= factor * m[c][j];
        }
    }
    for (int j = 0; j < count; ++j) acc.add(points[j].vertex, scale * m[j][count] / m[j][j]);
}

}  // namespace

int CatmarkButterflyMasks::curveContinuation(int v, int previous) const {
    // A corner ends the curve; so does a vertex on more than two sharp edges, found without
    // scanning its edges (a pole on many creases would cost its valence per sharp edge).
    if (isSharp(t_.vertSharpness[v]) || sharpEdges_[size_t(v)] != 2) return -1;
    int next = -1;
    for (int e : t_.edgesOfVertex(v))
        if (isSharp(t_.edgeSharpness[e]) && t_.otherVertex(e, v) != previous) next = t_.otherVertex(e, v);
    return next;
}

// The edge point lies on the triangle side (its faces are triangles), so it is interpolated:
// the 4-point rule, or (3/8, 3/4, −1/8) where the curve ends at one endpoint, or the rule
// solved for approximated points when the curve has crossed the seam.
void CatmarkButterflyMasks::sharpEdgePoint(int e, double scale) {
    if (!touchesSharpEdge(e)) return StamLoopMasks::sharpEdgePoint(e, scale);
    const int a = t_.edgeVerts[2 * e], b = t_.edgeVerts[2 * e + 1];
    const int before = curveContinuation(a, b), after = curveContinuation(b, a);
    CurvePoint points[4];
    int count = 0;
    if (before >= 0) points[count++] = {before, -1.0, !interpolated(before)};
    points[count++] = {a, 0.0, !interpolated(a)};
    points[count++] = {b, 1.0, !interpolated(b)};
    if (after >= 0) points[count++] = {after, 2.0, !interpolated(after)};
    addCurveMask(points, count, 0.5, false, acc_, scale);
}

// A crease vertex on the seam (it touches a quad, so it is approximated): the cubic B-spline
// (⅛, ¾, ⅛) when both curve neighbours are approximated, (3/32, 13/16, 3/32) when both are
// interpolated, and when the curve crosses the seam here the 4-point window that reaches one
// more point into the triangle side, where the 4-point rule needs it.
void CatmarkButterflyMasks::creaseVertex(int v, const float* edgeSharpness, double scale) {
    int ends[2] = {-1, -1}, found = 0;
    const IndexSpan edges = t_.edgesOfVertex(v);
    for (int i = 0; i < edges.size() && found < 2; ++i)
        if (isSharp(edgeSharpness[i])) ends[found++] = t_.otherVertex(edges[i], v);
    CurvePoint points[4] = {{ends[0], -1.0, !interpolated(ends[0])}, {v, 0.0, true}, {ends[1], 1.0, !interpolated(ends[1])}};
    int count = 3;
    if (interpolated(ends[0]) != interpolated(ends[1])) {
        const bool second = interpolated(ends[1]);
        const int beyond = curveContinuation(ends[second ? 1 : 0], v);
        if (beyond >= 0) points[count++] = {beyond, second ? 2.0 : -2.0, !interpolated(beyond)};
    }
    addCurveMask(points, count, 0.0, true, acc_, scale);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
