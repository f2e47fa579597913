// One bench case on OpenSubdiv's side (the only part of the bench that includes OpenSubdiv):
// Far::TopologyRefiner + Far::StencilTableFactory, per-level and factorized tables, evaluated with
// Osd::CpuEvaluator and Osd::OmpEvaluator.
#pragma once

#include <memory>
#include <vector>

#include "bench/figures.h"
#include "bench/torus.h"

namespace quadtri::bench {

enum class OsdScheme { Catmark, Loop };

class OsdCase {
public:
    OsdCase(const ControlMesh& mesh, OsdScheme scheme, int level);
    ~OsdCase();

    // The untimed first run: builds both tables, runs every evaluator once, and checks that the
    // factorized and OpenMP results agree with the per-level CPU result (std::runtime_error if not).
    void prepare();

    // Last-level positions of the per-level CPU evaluation, in OpenSubdiv's vertex order.
    std::vector<float> lastLevel() const;
    int refinedVertices() const;

    // Medians of `reps` timed runs after a warm-up (the builds' warm-up is prepare()).
    OsdFigures measure(int reps);

private:
    struct State;
    std::unique_ptr<State> s_;
};

}  // namespace quadtri::bench
