#version 450
#extension GL_EXT_control_flow_attributes : require  // [[unroll]] in lighting.glsl
// The deferred lighting pass: the equation once per pixel, from what the G-buffer pass
// (fragment.frag under GBUFFER) wrote there, with the draw's materials from its record.
// The arithmetic is fragment.frag's, on the values the G-buffer keeps (gbuffer.glsl).
// The G-buffer (gbuffer.glsl): the surface (record, facing, normal, depth) and the color.
layout(set = 1, binding = 0) uniform usampler2D g_surface;
layout(set = 1, binding = 1) uniform usampler2D g_color;
// What rebuilds a pixel's eye-space position from its depth: the inverse of the state's
// projection (Vulkan's clip space), and 1 / the extent; and the state this pass lights.
layout(push_constant) uniform Pass {
    mat4 eye_from_clip;
    vec2 pixel_size;
    uint state;
} pass;
// The frame's draw records (src/gpu/layout.rs, DrawRecord), read at the index the G-buffer
// holds, as RGBA32F texels: a record takes SPEC_RECORD_VEC4S of them (its size rounded up to
// the device's uniform offset alignment, the ring's stride), so the stride is the device's,
// not one fixed here. Offsets in texels: normal_matrix 4-6 (w: front and back SHININESS),
// front 7-10, back 11-14 (AMBIENT, DIFFUSE, SPECULAR, EMISSION). A texel buffer, not a
// storage buffer: llvmpipe gathers a texel fetch at per-pixel indices, where it loads a
// storage buffer lane by lane (the lighting pass took about 3× as long that way).
layout(set = 1, binding = 4) uniform samplerBuffer records;
vec4 record_vec4(uint i) {
    return texelFetch(records, int(i));
}

// Each record's lighting state, by record index: a frame of several states draws this pass
// once per state, and each leaves the others' pixels alone.
layout(std430, set = 1, binding = 6) readonly buffer States {
    uint record_state[];
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
// The depth test (GREATER against the pass's depth 1: only where a draw left a nearer depth)
// before the shader, discard or not: pixels nothing was drawn at are never shaded.
layout(early_fragment_tests) in;

// A zero the compiler cannot prove zero (fragments lie inside the framebuffer, at x >= 0).
#define FFVK_HIDDEN_ZERO uint(gl_FragCoord.x < 0.0)
#include "draw.glsl"
#include "ffvk/lighting.glsl"
#include "gbuffer.glsl"

void main() {
    ivec2 at = ivec2(gl_FragCoord.xy);
    uvec4 surface = texelFetch(g_surface, at, 0);
    uint record = surface.x & RECORD_BITS;
    // Nothing drawn here: the clear color stays.
    if (record == 0u) discard;
    // Another state's pixel: its own pass lights it.
    if (record_state[record - 1u] != pass.state) discard;
#ifdef COUNT
    atomicAdd(evaluations, 1u);
#endif
    uint r = (record - 1u) * uint(SPEC_RECORD_VEC4S);
    draw_front = Material(record_vec4(r + 7u), record_vec4(r + 8u), record_vec4(r + 9u),
                          record_vec4(r + 10u), record_vec4(r + 4u).w);
    draw_back = Material(record_vec4(r + 11u), record_vec4(r + 12u), record_vec4(r + 13u),
                         record_vec4(r + 14u), record_vec4(r + 5u).w);
    // The pixel centre at the fragment's depth, back through the projection: the point of the
    // triangle the forward path's interpolated eye position names.
    vec2 ndc = gl_FragCoord.xy * pass.pixel_size * 2.0 - 1.0;
    vec4 eye = pass.eye_from_clip * vec4(ndc, uintBitsToFloat(surface.w), 1.0);
    vec4 eye_position = eye / eye.w;
    uvec2 c = texelFetch(g_color, at, 0).xy;
    vec4 color = vec4(unpackHalf2x16(c.x), unpackHalf2x16(c.y));
    LitColor lit;
    if (!lighting_enabled()) {
        lit.c_pri = color;
        lit.c_sec = vec4(0.0, 0.0, 0.0, 1.0);
    } else {
        vec3 n = octahedron_decode(surface.y) * uintBitsToFloat(surface.z);
        bool back_face = two_side() && (surface.x & BACK_FACE_BIT) != 0u;
        lit = back_face ? light_equation(eye_position, -n, face_material(draw_front, draw_back, true, color))
                        : light_equation(eye_position, n, face_material(draw_front, draw_back, false, color));
    }
    out_color = color_sum(lit);
}
