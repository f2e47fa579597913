// Sharpness edits on a loaded cage: the `t crease` / `t corner` entries of its ObjMesh are what
// the viewer edits, so that the refiner rebuilt from the mesh and the file saved from it agree
// (docs/viewer.md).
#pragma once

#include <ostream>
#include <string>

#include "tools/obj_io.h"

namespace quadtri::view {

// The sharpness of edge (a, b) (0-based, either order) as the mesh's tags give it: the last
// `t crease` entry naming it, 0 without one.
float creaseSharpness(const io::ObjMesh& mesh, int a, int b);
float cornerSharpness(const io::ObjMesh& mesh, int vertex);
// Replaces every entry of the edge / vertex by one of `sharpness` (none at 0), so that the last
// word is the edit.
void setCreaseSharpness(io::ObjMesh& mesh, int a, int b, float sharpness);
void setCornerSharpness(io::ObjMesh& mesh, int vertex, float sharpness);

// The cage as OBJ with its tags: positions, UVs, faces (`f v/vt` with UVs), one `t crease 2/1`
// per crease, one `t corner 1/1` per corner, the holes and the interpolateboundary,
// creasemethod and smoothtriangles tags the mesh carries; readObj reads back the same mesh.
void writeCage(std::ostream& out, const io::ObjMesh& mesh);
// The same into `path` through a temporary file renamed over it (io::writeReplacing).
void writeCage(const std::string& path, const io::ObjMesh& mesh);

}  // namespace quadtri::view
