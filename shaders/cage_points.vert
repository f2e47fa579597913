#version 450
// Control vertices as screen-space squares (point sizes above 1 are not portable): vertex i is
// corner i % 6 of point i / 6's two triangles.

layout(std430, set = 0, binding = 0) readonly buffer Positions { float positions[]; };
layout(std430, set = 0, binding = 3) readonly buffer PointColors { vec4 pointColors[]; };

layout(push_constant) uniform Cage {
    mat4 viewProjection;
    vec4 viewport;  // width, height, half the edge width and half the point size in pixels
    vec4 eye;       // xyz; w: how far the cage is pulled towards the eye (world units)
} cage;

layout(location = 0) out vec3 color;

void main() {
    const uint v = uint(gl_VertexIndex) / 6u, k = uint(gl_VertexIndex) % 6u;
    const vec2 corner[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    const vec3 p = vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    // Pulled twice as far as the edges, so that a point covers the edges meeting there.
    vec4 c = cage.viewProjection * vec4(p + 2.0 * cage.eye.w * normalize(cage.eye.xyz - p), 1.0);
    c.xy += corner[k] * cage.viewport.w / (0.5 * cage.viewport.xy) * c.w;
    gl_Position = c;
    color = pointColors[v].rgb;
}
