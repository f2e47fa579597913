#include "bench/quadtri_case.h"

#include <sstream>
#include <stdexcept>

#include "bench/compare.h"
#include <quadtri/osd/tbb_evaluator.h>
#include "bench/timing.h"
#include <quadtri/osd/cpu_evaluator.h>

namespace quadtri::bench {

namespace {

const BufferDescriptor kXyz(0, 3, 3);

// Source vertices a table reads at least once.
std::size_t distinctSources(const StencilTable& table) {
    std::vector<char> seen(table.numSourceVertices, 0);
    std::size_t count = 0;
    for (int index : table.indices)
        if (!seen[index]) {
            seen[index] = 1;
            ++count;
        }
    return count;
}

}  // namespace

QuadtriCase::QuadtriCase(const ControlMesh& mesh, Scheme scheme, int level) : mesh_(mesh), level_(level) {
    options_.scheme = scheme;
}

QuadtriCase::~QuadtriCase() = default;

std::unique_ptr<Refiner> QuadtriCase::build() const {
    TopologyDescriptor desc;
    desc.numVertices = mesh_.numVertices;
    desc.numFaces = mesh_.numFaces();
    desc.numVertsPerFace = mesh_.faceSizes.data();
    desc.faceVertIndices = mesh_.faceVerts.data();
    auto refiner = std::make_unique<Refiner>(desc, options_);
    refiner->refineUniform(level_);
    return refiner;
}

void QuadtriCase::evalSerial() {
    for (int L = 1; L <= level_; ++L)
        CpuEvaluator::EvalStencils(serial_[L - 1].data(), kXyz, serial_[L].data(), kXyz, refiner_->levelStencils(L));
}

void QuadtriCase::evalThreaded() {
    for (int L = 1; L <= level_; ++L)
        TbbEvaluator::EvalStencils(threaded_[L - 1].data(), kXyz, threaded_[L].data(), kXyz, refiner_->levelStencils(L));
}

void QuadtriCase::prepare() {
    refiner_ = build();
    serial_.assign(level_ + 1, {});
    serial_[0] = mesh_.positions;
    for (int L = 1; L <= level_; ++L) serial_[L].assign(3 * size_t(refiner_->levelStencils(L).numStencils()), 0.0f);
    evalSerial();
    threaded_ = serial_;
    for (int L = 1; L <= level_; ++L) std::fill(threaded_[L].begin(), threaded_[L].end(), 0.0f);
    evalThreaded();
    const double diff = maxAbsDifference(serial_.back(), threaded_.back());
    if (diff > 1e-5 * mesh_.boundingBoxDiagonal()) {
        std::ostringstream s;
        s << mesh_.name << " level " << level_ << ": TbbEvaluator differs from CpuEvaluator by " << diff;
        throw std::runtime_error(s.str());
    }
}

QuadtriFigures QuadtriCase::measure(int reps) {
    QuadtriFigures f;
    std::vector<double> builds;
    for (int r = 0; r < reps; ++r) {
        Stopwatch watch;
        std::unique_ptr<Refiner> refiner = build();
        builds.push_back(watch.elapsedMs());
    }  // each refiner is destroyed outside its timed span
    f.buildMs = median(builds);

    for (int L = 1; L <= level_; ++L) {
        const StencilTable& t = refiner_->levelStencils(L);
        f.tableBytes += t.bytes();
        f.compulsoryBytes += double(t.bytes()) + 12.0 * double(distinctSources(t)) + 12.0 * t.numStencils();
    }
    f.evalSerialMs = medianMs(reps, [this] { evalSerial(); });
    f.evalThreadedMs = medianMs(reps, [this] { evalThreaded(); });
    return f;
}

}  // namespace quadtri::bench
