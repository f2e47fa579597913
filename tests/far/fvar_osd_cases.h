// The face-varying agreement cases shared by test_fvar_osd (refined UVs) and test_fvar_limit_osd
// (limit UVs): every shape of tests/meshes/osd with UVs under its own scheme and the pure ones
// under the mixed schemes, each FVarLinearInterpolation option, the creased shapes also with
// synthetic seams through their creases, the chaikin shapes also under Chaikin decay; and the
// matching of our level's corners to OpenSubdiv's (faces by their corners' matched vertices).
#pragma once

#include <array>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <quadtri/far/level_faces.h>
#include <quadtri/far/options.h>
#include <quadtri/far/stencil_table.h>
#include "tests/osd_reference.h"
#include "tools/obj_io.h"

namespace quadtri::test {

struct FVarCase {
    std::string shape;
    // The shape's own UVs, or replaced by a seam along every edge (perFaceUVs) or by two charts
    // (splitUVs).
    enum class UVs { Own, PerFace, Split } uvs = UVs::Own;
    bool chaikin = false;  // Chaikin creases whatever the shape's tag says
    OsdScheme reference = OsdScheme::Catmark;
    Scheme ours = Scheme::CatmullClark;
    FVarLinearInterpolation fvar = FVarLinearInterpolation::CornersPlus1;
};

std::ostream& operator<<(std::ostream& os, const FVarCase& c);
std::vector<FVarCase> fvarCases();
std::string caseName(const testing::TestParamInfo<FVarCase>& info);

// The case's mesh (its UVs replaced as the case asks) and options (the file's tags applied).
io::ObjMesh meshOf(const FVarCase& c);
Options optionsOf(const FVarCase& c, const io::ObjMesh& mesh);

// `width`-float data of level L from level L - 1's through one table (a plain loop in float).
std::vector<float> applyTable(const StencilTable& table, const std::vector<float>& src, int width);

// The UV range tolerances are relative to: the larger of the UVs' extent and magnitude.
double rangeOf(const std::vector<float>& uvs);

// For every corner of our level (faces' corner order), OpenSubdiv's value at the same corner:
// faces matched by their corners' vertices (`ourToReference`, vertices matched by position), then
// corners within the face by their vertex. Adds a gtest failure and returns an empty vector for a
// face OpenSubdiv does not have.
std::vector<int> referenceValueOfCorners(const LevelFaces& faces, const std::vector<int>& ourToReference,
                                         const std::vector<int>& referenceOffsets,
                                         const std::vector<int>& referenceVerts,
                                         const std::vector<int>& referenceValues);

// Collapsed edges (`4 3 5 5`) with UVs, for catmull-clark, which keeps them: catmark_nonman_quadpole8
// with a value per vertex (the planar projection: the collapsed edges' corners share a value) and
// with a value per corner (they differ), and a 2 x 2 grid with one collapsed quad and UVs per vertex.
std::vector<io::ObjMesh> collapsedEdgeMeshes();

// Every corner of a level as (position, UV). A collapsed edge's corners share a position, so
// faces cannot be matched by their corners' positions there: these are compared as sets instead.
using CornerPoint = std::array<double, 5>;
std::vector<CornerPoint> cornerPoints(const std::vector<int>& verts, const std::vector<int>& values,
                                      const std::vector<float>& positions, const std::vector<double>& uvs);
// The largest distance (max norm) from a point of `a` to its nearest in `b` (brute force: for a
// few thousand points).
double farthestFromNearest(const std::vector<CornerPoint>& a, const std::vector<CornerPoint>& b);

}  // namespace quadtri::test
