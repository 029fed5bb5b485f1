#version 450
#extension GL_EXT_control_flow_attributes : require  // [[unroll]] in lighting.glsl
// Fragment stage of the `vertex` and `flat` modes: picks the face's interpolated (or provoking)
// colors by window-space winding and sums them. With ONE_COLOR (pipelines specialized for
// one-sided, single-color or unlit states, where the back colors equal the front ones and
// the secondary color is (0, 0, 0, 1)) only the front primary color comes in.
layout(location = 0) INTERP in vec4 front_pri;
#ifndef ONE_COLOR
layout(location = 1) INTERP in vec4 front_sec;
layout(location = 2) INTERP in vec4 back_pri;
layout(location = 3) INTERP in vec4 back_sec;
#endif

#ifdef FOG
layout(location = 5) in float fog;  // draw.glsl, fog_varying
#endif

layout(location = 0) out vec4 out_color;

// A zero the compiler cannot prove zero (fragments lie inside the framebuffer, at x >= 0):
// the uber-shader's switches pass through it (draw.glsl, uber_value).
#define FFVK_HIDDEN_ZERO uint(gl_FragCoord.x < 0.0)
#include "draw.glsl"
#include "ffvk/lighting.glsl"
#ifdef TEXTURE
#include "units.glsl"
layout(location = 4) in vec4 stq;
layout(location = 8) in vec4 unit_stq[MAX_TEXTURE_UNITS - 1];  // units 1-3's
#endif

#include "stipple.glsl"
#ifdef EDGE_FLAGS
#define EDGES_FRAGMENT_STAGE
#include "edges.glsl"
#else
#define FRONT_FACING gl_FrontFacing
#endif

void main() {
    if (!stipple_passes()) discard;
#ifdef EDGE_FLAGS
    if (!on_boundary_edge()) discard;
#endif
    LitColor lit;
#ifdef ONE_COLOR
    lit.c_pri = front_pri;
    lit.c_sec = vec4(0.0, 0.0, 0.0, 1.0);
#else
    lit.c_pri = FRONT_FACING ? front_pri : back_pri;
    lit.c_sec = FRONT_FACING ? front_sec : back_sec;
#endif
#ifdef TEXTURE
    lit.c_pri = textured_color(lit.c_pri, vec4[](stq, unit_stq[0], unit_stq[1], unit_stq[2]));
#endif
#ifdef FOG
    out_color = apply_fog(color_sum(lit), fog);
#else
    out_color = color_sum(lit);
#endif
    if (!alpha_passes(out_color.a)) discard;
}
