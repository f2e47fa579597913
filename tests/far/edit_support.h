// What the edit tests share: a mesh with an edit's tags added as its file would carry them, a
// Refiner built from it, random edits.
#pragma once

#include <memory>
#include <random>

#include <quadtri/far/refiner.h>

#include "tools/obj_io.h"

namespace quadtri::test {

// `mesh` with the edits' tags added as its file would carry them (the last entry of an item
// wins, as in a descriptor; a hole edit replaces the face's entry).
void addTags(io::ObjMesh& mesh, const TagEdits& edits);

// A Refiner of `mesh` (its UVs as channel 0 where it has them) refined to `levels` in full.
std::unique_ptr<Refiner> build(const io::ObjMesh& mesh, const Options& options, int levels);

// `scheme` with the mesh file's tags applied.
Options optionsOf(const io::ObjMesh& mesh, Scheme scheme);
// build(mesh, optionsOf(mesh, scheme), levels), or null where the scheme refuses the mesh (loop
// and quads).
std::unique_ptr<Refiner> buildIfTaken(const io::ObjMesh& mesh, Scheme scheme, int levels);

// One to three creases on random edges, maybe a corner, with `holes` maybe a hole, sharpness
// from 0 to infinite.
TagEdits randomEdits(const Topology& level0, std::mt19937& random, bool holes);

}  // namespace quadtri::test
