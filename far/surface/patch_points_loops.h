// The loops of FaceSurface's batches (far/surface/patch_points.h), included by patch_points.cpp
// and, built with AVX2 (no fused multiply-adds: the same sums), by patch_points_avx2.cpp.
#pragma once

#include <algorithm>
#include <cstddef>

#include "far/surface/patch_basis.h"
#include "far/surface/patch_points.h"

namespace quadtri {
inline namespace v0 {
namespace internal {
namespace {

// Points of a batch taken together, so that each sum runs across them (vectorized).
constexpr int kLanes = 8;

// The points [first, first + lanes) of a batch, components [c, c + N), from their sums.
template <int N>
void storeLanes(const double p[N][kLanes], const double su[N][kLanes], const double sv[N][kLanes], int first, int lanes,
                int c, const PatchPoints& out) {
    for (int i = 0; i < lanes; ++i) {
        const std::size_t at = std::size_t(first + i) * std::size_t(out.outStride) + std::size_t(c);
        for (int j = 0; j < N; ++j) {
            out.position[at + std::size_t(j)] = float(p[j][i]);
            if (out.dPdu) out.dPdu[at + std::size_t(j)] = float(su[j][i]);
            if (out.dPdv) out.dPdv[at + std::size_t(j)] = float(sv[j][i]);
        }
    }
}

// Calls block(first, lanes, s, t) for the batch's points kLanes at a time: s[i] and t[i] the (u, v)
// of point first + i, the last point repeated past `lanes` so that every lane has one.
template <class Block>
void forEachLaneBlock(const PatchPoints& points, Block&& block) {
    for (int first = 0; first < points.count; first += kLanes) {
        const int lanes = std::min(kLanes, points.count - first);
        double s[kLanes], t[kLanes];
        for (int i = 0; i < kLanes; ++i) {
            s[i] = points.u[first + std::min(i, lanes - 1)];
            t[i] = points.v[first + std::min(i, lanes - 1)];
        }
        block(first, lanes, s, t);
    }
}

// Components [c, c + N) of `count` points of a regular quad: its 16 points read once, in double,
// then the points kLanes at a time, each summed as limit_surface.cpp's bSplinePoint sums one (the
// same result, bit for bit, where the compiler fuses no multiply and add).
template <int N>
void bSplineLanes(const int* sources, const float* control, int stride, int c, const PatchPoints& out) {
    double grid[16][N];
    for (int k = 0; k < 16; ++k) {
        const float* from = control + std::size_t(sources[k]) * std::size_t(stride) + c;
        for (int j = 0; j < N; ++j) grid[k][j] = from[j];
    }
    forEachLaneBlock(out, [&](int first, int lanes, const double* s0, const double* t0) {
        double P[N][kLanes], SU[N][kLanes], SV[N][kLanes];
        for (int i = 0; i < kLanes; ++i) {
            double bs[4], ds[4], bt[4], dt[4];
            cubicBSplineWeights(s0[i], bs, ds);
            cubicBSplineWeights(t0[i], bt, dt);
            for (int j = 0; j < N; ++j) {
                double p = 0, su = 0, sv = 0;
                for (int r = 0; r < 4; ++r) {
                    double q = 0, dq = 0;
                    for (int k = 0; k < 4; ++k) {
                        const double x = grid[4 * r + k][j];
                        q += bs[k] * x;
                        dq += ds[k] * x;
                    }
                    p += bt[r] * q;
                    su += bt[r] * dq;
                    sv += dt[r] * q;
                }
                P[j][i] = p;
                SU[j][i] = su;
                SV[j][i] = sv;
            }
        }
        storeLanes<N>(P, SU, SV, first, lanes, c, out);
    });
}

// Components [c, c + N) of `count` points of a regular triangle: its 12 points turned once into
// the coefficients of the box spline's 15 monomials, then the points kLanes at a time, each a
// polynomial (within rounding of limit_surface.cpp's boxSplinePoint: the same sums, grouped by monomial).
template <int N>
void boxSplineLanes(const int* sources, const float* control, int stride, int c, const PatchPoints& out) {
    double coefficient[15][N] = {};
    // Unrolled, the table's zeros (two in five) drop out.
#pragma GCC unroll 12
    for (int i = 0; i < 12; ++i) {
        const float* from = control + std::size_t(sources[i]) * std::size_t(stride) + c;
        double x[N];
        for (int j = 0; j < N; ++j) x[j] = from[j] * (1.0 / 12.0);
#pragma GCC unroll 15
        for (int k = 0; k < 15; ++k)
            if (kBoxSplineMonomials[i][k] != 0.0)
                for (int j = 0; j < N; ++j) coefficient[k][j] += kBoxSplineMonomials[i][k] * x[j];
    }
    forEachLaneBlock(out, [&](int first, int lanes, const double* s0, const double* t0) {
        double P[N][kLanes], SU[N][kLanes], SV[N][kLanes];
        for (int i = 0; i < kLanes; ++i) {
            // s^e at ps[e + 1], t^e at pt[e + 1]; ps[0] = pt[0] = 0 stands for s^-1, whose weight is 0.
            double ps[6] = {0.0, 1.0}, pt[6] = {0.0, 1.0};
            for (int e = 2; e < 6; ++e) {
                ps[e] = ps[e - 1] * s0[i];
                pt[e] = pt[e - 1] * t0[i];
            }
            double p[N] = {}, su[N] = {}, sv[N] = {};
#pragma GCC unroll 15
            for (int k = 0; k < 15; ++k) {
                const int a = kBoxSplinePowerS[k], b = kBoxSplinePowerT[k];
                const double m = ps[a + 1] * pt[b + 1], ms = a * ps[a] * pt[b + 1], mt = b * ps[a + 1] * pt[b];
                for (int j = 0; j < N; ++j) {
                    p[j] += m * coefficient[k][j];
                    su[j] += ms * coefficient[k][j];
                    sv[j] += mt * coefficient[k][j];
                }
            }
            for (int j = 0; j < N; ++j) {
                P[j][i] = p[j];
                SU[j][i] = su[j];
                SV[j][i] = sv[j];
            }
        }
        storeLanes<N>(P, SU, SV, first, lanes, c, out);
    });
}

// Every component group of a batch of a regular quad's (triangle's) points.
inline void bSplineBatch(const int* sources, const float* control, int stride, const PatchPoints& points) {
    byComponentGroups(points.width, [&](auto n, int c) {
        bSplineLanes<decltype(n)::value>(sources, control, stride, c, points);
    });
}
inline void boxSplineBatch(const int* sources, const float* control, int stride, const PatchPoints& points) {
    byComponentGroups(points.width, [&](auto n, int c) {
        boxSplineLanes<decltype(n)::value>(sources, control, stride, c, points);
    });
}

}  // namespace
}  // namespace internal
}  // namespace v0
}  // namespace quadtri
