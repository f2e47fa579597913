// One tessellation case: every face of a cage cut at a uniform rate into draw-ready triangles
// with limit positions and unit normals, serial. quadtri's way here (Tessellation: points of shared
// edges and vertices once, their stencils as one LimitStencilTable, CpuEvaluator every frame);
// OpenSubdiv's, Bfr::Tessellation face by face, in bench/opensubdiv/osd_tessellation_case.h.
#pragma once

#include <vector>

#include "bench/figures.h"
#include "bench/quadtri/surface_case.h"

namespace quadtri::bench {

// The sum of the triangles' areas, 3 indices a triangle into 3-float points.
double trianglesArea(const std::vector<int>& triangles, const std::vector<float>& points);

// quadtri's way on `cage` at `rate` segments an edge.
TessellationWay measureQuadtriTessellation(const SurfaceCage& cage, int rate, int reps);

}  // namespace quadtri::bench
