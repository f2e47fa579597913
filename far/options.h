// Inputs of the topology analyzer: the mesh as plain arrays plus the refinement options.
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <quadtri/export.h>

namespace quadtri {
inline namespace v0 {

// Each scheme's rules are registered in far/schemes/schemes.cpp; allSchemes() lists them.
enum class Scheme {
    Bilinear,  // linear subdivision only: corners stay, edge midpoints, face centroids
    StamLoop,  // Stam-Loop quad/triangle: Catmull-Clark on quads, Loop on triangles, corrected mixed vertices
    SchaeferWarren,  // Stam-Loop plus unzipping of the tri/quad network: C2 across the ordinary seam
    CatmarkButterfly,  // Catmull-Clark on quads, interpolating Butterfly on triangles (docs/catmark_butterfly/)
    CatmullClark,  // OpenSubdiv's Catmark exactly: every face, triangles too, split into quads (docs/schemes/catmull_clark.md)
    Loop,          // OpenSubdiv's Loop exactly, on triangle meshes only (docs/schemes/loop.md)
};

enum class BoundaryInterpolation {
    EdgeOnly,       // boundary edges sharp; a corner vertex (1 face, 2 edges) follows the crease rule
    EdgeAndCorner,  // boundary edges sharp; a corner vertex is fixed
    None,           // boundary edges sharp; faces at non-sharp boundary vertices become holes
};

enum class CreaseMethod {
    Uniform,  // s -> s - 1 per level
    Chaikin,  // 3:1 blend with the other semi-sharp edges at the vertex, then - 1
};

// Which face-varying values are interpolated linearly (kept as corners) rather than smoothly, as
// OpenSubdiv's Sdc::Options::FVarLinearInterpolation; Blender's "UV Smooth" label in brackets
// (docs/face_varying.md says what each one sharpens).
enum class FVarLinearInterpolation {
    None,          // smooth everywhere, seams as smooth boundaries ("All" in Blender: smooth all)
    CornersOnly,   // values at a seam corner (one face) are sharp ("Keep Corners")
    CornersPlus1,  // also junctions of 3+ values, and 2 values where one side is sharp ("Keep Corners, Junctions"); OpenSubdiv's default
    CornersPlus2,  // also darts and both values where one is a corner ("Keep Corners, Junctions, Concave")
    Boundaries,    // every value on a seam or the mesh boundary is linear ("Keep Boundaries")
    All,           // linear everywhere, bilinear on the channel's faces ("None" in Blender: no smoothing)
};

struct Options {
    Scheme scheme = Scheme::SchaeferWarren;
    BoundaryInterpolation boundary = BoundaryInterpolation::EdgeOnly;
    CreaseMethod creaseMethod = CreaseMethod::Uniform;
    // Faces are listed clockwise. Only the orientation of faces depends on it; no weight does.
    bool leftHanded = false;
    // OpenSubdiv's smooth-triangle rule (Sdc::Options::TRI_SUB_SMOOTH): edges beside a triangle
    // weigh the face points more. Catmull-Clark only; under any other scheme the Refiner refuses
    // it with a TopologyError.
    bool smoothTriangles = false;
    // How face-varying channels (TopologyDescriptor::fvarChannels) treat their seams and corners.
    FVarLinearInterpolation fvarLinearInterpolation = FVarLinearInterpolation::CornersPlus1;
    // A refinement whose estimated tables and output exceed this many bytes is refused.
    std::size_t memoryBudgetBytes = std::size_t(4) << 30;
};

// One face-varying channel (UVs, say): its own values, and one value index per face corner, in
// the order of TopologyDescriptor::faceVertIndices. Where two faces that share a mesh vertex give it
// different values, the channel has a seam there (docs/face_varying.md).
struct FVarChannel {
    int numValues = 0;
    const int* valueIndices = nullptr;  // sum(numVertsPerFace) entries, each in [0, numValues)
};

// Sharpness at or above this value is infinitely sharp.
constexpr float kInfiniteSharpness = 10.0f;

// The mesh as plain arrays; nothing is copied until the Refiner is built. A face that repeats a
// vertex is read as the simple loops it walks around (far/topology/face_loops.h): `4 3 5 5` is the
// triangle `4 3 5`, `1 2 3 1 4 5` the triangles `1 2 3` and `1 4 5`, and `1 1 2 2` has no area
// and is left out (Refiner::warnings() says so, except for collapsed edges like `4 3 5 5`).
// Catmull-Clark, which must equal OpenSubdiv, keeps `4 3 5 5` as the quad it is, with an edge
// from 5 to 5, as OpenSubdiv does.
struct TopologyDescriptor {
    int numVertices = 0;
    int numFaces = 0;
    const int* numVertsPerFace = nullptr;  // numFaces entries
    const int* faceVertIndices = nullptr;  // sum(numVertsPerFace) entries, 0-based

    int numCreases = 0;
    const int* creaseVertexPairs = nullptr;  // 2 * numCreases
    const float* creaseWeights = nullptr;    // numCreases sharpness values

    int numCorners = 0;
    const int* cornerVertexIndices = nullptr;  // numCorners
    const float* cornerWeights = nullptr;      // numCorners sharpness values

    int numHoles = 0;
    const int* holeIndices = nullptr;  // face indices

    // Face-varying channels, refined with the mesh (Refiner::fvarLevelStencils). A face that
    // repeats a vertex is read as the mesh reads it, its loops, each corner with the value of the
    // input corner it comes from (docs/face_varying.md).
    int numFVarChannels = 0;
    const FVarChannel* fvarChannels = nullptr;  // numFVarChannels
};

// One problem found in the input: which item (a face, crease, corner or hole, by its index in the
// descriptor's arrays), the vertex it is about if any, and what is wrong. A file reader renders it
// in the file's own numbering (line, 1-based OBJ indices); message() renders it 0-based:
// "face 2: vertex 7 appears more than once".
struct QUADTRI_API TopologyDiagnostic {
    enum class Component { None, Face, Crease, Corner, Hole };
    Component component = Component::None;
    int index = -1;   // item index in the descriptor, or -1
    int vertex = -1;  // 0-based vertex the problem is about, or -1; message() puts "vertex V " before problem
    std::string problem;  // the rest of the message

    std::string message() const;
};

// Malformed topology or an unsatisfiable request. The message names the face, vertex or level;
// diagnostic() says which input item is at fault, so that a file reader can point at the line
// it came from.
class QUADTRI_API TopologyError : public std::runtime_error {
public:
    using Component = TopologyDiagnostic::Component;
    explicit TopologyError(const std::string& what) : std::runtime_error(what), diagnostic_{Component::None, -1, -1, what} {}
    explicit TopologyError(TopologyDiagnostic diagnostic)
        : std::runtime_error(diagnostic.message()), diagnostic_(std::move(diagnostic)) {}
    Component component() const { return diagnostic_.component; }
    int index() const { return diagnostic_.index; }
    const TopologyDiagnostic& diagnostic() const { return diagnostic_; }

private:
    TopologyDiagnostic diagnostic_;
};

// The memory budget (Options::memoryBudgetBytes) refused a step before its allocations: `subject`
// says which ("level 4", "the factorized stencils of level 4"), `needed` is what it would have
// taken at least, counting what the Refiner already holds (`held`).
class QUADTRI_API MemoryBudgetError : public TopologyError {
public:
    MemoryBudgetError(std::string subject, std::size_t needed, std::size_t held, std::size_t budget);
    const std::string& subject() const { return subject_; }
    std::size_t needed() const { return needed_; }
    std::size_t held() const { return held_; }
    std::size_t budget() const { return budget_; }

private:
    std::string subject_;
    std::size_t needed_, held_, budget_;
};

QUADTRI_API const char* toString(Scheme scheme);  // the scheme's name: "stam-loop"
// Every scheme, in the order help texts list them; a one-line description of each; the scheme
// of a name as toString spells it, or nullopt.
QUADTRI_API const std::vector<Scheme>& allSchemes();
QUADTRI_API const char* describe(Scheme scheme);
QUADTRI_API std::optional<Scheme> schemeNamed(std::string_view name);
// Whether Options::smoothTriangles applies to the scheme (catmull-clark); the Refiner refuses it
// elsewhere.
QUADTRI_API bool takesSmoothTriangles(Scheme scheme);
QUADTRI_API const char* toString(BoundaryInterpolation boundary);
// The face-varying options by name ("corners-plus1"), every one in order, and back from a name.
QUADTRI_API const char* toString(FVarLinearInterpolation interpolation);
QUADTRI_API const std::vector<FVarLinearInterpolation>& allFVarLinearInterpolations();
QUADTRI_API std::optional<FVarLinearInterpolation> fvarLinearInterpolationNamed(std::string_view name);
QUADTRI_API const char* toString(CreaseMethod method);

}  // namespace v0
}  // namespace quadtri
