// The walks of far/surface/level_patch_builder.h.
#include "far/surface/level_patch_builder.h"

#include "far/limit/limit_table.h"
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

DescendantCorners::DescendantCorners(const Refiner& refiner, int K, int L)
    : refiner_(refiner), K_(K), L_(L),
      splitsTrianglesInFour_(rulesOf(refiner.options().scheme).triangleSplit() == TriangleSplit::FourTriangles) {
    for (int l = K; l < L; ++l) {
        const LevelFaces faces = refiner.faces(l);
        std::vector<int> first(std::size_t(faces.numFaces()));
        int next = 0;
        for (int f = 0; f < faces.numFaces(); ++f) {
            first[std::size_t(f)] = next;
            const int s = faces.faceSize(f);
            next += (s == 4 || (s == 3 && splitsTrianglesInFour_)) ? 4 : s;
        }
        firstChild_.push_back(std::move(first));
    }
}

// Row by row: a dense accumulator per level, cleared through the list of what it touched.
LimitStencilTable composeLimitRowsDown(const Refiner& refiner, int L, int K, const std::vector<int>& vertices) {
    const LimitStencilTable limit = refiner.limitStencils(L);
    LimitStencilTableD out;
    out.numSourceVertices = refiner.faces(K).numVertices();
    // Two accumulators, each as large as level L (the largest), used in turn level by level.
    const std::size_t largest = std::size_t(refiner.faces(L).numVertices());
    std::vector<double> weights[2] = {std::vector<double>(3 * largest), std::vector<double>(3 * largest)};
    std::vector<char> seen[2] = {std::vector<char>(largest, 0), std::vector<char>(largest, 0)};
    std::vector<int> touched[2];
    for (int v : vertices) {
        // Level L's row.
        int at = 0;
        touched[at].clear();
        const int* sources = limit.sourcesOf(v);
        const float* w = limit.weightsOf(v);
        for (int k = 0; k < limit.size(v); ++k) {
            const int s = sources[k];
            if (!seen[at][std::size_t(s)]) {
                seen[at][std::size_t(s)] = 1;
                touched[at].push_back(s);
                for (int c = 0; c < 3; ++c) weights[at][3 * std::size_t(s) + c] = 0.0;
            }
            for (int c = 0; c < 3; ++c) weights[at][3 * std::size_t(s) + c] += double(w[3 * k + c]);
        }
        // Down one level at a time.
        for (int l = L; l > K; --l) {
            const StencilTable& table = refiner.levelStencils(l);
            const int next = 1 - at;
            touched[next].clear();
            for (int child : touched[at]) {
                seen[at][std::size_t(child)] = 0;
                const double* cw = &weights[at][3 * std::size_t(child)];
                const float* tw = table.weightsOf(child);
                for (int k = table.offsets[std::size_t(child)]; k < table.offsets[std::size_t(child) + 1]; ++k) {
                    const int p = table.indices[std::size_t(k)];
                    if (!seen[next][std::size_t(p)]) {
                        seen[next][std::size_t(p)] = 1;
                        touched[next].push_back(p);
                        for (int c = 0; c < 3; ++c) weights[next][3 * std::size_t(p) + c] = 0.0;
                    }
                    const double x = double(tw[k - table.offsets[std::size_t(child)]]);
                    for (int c = 0; c < 3; ++c) weights[next][3 * std::size_t(p) + c] += x * cw[c];
                }
            }
            at = next;
        }
        out.offsets.push_back(int(out.indices.size()));
        out.sizes.push_back(int(touched[at].size()));
        for (int s : touched[at]) {
            seen[at][std::size_t(s)] = 0;
            out.indices.push_back(s);
            out.weights.insert(out.weights.end(), &weights[at][3 * std::size_t(s)], &weights[at][3 * std::size_t(s)] + 3);
        }
    }
    return toFloatTable(out);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
