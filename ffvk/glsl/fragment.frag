#version 450
#extension GL_EXT_control_flow_attributes : require  // [[unroll]] in lighting.glsl
// Fragment stage of the `fragment` mode: the equation at each fragment. The normal is
// the interpolated direction renormalized, times the interpolated length, so that an
// unnormalized normal (scaled modelview, no NORMALIZE) still shows as in GL.
layout(location = 0) in vec4 eye_position;
layout(location = 1) in vec3 normal_direction;
layout(location = 2) in float normal_length;
layout(location = 3) in vec4 color;
// The draw's materials (fragment.vert).
layout(location = 5) flat in vec4 front_a_cm;
layout(location = 6) flat in vec4 front_d_cm;
layout(location = 7) flat in vec4 front_s_cm;
layout(location = 8) flat in vec4 front_e_cm;
layout(location = 9) flat in vec4 back_a_cm;
layout(location = 10) flat in vec4 back_d_cm;
layout(location = 11) flat in vec4 back_s_cm;
layout(location = 12) flat in vec4 back_e_cm;
layout(location = 13) flat in vec2 s_rm;  // front, back

layout(location = 0) out vec4 out_color;

// A zero the compiler cannot prove zero (fragments lie inside the framebuffer, at x >= 0):
// the uber-shader's switches pass through it (draw.glsl, uber_value).
#define HIDDEN_ZERO uint(gl_FragCoord.x < 0.0)
#include "lighting.glsl"
#ifdef TEXTURE
#include "texture.glsl"
layout(location = 4) in vec4 stq;
#endif

void main() {
    draw_front = Material(front_a_cm, front_d_cm, front_s_cm, front_e_cm, s_rm.x);
    draw_back = Material(back_a_cm, back_d_cm, back_s_cm, back_e_cm, s_rm.y);
    LitColor lit;
    if (!lighting_enabled()) {
        lit.c_pri = color;
        lit.c_sec = vec4(0.0, 0.0, 0.0, 1.0);
    } else {
        vec3 n = unit(normal_direction) * normal_length;
        bool back_face = two_side() && !gl_FrontFacing;
        lit = back_face ? light_equation(eye_position, -n, face_material(true, color))
                        : light_equation(eye_position, n, face_material(false, color));
    }
#ifdef TEXTURE
    // After lighting, before the color sum: the secondary color is not textured.
    lit.c_pri = texture_environment(lit.c_pri, texel_at(stq));
#endif
    out_color = color_sum(lit);
}
