// The control mesh as OpenSubdiv's Far::TopologyRefiner, shared by the bench's OpenSubdiv cases
// (refinement tables and limit tables): edge-only boundaries, as quadtri's default.
#pragma once

#include <memory>

#include <opensubdiv/far/topologyRefiner.h>

#include "bench/opensubdiv/osd_case.h"
#include "bench/meshes/torus.h"

namespace quadtri::bench {

// Unrefined; std::runtime_error naming the mesh if OpenSubdiv refuses its topology.
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> osdTopologyRefiner(const ControlMesh& mesh, OsdScheme scheme);

}  // namespace quadtri::bench
