// The draw's own values in the vertex stages: its DrawRecord (src/gpu/layout.rs), read as
// per-instance vertex attributes from ffvk's record buffer, the draw's firstInstance naming its
// record. Locations 0-3 are the caller's vertex attributes.
#ifndef FFVK_RECORD_GLSL
#define FFVK_RECORD_GLSL

#include "draw.glsl"

layout(location = 4) in mat4 in_modelview;        // M (locations 4-7)
layout(location = 8) in vec4 in_normal_matrix_0;  // (M^-1)^T column 0; w: front SHININESS
layout(location = 9) in vec4 in_normal_matrix_1;  // column 1; w: back SHININESS
layout(location = 10) in vec4 in_normal_matrix_2; // column 2; w: RESCALE_NORMAL's factor (1 off)
layout(location = 11) in vec4 in_front_a_cm;      // front AMBIENT
layout(location = 12) in vec4 in_front_d_cm;      // front DIFFUSE
layout(location = 13) in vec4 in_front_s_cm;      // front SPECULAR
layout(location = 14) in vec4 in_front_e_cm;      // front EMISSION
layout(location = 15) in vec4 in_back_a_cm;       // back AMBIENT
layout(location = 16) in vec4 in_back_d_cm;       // back DIFFUSE
layout(location = 17) in vec4 in_back_s_cm;       // back SPECULAR
layout(location = 18) in vec4 in_back_e_cm;       // back EMISSION
layout(location = 19) in vec4 in_current_color;   // CURRENT_COLOR (glColor)

// Sets draw_front and draw_back from the record.
void load_record() {
    draw_front = Material(in_front_a_cm, in_front_d_cm, in_front_s_cm, in_front_e_cm, in_normal_matrix_0.w);
    draw_back = Material(in_back_a_cm, in_back_d_cm, in_back_s_cm, in_back_e_cm, in_normal_matrix_1.w);
}

// Section 2.11.3: n = (M^-1)^T n_object, then RESCALE_NORMAL, then NORMALIZE.
// A zero normal stays zero instead of becoming NaN.
vec3 eye_normal(vec3 n_object) {
    mat3 normal_matrix = mat3(in_normal_matrix_0.xyz, in_normal_matrix_1.xyz, in_normal_matrix_2.xyz);
    vec3 n = normal_matrix * n_object;
    n *= in_normal_matrix_2.w;
    // A select on the uniform switch, not an if (see face_material).
    float len = length(n);
    vec3 unit_n = len > 0.0 ? n / len : vec3(0.0);
    return state.normalize != 0u ? unit_n : n;
}

#endif
