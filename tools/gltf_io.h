// glTF 2.0 files of a refined level's draw buffers (far/draw_buffers.h), through Debian's tinygltf
// (libtinygltf-dev): one mesh of one triangle primitive with POSITION, NORMAL and TEXCOORD_0 where
// present. `.glb` is the binary container; `.gltf` is JSON with the buffer embedded (base64), so
// either is one self-contained file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace quadtri::io {

// What a file holds: per vertex 3 position floats, 3 normal floats and 2 UV floats (the last two
// may be empty), and 3 indices per triangle.
struct TriangleMesh {
    std::vector<float> positions, normals, uvs;
    std::vector<std::uint32_t> triangles;
    int numVertices() const { return int(positions.size() / 3); }
};

// Writes `mesh` to `path` (binary if it ends in .glb, any case) through writeReplacing (a
// temporary file renamed over `path`, never half written). UVs are flipped to glTF's convention
// (v' = 1 - v: glTF's origin is the image's top left, OBJ's the bottom left). ObjError
// ("path: ...") on a failure or a mesh whose arrays disagree in size.
void writeGltf(const std::string& path, const TriangleMesh& mesh);

// Reads the first primitive of the first mesh of a file writeGltf wrote (UVs flipped back); for
// tests and tools. ObjError naming the file on anything else.
TriangleMesh readGltf(const std::string& path);

}  // namespace quadtri::io
