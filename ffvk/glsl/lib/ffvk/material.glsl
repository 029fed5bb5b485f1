// ffvk's shader library: one face's material with COLOR_MATERIAL applied (section 2.14.3).
#ifndef FFVK_MATERIAL_GLSL
#define FFVK_MATERIAL_GLSL

#include "ffvk/switches.glsl"

// The material of one face (the back face's where back_face is true), with COLOR_MATERIAL
// applied for the current color c: `front` and `back` are the draw's materials, wherever the
// caller keeps them (a draw record, uniforms, vertex attributes).
Material face_material(Material front, Material back, bool back_face, vec4 c) {
    Material m = back_face ? back : front;
    if (color_material_enabled()) {
        // Selects rather than ifs on the face and mode, which are uniform values: lavapipe
        // compiles a shader variant per draw for an if on uniform values alone (see
        // light_term). all() and any() do not short-circuit, and mix() with a bvec4 is an
        // OpSelect in the SPIR-V (glslang turns ?: into one only between plain variables).
        bool tracks = back_face ? FFVK_STATE.color_material_back != 0u : FFVK_STATE.color_material_front != 0u;
        uint mode = FFVK_STATE.color_material_mode;
        bool ambient = any(bvec2(mode == CM_AMBIENT, mode == CM_AMBIENT_AND_DIFFUSE));
        bool diffuse = any(bvec2(mode == CM_DIFFUSE, mode == CM_AMBIENT_AND_DIFFUSE));
        m.e_cm = mix(m.e_cm, c, bvec4(all(bvec2(tracks, mode == CM_EMISSION))));
        m.a_cm = mix(m.a_cm, c, bvec4(all(bvec2(tracks, ambient))));
        m.d_cm = mix(m.d_cm, c, bvec4(all(bvec2(tracks, diffuse))));
        m.s_cm = mix(m.s_cm, c, bvec4(all(bvec2(tracks, mode == CM_SPECULAR))));
    }
    return m;
}


#endif
