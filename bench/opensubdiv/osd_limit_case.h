// OpenSubdiv's way to get the limit points and normals of a refined level every frame: a
// Far::LimitStencilTable with first derivatives at the level's vertices (their ptex locations on
// the control faces), evaluated by Osd::CpuEvaluator (and Osd::OmpEvaluator, and the table's own
// UpdateValues + UpdateDerivs templates) with du and dv, the normals normalize(du x dv) computed in
// a loop over the results.
#pragma once

#include <memory>
#include <vector>

#include "bench/figures.h"
#include "bench/opensubdiv/osd_case.h"
#include "bench/meshes/torus.h"

namespace quadtri::bench {

// OpenSubdiv's ways of applying the limit table: Osd::CpuEvaluator, Osd::OmpEvaluator, and Far's
// UpdateValues + UpdateDerivs templates compiled into the bench.
enum class OsdLimitEvaluator { Cpu, Omp, Far };

class OsdLimitCase {
public:
    // `mesh` a bench torus (quads under Catmark or triangles under Loop): each quad (i, j) gives the
    // 4^level vertices of level `level` that it owns, at dyadic (s, t).
    OsdLimitCase(const ControlMesh& mesh, OsdScheme scheme, int level);
    ~OsdLimitCase();

    // Builds the table (adaptive patches, isolation 2), evaluates once, and checks the limit
    // points against Far::PrimvarRefiner::Limit of the uniformly refined level as a set
    // (std::runtime_error if they differ): the locations are the level's vertices; Far's
    // templates must give CpuEvaluator's floats bitwise.
    void prepare();

    const std::vector<float>& positions() const;  // xyz per point, after prepare()
    const std::vector<float>& normals() const;
    int numPoints() const;

    OsdLimitFigures measure(int reps);

    // For the frame cases (bench/opensubdiv/osd_frame_case.h), after prepare(): the limit positions, du and
    // dv of a posed cage (3 floats per control vertex, the mesh's vertex order) by `evaluator`,
    // then normals() = normalize(du x dv) from them, as two calls so that each is timed.
    void evalDerivatives(const float* control, OsdLimitEvaluator evaluator);
    void evalNormals();

private:
    struct State;
    std::unique_ptr<State> s_;
};

}  // namespace quadtri::bench
