// MeshNormals: area-weighted vertex normals of a level (MeshNormalTable, EvalMeshNormals) on
// hand-checked meshes (a cube's corners, a flat grid, two faces of different areas, a hole, a
// vertex without faces), orientation (winding and Options::leftHanded), TbbEvaluator bitwise equal
// to CpuEvaluator on refined bench tori, the whole-level pass (face by face, chunks and seam
// vertices) bitwise equal to the per-vertex one (ranges) and within 1e-6 of the faces' shoelace
// sums in double, and the argument checks of both.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/far/refiner.h>
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#include "bench/meshes/torus.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

const BufferDescriptor kPacked(0, 3, 3);

// The table of level 0 of a mesh given by face sizes and corners.
MeshNormalTable tableOf(const std::vector<int>& sizes, const std::vector<int>& verts, int numVertices,
                        bool leftHanded = false, std::vector<int> holes = {}) {
    TopologyDescriptor desc = descriptorOf(numVertices, sizes, verts);
    desc.numHoles = int(holes.size());
    desc.holeIndices = holes.data();
    Options options;
    options.leftHanded = leftHanded;
    const Refiner refiner(desc, options);
    return buildMeshNormalTable(refiner.faces(0));
}

std::vector<float> normalsOf(const MeshNormalTable& t, const std::vector<float>& xyz) {
    std::vector<float> n(3 * std::size_t(t.numVertices), -7.0f);
    CpuEvaluator::EvalMeshNormals(xyz.data(), kPacked, n.data(), kPacked, t);
    return n;
}

void expectNormal(const std::vector<float>& n, int v, double x, double y, double z, const std::string& what) {
    const double len = std::sqrt(x * x + y * y + z * z);
    EXPECT_NEAR(n[3 * v], x / len, 1e-6) << what << " vertex " << v;
    EXPECT_NEAR(n[3 * v + 1], y / len, 1e-6) << what << " vertex " << v;
    EXPECT_NEAR(n[3 * v + 2], z / len, 1e-6) << what << " vertex " << v;
}

// The unit cube [0,1]^3, vertex (x, y, z) numbered x + 2y + 4z, faces counter-clockwise seen
// from outside.
const std::vector<int> kCubeSizes(6, 4);
const std::vector<int> kCubeVerts = {0, 2, 3, 1,  4, 5, 7, 6,  0, 1, 5, 4,  2, 6, 7, 3,  0, 4, 6, 2,  1, 3, 7, 5};
std::vector<float> cubePositions() {
    std::vector<float> xyz;
    for (int v = 0; v < 8; ++v) xyz.insert(xyz.end(), {float(v & 1), float((v >> 1) & 1), float((v >> 2) & 1)});
    return xyz;
}

std::vector<int> reversed(const std::vector<int>& sizes, const std::vector<int>& verts) {
    std::vector<int> out;
    std::size_t at = 0;
    for (int s : sizes) {
        for (int k = s - 1; k >= 0; --k) out.push_back(verts[at + k]);
        at += s;
    }
    return out;
}

// Each corner of a cube meets three unit faces whose normals are its three outward axes, so its
// normal is (±1, ±1, ±1)/sqrt(3), pointing away from the centre.
TEST(MeshNormals, CubeCornersPointOutwardAlongTheDiagonal) {
    const std::vector<float> xyz = cubePositions();
    const std::vector<float> n = normalsOf(tableOf(kCubeSizes, kCubeVerts, 8), xyz);
    for (int v = 0; v < 8; ++v)
        expectNormal(n, v, xyz[3 * v] - 0.5, xyz[3 * v + 1] - 0.5, xyz[3 * v + 2] - 0.5, "cube");
}

// Clockwise faces point inward, unless Options::leftHanded says they are listed clockwise.
TEST(MeshNormals, OrientationFollowsTheWindingUnlessLeftHanded) {
    const std::vector<float> xyz = cubePositions();
    const std::vector<int> clockwise = reversed(kCubeSizes, kCubeVerts);
    const std::vector<float> inward = normalsOf(tableOf(kCubeSizes, clockwise, 8), xyz);
    const std::vector<float> leftHanded = normalsOf(tableOf(kCubeSizes, clockwise, 8, true), xyz);
    for (int v = 0; v < 8; ++v) {
        const double x = xyz[3 * v] - 0.5, y = xyz[3 * v + 1] - 0.5, z = xyz[3 * v + 2] - 0.5;
        expectNormal(inward, v, -x, -y, -z, "clockwise read as right-handed");
        expectNormal(leftHanded, v, x, y, z, "clockwise under leftHanded");
    }
}

// A 4x3 grid of quads in the plane z = 1, every other one split into two triangles of unequal
// size: every normal is +z however the faces differ.
TEST(MeshNormals, FlatGridIsPlusZEverywhere) {
    const int nx = 4, ny = 3;
    std::vector<int> sizes, verts;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 2, d = a + nx + 1;
            if ((i + j) % 2) {
                sizes.insert(sizes.end(), {3, 3});
                verts.insert(verts.end(), {a, b, c, a, c, d});
            } else {
                sizes.push_back(4);
                verts.insert(verts.end(), {a, b, c, d});
            }
        }
    std::vector<float> xyz;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) xyz.insert(xyz.end(), {float(i) + 0.1f * float(j * j), 0.7f * float(j), 1.0f});
    const std::vector<float> n = normalsOf(tableOf(sizes, verts, (nx + 1) * (ny + 1)), xyz);
    for (int v = 0; v < (nx + 1) * (ny + 1); ++v) {
        EXPECT_EQ(n[3 * v], 0.0f) << v;
        EXPECT_EQ(n[3 * v + 1], 0.0f) << v;
        EXPECT_FLOAT_EQ(n[3 * v + 2], 1.0f) << v;
    }
}

// At the origin: a triangle of area 1/2 facing +z and one of area 2 facing +y, both with a right
// angle there. Area weighting gives (0, 2, 1/2) normalised; angle weighting would give (0, 1, 1).
TEST(MeshNormals, FacesWeighByTheirArea) {
    const std::vector<float> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 2, 2, 0, 0};
    const std::vector<float> n = normalsOf(tableOf({3, 3}, {0, 1, 2, 0, 3, 4}, 5), xyz);
    expectNormal(n, 0, 0, 2, 0.5, "two triangles");
    expectNormal(n, 1, 0, 0, 1, "first triangle only");
    expectNormal(n, 3, 0, 1, 0, "second triangle only");
}

// Newell's vector area sum_k p_k x p_{k+1} of each face, summed at vertex 0: a non-planar quad, a
// non-planar pentagon and a triangle around it.
TEST(MeshNormals, AnyPolygonAddsNewellsVectorArea) {
    const std::vector<float> xyz = {0, 0, 0,  1, 0, 0.3f,  1, 1, 0,  0, 1, -0.2f,  -1, 1, 0.1f,  -1.2f, 0, 0.4f,
                                    -1, -1, 0,  0.5f, -1, 0.2f};
    const std::vector<int> sizes = {4, 5, 3};
    const std::vector<int> verts = {0, 1, 2, 3,  0, 3, 4, 5, 6,  0, 6, 7};
    double expected[3] = {0, 0, 0};
    std::size_t at = 0;
    for (int s : sizes) {
        for (int k = 0; k < s; ++k) {
            const float* p = &xyz[3 * verts[at + k]];
            const float* q = &xyz[3 * verts[at + (k + 1) % s]];
            expected[0] += double(p[1]) * q[2] - double(p[2]) * q[1];
            expected[1] += double(p[2]) * q[0] - double(p[0]) * q[2];
            expected[2] += double(p[0]) * q[1] - double(p[1]) * q[0];
        }
        at += s;
    }
    const std::vector<float> n = normalsOf(tableOf(sizes, verts, 8), xyz);
    expectNormal(n, 0, expected[0], expected[1], expected[2], "quad + pentagon + triangle");
}

TEST(MeshNormals, HolesAndLonelyVerticesGiveNoNormal) {
    // Two quads side by side, the second a hole; vertex 6 belongs to no face.
    const std::vector<float> xyz = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 5, 5, 5};
    const MeshNormalTable t = tableOf({4, 4}, {0, 1, 4, 3, 1, 2, 5, 4}, 7, false, {1});
    EXPECT_EQ(t.numFaces(), 1);             // the drawn quad alone
    EXPECT_EQ(t.vertexFaces.size(), 4u);  // once per corner
    const std::vector<float> n = normalsOf(t, xyz);
    for (int v : {0, 1, 3, 4}) expectNormal(n, v, 0, 0, 1, "drawn quad");
    for (int v : {2, 5, 6})
        for (int c = 0; c < 3; ++c) EXPECT_EQ(n[3 * v + c], 0.0f) << "vertex " << v << " has no drawn face";
}

// A level's normals from its refined positions, with padded layouts.
struct Level {
    MeshNormalTable table;
    std::vector<float> src;  // layout kSrc
};
const BufferDescriptor kSrc(2, 3, 5), kDst(1, 3, 4);

Level refinedTorus(bench::TorusFaces faces, Scheme scheme, int level) {
    const bench::ControlMesh m = bench::makeTorus(24, faces);
    const TopologyDescriptor desc = descriptorOf(m.numVertices, m.faceSizes, m.faceVerts);
    Options options;
    options.scheme = scheme;
    Refiner refiner(desc, options);
    refiner.refineUniform(level);
    const std::vector<std::vector<float>> xyz = evaluateLevels(refiner, m.positions, 3);
    Level out{buildMeshNormalTable(refiner.faces(level)), {}};
    const int n = out.table.numVertices;
    out.src.assign(std::size_t(kSrc.offset) + std::size_t(n) * kSrc.stride, -3.0f);
    for (int v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c) out.src[kSrc.offset + std::size_t(v) * kSrc.stride + c] = xyz[level][3 * v + c];
    return out;
}

TEST(MeshNormals, TbbEqualsCpuBitwiseAndNormalsAreUnitAndOutward) {
    for (bench::TorusFaces faces : {bench::TorusFaces::Quads, bench::TorusFaces::Triangles, bench::TorusFaces::Mixed}) {
        const Level L = refinedTorus(faces, Scheme::SchaeferWarren, 3);
        const int n = L.table.numVertices;
        const std::size_t floats = std::size_t(kDst.offset) + std::size_t(n) * kDst.stride;
        std::vector<float> cpu(floats, -9.0f), partial(floats, -9.0f);
        CpuEvaluator::EvalMeshNormals(L.src.data(), kSrc, cpu.data(), kDst, L.table);
        for (int threads : {1, 2}) {
            std::vector<float> tbb(floats, -9.0f);
            tbb::task_arena(threads).execute(
                [&] { TbbEvaluator::EvalMeshNormals(L.src.data(), kSrc, tbb.data(), kDst, L.table); });
            EXPECT_EQ(std::memcmp(cpu.data(), tbb.data(), floats * sizeof(float)), 0) << threads << " threads";
        }
        // A range writes its rows only.
        CpuEvaluator::EvalMeshNormals(L.src.data(), kSrc, partial.data(), kDst, L.table, 100, 5000);
        for (int v = 0; v < n; ++v)
            for (int c = 0; c < 3; ++c) {
                const std::size_t at = kDst.offset + std::size_t(v) * kDst.stride + c;
                EXPECT_EQ(partial[at], v >= 100 && v < 5000 ? cpu[at] : -9.0f);
            }
        // Unit length, and outward on a torus (major radius 2): the normal leans away from the
        // tube's core circle.
        for (int v = 0; v < n; ++v) {
            const float* p = &L.src[kSrc.offset + std::size_t(v) * kSrc.stride];
            const float* q = &cpu[kDst.offset + std::size_t(v) * kDst.stride];
            const double len = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2]);
            ASSERT_NEAR(len, 1.0, 1e-6) << v;
            const double r = std::hypot(p[0], p[1]);
            const double out[3] = {p[0] - 2.0 * p[0] / r, p[1] - 2.0 * p[1] / r, p[2]};
            ASSERT_GT(out[0] * q[0] + out[1] * q[1] + out[2] * q[2], 0.0) << v;
        }
    }
}

// The same normals in double by another formula: each drawn face's doubled vector area as the
// sum of p_k x p_(k+1) around it, added to each of its corners, face by face.
std::vector<double> shoelaceNormals(const MeshNormalTable& t, const float* src, int stride) {
    std::vector<double> out(3 * std::size_t(t.numVertices), 0.0);
    auto p = [&](int corner, int c) {
        return double(src[std::size_t(corner & MeshNormalTable::kCornerIndexMask) * stride + c]);
    };
    for (int f = 0; f < t.numFaces(); ++f) {
        const int first = t.faceOffsets[f], n = t.faceOffsets[f + 1] - first;
        double a[3] = {0, 0, 0};
        for (int k = 0; k < n; ++k) {
            const int i = t.faceCorners[first + k], j = t.faceCorners[first + (k + 1) % n];
            a[0] += p(i, 1) * p(j, 2) - p(i, 2) * p(j, 1);
            a[1] += p(i, 2) * p(j, 0) - p(i, 0) * p(j, 2);
            a[2] += p(i, 0) * p(j, 1) - p(i, 1) * p(j, 0);
        }
        for (int k = 0; k < n; ++k) {
            const int v = t.faceCorners[first + k] & MeshNormalTable::kCornerIndexMask;
            for (int c = 0; c < 3; ++c) out[3 * std::size_t(v) + c] += a[c];
        }
    }
    for (int v = 0; v < t.numVertices; ++v) {
        double* n = &out[3 * std::size_t(v)];
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int c = 0; c < 3; ++c) n[c] = len > 0 ? n[c] / len : 0.0;
    }
    return out;
}

TEST(MeshNormals, WholeLevelPassEqualsPerVertexPassAndTheShoelaceSums) {
    for (bench::TorusFaces faces : {bench::TorusFaces::Quads, bench::TorusFaces::Triangles, bench::TorusFaces::Mixed}) {
        const Level L = refinedTorus(faces, Scheme::SchaeferWarren, 3);
        const MeshNormalTable& t = L.table;
        const int n = t.numVertices;
        // The parallel form really has chunks and seams here.
        ASSERT_GT(t.numChunks(), 2);
        ASSERT_GT(t.seamVertices.size(), 0u);
        // Packed positions too: the whole-level loops have a form for that layout of their own.
        std::vector<float> packed(3 * std::size_t(n));
        for (int v = 0; v < n; ++v)
            for (int c = 0; c < 3; ++c)
                packed[3 * std::size_t(v) + c] = L.src[kSrc.offset + std::size_t(v) * kSrc.stride + c];
        struct Layout {
            const float* src;
            BufferDescriptor srcDesc, dstDesc;
        };
        for (const Layout& layout : {Layout{packed.data(), kPacked, kPacked}, Layout{L.src.data(), kSrc, kDst}}) {
            const std::size_t floats =
                std::size_t(layout.dstDesc.offset) + std::size_t(n) * std::size_t(layout.dstDesc.stride);
            std::vector<float> whole(floats, -9.0f), perVertex(floats, -9.0f), tbb(floats, -9.0f);
            CpuEvaluator::EvalMeshNormals(layout.src, layout.srcDesc, whole.data(), layout.dstDesc, t);
            // Two ranges, each shorter than the level: the per-vertex gather.
            CpuEvaluator::EvalMeshNormals(layout.src, layout.srcDesc, perVertex.data(), layout.dstDesc, t, 0, n / 3);
            CpuEvaluator::EvalMeshNormals(layout.src, layout.srcDesc, perVertex.data(), layout.dstDesc, t, n / 3, n);
            tbb::task_arena(2).execute(
                [&] { TbbEvaluator::EvalMeshNormals(layout.src, layout.srcDesc, tbb.data(), layout.dstDesc, t); });
            EXPECT_EQ(std::memcmp(whole.data(), perVertex.data(), floats * sizeof(float)), 0);
            EXPECT_EQ(std::memcmp(whole.data(), tbb.data(), floats * sizeof(float)), 0);
            const std::vector<double> reference =
                shoelaceNormals(t, layout.src + layout.srcDesc.offset, layout.srcDesc.stride);
            double worst = 0.0;
            for (int v = 0; v < n; ++v) {
                const float* got = &whole[layout.dstDesc.offset + std::size_t(v) * layout.dstDesc.stride];
                for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[c] - reference[3 * std::size_t(v) + c]));
            }
            EXPECT_LT(worst, 1e-6) << "unit normals against the shoelace sums in double";
        }
    }
}

TEST(MeshNormals, BadArgumentsGiveTheSameMessageOnBothEvaluators) {
    const MeshNormalTable t = tableOf(kCubeSizes, kCubeVerts, 8);
    const std::vector<float> xyz = cubePositions();
    std::vector<float> out(64);
    struct Case {
        BufferDescriptor src, dst;
        const float* s;
        float* d;
        int start, end;
        const char* expected;
    };
    const Case cases[] = {
        {BufferDescriptor(0, 0, 3), kPacked, xyz.data(), out.data(), 0, -1, "EvalMeshNormals: invalid BufferDescriptor"},
        {BufferDescriptor(0, 4, 4), kPacked, xyz.data(), out.data(), 0, -1,
         "EvalMeshNormals: positions and normals are 3 floats (source length 4, destination length 3)"},
        {kPacked, kPacked, xyz.data(), out.data(), 2, 9, "EvalMeshNormals: range [2, 9) outside the table's 8 vertices"},
        {kPacked, kPacked, xyz.data(), out.data(), 5, 4, "EvalMeshNormals: range [5, 4)"},
        {kPacked, kPacked, nullptr, out.data(), 0, -1, "EvalMeshNormals: null buffer"},
    };
    for (const Case& c : cases) {
        const std::string cpu = messageOf([&] { CpuEvaluator::EvalMeshNormals(c.s, c.src, c.d, c.dst, t, c.start, c.end); });
        const std::string tbb = messageOf([&] { TbbEvaluator::EvalMeshNormals(c.s, c.src, c.d, c.dst, t, c.start, c.end); });
        EXPECT_EQ(cpu.rfind(c.expected, 0), 0u) << cpu;
        EXPECT_EQ(cpu, tbb);
    }
    // An empty range needs no buffers.
    EXPECT_NO_THROW(CpuEvaluator::EvalMeshNormals(nullptr, kPacked, nullptr, kPacked, t, 3, 3));
}

}  // namespace
}  // namespace quadtri::test
