#include "bench/opensubdiv/osd_case.h"

#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/osd/bufferDescriptor.h>
#include <opensubdiv/osd/cpuEvaluator.h>
#include <opensubdiv/osd/ompEvaluator.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "bench/compare.h"
#include "bench/opensubdiv/osd_topology.h"
#include "bench/opensubdiv/osd_vertex_view.h"
#include "bench/measure/peak_memory.h"
#include "bench/measure/timing.h"

namespace quadtri::bench {

namespace Far = OpenSubdiv::Far;
namespace Osd = OpenSubdiv::Osd;

// Far::StencilTableFactory::Create is a wrapper that static_casts the StencilTableReal<float> built by
// StencilTableFactoryReal<float>::Create to its subclass StencilTable, a downcast UBSan rejects:
// the bench calls the template and keeps the StencilTableReal<float> it returns.
using Table = Far::StencilTableReal<float>;
using TableFactory = Far::StencilTableFactoryReal<float>;
using TablePtr = std::unique_ptr<const Table>;

namespace {

// OpenSubdiv's CPU ways of applying a table: Osd::CpuEvaluator and Osd::OmpEvaluator (compiled
// into libosdCPU), and Far::StencilTable::UpdateValues, a template compiled into the bench over
// the vertex type it is given.
enum class Evaluator { Cpu, Omp, Far };

const char* evaluatorName(Evaluator e) { return e == Evaluator::Cpu ? "cpu" : e == Evaluator::Omp ? "omp" : "far"; }

// One way of evaluating the case: a table, an evaluator, a width, and the buffer it writes
// (per-level: the control vertices, then the vertices of levels 1..L; factorized: the last level).
struct Way {
    bool factorized;
    Evaluator evaluator;
    int width;
    std::vector<float> buffer;
};

// xyz of each `width`-float vertex of `values` from vertex `first` on.
std::vector<float> xyzOf(const std::vector<float>& values, int width, std::size_t first) {
    std::vector<float> out;
    for (std::size_t at = first * std::size_t(width); at < values.size(); at += std::size_t(width))
        out.insert(out.end(), &values[at], &values[at] + 3);
    return out;
}

std::vector<float> padded(const std::vector<float>& xyz) {
    std::vector<float> out(xyz.size() / 3 * 4, 0.0f);
    for (std::size_t v = 0; v < xyz.size() / 3; ++v) std::memcpy(&out[4 * v], &xyz[3 * v], 3 * sizeof(float));
    return out;
}

std::size_t tableBytes(const Table& t) {
    return t.GetSizes().size() * sizeof(int) + t.GetOffsets().size() * sizeof(Far::Index) +
           t.GetControlIndices().size() * sizeof(Far::Index) + t.GetWeights().size() * sizeof(float);
}

}  // namespace

struct OsdCase::State {
    const ControlMesh& mesh;
    OsdScheme scheme;
    int level;
    int numControl = 0;
    std::vector<int> firstStencil;  // per level L >= 1: first stencil of level L in the per-level table
    TablePtr perLevel, factorized;
    std::vector<float> control4;    // the control positions padded to 4 floats
    std::vector<Way> ways;          // ways[0]: per-level, CPU, 3 floats (the reference)
    MemoryFigures memory;

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

    int lastCount() const { return firstStencil[level] - firstStencil[level - 1]; }

    Way makeWay(bool factorize, Evaluator evaluator, int width) const {
        const int vertices = factorize ? lastCount() : numControl + firstStencil.back();
        Way w{factorize, evaluator, width, std::vector<float>(std::size_t(width) * std::size_t(vertices), 0.0f)};
        if (!factorize) {
            const std::vector<float>& control = width == 4 ? control4 : mesh.positions;
            std::copy(control.begin(), control.end(), w.buffer.begin());
        }
        return w;
    }

    // Stencils [start, end) of `t` from src to dst (descriptors at the range's first source and
    // destination vertex). Osd::CpuEvaluator's 4- and 8-float SIMD path misreads a range with
    // start > 0 (CpuEvalStencils advances `sizes` by start, then its kernel indexes sizes, and
    // writes dst, from start again: past the arrays' end on the last level): it is given arrays
    // already offset to the range and start = 0, which its generic path reads the same way.
    // Osd::OmpEvaluator has no such path and reads `offsets` as absolute positions: it gets the
    // whole arrays and the range. UpdateValues writes destination start + i: it gets the
    // destination's vertex 0 as the range's first less start.
    template <Evaluator E>
    static void evalRange(const Table& t, const float* src, const Osd::BufferDescriptor& srcDesc, float* dst,
                          const Osd::BufferDescriptor& dstDesc, int start, int end) {
        const int* sizes = t.GetSizes().data();
        const int* offsets = t.GetOffsets().data();
        const int* indices = t.GetControlIndices().data();
        const float* weights = t.GetWeights().data();
        if constexpr (E == Evaluator::Cpu) {
            const int first = offsets[start];
            Osd::CpuEvaluator::EvalStencils(src, srcDesc, dst, dstDesc, sizes + start, offsets + start, indices + first,
                                            weights + first, 0, end - start);
        } else if constexpr (E == Evaluator::Omp) {
            Osd::OmpEvaluator::EvalStencils(src, srcDesc, dst, dstDesc, sizes, offsets, indices, weights, start, end);
        } else {
            auto update = [&](auto width) {
                constexpr int n = decltype(width)::value;
                const VertexView<n, const float> from{src + srcDesc.offset};
                VertexView<n, float> to{dst + dstDesc.offset - std::ptrdiff_t(start) * n};
                t.UpdateValues(from, to, start, end);
            };
            if (srcDesc.length == 4) update(std::integral_constant<int, 4>());
            else update(std::integral_constant<int, 3>());
        }
    }

    // Level by level: the stencils of level L index level L-1's vertices from 0, so the source
    // descriptor starts at level L-1 in the buffer and the destination at level L. Within a level
    // the stencils are independent, so OmpEvaluator may run them in parallel.
    template <Evaluator E>
    void evalPerLevel(Way& w) const {
        const int n = w.width;
        for (int L = 1; L <= level; ++L) {
            const int start = firstStencil[L - 1], end = firstStencil[L];
            const int srcFirst = L == 1 ? 0 : numControl + firstStencil[L - 2];
            evalRange<E>(*perLevel, w.buffer.data(), Osd::BufferDescriptor(n * srcFirst, n, n), w.buffer.data(),
                         Osd::BufferDescriptor(n * (numControl + start), n, n), start, end);
        }
    }

    template <Evaluator E>
    void evalFactorized(Way& w) const {
        const float* control = w.width == 4 ? control4.data() : mesh.positions.data();
        const Osd::BufferDescriptor desc(0, w.width, w.width);
        evalRange<E>(*factorized, control, desc, w.buffer.data(), desc, 0, factorized->GetNumStencils());
    }

    void eval(Way& w) const {
        switch (w.evaluator) {
        case Evaluator::Cpu: w.factorized ? evalFactorized<Evaluator::Cpu>(w) : evalPerLevel<Evaluator::Cpu>(w); break;
        case Evaluator::Omp: w.factorized ? evalFactorized<Evaluator::Omp>(w) : evalPerLevel<Evaluator::Omp>(w); break;
        case Evaluator::Far: w.factorized ? evalFactorized<Evaluator::Far>(w) : evalPerLevel<Evaluator::Far>(w); break;
        }
    }

    // The last level's xyz as `w` wrote it.
    std::vector<float> lastOf(const Way& w) const {
        return xyzOf(w.buffer, w.width, w.factorized ? 0 : std::size_t(numControl + firstStencil[level - 1]));
    }
};

OsdCase::OsdCase(const ControlMesh& mesh, OsdScheme scheme, int level)
    : s_(std::make_unique<State>(mesh, scheme, level)) {}

OsdCase::~OsdCase() = default;

void OsdCase::prepare() {
    State& s = *s_;
    // OpenMP on as many threads as the TbbEvaluator it is compared with.
    Osd::OmpEvaluator::SetNumThreads(tbb::this_task_arena::max_concurrency());
    s.ways.clear();
    s.control4 = padded(s.mesh.positions);
    {
        const PeakMemory peak;
        {
            std::unique_ptr<Far::TopologyRefiner> refiner = s.refine();
            s.numControl = refiner->GetLevel(0).GetNumVertices();
            s.firstStencil.assign(1, 0);
            for (int L = 1; L <= s.level; ++L)
                s.firstStencil.push_back(s.firstStencil.back() + refiner->GetLevel(L).GetNumVertices());
            s.perLevel = s.stencils(*refiner, false);
        }
        s.ways.push_back(s.makeWay(false, Evaluator::Cpu, 3));
        s.eval(s.ways[0]);
        s.memory.tableBytes = tableBytes(*s.perLevel);
        s.memory.bufferBytes = s.ways[0].buffer.size() * sizeof(float);
        s.memory.peakResidentBytes = peak.peakAboveStart();
    }
    s.factorized = s.stencils(*s.refine(), true);
    if (s.perLevel->GetNumStencils() != s.firstStencil.back() || s.factorized->GetNumStencils() != s.lastCount()) {
        std::ostringstream m;
        m << s.mesh.name << " level " << s.level << ": OpenSubdiv tables have " << s.perLevel->GetNumStencils()
          << " (per level) and " << s.factorized->GetNumStencils() << " (factorized) stencils, expected "
          << s.firstStencil.back() << " and " << s.lastCount();
        throw std::runtime_error(m.str());
    }
    for (bool factorize : {false, true})
        for (Evaluator evaluator : {Evaluator::Cpu, Evaluator::Omp, Evaluator::Far})
            for (int width : {3, 4})
                if (factorize || evaluator != Evaluator::Cpu || width != 3)
                    s.ways.push_back(s.makeWay(factorize, evaluator, width));
    for (std::size_t i = 1; i < s.ways.size(); ++i) s.eval(s.ways[i]);

    // Float rounding grows with the entries summed: masks of up to 100 entries (the tori) keep
    // 1e-5 of the diagonal, a pole's factorized masks (thousands of entries) proportionally more.
    int largest = 0;
    for (int i = 0; i < s.factorized->GetNumStencils(); ++i) largest = std::max(largest, s.factorized->GetSizes()[i]);
    const double tolerance = 1e-5 * s.mesh.boundingBoxDiagonal() * std::max(1.0, largest / 100.0);
    const std::vector<float> reference = s.lastOf(s.ways[0]);
    std::vector<float> factorizedReference;
    for (const Way& w : s.ways) {
        const std::vector<float> last = s.lastOf(w);
        std::ostringstream m;
        m << s.mesh.name << " level " << s.level << ": OpenSubdiv's " << evaluatorName(w.evaluator) << " evaluation"
          << " on the " << (w.factorized ? "factorized" : "per-level") << " table, " << w.width << " floats, ";
        if (!w.factorized && last != reference)
            throw std::runtime_error(m.str() + "differs from its per-level 3-float CPU evaluation");
        if (w.factorized && factorizedReference.empty()) {
            const double d = maxAbsDifference(reference, last);
            if (d > tolerance)
                throw std::runtime_error(m.str() + "differs from the per-level one by " + std::to_string(d));
            factorizedReference = last;
        }
        if (w.factorized && last != factorizedReference)
            throw std::runtime_error(m.str() + "differs from its factorized 3-float CPU evaluation");
    }
}

std::vector<float> OsdCase::lastLevel() const { return s_->lastOf(s_->ways[0]); }

int OsdCase::refinedVertices() const { return s_->lastCount(); }

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
        (factorize ? f.buildFactorizedMs : f.buildPerLevelMs) = summarize(builds);
    }
    f.tableBytes = tableBytes(*s.perLevel);
    f.tableBytesFactorized = tableBytes(*s.factorized);
    for (Way& w : s.ways)
        f.evaluations.push_back({w.factorized ? "factorized" : "per_level", evaluatorName(w.evaluator), w.width,
                                 timeMs(reps, [&] { s.eval(w); })});
    f.memory = s.memory;
    return f;
}

}  // namespace quadtri::bench
