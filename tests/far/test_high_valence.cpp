// Affine invariance at the extremes of valence, under every scheme: every mask of every level
// sums to 1, and translating the control points translates every refined point by the same
// vector. Low end: closed fans of two faces (two triangles or two quads back to back), single
// faces (corners of one face), non-manifold fins and bow ties, the tetrahedron and octahedron
// (Zorin's K = 3 and K = 4). High end: a UV sphere of 2000 segments, whose poles have valence
// 2000, refined to level 2. Its ctest TIMEOUT is the guard against rules that walk a pole's ring
// once per edge (catmark-butterfly's case took 30-70 s so; about a second when every rule costs
// the size of the mask it writes).
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include <quadtri/far/refiner.h>
#include "tests/local_meshes.h"
#include "tests/schemes/seam_support.h"
#include "tests/test_support.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri {
// Test names and messages show the scheme's name, not its bytes.
void PrintTo(Scheme scheme, std::ostream* out) { *out << toString(scheme); }
}  // namespace quadtri

namespace {

using namespace quadtri;
using namespace quadtri::test;
using namespace quadtri::internal;

// Loop takes no quads, which every shape here has.
const std::vector<Scheme> kSchemes = schemesTakingQuads();

struct Shape {
    std::string name;
    LocalMesh mesh;
    std::vector<double> xyz;  // 3 per vertex
};

// The weight sums of every level's masks, and the translation of the refined points, checked
// level by level in double. `tolerance` bounds the translation error: rounding grows with the
// coordinates' size and with the number of entries summed (2001 at a sphere's pole).
void expectAffineInvariance(const Shape& shape, const Options& options, int levels, double tolerance) {
    SCOPED_TRACE(shape.name + " under " + toString(options.scheme) + ", boundary " + toString(options.boundary) +
                 ", crease method " + toString(options.creaseMethod));
    Refiner refiner(shape.mesh.descriptor(), options);
    refiner.refineUniform(levels, TopologyDetail::Full);
    const double t[3] = {10.0, -20.0, 30.0};
    std::vector<double> points = shape.xyz, moved = shape.xyz;
    for (size_t i = 0; i < moved.size(); ++i) moved[i] += t[i % 3];
    for (int L = 1; L <= levels; ++L) {
        const StencilTableD table = doubleLevelTable(refiner, L);
        ASSERT_EQ(int(table.sizes.size()), refiner.faces(L).numVertices()) << "level " << L;
        for (size_t i = 0; i < table.sizes.size(); ++i) {
            double sum = 0.0;
            for (int k = 0; k < table.sizes[i]; ++k) sum += table.weights[size_t(table.offsets[i] + k)];
            ASSERT_NEAR(sum, 1.0, 1e-12) << "level " << L << " stencil " << i;
        }
        points = applyTable(table, points, 3);
        moved = applyTable(table, moved, 3);
        for (size_t i = 0; i < points.size(); ++i)
            ASSERT_NEAR(moved[i] - points[i], t[i % 3], tolerance) << "level " << L << " vertex " << i / 3;
    }
}

// Every scheme, both boundary rules that keep faces, both crease methods.
void expectAffineInvarianceEverywhere(const Shape& shape, int levels) {
    for (Scheme scheme : kSchemes)
        for (BoundaryInterpolation boundary : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner})
            for (CreaseMethod method : {CreaseMethod::Uniform, CreaseMethod::Chaikin}) {
                Options options;
                options.scheme = scheme;
                options.boundary = boundary;
                options.creaseMethod = method;
                expectAffineInvariance(shape, options, levels, 1e-12);
            }
}

Shape shape(const std::string& name, const std::vector<std::vector<int>>& faces, const std::vector<double>& xyz) {
    Shape s{name, {}, xyz};
    s.mesh.numVertices = int(xyz.size() / 3);
    for (const std::vector<int>& f : faces) s.mesh.addFace(f);
    return s;
}

const std::vector<double> kTriangle = {0, 0, 0, 1, 0, 0.2, 0.3, 1, -0.4};
const std::vector<double> kQuad = {0, 0, 0, 1, 0, 0.2, 1.1, 1, -0.4, -0.1, 0.9, 0.3};

// OBJ `f 1 2 3` / `f 1 3 2`: every vertex is interior with valence 2 (Zorin's K >= 5 formula
// there summed to 1.5). Its edge points are the plain Butterfly, the wings being the edge's ends.
TEST(LowValence, TwoTrianglesBackToBack) {
    expectAffineInvarianceEverywhere(shape("two triangles back to back", {{0, 1, 2}, {0, 2, 1}}, kTriangle), 3);
}

TEST(LowValence, TwoQuadsBackToBack) {
    expectAffineInvarianceEverywhere(shape("two quads back to back", {{0, 1, 2, 3}, {0, 3, 2, 1}}, kQuad), 3);
}

// A quad closed by two triangles: vertices 1 and 3 have valence 2 with a quad and a triangle
// (Stam-Loop's tabulated η of (nE, nQ) = (2, 1)), every quad edge is a seam.
TEST(LowValence, QuadClosedByTwoTriangles) {
    expectAffineInvarianceEverywhere(shape("quad and two triangles", {{0, 1, 2, 3}, {0, 3, 2}, {0, 2, 1}}, kQuad), 3);
}

// Corners of a single face: one face, two edges.
TEST(LowValence, SingleFaces) {
    expectAffineInvarianceEverywhere(shape("one triangle", {{0, 1, 2}}, kTriangle), 3);
    expectAffineInvarianceEverywhere(shape("one quad", {{0, 1, 2, 3}}, kQuad), 3);
}

// A semi-sharp edge on the valence-2 pillow: blends of crease and smooth masks (Chaikin too).
TEST(LowValence, CreasedPillow) {
    Shape s = shape("creased pillow", {{0, 1, 2}, {0, 2, 1}}, kTriangle);
    s.mesh.creasePairs = {0, 1};
    s.mesh.creaseWeights = {1.5f};
    expectAffineInvarianceEverywhere(s, 3);
}

// Three triangles on one edge (a non-manifold fin) and two faces sharing one vertex only.
TEST(LowValence, FinsAndBowTies) {
    const std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0.1, 0.5, 0.1, 1};
    expectAffineInvarianceEverywhere(shape("fin", {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}, xyz), 2);
    const std::vector<double> bowTie = {0, 0, 0, 1, 0.2, 0, 1, 1, 0.1, -1, -0.1, 0.2, -1, -1, 0, -0.2, -1.2, 0.3};
    expectAffineInvarianceEverywhere(shape("bow tie", {{0, 1, 2}, {0, 3, 4, 5}}, bowTie), 2);
}

// Closed triangle meshes whose every vertex takes Zorin's K = 3 and K = 4 special cases.
TEST(LowValence, TetrahedronAndOctahedron) {
    expectAffineInvarianceEverywhere(
        shape("tetrahedron", {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}, {0, 0, 0, 1, 0, 0.1, 0.2, 1, 0, 0.3, 0.4, 1}), 3);
    const std::vector<double> xyz = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    expectAffineInvarianceEverywhere(shape("octahedron", {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5},
                                                          {1, 2, 5}, {3, 1, 5}, {0, 3, 5}},
                                           xyz),
                                     3);
}

// A UV sphere: `segments` around, `rings` bands from pole to pole; the bands at the poles are
// triangle fans (the poles have valence `segments`), the others quads, or each quad split in two
// triangles when `triangulated` (then no vertex but the poles' neighbours touches a quad rule).
Shape uvSphere(int segments, int rings, bool triangulated) {
    Shape s{std::string(triangulated ? "triangulated" : "quad") + " UV sphere", {}, {0, 0, 1}};
    for (int r = 1; r < rings; ++r)
        for (int j = 0; j < segments; ++j) {
            const double theta = M_PI * r / rings, phi = 2 * M_PI * j / segments;
            s.xyz.insert(s.xyz.end(), {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
        }
    s.xyz.insert(s.xyz.end(), {0, 0, -1});
    const int south = int(s.xyz.size() / 3) - 1;
    s.mesh.numVertices = south + 1;
    auto at = [&](int r, int j) { return 1 + (r - 1) * segments + j % segments; };
    for (int j = 0; j < segments; ++j) s.mesh.addFace({0, at(1, j), at(1, j + 1)});
    for (int r = 1; r + 1 < rings; ++r)
        for (int j = 0; j < segments; ++j) {
            const int a = at(r, j), b = at(r + 1, j), c = at(r + 1, j + 1), d = at(r, j + 1);
            if (triangulated) {
                s.mesh.addFace({a, b, c});
                s.mesh.addFace({a, c, d});
            } else {
                s.mesh.addFace({a, b, c, d});
            }
        }
    for (int j = 0; j < segments; ++j) s.mesh.addFace({south, at(rings - 1, j + 1), at(rings - 1, j)});
    return s;
}

class HighValence : public testing::TestWithParam<Scheme> {};

// Level 2 of both spheres. Translation error: about 1e-16 per entry of coordinates up to 40,
// over masks of up to 2001 entries and two levels.
TEST_P(HighValence, UvSphereOf2000SegmentsAtLevel2) {
    Options options;
    options.scheme = GetParam();
    for (bool triangulated : {false, true}) expectAffineInvariance(uvSphere(2000, 4, triangulated), options, 2, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(EveryScheme, HighValence, testing::ValuesIn(kSchemes),
                         [](const testing::TestParamInfo<Scheme>& info) {
                             std::string name = toString(info.param);
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

}  // namespace
