// The layer example's vertex stage. PER_FRAGMENT: pass what the fragment stage lights with
// (GL's per-fragment lighting); otherwise light here, front and back (GL's SMOOTH, or FLAT
// with INTERP defined as `flat`). Its `#version` line and the target's lines come first
// (../layer.rs, `source`).
layout(location = 0) in vec4 in_position;  // the layer's positions (binding 0)
layout(location = 1) in vec3 in_normal;    // its normals (binding 1)
layout(location = 2) in vec4 in_color;     // its 8-bit colors (binding 1)

// A zero the compiler cannot prove zero: the library's switches pass the block's values
// through it, so that lavapipe does not compile a variant per draw (docs/shader-library.md).
#ifdef FFVK_GLSL_ES
#define FFVK_HIDDEN_ZERO uint(gl_VertexID < 0)
#else
#define FFVK_HIDDEN_ZERO uint(gl_VertexIndex < 0)
#endif
#include "layer.glsl"

LAYER_LOCATION(5) out float fog;
#ifdef PER_FRAGMENT
LAYER_LOCATION(0) out vec4 eye_position;
LAYER_LOCATION(1) out vec4 normal;  // the direction; w: the length
LAYER_LOCATION(3) out vec4 color;
#else
LAYER_LOCATION(0) INTERP out vec4 front_pri;
LAYER_LOCATION(1) INTERP out vec4 front_sec;
LAYER_LOCATION(2) INTERP out vec4 back_pri;
LAYER_LOCATION(3) INTERP out vec4 back_sec;
#endif

// With lighting off, the secondary color GL sums (section 2.14): the current one, clamped,
// or nothing while COLOR_SUM is off.
vec4 unlit_secondary() {
    vec4 c = layer_draw.current_secondary_color;
    return color_sum_enabled() ? vec4(clamp(c.rgb, 0.0, 1.0), 1.0) : vec4(0.0, 0.0, 0.0, 1.0);
}

void main() {
    vec4 V = layer_draw.modelview * in_position;
    gl_Position = FFVK_STATE.projection * V;
    fog = fog_varying(V, 0.0);  // the layer draws no fog coordinates: FRAGMENT_DEPTH only
    mat3 normal_matrix = mat3(layer_draw.normal_matrix[0].xyz, layer_draw.normal_matrix[1].xyz,
                              layer_draw.normal_matrix[2].xyz);
    vec3 n = eye_normal(normal_matrix, layer_draw.normal_matrix[2].w, in_normal);
    vec4 c = in_color;
#ifdef PER_FRAGMENT
    eye_position = V;
    float normal_length = length(n);
    vec4 lit_normal = vec4(normal_length > 0.0 ? n / normal_length : vec3(0.0), normal_length);
    // Unlit, the varying carries the secondary color instead.
    normal = mix(unlit_secondary(), lit_normal, bvec4(lighting_enabled()));
    color = lighting_enabled() ? c : clamp(c, 0.0, 1.0);
#else
    if (!lighting_enabled()) {
        front_pri = clamp(c, 0.0, 1.0);  // section 2.14.6
        back_pri = front_pri;
        front_sec = unlit_secondary();
        back_sec = front_sec;
        return;
    }
    Material front = layer_front(), back = layer_back();
    LitColor f = light_equation(V, n, face_material(front, back, false, c));
    front_pri = f.c_pri;
    front_sec = f.c_sec;
    if (two_side()) {
        // The back face: the back material and -n (section 2.14.1).
        LitColor b = light_equation(V, -n, face_material(front, back, true, c));
        back_pri = b.c_pri;
        back_sec = b.c_sec;
    } else {
        back_pri = f.c_pri;
        back_sec = f.c_sec;
    }
#endif
}
