#version 450
// gouraud mode: per_vertex.vert.glsl with smooth interpolation.
#define INTERP smooth
#include "per_vertex.vert.glsl"
