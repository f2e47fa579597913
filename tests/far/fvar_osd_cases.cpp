#include "tests/far/fvar_osd_cases.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "tests/test_support.h"

namespace quadtri::test {

namespace {

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

}  // namespace

std::ostream& operator<<(std::ostream& os, const FVarCase& c) {
    return os << c.shape << (c.chaikin ? " chaikin" : "") << (c.uvs == FVarCase::UVs::PerFace ? " per-face UVs" : c.uvs == FVarCase::UVs::Split ? " split UVs" : "") << " (" << toString(c.ours) << ", " << toString(c.fvar) << ")";
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

io::ObjMesh meshOf(const FVarCase& c) {
    io::ObjMesh mesh = io::readObj(meshPath("osd/" + c.shape + ".obj"));
    if (c.uvs == FVarCase::UVs::PerFace) perFaceUVs(mesh);
    if (c.uvs == FVarCase::UVs::Split) splitUVs(mesh);
    return mesh;
}

Options optionsOf(const FVarCase& c, const io::ObjMesh& mesh) {
    Options options;
    options.scheme = c.ours;
    options.fvarLinearInterpolation = c.fvar;
    options = mesh.applyTags(options);
    if (c.chaikin) options.creaseMethod = CreaseMethod::Chaikin;
    return options;
}

std::vector<int> referenceValueOfCorners(const LevelFaces& faces, const std::vector<int>& ourToReference,
                                         const std::vector<int>& referenceOffsets,
                                         const std::vector<int>& referenceVerts,
                                         const std::vector<int>& referenceValues) {
    // OpenSubdiv's faces by their (sorted) vertices.
    std::map<std::vector<int>, int> referenceFaceOf;
    for (int g = 0; g + 1 < int(referenceOffsets.size()); ++g) {
        std::vector<int> key(referenceVerts.begin() + referenceOffsets[g], referenceVerts.begin() + referenceOffsets[g + 1]);
        std::sort(key.begin(), key.end());
        referenceFaceOf[key] = g;
    }
    std::vector<int> out;
    for (int f = 0; f < faces.numFaces(); ++f) {
        const IndexSpan corners = faces.verticesOfFace(f);
        std::vector<int> key;
        for (int v : corners) key.push_back(ourToReference[std::size_t(v)]);
        std::vector<int> sorted = key;
        std::sort(sorted.begin(), sorted.end());
        const auto found = referenceFaceOf.find(sorted);
        if (found == referenceFaceOf.end()) {
            ADD_FAILURE() << "face " << f << " has no OpenSubdiv face with its corners";
            return {};
        }
        const int b = referenceOffsets[found->second];
        for (int k = 0; k < corners.size(); ++k) {
            int j = 0;
            while (referenceVerts[std::size_t(b + j)] != key[std::size_t(k)]) ++j;
            out.push_back(referenceValues[std::size_t(b + j)]);
        }
    }
    return out;
}

std::vector<float> applyTable(const StencilTable& table, const std::vector<float>& src, int width) {
    std::vector<float> dst(std::size_t(table.numStencils()) * width, 0.0f);
    for (int i = 0; i < table.numStencils(); ++i) {
        const float* w = table.weightsOf(i);
        for (int k = 0; k < table.size(i); ++k)
            for (int c = 0; c < width; ++c)
                dst[std::size_t(i) * width + c] += w[k] * src[std::size_t(table.indices[table.offsets[i] + k]) * width + c];
    }
    return dst;
}

std::vector<io::ObjMesh> collapsedEdgeMeshes() {
    const io::ObjMesh pole = io::readObj(meshPath("osd/catmark_nonman_quadpole8.obj"));
    io::ObjMesh grid;
    grid.name = "grid with a collapsed quad";
    grid.positions = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0.3f, 2, 1, 0, 0, 2, 0, 1, 2, 0, 2, 2, 0};
    grid.faceSizes = {4, 4, 4, 4};
    grid.faceVerts = {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 8};
    std::vector<io::ObjMesh> meshes{pole, pole, grid};
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        io::ObjMesh& mesh = meshes[i];
        mesh.uvs.clear();
        mesh.faceUVs.clear();
        const int down = i == 2 ? 1 : 2;  // the pole's axis is y, the grid's z
        if (i == 1) {  // a value per corner: its vertex's projection moved a little
            mesh.name += " per-corner UVs";
            for (int v : mesh.faceVerts) {
                mesh.faceUVs.push_back(mesh.numUVs());
                mesh.uvs.push_back(mesh.positions[3 * std::size_t(v)] + 0.01f * float(mesh.faceUVs.size() % 5));
                mesh.uvs.push_back(mesh.positions[3 * std::size_t(v) + down] - 0.02f * float(mesh.faceUVs.size() % 3));
            }
        } else {
            for (int v = 0; v < mesh.numVertices(); ++v) {
                mesh.uvs.push_back(mesh.positions[3 * std::size_t(v)]);
                mesh.uvs.push_back(mesh.positions[3 * std::size_t(v) + down]);
            }
            mesh.faceUVs = mesh.faceVerts;
        }
    }
    return meshes;
}

std::vector<CornerPoint> cornerPoints(const std::vector<int>& verts, const std::vector<int>& values,
                                      const std::vector<float>& positions, const std::vector<double>& uvs) {
    std::vector<CornerPoint> out;
    for (std::size_t k = 0; k < verts.size(); ++k) {
        const float* p = &positions[3 * std::size_t(verts[k])];
        const double* t = &uvs[2 * std::size_t(values[k])];
        out.push_back({p[0], p[1], p[2], t[0], t[1]});
    }
    return out;
}

double farthestFromNearest(const std::vector<CornerPoint>& a, const std::vector<CornerPoint>& b) {
    double worst = 0;
    for (const CornerPoint& x : a) {
        double nearest = 1e300;
        for (const CornerPoint& y : b) {
            double d = 0;
            for (std::size_t i = 0; i < x.size(); ++i) d = std::max(d, std::fabs(x[i] - y[i]));
            nearest = std::min(nearest, d);
        }
        worst = std::max(worst, nearest);
    }
    return worst;
}

}  // namespace quadtri::test
