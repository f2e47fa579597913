// `quadtri view` on an Xvfb server of the test's own, driven by a script, with the Vulkan validation layer on and silent:
// raising a cage edge's sharpness changes the screenshot near that edge (projected with the
// viewer's camera) and nowhere far from it; the saved cage carries the `t crease` tag; a file
// that fails to load keeps the mesh; no display, a bad script or a bad file: one message, status 2.
#include <gtest/gtest.h>

#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "tools/obj_io.h"
#include "tools/render/camera.h"
#include "tools/render/image.h"
#include "tools/view/core/cage_edits.h"
#include "tools/view/core/picking.h"

namespace quadtri::test {
namespace {

constexpr int kWidth = 640, kHeight = 480;
const std::string kTorus = std::string(QUADTRI_DATA) + "/mixed_torus.obj";

struct Outcome {
    int status = -1;
    std::string errors;  // stderr
};

// A file of the running test's own: ctest runs the cases in parallel.
std::string work(const std::string& name) {
    return testing::TempDir() + "viewer_" + testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + name;
}

std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// `command` through the shell with validation on and LeakSanitizer off (the X and Vulkan
// libraries keep blocks to the end), stderr kept.
Outcome run(const std::string& command) {
    const std::string errors = work("stderr.txt");
    const std::string line = "QUADTRI_VK_VALIDATION=1 ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 " + command +
                             " > /dev/null 2> '" + errors + "'";
    const int raw = std::system(line.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, readText(errors)};
}

// An Xvfb server of this process's own on a free display (Xvfb -displayfd picks it: no race
// with other tests' servers, as xvfb-run -a has), stopped at exit. Empty display: no Xvfb.
class Xvfb {
public:
    static const std::string& display() {
        static Xvfb server;
        return server.display_;
    }

private:
    Xvfb() {
        int fds[2];
        if (pipe(fds) != 0) return;
        pid_ = fork();
        if (pid_ == 0) {
            prctl(PR_SET_PDEATHSIG, SIGTERM);  // the server goes with the test, even one that crashes
            close(fds[0]);
            const std::string fd = std::to_string(fds[1]);
            execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1024x768x24", "-nolisten", "tcp",
                   static_cast<char*>(nullptr));
            _exit(127);
        }
        close(fds[1]);
        // The display number and a newline once the server accepts connections.
        std::string number;
        pollfd p{fds[0], POLLIN, 0};
        char c = 0;
        while (pid_ > 0 && poll(&p, 1, 20000) == 1 && read(fds[0], &c, 1) == 1 && c != '\n') number += c;
        close(fds[0]);
        if (!number.empty()) display_ = ":" + number;
    }
    ~Xvfb() {
        if (pid_ <= 0) return;
        kill(pid_, SIGTERM);
        waitpid(pid_, nullptr, 0);
    }
    pid_t pid_ = -1;
    std::string display_;
};

bool haveXvfb() { return !Xvfb::display().empty(); }

// The viewer on `mesh` on this process's Xvfb display, running `script`.
Outcome view(const std::string& mesh, const std::string& script) {
    const std::string path = work("script.txt");
    writeText(path, script);
    return run("DISPLAY=" + Xvfb::display() + " '" + QUADTRI_CLI + "' view '" + mesh + "' --size " +
               std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --level 3 --script '" + path + "'");
}

// Skips (or, with QUADTRI_REQUIRE_VULKAN, fails) when the run found no Vulkan device.
bool noDevice(const Outcome& r) { return r.status == 2 && r.errors.find("needs a Vulkan device") != std::string::npos; }

#define SKIP_WITHOUT_XVFB()                                                                         \
    if (!haveXvfb()) GTEST_SKIP() << "Xvfb is not installed or does not start (Debian: xvfb): the viewer needs a display"
#define SKIP_WITHOUT_DEVICE(r)                                                      \
    if (noDevice(r)) {                                                              \
        if (std::getenv("QUADTRI_REQUIRE_VULKAN")) FAIL() << r.errors;              \
        GTEST_SKIP() << "no Vulkan device that can present: " << r.errors;          \
    }

// The cage edges of `mesh` (consecutive face corners), each once, smaller vertex first.
std::vector<std::pair<int, int>> cageEdges(const io::ObjMesh& mesh) {
    std::vector<std::pair<int, int>> edges;
    std::size_t first = 0;
    for (int size : mesh.faceSizes) {
        for (int k = 0; k < size; ++k) {
            const int a = mesh.faceVerts[first + std::size_t(k)], b = mesh.faceVerts[first + std::size_t((k + 1) % size)];
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
        first += std::size_t(size);
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

int channelDifference(const render::Image& a, const render::Image& b, int x, int y) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
    return d;
}

TEST(Viewer, RaisingAnEdgesSharpnessChangesTheViewNearItOnlyAndTheSavedCageHasTheTag) {
    SKIP_WITHOUT_XVFB();
    const io::ObjMesh mesh = io::readObj(kTorus);
    // The viewer's camera at start: the default angles, framed on the cage's bounding sphere.
    render::Camera camera;
    camera.frame(render::boundingSphere(mesh.positions.data(), mesh.numVertices()), float(kWidth) / float(kHeight));
    const glm::mat4 viewProjection = camera.projection(float(kWidth) / float(kHeight), 1.0f) * camera.view();
    const std::vector<view::ScreenPoint> points =
        view::projectPoints(viewProjection, mesh.positions.data(), mesh.numVertices(), {0, 0}, {kWidth, kHeight});
    // The edge nearest the eye faces the camera, in the open.
    const std::vector<std::pair<int, int>> edges = cageEdges(mesh);
    std::pair<int, int> chosen = edges[0];
    float nearest = 1e30f;
    std::vector<float> lengths;
    for (const auto& [a, b] : edges) {
        const glm::vec3 mid = 0.5f * (glm::vec3(mesh.positions[3 * a], mesh.positions[3 * a + 1], mesh.positions[3 * a + 2]) +
                                      glm::vec3(mesh.positions[3 * b], mesh.positions[3 * b + 1], mesh.positions[3 * b + 2]));
        const float d = glm::length(mid - camera.eye());
        if (d < nearest) nearest = d, chosen = {a, b};
        lengths.push_back(glm::length(points[a].pixel - points[b].pixel));
    }
    // A cage edge's typical length on the screen.
    std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2), lengths.end());
    const float typical = lengths[lengths.size() / 2];
    const auto [a, b] = chosen;
    ASSERT_EQ(view::creaseSharpness(mesh, a, b), 0.0f);

    const std::string before = work("before.png"), after = work("after.png"), other = work("other.png");
    const std::string saved = work("saved.obj");
    const Outcome r = view(kTorus, "shading reflection-lines\nselect-edge " + std::to_string(a + 1) + " " + std::to_string(b + 1) + "\nscreenshot " +
                                   before + "\nsharpness 10\nscreenshot " + after +
                                   "\nlevel 2\nscheme catmull-clark\nscreenshot " + other + "\nsave " + saved + "\nquit\n");
    SKIP_WITHOUT_DEVICE(r);
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_EQ(r.errors.find("alidation"), std::string::npos) << r.errors;

    const render::Image smooth = render::readImage(before), creased = render::readImage(after);
    const render::Image changed = render::readImage(other);
    ASSERT_EQ(smooth.width, kWidth);
    ASSERT_EQ(smooth.height, kHeight);
    // Near: within a typical cage edge's length of the edge on the screen; far: beyond three,
    // where the edge's sharpness does not reach (the limit surface near a cage vertex depends on
    // the cage within two rings of faces of it).
    const uint8_t* corner = smooth.pixel(0, 0);  // the background
    int changedNear = 0, changedFar = 0, farSurface = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const float d = view::distanceToSegment({x + 0.5f, y + 0.5f}, points[a].pixel, points[b].pixel);
            const int difference = channelDifference(smooth, creased, x, y);
            if (d < typical) changedNear += difference > 16;
            if (d > 3.0f * typical) {
                const uint8_t* p = smooth.pixel(x, y);
                farSurface += std::abs(p[0] - corner[0]) + std::abs(p[1] - corner[1]) + std::abs(p[2] - corner[2]) > 24;
                changedFar += difference > 2;
            }
        }
    EXPECT_GT(changedNear, 200) << "the crease should show near edge " << a + 1 << "-" << b + 1;
    EXPECT_EQ(changedFar, 0) << "far from the edge";
    EXPECT_GT(farSurface, kWidth * kHeight / 10) << "the far region should hold much of the surface";
    int levelChanged = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) levelChanged += channelDifference(creased, changed, x, y) > 16;
    EXPECT_GT(levelChanged, 500) << "level 2 under catmull-clark should look different";

    const io::ObjMesh back = io::readObj(saved);
    EXPECT_EQ(view::creaseSharpness(back, a, b), 10.0f);
    EXPECT_EQ(back.positions, mesh.positions);
    EXPECT_EQ(back.faceVerts, mesh.faceVerts);
    EXPECT_NE(readText(saved).find("t crease 2/1/0 " + std::to_string(a) + " " + std::to_string(b) + " 10\n"),
              std::string::npos);
}

TEST(Viewer, AClickPicksTheEdgeUnderTheCursorAndShiftAddsAVertex) {
    SKIP_WITHOUT_XVFB();
    const io::ObjMesh mesh = io::readObj(kTorus);
    render::Camera camera;
    camera.frame(render::boundingSphere(mesh.positions.data(), mesh.numVertices()), float(kWidth) / float(kHeight));
    const glm::mat4 viewProjection = camera.projection(float(kWidth) / float(kHeight), 1.0f) * camera.view();
    const std::vector<view::ScreenPoint> points =
        view::projectPoints(viewProjection, mesh.positions.data(), mesh.numVertices(), {0, 0}, {kWidth, kHeight});
    // The longest edge on the screen, clicked a third of the way along (away from both ends'
    // vertex radius), and then the first vertex in the picture, with shift.
    const std::vector<std::pair<int, int>> edges = cageEdges(mesh);
    std::pair<int, int> edge = edges[0];
    for (const auto& e : edges)
        if (glm::length(points[e.first].pixel - points[e.second].pixel) >
            glm::length(points[edge.first].pixel - points[edge.second].pixel))
            edge = e;
    const glm::vec2 click = points[edge.first].pixel + (points[edge.second].pixel - points[edge.first].pixel) / 3.0f;
    int vertex = 0;
    while (points[vertex].pixel.x < 0 || points[vertex].pixel.x >= kWidth || points[vertex].pixel.y < 0 ||
           points[vertex].pixel.y >= kHeight)
        ++vertex;
    const std::string saved = work("clicked.obj");
    const Outcome r = view(kTorus, "click " + std::to_string(click.x) + " " + std::to_string(click.y) +
                                       "\nshift-click " + std::to_string(points[vertex].pixel.x) + " " +
                                       std::to_string(points[vertex].pixel.y) + "\nsharpness 4\nsave " + saved +
                                       "\nquit\n");
    SKIP_WITHOUT_DEVICE(r);
    ASSERT_EQ(r.status, 0) << r.errors;
    const io::ObjMesh back = io::readObj(saved);
    EXPECT_EQ(back.creaseSharpness, std::vector<float>{4.0f});
    EXPECT_EQ(view::creaseSharpness(back, edge.first, edge.second), 4.0f);
    EXPECT_EQ(back.corners, std::vector<int>{vertex});
    EXPECT_EQ(back.cornerSharpness, std::vector<float>{4.0f});
}

int changedPixels(const render::Image& a, const render::Image& b) {
    int count = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) count += channelDifference(a, b, x, y) > 16;
    return count;
}

TEST(Viewer, ClosingWithUnsavedEditsPromptsAndWithoutThemQuits) {
    SKIP_WITHOUT_XVFB();
    const std::string open = work("open.png"), prompt = work("prompt.png"), never = work("never.obj");
    // Edited: `close` opens the modal prompt and the viewer stays. Dear ImGui fades the prompt's
    // veil over the whole window in 1/6 s; a script's frames are 1/60 s apart, so after 12
    // frames it is fully there on any machine.
    Outcome r = view(kTorus, "select-edge 1 2\nsharpness 3\nscreenshot-window " + open +
                                 "\nclose\nframes 12\nscreenshot-window " + prompt + "\nquit\n");
    SKIP_WITHOUT_DEVICE(r);
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_GT(changedPixels(render::readImage(open), render::readImage(prompt)), kWidth * kHeight / 2);
    // Unedited: `close` quits at once; the save after it never runs.
    r = view(kTorus, "close\nsave " + never + "\n");
    EXPECT_EQ(r.status, 0) << r.errors;
    EXPECT_FALSE(std::ifstream(never).good());
}

TEST(Viewer, TheThreeEvaluatorsDrawTheSamePicture) {
    SKIP_WITHOUT_XVFB();
    const std::string vulkan = work("vulkan.png"), cpu = work("cpu.png"), tbb = work("tbb.png");
    // A creased cage in reflection lines: any difference in positions or normals shows.
    const Outcome r = view(kTorus, "select-edge 1 2\nsharpness 2\nshading reflection-lines\n"
                                   "evaluator vulkan\nscreenshot " + vulkan +
                                   "\nevaluator cpu\nscreenshot " + cpu + "\nevaluator tbb\nscreenshot " + tbb + "\nquit\n");
    SKIP_WITHOUT_DEVICE(r);
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_EQ(r.errors.find("alidation"), std::string::npos) << r.errors;
    const render::Image v = render::readImage(vulkan), c = render::readImage(cpu), t = render::readImage(tbb);
    // oneTBB's results are the CPU's bitwise; Vulkan's within 1e-5, which may move a stripe's or
    // a silhouette's edge by a pixel here and there.
    EXPECT_EQ(changedPixels(c, t), 0);
    EXPECT_LT(changedPixels(v, c), kWidth * kHeight / 1000);
}

// The patch route draws what the factorized table draws: on the device, whose buffers hold the
// patch table's order (the draw and the curvature remapped), and on the CPU (read back in level
// order), in reflection lines and in mean curvature.
TEST(Viewer, ThePatchRouteDrawsTheSamePicture) {
    SKIP_WITHOUT_XVFB();
    std::vector<std::string> shots;
    for (const char* name : {"lines_table", "lines_patches", "lines_patches_cpu", "curvature_patches_cpu",
                             "curvature_table_cpu", "curvature_patches"})
        shots.push_back(work(std::string(name) + ".png"));
    const Outcome r = view(kTorus, "select-edge 1 2\nsharpness 2\nshading reflection-lines\nscreenshot " + shots[0] +
                                       "\ntables patches\nscreenshot " + shots[1] + "\nevaluator cpu\nscreenshot " +
                                       shots[2] + "\nshading mean-curvature\nscreenshot " + shots[3] +
                                       "\ntables factorized\nscreenshot " + shots[4] +
                                       "\ntables patches\nevaluator vulkan\nscreenshot " + shots[5] + "\nquit\n");
    SKIP_WITHOUT_DEVICE(r);
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_EQ(r.errors.find("alidation"), std::string::npos) << r.errors;
    std::vector<render::Image> images;
    for (const std::string& shot : shots) images.push_back(render::readImage(shot));
    // Within float rounding of each other: a stripe's or a silhouette's edge moved by a pixel here
    // and there, where a remapping mistake would scramble the whole surface.
    for (auto [a, b] : {std::pair{0, 1}, std::pair{1, 2}, std::pair{3, 4}, std::pair{4, 5}})
        EXPECT_LT(changedPixels(images[std::size_t(a)], images[std::size_t(b)]), kWidth * kHeight / 1000)
            << shots[std::size_t(a)] << " against " << shots[std::size_t(b)];
    EXPECT_GT(changedPixels(images[2], images[3]), kWidth * kHeight / 20);  // the shading did change
}

// A sharpness change is an edit of the surface in place (Refiner::applyEdits, the tables
// updated): under every evaluator and table route it draws what the viewer draws of the saved
// cage loaded afresh, and it did change the picture.
TEST(Viewer, AnEditedSurfaceDrawsWhatARebuiltOneDraws) {
    SKIP_WITHOUT_XVFB();
    const std::vector<std::pair<std::string, std::string>> ways = {
        {"vulkan", "factorized"}, {"cpu", "factorized"}, {"tbb", "levels"}, {"vulkan", "levels"}, {"cpu", "patches"},
        {"vulkan", "patches"}};
    const std::string saved = work("edited.obj");
    std::string edit = "shading reflection-lines\n", again = "shading reflection-lines\n";
    auto shot = [&](const std::string& kind, std::size_t k) { return work(kind + std::to_string(k) + ".png"); };
    for (std::size_t k = 0; k < ways.size(); ++k) {
        const std::string choose = "evaluator " + ways[k].first + "\ntables " + ways[k].second + "\n";
        // The choice rebuilds from the cage as edited so far; the edits after it are in place.
        edit += choose + "select-edge 1 2\nadd-edge 2 3\nsharpness 0\nselect-vertex 5\nsharpness 0\nclear-selection\nscreenshot " +
                shot("before", k) + "\nselect-edge 1 2\nadd-edge 2 3\nsharpness 3\nselect-vertex 5\nsharpness 2.5\nclear-selection\nscreenshot " +
                shot("edited", k) + "\n";
        again += choose + "select-vertex 5\nclear-selection\nscreenshot " + shot("rebuilt", k) + "\n";  // the same marks
    }
    Outcome r = view(kTorus, edit + "save " + saved + "\nquit\n");
    SKIP_WITHOUT_DEVICE(r);
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_EQ(r.errors.find("alidation"), std::string::npos) << r.errors;
    r = view(saved, again + "quit\n");
    ASSERT_EQ(r.status, 0) << r.errors;
    for (std::size_t k = 0; k < ways.size(); ++k) {
        const render::Image before = render::readImage(shot("before", k)), edited = render::readImage(shot("edited", k)),
                            rebuilt = render::readImage(shot("rebuilt", k));
        const std::string way = ways[k].first + ", " + ways[k].second;
        EXPECT_GT(changedPixels(before, edited), 200) << way << ": the edit should show";
        // Bit for bit but where the factorized table's update rounds a weight otherwise (1e-6).
        EXPECT_LT(changedPixels(edited, rebuilt), kWidth * kHeight / 1000) << way;
    }
}

// Adaptive tessellation: at a few pixels per segment it draws what the uniform level draws
// (reflection lines: any difference in positions or normals shows), on the device and on the CPU,
// at hundreds (every edge one segment: the base faces' flat triangles) something else; off
// again, the level comes back.
TEST(Viewer, AdaptiveTessellationFollowsItsTarget) {
    SKIP_WITHOUT_XVFB();
    std::vector<std::string> shots;
    for (const char* name : {"level", "fine", "coarse", "level_again", "fine_cpu"})
        shots.push_back(work(std::string(name) + ".png"));
    const Outcome r = view(kTorus, "shading reflection-lines\nscreenshot " + shots[0] +
                                       "\nadaptive on\nsegment-pixels 3\nscreenshot " + shots[1] +
                                       "\nsegment-pixels 500\nscreenshot " + shots[2] +
                                       "\nadaptive off\nscreenshot " + shots[3] +
                                       "\nevaluator cpu\nadaptive on\nsegment-pixels 3\nscreenshot " + shots[4] +
                                       "\nquit\n");
    SKIP_WITHOUT_DEVICE(r);
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_EQ(r.errors.find("alidation"), std::string::npos) << r.errors;
    std::vector<render::Image> images;
    for (const std::string& shot : shots) images.push_back(render::readImage(shot));
    const int fine = changedPixels(images[0], images[1]), coarse = changedPixels(images[0], images[2]);
    EXPECT_LT(fine, kWidth * kHeight / 100);
    EXPECT_GT(coarse, 5 * fine + kWidth * kHeight / 100);
    EXPECT_EQ(changedPixels(images[0], images[3]), 0);
    EXPECT_LT(changedPixels(images[1], images[4]), kWidth * kHeight / 1000);  // the device's, the CPU's
}

TEST(Viewer, ALoadedTextureReplacesTheChecker) {
    SKIP_WITHOUT_XVFB();
    // A cube with UVs, textured with the checker, then with the checker's own screenshot.
    const std::string cube = std::string(QUADTRI_TEST_MESHES) + "/osd/catmark_cube.obj";
    const std::string checker = work("checker.png"), loaded = work("loaded.png");
    const Outcome r = view(cube, "shading textured\nscreenshot " + checker + "\ntexture " + checker + "\nscreenshot " +
                                     loaded + "\nquit\n");
    SKIP_WITHOUT_DEVICE(r);
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_EQ(r.errors.find("alidation"), std::string::npos) << r.errors;
    EXPECT_GT(changedPixels(render::readImage(checker), render::readImage(loaded)), kWidth * kHeight / 20);
}

TEST(Viewer, AFileThatFailsToLoadKeepsTheMeshShown) {
    SKIP_WITHOUT_XVFB();
    const std::string bad = work("bad.obj"), saved = work("kept.obj");
    writeText(bad, "v 0 0 0\nv 1 0 zero\n");
    const Outcome r = view(kTorus, "select-edge 1 2\nsharpness 3\nload " + bad + "\nsave " + saved + "\nquit\n");
    SKIP_WITHOUT_DEVICE(r);
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_NE(r.errors.find("script.txt:3: " + bad + ":2: "), std::string::npos) << r.errors;
    const io::ObjMesh back = io::readObj(saved);
    EXPECT_EQ(back.numVertices(), io::readObj(kTorus).numVertices());
    EXPECT_EQ(view::creaseSharpness(back, 0, 1), 3.0f);  // the edit survives the failed load
}

TEST(Viewer, ScriptErrorsNameTheLineAndExitWithStatus2) {
    SKIP_WITHOUT_XVFB();
    Outcome r = view(kTorus, "level 2\nselect-edge 1 1000\n");
    SKIP_WITHOUT_DEVICE(r);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find("script.txt:2: vertex 1000 does not exist (the mesh has 96)"), std::string::npos) << r.errors;
    r = view(kTorus, "scheme no-such\n");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find("script.txt:1: unknown scheme 'no-such'"), std::string::npos) << r.errors;
    r = view(kTorus, "frames 2\ntexture /nonexistent/picture.png\n");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find("script.txt:2: /nonexistent/picture.png: "), std::string::npos) << r.errors;
    r = view(kTorus, "frames 2\nzoom 3\n");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find("script.txt:2: unknown command 'zoom'"), std::string::npos) << r.errors;
}

TEST(Viewer, ABadFileIsRefusedWithItsLine) {
    SKIP_WITHOUT_XVFB();
    const std::string bad = work("broken.obj");
    writeText(bad, "v 0 0 0\nf 1 2\n");
    const Outcome r = view(bad, "quit\n");
    SKIP_WITHOUT_DEVICE(r);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find(bad + ":2: "), std::string::npos) << r.errors;
}

TEST(Viewer, WithoutAVulkanDeviceOneMessageAndStatus2) {
    SKIP_WITHOUT_XVFB();
    const Outcome r = run("QUADTRI_VK_DEVICE=no-such-device DISPLAY=" + Xvfb::display() + " '" + QUADTRI_CLI +
                          "' view '" + kTorus + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find("quadtri: view needs a Vulkan device that can draw to the window: "), std::string::npos)
        << r.errors;
    EXPECT_EQ(std::count(r.errors.begin(), r.errors.end(), '\n'), 1) << r.errors;
}

TEST(Viewer, WithoutADisplayOneMessageAndStatus2) {
    const Outcome r = run(std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") + QUADTRI_CLI + "' view '" + kTorus + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find("no display"), std::string::npos) << r.errors;
    EXPECT_EQ(std::count(r.errors.begin(), r.errors.end(), '\n'), 1) << r.errors;
}

}  // namespace
}  // namespace quadtri::test
