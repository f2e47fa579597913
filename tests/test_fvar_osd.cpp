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
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "tests/osd_reference.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

constexpr int kMaxLevel = 3;
// Relative to the UV range: the larger of the control UVs' extent and magnitude (both libraries
// refine in float, and float UVs of magnitude m round by m * 2^-24 at every step).
constexpr double kUVTolerance = 1e-6;
constexpr double kPositionTolerance = 1e-5;  // relative to the control mesh's diagonal

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

std::ostream& operator<<(std::ostream& os, const FVarCase& c) {
    return os << c.shape << (c.chaikin ? " chaikin" : "") << (c.uvs == FVarCase::UVs::PerFace ? " per-face UVs" : c.uvs == FVarCase::UVs::Split ? " split UVs" : "") << " (" << toString(c.ours) << ", " << toString(c.fvar) << ")";
}

bool hasUVCorners(const std::filesystem::path& path) {
    std::ifstream in(path);
    bool vt = false, corner = false;
    for (std::string line; std::getline(in, line);) {
        vt = vt || line.rfind("vt ", 0) == 0;
        if (line.rfind("f ", 0) == 0) corner = corner || line.find('/') != std::string::npos;
    }
    return vt && corner;
}

// Whether the shape tags creases or corners.
bool hasSharpness(const std::string& path) {
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);)
        if (line.rfind("t crease", 0) == 0 || line.rfind("t corner", 0) == 0) return true;
    return false;
}

// The shape's own scheme, then the mixed schemes where test_osd_agreement has them equal
// OpenSubdiv: shapes without a triangle (catmark) or a collapsed edge (both).
std::vector<Scheme> schemesOf(const std::string& shape, Scheme own) {
    const io::ObjMesh mesh = io::readObj(meshPath("osd/" + shape + ".obj"));
    bool triangles = false, collapsed = false;
    for (int f = 0, corner = 0; f < mesh.numFaces(); corner += mesh.faceSizes[f++]) {
        triangles = triangles || mesh.faceSizes[f] == 3;
        for (int i = 0; i < mesh.faceSizes[f]; ++i)
            collapsed = collapsed || mesh.faceVerts[corner + i] == mesh.faceVerts[corner + (i + 1) % mesh.faceSizes[f]];
    }
    std::vector<Scheme> schemes{own};
    if (own == Scheme::CatmullClark && !triangles && !collapsed)
        schemes.insert(schemes.end(), {Scheme::StamLoop, Scheme::SchaeferWarren, Scheme::CatmarkButterfly});
    if (own == Scheme::Loop && !collapsed) schemes.insert(schemes.end(), {Scheme::StamLoop, Scheme::SchaeferWarren});
    return schemes;
}

std::vector<FVarCase> fvarCases() {
    std::vector<std::string> shapes;
    for (const auto& entry : std::filesystem::directory_iterator(meshPath("osd")))
        if (entry.path().extension() == ".obj" && hasUVCorners(entry.path())) shapes.push_back(entry.path().stem().string());
    std::sort(shapes.begin(), shapes.end());
    std::vector<FVarCase> cases;
    for (const std::string& shape : shapes) {
        FVarCase c;
        c.shape = shape;
        if (shape.rfind("catmark_", 0) == 0) {
            c.reference = OsdScheme::Catmark;
            c.ours = Scheme::CatmullClark;
        } else if (shape.rfind("loop_", 0) == 0) {
            c.reference = OsdScheme::Loop;
            c.ours = Scheme::Loop;
        } else if (shape.rfind("bilinear_", 0) == 0) {
            c.reference = OsdScheme::Bilinear;
            c.ours = Scheme::Bilinear;
        } else {
            continue;
        }
        const Scheme own = c.ours;
        for (Scheme scheme : schemesOf(shape, own)) {
            c.ours = scheme;
            for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
                c.fvar = fvar;
                cases.push_back(c);
            }
        }
        if (hasSharpness(meshPath("osd/" + shape + ".obj"))) {
            c.ours = own;
            // The chaikin shapes' tags ask for uniform decay ("normal"): Chaikin's too.
            for (bool chaikin : {false, true}) {
                if (chaikin && shape.find("chaikin") == std::string::npos) continue;
                c.chaikin = chaikin;
                for (FVarCase::UVs uvs : {FVarCase::UVs::Own, FVarCase::UVs::PerFace, FVarCase::UVs::Split}) {
                    if (uvs == FVarCase::UVs::Own && !chaikin) continue;
                    c.uvs = uvs;
                    for (FVarLinearInterpolation fvar : allFVarLinearInterpolations()) {
                        c.fvar = fvar;
                        cases.push_back(c);
                    }
                }
            }
        }
    }
    return cases;
}

std::string caseName(const testing::TestParamInfo<FVarCase>& info) {
    return testNameOf(info.param.shape + (info.param.chaikin ? "_chaikin" : "") + (info.param.uvs == FVarCase::UVs::PerFace ? "_per_face" : info.param.uvs == FVarCase::UVs::Split ? "_split" : "") + "_" + toString(info.param.ours) + "_" +
                      toString(info.param.fvar));
}

// `width`-float data of level L from level L - 1's through one table.
std::vector<float> apply(const StencilTable& table, const std::vector<float>& src, int width) {
    std::vector<float> dst(std::size_t(table.numStencils()) * width, 0.0f);
    for (int i = 0; i < table.numStencils(); ++i) {
        const float* w = table.weightsOf(i);
        for (int k = 0; k < table.size(i); ++k)
            for (int c = 0; c < width; ++c)
                dst[std::size_t(i) * width + c] += w[k] * src[std::size_t(table.indices[table.offsets[i] + k]) * width + c];
    }
    return dst;
}

double rangeOf(const std::vector<float>& uvs) {
    double range = 0;
    for (int c = 0; c < 2; ++c) {
        double lo = 1e300, hi = -1e300;
        for (std::size_t i = c; i < uvs.size(); i += 2) {
            lo = std::min(lo, double(uvs[i]));
            hi = std::max(hi, double(uvs[i]));
        }
        range = std::max({range, hi - lo, std::fabs(lo), std::fabs(hi)});
    }
    return range > 0 ? range : 1.0;
}

// Every face its own values, each corner's UV a linear map of its vertex's position: every edge is a seam and every
// vertex has as many values as faces (junctions, darts, corners and semi-sharp spans everywhere).
void perFaceUVs(io::ObjMesh& mesh) {
    mesh.uvs.clear();
    mesh.faceUVs.clear();
    for (int v : mesh.faceVerts) {
        mesh.faceUVs.push_back(mesh.numUVs());
        const float* p = &mesh.positions[3 * std::size_t(v)];
        mesh.uvs.push_back(p[0] + 0.5f * p[1] + 0.01f * float(mesh.faceUVs.size() % 7));
        mesh.uvs.push_back(p[2] - 0.3f * p[1]);
    }
}

// Two charts, each corner's UV a linear map of its vertex's position (shifted in the second chart): faces whose
// centroid has x below the middle of the bounding box, and the others. The seam between them runs
// through the mesh, across its creases, so that seam vertices keep sharp edges on both sides.
void splitUVs(io::ObjMesh& mesh) {
    float lo = 1e30f, hi = -1e30f;
    for (std::size_t i = 0; i < mesh.positions.size(); i += 3) {
        lo = std::min(lo, mesh.positions[i]);
        hi = std::max(hi, mesh.positions[i]);
    }
    const float middle = 0.5f * (lo + hi) + 0.01f * (hi - lo);
    mesh.uvs.clear();
    mesh.faceUVs.clear();
    for (int v = 0; v < 2 * mesh.numVertices(); ++v) {
        const int p = v % mesh.numVertices();
        const float* x = &mesh.positions[3 * std::size_t(p)];
        mesh.uvs.push_back(x[0] + 0.5f * x[1] + (v >= mesh.numVertices() ? 0.25f : 0.0f));
        mesh.uvs.push_back(x[2] - 0.3f * x[1]);
    }
    for (int f = 0, b = 0; f < mesh.numFaces(); b += mesh.faceSizes[f++]) {
        float x = 0;
        for (int k = 0; k < mesh.faceSizes[f]; ++k) x += mesh.positions[3 * std::size_t(mesh.faceVerts[b + k])];
        const int chart = x / float(mesh.faceSizes[f]) < middle ? 0 : mesh.numVertices();
        for (int k = 0; k < mesh.faceSizes[f]; ++k) mesh.faceUVs.push_back(mesh.faceVerts[b + k] + chart);
    }
}

class FVarAgreement : public testing::TestWithParam<FVarCase> {};

TEST_P(FVarAgreement, RefinedUVsEqualOpenSubdivCornerByCorner) {
    const FVarCase& c = GetParam();
    io::ObjMesh mesh = io::readObj(meshPath("osd/" + c.shape + ".obj"));
    if (c.uvs == FVarCase::UVs::PerFace) perFaceUVs(mesh);
    if (c.uvs == FVarCase::UVs::Split) splitUVs(mesh);
    ASSERT_TRUE(mesh.hasUVs());
    Options options;
    options.scheme = c.ours;
    options.fvarLinearInterpolation = c.fvar;
    options = mesh.applyTags(options);
    if (c.chaikin) options.creaseMethod = CreaseMethod::Chaikin;
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
        positions = apply(refiner.levelStencils(L), positions, 3);
        uvs = apply(refiner.fvarLevelStencils(0, L), uvs, 2);
        ASSERT_EQ(int(uvs.size() / 2), refiner.numFVarValues(0, L));
        const LevelFaces faces = refiner.faces(L);
        ASSERT_EQ(faces.numFaces(), int(osd.faceOffsets[L].size()) - 1);
        const PositionMatch match = matchPositions(positions, osd.positions[L], diagonal, kPositionTolerance);
        ASSERT_TRUE(match.countsEqual && match.outliers.empty() && match.numCollisions == 0)
            << "refined vertices do not match OpenSubdiv's: worst " << match.maxRelative();
        // OpenSubdiv's faces by their (sorted) vertices.
        std::map<std::vector<int>, int> osdFaceOf;
        for (int g = 0; g + 1 < int(osd.faceOffsets[L].size()); ++g) {
            std::vector<int> key(osd.faceVerts[L].begin() + osd.faceOffsets[L][g],
                                 osd.faceVerts[L].begin() + osd.faceOffsets[L][g + 1]);
            std::sort(key.begin(), key.end());
            osdFaceOf[key] = g;
        }
        int failures = 0;
        for (int f = 0; f < faces.numFaces(); ++f) {
            const IndexSpan corners = faces.verticesOfFace(f);
            const IndexSpan values = refiner.fvarValuesOfFace(0, L, f);
            ASSERT_EQ(values.size(), corners.size());
            std::vector<int> key;
            for (int v : corners) key.push_back(match.ourToReference[std::size_t(v)]);
            std::vector<int> sorted = key;
            std::sort(sorted.begin(), sorted.end());
            const auto found = osdFaceOf.find(sorted);
            ASSERT_NE(found, osdFaceOf.end()) << "face " << f << " has no OpenSubdiv face with its corners";
            const int g = found->second, b = osd.faceOffsets[L][g];
            for (int k = 0; k < corners.size(); ++k) {
                int j = 0;
                while (osd.faceVerts[L][std::size_t(b + j)] != key[std::size_t(k)]) ++j;
                const int ours = values[k], theirs = osd.faceValues[L][std::size_t(b + j)];
                for (int axis = 0; axis < 2; ++axis) {
                    const double error = std::fabs(double(uvs[2 * std::size_t(ours) + axis]) -
                                                   double(osd.uvs[L][2 * std::size_t(theirs) + axis])) /
                                         extent;
                    worst = std::max(worst, error);
                    if (error > kUVTolerance && failures++ < 5)
                        ADD_FAILURE() << "face " << f << " corner " << k << " (vertex " << corners[k] << ", value "
                                      << ours << "): " << uvs[2 * std::size_t(ours) + axis] << " against OpenSubdiv's "
                                      << osd.uvs[L][2 * std::size_t(theirs) + axis] << " (axis " << axis << ")";
                }
            }
        }
        EXPECT_EQ(failures, 0) << failures << " corner values differ from OpenSubdiv's";
    }
    RecordProperty("worst_relative_uv_error", std::to_string(worst));
    std::printf("fvar-osd %s %s %s worst %.3g\n", c.shape.c_str(), toString(c.ours), toString(c.fvar), worst);
}

INSTANTIATE_TEST_SUITE_P(OsdShapes, FVarAgreement, testing::ValuesIn(fvarCases()), caseName);

}  // namespace
}  // namespace quadtri::test
