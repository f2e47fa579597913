// Curvature across the tri/quad seam of mixed_torus: Schaefer-Warren's jump shrinks with the
// level (C2), Stam-Loop's does not (C1).
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
// 3. Curvature across the seam of mixed_torus.

// Gaussian and mean curvature per vertex from a least-squares fit of the height function
// z = a x² + b xy + c y² + d x + e y over the other corners of the faces around the vertex (8 on
// a regular quad lattice, 6 on a regular triangle lattice), in a frame whose z axis is the
// area-weighted face normal. The rings are centrally symmetric on a regular lattice, so the odd
// (cubic) terms of the surface do not leak into the quadratic coefficients.
// (The angle defect is no good here: on a quad lattice it sees only the four edge directions and
// misses the twist f_xy, e.g. z = xy sampled along the axes has no defect at all, an O(1) bias
// that differs between the quad and the triangle side and does not shrink with the level.)
struct Curvatures {
    std::vector<double> gauss, mean;
};

Curvatures fitCurvatures(const Topology& t, const std::vector<double>& p) {
    using V3 = std::array<double, 3>;
    auto at = [&](int v) { return V3{p[3 * size_t(v)], p[3 * size_t(v) + 1], p[3 * size_t(v) + 2]}; };
    auto sub = [](const V3& a, const V3& b) { return V3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    auto cross = [](const V3& a, const V3& b) {
        return V3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    auto dot = [](const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    auto unit = [&](V3 a) {
        const double n = std::sqrt(dot(a, a));
        return V3{a[0] / n, a[1] / n, a[2] / n};
    };
    Curvatures out;
    out.gauss.assign(size_t(t.numVertices), 0.0);
    out.mean.assign(size_t(t.numVertices), 0.0);
    std::vector<int> ring;
    for (int v = 0; v < t.numVertices; ++v) {
        const V3 c = at(v);
        V3 n{0, 0, 0};
        ring.clear();
        for (int i = t.vertFaceOffsets[v]; i < t.vertFaceOffsets[v + 1]; ++i) {
            const int f = t.vertFaces[size_t(i)], b = t.faceOffsets[f], k = t.faceSize(f);
            const int* fv = &t.faceVerts[size_t(b)];
            const V3 fn = k == 3 ? cross(sub(at(fv[1]), at(fv[0])), sub(at(fv[2]), at(fv[0])))
                                 : cross(sub(at(fv[2]), at(fv[0])), sub(at(fv[3]), at(fv[1])));
            for (int j = 0; j < 3; ++j) n[size_t(j)] += fn[size_t(j)];
            for (int j = 0; j < k; ++j)
                if (fv[j] != v && std::find(ring.begin(), ring.end(), fv[j]) == ring.end()) ring.push_back(fv[j]);
        }
        n = unit(n);
        const V3 helper = std::fabs(n[0]) < 0.6 ? V3{1, 0, 0} : V3{0, 1, 0};
        const V3 t1 = unit(cross(n, helper)), t2 = cross(n, t1);
        // Normal equations of the 5-parameter fit.
        double A[5][6] = {};
        for (int w : ring) {
            const V3 d = sub(at(w), c);
            const double x = dot(d, t1), y = dot(d, t2), z = dot(d, n);
            const double basis[5] = {x * x, x * y, y * y, x, y};
            for (int r = 0; r < 5; ++r) {
                for (int q = 0; q < 5; ++q) A[r][q] += basis[r] * basis[q];
                A[r][5] += basis[r] * z;
            }
        }
        // Gaussian elimination with partial pivoting.
        for (int col = 0; col < 5; ++col) {
            int piv = col;
            for (int r = col + 1; r < 5; ++r)
                if (std::fabs(A[r][col]) > std::fabs(A[piv][col])) piv = r;
            for (int q = 0; q < 6; ++q) std::swap(A[col][q], A[piv][q]);
            for (int r = 0; r < 5; ++r) {
                if (r == col) continue;
                const double m = A[r][col] / A[col][col];
                for (int q = col; q < 6; ++q) A[r][q] -= m * A[col][q];
            }
        }
        double coef[5];
        for (int r = 0; r < 5; ++r) coef[r] = A[r][5] / A[r][r];
        const double fxx = 2 * coef[0], fxy = coef[1], fyy = 2 * coef[2], fx = coef[3], fy = coef[4];
        const double g = 1 + fx * fx + fy * fy;
        out.gauss[size_t(v)] = (fxx * fyy - fxy * fxy) / (g * g);
        out.mean[size_t(v)] = ((1 + fy * fy) * fxx - 2 * fx * fy * fxy + (1 + fx * fx) * fyy) / (2 * std::pow(g, 1.5));
    }
    return out;
}

// The seam of level L (kVertexSeam: on an edge with a triangle on one side and a quad on the
// other) and, for every seam vertex s, the vertices `ring` edges away from the seam (graph
// distance, BFS from all seam vertices) and at most `ring` edges from s, split by side (all
// faces quads / all triangles). jump(s) = |mean curvature-estimate on the quad side − mean on the
// triangle side|; the measure is the maximum over s.
//
// Why ring 2 and not the seam's direct neighbours: the control points of a refined level sit
// off the limit surface by h² times a constant that depends on the region (the K of the
// quadratic test: f_yy/6 on quads, f_yy/8 on triangles, 7 f_yy/48 on the seam). A fit whose
// neighbourhood mixes seam vertices with one side's vertices sees that step as an O(1) error in
// a second difference, for Schaefer-Warren too. The face ring of a ring-2 vertex stays inside its
// own region, where the offset is smooth, so its estimate converges to the curvature at
// distance 2h from the seam: for a C2 surface the quad-side and triangle-side values at ∓2h differ
// by O(h), halving per level; for a C1 surface with a curvature jump the difference tends to
// the jump.
struct SeamJump {
    int seamVertices = 0;
    double jump = 0;
    double scale = 0;  // max |curvature| over the level, for scale
};

SeamJump seamJump(const Topology& t, const std::vector<double>& k, int ring) {
    SeamJump r;
    std::vector<int> seam;
    for (int v = 0; v < t.numVertices; ++v)
        if (t.vertFlags[size_t(v)] & kVertexSeam) seam.push_back(v);
    r.seamVertices = int(seam.size());
    const std::vector<int> d = bfsDistance(t, seam);
    for (double x : k) r.scale = std::max(r.scale, std::fabs(x));
    std::vector<int> near, next;
    std::vector<int> mark(size_t(t.numVertices), -1);
    for (int s : seam) {
        near = {s};
        mark[size_t(s)] = s;
        size_t begin = 0;
        for (int step = 0; step < ring; ++step) {
            const size_t end = near.size();
            for (size_t i = begin; i < end; ++i)
                for (int j = t.vertEdgeOffsets[near[i]]; j < t.vertEdgeOffsets[near[i] + 1]; ++j) {
                    const int w = t.otherVertex(t.vertEdges[size_t(j)], near[i]);
                    if (mark[size_t(w)] == s) continue;
                    mark[size_t(w)] = s;
                    near.push_back(w);
                }
            begin = end;
        }
        double sum[2] = {0, 0};
        int count[2] = {0, 0};
        for (int v : near) {
            if (d[size_t(v)] != ring) continue;
            const int side = t.faceSize(t.vertFaces[size_t(t.vertFaceOffsets[v])]) == 3 ? 1 : 0;
            sum[side] += k[size_t(v)];
            ++count[side];
        }
        if (count[0] == 0 || count[1] == 0) {
            ADD_FAILURE() << "seam vertex " << s << " has no vertex " << ring << " rings away on the "
                          << (count[0] == 0 ? "quad" : "triangle") << " side";
            continue;
        }
        r.jump = std::max(r.jump, std::fabs(sum[0] / count[0] - sum[1] / count[1]));
    }
    return r;
}

// mixed_torus: 12 rings of 8 vertices (R = 2, r = 0.7), six bands of quads and six bands of
// triangles: two seam circles of ordinary seam vertices (5 edges, 2 quads, 3 triangles), 8 each,
// 8·2^L each at level L. Levels 4-6 under both schemes, evaluated in double through the
// analyzer's double per-level tables (at level 6 an edge is ~0.008 long and the curvature
// signal in the positions is ~1e-5: float positions would drown it).
TEST(Curvature, JumpAcrossTheSeamOfMixedTorus) {
    const io::ObjMesh mesh = io::readObj(meshPath("mixed/mixed_torus.obj"));
    constexpr int kFirst = 4, kLast = 6, kRing = 2;
    struct Row {
        SeamJump mean, gauss;
    };
    std::map<Scheme, std::map<int, Row>> rows;
    for (Scheme scheme : {Scheme::SchaeferWarren, Scheme::StamLoop}) {
        Refiner refiner(mesh.descriptor(), mesh.applyTags(schemeOptions(scheme)));
        refiner.refineUniform(kLast, TopologyDetail::Full);
        std::vector<double> pos(mesh.positions.begin(), mesh.positions.end());
        for (int L = 1; L <= kLast; ++L) {
            const StencilTableD table = doubleLevelTable(refiner, L);
            ASSERT_EQ(int(table.sizes.size()), refiner.faces(L).numVertices());
            pos = applyTable(table, pos, 3);
            if (L < kFirst) continue;
            const Topology& t = refiner.level(L);
            const Curvatures c = fitCurvatures(t, pos);
            Row& r = rows[scheme][L];
            r.mean = seamJump(t, c.mean, kRing);
            r.gauss = seamJump(t, c.gauss, kRing);
            EXPECT_EQ(r.mean.seamVertices, 2 * 8 << L) << toString(scheme) << " level " << L;
        }
    }

    std::cout << "\nCurvature jump across the tri/quad seam of mixed_torus: max over seam vertices of\n"
                 "|curvature on the quad side - on the triangle side|, two rings from the seam\n"
                 "(quadric fit over each vertex's face ring, positions in double)\n\n"
                 "| level | seam verts | mean H: schaefer-warren | mean H: stam-loop | Gauss K: schaefer-warren | Gauss K: stam-loop |\n"
                 "|---|---|---|---|---|---|\n";
    char buf[256];
    for (int L = kFirst; L <= kLast; ++L) {
        const Row &sw = rows[Scheme::SchaeferWarren][L], &sl = rows[Scheme::StamLoop][L];
        std::snprintf(buf, sizeof buf, "| %d | %d | %.4f | %.4f | %.4f | %.4f |\n", L, sw.mean.seamVertices,
                      sw.mean.jump, sl.mean.jump, sw.gauss.jump, sl.gauss.jump);
        std::cout << buf;
    }
    std::snprintf(buf, sizeof buf, "\n(max |H| %.3f, max |K| %.3f over the level-%d surface)\n\n",
                  rows[Scheme::SchaeferWarren][kLast].mean.scale, rows[Scheme::SchaeferWarren][kLast].gauss.scale, kLast);
    std::cout << buf;

    for (const char* which : {"mean", "gauss"}) {
        auto jump = [&](Scheme s, int L) {
            const Row& r = rows[s][L];
            return std::string(which) == "mean" ? r.mean.jump : r.gauss.jump;
        };
        const double sw4 = jump(Scheme::SchaeferWarren, 4), sw5 = jump(Scheme::SchaeferWarren, 5),
                     sw6 = jump(Scheme::SchaeferWarren, 6);
        const double sl4 = jump(Scheme::StamLoop, 4), sl6 = jump(Scheme::StamLoop, 6);
        // C2: the jump is O(h) and halves per level; allow 0.75 per level.
        EXPECT_LT(sw5, 0.75 * sw4) << which << " curvature, schaefer-warren level 5 vs 4";
        EXPECT_LT(sw6, 0.75 * sw5) << which << " curvature, schaefer-warren level 6 vs 5";
        EXPECT_LT(sw6, 0.5 * sl6) << which << " curvature at level 6: schaefer-warren vs stam-loop";
        // C1 with a curvature jump: the measure tends to the jump, not to 0.
        EXPECT_GE(sl6, 0.5 * sl4) << which << " curvature, stam-loop level 6 vs 4";
    }
}

}  // namespace
