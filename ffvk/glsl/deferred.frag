#version 450
#extension GL_EXT_control_flow_attributes : require  // [[unroll]] in lighting.glsl
// The deferred lighting pass: the equation once per pixel, from what the G-buffer pass
// (fragment.frag under GBUFFER) wrote there, with the draw's materials from its record.
// The arithmetic is fragment.frag's, on the same values.
layout(set = 1, binding = 0) uniform sampler2D g_position;
layout(set = 1, binding = 1) uniform sampler2D g_normal;
layout(set = 1, binding = 2) uniform sampler2D g_color;
layout(set = 1, binding = 3) uniform usampler2D g_record;
// The frame's draw records (src/gpu/layout.rs, DrawRecord), read at the index the G-buffer
// holds. Members are read one by one: SPIRV-Tools rejects glslang's struct copies (README).
struct Record {
    mat4 modelview;
    vec4 normal_matrix[3];  // w: front SHININESS, back SHININESS, RESCALE_NORMAL's factor
    vec4 front[4];          // AMBIENT, DIFFUSE, SPECULAR, EMISSION
    vec4 back[4];
    vec4 current_color;
};
layout(std430, set = 1, binding = 4) readonly buffer Records {
    Record records[];
};

#ifdef COUNT
// The pass's own count of the pixels it evaluates the equation at (the `deferred_counted`
// build, for measured frames): one atomic add per lit pixel, whatever blocks the rasterizer
// shades.
layout(std430, set = 1, binding = 5) buffer Evaluations {
    uint evaluations;
};
#endif

layout(location = 0) out vec4 out_color;

// A zero the compiler cannot prove zero (fragments lie inside the framebuffer, at x >= 0).
#define HIDDEN_ZERO uint(gl_FragCoord.x < 0.0)
#include "lighting.glsl"

void main() {
    ivec2 at = ivec2(gl_FragCoord.xy);
    uint record = texelFetch(g_record, at, 0).r;
    // Nothing drawn here: the clear color stays.
    if (record == 0u) discard;
#ifdef COUNT
    atomicAdd(evaluations, 1u);
#endif
    uint i = record - 1u;
    draw_front = Material(records[i].front[0], records[i].front[1], records[i].front[2],
                          records[i].front[3], records[i].normal_matrix[0].w);
    draw_back = Material(records[i].back[0], records[i].back[1], records[i].back[2],
                         records[i].back[3], records[i].normal_matrix[1].w);
    vec4 eye_position = texelFetch(g_position, at, 0);
    vec4 normal = texelFetch(g_normal, at, 0);
    vec4 color = texelFetch(g_color, at, 0);
    LitColor lit;
    if (!lighting_enabled()) {
        lit.c_pri = color;
        lit.c_sec = vec4(0.0, 0.0, 0.0, 1.0);
    } else {
        vec3 n = normal.xyz;
        bool back_face = two_side() && normal.w < 0.0;
        lit = back_face ? light_equation(eye_position, -n, face_material(true, color))
                        : light_equation(eye_position, n, face_material(false, color));
    }
    out_color = color_sum(lit);
}
