// GLSL mirror of kernels/stencil_kernel.h: one invocation per stencil,
// dst[i] = sum_k weights[weightOffsets[i]+k] * src[indices[offsets[i]+k]] for
// k < offsets[i+1] - offsets[i] and i in [start, end) (identical weight sequences are pooled).
// Stencil i writes destination element i (the CpuEvaluator contract). Compiled to SPIR-V at build
// time and embedded in quadtri_vulkan (see shaders/embed_spirv.cmake).
#version 450

layout(local_size_x_id = 0) in;               // workgroup size, default 64
layout(constant_id = 1) const int LENGTH = 3;  // floats evaluated per element
layout(constant_id = 2) const int SRC_STRIDE = 3;
layout(constant_id = 3) const int DST_STRIDE = 3;
// Where the index and weight pools (POOL_TEXELS) and the source (SOURCE_TEXELS) are read: through
// the uniform texel buffers of bindings 6-8, which lavapipe turns into vector gathers where a
// storage-buffer load is a branch per lane (docs/architecture.md, "Vulkan on lavapipe"), or
// through the storage buffers (a pool past the context's texelBufferLimit(), a source with no view).
layout(constant_id = 4) const bool POOL_TEXELS = false;
layout(constant_id = 5) const bool SOURCE_TEXELS = false;

layout(std430, set = 0, binding = 0) readonly buffer Offsets { int offsets[]; };  // numStencils + 1
layout(std430, set = 0, binding = 1) readonly buffer Indices { int indices[]; };
layout(std430, set = 0, binding = 2) readonly buffer WeightOffsets { int weightOffsets[]; };
layout(std430, set = 0, binding = 3) readonly buffer Weights { float weights[]; };
// src and dst may be the same buffer (all levels in one): different elements, so not restrict.
layout(std430, set = 0, binding = 4) readonly buffer Src { float src[]; };
layout(std430, set = 0, binding = 5) writeonly buffer Dst { float dst[]; };
layout(set = 0, binding = 6) uniform isamplerBuffer indexTexels;
layout(set = 0, binding = 7) uniform samplerBuffer weightTexels;
layout(set = 0, binding = 8) uniform samplerBuffer srcTexels;  // pc.srcOffset counts from its texel 0

layout(push_constant) uniform Push {
    uint srcOffset;  // floats before source element 0 in the bound range (or the texel view)
    uint dstOffset;  // floats before destination element 0
    uint start;      // first stencil of this dispatch
    uint end;        // one past the last stencil
} pc;

int poolIndex(int k) { return POOL_TEXELS ? texelFetch(indexTexels, k).x : indices[k]; }
float poolWeight(int k) { return POOL_TEXELS ? texelFetch(weightTexels, k).x : weights[k]; }
float sourceFloat(uint s) { return SOURCE_TEXELS ? texelFetch(srcTexels, int(s)).x : src[s]; }

void main() {
    const uint i = pc.start + gl_GlobalInvocationID.x;
    if (i >= pc.end) return;
    float acc[LENGTH];
    for (int c = 0; c < LENGTH; ++c) acc[c] = 0.0;
    const int first = offsets[i];
    const int n = offsets[i + 1] - first;
    const int firstWeight = weightOffsets[i];
    for (int k = 0; k < n; ++k) {
        const uint s = pc.srcOffset + uint(poolIndex(first + k)) * uint(SRC_STRIDE);
        const float w = poolWeight(firstWeight + k);
        for (int c = 0; c < LENGTH; ++c) acc[c] += w * sourceFloat(s + uint(c));
    }
    const uint d = pc.dstOffset + i * uint(DST_STRIDE);
    for (int c = 0; c < LENGTH; ++c) dst[d + uint(c)] = acc[c];
}
