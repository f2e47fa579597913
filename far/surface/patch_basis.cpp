// Patch bases (far/surface/patch_basis.h). The box spline's coefficients are Stam's basis
// ("Evaluation of Loop Subdivision Surfaces", 1998) in the monomials of (s, t), as OpenSubdiv
// tabulates them; derivatives come from differentiating the monomials.
#include "far/surface/patch_basis.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// The box spline's basis (patch_basis.h), one row per monomial.
struct Transposed {
    double c[15][12];
};
constexpr Transposed transposed() {
    Transposed t{};
    for (int k = 0; k < 15; ++k)
        for (int i = 0; i < 12; ++i) t.c[k][i] = kBoxSplineMonomials[i][k];
    return t;
}
constexpr Transposed kBoxSplineByMonomial = transposed();

// The tensor product of two n-point univariate bases (values l, derivatives d), point (i, j) at
// [n j + i].
void tensorProduct(int n, const double* ls, const double* ds, const double* lt, const double* dt, double* wP,
                   double* wDs, double* wDt) {
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            wP[n * j + i] = ls[i] * lt[j];
            wDs[n * j + i] = ds[i] * lt[j];
            wDt[n * j + i] = ls[i] * dt[j];
        }
}

}  // namespace

void bSplineWeights(double s, double t, double wP[16], double wDs[16], double wDt[16]) {
    double bs[4], ds[4], bt[4], dt[4];
    cubicBSplineWeights(s, bs, ds);
    cubicBSplineWeights(t, bt, dt);
    tensorProduct(4, bs, ds, bt, dt, wP, wDs, wDt);
}

void boxSplineWeights(double s, double t, double wP[12], double wDs[12], double wDt[12]) {
    const double ps[5] = {1, s, s * s, s * s * s, s * s * s * s}, pt[5] = {1, t, t * t, t * t * t, t * t * t * t};
    double m[15], ms[15], mt[15];
    for (int k = 0; k < 15; ++k) {
        const int a = kBoxSplinePowerS[k], b = kBoxSplinePowerT[k];
        m[k] = ps[a] * pt[b];
        ms[k] = a > 0 ? a * ps[a - 1] * pt[b] : 0.0;
        mt[k] = b > 0 ? b * ps[a] * pt[b - 1] : 0.0;
    }
    // Monomial by monomial over the 12 points at once (each point's sum in the same order).
    double p[12] = {}, d[12] = {}, e[12] = {};
    for (int k = 0; k < 15; ++k)
        for (int i = 0; i < 12; ++i) {
            p[i] += kBoxSplineByMonomial.c[k][i] * m[k];
            d[i] += kBoxSplineByMonomial.c[k][i] * ms[k];
            e[i] += kBoxSplineByMonomial.c[k][i] * mt[k];
        }
    // Times 1/12 rather than over 12: 36 divisions were most of the call.
    constexpr double kTwelfth = 1.0 / 12.0;
    for (int i = 0; i < 12; ++i) {
        wP[i] = p[i] * kTwelfth;
        wDs[i] = d[i] * kTwelfth;
        wDt[i] = e[i] * kTwelfth;
    }
}

void bilinearWeights(double s, double t, double wP[4], double wDs[4], double wDt[4]) {
    wP[0] = (1 - s) * (1 - t);
    wP[1] = s * (1 - t);
    wP[2] = s * t;
    wP[3] = (1 - s) * t;
    wDs[0] = -(1 - t);
    wDs[1] = 1 - t;
    wDs[2] = t;
    wDs[3] = -t;
    wDt[0] = -(1 - s);
    wDt[1] = -s;
    wDt[2] = s;
    wDt[3] = 1 - s;
}

void linearWeights(double s, double t, double wP[3], double wDs[3], double wDt[3]) {
    wP[0] = 1 - s - t;
    wP[1] = s;
    wP[2] = t;
    wDs[0] = -1;
    wDs[1] = 1;
    wDs[2] = 0;
    wDt[0] = -1;
    wDt[1] = 0;
    wDt[2] = 1;
}

void quadraticQuadWeights(double s, double t, double wP[9], double wDs[9], double wDt[9]) {
    // Lagrange polynomials of the nodes 0, ½, 1 and their derivatives.
    auto lagrange = [](double x, double l[3], double d[3]) {
        l[0] = 2 * (x - 0.5) * (x - 1);
        l[1] = -4 * x * (x - 1);
        l[2] = 2 * x * (x - 0.5);
        d[0] = 4 * x - 3;
        d[1] = 4 - 8 * x;
        d[2] = 4 * x - 1;
    };
    double ls[3], ds[3], lt[3], dt[3];
    lagrange(s, ls, ds);
    lagrange(t, lt, dt);
    tensorProduct(3, ls, ds, lt, dt, wP, wDs, wDt);
}

void quadraticTriangleWeights(double s, double t, double wP[6], double wDs[6], double wDt[6]) {
    const double l[3] = {1 - s - t, s, t};
    const double ls[3] = {-1, 1, 0}, lt[3] = {-1, 0, 1};  // derivatives of the barycentrics
    for (int i = 0; i < 3; ++i) {
        wP[i] = l[i] * (2 * l[i] - 1);
        wDs[i] = (4 * l[i] - 1) * ls[i];
        wDt[i] = (4 * l[i] - 1) * lt[i];
        const int j = (i + 1) % 3;  // the midpoint of edge i, between corners i and i + 1
        wP[3 + i] = 4 * l[i] * l[j];
        wDs[3 + i] = 4 * (ls[i] * l[j] + l[i] * ls[j]);
        wDt[3 + i] = 4 * (lt[i] * l[j] + l[i] * lt[j]);
    }
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
