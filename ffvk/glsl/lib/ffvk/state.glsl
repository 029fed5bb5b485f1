// ffvk's shader library, interface version FFVK_LIBRARY_VERSION: GL 2.1's fixed-function state
// as the library's functions read it. The structs of one light, one face's material and one
// texture unit (src/gpu/layout.rs mirrors them, std140), the values of the state's enumerated
// members, and FFVK_STATE_MEMBERS, the members of the state block in std140 order. The caller
// declares the block where it chooses and names it:
//
//     layout(std140, set = 3, binding = 0) uniform FfvkState { FFVK_STATE_MEMBERS } ffvk_state;
//     #define FFVK_STATE ffvk_state
//
// before including the files that read it (spec.glsl's switches, lighting.glsl, ...).
#ifndef FFVK_STATE_GLSL
#define FFVK_STATE_GLSL

// The interface's version: a change of the state block's layout, of a function's inputs or
// outputs, of a specialization constant's meaning or ID, or of what the caller must define is
// a new version.
#define FFVK_LIBRARY_VERSION 2

// The loops the library unrolls: [[unroll]] (GL_EXT_control_flow_attributes, which a Vulkan
// caller's shader enables), nothing in GLSL ES (ffvk/es.glsl), which has no attributes.
#ifndef FFVK_UNROLL
#define FFVK_UNROLL [[unroll]]
#endif

#define MAX_LIGHTS 16

// Table 2.10, one face.
struct Material {
    vec4 a_cm;   // AMBIENT
    vec4 d_cm;   // DIFFUSE
    vec4 s_cm;   // SPECULAR
    vec4 e_cm;   // EMISSION
    float s_rm;  // SHININESS
};

// Table 2.10, one light; positions and directions already in eye space (glLight time).
struct Light {
    vec4 a_cli;       // AMBIENT
    vec4 d_cli;       // DIFFUSE
    vec4 s_cli;       // SPECULAR
    vec4 P_pli;       // POSITION
    vec3 s_dli;       // SPOT_DIRECTION
    float s_rli;      // SPOT_EXPONENT
    float c_rli;      // SPOT_CUTOFF, degrees
    float cos_c_rli;  // cos(c_rli), computed on the host in double precision
    float k0;         // CONSTANT_ATTENUATION
    float k1;         // LINEAR_ATTENUATION
    float k2;         // QUADRATIC_ATTENUATION
    uint spot_edge;   // EDGE_* (ffvk's extension; GL's is EDGE_GL_EXPONENT)
    float cos_inner;  // cos of a soft edge's inner angle, computed on the host
    uint falloff;     // FALLOFF_* (ffvk's extension; GL's is FALLOFF_GL_K012)
    float range;      // glTF's range, 0 for none
    // GL's derived state of a directional light (w = 0), computed on the host when the state
    // changes: the unit vector toward it (VP_pli of every finite vertex) and the unit halfway
    // vector of that and the infinite viewer's (0, 0, 1) (GLSL 1.20's halfVector). Zero for a
    // positional light.
    vec3 VP_hat_inf;
    vec3 h_hat_inf;
};

// Values of Light.spot_edge, Light.falloff and specular_model: GL's is 0 in each.
#define EDGE_GL_EXPONENT 0u
#define EDGE_LINEAR_INNER_OUTER 1u
#define EDGE_SMOOTHSTEP_INNER_OUTER 2u
#define FALLOFF_GL_K012 0u
#define FALLOFF_GLTF_INVERSE_SQUARE 1u
#define SPECULAR_BLINN_HALFWAY 0u
#define SPECULAR_PHONG_REFLECT 1u

// One texture unit's state (GL_TEXTUREi), GpuTextureUnit in src/gpu/layout.rs: read by the
// TEXTURE builds for the units SPEC_TEXTURE_UNITS names.
#define MAX_TEXTURE_UNITS 4
struct TextureUnitState {
    mat4 matrix;             // GL_TEXTURE matrix
    vec4 c_c;                // TEXTURE_ENV_COLOR
    vec4 texgen_planes[4];   // S, T, R, Q: OBJECT_PLANE or EYE_PLANE (p M^-1), as the mode reads
    uint env_mode;           // TEXTURE_ENV_MODE, TEV_* in texture.glsl
    uint combine;            // GL_COMBINE's state (Combine::code), read under TEXTURE_ENV_MODE COMBINE
    uint crossbar;           // GL_COMBINE's GL_TEXTUREn sources (Combine::crossbar_code)
    uint texgen;             // TEXTURE_GEN_S..Q with their modes, 3 bits each (texgen.glsl)
};

// Values of color_material_mode.
#define CM_EMISSION 0u
#define CM_AMBIENT 1u
#define CM_DIFFUSE 2u
#define CM_SPECULAR 3u
#define CM_AMBIENT_AND_DIFFUSE 4u

// The state block's members: GL's lighting state but a draw's own values (its materials, its
// current color and normal), with the stages around lighting. FFVK_STATE names the block.
#define FFVK_STATE_MEMBERS \
    mat4 projection;  /* GL projection, premultiplied by GL-to-Vulkan clip conversion */ \
    vec4 a_cs;  /* LIGHT_MODEL_AMBIENT */ \
    uint light_count;  /* enabled lights, packed in index order */ \
    uint lighting;  /* LIGHTING enabled */ \
    uint v_bs;  /* LIGHT_MODEL_LOCAL_VIEWER */ \
    uint t_bs;  /* LIGHT_MODEL_TWO_SIDE */ \
    uint separate_specular;  /* LIGHT_MODEL_COLOR_CONTROL == SEPARATE_SPECULAR_COLOR */ \
    uint color_material;  /* COLOR_MATERIAL enabled */ \
    uint color_material_front;  /* ColorMaterial face includes FRONT */ \
    uint color_material_back;  /* ColorMaterial face includes BACK */ \
    uint color_material_mode;  /* CM_* */ \
    uint normalize;  /* NORMALIZE enabled */ \
    uint specular_model;  /* SPECULAR_* (ffvk's extension) */ \
    uint color_sum;  /* COLOR_SUM */ \
    uint alpha_func;  /* ALPHA_TEST_FUNC, 0 NEVER .. 7 ALWAYS (7 while the test is off) */ \
    float alpha_ref;  /* ALPHA_TEST_REF, in [0, 1] */ \
    uint pad_0; \
    uint pad_1; \
    vec4 fog_color;  /* FOG_COLOR */ \
    float fog_start;  /* FOG_START */ \
    float fog_end;  /* FOG_END */ \
    float fog_density;  /* FOG_DENSITY */ \
    float fog_scale;  /* 1 / (FOG_END - FOG_START), 0 where they are equal */ \
    uint fog_mode;  /* 0 off, 1 LINEAR, 2 EXP, 3 EXP2 */ \
    uint fog_source;  /* 1 FOG_COORD, 0 FRAGMENT_DEPTH */ \
    uint fog_per_vertex;  /* 1 for FOG_HINT FASTEST */ \
    uint clip_mask;  /* the enabled CLIP_PLANEi, a bit each */ \
    vec4 clip_planes[6];  /* CLIP_PLANEi in eye space (glClipPlane's p M^-1) */ \
    TextureUnitState units[MAX_TEXTURE_UNITS]; \
    Light lights[MAX_LIGHTS];

#endif
