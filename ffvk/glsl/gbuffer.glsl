// The deferred path's G-buffer encoding: written by the G-buffer pass (fragment.frag under
// GBUFFER), read by the lighting pass (deferred.frag). See GBUFFER_FORMATS in
// src/draw/pipeline.rs.
#ifndef FFVK_GBUFFER_GLSL
#define FFVK_GBUFFER_GLSL

// The surface's x: the record index + 1 in bits 0-30, bit 31 set for a back face.
#define BACK_FACE_BIT 0x80000000u
#define RECORD_BITS 0x7fffffffu

vec2 sign_not_zero(vec2 v) {
    return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

// A unit vector's octahedral encoding: projected onto the octahedron |x| + |y| + |z| = 1, the
// lower half folded over the upper, in two 16-bit SNORM values (about 3e-5 apart: the
// direction comes back within about 2e-5 radians). A zero vector encodes as +z; its length,
// stored apart, keeps it zero.
uint octahedron_encode(vec3 n) {
    float l1 = abs(n.x) + abs(n.y) + abs(n.z);
    vec2 p = l1 > 0.0 ? n.xy / l1 : vec2(0.0);
    if (n.z < 0.0) p = (1.0 - abs(p.yx)) * sign_not_zero(p);
    return packSnorm2x16(p);
}

// The unit vector octahedron_encode encoded.
vec3 octahedron_decode(uint e) {
    vec2 p = unpackSnorm2x16(e);
    vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
    if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * sign_not_zero(n.xy);
    return normalize(n);
}

#endif
