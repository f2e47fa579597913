// The MeshNormals sums in GLSL (docs/limit_evaluation.md): one invocation per vertex v, its normal
// the normalised sum over v's faces (MeshNormalTable::vertexFaces, in face order) of each face's
// doubled vector area, computed as the host's faceArea (kernels/mesh_normal_kernel.h) computes it,
// (0, 0, 0) when that sum is zero. Compiled to SPIR-V at build time and embedded in
// quadtri_vulkan (see shaders/embed_spirv.cmake).
#version 450

layout(local_size_x_id = 0) in;                   // workgroup size, default 64
layout(constant_id = 1) const int SRC_STRIDE = 3;
layout(constant_id = 2) const int DST_STRIDE = 3;

layout(std430, set = 0, binding = 0) readonly buffer FaceOffsets { int faceOffsets[]; };  // drawn faces + 1
layout(std430, set = 0, binding = 1) readonly buffer FaceCorners { int faceCorners[]; };  // flagged vertex indices
layout(std430, set = 0, binding = 2) readonly buffer VertexFaceOffsets { int vertexFaceOffsets[]; };  // numVertices + 1
layout(std430, set = 0, binding = 3) readonly buffer VertexFaces { int vertexFaces[]; };
layout(std430, set = 0, binding = 4) readonly buffer Src { float src[]; };
layout(std430, set = 0, binding = 5) writeonly buffer Dst { float dst[]; };

layout(push_constant) uniform Push {
    uint srcOffset;  // floats before source element 0 in the bound range
    uint dstOffset;
    uint start;      // first vertex of this dispatch
    uint end;
} pc;

const int CORNER_INDEX_MASK = (1 << 30) - 1;  // MeshNormalTable::kCornerIndexMask (above it: the seam flag)

vec3 corner(int k) {
    const uint s = pc.srcOffset + uint(faceCorners[k] & CORNER_INDEX_MASK) * uint(SRC_STRIDE);
    return vec3(src[s], src[s + 1u], src[s + 2u]);
}

// (r - p) x (s - q) of corners p, q, r, s: twice a quad's vector area.
vec3 facet(int p, int q, int r, int s) { return cross(corner(r) - corner(p), corner(s) - corner(q)); }

// Twice face f's vector area: a triangle as (c0, c1, c2, c2), a larger face as a fan of quads
// (c0, ck, ck+1, ck+2) closed by such a triangle.
vec3 faceArea(int f) {
    const int b = faceOffsets[f], n = faceOffsets[f + 1] - b;
    if (n == 3) return facet(b, b + 1, b + 2, b + 2);
    vec3 a = facet(b, b + 1, b + 2, b + 3);
    int k = 3;
    for (; k + 2 < n; k += 2) a += facet(b, b + k, b + k + 1, b + k + 2);
    if (k + 1 < n) a += facet(b, b + k, b + k + 1, b + k + 1);
    return a;
}

void main() {
    const uint v = pc.start + gl_GlobalInvocationID.x;
    if (v >= pc.end) return;
    vec3 n = vec3(0.0);
    for (int k = vertexFaceOffsets[v]; k < vertexFaceOffsets[v + 1u]; ++k) n += faceArea(vertexFaces[k]);
    const float len2 = dot(n, n);
    n *= len2 > 0.0 ? inversesqrt(len2) : 0.0;
    const uint d = pc.dstOffset + v * uint(DST_STRIDE);
    dst[d] = n.x;
    dst[d + 1u] = n.y;
    dst[d + 2u] = n.z;
}
