// `quadtri refine` on meshes with UVs, run as a program: the OBJ it writes has one `vt` per value
// of the refined channel and each corner's value index, the values the channel's factorized
// table gives under the chosen --uv-interpolation (a second path through the library); the glTF
// it writes has one TEXCOORD_0 per draw vertex, and every triangle corner the UV of its level
// corner. Meshes without UVs write none.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <quadtri/far/draw_buffers.h>
#include <quadtri/far/refiner.h>
#include <quadtri/osd/cpu_evaluator.h>
#include "tests/test_support.h"
#include "tools/gltf_io.h"
#include "tools/obj_io.h"

namespace quadtri::test {
namespace {

constexpr int kLevel = 2;

// Shapes with UVs: closed with seams, mixed triangles and quads, a hole, n-gons, a boundary.
const std::vector<std::string> kMeshes = {"osd/catmark_cube.obj", "osd/catmark_pyramid.obj",
                                          "osd/catmark_hole_test1.obj", "osd/catmark_nonquads.obj",
                                          "osd/catmark_edgecorner.obj"};

std::string scratch(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "quadtri_test_cli_uvs";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

// Runs the quadtri program with `args`; its exit status.
int runCli(const std::string& args) {
    const std::string command = std::string("'") + QUADTRI_CLI + "' " + args + " > /dev/null";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// What the CLI should write, computed through the library: the file's mesh refined with its UVs
// under `interpolation`, positions through the per-level tables, UVs through the factorized one.
struct Expected {
    io::ObjMesh mesh;
    std::unique_ptr<Refiner> refiner;
    std::vector<float> positions, uvs;
};
Expected expected(const std::string& relative, FVarLinearInterpolation interpolation) {
    Expected e;
    e.mesh = io::readObj(meshPath(relative));
    Options base;
    base.fvarLinearInterpolation = interpolation;
    FVarChannel channel;
    e.refiner = std::make_unique<Refiner>(e.mesh.descriptor(channel), e.mesh.applyTags(base));
    e.refiner->refineUniform(kLevel);
    e.positions = evaluateLevels(*e.refiner, e.mesh.positions, 3)[kLevel];
    const StencilTable table = e.refiner->fvarFactorizedStencils(0, kLevel);
    e.uvs.assign(std::size_t(table.numStencils()) * 2, 0.0f);
    CpuEvaluator::EvalStencils(e.mesh.uvs.data(), BufferDescriptor(0, 2, 2), e.uvs.data(), BufferDescriptor(0, 2, 2),
                               table);
    return e;
}

// The composed table rounds differently from the per-level ones: within this of the UV range.
constexpr float kUVTolerance = 1e-6f;

class CliUVs : public ::testing::TestWithParam<std::tuple<std::string, FVarLinearInterpolation>> {};

TEST_P(CliUVs, ObjHasTheRefinedChannel) {
    const auto& [relative, interpolation] = GetParam();
    const Expected e = expected(relative, interpolation);
    const std::string out = scratch(testNameOf(relative) + "_" + testNameOf(toString(interpolation)) + ".obj");
    ASSERT_EQ(runCli("refine '" + meshPath(relative) + "' -l " + std::to_string(kLevel) + " --uv-interpolation " +
                     toString(interpolation) + " -o '" + out + "'"),
              0);
    const io::ObjMesh written = io::readObj(out);
    const LevelFaces faces = e.refiner->faces(kLevel);
    const IndexSpan values = e.refiner->fvarValues(0, kLevel);
    ASSERT_EQ(written.numUVs(), e.refiner->numFVarValues(0, kLevel));
    ASSERT_EQ(written.positions, e.positions);  // %.9g reads back every float exactly
    // Corner for corner, the non-hole faces' vertices and value indices.
    std::vector<int> verts, uvs;
    for (int f = 0; f < faces.numFaces(); ++f) {
        if (faces.isHole(f)) continue;
        for (int k = faces.offsets()[f]; k < faces.offsets()[f + 1]; ++k) {
            verts.push_back(faces.vertices()[k]);
            uvs.push_back(values[k]);
        }
    }
    EXPECT_EQ(written.faceVerts, verts);
    EXPECT_EQ(written.faceUVs, uvs);
    ASSERT_EQ(written.uvs.size(), e.uvs.size());
    for (std::size_t i = 0; i < e.uvs.size(); ++i) EXPECT_NEAR(written.uvs[i], e.uvs[i], kUVTolerance) << "value " << i / 2;
}

INSTANTIATE_TEST_SUITE_P(Meshes, CliUVs,
                         ::testing::Combine(::testing::ValuesIn(kMeshes),
                                            ::testing::ValuesIn(allFVarLinearInterpolations())),
                         [](const auto& info) {
                             return testNameOf(std::get<0>(info.param)) + "_" +
                                    testNameOf(toString(std::get<1>(info.param)));
                         });

// The options give the cube different UVs, so the comparison above sees which one the flag chose.
TEST(CliUVsOption, ChangesTheCubesUVs) {
    const Expected smooth = expected("osd/catmark_cube.obj", FVarLinearInterpolation::None);
    const Expected linear = expected("osd/catmark_cube.obj", FVarLinearInterpolation::All);
    ASSERT_EQ(smooth.uvs.size(), linear.uvs.size());
    float largest = 0;
    for (std::size_t i = 0; i < smooth.uvs.size(); ++i) largest = std::max(largest, std::abs(smooth.uvs[i] - linear.uvs[i]));
    EXPECT_GT(largest, 100 * kUVTolerance);
}

class CliGltfUVs : public ::testing::TestWithParam<std::string> {};

// Each triangle lies in one level face; its corners carry that face's corners' UVs.
TEST_P(CliGltfUVs, TriangleCornersHaveTheirCornersUVs) {
    const std::string relative = GetParam();
    const Expected e = expected(relative, Options().fvarLinearInterpolation);
    const std::string out = scratch(testNameOf(relative) + ".glb");
    ASSERT_EQ(runCli("refine '" + meshPath(relative) + "' -l " + std::to_string(kLevel) + " -o '" + out + "'"), 0);
    const io::TriangleMesh m = io::readGltf(out);
    const LevelFaces faces = e.refiner->faces(kLevel);
    const IndexSpan values = e.refiner->fvarValues(0, kLevel);
    const DrawBuffers b = buildDrawBuffers(faces, {values.begin()}, {e.refiner->numFVarValues(0, kLevel)});
    ASSERT_EQ(m.numVertices(), b.numVertices());
    ASSERT_EQ(m.uvs.size(), 2 * std::size_t(b.numVertices()));
    ASSERT_EQ(m.triangles.size(), b.triangles.size());

    // The level's vertex at each written position (the level's positions are distinct).
    std::map<std::array<float, 3>, int> vertexAt;
    for (int v = 0; v < faces.numVertices(); ++v)
        vertexAt[{e.positions[3 * v], e.positions[3 * v + 1], e.positions[3 * v + 2]}] = v;
    ASSERT_EQ(int(vertexAt.size()), faces.numVertices());
    std::vector<std::vector<int>> facesOfVertex(std::size_t(faces.numVertices()));
    for (int f = 0; f < faces.numFaces(); ++f)
        if (!faces.isHole(f))
            for (int v : faces.verticesOfFace(f)) facesOfVertex[std::size_t(v)].push_back(f);

    for (std::size_t t = 0; t < m.triangles.size(); t += 3) {
        int corner[3];
        for (int k = 0; k < 3; ++k) {
            const float* p = &m.positions[3 * std::size_t(m.triangles[t + k])];
            const auto it = vertexAt.find({p[0], p[1], p[2]});
            ASSERT_NE(it, vertexAt.end()) << "triangle " << t / 3 << " corner " << k << ": no level vertex there";
            corner[k] = it->second;
        }
        // The face holding all three corners.
        int face = -1;
        for (int f : facesOfVertex[std::size_t(corner[0])]) {
            const IndexSpan vs = faces.verticesOfFace(f);
            if (std::find(vs.begin(), vs.end(), corner[1]) != vs.end() && std::find(vs.begin(), vs.end(), corner[2]) != vs.end())
                face = f;
        }
        ASSERT_GE(face, 0) << "triangle " << t / 3 << " lies in no face";
        const IndexSpan vs = faces.verticesOfFace(face);
        for (int k = 0; k < 3; ++k) {
            const int at = faces.offsets()[face] + int(std::find(vs.begin(), vs.end(), corner[k]) - vs.begin());
            const float* uv = &m.uvs[2 * std::size_t(m.triangles[t + k])];
            const float* want = &e.uvs[2 * std::size_t(values[at])];
            EXPECT_NEAR(uv[0], want[0], kUVTolerance) << "triangle " << t / 3 << " corner " << k;
            EXPECT_NEAR(uv[1], want[1], kUVTolerance) << "triangle " << t / 3 << " corner " << k;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, CliGltfUVs, ::testing::ValuesIn(kMeshes),
                         [](const auto& info) { return testNameOf(info.param); });

// A mesh without `vt` writes no UVs to either format.
TEST(CliNoUVs, WritesNone) {
    const std::string mesh = meshPath("mixed/cylinder_capped.obj");
    const std::string obj = scratch("cylinder.obj"), glb = scratch("cylinder.glb");
    ASSERT_EQ(runCli("refine '" + mesh + "' -l 1 -o '" + obj + "'"), 0);
    ASSERT_EQ(runCli("refine '" + mesh + "' -l 1 -o '" + glb + "'"), 0);
    const io::ObjMesh written = io::readObj(obj);
    EXPECT_EQ(written.numUVs(), 0);
    EXPECT_FALSE(written.hasUVs());
    EXPECT_TRUE(io::readGltf(glb).uvs.empty());
}

}  // namespace
}  // namespace quadtri::test
