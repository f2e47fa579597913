// GLSL mirror of kernels/limit_kernel.h: one invocation per limit stencil gathers its support
// (the run indices[offsets[i] .. offsets[i] + sizes[i]), perhaps shared with other stencils)
// once, weighing each source with the entry's (position, dU, dV) triple
// weights[weightOffsets[i] + 3k + 0, 1, 2] (the tangents relative to the first source, as the
// host), and writes the outputs OUTPUTS selects; the normal is
// normalize(dU x dV), or where the tangents are parallel (sine below DEGENERATE_SINE) the
// area-weighted face normal of the fallback table at vertex i (as shaders/mesh_normals.comp), or
// (0, 0, 0) without one. Compiled to SPIR-V at build time and embedded in quadtri_vulkan.
#version 450

layout(local_size_x_id = 0) in;  // workgroup size, default 64
layout(constant_id = 1) const int LENGTH = 3;  // floats per element of the source, position, dU, dV
layout(constant_id = 2) const int SRC_STRIDE = 3;
layout(constant_id = 3) const int POSITION_STRIDE = 3;
layout(constant_id = 4) const int DU_STRIDE = 3;
layout(constant_id = 5) const int DV_STRIDE = 3;
layout(constant_id = 6) const int NORMAL_STRIDE = 3;
layout(constant_id = 7) const int OUTPUTS = 15;     // bits: position, dU, dV, normal, fallback
// Whether the index and weight pools are read through the texel buffers of bindings 14 and 15
// (lavapipe turns a texel fetch into a vector gather, a storage-buffer load into a branch per
// lane: docs/architecture.md, "Vulkan on lavapipe") or, where the pools exceed
// the context's texelBufferLimit(), through the storage buffers of bindings 2 and 4.
layout(constant_id = 8) const bool POOL_TEXELS = true;
// Whether the source is read through the texel buffer of binding 16 (the caller gave a view).
layout(constant_id = 9) const bool SOURCE_TEXELS = false;

const float DEGENERATE_SINE = 1e-4;
const bool WRITE_POSITION = (OUTPUTS & 1) != 0;
const bool WRITE_DU = (OUTPUTS & 2) != 0;
const bool WRITE_DV = (OUTPUTS & 4) != 0;
const bool WRITE_NORMAL = (OUTPUTS & 8) != 0;
const bool USE_FALLBACK = (OUTPUTS & 16) != 0;

layout(std430, set = 0, binding = 0) readonly buffer Sizes { int sizes[]; };      // numStencils
layout(std430, set = 0, binding = 1) readonly buffer Offsets { int offsets[]; };  // numStencils; runs may be shared
layout(std430, set = 0, binding = 2) readonly buffer Indices { int indices[]; };
layout(std430, set = 0, binding = 3) readonly buffer WeightOffsets { int weightOffsets[]; };
layout(std430, set = 0, binding = 4) readonly buffer Weights { float weights[]; };
layout(std430, set = 0, binding = 5) readonly buffer Src { float src[]; };
layout(std430, set = 0, binding = 6) writeonly buffer Position { float position[]; };
layout(std430, set = 0, binding = 7) writeonly buffer Du { float du[]; };
layout(std430, set = 0, binding = 8) writeonly buffer Dv { float dv[]; };
layout(std430, set = 0, binding = 9) writeonly buffer Normal { float normal[]; };
// The fallback MeshNormalTable (as shaders/mesh_normals.comp reads it).
layout(std430, set = 0, binding = 10) readonly buffer FaceOffsets { int faceOffsets[]; };
layout(std430, set = 0, binding = 11) readonly buffer FaceCorners { int faceCorners[]; };
layout(std430, set = 0, binding = 12) readonly buffer VertexFaceOffsets { int vertexFaceOffsets[]; };
layout(std430, set = 0, binding = 13) readonly buffer VertexFaces { int vertexFaces[]; };
layout(set = 0, binding = 14) uniform isamplerBuffer indexTexels;  // the same pools as texels
layout(set = 0, binding = 15) uniform samplerBuffer weightTexels;
layout(set = 0, binding = 16) uniform samplerBuffer srcTexels;  // pc.srcOffset counts from its texel 0

layout(push_constant) uniform Push {
    uint srcOffset;  // floats before element 0 in each bound range
    uint positionOffset;
    uint duOffset;
    uint dvOffset;
    uint normalOffset;
    uint start;  // first stencil of this dispatch
    uint end;
} pc;

int poolIndex(int k) { return POOL_TEXELS ? texelFetch(indexTexels, k).x : indices[k]; }
float poolWeight(int k) { return POOL_TEXELS ? texelFetch(weightTexels, k).x : weights[k]; }

float sourceFloat(uint s) { return SOURCE_TEXELS ? texelFetch(srcTexels, int(s)).x : src[s]; }

vec3 source(int v) {
    const uint s = pc.srcOffset + uint(v) * uint(SRC_STRIDE);
    return vec3(sourceFloat(s), sourceFloat(s + 1u), sourceFloat(s + 2u));
}

const int CORNER_INDEX_MASK = (1 << 30) - 1;  // MeshNormalTable::kCornerIndexMask

vec3 corner(int k) { return source(faceCorners[k] & CORNER_INDEX_MASK); }

// (r - p) x (s - q) of corners p, q, r, s: twice a quad's vector area (kernels/mesh_normal_kernel.h).
vec3 facet(int p, int q, int r, int s) { return cross(corner(r) - corner(p), corner(s) - corner(q)); }

// Twice face f's vector area, as the host's faceArea: a triangle as (c0, c1, c2, c2), a larger
// face as a fan of quads (c0, ck, ck+1, ck+2) closed by such a triangle.
vec3 faceArea(int f) {
    const int b = faceOffsets[f], n = faceOffsets[f + 1] - b;
    if (n == 3) return facet(b, b + 1, b + 2, b + 2);
    vec3 a = facet(b, b + 1, b + 2, b + 3);
    int k = 3;
    for (; k + 2 < n; k += 2) a += facet(b, b + k, b + k + 1, b + k + 2);
    if (k + 1 < n) a += facet(b, b + k, b + k + 1, b + k + 1);
    return a;
}

vec3 meshNormal(uint v) {
    vec3 n = vec3(0.0);
    for (int k = vertexFaceOffsets[v]; k < vertexFaceOffsets[v + 1u]; ++k) n += faceArea(vertexFaces[k]);
    const float len2 = dot(n, n);
    return n * (len2 > 0.0 ? inversesqrt(len2) : 0.0);
}

void main() {
    const uint i = pc.start + gl_GlobalInvocationID.x;
    if (i >= pc.end) return;
    float p[LENGTH], u[LENGTH], v[LENGTH];
    for (int c = 0; c < LENGTH; ++c) p[c] = u[c] = v[c] = 0.0;
    const int first = offsets[i];
    const int n = sizes[i];
    int w = weightOffsets[i];
    float base[LENGTH];
    const uint s0 = n > 0 ? pc.srcOffset + uint(poolIndex(first)) * uint(SRC_STRIDE) : 0u;
    for (int c = 0; c < LENGTH; ++c) base[c] = n > 0 ? sourceFloat(s0 + uint(c)) : 0.0;
    for (int k = 0; k < n; ++k, w += 3) {
        const uint s = pc.srcOffset + uint(poolIndex(first + k)) * uint(SRC_STRIDE);
        const float wp = poolWeight(w), wu = poolWeight(w + 1), wv = poolWeight(w + 2);
        for (int c = 0; c < LENGTH; ++c) {
            const float x = sourceFloat(s + uint(c));
            const float d = x - base[c];
            p[c] += wp * x;
            u[c] += wu * d;
            v[c] += wv * d;
        }
    }
    for (int c = 0; c < LENGTH; ++c) {
        if (WRITE_POSITION) position[pc.positionOffset + i * uint(POSITION_STRIDE) + uint(c)] = p[c];
        if (WRITE_DU) du[pc.duOffset + i * uint(DU_STRIDE) + uint(c)] = u[c];
        if (WRITE_DV) dv[pc.dvOffset + i * uint(DV_STRIDE) + uint(c)] = v[c];
    }
    if (WRITE_NORMAL) {  // LENGTH is 3 here (the host checks it)
        const int y = min(1, LENGTH - 1), z = min(2, LENGTH - 1);
        const vec3 tu = vec3(u[0], u[y], u[z]), tv = vec3(v[0], v[y], v[z]);
        const vec3 c = cross(tu, tv);
        const float c2 = dot(c, c);
        vec3 result = vec3(0.0);
        if (c2 > DEGENERATE_SINE * DEGENERATE_SINE * dot(tu, tu) * dot(tv, tv))
            result = c * inversesqrt(c2);
        else if (USE_FALLBACK)
            result = meshNormal(i);
        const uint d = pc.normalOffset + i * uint(NORMAL_STRIDE);
        normal[d] = result.x;
        normal[d + 1u] = result.y;
        normal[d + 2u] = result.z;
    }
}
