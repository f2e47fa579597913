#include "bench/opensubdiv/osd_tessellation_case.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/bfr/tessellation.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "bench/compare.h"
#include "bench/opensubdiv/osd_topology.h"

namespace quadtri::bench {

namespace Bfr = OpenSubdiv::Bfr;
namespace Far = OpenSubdiv::Far;

namespace {

// Per face its Surface and its tessellation's coordinates; the points, normals and triangles of
// all faces together, each face's after the one before.
struct BfrTessellated {
    std::vector<Bfr::Surface<float>> surfaces;
    std::vector<std::vector<float>> coords;  // (u, v) per point, per face
    std::vector<float> positions, normals, patchPoints;
    std::vector<int> triangles;
};

void evaluate(const SurfaceCage& cage, BfrTessellated& t) {
    const Bfr::Surface<float>::PointDescriptor layout(3);
    std::size_t point = 0;
    for (std::size_t f = 0; f < t.surfaces.size(); ++f) {
        const Bfr::Surface<float>& surface = t.surfaces[f];
        t.patchPoints.resize(3 * std::size_t(surface.GetNumPatchPoints()));
        surface.PreparePatchPoints(cage.mesh.positions.data(), layout, t.patchPoints.data(), layout);
        const std::vector<float>& uv = t.coords[f];
        for (std::size_t k = 0; k < uv.size(); k += 2, ++point) {
            float du[3], dv[3];
            surface.Evaluate(&uv[k], t.patchPoints.data(), layout, &t.positions[3 * point], du, dv);
            unitNormal(du, dv, &t.normals[3 * point]);
        }
    }
}

void tessellate(const SurfaceCage& cage, OsdScheme scheme, int rate, BfrTessellated& t) {
    const std::unique_ptr<Far::TopologyRefiner> refiner =
        osdTopologyRefiner(cage.mesh, scheme, cage.creasePairs, cage.creaseSharpness);
    const Bfr::RefinerSurfaceFactory<> factory(*refiner);
    const int numFaces = cage.mesh.numFaces();
    t.surfaces.assign(std::size_t(numFaces), Bfr::Surface<float>());
    t.coords.assign(std::size_t(numFaces), {});
    t.triangles.clear();
    int numPoints = 0;
    std::vector<int> facets;
    for (int f = 0; f < numFaces; ++f) {
        if (!factory.InitVertexSurface(f, &t.surfaces[std::size_t(f)]))
            throw std::runtime_error(cage.mesh.name + ": Bfr has no surface for face " + std::to_string(f));
        Bfr::Tessellation tess(t.surfaces[std::size_t(f)].GetParameterization(), rate);
        std::vector<float>& uv = t.coords[std::size_t(f)];
        uv.resize(2 * std::size_t(tess.GetNumCoords()));
        tess.GetCoords(uv.data());
        facets.resize(3 * std::size_t(tess.GetNumFacets()));
        tess.GetFacets(facets.data());
        tess.TransformFacetCoordIndices(facets.data(), numPoints);
        t.triangles.insert(t.triangles.end(), facets.begin(), facets.end());
        numPoints += tess.GetNumCoords();
    }
    t.positions.resize(3 * std::size_t(numPoints));
    t.normals.resize(t.positions.size());
    evaluate(cage, t);
}

}  // namespace

TessellationWay measureBfrTessellation(const SurfaceCage& cage, OsdScheme scheme, int rate, int reps) {
    TessellationWay way;
    way.library = "opensubdiv";
    way.way = "bfr_tessellation";
    BfrTessellated t;
    tessellate(cage, scheme, rate, t);
    way.points = int(t.positions.size() / 3);
    way.triangles = int(t.triangles.size() / 3);
    way.area = trianglesArea(t.triangles, t.positions);
    way.firstMs = timeMs(reps, [&] {
        BfrTessellated fresh;
        tessellate(cage, scheme, rate, fresh);
    });
    way.frameMs = timeMs(reps, [&] { evaluate(cage, t); });
    return way;
}

}  // namespace quadtri::bench
