// The subcommands of the `quadtri` command-line tool. Each returns the process exit status and
// lets TopologyError, io::ObjError and other exceptions escape to main(), which reports them.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/refiner.h>
#include <quadtri/far/stencil_table.h>
#include "tools/obj_io.h"
#include "tools/realtime/frame_evaluator.h"
#include "tools/realtime/surface_tables.h"

namespace quadtri::cli {

// Flags shared by every subcommand.
struct MeshArgs {
    std::string input;
    std::optional<Scheme> scheme;                   // default: Schaefer-Warren
    std::optional<BoundaryInterpolation> boundary;  // default: the file's tag, else edge only
    std::optional<CreaseMethod> creaseMethod;       // default: the file's tag, else uniform
    std::optional<FVarLinearInterpolation> uvInterpolation;  // default: Options' (OpenSubdiv's corners-plus1)
    std::optional<std::size_t> memoryBudget;        // default: Options::memoryBudgetBytes
    bool smoothTriangles = false;                   // --smooth-triangles (catmull-clark only); else the file's tag
};

// The file, refused with an ObjError when it has no faces; its warnings printed.
io::ObjMesh loadMesh(const MeshArgs& args);
// Defaults, then the file's tags, then explicit flags. The scheme comes first: whether the
// file's smoothtriangles tag applies depends on it.
Options makeOptions(const MeshArgs& args, const io::ObjMesh& mesh);
// The analyzer over a file's mesh, with its UVs as face-varying channel 0 when the file has
// them; topology errors name the file line of the face or tag at fault.
Refiner makeRefiner(const io::ObjMesh& mesh, const Options& options);
// Refuses non-finite refined positions, naming the level and scheme (a mesh the scheme cannot take).
void checkFinite(const std::vector<float>& positions, const io::ObjMesh& mesh, int level, Scheme scheme);

// Largest refinement level accepted on the command line (the memory budget may refuse less).
constexpr int kMaxLevel = 10;

// Which evaluator applies the stencils (`refine --evaluator`).
enum class EvaluatorKind { Cpu, Tbb, Vulkan };

// Which normals `refine` writes (`--normals`): none, the refined mesh's area-weighted vertex
// normals, or the limit surface's normals at the written vertices.
enum class NormalKind { None, Mesh, Limit };

struct RefineArgs {
    MeshArgs mesh;
    int level = 1;
    std::string output;
    EvaluatorKind evaluator = EvaluatorKind::Cpu;
    bool limit = false;                     // --limit: the vertices moved onto the limit surface
    std::optional<NormalKind> normals;      // default: limit normals with --limit, else none
};

// What `refine` writes: level `level`'s positions (moved onto the limit surface when `limit`)
// and, unless `normals` is None, one unit normal per vertex (3 floats each).
struct Surface {
    std::vector<float> positions;
    std::vector<float> normals;
};
// `refined` is level `level`'s positions (evaluateLevels). The limit table and mesh normals are
// evaluated with `kind`; Vulkan without a usable device falls back to the CPU, saying so.
Surface evaluateSurface(EvaluatorKind kind, const Refiner& refiner, int level, std::vector<float> refined, bool limit,
                        NormalKind normals);

// Data refined with the mesh: `width` floats per element of `control`, taken through the
// per-level tables of levels 1, 2, ... one after another.
struct LevelData {
    std::vector<const StencilTable*> tables;
    int width = 3;
    const std::vector<float>* control = nullptr;
};
// Level 1..level's tables of the positions (3 floats) and of face-varying channel `channel`.
LevelData positionLevels(const Refiner& refiner, int level, const std::vector<float>& control);
LevelData fvarLevels(const Refiner& refiner, int channel, int level, const std::vector<float>& values, int width);

// Each of `data` at its last level, through the chosen evaluator (linear in the tables; a
// factorized table can be far larger near high-valence vertices). Vulkan without a usable device
// falls back to the CPU evaluator, saying so on stderr.
std::vector<std::vector<float>> evaluateLevels(EvaluatorKind kind, const std::vector<LevelData>& data);
// 3-float positions of level `level` (>= 1) of `refiner`, as above.
std::vector<float> evaluateLevels(EvaluatorKind kind, const Refiner& refiner, int level, const std::vector<float>& control);

// The Vulkan side (tools/vulkan_side.cpp, or tools/no_vulkan.cpp in a build without Vulkan).
// Each of `data` at its last level on a headless Vulkan device, level by level, or nothing
// without one (saying why on stderr).
std::optional<std::vector<std::vector<float>>> evaluateLevelsOnVulkan(const std::vector<LevelData>& data);
// The same as evaluateSurface on a headless Vulkan device, or nothing without one (saying why).
std::optional<Surface> evaluateSurfaceOnVulkan(const Refiner& refiner, int level, const std::vector<float>& refined,
                                               bool limit, NormalKind normals);
// For the demo: the real-time loop on a headless Vulkan device with `tables` uploaded, or null
// (saying why on stderr). `device` gets the device's name.
std::unique_ptr<realtime::FrameEvaluator> makeVulkanFrameEvaluator(const realtime::SurfaceTables& tables,
                                                                   std::string& device);

// Where face-varying channel `channel` of `refiner` is cut at level 0: the mesh edges whose faces
// disagree on a value at either end, and the vertices with more than one value.
struct FVarSeams {
    int edges = 0;
    int vertices = 0;
};
FVarSeams countFVarSeams(const Refiner& refiner, int channel);

struct InfoArgs {
    MeshArgs mesh;
    int level = 3;
};

// `quadtri demo`: the real-time loop (tools/realtime/) timed per evaluator.
struct DemoArgs {
    MeshArgs mesh;
    int level = 3;
    int frames = 120;         // timed frames per evaluator, at most
    double seconds = 2.0;     // time per evaluator, at most (at least 3 frames are timed)
    std::vector<EvaluatorKind> evaluators{EvaluatorKind::Cpu, EvaluatorKind::Tbb, EvaluatorKind::Vulkan};
    std::optional<realtime::TableRoute> route;  // default: realtime::fastestSurfaceTables' choice
};

// `quadtri render` (tools/render_command.cpp; docs/rendering.md).
struct RenderArgs {
    MeshArgs mesh;
    int level = 3;
    std::string output;
    std::string shading = "smooth";  // a name of renderShadings()
    bool cage = false, points = false, hideSurface = false;
    bool limit = false;                // vertices on the limit surface
    float yaw = 30.0f, pitch = 20.0f;  // degrees
    int width = 800, height = 600;     // of each panel
    std::array<float, 3> lightDirection{-0.3f, 0.5f, 0.8f};  // towards the light, view space
    std::array<float, 3> lightColor{1.0f, 1.0f, 1.0f};
    std::string texture;               // PNG or JPEG for textured shading; empty: a checker
    EvaluatorKind evaluator = EvaluatorKind::Cpu;
    std::optional<float> creaseSharpness;  // replaces every `t crease` sharpness of the file
    std::vector<Scheme> compare;           // one panel per scheme, labelled
    float stripes = 16.0f;                 // reflection lines over the half circle
    std::optional<float> curvatureRange;   // mean curvature at the colour map's ends; default: data's 95th percentile
    std::string label;                     // written in the top-left corner (with --compare: after the scheme)
    int supersample = 1;                   // drawn k times larger, each k x k block averaged
};
// The shading names `--shading` takes, in help order.
const std::vector<std::string>& renderShadings();

// `quadtri evaluate`: the limit surface at the points of a file (docs/command_line.md).
struct EvaluateArgs {
    MeshArgs mesh;
    std::string points;  // one `face u v` per line, faces from 1 in the order of the file's f lines
    std::string output;  // empty: standard output
    bool derivatives = false;
    bool uv = false;  // add the limit UV (the file's vt) to each line
};

// `quadtri tessellate`: every face at a rate per edge, on the limit surface (docs/command_line.md).
struct TessellateArgs {
    MeshArgs mesh;
    int rate = 4;
    std::string output;  // .obj, or .glb / .gltf
};

int runRefine(const RefineArgs& args);
int runEvaluate(const EvaluateArgs& args);
int runTessellate(const TessellateArgs& args);
int runInfo(const InfoArgs& args);
int runDemo(const DemoArgs& args);
// Exit status 2, with the reason on stderr, without a Vulkan device (or in a build without Vulkan).
int runRender(const RenderArgs& args);

}  // namespace quadtri::cli
