#version 450
// gouraud mode, one color between the stages (specialized one-sided, single-color states):
// per_vertex.frag.glsl with smooth interpolation and ONE_COLOR.
#define INTERP smooth
#define ONE_COLOR
#include "per_vertex.frag.glsl"
