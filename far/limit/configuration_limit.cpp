// Limit masks of a configuration from its local subdivision matrix (docs/limit_eigen.md): the
// fixed left vector gives the position, the subdominant left subspace the tangent plane, and its
// basis is chosen so that it maps the configuration's plane layout to the identity (a fixed
// orientation: tangent1 × tangent2 points the way the faces turn).
#include "far/limit/configuration_limit.h"

#include <chrono>
#include <cmath>
#include <string>

#include "far/limit/eigen_analysis.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// Rows t1, t2 of the 2 x n `basis` replaced by M⁻¹ [t1; t2] with M = basis · layout, so that
// t1 · layout = (1, 0) and t2 · layout = (0, 1); false where M is singular.
bool alignToLayout(std::vector<double>& basis, const std::vector<double>& layout, int n) {
    double M[2][2] = {{0, 0}, {0, 0}};
    for (int r = 0; r < 2; ++r)
        for (int k = 0; k < n; ++k)
            for (int c = 0; c < 2; ++c) M[r][c] += basis[size_t(r) * n + k] * layout[2 * size_t(k) + c];
    const double det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
    const double norm = std::fabs(M[0][0]) + std::fabs(M[0][1]) + std::fabs(M[1][0]) + std::fabs(M[1][1]);
    if (!(std::fabs(det) > 1e-9 * norm * norm)) return false;
    const double inv[2][2] = {{M[1][1] / det, -M[0][1] / det}, {-M[1][0] / det, M[0][0] / det}};
    std::vector<double> out(basis.size());
    for (int r = 0; r < 2; ++r)
        for (int k = 0; k < n; ++k)
            out[size_t(r) * n + k] = inv[r][0] * basis[k] + inv[r][1] * basis[size_t(n) + k];
    basis.swap(out);
    return true;
}

// The estimate where S has no clean subdominant pair: the layout's two coordinate functions
// (made to sum to zero at the centre) pushed six levels down, t ← t S, along l0's complement.
std::vector<double> estimatedTangents(const LocalMatrix& m, const std::vector<double>& l0) {
    const int n = m.size;
    std::vector<double> basis(2 * size_t(n));
    for (int r = 0; r < 2; ++r) {
        double* t = &basis[size_t(r) * n];
        double sum = 0;
        for (int k = 0; k < n; ++k) sum += (t[k] = m.layout[2 * size_t(k) + r]);
        t[0] -= sum;
        for (int level = 0; level < 6; ++level) {
            std::vector<double> next(size_t(n), 0.0);
            for (int i = 0; i < n; ++i)
                for (int k = 0; k < n; ++k) next[k] += t[i] * m.S[size_t(i) * n + k];
            double total = 0;
            for (double w : next) total += w;
            for (int k = 0; k < n; ++k) t[k] = next[k] - total * l0[k];
        }
    }
    return basis;
}

// A clean pair: converged, and strictly above the rest of the spectrum.
bool isClean(const SubdominantSpace& space) { return space.converged && space.lambda3 < space.lambda2 * (1.0 - 1e-3); }

}  // namespace

std::optional<LocalLimitMask> analyseConfiguration(const VertexConfiguration& c, const Options& options) {
    const auto start = std::chrono::steady_clock::now();
    const std::optional<LocalMatrix> m = buildLocalMatrix(c, options);
    if (!m) return std::nullopt;
    const int n = m->size;
    LocalLimitMask out;
    out.rings = m->rings;
    out.signature = m->signature;
    std::optional<std::vector<double>> l0 = fixedLeftVector(m->S, n);
    out.exactPosition = l0.has_value();
    if (!l0) {
        l0.emplace(size_t(n), 0.0);
        (*l0)[0] = 1.0;
    }
    out.position = *l0;
    const SubdominantSpace space = subdominantLeftSpace(m->S, n, *l0);
    out.lambda1 = space.lambda1;
    out.lambda2 = space.lambda2;
    out.lambda3 = space.lambda3;
    out.imaginary = space.imaginary;
    out.iterations = space.iterations;
    std::vector<double> basis = space.basis;
    out.tangents = TangentSource::Eigen;
    if (!isClean(space) || !alignToLayout(basis, m->layout, n)) {
        out.tangents = TangentSource::Estimate;
        basis = estimatedTangents(*m, *l0);
        if (!alignToLayout(basis, m->layout, n)) basis.assign(2 * size_t(n), 0.0);
    }
    out.du.assign(basis.begin(), basis.begin() + n);
    out.dv.assign(basis.begin() + n, basis.end());
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

namespace {

// The configuration's key (VertexConfiguration::key) and what else changes its masks, into k.
void cacheKey(const VertexConfiguration& c, const Options& options, std::vector<int>& k) {
    const std::string key = c.key();
    k.assign(key.begin(), key.end());
    k.push_back(options.smoothTriangles ? 1 : 0);
    k.push_back(int(options.creaseMethod));
}

}  // namespace

const LocalLimitMask& cachedLimit(const VertexConfiguration& c, const Options& options, LimitMaskCache& cache) {
    std::vector<int>& key = cache.scratch().configurationKey;
    cacheKey(c, options, key);
    if (const LocalLimitMask* found = cache.find(key)) return *found;
    std::optional<LocalLimitMask> analysed = analyseConfiguration(c, options);
    return cache.insert(key, analysed ? std::move(*analysed) : LocalLimitMask{});
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
