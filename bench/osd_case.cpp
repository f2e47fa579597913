#include "bench/osd_case.h"

#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/osd/bufferDescriptor.h>
#include <opensubdiv/osd/cpuEvaluator.h>
#include <opensubdiv/osd/ompEvaluator.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "bench/compare.h"
#include "bench/osd_topology.h"
#include "bench/timing.h"

namespace quadtri::bench {

namespace Far = OpenSubdiv::Far;
namespace Osd = OpenSubdiv::Osd;

// Far::StencilTableFactory::Create is a wrapper that static_casts the StencilTableReal<float> built by
// StencilTableFactoryReal<float>::Create to its subclass StencilTable, a downcast UBSan rejects:
// the bench calls the template and keeps the StencilTableReal<float> it returns.
using Table = Far::StencilTableReal<float>;
using TableFactory = Far::StencilTableFactoryReal<float>;
using TablePtr = std::unique_ptr<const Table>;

struct OsdCase::State {
    const ControlMesh& mesh;
    OsdScheme scheme;
    int level;
    int numControl = 0;
    std::vector<int> firstStencil;  // per level L >= 1: first stencil of level L in the per-level table
    TablePtr perLevel, factorized;
    // perLevelBuffer / ompBuffer: the control vertices, then the vertices of levels 1..L.
    std::vector<float> perLevelBuffer, ompBuffer, factorizedOut;

    State(const ControlMesh& m, OsdScheme s, int l) : mesh(m), scheme(s), level(l) {}

    std::unique_ptr<Far::TopologyRefiner> refine() const {
        std::unique_ptr<Far::TopologyRefiner> refiner = osdTopologyRefiner(mesh, scheme);
        refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(level));
        return refiner;
    }

    TablePtr stencils(const Far::TopologyRefiner& refiner, bool factorize) const {
        TableFactory::Options o;
        o.generateOffsets = true;
        o.generateControlVerts = false;
        o.generateIntermediateLevels = !factorize;
        o.factorizeIntermediateLevels = factorize;
        o.maxLevel = static_cast<unsigned>(level);
        return TablePtr(TableFactory::Create(refiner, o));
    }

    // Level by level: the stencils of level L index level L-1's vertices from 0, so the source
    // descriptor starts at level L-1 in the buffer and the destination at level L; a range
    // [start, end) writes its first stencil at the destination descriptor's offset. Within a level
    // the stencils are independent, so OmpEvaluator may run them in parallel.
    template <class Evaluator>
    void evalPerLevel(std::vector<float>& buffer) {
        const Table& t = *perLevel;
        for (int L = 1; L <= level; ++L) {
            const int start = firstStencil[L - 1], end = firstStencil[L];
            const int srcFirst = L == 1 ? 0 : numControl + firstStencil[L - 2];
            Evaluator::EvalStencils(buffer.data(), Osd::BufferDescriptor(3 * srcFirst, 3, 3), buffer.data(),
                                    Osd::BufferDescriptor(3 * (numControl + start), 3, 3), t.GetSizes().data(),
                                    t.GetOffsets().data(), t.GetControlIndices().data(), t.GetWeights().data(), start,
                                    end);
        }
    }
    void evalCpuPerLevel() { evalPerLevel<Osd::CpuEvaluator>(perLevelBuffer); }
    void evalOmp() { evalPerLevel<Osd::OmpEvaluator>(ompBuffer); }

    void evalCpuFactorized() {
        const Table& t = *factorized;
        Osd::CpuEvaluator::EvalStencils(mesh.positions.data(), Osd::BufferDescriptor(0, 3, 3), factorizedOut.data(),
                                        Osd::BufferDescriptor(0, 3, 3), t.GetSizes().data(), t.GetOffsets().data(),
                                        t.GetControlIndices().data(), t.GetWeights().data(), 0, t.GetNumStencils());
    }

    std::vector<float> lastOf(const std::vector<float>& buffer) const {
        return std::vector<float>(buffer.begin() + 3 * size_t(numControl + firstStencil[level - 1]), buffer.end());
    }
};

namespace {

std::size_t tableBytes(const Table& t) {
    return t.GetSizes().size() * sizeof(int) + t.GetOffsets().size() * sizeof(Far::Index) +
           t.GetControlIndices().size() * sizeof(Far::Index) + t.GetWeights().size() * sizeof(float);
}

}  // namespace

OsdCase::OsdCase(const ControlMesh& mesh, OsdScheme scheme, int level)
    : s_(std::make_unique<State>(mesh, scheme, level)) {}

OsdCase::~OsdCase() = default;

void OsdCase::prepare() {
    State& s = *s_;
    {
        std::unique_ptr<Far::TopologyRefiner> refiner = s.refine();
        s.numControl = refiner->GetLevel(0).GetNumVertices();
        s.firstStencil.assign(1, 0);
        for (int L = 1; L <= s.level; ++L)
            s.firstStencil.push_back(s.firstStencil.back() + refiner->GetLevel(L).GetNumVertices());
        s.perLevel = s.stencils(*refiner, false);
    }
    s.factorized = s.stencils(*s.refine(), true);
    const int lastCount = s.firstStencil[s.level] - s.firstStencil[s.level - 1];
    if (s.perLevel->GetNumStencils() != s.firstStencil.back() || s.factorized->GetNumStencils() != lastCount) {
        std::ostringstream m;
        m << s.mesh.name << " level " << s.level << ": OpenSubdiv tables have " << s.perLevel->GetNumStencils()
          << " (per level) and " << s.factorized->GetNumStencils() << " (factorized) stencils, expected "
          << s.firstStencil.back() << " and " << lastCount;
        throw std::runtime_error(m.str());
    }

    s.perLevelBuffer.assign(3 * size_t(s.numControl + s.firstStencil.back()), 0.0f);
    std::copy(s.mesh.positions.begin(), s.mesh.positions.end(), s.perLevelBuffer.begin());
    s.ompBuffer = s.perLevelBuffer;
    s.factorizedOut.assign(3 * size_t(lastCount), 0.0f);
    s.evalCpuPerLevel();
    s.evalCpuFactorized();
    s.evalOmp();

    const std::vector<float> reference = lastLevel();
    // Float rounding grows with the entries summed: masks of up to 100 entries (the tori) keep
    // 1e-5 of the diagonal, a pole's factorized masks (thousands of entries) proportionally more.
    int largest = 0;
    for (int i = 0; i < s.factorized->GetNumStencils(); ++i) largest = std::max(largest, s.factorized->GetSizes()[i]);
    const double tolerance = 1e-5 * s.mesh.boundingBoxDiagonal() * std::max(1.0, largest / 100.0);
    const double dFactorized = maxAbsDifference(reference, s.factorizedOut);
    const double dOmp = maxAbsDifference(reference, s.lastOf(s.ompBuffer));
    if (dFactorized > tolerance || dOmp > tolerance) {
        std::ostringstream m;
        m << s.mesh.name << " level " << s.level << ": OpenSubdiv evaluations disagree with the per-level CPU one "
          << "(factorized by " << dFactorized << ", OpenMP by " << dOmp << ")";
        throw std::runtime_error(m.str());
    }
}

std::vector<float> OsdCase::lastLevel() const { return s_->lastOf(s_->perLevelBuffer); }

int OsdCase::refinedVertices() const { return s_->firstStencil[s_->level] - s_->firstStencil[s_->level - 1]; }

OsdFigures OsdCase::measure(int reps) {
    State& s = *s_;
    OsdFigures f;
    for (bool factorize : {false, true}) {
        std::vector<double> builds;
        for (int r = 0; r < reps; ++r) {
            Stopwatch watch;
            std::unique_ptr<Far::TopologyRefiner> refiner = s.refine();
            TablePtr table = s.stencils(*refiner, factorize);
            builds.push_back(watch.elapsedMs());
        }  // refiner and table are destroyed outside the timed span
        (factorize ? f.buildMsFactorized : f.buildMsPerLevel) = median(builds);
    }
    f.tableBytes = tableBytes(*s.perLevel);
    f.tableBytesFactorized = tableBytes(*s.factorized);
    f.evalCpuPerLevelMs = medianMs(reps, [&s] { s.evalCpuPerLevel(); });
    f.evalCpuFactorizedMs = medianMs(reps, [&s] { s.evalCpuFactorized(); });
    f.evalOmpMs = medianMs(reps, [&s] { s.evalOmp(); });
    return f;
}

}  // namespace quadtri::bench
