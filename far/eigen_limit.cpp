// Limit masks of a configuration from its local subdivision matrix (docs/limit_eigen.md): the
// fixed left vector gives the position, the subdominant left subspace the tangent plane, and its
// basis is chosen so that it maps the configuration's plane layout to the identity (a fixed
// orientation: tangent1 × tangent2 points the way the faces turn).
#include "far/internal/eigen_limit.h"

#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "far/internal/eigen_analysis.h"

namespace quadtri {
inline namespace v0 {

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

std::optional<ConfigurationLimit> analyseConfiguration(const VertexConfiguration& c, const Options& options) {
    const auto start = std::chrono::steady_clock::now();
    const std::optional<LocalMatrix> m = buildLocalMatrix(c, options);
    if (!m) return std::nullopt;
    const int n = m->size;
    ConfigurationLimit out;
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
    out.tangent1.assign(basis.begin(), basis.begin() + n);
    out.tangent2.assign(basis.begin() + n, basis.end());
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

namespace {

// Everything the masks depend on besides the configuration itself.
std::string cacheKey(const VertexConfiguration& c, const Options& options) {
    std::string key = c.key();
    key += options.smoothTriangles ? "/s" : "/-";
    return key;
}

struct Cache {
    std::mutex mutex;
    std::map<std::string, std::unique_ptr<const ConfigurationLimit>> entries;  // null: no closed neighbourhood
};

Cache& cache() {
    static Cache c;
    return c;
}

}  // namespace

// Analysed outside the lock: two threads meeting a new configuration at once may both analyse
// it (the same result); the first stored is kept.
const ConfigurationLimit* cachedLimit(const VertexConfiguration& c, const Options& options) {
    const std::string key = cacheKey(c, options);
    Cache& store = cache();
    {
        std::lock_guard<std::mutex> lock(store.mutex);
        const auto it = store.entries.find(key);
        if (it != store.entries.end()) return it->second.get();
    }
    std::optional<ConfigurationLimit> analysed = analyseConfiguration(c, options);
    std::unique_ptr<const ConfigurationLimit> entry =
        analysed ? std::make_unique<const ConfigurationLimit>(std::move(*analysed)) : nullptr;
    std::lock_guard<std::mutex> lock(store.mutex);
    return store.entries.emplace(key, std::move(entry)).first->second.get();
}

std::optional<VertexLimitMasks> eigenLimitMasks(const Topology& t, int vertex, const Options& options) {
    const std::optional<VertexFan> fan = fanOf(t, vertex, options);
    if (!fan) return std::nullopt;
    const ConfigurationLimit* limit = cachedLimit(fan->configuration, options);
    if (!limit) return std::nullopt;
    Neighbourhood ring = gatherNeighbourhood(t, vertex, fan->faces[0], limit->rings);
    if (ring.vertices.size() != limit->position.size()) return std::nullopt;
    VertexLimitMasks masks;
    masks.vertices = std::move(ring.vertices);
    masks.position = limit->position;
    masks.tangent1 = limit->tangent1;
    masks.tangent2 = limit->tangent2;
    masks.analysis = limit;
    masks.settled = gatherNeighbourhood(t, vertex, fan->faces[0], limit->rings + 1).signature == limit->signature;
    return masks;
}

}  // namespace v0
}  // namespace quadtri
