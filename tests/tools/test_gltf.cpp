// glTF output (tools/gltf_io.h): a refined level written as .glb and .gltf and read back with
// tinygltf has the draw buffers' counts (triangles: the closed form over the level's faces) and
// exactly their positions, normals, UVs and indices; bad meshes and unwritable paths are refused
// without leaving a file.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <quadtri/far/draw_buffers.h>
#include <quadtri/far/refiner.h>
#include "tests/test_support.h"
#include "tools/gltf_io.h"
#include "tools/obj_io.h"

namespace quadtri::test {
namespace {

std::filesystem::path scratch(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "quadtri_test_gltf";
    std::filesystem::create_directories(dir);
    return dir / name;
}

// Level 2 of a mixed mesh as draw buffers, with its positions, a made-up normal per vertex and a
// UV per draw vertex (values in [0, 1) that differ per face: a seam everywhere).
io::TriangleMesh refinedMesh(int& expectedTriangles) {
    const RefinedMesh r = refineMesh("mixed/cylinder_capped.obj", 2);
    const LevelFaces faces = r.refiner->faces(2);
    std::vector<int> perFace(faces.numCorners());
    expectedTriangles = 0;
    for (int f = 0; f < faces.numFaces(); ++f) {
        for (int c = faces.offsets()[f]; c < faces.offsets()[f + 1]; ++c) perFace[c] = f;
        if (!faces.isHole(f)) expectedTriangles += faces.faceSize(f) - 2;
    }
    const DrawBuffers b = buildDrawBuffers(faces, {perFace.data()}, {faces.numFaces()});
    io::TriangleMesh m;
    m.triangles = b.triangles;
    for (int d = 0; d < b.numVertices(); ++d) {
        const int v = b.vertexOf[d];
        for (int c = 0; c < 3; ++c) m.positions.push_back(r.positions[2][3 * std::size_t(v) + c]);
        m.normals.insert(m.normals.end(), {0.0f, 0.6f, 0.8f});
        m.uvs.push_back(float(b.valueOf[0][d] % 97) / 97.0f);
        m.uvs.push_back(float(d % 89) / 89.0f);
    }
    return m;
}

TEST(Gltf, RoundTripsThroughTinygltf) {
    int expectedTriangles = 0;
    const io::TriangleMesh m = refinedMesh(expectedTriangles);
    ASSERT_EQ(int(m.triangles.size()), 3 * expectedTriangles);
    for (const char* name : {"level2.glb", "level2.gltf", "LEVEL2.GLB"}) {
        const std::string path = scratch(name).string();
        io::writeGltf(path, m);
        const io::TriangleMesh back = io::readGltf(path);
        EXPECT_EQ(back.triangles, m.triangles) << name;
        EXPECT_EQ(back.positions, m.positions) << name;
        EXPECT_EQ(back.normals, m.normals) << name;
        ASSERT_EQ(back.uvs.size(), m.uvs.size()) << name;
        for (std::size_t i = 0; i < m.uvs.size(); ++i) EXPECT_NEAR(back.uvs[i], m.uvs[i], 1e-7) << name;  // 1 - (1 - v)
    }
    // .glb is the binary container: its magic, then version 2.
    std::FILE* f = std::fopen(scratch("level2.glb").string().c_str(), "rb");
    ASSERT_NE(f, nullptr);
    unsigned char header[8] = {};
    ASSERT_EQ(std::fread(header, 1, 8, f), 8u);
    std::fclose(f);
    EXPECT_EQ(std::string(reinterpret_cast<char*>(header), 4), "glTF");
    EXPECT_EQ(header[4], 2);
}

TEST(Gltf, AttributesAreOptional) {
    io::TriangleMesh m;
    m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    m.triangles = {0, 1, 2};
    const std::string path = scratch("bare.gltf").string();
    io::writeGltf(path, m);
    const io::TriangleMesh back = io::readGltf(path);
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_TRUE(back.normals.empty());
    EXPECT_TRUE(back.uvs.empty());
}

TEST(Gltf, BadMeshesAndPathsAreRefusedWithoutAFile) {
    io::TriangleMesh m;
    m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    m.triangles = {0, 1, 3};
    const std::filesystem::path path = scratch("bad.glb");
    std::filesystem::remove(path);
    try {
        io::writeGltf(path.string(), m);
        FAIL() << "wrote an index out of range";
    } catch (const io::ObjError& e) {
        EXPECT_EQ(std::string(e.what()), path.string() + ": cannot write glTF: triangle index 3 out of range");
    }
    m.triangles = {0, 1, 2};
    m.normals = {0, 0, 1};
    EXPECT_THROW(io::writeGltf(path.string(), m), io::ObjError);
    EXPECT_FALSE(std::filesystem::exists(path));
    m.normals.clear();
    EXPECT_THROW(io::writeGltf((scratch("no_such_dir") / "x.glb").string(), m), io::ObjError);
    EXPECT_THROW(io::readGltf(scratch("missing.glb").string()), io::ObjError);
}

}  // namespace
}  // namespace quadtri::test
