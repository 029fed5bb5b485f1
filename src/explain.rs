//! `ffvk explain`: every term of the equation at one pixel, from the CPU reference.

use std::fmt::Write as _;

use glam::{DVec3, DVec4};

use ffvk::gl::state::{Attenuation, Face, Light, LightingMode, SpecularModel, SpotEdge};
use ffvk::reference::{self, Coverage, EyeVertex, LightTerms, Lit};
use ffvk::scene::Scene;

/// The surface at a pixel: which mesh and triangle, and where in it.
pub struct Hit {
    pub mesh: usize,
    pub triangle: usize,
    pub vertices: [usize; 3],
    pub coverage: Coverage,
    pub depth: f64,
}

/// The nearest triangle whose interior holds the center of pixel (x, y), row 0 at the top,
/// among those the mesh's culling keeps.
pub fn find_surface(scene: &Scene, x: u32, y: u32) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    for (mi, mesh) in scene.meshes.iter().enumerate() {
        let state = scene.draw_state(mesh);
        let cull = scene.cull_face(mesh);
        let modelview = scene.modelview(mesh);
        let clip: Vec<DVec4> = mesh
            .data
            .vertices
            .iter()
            .map(|v| reference::transform(&state, modelview, scene.projection, v).clip)
            .collect();
        // Points and lines cover no area explain can describe: only triangle lists are hit.
        if mesh.data.topology != ffvk::Topology::TriangleList {
            continue;
        }
        for (ti, t) in mesh.data.indices.chunks_exact(3).enumerate() {
            let idx = [t[0] as usize, t[1] as usize, t[2] as usize];
            let c = idx.map(|i| clip[i]);
            if c.iter().any(|c| c.w <= 0.0) {
                continue; // behind the eye: clipped away, not something explain handles
            }
            let Some(cov) = reference::coverage(c, scene.width, scene.height, x, y) else {
                continue;
            };
            let culled = match cull {
                None => false,
                Some(Face::Back) => !cov.front,
                Some(Face::Front) => cov.front,
                Some(Face::FrontAndBack) => true,
            };
            if culled {
                continue;
            }
            let w = cov.weights;
            let depth = (c[0].z / c[0].w) * w.x + (c[1].z / c[1].w) * w.y + (c[2].z / c[2].w) * w.z;
            if !(-1.0..=1.0).contains(&depth) {
                continue;
            }
            if best.as_ref().is_none_or(|b| !scene.depth_test || depth < b.depth) {
                best = Some(Hit {
                    mesh: mi,
                    triangle: ti,
                    vertices: idx,
                    coverage: cov,
                    depth,
                });
            }
        }
    }
    best
}

fn rgb(v: DVec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z)
}

fn rgba(v: DVec4) -> String {
    format!("({:.4}, {:.4}, {:.4}, {:.4})", v.x, v.y, v.z, v.w)
}

fn bytes(v: DVec4) -> String {
    let b = |c: f64| (c.clamp(0.0, 1.0) * 255.0).round() as u8;
    format!("[{}, {}, {}, {}]", b(v.x), b(v.y), b(v.z), b(v.w))
}

/// How a light's att_i came about: the attenuation's name and its inputs.
fn attenuation_terms(t: &LightTerms, l: &Light) -> String {
    match (t.distance, t.attenuation) {
        (None, _) => "directional, never attenuated".into(),
        (Some(d), Attenuation::GlK012) => format!(
            "gl_k012: 1 / (k0 + k1 d + k2 d²), k0 {} k1 {} k2 {} d {d:.4}",
            l.constant_attenuation, l.linear_attenuation, l.quadratic_attenuation
        ),
        (Some(d), Attenuation::GltfInverseSquare { range: None }) => {
            format!("gltf_inverse_square: 1 / d², d {d:.4}, no range")
        }
        (Some(d), Attenuation::GltfInverseSquare { range: Some(r) }) => {
            format!("gltf_inverse_square: clamp(1 − (d / range)⁴, 0, 1) / d², d {d:.4}, range {r}")
        }
        (Some(d), other) => format!("{other:?}, d {d:.4}"),
    }
}

/// How a light's spot_i came about: the edge's name and its inputs.
fn spot_terms(t: &LightTerms, l: &Light) -> String {
    let Some(c) = t.cos_spot else {
        return "no cone (c_rli = 180)".into();
    };
    let outer = l.spot_cutoff;
    match t.spot_edge {
        SpotEdge::GlExponent => format!(
            "gl_exponent: (cos θ)^s_rli inside c_rli, cos θ {c:.4}, c_rli {outer}°, s_rli {}",
            l.spot_exponent
        ),
        SpotEdge::LinearInnerOuter { inner_degrees } => format!(
            "linear_inner_outer: clamp((cos θ − cos outer) / (cos inner − cos outer), 0, 1), cos θ {c:.4}, outer {outer}°, inner {inner_degrees}°"
        ),
        SpotEdge::SmoothstepInnerOuter { inner_degrees } => format!(
            "smoothstep_inner_outer: smoothstep(cos outer, cos inner, cos θ), cos θ {c:.4}, outer {outer}°, inner {inner_degrees}°"
        ),
        other => format!("{other:?}, cos θ {c:.4}, outer {outer}°"),
    }
}

/// Writes the terms of one evaluation of the equation; `indices` are the GL indices of the
/// enabled lights, in the order the sum runs.
fn terms(out: &mut String, indent: &str, lit: &Lit, indices: &[usize], lights: &[Light]) {
    let _ = writeln!(out, "{indent}e_cm (emission)            {}", rgb(lit.emission));
    let _ = writeln!(
        out,
        "{indent}a_cm * a_cs (scene ambient) {}",
        rgb(lit.scene_ambient)
    );
    let specular = match lit.specular_model {
        SpecularModel::BlinnHalfway => "f_i (n ⊙ ĥ_i)^s_rm s_cm * s_cli",
        SpecularModel::PhongReflect => "f_i (r_i ⊙ v)^s_rm s_cm * s_cli",
        _ => "f_i (specular term)^s_rm s_cm * s_cli",
    };
    for (i, t) in indices.iter().zip(&lit.lights) {
        let l = &lights[*i];
        let _ = writeln!(
            out,
            "{indent}GL_LIGHT{i}: att_i {:.4}  spot_i {:.4}  f_i {}",
            t.att_i, t.spot_i, t.f_i
        );
        let _ = writeln!(out, "{indent}  att_i  {}", attenuation_terms(t, l));
        let _ = writeln!(out, "{indent}  spot_i {}", spot_terms(t, l));
        let _ = writeln!(out, "{indent}  a_cm * a_cli               {}", rgb(t.ambient));
        let _ = writeln!(out, "{indent}  (n ⊙ VP_pli) d_cm * d_cli  {}", rgb(t.diffuse));
        let _ = writeln!(
            out,
            "{indent}  {specular} {}  ({}, factor {:.4})",
            rgb(t.specular),
            lit.specular_model.name(),
            t.specular_factor
        );
    }
    let _ = writeln!(out, "{indent}c_pri (clamped)            {}", rgba(lit.c_pri));
    let _ = writeln!(out, "{indent}c_sec (clamped)            {}", rgba(lit.c_sec));
}

/// The explanation of pixel (x, y) in `mode`, or `None` when nothing covers it.
pub fn explain(scene: &Scene, x: u32, y: u32, mode: LightingMode) -> Option<String> {
    let hit = find_surface(scene, x, y)?;
    let mesh = &scene.meshes[hit.mesh];
    let mut state = scene.draw_state(mesh);
    state.mode = mode;
    let modelview = scene.modelview(mesh);
    let verts = hit.vertices.map(|i| &mesh.data.vertices[i]);
    let eye: [EyeVertex; 3] = verts.map(|v| reference::transform(&state, modelview, scene.projection, v));
    let back = !hit.coverage.front;
    let w = hit.coverage.weights;

    let mut out = String::new();
    let _ = writeln!(
        out,
        "pixel ({x}, {y}) of {} ({}x{}), {} mode",
        scene.path.display(),
        scene.width,
        scene.height,
        mode.name()
    );
    let _ = writeln!(
        out,
        "surface: mesh {:?} triangle {} (vertices {:?}), {} face, window depth {:.5}",
        mesh.name,
        hit.triangle,
        hit.vertices,
        if back { "back" } else { "front" },
        hit.depth * 0.5 + 0.5
    );
    let _ = writeln!(
        out,
        "perspective-correct weights: ({:.4}, {:.4}, {:.4})",
        w.x, w.y, w.z
    );
    for note in &scene.notes {
        let _ = writeln!(out, "scene: {note}");
    }
    if let Some(meaning) = &mesh.gltf {
        let _ = writeln!(out, "glTF meaning for this mesh: {}", meaning.describe());
    }
    let indices: Vec<usize> = (0..state.lights.len())
        .filter(|&i| state.lights[i].enabled)
        .collect();
    let two_sided_back = back && state.model.two_side;
    let _ = writeln!(
        out,
        "material: {} material{}",
        if two_sided_back { "back" } else { "front" },
        if two_sided_back {
            ", normal negated (two-sided lighting)"
        } else {
            ""
        }
    );
    if !state.lighting {
        let _ = writeln!(out, "LIGHTING is disabled: the vertex color passes through.");
    }

    // The terms are printed from here; the colors at the pixel come from pixel_terms below.
    match mode {
        LightingMode::Vertex | LightingMode::Flat => {
            let shown: Vec<usize> = if mode == LightingMode::Flat {
                vec![2]
            } else {
                vec![0, 1, 2]
            };
            let mut pri = DVec4::ZERO;
            let mut sec = DVec4::ZERO;
            for k in 0..3 {
                let e = &eye[k];
                let lit = reference::light_face(&state, e.eye, e.normal, e.color, back);
                let weight = if mode == LightingMode::Flat {
                    [0.0, 0.0, 1.0][k]
                } else {
                    w[k]
                };
                if !shown.contains(&k) {
                    continue;
                }
                let _ = writeln!(
                    out,
                    "vertex {} (index {}){}: eye {}, normal {}, color {}",
                    k,
                    hit.vertices[k],
                    if mode == LightingMode::Flat {
                        " [provoking: the triangle's last vertex]"
                    } else {
                        ""
                    },
                    rgba(e.eye),
                    rgb(e.normal),
                    rgba(e.color)
                );
                if state.lighting {
                    terms(&mut out, "  ", &lit, &indices, &state.lights);
                }
                let (p, s) = reference::vertex_color(&state, e, back);
                pri += p * weight;
                sec += s * weight;
            }
            if mode == LightingMode::Vertex {
                let _ = writeln!(out, "interpolated c_pri {}  c_sec {}", rgba(pri), rgba(sec));
            }
        }
        LightingMode::Fragment => {
            let p = eye[0].eye * w.x + eye[1].eye * w.y + eye[2].eye * w.z;
            let c = eye[0].color * w.x + eye[1].color * w.y + eye[2].color * w.z;
            let _ = writeln!(out, "fragment: eye {}, color {}", rgba(p), rgba(c));
            if state.lighting {
                let unit = |v: DVec3| {
                    if v.length() > 0.0 {
                        v / v.length()
                    } else {
                        DVec3::ZERO
                    }
                };
                let dir = unit(eye[0].normal) * w.x + unit(eye[1].normal) * w.y + unit(eye[2].normal) * w.z;
                let len = eye[0].normal.length() * w.x
                    + eye[1].normal.length() * w.y
                    + eye[2].normal.length() * w.z;
                let n = unit(dir) * len;
                let _ = writeln!(
                    out,
                    "fragment normal (renormalized direction × interpolated length) {}",
                    rgb(n)
                );
                terms(
                    &mut out,
                    "  ",
                    &reference::light_face(&state, p, n, c, back),
                    &indices,
                    &state.lights,
                );
            }
        }
    }
    let bound = mesh.texture.as_ref().map(|t| (&*t.image, &t.sampling));
    let pixel = reference::pixel_terms(&state, modelview, scene.projection, verts, hit.coverage, bound);
    match (&mesh.texture, pixel.textured) {
        (Some(t), Some(tex)) => {
            let image = &t.image;
            let _ = writeln!(
                out,
                "texture: {} ({}x{}, {} level(s){}), min {} mag {}, wrap {} {}, env {}",
                t.source,
                image.width(),
                image.height(),
                image.levels().len(),
                if image.srgb { ", sRGB" } else { "" },
                t.sampling.min_filter.name(),
                t.sampling.mag_filter.name(),
                t.sampling.wrap_s.name(),
                t.sampling.wrap_t.name(),
                t.unit.env_mode.name()
            );
            let _ = writeln!(
                out,
                "  (s/q, t/q) ({:.4}, {:.4}), texel ({:.2}, {:.2}) of level 0, λ {:.3}",
                tex.st.x,
                tex.st.y,
                tex.st.x * image.width() as f64,
                tex.st.y * image.height() as f64,
                tex.lambda
            );
            let _ = writeln!(
                out,
                "  C_s, A_s (filtered texel)  {} = {}",
                rgba(tex.texel),
                bytes(tex.texel)
            );
            let _ = writeln!(out, "  C_f, A_f (c_pri)           {}", rgba(pixel.c_pri));
            let _ = writeln!(
                out,
                "  C_v, A_v ({})         {}",
                t.unit.env_mode.name(),
                rgba(tex.env)
            );
            let _ = writeln!(out, "  c_sec, added after texturing {}", rgba(pixel.c_sec));
        }
        (Some(t), None) => {
            let _ = writeln!(
                out,
                "texture: {} textures nothing (GL_TEXTURE_2D off, or incomplete: min filter {} without mipmaps)",
                t.source,
                t.sampling.min_filter.name()
            );
        }
        (None, _) => {}
    }
    let color = pixel.color;
    let _ = writeln!(
        out,
        "final color (clamp(c_pri + c_sec), alpha of c_pri; textured: C_v for c_pri) {} = {}",
        rgba(color),
        bytes(color)
    );
    Some(out)
}
