#version 450
// flat mode, one color between the stages (specialized one-sided, single-color states):
// per_vertex.vert.glsl with flat interpolation and ONE_COLOR.
#define INTERP flat
#define ONE_COLOR
#include "per_vertex.vert.glsl"
