// OpenSubdiv's ways to evaluate a surface at (face, u, v): Bfr::Surface from a
// Bfr::RefinerSurfaceFactory at its default approximation levels (2 smooth, 6 sharp) and with
// both at 10 (timed in float; evaluated in double as the reference the errors are measured from:
// in float its level-10 patch points lose digits, up to 6e-3 rad in the limb's normals), and the older route, a Far::PatchTable
// (adaptive refinement to level 2, Gregory-basis end caps) with a Far::PatchMap to find each
// point's patch and Osd::CpuEvaluator::EvalPatches, its local points from a stencil table every
// evaluation. All serial, floats, 3 a vertex; position, du, dv, then the normal normalize(du x dv).
#pragma once

#include <memory>
#include <vector>

#include "bench/figures.h"
#include "bench/opensubdiv/osd_case.h"
#include "bench/quadtri/surface_case.h"

namespace quadtri::bench {

class OsdSurfaceCase {
public:
    OsdSurfaceCase(const SurfaceCage& cage, OsdScheme scheme, const SurfacePoints& points);
    ~OsdSurfaceCase();

    // Builds every way and evaluates the points once each way.
    void prepare();

    // Bfr at level 10's points and normals evaluated in double (3 floats a point), after prepare().
    const std::vector<float>& referencePositions() const;
    const std::vector<float>& referenceNormals() const;

    // Every way, timed, with its errors against Bfr at level 10.
    std::vector<SurfaceWay> measure(int reps);

private:
    struct State;
    std::unique_ptr<State> s_;
};

}  // namespace quadtri::bench
