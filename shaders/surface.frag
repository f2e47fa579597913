#version 450
// The shading modes of docs/rendering.md: smooth (interpolated limit normals), flat (the
// triangle's own normal), reflection lines, mean curvature, face type, textured.

layout(set = 0, binding = 7) uniform sampler2D surfaceTexture;

layout(push_constant) uniform View {
    mat4 viewProjection;
    vec4 eye;
    vec4 lightDir;
    vec4 lightColor;
    ivec4 params;
} view;

const int kModeSmooth = 0, kModeFlat = 1, kModeReflectionLines = 2, kModeMeanCurvature = 3, kModeFaceType = 4,
          kModeTextured = 5;
const int kHasUVs = 1, kHasTexture = 2;
const float kPi = 3.14159265358979;

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 uv;
layout(location = 3) in float scalar;
layout(location = 4) flat in uint origin;

layout(location = 0) out vec4 outColor;

// Blue (negative) through white to red (positive), t in [-1, 1].
vec3 diverging(float t) {
    const vec3 negative = vec3(0.23, 0.30, 0.75), middle = vec3(0.87, 0.87, 0.87), positive = vec3(0.71, 0.02, 0.15);
    return t < 0.0 ? mix(middle, negative, -t) : mix(middle, positive, t);
}

// Ambient + diffuse + a little specular, two-sided (n is turned towards the viewer).
vec3 lit(vec3 albedo, vec3 n, vec3 toEye, float specular) {
    const vec3 l = normalize(view.lightDir.xyz);
    const vec3 h = normalize(l + toEye);
    const float diffuse = max(dot(n, l), 0.0);
    const float shine = specular * pow(max(dot(n, h), 0.0), 48.0);
    return albedo * (0.22 + 0.78 * diffuse * view.lightColor.rgb) + shine * view.lightColor.rgb;
}

void main() {
    const int mode = view.params.x;
    const vec3 toEye = normalize(view.eye.xyz - worldPosition);
    vec3 n = mode == kModeFlat ? cross(dFdx(worldPosition), dFdy(worldPosition)) : worldNormal;
    n = length(n) > 0.0 ? normalize(n) : toEye;
    if (dot(n, toEye) < 0.0) n = -n;

    vec3 color;
    if (mode == kModeReflectionLines) {
        // Stripe floor(k acos(r . d) / pi) of the reflected view vector r against the fixed
        // direction d (world up): two tones, no lighting.
        const vec3 r = reflect(-toEye, n);
        const float angle = acos(clamp(r.y, -1.0, 1.0));
        const int stripe = int(floor(view.eye.w * angle / kPi));
        color = (stripe & 1) == 0 ? vec3(0.05) : vec3(0.95);
    } else if (mode == kModeMeanCurvature) {
        const float t = clamp(scalar / max(view.lightDir.w, 1e-30), -1.0, 1.0);
        color = diverging(t) * (0.6 + 0.4 * max(dot(n, normalize(view.lightDir.xyz)), 0.0));
    } else if (mode == kModeFaceType) {
        const vec3 fromTriangle = vec3(0.93, 0.55, 0.25), fromQuad = vec3(0.35, 0.55, 0.85), other = vec3(0.45, 0.75, 0.45);
        color = lit(origin == 0u ? fromTriangle : origin == 1u ? fromQuad : other, n, toEye, 0.15);
    } else if (mode == kModeTextured && (view.params.w & kHasUVs) != 0) {
        vec3 albedo;
        if ((view.params.w & kHasTexture) != 0) {
            albedo = texture(surfaceTexture, vec2(uv.x, 1.0 - uv.y)).rgb;
        } else {
            // A procedural checker of 8 x 8 squares over the unit square of UV space.
            const ivec2 cell = ivec2(floor(uv * 8.0));
            albedo = ((cell.x + cell.y) & 1) == 0 ? vec3(0.92, 0.92, 0.88) : vec3(0.85, 0.25, 0.20);
        }
        color = lit(albedo, n, toEye, 0.1);
    } else {
        color = lit(vec3(0.72, 0.74, 0.78), n, toEye, 0.35);
    }
    outColor = vec4(color, 1.0);
}
