#version 450
// gouraud mode: per_vertex.frag.glsl with smooth interpolation.
#define INTERP smooth
#include "per_vertex.frag.glsl"
