// quadtri: refine OBJ meshes with the quad/triangle analyzer, report on them, time them.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <map>
#include <new>

#include <quadtri/far/options.h>
#include <quadtri/version.h>
#include "tools/byte_size.h"
#include "tools/commands.h"
#include "tools/obj_io.h"

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
    // The registered schemes (far/schemes.cpp), by name.
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
    static const std::map<std::string, realtime::TableRoute> routes{
        {"factorized", realtime::TableRoute::FactorizedLimit}, {"levels", realtime::TableRoute::LevelsThenLimit}};
    demoCmd->add_option_function<std::string>(
            "--tables", [&demo](const std::string& s) { demo.route = routes.at(s); },
            "factorized: one limit pass from the cage (default); levels: the per-level tables, then the limit "
            "table over the last level")
        ->check(oneOf(routes, "table route"));

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        std::cerr << "quadtri: " << e.what() << "\nRun 'quadtri --help' for usage.\n";
        return 2;
    }

    const std::string& input = *refineCmd ? refine.mesh.input : *infoCmd ? info.mesh.input : demo.mesh.input;
    try {
        if (*refineCmd) return cli::runRefine(refine);
        if (*infoCmd) return cli::runInfo(info);
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
