// Edits at interactive speed (docs/edits.md): one edit of a cage's tags (an edge's sharpness, ten
// edges along a loop, a corner, a hole) applied in place by Refiner::applyEdits and
// LimitTableUpdate to what the frame's default route reads (the factorized limit table), against
// building the Refiner and that table again; OpenSubdiv's rebuild of its tables for the same cage
// beside it (bench/opensubdiv/osd_edit_case.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bench/figures.h"
#include "bench/opensubdiv/osd_case.h"
#include "bench/quadtri/surface_case.h"

namespace quadtri::bench {

enum class EditKind { Edge, EdgeLoop, Corner, Hole };
const char* toString(EditKind kind);  // "edge", "edge_loop", "corner", "hole"

// The edit, in the cage's own vertex and face numbering: creases (2 vertices each) or a corner set
// to `sharpness`, or a face made a hole.
struct CageEdit {
    std::vector<int> creasePairs;
    int corner = -1;
    int hole = -1;
    float sharpness = 2.5f;
};

// The edit of `kind` on `cage`: the interior edge (and loop, and vertex, and face) nearest the
// middle of its numbering, so that every run edits the same items.
CageEdit chooseEdit(const SurfaceCage& cage, EditKind kind);

// `cage` with the edit's tags, for a Refiner or OpenSubdiv built afresh.
SurfaceCage withEdit(const SurfaceCage& cage, const CageEdit& edit);

// With `osd`, OpenSubdiv's rebuild under that scheme beside it.
EditCaseResult runEditCase(const SurfaceCage& cage, const std::string& scheme, int level, EditKind kind, int reps,
                           std::optional<OsdScheme> osd);

}  // namespace quadtri::bench
