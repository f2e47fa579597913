// What the renderer draws besides positions and normals, computed on the CPU from the analyzer's
// levels: per triangle the kind of control face it descends from, per vertex the mean curvature,
// and the cage with its sharpness colours (docs/rendering.md).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <quadtri/far/draw_buffers.h>
#include <quadtri/far/refiner.h>
#include <quadtri/far/topology.h>

namespace quadtri::render {

// The control face each face of level `level` descends from: children of a face are contiguous
// in the next level, in parent order (4 per triangle split in four, n per n-gon split around a
// face point).
std::vector<int> rootFaces(const Refiner& refiner, int level);

enum FaceOrigin : uint32_t { kFromTriangle = 0, kFromQuad = 1, kFromOtherPolygon = 2 };
// Per triangle of `draw` (built from `faces`: a non-hole face of n corners gives n - 2
// triangles, in face order), the FaceOrigin of its root face.
std::vector<uint32_t> triangleOrigins(const LevelFaces& faces, const LevelFaces& controlFaces,
                                      const std::vector<int>& roots, const DrawBuffers& draw);

// Signed mean curvature per vertex from the cotangent Laplacian of the level's triangles:
// |Δx| / 2 with Δx = (1 / 2A) Σ (cot α + cot β)(x_j - x_i) over the one-ring (A a third of the
// ring's area), positive where Δx points against the normal (convex). Quads count as both their
// triangulations, half each; boundary vertices get 0.
std::vector<float> meanCurvature(const LevelFaces& faces, const float* positions, const float* normals);
// A symmetric colour range for `curvature`: the 95th percentile of |H| (0 when all are 0).
float curvatureRange(const std::vector<float>& curvature);

// The sharpness colour code (docs/rendering.md): 0 grey, a ramp from yellow (just above 0)
// through orange to red (just below 10), infinite (10 and above, kInfiniteSharpness) magenta;
// selected items cyan.
glm::vec3 sharpnessColor(float sharpness);
glm::vec3 selectedColor();

// The control cage as the renderer draws it.
struct Cage {
    std::vector<float> positions;  // 3 per control vertex
    std::vector<uint32_t> edges;   // 2 per edge
    std::vector<glm::vec4> edgeColors, pointColors;
};
// Edges of `level0` coloured by their sharpness (boundary edges as infinite), vertices by their
// corner sharpness; `selectedEdges` / `selectedVertices` (indices) highlighted.
Cage cageOf(const Topology& level0, const float* positions, const std::vector<int>& selectedEdges = {},
            const std::vector<int>& selectedVertices = {});

}  // namespace quadtri::render
