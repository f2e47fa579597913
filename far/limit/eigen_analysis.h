// Left eigen-structure of a small dense subdivision matrix, in double, without external
// libraries (docs/limit_eigen.md, "Numerics"): the fixed left vector of eigenvalue 1 and the
// dominant left invariant subspace after it.
#pragma once

#include <optional>
#include <vector>

namespace quadtri {
inline namespace v0 {
namespace internal {

// l with l S = l and Σ l = 1 (S n x n, row-major, rows summing to 1), from the bordered system
// [Sᵀ − I, 1; 1ᵀ, 0] [l; μ] = [0; 1] by Gaussian elimination with partial pivoting; nullopt when
// it is singular (eigenvalue 1 is not simple).
std::optional<std::vector<double>> fixedLeftVector(const std::vector<double>& S, int n);

// The 2-D left invariant subspace of S belonging to its two largest eigenvalues after 1, found by
// orthogonal subspace iteration on Sᵀ with the eigenvalue-1 part removed (every vector kept
// summing to zero along l0).
struct SubdominantSpace {
    std::vector<double> basis;   // 2 x n, row-major, orthonormal rows each summing to 0
    double lambda1 = 0, lambda2 = 0;  // moduli of the pair, |λ1| >= |λ2|
    double imaginary = 0;        // |Im λ| of the pair (0 when real)
    double lambda3 = 0;          // modulus of the next eigenvalue (an estimate from the block)
    bool converged = false;      // the pair's subspace is invariant to the tolerance
    int iterations = 0;
    double residual = 0;         // ‖Sᵀ B − B H‖ of the pair at the end
};
SubdominantSpace subdominantLeftSpace(const std::vector<double>& S, int n, const std::vector<double>& l0);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
