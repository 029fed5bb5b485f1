// ffvk's own pipelines' declarations around the shader library (lib/ffvk/): the State block
// at set 0, binding 0, the draw's materials, and the library's state, switches, stages and
// material. src/gpu/layout.rs mirrors the block (a test checks the offsets in the compiled
// SPIR-V against the Rust structs).
#ifndef FFVK_DRAW_GLSL
#define FFVK_DRAW_GLSL

#include "ffvk/state.glsl"

// GL's lighting state but the draw's own values: staged when it changes (a new block only when
// a draw's state differs from the draw before), bound at a dynamic offset.
layout(std140, set = 0, binding = 0) uniform State { FFVK_STATE_MEMBERS } state;
#define FFVK_STATE state

// The draw's own materials (its DrawRecord, src/gpu/layout.rs): each stage's main sets them
// before lighting, from the record's instance attributes (vertex stages, record.glsl) or from
// the record as a uniform block (the fragment stage of the fragment mode). Per-draw values are
// vertex data, not uniforms, in the vertex stages: a frame of draws that change only these
// binds nothing between them in the vertex and flat modes.
Material draw_front;
Material draw_back;

#include "ffvk/spec.glsl"
#include "ffvk/switches.glsl"
#include "ffvk/stages.glsl"
#include "ffvk/material.glsl"

#endif
