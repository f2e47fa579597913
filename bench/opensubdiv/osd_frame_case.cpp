#include "bench/opensubdiv/osd_frame_case.h"

#include <stdexcept>
#include <string>

#include "bench/quadtri/frame_case.h"
#include "bench/measure/timing.h"

namespace quadtri::bench {

namespace {

// OsdLimitCase's table as one of the real-time loop's evaluators: it reads the posed cage in
// place, as quadtri's host evaluators do; evaluate is the limit positions with du and dv, normals
// the normalize(du x dv) loop after it.
class OsdLimitFrameEvaluator : public realtime::FrameEvaluator {
public:
    OsdLimitFrameEvaluator(OsdLimitCase& limit, OsdLimitEvaluator evaluator) : limit_(limit), evaluator_(evaluator) {}

    std::string name() const override {
        return evaluator_ == OsdLimitEvaluator::Cpu ? "cpu" : evaluator_ == OsdLimitEvaluator::Omp ? "omp" : "far";
    }
    void setCage(const float* cage) override { cage_ = cage; }
    void evaluate(realtime::PhaseTimes& times) override {
        Stopwatch evaluate;
        limit_.evalDerivatives(cage_, evaluator_);
        times.evaluateMs = evaluate.elapsedMs();
        Stopwatch normals;
        limit_.evalNormals();
        times.normalsMs = normals.elapsedMs();
    }
    void readBack(std::vector<float>& positions, std::vector<float>& normals) override {
        positions = limit_.positions();
        normals = limit_.normals();
    }

private:
    OsdLimitCase& limit_;
    OsdLimitEvaluator evaluator_;
    const float* cage_ = nullptr;
};

}  // namespace

OsdFrameCase::OsdFrameCase(const ControlMesh& mesh, OsdScheme scheme, int level)
    : limit_(mesh, scheme, level), surface_(realtime::TwoBoneSkin(mesh.positions)) {
    for (OsdLimitEvaluator e : {OsdLimitEvaluator::Cpu, OsdLimitEvaluator::Omp, OsdLimitEvaluator::Far})
        evaluators_.push_back(std::make_unique<OsdLimitFrameEvaluator>(limit_, e));
}

OsdFrameCase::~OsdFrameCase() = default;

void OsdFrameCase::prepare(float radians) {
    limit_.prepare();
    std::vector<float> p, n;
    for (std::size_t i = 0; i < evaluators_.size(); ++i) {
        surface_.frame(*evaluators_[i], radians);
        evaluators_[i]->readBack(p, n);
        if (i == 0) {
            positions_ = p;
            normals_ = n;
        } else if (p != positions_ || n != normals_) {
            throw std::runtime_error("OpenSubdiv's frame on " + evaluators_[i]->name() + " differs from Osd::CpuEvaluator's");
        }
    }
}

std::vector<FrameTiming> OsdFrameCase::measure(int frames) {
    std::vector<FrameTiming> timings;
    for (auto& e : evaluators_) timings.push_back(timeFrames(surface_, *e, "limit_stencils", frames));
    return timings;
}

}  // namespace quadtri::bench
