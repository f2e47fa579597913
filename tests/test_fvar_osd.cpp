// Face-varying refinement against OpenSubdiv: every shape of tests/meshes/osd with UVs (`vt`),
// catmark_* under catmull-clark, loop_* under loop, bilinear_* under bilinear, and the pure ones
// under the mixed schemes too (as test_osd_agreement), under each of the six
// FVarLinearInterpolation options, levels 1-3; the creased shapes also with synthetic UVs whose
// seams run through their creases, the chaikin shapes also under Chaikin decay: the refined UVs equal
// Far::PrimvarRefiner::InterpolateFaceVarying's, corner by corner. The two libraries number
// refined vertices, faces and values differently, so faces are matched by the positions of their
// corners (vertices matched by position first), then corners within the face by their vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/fvar_osd_cases.h"
#include "tests/osd_reference.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

constexpr int kMaxLevel = 3;
// Relative to the UV range: the larger of the control UVs' extent and magnitude (both libraries
// refine in float, and float UVs of magnitude m round by m * 2^-24 at every step).
constexpr double kUVTolerance = 1e-6;
constexpr double kPositionTolerance = 1e-5;  // relative to the control mesh's diagonal


class FVarAgreement : public testing::TestWithParam<FVarCase> {};

TEST_P(FVarAgreement, RefinedUVsEqualOpenSubdivCornerByCorner) {
    const FVarCase& c = GetParam();
    const io::ObjMesh mesh = meshOf(c);
    ASSERT_TRUE(mesh.hasUVs());
    const Options options = optionsOf(c, mesh);
    FVarChannel uvChannel;
    Refiner refiner(mesh.descriptor(uvChannel), options);
    ASSERT_EQ(refiner.numFVarChannels(), 1);
    refiner.refineUniform(kMaxLevel);
    const OsdFaceVarying osd =
        osdFaceVarying(mesh, c.reference, options.boundary, options.creaseMethod, c.fvar, kMaxLevel);

    const double diagonal = boundingBoxDiagonal(mesh.positions);
    const double extent = rangeOf(mesh.uvs);
    std::vector<float> positions = mesh.positions, uvs = mesh.uvs;
    double worst = 0;
    for (int L = 1; L <= kMaxLevel; ++L) {
        SCOPED_TRACE("level " + std::to_string(L));
        positions = applyTable(refiner.levelStencils(L), positions, 3);
        uvs = applyTable(refiner.fvarLevelStencils(0, L), uvs, 2);
        ASSERT_EQ(int(uvs.size() / 2), refiner.numFVarValues(0, L));
        const LevelFaces faces = refiner.faces(L);
        ASSERT_EQ(faces.numFaces(), int(osd.faceOffsets[L].size()) - 1);
        const PositionMatch match = matchPositions(positions, osd.positions[L], diagonal, kPositionTolerance);
        ASSERT_TRUE(match.countsEqual && match.outliers.empty() && match.numCollisions == 0)
            << "refined vertices do not match OpenSubdiv's: worst " << match.maxRelative();
        const std::vector<int> theirsOf = referenceValueOfCorners(faces, match.ourToReference, osd.faceOffsets[L],
                                                                  osd.faceVerts[L], osd.faceValues[L]);
        ASSERT_EQ(int(theirsOf.size()), faces.numCorners());
        const IndexSpan values = refiner.fvarValues(0, L);
        int failures = 0;
        for (int k = 0; k < faces.numCorners(); ++k) {
            const int ours = values[k], theirs = theirsOf[std::size_t(k)];
            for (int axis = 0; axis < 2; ++axis) {
                const double error = std::fabs(double(uvs[2 * std::size_t(ours) + axis]) -
                                               double(osd.uvs[L][2 * std::size_t(theirs) + axis])) /
                                     extent;
                worst = std::max(worst, error);
                if (error > kUVTolerance && failures++ < 5)
                    ADD_FAILURE() << "corner " << k << " (vertex " << faces.vertices()[k] << ", value " << ours
                                  << "): " << uvs[2 * std::size_t(ours) + axis] << " against OpenSubdiv's "
                                  << osd.uvs[L][2 * std::size_t(theirs) + axis] << " (axis " << axis << ")";
            }
        }
        EXPECT_EQ(failures, 0) << failures << " corner values differ from OpenSubdiv's";
    }
    RecordProperty("worst_relative_uv_error", std::to_string(worst));
    std::printf("fvar-osd %s %s %s worst %.3g\n", c.shape.c_str(), toString(c.ours), toString(c.fvar), worst);
}

INSTANTIATE_TEST_SUITE_P(OsdShapes, FVarAgreement, testing::ValuesIn(fvarCases()), caseName);

// Every corner of a level as (position, UV), 5 doubles.
using CornerPoint = std::array<double, 5>;
std::vector<CornerPoint> cornerPoints(const std::vector<int>& verts, const std::vector<int>& values,
                                      const std::vector<float>& positions, const std::vector<float>& uvs) {
    std::vector<CornerPoint> out;
    for (std::size_t k = 0; k < verts.size(); ++k) {
        const float* p = &positions[3 * std::size_t(verts[k])];
        const float* t = &uvs[2 * std::size_t(values[k])];
        out.push_back({p[0], p[1], p[2], t[0], t[1]});
    }
    return out;
}

// The largest distance from a point of `a` to its nearest in `b` (brute force: a few thousand).
double farthestFromNearest(const std::vector<CornerPoint>& a, const std::vector<CornerPoint>& b) {
    double worst = 0;
    for (const CornerPoint& x : a) {
        double nearest = 1e300;
        for (const CornerPoint& y : b) {
            double d = 0;
            for (int i = 0; i < 5; ++i) d = std::max(d, std::fabs(x[std::size_t(i)] - y[std::size_t(i)]));
            nearest = std::min(nearest, d);
        }
        worst = std::max(worst, nearest);
    }
    return worst;
}

// Collapsed edges (`4 3 5 5`, kept as they are under catmull-clark) with UVs, against OpenSubdiv:
// a collapsed edge's corners with one value (UVs per vertex, the pole's planar projection, and a
// 2 x 2 grid with one collapsed quad) and with two (a value per corner). A level's corners sit by
// twos on one position there (the collapsed edge's point is its vertex's), so the position
// matching of the shapes' cases cannot tell them apart: instead every corner as (position, UV)
// must be one of OpenSubdiv's and the other way round, in equal numbers.
TEST(FVarAgreementCollapsedEdges, CornersEqualOpenSubdivsAsPositionAndUV) {
    io::ObjMesh pole = io::readObj(meshPath("osd/catmark_nonman_quadpole8.obj"));
    io::ObjMesh grid;
    grid.positions = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0.3f, 2, 1, 0, 0, 2, 0, 1, 2, 0, 2, 2, 0};
    grid.faceSizes = {4, 4, 4, 4};
    grid.faceVerts = {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 8};
    for (int variant = 0; variant < 3; ++variant) {
        io::ObjMesh mesh = variant == 2 ? grid : pole;
        mesh.uvs.clear();
        mesh.faceUVs.clear();
        if (variant == 1) {  // a value per corner, each its vertex's projection moved a little
            for (int v : mesh.faceVerts) {
                mesh.faceUVs.push_back(mesh.numUVs());
                mesh.uvs.push_back(mesh.positions[3 * std::size_t(v)] + 0.01f * float(mesh.faceUVs.size() % 5));
                mesh.uvs.push_back(mesh.positions[3 * std::size_t(v) + 2] - 0.02f * float(mesh.faceUVs.size() % 3));
            }
        } else {  // a value per vertex: the planar projection
            for (int v = 0; v < mesh.numVertices(); ++v) {
                mesh.uvs.push_back(mesh.positions[3 * std::size_t(v)]);
                mesh.uvs.push_back(mesh.positions[3 * std::size_t(v) + (variant == 2 ? 1 : 2)]);
            }
            mesh.faceUVs = mesh.faceVerts;
        }
        for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
            SCOPED_TRACE("variant " + std::to_string(variant) + " " + toString(fvar));
            Options options;
            options.scheme = Scheme::CatmullClark;
            options.fvarLinearInterpolation = fvar;
            FVarChannel uvChannel;
            Refiner refiner(mesh.descriptor(uvChannel), options);
            refiner.refineUniform(kMaxLevel);
            const OsdFaceVarying osd =
                osdFaceVarying(mesh, OsdScheme::Catmark, options.boundary, options.creaseMethod, fvar, kMaxLevel);
            std::vector<float> positions = mesh.positions, uvs = mesh.uvs;
            for (int L = 1; L <= kMaxLevel; ++L) {
                SCOPED_TRACE("level " + std::to_string(L));
                positions = applyTable(refiner.levelStencils(L), positions, 3);
                uvs = applyTable(refiner.fvarLevelStencils(0, L), uvs, 2);
                const LevelFaces faces = refiner.faces(L);
                const IndexSpan values = refiner.fvarValues(0, L);
                const std::vector<CornerPoint> ours =
                    cornerPoints({faces.vertices(), faces.vertices() + faces.numCorners()}, {values.begin(), values.end()},
                                 positions, uvs);
                const std::vector<CornerPoint> theirs = cornerPoints(osd.faceVerts[L], osd.faceValues[L], osd.positions[L], osd.uvs[L]);
                ASSERT_EQ(ours.size(), theirs.size());
                EXPECT_LE(farthestFromNearest(ours, theirs), 1e-5);
                EXPECT_LE(farthestFromNearest(theirs, ours), 1e-5);
            }
        }
    }
}

}  // namespace
}  // namespace quadtri::test
