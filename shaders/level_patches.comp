// GLSL mirror of kernels/patch_kernel_loops.h: a workgroup per regular patch of a
// LevelPatchTable (or per few, where the rate is low), each invocation holding the patch's 16
// (B-spline) or 12 (box-spline) points and writing every span-th of the patch's outputs: the
// position and the unit normal at its grid cell (i, j), the tangents summed relative to the
// patch's first point as the host sums them, the normal (0, 0, 0) where they are parallel.
// The table's stencils are limit_eval.comp's. Compiled to SPIR-V at build time and embedded in
// quadtri_vulkan.
#version 450

layout(local_size_x_id = 0) in;  // workgroup size, default 64
layout(constant_id = 1) const int SRC_STRIDE = 3;
layout(constant_id = 2) const int POSITION_STRIDE = 3;
layout(constant_id = 3) const int NORMAL_STRIDE = 3;
layout(constant_id = 4) const int OUTPUTS = 3;  // bits: position, normal
// Whether the source is read through the texel buffer of binding 9 (the caller gave a view;
// lavapipe turns a texel fetch into a vector gather, a storage-buffer load into a branch per
// lane: docs/architecture.md, "Vulkan on lavapipe").
layout(constant_id = 5) const bool SOURCE_TEXELS = false;
// Whether patchPoints, outputCells and boxSplineWeights are read through the texel buffers of
// bindings 10-12 (the table has views: its arrays are within the device's texel limit).
layout(constant_id = 6) const bool TABLE_TEXELS = false;

const float DEGENERATE_SINE = 1e-4;
const bool WRITE_POSITION = (OUTPUTS & 1) != 0;
const bool WRITE_NORMAL = (OUTPUTS & 2) != 0;

layout(std430, set = 0, binding = 0) readonly buffer PatchBasis { int patchBasis[]; };  // 0 B-spline, 1 box spline
layout(std430, set = 0, binding = 1) readonly buffer PointOffsets { int pointOffsets[]; };
layout(std430, set = 0, binding = 2) readonly buffer PatchPoints { int patchPoints[]; };
layout(std430, set = 0, binding = 3) readonly buffer OutputOffsets { int outputOffsets[]; };
// Two 16-bit cells i + 256 j per word, output o in the low half when o is even.
layout(std430, set = 0, binding = 4) readonly buffer OutputCells { uint outputCells[]; };
// Per cell j (rate + 1) + i, per point: the weights of the position, d/ds and d/dt.
layout(std430, set = 0, binding = 5) readonly buffer BoxSplineWeights { float boxSplineWeights[]; };
layout(std430, set = 0, binding = 6) readonly buffer Src { float src[]; };
layout(std430, set = 0, binding = 7) writeonly buffer Position { float position[]; };
layout(std430, set = 0, binding = 8) writeonly buffer Normal { float normal[]; };
layout(set = 0, binding = 9) uniform samplerBuffer srcTexels;  // pc.srcOffset counts from its texel 0
layout(set = 0, binding = 10) uniform isamplerBuffer pointTexels;
layout(set = 0, binding = 11) uniform usamplerBuffer cellTexels;
layout(set = 0, binding = 12) uniform samplerBuffer boxTexels;

layout(push_constant) uniform Push {
    uint srcOffset;  // floats before element 0 in each bound range
    uint positionOffset;
    uint normalOffset;
    uint rate;
    uint patchesPerGroup;  // max(1, gl_WorkGroupSize.x / (rate + 1)^2): low rates share a workgroup
    uint numPatches;
    uint start;  // invocations, whole workgroups
    uint end;
} pc;

// The cubic B-spline's 4 weights at t in [0, 1] and their derivatives (the table's curveWeights,
// which are not uploaded: arithmetic is cheaper than a load per lane).
void cubicBSpline(float t, out vec4 w, out vec4 dw) {
    const float r = 1.0 - t, t2 = t * t, t3 = t2 * t;
    w = vec4(r * r * r, 3.0 * t3 - 6.0 * t2 + 4.0, -3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0, t3) * (1.0 / 6.0);
    dw = vec4(-r * r, 3.0 * t2 - 4.0 * t, -3.0 * t2 + 2.0 * t + 1.0, t2) * 0.5;
}

float sourceFloat(uint s) { return SOURCE_TEXELS ? texelFetch(srcTexels, int(s)).x : src[s]; }

int patchPoint(int k) { return TABLE_TEXELS ? texelFetch(pointTexels, k).x : patchPoints[k]; }
uint cellWord(uint k) { return TABLE_TEXELS ? texelFetch(cellTexels, int(k)).x : outputCells[k]; }
float boxWeight(uint k) { return TABLE_TEXELS ? texelFetch(boxTexels, int(k)).x : boxSplineWeights[k]; }

vec3 source(int point) {
    const uint s = pc.srcOffset + uint(patchPoint(point)) * uint(SRC_STRIDE);
    return vec3(sourceFloat(s), sourceFloat(s + 1u), sourceFloat(s + 2u));
}

// Four of the patch's points from `first` on, relative to p0, as the columns of a matrix. Named
// matrices rather than an array indexed in a loop: a driver may keep such an array in memory.
mat4x3 pointsFrom(int first, vec3 p0) {
    return mat4x3(source(first) - p0, source(first + 1) - p0, source(first + 2) - p0, source(first + 3) - p0);
}

// The box spline's weights of one cell for points 4 g .. 4 g + 3: of the position, d/ds, d/dt.
void boxWeights(uint cell, uint g, out vec4 w, out vec4 ws, out vec4 wt) {
    const uint b = cell + 12u * g;
    w = vec4(boxWeight(b), boxWeight(b + 3u), boxWeight(b + 6u), boxWeight(b + 9u));
    ws = vec4(boxWeight(b + 1u), boxWeight(b + 4u), boxWeight(b + 7u), boxWeight(b + 10u));
    wt = vec4(boxWeight(b + 2u), boxWeight(b + 5u), boxWeight(b + 8u), boxWeight(b + 11u));
}

void main() {
    // Each of the workgroup's patches has `span` invocations.
    const uint group = gl_WorkGroupSize.x, span = group / pc.patchesPerGroup;
    const uint slot = gl_LocalInvocationID.x / span, lane = gl_LocalInvocationID.x % span;
    const uint face = (pc.start / group + gl_WorkGroupID.x) * pc.patchesPerGroup + slot;  // "patch" is a keyword
    if (slot >= pc.patchesPerGroup || face >= pc.numPatches) return;
    const uint firstOutput = uint(outputOffsets[face]), last = uint(outputOffsets[face + 1u]);
    if (firstOutput + lane >= last) return;  // an invocation with no output gathers nothing
    const bool bSpline = patchBasis[face] == 0;
    const int first = pointOffsets[face];
    // Each invocation gathers the points itself: on a GPU the workgroup's loads of one address
    // are one, and lavapipe runs a shared-memory copy and its barrier no faster.
    const vec3 p0 = source(first);
    const mat4x3 a = pointsFrom(first, p0), b = pointsFrom(first + 4, p0), c = pointsFrom(first + 8, p0);
    const mat4x3 e = bSpline ? pointsFrom(first + 12, p0) : mat4x3(0.0);
    const uint rows = pc.rate + 1u;
    const float step = 1.0 / float(pc.rate);
    for (uint o = firstOutput + lane; o < last; o += span) {
        const uint cell = (cellWord(o >> 1) >> ((o & 1u) * 16u)) & 0xffffu;
        const uint i = cell & 0xffu, j = cell >> 8;
        vec3 p, du, dv;
        if (bSpline) {
            // Each row's curve at i and its derivative, then the rows at j: a tensor product.
            vec4 wi, dwi, wj, dwj;
            cubicBSpline(float(i) * step, wi, dwi);
            cubicBSpline(float(j) * step, wj, dwj);
            const mat4x3 q = mat4x3(a * wi, b * wi, c * wi, e * wi), dq = mat4x3(a * dwi, b * dwi, c * dwi, e * dwi);
            p = q * wj;
            du = dq * wj;
            dv = q * dwj;
        } else {
            const uint at = (j * rows + i) * 36u;
            vec4 w, ws, wt;
            boxWeights(at, 0u, w, ws, wt);
            p = a * w, du = a * ws, dv = a * wt;
            boxWeights(at, 1u, w, ws, wt);
            p += b * w, du += b * ws, dv += b * wt;
            boxWeights(at, 2u, w, ws, wt);
            p += c * w, du += c * ws, dv += c * wt;
        }
        p += p0;
        if (WRITE_POSITION) {
            const uint d = pc.positionOffset + o * uint(POSITION_STRIDE);
            position[d] = p.x;
            position[d + 1u] = p.y;
            position[d + 2u] = p.z;
        }
        if (WRITE_NORMAL) {
            const vec3 n = cross(du, dv);
            const float n2 = dot(n, n);
            const vec3 result = n2 > DEGENERATE_SINE * DEGENERATE_SINE * dot(du, du) * dot(dv, dv) ? n * inversesqrt(n2)
                                                                                               : vec3(0.0);
            const uint d = pc.normalOffset + o * uint(NORMAL_STRIDE);
            normal[d] = result.x;
            normal[d + 1u] = result.y;
            normal[d + 2u] = result.z;
        }
    }
}
