#include "bench/opensubdiv/osd_limit_case.h"

#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/osd/bufferDescriptor.h>
#include <opensubdiv/osd/cpuEvaluator.h>
#include <opensubdiv/osd/ompEvaluator.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "bench/compare.h"
#include "bench/opensubdiv/osd_topology.h"
#include "bench/opensubdiv/osd_vertex_view.h"
#include "bench/measure/peak_memory.h"
#include "bench/measure/timing.h"

namespace quadtri::bench {

namespace Far = OpenSubdiv::Far;
namespace Osd = OpenSubdiv::Osd;

// As in osd_case.cpp: the Real templates, not the float wrappers whose downcast UBSan rejects.
using LimitTable = Far::LimitStencilTableReal<float>;
using LimitFactory = Far::LimitStencilTableFactoryReal<float>;

struct OsdLimitCase::State {
    const ControlMesh& mesh;
    OsdScheme scheme;
    int level;
    std::vector<float> s, t;  // the locations, per control face in face order
    std::unique_ptr<const LimitTable> table;
    std::vector<float> position, du, dv, normal;
    MemoryFigures memory;  // the table's build, the table and the four outputs

    State(const ControlMesh& m, OsdScheme sc, int l) : mesh(m), scheme(sc), level(l) {}

    std::unique_ptr<Far::TopologyRefiner> refiner() const { return osdTopologyRefiner(mesh, scheme); }

    // Dyadic locations owning each level vertex once. A quad face (a, b, c, d) owns s, t in
    // [0, 1) (corner a at (0, 0), b at (1, 0)); the torus's triangles (a, b, c) and (a, c, d) of
    // quad (i, j) own i + j < n, the second without its first edge (a c, which the first owns).
    void locations(std::vector<Far::LimitStencilTableFactory::LocationArray>& out) {
        const int n = 1 << level;
        std::vector<int> counts;
        for (int f = 0; f < mesh.numFaces(); ++f) {
            const std::size_t before = s.size();
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    if (mesh.faceSizes[f] == 3) {
                        const bool second = f % 2 == 1;
                        if (i + j >= n || (second && j == 0)) continue;
                    }
                    s.push_back(float(i) / float(n));
                    t.push_back(float(j) / float(n));
                }
            counts.push_back(int(s.size() - before));
        }
        std::size_t at = 0;
        for (int f = 0; f < mesh.numFaces(); ++f) {
            Far::LimitStencilTableFactory::LocationArray a;
            a.ptexIdx = f;  // one ptex face per quad (Catmark) or triangle (Loop)
            a.numLocations = counts[f];
            a.s = s.data() + at;
            a.t = t.data() + at;
            at += std::size_t(counts[f]);
            out.push_back(a);
        }
    }

    template <class Evaluator>
    void eval(const float* control) {
        const LimitTable& tb = *table;
        const Osd::BufferDescriptor xyz(0, 3, 3);
        Evaluator::EvalStencils(control, xyz, position.data(), xyz, du.data(), xyz, dv.data(), xyz,
                                tb.GetSizes().data(), tb.GetOffsets().data(), tb.GetControlIndices().data(),
                                tb.GetWeights().data(), tb.GetDuWeights().data(), tb.GetDvWeights().data(), 0,
                                tb.GetNumStencils());
    }

    // Far's templates, compiled into the bench over 3-float vertices: one pass over the table
    // for the positions, one for each derivative.
    void evalFar(const float* controlPositions) {
        const VertexView<3, const float> control{controlPositions};
        VertexView<3, float> p{position.data()}, u{du.data()}, v{dv.data()};
        table->UpdateValues(control, p);
        table->UpdateDerivs(control, u, v);
    }

    // One evaluation of the rest cage with its normals: the limit case's figure.
    void evalRest(OsdLimitEvaluator evaluator) {
        evalDerivatives(mesh.positions.data(), evaluator);
        normalize();
    }

    void evalDerivatives(const float* control, OsdLimitEvaluator evaluator) {
        switch (evaluator) {
        case OsdLimitEvaluator::Cpu: eval<Osd::CpuEvaluator>(control); break;
        case OsdLimitEvaluator::Omp: eval<Osd::OmpEvaluator>(control); break;
        case OsdLimitEvaluator::Far: evalFar(control); break;
        }
    }

    // normal = normalize(du x dv) per point.
    void normalize() {
        const std::size_t n = position.size() / 3;
        for (std::size_t i = 0; i < n; ++i) {
            const float* a = &du[3 * i];
            const float* b = &dv[3 * i];
            const float c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
            const float len2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
            const float k = len2 > 0.0f ? 1.0f / std::sqrt(len2) : 0.0f;
            normal[3 * i] = c[0] * k, normal[3 * i + 1] = c[1] * k, normal[3 * i + 2] = c[2] * k;
        }
    }
};

OsdLimitCase::OsdLimitCase(const ControlMesh& mesh, OsdScheme scheme, int level)
    : s_(std::make_unique<State>(mesh, scheme, level)) {}

OsdLimitCase::~OsdLimitCase() = default;

void OsdLimitCase::prepare() {
    State& st = *s_;
    // OpenMP on as many threads as the TbbEvaluator it is compared with.
    Osd::OmpEvaluator::SetNumThreads(tbb::this_task_arena::max_concurrency());
    const PeakMemory peak;
    std::vector<Far::LimitStencilTableFactory::LocationArray> where;
    st.locations(where);
    {
        std::unique_ptr<Far::TopologyRefiner> r = st.refiner();
        r->RefineAdaptive(Far::TopologyRefiner::AdaptiveOptions(2));
        LimitFactory::Options o;
        o.generate1stDerivatives = true;
        st.table.reset(LimitFactory::Create(*r, where, nullptr, nullptr, o));
    }
    const std::size_t n = std::size_t(st.table->GetNumStencils());
    st.position.assign(3 * n, 0.0f);
    st.du = st.dv = st.normal = st.position;
    st.evalRest(OsdLimitEvaluator::Far);
    const std::vector<float> farPosition = st.position, farNormal = st.normal;
    st.evalRest(OsdLimitEvaluator::Cpu);
    if (farPosition != st.position || farNormal != st.normal)
        throw std::runtime_error(st.mesh.name + " level " + std::to_string(st.level) +
                                 ": Far's UpdateValues and UpdateDerivs differ from Osd::CpuEvaluator");
    const LimitTable& t = *st.table;
    st.memory.tableBytes = t.GetSizes().size() * sizeof(int) + t.GetOffsets().size() * sizeof(int) +
                           t.GetControlIndices().size() * sizeof(int) +
                           (t.GetWeights().size() + t.GetDuWeights().size() + t.GetDvWeights().size()) * sizeof(float);
    st.memory.bufferBytes = 4 * st.position.size() * sizeof(float);
    st.memory.peakResidentBytes = peak.peakAboveStart();  // not the reference below

    // The reference: the exact limit of every vertex of the uniformly refined level.
    std::unique_ptr<Far::TopologyRefiner> r = st.refiner();
    Far::TopologyRefiner::UniformOptions uniform(st.level);
    uniform.fullTopologyInLastLevel = true;  // Limit needs it
    r->RefineUniform(uniform);
    struct Xyz {
        float p[3];
        void Clear() { p[0] = p[1] = p[2] = 0.0f; }
        void AddWithWeight(const Xyz& o, float w) {
            for (int c = 0; c < 3; ++c) p[c] += w * o.p[c];
        }
    };
    std::vector<Xyz> levels(std::size_t(r->GetNumVerticesTotal()));
    for (int v = 0; v < st.mesh.numVertices; ++v)
        for (int c = 0; c < 3; ++c) levels[std::size_t(v)].p[c] = st.mesh.positions[3 * std::size_t(v) + c];
    Far::PrimvarRefinerReal<float> primvar(*r);
    Xyz* at = levels.data();
    for (int L = 1; L <= st.level; ++L) {
        Xyz* next = at + r->GetLevel(L - 1).GetNumVertices();
        primvar.Interpolate(L, at, next);
        at = next;
    }
    const int last = r->GetLevel(st.level).GetNumVertices();
    std::vector<Xyz> limit(static_cast<std::size_t>(last));
    primvar.Limit(at, limit);
    std::vector<float> reference;
    for (const Xyz& x : limit) reference.insert(reference.end(), x.p, x.p + 3);
    const MatchResult m = matchPositions(st.position, reference, 1e-5 * st.mesh.boundingBoxDiagonal());
    if (!m.ok)
        throw std::runtime_error(st.mesh.name + " level " + std::to_string(st.level) +
                                 ": OpenSubdiv's limit stencils miss the level's limit points (" + m.describe() + ")");
}

const std::vector<float>& OsdLimitCase::positions() const { return s_->position; }
const std::vector<float>& OsdLimitCase::normals() const { return s_->normal; }
int OsdLimitCase::numPoints() const { return s_->table->GetNumStencils(); }

void OsdLimitCase::evalDerivatives(const float* control, OsdLimitEvaluator evaluator) {
    s_->evalDerivatives(control, evaluator);
}

void OsdLimitCase::evalNormals() { s_->normalize(); }

OsdLimitFigures OsdLimitCase::measure(int reps) {
    State& st = *s_;
    OsdLimitFigures f;
    f.evalCpuMs = timeMs(reps, [&st] { st.evalRest(OsdLimitEvaluator::Cpu); });
    f.evalOmpMs = timeMs(reps, [&st] { st.evalRest(OsdLimitEvaluator::Omp); });
    f.evalFarMs = timeMs(reps, [&st] { st.evalRest(OsdLimitEvaluator::Far); });
    f.tableBytes = st.memory.tableBytes;
    f.memory = st.memory;
    return f;
}

}  // namespace quadtri::bench
