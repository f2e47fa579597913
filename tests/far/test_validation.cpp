// Malformed descriptors must be refused with a TopologyError naming the offending face, vertex,
// crease, corner or hole; never a crash, another exception type, or silent acceptance.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <quadtri/far/refiner.h>
#include "tests/local_meshes.h"
#include "tests/test_support.h"

namespace {

using namespace quadtri;
using namespace quadtri::test;

// A cube: 8 vertices, 6 quads (face 2 is the one the tests break).
LocalMesh cube() {
    LocalMesh m;
    m.numVertices = 8;
    m.addFace({0, 1, 3, 2});
    m.addFace({4, 6, 7, 5});
    m.addFace({0, 4, 5, 1});
    m.addFace({2, 3, 7, 6});
    m.addFace({0, 2, 6, 4});
    m.addFace({1, 5, 7, 3});
    return m;
}

// A cube whose face 2 has the given corners.
LocalMesh cubeWithFace2(const std::vector<int>& corners) {
    const LocalMesh c = cube();
    LocalMesh m;
    m.numVertices = c.numVertices;
    int offset = 0;
    for (int f = 0; f < c.numFaces(); ++f) {
        const int n = c.faceSizes[f];
        if (f == 2)
            m.addFace(corners);
        else
            m.addFace(std::vector<int>(c.faceVerts.begin() + offset, c.faceVerts.begin() + offset + n));
        offset += n;
    }
    return m;
}

// What building a Refiner from `d` threw: a TopologyError's message and the component/index it
// blames, or thrown == false. Any other exception propagates and fails the test.
struct Refusal {
    bool thrown = false;
    std::string message;
    TopologyError::Component component = TopologyError::Component::None;
    int index = -1;
};

Refusal refusalOf(const TopologyDescriptor& d, const Options& o = Options()) {
    Refusal r;
    try {
        Refiner refiner(d, o);
    } catch (const TopologyError& e) {
        r.thrown = true;
        r.message = e.what();
        r.component = e.component();
        r.index = e.index();
    }
    return r;
}

std::string errorOf(const TopologyDescriptor& d, const Options& o = Options()) {
    return refusalOf(d, o).message;
}

using Component = TopologyError::Component;

// Refused with every substring of `mustContain` in the message; where `component` is given, the
// error also blames that input item (for a reader to point at the file line).
void expectRefused(const TopologyDescriptor& d, const std::vector<std::string>& mustContain, const std::string& what,
                   Component component = Component::None, int index = -1) {
    const Refusal r = refusalOf(d);
    EXPECT_TRUE(r.thrown) << what << ": accepted";
    for (const std::string& s : mustContain)
        EXPECT_NE(r.message.find(s), std::string::npos)
            << what << ": message \"" << r.message << "\" lacks \"" << s << "\"";
    if (component != Component::None) {
        EXPECT_EQ(int(r.component), int(component)) << what << ": " << r.message;
        EXPECT_EQ(r.index, index) << what << ": " << r.message;
    }
}

TEST(Validation, ValidCubeIsAccepted) {
    const LocalMesh m = cube();
    EXPECT_EQ(errorOf(m.descriptor()), "");
}

TEST(Validation, FaceWithFewerThanThreeVertices) {
    expectRefused(cubeWithFace2({0, 4}).descriptor(), {"face 2", "2 vertices", "at least 3"}, "2-gon", Component::Face,
                  2);
    expectRefused(cubeWithFace2({0}).descriptor(), {"face 2", "1 vertices", "at least 3"}, "1-gon", Component::Face, 2);
    expectRefused(cubeWithFace2({}).descriptor(), {"face 2", "0 vertices", "at least 3"}, "0-gon", Component::Face, 2);
    // A negative count: face 2 claims -1 corners (the arrays are otherwise the cube's).
    LocalMesh m = cube();
    m.faceSizes[2] = -1;
    expectRefused(m.descriptor(), {"face 2", "at least 3"}, "negative size", Component::Face, 2);
}

TEST(Validation, VertexIndexOutOfRange) {
    expectRefused(cubeWithFace2({0, 4, 8, 1}).descriptor(), {"face 2", "vertex index 8", "out of range"}, "index 8",
                  Component::Face, 2);
    expectRefused(cubeWithFace2({0, 4, -1, 1}).descriptor(), {"face 2", "vertex index -1", "out of range"}, "index -1",
                  Component::Face, 2);
    expectRefused(cubeWithFace2({0, 4, 1000000, 1}).descriptor(), {"face 2", "1000000", "out of range"},
                  "index 1000000", Component::Face, 2);
}

// A face that repeats a vertex is read as the simple loops it walks around (far/topology/face_loops.h):
// the result must be the same surface, bitwise, as the mesh written with those loops as faces,
// with a warning naming the face and the vertex.
void expectSameRefinement(const LocalMesh& degenerate, const LocalMesh& clean, const std::string& what) {
    // Every scheme that takes quads and reads a repeated corner as face loops (Catmull-Clark keeps
    // a collapsed edge as OpenSubdiv does: test_catmull_clark).
    const std::vector<Scheme> schemes = schemesWhere([](const SchemeRules& rules) {
        return rules.acceptsNonTriangles() && rules.collapsedEdges() == CollapsedEdges::Drop;
    });
    for (Scheme scheme : schemes)
        for (bool leftHanded : {false, true}) {
            Options o;
            o.scheme = scheme;
            o.leftHanded = leftHanded;
            Refiner a(degenerate.descriptor(), o), b(clean.descriptor(), o);
            a.refineUniform(2, TopologyDetail::Full);
            b.refineUniform(2, TopologyDetail::Full);
            const std::string where = what + " under " + toString(scheme) + (leftHanded ? ", left-handed" : "");
            for (int L = 0; L <= 2; ++L) {
                EXPECT_EQ(cornersOf(a.faces(L)), cornersOf(b.faces(L))) << where << " level " << L;
                EXPECT_EQ(offsetsOf(a.faces(L)), offsetsOf(b.faces(L))) << where << " level " << L;
                EXPECT_EQ(holesOf(a.faces(L)), holesOf(b.faces(L))) << where << " level " << L;
            }
            for (int L = 1; L <= 2; ++L) {
                const StencilTable &ta = a.levelStencils(L), &tb = b.levelStencils(L);
                EXPECT_EQ(ta.indices, tb.indices) << where << " level " << L;
                EXPECT_EQ(ta.offsets, tb.offsets) << where << " level " << L;
                EXPECT_EQ(ta.weights, tb.weights) << where << " level " << L;
            }
        }
}

const TopologyDiagnostic& onlyWarning(const LocalMesh& m) {
    static std::vector<TopologyDiagnostic> kept;
    Refiner refiner(m.descriptor(), Options());
    kept = refiner.warnings();
    if (kept.size() != 1) throw std::runtime_error(std::to_string(kept.size()) + " warnings, expected 1");
    return kept[0];
}

TEST(Validation, BowTieFaceIsReadAsItsTwoLoops) {
    LocalMesh bowTie, triangles;
    bowTie.numVertices = triangles.numVertices = 5;
    bowTie.addFace({0, 1, 2, 0, 3, 4});
    triangles.addFace({0, 1, 2});
    triangles.addFace({0, 3, 4});
    expectSameRefinement(bowTie, triangles, "bow tie 0 1 2 0 3 4");
    const TopologyDiagnostic& w = onlyWarning(bowTie);
    EXPECT_EQ(int(w.component), int(Component::Face));
    EXPECT_EQ(w.index, 0);
    EXPECT_EQ(w.vertex, 0);
    EXPECT_NE(w.message().find("read as 2 faces"), std::string::npos) << w.message();
    // A hole on the face makes both loops holes.
    LocalMesh holed = bowTie;
    const int hole = 0;
    TopologyDescriptor d = holed.descriptor();
    d.numHoles = 1;
    d.holeIndices = &hole;
    Refiner refiner(d, Options());
    EXPECT_EQ(refiner.level(0).faceHole, (std::vector<uint8_t>{1, 1}));
}

// `f 1 1 2 2` (OpenSubdiv's catmark_nonman_edges has one) and `f 1 2 1 3` have no area: left out,
// so the cube with such a face refines exactly as the cube.
TEST(Validation, FacesWithoutAreaAreLeftOut) {
    const LocalMesh plain = cube();
    struct Case {
        std::vector<int> corners;
        int vertex;
        const char* text;
    };
    for (const Case& c : {Case{{0, 0, 1, 1}, -1, "fewer than 3 distinct corners"},
                          Case{{0, 1, 0, 2}, 0, "appears again further on"},
                          Case{{5, 5, 5}, -1, "fewer than 3 distinct corners"},
                          Case{{2, 3, 2, 3}, 2, "pieces of fewer than 3 corners"}}) {
        LocalMesh m = plain;
        m.addFace(c.corners);
        std::string what = "cube + face";
        for (int v : c.corners) what += " " + std::to_string(v);
        expectSameRefinement(m, plain, what);
        const TopologyDiagnostic& w = onlyWarning(m);
        EXPECT_EQ(w.index, 6) << what;
        EXPECT_EQ(w.vertex, c.vertex) << what;
        EXPECT_NE(w.message().find(c.text), std::string::npos) << what << ": " << w.message();
        EXPECT_NE(w.message().find("left out"), std::string::npos) << what << ": " << w.message();
    }
}

// A pinched quad with one real loop: `0 1 3 2 1` is the quad's loop 1 3 2 ... read as the
// triangle 1 3 2 plus the dropped digon 0 1.
TEST(Validation, PinchedFaceKeepsItsRealLoop) {
    LocalMesh pinched, clean;
    pinched.numVertices = clean.numVertices = 4;
    pinched.addFace({0, 1, 3, 2, 1});
    clean.addFace({1, 3, 2});
    expectSameRefinement(pinched, clean, "0 1 3 2 1");
    EXPECT_NE(onlyWarning(pinched).message().find("1 piece of fewer than 3 corners left out"), std::string::npos)
        << onlyWarning(pinched).message();
}

// No faces, and vertices no face uses (the last one too), are valid input: such vertices are
// isolated and stay put at every level. (Indexing one past the end of an incidence array here
// aborted under _GLIBCXX_ASSERTIONS.)
TEST(Validation, IsolatedVerticesAndNoFaces) {
    for (int extra : {0, 1, 3}) {
        LocalMesh m;
        if (extra == 0) {
            m.numVertices = 4;  // no faces at all
        } else {
            m = cube();
            m.numVertices += extra;  // unused vertices after the last used one
        }
        for (Scheme scheme : schemesTakingQuads()) {
            Options o;
            o.scheme = scheme;
            Refiner refiner(m.descriptor(), o);
            refiner.refineUniform(3);
            const StencilTable table = refiner.factorizedStencils(3);
            const int n = table.numStencils();
            ASSERT_GE(n, m.numVertices);
            // The isolated vertices are the last vertex points: identity stencils.
            for (int k = 0; k < (extra == 0 ? m.numVertices : extra); ++k) {
                const int i = n - 1 - k, v = m.numVertices - 1 - k;
                ASSERT_EQ(table.size(i), 1) << toString(scheme);
                EXPECT_EQ(table.indices[size_t(table.offsets[i])], v) << toString(scheme);
                EXPECT_EQ(table.weightsOf(i)[0], 1.0f) << toString(scheme);
            }
            if (extra == 0) {
                EXPECT_EQ(refiner.faces(3).numFaces(), 0);
            }
        }
    }
}

// OpenSubdiv warns about a crease on a pair that is not an edge and goes on: so does quadtri, and
// the crease is ignored (the result equals the mesh without it).
TEST(Validation, CreaseOnAPairThatIsNotAnEdgeIsIgnoredWithAWarning) {
    LocalMesh m = cube();
    m.creasePairs = {0, 1, 0, 7, 0, 3};  // 0-1 is an edge, 0-7 the cube's diagonal, 0-3 a face diagonal
    m.creaseWeights = {2.0f, 2.0f, 2.0f};
    Refiner refiner(m.descriptor(), Options());
    ASSERT_EQ(refiner.warnings().size(), 2u);
    for (int k = 0; k < 2; ++k) {
        const TopologyDiagnostic& w = refiner.warnings()[size_t(k)];
        EXPECT_EQ(int(w.component), int(Component::Crease));
        EXPECT_EQ(w.index, k + 1);
        EXPECT_NE(w.message().find(k == 0 ? "0, 7" : "0, 3"), std::string::npos) << w.message();
        EXPECT_NE(w.message().find("not an edge"), std::string::npos) << w.message();
    }
    int sharp = 0;
    for (float s : refiner.level(0).edgeSharpness) sharp += s > 0;
    EXPECT_EQ(sharp, 1);  // only 0-1
}

TEST(Validation, MalformedCreases) {
    LocalMesh m = cube();
    m.creaseWeights = {2.0f, 2.0f};
    m.creasePairs = {0, 1, 2, 2};
    expectRefused(m.descriptor(), {"crease 1", "same vertex"}, "degenerate crease", Component::Crease, 1);
    m.creasePairs = {0, 1, 2, 9};
    expectRefused(m.descriptor(), {"crease 1", "9", "out of range"}, "crease vertex out of range", Component::Crease,
                  1);
    m.creasePairs = {-3, 1, 0, 1};
    expectRefused(m.descriptor(), {"crease 0", "-3", "out of range"}, "negative crease vertex", Component::Crease, 0);
}

TEST(Validation, NegativeOrNaNCreaseSharpness) {
    LocalMesh m = cube();
    m.creasePairs = {0, 1, 1, 3};
    m.creaseWeights = {1.0f, -1.0f};
    expectRefused(m.descriptor(), {"crease 1", "negative"}, "negative crease", Component::Crease, 1);
    m.creaseWeights = {std::numeric_limits<float>::quiet_NaN(), 1.0f};
    expectRefused(m.descriptor(), {"crease 0", "sharpness"}, "NaN crease", Component::Crease, 0);
    // A valid sharp crease is accepted.
    m.creaseWeights = {1.0f, 10.0f};
    EXPECT_EQ(errorOf(m.descriptor()), "");
}

TEST(Validation, CornerProblems) {
    LocalMesh m = cube();
    m.corners = {2, 5};
    m.cornerWeights = {1.0f, -2.0f};
    expectRefused(m.descriptor(), {"corner 1", "vertex 5", "negative"}, "negative corner", Component::Corner, 1);
    m.cornerWeights = {std::numeric_limits<float>::quiet_NaN(), 1.0f};
    expectRefused(m.descriptor(), {"corner 0", "vertex 2", "sharpness"}, "NaN corner", Component::Corner, 0);
    m.cornerWeights = {1.0f, 1.0f};
    m.corners = {2, 8};
    expectRefused(m.descriptor(), {"corner 1", "vertex 8", "out of range"}, "corner out of range", Component::Corner,
                  1);
    m.corners = {-1, 2};
    expectRefused(m.descriptor(), {"corner 0", "vertex -1", "out of range"}, "negative corner vertex",
                  Component::Corner, 0);
    m.corners = {2, 5};
    EXPECT_EQ(errorOf(m.descriptor()), "");
}

TEST(Validation, HoleFaceOutOfRange) {
    const LocalMesh m = cube();
    for (int bad : {6, -1, 100}) {
        const std::vector<int> holes = {1, bad};
        TopologyDescriptor d = m.descriptor();
        d.numHoles = 2;
        d.holeIndices = holes.data();
        expectRefused(d, {"hole 1", "face index " + std::to_string(bad), "out of range"}, "hole " + std::to_string(bad),
                      Component::Hole, 1);
    }
    const std::vector<int> ok = {1, 5};
    TopologyDescriptor d = m.descriptor();
    d.numHoles = 2;
    d.holeIndices = ok.data();
    EXPECT_EQ(errorOf(d), "");
}

TEST(Validation, NegativeCounts) {
    const LocalMesh m = cube();
    TopologyDescriptor d = m.descriptor();
    d.numVertices = -1;
    expectRefused(d, {"numVertices", "negative"}, "numVertices < 0");
    d = m.descriptor();
    d.numFaces = -2;
    expectRefused(d, {"numFaces", "negative"}, "numFaces < 0");
    d = m.descriptor();
    d.numCreases = -1;
    expectRefused(d, {"numCreases", "negative"}, "numCreases < 0");
    d = m.descriptor();
    d.numCorners = -1;
    expectRefused(d, {"numCorners", "negative"}, "numCorners < 0");
    d = m.descriptor();
    d.numHoles = -1;
    expectRefused(d, {"numHoles", "negative"}, "numHoles < 0");
    // Vertices too few for the faces.
    d = m.descriptor();
    d.numVertices = 7;
    expectRefused(d, {"face 1", "vertex index 7", "out of range"}, "numVertices 7", Component::Face, 1);
}

TEST(Validation, NullArraysWithNonzeroCounts) {
    const LocalMesh m = cube();
    const std::vector<int> pairs = {0, 1};
    const std::vector<float> weights = {1.0f};
    const std::vector<int> one = {0};
    TopologyDescriptor d = m.descriptor();
    d.numVertsPerFace = nullptr;
    expectRefused(d, {"numVertsPerFace", "null"}, "null numVertsPerFace");
    d = m.descriptor();
    d.faceVertIndices = nullptr;
    expectRefused(d, {"faceVertIndices", "null"}, "null faceVertIndices");
    d = m.descriptor();
    d.numCreases = 1;
    d.creaseWeights = weights.data();
    expectRefused(d, {"creaseVertexPairs", "null"}, "null creaseVertexPairs");
    d = m.descriptor();
    d.numCreases = 1;
    d.creaseVertexPairs = pairs.data();
    expectRefused(d, {"creaseWeights", "null"}, "null creaseWeights");
    d = m.descriptor();
    d.numCorners = 1;
    d.cornerWeights = weights.data();
    expectRefused(d, {"cornerVertexIndices", "null"}, "null cornerVertexIndices");
    d = m.descriptor();
    d.numCorners = 1;
    d.cornerVertexIndices = one.data();
    expectRefused(d, {"cornerWeights", "null"}, "null cornerWeights");
    d = m.descriptor();
    d.numHoles = 1;
    expectRefused(d, {"holeIndices", "null"}, "null holeIndices");
    // Zero counts with null arrays are fine: an empty mesh.
    TopologyDescriptor empty;
    EXPECT_EQ(errorOf(empty), "");
}

TEST(Validation, MemoryBudget) {
    const LocalMesh m = cube();
    Options tiny;
    tiny.memoryBudgetBytes = 3000;  // level 0 fits, level 1 does not
    std::unique_ptr<Refiner> refiner;
    ASSERT_NO_THROW(refiner = std::make_unique<Refiner>(m.descriptor(), tiny));
    const std::size_t estimate = refiner->estimateLevelBytes(1);
    EXPECT_GT(refiner->bytes() + estimate, 3000u);
    std::string message;
    try {
        refiner->refineUniform(1);
    } catch (const MemoryBudgetError& e) {
        message = e.what();
        EXPECT_EQ(e.needed(), refiner->bytes() + estimate);
        EXPECT_EQ(e.held(), refiner->bytes());
        EXPECT_EQ(e.budget(), 3000u);
        EXPECT_EQ(e.subject(), "level 1");
    }
    ASSERT_FALSE(message.empty()) << "a 3000-byte budget was accepted for an estimate of " << estimate;
    EXPECT_NE(message.find("bytes"), std::string::npos) << message;
    EXPECT_NE(message.find(std::to_string(refiner->bytes() + estimate)), std::string::npos) << message;
    EXPECT_NE(message.find("level 1"), std::string::npos) << message;
    EXPECT_EQ(refiner->maxLevel(), 0) << "refused before building anything";

    // The budget is inclusive: what the Refiner holds plus exactly the estimate passes, one byte
    // less fails.
    Options exact;
    exact.memoryBudgetBytes = refiner->bytes() + estimate;
    Refiner fits(m.descriptor(), exact);
    EXPECT_NO_THROW(fits.refineUniform(1));
    EXPECT_EQ(fits.maxLevel(), 1);
    // The next level is larger than the budget that fitted level 1.
    EXPECT_GT(fits.estimateLevelBytes(2), estimate);
    message.clear();
    try {
        fits.refineUniform(2);
    } catch (const TopologyError& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("level 2"), std::string::npos) << message;
    Options oneLess;
    oneLess.memoryBudgetBytes = exact.memoryBudgetBytes - 1;
    Refiner tight(m.descriptor(), oneLess);
    EXPECT_THROW(tight.refineUniform(1), TopologyError);

    // A faces-only last level (no edges yet) must not make the next level look cheaper.
    Refiner facesOnly(m.descriptor(), Options()), full(m.descriptor(), Options());
    facesOnly.refineUniform(1);
    full.refineUniform(1, TopologyDetail::Full);
    ASSERT_EQ(facesOnly.detail(1), TopologyDetail::FacesOnly);
    EXPECT_GE(facesOnly.estimateLevelBytes(2), full.estimateLevelBytes(2));
}

TEST(Validation, RefineToLevelZeroAndNegativeLevels) {
    const LocalMesh m = cube();
    Refiner refiner(m.descriptor(), Options());
    EXPECT_NO_THROW(refiner.refineUniform(0));
    EXPECT_EQ(refiner.maxLevel(), 0);
    EXPECT_EQ(refiner.faces(0).numVertices(), 8);
    EXPECT_EQ(refiner.faces(0).numFaces(), 6);
    EXPECT_EQ(refiner.level(0).numEdges(), 12);
    EXPECT_THROW(refiner.refineUniform(-1), TopologyError);
    EXPECT_EQ(refiner.maxLevel(), 0);
    // Refining again after level 0 still works and is idempotent for lower requests.
    refiner.refineUniform(1);
    EXPECT_EQ(refiner.maxLevel(), 1);
    refiner.refineUniform(0);
    EXPECT_EQ(refiner.maxLevel(), 1);
}

// A corner equal to the previous one (cyclically) is a collapsed edge: dropped, not an error.
TEST(Validation, CollapsedEdgeIsDropped) {
    const std::vector<int> sizes = {4, 4};
    const std::vector<int> verts = {0, 1, 2, 2, 3, 3, 1, 0};  // quads 0 1 2 2 and 3 3 1 0
    TopologyDescriptor d;
    d.numVertices = 4;
    d.numFaces = 2;
    d.numVertsPerFace = sizes.data();
    d.faceVertIndices = verts.data();
    Refiner refiner(d, Options());
    const Topology& t = refiner.level(0);
    ASSERT_EQ(t.numFaces(), 2);
    EXPECT_EQ(t.faceSize(0), 3);
    EXPECT_EQ(t.faceSize(1), 3);
    EXPECT_EQ(std::vector<int>(t.faceVerts.begin(), t.faceVerts.begin() + 3), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(std::vector<int>(t.faceVerts.begin() + 3, t.faceVerts.end()), (std::vector<int>{3, 1, 0}));
    EXPECT_EQ(t.numEdges(), 5);
}

}  // namespace
