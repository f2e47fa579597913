// The bench's high-valence control mesh: a UV sphere generated in code, whose two poles have a
// valence in the thousands (what a rule walking a vertex's ring per edge cannot afford).
#pragma once

#include "bench/meshes/torus.h"

namespace quadtri::bench {

enum class SpherePoles {
    TriangleFans,  // triangles at the poles, quads elsewhere: a mixed mesh, poles of valence `segments`
    QuadFans,      // quads (pole, three consecutive ring vertices) at the poles: all quads, valence segments/2
};

// `segments` (even) vertices around each of `rings` - 1 latitude rings, plus the two poles; unit
// radius. Named e.g. "sphere2000x8_mixed" / "sphere2000x8_quad".
ControlMesh makeUvSphere(int segments, int rings, SpherePoles poles);

}  // namespace quadtri::bench
