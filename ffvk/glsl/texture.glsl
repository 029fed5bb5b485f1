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

uint tex_env_mode() {
    return SPEC_TEX_ENV < 0 ? uber_value(state.tex_env_mode) : uint(SPEC_TEX_ENV);
}

// Table 3.22 for an RGBA texture: fragment color C_f (the primary color), texel C_s,
// environment color c_c.
vec4 texture_environment(vec4 C_f, vec4 C_s) {
    vec3 c_c = state.c_c.rgb;
    uint mode = tex_env_mode();
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
