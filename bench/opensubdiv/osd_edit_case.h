// What OpenSubdiv builds again after an edit of a cage's tags (bench/quadtri/edit_case.h): it
// has no edit in place, so a crease changed is a new Far::TopologyRefiner, its uniform refinement
// and factorized Far::StencilTable, and for the limit a refiner refined adaptively (isolation 2)
// with its Far::LimitStencilTable at every vertex of level N (their ptex locations), serial.
#pragma once

#include "bench/measure/timing.h"
#include "bench/opensubdiv/osd_case.h"
#include "bench/opensubdiv/osd_topology.h"

namespace quadtri::bench {

// The median, fastest and slowest of `reps` rebuilds of `mesh` with `tags` at `level`.
Timing osdRebuild(const ControlMesh& mesh, OsdScheme scheme, const OsdTags& tags, int level, int reps);

}  // namespace quadtri::bench
