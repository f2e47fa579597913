// Limit UVs against OpenSubdiv: the cases of test_fvar_osd (tests/far/fvar_osd_cases.h) but the
// bilinear ones, levels 0-3:
// our limit stencils of level L's values (Refiner::fvarLimitStencils) applied to level L's UVs
// equal Far::PrimvarRefinerReal<double>::LimitFaceVarying of OpenSubdiv's level L, corner by
// corner (faces matched by their corners' positions, as test_fvar_osd matches them).
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
// Relative to the UV range (tests/far/fvar_osd_cases.h, rangeOf): our levels' UVs are refined in
// float, OpenSubdiv's in double.
constexpr double kUVTolerance = 1e-6;
constexpr double kPositionTolerance = 1e-5;  // relative to the control mesh's diagonal


// The limit positions of 2-float data, in double.
std::vector<double> limitOf(const LimitStencilTable& table, const std::vector<float>& src) {
    std::vector<double> dst(2 * std::size_t(table.numStencils()), 0.0);
    for (int i = 0; i < table.numStencils(); ++i) {
        const int* sources = table.sourcesOf(i);
        const float* w = table.weightsOf(i);
        for (int k = 0; k < table.size(i); ++k)
            for (int c = 0; c < 2; ++c) dst[2 * std::size_t(i) + c] += double(w[3 * k]) * src[2 * std::size_t(sources[k]) + c];
    }
    return dst;
}

// Every level's limit UVs, the Refiner refined to that level and no further (its last level,
// faces only, as refineUniform leaves it) against OpenSubdiv's refined to the same level, corner
// by corner; and each level's table the same once the Refiner has refined past it. Returns the
// worst error relative to the UV range.
double expectLimitsAgree(const io::ObjMesh& mesh, const Options& options, OsdScheme reference) {
    FVarChannel uvChannel;
    Refiner refiner(mesh.descriptor(uvChannel), options);
    const double diagonal = boundingBoxDiagonal(mesh.positions);
    const double extent = rangeOf(mesh.uvs);
    std::vector<float> positions = mesh.positions, uvs = mesh.uvs;
    std::vector<LimitStencilTable> tables;
    double worst = 0;
    for (int L = 0; L <= kMaxLevel; ++L) {
        SCOPED_TRACE("level " + std::to_string(L));
        refiner.refineUniform(L);
        if (L > 0) {
            positions = applyTable(refiner.levelStencils(L), positions, 3);
            uvs = applyTable(refiner.fvarLevelStencils(0, L), uvs, 2);
        }
        tables.push_back(refiner.fvarLimitStencils(0, L));
        const LimitStencilTable& table = tables.back();
        EXPECT_EQ(table.numStencils(), refiner.numFVarValues(0, L));
        if (table.numStencils() != refiner.numFVarValues(0, L)) return worst;
        const std::vector<double> limit = limitOf(table, uvs);
        const OsdFaceVaryingLimit osd =
            osdFaceVaryingLimit(mesh, reference, options.boundary, options.creaseMethod, options.fvarLinearInterpolation, L);
        const LevelFaces faces = refiner.faces(L);
        const PositionMatch match = matchPositions(positions, osd.positions, diagonal, kPositionTolerance);
        EXPECT_TRUE(match.countsEqual && match.outliers.empty() && match.numCollisions == 0)
            << "refined vertices do not match OpenSubdiv's: worst " << match.maxRelative();
        if (!match.countsEqual || !match.outliers.empty() || match.numCollisions != 0) return worst;
        const std::vector<int> theirsOf =
            referenceValueOfCorners(faces, match.ourToReference, osd.faceOffsets, osd.faceVerts, osd.faceValues);
        if (int(theirsOf.size()) != faces.numCorners()) return worst;
        const IndexSpan values = refiner.fvarValues(0, L);
        // At level 0 a value given at two vertices has one stencil (the last vertex's, as
        // OpenSubdiv's last write): its corners at the other vertex are not compared.
        std::vector<int> vertexOf(std::size_t(refiner.numFVarValues(0, L)), -1);
        std::vector<char> shared(vertexOf.size(), 0);
        for (int k = 0; k < faces.numCorners() && L == 0; ++k) {
            int& v = vertexOf[std::size_t(values[k])];
            if (v >= 0 && v != faces.vertices()[k]) shared[std::size_t(values[k])] = 1;
            v = faces.vertices()[k];
        }
        int failures = 0;
        for (int k = 0; k < faces.numCorners(); ++k) {
            const int ours = values[k], theirs = theirsOf[std::size_t(k)];
            if (shared[std::size_t(ours)]) continue;
            for (int axis = 0; axis < 2; ++axis) {
                const double mine = limit[2 * std::size_t(ours) + axis], expected = osd.limit[2 * std::size_t(theirs) + axis];
                const double error = std::fabs(mine - expected) / extent;
                worst = std::max(worst, error);
                if (error > kUVTolerance && failures++ < 5)
                    ADD_FAILURE() << "corner " << k << " (vertex " << faces.vertices()[k] << ", value " << ours
                                  << "): limit " << mine << " against OpenSubdiv's " << expected << " (axis " << axis
                                  << "; refined " << uvs[2 * std::size_t(ours) + axis] << ", OpenSubdiv's "
                                  << osd.uvs[2 * std::size_t(theirs) + axis] << ")";
            }
        }
        EXPECT_EQ(failures, 0) << failures << " corner limits differ from OpenSubdiv's";
    }
    for (int L = 0; L < kMaxLevel; ++L) {
        const LimitStencilTable again = refiner.fvarLimitStencils(0, L);
        EXPECT_EQ(again.sizes, tables[std::size_t(L)].sizes) << "level " << L;
        EXPECT_EQ(again.weights, tables[std::size_t(L)].weights) << "level " << L;
    }
    return worst;
}

class FVarLimitAgreement : public testing::TestWithParam<FVarCase> {};

TEST_P(FVarLimitAgreement, LimitUVsEqualOpenSubdivCornerByCorner) {
    const FVarCase& c = GetParam();
    const io::ObjMesh mesh = meshOf(c);
    ASSERT_TRUE(mesh.hasUVs());
    const double worst = expectLimitsAgree(mesh, optionsOf(c, mesh), c.reference);
    RecordProperty("worst_relative_uv_error", std::to_string(worst));
    std::printf("fvar-limit-osd %s %s %s worst %.3g\n", caseName(testing::TestParamInfo<FVarCase>(c, 0)).c_str(),
                toString(c.ours), toString(c.fvar), worst);
}

// A 4 x 4 quad grid cut by a UV seam along the column x = 2 up to the middle vertex (2, 2), so
// that the vertices on it have two values; a semi-sharp edge inside one side's faces only makes
// that value semi-sharp and, under CornersPlus1 and CornersPlus2, the other one dependent on it:
// a corner for as long as the first stays semi-sharp (sharpness 2.5 here: through level 2).
io::ObjMesh dependentSeamGrid() {
    io::ObjMesh mesh;
    const int n = 4;
    auto vertex = [&](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) mesh.positions.insert(mesh.positions.end(), {float(i), float(j), 0.1f * float(i * j % 3)});
    // Values: one per vertex, and a second one for the seam's vertices (x = 2, y <= 2) on the right.
    // Curved in both directions, so that no mask reproduces another by linearity.
    auto uv = [&](float x, float y, float shift) {
        mesh.uvs.insert(mesh.uvs.end(), {0.2f * x + 0.03f * y * y + shift, 0.2f * y + 0.02f * x * x});
    };
    for (int v = 0; v < mesh.numVertices(); ++v) uv(mesh.positions[3 * v], mesh.positions[3 * v + 1], 0.0f);
    std::vector<int> second(std::size_t(mesh.numVertices()), -1);
    for (int j = 0; j <= 2; ++j) {
        second[std::size_t(vertex(2, j))] = mesh.numUVs();
        uv(2.0f, float(j), 0.5f);
    }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int corners[4] = {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
            mesh.faceSizes.push_back(4);
            for (int v : corners) {
                mesh.faceVerts.push_back(v);
                const bool right = i >= 2 && j < 2;
                mesh.faceUVs.push_back(right && second[std::size_t(v)] >= 0 ? second[std::size_t(v)] : v);
            }
        }
    // Semi-sharp edges inside the left side, ending at the seam's vertices.
    mesh.creasePairs = {vertex(1, 1), vertex(2, 1), vertex(1, 2), vertex(2, 2)};
    mesh.creaseSharpness = {2.5f, 1.5f};
    return mesh;
}

TEST(FVarLimitAgreement, DependentValuesAreCornersAsOpenSubdivTakesThem) {
    const io::ObjMesh mesh = dependentSeamGrid();
    for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
        SCOPED_TRACE(toString(fvar));
        Options options;
        options.fvarLinearInterpolation = fvar;
        const double worst = expectLimitsAgree(mesh, options, OsdScheme::Catmark);
        std::printf("fvar-limit-osd dependent-seam-grid %s worst %.3g\n", toString(fvar), worst);
    }
}

// Bilinear refinement never moves a value, so its limit is every value itself; OpenSubdiv's
// LimitFaceVarying gives bilinear seam values (tagged creases) the crease mask all the same
// (docs/face_varying.md, "Limit UVs"): test_fvar checks bilinear channels instead.
std::vector<FVarCase> limitCases() {
    std::vector<FVarCase> cases = fvarCases();
    cases.erase(std::remove_if(cases.begin(), cases.end(), [](const FVarCase& c) { return c.reference == OsdScheme::Bilinear; }),
                cases.end());
    return cases;
}

INSTANTIATE_TEST_SUITE_P(OsdShapes, FVarLimitAgreement, testing::ValuesIn(limitCases()), caseName);

// Collapsed edges under catmull-clark (collapsedEdgeMeshes, as test_fvar_osd): at levels 0-3 every
// corner as (level position, limit UV) is one of OpenSubdiv's and the other way round (a collapsed
// edge's corners share a position, so faces are not matched by their corners' positions).
TEST(FVarLimitAgreementCollapsedEdges, CornersEqualOpenSubdivsAsPositionAndLimitUV) {
    for (const io::ObjMesh& mesh : collapsedEdgeMeshes()) {
        for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
            SCOPED_TRACE(mesh.name + " " + toString(fvar));
            Options options;
            options.scheme = Scheme::CatmullClark;
            options.fvarLinearInterpolation = fvar;
            FVarChannel uvChannel;
            Refiner refiner(mesh.descriptor(uvChannel), options);
            refiner.refineUniform(kMaxLevel);
            std::vector<float> positions = mesh.positions, uvs = mesh.uvs;
            for (int L = 0; L <= kMaxLevel; ++L) {
                SCOPED_TRACE("level " + std::to_string(L));
                if (L > 0) {
                    positions = applyTable(refiner.levelStencils(L), positions, 3);
                    uvs = applyTable(refiner.fvarLevelStencils(0, L), uvs, 2);
                }
                const OsdFaceVaryingLimit osd =
                    osdFaceVaryingLimit(mesh, OsdScheme::Catmark, options.boundary, options.creaseMethod, fvar, L);
                const LevelFaces faces = refiner.faces(L);
                const IndexSpan values = refiner.fvarValues(0, L);
                const std::vector<CornerPoint> ours =
                    cornerPoints({faces.vertices(), faces.vertices() + faces.numCorners()}, {values.begin(), values.end()},
                                 positions, limitOf(refiner.fvarLimitStencils(0, L), uvs));
                const std::vector<CornerPoint> theirs = cornerPoints(osd.faceVerts, osd.faceValues, osd.positions, osd.limit);
                ASSERT_EQ(ours.size(), theirs.size());
                EXPECT_LE(farthestFromNearest(ours, theirs), 1e-5);
                EXPECT_LE(farthestFromNearest(theirs, ours), 1e-5);
            }
        }
    }
}

}  // namespace
}  // namespace quadtri::test
