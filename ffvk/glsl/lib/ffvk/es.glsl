// ffvk's shader library's declaration header for GLSL ES 3.00 (OpenGL ES 3.0 and later): a
// shader for ES includes it first, right after `#version 300 es`, then the switches as defines
// (GLSL ES has no specialization constants: `ffvk::shaders::spec_defines`), then the library's
// files as a Vulkan shader does, their includes inlined (`ffvk::shaders::resolve`; GLSL ES has
// no #include). The caller declares the state block without a set or binding
// (`layout(std140) uniform FfvkState { FFVK_STATE_MEMBERS } ffvk_state;`, bound with
// glUniformBlockBinding), defines FFVK_HIDDEN_ZERO from gl_VertexID (vertex stages) or
// gl_FragCoord (fragment stages), and takes a draw's own values from uniforms: ES guarantees
// only 16 vertex attributes.
#ifndef FFVK_ES_GLSL
#define FFVK_ES_GLSL

// The library computes in single precision, as GL's fixed function does.
precision highp float;
precision highp int;

#define FFVK_GLSL_ES 1
// GLSL ES has no loop attributes; its compilers unroll constant-count loops themselves.
#define FFVK_UNROLL

#endif
