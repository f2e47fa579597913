// What the updates of tables over the control vertices share (docs/edits.md, "Limit tables"):
// which stencils over the control vertices an edit changed, level by level, and those stencils
// composed again directly.
#pragma once

#include <cstdint>
#include <vector>

#include <quadtri/far/refiner.h>
#include <quadtri/far/tag_edits.h>
#include <quadtri/far/topology.h>
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// Per vertex of level L (>= 1), whether its stencil over the control vertices changed with the
// edit `report` describes: its own per-level stencil did, or it reads a vertex of level L - 1
// whose composed stencil did, and so on up to level 1. Readers are found among the children of
// the faces within the scheme's surfaceRings() of a changed vertex, and kept where their stencil
// reads one. The Refiner must hold levels 1..L's tables.
std::vector<std::uint8_t> composedChanges(const Refiner& refiner, int L, const EditReport& report);

// The stencils of level L's `vertices` (sorted) over the control vertices, composed in double as
// the Refiner composes them (level by level, each level's float table read as double), without
// the regular faces' templates.
StencilTableD composedRows(const Refiner& refiner, int L, const std::vector<int>& vertices);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
