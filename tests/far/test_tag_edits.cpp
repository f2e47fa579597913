// Refiner::applyEdits against a Refiner built from the edited descriptor: every level's tags and
// every per-level table stencil for stencil, bit for bit, for every mesh and scheme; a hundred
// edits in a row; the report naming exactly the stencils that changed; refused edits.
#include <cstring>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "far/schemes/scheme.h"
#include "tests/far/edit_support.h"
#include "tests/test_support.h"

namespace quadtri::test {
namespace {

bool sameStencil(const StencilTable& a, const StencilTable& b, int i) {
    const int n = a.size(i);
    return n == b.size(i) &&
           std::equal(a.indices.begin() + a.offsets[i], a.indices.begin() + a.offsets[i + 1],
                      b.indices.begin() + b.offsets[i]) &&
           std::memcmp(a.weightsOf(i), b.weightsOf(i), sizeof(float) * std::size_t(n)) == 0;
}

// The first stencil where the tables differ, or -1.
int firstDifference(const StencilTable& a, const StencilTable& b) {
    if (a.numStencils() != b.numStencils()) return std::min(a.numStencils(), b.numStencils());
    for (int i = 0; i < a.numStencils(); ++i)
        if (!sameStencil(a, b, i)) return i;
    return -1;
}

// Every level's tags and every per-level and face-varying table, stencil for stencil.
void expectSameRefiner(const Refiner& edited, const Refiner& rebuilt, const std::string& where) {
    ASSERT_EQ(edited.maxLevel(), rebuilt.maxLevel()) << where;
    for (int L = 0; L <= edited.maxLevel(); ++L) {
        const Topology &a = edited.level(L), &b = rebuilt.level(L);
        EXPECT_EQ(a.edgeSharpness, b.edgeSharpness) << where << ", level " << L;
        EXPECT_EQ(a.vertSharpness, b.vertSharpness) << where << ", level " << L;
        EXPECT_EQ(a.faceHole, b.faceHole) << where << ", level " << L;
        if (L == 0) continue;
        EXPECT_EQ(firstDifference(edited.levelStencils(L), rebuilt.levelStencils(L)), -1) << where << ", level " << L;
        for (int c = 0; c < edited.numFVarChannels(); ++c)
            EXPECT_EQ(firstDifference(edited.fvarLevelStencils(c, L), rebuilt.fvarLevelStencils(c, L)), -1)
                << where << ", channel " << c << ", level " << L;
    }
}

// Edits with and without holes on every mesh under every scheme, both crease methods.
TEST(TagEdits, EqualARebuildOnEveryMeshAndScheme) {
    std::mt19937 random(7);
    for (const std::string& name : allMeshes()) {
        io::ObjMesh mesh = io::readObj(meshPath(name));
        const int levels = mesh.numFaces() > 2000 ? 1 : 3;
        for (Scheme scheme : allSchemes()) {
            Options options;
            options.scheme = scheme;
            options = mesh.applyTags(options);
            if (scheme == Scheme::SchaeferWarren || scheme == Scheme::CatmullClark)
                options.creaseMethod = random() % 2 ? CreaseMethod::Chaikin : CreaseMethod::Uniform;
            std::unique_ptr<Refiner> refiner;
            try {
                refiner = build(mesh, options, levels);
            } catch (const TopologyError&) {
                continue;  // a scheme that refuses the mesh (loop and quads)
            }
            // Holes only where level 0's faces are the file's (no face read as several loops).
            const bool holes = refiner->faces(0).numFaces() == mesh.numFaces();
            io::ObjMesh edited = mesh;
            for (int trial = 0; trial < 3; ++trial) {
                const TagEdits edits = randomEdits(refiner->level(0), random, holes);
                refiner->applyEdits(edits);
                addTags(edited, edits);
                const std::string where = name + ", " + toString(scheme) + ", edit " + std::to_string(trial);
                expectSameRefiner(*refiner, *build(edited, options, levels), where);
                if (HasFailure()) return;
            }
        }
    }
}

// A hundred random edits in a row on one Refiner, compared with a rebuild every ten.
TEST(TagEdits, AHundredEditsInARowEqualARebuild) {
    const struct {
        const char* mesh;
        Scheme scheme;
        CreaseMethod method;
    } cases[] = {{"mixed/cylinder_capped_creased.obj", Scheme::SchaeferWarren, CreaseMethod::Uniform},
                 {"mixed/mixed_torus.obj", Scheme::SchaeferWarren, CreaseMethod::Chaikin},
                 {"mixed/checker_cube.obj", Scheme::CatmarkButterfly, CreaseMethod::Uniform},
                 {"osd/catmark_pawn.obj", Scheme::CatmullClark, CreaseMethod::Chaikin},
                 {"osd/loop_cube.obj", Scheme::Loop, CreaseMethod::Uniform}};
    for (const auto& c : cases) {
        io::ObjMesh mesh = io::readObj(meshPath(c.mesh));
        Options options;
        options.scheme = c.scheme;
        options = mesh.applyTags(options);
        options.creaseMethod = c.method;
        std::unique_ptr<Refiner> refiner = build(mesh, options, 3);
        std::mt19937 random(11);
        for (int k = 1; k <= 100; ++k) {
            const TagEdits edits = randomEdits(refiner->level(0), random, true);
            refiner->applyEdits(edits);
            addTags(mesh, edits);
            if (k % 10 == 0)
                expectSameRefiner(*refiner, *build(mesh, options, 3),
                                  std::string(c.mesh) + ", edit " + std::to_string(k));
            if (HasFailure()) return;
        }
    }
}

// The report lists exactly the stencils that differ from before the edit, and the tags.
TEST(TagEdits, TheReportNamesWhatChanged) {
    io::ObjMesh mesh = io::readObj(meshPath("mixed/mixed_torus.obj"));
    Options options;
    options.scheme = Scheme::SchaeferWarren;
    std::unique_ptr<Refiner> refiner = build(mesh, options, 3);
    std::mt19937 random(3);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<StencilTable> before;
        std::vector<Topology> levelsBefore;
        for (int L = 0; L <= 3; ++L) levelsBefore.push_back(refiner->level(L));
        for (int L = 1; L <= 3; ++L) before.push_back(refiner->levelStencils(L));
        const EditReport report = refiner->applyEdits(randomEdits(refiner->level(0), random, true));
        ASSERT_EQ(report.levels.size(), 4u);
        for (int L = 0; L <= 3; ++L) {
            const Topology &t = refiner->level(L), &old = levelsBefore[std::size_t(L)];
            std::vector<int> edges, vertices, faces;
            for (int e = 0; e < t.numEdges(); ++e)
                if (t.edgeSharpness[std::size_t(e)] != old.edgeSharpness[std::size_t(e)]) edges.push_back(e);
            for (int v = 0; v < t.numVertices; ++v)
                if (t.vertSharpness[std::size_t(v)] != old.vertSharpness[std::size_t(v)]) vertices.push_back(v);
            for (int f = 0; f < t.numFaces(); ++f)
                if (t.faceHole[std::size_t(f)] != old.faceHole[std::size_t(f)]) faces.push_back(f);
            const EditedLevel& level = report.levels[std::size_t(L)];
            EXPECT_EQ(level.edges, edges) << "level " << L;
            EXPECT_EQ(level.vertices, vertices) << "level " << L;
            EXPECT_EQ(level.faces, faces) << "level " << L;
            if (L == 0) continue;
            const StencilTable& table = refiner->levelStencils(L);
            std::vector<int> changed;
            bool resized = false;
            for (int i = 0; i < table.numStencils(); ++i)
                if (!sameStencil(table, before[std::size_t(L) - 1], i)) {
                    changed.push_back(i);
                    resized = resized || table.size(i) != before[std::size_t(L) - 1].size(i);
                }
            EXPECT_EQ(level.stencils, changed) << "level " << L;
            EXPECT_EQ(level.tableResized, resized) << "level " << L;
            EXPECT_GE(level.recomputedStencils, int(changed.size()));
        }
    }
}

// Dragging a crease through many sharpness values keeps the weight pool bounded.
TEST(TagEdits, APoolOfManySharpnessValuesStaysBounded) {
    io::ObjMesh mesh = io::readObj(meshPath("mixed/mixed_torus.obj"));
    const Options options = optionsOf(mesh, Scheme::SchaeferWarren);
    std::unique_ptr<Refiner> refiner = build(mesh, options, 2);
    const Topology& level0 = refiner->level(0);
    const int a = level0.edgeVerts[0], b = level0.edgeVerts[1];
    std::size_t largest = 0;
    for (int k = 1; k <= 2000; ++k) {
        TagEdits edits;
        edits.setCrease(a, b, 0.001f * float(k));
        refiner->applyEdits(edits);
        for (int L = 1; L <= 2; ++L) largest = std::max(largest, refiner->levelStencils(L).weights.size());
    }
    addTags(mesh, [&] {
        TagEdits last;
        last.setCrease(a, b, 2.0f);
        return last;
    }());
    std::size_t built = 0;
    const std::unique_ptr<Refiner> rebuilt = build(mesh, options, 2);
    for (int L = 1; L <= 2; ++L) built = std::max(built, rebuilt->levelStencils(L).weights.size());
    EXPECT_LT(largest, 3 * built + 8192);
}

TEST(TagEdits, RefusedEditsNameTheItemAndChangeNothing) {
    io::ObjMesh mesh = io::readObj(meshPath("mixed/mixed_torus.obj"));
    const Options options = optionsOf(mesh, Scheme::SchaeferWarren);
    std::unique_ptr<Refiner> refiner = build(mesh, options, 2);
    const Topology& level0 = refiner->level(0);
    const int a = level0.edgeVerts[0], b = level0.edgeVerts[1];
    auto refusal = [&](const TagEdits& edits) {
        const std::vector<float> before = refiner->level(1).edgeSharpness;
        std::string message = "(no exception)";
        try {
            refiner->applyEdits(edits);
        } catch (const TopologyError& e) {
            message = e.what();
        }
        EXPECT_EQ(refiner->level(1).edgeSharpness, before) << message;
        return message;
    };
    TagEdits notAnEdge;
    notAnEdge.setCrease(a, b, 2.0f);  // taken: refused edits come later in the same batch
    int far = 0;
    while (findEdge(level0, a, far) >= 0 || far == a) ++far;
    notAnEdge.setCrease(a, far, 2.0f);
    EXPECT_EQ(refusal(notAnEdge),
              "crease 1: vertices " + std::to_string(a) + ", " + std::to_string(far) + " are not an edge of level 0");
    TagEdits outOfRange;
    outOfRange.setCorner(level0.numVertices, 1.0f);
    EXPECT_EQ(refusal(outOfRange), "corner 0: vertex " + std::to_string(level0.numVertices) +
                                       " is out of range (level 0 has " + std::to_string(level0.numVertices) +
                                       " vertices)");
    TagEdits notANumber;
    notANumber.setCrease(a, b, std::nanf(""));
    EXPECT_EQ(refusal(notANumber), "crease 0: sharpness is not a finite number");
    TagEdits negative;
    negative.setCorner(a, -1.0f);
    EXPECT_NE(refusal(negative).find("corner 0: negative sharpness"), std::string::npos);
    TagEdits noFace;
    noFace.setHole(-1, true);
    EXPECT_EQ(refusal(noFace),
              "hole 0: face -1 is out of range (level 0 has " + std::to_string(level0.numFaces()) + " faces)");
}

}  // namespace
}  // namespace quadtri::test

namespace quadtri::test {
namespace {

// Creases and corners on and next to the tri/quad seam, where the mixed schemes' masks read the
// most (Schaefer-Warren's unzipped copies, Butterfly's wings): one at a time, each undone after.
TEST(TagEdits, EditsAtTheSeamEqualARebuild) {
    for (const char* name : {"mixed/mixed_torus.obj", "mixed/cylinder_capped.obj", "mixed/checker_cube.obj"}) {
        const io::ObjMesh mesh = io::readObj(meshPath(name));
        for (Scheme scheme : allSchemes()) {
            if (!internal::rulesOf(scheme).acceptsNonTriangles()) continue;
            Options options;
            options.scheme = scheme;
            options = mesh.applyTags(options);
            std::unique_ptr<Refiner> refiner = build(mesh, options, 2);
            const Topology level0 = refiner->level(0);
            int tried = 0;
            for (int e = 0; e < level0.numEdges() && tried < 24; ++e) {
                const int a = level0.edgeVerts[2 * std::size_t(e)], b = level0.edgeVerts[2 * std::size_t(e) + 1];
                if (!((level0.vertFlags[std::size_t(a)] | level0.vertFlags[std::size_t(b)]) & kVertexSeam)) continue;
                ++tried;
                for (float s : {0.5f, 1.5f, kInfiniteSharpness}) {
                    TagEdits edits;
                    (tried % 3 == 0) ? edits.setCorner(a, s) : edits.setCrease(a, b, s);
                    refiner->applyEdits(edits);
                    io::ObjMesh edited = mesh;
                    addTags(edited, edits);
                    expectSameRefiner(*refiner, *build(edited, options, 2),
                                      std::string(name) + ", " + toString(scheme) + ", edge " + std::to_string(e));
                    if (HasFailure()) return;
                    TagEdits undo;
                    (tried % 3 == 0) ? undo.setCorner(a, 0.0f) : undo.setCrease(a, b, 0.0f);
                    refiner->applyEdits(undo);
                }
            }
        }
    }
}

}  // namespace
}  // namespace quadtri::test
