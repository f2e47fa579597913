// One bench case on OpenSubdiv's side (the only part of the bench that includes OpenSubdiv):
// Far::TopologyRefiner + Far::StencilTableFactory, per-level and factorized tables, evaluated with
// Osd::CpuEvaluator, Osd::OmpEvaluator and Far::StencilTable::UpdateValues on 3-float positions
// and on the same positions padded to 4 floats (the width its CPU kernel has a SIMD path for), so
// that its best way is timed.
#pragma once

#include <memory>
#include <vector>

#include "bench/figures.h"
#include "bench/meshes/torus.h"

namespace quadtri::bench {

enum class OsdScheme { Catmark, Loop };

class OsdCase {
public:
    OsdCase(const ControlMesh& mesh, OsdScheme scheme, int level);
    ~OsdCase();

    // The untimed first run: builds both tables, runs every evaluation once, and checks them
    // against the per-level 3-float CPU one (std::runtime_error if not): bitwise at the other
    // width and on the other evaluators of the same table, so that the padding changes no float,
    // within a tolerance on the factorized table. The case's memory is that of the per-level
    // table's build and its 3-float buffer, as on quadtri's side.
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
