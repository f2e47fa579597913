// One bench case on quadtri's side: the analyzer build (on one thread and on all), the per-level
// tables, and their serial and threaded evaluation level by level into preallocated buffers, of
// 3-float positions and of the same positions padded to 4 floats, through each level's StencilRuns
// (built once, as an application sets up its evaluation; untimed).
#pragma once

#include <memory>
#include <vector>

#include "bench/figures.h"
#include "bench/meshes/torus.h"
#include <quadtri/far/options.h>
#include <quadtri/far/refiner.h>
#include <quadtri/osd/stencil_runs.h>

namespace quadtri::bench {

class QuadtriCase {
public:
    // `factorized`: also time the factorized build (where OpenSubdiv's factorized factory is timed
    // beside it: near the spheres' poles a factorized table takes seconds to build).
    QuadtriCase(const ControlMesh& mesh, Scheme scheme, int level, bool factorized);
    ~QuadtriCase();

    // The untimed first run: builds the refiner and the runs, evaluates serially through the
    // tables, then through the runs serially and threaded at both widths, and checks that the
    // evaluations agree bitwise (std::runtime_error if not); the
    // case's memory is that of the build and the 3-float serial buffers.
    void prepare();

    // Last-level positions of the serial evaluation (after prepare()).
    const std::vector<float>& lastLevel() const { return serial_.back(); }
    int refinedVertices() const { return int(serial_.back().size() / 3); }
    const Refiner& refiner() const { return *refiner_; }

    // Medians of `reps` timed runs after a warm-up (the build's warm-up is prepare()).
    QuadtriFigures measure(int reps);

private:
    // The topology of every level, with the per-level tables unless `tables` says None.
    std::unique_ptr<Refiner> build(LevelTables tables = LevelTables::Build) const;
    // The topology and the last level's factorized table, without per-level tables (the factorized
    // build makes those only where a stencil reads them), as OpenSubdiv's factorized factory
    // builds it.
    struct FactorizedBuild {
        std::unique_ptr<Refiner> refiner;
        StencilTable table;
    };
    FactorizedBuild buildFactorized() const;
    // Levels 1..level_ through runs_ (or through the tables themselves).
    template <class Evaluator>
    void eval(std::vector<std::vector<float>>& levels, int width, bool throughTables = false);

    const ControlMesh& mesh_;
    Options options_;
    int level_;
    std::unique_ptr<Refiner> refiner_;
    std::vector<StencilRuns> runs_;  // runs_[L - 1]: levelStencils(L)'s
    // Per level: level 0 is the control positions; level L >= 1 is written by levelStencils(L).
    // padded_: the same at 4 floats a vertex (the fourth 0).
    std::vector<std::vector<float>> serial_, threaded_, padded_;
    MemoryFigures memory_;
    bool factorized_;
    bool factorizedFits_ = false;  // whether prepare() built the factorized table (asked, within the budget)
};

}  // namespace quadtri::bench
