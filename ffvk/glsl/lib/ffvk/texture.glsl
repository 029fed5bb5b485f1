// ffvk's shader library: texture application (GL 2.1 sections 3.8.13-3.8.16): the texel at the
// fragment's (s/q, t/q), combined with the primary color by the texture environment, before
// the color sum adds the secondary color (section 3.9). The CPU reference's copy is
// ffvk/src/reference/texture.rs.
#ifndef FFVK_TEXTURE_GLSL
#define FFVK_TEXTURE_GLSL

#include "ffvk/switches.glsl"

// The units' texels come from the caller: FFVK_TEXEL_2D(i, st) is unit i's 2D texture filtered
// at (s, t), FFVK_TEXEL_CUBE(i, str) its cube map in the direction (s, t, r), each an RGBA
// vec4 (texture() on the caller's samplers; i is a constant once the unit loops unroll).

// Values of a unit's env_mode (GL_TEXTURE_ENV_MODE), mirrored by TexEnvMode::code.
#define TEV_MODULATE 0u
#define TEV_REPLACE 1u
#define TEV_DECAL 2u
#define TEV_BLEND 3u
#define TEV_ADD 4u
#define TEV_COMBINE 5u

// GL_COMBINE (section 3.8.13, table 3.24), its state in Combine::code's bits: the functions
// (CombineFunc::code), sources (CombineSource::code), operands (RgbOperand::code, and one bit
// "one minus" per alpha operand) and scales; its GL_TEXTUREn sources in Combine::crossbar_code's
// 3 bits per argument (n + 1). The CPU reference's copy is src/reference/texture.rs (combine).
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
#define SOURCE_PRIMARY_COLOR 2u
#define SOURCE_PREVIOUS 3u

uint combine_bits(uint i) {
    int c = unit_constant(i, SPEC_COMBINE, SPEC_COMBINE_1, SPEC_COMBINE_2, SPEC_COMBINE_3);
    return c < 0 ? uber_value(FFVK_STATE.units[i].combine) : uint(c);
}
uint crossbar_bits(uint i) {
    int c = unit_constant(i, SPEC_CROSSBAR, SPEC_CROSSBAR_1, SPEC_CROSSBAR_2, SPEC_CROSSBAR_3);
    return c < 0 ? uber_value(FFVK_STATE.units[i].crossbar) : uint(c);
}
uint tex_env_mode(uint i) {
    int c = unit_constant(i, SPEC_TEX_ENV, SPEC_TEX_ENV_1, SPEC_TEX_ENV_2, SPEC_TEX_ENV_3);
    return c < 0 ? uber_value(FFVK_STATE.units[i].env_mode) : uint(c);
}

// The inputs of unit i: C_f the fragment's primary color (GL_PRIMARY_COLOR), C_p the previous
// unit's result (GL_PREVIOUS; C_f for unit 0), C_s every sampled unit's texel.
struct UnitInputs {
    vec4 C_f;
    vec4 C_p;
    vec4 C_s[MAX_TEXTURE_UNITS];
};

// One source's value for unit i; `unit` is the crossbar's n + 1 for GL_TEXTUREn, else 0.
vec4 combine_source(uint i, uint source, uint unit, UnitInputs v) {
    if (unit != 0u) return v.C_s[unit - 1u];
    if (source == SOURCE_TEXTURE) return v.C_s[i];
    if (source == SOURCE_CONSTANT) return FFVK_STATE.units[i].c_c;
    return source == SOURCE_PRIMARY_COLOR ? v.C_f : v.C_p;
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

vec4 combine(uint i, UnitInputs v) {
    uint bits = combine_bits(i);
    uint crossbar = crossbar_bits(i);
    vec3 rgb_args[3];
    vec3 alpha_args[3];
    FFVK_UNROLL for (uint k = 0u; k < 3u; k++) {
        uint rgb_unit = (crossbar >> (3u * k)) & 7u;
        uint alpha_unit = (crossbar >> (9u + 3u * k)) & 7u;
        vec4 c = combine_source(i, (bits >> (6u + 2u * k)) & 3u, rgb_unit, v);
        uint op = (bits >> (18u + 2u * k)) & 3u;
        vec3 rgb = op < 2u ? c.rgb : vec3(c.a);
        rgb_args[k] = (op & 1u) != 0u ? 1.0 - rgb : rgb;
        float a = combine_source(i, (bits >> (12u + 2u * k)) & 3u, alpha_unit, v).a;
        alpha_args[k] = vec3(((bits >> (24u + k)) & 1u) != 0u ? 1.0 - a : a);
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

// Values of unit_format (BaseFormat::code): which components the texture has (table 3.15).
#define FORMAT_RGBA 0u
#define FORMAT_RGB 1u
#define FORMAT_ALPHA 2u
#define FORMAT_LUMINANCE 3u
#define FORMAT_LUMINANCE_ALPHA 4u
#define FORMAT_INTENSITY 5u

// The texel (C_s, A_s) of a filtered RGBA8 texel c in base format f: luminance and intensity
// from R, alpha from A, as GL converts RGBA pixels (BaseFormat::texel).
vec4 format_texel(uint f, vec4 c) {
    if (f == FORMAT_RGB) return vec4(c.rgb, 1.0);
    if (f == FORMAT_ALPHA) return vec4(0.0, 0.0, 0.0, c.a);
    if (f == FORMAT_LUMINANCE) return vec4(c.rrr, 1.0);
    if (f == FORMAT_LUMINANCE_ALPHA) return vec4(c.rrr, c.a);
    if (f == FORMAT_INTENSITY) return c.rrrr;
    return c;  // FORMAT_RGBA
}

// Unit i's environment (table 3.22 for its texture's base format, or GL_COMBINE), clamped to
// [0, 1] as GL clamps each unit's result before the next unit (section 3.8.13). A format without
// color (ALPHA) keeps C_p, one without alpha (LUMINANCE, RGB) keeps A_p; INTENSITY blends and
// adds its alpha as its color. The CPU reference's copy is src/reference/texture.rs (unit_env).
vec4 texture_environment(uint i, UnitInputs v) {
    vec4 C_p = v.C_p;
    vec4 C_s = v.C_s[i];
    vec4 c_c = FFVK_STATE.units[i].c_c;
    uint f = unit_format(i);
    bool color = f != FORMAT_ALPHA;
    bool alpha = f == FORMAT_ALPHA || f == FORMAT_LUMINANCE_ALPHA || f == FORMAT_RGBA || f == FORMAT_INTENSITY;
    uint mode = tex_env_mode(i);
    vec3 C;
    float A;
    if (mode == TEV_COMBINE) return clamp(combine(i, v), 0.0, 1.0);
    if (mode == TEV_REPLACE) {
        C = color ? C_s.rgb : C_p.rgb;
        A = alpha ? C_s.a : C_p.a;
    } else if (mode == TEV_DECAL) {
        C = mix(C_p.rgb, C_s.rgb, C_s.a);
        A = C_p.a;
    } else if (mode == TEV_BLEND) {
        C = color ? C_p.rgb * (1.0 - C_s.rgb) + c_c.rgb * C_s.rgb : C_p.rgb;
        A = f == FORMAT_INTENSITY ? C_p.a * (1.0 - C_s.a) + c_c.a * C_s.a : (alpha ? C_p.a * C_s.a : C_p.a);
    } else if (mode == TEV_ADD) {
        C = color ? C_p.rgb + C_s.rgb : C_p.rgb;
        A = f == FORMAT_INTENSITY ? C_p.a + C_s.a : (alpha ? C_p.a * C_s.a : C_p.a);
    } else {  // TEV_MODULATE
        C = color ? C_p.rgb * C_s.rgb : C_p.rgb;
        A = alpha ? C_p.a * C_s.a : C_p.a;
    }
    return clamp(vec4(C, A), 0.0, 1.0);
}

// Section 3.3 with GL_COORD_REPLACE: a sprite's texture coordinates (s, t, 0, 1), t from the
// top (GL_UPPER_LEFT) or from the bottom (GL_LOWER_LEFT), for the units whose bit of
// SPEC_POINT_SPRITE says so (bit 1 unit 0, bits 3-5 units 1-3). ffvk's images have GL's top
// row first, as Vulkan's framebuffer does, so gl_PointCoord's t is GL_UPPER_LEFT's.
vec4 sprite_or(uint i, vec4 stq) {
    int replace = i == 0u ? 2 : (4 << i);
    if ((SPEC_POINT_SPRITE & 1) == 0 || (SPEC_POINT_SPRITE & replace) == 0) return stq;
    float t = (SPEC_POINT_SPRITE & 4) != 0 ? 1.0 - gl_PointCoord.y : gl_PointCoord.y;
    return vec4(gl_PointCoord.x, t, 0.0, 1.0);
}

// Unit i's texel at interpolated texture coordinates stq = (s, t, r, q), or a point sprite's:
// a 2D texture at (s/q, t/q); a cube map in the direction (s, t, r) (section 3.8.6: the face
// its largest component points at, q not read).
vec4 texel_at(uint i, vec4 stq) {
    vec4 c = sprite_or(i, stq);
    if (unit_is_cube(i)) return format_texel(unit_format(i), FFVK_TEXEL_CUBE(i, c.xyz));
    return format_texel(unit_format(i), FFVK_TEXEL_2D(i, c.xy / c.w));
}

// Section 3.8.16: the applied units in order, each on the one before's result, from the
// primary color C_f; stq holds each unit's interpolated coordinates.
vec4 textured_color(vec4 C_f, vec4 stq[MAX_TEXTURE_UNITS]) {
    UnitInputs v;
    v.C_f = C_f;
    v.C_p = C_f;
    FFVK_UNROLL for (uint i = 0u; i < MAX_TEXTURE_UNITS; i++) {
        v.C_s[i] = unit_sampled(i) ? texel_at(i, stq[i]) : vec4(0.0);
    }
    FFVK_UNROLL for (uint i = 0u; i < MAX_TEXTURE_UNITS; i++) {
        if (unit_applied(i)) v.C_p = texture_environment(i, v);
    }
    return v.C_p;
}

#endif
