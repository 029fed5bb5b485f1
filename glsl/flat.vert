#version 450
// flat mode: per_vertex.vert.glsl with flat interpolation.
#define INTERP flat
#include "per_vertex.vert.glsl"
