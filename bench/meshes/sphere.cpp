#include "bench/meshes/sphere.h"

#include <cmath>
#include <initializer_list>
#include <string>

namespace quadtri::bench {

ControlMesh makeUvSphere(int segments, int rings, SpherePoles poles) {
    const double kPi = std::acos(-1.0);
    ControlMesh mesh;
    mesh.name = "sphere" + std::to_string(segments) + "x" + std::to_string(rings) +
                (poles == SpherePoles::TriangleFans ? "_mixed" : "_quad");
    mesh.numVertices = 2 + (rings - 1) * segments;
    mesh.positions = {0.0f, 0.0f, 1.0f};
    for (int r = 1; r < rings; ++r)
        for (int j = 0; j < segments; ++j) {
            const double theta = kPi * r / rings, phi = 2.0 * kPi * j / segments;
            mesh.positions.insert(mesh.positions.end(), {float(std::sin(theta) * std::cos(phi)),
                                                         float(std::sin(theta) * std::sin(phi)), float(std::cos(theta))});
        }
    mesh.positions.insert(mesh.positions.end(), {0.0f, 0.0f, -1.0f});
    const int south = mesh.numVertices - 1;
    auto at = [&](int r, int j) { return 1 + (r - 1) * segments + j % segments; };
    auto face = [&](std::initializer_list<int> verts) {
        mesh.faceSizes.push_back(int(verts.size()));
        mesh.faceVerts.insert(mesh.faceVerts.end(), verts);
    };
    // Each pole's fan keeps the outward orientation of the quads between the rings.
    const int step = poles == SpherePoles::TriangleFans ? 1 : 2;
    for (int j = 0; j < segments; j += step) {
        if (step == 1) face({0, at(1, j), at(1, j + 1)});
        else face({0, at(1, j), at(1, j + 1), at(1, j + 2)});
    }
    for (int r = 1; r + 1 < rings; ++r)
        for (int j = 0; j < segments; ++j) face({at(r, j), at(r + 1, j), at(r + 1, j + 1), at(r, j + 1)});
    for (int j = 0; j < segments; j += step) {
        if (step == 1) face({south, at(rings - 1, j + 1), at(rings - 1, j)});
        else face({south, at(rings - 1, j + 2), at(rings - 1, j + 1), at(rings - 1, j)});
    }
    return mesh;
}

}  // namespace quadtri::bench
