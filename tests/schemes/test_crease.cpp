// DeRose creases: sharpness decay (uniform and Chaikin) against hand-computed values, the
// fractional blend when a vertex's rule relaxes, and a semi-sharp crease on a mixed mesh.
#include <gtest/gtest.h>

#include <cmath>

#include "far/schemes/crease.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

// A (n+1) x (n+1) grid of unit quads with bumpy heights, so that smooth and sharp rules differ.
struct Grid {
    int n;
    std::vector<float> positions;
    std::vector<int> sizes, verts;
    explicit Grid(int n_) : n(n_) {
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                positions.insert(positions.end(), {float(i), float(j), float(std::sin(1.3 * i + 0.7 * j * j))});
            }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                sizes.push_back(4);
                verts.insert(verts.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            }
    }
    int id(int i, int j) const { return j * (n + 1) + i; }
};

struct Crease {
    int a, b;
    float sharpness;
};

Refiner refineGrid(const Grid& g, const std::vector<Crease>& creases, CreaseMethod method, int levels) {
    std::vector<int> pairs;
    std::vector<float> sharpness;
    for (const Crease& c : creases) {
        pairs.insert(pairs.end(), {c.a, c.b});
        sharpness.push_back(c.sharpness);
    }
    TopologyDescriptor d;
    d.numVertices = int(g.positions.size() / 3);
    d.numFaces = int(g.sizes.size());
    d.numVertsPerFace = g.sizes.data();
    d.faceVertIndices = g.verts.data();
    d.numCreases = int(creases.size());
    d.creaseVertexPairs = pairs.data();
    d.creaseWeights = sharpness.data();
    Options options;
    options.creaseMethod = method;
    Refiner refiner(d, options);
    refiner.refineUniform(levels, TopologyDetail::Full);
    return refiner;
}

// Sharpness of the level-1 child of edge (a, b) at a's end.
float childSharpness(const Refiner& r, int a, int b) {
    const Topology& p = r.level(0);
    const int e = findEdge(p, a, b);
    int facePoints = 0;
    for (int f = 0; f < p.numFaces(); ++f) facePoints += p.faceSize(f) != 3;
    const int child = findEdge(r.level(1), facePoints + p.numEdges() + a, facePoints + e);
    EXPECT_GE(child, 0);
    return r.level(1).edgeSharpness[child];
}

TEST(SharpnessDecay, UniformSubtractsOne) {
    EXPECT_FLOAT_EQ(decrementSharpness(2.5f), 1.5f);
    EXPECT_FLOAT_EQ(decrementSharpness(1.0f), 0.0f);
    EXPECT_FLOAT_EQ(decrementSharpness(0.7f), 0.0f);
    EXPECT_FLOAT_EQ(decrementSharpness(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(decrementSharpness(10.0f), 10.0f);  // infinite stays
    const Grid g(4);
    const int c = g.id(2, 2);
    const Refiner r = refineGrid(g, {{c, g.id(3, 2), 3.0f}, {c, g.id(1, 2), 1.0f}, {c, g.id(2, 3), 10.0f}},
                                 CreaseMethod::Uniform, 1);
    EXPECT_FLOAT_EQ(childSharpness(r, c, g.id(3, 2)), 2.0f);
    EXPECT_FLOAT_EQ(childSharpness(r, c, g.id(1, 2)), 0.0f);
    EXPECT_FLOAT_EQ(childSharpness(r, c, g.id(2, 3)), 10.0f);
    EXPECT_FLOAT_EQ(childSharpness(r, c, g.id(2, 1)), 0.0f);
}

TEST(SharpnessDecay, ChaikinBlendsWithTheOtherSemiSharpEdges) {
    // Centre vertex with edges of sharpness 3, 1, 2 and a smooth one: each child gets
    // ¾ s + ¼ mean(other semi-sharp) − 1:
    //   3 -> 2.25 + 0.25·1.5 − 1 = 1.625;  1 -> 0.75 + 0.25·2.5 − 1 = 0.375;  2 -> 1.5 + 0.25·2 − 1 = 1.
    const Grid g(4);
    const int c = g.id(2, 2);
    const Refiner r = refineGrid(g, {{c, g.id(3, 2), 3.0f}, {c, g.id(1, 2), 1.0f}, {c, g.id(2, 3), 2.0f}},
                                 CreaseMethod::Chaikin, 1);
    EXPECT_FLOAT_EQ(childSharpness(r, c, g.id(3, 2)), 1.625f);
    EXPECT_FLOAT_EQ(childSharpness(r, c, g.id(1, 2)), 0.375f);
    EXPECT_FLOAT_EQ(childSharpness(r, c, g.id(2, 3)), 1.0f);
    EXPECT_FLOAT_EQ(childSharpness(r, c, g.id(2, 1)), 0.0f);
    // At the far ends each edge is the only semi-sharp one: plain s − 1.
    EXPECT_FLOAT_EQ(childSharpness(r, g.id(3, 2), c), 2.0f);
    EXPECT_FLOAT_EQ(childSharpness(r, g.id(1, 2), c), 0.0f);
}

TEST(SharpnessDecay, ChaikinIgnoresInfiniteEdgesInTheMean) {
    // Edges 2 and 10 at the centre: 10 is not semi-sharp, so 2 decays as if alone (2 − 1 = 1).
    const Grid g(4);
    const int c = g.id(2, 2);
    const Refiner r =
        refineGrid(g, {{c, g.id(3, 2), 2.0f}, {c, g.id(1, 2), 10.0f}}, CreaseMethod::Chaikin, 1);
    EXPECT_FLOAT_EQ(childSharpness(r, c, g.id(3, 2)), 1.0f);
    EXPECT_FLOAT_EQ(childSharpness(r, c, g.id(1, 2)), 10.0f);
}

// Level-1 position of the child of grid vertex v.
std::vector<float> childOfVertex(const Refiner& r, const Grid& g, int v) {
    const std::vector<std::vector<float>> levels = evaluateLevels(r, g.positions, 3);
    const int child = r.faces(0).numFaces() + r.level(0).numEdges() + v;
    return {levels[1][3 * child], levels[1][3 * child + 1], levels[1][3 * child + 2]};
}

TEST(FractionalBlend, HalfSharpCreaseIsHalfwayBetweenSmoothAndCrease) {
    const Grid g(4);
    const int c = g.id(2, 2), a = g.id(1, 2), b = g.id(3, 2);
    const std::vector<float> half = childOfVertex(refineGrid(g, {{c, a, 0.5f}, {c, b, 0.5f}}, CreaseMethod::Uniform, 1), g, c);
    const std::vector<float> smooth = childOfVertex(refineGrid(g, {}, CreaseMethod::Uniform, 1), g, c);
    const std::vector<float> crease = childOfVertex(refineGrid(g, {{c, a, 5.0f}, {c, b, 5.0f}}, CreaseMethod::Uniform, 1), g, c);
    for (int k = 0; k < 3; ++k) {
        // The crease result is ¾ v + ⅛ (a + b); smooth is Catmull-Clark's; half is their mean.
        const float expectedCrease = 0.75f * g.positions[3 * c + k] + 0.125f * (g.positions[3 * a + k] + g.positions[3 * b + k]);
        EXPECT_NEAR(crease[k], expectedCrease, 1e-6);
        EXPECT_NEAR(half[k], 0.5f * (smooth[k] + crease[k]), 1e-6) << "component " << k;
    }
    EXPECT_GT(std::abs(smooth[2] - crease[2]), 1e-3) << "the test needs smooth and crease to differ";
}

// Height above the bottom cap (z = -1) of the level-`level` descendants of the rim vertices 0..7
// of cylinder_capped_creased with the rim's sharpness replaced by `sharpness`.
std::vector<double> rimHeights(float sharpness, int level) {
    io::ObjMesh mesh = io::readObj(meshPath("mixed/cylinder_capped_creased.obj"));
    for (float& s : mesh.creaseSharpness) s = sharpness;
    Refiner refiner(mesh.descriptor(), mesh.applyTags(Options()));
    refiner.refineUniform(level);
    const std::vector<std::vector<float>> levels = evaluateLevels(refiner, mesh.positions, 3);
    for (int L = 1; L <= level; ++L)
        for (int i = 0; i < refiner.levelStencils(L).numStencils(); ++i)
            EXPECT_NEAR(stencilWeightSum(refiner.levelStencils(L), i), 1.0, 1e-6);
    std::vector<double> heights;
    for (int rim = 0; rim < 8; ++rim) {
        int v = rim;
        for (int L = 1; L <= level; ++L) {
            const Topology& p = refiner.level(L - 1);
            int facePoints = 0;
            for (int f = 0; f < p.numFaces(); ++f) facePoints += p.faceSize(f) != 3;
            v = facePoints + p.numEdges() + v;
        }
        heights.push_back(levels[level][3 * v + 2] + 1.0);
    }
    return heights;
}

TEST(MixedCrease, CylinderRimStaysSharpForTwoLevelsThenSoftens) {
    // Sharpness 2.5: the rim follows the crease rule at levels 1 and 2 and stays in the cap's plane.
    for (int level : {1, 2})
        for (double h : rimHeights(2.5f, level)) EXPECT_NEAR(h, 0.0, 1e-6) << "level " << level;
    for (double h : rimHeights(2.5f, 3)) EXPECT_GT(h, 1e-4) << "level 3 has softened";
    // At level 4, the rim rises less the sharper it is; infinitely sharp never leaves the plane.
    const std::vector<double> h0 = rimHeights(0.0f, 4), h1 = rimHeights(1.0f, 4), h25 = rimHeights(2.5f, 4),
                              h10 = rimHeights(10.0f, 4);
    for (int i = 0; i < 8; ++i) {
        EXPECT_GT(h0[i], h1[i]) << "rim vertex " << i;
        EXPECT_GT(h1[i], h25[i]) << "rim vertex " << i;
        EXPECT_GT(h25[i], h10[i]) << "rim vertex " << i;
        EXPECT_NEAR(h10[i], 0.0, 1e-6) << "rim vertex " << i;
    }
}

}  // namespace
}  // namespace quadtri::test
