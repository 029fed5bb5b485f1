// ffvk's shader library: the state's switches as the functions read them, each the
// specialization constant where the pipeline is specialized, else the state block's member
// through the caller's FFVK_HIDDEN_ZERO (see uber_value).
#ifndef FFVK_SWITCHES_GLSL
#define FFVK_SWITCHES_GLSL

#include "ffvk/state.glsl"
#include "ffvk/spec.glsl"

// Unit i's constant among four (i a constant once the unit loops unroll).
int unit_constant(uint i, int c0, int c1, int c2, int c3) {
    return i == 0u ? c0 : (i == 1u ? c1 : (i == 2u ? c2 : c3));
}
// Whether a TEXTURE build samples unit i, and whether it applies it.
bool unit_sampled(uint i) {
    return (SPEC_TEXTURE_UNITS & (1 << i)) != 0;
}
bool unit_applied(uint i) {
    return (SPEC_TEXTURE_UNITS & (16 << i)) != 0;
}
bool unit_is_cube(uint i) {
    return (SPEC_TEXTURE_UNITS & (256 << i)) != 0;
}
// A sampled unit's base internal format, FORMAT_* in texture.glsl (BaseFormat::code).
uint unit_format(uint i) {
    return uint(SPEC_TEXTURE_UNITS >> (12u + 3u * i)) & 7u;
}

// A switch of the uber-shader, read from the uniform block. lavapipe 22.3 compiles a shader
// variant for every draw whose uniforms changed when an if or a loop bound depends on uniform
// values alone (BENCHMARKS.md, "Many draws"); OR-ing in a zero it cannot prove zero keeps the
// uber-shader's switches and light count out of its sight, with the same value.
uint uber_value(uint value) {
    return value | FFVK_HIDDEN_ZERO;
}

// The state as the shader sees it: the specialization constant when set, else the uniform.
// (The light count is chosen the same way, in light_equation: SPEC_LIGHT_COUNT < 0 reads
// FFVK_STATE.light_count.)
bool lighting_enabled() {
    return SPEC_LIGHTING < 0 ? uber_value(FFVK_STATE.lighting) != 0u : SPEC_LIGHTING != 0;
}
bool local_viewer() {
    return SPEC_LOCAL_VIEWER < 0 ? uber_value(FFVK_STATE.v_bs) != 0u : SPEC_LOCAL_VIEWER != 0;
}
bool two_side() {
    return SPEC_TWO_SIDE < 0 ? uber_value(FFVK_STATE.t_bs) != 0u : SPEC_TWO_SIDE != 0;
}
bool separate_specular() {
    return SPEC_SEPARATE_SPECULAR < 0
        ? uber_value(FFVK_STATE.separate_specular) != 0u
        : SPEC_SEPARATE_SPECULAR != 0;
}
bool color_material_enabled() {
    return SPEC_COLOR_MATERIAL < 0 ? uber_value(FFVK_STATE.color_material) != 0u : SPEC_COLOR_MATERIAL != 0;
}
// Whether light i may be positional or a spot: its own bit where the pipeline is specialized
// (i is a constant once the driver unrolls the light loop), else only the promise 0 answers
// "no" for all lights.
bool may_be_local(uint i) {
    return SPEC_DIRECTIONAL_LIGHTS >= 0 ? ((uint(SPEC_DIRECTIONAL_LIGHTS) >> i) & 1u) == 0u : SPEC_ANY_LOCAL_LIGHT != 0;
}
bool may_be_spot(uint i) {
    return SPEC_SPOT_LIGHTS >= 0 ? ((uint(SPEC_SPOT_LIGHTS) >> i) & 1u) != 0u : SPEC_ANY_SPOT_LIGHT != 0;
}
bool may_be_soft_spot() {
    return SPEC_ANY_SOFT_SPOT != 0;
}
bool may_be_gltf_falloff() {
    return SPEC_ANY_GLTF_FALLOFF != 0;
}
// Light i is known directional and every vertex finite: VP_pli and ĥ_i are its derived FFVK_STATE.
bool directional_at_finite_vertices(uint i) {
    return SPEC_FINITE_VERTICES == 1 && !may_be_local(i);
}
bool color_sum_enabled() {
    return SPEC_COLOR_SUM < 0 ? uber_value(FFVK_STATE.color_sum) != 0u : SPEC_COLOR_SUM != 0;
}


uint specular_model() {
    return SPEC_SPECULAR_MODEL < 0 ? uber_value(FFVK_STATE.specular_model) : uint(SPEC_SPECULAR_MODEL);
}

#endif
