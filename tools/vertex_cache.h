// Draw buffers reordered for the GPU with Debian's meshoptimizer (libmeshoptimizer-dev): triangles
// in an order that reuses the post-transform vertex cache, then draw vertices in the order the
// triangles first use them, so fetching them walks the vertex buffer forward.
#pragma once

#include <quadtri/far/draw_buffers.h>

namespace quadtri::io {

// Reorders `buffers` in place: the same triangles (each keeping its corners' cyclic order, so its
// orientation) over the same draw vertices, renumbered. vertexOf / valueOf follow the vertices.
void optimizeVertexCache(DrawBuffers& buffers);

// meshoptimizer's average cache miss ratio (vertices transformed per triangle) of `buffers` for a
// cache of `cacheSize` vertices: 0.5 is the best a regular grid allows, 3 the worst.
double averageCacheMissRatio(const DrawBuffers& buffers, unsigned cacheSize = 16);

}  // namespace quadtri::io
