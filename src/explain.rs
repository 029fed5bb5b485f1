//! `ffvk explain`: every term of the equation at one pixel, from the CPU reference.

use std::fmt::Write as _;

use glam::{DVec3, DVec4};

use ffvk::gl::state::{Attenuation, Face, FogMode, FogSource, Light, LightingMode, SpecularModel, SpotEdge};
use ffvk::reference::{self, Coverage, EyeVertex, LightTerms, Lit};
use ffvk::scene::Scene;

mod units;

/// The surface at a pixel: which mesh and triangle, and where in it.
pub struct Hit {
    pub mesh: usize,
    pub triangle: usize,
    pub vertices: [usize; 3],
    pub coverage: Coverage,
    pub depth: f64,
}

/// The surface pixel (x, y) shows in `mode`: the first of [`surfaces_at`] whose fragment the
/// user clip planes and the alpha test keep.
pub fn find_surface(scene: &Scene, x: u32, y: u32, mode: LightingMode) -> Option<Hit> {
    surfaces_at(scene, x, y)
        .into_iter()
        .find(|hit| pixel_terms(scene, hit, mode).kept)
}

/// The CPU reference's terms for `hit` drawn in `mode`.
pub fn pixel_terms(scene: &Scene, hit: &Hit, mode: LightingMode) -> reference::PixelTerms {
    let mesh = &scene.meshes[hit.mesh];
    let mut state = scene.draw_state(mesh);
    state.mode = mode;
    let verts = hit.vertices.map(|i| &mesh.data.vertices[i]);
    reference::pixel_terms(
        &state,
        scene.modelview(mesh),
        scene.projection,
        verts,
        hit.coverage,
        mesh.draw_textures().for_triangle(&mesh.data, hit.vertices),
    )
}

/// Every triangle whose interior holds the center of pixel (x, y), row 0 at the top, among
/// those the mesh's culling keeps, the one drawn on top first: by depth with the depth test
/// on (the nearest first, the earlier drawn first among equals, as `GL_LESS` keeps it), in
/// reverse drawing order without it.
pub fn surfaces_at(scene: &Scene, x: u32, y: u32) -> Vec<Hit> {
    let mut hits: Vec<Hit> = Vec::new();
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
            hits.push(Hit {
                mesh: mi,
                triangle: ti,
                vertices: idx,
                coverage: cov,
                depth,
            });
        }
    }
    if scene.depth_test {
        // A stable sort: among equal depths the earlier drawn stays first.
        hits.sort_by(|a, b| a.depth.total_cmp(&b.depth));
    } else {
        hits.reverse();
    }
    hits
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

/// Why the clip planes or the alpha test discard a fragment, or `None` where they keep it.
fn discarded_by(terms: &reference::PixelTerms) -> Option<String> {
    let clipped: Vec<String> = terms
        .clip_distances
        .iter()
        .filter(|(_, d)| *d < 0.0)
        .map(|(i, d)| format!("GL_CLIP_PLANE{i} (distance {d:.4} < 0)"))
        .collect();
    if !clipped.is_empty() {
        return Some(format!("clipped by {}", clipped.join(" and ")));
    }
    let a = &terms.alpha_test;
    (!a.passes).then(|| {
        format!(
            "discarded by the alpha test: alpha {} {} reference {} fails (8-bit values)",
            a.alpha,
            a.func.gl_name(),
            a.reference
        )
    })
}

/// The explanation of pixel (x, y) in `mode`, or `None` when nothing covers it.
pub fn explain(scene: &Scene, x: u32, y: u32, mode: LightingMode) -> Option<String> {
    let surfaces = surfaces_at(scene, x, y);
    if surfaces.is_empty() {
        return None;
    }
    let mut out = String::new();
    let _ = writeln!(
        out,
        "pixel ({x}, {y}) of {} ({}x{}), {} mode",
        scene.path.display(),
        scene.width,
        scene.height,
        mode.name()
    );
    for note in &scene.notes {
        let _ = writeln!(out, "scene: {note}");
    }
    for hit in &surfaces {
        let terms = pixel_terms(scene, hit, mode);
        match discarded_by(&terms) {
            None => {
                explain_surface(&mut out, scene, (hit, &terms), mode);
                return Some(out);
            }
            Some(why) => {
                let _ = writeln!(
                    out,
                    "mesh {:?} triangle {} (window depth {:.5}) covers the pixel but is {why}: what lies behind shows",
                    scene.meshes[hit.mesh].name,
                    hit.triangle,
                    hit.depth * 0.5 + 0.5
                );
            }
        }
    }
    let c = scene.clear_color;
    let _ = writeln!(
        out,
        "final color: every surface here is discarded, the clear color stays {} = {}",
        rgba(c.as_dvec4()),
        bytes(c.as_dvec4())
    );
    Some(out)
}

/// Writes the terms of the surface `hit`, whose fragment is kept, at its pixel (`pixel`: the
/// CPU reference's terms there).
fn explain_surface(
    out: &mut String,
    scene: &Scene,
    (hit, pixel): (&Hit, &reference::PixelTerms),
    mode: LightingMode,
) {
    let mesh = &scene.meshes[hit.mesh];
    let mut state = scene.draw_state(mesh);
    state.mode = mode;
    let modelview = scene.modelview(mesh);
    let verts = hit.vertices.map(|i| &mesh.data.vertices[i]);
    let eye: [EyeVertex; 3] = verts.map(|v| reference::transform(&state, modelview, scene.projection, v));
    let back = !hit.coverage.front;
    let w = hit.coverage.weights;

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
                    terms(out, "  ", &lit, &indices, &state.lights);
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
                    out,
                    "  ",
                    &reference::light_face(&state, p, n, c, back),
                    &indices,
                    &state.lights,
                );
            }
        }
    }
    units::texture_terms(out, mesh, pixel);
    stage_terms(out, &state, pixel);
    let color = pixel.color;
    let how = if pixel.fog.is_some() {
        "clamp(c_pri + c_sec), alpha of c_pri, fogged; textured: C_v for c_pri"
    } else {
        "clamp(c_pri + c_sec), alpha of c_pri; textured: C_v for c_pri"
    };
    let _ = writeln!(out, "final color ({how}) {} = {}", rgba(color), bytes(color));
}

/// Writes the terms of the stages after texturing (the color sum with lighting off, fog, the
/// alpha test) and the user clip planes' distances, where they are on.
fn stage_terms(out: &mut String, state: &ffvk::gl::state::FixedFunctionState, pixel: &reference::PixelTerms) {
    if !state.lighting && state.fragment.color_sum {
        let _ = writeln!(
            out,
            "GL_COLOR_SUM with lighting off: c_sec is the current secondary color {} (clamped), sum {}",
            rgba(pixel.c_sec),
            rgba(pixel.summed)
        );
    }
    if let Some(fog) = &pixel.fog {
        let f = &state.fragment.fog;
        let source = match f.source {
            FogSource::FragmentDepth => "GL_FRAGMENT_DEPTH: c = |z_e|".to_string(),
            FogSource::FogCoord => {
                format!("GL_FOG_COORD: c = the fog coordinate {}", state.current_fog_coord)
            }
            _ => "c".into(),
        };
        let formula = match f.mode {
            FogMode::Linear => format!("(end − c) / (end − start), start {} end {}", f.start, f.end),
            FogMode::Exp => format!("exp(−density · c), density {}", f.density),
            FogMode::Exp2 => format!("exp(−(density · c)²), density {}", f.density),
            _ => "f".into(),
        };
        let _ = writeln!(out, "fog: {} = {formula}; {source}", f.mode.gl_name());
        let c = fog.c_vertices;
        if fog.per_vertex {
            let _ = writeln!(
                out,
                "  GL_FOG_HINT GL_FASTEST: f per vertex (c {:.4}, {:.4}, {:.4}), interpolated: f {:.4}",
                c[0], c[1], c[2], fog.f
            );
        } else {
            let _ = writeln!(
                out,
                "  c at the pixel {:.4} (interpolated), f {:.4}",
                fog.c, fog.f
            );
        }
        let _ = writeln!(
            out,
            "  rgb = f · rgb + (1 − f) · fog color {}: {} -> {}",
            rgba(f.color.as_dvec4()),
            rgba(fog.before),
            rgba(fog.after)
        );
    }
    let a = &pixel.alpha_test;
    if state.fragment.alpha_test.enabled {
        let _ = writeln!(
            out,
            "alpha test: alpha {} {} reference {} at 8 bits (GL_ALPHA_TEST_REF {}): {}",
            a.alpha,
            a.func.gl_name(),
            a.reference,
            state.fragment.alpha_test.reference,
            if a.passes { "kept" } else { "discarded" }
        );
    }
    for (i, d) in &pixel.clip_distances {
        let _ = writeln!(
            out,
            "GL_CLIP_PLANE{i}: p_eye · e = {d:.4} ({})",
            if *d >= 0.0 { "kept" } else { "clipped" }
        );
    }
}
