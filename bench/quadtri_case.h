// One bench case on quadtri's side: the analyzer build, the per-level tables, and their serial
// and threaded evaluation level by level into preallocated buffers.
#pragma once

#include <memory>
#include <vector>

#include "bench/figures.h"
#include "bench/torus.h"
#include <quadtri/far/options.h>
#include <quadtri/far/refiner.h>

namespace quadtri::bench {

class QuadtriCase {
public:
    QuadtriCase(const ControlMesh& mesh, Scheme scheme, int level);
    ~QuadtriCase();

    // The untimed first run: builds the refiner, evaluates serially and (when linked) threaded,
    // and checks that the two evaluations agree (std::runtime_error if not).
    void prepare();

    // Last-level positions of the serial evaluation (after prepare()).
    const std::vector<float>& lastLevel() const { return serial_.back(); }
    int refinedVertices() const { return int(serial_.back().size() / 3); }
    const Refiner& refiner() const { return *refiner_; }

    // Medians of `reps` timed runs after a warm-up (the build's warm-up is prepare()).
    QuadtriFigures measure(int reps);

private:
    std::unique_ptr<Refiner> build() const;
    void evalSerial();
    void evalThreaded();

    const ControlMesh& mesh_;
    Options options_;
    int level_;
    std::unique_ptr<Refiner> refiner_;
    // Per level: level 0 is the control positions; level L >= 1 is written by levelStencils(L).
    std::vector<std::vector<float>> serial_, threaded_;
};

}  // namespace quadtri::bench
