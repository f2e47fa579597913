// The viewer's parts that need no window: picking the nearest projected edge, the script
// parser's errors, and the sharpness edits with the cage they save (read back by the OBJ reader).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "tools/view/core/cage_edits.h"
#include "tools/view/core/document.h"
#include "tools/view/core/picking.h"
#include "tools/view/core/script.h"

namespace quadtri::test {
namespace {

using view::ScreenPoint;

ScreenPoint at(float x, float y, float depth = 1.0f) { return {glm::vec2(x, y), depth, true}; }

TEST(Picking, DistanceToASegmentIsToItsNearestPoint) {
    EXPECT_FLOAT_EQ(view::distanceToSegment({5, 3}, {0, 0}, {10, 0}), 3.0f);  // beside the middle
    EXPECT_FLOAT_EQ(view::distanceToSegment({13, 4}, {0, 0}, {10, 0}), 5.0f);  // past an end: to the end
    EXPECT_FLOAT_EQ(view::distanceToSegment({3, 4}, {0, 0}, {0, 0}), 5.0f);    // a point
}

TEST(Picking, NearestEdgeWithinTheRadiusOnly) {
    // A square, 100 pixels wide, and its diagonal.
    const std::vector<ScreenPoint> points{at(0, 0), at(100, 0), at(100, 100), at(0, 100)};
    const std::vector<uint32_t> edges{0, 1, 1, 2, 2, 3, 3, 0, 0, 2};
    EXPECT_EQ(view::nearestEdge(points, edges, {50, 3}, 6.0f), 0);
    EXPECT_EQ(view::nearestEdge(points, edges, {97, 50}, 6.0f), 1);
    EXPECT_EQ(view::nearestEdge(points, edges, {52, 49}, 6.0f), 4);  // the diagonal
    EXPECT_EQ(view::nearestEdge(points, edges, {25, 60}, 6.0f), -1);  // 25 px from the left edge, 24.7 from the diagonal
    EXPECT_EQ(view::nearestEdge(points, edges, {50, -7}, 6.0f), -1);
}

TEST(Picking, OfTwoEdgesOnTopOfEachOtherTheNearerTheCameraWins) {
    const std::vector<ScreenPoint> points{at(0, 0, 5), at(100, 0, 5), at(0, 0.2f, 2), at(100, 0.2f, 2)};
    const std::vector<uint32_t> edges{0, 1, 2, 3};
    EXPECT_EQ(view::nearestEdge(points, edges, {50, 0.1f}, 6.0f), 1);
}

TEST(Picking, EdgesWithAnEndBehindTheCameraAreNotPicked) {
    std::vector<ScreenPoint> points{at(0, 0), at(100, 0)};
    points[1].visible = false;
    EXPECT_EQ(view::nearestEdge(points, {0, 1}, {50, 0}, 6.0f), -1);
    EXPECT_EQ(view::nearestPoint(points, {99, 0}, 6.0f), -1);
    EXPECT_EQ(view::nearestPoint(points, {2, 1}, 6.0f), 0);
}

TEST(Picking, ProjectionPutsTheTargetAtTheViewportCentre) {
    // Looking down -z at the origin from z = 5; Vulkan's y points down.
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(90.0f), 2.0f, 0.1f, 100.0f);
    projection[1][1] = -projection[1][1];
    const float xyz[9] = {0, 0, 0, 0, 5, 0, 0, 0, 10};  // the target, 5 up (the top edge at 90 degrees), behind
    const std::vector<ScreenPoint> p = view::projectPoints(projection * view, xyz, 3, {100, 50}, {400, 200});
    EXPECT_NEAR(p[0].pixel.x, 300.0f, 1e-3f);
    EXPECT_NEAR(p[0].pixel.y, 150.0f, 1e-3f);
    EXPECT_NEAR(p[1].pixel.y, 50.0f, 1e-3f);  // the viewport's top
    EXPECT_TRUE(p[0].visible && p[1].visible);
    EXPECT_FALSE(p[2].visible);
}

std::string parseError(const std::string& text) {
    std::istringstream in(text);
    try {
        view::parseScript(in, "s.txt");
    } catch (const view::ScriptError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Script, ParsesCommandsWithTheirLines) {
    std::istringstream in("# a comment\nselect-edge 1 2\n\n  sharpness inf  # infinite\nlevel 6\nscheme loop\nquit\n");
    const std::vector<view::ScriptCommand> c = view::parseScript(in, "s.txt");
    ASSERT_EQ(c.size(), 5u);
    EXPECT_EQ(c[0].verb, view::ScriptVerb::SelectEdge);
    EXPECT_EQ(c[0].line, 2);
    EXPECT_EQ(c[0].numbers, (std::vector<double>{1, 2}));
    EXPECT_EQ(c[1].verb, view::ScriptVerb::Sharpness);
    EXPECT_EQ(c[1].line, 4);
    EXPECT_TRUE(std::isinf(c[1].numbers[0]));
    EXPECT_EQ(c[3].words, (std::vector<std::string>{"loop"}));
    EXPECT_EQ(c[4].verb, view::ScriptVerb::Quit);
}

TEST(Script, ErrorsNameTheFileAndLine) {
    EXPECT_EQ(parseError("level 2\nzoom 3\n").rfind("s.txt:2: unknown command 'zoom' (expected one of ", 0), 0u);
    EXPECT_EQ(parseError("select-edge 1\n"), "s.txt:1: 'select-edge' takes 2 arguments, got 1");
    EXPECT_EQ(parseError("quit now\n"), "s.txt:1: 'quit' takes 0 arguments, got 1");
    EXPECT_EQ(parseError("\nselect-edge 0 2\n"), "s.txt:2: 'select-edge': '0' is not a positive integer");
    EXPECT_EQ(parseError("select-vertex 1.5\n"), "s.txt:1: 'select-vertex': '1.5' is not a positive integer");
    EXPECT_EQ(parseError("level 7\n"), "s.txt:1: 'level': level 7 is outside 0-6");
    EXPECT_EQ(parseError("level two\n"), "s.txt:1: 'level': 'two' is not a number");
    EXPECT_EQ(parseError("sharpness -1\n"), "s.txt:1: 'sharpness': sharpness -1 is negative");
    EXPECT_EQ(parseError("sharpness 1e999\n"), "s.txt:1: 'sharpness': '1e999' is not a number");
    EXPECT_EQ(parseError("camera 30 nan\n"), "s.txt:1: 'camera': 'nan' is not a number");
    EXPECT_EQ(parseError("level 3x\n"), "s.txt:1: 'level': '3x' is not a number");
}

TEST(Script, AMissingFileIsAnError) {
    EXPECT_THROW(view::readScript("/nonexistent/script.txt"), view::ScriptError);
}

io::ObjMesh quadStrip() {
    std::istringstream in("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nvt 0 0\nvt 1 1\n"
                          "f 1/1 2/2 5/1 4/2\nf 2/1 3/2 6/1 5/2\nt crease 2/1/0 1 4 3\nt crease 2/1/0 4 1 2\n"
                          "t interpolateboundary 1/0/0 1\nt creasemethod 0/0/1 chaikin\n");
    return io::parseObj(in, "strip.obj");
}

TEST(CageEdits, TheLastEntryOfAnEdgeIsItsSharpnessAndAnEditReplacesThemAll) {
    io::ObjMesh mesh = quadStrip();
    EXPECT_FLOAT_EQ(view::creaseSharpness(mesh, 1, 4), 2.0f);  // the later entry, either order
    view::setCreaseSharpness(mesh, 4, 1, 7.5f);
    EXPECT_EQ(mesh.creaseSharpness, (std::vector<float>{7.5f}));
    view::setCreaseSharpness(mesh, 1, 4, 0.0f);
    EXPECT_TRUE(mesh.creaseSharpness.empty());
    EXPECT_TRUE(mesh.creaseLines.empty());
    view::setCornerSharpness(mesh, 2, 3.0f);
    view::setCornerSharpness(mesh, 2, 4.0f);
    EXPECT_EQ(mesh.corners, (std::vector<int>{2}));
    EXPECT_FLOAT_EQ(view::cornerSharpness(mesh, 2), 4.0f);
}

TEST(CageEdits, TheSavedCageReadsBackWithItsTags) {
    io::ObjMesh mesh = quadStrip();
    view::setCreaseSharpness(mesh, 0, 1, 10.0f);
    view::setCornerSharpness(mesh, 5, 1.25f);
    std::stringstream file;
    view::writeCage(file, mesh);
    const io::ObjMesh back = io::parseObj(file, "back.obj");
    EXPECT_TRUE(back.warnings.empty());
    EXPECT_EQ(back.positions, mesh.positions);
    EXPECT_EQ(back.faceVerts, mesh.faceVerts);
    EXPECT_EQ(back.faceUVs, mesh.faceUVs);
    EXPECT_EQ(back.uvs, mesh.uvs);
    EXPECT_EQ(back.creasePairs, mesh.creasePairs);
    EXPECT_EQ(back.creaseSharpness, mesh.creaseSharpness);
    EXPECT_EQ(back.corners, std::vector<int>{5});
    EXPECT_EQ(back.cornerSharpness, std::vector<float>{1.25f});
    EXPECT_EQ(back.boundary, BoundaryInterpolation::EdgeAndCorner);
    EXPECT_EQ(back.creaseMethod, CreaseMethod::Chaikin);
    EXPECT_NE(file.str().find("t crease 2/1/0 0 1 10\n"), std::string::npos);
}

TEST(Document, SelectionWithShiftAddsAndTogglesAndSharpnessMarksEdits) {
    view::Document doc;
    const std::string path = testing::TempDir() + "strip.obj";
    {
        std::stringstream text;
        view::writeCage(text, quadStrip());
        io::writeReplacing(path, [&text](std::ostream& out) { out << text.str(); });
    }
    doc.load(path);
    EXPECT_FALSE(doc.unsaved());
    doc.selectEdge(4, 1, false);
    doc.selectEdge(0, 1, true);
    EXPECT_EQ(doc.selectedEdges().size(), 2u);
    EXPECT_FLOAT_EQ(doc.selectionSharpness(), 2.0f);  // the first selected: (1, 4)
    doc.selectEdge(1, 0, true);                        // shift on a selected edge: off again
    EXPECT_EQ(doc.selectedEdges().size(), 1u);
    doc.setSelectionSharpness(100.0f);                 // past 10: infinite, stored as 10
    EXPECT_TRUE(doc.unsaved());
    EXPECT_FLOAT_EQ(view::creaseSharpness(doc.mesh(), 1, 4), 10.0f);
    doc.save(path);
    EXPECT_FALSE(doc.unsaved());
    view::Document failed = doc;
    EXPECT_THROW(failed.load(path + ".missing"), io::ObjError);
    EXPECT_EQ(failed.mesh().positions, doc.mesh().positions);  // kept
}

}  // namespace
}  // namespace quadtri::test
