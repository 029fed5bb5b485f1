#version 450
// Geometry stage of the `_edges` builds (edges.glsl): a triangle list with adjacency in, each
// triangle out unchanged (culling, facing, polygon offset and the polygon mode stay Vulkan's),
// with its corner weights and the mask of its boundary edges for the fragment stage.
// build.rs compiles it with the build's macros, so that it passes exactly the varyings the
// vertex stage writes: `EDGES_OF_FRAGMENT_MODE` for the fragment mode's (fragment.vert), else
// vertex.vert's.
#include "edges.glsl"

// glFrontFace of the pipeline's draws: 1 for GL_CW (VK_FRONT_FACE_CLOCKWISE), 0 for GL_CCW.
// Specialized (the `_edges` pipelines key on the front face): the geometry stage tells the
// fragment stage each triangle's facing itself, since lavapipe 22.3 loses gl_FrontFacing's
// slot on polygons drawn as lines or points after a geometry stage (it overwrites a varying).
layout(constant_id = 0) const int SPEC_FRONT_FACE_CW = 0;

layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 3) out;

// gl_in and the outputs keep GL's built-in blocks as they are (the validation layer wants
// the vertex stage's block, member for member); gl_ClipDistance takes its size, 6, from the
// copy below.

layout(location = VERTEX_INDEX_LOCATION) flat in uint vertex_index[];

#ifdef EDGES_OF_FRAGMENT_MODE
// fragment.vert's varyings.
layout(location = 0) in vec4 in0[];
layout(location = 1) in vec4 in1[];
layout(location = 3) in vec4 in3[];
layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;
layout(location = 3) out vec4 out3;
#ifdef FOG
layout(location = 15) in float in_fog[];
layout(location = 15) out float out_fog;
#endif
#ifdef VARYING_MATERIALS
// The draw's materials (locations 5-12) and shininesses (13), flat.
layout(location = 5) in vec4 in_m0[];
layout(location = 6) in vec4 in_m1[];
layout(location = 7) in vec4 in_m2[];
layout(location = 8) in vec4 in_m3[];
layout(location = 9) in vec4 in_m4[];
layout(location = 10) in vec4 in_m5[];
layout(location = 11) in vec4 in_m6[];
layout(location = 12) in vec4 in_m7[];
layout(location = 5) flat out vec4 out_m0;
layout(location = 6) flat out vec4 out_m1;
layout(location = 7) flat out vec4 out_m2;
layout(location = 8) flat out vec4 out_m3;
layout(location = 9) flat out vec4 out_m4;
layout(location = 10) flat out vec4 out_m5;
layout(location = 11) flat out vec4 out_m6;
layout(location = 12) flat out vec4 out_m7;
layout(location = 13) in vec2 in_s_rm[];
layout(location = 13) flat out vec2 out_s_rm;
#endif
#else
// vertex.vert's varyings (the builds with all four colors).
layout(location = 0) in vec4 in0[];
layout(location = 1) in vec4 in1[];
layout(location = 2) in vec4 in2[];
layout(location = 3) in vec4 in3[];
layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;
layout(location = 2) out vec4 out2;
layout(location = 3) out vec4 out3;
#ifdef FOG
layout(location = 5) in float in_fog[];
layout(location = 5) out float out_fog;
#endif
#endif
#ifdef TEXTURE
layout(location = 4) in vec4 in_stq[];
layout(location = 4) out vec4 out_stq;
// Units 1-3's coordinates, after the stage's other varyings.
#ifdef EDGES_OF_FRAGMENT_MODE
#define UNIT_STQ_LOCATION 16
#else
#define UNIT_STQ_LOCATION 8
#endif
layout(location = UNIT_STQ_LOCATION) in vec4 in_unit_stq[][3];
layout(location = UNIT_STQ_LOCATION) out vec4 out_unit_stq[3];
#endif

layout(location = EDGE_LOCATION) noperspective out vec4 edge;

// Emits corner k of the triangle (input vertex 2k) with its weights and the edge mask.
void corner(int k, uint bits) {
    int i = 2 * k;
    gl_Position = gl_in[i].gl_Position;
    // The vertex stage's size where it writes one (polygons drawn as points, SPEC_POINTS).
    gl_PointSize = gl_in[i].gl_PointSize;
#ifdef CLIP_PLANES
    gl_ClipDistance[0] = gl_in[i].gl_ClipDistance[0];
    gl_ClipDistance[1] = gl_in[i].gl_ClipDistance[1];
    gl_ClipDistance[2] = gl_in[i].gl_ClipDistance[2];
    gl_ClipDistance[3] = gl_in[i].gl_ClipDistance[3];
    gl_ClipDistance[4] = gl_in[i].gl_ClipDistance[4];
    gl_ClipDistance[5] = gl_in[i].gl_ClipDistance[5];
#endif
    out0 = in0[i];
    out1 = in1[i];
#ifndef EDGES_OF_FRAGMENT_MODE
    out2 = in2[i];
#endif
    out3 = in3[i];
#ifdef FOG
    out_fog = in_fog[i];
#endif
#ifdef VARYING_MATERIALS
    out_m0 = in_m0[i];
    out_m1 = in_m1[i];
    out_m2 = in_m2[i];
    out_m3 = in_m3[i];
    out_m4 = in_m4[i];
    out_m5 = in_m5[i];
    out_m6 = in_m6[i];
    out_m7 = in_m7[i];
    out_s_rm = in_s_rm[i];
#endif
#ifdef TEXTURE
    out_stq = in_stq[i];
    out_unit_stq = in_unit_stq[i];
#endif
    edge = vec4(float(k == 0), float(k == 1), float(k == 2), float(bits));
    EmitVertex();
}

void main() {
    // Edge e is a boundary edge where its adjacency vertex repeats its first corner.
    uint mask = 0u;
    for (int e = 0; e < 3; e++) {
        if (vertex_index[2 * e + 1] == vertex_index[2 * e]) mask |= 1u << e;
    }
    // Facing as Vulkan finds it (§28.7.1: area a = -1/2 Σ x_i y_i+1 - x_i+1 y_i in framebuffer
    // coordinates, front where a > 0 for VK_FRONT_FACE_COUNTER_CLOCKWISE; ffvk's viewports have
    // a positive height), from the clip-space corners: the determinant of their (x, y, w) has
    // the sign of Σ x_i y_i+1 - x_i+1 y_i of the triangle's visible part, w < 0 or not.
    vec4 p0 = gl_in[0].gl_Position, p1 = gl_in[2].gl_Position, p2 = gl_in[4].gl_Position;
    float det = dot(p0.xyw, cross(p1.xyw, p2.xyw));
    bool front = (det <= 0.0) == (SPEC_FRONT_FACE_CW == 0);
    uint bits = mask | (front ? 8u : 0u);
    // The corners in their order: the last stays the provoking vertex (flat shading).
    // Constant indices: NIR folds them once corner() is inlined.
    corner(0, bits);
    corner(1, bits);
    corner(2, bits);
    EndPrimitive();
}
