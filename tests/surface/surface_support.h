// Helpers shared by the surface tests: dyadic (u, v) of a base face against the vertices of a
// uniform level, and which uniform limits are exact.
#pragma once

#include <functional>
#include <random>
#include <string>
#include <utility>

#include <quadtri/far/limit_surface.h>
#include <quadtri/far/refiner.h>
#include "tests/test_support.h"

namespace quadtri::test {

// Calls visit(face of level L, its corner, u, v) for the corners of every level-L descendant of
// base face `face`, (u, v) in the face's parameterization: each child's corners are its parent's
// corners, edge midpoints and centre in (u, v), as the children are in space.
void forEachDescendantCorner(const Refiner& r, int face, int L,
                             const std::function<void(int, int, double, double)>& visit);

// Whether the uniform limit of `vertex` is exact: OpenSubdiv's Limit (and quadtri's, which equals
// it) counts a semi-sharp edge or vertex as sharp and gives a dart the smooth mask, both exact
// only in the limit of refinement.
bool exactUniformLimit(const Topology& t, int vertex);

// A random (u, v) in the face's domain; for a face of quad sub-faces, in sub-face k % faceSize.
std::pair<double, double> randomPointOf(const FaceParameterization& p, int k, std::mt19937& random);

// visit(mesh, scheme, r) for every test mesh refined to `levels` under every scheme that takes it
// (loop refuses quads).
void forEachMeshAndScheme(int levels, const std::function<void(const std::string&, Scheme, RefinedMesh&)>& visit);

// Surface options at `maxDepth` with the scheme's own cuts, and with wider ones (a ring more than
// its steps', at least its limit masks'): what local refinement cut before it cut narrowly.
std::pair<LimitSurfaceOptions, LimitSurfaceOptions> narrowAndWiderCuts(Scheme scheme, int maxDepth);

// Whether two stencils hold the same weights on the same indices, bit for bit, in any order.
bool sameWeights(const LimitPointStencil& a, const LimitPointStencil& b);

}  // namespace quadtri::test
