// glTF through tinygltf: the arrays become one buffer (indices, then each attribute), one view
// and one accessor per array, positions with the min/max glTF requires.
#include "tools/gltf_io.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <limits>
#include <ostream>

#include <tiny_gltf.h>

#include "tools/obj_io.h"

namespace quadtri::io {

namespace {

bool isBinary(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return extension == ".glb";
}

// Appends `bytes` of `data` to the model's one buffer as a view, and an accessor over it.
int addAccessor(tinygltf::Model& model, const void* data, std::size_t bytes, int componentType, int type,
                std::size_t count, int target) {
    std::vector<unsigned char>& buffer = model.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    const unsigned char* first = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), first, first + bytes);
    buffer.resize((buffer.size() + 3) / 4 * 4, 0);  // every view starts 4-byte aligned
    model.bufferViews.push_back(view);
    tinygltf::Accessor accessor;
    accessor.bufferView = int(model.bufferViews.size()) - 1;
    accessor.byteOffset = 0;
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    model.accessors.push_back(accessor);
    return int(model.accessors.size()) - 1;
}

int addFloats(tinygltf::Model& model, const std::vector<float>& values, int width) {
    return addAccessor(model, values.data(), values.size() * sizeof(float), TINYGLTF_COMPONENT_TYPE_FLOAT,
                       width == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC2, values.size() / width,
                       TINYGLTF_TARGET_ARRAY_BUFFER);
}

std::vector<float> flippedV(const std::vector<float>& uvs) {
    std::vector<float> out = uvs;
    for (std::size_t i = 1; i < out.size(); i += 2) out[i] = 1.0f - out[i];
    return out;
}

}  // namespace

void writeGltf(const std::string& path, const TriangleMesh& mesh) {
    const std::size_t n = mesh.positions.size() / 3;
    if (mesh.positions.size() != 3 * n || (!mesh.normals.empty() && mesh.normals.size() != 3 * n) ||
        (!mesh.uvs.empty() && mesh.uvs.size() != 2 * n) || mesh.triangles.size() % 3 != 0)
        throw ObjError(path + ": cannot write glTF: the vertex arrays disagree in size");
    for (std::uint32_t i : mesh.triangles)
        if (i >= n) throw ObjError(path + ": cannot write glTF: triangle index " + std::to_string(i) + " out of range");
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "quadtri";
    model.buffers.resize(1);
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.indices = addAccessor(model, mesh.triangles.data(), mesh.triangles.size() * sizeof(std::uint32_t),
                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, mesh.triangles.size(),
                                    TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    const int positions = addFloats(model, mesh.positions, 3);
    std::vector<double> lo(3, std::numeric_limits<double>::max()), hi(3, std::numeric_limits<double>::lowest());
    for (std::size_t v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], double(mesh.positions[3 * v + c]));
            hi[c] = std::max(hi[c], double(mesh.positions[3 * v + c]));
        }
    if (n > 0) model.accessors[positions].minValues = lo, model.accessors[positions].maxValues = hi;
    primitive.attributes["POSITION"] = positions;
    if (!mesh.normals.empty()) primitive.attributes["NORMAL"] = addFloats(model, mesh.normals, 3);
    if (!mesh.uvs.empty()) primitive.attributes["TEXCOORD_0"] = addFloats(model, flippedV(mesh.uvs), 2);
    tinygltf::Mesh gltfMesh;
    gltfMesh.primitives.push_back(primitive);
    model.meshes.push_back(gltfMesh);
    tinygltf::Node node;
    node.mesh = 0;
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    const bool binary = isBinary(path);
    writeReplacing(path, [&](std::ostream& out) {
        tinygltf::TinyGLTF writer;
        if (!writer.WriteGltfSceneToStream(&model, out, !binary, binary)) out.setstate(std::ios::failbit);
    });
}

namespace {

// The accessor's floats (width per element, tightly packed or strided), or empty if absent.
std::vector<float> floatsOf(const tinygltf::Model& model, const tinygltf::Primitive& p, const char* name, int width,
                            const std::string& path) {
    const auto it = p.attributes.find(name);
    if (it == p.attributes.end()) return {};
    const tinygltf::Accessor& a = model.accessors.at(it->second);
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) throw ObjError(path + ": " + name + " is not float");
    const tinygltf::BufferView& view = model.bufferViews.at(a.bufferView);
    const std::vector<unsigned char>& data = model.buffers.at(view.buffer).data;
    const std::size_t stride = view.byteStride ? view.byteStride : width * sizeof(float);
    std::vector<float> out(a.count * width);
    for (std::size_t i = 0; i < a.count; ++i) {
        const std::size_t at = view.byteOffset + a.byteOffset + i * stride;
        if (at + width * sizeof(float) > data.size()) throw ObjError(path + ": " + name + " runs past its buffer");
        std::memcpy(&out[i * width], &data[at], width * sizeof(float));
    }
    return out;
}

}  // namespace

TriangleMesh readGltf(const std::string& path) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    const bool ok = isBinary(path) ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                                   : loader.LoadASCIIFromFile(&model, &error, &warning, path);
    if (!ok) throw ObjError(path + ": cannot read glTF: " + error);
    if (model.meshes.empty() || model.meshes[0].primitives.empty()) throw ObjError(path + ": no mesh primitive");
    const tinygltf::Primitive& p = model.meshes[0].primitives[0];
    TriangleMesh mesh;
    mesh.positions = floatsOf(model, p, "POSITION", 3, path);
    mesh.normals = floatsOf(model, p, "NORMAL", 3, path);
    mesh.uvs = flippedV(floatsOf(model, p, "TEXCOORD_0", 2, path));
    const tinygltf::Accessor& a = model.accessors.at(p.indices);
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) throw ObjError(path + ": indices are not uint32");
    const tinygltf::BufferView& view = model.bufferViews.at(a.bufferView);
    const std::vector<unsigned char>& data = model.buffers.at(view.buffer).data;
    if (view.byteOffset + a.byteOffset + a.count * sizeof(std::uint32_t) > data.size())
        throw ObjError(path + ": indices run past their buffer");
    mesh.triangles.resize(a.count);
    std::memcpy(mesh.triangles.data(), &data[view.byteOffset + a.byteOffset], a.count * sizeof(std::uint32_t));
    return mesh;
}

}  // namespace quadtri::io
