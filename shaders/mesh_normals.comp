// GLSL mirror of kernels/mesh_normal_kernel.h: one invocation per vertex, its normal the
// normalised sum of the doubled vector areas sum_k (p_k - p_0) x (p_{k+1} - p_0) of the faces
// around it, (0, 0, 0) when that sum is zero. Compiled to SPIR-V at build time and embedded in
// quadtri_vulkan (see shaders/embed_spirv.cmake).
#version 450

layout(local_size_x_id = 0) in;                   // workgroup size, default 64
layout(constant_id = 1) const int SRC_STRIDE = 3;
layout(constant_id = 2) const int DST_STRIDE = 3;

layout(std430, set = 0, binding = 0) readonly buffer VertexOffsets { int vertexOffsets[]; };
layout(std430, set = 0, binding = 1) readonly buffer VertexFaces { int vertexFaces[]; };
layout(std430, set = 0, binding = 2) readonly buffer FaceOffsets { int faceOffsets[]; };
layout(std430, set = 0, binding = 3) readonly buffer FaceVerts { int faceVerts[]; };
layout(std430, set = 0, binding = 4) readonly buffer Src { float src[]; };
layout(std430, set = 0, binding = 5) writeonly buffer Dst { float dst[]; };

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
    vec3 n = vec3(0.0);
    for (int k = vertexOffsets[v]; k < vertexOffsets[v + 1u]; ++k) {
        const int f = vertexFaces[k];
        const int first = faceOffsets[f], last = faceOffsets[f + 1];
        const vec3 p0 = position(faceVerts[first]);
        vec3 a = position(faceVerts[first + 1]) - p0;
        for (int c = first + 2; c < last; ++c) {
            const vec3 b = position(faceVerts[c]) - p0;
            n += cross(a, b);
            a = b;
        }
    }
    const float len2 = dot(n, n);
    n *= len2 > 0.0 ? inversesqrt(len2) : 0.0;
    const uint d = pc.dstOffset + v * uint(DST_STRIDE);
    dst[d] = n.x;
    dst[d + 1u] = n.y;
    dst[d + 2u] = n.z;
}
