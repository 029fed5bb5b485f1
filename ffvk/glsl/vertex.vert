#version 450
#extension GL_EXT_control_flow_attributes : require  // [[unroll]] in lighting.glsl
// Vertex stage of the `vertex` and `flat` modes: lights each vertex, front and back, with
// both colors clamped here. build.rs defines INTERP (`smooth` or `flat`) and, for the
// *_one_color variants, ONE_COLOR (see vertex.frag): then only the front primary color
// leaves the stage; the others are computed as always and dropped, since they cannot differ
// from what the fragment stage assumes in the states such a pipeline draws.
// (x, y, z, w): a layout with fewer components gets z = 0 and w = 1 from Vulkan, as from GL.
layout(location = 0) in vec4 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_color;

layout(location = 0) INTERP out vec4 front_pri;
#ifdef ONE_COLOR
vec4 front_sec;
vec4 back_pri;
vec4 back_sec;
#else
layout(location = 1) INTERP out vec4 front_sec;
layout(location = 2) INTERP out vec4 back_pri;
layout(location = 3) INTERP out vec4 back_sec;
#endif

#ifdef CLIP_PLANES
// GL's user clip planes (the `_clipped` builds; the device's shaderClipDistance).
out float gl_ClipDistance[6];
#endif

#ifdef FOG
// Fog: c, or f where it is computed per vertex (draw.glsl, fog_varying). Only the `_fog`
// builds pass it: an output the fragment stage does not read still costs lavapipe per vertex.
layout(location = 5) out float fog;
#endif

#ifdef TEXTURE
// Texture coordinates (s, t) in, (s, t, r, q) after the texture matrix out: always
// interpolated, whatever the shade model (GL's flat shading is about colors only).
// (s, t, r, q): r = 0 and q = 1 where the layout gives fewer, as in GL.
layout(location = 3) in vec4 in_texcoord;
layout(location = 4) out vec4 stq;
// Units 1-3's: their arrays (glClientActiveTexture, glTexCoordPointer) or their current
// coordinates (glMultiTexCoord), and out after their texture matrices.
layout(location = 23) in vec4 in_texcoord_1;
layout(location = 24) in vec4 in_texcoord_2;
layout(location = 25) in vec4 in_texcoord_3;
layout(location = 8) out vec4 unit_stq[3];  // MAX_TEXTURE_UNITS - 1
#endif

#ifdef EDGE_FLAGS
// The `_edges` builds: the vertex's index, for edges.geom (edges.glsl).
#include "edges.glsl"
layout(location = VERTEX_INDEX_LOCATION) flat out uint vertex_index;
#endif

// A zero the compiler cannot prove zero (valid draws have no negative vertex index): the
// uber-shader's switches pass through it (draw.glsl, uber_value).
#define FFVK_HIDDEN_ZERO uint(gl_VertexIndex < 0)
#include "draw.glsl"
#include "ffvk/lighting.glsl"
#include "record.glsl"
#ifdef TEXTURE
#include "ffvk/texgen.glsl"
#endif

void main() {
    vec4 V = in_modelview * in_position;
#ifdef EDGE_FLAGS
    vertex_index = uint(gl_VertexIndex);
#endif
    // GL's point size; Vulkan leaves a point's size undefined unless it is written.
    if (SPEC_POINTS != 0) gl_PointSize = point_width(V);
    gl_Position = state.projection * V;
#ifdef FOG
    fog = fog_varying(V, in_fog_coord);
#endif
#ifdef CLIP_PLANES
    [[unroll]] for (uint i = 0u; i < 6u; i++) gl_ClipDistance[i] = clip_distance(i, V);
#endif
#ifdef TEXTURE
    vec3 n_f = texgen_reads_normal() ? eye_normal(vertex_normal(in_normal)) : vec3(0.0);
    vec4 coords[MAX_TEXTURE_UNITS];
    vec4 given[MAX_TEXTURE_UNITS] = vec4[](in_texcoord, in_texcoord_1, in_texcoord_2, in_texcoord_3);
    unit_coords(given, in_position, V, n_f, coords);
    if (unit_sampled(0u)) stq = coords[0];
    [[unroll]] for (uint i = 1u; i < MAX_TEXTURE_UNITS; i++) {
        if (unit_sampled(i)) unit_stq[i - 1u] = coords[i];
    }
#endif

    vec4 c = vertex_color(in_color);
    if (!lighting_enabled()) {
        // Section 2.14.6: colors are clamped after lighting, whether enabled or not.
        front_pri = clamp(c, 0.0, 1.0);
        back_pri = front_pri;
        front_sec = unlit_secondary();
        back_sec = front_sec;
        return;
    }
    load_record();
    vec3 n = eye_normal(vertex_normal(in_normal));
    LitColor front = light_equation(V, n, face_material(draw_front, draw_back, false, c));
    front_pri = front.c_pri;
    front_sec = front.c_sec;
    if (two_side()) {
        // Two-sided: the back color uses the back material and -n.
        LitColor back = light_equation(V, -n, face_material(draw_front, draw_back, true, c));
        back_pri = back.c_pri;
        back_sec = back.c_sec;
    } else {
        back_pri = front.c_pri;
        back_sec = front.c_sec;
    }
}
