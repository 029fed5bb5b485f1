// The draw's own values in the vertex stages: its DrawRecord (src/gpu/layout.rs), read as
// per-instance vertex attributes from ffvk's record buffer, the draw's firstInstance naming its
// record. Locations 0-3 are the vertex's position, normal, color and texture coordinates: the
// caller's arrays, or where a layout has none, the record's current values (the pipeline's
// vertex input says which; the shaders read them alike). A layout may also take any material
// input below (11-20) from an array of its own, per vertex: glMaterial between glBegin and glEnd.
#ifndef FFVK_RECORD_GLSL
#define FFVK_RECORD_GLSL

#include "draw.glsl"
#include "ffvk/normal.glsl"

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
layout(location = 19) in float in_front_s_rm;    // front SHININESS (in_normal_matrix_0.w)
layout(location = 20) in float in_back_s_rm;     // back SHININESS (in_normal_matrix_1.w)
// The secondary color (glSecondaryColorPointer, or the record's current one): summed with
// lighting off under COLOR_SUM.
layout(location = 21) in vec4 in_secondary_color;
// The fog coordinate (glFogCoordPointer, or the record's current one).
layout(location = 22) in float in_fog_coord;

// Sets draw_front and draw_back from the record (or the layout's per-vertex materials).
void load_record() {
    draw_front = Material(in_front_a_cm, in_front_d_cm, in_front_s_cm, in_front_e_cm, in_front_s_rm);
    draw_back = Material(in_back_a_cm, in_back_d_cm, in_back_s_cm, in_back_e_cm, in_back_s_rm);
}

// GL 2.1's conversion of a signed normalized integer c of b bits (table 2.9): (2c + 1) / (2^b - 1),
// where Vulkan's SNORM takes max(c / (2^(b-1) - 1), -1). A layout's SNORM normals and colors are
// fetched as SSCALED (the integer c, as a float) and converted here; `code` is the attribute's
// byte of SPEC_GL_SNORM: b in bits 0-4 (0: not converted), bit 7 set when w is one of the
// array's components (else Vulkan's 1 stands in for it and stays).
vec4 signed_normalized(vec4 c, int code) {
    if (code == 0) return c;
    vec4 f = (2.0 * c + 1.0) / (exp2(float(code & 31)) - 1.0);
    return (code & 128) != 0 ? f : vec4(f.xyz, c.w);
}
vec3 vertex_normal(vec3 n) {
    return signed_normalized(vec4(n, 0.0), SPEC_GL_SNORM & 255).xyz;
}
vec4 vertex_color(vec4 c) {
    return signed_normalized(c, (SPEC_GL_SNORM >> 8) & 255);
}
// Section 2.14 with lighting off: the clamped secondary color, or (0, 0, 0, 1) when the color
// sum is off (it then adds nothing).
vec4 unlit_secondary() {
    vec4 c = signed_normalized(in_secondary_color, (SPEC_GL_SNORM >> 16) & 255);
    return color_sum_enabled() ? vec4(clamp(c.rgb, 0.0, 1.0), 1.0) : vec4(0.0, 0.0, 0.0, 1.0);
}

// Section 2.11.3 with the record's normal matrix and rescale factor (lib/ffvk/normal.glsl).
vec3 eye_normal(vec3 n_object) {
    mat3 normal_matrix = mat3(in_normal_matrix_0.xyz, in_normal_matrix_1.xyz, in_normal_matrix_2.xyz);
    return eye_normal(normal_matrix, in_normal_matrix_2.w, n_object);
}

#endif
