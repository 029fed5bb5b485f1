// Fragment stage of the per-vertex modes: picks the face's interpolated (or provoking)
// colors by window-space winding and sums them.
layout(location = 0) INTERP in vec4 front_pri;
layout(location = 1) INTERP in vec4 front_sec;
layout(location = 2) INTERP in vec4 back_pri;
layout(location = 3) INTERP in vec4 back_sec;

layout(location = 0) out vec4 out_color;

#include "lighting.glsl"

void main() {
    LitColor lit;
    lit.c_pri = gl_FrontFacing ? front_pri : back_pri;
    lit.c_sec = gl_FrontFacing ? front_sec : back_sec;
    out_color = color_sum(lit);
}
