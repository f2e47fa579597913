#version 450
// Control edges as screen-space quads a few pixels wide (wide lines are not portable): vertex i
// is corner i % 6 of edge i / 6's two triangles, pulled a little towards the eye so that the
// cage shows where it lies on the surface.

layout(std430, set = 0, binding = 0) readonly buffer Positions { float positions[]; };
layout(std430, set = 0, binding = 1) readonly buffer Edges { uint edges[]; };
layout(std430, set = 0, binding = 2) readonly buffer EdgeColors { vec4 edgeColors[]; };

layout(push_constant) uniform Cage {
    mat4 viewProjection;
    vec4 viewport;  // width, height, half the edge width and half the point size in pixels
    vec4 eye;       // xyz; w: how far the cage is pulled towards the eye (world units)
} cage;

layout(location = 0) out vec3 color;

vec4 clipOf(uint v) {
    const vec3 p = vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    return cage.viewProjection * vec4(p + cage.eye.w * normalize(cage.eye.xyz - p), 1.0);
}

void main() {
    const uint e = uint(gl_VertexIndex) / 6u, k = uint(gl_VertexIndex) % 6u;
    const uint endOf[6] = uint[](0u, 1u, 1u, 0u, 1u, 0u);
    const float sideOf[6] = float[](-1.0, -1.0, 1.0, -1.0, 1.0, 1.0);
    const vec4 a = clipOf(edges[2u * e]), b = clipOf(edges[2u * e + 1u]);
    const vec2 halfViewport = 0.5 * cage.viewport.xy;
    const vec2 d = (b.xy / b.w - a.xy / a.w) * halfViewport;
    const vec2 dir = length(d) > 1e-6 ? normalize(d) : vec2(1.0, 0.0);
    const vec2 across = vec2(-dir.y, dir.x) * sideOf[k] * cage.viewport.z / halfViewport;
    vec4 c = endOf[k] == 0u ? a : b;
    c.xy += across * c.w;
    gl_Position = c;
    color = edgeColors[e].rgb;
}
