// `quadtri demo`: the real-time loop of tools/realtime/ (a skinned cage, level N's limit positions
// and normals every frame) timed on each evaluator, phase by phase (docs/realtime_loop.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "tools/commands.h"
#include "tools/realtime/deforming_surface.h"
#include "tools/realtime/host_frame_evaluator.h"

namespace quadtri::cli {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kPi = 3.14159265358979323846;
// Where the evaluators are compared: a frame well into the bend.
constexpr float kCheckRadians = 1.2f;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// "6144 quads, 3840 triangles" (and "n other faces" when there are larger ones).
std::string faceKinds(const LevelFaces& faces) {
    int quads = 0, triangles = 0;
    for (int f = 0; f < faces.numFaces(); ++f) {
        const int n = faces.verticesOfFace(f).size();
        quads += n == 4;
        triangles += n == 3;
    }
    std::string text = std::to_string(quads) + " quads, " + std::to_string(triangles) + " triangles";
    const int others = faces.numFaces() - quads - triangles;
    return others ? text + ", " + std::to_string(others) + " other faces" : text;
}

// Medians over the timed frames: of each phase, and of the frames' totals.
struct Row {
    std::string name;
    int frames = 0;
    realtime::PhaseTimes phases;
    double frameMs = 0;
};

// One warm-up frame, then frames along the demo's motion until `args.frames` or `args.seconds`
// (at least 3 frames); each phase's median.
Row timeEvaluator(realtime::DeformingSurface& surface, realtime::FrameEvaluator& evaluator, const DemoArgs& args) {
    surface.frame(evaluator, 0.0f);
    std::vector<double> deform, evaluate, normals, frame;
    const Clock::time_point start = Clock::now();
    while (int(frame.size()) < args.frames && (frame.size() < 3 || msSince(start) < 1000.0 * args.seconds)) {
        // The motion's time advances by the frame just measured, as a real-time loop's would.
        const double t = 1e-3 * msSince(start);
        const realtime::PhaseTimes times = surface.frame(evaluator, realtime::bendAngle(t));
        deform.push_back(times.deformMs);
        evaluate.push_back(times.evaluateMs);
        normals.push_back(times.normalsMs);
        frame.push_back(times.frameMs());
    }
    return {evaluator.name(), int(frame.size()), {median(deform), median(evaluate), median(normals)}, median(frame)};
}

// Largest |a_i - b_i| over two equally long arrays.
float maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
    float largest = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) largest = std::max(largest, std::fabs(a[i] - b[i]));
    return largest;
}

}  // namespace

int runDemo(const DemoArgs& args) {
    io::ObjMesh mesh = loadMesh(args.mesh);
    const Options options = makeOptions(args.mesh, mesh);
    Refiner refiner = makeRefiner(mesh, options);
    std::printf("%s: %d vertices, %d faces (%s); scheme %s\n", args.mesh.input.c_str(), mesh.numVertices(),
                mesh.numFaces(), faceKinds(refiner.faces(0)).c_str(), toString(options.scheme));

    Clock::time_point start = Clock::now();
    refiner.refineUniform(args.level);
    const realtime::SurfaceTables tables = args.route ? realtime::SurfaceTables(refiner, args.level, *args.route)
                                                      : realtime::fastestSurfaceTables(refiner, args.level);
    const LevelFaces faces = refiner.faces(args.level);
    if (tables.patches)
        std::printf("level %d: %d vertices, %d faces; limit positions and normals through the %s tables (%d patches of "
                    "level %d give %d points, %d stencils the rest; %.1f MiB), analysed in %.0f ms\n",
                    args.level, faces.numVertices(), faces.numFaces() - faces.numHoles(),
                    realtime::toString(tables.route), tables.patches->numPatches(), tables.patches->patchLevel,
                    tables.patches->numPatchOutputs(), tables.patches->stencils.numStencils(),
                    double(tables.patches->bytes()) / (1 << 20), msSince(start));
    else
        std::printf("level %d: %d vertices, %d faces; limit positions and normals through the %s tables (limit table "
                    "%.1f MiB, %zu entries), analysed in %.0f ms\n",
                    args.level, faces.numVertices(), faces.numFaces() - faces.numHoles(),
                    realtime::toString(tables.route), double(tables.limit.bytes()) / (1 << 20),
                    tables.limit.numEntries(), msSince(start));

    realtime::DeformingSurface surface{realtime::TwoBoneSkin(mesh.positions)};
    const realtime::TwoBoneSkin& skin = surface.skin();
    const char* axes = "xyz";
    std::printf("skin: two bones along %c joined at (%.3g, %.3g, %.3g), blended over 20%% of the length; bend about "
                "%c from 0 to %.0f degrees and back every 2 s\n",
                axes[skin.longAxis()], double(skin.joint()[0]), double(skin.joint()[1]), double(skin.joint()[2]),
                axes[skin.bendAxis()], double(realtime::bendAngle(1.0)) * 180.0 / kPi);

    std::vector<std::unique_ptr<realtime::FrameEvaluator>> evaluators;
    for (EvaluatorKind kind : args.evaluators) {
        if (kind == EvaluatorKind::Vulkan) {
            std::string device;
            if (auto vulkan = makeVulkanFrameEvaluator(tables, device)) {
                std::printf("vulkan: device %s\n", device.c_str());
                evaluators.push_back(std::move(vulkan));
            }
        } else {
            evaluators.push_back(std::make_unique<realtime::HostFrameEvaluator>(tables, kind == EvaluatorKind::Tbb));
        }
    }
    // The same frame through every evaluator, checked against the first before any timing.
    std::vector<float> firstPositions, firstNormals, positions, normals;
    for (std::size_t e = 0; e < evaluators.size(); ++e) {
        surface.frame(*evaluators[e], kCheckRadians);
        evaluators[e]->readBack(positions, normals);
        if (e == 0) {
            checkFinite(positions, mesh, args.level, options.scheme);
            firstPositions.swap(positions);
            firstNormals.swap(normals);
            continue;
        }
        std::printf("%s against %s, same frame: positions within %.2g, normals within %.2g\n",
                    evaluators[e]->name().c_str(), evaluators[0]->name().c_str(),
                    double(maxDifference(positions, firstPositions)), double(maxDifference(normals, firstNormals)));
    }

    std::printf("\n| evaluator | frames | deform ms | evaluate ms | normals ms | frame ms | fps |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
    for (const auto& evaluator : evaluators) {
        const Row row = timeEvaluator(surface, *evaluator, args);
        char normalsMs[32] = "(in evaluate)";
        if (tables.route != realtime::TableRoute::FactorizedLimit)
            std::snprintf(normalsMs, sizeof normalsMs, "%.3f", row.phases.normalsMs);
        std::printf("| %s | %d | %.3f | %.3f | %s | %.3f | %.1f |\n", row.name.c_str(), row.frames, row.phases.deformMs,
                    row.phases.evaluateMs, normalsMs, row.frameMs, 1000.0 / row.frameMs);
        std::fflush(stdout);
    }
    return 0;
}

}  // namespace quadtri::cli
