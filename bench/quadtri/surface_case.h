// One surface case on quadtri's side: the limit position, du, dv and unit normal at random (u, v)
// on every face of a cage, by FaceSurfaceFactory and FaceSurface::evaluate, serial, a face's points
// as one batch; the factory's cost (LimitSurface from the mesh's arrays + FaceSurfaceFactory) beside it. OpenSubdiv's ways are
// bench/opensubdiv/osd_surface_case.h.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "bench/figures.h"
#include "bench/meshes/torus.h"
#include <quadtri/far/options.h>

namespace quadtri {
inline namespace v0 {
class LimitSurface;
class FaceSurfaceFactory;
}  // namespace v0
}  // namespace quadtri

namespace quadtri::bench {

// A cage with its tags, and the options quadtri runs it with (its scheme and the file's tags).
// The surface cases take creases only; the edit cases (bench/edit_case.h) corners and holes too.
struct SurfaceCage {
    ControlMesh mesh;
    std::vector<int> creasePairs;  // 2 vertices per crease
    std::vector<float> creaseSharpness;
    std::vector<int> corners;
    std::vector<float> cornerSharpness;
    std::vector<int> holes;
    Options options;

    TopologyDescriptor descriptor() const;  // the mesh's, with the tags
};

// The points every way evaluates: per point its face and (u, v) on it (OpenSubdiv's Bfr
// parameterization), grouped by face.
struct SurfacePoints {
    std::vector<int> faces;
    std::vector<double> u, v;
    int size() const { return int(faces.size()); }
};

class SurfaceCase {
public:
    // `pointsPerFace` random points on each face (a fixed seed: the same points every run).
    SurfaceCase(const SurfaceCage& cage, int pointsPerFace);
    ~SurfaceCase();

    // Builds the surface, makes the points and evaluates them once.
    void prepare();

    const SurfacePoints& points() const { return points_; }
    const std::vector<float>& positions() const { return position_; }  // 3 floats a point, after prepare()
    const std::vector<float>& normals() const { return normal_; }

    SurfaceWay measure(int reps);

private:
    // Every point through `factory` into position_ and normal_.
    void evaluate(FaceSurfaceFactory& factory);

    const SurfaceCage& cage_;
    int pointsPerFace_;
    std::unique_ptr<LimitSurface> surface_;
    std::unique_ptr<FaceSurfaceFactory> warm_;  // has seen every point
    SurfacePoints points_;
    std::vector<float> position_, normal_;
    std::vector<float> du_, dv_;  // per point, for its normal
};

}  // namespace quadtri::bench
