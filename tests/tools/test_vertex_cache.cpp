// Vertex-cache order (tools/vertex_cache.h, meshoptimizer): the reordered draw buffers hold the
// same triangles (corners in the same cyclic order, so the same orientation) over the same
// (vertex, value) combinations, the vertices numbered in the order the triangles first use them,
// and meshoptimizer's cache miss ratio no higher than the refined faces' own order gives (which is
// already good: a face's children are consecutive).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include <quadtri/far/draw_buffers.h>
#include <quadtri/far/refiner.h>
#include "tests/test_support.h"
#include "tools/vertex_cache.h"

namespace quadtri::test {
namespace {

using Corner = std::array<int, 2>;  // (level vertex, channel value)
using Triangle = std::array<Corner, 3>;

// The triangles as corner combinations, each rotated to start at its smallest corner, sorted.
std::vector<Triangle> trianglesOf(const DrawBuffers& b) {
    std::vector<Triangle> out;
    for (int t = 0; t < b.numTriangles(); ++t) {
        Triangle tri;
        for (int j = 0; j < 3; ++j) {
            const int d = int(b.triangles[3 * t + j]);
            tri[j] = {b.vertexOf[d], b.valueOf.empty() ? -1 : b.valueOf[0][d]};
        }
        std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
        out.push_back(tri);
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(VertexCache, SameTrianglesNoMoreCacheMisses) {
    for (const std::string& mesh : {std::string("mixed/cylinder_capped.obj"), std::string("osd/catmark_torus.obj"),
                                    std::string("osd/loop_xord_interior.obj")}) {
        const RefinedMesh r = refineMesh(mesh, 3);
        const LevelFaces faces = r.refiner->faces(3);
        std::vector<int> perFace(faces.numCorners());  // a seam along every control edge's children too
        for (int f = 0; f < faces.numFaces(); ++f)
            for (int c = faces.offsets()[f]; c < faces.offsets()[f + 1]; ++c) perFace[c] = f / 16;
        DrawBuffers b = buildDrawBuffers(faces, {perFace.data()}, {faces.numFaces()});
        const std::vector<Triangle> before = trianglesOf(b);
        const double missesBefore = io::averageCacheMissRatio(b);
        const int vertices = b.numVertices();
        io::optimizeVertexCache(b);
        EXPECT_EQ(b.numVertices(), vertices) << mesh;
        EXPECT_EQ(trianglesOf(b), before) << mesh;
        const double missesAfter = io::averageCacheMissRatio(b);
        EXPECT_LE(missesAfter, missesBefore) << mesh;
        EXPECT_LT(missesAfter, 1.0) << mesh << " (before: " << missesBefore << ")";
        // Fetch order: the k-th new vertex the triangles meet is vertex k.
        int next = 0;
        for (std::uint32_t d : b.triangles) {
            ASSERT_LE(int(d), next) << mesh;
            if (int(d) == next) ++next;
        }
        EXPECT_EQ(next, vertices) << mesh;
        std::printf("%s: average cache miss ratio %.3f -> %.3f\n", mesh.c_str(), missesBefore, missesAfter);
    }
}

}  // namespace
}  // namespace quadtri::test
