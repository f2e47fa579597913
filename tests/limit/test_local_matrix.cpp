// The local subdivision matrix of a vertex configuration (far/limit/local_matrix.h), built on
// a mesh of regular sectors, against the same matrix read off the analyzer's tables on real
// meshes (the ring meshes of local_meshes.h refined two levels), and its spectrum against the
// closed forms of Catmull-Clark and Loop (as test_eigen derives them).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "far/limit/local_matrix.h"
#include <quadtri/far/refiner.h>
#include "tests/local_meshes.h"

namespace {

using namespace quadtri;
using namespace quadtri::test;
using namespace quadtri::internal;

const double kPi = std::acos(-1.0);

Options withScheme(Scheme s) {
    Options o;
    o.scheme = s;
    return o;
}

// The configuration of the centre of a ring mesh (closed, smooth), as the analyzer reads it.
VertexConfiguration closedFan(Scheme scheme, const std::string& ring) {
    const RingMesh r = buildRingMesh(ring);
    Refiner refiner(r.mesh.descriptor(), withScheme(scheme));
    return fanOf(refiner.level(0), r.center, withScheme(scheme))->configuration;
}

Eigen::MatrixXd toEigen(const LocalMatrix& m) {
    Eigen::MatrixXd S(m.size, m.size);
    for (int i = 0; i < m.size; ++i)
        for (int j = 0; j < m.size; ++j) S(i, j) = m.S[size_t(i) * m.size + j];
    return S;
}

std::vector<double> moduli(const Eigen::MatrixXd& S) {
    Eigen::EigenSolver<Eigen::MatrixXd> solver(S, false);
    std::vector<double> v;
    for (int i = 0; i < solver.eigenvalues().size(); ++i) v.push_back(std::abs(solver.eigenvalues()[i]));
    std::sort(v.rbegin(), v.rend());
    return v;
}

// The matrix at the centre's descendant in a refined ring mesh: rows the level-(L+1) ring
// neighbourhood of its child, columns the level-L one, both in ring-relative order.
Eigen::MatrixXd matrixOnMesh(const std::string& ring, Scheme scheme, int L, int rings, bool* settled,
                             const std::vector<int>& signature) {
    const RingMesh r = buildRingMesh(ring);
    const Options o = withScheme(scheme);
    Refiner refiner(r.mesh.descriptor(), o);
    refiner.refineUniform(L + 1, TopologyDetail::Full);
    int v = r.center;
    for (int l = 0; l < L; ++l) v = childOfVertex(refiner.level(l), v);
    const Topology& t = refiner.level(L);
    const Topology& child = refiner.level(L + 1);
    const int vChild = childOfVertex(t, v);
    const auto fan = fanOf(t, v, o);
    const auto fanChild = fanOf(child, vChild, o);
    const Neighbourhood n = gatherNeighbourhood(t, v, fan->faces[0], rings);
    const Neighbourhood nc = gatherNeighbourhood(child, vChild, fanChild->faces[0], rings);
    *settled = n.signature == signature;
    const int size = int(n.vertices.size());
    Eigen::MatrixXd S = Eigen::MatrixXd::Zero(size, size);
    if (int(nc.vertices.size()) != size) return S;
    const StencilTable& table = refiner.levelStencils(L + 1);
    for (int i = 0; i < size; ++i) {
        const std::vector<double> w = denseStencil(table, nc.vertices[i]);
        for (int j = 0; j < size; ++j) S(i, j) = w[n.vertices[j]];
    }
    return S;
}

TEST(LocalMatrix, OneRingUnderStamLoopAndThePureSchemes) {
    for (const std::string ring : {"QQQ", "QQQQ", "QQQQQQQ", "TTT", "TTTTTT", "QT", "QTT", "QQT", "QQTTT", "QTQT"}) {
        const auto m = buildLocalMatrix(closedFan(Scheme::StamLoop, ring), withScheme(Scheme::StamLoop));
        ASSERT_TRUE(m) << ring;
        const int nQ = int(std::count(ring.begin(), ring.end(), 'Q'));
        EXPECT_EQ(m->rings, 1) << ring;
        EXPECT_EQ(m->size, 1 + int(ring.size()) + nQ) << ring;
        for (int i = 0; i < m->size; ++i) {
            double sum = 0;
            for (int j = 0; j < m->size; ++j) sum += m->S[size_t(i) * m->size + j];
            EXPECT_NEAR(sum, 1.0, 1e-12) << ring << " row " << i;
        }
    }
}

TEST(LocalMatrix, CatmullClarkAndLoopSpectra) {
    for (int n = 3; n <= 8; ++n) {
        const double c2 = std::cos(2 * kPi / n);
        const double cc = (5 + c2 + std::cos(kPi / n) * std::sqrt(2 * (9 + c2))) / 16;
        for (Scheme s : {Scheme::CatmullClark, Scheme::StamLoop}) {
            const auto m = buildLocalMatrix(closedFan(s, std::string(size_t(n), 'Q')), withScheme(s));
            ASSERT_TRUE(m);
            const auto ev = moduli(toEigen(*m));
            EXPECT_NEAR(ev[0], 1.0, 1e-9);
            EXPECT_NEAR(ev[1], cc, 1e-9) << "valence " << n;
            EXPECT_NEAR(ev[2], cc, 1e-9) << "valence " << n;
        }
        for (Scheme s : {Scheme::Loop, Scheme::StamLoop}) {
            const auto m = buildLocalMatrix(closedFan(s, std::string(size_t(n), 'T')), withScheme(s));
            ASSERT_TRUE(m);
            const auto ev = moduli(toEigen(*m));
            EXPECT_NEAR(ev[1], 3.0 / 8 + 0.25 * c2, 1e-9) << "valence " << n;
            EXPECT_NEAR(ev[2], 3.0 / 8 + 0.25 * c2, 1e-9) << "valence " << n;
        }
    }
}

// The configuration's matrix is the one the analyzer's own level tables give at a vertex of that
// configuration two levels down a real mesh, entry for entry (float tables: 1e-6).
TEST(LocalMatrix, EqualsTheMatrixOfARefinedMesh) {
    for (Scheme s : {Scheme::StamLoop, Scheme::SchaeferWarren, Scheme::CatmarkButterfly}) {
        for (const std::string ring : {"QT", "QTT", "QQT", "QTTT", "QQTT", "QTQT", "QQTTT", "QQQTTT", "QTTTTT", "QQQQT"}) {
            SCOPED_TRACE(std::string(toString(s)) + " " + ring);
            const auto m = buildLocalMatrix(closedFan(s, ring), withScheme(s));
            ASSERT_TRUE(m);
            bool settled = false;
            const Eigen::MatrixXd onMesh = matrixOnMesh(ring, s, 2, m->rings, &settled, m->signature);
            EXPECT_TRUE(settled);
            ASSERT_EQ(onMesh.rows(), m->size);
            EXPECT_LE((onMesh - toEigen(*m)).cwiseAbs().maxCoeff(), 1e-6) << "rings " << m->rings;
        }
    }
}

// The neighbourhood each scheme needs (docs/limit_eigen.md, "The neighbourhood per scheme"): the
// 1-ring with quad corners under Stam-Loop and at catmark-butterfly's triangle-only vertices
// (Zorin's rule reads only the extraordinary end's ring); three rings where Schaefer-Warren
// unzips (a seam neighbour's vertex point reads the copy of the next seam vertex, whose unzip reads
// the one after); two at catmark-butterfly's seam (the wings of the triangle-side edge masks).
TEST(LocalMatrix, NeighbourhoodPerScheme) {
    struct Case {
        Scheme scheme;
        const char* ring;
        int rings;
    };
    const Case cases[] = {{Scheme::StamLoop, "QQTTT", 1}, {Scheme::SchaeferWarren, "QQTTT", 3},
                          {Scheme::SchaeferWarren, "QTT", 3},  {Scheme::SchaeferWarren, "QQQQ", 1},
                          {Scheme::CatmarkButterfly, "QQTTT", 2}, {Scheme::CatmarkButterfly, "TTTTT", 1},
                          {Scheme::CatmarkButterfly, "QQQQQ", 1}};
    for (const Case& c : cases) {
        const auto m = buildLocalMatrix(closedFan(c.scheme, c.ring), withScheme(c.scheme));
        ASSERT_TRUE(m) << c.ring;
        EXPECT_EQ(m->rings, c.rings) << toString(c.scheme) << " " << c.ring << " (" << m->size << " vertices)";
    }
}

}  // namespace
