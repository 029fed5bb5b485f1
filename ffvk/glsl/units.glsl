// ffvk's own pipelines' texture units: one binding of four combined image samplers, read as 2D
// textures and, aliased, as cube maps, behind the library's texturing (lib/ffvk/texture.glsl).
#ifndef FFVK_UNITS_GLSL
#define FFVK_UNITS_GLSL

#include "draw.glsl"

// The units' textures: unit i's GL_TEXTURE_2D image and its parameters (a VkSampler made from
// glTexParameter's values) in element i. Set 1 is moved to the set after the State block's at
// pipeline creation; a unit a draw does not sample holds another of its textures.
layout(set = 1, binding = 0) uniform sampler2D unit_2d[MAX_TEXTURE_UNITS];
// The same binding read as cube maps: element i holds unit i's GL_TEXTURE_CUBE_MAP (a cube
// view of its six faces in GL's order) instead of its 2D texture where SPEC_TEXTURE_UNITS says
// the unit samples its cube map (GL_TEXTURE_CUBE_MAP's precedence); the shader reads each
// element through the one of the two arrays its view's type matches.
layout(set = 1, binding = 0) uniform samplerCube unit_cube[MAX_TEXTURE_UNITS];

#define FFVK_TEXEL_2D(i, st) texture(unit_2d[i], st)
#define FFVK_TEXEL_CUBE(i, str) texture(unit_cube[i], str)
#include "ffvk/texture.glsl"

#endif
