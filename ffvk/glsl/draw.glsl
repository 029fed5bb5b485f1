// GL lighting state as the shaders see it: the State uniform block in std140 and the draw's
// materials, mirrored by src/gpu/layout.rs (a test checks the offsets in the compiled SPIR-V
// against the Rust structs).
#ifndef FFVK_DRAW_GLSL
#define FFVK_DRAW_GLSL

#define MAX_LIGHTS 16

// Table 2.10, one face.
struct Material {
    vec4 a_cm;   // AMBIENT
    vec4 d_cm;   // DIFFUSE
    vec4 s_cm;   // SPECULAR
    vec4 e_cm;   // EMISSION
    float s_rm;  // SHININESS
};

// Table 2.10, one light; positions and directions already in eye space (glLight time).
struct Light {
    vec4 a_cli;       // AMBIENT
    vec4 d_cli;       // DIFFUSE
    vec4 s_cli;       // SPECULAR
    vec4 P_pli;       // POSITION
    vec3 s_dli;       // SPOT_DIRECTION
    float s_rli;      // SPOT_EXPONENT
    float c_rli;      // SPOT_CUTOFF, degrees
    float cos_c_rli;  // cos(c_rli), computed on the host in double precision
    float k0;         // CONSTANT_ATTENUATION
    float k1;         // LINEAR_ATTENUATION
    float k2;         // QUADRATIC_ATTENUATION
    uint spot_edge;   // EDGE_* (ffvk's extension; GL's is EDGE_GL_EXPONENT)
    float cos_inner;  // cos of a soft edge's inner angle, computed on the host
    uint falloff;     // FALLOFF_* (ffvk's extension; GL's is FALLOFF_GL_K012)
    float range;      // glTF's range, 0 for none
    // GL's derived state of a directional light (w = 0), computed on the host when the state
    // changes: the unit vector toward it (VP_pli of every finite vertex) and the unit halfway
    // vector of that and the infinite viewer's (0, 0, 1) (GLSL 1.20's halfVector). Zero for a
    // positional light.
    vec3 VP_hat_inf;
    vec3 h_hat_inf;
};

// Values of Light.spot_edge, Light.falloff and specular_model: GL's is 0 in each.
#define EDGE_GL_EXPONENT 0u
#define EDGE_LINEAR_INNER_OUTER 1u
#define EDGE_SMOOTHSTEP_INNER_OUTER 2u
#define FALLOFF_GL_K012 0u
#define FALLOFF_GLTF_INVERSE_SQUARE 1u
#define SPECULAR_BLINN_HALFWAY 0u
#define SPECULAR_PHONG_REFLECT 1u

// One texture unit's state (GL_TEXTUREi), GpuTextureUnit in src/gpu/layout.rs: read by the
// TEXTURE builds for the units SPEC_TEXTURE_UNITS names.
#define MAX_TEXTURE_UNITS 4
struct TextureUnitState {
    mat4 matrix;             // GL_TEXTURE matrix
    vec4 c_c;                // TEXTURE_ENV_COLOR
    vec4 texgen_planes[4];   // S, T, R, Q: OBJECT_PLANE or EYE_PLANE (p M^-1), as the mode reads
    uint env_mode;           // TEXTURE_ENV_MODE, TEV_* in texture.glsl
    uint combine;            // GL_COMBINE's state (Combine::code), read under TEXTURE_ENV_MODE COMBINE
    uint crossbar;           // GL_COMBINE's GL_TEXTUREn sources (Combine::crossbar_code)
    uint texgen;             // TEXTURE_GEN_S..Q with their modes, 3 bits each (texgen.glsl)
};

// Values of color_material_mode.
#define CM_EMISSION 0u
#define CM_AMBIENT 1u
#define CM_DIFFUSE 2u
#define CM_SPECULAR 3u
#define CM_AMBIENT_AND_DIFFUSE 4u

// GL's lighting state but the draw's own values: staged when it changes (a new block only when
// a draw's state differs from the draw before), bound at a dynamic offset.
layout(std140, set = 0, binding = 0) uniform State {
    mat4 projection;      // GL projection, premultiplied by GL-to-Vulkan clip conversion
    vec4 a_cs;            // LIGHT_MODEL_AMBIENT
    uint light_count;     // enabled lights, packed in index order
    uint lighting;        // LIGHTING enabled
    uint v_bs;            // LIGHT_MODEL_LOCAL_VIEWER
    uint t_bs;            // LIGHT_MODEL_TWO_SIDE
    uint separate_specular;  // LIGHT_MODEL_COLOR_CONTROL == SEPARATE_SPECULAR_COLOR
    uint color_material;     // COLOR_MATERIAL enabled
    uint color_material_front;  // ColorMaterial face includes FRONT
    uint color_material_back;   // ColorMaterial face includes BACK
    uint color_material_mode;   // CM_*
    uint normalize;       // NORMALIZE enabled
    uint specular_model;  // SPECULAR_* (ffvk's extension)
    uint color_sum;       // COLOR_SUM
    uint alpha_func;      // ALPHA_TEST_FUNC, 0 NEVER .. 7 ALWAYS (7 while the test is off)
    float alpha_ref;      // ALPHA_TEST_REF, in [0, 1]
    uint pad_0;
    uint pad_1;
    vec4 fog_color;       // FOG_COLOR
    float fog_start;      // FOG_START
    float fog_end;        // FOG_END
    float fog_density;    // FOG_DENSITY
    float fog_scale;      // 1 / (FOG_END - FOG_START), 0 where they are equal
    uint fog_mode;        // 0 off, 1 LINEAR, 2 EXP, 3 EXP2
    uint fog_source;      // 1 FOG_COORD, 0 FRAGMENT_DEPTH
    uint fog_per_vertex;  // 1 for FOG_HINT FASTEST
    uint clip_mask;       // the enabled CLIP_PLANEi, a bit each
    vec4 clip_planes[6];  // CLIP_PLANEi in eye space (glClipPlane's p M^-1)
    TextureUnitState units[MAX_TEXTURE_UNITS];
    Light lights[MAX_LIGHTS];
} state;

// The draw's own materials (its DrawRecord, src/gpu/layout.rs): each stage's main sets them
// before lighting, from the record's instance attributes (vertex stages, record.glsl) or from
// the record as a uniform block (the fragment stage of the fragment mode). Per-draw values are
// vertex data, not uniforms, in the vertex stages: a frame of draws that change only these
// binds nothing between them in the vertex and flat modes.
Material draw_front;
Material draw_back;

// Specialization constants, mirrored by src/gpu/layout.rs (`SpecConstant`; a test reads the
// SpecId decorations from the SPIR-V). The default, -1, means "read the uniform": the
// uber-shader. A pipeline specialized for one state sets them to that state's values (0 or 1,
// or the light count), so the driver folds the branches and unrolls the light loop.
// SPEC_ANY_LOCAL_LIGHT and SPEC_ANY_SPOT_LIGHT are promises: 0 says no enabled light is
// positional (w != 0) or a spot (cutoff != 180), so attenuation or the cone is never needed.
layout(constant_id = 0) const int SPEC_LIGHT_COUNT = -1;        // 0..=MAX_LIGHTS
layout(constant_id = 1) const int SPEC_LIGHTING = -1;           // LIGHTING
layout(constant_id = 2) const int SPEC_LOCAL_VIEWER = -1;       // LIGHT_MODEL_LOCAL_VIEWER
layout(constant_id = 3) const int SPEC_TWO_SIDE = -1;           // LIGHT_MODEL_TWO_SIDE
layout(constant_id = 4) const int SPEC_SEPARATE_SPECULAR = -1;  // LIGHT_MODEL_COLOR_CONTROL
layout(constant_id = 5) const int SPEC_COLOR_MATERIAL = -1;     // COLOR_MATERIAL
layout(constant_id = 6) const int SPEC_ANY_LOCAL_LIGHT = -1;    // some light has w != 0
layout(constant_id = 7) const int SPEC_ANY_SPOT_LIGHT = -1;     // some light has cutoff != 180
layout(constant_id = 8) const int SPEC_TEX_ENV = -1;            // TEXTURE_ENV_MODE, TEV_*
// ffvk's extensions: the specular term, and promises (0) that every light has GL's spot edge
// and GL's attenuation, so that GL's own path carries none of the other variants.
layout(constant_id = 9) const int SPEC_SPECULAR_MODEL = -1;     // SPECULAR_*
layout(constant_id = 10) const int SPEC_ANY_SOFT_SPOT = -1;     // some light has a soft edge
layout(constant_id = 11) const int SPEC_ANY_GLTF_FALLOFF = -1;  // some light has glTF's falloff
// A promise (1) that every vertex is finite (w != 0: an affine modelview), so that VP_pli and
// the infinite viewer's ĥ_i are the derived state of each directional light.
layout(constant_id = 12) const int SPEC_FINITE_VERTICES = -1;
// 1 in pipelines drawing points (their vertex stage writes the point size), 0 in others; the
// uber-shader (-1) writes it always.
layout(constant_id = 13) const int SPEC_POINTS = -1;
// The point size (GL's glPointSize), set in every pipeline.
layout(constant_id = 14) const float SPEC_POINT_SIZE = 1.0;
// Each enabled light's own kind, a bit per light in packed order (as Mesa's fixed-function key
// has it): directional (w = 0) and spot (cutoff != 180). -1: unknown (the uber-shader), every
// light may be either.
layout(constant_id = 15) const int SPEC_DIRECTIONAL_LIGHTS = -1;
layout(constant_id = 16) const int SPEC_SPOT_LIGHTS = -1;
// The vertex layout's GL conversions (record.glsl, gl_signed_normalized): a byte per attribute,
// the normal's in bits 0-7, the color's in bits 8-15; 0: none. Set in every pipeline.
layout(constant_id = 17) const int SPEC_GL_SNORM = 0;
// vec4s from one draw record to the next in the record buffer (deferred.frag): the ring's
// stride, set in every pipeline.
layout(constant_id = 18) const int SPEC_RECORD_VEC4S = 22;
// COLOR_SUM with lighting off (lit draws always sum the separate specular color).
layout(constant_id = 19) const int SPEC_COLOR_SUM = -1;
// The alpha test's function, 0 NEVER .. 7 ALWAYS (ALWAYS while the test is off).
layout(constant_id = 20) const int SPEC_ALPHA_FUNC = -1;
// The color attachment's alpha bits when UNORM (the alpha test compares at that fixed-point
// precision, GL 2.1 section 4.1.4), 0 for a float compare; set in every pipeline.
layout(constant_id = 21) const int SPEC_ALPHA_BITS = 0;
// Fog (section 3.10): 0 off, 1 LINEAR, 2 EXP, 3 EXP2; its source (1 FOG_COORD, 0 the eye-space
// depth); 1 where f is computed per vertex (FOG_HINT FASTEST).
layout(constant_id = 22) const int SPEC_FOG_MODE = -1;
layout(constant_id = 23) const int SPEC_FOG_SOURCE = -1;
layout(constant_id = 24) const int SPEC_FOG_PER_VERTEX = -1;
// The enabled user clip planes, a bit each (the `_clipped` builds write gl_ClipDistance).
layout(constant_id = 25) const int SPEC_CLIP_PLANES = -1;
// Points (section 3.3), the pipeline's own constants (set for points pipelines, "off" in the
// others): whether the size falls with the distance, GL_POINT_DISTANCE_ATTENUATION's (a, b, c),
// GL_POINT_SIZE_MIN and _MAX, and the sprite bits (1 GL_POINT_SPRITE, 2 GL_COORD_REPLACE,
// 4 GL_POINT_SPRITE_COORD_ORIGIN GL_LOWER_LEFT).
layout(constant_id = 26) const int SPEC_POINT_ATTENUATION = 0;
layout(constant_id = 27) const float SPEC_POINT_ATTENUATION_A = 1.0;
layout(constant_id = 28) const float SPEC_POINT_ATTENUATION_B = 0.0;
layout(constant_id = 29) const float SPEC_POINT_ATTENUATION_C = 0.0;
layout(constant_id = 30) const float SPEC_POINT_SIZE_MIN = 0.0;
layout(constant_id = 31) const float SPEC_POINT_SIZE_MAX = 3.40282347e38;  // FLT_MAX
layout(constant_id = 32) const int SPEC_POINT_SPRITE = 0;
// Texture coordinate generation: each coordinate's mode, 3 bits from S (texgen.glsl).
layout(constant_id = 33) const int SPEC_TEXGEN = -1;
// GL_COMBINE's functions, sources, operands and scales (texture.glsl, Combine::code).
layout(constant_id = 34) const int SPEC_COMBINE = -1;
// The texture units of a TEXTURE build: bits 0-3 the units sampled (enabled, with a complete
// texture), bits 4-7 the units applied (sampled, and not reading a missing unit's texel through
// GL_TEXTUREn), bits 8-11 the sampled units that sample their cube map, and from bit 12 each
// sampled unit's base internal format in 3 bits. The pipeline's own, set in every pipeline (the
// uber-shader's too).
layout(constant_id = 35) const int SPEC_TEXTURE_UNITS = 0x11;
// GL_COMBINE's GL_TEXTUREn sources (Combine::crossbar_code), unit 0's; then units 1-3's
// TEXTURE_ENV_MODE, texgen, GL_COMBINE and crossbar, as SPEC_TEX_ENV, SPEC_TEXGEN,
// SPEC_COMBINE and SPEC_CROSSBAR are unit 0's.
layout(constant_id = 36) const int SPEC_CROSSBAR = -1;
layout(constant_id = 37) const int SPEC_TEX_ENV_1 = -1;
layout(constant_id = 38) const int SPEC_TEX_ENV_2 = -1;
layout(constant_id = 39) const int SPEC_TEX_ENV_3 = -1;
layout(constant_id = 40) const int SPEC_TEXGEN_1 = -1;
layout(constant_id = 41) const int SPEC_TEXGEN_2 = -1;
layout(constant_id = 42) const int SPEC_TEXGEN_3 = -1;
layout(constant_id = 43) const int SPEC_COMBINE_1 = -1;
layout(constant_id = 44) const int SPEC_COMBINE_2 = -1;
layout(constant_id = 45) const int SPEC_COMBINE_3 = -1;
layout(constant_id = 46) const int SPEC_CROSSBAR_1 = -1;
layout(constant_id = 47) const int SPEC_CROSSBAR_2 = -1;
layout(constant_id = 48) const int SPEC_CROSSBAR_3 = -1;

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
    return value | HIDDEN_ZERO;
}

// The state as the shader sees it: the specialization constant when set, else the uniform.
// (The light count is chosen the same way, in light_equation: SPEC_LIGHT_COUNT < 0 reads
// state.light_count.)
bool lighting_enabled() {
    return SPEC_LIGHTING < 0 ? uber_value(state.lighting) != 0u : SPEC_LIGHTING != 0;
}
bool local_viewer() {
    return SPEC_LOCAL_VIEWER < 0 ? uber_value(state.v_bs) != 0u : SPEC_LOCAL_VIEWER != 0;
}
bool two_side() {
    return SPEC_TWO_SIDE < 0 ? uber_value(state.t_bs) != 0u : SPEC_TWO_SIDE != 0;
}
bool separate_specular() {
    return SPEC_SEPARATE_SPECULAR < 0
        ? uber_value(state.separate_specular) != 0u
        : SPEC_SEPARATE_SPECULAR != 0;
}
bool color_material_enabled() {
    return SPEC_COLOR_MATERIAL < 0 ? uber_value(state.color_material) != 0u : SPEC_COLOR_MATERIAL != 0;
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
// Light i is known directional and every vertex finite: VP_pli and ĥ_i are its derived state.
bool directional_at_finite_vertices(uint i) {
    return SPEC_FINITE_VERTICES == 1 && !may_be_local(i);
}
bool color_sum_enabled() {
    return SPEC_COLOR_SUM < 0 ? uber_value(state.color_sum) != 0u : SPEC_COLOR_SUM != 0;
}

// Section 4.1.4: whether a fragment of alpha a passes the alpha test, the alpha and the
// reference compared as fixed-point values at the color buffer's precision. The comparisons
// are selected, not branched on: the uber-shader's function is a uniform value.
bool alpha_passes(float a) {
    if (SPEC_ALPHA_FUNC == 7) return true;
    uint func = SPEC_ALPHA_FUNC < 0 ? uber_value(state.alpha_func) : uint(SPEC_ALPHA_FUNC);
    float scale = exp2(float(SPEC_ALPHA_BITS)) - 1.0;
    float v = SPEC_ALPHA_BITS > 0 ? floor(clamp(a, 0.0, 1.0) * scale + 0.5) : a;
    float r = SPEC_ALPHA_BITS > 0 ? floor(state.alpha_ref * scale + 0.5) : state.alpha_ref;
    bool passes[8] = bool[8](false, v < r, v == r, v <= r, v > r, v != r, v >= r, true);
    return passes[min(func, 7u)];
}

uint fog_mode() {
    return SPEC_FOG_MODE < 0 ? uber_value(state.fog_mode) : uint(SPEC_FOG_MODE);
}
bool fog_per_vertex() {
    return SPEC_FOG_PER_VERTEX < 0 ? uber_value(state.fog_per_vertex) != 0u : SPEC_FOG_PER_VERTEX != 0;
}

// Section 3.10: the fog's distance c of a vertex at eye position V with fog coordinate
// `coord`: the coordinate as it is (FOG_COORD: no absolute value, as the spec says), or
// |z_e| (FRAGMENT_DEPTH: the approximation of the eye-space distance GL 2.1 allows).
float fog_distance(vec4 V, float coord) {
    bool from_coord = SPEC_FOG_SOURCE < 0 ? uber_value(state.fog_source) != 0u : SPEC_FOG_SOURCE != 0;
    return from_coord ? coord : abs(V.z);
}

// The fog factor f for distance c, clamped to [0, 1]; the three modes selected, not branched
// on (the uber-shader's mode is a uniform value).
float fog_factor(float c) {
    float linear = state.fog_scale == 0.0 ? 1.0 : (state.fog_end - c) * state.fog_scale;
    float dc = state.fog_density * c;
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
    vec4 fogged = vec4(mix(state.fog_color.rgb, color.rgb, f), color.a);
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
    uint mask = SPEC_CLIP_PLANES < 0 ? uber_value(state.clip_mask) : uint(SPEC_CLIP_PLANES);
    bool on = ((mask >> i) & 1u) != 0u;
    return on ? dot(state.clip_planes[i], V) : 1.0;
}

uint specular_model() {
    return SPEC_SPECULAR_MODEL < 0 ? uber_value(state.specular_model) : uint(SPEC_SPECULAR_MODEL);
}

// The material of one face, with COLOR_MATERIAL applied for the current color c.
Material face_material(bool back_face, vec4 c) {
    Material m = back_face ? draw_back : draw_front;
    if (color_material_enabled()) {
        // Selects rather than ifs on the face and mode, which are uniform values: lavapipe
        // compiles a shader variant per draw for an if on uniform values alone (see
        // light_term). all() and any() do not short-circuit, and mix() with a bvec4 is an
        // OpSelect in the SPIR-V (glslang turns ?: into one only between plain variables).
        bool tracks = back_face ? state.color_material_back != 0u : state.color_material_front != 0u;
        uint mode = state.color_material_mode;
        bool ambient = any(bvec2(mode == CM_AMBIENT, mode == CM_AMBIENT_AND_DIFFUSE));
        bool diffuse = any(bvec2(mode == CM_DIFFUSE, mode == CM_AMBIENT_AND_DIFFUSE));
        m.e_cm = mix(m.e_cm, c, bvec4(all(bvec2(tracks, mode == CM_EMISSION))));
        m.a_cm = mix(m.a_cm, c, bvec4(all(bvec2(tracks, ambient))));
        m.d_cm = mix(m.d_cm, c, bvec4(all(bvec2(tracks, diffuse))));
        m.s_cm = mix(m.s_cm, c, bvec4(all(bvec2(tracks, mode == CM_SPECULAR))));
    }
    return m;
}

#endif
