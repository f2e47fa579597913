// Draw buffers (far/draw_buffers.h): every drawn face corner maps to a draw vertex with that
// corner's vertex and values; the triangle count is the closed form sum over drawn faces of
// (size - 2); draw vertices are exactly the distinct (vertex, values) combinations of drawn
// corners; holes are left out; triangles keep the faces' orientation; the gather tables copy the
// level's data through any evaluator; bad value indices are refused naming the face.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <quadtri/far/draw_buffers.h>
#include <quadtri/far/refiner.h>
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

// A unit cube (faces counter-clockwise from outside) with the common 14-value cross UV layout's
// topology: the net cut along 7 edges, as in OpenSubdiv's catmark_cube.
struct Cube {
    std::vector<int> sizes = std::vector<int>(6, 4);
    std::vector<int> verts = {0, 1, 3, 2, 2, 3, 5, 4, 4, 5, 7, 6, 6, 7, 1, 0, 1, 7, 5, 3, 6, 0, 2, 4};
    std::vector<int> uvs = {0, 1, 3, 2, 2, 3, 5, 4, 4, 5, 7, 6, 6, 7, 9, 8, 1, 10, 11, 3, 12, 0, 2, 13};
    std::vector<float> positions = {0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1, 0, 1, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0};
};

// The face corners' checks shared by the tests: corner -> draw vertex -> (vertex, values).
void expectCornersMapped(const LevelFaces& faces, const std::vector<const int*>& values, const DrawBuffers& b) {
    int triangle = 0, expectedTriangles = 0;
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        const int n = faces.faceSize(f), start = faces.offsets()[f];
        expectedTriangles += n - 2;
        for (int i = 2; i < n; ++i, ++triangle) {
            const int corner[3] = {0, i - 1, i};
            for (int j = 0; j < 3; ++j) {
                const int d = int(b.triangles[3 * triangle + j]), c = start + corner[j];
                ASSERT_EQ(b.vertexOf[d], faces.vertices()[c]) << "face " << f;
                for (std::size_t k = 0; k < values.size(); ++k) ASSERT_EQ(b.valueOf[k][d], values[k][c]) << "face " << f;
            }
        }
    }
    EXPECT_EQ(b.numTriangles(), expectedTriangles);
    // Draw vertices are exactly the distinct combinations the drawn corners use.
    std::set<std::vector<int>> used, made;
    for (int f = 0; f < faces.numFaces(); ++f)
        for (int c = faces.offsets()[f]; !faces.isHole(f) && c < faces.offsets()[f + 1]; ++c) {
            std::vector<int> key{faces.vertices()[c]};
            for (const int* v : values) key.push_back(v[c]);
            used.insert(key);
        }
    for (int d = 0; d < b.numVertices(); ++d) {
        std::vector<int> key{b.vertexOf[d]};
        for (const auto& v : b.valueOf) key.push_back(v[d]);
        EXPECT_TRUE(made.insert(key).second) << "draw vertex " << d << " repeats a combination";
    }
    EXPECT_EQ(made, used);
}

TEST(DrawBuffers, ControlCubeWithUvSeams) {
    const Cube cube;
    Refiner refiner(descriptorOf(8, cube.sizes, cube.verts), Options());
    const LevelFaces faces = refiner.faces(0);
    const DrawBuffers plain = buildDrawBuffers(faces);
    EXPECT_EQ(plain.numVertices(), 8);
    EXPECT_EQ(plain.numTriangles(), 12);
    expectCornersMapped(faces, {}, plain);
    const DrawBuffers textured = buildDrawBuffers(faces, {cube.uvs.data()}, {14});
    EXPECT_EQ(textured.numVertices(), 14);  // the net's 14 corners
    expectCornersMapped(faces, {cube.uvs.data()}, textured);
}

// Levels 0-2 of meshes with holes, n-gons and non-manifold parts, welded (no channel) and with a
// channel that takes a different value on every face (a seam on every edge: one draw vertex per
// drawn corner).
TEST(DrawBuffers, RefinedLevelsAndHoles) {
    for (const std::string& mesh : {std::string("osd/catmark_hole_test1.obj"), std::string("mixed/book_nonmanifold.obj"),
                                    std::string("osd/catmark_nonquads.obj")}) {
        const RefinedMesh r = refineMesh(mesh, 2);
        for (int L = 0; L <= 2; ++L) {
            const LevelFaces faces = r.refiner->faces(L);
            // A channel that is a different value for every face: every corner its own draw vertex.
            std::vector<int> perFace(faces.numCorners());
            for (int f = 0; f < faces.numFaces(); ++f)
                for (int c = faces.offsets()[f]; c < faces.offsets()[f + 1]; ++c) perFace[c] = f;
            const DrawBuffers welded = buildDrawBuffers(faces);
            expectCornersMapped(faces, {}, welded);
            const DrawBuffers split = buildDrawBuffers(faces, {perFace.data()}, {faces.numFaces()});
            expectCornersMapped(faces, {perFace.data()}, split);
            int drawnCorners = 0;
            for (int f = 0; f < faces.numFaces(); ++f) drawnCorners += faces.isHole(f) ? 0 : faces.faceSize(f);
            EXPECT_EQ(split.numVertices(), drawnCorners) << mesh << " level " << L;
        }
    }
}

// The triangles face the way their faces do: on a refined cube (convex), each triangle's normal
// points away from the centre.
TEST(DrawBuffers, TrianglesKeepTheFacesOrientation) {
    const Cube cube;
    for (bool leftHanded : {false, true}) {
        std::vector<int> verts = cube.verts;
        if (leftHanded)
            for (int f = 0; f < 6; ++f) std::reverse(verts.begin() + 4 * f, verts.begin() + 4 * f + 4);
        Options options;
        options.leftHanded = leftHanded;
        Refiner refiner(descriptorOf(8, cube.sizes, verts), options);
        refiner.refineUniform(2);
        const std::vector<float> xyz = evaluateLevels(refiner, cube.positions, 3)[2];
        const DrawBuffers b = buildDrawBuffers(refiner.faces(2));
        for (int t = 0; t < b.numTriangles(); ++t) {
            const float* p[3];
            for (int j = 0; j < 3; ++j) p[j] = &xyz[3 * std::size_t(b.vertexOf[b.triangles[3 * t + j]])];
            const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
            const double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
            const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
            double outward = 0;
            for (int c = 0; c < 3; ++c) outward += n[c] * ((p[0][c] + p[1][c] + p[2][c]) / 3 - 0.5);
            ASSERT_GT(outward, 0) << "triangle " << t << (leftHanded ? " (left-handed)" : "");
        }
    }
}

// Positions and a 2-float channel gathered into one interleaved buffer (xyz uv, stride 5) by the
// gather tables, on the CPU and oneTBB evaluators: each draw vertex holds its vertex's position
// and its value.
TEST(DrawBuffers, GatherTablesFillAnInterleavedVertexBuffer) {
    const Cube cube;
    Refiner refiner(descriptorOf(8, cube.sizes, cube.verts), Options());
    std::vector<float> uv(28);
    for (int i = 0; i < 14; ++i) uv[2 * i] = float(i), uv[2 * i + 1] = float(-i) / 7;
    const DrawBuffers b = buildDrawBuffers(refiner.faces(0), {cube.uvs.data()}, {14});
    const StencilTable positions = b.gatherStencils(), values = b.gatherStencils(0);
    EXPECT_EQ(positions.numStencils(), b.numVertices());
    EXPECT_EQ(positions.numSourceVertices, 8);
    EXPECT_EQ(values.numSourceVertices, 14);
    for (auto eval : {&CpuEvaluator::EvalStencils, &TbbEvaluator::EvalStencils}) {
        std::vector<float> vertices(5 * std::size_t(b.numVertices()), -1.0f);
        eval(cube.positions.data(), BufferDescriptor(0, 3, 3), vertices.data(), BufferDescriptor(0, 3, 5), positions, 0,
             -1);
        eval(uv.data(), BufferDescriptor(0, 2, 2), vertices.data(), BufferDescriptor(3, 2, 5), values, 0, -1);
        for (int d = 0; d < b.numVertices(); ++d) {
            for (int c = 0; c < 3; ++c) EXPECT_EQ(vertices[5 * d + c], cube.positions[3 * b.vertexOf[d] + c]);
            for (int c = 0; c < 2; ++c) EXPECT_EQ(vertices[5 * d + 3 + c], uv[2 * b.valueOf[0][d] + c]);
        }
    }
    EXPECT_THROW(b.gatherStencils(1), TopologyError);
    EXPECT_THROW(b.gatherStencils(-2), TopologyError);
}

TEST(DrawBuffers, BadValueIndicesNameTheFace) {
    const Cube cube;
    Refiner refiner(descriptorOf(8, cube.sizes, cube.verts), Options());
    std::vector<int> uvs = cube.uvs;
    uvs[9] = 14;  // face 2, corner 1
    try {
        buildDrawBuffers(refiner.faces(0), {uvs.data()}, {14});
        FAIL() << "accepted a value index out of range";
    } catch (const TopologyError& e) {
        EXPECT_EQ(e.diagnostic().component, TopologyDiagnostic::Component::Face);
        EXPECT_EQ(e.diagnostic().index, 2);
        EXPECT_EQ(std::string(e.what()), "face 2: channel 0 value 14 is out of range [0, 14)");
    }
    EXPECT_THROW(buildDrawBuffers(refiner.faces(0), {uvs.data()}, {}), TopologyError);
}

}  // namespace
}  // namespace quadtri::test
