// quadtri: refine OBJ meshes with the quad/triangle analyzer, report on them, time them.
#include <CLI/CLI.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <map>
#include <new>
#include <optional>
#include <sstream>

#include <quadtri/far/options.h>
#include <quadtri/far/tessellation.h>
#include <quadtri/version.h>
#include "tools/byte_size.h"
#include "tools/commands.h"
#include "tools/obj_io.h"
#include "tools/view/view_command.h"

namespace {

using namespace quadtri;

// A validator accepting the names in `names` (reported as "unknown <what> 'x' (expected a, b)").
template <typename T>
CLI::Validator oneOf(const std::map<std::string, T>& names, const std::string& what) {
    std::string list;
    for (const auto& entry : names) list += (list.empty() ? "" : ", ") + entry.first;
    return CLI::Validator(
        [names, what, list](std::string& s) {
            return names.count(s) ? std::string() : "unknown " + what + " '" + s + "' (expected " + list + ")";
        },
        "{" + list + "}");
}

// "Subdivision scheme (default ...)" and one line per scheme.
std::string schemeHelp() {
    std::string help = std::string("Subdivision scheme (default ") + toString(Options().scheme) + "):";
    for (Scheme scheme : allSchemes()) help += std::string("\n  ") + toString(scheme) + ": " + describe(scheme);
    return help;
}

// "UV interpolation (default ...)" and one line per option with Blender's "UV Smooth" label
// (docs/face_varying.md has the table).
std::string uvInterpolationHelp() {
    static const std::map<FVarLinearInterpolation, const char*> blender{
        {FVarLinearInterpolation::None, "All"},
        {FVarLinearInterpolation::CornersOnly, "Keep Corners"},
        {FVarLinearInterpolation::CornersPlus1, "Keep Corners, Junctions"},
        {FVarLinearInterpolation::CornersPlus2, "Keep Corners, Junctions, Concave"},
        {FVarLinearInterpolation::Boundaries, "Keep Boundaries"},
        {FVarLinearInterpolation::All, "None"}};
    std::string help = std::string("How the file's UVs (vt) are kept linear at seams and corners, as OpenSubdiv's "
                                   "FVarLinearInterpolation (default ") +
                       toString(Options().fvarLinearInterpolation) + "); Blender's UV Smooth in brackets:";
    for (FVarLinearInterpolation option : allFVarLinearInterpolations())
        help += std::string("\n  ") + toString(option) + " (" + blender.at(option) + ")";
    return help;
}

void addMeshFlags(CLI::App& cmd, cli::MeshArgs& args) {
    // The registered schemes (far/schemes/schemes.cpp), by name.
    static const std::map<std::string, Scheme> schemes = [] {
        std::map<std::string, Scheme> byName;
        for (Scheme scheme : allSchemes()) byName.emplace(toString(scheme), scheme);
        return byName;
    }();
    static const std::map<std::string, BoundaryInterpolation> boundaries{
        {"edge-only", BoundaryInterpolation::EdgeOnly},
        {"edge-and-corner", BoundaryInterpolation::EdgeAndCorner},
        {"none", BoundaryInterpolation::None}};
    static const std::map<std::string, CreaseMethod> creaseMethods{{"uniform", CreaseMethod::Uniform},
                                                                   {"chaikin", CreaseMethod::Chaikin}};
    cmd.add_option("input", args.input, "Input OBJ file")->required();
    cmd.add_option_function<std::string>(
           "--scheme", [&args](const std::string& s) { args.scheme = schemes.at(s); },
           schemeHelp())
        ->check(oneOf(schemes, "scheme"));
    cmd.add_option_function<std::string>(
           "--boundary", [&args](const std::string& s) { args.boundary = boundaries.at(s); },
           "Boundary interpolation; overrides the file's interpolateboundary tag (default edge-only)")
        ->check(oneOf(boundaries, "boundary"));
    cmd.add_option_function<std::string>(
           "--crease-method", [&args](const std::string& s) { args.creaseMethod = creaseMethods.at(s); },
           "Sharpness decay per level; overrides the file's creasemethod tag (default uniform)")
        ->check(oneOf(creaseMethods, "crease method"));
    static const std::map<std::string, FVarLinearInterpolation> uvInterpolations = [] {
        std::map<std::string, FVarLinearInterpolation> byName;
        for (FVarLinearInterpolation option : allFVarLinearInterpolations()) byName.emplace(toString(option), option);
        return byName;
    }();
    cmd.add_option_function<std::string>(
           "--uv-interpolation", [&args](const std::string& s) { args.uvInterpolation = uvInterpolations.at(s); },
           uvInterpolationHelp())
        ->type_name("NAME")
        ->check(oneOf(uvInterpolations, "UV interpolation"));
    cmd.add_flag("--smooth-triangles", args.smoothTriangles,
                 "OpenSubdiv's smooth-triangle rule (TRI_SUB_SMOOTH) for triangles; catmull-clark only "
                 "(default: the file's smoothtriangles tag)");
    cmd.add_option_function<std::string>(
           "--memory-budget", [&args](const std::string& s) { args.memoryBudget = cli::parseByteSize(s); },
           "Refuse a level whose estimated tables and output exceed SIZE (e.g. 512MiB, 8GiB; default 4GiB)")
        ->type_name("SIZE")
        ->check(CLI::Validator(
            [](std::string& s) {
                return cli::parseByteSize(s) ? std::string() : "'" + s + "' is not a size: expected " + cli::kByteSizeForms;
            },
            "SIZE"));
}

CLI::Option* addLevel(CLI::App& cmd, const char* name, int& level, const char* help, int minLevel = 0) {
    return cmd.add_option(name, level, help)->check(CLI::Range(minLevel, cli::kMaxLevel))->capture_default_str();
}

// "x,y,z" (or "r,g,b") as three floats, each within [lo, hi] and, with `nonZero`, not all 0;
// nullopt otherwise.
std::optional<std::array<float, 3>> parseTriple(const std::string& s, float lo, float hi, bool nonZero) {
    std::array<float, 3> v{};
    char tail = 0;
    if (std::sscanf(s.c_str(), "%f,%f,%f%c", &v[0], &v[1], &v[2], &tail) != 3) return std::nullopt;
    for (float x : v)
        if (!std::isfinite(x) || x < lo || x > hi) return std::nullopt;
    if (nonZero && v[0] == 0 && v[1] == 0 && v[2] == 0) return std::nullopt;
    return v;
}

CLI::Validator tripleCheck(const char* what, float lo, float hi, bool nonZero) {
    return CLI::Validator(
        [what, lo, hi, nonZero](std::string& s) {
            if (parseTriple(s, lo, hi, nonZero)) return std::string();
            char range[96];
            std::snprintf(range, sizeof range, "%g, %g", double(lo), double(hi));
            return "'" + s + "' is not " + what + ": expected three numbers a,b,c in [" + range + "]" +
                   (nonZero ? ", not all 0" : "");
        },
        "X,Y,Z");
}

void addRenderFlags(CLI::App& cmd, cli::RenderArgs& args, const std::map<std::string, cli::EvaluatorKind>& evaluators) {
    addMeshFlags(cmd, args.mesh);
    addLevel(cmd, "--level,-l", args.level, "Refinement level drawn");
    cmd.add_option("-o,--output", args.output, "Output PNG file")->required();
    std::map<std::string, int> shadings;
    for (const std::string& name : cli::renderShadings()) shadings.emplace(name, 0);
    cmd.add_option("--shading", args.shading,
                   "smooth (limit normals), flat (face normals), reflection-lines (zebra stripes), mean-curvature "
                   "(blue concave, red convex), face-type (orange: from a control triangle, blue: from a quad), "
                   "textured (the file's UVs: --texture, else a checker)")
        ->check(oneOf(shadings, "shading"))
        ->capture_default_str();
    cmd.add_flag("--cage", args.cage, "Draw the control edges, coloured by sharpness (docs/rendering.md)");
    cmd.add_flag("--points", args.points, "Draw the control vertices, coloured by corner sharpness");
    cmd.add_flag("--no-surface", args.hideSurface, "Do not draw the refined surface");
    cmd.add_flag("--limit", args.limit, "Move the vertices onto the limit surface");
    cmd.add_option("--yaw", args.yaw, "Camera angle about the vertical axis, degrees")
        ->check(CLI::Range(-360.0f, 360.0f))
        ->capture_default_str();
    cmd.add_option("--pitch", args.pitch, "Camera angle above the horizon, degrees")
        ->check(CLI::Range(-89.0f, 89.0f))
        ->capture_default_str();
    cmd.add_option_function<std::string>(
           "--size",
           [&args](const std::string& s) { std::sscanf(s.c_str(), "%dx%d", &args.width, &args.height); },
           "Image size WxH of each panel (default 800x600)")
        ->type_name("WxH")
        ->check(CLI::Validator(
            [](std::string& s) {
                int w = 0, h = 0;
                char tail = 0;
                const bool ok = std::sscanf(s.c_str(), "%dx%d%c", &w, &h, &tail) == 2 && w >= 16 && h >= 16 &&
                                w <= 8192 && h <= 8192;
                return ok ? std::string() : "'" + s + "' is not a size: expected WxH, each 16 to 8192, e.g. 800x600";
            },
            "WxH"));
    cmd.add_option_function<std::string>(
           "--light-dir", [&args](const std::string& s) { args.lightDirection = *parseTriple(s, -1e6f, 1e6f, true); },
           "Direction towards the light in view space: x right, y up, z towards the viewer (default -0.3,0.5,0.8)")
        ->check(tripleCheck("a direction", -1e6f, 1e6f, true));
    cmd.add_option_function<std::string>(
           "--light-color", [&args](const std::string& s) { args.lightColor = *parseTriple(s, 0.0f, 1.0f, false); },
           "Light colour r,g,b in [0, 1] (default 1,1,1)")
        ->check(tripleCheck("a colour", 0.0f, 1.0f, false));
    cmd.add_option("--texture", args.texture, "PNG or JPEG image for --shading textured (default: a checker)");
    cmd.add_option_function<std::string>(
           "--evaluator", [&args, evaluators](const std::string& s) { args.evaluator = evaluators.at(s); },
           "Stencil evaluator: cpu, tbb, or vulkan (on the renderer's device, its buffers drawn directly)")
        ->check(oneOf(evaluators, "evaluator"));
    cmd.add_option("--crease-sharpness", args.creaseSharpness,
                   "Replace the sharpness of every 't crease' of the file (10 and above: infinite)")
        ->check(CLI::NonNegativeNumber);
    cmd.add_option_function<std::string>(
           "--compare",
           [&args](const std::string& s) {
               std::stringstream list(s);
               for (std::string name; std::getline(list, name, ',');) args.compare.push_back(*schemeNamed(name));
           },
           "Schemes s1,s2,... side by side, one labelled panel each")
        ->type_name("S1,S2,...")
        ->check(CLI::Validator(
            [](std::string& s) {
                std::stringstream list(s);
                int count = 0;
                for (std::string name; std::getline(list, name, ',');) {
                    if (!schemeNamed(name)) return "unknown scheme '" + name + "' in --compare";
                    ++count;
                }
                return count ? std::string() : std::string("--compare needs at least one scheme");
            },
            "S1,S2,..."));
    cmd.add_option("--stripes", args.stripes, "Reflection lines: stripes over the half circle of directions")
        ->check(CLI::Range(1.0f, 200.0f))
        ->capture_default_str();
    cmd.add_option("--supersample", args.supersample,
                   "Anti-aliasing: draw K times wider and higher and average each K x K block")
        ->check(CLI::Range(1, 4))
        ->capture_default_str();
    cmd.add_option("--label", args.label,
                   "Text written in the image's top-left corner (with --compare, after each scheme's name)");
    cmd.add_option("--curvature-range", args.curvatureRange,
                   "Mean curvature shown at the colour map's ends (default: the 95th percentile of |H|)")
        ->check(CLI::PositiveNumber);
}

// The table routes as --tables names them.
const std::map<std::string, realtime::TableRoute>& tableRoutes() {
    static const std::map<std::string, realtime::TableRoute> routes = [] {
        std::map<std::string, realtime::TableRoute> named;
        for (realtime::TableRoute route : realtime::allTableRoutes()) named[realtime::tablesWord(route)] = route;
        return named;
    }();
    return routes;
}

void addViewFlags(CLI::App& cmd, view::ViewerArgs& args, const std::map<std::string, cli::EvaluatorKind>& evaluators) {
    addMeshFlags(cmd, args.mesh);
    addLevel(cmd, "--level,-l", args.level, "Refinement level shown first (0-6)")->check(CLI::Range(0, 6));
    cmd.add_option_function<std::string>(
           "--evaluator", [&args, evaluators](const std::string& s) { args.evaluator = evaluators.at(s); },
           "Evaluator at start: cpu, tbb, or vulkan (default; on the viewer's device, its buffers drawn directly)")
        ->check(oneOf(evaluators, "evaluator"));
    cmd.add_option_function<std::string>(
           "--tables", [&args](const std::string& s) { args.tables = tableRoutes().at(s); },
           "The frame's tables at start: factorized (default), levels or patches, as `quadtri demo --tables`")
        ->check(oneOf(tableRoutes(), "table route"));
    cmd.add_option("--texture", args.texture, "PNG or JPEG image for textured shading (default: a checker)");
    cmd.add_option("--script", args.script,
                   "Run the commands of FILE (docs/viewer.md), one per rendered frame, then quit");
    cmd.add_option_function<std::string>(
           "--size", [&args](const std::string& s) { std::sscanf(s.c_str(), "%dx%d", &args.width, &args.height); },
           "Window size WxH (default 1280x800)")
        ->type_name("WxH")
        ->check(CLI::Validator(
            [](std::string& s) {
                int w = 0, h = 0;
                char tail = 0;
                const bool ok = std::sscanf(s.c_str(), "%dx%d%c", &w, &h, &tail) == 2 && w >= 64 && h >= 64 &&
                                w <= 8192 && h <= 8192;
                return ok ? std::string() : "'" + s + "' is not a size: expected WxH, each 64 to 8192, e.g. 1280x800";
            },
            "WxH"));
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"quadtri: quad/triangle subdivision of OBJ meshes", "quadtri"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "quadtri " QUADTRI_VERSION_STRING);

    cli::RefineArgs refine;
    CLI::App* refineCmd = app.add_subcommand("refine", "Refine a mesh uniformly and write the last level as OBJ or glTF");
    addMeshFlags(*refineCmd, refine.mesh);
    addLevel(*refineCmd, "--level,-l", refine.level, "Refinement level")->required();
    refineCmd->add_option("-o,--output", refine.output,
                          "Output file: OBJ (.obj), or glTF 2.0 triangles (.gltf, .glb: binary) with normals")
        ->required();
    static const std::map<std::string, cli::EvaluatorKind> evaluators{
        {"cpu", cli::EvaluatorKind::Cpu}, {"tbb", cli::EvaluatorKind::Tbb}, {"vulkan", cli::EvaluatorKind::Vulkan}};
    refineCmd->add_option_function<std::string>(
            "--evaluator", [&refine](const std::string& s) { refine.evaluator = evaluators.at(s); },
            "Stencil evaluator: cpu, tbb (threads) or vulkan (falls back to cpu without a device; default cpu)")
        ->check(oneOf(evaluators, "evaluator"));
    refineCmd->add_flag("--limit", refine.limit,
                        "Move the vertices onto the limit surface and write its normals (vn) with them");
    static const std::map<std::string, cli::NormalKind> normalKinds{
        {"none", cli::NormalKind::None}, {"mesh", cli::NormalKind::Mesh}, {"limit", cli::NormalKind::Limit}};
    refineCmd->add_option_function<std::string>(
            "--normals", [&refine](const std::string& s) { refine.normals = normalKinds.at(s); },
            "Normals written (OBJ vn, glTF NORMAL): none, mesh (area-weighted face normals of the written mesh) or "
            "limit (the limit surface's, at the written vertices); default limit with --limit, else none for OBJ "
            "and mesh for glTF")
        ->check(oneOf(normalKinds, "normal kind"));

    cli::EvaluateArgs evaluate;
    CLI::App* evaluateCmd = app.add_subcommand(
        "evaluate", "Evaluate the limit surface at points of faces (position and normal; docs/surface.md)");
    addMeshFlags(*evaluateCmd, evaluate.mesh);
    evaluateCmd->add_option("--points", evaluate.points,
                            "File of points, one 'face u v' per line (faces from 1 in the order of the f lines; "
                            "blank lines and # comments skipped)")
        ->required();
    evaluateCmd->add_option("-o,--output", evaluate.output,
                            "Output file, one 'x y z nx ny nz' line per point (default: standard output)");
    evaluateCmd->add_flag("--derivatives", evaluate.derivatives, "Add dPdu and dPdv to each line");
    evaluateCmd->add_flag("--uv", evaluate.uv,
                          "Add the limit UV (from the file's vt, under --uv-interpolation) to each line, last");

    cli::TessellateArgs tessellate;
    CLI::App* tessellateCmd = app.add_subcommand(
        "tessellate", "Cut every face into triangles on the limit surface, watertight, with limit normals "
                      "and, where the file has vt, limit UVs (docs/surface.md)");
    addMeshFlags(*tessellateCmd, tessellate.mesh);
    tessellateCmd->add_option("--rate,-r", tessellate.rate, "Segments per edge (edges of n-gons, and of triangles under "
                                                            "catmull-clark, take the next even number)")
        ->check(CLI::Range(1, Tessellation::kMaxRate));
    tessellateCmd->add_option("-o,--output", tessellate.output, "Output file: .obj, or .gltf / .glb")->required();

    cli::InfoArgs info;
    CLI::App* infoCmd = app.add_subcommand("info", "Print topology statistics and table sizes per level");
    addMeshFlags(*infoCmd, info.mesh);
    addLevel(*infoCmd, "--level,-l", info.level, "Deepest level reported");

    cli::DemoArgs demo;
    CLI::App* demoCmd = app.add_subcommand(
        "demo", "Time the real-time loop: the cage skinned every frame, then the level's limit positions and normals, "
                "on each evaluator");
    addMeshFlags(*demoCmd, demo.mesh);
    addLevel(*demoCmd, "--level,-l", demo.level, "Refinement level evaluated every frame", 1);
    demoCmd->add_option("--frames", demo.frames, "Frames timed per evaluator, at most")
        ->check(CLI::Range(1, 1000000))
        ->capture_default_str();
    demoCmd->add_option("--seconds", demo.seconds, "Seconds per evaluator, at most (at least 3 frames are timed)")
        ->check(CLI::Range(0.0, 3600.0))
        ->capture_default_str();
    demoCmd->add_option_function<std::vector<std::string>>(
            "--evaluators",
            [&demo](const std::vector<std::string>& names) {
                demo.evaluators.clear();
                for (const std::string& name : names) demo.evaluators.push_back(evaluators.at(name));
            },
            "Evaluators timed, comma-separated, in order (default cpu,tbb,vulkan; vulkan is skipped, saying why, "
            "without a device)")
        ->delimiter(',')
        ->check(oneOf(evaluators, "evaluator"));
    demoCmd->add_option_function<std::string>(
            "--tables", [&demo](const std::string& s) { demo.route = tableRoutes().at(s); },
            "factorized: one limit pass from the cage (default); levels: the per-level tables, then the limit "
            "table over the last level; patches: the per-level tables to level - 3, then the regular patches "
            "(docs/patches.md)")
        ->check(oneOf(tableRoutes(), "table route"));

    cli::RenderArgs render;
    CLI::App* renderCmd = app.add_subcommand("render", "Draw the refined surface offscreen with Vulkan and write a PNG");
    addRenderFlags(*renderCmd, render, evaluators);

    view::ViewerArgs viewer;
    CLI::App* viewCmd = app.add_subcommand("view", "Open the interactive viewer: cage and refined surface, sharpness "
                                                   "editing, live schemes and evaluators (docs/viewer.md)");
    addViewFlags(*viewCmd, viewer, evaluators);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        std::cerr << "quadtri: " << e.what() << "\nRun 'quadtri --help' for usage.\n";
        return 2;
    }

    const std::string& input = *refineCmd    ? refine.mesh.input
                               : *evaluateCmd ? evaluate.mesh.input
                               : *tessellateCmd ? tessellate.mesh.input
                               : *infoCmd   ? info.mesh.input
                               : *renderCmd ? render.mesh.input
                               : *viewCmd   ? viewer.mesh.input
                                            : demo.mesh.input;
    try {
        if (*refineCmd) return cli::runRefine(refine);
        if (*evaluateCmd) return cli::runEvaluate(evaluate);
        if (*tessellateCmd) return cli::runTessellate(tessellate);
        if (*infoCmd) return cli::runInfo(info);
        if (*renderCmd) return cli::runRender(render);
        if (*viewCmd) return view::runView(viewer);
        return cli::runDemo(demo);
    } catch (const io::ObjError& e) {
        std::cerr << "quadtri: " << e.what() << "\n";  // already "file:line: problem"
    } catch (const MemoryBudgetError& e) {
        std::cerr << "quadtri: " << cli::budgetRefusal(input, e) << "\n";
    } catch (const TopologyError& e) {
        std::cerr << "quadtri: " << input << ": " << e.what() << "\n";
    } catch (const std::bad_alloc&) {
        std::cerr << "quadtri: out of memory\n";
    } catch (const std::exception& e) {
        std::cerr << "quadtri: " << e.what() << "\n";
    }
    return 2;
}
