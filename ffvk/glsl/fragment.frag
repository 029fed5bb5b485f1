#version 450
#extension GL_EXT_control_flow_attributes : require  // [[unroll]] in lighting.glsl
// Fragment stage of the `fragment` mode: the equation at each fragment. The normal is
// the interpolated direction renormalized, times the interpolated length, so that an
// unnormalized normal (scaled modelview, no NORMALIZE) still shows as in GL.
#ifndef GBUFFER
layout(location = 0) in vec4 eye_position;
#endif
layout(location = 1) in vec4 normal;  // xyz: the direction; w: the length
layout(location = 3) in vec4 color;
#ifdef FOG
layout(location = 15) in float fog;  // draw.glsl, fog_varying
#endif
#ifdef VARYING_MATERIALS
// The draw's materials (fragment.vert), for small draws: flat inputs cost lavapipe a setup
// per attribute per triangle, which few triangles make cheaper than a draw's own uniform block.
layout(location = 5) flat in vec4 front_a_cm;
layout(location = 6) flat in vec4 front_d_cm;
layout(location = 7) flat in vec4 front_s_cm;
layout(location = 8) flat in vec4 front_e_cm;
layout(location = 9) flat in vec4 back_a_cm;
layout(location = 10) flat in vec4 back_d_cm;
layout(location = 11) flat in vec4 back_s_cm;
layout(location = 12) flat in vec4 back_e_cm;
layout(location = 13) flat in vec2 s_rm;  // front, back
#else
// The draw's record (src/gpu/layout.rs, DrawRecord), the same bytes the vertex stage reads as
// instance attributes, here as a uniform block at the draw's own offset: its materials. Flat
// inputs would cost lavapipe a setup per attribute per triangle (about 15 ms per vec4 on a
// million triangles); a block read at constant offsets costs a new fragment constant buffer per
// draw (about 5 µs there), the better deal for draws of more than a few dozen triangles. Set 2
// is moved after the texture's set at pipeline creation.
layout(std140, set = 2, binding = 0) uniform Record {
    mat4 modelview;
    vec4 normal_matrix[3];  // w: front SHININESS, back SHININESS, RESCALE_NORMAL's factor
    vec4 front[4];          // AMBIENT, DIFFUSE, SPECULAR, EMISSION
    vec4 back[4];
    vec4 current_color;
    vec4 current_normal;
    vec4 current_texcoord;
    vec4 current_secondary_color;
    vec4 current_unit_texcoords[3];  // units 1-3's
} record;
#endif

#ifdef GBUFFER
// The deferred path's first pass: what the equation needs at this pixel, for the lighting
// pass (deferred.frag) to evaluate it once per pixel with the same arithmetic.
layout(location = 14) flat in uint record_index;
// x: the draw's record index + 1 (0: nothing drawn), bit 31 set for a back face; y: the
// normal's direction, octahedron-encoded (packSnorm2x16); z: its length (float bits); w: the
// fragment's depth (float bits), from which deferred.frag rebuilds the eye-space position.
layout(location = 0) out uvec4 g_surface;
// The primary color (color material's input, or the unlit color) as four 16-bit floats.
layout(location = 1) out uvec2 g_color;
#include "gbuffer.glsl"
#else
layout(location = 0) out vec4 out_color;
#endif

// A zero the compiler cannot prove zero (fragments lie inside the framebuffer, at x >= 0):
// the uber-shader's switches pass through it (draw.glsl, uber_value).
#define FFVK_HIDDEN_ZERO uint(gl_FragCoord.x < 0.0)
#include "draw.glsl"
#include "ffvk/lighting.glsl"
#ifdef TEXTURE
#include "units.glsl"
layout(location = 4) in vec4 stq;
layout(location = 16) in vec4 unit_stq[MAX_TEXTURE_UNITS - 1];  // units 1-3's
#endif

#include "stipple.glsl"
#ifdef EDGE_FLAGS
#define EDGES_FRAGMENT_STAGE
#include "edges.glsl"
#else
#define FRONT_FACING gl_FrontFacing
#endif

void main() {
    if (!stipple_passes()) discard;
#ifdef EDGE_FLAGS
    if (!on_boundary_edge()) discard;
#endif
#ifdef GBUFFER
    g_surface = uvec4((record_index + 1u) | (FRONT_FACING ? 0u : BACK_FACE_BIT), octahedron_encode(unit(normal.xyz)),
                      floatBitsToUint(normal.w), floatBitsToUint(gl_FragCoord.z));
    g_color = uvec2(packHalf2x16(color.rg), packHalf2x16(color.ba));
#else
#ifdef VARYING_MATERIALS
    draw_front = Material(front_a_cm, front_d_cm, front_s_cm, front_e_cm, s_rm.x);
    draw_back = Material(back_a_cm, back_d_cm, back_s_cm, back_e_cm, s_rm.y);
#else
    draw_front = Material(record.front[0], record.front[1], record.front[2], record.front[3],
                          record.normal_matrix[0].w);
    draw_back = Material(record.back[0], record.back[1], record.back[2], record.back[3],
                         record.normal_matrix[1].w);
#endif
    LitColor lit;
    if (!lighting_enabled()) {
        lit.c_pri = color;
        lit.c_sec = normal;  // the secondary color rides in the normal's varying (fragment.vert)
    } else {
        vec3 n = unit(normal.xyz) * normal.w;
        bool back_face = two_side() && !FRONT_FACING;
        lit = back_face ? light_equation(eye_position, -n, face_material(draw_front, draw_back, true, color))
                        : light_equation(eye_position, n, face_material(draw_front, draw_back, false, color));
    }
#ifdef TEXTURE
    // After lighting, before the color sum: the secondary color is not textured.
    lit.c_pri = textured_color(lit.c_pri, vec4[](stq, unit_stq[0], unit_stq[1], unit_stq[2]));
#endif
#ifdef FOG
    out_color = apply_fog(color_sum(lit), fog);
#else
    out_color = color_sum(lit);
#endif
    if (!alpha_passes(out_color.a)) discard;
#endif
}
