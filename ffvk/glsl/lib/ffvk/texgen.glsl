// ffvk's shader library: texture coordinate generation (GL 2.1 §2.11.4), in vertex stages:
// each coordinate whose GL_TEXTURE_GEN_S (_T, _R, _Q) is on is replaced, before the texture
// matrix, by the value its GL_TEXTURE_GEN_MODE makes of the vertex. Evaluated per vertex in every
// lighting mode, as GL does. The CPU reference's copy is ffvk/src/reference/texture.rs
// (generated_coords).
#ifndef FFVK_TEXGEN_GLSL
#define FFVK_TEXGEN_GLSL

#include "ffvk/switches.glsl"

// Values of each coordinate's 3 bits of a unit's SPEC_TEXGEN and texgen, S in bits 0-2, T 3-5,
// R 6-8, Q 9-11; mirrored by TexGenMode::code.
#define TEXGEN_OFF 0u
#define TEXGEN_OBJECT_LINEAR 1u
#define TEXGEN_EYE_LINEAR 2u
#define TEXGEN_SPHERE_MAP 3u
#define TEXGEN_REFLECTION_MAP 4u
#define TEXGEN_NORMAL_MAP 5u

uint texgen_modes(uint unit) {
    int c = unit_constant(unit, SPEC_TEXGEN, SPEC_TEXGEN_1, SPEC_TEXGEN_2, SPEC_TEXGEN_3);
    return c < 0 ? uber_value(FFVK_STATE.units[unit].texgen) : uint(c);
}

// Whether some coordinate of a sampled unit reads the eye-space normal (sphere, reflection,
// normal map).
bool texgen_reads_normal() {
    bool reads = false;
    FFVK_UNROLL for (uint unit = 0u; unit < MAX_TEXTURE_UNITS; unit++) {
        if (!unit_sampled(unit)) continue;
        uint modes = texgen_modes(unit);
        FFVK_UNROLL for (uint i = 0u; i < 4u; i++) reads = reads || ((modes >> (3u * i)) & 7u) >= TEXGEN_SPHERE_MAP;
    }
    return reads;
}

// Unit `unit`'s (s, t, r, q) = c with the generated coordinates replaced: p_o the vertex in
// object coordinates, p_e in eye coordinates, n_f the eye-space normal as lighting takes it
// (GL_NORMALIZE and GL_RESCALE_NORMAL applied). The plane of coordinate i is the unit's
// texgen_planes[i]: its object plane for GL_OBJECT_LINEAR, its eye plane (already p M⁻¹) for
// GL_EYE_LINEAR.
vec4 generated_coords(uint unit, vec4 c, vec4 p_o, vec4 p_e, vec3 n_f) {
    uint modes = texgen_modes(unit);
    if (modes == TEXGEN_OFF) return c;
    // u: the unit vector from the eye to the vertex; r: its reflection about n_f.
    vec3 u = normalize(p_e.xyz);
    vec3 r = u - 2.0 * n_f * dot(n_f, u);
    float m = 2.0 * sqrt(r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0));
    float sphere[4] = float[4](r.x / m + 0.5, r.y / m + 0.5, 0.0, 0.0);
    float reflected[4] = float[4](r.x, r.y, r.z, 0.0);
    float normal[4] = float[4](n_f.x, n_f.y, n_f.z, 0.0);
    vec4 g = c;
    FFVK_UNROLL for (uint i = 0u; i < 4u; i++) {
        uint mode = (modes >> (3u * i)) & 7u;
        vec4 plane = FFVK_STATE.units[unit].texgen_planes[i];
        if (mode == TEXGEN_OBJECT_LINEAR) g[i] = dot(plane, p_o);
        else if (mode == TEXGEN_EYE_LINEAR) g[i] = dot(plane, p_e);
        else if (mode == TEXGEN_SPHERE_MAP) g[i] = sphere[i];
        else if (mode == TEXGEN_REFLECTION_MAP) g[i] = reflected[i];
        else if (mode == TEXGEN_NORMAL_MAP) g[i] = normal[i];
    }
    return g;
}

// Section 2.11.4 for every sampled unit: its coordinates (`c`, the vertex's or the current
// ones), generated where the unit says, times its texture matrix. Units not sampled are
// left unwritten (their varyings are never read).
void unit_coords(vec4 c[MAX_TEXTURE_UNITS], vec4 p_o, vec4 p_e, vec3 n_f, out vec4 stq[MAX_TEXTURE_UNITS]) {
    FFVK_UNROLL for (uint i = 0u; i < MAX_TEXTURE_UNITS; i++) {
        if (unit_sampled(i)) stq[i] = FFVK_STATE.units[i].matrix * generated_coords(i, c[i], p_o, p_e, n_f);
    }
}

#endif
