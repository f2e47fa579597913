// Eigen-analysis of local subdivision matrices built from the analyzer's own level-1 masks.
//
// Around an interior vertex c with nE edges and nQ quads the local vertex set is
// {c, p_0..p_{nE-1}, q_0..q_{nQ-1}} (centre, edge neighbours, opposite quad corners). One level
// maps it onto the same configuration: c -> vertex point of c, p_i -> edge point of c-p_i,
// q_j -> face point of quad j. S (1 + nE + nQ square) holds the analyzer's weights of those
// level-1 vertices over the level-0 local vertices; any weight outside the set fails the test.
//
// Checks: Catmull-Clark's and Loop's subdominant eigenvalues in closed form, the ordinary seam's
// spectrum, and the eta table (docs/schemes/stam_loop.md, §3) reproduced from the eigen-criterion
// (subsubdominant eigenvalue = lambda_1^2, or a zero eigenvalue for (3,1) and (3,2)).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <string>
#include <vector>

#include <quadtri/far/refiner.h>
#include "tests/local_meshes.h"

namespace {

using namespace quadtri;
using namespace quadtri::test;

const double kPi = std::acos(-1.0);

struct LocalMatrix {
    std::string ring;
    int nE = 0, nQ = 0;
    Eigen::MatrixXd S;   // rows: level-1 local vertices; columns: level-0 local vertices
    double outside = 0;  // largest |weight| a local row puts on a vertex outside the set
};

// The local vertex set of one level: centre, edge neighbours (ring order), opposite quad corners.
struct LocalSet {
    int center = -1;
    std::vector<int> p, q;
};

// The face of level t at `c` whose corners include a and b (a quad when `quad`), or -1.
int faceAt(const Topology& t, int c, int a, int b, bool quad) {
    for (int i = t.vertFaceOffsets[c]; i < t.vertFaceOffsets[c + 1]; ++i) {
        const int f = t.vertFaces[i];
        if ((t.faceSize(f) == 4) != quad)
            continue;
        bool hasA = false, hasB = false;
        for (int k = t.faceOffsets[f]; k < t.faceOffsets[f + 1]; ++k) {
            hasA = hasA || t.faceVerts[k] == a;
            hasB = hasB || t.faceVerts[k] == b;
        }
        if (hasA && hasB)
            return f;
    }
    return -1;
}

// The η table and the eigenvalues below are Stam-Loop's (Schaefer-Warren unzips seam vertices).
Options stamLoopOptions() {
    Options o;
    o.scheme = Scheme::StamLoop;
    return o;
}

// S of level `level` (>= 1): rows are the level-`level` children of the local set of level-1,
// columns that local set. At level 1 the set is the ring mesh's own c, p_i, q_j; one level on,
// it is c's vertex point, the edge points of c's edges and the face points of c's quads.
LocalMatrix buildLocalMatrix(const std::string& ring, const Options& options = stamLoopOptions(), int level = 1) {
    const RingMesh r = buildRingMesh(ring);
    Refiner refiner(r.mesh.descriptor(), options);
    refiner.refineUniform(level);

    LocalMatrix m;
    m.ring = ring;
    m.nE = int(ring.size());
    m.nQ = int(r.quadOf.size());
    const int N = 1 + m.nE + m.nQ;

    LocalSet set;
    set.center = r.center;
    set.p = r.p;
    for (int k = 0; k < m.nQ; ++k)
        set.q.push_back(r.q[r.quadOf[k]]);
    std::vector<int> rows;
    for (int L = 0; L < level; ++L) {
        const Topology& t = refiner.level(L);
        LocalSet next;
        next.center = childOfVertex(t, set.center);
        for (int i = 0; i < m.nE; ++i) {
            const int e = edgeBetween(t, set.center, set.p[i]);
            if (e < 0)
                throw std::runtime_error("level " + std::to_string(L) + ": edge c-p" + std::to_string(i) + " missing");
            next.p.push_back(childOfEdge(t, e));
        }
        for (int k = 0; k < m.nQ; ++k) {
            const int f = faceAt(t, set.center, set.p[r.quadOf[k]], set.q[k], true);
            if (f < 0)
                throw std::runtime_error("level " + std::to_string(L) + ": quad " + std::to_string(k) + " missing");
            next.q.push_back(childOfFace(t, f));
        }
        if (L + 1 == level) {
            rows.push_back(next.center);
            rows.insert(rows.end(), next.p.begin(), next.p.end());
            rows.insert(rows.end(), next.q.begin(), next.q.end());
        } else {
            set = next;
        }
    }
    const StencilTable& table = refiner.levelStencils(level);
    std::vector<int> local(size_t(table.numSourceVertices), -1);
    local[set.center] = 0;
    for (int i = 0; i < m.nE; ++i)
        local[set.p[i]] = 1 + i;
    for (int k = 0; k < m.nQ; ++k)
        local[set.q[k]] = 1 + m.nE + k;

    m.S = Eigen::MatrixXd::Zero(N, N);
    for (int row = 0; row < N; ++row) {
        const std::vector<double> w = denseStencil(table, rows[row]);
        for (size_t v = 0; v < w.size(); ++v) {
            if (local[v] >= 0)
                m.S(row, local[v]) += w[v];
            else
                m.outside = std::max(m.outside, std::fabs(w[v]));
        }
    }
    return m;
}

// Eigenvalues sorted by decreasing magnitude.
std::vector<std::complex<double>> spectrum(const Eigen::MatrixXd& S) {
    Eigen::EigenSolver<Eigen::MatrixXd> solver(S, false);
    const auto& ev = solver.eigenvalues();
    std::vector<std::complex<double>> v(ev.data(), ev.data() + ev.size());
    std::stable_sort(v.begin(), v.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
    return v;
}

std::string show(const std::vector<std::complex<double>>& v) {
    std::string s;
    for (auto x : v) {
        char buf[64];
        std::snprintf(buf, sizeof buf, " %.7f%+.1ei", x.real(), x.imag());
        s += buf;
    }
    return s;
}

// The averaged (uncorrected) vertex v1 of the centre (docs/schemes/stam_loop.md, §1), expanded over
// the level-0 local vertices: alpha c + beta sum m_i + gamma sum F_j with m_i = (c + p_i)/2, F_j
// the quad centroids, alpha = 1/(1 + nE/2 + nQ/4), beta = alpha/2, gamma = alpha/4.
Eigen::VectorXd averagedCentre(const std::string& ring) {
    const int nE = int(ring.size());
    const int nQ = int(std::count(ring.begin(), ring.end(), 'Q'));
    const double alpha = 1.0 / (1.0 + nE / 2.0 + nQ / 4.0), beta = alpha / 2, gamma = alpha / 4;
    Eigen::VectorXd v = Eigen::VectorXd::Zero(1 + nE + nQ);
    v[0] += alpha;
    for (int i = 0; i < nE; ++i) {
        v[0] += beta / 2;
        v[1 + i] += beta / 2;
    }
    int k = 0;
    for (int i = 0; i < nE; ++i) {
        if (ring[i] != 'Q')
            continue;
        for (int idx : {0, 1 + i, 1 + (i + 1) % nE, 1 + nE + k})
            v[idx] += gamma / 4;
        ++k;
    }
    return v;
}

// The local configuration maps onto itself: the matrix of level 2 over the level-1 local set
// (built from the level-2 masks) is the level-1 matrix, so its eigenvalues govern every level.
TEST(EigenLocalMatrix, StationaryAcrossLevels) {
    for (const std::string ring :
         {"QQQ", "QQQQQ", "TTTT", "TTTTTTT", "QT", "QTT", "QQT", "QTTT", "QQTT", "QQQT", "QQTTT"}) {
        const LocalMatrix m1 = buildLocalMatrix(ring, stamLoopOptions(), 1);
        const LocalMatrix m2 = buildLocalMatrix(ring, stamLoopOptions(), 2);
        EXPECT_LE(m2.outside, 1e-7) << ring;
        EXPECT_LE((m1.S - m2.S).cwiseAbs().maxCoeff(), 1e-6) << ring << "\nlevel 1:\n"
                                                             << m1.S << "\nlevel 2:\n"
                                                             << m2.S;
    }
}

// ---- Catmull-Clark and Loop ---------------------------------------------------------------

double catmullClarkSubdominant(int n) {
    const double c2 = std::cos(2 * kPi / n);
    return (5 + c2 + std::cos(kPi / n) * std::sqrt(2 * (9 + c2))) / 16;
}

// Sanity of the closed form itself: n = 4 is the regular bicubic case, lambda = 1/2.
TEST(EigenCatmullClark, ClosedFormRegular) {
    EXPECT_NEAR(catmullClarkSubdominant(4), 0.5, 1e-15);
}

TEST(EigenCatmullClark, SubdominantEigenvalue) {
    for (int n = 3; n <= 8; ++n) {
        const LocalMatrix m = buildLocalMatrix(std::string(size_t(n), 'Q'));
        EXPECT_LE(m.outside, 1e-7) << "valence " << n << ": local masks read outside the 1-ring";
        const auto ev = spectrum(m.S);
        ASSERT_EQ(int(ev.size()), 1 + 2 * n);
        const double lambda = catmullClarkSubdominant(n);
        SCOPED_TRACE("valence " + std::to_string(n) + ", spectrum" + show(ev));
        EXPECT_NEAR(ev[0].real(), 1.0, 1e-6);
        EXPECT_NEAR(ev[0].imag(), 0.0, 1e-6);
        EXPECT_NEAR(ev[1].real(), lambda, 1e-6);
        EXPECT_NEAR(ev[2].real(), lambda, 1e-6);  // a double eigenvalue
        EXPECT_NEAR(ev[1].imag(), 0.0, 1e-6);
        EXPECT_NEAR(ev[2].imag(), 0.0, 1e-6);
        EXPECT_LT(std::abs(ev[3]), lambda - 1e-3);  // and strictly subdominant
    }
}

TEST(EigenLoop, SubdominantEigenvalue) {
    for (int n = 3; n <= 8; ++n) {
        const LocalMatrix m = buildLocalMatrix(std::string(size_t(n), 'T'));
        EXPECT_LE(m.outside, 1e-7) << "valence " << n;
        const auto ev = spectrum(m.S);
        ASSERT_EQ(int(ev.size()), 1 + n);
        const double lambda = 3.0 / 8 + 0.25 * std::cos(2 * kPi / n);
        SCOPED_TRACE("valence " + std::to_string(n) + ", spectrum" + show(ev));
        EXPECT_NEAR(ev[0].real(), 1.0, 1e-6);
        EXPECT_NEAR(ev[1].real(), lambda, 1e-6);
        EXPECT_NEAR(ev[2].real(), lambda, 1e-6);
        EXPECT_NEAR(ev[1].imag(), 0.0, 1e-6);
        EXPECT_LT(std::abs(ev[3]), lambda - 1e-3);
        // Loop's rotation-invariant block [[1 - n beta, n beta], [3/8, 5/8]] adds 5/8 - n beta.
        const double c = 3.0 / 8 + 0.25 * std::cos(2 * kPi / n);
        const double nBeta = 5.0 / 8 - c * c;
        bool found = false;
        for (auto x : ev)
            found = found || std::abs(x - (5.0 / 8 - nBeta)) < 1e-6;
        EXPECT_TRUE(found) << "no eigenvalue 5/8 - n beta = " << 5.0 / 8 - nBeta;
    }
}

// The ordinary seam vertex (two quads, three triangles): 1, 1/2, 1/2, 1/4, 1/4, 1/4
// (docs/schemes/stam_loop.md, §4).
TEST(EigenSeam, OrdinarySeamSpectrum) {
    const LocalMatrix m = buildLocalMatrix("QQTTT");
    EXPECT_LE(m.outside, 1e-7);
    const auto ev = spectrum(m.S);
    SCOPED_TRACE("spectrum" + show(ev));
    const double expected[] = {1, 0.5, 0.5, 0.25, 0.25, 0.25};
    for (int i = 0; i < 6; ++i)
        EXPECT_NEAR(std::abs(ev[i]), expected[i], 1e-5) << "eigenvalue " << i;
    EXPECT_LT(std::abs(ev[6]), 0.25 - 1e-3);
}

// ---- The eta table ------------------------------------------------------------------------

struct EtaCase {
    const char* ring;  // quads first, then triangles (the (4,2) table value is for adjacent quads)
    int nE, nQ;
    double eta;  // docs/schemes/stam_loop.md, §3
    bool zeroCriterion;
};

const EtaCase kEtaTable[] = {
    {"QT", 2, 1, -0.20505, false},  {"QTT", 3, 1, 54.0 / 67, true}, {"QQT", 3, 2, 8.0 / 13, true},
    {"QTTT", 4, 1, 0.34792, false}, {"QQTT", 4, 2, 0.21380, false}, {"QQQT", 4, 3, 0.10550, false},
};

// Reads eta back from the analyzer's centre row r = (1 + eta) v1 - eta e_c, with v1 the
// averaged vertex of docs/schemes/stam_loop.md, §1: eta = (r_c - v1_c) / (v1_c - 1).
double readEta(const LocalMatrix& m) {
    const Eigen::VectorXd v1 = averagedCentre(m.ring);
    return (m.S(0, 0) - v1[0]) / (v1[0] - 1.0);
}

// S with the analyzer's centre row re-parametrized: r(eta) = (1 + eta) v1A - eta e_c, where v1A is
// recovered from the analyzer's own row and its read-back eta (all other rows untouched).
std::function<Eigen::MatrixXd(double)> family(const LocalMatrix& m) {
    const double etaHat = readEta(m);
    Eigen::VectorXd v1A = m.S.row(0).transpose();
    v1A[0] += etaHat;
    v1A /= (1.0 + etaHat);
    const Eigen::MatrixXd S = m.S;
    return [S, v1A](double eta) {
        Eigen::MatrixXd T = S;
        T.row(0) = ((1.0 + eta) * v1A).transpose();
        T(0, 0) -= eta;
        return T;
    };
}

// |nu_3| - |nu_1|^2: the eigenvalue after the subdominant pair against the subdominant squared.
double curvatureCriterion(const Eigen::MatrixXd& S) {
    const auto ev = spectrum(S);
    return std::abs(ev[3]) - std::norm(ev[1]);
}

// Roots of the criterion on [-1, 1.5] (scan at 0.01, then bisection); the one nearest the
// uncorrected scheme (smallest |eta|) is returned, NaN if there is none.
double solveCurvatureEta(const std::function<Eigen::MatrixXd(double)>& S) {
    auto f = [&](double eta) { return curvatureCriterion(S(eta)); };
    double best = NAN;
    const double step = 0.01;
    double x0 = -1.0, f0 = f(x0);
    for (int i = 1; i <= 250; ++i) {
        const double x1 = -1.0 + i * step, f1 = f(x1);
        if ((f0 < 0) != (f1 < 0)) {
            double lo = x0, hi = x1, flo = f0;
            for (int it = 0; it < 60; ++it) {
                const double mid = 0.5 * (lo + hi), fm = f(mid);
                if ((fm < 0) == (flo < 0)) {
                    lo = mid;
                    flo = fm;
                } else {
                    hi = mid;
                }
            }
            const double root = 0.5 * (lo + hi);
            if (std::fabs(f(root)) < 1e-8 && (std::isnan(best) || std::fabs(root) < std::fabs(best)))
                best = root;
        }
        x0 = x1;
        f0 = f1;
    }
    return best;
}

TEST(EigenEta, AnalyzerMasksHaveTheTableEta) {
    for (const EtaCase& c : kEtaTable) {
        SCOPED_TRACE(std::string(c.ring) + " (" + std::to_string(c.nE) + "," + std::to_string(c.nQ) + ")");
        const LocalMatrix m = buildLocalMatrix(c.ring);
        ASSERT_EQ(m.nE, c.nE);
        ASSERT_EQ(m.nQ, c.nQ);
        EXPECT_LE(m.outside, 1e-7) << "the local masks read outside the 1-ring";
        // The centre row is (1 + eta) v1 - eta e_c for one eta, everywhere, not just at c.
        const double eta = readEta(m);
        Eigen::VectorXd expected = (1.0 + eta) * averagedCentre(c.ring);
        expected[0] -= eta;
        EXPECT_LE((m.S.row(0).transpose() - expected).cwiseAbs().maxCoeff(), 1e-6)
            << "centre row " << m.S.row(0)
            << "\n not of the form (1+eta) v1 - eta c; v1 = " << averagedCentre(c.ring).transpose();
        // The analyzer uses the exact fractions and the 5-digit values (floats: ~1e-7).
        EXPECT_NEAR(eta, c.eta, c.zeroCriterion ? 1e-6 : 1e-5);
        // Every other row: partition of unity (the family below keeps the centre row's sum at 1).
        for (int r = 0; r < m.S.rows(); ++r)
            EXPECT_NEAR(m.S.row(r).sum(), 1.0, 1e-6) << "row " << r;
    }
}

TEST(EigenEta, CriterionHoldsAtTheAnalyzersEta) {
    for (const EtaCase& c : kEtaTable) {
        const LocalMatrix m = buildLocalMatrix(c.ring);
        const auto ev = spectrum(m.S);
        SCOPED_TRACE(std::string(c.ring) + ", spectrum" + show(ev));
        EXPECT_NEAR(std::abs(ev[0]), 1.0, 1e-6);
        if (c.zeroCriterion) {
            EXPECT_LT(std::abs(ev.back()), 1e-6) << "smallest eigenvalue is not 0";
        } else {
            // The 5-digit eta gives nu_3 = nu_1^2 to a few 1e-5.
            EXPECT_LT(std::fabs(curvatureCriterion(m.S)), 5e-4);
        }
    }
}

TEST(EigenEta, TableReproducedByEigenAnalysis) {
    for (const EtaCase& c : kEtaTable) {
        SCOPED_TRACE(c.ring);
        const LocalMatrix m = buildLocalMatrix(c.ring);
        const auto S = family(m);
        if (c.zeroCriterion) {
            // Only the centre row depends on eta, linearly, so det S(eta) is affine in eta:
            // its single root is where the smallest eigenvalue reaches 0.
            const double d0 = S(0.0).determinant(), d1 = S(1.0).determinant();
            ASSERT_GT(std::fabs(d1 - d0), 1e-12);
            const double eta = -d0 / (d1 - d0);
            EXPECT_NEAR(eta, c.eta, 1e-6);
            EXPECT_LT(std::abs(spectrum(S(eta)).back()), 1e-9);
        } else {
            const double eta = solveCurvatureEta(S);
            ASSERT_FALSE(std::isnan(eta)) << "no eta with nu_3 = nu_1^2 in [-1, 1.5]";
            EXPECT_NEAR(eta, c.eta, 5e-4);
        }
    }
}

// The (4,2) value belongs to the arrangement with the two quads adjacent: with alternating quads
// (QTQT) the criterion's root is elsewhere (the table has one value per (nE, nQ)).
TEST(EigenEta, AlternatingFourTwoIsADifferentConfiguration) {
    const LocalMatrix adjacent = buildLocalMatrix("QQTT");
    const LocalMatrix alternating = buildLocalMatrix("QTQT");
    EXPECT_NEAR(readEta(alternating), readEta(adjacent), 1e-6) << "eta depends only on (nE, nQ)";
    const double etaAlternating = solveCurvatureEta(family(alternating));
    ASSERT_FALSE(std::isnan(etaAlternating));
    EXPECT_GT(std::fabs(etaAlternating - 0.21380), 1e-2);
}

// Every other mixed configuration is uncorrected: eta = 0.
TEST(EigenEta, OtherMixedConfigurationsAreUncorrected) {
    for (const std::string ring : {"QTTTT", "QQTTT", "QQQTT", "QQQQT", "QQQTTT", "QTQTQT", "QTTTTTT", "QQQQQQT"}) {
        const LocalMatrix m = buildLocalMatrix(ring);
        EXPECT_LE(m.outside, 1e-7) << ring;
        EXPECT_NEAR(readEta(m), 0.0, 1e-6) << ring;
        EXPECT_LE((m.S.row(0).transpose() - averagedCentre(ring)).cwiseAbs().maxCoeff(), 1e-6) << ring;
    }
}

}  // namespace
