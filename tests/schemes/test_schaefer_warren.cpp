// Schaefer-Warren (docs/schemes/schaefer_warren.md): the unzip masks read back from the analyzer,
// quadratic generation across the ordinary tri/quad seam (which tells it from Stam-Loop), curvature
// continuity across the seam of a refined torus, robustness on every mixed mesh, and equality with
// Stam-Loop wherever there is no seam.
//
// Every expected value below is derived in closed form in the comments; none is read off the
// analyzer's output.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "far/topology/refine_topology.h"
#include <quadtri/far/refiner.h>
#include "far/tables/level_stencils.h"
#include "far/schemes/unzip.h"
#include "tests/local_meshes.h"
#include "tests/schemes/seam_support.h"
#include "tests/test_support.h"
#include "far/internal/stencil_table_double.h"

namespace {

using namespace quadtri;
using namespace quadtri::test;

// ---------------------------------------------------------------------------------------------
// Helpers that do not use the analyzer's own notion of the network or of the seam.

// Stencil i of a double table as a map source -> weight (repeated indices summed).
std::map<int, double> row(const StencilTableD& table, int i) {
    std::map<int, double> w;
    for (int k = 0; k < table.sizes[i]; ++k) w[table.indices[table.offsets[i] + k]] += table.weights[table.offsets[i] + k];
    return w;
}

// Vertex v's copy for a piece: its row, or v itself where it does not split.
std::map<int, double> copyRow(const UnzippedCopies& copies, Piece piece, int v) {
    if (!copies.splits(v)) return {{v, 1.0}};
    const int r = copies.rowOf[size_t(v)];
    const std::vector<double>& weights = copies.weightsOf(piece);
    std::map<int, double> w;
    for (int k = copies.offsets[size_t(r)]; k < copies.offsets[size_t(r) + 1]; ++k)
        w[copies.indices[size_t(k)]] += weights[size_t(k)];
    return w;
}

// Largest |a - b| over the union of the supports (missing entries are 0).
double rowDistance(const std::map<int, double>& a, const std::map<int, double>& b) {
    double d = 0;
    for (const auto& [k, w] : a) {
        const auto it = b.find(k);
        d = std::max(d, std::fabs(w - (it == b.end() ? 0.0 : it->second)));
    }
    for (const auto& [k, w] : b)
        if (a.find(k) == a.end()) d = std::max(d, std::fabs(w));
    return d;
}

std::string describe(const std::map<int, double>& w) {
    std::string s;
    char buf[64];
    for (const auto& [k, x] : w) {
        std::snprintf(buf, sizeof buf, " %d:%.17g", k, x);
        s += buf;
    }
    return s;
}

// The tri/quad network straight from the face lists: an edge with exactly two faces, one a
// triangle and the other with four or more corners, whose sharpness is below 10 (infinitely
// sharp edges are never unzipped, docs/schemes/schaefer_warren.md, §1). Returns, per vertex, the
// far ends of its network edges.
std::vector<std::vector<int>> networkNeighbours(int numVertices, const std::vector<int>& faceSizes,
                                                const std::vector<int>& faceVerts,
                                                const std::vector<int>& creasePairs = {},
                                                const std::vector<float>& creaseSharpness = {}) {
    std::map<std::pair<int, int>, std::vector<int>> edgeFaceSizes;
    size_t offset = 0;
    for (int size : faceSizes) {
        for (int i = 0; i < size; ++i) {
            const int a = faceVerts[offset + i], b = faceVerts[offset + (i + 1) % size];
            edgeFaceSizes[{std::min(a, b), std::max(a, b)}].push_back(size);
        }
        offset += size;
    }
    std::map<std::pair<int, int>, float> sharp;
    for (size_t c = 0; c < creaseSharpness.size(); ++c) {
        const int a = creasePairs[2 * c], b = creasePairs[2 * c + 1];
        sharp[{std::min(a, b), std::max(a, b)}] = creaseSharpness[c];
    }
    std::vector<std::vector<int>> out(size_t(numVertices), std::vector<int>{});
    for (const auto& [e, sizes] : edgeFaceSizes) {
        if (sizes.size() != 2) continue;
        const bool seam = (sizes[0] == 3) != (sizes[1] == 3);
        const auto s = sharp.find(e);
        if (!seam || (s != sharp.end() && s->second >= 10.0f)) continue;
        out[size_t(e.first)].push_back(e.second);
        out[size_t(e.second)].push_back(e.first);
    }
    return out;
}

// v_t = v + (1/48) Σ_k (w_k − v), v_q = v − (1/48) Σ_k (w_k − v) (docs/schemes/schaefer_warren.md).
std::map<int, double> expectedCopy(int v, const std::vector<int>& network, Piece piece) {
    const double sign = piece == Piece::Triangle ? 1.0 : -1.0;
    std::map<int, double> w;
    w[v] = 1.0 - sign * double(network.size()) / 48.0;
    for (int n : network) w[n] += sign / 48.0;
    return w;
}

int findVertex(const std::vector<float>& xyz, double x, double y, double z) {
    for (size_t i = 0; i + 2 < xyz.size(); i += 3)
        if (xyz[i] == x && xyz[i + 1] == y && xyz[i + 2] == z) return int(i / 3);
    return -1;
}

// Every row of both copy tables against the closed form over the independently found network.
void expectAllRowsClosedForm(const Topology& t, const std::vector<std::vector<int>>& network, const std::string& what) {
    const UnzippedCopies copies = unzipCopies(t);
    ASSERT_EQ(copies.splitting.size(), size_t(t.numVertices)) << what;
    ASSERT_EQ(copies.rowOf.size(), size_t(t.numVertices)) << what;
    int splitting = 0;
    for (int v = 0; v < t.numVertices; ++v) splitting += copies.splits(v) ? 1 : 0;
    ASSERT_EQ(copies.offsets.size(), size_t(splitting) + 1) << what;
    ASSERT_EQ(copies.indices.size(), size_t(copies.offsets.back())) << what;
    for (Piece piece : {Piece::Triangle, Piece::Quad}) {
        ASSERT_EQ(copies.weightsOf(piece).size(), copies.indices.size()) << what;
        int bad = 0;
        for (int v = 0; v < t.numVertices; ++v) {
            const auto got = copyRow(copies, piece, v), want = expectedCopy(v, network[size_t(v)], piece);
            if (rowDistance(got, want) > 1e-15 && ++bad <= 5)
                ADD_FAILURE() << what << (piece == Piece::Triangle ? " v_t" : " v_q") << " of vertex " << v << " ("
                              << network[size_t(v)].size() << " network edges): got" << describe(got) << ", want"
                              << describe(want);
        }
        EXPECT_EQ(bad, 0) << what;
    }
}

// ---------------------------------------------------------------------------------------------
// 1. Unzip masks.

// split_plane: quads on Z² for x ≤ 0, triangles on (k, j + k/2) for x ≥ 0, y in [0, 8]. The
// seam is the column x = 0: vertices (0, y), y = 0..8, joined by the edges (0, y)-(0, y+1), each
// with a quad on its left and a triangle on its right. An interior seam vertex (0 < y < 8) has
// exactly two network edges, to (0, y − 1) and (0, y + 1): U_t = (1/48, 23/24, 1/48),
// U_q = (−1/48, 25/24, −1/48). The two end vertices (0, 0) and (0, 8) have one.
TEST(Unzip, TwoNetworkEdgesOnSplitPlane) {
    const io::ObjMesh mesh = io::readObj(meshPath("mixed/split_plane.obj"));
    Refiner refiner(mesh.descriptor(), mesh.applyTags(schemeOptions(Scheme::SchaeferWarren)));
    const Topology& t = refiner.level(0);
    const UnzippedCopies copies = unzipCopies(t);
    int checked = 0;
    for (int y = 1; y <= 7; ++y) {
        const int v = findVertex(mesh.positions, 0, y, 0), up = findVertex(mesh.positions, 0, y + 1, 0),
                  down = findVertex(mesh.positions, 0, y - 1, 0);
        ASSERT_GE(v, 0);
        ASSERT_GE(up, 0);
        ASSERT_GE(down, 0);
        const std::map<int, double> wantT{{down, 1.0 / 48}, {v, 23.0 / 24}, {up, 1.0 / 48}};
        const std::map<int, double> wantQ{{down, -1.0 / 48}, {v, 25.0 / 24}, {up, -1.0 / 48}};
        const auto gotT = copyRow(copies, Piece::Triangle, v), gotQ = copyRow(copies, Piece::Quad, v);
        EXPECT_LE(rowDistance(gotT, wantT), 1e-15) << "U_t at (0, " << y << "):" << describe(gotT);
        EXPECT_LE(rowDistance(gotQ, wantQ), 1e-15) << "U_q at (0, " << y << "):" << describe(gotQ);
        ++checked;
    }
    EXPECT_EQ(checked, 7);

    // Every row, including the identity rows off the network: exactly the 9 seam vertices move.
    const auto network = networkNeighbours(mesh.numVertices(), mesh.faceSizes, mesh.faceVerts);
    int onNetwork = 0;
    for (int v = 0; v < mesh.numVertices(); ++v)
        if (!network[size_t(v)].empty()) {
            ++onNetwork;
            EXPECT_EQ(mesh.positions[3 * size_t(v)], 0.0f) << "network vertex " << v << " off the seam column";
        }
    EXPECT_EQ(onNetwork, 9);
    expectAllRowsClosedForm(t, network, "split_plane");
    // Only they have rows: every other vertex keeps one position (its copies are itself).
    int splitting = 0;
    for (int v = 0; v < t.numVertices; ++v)
        if (copies.splits(v)) {
            ++splitting;
            EXPECT_FALSE(network[size_t(v)].empty()) << "vertex " << v << " splits off the network";
        }
    EXPECT_EQ(splitting, 9);
}

// checker_cube: the quad faces x = −1, y = −1, z = −1 meet the triangulated faces x = +1,
// y = +1, z = +1 along six cube edges forming a hexagon through the six vertices other than
// (−1,−1,−1) and (1,1,1). Each hexagon vertex lies on two network edges (on a closed manifold
// mesh the triangle/quad type changes an even number of times around a vertex, so a vertex never
// has three). (−1,−1,−1) (all quads) and (1,1,1) (all triangles) keep identity rows; the face
// diagonals of the triangulated faces join two triangles and are not in the network.
TEST(Unzip, CheckerCubeHexagon) {
    const io::ObjMesh mesh = io::readObj(meshPath("mixed/checker_cube.obj"));
    Refiner refiner(mesh.descriptor(), mesh.applyTags(schemeOptions(Scheme::SchaeferWarren)));
    const Topology& t = refiner.level(0);
    const auto network = networkNeighbours(mesh.numVertices(), mesh.faceSizes, mesh.faceVerts);
    const int allQuads = findVertex(mesh.positions, -1, -1, -1), allTris = findVertex(mesh.positions, 1, 1, 1);
    ASSERT_GE(allQuads, 0);
    ASSERT_GE(allTris, 0);
    for (int v = 0; v < mesh.numVertices(); ++v) {
        const size_t want = (v == allQuads || v == allTris) ? 0 : 2;
        EXPECT_EQ(network[size_t(v)].size(), want) << "vertex " << v;
    }
    const UnzippedCopies copies = unzipCopies(t);
    for (int v = 0; v < mesh.numVertices(); ++v) {
        if (network[size_t(v)].empty()) continue;
        const int a = network[size_t(v)][0], b = network[size_t(v)][1];
        EXPECT_LE(rowDistance(copyRow(copies, Piece::Triangle, v), {{a, 1.0 / 48}, {v, 23.0 / 24}, {b, 1.0 / 48}}), 1e-15)
            << v;
        EXPECT_LE(rowDistance(copyRow(copies, Piece::Quad, v), {{a, -1.0 / 48}, {v, 25.0 / 24}, {b, -1.0 / 48}}), 1e-15)
            << v;
    }
    EXPECT_EQ(rowDistance(copyRow(copies, Piece::Triangle, allQuads), {{allQuads, 1.0}}), 0.0);
    EXPECT_EQ(rowDistance(copyRow(copies, Piece::Quad, allTris), {{allTris, 1.0}}), 0.0);
    expectAllRowsClosedForm(t, network, "checker_cube");
}

// n = 3 needs an open fan (n = 4 a closed one): centre 0 with faces Q(0,1,6,2), T(0,2,3),
// Q(0,3,7,4), T(0,4,5); its interior edges 0-2 (Q|T), 0-3 (T|Q), 0-4 (Q|T) are network edges,
// 0-1 and 0-5 are boundary edges. U_t: centre 1 − 3/48 = 15/16, 1/48 at 2, 3, 4; U_q: 17/16 and
// −1/48. The closed ring Q T Q T has four network edges at its centre: 1 − 4/48 = 11/12.
TEST(Unzip, ThreeAndFourNetworkEdges) {
    LocalMesh fan;
    fan.numVertices = 8;
    fan.addFace({0, 1, 6, 2});
    fan.addFace({0, 2, 3});
    fan.addFace({0, 3, 7, 4});
    fan.addFace({0, 4, 5});
    {
        Refiner refiner(fan.descriptor(), schemeOptions(Scheme::SchaeferWarren));
        const Topology& t = refiner.level(0);
        EXPECT_LE(rowDistance(copyRow(unzipCopies(t), Piece::Triangle, 0),
                              {{0, 15.0 / 16}, {2, 1.0 / 48}, {3, 1.0 / 48}, {4, 1.0 / 48}}),
                  1e-15);
        EXPECT_LE(rowDistance(copyRow(unzipCopies(t), Piece::Quad, 0),
                              {{0, 17.0 / 16}, {2, -1.0 / 48}, {3, -1.0 / 48}, {4, -1.0 / 48}}),
                  1e-15);
        expectAllRowsClosedForm(t, networkNeighbours(fan.numVertices, fan.faceSizes, fan.faceVerts), "open QTQT fan");
    }
    const RingMesh ring = buildRingMesh("QTQT");
    Refiner refiner(ring.mesh.descriptor(), schemeOptions(Scheme::SchaeferWarren));
    const Topology& t = refiner.level(0);
    std::map<int, double> wantT{{ring.center, 11.0 / 12}}, wantQ{{ring.center, 13.0 / 12}};
    for (int p : ring.p) {
        wantT[p] = 1.0 / 48;
        wantQ[p] = -1.0 / 48;
    }
    EXPECT_LE(rowDistance(copyRow(unzipCopies(t), Piece::Triangle, ring.center), wantT), 1e-15);
    EXPECT_LE(rowDistance(copyRow(unzipCopies(t), Piece::Quad, ring.center), wantQ), 1e-15);
    expectAllRowsClosedForm(t, networkNeighbours(ring.mesh.numVertices, ring.mesh.faceSizes, ring.mesh.faceVerts),
                            "closed QTQT ring");
}

// An infinitely sharp seam edge (sharpness 10) leaves the network: tagging (0,3)-(0,4) on
// split_plane leaves (0,3) with its one network edge to (0,2): U_t = (1/48, 47/48), nothing at
// (0,4). A semi-sharp seam edge (2.5) stays in the network (unzipped on the smooth path).
TEST(Unzip, InfinitelySharpSeamEdgesAreNotInTheNetwork) {
    for (float sharpness : {10.0f, 2.5f}) {
        io::ObjMesh mesh = io::readObj(meshPath("mixed/split_plane.obj"));
        const int a = findVertex(mesh.positions, 0, 3, 0), b = findVertex(mesh.positions, 0, 4, 0),
                  below = findVertex(mesh.positions, 0, 2, 0), above = findVertex(mesh.positions, 0, 5, 0);
        ASSERT_TRUE(a >= 0 && b >= 0 && below >= 0 && above >= 0);
        mesh.creasePairs = {a, b};
        mesh.creaseSharpness = {sharpness};
        Refiner refiner(mesh.descriptor(), mesh.applyTags(schemeOptions(Scheme::SchaeferWarren)));
        const Topology& t = refiner.level(0);
        const int e = findEdge(t, a, b);
        ASSERT_GE(e, 0);
        const bool infinite = sharpness >= 10.0f;
        EXPECT_EQ(isNetworkEdge(t, e), !infinite) << "sharpness " << sharpness;
        const UnzippedCopies copies = unzipCopies(t);
        if (infinite) {
            const auto triA = copyRow(copies, Piece::Triangle, a), quadA = copyRow(copies, Piece::Quad, a),
                       triB = copyRow(copies, Piece::Triangle, b);
            EXPECT_LE(rowDistance(triA, {{below, 1.0 / 48}, {a, 47.0 / 48}}), 1e-15) << describe(triA);
            EXPECT_LE(rowDistance(quadA, {{below, -1.0 / 48}, {a, 49.0 / 48}}), 1e-15) << describe(quadA);
            EXPECT_LE(rowDistance(triB, {{above, 1.0 / 48}, {b, 47.0 / 48}}), 1e-15) << describe(triB);
        } else {
            EXPECT_LE(rowDistance(copyRow(copies, Piece::Triangle, a), {{below, 1.0 / 48}, {a, 23.0 / 24}, {b, 1.0 / 48}}), 1e-15);
            EXPECT_LE(rowDistance(copyRow(copies, Piece::Quad, b), {{a, -1.0 / 48}, {b, 25.0 / 24}, {above, -1.0 / 48}}), 1e-15);
        }
        expectAllRowsClosedForm(
            t, networkNeighbours(mesh.numVertices(), mesh.faceSizes, mesh.faceVerts, mesh.creasePairs, mesh.creaseSharpness),
            "split_plane with (0,3)-(0,4) at sharpness " + std::to_string(sharpness));
    }
}

// ---------------------------------------------------------------------------------------------
// 2. Quadratic generation at the seam (docs/schemes/schaefer_warren.md, §4).
//
// Derivation of the constants. For a box spline M with direction set Ξ (centred), and a
// quadratic f, Σ_j f(j) M(x − j) = f(x) + ½ tr(H Σ), H the Hessian of f and
// Σ = (1/12) Σ_{ξ∈Ξ} ξ ξᵀ the covariance of M (a sum of independent uniform segments ξ·U[0,1]).
// So control values Q f = f − ½ tr(H Σ) have the limit f exactly.
//  - Bicubic B-spline (quads on Z²): each axis four times, Σ = (1/3) I, so
//    Q f = f − f_xx/6 − f_yy/6.
//  - Loop (the 222 box spline) on the lattice (k, j + k/2): directions (0,1), (1,½), (1,−½), each
//    twice, Σ = (1/6) [(0,0;0,1) + (1,½;½,¼) + (1,−½;−½,¼)] = diag(1/3, 1/4), so
//    Q f = f − f_xx/6 − f_yy/8.
//  - Seam vertices (Schaefer-Warren): the mean of the two sides, f − f_xx/6 − 7 f_yy/48.
// One level halves the lattice spacing, Σ → Σ/4: a refined vertex p' holds f(p') − K/4 with K the
// constant of its region, once the refined vertex is far enough from the outer boundary that no
// boundary rule reaches it (three rings of the refined mesh).
struct Quadratic {
    const char* name;
    std::function<double(double, double)> f;
    double fxx, fyy;
};

const std::vector<Quadratic>& quadratics() {
    static const std::vector<Quadratic> q = {
        {"1", [](double, double) { return 1.0; }, 0, 0},
        {"x", [](double x, double) { return x; }, 0, 0},
        {"y", [](double, double y) { return y; }, 0, 0},
        {"x^2", [](double x, double) { return x * x; }, 2, 0},
        {"xy", [](double x, double y) { return x * y; }, 0, 0},
        {"y^2", [](double, double y) { return y * y; }, 0, 2},
    };
    return q;
}

// K of the region of a point with abscissa x: quads (x < 0), triangles (x > 0), seam (x = 0).
double regionConstant(const Quadratic& q, double x) {
    if (std::fabs(x) <= 1e-9) return q.fxx / 6 + 7 * q.fyy / 48;
    return x < 0 ? q.fxx / 6 + q.fyy / 6 : q.fxx / 6 + q.fyy / 8;
}

struct QuadraticResult {
    std::vector<double> maxError;  // per quadratic
    int checkedSeam = 0, checkedQuad = 0, checkedTri = 0;  // refined vertices checked, by region
};

QuadraticResult quadraticGeneration(Scheme scheme) {
    const io::ObjMesh mesh = io::readObj(meshPath("mixed/split_plane.obj"));
    Refiner refiner(mesh.descriptor(), mesh.applyTags(schemeOptions(scheme)));
    refiner.refineUniform(1, TopologyDetail::Full);
    const StencilTableD table = doubleLevelTable(refiner, 1);
    const Topology& fine = refiner.level(1);
    EXPECT_EQ(int(table.sizes.size()), fine.numVertices);

    std::vector<double> control(mesh.positions.begin(), mesh.positions.end());  // exact small numbers
    const std::vector<double> refined = applyTable(table, control, 3);

    // Rings from the outer boundary of the refined mesh: boundary edges have one face.
    std::vector<int> boundary;
    for (int e = 0; e < fine.numEdges(); ++e)
        if (fine.edgeFaceCount(e) == 1) {
            boundary.push_back(fine.edgeVerts[2 * e]);
            boundary.push_back(fine.edgeVerts[2 * e + 1]);
        }
    const std::vector<int> ring = bfsDistance(fine, boundary);

    QuadraticResult result;
    result.maxError.assign(quadratics().size(), 0.0);
    for (size_t qi = 0; qi < quadratics().size(); ++qi) {
        const Quadratic& q = quadratics()[qi];
        std::vector<double> values(size_t(mesh.numVertices()));
        for (int v = 0; v < mesh.numVertices(); ++v) {
            const double x = control[3 * size_t(v)], y = control[3 * size_t(v) + 1];
            values[size_t(v)] = q.f(x, y) - regionConstant(q, x);
        }
        const std::vector<double> out = applyTable(table, values, 1);
        for (int v = 0; v < fine.numVertices; ++v) {
            if (ring[size_t(v)] < 3) continue;
            const double x = refined[3 * size_t(v)], y = refined[3 * size_t(v) + 1];
            const double want = q.f(x, y) - regionConstant(q, x) / 4;
            result.maxError[qi] = std::max(result.maxError[qi], std::fabs(out[size_t(v)] - want));
            if (qi == 0) (std::fabs(x) <= 1e-9 ? result.checkedSeam : x < 0 ? result.checkedQuad : result.checkedTri)++;
        }
    }
    return result;
}

TEST(QuadraticGeneration, SchaeferWarrenReproducesAllQuadraticsAtTheSeam) {
    const QuadraticResult r = quadraticGeneration(Scheme::SchaeferWarren);
    // The split plane's level 1 has 17 seam vertices on x = 0 (y = 0, ½, ..., 8); rings >= 3 keeps
    // y = 1.5 .. 6.5: 11 of them, and a few hundred on each side.
    EXPECT_EQ(r.checkedSeam, 11);
    EXPECT_GT(r.checkedQuad, 100);
    EXPECT_GT(r.checkedTri, 100);
    for (size_t qi = 0; qi < quadratics().size(); ++qi) {
        std::printf("[ quadratic ] schaefer-warren  f = %-4s max |Sf - (f(p') - K/4)| = %.3g\n", quadratics()[qi].name,
                    r.maxError[qi]);
        EXPECT_LE(r.maxError[qi], 1e-10) << "f = " << quadratics()[qi].name;
    }
}

// The test has power: Stam-Loop is only C1 at the seam and misses y² there.
TEST(QuadraticGeneration, StamLoopMissesYSquaredAtTheSeam) {
    const QuadraticResult r = quadraticGeneration(Scheme::StamLoop);
    for (size_t qi = 0; qi < quadratics().size(); ++qi)
        std::printf("[ quadratic ] stam-loop        f = %-4s max |Sf - (f(p') - K/4)| = %.3g\n", quadratics()[qi].name,
                    r.maxError[qi]);
    EXPECT_GT(r.maxError[5], 1e-3) << "y^2 under stam-loop";
}

// ---------------------------------------------------------------------------------------------
// 4. Every mixed mesh refines to level 4 under schaefer-warren: per-level stencils sum to 1,
// weights and positions are finite.

const char* const kMixedMeshes[] = {
    "mixed/book_nonmanifold.obj", "mixed/checker_cube.obj", "mixed/cylinder_capped.obj",
    "mixed/cylinder_capped_creased.obj", "mixed/mixed_torus.obj", "mixed/split_plane.obj",
    "osd/catmark_rook.obj", "osd/catmark_pole8.obj", "osd/catmark_pyramid.obj",
};

std::string meshTestName(const testing::TestParamInfo<const char*>& info) {
    std::string name = info.param;
    name = name.substr(name.find('/') + 1);
    return testNameOf(name.substr(0, name.rfind('.')));
}

class SchaeferWarrenMixed : public testing::TestWithParam<const char*> {};

TEST_P(SchaeferWarrenMixed, RefinesToLevel4) {
    constexpr int kLevel = 4;
    const RefinedMesh r = refineMesh(GetParam(), kLevel, schemeOptions(Scheme::SchaeferWarren));
    ASSERT_EQ(r.refiner->options().scheme, Scheme::SchaeferWarren);
    for (int L = 1; L <= kLevel; ++L) {
        const StencilTable& table = r.refiner->levelStencils(L);
        ASSERT_EQ(table.numStencils(), r.refiner->level(L).numVertices) << "level " << L;
        ASSERT_EQ(table.numSourceVertices, r.refiner->level(L - 1).numVertices) << "level " << L;
        int badSum = 0, badWeight = 0, badIndex = 0;
        double worst = 0;
        for (int i = 0; i < table.numStencils(); ++i) {
            for (int k = 0; k < table.size(i); ++k) {
                const int j = table.offsets[i] + k;
                if (!std::isfinite(table.weightsOf(i)[k])) ++badWeight;
                if (table.indices[size_t(j)] < 0 || table.indices[size_t(j)] >= table.numSourceVertices) ++badIndex;
            }
            const double error = std::fabs(stencilWeightSum(table, i) - 1.0);
            worst = std::max(worst, std::isfinite(error) ? error : INFINITY);
            if (!(error <= 1e-6)) ++badSum;
        }
        EXPECT_EQ(badWeight, 0) << "level " << L << ": NaN or infinite weights";
        EXPECT_EQ(badIndex, 0) << "level " << L << ": indices out of range";
        EXPECT_EQ(badSum, 0) << "level " << L << ": stencils whose weights miss 1 by more than 1e-6 (worst "
                             << worst << ")";
        const std::vector<float>& p = r.positions.at(size_t(L));
        ASSERT_EQ(p.size(), 3 * size_t(r.refiner->level(L).numVertices));
        EXPECT_EQ(std::count_if(p.begin(), p.end(), [](float x) { return !std::isfinite(x); }), 0)
            << "level " << L << ": NaN or infinite positions";
    }
    std::printf("[ sw level 4 ] %-36s %7d vertices\n", GetParam(), r.refiner->level(kLevel).numVertices);
}

INSTANTIATE_TEST_SUITE_P(Meshes, SchaeferWarrenMixed, testing::ValuesIn(kMixedMeshes), meshTestName);

// ---------------------------------------------------------------------------------------------
// 5. Schaefer-Warren is Stam-Loop wherever there is no seam (no vertex has copies), and the
// scheme option is live on the mixed meshes.

// Positions of levels 1..maxLevel through the refiner's per-level (float) tables, accumulated
// in double so that the comparison sees the tables, not float rounding of the arithmetic.
std::vector<std::vector<double>> levelPositions(const Refiner& refiner, const std::vector<float>& control) {
    std::vector<std::vector<double>> out{std::vector<double>(control.begin(), control.end())};
    for (int L = 1; L <= refiner.maxLevel(); ++L)
        out.push_back(applyTable(toDoubleTable(refiner.levelStencils(L)), out.back(), 3));
    return out;
}

// Largest distance between the two schemes' positions at any level 1..maxLevel, over the
// bounding-box diagonal of the control mesh (same topology, so vertices match by index).
double maxRelativeDifference(const char* path, int maxLevel) {
    const io::ObjMesh mesh = io::readObj(meshPath(path));
    std::vector<std::vector<double>> p[2];
    const Scheme schemes[2] = {Scheme::SchaeferWarren, Scheme::StamLoop};
    for (int i = 0; i < 2; ++i) {
        Refiner refiner(mesh.descriptor(), mesh.applyTags(schemeOptions(schemes[i])));
        refiner.refineUniform(maxLevel);
        p[i] = levelPositions(refiner, mesh.positions);
    }
    const double diagonal = boundingBoxDiagonal(mesh.positions);
    double worst = 0;
    for (int L = 1; L <= maxLevel; ++L) {
        const std::vector<double>&a = p[0].at(size_t(L)), &b = p[1].at(size_t(L));
        EXPECT_EQ(a.size(), b.size()) << path << " level " << L;
        if (a.size() != b.size()) return INFINITY;
        for (size_t i = 0; i + 2 < a.size(); i += 3) {
            double d2 = 0;
            for (int c = 0; c < 3; ++c) d2 += (a[i + c] - b[i + c]) * (a[i + c] - b[i + c]);
            if (!std::isfinite(d2)) return INFINITY;
            worst = std::max(worst, std::sqrt(d2) / diagonal);
        }
    }
    return worst;
}

TEST(SchaeferWarrenVsStamLoop, EqualOnPureMeshes) {
    const struct {
        const char* mesh;
        int level;
    } cases[] = {{"osd/catmark_cube.obj", 4}, {"osd/catmark_torus_creases0.obj", 4}, {"osd/loop_icosahedron.obj", 4},
                 {"osd/catmark_pawn.obj", 3}};
    for (const auto& c : cases) {
        const io::ObjMesh mesh = io::readObj(meshPath(c.mesh));
        const auto network = networkNeighbours(mesh.numVertices(), mesh.faceSizes, mesh.faceVerts);
        ASSERT_TRUE(std::all_of(network.begin(), network.end(), [](const std::vector<int>& n) { return n.empty(); }))
            << c.mesh << " is not a pure mesh";
        const double d = maxRelativeDifference(c.mesh, c.level);
        // The masks themselves, in double, level by level over the same topology.
        Refiner sw(mesh.descriptor(), mesh.applyTags(schemeOptions(Scheme::SchaeferWarren)));
        Refiner sl(mesh.descriptor(), mesh.applyTags(schemeOptions(Scheme::StamLoop)));
        sw.refineUniform(c.level - 1, TopologyDetail::Full);  // level c.level - 1 is a parent below
        sl.refineUniform(c.level - 1, TopologyDetail::Full);  // level c.level - 1 is a parent below
        double weights = 0;
        for (int L = 1; L <= c.level; ++L) {
            // A pure level splits no vertex: no copy rows, no per-vertex array.
            const UnzippedCopies copies = unzipCopies(sw.level(L - 1));
            EXPECT_TRUE(copies.splitting.empty() && copies.rowOf.empty() && copies.offsets.empty() &&
                        copies.indices.empty() && copies.triangleWeights.empty() && copies.quadWeights.empty())
                << c.mesh << " level " << L - 1;
            const StencilTableD a = doubleLevelTable(sw, L), b = doubleLevelTable(sl, L);
            ASSERT_EQ(a.sizes.size(), b.sizes.size());
            for (size_t i = 0; i < a.sizes.size(); ++i)
                weights = std::max(weights, rowDistance(row(a, int(i)), row(b, int(i))));
        }
        std::printf("[ sw vs sl   ] %-36s levels 1-%d  max |sw - sl| / diagonal = %.3g, max weight difference %.3g\n",
                    c.mesh, c.level, d, weights);
        EXPECT_LE(d, 1e-6) << c.mesh;
        EXPECT_LE(weights, 1e-12) << c.mesh;
    }
}

TEST(SchaeferWarrenVsStamLoop, DifferOnMixedMeshes) {
    for (const char* mesh : kMixedMeshes) {
        const double d = maxRelativeDifference(mesh, 2);
        std::printf("[ sw vs sl   ] %-36s levels 1-2  max |sw - sl| / diagonal = %.3g\n", mesh, d);
        EXPECT_GT(d, 1e-4) << mesh;
    }
}

}  // namespace
