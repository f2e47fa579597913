#include "bench/meshes/torus.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace quadtri::bench {

TopologyDescriptor ControlMesh::descriptor() const {
    TopologyDescriptor desc;
    desc.numVertices = numVertices;
    desc.numFaces = numFaces();
    desc.numVertsPerFace = faceSizes.data();
    desc.faceVertIndices = faceVerts.data();
    return desc;
}

double ControlMesh::boundingBoxDiagonal() const {
    double lo[3], hi[3];
    std::fill(lo, lo + 3, std::numeric_limits<double>::max());
    std::fill(hi, hi + 3, -std::numeric_limits<double>::max());
    for (int v = 0; v < numVertices; ++v)
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], double(positions[3 * size_t(v) + c]));
            hi[c] = std::max(hi[c], double(positions[3 * size_t(v) + c]));
        }
    double d2 = 0;
    for (int c = 0; c < 3; ++c) d2 += numVertices > 0 ? (hi[c] - lo[c]) * (hi[c] - lo[c]) : 0.0;
    return std::sqrt(d2);
}

std::string torusName(int n, TorusFaces faces) {
    static const char* const kSuffix[] = {"quad", "tri", "mixed"};
    return "torus" + std::to_string(n) + "_" + kSuffix[int(faces)];
}

ControlMesh makeTorus(int n, TorusFaces faces) {
    const double kMajor = 2.0, kMinor = 1.0, kTwoPi = 2.0 * std::acos(-1.0);
    ControlMesh mesh;
    mesh.name = torusName(n, faces);
    mesh.numVertices = n * n;
    mesh.positions.reserve(3 * size_t(n) * n);
    for (int i = 0; i < n; ++i) {
        const double u = kTwoPi * i / n;
        for (int j = 0; j < n; ++j) {
            const double v = kTwoPi * j / n;
            const double ring = kMajor + kMinor * std::cos(v);
            mesh.positions.push_back(float(ring * std::cos(u)));
            mesh.positions.push_back(float(ring * std::sin(u)));
            mesh.positions.push_back(float(kMinor * std::sin(v)));
        }
    }
    auto id = [n](int i, int j) { return (i % n) * n + (j % n); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            const bool split = faces == TorusFaces::Triangles || (faces == TorusFaces::Mixed && i % 2 == 1);
            if (split) {
                mesh.faceSizes.insert(mesh.faceSizes.end(), {3, 3});
                mesh.faceVerts.insert(mesh.faceVerts.end(), {a, b, c, a, c, d});
            } else {
                mesh.faceSizes.push_back(4);
                mesh.faceVerts.insert(mesh.faceVerts.end(), {a, b, c, d});
            }
        }
    return mesh;
}

}  // namespace quadtri::bench
