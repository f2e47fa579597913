// Inputs of the topology analyzer: the mesh as plain arrays plus the refinement options.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace quadtri {

enum class Scheme {
    Bilinear,  // linear subdivision only: corners stay, edge midpoints, face centroids
    StamLoop,  // Stam-Loop quad/triangle: Catmull-Clark on quads, Loop on triangles, corrected mixed vertices
    SchaeferWarren,  // Stam-Loop plus unzipping of the tri/quad network: C2 across the ordinary seam
    CatmarkButterfly,  // Catmull-Clark on quads, interpolating Butterfly on triangles, seed 001's seam rules
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

struct Options {
    Scheme scheme = Scheme::SchaeferWarren;
    BoundaryInterpolation boundary = BoundaryInterpolation::EdgeOnly;
    CreaseMethod creaseMethod = CreaseMethod::Uniform;
    // Faces are listed clockwise. Only the orientation of faces depends on it; no weight does.
    bool leftHanded = false;
    // A refinement whose estimated tables and output exceed this many bytes is refused.
    std::size_t memoryBudgetBytes = std::size_t(4) << 30;
};

// Sharpness at or above this value is infinitely sharp.
constexpr float kInfiniteSharpness = 10.0f;

// The mesh as plain arrays; nothing is copied until the Refiner is built. A face corner equal to
// the corner before it is a collapsed edge and is dropped (`4 3 5 5` is the triangle `4 3 5`).
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
};

// Malformed topology or an unsatisfiable request. The message names the face, vertex or level;
// component() and index() say which input item is at fault, so that a file reader can point at
// the line it came from.
class TopologyError : public std::runtime_error {
public:
    enum class Component { None, Face, Crease, Corner, Hole };
    explicit TopologyError(const std::string& what, Component component = Component::None, int index = -1)
        : std::runtime_error(what), component_(component), index_(index) {}
    Component component() const { return component_; }
    int index() const { return index_; }

private:
    Component component_;
    int index_;
};

const char* toString(Scheme scheme);
const char* toString(BoundaryInterpolation boundary);
const char* toString(CreaseMethod method);

}  // namespace quadtri
