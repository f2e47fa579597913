// Draw-ready buffers for one level: a triangle index buffer over a vertex set in which a vertex is
// copied wherever a face-varying channel (UVs) takes different values around it, with the map
// back to the level's vertices and values (docs/draw_buffers.md).
#pragma once

#include <cstdint>
#include <vector>

#include <quadtri/export.h>
#include <quadtri/far/level_faces.h>
#include <quadtri/far/stencil_table.h>

namespace quadtri {
inline namespace v0 {

struct QUADTRI_API DrawBuffers {
    // 3 per triangle, over the draw vertices, counter-clockwise as the faces: a quad (a, b, c, d)
    // is (a, b, c) and (a, c, d); a larger face (level 0 only) is the fan from its first corner.
    // Holes are left out.
    std::vector<std::uint32_t> triangles;
    // Per draw vertex: the level's vertex it shows (positions, normals), and per channel the
    // channel's value there. Draw vertices are numbered in the order the faces' corners first use
    // them; a vertex used only by holes has none.
    std::vector<int> vertexOf;
    std::vector<std::vector<int>> valueOf;
    int numLevelVertices = 0;            // the level's vertices (what vertexOf indexes)
    std::vector<int> numChannelValues;   // per channel: its values (what valueOf[k] indexes)

    int numVertices() const { return int(vertexOf.size()); }
    int numTriangles() const { return int(triangles.size() / 3); }

    // Tables that copy the level's vertex data (`channel` = -1) or a channel's values into draw
    // vertex order: one stencil per draw vertex, one entry of weight 1. Any evaluator applies
    // them, writing each draw vertex's data wherever its descriptor says (several attributes
    // interleaved in one vertex buffer through offsets and a common stride).
    StencilTable gatherStencils(int channel = -1) const;
};

// The draw buffers of `faces`. `cornerValues` holds, per face-varying channel, one value index per
// corner of `faces` in its corner order (LevelFaces::vertices()); a draw vertex is a distinct
// (vertex, value of every channel) combination. `numValues` has each channel's number of values:
// a value index outside [0, numValues) is a TopologyError naming the face.
QUADTRI_API DrawBuffers buildDrawBuffers(const LevelFaces& faces, const std::vector<const int*>& cornerValues = {},
                             const std::vector<int>& numValues = {});

}  // namespace v0
}  // namespace quadtri
