#version 450
#extension GL_EXT_control_flow_attributes : require  // [[unroll]] (the clip planes)
// Vertex stage of the `fragment` mode: passes the eye-space position, the normal's
// direction and length, and the current color.
// (x, y, z, w): a layout with fewer components gets z = 0 and w = 1 from Vulkan, as from GL.
layout(location = 0) in vec4 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_color;

#ifdef GBUFFER
// The G-buffer keeps the fragment's depth instead (deferred.frag rebuilds the position).
vec4 eye_position;
#else
layout(location = 0) out vec4 eye_position;
#endif
// The normal's direction (xyz) and length (w) in one varying: lavapipe's triangle setup costs
// per varying slot, and a float alone takes a slot.
layout(location = 1) out vec4 normal;
layout(location = 3) out vec4 color;
#ifdef FOG
layout(location = 15) out float fog;      // c, or f per vertex (draw.glsl, fog_varying)
#endif
#ifdef CLIP_PLANES
// GL's user clip planes (the `_clipped` builds; the device's shaderClipDistance).
out float gl_ClipDistance[6];
#endif
#ifdef VARYING_MATERIALS
// The draw's materials, the same for every vertex of it (fragment.frag).
layout(location = 5) flat out vec4 front_a_cm;
layout(location = 6) flat out vec4 front_d_cm;
layout(location = 7) flat out vec4 front_s_cm;
layout(location = 8) flat out vec4 front_e_cm;
layout(location = 9) flat out vec4 back_a_cm;
layout(location = 10) flat out vec4 back_d_cm;
layout(location = 11) flat out vec4 back_s_cm;
layout(location = 12) flat out vec4 back_e_cm;
layout(location = 13) flat out vec2 s_rm;  // front, back
#endif

#ifdef GBUFFER
// The draw's record in its chunk (firstInstance picks it): the deferred lighting pass reads
// the draw's materials there (deferred.frag).
layout(location = 14) flat out uint record_index;
#endif

#ifdef TEXTURE
// Texture coordinates, as in vertex.vert.
// (s, t, r, q): r = 0 and q = 1 where the layout gives fewer, as in GL.
layout(location = 3) in vec4 in_texcoord;
layout(location = 4) out vec4 stq;
// Units 1-3's: their arrays (glClientActiveTexture, glTexCoordPointer) or their current
// coordinates (glMultiTexCoord), and out after their texture matrices.
layout(location = 23) in vec4 in_texcoord_1;
layout(location = 24) in vec4 in_texcoord_2;
layout(location = 25) in vec4 in_texcoord_3;
layout(location = 16) out vec4 unit_stq[3];  // MAX_TEXTURE_UNITS - 1
#endif

#ifdef EDGE_FLAGS
// The `_edges` builds: the vertex's index, for edges.geom (edges.glsl).
#include "edges.glsl"
layout(location = VERTEX_INDEX_LOCATION) flat out uint vertex_index;
#endif

// A zero the compiler cannot prove zero (valid draws have no negative vertex index): the
// uber-shader's switches pass through it (draw.glsl, uber_value).
#define FFVK_HIDDEN_ZERO uint(gl_VertexIndex < 0)
#include "record.glsl"
#ifdef TEXTURE
#include "ffvk/texgen.glsl"
#endif

void main() {
    eye_position = in_modelview * in_position;
#ifdef EDGE_FLAGS
    vertex_index = uint(gl_VertexIndex);
#endif
    // GL's point size; Vulkan leaves a point's size undefined unless it is written.
    if (SPEC_POINTS != 0) gl_PointSize = point_width(eye_position);
    gl_Position = state.projection * eye_position;
#ifdef FOG
    fog = fog_varying(eye_position, in_fog_coord);
#endif
#ifdef CLIP_PLANES
    [[unroll]] for (uint i = 0u; i < 6u; i++) gl_ClipDistance[i] = clip_distance(i, eye_position);
#endif
#ifdef TEXTURE
    vec3 n_f = texgen_reads_normal() ? eye_normal(vertex_normal(in_normal)) : vec3(0.0);
    vec4 coords[MAX_TEXTURE_UNITS];
    vec4 given[MAX_TEXTURE_UNITS] = vec4[](in_texcoord, in_texcoord_1, in_texcoord_2, in_texcoord_3);
    unit_coords(given, in_position, eye_position, n_f, coords);
    if (unit_sampled(0u)) stq = coords[0];
    [[unroll]] for (uint i = 1u; i < MAX_TEXTURE_UNITS; i++) {
        if (unit_sampled(i)) unit_stq[i - 1u] = coords[i];
    }
#endif
#ifdef GBUFFER
    record_index = uint(gl_InstanceIndex);
#endif
#ifdef VARYING_MATERIALS
    front_a_cm = in_front_a_cm;
    front_d_cm = in_front_d_cm;
    front_s_cm = in_front_s_cm;
    front_e_cm = in_front_e_cm;
    back_a_cm = in_back_a_cm;
    back_d_cm = in_back_d_cm;
    back_s_cm = in_back_s_cm;
    back_e_cm = in_back_e_cm;
    s_rm = vec2(in_front_s_rm, in_back_s_rm);
#endif
    vec3 n = eye_normal(vertex_normal(in_normal));
    float normal_length = length(n);
    // With lighting off the normal is not read: the varying carries the clamped secondary
    // color instead (fragment.frag), so the color sum costs no varying of its own.
    vec4 lit_normal = vec4(normal_length > 0.0 ? n / normal_length : vec3(0.0), normal_length);
    normal = mix(unlit_secondary(), lit_normal, bvec4(lighting_enabled()));
    // Lighting off: the clamped current color (section 2.14.6); lighting on: unclamped, as
    // COLOR_MATERIAL takes it.
    vec4 c = vertex_color(in_color);
    color = lighting_enabled() ? c : clamp(c, 0.0, 1.0);
}
