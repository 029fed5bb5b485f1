#version 450
// The bench floor's vertex stage (src/bench/floor/): GL 2.1's lighting equation (section
// 2.14.1) per vertex for exactly the draws sweep's two lights, a directional light 0 and a
// point light 1, one-sided, infinite viewer, no NORMALIZE, no separate specular. Nothing
// branches on a uniform value: lavapipe 22.3 compiles a shader variant per draw when control
// flow depends on uniform values that changed, so there is no if and no loop here at all,
// and every ?: is a select of values already computed.
//
// build.rs compiles it once per data path, PATH_INSTANCE, PATH_STORAGE, PATH_UNIFORM or
// PATH_PUSH, which says where the draw's Record comes from.
#ifdef PATH_STORAGE
#extension GL_ARB_shader_draw_parameters : require
#endif

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 0) out vec4 out_color;

// GL's derived state of the frame, set once per frame (the host's glLight and
// glLightModel), std140.
layout(set = 0, binding = 0, std140) uniform Frame {
    mat4 projection;    // GL's projection premultiplied by Vulkan's clip-space change
    vec4 scene;         // e_cm + a_cm * a_cs (rgb)
    vec4 l0_vp;         // light 0: VP_pl0 = unit(P_pl0.xyz), directional
    vec4 l0_h;          // light 0: unit(VP_pl0 + (0, 0, 1)), infinite viewer
    vec4 l0_ambient;    // light 0: a_cm * a_cl0
    vec4 l0_diffuse;    // light 0: d_cl0
    vec4 l0_specular;   // light 0: s_cl0
    vec4 l1_position;   // light 1: P_pl1, eye space, w = 1
    vec4 l1_ambient;    // light 1: a_cm * a_cl1
    vec4 l1_diffuse;    // light 1: d_cl1
    vec4 l1_specular;   // light 1: s_cl1
    vec4 l1_k;          // light 1: k0, k1, k2
} frame;

// The draw's own values, 128 bytes: the modelview's first three rows (the last is
// (0, 0, 0, 1)), the normal matrix (M^-1)^T's columns (w unused), the front diffuse and the
// front specular (rgb) with the shininess (w).
#define RECORD_FIELDS \
    vec4 mv0; vec4 mv1; vec4 mv2; \
    vec4 nm0; vec4 nm1; vec4 nm2; \
    vec4 diffuse; vec4 specular;

#if defined(PATH_INSTANCE)
// Per-instance vertex attributes, the draw's firstInstance naming its entry.
layout(location = 2) in vec4 r_mv0;
layout(location = 3) in vec4 r_mv1;
layout(location = 4) in vec4 r_mv2;
layout(location = 5) in vec4 r_nm0;
layout(location = 6) in vec4 r_nm1;
layout(location = 7) in vec4 r_nm2;
layout(location = 8) in vec4 r_diffuse;
layout(location = 9) in vec4 r_specular;
#define R(field) r_##field
#elif defined(PATH_STORAGE)
// One storage buffer of every draw's record; a multi-draw's gl_DrawID names the draw in its
// batch and the batch's firstInstance (gl_InstanceIndex, one instance per draw) where the
// batch starts.
struct Record { RECORD_FIELDS };
layout(set = 0, binding = 1, std430) readonly buffer Records {
    Record records[];
};
#define R(field) records[gl_InstanceIndex + gl_DrawIDARB].field
#elif defined(PATH_UNIFORM)
// A uniform block at the draw's dynamic offset.
layout(set = 0, binding = 1, std140) uniform Draw { RECORD_FIELDS } draw;
#define R(field) draw.field
#elif defined(PATH_PUSH)
// Push constants, pushed before each draw.
layout(push_constant, std430) uniform Push { RECORD_FIELDS } push;
#define R(field) push.field
#else
#error "build.rs defines one PATH_*"
#endif

// x^y with 0^0 = 1 (section 2.1.1): a select.
float pow_gl(float x, float y) {
    float p = pow(x, y);
    return y == 0.0 ? 1.0 : p;
}

// v / |v|, a zero vector kept zero: a select.
vec3 unit(vec3 v) {
    float len = length(v);
    vec3 q = v / len;
    return len > 0.0 ? q : vec3(0.0);
}

void main() {
    mat4 modelview = transpose(mat4(R(mv0), R(mv1), R(mv2), vec4(0.0, 0.0, 0.0, 1.0)));
    vec4 V = modelview * vec4(in_position, 1.0);
    gl_Position = frame.projection * V;
    // Section 2.11.3: n = (M^-1)^T n_object, not normalized.
    vec3 n = mat3(R(nm0).xyz, R(nm1).xyz, R(nm2).xyz) * in_normal;
    vec4 d_cm = R(diffuse);
    vec3 s_cm = R(specular).rgb;
    float s_rm = R(specular).w;

    vec3 c = frame.scene.rgb;

    // Light 0, directional: att = spot = 1; VP and the halfway vector are the frame's.
    float n_vp0 = max(dot(n, frame.l0_vp.xyz), 0.0);
    float f0 = n_vp0 != 0.0 ? 1.0 : 0.0;
    vec3 diffuse0 = n_vp0 * d_cm.rgb * frame.l0_diffuse.rgb;
    vec3 specular0 = f0 * pow_gl(max(dot(n, frame.l0_h.xyz), 0.0), s_rm) * s_cm * frame.l0_specular.rgb;
    c += frame.l0_ambient.rgb + diffuse0 + specular0;

    // Light 1, a point light: VP = unit(P - V), attenuated by 1 / (k0 + k1 d + k2 d^2).
    vec3 to_light = frame.l1_position.xyz - V.xyz;
    float d = length(to_light);
    vec3 vp1 = unit(to_light);
    float att1 = 1.0 / (frame.l1_k.x + frame.l1_k.y * d + frame.l1_k.z * d * d);
    float n_vp1 = max(dot(n, vp1), 0.0);
    float f1 = n_vp1 != 0.0 ? 1.0 : 0.0;
    vec3 h1 = unit(vp1 + vec3(0.0, 0.0, 1.0));
    vec3 diffuse1 = n_vp1 * d_cm.rgb * frame.l1_diffuse.rgb;
    vec3 specular1 = f1 * pow_gl(max(dot(n, h1), 0.0), s_rm) * s_cm * frame.l1_specular.rgb;
    c += att1 * (frame.l1_ambient.rgb + diffuse1 + specular1);

    // Section 2.14.6: clamped; alpha is the diffuse material's.
    out_color = clamp(vec4(c, d_cm.a), 0.0, 1.0);
}
