// Wavefront OBJ with OpenSubdiv's tags (`t crease`, `t corner`, `t hole`, `t interpolateboundary`,
// `t creasemethod`, `t smoothtriangles`), as described in tests/meshes/README.md.
#pragma once

#include <functional>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/level_faces.h>
#include <quadtri/far/topology.h>

namespace quadtri::io {

// A malformed file. The message starts with "file:line: ".
class ObjError : public std::runtime_error {
public:
    explicit ObjError(const std::string& what) : std::runtime_error(what) {}
};

struct ObjMesh {
    std::vector<float> positions;  // 3 floats per `v` line
    std::vector<int> faceSizes;    // corners per `f` line
    std::vector<int> faceVerts;    // 0-based position indices
    // Texture coordinates: 2 floats per `vt` line (a third, w, is checked and dropped), and per
    // face corner its 0-based `vt` index (`f v/vt`, `f v/vt/vn`), parallel to faceVerts; empty
    // when no corner names one. Either every corner names one or none does.
    std::vector<float> uvs;
    std::vector<int> faceUVs;
    std::vector<int> creasePairs;  // 2 per crease
    std::vector<float> creaseSharpness;
    std::vector<int> corners;
    std::vector<float> cornerSharpness;
    std::vector<int> holes;
    std::optional<BoundaryInterpolation> boundary;  // from `t interpolateboundary`
    std::optional<CreaseMethod> creaseMethod;       // from `t creasemethod`
    std::optional<bool> smoothTriangles;            // from `t smoothtriangles 0/0/1 smooth` (or `catmark`: false)
    std::vector<std::string> warnings;              // "file:line: ..." for ignored content

    // Where each item came from, so that topology errors can name the line.
    std::string name;
    std::vector<int> faceLines, creaseLines, cornerLines, holeLines;

    int numVertices() const { return int(positions.size() / 3); }
    int numFaces() const { return int(faceSizes.size()); }
    int numUVs() const { return int(uvs.size() / 2); }
    bool hasUVs() const { return !faceUVs.empty(); }
    // A view of the arrays above; valid while this mesh lives. No face-varying channel.
    TopologyDescriptor descriptor() const;
    // The same with the UVs as face-varying channel 0 when the file has them (`uvChannel` is
    // where the channel's view is kept: it must outlive the descriptor); none without.
    TopologyDescriptor descriptor(FVarChannel& uvChannel) const;
    // `base` with the boundary and crease method replaced where the file has tags for them, and
    // the smooth-triangle rule where the file asks for it and base.scheme has it (catmull-clark;
    // OpenSubdiv's own shape reader likewise applies the tag to Catmark shapes only).
    Options applyTags(Options base) const;
    // The whole message in the file's numbering, "file:line: " first: a face is the K-th `f`
    // statement with 1-based vertices ("face 2: vertex 4 appears more than once"); a tag keeps
    // the 0-based indices its own syntax uses ("t crease: vertices 1, 3 are not an edge ...").
    std::string describe(const TopologyDiagnostic& diagnostic) const;
};

// ObjError names the line for anything that is not an OBJ mesh statement by statement: binary
// data, PLY, glTF or STL content, malformed numbers and indices, tags. Unknown statements are
// warned about once per keyword. A UTF-8 byte-order mark is skipped.
ObjMesh parseObj(std::istream& in, const std::string& name);
ObjMesh readObj(const std::string& path);  // ObjError if the file cannot be opened

// Texture coordinates to write with a level: `numValues` values of 2 floats, and per corner of
// the level's faces (LevelFaces::vertices() order) its value index.
struct ObjUVs {
    const float* values = nullptr;
    int numValues = 0;
    const int* cornerValues = nullptr;
};

// Writes positions (3 floats each, %.9g) and the non-hole faces, 1-based. With `normals` (3
// floats per vertex), also one `vn` per vertex and faces as `f v//v`. With `uvs` (values set),
// also one `vt` per value (%.9g) and corners as `f v/vt` (`f v/vt/v` with normals).
void writeObj(std::ostream& out, const float* positions, const LevelFaces& faces, const float* normals = nullptr,
              const ObjUVs& uvs = {});
// The same into the file `path`, through writeReplacing.
void writeObj(const std::string& path, const float* positions, const LevelFaces& faces,
              const float* normals = nullptr, const ObjUVs& uvs = {});

// Writes `path` through `write` into a temporary file beside it and renames that over `path` once
// every byte is written and the file is closed, so that a failure or a kill leaves any old
// `path` whole. An existing non-regular target (/dev/stdout, a pipe) is written directly. On any
// failure, including `write` leaving the stream failed or throwing, the temporary is removed
// and ObjError says "path: cannot write file (reason)".
void writeReplacing(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace quadtri::io
