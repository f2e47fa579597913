#include "tests/limit/limit_test_tables.h"

#include <random>

#include <quadtri/far/refiner.h>
#include "bench/meshes/torus.h"
#include "tests/test_support.h"

namespace quadtri::test {

LimitStencilTable randomLimitTable(int numStencils, int numSources, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> weight(-1.0f, 1.0f);
    LimitStencilTable t;
    t.numSourceVertices = numSources;
    std::vector<std::pair<int, int>> runs;  // (size, offset) of each run so far
    for (int i = 0; i < numStencils; ++i) {
        int size = 0;
        if (i > 0 && rng() % 3 == 0) {  // an earlier stencil's run of sources: offsets go back
            const int j = int(rng() % unsigned(i));
            size = t.sizes[j];
            t.offsets.push_back(t.offsets[j]);
        } else {
            size = 1 + int(rng() % 24);
            t.offsets.push_back(int(t.indices.size()));
            for (int k = 0; k < size; ++k) t.indices.push_back(int(rng() % unsigned(numSources)));
        }
        t.sizes.push_back(size);
        int shared = -1;
        if (rng() % 3 == 0)
            for (const auto& [s, at] : runs)
                if (s == size) shared = at;
        if (shared >= 0) {
            t.weightOffsets.push_back(shared);
            continue;
        }
        t.weightOffsets.push_back(int(t.weights.size()));
        runs.push_back({size, int(t.weights.size())});
        float sums[3] = {0, 0, 0};
        for (int k = 0; k < size; ++k)
            for (int c = 0; c < 3; ++c) {
                const float w = k + 1 < size ? weight(rng) : (c == 0 ? 1.0f : 0.0f) - sums[c];
                t.weights.push_back(w);
                sums[c] += w;
            }
    }
    return t;
}

bool isDegenerateCorner(int v) { return v % 7 == 3 || v % 11 == 5; }

CornerLevel cornerLevel(int level) {
    const bench::ControlMesh m = bench::makeTorus(12, bench::TorusFaces::Mixed);
    const TopologyDescriptor desc = descriptorOf(m.numVertices, m.faceSizes, m.faceVerts);
    Refiner refiner(desc, Options());
    refiner.refineUniform(level);
    CornerLevel out;
    out.positions = evaluateLevels(refiner, m.positions, 3)[level];
    const LevelFaces faces = refiner.faces(level);
    out.meshNormals = buildMeshNormalTable(faces);
    const MeshNormalTable& mn = out.meshNormals;
    LimitStencilTable& t = out.table;
    t.numSourceVertices = mn.numVertices;
    for (int v = 0; v < mn.numVertices; ++v) {
        // v's neighbours after and before it around its first face.
        const int f = mn.vertexFaces[std::size_t(mn.vertexFaceOffsets[v])];
        const int first = mn.faceOffsets[f], n = mn.faceOffsets[f + 1] - first;
        auto vertexAt = [&](int k) { return mn.faceCorners[first + (k + n) % n] & MeshNormalTable::kCornerIndexMask; };
        int at = 0;
        while (vertexAt(at) != v) ++at;
        const int next = vertexAt(at + 1), prev = vertexAt(at - 1);
        t.sizes.push_back(3);
        t.offsets.push_back(int(t.indices.size()));
        t.indices.insert(t.indices.end(), {v, next, prev});
        t.weightOffsets.push_back(int(t.weights.size()));
        if (v % 11 == 5)
            t.weights.insert(t.weights.end(), {1, 0, 0, 0, 0, 0, 0, 0, 0});
        else if (v % 7 == 3)
            t.weights.insert(t.weights.end(), {1, -1, -2, 0, 1, 2, 0, 0, 0});
        else
            t.weights.insert(t.weights.end(), {1, -1, -1, 0, 1, 0, 0, 0, 1});
    }
    return out;
}

template <class Real>
void referenceLimit(const LimitStencilTable& t, const std::vector<float>& src, const BufferDescriptor& d,
                    std::vector<Real>& position, std::vector<Real>& du, std::vector<Real>& dv) {
    const int n = t.numStencils(), w = d.length;
    position.assign(std::size_t(n) * w, Real(0));
    du = dv = position;
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < t.size(i); ++k) {
            const float* s = &src[d.offset + std::size_t(t.indices[t.offsets[i] + k]) * d.stride];
            const float* s0 = &src[d.offset + std::size_t(t.indices[t.offsets[i]]) * d.stride];
            const float* wk = t.weightsOf(i) + 3 * k;
            for (int c = 0; c < w; ++c) {
                const Real diff = Real(s[c]) - Real(s0[c]);
                position[std::size_t(i) * w + c] += Real(wk[0]) * Real(s[c]);
                du[std::size_t(i) * w + c] += Real(wk[1]) * diff;
                dv[std::size_t(i) * w + c] += Real(wk[2]) * diff;
            }
        }
}

template void referenceLimit<float>(const LimitStencilTable&, const std::vector<float>&, const BufferDescriptor&,
                                    std::vector<float>&, std::vector<float>&, std::vector<float>&);
template void referenceLimit<double>(const LimitStencilTable&, const std::vector<float>&, const BufferDescriptor&,
                                     std::vector<double>&, std::vector<double>&, std::vector<double>&);

}  // namespace quadtri::test
