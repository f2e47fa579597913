// Helpers shared by the surface tests: dyadic (u, v) of a base face against the vertices of a
// uniform level, and which uniform limits are exact.
#pragma once

#include <functional>
#include <random>
#include <utility>

#include <quadtri/far/limit_surface.h>
#include <quadtri/far/refiner.h>

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

}  // namespace quadtri::test
