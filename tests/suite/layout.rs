//! The std140 layout of the `State` block and the locations of the draw record's attributes,
//! read from the SPIR-V glslang compiled, must match the Rust structs that fill them.

use std::collections::HashMap;
use std::mem::{offset_of, size_of};

use ffvk::gpu::layout::{
    DrawRecord, GpuLight, GpuTextureUnit, SpecConstant, SpecKey, StateBlock, RECORD_FIRST_LOCATION,
    RECORD_LOCATIONS, SPEC_CONSTANT_COUNT,
};

const OP_NAME: u32 = 5;
const OP_MEMBER_NAME: u32 = 6;
const OP_TYPE_ARRAY: u32 = 28;
const OP_TYPE_STRUCT: u32 = 30;
const OP_SPEC_CONSTANT: u32 = 50;
const OP_DECORATE: u32 = 71;
const OP_MEMBER_DECORATE: u32 = 72;
const DECORATION_SPEC_ID: u32 = 1;
const DECORATION_ARRAY_STRIDE: u32 = 6;
const DECORATION_OFFSET: u32 = 35;
const DECORATION_LOCATION: u32 = 30;
const DECORATION_BINDING: u32 = 33;
const DECORATION_DESCRIPTOR_SET: u32 = 34;

/// What a test needs of a module: struct names, member names and offsets, array strides.
#[derive(Default)]
struct Reflection {
    names: HashMap<u32, String>,
    member_names: HashMap<(u32, u32), String>,
    offsets: HashMap<(u32, u32), u32>,
    strides: HashMap<u32, u32>,
    struct_members: HashMap<u32, Vec<u32>>,
    array_element: HashMap<u32, u32>,
    /// SpecId decorations: result id to constant_id.
    spec_ids: HashMap<u32, u32>,
    /// OpSpecConstant default values (32-bit), by result id.
    spec_defaults: HashMap<u32, u32>,
    /// Location decorations: result id to location.
    locations: HashMap<u32, u32>,
    /// DescriptorSet and Binding decorations: result id to (set, binding).
    bindings: HashMap<u32, (Option<u32>, Option<u32>)>,
}

fn string(words: &[u32]) -> String {
    let bytes: Vec<u8> = words
        .iter()
        .flat_map(|w| w.to_le_bytes())
        .take_while(|&b| b != 0)
        .collect();
    String::from_utf8(bytes).unwrap()
}

fn reflect(spirv: &[u8]) -> Reflection {
    let words: Vec<u32> = spirv
        .chunks(4)
        .map(|c| u32::from_le_bytes(c.try_into().unwrap()))
        .collect();
    assert_eq!(words[0], 0x0723_0203, "SPIR-V magic");
    let mut r = Reflection::default();
    let mut at = 5;
    while at < words.len() {
        let (count, op) = ((words[at] >> 16) as usize, words[at] & 0xffff);
        let ins = &words[at + 1..at + count];
        match op {
            OP_NAME => {
                r.names.insert(ins[0], string(&ins[1..]));
            }
            OP_MEMBER_NAME => {
                r.member_names.insert((ins[0], ins[1]), string(&ins[2..]));
            }
            OP_MEMBER_DECORATE if ins[2] == DECORATION_OFFSET => {
                r.offsets.insert((ins[0], ins[1]), ins[3]);
            }
            OP_DECORATE if ins[1] == DECORATION_ARRAY_STRIDE => {
                r.strides.insert(ins[0], ins[2]);
            }
            OP_DECORATE if ins[1] == DECORATION_LOCATION => {
                r.locations.insert(ins[0], ins[2]);
            }
            OP_DECORATE if ins[1] == DECORATION_DESCRIPTOR_SET => {
                r.bindings.entry(ins[0]).or_default().0 = Some(ins[2]);
            }
            OP_DECORATE if ins[1] == DECORATION_BINDING => {
                r.bindings.entry(ins[0]).or_default().1 = Some(ins[2]);
            }
            OP_DECORATE if ins[1] == DECORATION_SPEC_ID => {
                r.spec_ids.insert(ins[0], ins[2]);
            }
            OP_SPEC_CONSTANT => {
                r.spec_defaults.insert(ins[1], ins[2]);
            }
            OP_TYPE_STRUCT => {
                r.struct_members.insert(ins[0], ins[1..].to_vec());
            }
            OP_TYPE_ARRAY => {
                r.array_element.insert(ins[0], ins[1]);
            }
            _ => {}
        }
        at += count;
    }
    r
}

impl Reflection {
    /// The block-layout struct named `name` (the one carrying Offset decorations).
    fn struct_id(&self, name: &str) -> u32 {
        *self
            .names
            .iter()
            .find(|(id, n)| *n == name && self.offsets.contains_key(&(**id, 0)))
            .unwrap_or_else(|| panic!("no laid-out struct {name} in the SPIR-V"))
            .0
    }

    /// (member name, offset) of every member of struct `id`.
    fn members(&self, id: u32) -> Vec<(String, u32)> {
        (0..self.struct_members[&id].len() as u32)
            .map(|m| (self.member_names[&(id, m)].clone(), self.offsets[&(id, m)]))
            .collect()
    }
}

/// Every compiled vertex and fragment stage of every variant, named `<variant>.<vert|frag>`
/// (the `_edges` builds' geometry stages: [`the_edges_geometry_stage_takes_only_the_front_face`]).
fn stages() -> Vec<(String, &'static [u8])> {
    let mut stages = Vec::new();
    for v in ffvk::gpu::shaders::VARIANTS {
        stages.push((format!("{}.vert", v.name), v.vertex));
        stages.push((format!("{}.frag", v.name), v.fragment));
    }
    assert_eq!(
        stages.len(),
        172,
        "eighty-six variants (nine, six of them also with fog, clip planes or both, each untextured \
         and textured; and the 32 `_edges` builds of four of them) of two stages"
    );
    stages
}

/// glsl/edges.geom, in each `_edges` build and no other: one specialization constant, the front
/// face at SpecId 0 (its own stage's, set by draw/pipeline.rs), and no block of the state or
/// the record.
#[test]
fn the_edges_geometry_stage_takes_only_the_front_face() {
    let mut edges = 0;
    for v in ffvk::gpu::shaders::VARIANTS {
        assert_eq!(
            v.geometry.is_some(),
            v.name.ends_with("_edges"),
            "{}: a geometry stage",
            v.name
        );
        let Some(spirv) = v.geometry else { continue };
        edges += 1;
        let r = reflect(spirv);
        let constants: Vec<(&str, u32)> = r
            .spec_ids
            .iter()
            .map(|(id, spec)| (r.names.get(id).map_or("(unnamed)", String::as_str), *spec))
            .collect();
        assert_eq!(constants, [("SPEC_FRONT_FACE_CW", 0)], "{}.geom", v.name);
        for block in ["State", "Record"] {
            assert!(
                !r.names.values().any(|n| n == block),
                "{}.geom declares {block}",
                v.name
            );
        }
    }
    assert_eq!(
        edges, 32,
        "vertex, flat, fragment and fragment_small: fog, clipped, textured"
    );
}

/// The deferred lighting pass's vertex stages: a full-screen triangle, no state, no record.
fn full_screen(stage: &str) -> bool {
    stage.starts_with("deferred") && stage.ends_with(".vert")
}

macro_rules! rust_offsets {
    ($ty:ty: $($field:ident),*) => {
        vec![$((stringify!($field).to_string(), offset_of!($ty, $field) as u32)),*]
    };
}

#[test]
fn the_state_block_matches_the_glsl_in_every_stage() {
    for (stage, spirv) in stages().into_iter().filter(|(s, _)| !full_screen(s)) {
        check_state_block(&reflect(spirv), "State", &stage);
    }
}

/// The block struct `name` of `r` has `StateBlock`'s members at `StateBlock`'s offsets, with
/// its lights and texture units laid out as `GpuLight` and `GpuTextureUnit` are.
fn check_state_block(r: &Reflection, name: &str, stage: &str) {
    {
        let block = r.struct_id(name);
        let want = rust_offsets!(StateBlock: projection, a_cs, light_count, lighting,
            v_bs, t_bs, separate_specular, color_material, color_material_front, color_material_back,
            color_material_mode, normalize, specular_model, color_sum, alpha_func, alpha_ref,
            pad_0, pad_1, fog_color, fog_start, fog_end, fog_density, fog_scale, fog_mode, fog_source, fog_per_vertex,
            clip_mask, clip_planes, units, lights);
        assert_eq!(r.members(block), want, "{stage}: State block offsets");

        let unit = r.struct_id("TextureUnitState");
        let want =
            rust_offsets!(GpuTextureUnit: matrix, c_c, texgen_planes, env_mode, combine, crossbar, texgen);
        assert_eq!(r.members(unit), want, "{stage}: TextureUnitState offsets");
        let units_type = r.struct_members[&block][28];
        assert_eq!(
            r.array_element[&units_type], unit,
            "{stage}: units is an array of TextureUnitState"
        );
        assert_eq!(
            r.strides[&units_type] as usize,
            size_of::<GpuTextureUnit>(),
            "{stage}: TextureUnitState array stride"
        );

        let light = r.struct_id("Light");
        let want = rust_offsets!(GpuLight: a_cli, d_cli, s_cli, P_pli, s_dli, s_rli, c_rli, cos_c_rli, k0, k1, k2, spot_edge, cos_inner, falloff, range, VP_hat_inf, h_hat_inf);
        assert_eq!(r.members(light), want, "{stage}: Light offsets");

        // The lights array: its stride is the Rust struct's size, and it ends the block.
        let members = &r.struct_members[&block];
        let lights_type = *members.last().unwrap();
        assert_eq!(
            r.array_element[&lights_type], light,
            "{stage}: lights is an array of Light"
        );
        assert_eq!(
            r.strides[&lights_type] as usize,
            size_of::<GpuLight>(),
            "{stage}: Light array stride"
        );
        assert_eq!(
            offset_of!(StateBlock, lights) + ffvk::gl::state::MAX_LIGHTS * size_of::<GpuLight>(),
            size_of::<StateBlock>(),
            "the lights end the block"
        );
    }
}

#[test]
fn the_record_block_of_the_fragment_stages_matches_the_draw_record() {
    let mut seen = 0;
    // The fragment mode's stages for large draws read it as a uniform block.
    for (stage, spirv) in stages().into_iter().filter(|(s, _)| {
        s.starts_with("fragment")
            && !s.starts_with("fragment_small")
            && !s.starts_with("fragment_gbuffer")
            && s.ends_with(".frag")
    }) {
        let r = reflect(spirv);
        let block = r.struct_id("Record");
        let want = rust_offsets!(
            DrawRecord: modelview,
            normal_matrix,
            front,
            back,
            current_color,
            current_normal,
            current_texcoord,
            current_secondary_color,
            current_unit_texcoords
        );
        assert_eq!(r.members(block), want, "{stage}: Record block offsets");
        seen += 1;
    }
    assert_eq!(
        seen, 16,
        "the fragment mode's fragment stages for large draws, textured or not, fogged or not, \
         clipped or not, with edge flags or not"
    );
    // The deferred lighting pass reads the frame's records as vec4s, at these indices of a
    // record's (deferred.frag): the normal matrix's columns (w: the shininesses) at 4 and 5,
    // the front material at 7-10, the back's at 11-14.
    assert_eq!(offset_of!(DrawRecord, normal_matrix) / 16, 4);
    assert_eq!(offset_of!(DrawRecord, front) / 16, 7);
    assert_eq!(offset_of!(DrawRecord, back) / 16, 11);
    assert_eq!(size_of::<DrawRecord>() % 16, 0, "a record is whole vec4s");
}

#[test]
fn the_draw_records_attributes_sit_at_the_locations_the_vertex_stages_read() {
    let at = |offset: usize| RECORD_FIRST_LOCATION + (offset / 16) as u32;
    let nm = offset_of!(DrawRecord, normal_matrix);
    let (front, back) = (offset_of!(DrawRecord, front), offset_of!(DrawRecord, back));
    let want = [
        ("in_modelview", at(offset_of!(DrawRecord, modelview))),
        ("in_normal_matrix_0", at(nm)),
        ("in_normal_matrix_1", at(nm + 16)),
        ("in_normal_matrix_2", at(nm + 32)),
        ("in_front_a_cm", at(front)),
        ("in_front_d_cm", at(front + 16)),
        ("in_front_s_cm", at(front + 32)),
        ("in_front_e_cm", at(front + 48)),
        ("in_back_a_cm", at(back)),
        ("in_back_d_cm", at(back + 16)),
        ("in_back_s_cm", at(back + 32)),
        ("in_back_e_cm", at(back + 48)),
        // The shininesses have locations of their own after the record's vec4s (a layout may
        // give them per vertex), read from the normal matrix's first two columns' w.
        ("in_front_s_rm", RECORD_FIRST_LOCATION + 15),
        ("in_back_s_rm", RECORD_FIRST_LOCATION + 16),
        // Units 1-3's texture coordinates: the layout's arrays or the record's current ones.
        ("in_texcoord_1", 23),
        ("in_texcoord_2", 24),
        ("in_texcoord_3", 25),
    ];
    assert_eq!(RECORD_LOCATIONS, 17, "15 vec4s and two shininesses");
    for (stage, spirv) in stages()
        .into_iter()
        .filter(|(s, _)| s.ends_with(".vert") && !full_screen(s))
    {
        let r = reflect(spirv);
        let mut seen = 0;
        for (name, location) in want {
            let found: Vec<u32> = r
                .names
                .iter()
                .filter(|(_, n)| n.as_str() == name)
                .filter_map(|(id, _)| r.locations.get(id).copied())
                .collect();
            // glslang keeps only the inputs a stage reads; each one it keeps is where the
            // record's attribute descriptions put it (their offsets: vertex_input.rs's tests).
            assert!(
                found.iter().all(|&l| l == location),
                "{stage}: {name} at {found:?}, expected {location}"
            );
            seen += found.len();
        }
        assert!(
            seen >= 12,
            "{stage}: only {seen} of the record's attributes found"
        );
    }
}

/// The stages that evaluate the lighting equation, and so read every specialization constant.
const LIGHTING_STAGES: [&str; 8] = [
    "vertex.vert",
    "vertex_one_color.vert",
    "flat.vert",
    "flat_one_color.vert",
    "fragment.frag",
    "fragment_small.frag",
    "deferred.frag",
    "deferred_counted.frag",
];

#[test]
fn specialization_constant_ids_match_the_rust_side() {
    for (stage, spirv) in stages() {
        let r = reflect(spirv);
        let mut found = Vec::new();
        for (&id, &spec_id) in &r.spec_ids {
            let name = r.names.get(&id).map(String::as_str).unwrap_or("(unnamed)");
            // glsl/stipple.glsl's, which only stippled pipelines set (draw/stipple.rs): the
            // stipple right after the others, its 32 rows after it.
            if let Some(row) = name.strip_prefix("SPEC_STIPPLE") {
                let at = row
                    .strip_prefix("_ROW_")
                    .map_or(0, |r| r.parse::<u32>().unwrap() + 1);
                assert_eq!(
                    spec_id,
                    SPEC_CONSTANT_COUNT as u32 + at,
                    "{stage}: SpecId of {name}"
                );
                continue;
            }
            let constant = SpecConstant::ALL
                .into_iter()
                .find(|c| c.glsl_name() == name)
                .unwrap_or_else(|| panic!("{stage}: {name} (SpecId {spec_id}) has no SpecConstant"));
            assert_eq!(constant.id(), spec_id, "{stage}: SpecId of {name}");
            // The default, -1, is the uber-shader's "read the uniform"; the point size's, a
            // float, is GL's 1.
            let default = match constant {
                SpecConstant::PointSize => 1.0f32.to_bits() as i32,
                // The layout's and target's constants, set in every pipeline: no conversion,
                // the record's 22 vec4s, a float alpha compare.
                SpecConstant::GlSnorm => 0,
                SpecConstant::RecordVec4s => 22,
                // A textured pipeline's units, set in every one: unit 0 sampled and applied.
                SpecConstant::TextureUnits => 0x11,
                SpecConstant::AlphaBits => 0,
                // The point constants' "off" values: no attenuation, (a, b, c) = (1, 0, 0),
                // the clamp [0, FLT_MAX], no sprite.
                SpecConstant::PointAttenuation => 0,
                SpecConstant::PointAttenuationA => 1.0f32.to_bits() as i32,
                SpecConstant::PointAttenuationB | SpecConstant::PointAttenuationC => 0,
                SpecConstant::PointSizeMin => 0,
                SpecConstant::PointSizeMax => f32::MAX.to_bits() as i32,
                SpecConstant::PointSprite => 0,
                _ => -1,
            };
            assert_eq!(
                r.spec_defaults.get(&id).map(|&v| v as i32),
                Some(default),
                "{stage}: default of {name}"
            );
            found.push(constant);
        }
        // The equation's stages read every constant but the texture environment's, which
        // the textured fragment stages read.
        let untextured = stage.replace("_textured", "");
        if LIGHTING_STAGES.contains(&untextured.as_str()) {
            for c in SpecConstant::ALL
                .into_iter()
                .filter(|&c| c != SpecConstant::TexEnv)
            {
                assert!(found.contains(&c), "{stage} does not declare {}", c.glsl_name());
            }
        }
        if stage.ends_with("_textured.frag") {
            assert!(
                found.contains(&SpecConstant::TexEnv),
                "{stage} does not declare SPEC_TEX_ENV"
            );
        }
    }
    // The key's bytes are the specialization data: constant i at offset 4 i.
    for (i, c) in SpecConstant::ALL.into_iter().enumerate() {
        assert_eq!(c.id() as usize, i, "SpecConstant::ALL is in constant_id order");
    }
    assert_eq!(size_of::<SpecKey>(), 4 * SPEC_CONSTANT_COUNT);
    assert_eq!(SpecKey::UBER.values, [-1; SPEC_CONSTANT_COUNT]);
}

#[test]
fn the_embedding_guide_states_the_block_and_record_sizes_and_the_constant_ids_the_code_has() {
    let guide = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/embedding-rust.md");
    let guide = std::fs::read_to_string(guide).unwrap();
    let size = size_of::<StateBlock>();
    let with_comma = format!("{},{:03}", size / 1000, size % 1000);
    let block = format!("one {with_comma}-byte block of GL state per change of state");
    assert!(
        guide.contains(&block),
        "docs/embedding-rust.md should say \"{block}\""
    );
    let record = format!("one {}-byte record per draw", size_of::<DrawRecord>());
    assert!(
        guide.contains(&record),
        "docs/embedding-rust.md should say \"{record}\""
    );
    let ids = format!("constant_id 0-{}", SPEC_CONSTANT_COUNT - 1);
    assert!(
        guide.contains(&ids),
        "docs/embedding-rust.md should say \"{ids}\""
    );
}

/// A fragment shader of a caller's own around the library: its state block at set 3, binding 1,
/// a constant of its own at ID 0; `SPEC_LINES` is replaced by the caller's choice of
/// specialization.
const CALLER: &str = r#"#version 450
#extension GL_EXT_control_flow_attributes : require
SPEC_LINES
#include "ffvk/state.glsl"
layout(std140, set = 3, binding = 1) uniform FfvkState { FFVK_STATE_MEMBERS } ffvk_state;
#define FFVK_STATE ffvk_state
#define FFVK_HIDDEN_ZERO uint(gl_FragCoord.x < 0.0)
layout(constant_id = 0) const int MY_OWN = 7;
#include "ffvk/lighting.glsl"
#include "ffvk/material.glsl"
#include "ffvk/stages.glsl"
layout(location = 0) in vec4 eye;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;
layout(location = 3) flat in vec4 material[5];
layout(location = 0) out vec4 out_color;
void main() {
    Material m = Material(material[0], material[1], material[2], material[3], material[4].x);
    Material face = face_material(m, m, !gl_FrontFacing, color);
    LitColor lit = light_equation(eye, normalize(normal), face);
    out_color = apply_fog(color_sum(lit), abs(eye.z)) * float(MY_OWN);
    if (!alpha_passes(out_color.a)) discard;
}
"#;

/// glslc's SPIR-V of `source` (a fragment stage) with the library inlined by
/// `shaders::resolve`, as a compiler without `#include` takes it; or its messages.
fn glslc(name: &str, source: &str) -> Result<Vec<u8>, String> {
    let resolved = ffvk::shaders::resolve(source).map_err(|e| e.to_string())?;
    let dir = crate::support::output_dir().join("shader_library");
    std::fs::create_dir_all(&dir).unwrap();
    let (glsl, spv) = (
        dir.join(format!("{name}.frag")),
        dir.join(format!("{name}.frag.spv")),
    );
    std::fs::write(&glsl, &resolved).unwrap();
    let glslc = std::env::var_os("GLSLC").unwrap_or_else(|| "glslc".into());
    let out = std::process::Command::new(glslc)
        .args([
            "-fshader-stage=frag",
            "--target-env=vulkan1.3",
            "-O0",
            "-Werror",
            "-o",
        ])
        .arg(&spv)
        .arg(&glsl)
        .output()
        .expect("glslc runs (the build needs it too)");
    if !out.status.success() {
        return Err(String::from_utf8_lossy(&out.stderr).into_owned());
    }
    Ok(std::fs::read(&spv).unwrap())
}

/// A shader of a caller's own that includes the shader library, its state block at the set and
/// binding it chooses and the library's constants from ID 100, beside a constant of its own at
/// ID 0: the block's members sit where `StateBlock` puts them, and each library constant's ID
/// is its `SpecConstant`'s plus the base.
#[test]
fn a_callers_shader_places_the_librarys_block_and_constants_where_it_chooses() {
    let source = CALLER.replace("SPEC_LINES\n", "#define FFVK_SPEC_BASE 100\n");
    let r = reflect(&glslc("caller", &source).unwrap_or_else(|e| panic!("{e}")));
    check_state_block(&r, "FfvkState", "the caller's shader");
    let variable = r
        .names
        .iter()
        .find(|(_, n)| *n == "ffvk_state")
        .map(|(id, _)| *id)
        .unwrap();
    assert_eq!(
        r.bindings[&variable],
        (Some(3), Some(1)),
        "the block's set and binding"
    );
    let mut library = 0;
    for (&id, &spec_id) in &r.spec_ids {
        let name = r.names[&id].as_str();
        if name == "MY_OWN" {
            assert_eq!(spec_id, 0);
            continue;
        }
        let constant = SpecConstant::ALL
            .into_iter()
            .find(|c| c.glsl_name() == name)
            .unwrap();
        assert_eq!(spec_id, 100 + constant.id(), "SpecId of {name}");
        library += 1;
    }
    assert!(
        library >= 20,
        "only {library} of the library's constants were declared"
    );
}

/// The library's switches as plain constants (`FFVK_SPEC_AS_DEFINES` with
/// `shaders::spec_defines` of a state's `SpecKey`): the shader compiles and declares none of
/// the library's specialization constants (the caller's own stays), and a value left out fails
/// the compile, naming it, rather than defaulting.
#[test]
fn the_librarys_switches_compile_as_defines_of_a_states_values() {
    let mut gl = ffvk::gl::state::GlState::new();
    gl.enable(ffvk::gl::state::Cap::Lighting).unwrap();
    gl.enable(ffvk::gl::state::Cap::Light(0)).unwrap();
    let mut key = SpecKey::for_state(&gl.lighting);
    // A pipeline's own constants are the caller's to set, as ffvk sets them per pipeline.
    key.values[SpecConstant::PointSizeMax as usize] = f32::MAX.to_bits() as i32;
    key.values[SpecConstant::PointSize as usize] = 1.5f32.to_bits() as i32;
    let defines = ffvk::shaders::spec_defines(&key);
    assert!(defines.contains("#define SPEC_POINT_SIZE 1.5\n"), "{defines}");
    assert!(defines.contains("#define SPEC_LIGHT_COUNT 1\n"), "{defines}");
    assert!(
        defines.contains("#define SPEC_POINT_SIZE_MAX 3.4028235e38\n"),
        "{defines}"
    );
    let spirv =
        glslc("caller_defines", &CALLER.replace("SPEC_LINES\n", &defines)).unwrap_or_else(|e| panic!("{e}"));
    let r = reflect(&spirv);
    let names: Vec<&str> = r.spec_ids.keys().map(|id| r.names[id].as_str()).collect();
    assert_eq!(names, ["MY_OWN"], "only the caller's own constant is specialized");
    check_state_block(&r, "FfvkState", "the caller's shader, defines");
    let short = defines.replace("#define SPEC_FOG_MODE ", "#define UNUSED_VALUE ");
    let e = glslc("caller_short", &CALLER.replace("SPEC_LINES\n", &short)).unwrap_err();
    assert!(e.contains("SPEC_FOG_MODE"), "{e}");
}

/// The block layout tables of docs/shader-library.md (each row `| offset | \`member\` | ...`,
/// under the heading naming the struct) against a caller's shader's SPIR-V: every member, in
/// order, at the offset the guide states, and the arrays' strides.
#[test]
fn the_shader_library_guide_states_the_block_layout_the_spirv_has() {
    let guide = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/shader-library.md");
    let guide = std::fs::read_to_string(guide).unwrap();
    let source = CALLER.replace("SPEC_LINES\n", "#define FFVK_SPEC_BASE 100\n");
    let r = reflect(&glslc("caller_guide", &source).unwrap_or_else(|e| panic!("{e}")));
    for (heading, name) in [
        ("#### The state block", "FfvkState"),
        ("#### `Light`", "Light"),
        ("#### `TextureUnitState`", "TextureUnitState"),
    ] {
        let at = guide
            .find(heading)
            .unwrap_or_else(|| panic!("docs/shader-library.md has no heading {heading:?}"));
        let rows: Vec<(String, u32)> = guide[at..]
            .lines()
            .skip(1)
            .skip_while(|l| !l.starts_with('|'))
            .take_while(|l| l.starts_with('|'))
            .filter_map(|l| {
                let cells: Vec<&str> = l.split('|').map(str::trim).collect();
                let offset = cells.get(1)?.replace(',', "").parse().ok()?;
                Some((cells.get(2)?.trim_matches('`').to_string(), offset))
            })
            .collect();
        let want = r.members(r.struct_id(name));
        assert_eq!(
            rows, want,
            "docs/shader-library.md, {heading}: (member, offset) in order"
        );
    }
    for (what, stride) in [
        ("`Light` array stride", size_of::<GpuLight>()),
        ("`TextureUnitState` array stride", size_of::<GpuTextureUnit>()),
        ("block size", size_of::<StateBlock>()),
    ] {
        let phrase = format!("{what} {}", stride);
        assert!(
            guide.contains(&phrase),
            "docs/shader-library.md should say \"{phrase}\""
        );
    }
}

/// The guide's Vulkan snippet (docs/shader-library.md, "What your shader defines") with a
/// `main` added compiles, its block at the set and binding it states.
#[test]
fn the_shader_library_guides_vulkan_snippet_compiles() {
    let guide = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/shader-library.md");
    let guide = std::fs::read_to_string(guide).unwrap();
    let snippet = guide
        .split("```glsl\n")
        .skip(1)
        .map(|s| s.split("```").next().unwrap())
        .find(|s| s.starts_with("#version 450"))
        .expect("docs/shader-library.md has a Vulkan GLSL snippet");
    let source = format!(
        "{snippet}layout(location = 0) out vec4 out_color;\nvoid main() {{ out_color = vec4(float(lighting_enabled())); }}\n"
    );
    let r = reflect(&glslc("guide_snippet", &source).unwrap_or_else(|e| panic!("{e}")));
    check_state_block(&r, "FfvkState", "the guide's snippet");
}
