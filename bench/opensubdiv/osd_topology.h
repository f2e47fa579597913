// The control mesh as OpenSubdiv's Far::TopologyRefiner, shared by the bench's OpenSubdiv cases
// (refinement tables and limit tables): edge-only boundaries, as quadtri's default.
#pragma once

#include <memory>
#include <vector>

#include <opensubdiv/far/topologyRefiner.h>

#include "bench/opensubdiv/osd_case.h"
#include "bench/meshes/torus.h"

namespace quadtri::bench {

// Unrefined, with the given creases (2 vertices and a sharpness each), corners and holes;
// std::runtime_error naming the mesh if OpenSubdiv refuses its topology.
struct OsdTags {
    std::vector<int> creasePairs;
    std::vector<float> creaseSharpness;
    std::vector<int> corners;
    std::vector<float> cornerSharpness;
    std::vector<int> holes;
};
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> osdTopologyRefiner(const ControlMesh& mesh, OsdScheme scheme,
                                                                     const OsdTags& tags);
inline std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> osdTopologyRefiner(const ControlMesh& mesh, OsdScheme scheme,
                                                                            const std::vector<int>& creasePairs = {},
                                                                            const std::vector<float>& creaseSharpness = {}) {
    return osdTopologyRefiner(mesh, scheme, OsdTags{creasePairs, creaseSharpness, {}, {}, {}});
}

}  // namespace quadtri::bench
