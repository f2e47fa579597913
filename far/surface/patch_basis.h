// The bases of the patches a point is evaluated on (docs/surface.md): weights of the position and
// of its s and t derivatives over the patch's points, at (s, t) of the patch's own domain.
#pragma once

namespace quadtri {
inline namespace v0 {
namespace internal {

// Uniform cubic B-spline: the four weights and their derivatives at x in [0, 1]. Inline, so that
// loops over many points vectorize; each file has its own copy (an unnamed namespace), so that
// patch_points_avx2.cpp's AVX2 build never stands in for the baseline one.
namespace {
inline void cubicBSplineWeights(double x, double w[4], double d[4]) {
    const double y = 1.0 - x, x2 = x * x, x3 = x2 * x;
    w[0] = y * y * y / 6.0;
    w[1] = (3.0 * x3 - 6.0 * x2 + 4.0) / 6.0;
    w[2] = (-3.0 * x3 + 3.0 * x2 + 3.0 * x + 1.0) / 6.0;
    w[3] = x3 / 6.0;
    d[0] = -0.5 * y * y;
    d[1] = 1.5 * x2 - 2.0 * x;
    d[2] = -1.5 * x2 + x + 0.5;
    d[3] = 0.5 * x2;
}
}  // namespace

// Bicubic uniform B-spline over a 4 × 4 grid, point (i, j) at [4 j + i] (i along s); the patch
// spans the middle square, (s, t) = (0, 0) at point (1, 1).
void bSplineWeights(double s, double t, double wP[16], double wDs[16], double wDt[16]);

// Quartic box spline (Loop's regular patch) over 12 points of the triangular lattice, at lattice
// coordinates (a, b) (a along s, b along t, 60° apart): (0,-1) (1,-1) (2,-1) (-1,0) (0,0) (1,0)
// (2,0) (-1,1) (0,1) (1,1) (-1,2) (0,2); the patch is the triangle of points 4, 5, 8.
void boxSplineWeights(double s, double t, double wP[12], double wDs[12], double wDt[12]);

// The same box spline as a polynomial in (s, t): Stam's basis times 12, one row per point, over
// the monomials 1, s, t, s², st, t², s³, s²t, st², t³, s⁴, s³t, s²t², st³, t⁴ (monomial k is
// s^kBoxSplinePowerS[k] · t^kBoxSplinePowerT[k]).
inline constexpr double kBoxSplineMonomials[12][15] = {
    {1, -2, -4, 0, 6, 6, 2, 0, -6, -4, -1, -2, 0, 2, 1},
    {1, 2, -2, 0, -6, 0, -4, 0, 6, 2, 2, 4, 0, -2, -1},
    {0, 0, 0, 0, 0, 0, 2, 0, 0, 0, -1, -2, 0, 0, 0},
    {1, -4, -2, 6, 6, 0, -4, -6, 0, 2, 1, 2, 0, -2, -1},
    {6, 0, 0, -12, -12, -12, 8, 12, 12, 8, -1, -2, 0, -2, -1},
    {1, 4, 2, 6, 6, 0, -4, -6, -12, -4, -1, -2, 0, 4, 2},
    {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 0, 0, 0},
    {1, -2, 2, 0, -6, 0, 2, 6, 0, -4, -1, -2, 0, 4, 2},
    {1, 2, 4, 0, 6, 6, -4, -12, -6, -4, 2, 4, 0, -2, -1},
    {0, 0, 0, 0, 0, 0, 2, 6, 6, 2, -1, -2, 0, -2, -1},
    {0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, -2, -1},
    {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 1},
};
inline constexpr int kBoxSplinePowerS[15] = {0, 1, 0, 2, 1, 0, 3, 2, 1, 0, 4, 3, 2, 1, 0};
inline constexpr int kBoxSplinePowerT[15] = {0, 0, 1, 0, 1, 2, 0, 1, 2, 3, 0, 1, 2, 3, 4};

// Bilinear over a quad's corners in order ((0,0), (1,0), (1,1), (0,1)); linear over a triangle's.
void bilinearWeights(double s, double t, double wP[4], double wDs[4], double wDt[4]);
void linearWeights(double s, double t, double wP[3], double wDs[3], double wDt[3]);

// Quadratic interpolation of 9 nodes of a quad, row by row at s, t in {0, ½, 1}; of 6 nodes of a
// triangle, its corners then the midpoints of its edges 0 (corner 0 to 1), 1 and 2.
void quadraticQuadWeights(double s, double t, double wP[9], double wDs[9], double wDt[9]);
void quadraticTriangleWeights(double s, double t, double wP[6], double wDs[6], double wDt[6]);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
