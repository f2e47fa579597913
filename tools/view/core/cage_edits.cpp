#include "tools/view/core/cage_edits.h"

#include <cstdio>

namespace quadtri::view {

namespace {

bool sameEdge(const io::ObjMesh& mesh, std::size_t crease, int a, int b) {
    const int p = mesh.creasePairs[2 * crease], q = mesh.creasePairs[2 * crease + 1];
    return (p == a && q == b) || (p == b && q == a);
}

std::string number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(value));
    return text;
}

}  // namespace

float creaseSharpness(const io::ObjMesh& mesh, int a, int b) {
    float sharpness = 0.0f;
    for (std::size_t c = 0; c < mesh.creaseSharpness.size(); ++c)
        if (sameEdge(mesh, c, a, b)) sharpness = mesh.creaseSharpness[c];
    return sharpness;
}

float cornerSharpness(const io::ObjMesh& mesh, int vertex) {
    float sharpness = 0.0f;
    for (std::size_t c = 0; c < mesh.corners.size(); ++c)
        if (mesh.corners[c] == vertex) sharpness = mesh.cornerSharpness[c];
    return sharpness;
}

void setCreaseSharpness(io::ObjMesh& mesh, int a, int b, float sharpness) {
    std::size_t kept = 0;
    for (std::size_t c = 0; c < mesh.creaseSharpness.size(); ++c) {
        if (sameEdge(mesh, c, a, b)) continue;
        mesh.creasePairs[2 * kept] = mesh.creasePairs[2 * c];
        mesh.creasePairs[2 * kept + 1] = mesh.creasePairs[2 * c + 1];
        mesh.creaseSharpness[kept] = mesh.creaseSharpness[c];
        mesh.creaseLines[kept] = mesh.creaseLines[c];
        ++kept;
    }
    mesh.creasePairs.resize(2 * kept);
    mesh.creaseSharpness.resize(kept);
    mesh.creaseLines.resize(kept);
    if (sharpness <= 0.0f) return;
    mesh.creasePairs.push_back(a);
    mesh.creasePairs.push_back(b);
    mesh.creaseSharpness.push_back(sharpness);
    mesh.creaseLines.push_back(0);  // an edit, on no line of the file
}

void setCornerSharpness(io::ObjMesh& mesh, int vertex, float sharpness) {
    std::size_t kept = 0;
    for (std::size_t c = 0; c < mesh.corners.size(); ++c) {
        if (mesh.corners[c] == vertex) continue;
        mesh.corners[kept] = mesh.corners[c];
        mesh.cornerSharpness[kept] = mesh.cornerSharpness[c];
        mesh.cornerLines[kept] = mesh.cornerLines[c];
        ++kept;
    }
    mesh.corners.resize(kept);
    mesh.cornerSharpness.resize(kept);
    mesh.cornerLines.resize(kept);
    if (sharpness <= 0.0f) return;
    mesh.corners.push_back(vertex);
    mesh.cornerSharpness.push_back(sharpness);
    mesh.cornerLines.push_back(0);
}

void writeCage(std::ostream& out, const io::ObjMesh& mesh) {
    out << "# written by quadtri view\n";
    for (int v = 0; v < mesh.numVertices(); ++v)
        out << "v " << number(mesh.positions[3 * std::size_t(v)]) << ' ' << number(mesh.positions[3 * std::size_t(v) + 1])
            << ' ' << number(mesh.positions[3 * std::size_t(v) + 2]) << '\n';
    for (int t = 0; t < mesh.numUVs(); ++t)
        out << "vt " << number(mesh.uvs[2 * std::size_t(t)]) << ' ' << number(mesh.uvs[2 * std::size_t(t) + 1]) << '\n';
    std::size_t corner = 0;
    for (int size : mesh.faceSizes) {
        out << 'f';
        for (int k = 0; k < size; ++k, ++corner) {
            out << ' ' << mesh.faceVerts[corner] + 1;
            if (mesh.hasUVs()) out << '/' << mesh.faceUVs[corner] + 1;
        }
        out << '\n';
    }
    for (std::size_t c = 0; c < mesh.creaseSharpness.size(); ++c)
        out << "t crease 2/1/0 " << mesh.creasePairs[2 * c] << ' ' << mesh.creasePairs[2 * c + 1] << ' '
            << number(mesh.creaseSharpness[c]) << '\n';
    for (std::size_t c = 0; c < mesh.corners.size(); ++c)
        out << "t corner 1/1/0 " << mesh.corners[c] << ' ' << number(mesh.cornerSharpness[c]) << '\n';
    if (!mesh.holes.empty()) {
        out << "t hole " << mesh.holes.size() << "/0/0";
        for (int h : mesh.holes) out << ' ' << h;
        out << '\n';
    }
    if (mesh.boundary)
        out << "t interpolateboundary 1/0/0 "
            << (*mesh.boundary == BoundaryInterpolation::None ? 0 : *mesh.boundary == BoundaryInterpolation::EdgeAndCorner ? 1 : 2)
            << '\n';
    if (mesh.creaseMethod)
        out << "t creasemethod 0/0/1 " << (*mesh.creaseMethod == CreaseMethod::Chaikin ? "chaikin" : "uniform") << '\n';
    if (mesh.smoothTriangles) out << "t smoothtriangles 0/0/1 " << (*mesh.smoothTriangles ? "smooth" : "catmark") << '\n';
}

void writeCage(const std::string& path, const io::ObjMesh& mesh) {
    io::writeReplacing(path, [&mesh](std::ostream& out) { writeCage(out, mesh); });
}

}  // namespace quadtri::view
