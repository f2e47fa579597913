// quadtri against OpenSubdiv on OpenSubdiv's own regression shapes (tests/meshes/osd): every
// shape under its own scheme, catmark_* under catmull-clark (also with the smooth-triangle rule,
// against TRI_SUB_SMOOTH), loop_* under loop, bilinear_cube under bilinear; and the shapes without
// triangles or collapsed edges under the mixed schemes too (pure-quad catmark_* under stam-loop,
// schaefer-warren and catmark-butterfly, loop_* under stam-loop and schaefer-warren), which must
// equal OpenSubdiv there. Vertices are matched by position (the two libraries order
// refined vertices differently); on a mismatch the failure message lists, per kind of child
// (face / edge / vertex point), which quadtri child differs from OpenSubdiv's child of the same
// parent component, with the parent's tags on both sides.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "far/topology/refine_topology.h"
#include "far/schemes/scheme.h"
#include "tests/osd_reference.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

constexpr double kTolerance = 1e-5;  // relative to the bounding-box diagonal of the control mesh

struct ShapeCase {
    std::string shape;  // file name without .obj, e.g. "catmark_cube"
    OsdScheme reference = OsdScheme::Catmark;
    Scheme ours = Scheme::StamLoop;
    bool smoothTriangles = false;  // catmull-clark with Options::smoothTriangles, against TRI_SUB_SMOOTH
    int level = 1;
    int numFaces = 0;
};

std::ostream& operator<<(std::ostream& os, const ShapeCase& c) {
    return os << c.shape << " level " << c.level << " (OSD " << toString(c.reference)
              << (c.smoothTriangles ? " TRI_SUB_SMOOTH" : "") << ", quadtri " << toString(c.ours)
              << (c.smoothTriangles ? " smooth triangles" : "") << ")";
}

// Face count, triangles and faces with a collapsed edge (a corner repeating the one before it),
// read straight from the `f` lines (no dependency on the OBJ reader at test registration time).
struct FaceStats {
    int faces = 0;
    int triangles = 0;
    int collapsed = 0;
};

FaceStats readFaceStats(const std::filesystem::path& path) {
    FaceStats stats;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.size() < 2 || line[0] != 'f' || (line[1] != ' ' && line[1] != '\t')) continue;
        std::istringstream tokens(line.substr(1));
        std::vector<std::string> corners;
        for (std::string token; tokens >> token;) corners.push_back(token.substr(0, token.find('/')));
        ++stats.faces;
        if (corners.size() == 3) ++stats.triangles;
        for (size_t i = 0; i < corners.size(); ++i)
            if (corners[i] == corners[(i + 1) % corners.size()]) {
                ++stats.collapsed;
                break;
            }
    }
    return stats;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

std::vector<ShapeCase> osdCases() {
    std::vector<std::string> shapes;
    for (const auto& entry : std::filesystem::directory_iterator(meshPath("osd"))) {
        if (!entry.is_regular_file() || entry.path().extension() != ".obj") continue;
        shapes.push_back(entry.path().stem().string());
    }
    std::sort(shapes.begin(), shapes.end());

    std::vector<ShapeCase> cases;
    for (const std::string& shape : shapes) {
        ShapeCase c;
        c.shape = shape;
        const FaceStats stats = readFaceStats(meshPath("osd/" + shape + ".obj"));
        c.numFaces = stats.faces;
        // The shape's own scheme, then the mixed schemes where they must agree with it: pure
        // shapes have no tri/quad seam. A collapsed edge (`4 3 5 5`) makes a triangle for them.
        std::vector<std::pair<Scheme, bool>> ours;  // scheme, smooth triangles
        const bool pure = stats.collapsed == 0;
        if (startsWith(shape, "catmark_")) {
            c.reference = OsdScheme::Catmark;
            ours = {{Scheme::CatmullClark, false}, {Scheme::CatmullClark, true}};
            // Catmark and the mixed schemes differ on triangles by design; catmark-butterfly is
            // Catmull-Clark wherever there is no triangle.
            if (pure && stats.triangles == 0)
                for (Scheme s : {Scheme::StamLoop, Scheme::SchaeferWarren, Scheme::CatmarkButterfly}) ours.push_back({s, false});
        } else if (startsWith(shape, "loop_")) {
            c.reference = OsdScheme::Loop;
            ours = {{Scheme::Loop, false}};
            if (pure)
                for (Scheme s : {Scheme::StamLoop, Scheme::SchaeferWarren}) ours.push_back({s, false});
        } else if (startsWith(shape, "bilinear_")) {
            c.reference = OsdScheme::Bilinear;
            ours = {{Scheme::Bilinear, false}};
        } else {
            continue;
        }
        // Levels 1-4, and 1-3 for shapes over 500 faces (their level 4 is large and adds nothing).
        const int maxLevel = c.numFaces > 500 ? 3 : 4;
        for (const auto& [scheme, smoothTriangles] : ours) {
            c.ours = scheme;
            c.smoothTriangles = smoothTriangles;
            for (int level = 1; level <= maxLevel; ++level) {
                c.level = level;
                cases.push_back(c);
            }
        }
    }
    return cases;
}

std::string caseName(const testing::TestParamInfo<ShapeCase>& info) {
    return testNameOf(info.param.shape + "_L" + std::to_string(info.param.level) + "_" + toString(info.param.ours) +
                      (info.param.smoothTriangles ? "_smooth_triangles" : ""));
}

std::string formatPoint(const float* p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.9g, %.9g, %.9g)", p[0], p[1], p[2]);
    return buf;
}

double distance(const float* a, const float* b) {
    double d2 = 0;
    for (int c = 0; c < 3; ++c) d2 += (double(a[c]) - double(b[c])) * (double(a[c]) - double(b[c]));
    return std::sqrt(d2);
}

std::string edgeFlagString(uint8_t flags) {
    std::string s;
    if (flags & kEdgeBoundary) s += " boundary";
    if (flags & kEdgeNonManifold) s += " nonmanifold";
    if (flags & kEdgeSeam) s += " seam";
    return s.empty() ? " interior" : s;
}

std::string vertexFlagString(uint8_t flags) {
    std::string s;
    if (flags & kVertexBoundary) s += " boundary";
    if (flags & kVertexNonManifold) s += " nonmanifold";
    if (flags & kVertexSeam) s += " seam";
    if (flags & kVertexCorner) s += " corner";
    return s.empty() ? " interior" : s;
}

// Compares every quadtri child of level L with OpenSubdiv's child of the same parent component,
// given a vertex map of level L-1 (ours -> OSD). Returns a readable report of the differences.
std::string diagnoseByParent(const RefinedMesh& ours, const OsdRefinement& osd, int L,
                             const std::vector<int>& parentMap, double diagonal) {
    const Topology& T = ours.refiner->level(L - 1);
    const OsdLevelTopology& O = osd.topology.at(L - 1);
    const std::vector<float>& ourPos = ours.positions.at(L);
    const std::vector<float>& osdPos = osd.positions.at(L);
    const int numOurs = int(ourPos.size() / 3);

    const ChildNumbering numbering = numberChildren(T, rulesOf(ours.options.scheme).triangleSplit());
    const int numFacePoints = numbering.numFacePoints;
    std::ostringstream out;
    if (numFacePoints + T.numEdges() + T.numVertices != numOurs) {
        out << "  (per-parent diagnosis unavailable: level " << L << " has " << numOurs
            << " vertices, not face points + edges + vertices of level " << L - 1 << " = " << numFacePoints << " + "
            << T.numEdges() << " + " << T.numVertices << ")\n";
        return out.str();
    }

    // OSD faces by sorted vertex set, OSD edges by endpoint pair.
    std::map<std::vector<int>, int> osdFaces;
    for (int f = 0; f < O.numFaces(); ++f) {
        std::vector<int> key(O.faceVerts.begin() + O.faceOffsets[f], O.faceVerts.begin() + O.faceOffsets[f + 1]);
        std::sort(key.begin(), key.end());
        osdFaces.emplace(key, f);
    }
    std::map<std::pair<int, int>, int> osdEdges;
    for (int e = 0; e < O.numEdges(); ++e) {
        const int a = O.edgeVerts[2 * e], b = O.edgeVerts[2 * e + 1];
        osdEdges.emplace(std::make_pair(std::min(a, b), std::max(a, b)), e);
    }

    const char* kindName[3] = {"face point", "edge point", "vertex point"};
    int bad[3] = {0, 0, 0}, total[3] = {0, 0, 0}, unmapped[3] = {0, 0, 0};
    double worst[3] = {0, 0, 0};
    std::vector<std::string> examples[3];
    const double tol = kTolerance * diagonal;

    int faceIndex = 0;  // our face of the next face point
    for (int i = 0; i < numOurs; ++i) {
        int kind, parent, osdChild = -1;
        std::ostringstream what;
        if (i < numFacePoints) {
            kind = 0;
            while (numbering.facePoint[faceIndex] < 0) ++faceIndex;
            parent = faceIndex++;
            std::vector<int> key;
            for (int k = T.faceOffsets[parent]; k < T.faceOffsets[parent + 1]; ++k) key.push_back(parentMap[T.faceVerts[k]]);
            std::sort(key.begin(), key.end());
            auto it = osdFaces.find(key);
            if (it != osdFaces.end()) osdChild = O.faceChild[it->second];
            what << "face " << parent << " (size " << T.faceSize(parent)
                 << (T.faceHole.size() > size_t(parent) && T.faceHole[parent] ? ", hole" : "") << ")";
        } else if (i < numFacePoints + T.numEdges()) {
            kind = 1;
            parent = i - numFacePoints;
            const int a = T.edgeVerts[2 * parent], b = T.edgeVerts[2 * parent + 1];
            const int oa = parentMap[a], ob = parentMap[b];
            auto it = osdEdges.find(std::make_pair(std::min(oa, ob), std::max(oa, ob)));
            what << "edge " << parent << " (" << a << "-" << b << ", " << T.edgeFaceCount(parent)
                 << " faces, sharpness " << T.edgeSharpness[parent] << "," << edgeFlagString(T.edgeFlags[parent]) << ")";
            if (it != osdEdges.end()) {
                osdChild = O.edgeChild[it->second];
                what << " / OSD edge " << it->second << " sharpness " << O.edgeSharpness[it->second]
                     << (O.edgeNonManifold[it->second] ? " nonmanifold" : "");
            }
        } else {
            kind = 2;
            parent = i - numFacePoints - T.numEdges();
            const VertexFaceCounts counts = countVertexFaces(T, parent);
            what << "vertex " << parent << " (" << T.vertexEdgeCount(parent) << " edges, " << T.vertexFaceCount(parent)
                 << " faces [" << counts.quads << "q " << counts.triangles << "t], sharpness "
                 << T.vertSharpness[parent] << "," << vertexFlagString(T.vertFlags[parent]) << ")";
            const int ov = parentMap[parent];
            if (ov >= 0) {
                osdChild = O.vertexChild[ov];
                what << " / OSD vertex " << ov << " rule " << vertexRuleName(O.vertexRule[ov]) << " sharpness "
                     << O.vertexSharpness[ov] << (O.vertexBoundary[ov] ? " boundary" : "")
                     << (O.vertexNonManifold[ov] ? " nonmanifold" : "");
            }
        }
        ++total[kind];
        if (osdChild < 0) {
            ++unmapped[kind];
            if (examples[kind].size() < 4) examples[kind].push_back("    our " + std::to_string(i) + ": " + what.str() + ": no OSD counterpart");
            continue;
        }
        const double d = distance(&ourPos[3 * size_t(i)], &osdPos[3 * size_t(osdChild)]);
        worst[kind] = std::max(worst[kind], d);
        if (d > tol) {
            ++bad[kind];
            if (examples[kind].size() < 4) {
                std::ostringstream ex;
                ex << "    our " << i << " " << formatPoint(&ourPos[3 * size_t(i)]) << " vs OSD " << osdChild << " "
                   << formatPoint(&osdPos[3 * size_t(osdChild)]) << " rel " << d / diagonal << ": " << what.str();
                examples[kind].push_back(ex.str());
            }
        }
    }
    out << "  per-parent comparison of level " << L << " (given level " << L - 1 << " matched):\n";
    for (int k = 0; k < 3; ++k) {
        out << "   " << kindName[k] << "s: " << bad[k] << " of " << total[k] << " differ (max rel "
            << worst[k] / diagonal << ")";
        if (unmapped[k]) out << ", " << unmapped[k] << " without OSD counterpart";
        out << "\n";
        for (const std::string& ex : examples[k]) out << ex << "\n";
    }
    return out.str();
}

class OsdAgreement : public testing::TestWithParam<ShapeCase> {};

TEST_P(OsdAgreement, PositionsMatch) {
    const ShapeCase& c = GetParam();
    Options base;
    base.scheme = c.ours;
    base.smoothTriangles = c.smoothTriangles;
    RefinedMesh ours;
    try {
        ours = refineMesh("osd/" + c.shape + ".obj", c.level, base);
    } catch (const std::exception& e) {
        // Say whether OpenSubdiv accepts the same input, to tell a quadtri limitation from bad data.
        std::string osdVerdict;
        try {
            const io::ObjMesh mesh = io::readObj(meshPath("osd/" + c.shape + ".obj"));
            const Options resolved = mesh.applyTags(base);
            const OsdRefinement osd =
                osdRefine(mesh, c.reference, resolved.boundary, resolved.creaseMethod, c.level, c.smoothTriangles);
            osdVerdict = "OpenSubdiv accepts this input (" + std::to_string(osd.numVertices[c.level]) +
                         " vertices at level " + std::to_string(c.level) + ")";
        } catch (const std::exception& osdError) {
            osdVerdict = std::string("OpenSubdiv fails too: ") + osdError.what();
        }
        FAIL() << "quadtri failed on " << c << ": " << e.what() << "; " << osdVerdict;
    }
    OsdRefinement osd;
    try {
        osd = osdRefine(ours.mesh, c.reference, ours.options.boundary, ours.options.creaseMethod, c.level,
                        ours.options.smoothTriangles);
    } catch (const std::exception& e) {
        FAIL() << "OpenSubdiv failed on " << c << ": " << e.what();
    }
    const double diagonal = boundingBoxDiagonal(ours.mesh.positions);
    const std::string setup = std::string("boundary ") + toString(ours.options.boundary) + ", crease method " +
                              toString(ours.options.creaseMethod);

    // Per-level counts.
    bool countsOk = true;
    for (int L = 1; L <= c.level; ++L) {
        const Topology& T = ours.refiner->level(L);
        const int ourHoles = int(std::count(T.faceHole.begin(), T.faceHole.end(), uint8_t(1)));
        std::ostringstream holes;
        if (!ours.mesh.holes.empty() || osd.numHoleFaces(L) > 0 || ourHoles > 0)
            holes << " [shape has holes: " << ours.mesh.holes.size() << " control hole faces; hole faces at level " << L
                  << ": quadtri " << ourHoles << ", OSD " << osd.numHoleFaces(L)
                  << "; OSD keeps refining hole faces, so a vertex-count difference may be a hole-handling difference]";
        EXPECT_EQ(T.numVertices, osd.numVertices[L])
            << c << ": vertex count of level " << L << " (" << setup << ")" << holes.str();
        EXPECT_EQ(T.numFaces(), osd.numFaces[L])
            << c << ": face count of level " << L << " (" << setup << ")" << holes.str();
        if (T.numVertices != osd.numVertices[L]) countsOk = false;
    }

    // Positions of the tested level, matched one-to-one by position.
    const PositionMatch m = matchPositions(ours.positions.at(c.level), osd.positions.at(c.level), diagonal, kTolerance);
    std::printf("[ osd      ] %-28s L%d %-15s%s  verts %6d/%-6d  max rel dist %.3g%s\n", c.shape.c_str(), c.level,
                toString(c.ours), c.smoothTriangles ? " smooth-tri" : "", m.numOurs, m.numReference, m.maxRelative(),
                m.maxRelative() <= kTolerance && countsOk ? "" : "  FAIL");
    if (m.maxRelative() <= kTolerance) return;

    std::ostringstream msg;
    msg << c << " (" << setup << "): max distance / bbox diagonal = " << m.maxRelative() << " > " << kTolerance
        << "; " << m.outliers.size() << " of " << m.numOurs << " quadtri vertices farther than the tolerance from "
        << "their matched OSD vertex (" << m.numCollisions << " nearest-neighbour collisions)";
    if (m.worstOurs >= 0) {
        msg << "; worst: quadtri " << m.worstOurs << " " << formatPoint(&ours.positions[c.level][3 * size_t(m.worstOurs)]);
        if (m.worstReference >= 0)
            msg << " vs OSD " << m.worstReference << " " << formatPoint(&osd.positions[c.level][3 * size_t(m.worstReference)]);
    }
    msg << "\n";

    // Locate the difference: level L-1 must match for a per-parent comparison of level L.
    std::vector<int> parentMap;
    bool parentOk = true;
    if (c.level == 1) {
        parentMap.resize(ours.mesh.numVertices());
        for (int v = 0; v < ours.mesh.numVertices(); ++v) parentMap[v] = v;
    } else {
        const PositionMatch pm =
            matchPositions(ours.positions.at(c.level - 1), osd.positions.at(c.level - 1), diagonal, kTolerance);
        parentOk = pm.countsEqual && pm.maxRelative() <= kTolerance;
        parentMap = pm.ourToReference;
        if (!parentOk)
            msg << "  level " << c.level - 1 << " differs too (max rel " << pm.maxRelative()
                << "): see that level's test for the first difference\n";
    }
    if (parentOk) msg << diagnoseByParent(ours, osd, c.level, parentMap, diagonal);
    ADD_FAILURE() << msg.str();
}

INSTANTIATE_TEST_SUITE_P(Shapes, OsdAgreement, testing::ValuesIn(osdCases()), caseName);

// --- The OpenSubdiv wrapper and the matcher on their own (no quadtri refinement involved). ---

io::ObjMesh unitCube() {
    io::ObjMesh m;
    m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    m.faceSizes = {4, 4, 4, 4, 4, 4};
    m.faceVerts = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
    return m;
}

io::ObjMesh tetrahedron() {
    io::ObjMesh m;
    m.positions = {1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1};
    m.faceSizes = {3, 3, 3, 3};
    m.faceVerts = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
    return m;
}

bool containsPoint(const std::vector<float>& xyz, float x, float y, float z, float eps = 1e-6f) {
    for (size_t i = 0; i + 2 < xyz.size(); i += 3)
        if (std::abs(xyz[i] - x) <= eps && std::abs(xyz[i + 1] - y) <= eps && std::abs(xyz[i + 2] - z) <= eps) return true;
    return false;
}

// No regression shape uses boundary interpolation "none": force it on open shapes and compare
// positions and which faces become holes, level by level.
class OsdAgreementBoundaryNone : public testing::TestWithParam<Scheme> {};

TEST_P(OsdAgreementBoundaryNone, OpenShapes) {
    const struct {
        const char* shape;
        OsdScheme reference;
    } shapes[] = {{"catmark_edgecorner", OsdScheme::Catmark}, {"catmark_tent", OsdScheme::Catmark},
                  {"catmark_xord_boundary", OsdScheme::Catmark}, {"loop_saddle_edgeonly", OsdScheme::Loop},
                  {"loop_triangle_edgeonly", OsdScheme::Loop}};
    // catmull-clark and loop are tried on their own shapes; the mixed schemes on all of them.
    const bool ownShapesOnly = GetParam() == Scheme::CatmullClark || GetParam() == Scheme::Loop;
    for (const auto& s : shapes) {
        if (ownShapesOnly && (s.reference == OsdScheme::Loop) != (GetParam() == Scheme::Loop)) continue;
        Options options;
        options.scheme = GetParam();
        options.boundary = BoundaryInterpolation::None;
        io::ObjMesh mesh = io::readObj(meshPath(std::string("osd/") + s.shape + ".obj"));
        mesh.boundary.reset();  // the flag above wins over the file's tag
        Refiner refiner(mesh.descriptor(), mesh.applyTags(options));
        refiner.refineUniform(3);
        const std::vector<std::vector<float>> ours = evaluateLevels(refiner, mesh.positions, 3);
        const OsdRefinement osd =
            osdRefine(mesh, s.reference, BoundaryInterpolation::None, refiner.options().creaseMethod, 3);
        const double diagonal = boundingBoxDiagonal(mesh.positions);
        for (int L = 0; L <= 3; ++L) {
            const int holes = refiner.faces(L).numHoles();
            EXPECT_GT(holes, 0) << s.shape << " level " << L;
            EXPECT_EQ(holes, osd.numHoleFaces(L)) << s.shape << " level " << L;
            const PositionMatch m = matchPositions(ours[L], osd.positions[L], diagonal, 1e-5);
            EXPECT_TRUE(m.countsEqual) << s.shape << " level " << L;
            EXPECT_LE(m.maxRelative(), 1e-5) << s.shape << " level " << L;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Schemes, OsdAgreementBoundaryNone,
                         testing::Values(Scheme::StamLoop, Scheme::SchaeferWarren, Scheme::CatmullClark, Scheme::Loop),
                         [](const testing::TestParamInfo<Scheme>& info) {
                             std::string name = toString(info.param);
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(OsdReference, CatmarkCube) {
    const OsdRefinement r =
        osdRefine(unitCube(), OsdScheme::Catmark, BoundaryInterpolation::EdgeOnly, CreaseMethod::Uniform, 2);
    EXPECT_EQ(r.numVertices, (std::vector<int>{8, 26, 98}));
    EXPECT_EQ(r.numFaces, (std::vector<int>{6, 24, 96}));
    EXPECT_EQ(r.numHoleFaces(1), 0);
    EXPECT_TRUE(containsPoint(r.positions[1], 0.5f, 0.5f, 0.0f)) << "face point of the bottom face";
    EXPECT_TRUE(containsPoint(r.positions[1], 0.5f, 0.5f, 1.0f)) << "face point of the top face";
    // Edge point of edge 0-1: (v0 + v1 + two adjacent face points) / 4.
    EXPECT_TRUE(containsPoint(r.positions[1], 0.5f, 0.125f, 0.125f));
    // Vertex point of corner 0 (valence 3): (F + 2R + (n-3)S) / n with F, R averages of face / edge midpoints.
    // F = (1/6)(1,1,1)*... -> by symmetry the point is (t,t,t), t = (1/3 + 2*(1/6)) / 3 = 2/9.
    EXPECT_TRUE(containsPoint(r.positions[1], 2.0f / 9, 2.0f / 9, 2.0f / 9));
    // The child of vertex 0 is where OpenSubdiv says.
    const int child = r.topology[0].vertexChild[0];
    ASSERT_GE(child, 0);
    EXPECT_NEAR(r.positions[1][3 * child], 2.0f / 9, 1e-6);
}

TEST(OsdReference, LoopTetrahedron) {
    const OsdRefinement r =
        osdRefine(tetrahedron(), OsdScheme::Loop, BoundaryInterpolation::EdgeOnly, CreaseMethod::Uniform, 2);
    EXPECT_EQ(r.numVertices, (std::vector<int>{4, 10, 34}));
    EXPECT_EQ(r.numFaces, (std::vector<int>{4, 16, 64}));
    // Loop vertex point of valence 3: beta = 3/16, (1 - 3 beta) v + beta * sum = 7/16 v + 3/16 (-v) = v/4.
    EXPECT_TRUE(containsPoint(r.positions[1], 0.25f, 0.25f, 0.25f));
    // Edge point of 0-1: 3/8 (v0 + v1) + 1/8 (v2 + v3) = (0, 0, 1/2).
    EXPECT_TRUE(containsPoint(r.positions[1], 0.0f, 0.0f, 0.5f));
}

// Collapsed edges anywhere in a face, as catmull-clark reads them: catmark_nonman_quadpole8 with
// its `f 4 3 5 5` quads rotated so that the collapsed edge wraps around (`5 4 3 5`) or sits first
// (`5 5 4 3`), and one made a pentagon with two collapsed edges in a row (`4 3 5 5 5`), with a
// crease and the left-handed flag; OpenSubdiv refines the same faces.
TEST(OsdAgreementCollapsedEdges, RotatedAndRepeated) {
    io::ObjMesh mesh = io::readObj(meshPath("osd/catmark_nonman_quadpole8.obj"));
    std::vector<int> sizes, verts;
    for (int f = 0, b = 0; f < mesh.numFaces(); b += mesh.faceSizes[f++]) {
        std::vector<int> face(mesh.faceVerts.begin() + b, mesh.faceVerts.begin() + b + mesh.faceSizes[f]);
        if (f == 1) face.push_back(face.back());                               // 4 3 5 5 5
        if (f == 3) std::rotate(face.begin(), face.begin() + 3, face.end());  // 5 3 7 5
        if (f == 5) std::rotate(face.begin(), face.begin() + 2, face.end());  // 5 5 7 9
        sizes.push_back(int(face.size()));
        verts.insert(verts.end(), face.begin(), face.end());
    }
    mesh.faceSizes = sizes;
    mesh.faceVerts = verts;
    mesh.creasePairs = {0, 1};
    mesh.creaseSharpness = {2.5f};
    for (bool leftHanded : {false, true}) {
        Options options;
        options.scheme = Scheme::CatmullClark;
        options.leftHanded = leftHanded;
        Refiner refiner(mesh.descriptor(), options);
        refiner.refineUniform(3, TopologyDetail::Full);
        const std::vector<std::vector<float>> ours = evaluateLevels(refiner, mesh.positions, 3);
        const OsdRefinement osd = osdRefine(mesh, OsdScheme::Catmark, options.boundary, options.creaseMethod, 3);
        const double diagonal = boundingBoxDiagonal(mesh.positions);
        for (int L = 1; L <= 3; ++L) {
            const PositionMatch m = matchPositions(ours[L], osd.positions[L], diagonal, kTolerance);
            EXPECT_TRUE(m.countsEqual) << "level " << L << ": " << m.numOurs << " vs " << m.numReference;
            EXPECT_LE(m.maxRelative(), kTolerance) << "level " << L << (leftHanded ? " left-handed" : "");
            EXPECT_EQ(refiner.level(L).numFaces(), osd.numFaces[L]) << "level " << L;
        }
    }
}

// The smooth-triangle cases compare something: OpenSubdiv's two triangle rules differ at level 1
// next to the pyramid's triangles, and agree where there is no triangle.
TEST(OsdReference, SmoothTrianglesChangeTriangleEdgesOnly) {
    const io::ObjMesh pyramid = io::readObj(meshPath("osd/catmark_pyramid.obj"));
    const OsdRefinement plain =
        osdRefine(pyramid, OsdScheme::Catmark, BoundaryInterpolation::EdgeOnly, CreaseMethod::Uniform, 1, false);
    const OsdRefinement smooth =
        osdRefine(pyramid, OsdScheme::Catmark, BoundaryInterpolation::EdgeOnly, CreaseMethod::Uniform, 1, true);
    const double diagonal = boundingBoxDiagonal(pyramid.positions);
    EXPECT_GT(matchPositions(smooth.positions[1], plain.positions[1], diagonal, kTolerance).maxRelative(), 1e-3);
    const OsdRefinement cube = osdRefine(unitCube(), OsdScheme::Catmark, BoundaryInterpolation::EdgeOnly,
                                         CreaseMethod::Uniform, 1, true);
    EXPECT_TRUE(containsPoint(cube.positions[1], 2.0f / 9, 2.0f / 9, 2.0f / 9));
}

TEST(OsdReference, BilinearAndHoles) {
    io::ObjMesh cube = unitCube();
    const OsdRefinement b =
        osdRefine(cube, OsdScheme::Bilinear, BoundaryInterpolation::EdgeOnly, CreaseMethod::Uniform, 1);
    EXPECT_EQ(b.numVertices[1], 26);
    EXPECT_TRUE(containsPoint(b.positions[1], 0.5f, 0.0f, 0.0f));
    EXPECT_TRUE(containsPoint(b.positions[1], 0.0f, 0.0f, 0.0f));
    cube.holes = {0};
    const OsdRefinement h =
        osdRefine(cube, OsdScheme::Catmark, BoundaryInterpolation::EdgeOnly, CreaseMethod::Uniform, 1);
    EXPECT_EQ(h.numHoleFaces(0), 1);
    EXPECT_EQ(h.numHoleFaces(1), 4);
}

TEST(OsdReference, InfinitelySharpCreaseIsInterpolated) {
    io::ObjMesh cube = unitCube();
    // Every edge of the cube infinitely sharp: the limit is the cube's wireframe, so an edge point
    // is the edge midpoint and a corner stays.
    const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto& e : edges) {
        cube.creasePairs.push_back(e[0]);
        cube.creasePairs.push_back(e[1]);
        cube.creaseSharpness.push_back(10.0f);
    }
    const OsdRefinement r =
        osdRefine(cube, OsdScheme::Catmark, BoundaryInterpolation::EdgeOnly, CreaseMethod::Uniform, 1);
    EXPECT_TRUE(containsPoint(r.positions[1], 0.5f, 0.0f, 0.0f));
    EXPECT_TRUE(containsPoint(r.positions[1], 0.0f, 0.0f, 0.0f));
    EXPECT_EQ(r.topology[0].vertexRule[0], 8) << vertexRuleName(r.topology[0].vertexRule[0]);
}

TEST(PositionMatcher, PermutationAndPerturbation) {
    const OsdRefinement r =
        osdRefine(unitCube(), OsdScheme::Catmark, BoundaryInterpolation::EdgeOnly, CreaseMethod::Uniform, 4);
    const std::vector<float>& ref = r.positions[4];
    const int n = int(ref.size() / 3);
    ASSERT_EQ(n, 1538);
    // A deterministic permutation.
    std::vector<int> perm(n);
    for (int i = 0; i < n; ++i) perm[i] = int((size_t(i) * 7919) % size_t(n));
    std::vector<float> shuffled(ref.size());
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) shuffled[3 * size_t(i) + c] = ref[3 * size_t(perm[i]) + c];
    const double diag = std::sqrt(3.0);
    PositionMatch m = matchPositions(shuffled, ref, diag, kTolerance);
    EXPECT_TRUE(m.countsEqual);
    EXPECT_EQ(m.maxDistance, 0.0);
    EXPECT_EQ(m.numCollisions, 0);
    for (int i = 0; i < n; ++i) ASSERT_EQ(m.ourToReference[i], perm[i]);

    // One vertex moved: found, with its distance.
    shuffled[3 * 100 + 1] += 0.01f;
    m = matchPositions(shuffled, ref, diag, kTolerance);
    EXPECT_NEAR(m.maxDistance, 0.01, 1e-6);
    EXPECT_EQ(m.worstOurs, 100);
    EXPECT_EQ(m.outliers, std::vector<int>{100});

    // A duplicated vertex in place of another: not one-to-one, the displaced one is far.
    std::vector<float> dup = ref;
    for (int c = 0; c < 3; ++c) dup[3 * 5 + c] = dup[3 * 6 + c];
    m = matchPositions(dup, ref, diag, kTolerance);
    EXPECT_GE(m.numCollisions, 1);
    EXPECT_GT(m.maxRelative(), kTolerance);

    // Far-away point (exercises the exhaustive fallback) and count mismatch.
    std::vector<float> extra = ref;
    extra.insert(extra.end(), {100.0f, 100.0f, 100.0f});
    m = matchPositions(extra, ref, diag, kTolerance);
    EXPECT_FALSE(m.countsEqual);
    EXPECT_GT(m.maxRelative(), 1.0);
}

}  // namespace
}  // namespace quadtri::test
