// ffvk's shader library: the GL 2.1 lighting equation, section 2.14.1, term for term, and the
// color sum (section 3.9). ffvk's own pipelines include it; the CPU reference
// (ffvk/src/reference.rs) is its only other copy.
#ifndef FFVK_LIGHTING_GLSL
#define FFVK_LIGHTING_GLSL

#include "ffvk/switches.glsl"

struct LitColor {
    vec4 c_pri;
    vec4 c_sec;
};

// d1 ⊙ d2 = max(d1 · d2, 0)
float odot(vec3 d1, vec3 d2) {
    return max(dot(d1, d2), 0.0);
}

// x^y with 0^0 = 1 (section 2.1.1); GLSL leaves pow(0, 0) undefined.
float pow_gl(float x, float y) {
    float p = pow(x, y);
    return y == 0.0 ? 1.0 : p;  // a select (see light_term)
}

// Normalizes, keeping a zero vector zero rather than NaN.
vec3 unit(vec3 v) {
    float len = length(v);
    vec3 q = v / len;
    return len > 0.0 ? q : vec3(0.0);  // a select: v may be a light's (see light_term)
}

// P1P2 with a hat: the unit vector from homogeneous point P1 to P2. The four cases choose the
// vector by selects and normalize once (unit(-x) is exactly -unit(x)): a light's w is
// uniform, so no branch may test it (see light_term), and a shader that computed all four
// cases paid four square roots and divisions per light and vertex.
vec3 unit_from_to(vec4 P1, vec4 P2) {
    bool far1 = P1.w == 0.0;
    bool far2 = P2.w == 0.0;
    vec3 finite = P2.xyz / P2.w - P1.xyz / P1.w;
    vec3 both_far = P2.xyz - P1.xyz;
    // mix() with a bvec3 is an OpSelect; glslang would make a nested ?: of expressions a branch.
    vec3 to_far = mix(P2.xyz, both_far, bvec3(far1));
    vec3 to_near = mix(finite, -P1.xyz, bvec3(far1));
    return unit(mix(to_near, to_far, bvec3(far2)));
}

// att_i, GL's: 1 / (k0 + k1 d + k2 d^2), d = ||VP_pli||.
float attenuation_gl_k012(float d, float k0, float k1, float k2) {
    return 1.0 / (k0 + k1 * d + k2 * d * d);
}

// att_i, glTF's (KHR_lights_punctual, ffvk's extension): 1 / d^2, windowed to 0 at the range
// by clamp(1 - (d / range)^4, 0, 1) when the light has one (range > 0).
float attenuation_gltf_inverse_square(float d, float range) {
    float windowed = clamp(1.0 - pow(d / range, 4.0), 0.0, 1.0);
    float window = range > 0.0 ? windowed : 1.0;  // a select (see light_term)
    return window / (d * d);
}

// spot_i, GL's: (P_pliV ⊙ ŝ_dli)^s_rli inside the cone, 0 outside.
float spot_gl_exponent(float cos_angle, float cos_c_rli, float s_rli) {
    return cos_angle >= cos_c_rli ? pow_gl(cos_angle, s_rli) : 0.0;
}

// spot_i with a linear edge (ffvk's extension): 1 inside the inner cone, 0 outside the outer
// (c_rli), a straight ramp in the cosine between; equal cones are a hard cutoff.
float spot_linear_inner_outer(float cos_angle, float cos_outer, float cos_inner) {
    float hard = cos_angle >= cos_outer ? 1.0 : 0.0;
    float ramp = clamp((cos_angle - cos_outer) / (cos_inner - cos_outer), 0.0, 1.0);
    return cos_inner <= cos_outer ? hard : ramp;  // a select (see light_term)
}

// spot_i with a smoothstep edge (ffvk's extension; glTF's cone): as the linear edge with
// smoothstep(cos outer, cos inner, cos θ) between the cones. GLSL leaves smoothstep
// undefined for equal edges, so equal cones are tested first.
float spot_smoothstep_inner_outer(float cos_angle, float cos_outer, float cos_inner) {
    float hard = cos_angle >= cos_outer ? 1.0 : 0.0;
    float ramp = smoothstep(cos_outer, cos_inner, cos_angle);
    return cos_inner <= cos_outer ? hard : ramp;  // a select (see light_term)
}

// The specular factor before f_i and the colors, GL's: (n ⊙ ĥ_i)^s_rm, ĥ_i the unit halfway
// vector of VP_pli and v (VPe for a local viewer, else (0, 0, 1)).
// The same with ĥ_i given (a directional light's, derived on the host).
float specular_blinn_unit_halfway(vec3 n, vec3 h_hat, float s_rm) {
    return pow_gl(odot(n, h_hat), s_rm);
}

float specular_blinn_halfway(vec3 n, vec3 VP_pli, vec3 v, float s_rm) {
    vec3 h_i = VP_pli + v;
    return specular_blinn_unit_halfway(n, unit(h_i), s_rm);
}

// The specular factor, Phong's (ffvk's extension): (r_i ⊙ v)^s_rm, r_i = 2 (n · VP_pli) n −
// VP_pli the reflection of VP_pli about n (with n as the equation receives it, as GL's ĥ_i
// term does).
float specular_phong_reflect(vec3 n, vec3 VP_pli, vec3 v, float s_rm) {
    vec3 r_i = 2.0 * dot(n, VP_pli) * n - VP_pli;
    return pow_gl(odot(r_i, v), s_rm);
}

// Light i's term of the sum over lights, added to c_pri and c_sec: vertex (or fragment) V,
// eye space, normal n, material m, VPe the unit vector from V to the eye.
void light_term(uint i, vec4 V, vec3 n, Material m, vec3 VPe, inout vec3 c_pri, inout vec3 c_sec) {
    // Read in place: glslang 12 copies a whole std140 struct with an OpStore that SPIR-V
    // validation rejects (block layout and function layout differ).
#define L FFVK_STATE.lights[i]

    // Where the pipeline promises directional lights and finite vertices, VP_pli and (for the
    // infinite viewer) ĥ_i are the same at every vertex: GL's derived state, computed on the
    // host (draw.glsl). The test is on constants and folds away. (A test on each vertex's w
    // would not help: lavapipe runs both sides of a branch that differs between vertices.)
    bool derived = directional_at_finite_vertices(i);
    vec3 VP_pli = derived ? L.VP_hat_inf : unit_from_to(V, L.P_pli);
    bool derived_h = derived && !local_viewer();

    // Branches on the light's own values (w, c_rli, its edge and falloff) are selects, not
    // ifs: lavapipe compiles a shader variant for every draw whose uniforms changed when an
    // "if" tests uniform values alone (BENCHMARKS.md, "Many draws"). The terms are computed
    // for every light the pipeline's promises allow and the select keeps GL's value.
    float att_i = 1.0;
    if (may_be_local(i)) {
        float d = length(L.P_pli.xyz / L.P_pli.w - V.xyz / V.w);  // ||VP_pli||
        float att_gl = attenuation_gl_k012(d, L.k0, L.k1, L.k2);
        float att_gltf = may_be_gltf_falloff() ? attenuation_gltf_inverse_square(d, L.range) : att_gl;
        float att = L.falloff == FALLOFF_GLTF_INVERSE_SQUARE ? att_gltf : att_gl;
        att_i = L.P_pli.w != 0.0 ? att : 1.0;
    }

    float spot_i = 1.0;
    if (may_be_spot(i)) {
        float cos_angle = odot(unit_from_to(L.P_pli, V), unit(L.s_dli));  // P_pliV ⊙ ŝ_dli
        float spot = spot_gl_exponent(cos_angle, L.cos_c_rli, L.s_rli);
        if (may_be_soft_spot()) {
            float linear = spot_linear_inner_outer(cos_angle, L.cos_c_rli, L.cos_inner);
            float smooth_ = spot_smoothstep_inner_outer(cos_angle, L.cos_c_rli, L.cos_inner);
            spot = L.spot_edge == EDGE_LINEAR_INNER_OUTER ? linear : spot;
            spot = L.spot_edge == EDGE_SMOOTHSTEP_INNER_OUTER ? smooth_ : spot;
        }
        spot_i = L.c_rli != 180.0 ? spot : 1.0;
    }

    float n_VP = odot(n, VP_pli);
    float f_i = n_VP != 0.0 ? 1.0 : 0.0;

    vec3 v = local_viewer() ? VPe : vec3(0.0, 0.0, 1.0);
    float s_factor = specular_model() == SPECULAR_PHONG_REFLECT
        ? specular_phong_reflect(n, VP_pli, v, m.s_rm)
        : derived_h ? specular_blinn_unit_halfway(n, L.h_hat_inf, m.s_rm)
                   : specular_blinn_halfway(n, VP_pli, v, m.s_rm);
    vec3 specular = f_i * s_factor * m.s_cm.rgb * L.s_cli.rgb;

    vec3 ambient = m.a_cm.rgb * L.a_cli.rgb;
    vec3 diffuse = n_VP * m.d_cm.rgb * L.d_cli.rgb;

    if (separate_specular()) {
        c_pri += att_i * spot_i * (ambient + diffuse);
        c_sec += att_i * spot_i * specular;
    } else {
        c_pri += att_i * spot_i * (ambient + diffuse + specular);
    }
#undef L
}

// Lights vertex (or fragment) V, eye space, with normal n and material m.
// Returns c_pri and c_sec, each clamped to [0, 1] (section 2.14.6).
LitColor light_equation(vec4 V, vec3 n, Material m) {
    const vec4 Pe = vec4(0.0, 0.0, 0.0, 1.0);
    vec3 VPe = unit_from_to(V, Pe);

    vec3 c_pri = m.e_cm.rgb + m.a_cm.rgb * FFVK_STATE.a_cs.rgb;
    vec3 c_sec = vec3(0.0);

    // The light count: SPEC_LIGHT_COUNT when the pipeline is specialized, else the uniform
    // (the uber-shader). The test folds away at specialization. A constant count is unrolled
    // (every stage that includes this file enables GL_EXT_control_flow_attributes), so that
    // lavapipe reads each light's uniforms at constant offsets; the uniform count is not,
    // since lavapipe would then run all MAX_LIGHTS iterations under a mask (BENCHMARKS.md).
    if (SPEC_LIGHT_COUNT >= 0) {
        FFVK_UNROLL for (int i = 0; i < SPEC_LIGHT_COUNT; i++) {
            light_term(uint(i), V, n, m, VPe, c_pri, c_sec);
        }
    } else {
        for (uint i = 0u; i < uber_value(FFVK_STATE.light_count); i++) {
            light_term(i, V, n, m, VPe, c_pri, c_sec);
        }
    }

    LitColor lit;
    lit.c_pri = clamp(vec4(c_pri, m.d_cm.a), 0.0, 1.0);
    lit.c_sec = clamp(vec4(c_sec, 1.0), 0.0, 1.0);
    return lit;
}

// Color sum (section 3.9): RGB is clamp(c_pri + c_sec), alpha from c_pri.
vec4 color_sum(LitColor lit) {
    return vec4(clamp(lit.c_pri.rgb + lit.c_sec.rgb, 0.0, 1.0), lit.c_pri.a);
}

#endif
