// Texture application (GL 2.1 section 3.13) for the TEXTURE variants: the texel at the
// fragment's (s/q, t/q), combined with the primary color by the texture environment, before
// the color sum adds the secondary color (section 3.9). The CPU reference's copy is
// src/reference/texture.rs.
#ifndef FFVK_TEXTURE_GLSL
#define FFVK_TEXTURE_GLSL

#include "draw.glsl"

// The bound texture: GL_TEXTURE_2D's image and its parameters (a VkSampler made from
// glTexParameter's values). Set 1 is moved to the set after the State block's at pipeline
// creation.
layout(set = 1, binding = 0) uniform sampler2D texture_2d;

// Values of tex_env_mode (GL_TEXTURE_ENV_MODE), mirrored by TexEnvMode::code.
#define TEV_MODULATE 0u
#define TEV_REPLACE 1u
#define TEV_DECAL 2u
#define TEV_BLEND 3u
#define TEV_ADD 4u
#define TEV_COMBINE 5u

// GL_COMBINE (section 3.8.13, table 3.24), its state in Combine::code's bits: the functions
// (CombineFunc::code), sources (CombineSource::code), operands (RgbOperand::code, and one bit
// "one minus" per alpha operand) and scales. The CPU reference's copy is
// src/reference/texture.rs (combine).
#define COMBINE_REPLACE 0u
#define COMBINE_MODULATE 1u
#define COMBINE_ADD 2u
#define COMBINE_ADD_SIGNED 3u
#define COMBINE_INTERPOLATE 4u
#define COMBINE_SUBTRACT 5u
#define COMBINE_DOT3_RGB 6u
#define COMBINE_DOT3_RGBA 7u
#define SOURCE_TEXTURE 0u
#define SOURCE_CONSTANT 1u
// 2 (PRIMARY_COLOR) and 3 (PREVIOUS) are both the primary color for the one unit.

uint combine_bits() {
    return SPEC_COMBINE < 0 ? uber_value(state.combine) : uint(SPEC_COMBINE);
}

// One source's value: the texel, the environment color or the primary color.
vec4 combine_source(uint source, vec4 C_f, vec4 C_s) {
    return source == SOURCE_TEXTURE ? C_s : (source == SOURCE_CONSTANT ? state.c_c : C_f);
}

// The function f of arguments a0, a1, a2 (one component each, or three).
vec3 combine_function(uint f, vec3 a0, vec3 a1, vec3 a2) {
    if (f == COMBINE_REPLACE) return a0;
    if (f == COMBINE_ADD) return a0 + a1;
    if (f == COMBINE_ADD_SIGNED) return a0 + a1 - 0.5;
    if (f == COMBINE_INTERPOLATE) return a0 * a2 + a1 * (1.0 - a2);
    if (f == COMBINE_SUBTRACT) return a0 - a1;
    if (f == COMBINE_DOT3_RGB || f == COMBINE_DOT3_RGBA) return vec3(4.0 * dot(a0 - 0.5, a1 - 0.5));
    return a0 * a1;  // COMBINE_MODULATE
}

// A scale's 2-bit code: 1, 2 or 4.
float combine_scale(uint code) {
    return code == 2u ? 4.0 : (code == 1u ? 2.0 : 1.0);
}

vec4 combine(vec4 C_f, vec4 C_s) {
    uint bits = combine_bits();
    vec3 rgb_args[3];
    vec3 alpha_args[3];
    [[unroll]] for (uint i = 0u; i < 3u; i++) {
        vec4 v = combine_source((bits >> (6u + 2u * i)) & 3u, C_f, C_s);
        uint op = (bits >> (18u + 2u * i)) & 3u;
        vec3 rgb = op < 2u ? v.rgb : vec3(v.a);
        rgb_args[i] = (op & 1u) != 0u ? 1.0 - rgb : rgb;
        float a = combine_source((bits >> (12u + 2u * i)) & 3u, C_f, C_s).a;
        alpha_args[i] = vec3(((bits >> (24u + i)) & 1u) != 0u ? 1.0 - a : a);
    }
    uint f_rgb = bits & 7u;
    vec3 rgb = combine_function(f_rgb, rgb_args[0], rgb_args[1], rgb_args[2]);
    float alpha = f_rgb == COMBINE_DOT3_RGBA
        ? rgb.r
        : combine_function((bits >> 3u) & 7u, alpha_args[0], alpha_args[1], alpha_args[2]).r;
    rgb = clamp(rgb * combine_scale((bits >> 27u) & 3u), 0.0, 1.0);
    alpha = clamp(alpha * combine_scale((bits >> 29u) & 3u), 0.0, 1.0);
    return vec4(rgb, alpha);
}

uint tex_env_mode() {
    return SPEC_TEX_ENV < 0 ? uber_value(state.tex_env_mode) : uint(SPEC_TEX_ENV);
}

// Table 3.22 for an RGBA texture: fragment color C_f (the primary color), texel C_s,
// environment color c_c.
vec4 texture_environment(vec4 C_f, vec4 C_s) {
    vec3 c_c = state.c_c.rgb;
    uint mode = tex_env_mode();
    if (mode == TEV_COMBINE) return combine(C_f, C_s);
    if (mode == TEV_REPLACE) return C_s;
    if (mode == TEV_DECAL) return vec4(mix(C_f.rgb, C_s.rgb, C_s.a), C_f.a);
    if (mode == TEV_BLEND) return vec4(C_f.rgb * (1.0 - C_s.rgb) + c_c * C_s.rgb, C_f.a * C_s.a);
    if (mode == TEV_ADD) return vec4(clamp(C_f.rgb + C_s.rgb, 0.0, 1.0), C_f.a * C_s.a);
    return C_f * C_s;  // TEV_MODULATE
}

// Section 3.3 with GL_COORD_REPLACE: a sprite's texture coordinates (s, t, 0, 1), t from the
// top (GL_UPPER_LEFT) or from the bottom (GL_LOWER_LEFT). ffvk's images have GL's top row
// first, as Vulkan's framebuffer does, so gl_PointCoord's t is GL_UPPER_LEFT's.
vec4 sprite_or(vec4 stq) {
    if ((SPEC_POINT_SPRITE & 3) != 3) return stq;
    float t = (SPEC_POINT_SPRITE & 4) != 0 ? 1.0 - gl_PointCoord.y : gl_PointCoord.y;
    return vec4(gl_PointCoord.x, t, 0.0, 1.0);
}

// The texel at interpolated texture coordinates stq = (s, t, r, q), or a point sprite's.
vec4 texel_at(vec4 stq) {
    vec4 c = sprite_or(stq);
    return texture(texture_2d, c.xy / c.w);
}

#endif
