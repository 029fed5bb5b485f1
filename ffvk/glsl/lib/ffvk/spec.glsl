// ffvk's shader library: the specialization constants that switch the library's functions.
// Each is declared at FFVK_SPEC_BASE + its ID (FFVK_SPEC_BASE is 0 unless the caller defines
// it first), so that a caller's own IDs never collide with the library's: IDs FFVK_SPEC_BASE
// to FFVK_SPEC_BASE + FFVK_SPEC_COUNT - 1 are the library's. Where the caller defines
// FFVK_SPEC_AS_DEFINES instead, the caller defines each constant's name as its value
// (`#define SPEC_LIGHT_COUNT 2`; all of them: `ffvk::shaders::spec_defines` writes the lines
// for a state), and nothing is declared here: for a compiler or a target without
// specialization constants or token pasting (GLSL ES). A value left out is an undeclared
// identifier, named by the compiler where the library first reads it.
#ifndef FFVK_SPEC_GLSL
#define FFVK_SPEC_GLSL

#ifndef FFVK_SPEC_BASE
#define FFVK_SPEC_BASE 0
#endif
#define FFVK_SPEC_COUNT 49
#if defined(FFVK_GLSL_ES) && !defined(FFVK_SPEC_AS_DEFINES)
#error "GLSL ES has no specialization constants: define the switches first (ffvk::shaders::spec_defines)"
#endif
// Each use is a whole declaration, its semicolon included, so that it can expand to nothing.
#ifdef FFVK_SPEC_AS_DEFINES
#define FFVK_SPEC_CONST(id, type, name, value)
#else
#define FFVK_SPEC_CONST(id, type, name, value) layout(constant_id = FFVK_SPEC_BASE + id) const type name = value;
#endif

// Specialization constants, mirrored by src/gpu/layout.rs (`SpecConstant`; a test reads the
// SpecId decorations from the SPIR-V). The default, -1, means "read the uniform": the
// uber-shader. A pipeline specialized for one state sets them to that state's values (0 or 1,
// or the light count), so the driver folds the branches and unrolls the light loop.
// SPEC_ANY_LOCAL_LIGHT and SPEC_ANY_SPOT_LIGHT are promises: 0 says no enabled light is
// positional (w != 0) or a spot (cutoff != 180), so attenuation or the cone is never needed.
FFVK_SPEC_CONST(0, int, SPEC_LIGHT_COUNT, -1)        // 0..=MAX_LIGHTS
FFVK_SPEC_CONST(1, int, SPEC_LIGHTING, -1)           // LIGHTING
FFVK_SPEC_CONST(2, int, SPEC_LOCAL_VIEWER, -1)       // LIGHT_MODEL_LOCAL_VIEWER
FFVK_SPEC_CONST(3, int, SPEC_TWO_SIDE, -1)           // LIGHT_MODEL_TWO_SIDE
FFVK_SPEC_CONST(4, int, SPEC_SEPARATE_SPECULAR, -1)  // LIGHT_MODEL_COLOR_CONTROL
FFVK_SPEC_CONST(5, int, SPEC_COLOR_MATERIAL, -1)     // COLOR_MATERIAL
FFVK_SPEC_CONST(6, int, SPEC_ANY_LOCAL_LIGHT, -1)    // some light has w != 0
FFVK_SPEC_CONST(7, int, SPEC_ANY_SPOT_LIGHT, -1)     // some light has cutoff != 180
FFVK_SPEC_CONST(8, int, SPEC_TEX_ENV, -1)            // TEXTURE_ENV_MODE, TEV_*
// ffvk's extensions: the specular term, and promises (0) that every light has GL's spot edge
// and GL's attenuation, so that GL's own path carries none of the other variants.
FFVK_SPEC_CONST(9, int, SPEC_SPECULAR_MODEL, -1)     // SPECULAR_*
FFVK_SPEC_CONST(10, int, SPEC_ANY_SOFT_SPOT, -1)     // some light has a soft edge
FFVK_SPEC_CONST(11, int, SPEC_ANY_GLTF_FALLOFF, -1)  // some light has glTF's falloff
// A promise (1) that every vertex is finite (w != 0: an affine modelview), so that VP_pli and
// the infinite viewer's ĥ_i are the derived state of each directional light.
FFVK_SPEC_CONST(12, int, SPEC_FINITE_VERTICES, -1)
// 1 in pipelines drawing points (their vertex stage writes the point size), 0 in others; the
// uber-shader (-1) writes it always.
FFVK_SPEC_CONST(13, int, SPEC_POINTS, -1)
// The point size (GL's glPointSize), set in every pipeline.
FFVK_SPEC_CONST(14, float, SPEC_POINT_SIZE, 1.0)
// Each enabled light's own kind, a bit per light in packed order (as Mesa's fixed-function key
// has it): directional (w = 0) and spot (cutoff != 180). -1: unknown (the uber-shader), every
// light may be either.
FFVK_SPEC_CONST(15, int, SPEC_DIRECTIONAL_LIGHTS, -1)
FFVK_SPEC_CONST(16, int, SPEC_SPOT_LIGHTS, -1)
// The vertex layout's GL conversions (record.glsl, gl_signed_normalized): a byte per attribute,
// the normal's in bits 0-7, the color's in bits 8-15; 0: none. Set in every pipeline.
FFVK_SPEC_CONST(17, int, SPEC_GL_SNORM, 0)
// vec4s from one draw record to the next in the record buffer (deferred.frag): the ring's
// stride, set in every pipeline.
FFVK_SPEC_CONST(18, int, SPEC_RECORD_VEC4S, 22)
// COLOR_SUM with lighting off (lit draws always sum the separate specular color).
FFVK_SPEC_CONST(19, int, SPEC_COLOR_SUM, -1)
// The alpha test's function, 0 NEVER .. 7 ALWAYS (ALWAYS while the test is off).
FFVK_SPEC_CONST(20, int, SPEC_ALPHA_FUNC, -1)
// The color attachment's alpha bits when UNORM (the alpha test compares at that fixed-point
// precision, GL 2.1 section 4.1.4), 0 for a float compare; set in every pipeline.
FFVK_SPEC_CONST(21, int, SPEC_ALPHA_BITS, 0)
// Fog (section 3.10): 0 off, 1 LINEAR, 2 EXP, 3 EXP2; its source (1 FOG_COORD, 0 the eye-space
// depth); 1 where f is computed per vertex (FOG_HINT FASTEST).
FFVK_SPEC_CONST(22, int, SPEC_FOG_MODE, -1)
FFVK_SPEC_CONST(23, int, SPEC_FOG_SOURCE, -1)
FFVK_SPEC_CONST(24, int, SPEC_FOG_PER_VERTEX, -1)
// The enabled user clip planes, a bit each (the `_clipped` builds write gl_ClipDistance).
FFVK_SPEC_CONST(25, int, SPEC_CLIP_PLANES, -1)
// Points (section 3.3), the pipeline's own constants (set for points pipelines, "off" in the
// others): whether the size falls with the distance, GL_POINT_DISTANCE_ATTENUATION's (a, b, c),
// GL_POINT_SIZE_MIN and _MAX, and the sprite bits (1 GL_POINT_SPRITE, 2 GL_COORD_REPLACE,
// 4 GL_POINT_SPRITE_COORD_ORIGIN GL_LOWER_LEFT).
FFVK_SPEC_CONST(26, int, SPEC_POINT_ATTENUATION, 0)
FFVK_SPEC_CONST(27, float, SPEC_POINT_ATTENUATION_A, 1.0)
FFVK_SPEC_CONST(28, float, SPEC_POINT_ATTENUATION_B, 0.0)
FFVK_SPEC_CONST(29, float, SPEC_POINT_ATTENUATION_C, 0.0)
FFVK_SPEC_CONST(30, float, SPEC_POINT_SIZE_MIN, 0.0)
FFVK_SPEC_CONST(31, float, SPEC_POINT_SIZE_MAX, 3.40282347e38)  // FLT_MAX
FFVK_SPEC_CONST(32, int, SPEC_POINT_SPRITE, 0)
// Texture coordinate generation: each coordinate's mode, 3 bits from S (texgen.glsl).
FFVK_SPEC_CONST(33, int, SPEC_TEXGEN, -1)
// GL_COMBINE's functions, sources, operands and scales (texture.glsl, Combine::code).
FFVK_SPEC_CONST(34, int, SPEC_COMBINE, -1)
// The texture units of a TEXTURE build: bits 0-3 the units sampled (enabled, with a complete
// texture), bits 4-7 the units applied (sampled, and not reading a missing unit's texel through
// GL_TEXTUREn), bits 8-11 the sampled units that sample their cube map, and from bit 12 each
// sampled unit's base internal format in 3 bits. The pipeline's own, set in every pipeline (the
// uber-shader's too).
FFVK_SPEC_CONST(35, int, SPEC_TEXTURE_UNITS, 0x11)
// GL_COMBINE's GL_TEXTUREn sources (Combine::crossbar_code), unit 0's; then units 1-3's
// TEXTURE_ENV_MODE, texgen, GL_COMBINE and crossbar, as SPEC_TEX_ENV, SPEC_TEXGEN,
// SPEC_COMBINE and SPEC_CROSSBAR are unit 0's.
FFVK_SPEC_CONST(36, int, SPEC_CROSSBAR, -1)
FFVK_SPEC_CONST(37, int, SPEC_TEX_ENV_1, -1)
FFVK_SPEC_CONST(38, int, SPEC_TEX_ENV_2, -1)
FFVK_SPEC_CONST(39, int, SPEC_TEX_ENV_3, -1)
FFVK_SPEC_CONST(40, int, SPEC_TEXGEN_1, -1)
FFVK_SPEC_CONST(41, int, SPEC_TEXGEN_2, -1)
FFVK_SPEC_CONST(42, int, SPEC_TEXGEN_3, -1)
FFVK_SPEC_CONST(43, int, SPEC_COMBINE_1, -1)
FFVK_SPEC_CONST(44, int, SPEC_COMBINE_2, -1)
FFVK_SPEC_CONST(45, int, SPEC_COMBINE_3, -1)
FFVK_SPEC_CONST(46, int, SPEC_CROSSBAR_1, -1)
FFVK_SPEC_CONST(47, int, SPEC_CROSSBAR_2, -1)
FFVK_SPEC_CONST(48, int, SPEC_CROSSBAR_3, -1)

#endif
