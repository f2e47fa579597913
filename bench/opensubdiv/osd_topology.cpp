#include "bench/opensubdiv/osd_topology.h"

#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <opensubdiv/sdc/options.h>

#include <stdexcept>

namespace quadtri::bench {

std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> osdTopologyRefiner(const ControlMesh& mesh, OsdScheme scheme,
                                                                     const OsdTags& tags) {
    namespace Far = OpenSubdiv::Far;
    namespace Sdc = OpenSubdiv::Sdc;
    Far::TopologyDescriptor desc;
    desc.numVertices = mesh.numVertices;
    desc.numFaces = mesh.numFaces();
    desc.numVertsPerFace = mesh.faceSizes.data();
    desc.vertIndicesPerFace = mesh.faceVerts.data();
    desc.numCreases = int(tags.creaseSharpness.size());
    desc.creaseVertexIndexPairs = tags.creasePairs.data();
    desc.creaseWeights = tags.creaseSharpness.data();
    desc.numCorners = int(tags.cornerSharpness.size());
    desc.cornerVertexIndices = tags.corners.data();
    desc.cornerWeights = tags.cornerSharpness.data();
    desc.numHoles = int(tags.holes.size());
    desc.holeIndices = tags.holes.data();
    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    const Sdc::SchemeType type = scheme == OsdScheme::Catmark ? Sdc::SCHEME_CATMARK : Sdc::SCHEME_LOOP;
    std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(type, sdc)));
    if (!refiner) throw std::runtime_error(mesh.name + ": OpenSubdiv refused the topology");
    return refiner;
}

}  // namespace quadtri::bench
