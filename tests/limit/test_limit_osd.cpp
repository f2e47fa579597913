// Limit positions and normals against OpenSubdiv's Far::PrimvarRefiner::Limit: every catmark_*
// shape of tests/meshes/osd under catmull-clark, every loop_* under loop, and the pure ones
// under the mixed schemes, at levels 0-3. Vertices are matched by their refined positions (the two
// libraries number refined vertices differently); limit positions must agree within 1e-5 of the
// control mesh's bounding-box diagonal, normals (normalised dU × dV on both sides, OpenSubdiv's
// tangents being scaled differently) within 1e-4 radians wherever OpenSubdiv's tangents span a
// plane. Normals are not compared at non-manifold vertices, where OpenSubdiv's tangents follow
// its internal incidence order (docs/limit.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "far/limit/limit_ring.h"
#include "far/limit/limit_table.h"
#include "far/tables/level_stencils.h"
#include "far/schemes/scheme.h"
#include "tests/limit/limit_support.h"
#include "tests/osd_reference.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

constexpr double kPositionTolerance = 1e-5;  // of the control mesh's bounding-box diagonal
constexpr double kNormalTolerance = 1e-4;    // radians
// Per-level float tables on float data: within kNormalTolerance, or where float data alone moves
// the normals further, within this factor of what it moves OpenSubdiv's own (PrimvarRefiner in float).
constexpr double kFloatDataFactor = 2.0;
constexpr int kMaxLevel = 3;

struct LimitCase {
    std::string shape;
    OsdScheme reference = OsdScheme::Catmark;
    Scheme ours = Scheme::CatmullClark;
    bool leftHanded = false;
    bool smoothTriangles = false;  // catmull-clark's smooth-triangle rule, against TRI_SUB_SMOOTH
    int firstLevel = 0;  // the mixed schemes start where every face is a quad (triangle)
};

void PrintTo(const LimitCase& c, std::ostream* os) {
    *os << c.shape << " under " << toString(c.ours) << (c.leftHanded ? " (left-handed)" : "")
        << (c.smoothTriangles ? " (smooth triangles)" : "") << " from level " << c.firstLevel;
}

std::string caseName(const testing::TestParamInfo<LimitCase>& info) {
    return testNameOf(info.param.shape + "_" + toString(info.param.ours) + (info.param.leftHanded ? "_left" : "") +
                      (info.param.smoothTriangles ? "_smooth_triangles" : ""));
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

std::vector<LimitCase> limitCases() {
    std::vector<std::string> shapes;
    for (const auto& entry : std::filesystem::directory_iterator(meshPath("osd")))
        if (entry.is_regular_file() && entry.path().extension() == ".obj") shapes.push_back(entry.path().stem().string());
    std::sort(shapes.begin(), shapes.end());
    std::vector<LimitCase> cases;
    for (const std::string& shape : shapes) {
        const io::ObjMesh mesh = io::readObj(meshPath("osd/" + shape + ".obj"));
        bool quads = true, triangles = true, collapsed = false;
        for (int f = 0, corner = 0; f < mesh.numFaces(); corner += mesh.faceSizes[f++]) {
            quads = quads && mesh.faceSizes[f] == 4;
            triangles = triangles && mesh.faceSizes[f] == 3;
            for (int i = 0; i < mesh.faceSizes[f]; ++i)
                collapsed = collapsed || mesh.faceVerts[corner + i] == mesh.faceVerts[corner + (i + 1) % mesh.faceSizes[f]];
        }
        LimitCase c;
        c.shape = shape;
        if (startsWith(shape, "catmark_")) {
            c.reference = OsdScheme::Catmark;
            cases.push_back(c);
            if (shape == "catmark_lefthanded") {
                c.leftHanded = true;
                cases.push_back(c);
                c.leftHanded = false;
            }
            // Without triangles every scheme is Catmull-Clark; n-gons make level 0 mixed.
            bool noTriangles = !collapsed;
            for (int size : mesh.faceSizes) noTriangles = noTriangles && size != 3;
            if (!noTriangles) {  // the smooth-triangle rule changes level 1 on
                c.smoothTriangles = true;
                cases.push_back(c);
                c.smoothTriangles = false;
            }
            c.firstLevel = quads ? 0 : 1;
            if (noTriangles)
                for (Scheme s : {Scheme::StamLoop, Scheme::SchaeferWarren, Scheme::CatmarkButterfly}) {
                    c.ours = s;
                    cases.push_back(c);
                }
        } else if (startsWith(shape, "loop_") && triangles) {
            c.reference = OsdScheme::Loop;
            for (Scheme s : {Scheme::Loop, Scheme::StamLoop, Scheme::SchaeferWarren}) {
                c.ours = s;
                cases.push_back(c);
            }
        }
    }
    return cases;
}

// The worst disagreement of one level's limit with OpenSubdiv's.
struct Worst {
    double position = 0, angle = 0;
    int positionVertex = -1, angleVertex = -1, compared = 0;
};

// Our limit data (`limit`, over our refined vertices `refined`) against OpenSubdiv's. Vertices that
// share a refined position (the children of a collapsed edge) are compared with the best of
// OpenSubdiv's vertices at that position, since matching by position cannot tell them apart.
Worst compare(const std::vector<float>& refined, const LimitData& limit, const OsdLimit& osd, double diagonal) {
    const PositionMatch match = matchPositions(refined, osd.refined, diagonal, kPositionTolerance);
    EXPECT_TRUE(match.countsEqual);
    EXPECT_LE(match.maxRelative(), kPositionTolerance) << "refined vertices differ";
    const int n = int(refined.size() / 3);
    auto positionError = [&](int v, int o) { return distance(limit.position[v], vec3(&osd.position[3 * o])) / diagonal; };
    // The angle between normals, or -1 where OpenSubdiv's is not defined (degenerate tangents or
    // a non-manifold vertex).
    auto angleError = [&](int v, int o) {
        if (osd.vertexNonManifold[o]) return -1.0;
        const Vec3 du = vec3(&osd.du[3 * o]), dv = vec3(&osd.dv[3 * o]), reference = cross(du, dv);
        if (norm(reference) == 0 || norm(reference) <= 1e-6 * norm(du) * norm(dv)) return -1.0;
        return angleBetween(cross(limit.du[v], limit.dv[v]), reference);
    };
    Worst worst;
    for (int v = 0; v < n; ++v) {
        int o = match.ourToReference[v];
        double d = positionError(v, o), angle = angleError(v, o);
        if (d > kPositionTolerance || angle > kNormalTolerance) {
            for (int other = 0; other < int(osd.refined.size() / 3); ++other) {
                if (distance(vec3(&refined[3 * v]), vec3(&osd.refined[3 * other])) > 1e-7 * diagonal) continue;
                const double d2 = positionError(v, other), angle2 = angleError(v, other);
                if (std::max(d2 / kPositionTolerance, angle2 / kNormalTolerance) <
                    std::max(d / kPositionTolerance, angle / kNormalTolerance))
                    o = other, d = d2, angle = angle2;
            }
        }
        if (d > worst.position) worst.position = d, worst.positionVertex = v;
        if (angle < 0) continue;
        ++worst.compared;
        if (angle > worst.angle) worst.angle = angle, worst.angleVertex = v;
    }
    return worst;
}

// Level L's refined vertices and limit from the double tables the rules build (no float rounding
// anywhere): the masks themselves against OpenSubdiv's.
struct ExactLevel {
    std::vector<float> refined;
    LimitData limit;
};

ExactLevel exactLimit(const Refiner& refiner, const std::vector<float>& control, int L) {
    const Options& options = refiner.options();
    const TriangleSplit split = rulesOf(options.scheme).triangleSplit();
    std::vector<double> positions(control.begin(), control.end());
    RingStarts starts(refiner.level(0));
    for (int l = 1; l <= L; ++l) {
        const Topology& parent = refiner.level(l - 1);
        const ChildNumbering numbering = numberChildren(parent, split);
        const StencilTableD table = buildLevelStencils<StencilTableD>(parent, numbering, options);
        std::vector<double> next(3 * table.sizes.size(), 0.0);
        for (std::size_t i = 0; i < table.sizes.size(); ++i)
            for (int k = 0; k < table.sizes[i]; ++k) {
                const int e = table.offsets[i] + k;
                for (int c = 0; c < 3; ++c) next[3 * i + c] += table.weights[e] * positions[3 * std::size_t(table.indices[e]) + c];
            }
        positions = std::move(next);
        starts.descend(parent, numbering, refiner.level(l).numVertices);
    }
    const LimitStencilTableD table = buildLimitStencils(refiner.level(L), options, &starts);
    ExactLevel out;
    out.refined.assign(positions.begin(), positions.end());
    for (int i = 0; i < table.numStencils(); ++i) {
        Vec3 p{0, 0, 0}, u{0, 0, 0}, v{0, 0, 0};
        for (int k = 0; k < table.sizes[i]; ++k) {
            const int e = table.offsets[i] + k;
            const double* w = table.weights.data() + 3 * std::size_t(e);
            const double* x = positions.data() + 3 * std::size_t(table.indices[e]);
            for (int c = 0; c < 3; ++c) p[c] += w[0] * x[c], u[c] += w[1] * x[c], v[c] += w[2] * x[c];
        }
        out.limit.position.push_back(p);
        out.limit.du.push_back(u);
        out.limit.dv.push_back(v);
    }
    return out;
}

// The largest angle between OpenSubdiv's normals computed in float and in double, vertex by vertex
// (both number the vertices alike), where the double ones are defined (as in compare).
double osdFloatNormalError(const OsdLimit& exact, const OsdLimit& inFloat) {
    double worst = 0;
    for (std::size_t o = 0; o < exact.vertexNonManifold.size(); ++o) {
        if (exact.vertexNonManifold[o]) continue;
        const Vec3 du = vec3(&exact.du[3 * o]), dv = vec3(&exact.dv[3 * o]), reference = cross(du, dv);
        if (norm(reference) == 0 || norm(reference) <= 1e-6 * norm(du) * norm(dv)) continue;
        worst = std::max(worst, angleBetween(cross(vec3(&inFloat.du[3 * o]), vec3(&inFloat.dv[3 * o])), reference));
    }
    return worst;
}

// The worst errors of a level, in the test's XML report (--gtest_output=xml).
void recordWorst(int L, const Worst& worst, const std::string& suffix = "") {
    char position[32], angle[32];
    std::snprintf(position, sizeof position, "%.3g", worst.position);
    std::snprintf(angle, sizeof angle, "%.3g", worst.angle);
    testing::Test::RecordProperty("level" + std::to_string(L) + suffix + "_position", position);
    testing::Test::RecordProperty("level" + std::to_string(L) + suffix + "_angle", angle);
}

class LimitAgainstOsd : public testing::TestWithParam<LimitCase> {};

// The case's shape refined to kMaxLevel under its scheme and options.
RefinedMesh refineCase(const LimitCase& c) {
    Options base;
    base.scheme = c.ours;
    base.leftHanded = c.leftHanded;
    base.smoothTriangles = c.smoothTriangles;
    return refineMesh("osd/" + c.shape + ".obj", kMaxLevel, base);
}

// The masks, evaluated without rounding, against OpenSubdiv's in double.
TEST_P(LimitAgainstOsd, MasksEqualOpenSubdiv) {
    const LimitCase& c = GetParam();
    const RefinedMesh ours = refineCase(c);
    const double diagonal = boundingBoxDiagonal(ours.mesh.positions);
    for (int L = c.firstLevel; L <= kMaxLevel; ++L) {
        const OsdLimit osd = osdLimit(ours.mesh, c.reference, ours.options.boundary, ours.options.creaseMethod, L,
                                      ours.options.smoothTriangles, c.leftHanded);
        const ExactLevel exact = exactLimit(*ours.refiner, ours.mesh.positions, L);
        const Worst worst = compare(exact.refined, exact.limit, osd, diagonal);
        EXPECT_LE(worst.position, kPositionTolerance) << "level " << L << ": limit position of vertex " << worst.positionVertex;
        EXPECT_LE(worst.angle, kNormalTolerance)
            << "level " << L << ": normal of vertex " << worst.angleVertex << ", " << worst.compared << " compared";
        recordWorst(L, worst);
    }
}

// What an engine gets, through the float tables. Per level: limitStencils(L) on the float refined
// positions of level L, whose own rounding (about 1e-7 of the coordinates) the tangents, differences
// of neighbours a refined edge apart, turn into up to 8e-4 rad at level 3 of the larger shapes
// (catmark_rook): OpenSubdiv computed in float moves its normals as far (8.0e-4 there), so the
// normals are held to kNormalTolerance or kFloatDataFactor times OpenSubdiv's own float error.
// Factorized: factorizedLimitStencils(L) on the control positions, which are exact: normals within
// kNormalTolerance.
TEST_P(LimitAgainstOsd, FloatTablesAgreeWithOpenSubdiv) {
    const LimitCase& c = GetParam();
    const RefinedMesh ours = refineCase(c);
    const double diagonal = boundingBoxDiagonal(ours.mesh.positions);
    for (int L = c.firstLevel; L <= kMaxLevel; ++L) {
        const OsdLimit osd = osdLimit(ours.mesh, c.reference, ours.options.boundary, ours.options.creaseMethod, L,
                                      ours.options.smoothTriangles, c.leftHanded);
        const LimitStencilTable table = ours.refiner->limitStencils(L);
        ASSERT_EQ(table.numStencils(), int(ours.positions[L].size() / 3)) << "level " << L;
        const Worst perLevel = compare(ours.positions[L], applyLimit(table, ours.positions[L]), osd, diagonal);
        EXPECT_LE(perLevel.position, kPositionTolerance) << "level " << L << ": limit position of vertex " << perLevel.positionVertex;
        const double osdInFloat = osdFloatNormalError(
            osd, osdLimitInFloat(ours.mesh, c.reference, ours.options.boundary, ours.options.creaseMethod, L,
                                 ours.options.smoothTriangles, c.leftHanded));
        EXPECT_LE(perLevel.angle, std::max(kNormalTolerance, kFloatDataFactor * osdInFloat))
            << "level " << L << ": normal of vertex " << perLevel.angleVertex << ", " << perLevel.compared
            << " compared; OpenSubdiv in float is off by " << osdInFloat;
        const LimitStencilTable factorized = ours.refiner->factorizedLimitStencils(L);
        const Worst fromControl = compare(ours.positions[L], applyLimit(factorized, ours.mesh.positions), osd, diagonal);
        EXPECT_LE(fromControl.position, kPositionTolerance)
            << "level " << L << " factorized: limit position of vertex " << fromControl.positionVertex;
        EXPECT_LE(fromControl.angle, kNormalTolerance)
            << "level " << L << " factorized: normal of vertex " << fromControl.angleVertex << ", " << fromControl.compared << " compared";
        recordWorst(L, perLevel);
        recordWorst(L, fromControl, "_factorized");
    }
}

INSTANTIATE_TEST_SUITE_P(OsdShapes, LimitAgainstOsd, testing::ValuesIn(limitCases()), caseName);

}  // namespace
}  // namespace quadtri::test
