// OpenSubdiv's way to tessellate a whole cage (bench/quadtri/tessellation_case.h): per face a
// Bfr::Surface from a Bfr::RefinerSurfaceFactory at its default approximation levels, a
// Bfr::Tessellation at the uniform rate, Surface::Evaluate at each of its coordinates (position
// and derivatives, then the unit normal) and its triangles offset to the face's first point, as
// Bfr's tutorials do; a shared edge's points evaluated once per face. A frame keeps each face's
// Surface and coordinates and evaluates them again from the moved cage. Serial, floats.
#pragma once

#include "bench/opensubdiv/osd_case.h"
#include "bench/quadtri/tessellation_case.h"

namespace quadtri::bench {

TessellationWay measureBfrTessellation(const SurfaceCage& cage, OsdScheme scheme, int rate, int reps);

}  // namespace quadtri::bench
