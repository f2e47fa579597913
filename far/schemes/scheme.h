// What a subdivision scheme supplies to the analyzer. A scheme is one stateless SchemeRules
// object (its name, how its faces split, what it prepares per level, its memory) and the
// SchemeMasks it makes for each worker, which append the weighted parent vertices of one child
// mask to the worker's accumulator. Everything else is shared by every scheme and lives in one
// place: crease decay, rule transitions and semi-sharp blends (rules.cpp calls the hooks below
// with a scale), the child numbering and topology (refine_topology.cpp, from triangleSplit()),
// the common memory estimate (level_estimate.cpp). Adding a scheme: docs/schemes/README.md.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "far/schemes/crease.h"
#include "far/topology/face_loops.h"
#include "far/limit/limit_eigen.h"
#include "far/limit/limit_mask.h"
#include <quadtri/far/options.h>
#include "far/topology/refine_topology.h"
#include "far/internal/sparse_accumulator.h"
#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

// What a scheme computes once per level and shares, read-only, among the threads building the
// level's masks (Schaefer-Warren's unzipped copies).
class SchemeLevel {
public:
    virtual ~SchemeLevel() = default;
};

// One worker's masks. Each call adds `scale` times the child's mask to the accumulator; the
// shared crease code may call several with scales summing to 1 (a semi-sharp blend). Hooks may
// keep per-mask scratch: every worker has its own object. One virtual call per mask, never per
// entry.
class SchemeMasks {
public:
    SchemeMasks(const Topology& topology, SparseAccumulator& accumulator) : t_(topology), acc_(accumulator) {}
    virtual ~SchemeMasks() = default;

    // Face point of a face that has one (every non-triangle, and triangles under ThreeQuads):
    // the centroid unless overridden.
    virtual void facePoint(int face, double scale) { centroid(face, scale); }
    // Edge point of an edge with two faces and no sharpness (or the smooth share of a blend).
    virtual void smoothEdgePoint(int edge, double scale) = 0;
    // Edge point of a sharp, boundary or non-manifold edge: the midpoint unless overridden.
    virtual void sharpEdgePoint(int edge, double scale);
    // Vertex point under `rule`; `edgeSharpness` (vertEdges order; null under Smooth on a level
    // without sharpness) tells which edges are the crease. Dispatches to the hooks below.
    virtual void vertexPoint(int vertex, VertexRule rule, const float* edgeSharpness, double scale);

    // Whether regular_masks.h may reuse a pooled mask for this child (SchemeRules::
    // regularMasksApply() says whether it may for the scheme at all): false where the scheme
    // builds a mask that differs from its plain rule of the same face sizes and valence.
    virtual bool regularFace(int /*face*/) const { return true; }
    virtual bool regularEdge(int /*edge*/) const { return true; }
    virtual bool regularVertex(int /*vertex*/) const { return true; }

protected:
    virtual void smoothVertexPoint(int vertex, double scale) = 0;  // Smooth and Dart
    // ¾ v + ⅛ at the far ends of the two sharp edges, unless overridden.
    virtual void creaseVertexPoint(int vertex, const float* edgeSharpness, double scale);
    virtual void cornerVertexPoint(int vertex, double scale) { acc_.add(vertex, scale); }

    void centroid(int face, double scale) {
        const IndexSpan corners = t_.verticesOfFace(face);
        const double w = scale / corners.size();
        for (int v : corners) acc_.add(v, w);
    }

    const Topology& t_;
    SparseAccumulator& acc_;
};

// Which faces of a level are regular patches of the scheme's limit surface, evaluated in closed
// form by far/surface/ (docs/surface.md, "Regular patches"). A regular quad: its 4 corners
// interior, manifold, of 4 quads, without sharpness on them or their edges, and no hole among
// those 9 faces; a regular triangle likewise with 6 triangles at each corner.
struct SurfacePatches {
    bool bilinear = false;            // every quad is its bilinear patch, every triangle its linear one
    bool bSplineQuads = false;        // a regular quad is the bicubic B-spline patch of its 16 points
    bool boxSplineTriangles = false;  // a regular triangle is the quartic box-spline patch of its 12
    // The patch's points must have only faces of the patch's own kind around them: where the
    // scheme's masks near the other kind (its seam rules) reach the corners' masks.
    bool pureNeighbourhood = false;
    // With every edge and vertex infinitely sharp (a face-varying channel under
    // FVarLinearInterpolation::All) each face is its bilinear (linear) patch: false where a crease
    // rule is not the midpoint (Butterfly's 4-point curves).
    bool sharpIsLinear = true;
};

// One scheme, stateless: one object per scheme, registered in schemes.cpp.
class SchemeRules {
public:
    virtual ~SchemeRules() = default;

    virtual const char* name() const = 0;         // as the CLI and toString(Scheme) spell it
    virtual const char* description() const = 0;  // one line, for help texts

    virtual TriangleSplit triangleSplit() const { return TriangleSplit::FourTriangles; }
    // False: a face of level 0 with other than 3 corners is a TopologyError naming the face.
    virtual bool acceptsNonTriangles() const { return true; }
    // What a face whose only repeated corners are collapsed edges (`4 3 5 5`) becomes at level 0
    // (face_loops.h): merged corners, or kept as it is, as OpenSubdiv reads it.
    virtual CollapsedEdges collapsedEdges() const { return CollapsedEdges::Drop; }
    // Whether Options::smoothTriangles means anything to the scheme; where not, asking for it is a
    // TopologyError.
    virtual bool acceptsSmoothTriangles() const { return false; }
    // False: sharpness never changes a mask (every level is built as smooth; Bilinear).
    virtual bool usesSharpness() const { return true; }
    // Whether the float-table short cut of regular_masks.h applies on smooth levels: the scheme's
    // plain masks of an edge between two triangles / two quads and of a vertex whose faces are
    // all triangles / all quads depend on that key (face size, valence) only.
    virtual bool regularMasksApply() const { return false; }

    // Built once per level before the masks, shared read-only by all workers; null if none.
    // With `faces` (sorted), only what the masks read within those faces of the level is
    // prepared: enough for the children of faces `surfaceRings()` rings inside them (an edit's
    // masks, far/edit/).
    virtual std::unique_ptr<SchemeLevel> prepareLevel(const Topology& /*parent*/, const Options& /*options*/,
                                                      const std::vector<int>* /*faces*/ = nullptr) const {
        return nullptr;
    }
    // A worker's masks; `prepared` is what prepareLevel returned for this level.
    virtual std::unique_ptr<SchemeMasks> makeMasks(const Topology& parent, const Options& options,
                                                   const SchemeLevel* prepared, SparseAccumulator& accumulator) const = 0;
    // Bytes this scheme needs for refining `parent` beyond the shared estimate
    // (level_estimate.cpp): its prepared level, masks longer than the shared bound. `parent`
    // may hold its faces only (TopologyDetail::FacesOnly): estimate from the faces then.
    virtual std::size_t extraLevelBytes(const Topology& /*parent*/) const { return 0; }

    // What far/surface/ may evaluate in closed form; how many face rings around a followed
    // sub-face keep its children's neighbourhoods off the local mesh's rim (1 where every mask
    // reads one ring of the parent: a child's one-ring reads no further than its parent's; 3
    // where masks read two, Butterfly's wings and Schaefer-Warren's copies); and how many around
    // a sub-face's next level keep its corners' limit masks off the rim (more where limit masks
    // are found by refining further, limit_deeper.h).
    virtual SurfacePatches surfacePatches() const { return {}; }
    virtual int surfaceRings() const { return 7; }
    virtual int surfaceLimitRings() const { return surfaceRings(); }

    // Appends to `out` (empty) the limit masks of one vertex of a level with full topology:
    // position, dU and dV (docs/limit.md). The default is the generic eigen-analysis of the
    // local subdivision matrix (limitFromLocalMatrix); schemes override it with closed forms
    // where they have them (Catmull-Clark, Loop, and the mixed schemes at pure vertices).
    virtual void limitMask(const LimitVertex& vertex, LimitMaskCache& cache, LimitMask& out) const {
        limitFromLocalMatrix(*this, vertex, cache, out);
    }
};

// The registry (schemes.cpp): the rules of a scheme, and every scheme in listing order.
const SchemeRules& rulesOf(Scheme scheme);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
