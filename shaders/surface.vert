#version 450
// The refined surface by vertex pulling (docs/rendering.md): vertex i of the draw is corner i % 3
// of triangle i / 3; its draw vertex indexes the level's vertex (vertexOf), whose position and
// normal are read from the evaluators' own output buffers.

layout(std430, set = 0, binding = 0) readonly buffer Positions { float positions[]; };
layout(std430, set = 0, binding = 1) readonly buffer Normals { float normals[]; };
layout(std430, set = 0, binding = 2) readonly buffer Triangles { uint triangles[]; };
layout(std430, set = 0, binding = 3) readonly buffer VertexOf { int vertexOf[]; };
layout(std430, set = 0, binding = 4) readonly buffer UVs { vec2 uvs[]; };
layout(std430, set = 0, binding = 5) readonly buffer Scalars { float scalars[]; };
layout(std430, set = 0, binding = 6) readonly buffer Origins { uint origins[]; };

layout(push_constant) uniform View {
    mat4 viewProjection;
    vec4 eye;          // xyz; w: reflection-line stripes
    vec4 lightDir;     // xyz towards the light (world space); w: mean-curvature range
    vec4 lightColor;   // rgb
    ivec4 params;      // mode, first position float, first normal float, flags
} view;

const int kHasUVs = 1, kHasCurvature = 4;

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec2 uv;
layout(location = 3) out float scalar;
layout(location = 4) flat out uint origin;

void main() {
    const uint corner = uint(gl_VertexIndex);
    const uint drawVertex = triangles[corner];
    const int v = vertexOf[drawVertex];
    const int p = view.params.y + 3 * v, n = view.params.z + 3 * v;
    worldPosition = vec3(positions[p], positions[p + 1], positions[p + 2]);
    worldNormal = vec3(normals[n], normals[n + 1], normals[n + 2]);
    uv = (view.params.w & kHasUVs) != 0 ? uvs[drawVertex] : vec2(0.0);
    scalar = (view.params.w & kHasCurvature) != 0 ? scalars[v] : 0.0;
    origin = origins[corner / 3u];
    gl_Position = view.viewProjection * vec4(worldPosition, 1.0);
}
