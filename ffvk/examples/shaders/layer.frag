// The layer example's fragment stage: GL's lighting (PER_FRAGMENT) or the face's lit colors,
// the color sum, fog, the layer's own vignette, then the alpha test. Its `#version` line and
// the target's lines come first (../layer.rs, `source`).
#define FFVK_HIDDEN_ZERO uint(gl_FragCoord.x < 0.0)
#include "layer.glsl"

LAYER_LOCATION(5) in float fog;
#ifdef PER_FRAGMENT
LAYER_LOCATION(0) in vec4 eye_position;
LAYER_LOCATION(1) in vec4 normal;
LAYER_LOCATION(3) in vec4 color;
#else
LAYER_LOCATION(0) INTERP in vec4 front_pri;
LAYER_LOCATION(1) INTERP in vec4 front_sec;
LAYER_LOCATION(2) INTERP in vec4 back_pri;
LAYER_LOCATION(3) INTERP in vec4 back_sec;
#endif
layout(location = 0) out vec4 out_color;

// The layer's vignette: 1 within 0.3 half-sizes of the image's centre, falling to 0.3 at
// 1.3 half-sizes (smoothstep of the distance d in half-sizes) and beyond.
float vignette(vec2 xy) {
    float d = length(xy - vec2(LAYER_HALF_SIZE)) / LAYER_HALF_SIZE;
    return 1.0 - 0.7 * smoothstep(0.3, 1.3, d);
}

void main() {
    LitColor lit;
#ifdef PER_FRAGMENT
    if (!lighting_enabled()) {
        lit.c_pri = color;
        lit.c_sec = normal;  // the secondary color, in the normal's varying
    } else {
        vec3 n = unit(normal.xyz) * normal.w;
        // Two-sided lighting picks the face by its window-space winding, not by the normal.
        bool back_face = two_side() && !gl_FrontFacing;
        Material front = layer_front(), back = layer_back();
        lit = back_face ? light_equation(eye_position, -n, face_material(front, back, true, color))
                        : light_equation(eye_position, n, face_material(front, back, false, color));
    }
#else
    lit.c_pri = gl_FrontFacing ? front_pri : back_pri;
    lit.c_sec = gl_FrontFacing ? front_sec : back_sec;
#endif
    // GL's order (sections 3.9-3.10, 4.1.4): the color sum, fog, then the alpha test; the
    // layer's vignette sits between fog and the test and leaves alpha alone.
    vec4 c = apply_fog(color_sum(lit), fog);
    if (LAYER_VIGNETTE != 0) c.rgb *= vignette(gl_FragCoord.xy);
    if (!alpha_passes(c.a)) discard;
    out_color = c;
}
