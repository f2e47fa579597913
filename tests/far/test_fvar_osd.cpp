// Face-varying refinement against OpenSubdiv: every shape of tests/meshes/osd with UVs (`vt`),
// catmark_* under catmull-clark, loop_* under loop, bilinear_* under bilinear, and the pure ones
// under the mixed schemes too (as test_osd_agreement), under each of the six
// FVarLinearInterpolation options, levels 1-3; the creased shapes also with synthetic UVs whose
// seams run through their creases, the chaikin shapes also under Chaikin decay: the refined UVs equal
// Far::PrimvarRefiner::InterpolateFaceVarying's, corner by corner. The two libraries number
// refined vertices, faces and values differently, so faces are matched by the positions of their
// corners (vertices matched by position first), then corners within the face by their vertex.
// Collapsed edges (catmull-clark keeps them) put two corners on one position: there every corner
// is compared as (position, UV) instead.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/far/fvar_osd_cases.h"
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

// Collapsed edges (`4 3 5 5`, kept as they are under catmull-clark) with UVs against OpenSubdiv,
// on collapsedEdgeMeshes (a collapsed edge's corners with one value and with two): every corner as
// (position, UV) is one of OpenSubdiv's and the other way round, in equal numbers.
TEST(FVarAgreementCollapsedEdges, CornersEqualOpenSubdivsAsPositionAndUV) {
    for (const io::ObjMesh& mesh : collapsedEdgeMeshes()) {
        for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
            SCOPED_TRACE(mesh.name + " " + toString(fvar));
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
                                 positions, {uvs.begin(), uvs.end()});
                const std::vector<CornerPoint> theirs = cornerPoints(osd.faceVerts[L], osd.faceValues[L], osd.positions[L],
                                                                     {osd.uvs[L].begin(), osd.uvs[L].end()});
                ASSERT_EQ(ours.size(), theirs.size());
                EXPECT_LE(farthestFromNearest(ours, theirs), 1e-5);
                EXPECT_LE(farthestFromNearest(theirs, ours), 1e-5);
            }
        }
    }
}

}  // namespace
}  // namespace quadtri::test
