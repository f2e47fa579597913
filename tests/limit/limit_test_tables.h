// Limit stencil tables for the evaluator tests, built here so that they test the evaluators
// alone: random tables (pooled runs of sources and weights, supports of 1-24 sources), and
// "corner" tables over a refined bench torus whose tangents run along each vertex's first face's
// edges, some made parallel or zero on purpose (the degenerate fallback). Also the plain
// reference loop.
#pragma once

#include <vector>

#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/osd/buffer_descriptor.h>

namespace quadtri::test {

// numStencils stencils over numSources sources; position weights sum to 1, tangent weights to
// 0; about a third of the stencils read an earlier one's run of sources (so offsets are not
// monotonic; runs are unsorted and may repeat a source), and about a third share a weight run
// with an earlier one.
LimitStencilTable randomLimitTable(int numStencils, int numSources, unsigned seed);

// A refined torus level: its 3-float positions (packed), its MeshNormalTable and a table over
// its own vertices. Stencil v: position = vertex v, dU = (next corner - v), dV = (previous
// corner - v) of v's first face, except: v % 7 == 3 has dV = 2 dU, v % 11 == 5 has dU = dV = 0.
struct CornerLevel {
    std::vector<float> positions;
    MeshNormalTable meshNormals;
    LimitStencilTable table;
};
CornerLevel cornerLevel(int level);
bool isDegenerateCorner(int v);

// The plain loop over the table's entries in the order the kernel documents (tangents relative to
// the stencil's first source), in float (what every evaluator must reproduce) or double (the
// exact value).
template <class Real>
void referenceLimit(const LimitStencilTable& t, const std::vector<float>& src, const BufferDescriptor& d,
                    std::vector<Real>& position, std::vector<Real>& du, std::vector<Real>& dv);

}  // namespace quadtri::test
