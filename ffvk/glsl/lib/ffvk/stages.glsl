// ffvk's shader library: the stages around lighting, GL 2.1's alpha test (section 4.1.4), fog
// (section 3.10), the point size (section 3.3) and the user clip planes (section 2.12).
#ifndef FFVK_STAGES_GLSL
#define FFVK_STAGES_GLSL

#include "ffvk/switches.glsl"

// Section 4.1.4: whether a fragment of alpha a passes the alpha test, the alpha and the
// reference compared as fixed-point values at the color buffer's precision. The comparisons
// are selected, not branched on: the uber-shader's function is a uniform value.
bool alpha_passes(float a) {
    if (SPEC_ALPHA_FUNC == 7) return true;
    uint func = SPEC_ALPHA_FUNC < 0 ? uber_value(FFVK_STATE.alpha_func) : uint(SPEC_ALPHA_FUNC);
    float scale = exp2(float(SPEC_ALPHA_BITS)) - 1.0;
    float v = SPEC_ALPHA_BITS > 0 ? floor(clamp(a, 0.0, 1.0) * scale + 0.5) : a;
    float r = SPEC_ALPHA_BITS > 0 ? floor(FFVK_STATE.alpha_ref * scale + 0.5) : FFVK_STATE.alpha_ref;
    bool passes[8] = bool[8](false, v < r, v == r, v <= r, v > r, v != r, v >= r, true);
    return passes[min(func, 7u)];
}

uint fog_mode() {
    return SPEC_FOG_MODE < 0 ? uber_value(FFVK_STATE.fog_mode) : uint(SPEC_FOG_MODE);
}
bool fog_per_vertex() {
    return SPEC_FOG_PER_VERTEX < 0 ? uber_value(FFVK_STATE.fog_per_vertex) != 0u : SPEC_FOG_PER_VERTEX != 0;
}

// Section 3.10: the fog's distance c of a vertex at eye position V with fog coordinate
// `coord`: the coordinate as it is (FOG_COORD: no absolute value, as the spec says), or
// |z_e| (FRAGMENT_DEPTH: the approximation of the eye-space distance GL 2.1 allows).
float fog_distance(vec4 V, float coord) {
    bool from_coord = SPEC_FOG_SOURCE < 0 ? uber_value(FFVK_STATE.fog_source) != 0u : SPEC_FOG_SOURCE != 0;
    return from_coord ? coord : abs(V.z);
}

// The fog factor f for distance c, clamped to [0, 1]; the three modes selected, not branched
// on (the uber-shader's mode is a uniform value).
float fog_factor(float c) {
    float linear = FFVK_STATE.fog_scale == 0.0 ? 1.0 : (FFVK_STATE.fog_end - c) * FFVK_STATE.fog_scale;
    float dc = FFVK_STATE.fog_density * c;
    uint mode = fog_mode();
    float f = mode == 1u ? linear : (mode == 2u ? exp(-dc) : exp(-dc * dc));
    return clamp(f, 0.0, 1.0);
}

// What the vertex stage passes for fog: f itself (per vertex) or c (f per fragment).
float fog_varying(vec4 V, float coord) {
    float c = fog_distance(V, coord);
    return fog_per_vertex() ? fog_factor(c) : c;
}

// Section 3.10 on the color after texturing and the color sum: rgb = f rgb + (1 - f) fog rgb,
// alpha untouched. `fog` is the vertex stage's fog_varying, interpolated.
vec4 apply_fog(vec4 color, float fog) {
    if (SPEC_FOG_MODE == 0) return color;
    float f = fog_per_vertex() ? clamp(fog, 0.0, 1.0) : fog_factor(fog);
    vec4 fogged = vec4(mix(FFVK_STATE.fog_color.rgb, color.rgb, f), color.a);
    bool off = fog_mode() == 0u;
    return mix(fogged, color, bvec4(off));
}

// Section 3.3: the width of a point at eye position V: GL_POINT_SIZE times
// sqrt(1 / (a + b d + c d^2)) at the eye distance d = |V.xyz| where the size is attenuated,
// clamped to [GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX] (the maximum first: a minimum above it
// wins), then, but for sprites, rounded to the nearest integer and at least 1 (3.3.1).
float point_width(vec4 V) {
    float size = SPEC_POINT_SIZE;
    if (SPEC_POINT_ATTENUATION != 0) {
        float d = length(V.xyz);
        float a = SPEC_POINT_ATTENUATION_A + SPEC_POINT_ATTENUATION_B * d + SPEC_POINT_ATTENUATION_C * d * d;
        size *= sqrt(1.0 / a);
    }
    size = max(min(size, SPEC_POINT_SIZE_MAX), SPEC_POINT_SIZE_MIN);
    return (SPEC_POINT_SPRITE & 1) != 0 ? size : max(floor(size + 0.5), 1.0);
}

// Section 2.12: the distance of eye position V to user clip plane i, kept where it is >= 0;
// 1 (kept) for a disabled plane.
float clip_distance(uint i, vec4 V) {
    uint mask = SPEC_CLIP_PLANES < 0 ? uber_value(FFVK_STATE.clip_mask) : uint(SPEC_CLIP_PLANES);
    bool on = ((mask >> i) & 1u) != 0u;
    return on ? dot(FFVK_STATE.clip_planes[i], V) : 1.0;
}



#endif
