// The control mesh as OpenSubdiv's Far::TopologyRefiner, shared by the bench's OpenSubdiv cases
// (refinement tables and limit tables): edge-only boundaries, as quadtri's default.
#pragma once

#include <memory>
#include <vector>

#include <opensubdiv/far/topologyRefiner.h>

#include "bench/opensubdiv/osd_case.h"
#include "bench/meshes/torus.h"

namespace quadtri::bench {

// Unrefined, with the given creases (2 vertices and a sharpness each); std::runtime_error naming
// the mesh if OpenSubdiv refuses its topology.
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> osdTopologyRefiner(const ControlMesh& mesh, OsdScheme scheme,
                                                                     const std::vector<int>& creasePairs = {},
                                                                     const std::vector<float>& creaseSharpness = {});

}  // namespace quadtri::bench
