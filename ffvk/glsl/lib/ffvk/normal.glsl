// ffvk's shader library: the eye-space normal (GL 2.1 section 2.11.3), in vertex stages.
#ifndef FFVK_NORMAL_GLSL
#define FFVK_NORMAL_GLSL

#include "ffvk/switches.glsl"

// n = (M^-1)^T n_object, then RESCALE_NORMAL (`rescale`: its factor, 1 while it is off), then
// NORMALIZE: `normal_matrix` is the upper 3x3 of the modelview's inverse transpose. A zero
// normal stays zero instead of becoming NaN.
vec3 eye_normal(mat3 normal_matrix, float rescale, vec3 n_object) {
    vec3 n = normal_matrix * n_object;
    n *= rescale;
    // A select on the uniform switch, not an if (see face_material).
    float len = length(n);
    vec3 unit_n = len > 0.0 ? n / len : vec3(0.0);
    return FFVK_STATE.normalize != 0u ? unit_n : n;
}

#endif
