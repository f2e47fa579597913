// Dense eigen-numerics for local subdivision matrices (docs/limit_eigen.md, "Numerics"). The
// matrices have at most a few hundred rows, so plain O(n³) elimination and O(n²) iterations are
// ample; everything is in double.
#include "far/limit/eigen_analysis.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace quadtri {
inline namespace v0 {
namespace internal {

std::optional<std::vector<double>> fixedLeftVector(const std::vector<double>& S, int n) {
    const int m = n + 1;
    std::vector<double> A(size_t(m) * m, 0.0), x(size_t(m), 0.0);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) A[size_t(i) * m + j] = S[size_t(j) * n + i] - (i == j ? 1.0 : 0.0);
        A[size_t(i) * m + n] = 1.0;
        A[size_t(n) * m + i] = 1.0;
    }
    x[n] = 1.0;
    for (int col = 0; col < m; ++col) {
        int pivot = col;
        for (int r = col + 1; r < m; ++r)
            if (std::fabs(A[size_t(r) * m + col]) > std::fabs(A[size_t(pivot) * m + col])) pivot = r;
        if (std::fabs(A[size_t(pivot) * m + col]) < 1e-12) return std::nullopt;
        if (pivot != col) {
            for (int j = 0; j < m; ++j) std::swap(A[size_t(pivot) * m + j], A[size_t(col) * m + j]);
            std::swap(x[pivot], x[col]);
        }
        for (int r = col + 1; r < m; ++r) {
            const double f = A[size_t(r) * m + col] / A[size_t(col) * m + col];
            if (f == 0.0) continue;
            for (int j = col; j < m; ++j) A[size_t(r) * m + j] -= f * A[size_t(col) * m + j];
            x[r] -= f * x[col];
        }
    }
    for (int r = m - 1; r >= 0; --r) {
        double sum = x[r];
        for (int j = r + 1; j < m; ++j) sum -= A[size_t(r) * m + j] * x[j];
        x[r] = sum / A[size_t(r) * m + r];
    }
    x.resize(size_t(n));
    return x;
}

namespace {

using Vector = std::vector<double>;

double dot(const Vector& a, const Vector& b) {
    double s = 0;
    for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
    return s;
}

// y = Sᵀ x with the component along l0 removed (x − (Σx) l0 keeps the eigenvalue-1 part out).
Vector applyDeflated(const Vector& S, int n, const Vector& l0, const Vector& x) {
    Vector y(size_t(n), 0.0);
    for (int r = 0; r < n; ++r) {
        const double xr = x[r];
        if (xr == 0.0) continue;
        for (int i = 0; i < n; ++i) y[i] += S[size_t(r) * n + i] * xr;
    }
    double sum = 0;
    for (double v : y) sum += v;
    for (int i = 0; i < n; ++i) y[i] -= sum * l0[i];
    return y;
}

// Modified Gram-Schmidt, in place.
void orthonormalize(std::vector<Vector>& block) {
    for (size_t j = 0; j < block.size(); ++j) {
        for (size_t k = 0; k < j; ++k) {
            const double d = dot(block[j], block[k]);
            for (size_t i = 0; i < block[j].size(); ++i) block[j][i] -= d * block[k][i];
        }
        const double norm = std::sqrt(dot(block[j], block[j]));
        for (double& v : block[j]) v = norm > 0 ? v / norm : 0.0;
    }
}

// Eigenvalues of [[a, b], [c, d]]: the larger and smaller modulus, and |Im| of a complex pair.
void eigenvalues2(double a, double b, double c, double d, double& big, double& small, double& imaginary) {
    const double half = 0.5 * (a + d), det = a * d - b * c, disc = half * half - det;
    if (disc >= 0) {
        const double r = std::sqrt(disc);
        big = std::max(std::fabs(half + r), std::fabs(half - r));
        small = std::min(std::fabs(half + r), std::fabs(half - r));
        imaginary = 0;
    } else {
        big = small = std::sqrt(std::max(det, 0.0));
        imaginary = std::sqrt(-disc);
    }
}

constexpr int kMaxIterations = 4000;
constexpr double kTolerance = 1e-12;

}  // namespace

SubdominantSpace subdominantLeftSpace(const std::vector<double>& S, int n, const std::vector<double>& l0) {
    SubdominantSpace out;
    const int p = std::min(4, n - 1);  // the block; its last columns estimate λ3
    if (p < 2) return out;
    // A fixed start with a component along every eigenvector (no symmetry of the ring order).
    std::vector<Vector> X(size_t(p), Vector(size_t(n), 0.0));
    for (int j = 0; j < p; ++j)
        for (int i = 0; i < n; ++i) X[j][i] = std::sin(1.0 + 0.7 * (i + 1) * (j + 1) + 0.3 * i * i);
    for (int j = 0; j < p; ++j) X[j] = applyDeflated(S, n, l0, X[j]);
    orthonormalize(X);
    std::vector<Vector> Y(static_cast<size_t>(p));
    for (int it = 1; it <= kMaxIterations; ++it) {
        for (int j = 0; j < p; ++j) Y[j] = applyDeflated(S, n, l0, X[j]);
        if (it % 8 == 0 || it == kMaxIterations) {
            // H = Xᵀ Y: the block's Rayleigh quotient; the pair's residual Y2 − X2 H2.
            double H[4][4];
            for (int a = 0; a < p; ++a)
                for (int b = 0; b < p; ++b) H[a][b] = dot(X[a], Y[b]);
            double residual = 0;
            for (int b = 0; b < 2; ++b)
                for (int i = 0; i < n; ++i) {
                    const double r = Y[b][i] - X[0][i] * H[0][b] - X[1][i] * H[1][b];
                    residual += r * r;
                }
            out.residual = std::sqrt(residual);
            out.iterations = it;
            const double scale = std::max(std::fabs(H[0][0]) + std::fabs(H[1][1]), 1e-300);
            if (out.residual <= kTolerance * std::max(1.0, scale) || it == kMaxIterations) {
                eigenvalues2(H[0][0], H[0][1], H[1][0], H[1][1], out.lambda1, out.lambda2, out.imaginary);
                double small = 0, imaginary = 0;
                if (p == 4)
                    eigenvalues2(H[2][2], H[2][3], H[3][2], H[3][3], out.lambda3, small, imaginary);
                else
                    out.lambda3 = p == 3 ? std::fabs(H[2][2]) : 0.0;
                out.converged = out.residual <= kTolerance * std::max(1.0, scale);
                out.basis.resize(2 * size_t(n));
                for (int i = 0; i < n; ++i) {
                    out.basis[i] = X[0][i];
                    out.basis[size_t(n) + i] = X[1][i];
                }
                return out;
            }
        }
        X.swap(Y);
        orthonormalize(X);
    }
    return out;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
