// The limit surface at any point of a base face: position and first derivatives at (face, u, v),
// for every scheme, as weights over the control vertices or applied to them (docs/surface.md).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <quadtri/export.h>
#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {

class Refiner;
class FaceSurface;
namespace internal {
class FaceTree;
class FVarChannelRefinement;
}

// How (u, v) cover a base face, as OpenSubdiv's Bfr::Parameterization: a quad is the unit square
// from its first corner (corner 1 at (1, 0), corner 3 at (0, 1)); a triangle under a scheme that
// splits triangles in four has its corners at (0, 0), (1, 0), (0, 1); any other face (an n-gon,
// or a triangle under catmull-clark) is cut into one quad per corner, sub-face i the square
// [x, x + ½] × [y, y + ½] at (x, y) = (i % gridWidth, i / gridWidth), its u along corner i's
// leaving edge and its v along its entering edge, the face's centre at (x + ½, y + ½).
struct QUADTRI_API FaceParameterization {
    enum class Type { Quad, Triangle, QuadSubFaces };
    Type type = Type::Quad;
    int faceSize = 4;
    int gridWidth = 0;  // QuadSubFaces: sub-faces per row of the (u, v) layout

    static FaceParameterization of(Scheme scheme, int faceSize);
    // Whether (u, v) lies in the face's domain, within `tolerance` of its edges.
    bool contains(double u, double v, double tolerance = 1e-9) const;
    // QuadSubFaces: the sub-face whose square holds (u, v) within `tolerance`, or -1.
    int subFaceAt(double u, double v, double tolerance = 1e-9) const;
    // The (u, v) of corner i.
    void cornerCoord(int corner, double& u, double& v) const;
    // The (u, v) at t in [0, 1] along edge i (from corner i to corner i + 1).
    void edgeCoord(int edge, double t, double& u, double& v) const;
    // The domain in words, for error messages: "the unit square", ...
    std::string describe() const;
};

// Weights of one point over the control vertices: the limit position and its derivatives along
// the face's u and v (OpenSubdiv's Bfr derivatives: for a sub-face, per unit of the face's u, v).
struct LimitPointStencil {
    std::vector<int> indices;
    std::vector<double> position;
    std::vector<double> du;
    std::vector<double> dv;
    int size() const { return int(indices.size()); }
};

struct LimitSurfaceOptions {
    // Levels of local refinement past which a point that is still in no regular sub-face is
    // interpolated from the exact limit points of its sub-face's next level (docs/surface.md,
    // "Error bound"). 10 leaves sub-faces of 1/1024 of the face.
    int maxDepth = 10;
    // Vertex rings of faces kept around the followed sub-face at each level (and around the
    // last level's sub-faces, whose limit masks it takes); 0 picks the scheme's own (1 where every
    // rule reads one ring, 2-3 where rules read two; 7 for the mixed schemes' limit masks).
    // Tests raise it to show the result does not change.
    int rings = 0;
};

// A point outside what the surface can evaluate: a face out of range or a hole, (u, v) outside
// the face's domain. The message names the face (0-based) and the coordinate.
class QUADTRI_API SurfaceError : public std::invalid_argument {
public:
    explicit SurfaceError(const std::string& what) : std::invalid_argument(what) {}
};

// The limit surface of a Refiner's control mesh (its level 0 and options; the Refiner may go
// afterwards), or of a mesh given as a TopologyDescriptor. Construction copies (or builds) level 0
// and nothing else: each point is found by refining
// the neighbourhood of its face locally, with the scheme's own rules, until the point lies in a
// regular sub-face (a bicubic B-spline patch on quads, a quartic box-spline patch on triangles)
// or maxDepth is reached. Every method is const and may run on many threads at once.
class QUADTRI_API LimitSurface {
public:
    explicit LimitSurface(const Refiner& refiner, LimitSurfaceOptions surfaceOptions = {});
    // Without a Refiner: level 0 built from the mesh's arrays straight into the surface, as a
    // Refiner would build it (TopologyError for bad input).
    LimitSurface(const TopologyDescriptor& desc, const Options& options, LimitSurfaceOptions surfaceOptions = {});
    ~LimitSurface();
    LimitSurface(LimitSurface&&) noexcept;
    LimitSurface& operator=(LimitSurface&&) noexcept;

    int numFaces() const;
    int numControlVertices() const;
    const Options& options() const { return options_; }
    // The control mesh's topology (the Refiner's level 0): its faces, edges and vertices.
    const Topology& topology() const { return *base_; }
    FaceParameterization parameterization(int face) const;
    bool isHole(int face) const;

    // The weights of the point (u, v) of `face` over the control vertices. Throws SurfaceError
    // for a face out of range or a hole, or (u, v) outside the face's domain.
    void stencil(int face, double u, double v, LimitPointStencil& out) const;

    // The point itself from `control` (numControlVertices() items of `width` floats, `stride`
    // floats apart): its position and, where not null, dPdu and dPdv (`width` floats each).
    void evaluate(int face, double u, double v, const float* control, int width, int stride, float* position,
                  float* dPdu = nullptr, float* dPdv = nullptr) const;

    // The stencils of `count` points (faces[i], u[i], v[i]) as one table over the control
    // vertices, stencil i for point i (as OpenSubdiv's LimitStencilTableFactory takes location
    // arrays): the evaluators' EvalLimitStencils then give positions, tangents and unit normals
    // of all of them, on any back end. The stencils are built on oneTBB's threads where there
    // are (the same table on any number). Throws SurfaceError, naming the point's index, for a point
    // `stencil` refuses.
    LimitStencilTable stencilTable(int count, const int* faces, const double* u, const double* v) const;

    // Face-varying channels (the Refiner's TopologyDescriptor::fvarChannels, UVs) at the same
    // (face, u, v): the limit of the channel's values as Refiner::fvarLimitStencils gives it at
    // the vertices of every level, under Options::fvarLinearInterpolation (docs/surface.md,
    // "Face-varying values"). Weights are over the channel's own values (numFVarValues(c));
    // du and dv are the value's derivatives along the face's u and v. Throws SurfaceError as
    // stencil does, and for a channel out of range.
    int numFVarChannels() const { return int(channels_.size()); }
    int numFVarValues(int channel) const;
    // Face f's value of the channel at each of its corners (the channel's value indices).
    IndexSpan fvarValuesOfFace(int channel, int face) const;
    void fvarStencil(int channel, int face, double u, double v, LimitPointStencil& out) const;
    void evaluateFVar(int channel, int face, double u, double v, const float* values, int width, int stride,
                      float* value, float* dValuedu = nullptr, float* dValuedv = nullptr) const;
    LimitStencilTable fvarStencilTable(int channel, int count, const int* faces, const double* u,
                                       const double* v) const;

private:
    friend class FaceSurfaceFactory;
    struct Channel;  // a channel's value mesh (limit_surface.cpp)

    LimitSurface(const Options& options, LimitSurfaceOptions surfaceOptions, std::shared_ptr<const Topology> base);
    void addChannel(const internal::FVarChannelRefinement& source);
    void check(int face, double u, double v) const;
    const Channel& channel(int c) const;
    // The table of the vertex surface (channel -1) or of face-varying channel `channel`.
    LimitStencilTable tableOf(int channel, int count, const int* faces, const double* u, const double* v) const;

    Options options_;
    LimitSurfaceOptions surfaceOptions_;
    std::shared_ptr<const Topology> base_;
    std::vector<std::shared_ptr<const Channel>> channels_;
};

// One base face's surface, for many points of it (as Bfr::Surface), made by a FaceSurfaceFactory:
// the local refinement one point needed stays for the next, so that points in a regular sub-face
// already reached cost one basis evaluation (docs/surface.md, "Faces' trees"). Each point's
// stencil is exactly the one LimitSurface::stencil (or fvarStencil) gives it.
class QUADTRI_API FaceSurface {
public:
    FaceSurface();
    ~FaceSurface();
    FaceSurface(FaceSurface&&) noexcept;
    FaceSurface& operator=(FaceSurface&&) noexcept;

    int face() const;  // -1 when empty
    const FaceParameterization& parameterization() const;

    // The weights of (u, v) over the control vertices (or the channel's values). Throws
    // SurfaceError for (u, v) outside the face's domain, or an empty FaceSurface.
    void stencil(double u, double v, LimitPointStencil& out);
    // The point from `control` (the control vertices, or the channel's values): `width` floats
    // each, `stride` floats apart, as LimitSurface::evaluate.
    void evaluate(double u, double v, const float* control, int width, int stride, float* position,
                  float* dPdu = nullptr, float* dPdv = nullptr);
    // `count` points (u[i], v[i]) at once, as many calls of the above would give them: point i's
    // position at position[i * outStride] (dPdu, dPdv likewise, where not null; outStride 0 is
    // `width`). A regular face reads its control points once for all of them. Throws SurfaceError,
    // naming the point's index, before anything is written if a point is outside the domain (and
    // for an empty surface, a negative count, an outStride below width).
    void evaluate(int count, const double* u, const double* v, const float* control, int width, int stride,
                  float* position, float* dPdu = nullptr, float* dPdv = nullptr, int outStride = 0);

private:
    void check(double u, double v, int point) const;  // SurfaceError outside the domain

    friend class FaceSurfaceFactory;
    std::shared_ptr<void> shared_;  // the factory's trees, alive while this surface is
    internal::FaceTree* tree_ = nullptr;
    int face_ = -1;
    const int* columns_ = nullptr;  // per column of the tree: the base vertex (value-mesh vertex)
    std::vector<int> sources_;  // face-varying: per column, the channel value it reads
    const std::vector<int>* valueOf_ = nullptr;
    LimitPointStencil local_;
};

// Makes the FaceSurfaces of a LimitSurface's faces: its vertex surface, or (channel >= 0) a
// face-varying channel's. Faces whose neighbourhoods have the same topology and sharpness share
// one tree of sub-patches (the tree depends on nothing else), as Bfr::SurfaceFactory caches its
// irregular patches, so that a mesh's repeated configurations are refined once. The factory and
// the FaceSurfaces it made are for one thread at a time: make one factory per thread. The
// LimitSurface must outlive them. Throws SurfaceError for a channel out of range.
class QUADTRI_API FaceSurfaceFactory {
public:
    explicit FaceSurfaceFactory(const LimitSurface& surface, int channel = -1);
    ~FaceSurfaceFactory();

    // Face `face`'s surface. Throws SurfaceError for a face out of range or a hole.
    FaceSurface faceSurface(int face);
    // The same into `surface`, reusing its memory. A face met again costs a lookup: the factory
    // keeps each face's tree and neighbourhood.
    void faceSurface(int face, FaceSurface& surface);
    // Neighbourhood shapes met so far that needed a tree of their own (regular faces need none).
    int numShapes() const;

private:
    struct Shared;
    const LimitSurface* surface_;
    const std::vector<int>* valueOf_ = nullptr;
    std::shared_ptr<Shared> shared_;
};

}  // namespace v0
}  // namespace quadtri
