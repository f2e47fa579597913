// The MeshNormals sums in GLSL (docs/limit_evaluation.md): one invocation per vertex v, its normal
// the normalised sum over its corner triples (a, b, c) (MeshNormalTable::offsets, corners) of
// (p_b - p_v) x (p_c - p_a), the doubled vector areas of the faces around it, (0, 0, 0) when that
// sum is zero. The host loops (kernels/mesh_normal_kernel.h) add the same areas face by face, from
// another corner, so the two agree to rounding. Compiled to SPIR-V at build time and embedded in
// quadtri_vulkan (see shaders/embed_spirv.cmake).
#version 450

layout(local_size_x_id = 0) in;                   // workgroup size, default 64
layout(constant_id = 1) const int SRC_STRIDE = 3;
layout(constant_id = 2) const int DST_STRIDE = 3;

layout(std430, set = 0, binding = 0) readonly buffer Offsets { int offsets[]; };  // numVertices + 1
layout(std430, set = 0, binding = 1) readonly buffer Corners { int corners[]; };  // 3 per triple
layout(std430, set = 0, binding = 2) readonly buffer Src { float src[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Dst { float dst[]; };

layout(push_constant) uniform Push {
    uint srcOffset;  // floats before source element 0 in the bound range
    uint dstOffset;
    uint start;      // first vertex of this dispatch
    uint end;
} pc;

vec3 position(int v) {
    const uint s = pc.srcOffset + uint(v) * uint(SRC_STRIDE);
    return vec3(src[s], src[s + 1u], src[s + 2u]);
}

void main() {
    const uint v = pc.start + gl_GlobalInvocationID.x;
    if (v >= pc.end) return;
    const vec3 p = position(int(v));
    vec3 n = vec3(0.0);
    for (int k = offsets[v]; k < offsets[v + 1u]; ++k)
        n += cross(position(corners[3 * k + 1]) - p, position(corners[3 * k + 2]) - position(corners[3 * k]));
    const float len2 = dot(n, n);
    n *= len2 > 0.0 ? inversesqrt(len2) : 0.0;
    const uint d = pc.dstOffset + v * uint(DST_STRIDE);
    dst[d] = n.x;
    dst[d + 1u] = n.y;
    dst[d + 2u] = n.z;
}
