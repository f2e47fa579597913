// The bench's control meshes: closed tori (major radius 2, minor radius 1) generated in code.
#pragma once

#include <string>
#include <vector>

#include <quadtri/far/topology.h>

namespace quadtri::bench {

struct ControlMesh {
    std::string name;
    int numVertices = 0;
    std::vector<int> faceSizes;
    std::vector<int> faceVerts;
    std::vector<float> positions;  // xyz per vertex

    int numFaces() const { return int(faceSizes.size()); }
    // The mesh as a Refiner reads it (pointing into this mesh).
    TopologyDescriptor descriptor() const;
    double boundingBoxDiagonal() const;
};

enum class TorusFaces {
    Quads,      // n x n quads
    Triangles,  // every quad split in two along the same diagonal
    Mixed,      // the quads of every other ring (odd i) split in two, the others kept
};

// "torus100_quad", "torus320_tri", ...: the name makeTorus gives.
std::string torusName(int n, TorusFaces faces);

// A torus of n x n vertices: vertex (i, j) at angle 2 pi i / n around the major circle and
// 2 pi j / n around the minor one. Named e.g. "torus100_quad".
ControlMesh makeTorus(int n, TorusFaces faces);

}  // namespace quadtri::bench
