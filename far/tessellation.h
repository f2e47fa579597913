// Every face of a limit surface cut into triangles at a rate per edge (OpenSubdiv's
// Bfr::Tessellation, for a whole mesh): which (face, u, v) to evaluate and the index buffer that
// joins them, with each point of a shared edge or vertex listed once (docs/surface.md).
#pragma once

#include <vector>

#include <quadtri/export.h>
#include <quadtri/far/limit_surface.h>

namespace quadtri {
inline namespace v0 {

// The points and triangles of a LimitSurface's faces (holes left out), from the face topology
// alone: evaluate the points with LimitSurface::stencilTable(numPoints(), faces(), u(), v()) and
// any evaluator's EvalLimitStencils, then draw triangles() over them.
//
// Edge e of the base mesh (Topology's numbering) is cut into rate(e) equal steps of its faces'
// parameter; the points of an edge or a vertex are shared by every face around it, so the mesh is
// watertight by construction. A face whose edges share one rate N is a regular grid (a quad:
// (N + 1)^2 points, 2 N^2 triangles; a triangle split in four: N^2 triangles). Otherwise its
// inside is a grid at the largest rate of each direction, joined to each edge's points by a strip.
// Faces cut into quad sub-faces (n-gons; triangles under catmull-clark) give their edges an even
// rate, so that each edge's midpoint, a corner of two sub-faces, is a point.
class QUADTRI_API Tessellation {
public:
    // Every edge at `rate` segments (1 or more).
    Tessellation(const LimitSurface& surface, int rate);
    // Edge e at edgeRates[e] segments (numEdges() of them, each 1 or more).
    Tessellation(const LimitSurface& surface, const std::vector<int>& edgeRates);

    // The points: point i lies at (faces()[i], u()[i], v()[i]), on a face that has it.
    int numPoints() const { return int(faces_.size()); }
    const int* faces() const { return faces_.data(); }
    const double* u() const { return u_.data(); }
    const double* v() const { return v_.data(); }

    // Three point indices per triangle, counter-clockwise as the faces are seen from outside
    // (LevelFaces' orientation), and the base face of each.
    int numTriangles() const { return int(triangleFaces_.size()); }
    const std::vector<int>& triangles() const { return triangles_; }
    const std::vector<int>& triangleFaces() const { return triangleFaces_; }

    // The rate each base edge was cut at (after rounding up to even where a sub-face needs it),
    // and the first of its rate - 1 inner points, numbered from the edge's first vertex
    // (Topology::edgeVerts), or -1 for an edge of holes only.
    int edgeRate(int edge) const { return edgeRates_[std::size_t(edge)]; }
    int firstEdgePoint(int edge) const { return edgePoints_[std::size_t(edge)]; }
    // The point of base vertex v, or -1 for a vertex of no face but holes.
    int vertexPoint(int vertex) const { return vertexPoints_[std::size_t(vertex)]; }

    // Face-varying values (UVs) on the tessellation. A point inside a face has one value; a point
    // on a base edge or vertex has one per distinct value of the channel around it (two across a
    // UV seam, one where the faces agree), each at the (u, v) of a face on its side. Evaluate them
    // with LimitSurface::fvarStencilTable(channel, numValues(), faces, u, v); cornerValues gives
    // each triangle corner's value, in triangles()' order.
    struct FVarPoints {
        std::vector<int> faces;
        std::vector<double> u, v;
        std::vector<int> cornerValues;
        int numValues() const { return int(faces.size()); }
    };
    FVarPoints fvarPoints(const LimitSurface& surface, int channel) const;

    // Limits on what one tessellation may hold; a rate over kMaxRate or more than kMaxPoints
    // points throws SurfaceError before anything is allocated.
    static constexpr int kMaxRate = 4096;
    static constexpr long long kMaxPoints = 1LL << 28;

private:
    void build(const LimitSurface& surface, std::vector<int> rates);

    std::vector<int> faces_;
    std::vector<double> u_, v_;
    std::vector<int> triangles_, triangleFaces_;
    std::vector<int> edgeRates_, edgePoints_, vertexPoints_;
};

}  // namespace v0
}  // namespace quadtri
