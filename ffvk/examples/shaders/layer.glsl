// The declarations both of the layer example's stages share: its own per-draw block, ffvk's
// state block where the layer puts it, the layer's own constants, and the library's files.
// The example (../layer.rs) puts the `#version` line and the target's lines first, inlines
// the includes with ffvk::shaders::resolve and compiles with glslc (Vulkan) or hands the
// text to OpenGL ES 3 (FFVK_GLSL_ES, from the library's ffvk/es.glsl).
#ifdef FFVK_GLSL_ES
// GLSL ES 3.00: no sets or bindings (glUniformBlockBinding binds the blocks), no locations
// on varyings (matched by name), no specialization constants (the layer's values are
// defines, as the library's are).
#define LAYER_BLOCK(set_, binding_) layout(std140)
#define LAYER_LOCATION(n)
const int LAYER_VIGNETTE = LAYER_VALUE_VIGNETTE;
const float LAYER_HALF_SIZE = LAYER_VALUE_HALF_SIZE;
#else
#extension GL_EXT_control_flow_attributes : require  // the library unrolls its light loop
#define LAYER_BLOCK(set_, binding_) layout(std140, set = set_, binding = binding_)
#define LAYER_LOCATION(n) layout(location = n)
// The layer's own stage, which ffvk does not have: a vignette that darkens the image towards
// its corners, after fog and before the alpha test. Its constants are at the layer's IDs.
layout(constant_id = 0) const int LAYER_VIGNETTE = 0;
layout(constant_id = 1) const float LAYER_HALF_SIZE = 128.0;
// The library's specialization constants from ID 100 up; IDs 0-99 are the layer's.
#define FFVK_SPEC_BASE 100
#endif

#include "ffvk/state.glsl"

// The layer's own draw values, one block per draw at set 0, binding 0. Its shape is the
// layer's choice; this one takes the bytes of ffvk::gpu::layout::DrawRecord, so that the
// values are packed as ffvk packs its own.
LAYER_BLOCK(0, 0) uniform LayerDraw {
    mat4 modelview;
    vec4 normal_matrix[3];  // (M^-1)^T's columns; w: front SHININESS, back SHININESS, rescale
    vec4 front[4];          // AMBIENT, DIFFUSE, SPECULAR, EMISSION
    vec4 back[4];
    vec4 current_color;
    vec4 current_normal;
    vec4 current_texcoord;
    vec4 current_secondary_color;
} layer_draw;

// GL's state for the library, at the binding the layer chose (set 0, binding 3), filled with
// ffvk::gpu::layout::StateBlock's bytes.
LAYER_BLOCK(0, 3) uniform FfvkState { FFVK_STATE_MEMBERS } ffvk_state;
#define FFVK_STATE ffvk_state

#include "ffvk/spec.glsl"
#include "ffvk/switches.glsl"
#include "ffvk/stages.glsl"
#include "ffvk/material.glsl"
#include "ffvk/normal.glsl"
#include "ffvk/lighting.glsl"

Material layer_front() {
    return Material(layer_draw.front[0], layer_draw.front[1], layer_draw.front[2], layer_draw.front[3],
                    layer_draw.normal_matrix[0].w);
}
Material layer_back() {
    return Material(layer_draw.back[0], layer_draw.back[1], layer_draw.back[2], layer_draw.back[3],
                    layer_draw.normal_matrix[1].w);
}
