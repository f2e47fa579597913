#include "bench/opensubdiv/osd_edit_case.h"

#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyRefiner.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace quadtri::bench {

namespace {

namespace Far = OpenSubdiv::Far;
// The templates the Far:: wrappers static_cast from (a downcast UBSan rejects: osd_case.cpp).
using TableFactory = Far::StencilTableFactoryReal<float>;
using LimitFactory = Far::LimitStencilTableFactoryReal<float>;

// Every ptex face's grid at level N: (rate + 1)^2 points, rate 2^N on a quad of Catmark or a
// triangle of Loop (its half, i + j <= rate), 2^(N-1) on the sub-faces of Catmark's other faces.
struct Locations {
    std::vector<float> s, t;
    std::vector<LimitFactory::LocationArray> arrays;

    Locations(const Far::TopologyRefiner& refiner, const ControlMesh& mesh, OsdScheme scheme, int level,
              const std::vector<int>& holes) {
        const Far::PtexIndices ptex(refiner);
        std::vector<std::pair<int, int>> faces;  // ptex face, rate
        for (int f = 0; f < mesh.numFaces(); ++f) {
            if (std::find(holes.begin(), holes.end(), f) != holes.end()) continue;  // no surface
            const int n = mesh.faceSizes[std::size_t(f)];
            const bool whole = scheme == OsdScheme::Loop || n == 4;
            for (int k = 0; k < (whole ? 1 : n); ++k)
                faces.emplace_back(ptex.GetFaceId(f) + k, whole ? 1 << level : 1 << std::max(level - 1, 0));
        }
        std::vector<int> counts;
        for (const auto& [face, rate] : faces) {
            const std::size_t before = s.size();
            for (int j = 0; j <= rate; ++j)
                for (int i = 0; i <= rate; ++i) {
                    if (scheme == OsdScheme::Loop && i + j > rate) continue;
                    s.push_back(float(i) / float(rate));
                    t.push_back(float(j) / float(rate));
                }
            counts.push_back(int(s.size() - before));
        }
        std::size_t at = 0;
        for (std::size_t k = 0; k < faces.size(); ++k) {
            LimitFactory::LocationArray a;
            a.ptexIdx = faces[k].first;
            a.numLocations = counts[k];
            a.s = s.data() + at;
            a.t = t.data() + at;
            at += std::size_t(counts[k]);
            arrays.push_back(a);
        }
    }
};

}  // namespace

Timing osdRebuild(const ControlMesh& mesh, OsdScheme scheme, const OsdTags& tags, int level, int reps) {
    std::vector<double> times;
    for (int r = 0; r < reps; ++r) {
        const Stopwatch watch;
        {
            std::unique_ptr<Far::TopologyRefiner> refiner = osdTopologyRefiner(mesh, scheme, tags);
            refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(level));
            TableFactory::Options o;
            o.generateIntermediateLevels = false;
            o.factorizeIntermediateLevels = true;
            std::unique_ptr<const Far::StencilTableReal<float>> table(TableFactory::Create(*refiner, o));
        }
        {
            std::unique_ptr<Far::TopologyRefiner> refiner = osdTopologyRefiner(mesh, scheme, tags);
            refiner->RefineAdaptive(Far::TopologyRefiner::AdaptiveOptions(2));
            const Locations where(*refiner, mesh, scheme, level, tags.holes);
            LimitFactory::Options o;
            o.generate1stDerivatives = true;
            std::unique_ptr<const Far::LimitStencilTableReal<float>> limit(
                LimitFactory::Create(*refiner, where.arrays, nullptr, nullptr, o));
        }
        times.push_back(watch.elapsedMs());
    }
    return summarize(times);
}

}  // namespace quadtri::bench
