#version 450
// flat mode: per_vertex.frag.glsl with flat interpolation.
#define INTERP flat
#include "per_vertex.frag.glsl"
