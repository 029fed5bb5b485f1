//! The stages' asset scenes (fog.toml, foliage.toml, section.toml, the raster state's
//! hidden_line.toml and mirror.toml, texture coordinate generation's chrome.toml, the texture
//! units' lightmap.toml) and variations of them, drawn through ffvk against Mesa's GL (vertex
//! and flat modes: GL has no per-fragment lighting) and against the CPU reference at a grid of
//! probes (every mode; the scenes of one texture unit, the one it applies), and explained.

use std::path::{Path, PathBuf};

use ffvk::gl::state::LightingMode;
use ffvk::scene::{render_scene, Scene};
use ffvk_cli::explain::{find_surface, pixel_terms, surfaces_at};
use ffvk_cli::gl_reference::{mesh_raster_calls, render_gl, GlDraw, GlScene};
use image::RgbaImage;

use crate::support::*;

fn asset(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("assets/scenes")
        .join(name)
}

/// `text` (an asset scene's, edited) as a scene file of its own, loaded at 128².
fn variant(name: &str, text: &str) -> Scene {
    let dir = output_dir().join("stage_scenes");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    load(&path)
}

/// `text` with `from` replaced by `to`; `from` must be there (a variant that changed nothing
/// would test its original twice).
fn replaced(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "the variant's original lacks {from:?}");
    text.replace(from, to)
}

fn load(path: &Path) -> Scene {
    let mut scene = Scene::load(path).unwrap();
    assert!(
        scene.warnings.is_empty(),
        "{}: {:?}",
        path.display(),
        scene.warnings
    );
    scene.set_size(128, 128);
    scene
}

fn read(name: &str) -> String {
    std::fs::read_to_string(asset(name)).unwrap()
}

/// The asset scenes and variations that move each stage to its other settings.
fn scenes() -> Vec<(String, Scene)> {
    let fog = read("fog.toml");
    let section = read("section.toml");
    let foliage = read("foliage.toml");
    let fog_with = |extra: &str| fog.replace("mode = \"linear\"\n", extra);
    vec![
        ("fog".into(), load(&asset("fog.toml"))),
        ("foliage".into(), load(&asset("foliage.toml"))),
        ("section".into(), load(&asset("section.toml"))),
        // The raster state of issue 50: an offset fill under GL_LINE, a stencil mirror.
        ("hidden_line".into(), load(&asset("hidden_line.toml"))),
        ("mirror".into(), load(&asset("mirror.toml"))),
        // A lit teapot sphere-mapped (glTexGen's GL_SPHERE_MAP on S and T).
        ("chrome".into(), load(&asset("chrome.toml"))),
        // Two texture units: a tiled base and a light map, the wall's through GL_COMBINE.
        ("lightmap".into(), load(&asset("lightmap.toml"))),
        (
            // The chrome teapot reflecting the built-in cube map by GL_REFLECTION_MAP on S, T
            // and R (a cube map's faces and seams across a lit, curved mesh).
            "chrome_reflection_map".into(),
            variant(
                "chrome_reflection_map",
                &replaced(
                    &read("chrome.toml"),
                    "texture = { builtin = \"checker\", min_filter = \"linear\", mag_filter = \"linear\", texgen = { s = { mode = \"sphere_map\" }, t = { mode = \"sphere_map\" } } }",
                    "texture = { cube_map = { builtin = \"faces\" }, min_filter = \"linear\", texgen = { s = { mode = \"reflection_map\" }, t = { mode = \"reflection_map\" }, r = { mode = \"reflection_map\" } } }",
                ),
            ),
        ),
        (
            // The fill screen-doored by a polygon stipple of 2 × 2 checks.
            "hidden_line_stippled".into(),
            variant(
                "hidden_line_stippled",
                &read("hidden_line.toml").replacen(
                    "[[meshes]]\n",
                    &format!(
                        "[[meshes]]\npolygon_stipple = [{}]\n",
                        (0..32)
                            .map(|y| if y % 4 < 2 { "0xCCCCCCCC" } else { "0x33333333" })
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                    1,
                ),
            ),
        ),
        (
            // Mesa takes |z_e| for the attenuation's distance (pinned in points.rs): the
            // sprites here are of one size, so that the comparison is about the rest.
            "particles_one_size".into(),
            variant(
                "particles_one_size",
                &read("particles.toml")
                    .replace("distance_attenuation = [0.0, 0.0, 1.0]\n", "")
                    .replace("size = 40.0", "size = 13.0"),
            ),
        ),
        (
            "fog_exp2_fastest".into(),
            variant(
                "fog_exp2_fastest",
                &fog_with("mode = \"exp2\"\ndensity = 0.2\nhint = \"fastest\"\n"),
            ),
        ),
        (
            "fog_exp_coord".into(),
            variant(
                "fog_exp_coord",
                &fog_with("mode = \"exp\"\ndensity = 0.3\ncoord_src = \"fog_coord\"\ncoord = 2.0\n"),
            ),
        ),
        (
            "section_two_planes".into(),
            variant(
                "section_two_planes",
                &format!("{section}\n[[clip_planes]]\nequation = [0.0, -1.0, 0.0, 0.35]\n"),
            ),
        ),
        (
            "foliage_lequal".into(),
            variant(
                "foliage_lequal",
                &foliage.replace("func = \"greater\"", "func = \"lequal\""),
            ),
        ),
        (
            // Lighting off: the vertex colors (white) with the current secondary color summed.
            "color_sum_unlit_fog".into(),
            variant(
                "color_sum_unlit_fog",
                &fog.replace(
                    "rescale_normal = true\n",
                    "rescale_normal = true\nlighting = false\ncolor_sum = true\nsecondary_color = [0.0, 0.2, 0.5]\n",
                ),
            ),
        ),
    ]
}

/// The scene drawn by Mesa's GL as a GL program would draw it: each mesh with its state, its
/// matrices and its texture.
pub(crate) fn gl_image(scene: &Scene, mode: LightingMode) -> RgbaImage {
    let draws = scene
        .meshes
        .iter()
        .map(|mesh| {
            let mut state = scene.draw_state(mesh);
            state.mode = mode;
            let mut draw = GlDraw::new(&mesh.data, scene.modelview(mesh), scene.projection, state);
            for (unit, texture) in draw.textures.iter_mut().zip(&mesh.textures) {
                *unit = texture.as_ref().map(|t| (&*t.image, t.sampling));
            }
            for (unit, texture) in draw.cube_maps.iter_mut().zip(&mesh.textures) {
                *unit = texture
                    .as_ref()
                    .and_then(|t| Some((&**t.cube_map.as_ref()?, t.sampling)));
            }
            draw.mesh_texcoords = mesh.mesh_texcoords();
            draw.second_texcoords = mesh.second_texcoords();
            draw.point_size = scene.point_size;
            draw.calls = mesh_raster_calls(&mesh.raster);
            draw
        })
        .collect();
    render_gl(&GlScene {
        width: scene.width,
        height: scene.height,
        clear_color: scene.clear_color.to_array(),
        depth_test: scene.depth_test,
        draws,
    })
    .unwrap()
}

/// Pixels whose channels differ by more than `tol`, out of all.
pub(crate) fn differing(a: &RgbaImage, b: &RgbaImage, tol: u8) -> (usize, u8) {
    let mut worst = 0;
    let n = a
        .pixels()
        .zip(b.pixels())
        .filter(|(p, q)| {
            let d = p.0.iter().zip(q.0).map(|(x, y)| x.abs_diff(y)).max().unwrap();
            worst = worst.max(d);
            d > tol
        })
        .count();
    (n, worst)
}

/// Every stage scene in the vertex and flat modes, against Mesa's GL: within 2/255 but on
/// edges (a silhouette, a leaf's cut or a clip plane's line may land a pixel apart), at most
/// 1.5 % of the pixels.
#[test]
fn the_stage_scenes_draw_as_mesas_gl_draws_them() {
    let mut r = renderer();
    let mut failures = Vec::new();
    for (name, scene) in scenes() {
        for mode in [LightingMode::Vertex, LightingMode::Flat] {
            let ours = render_scene(&mut r, &scene, Some(mode)).unwrap();
            let theirs = gl_image(&scene, mode);
            if name == "color_sum_unlit_fog" {
                // Mesa's deviation, pinned: it fogs the color sum before clamping it; GL 2.1
                // clamps the sum (§3.9) before fog (§3.10), as ffvk does (the CPU reference
                // test holds ffvk to the spec).
                mesa_fogs_the_color_sum_before_clamping_it(&scene, mode, &theirs);
                continue;
            }
            let (n, worst) = differing(&ours, &theirs, 2);
            let share = n as f64 / (ours.width() * ours.height()) as f64;
            let what = format!("{name}_{}", mode.name());
            let a = save_for_inspection(&ours, &format!("stage_scenes_{what}_ffvk"));
            save_for_inspection(&theirs, &format!("stage_scenes_{what}_gl"));
            println!(
                "{what}: {:.2} % of pixels beyond 2/255 (worst {worst})",
                share * 100.0
            );
            if share > 0.015 {
                failures.push(format!(
                    "{what}: {:.2} % of pixels differ from Mesa's GL by more than 2/255 (worst {worst}); images beside {}",
                    share * 100.0,
                    a.display()
                ));
            }
        }
    }
    finish(r);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Mesa's image of a color-summed, fogged scene is clamp(fog(c_pri + c_sec)): it fogs the sum
/// before clamping it, at every probe, where the spec's fog(clamp(c_pri + c_sec)) differs
/// from that by more than 8/255 at 20 probes at least.
fn mesa_fogs_the_color_sum_before_clamping_it(scene: &Scene, mode: LightingMode, gl: &RgbaImage) {
    let mut told_apart = 0;
    for j in 0..16 {
        for i in 0..16 {
            let (x, y) = (scene.width * (2 * i + 1) / 32, scene.height * (2 * j + 1) / 32);
            let Some(hit) = find_surface(scene, x, y, mode) else {
                continue;
            };
            if hit.coverage.weights.min_element() < 0.05 {
                continue;
            }
            let t = pixel_terms(scene, &hit, mode);
            let fog = t.fog.expect("the scene is fogged");
            let state = scene.draw_state(&scene.meshes[hit.mesh]);
            let unclamped = (t.c_pri.truncate() + t.c_sec.truncate()).extend(t.c_pri.w);
            let mesa = ffvk::reference::stages::apply_fog(&state.fragment.fog, unclamped, fog.f)
                .clamp(glam::DVec4::ZERO, glam::DVec4::ONE);
            let what = format!("Mesa's color sum fogged before its clamp, {}", mode.name());
            assert_pixel(gl, x, y, mesa, 2.0, &what);
            told_apart += usize::from((mesa - t.color).abs().max_element() > 8.0 / 255.0);
        }
    }
    assert!(told_apart >= 20, "only {told_apart} probes tell the two apart");
}

/// Whether the CPU reference's verdict at a probe is a rounding question: a clip distance
/// within 0.01 of 0 or an alpha within 1.5/255 of the alpha test's boundary, on any surface in
/// front of the one shown.
fn borderline(scene: &Scene, x: u32, y: u32, mode: LightingMode) -> bool {
    for hit in surfaces_at(scene, x, y) {
        if hit.coverage.weights.min_element() < 0.05 {
            return true;
        }
        let t = pixel_terms(scene, &hit, mode);
        if t.clip_distances.iter().any(|(_, d)| d.abs() < 0.01) {
            return true;
        }
        let test = scene.draw_state(&scene.meshes[hit.mesh]).fragment.alpha_test;
        if test.enabled && (t.color.w.clamp(0.0, 1.0) * 255.0 - t.alpha_test.reference).abs() < 1.5 {
            return true;
        }
        if t.kept {
            return false;
        }
    }
    false
}

/// The CPU reference's fog, alpha test, clip planes and color sum, pixel by pixel, in every
/// mode: a 16×16 grid of probes within 1/255 of the GPU's image, skipping only the probes
/// whose verdict is a rounding question; where every surface is discarded the clear color.
#[test]
fn the_cpu_reference_predicts_every_stage_at_a_grid_of_probes_in_every_mode() {
    let mut r = renderer();
    let mut seen_through = 0;
    // The CPU reference draws filled triangles under GL's raster defaults: the particles
    // (points) are left to points.rs, the raster state's scenes to Mesa (above). Every texture
    // unit and cube map is predicted.
    let plain = |scene: &Scene| scene.meshes.iter().all(|m| m.raster.is_default());
    for (name, scene) in scenes()
        .into_iter()
        .filter(|(n, s)| !n.starts_with("particles") && plain(s))
    {
        for mode in LightingMode::ALL {
            let image = render_scene(&mut r, &scene, Some(mode)).unwrap();
            let (mut probed, mut discarded) = (0, 0);
            for j in 0..16 {
                for i in 0..16 {
                    let (x, y) = (scene.width * (2 * i + 1) / 32, scene.height * (2 * j + 1) / 32);
                    if borderline(&scene, x, y, mode) {
                        continue;
                    }
                    let what = format!("stage_scenes {name} {}", mode.name());
                    match find_surface(&scene, x, y, mode) {
                        Some(hit) => {
                            let t = pixel_terms(&scene, &hit, mode);
                            // Mipmapped texels: the level of detail is the device's (from 2×2
                            // quads); as the texturing tests, 4/255 where λ ≤ 2.5.
                            let mesh = &scene.meshes[hit.mesh];
                            let mipmapped = (0..t.units.len()).any(|i| {
                                t.units[i].is_some()
                                    && mesh.textures[i]
                                        .as_ref()
                                        .is_some_and(|tex| tex.sampling.min_filter.uses_mipmaps())
                            });
                            let lambda = t.units.iter().flatten().map(|u| u.lambda).fold(0.0, f64::max);
                            if mipmapped && lambda > 2.5 {
                                continue;
                            }
                            // Each filtered texel is within about 1/255 of the CPU's (the
                            // device weighs texels at 8 bits); a product of units carries each
                            // unit's error, and GL_RGB_SCALE multiplies the sum.
                            let applied = t.units.iter().flatten().filter(|u| u.applied).count();
                            let scale = (0..t.units.len())
                                .filter(|&i| t.units[i].is_some_and(|u| u.applied))
                                .filter_map(|i| mesh.textures[i].as_ref())
                                .map(|tex| f64::from(tex.unit.combine.rgb_scale))
                                .fold(1.0, f64::max);
                            let filtered = applied.max(1) as f64 * scale;
                            let tol = if mipmapped { 4.0f64.max(filtered) } else { filtered };
                            assert_pixel(&image, x, y, t.color, tol, &what);
                        }
                        None if !surfaces_at(&scene, x, y).is_empty() => {
                            // Every surface here is clipped or fails the alpha test.
                            assert_pixel(&image, x, y, scene.clear_color.as_dvec4(), 1.0, &what);
                            discarded += 1;
                        }
                        None => continue,
                    }
                    probed += 1;
                }
            }
            assert!(probed >= 15, "{name} {}: only {probed} probes", mode.name());
            seen_through += discarded;
        }
    }
    finish(r);
    assert!(
        seen_through > 0,
        "no probe saw the clear color through a cut or a leaf"
    );
}

/// `ffvk explain` prints each stage's terms: the fog's distance and factor, the alpha test's
/// verdict, a clip plane's distance, and what a discarded surface lets through.
#[test]
fn explain_prints_the_fog_the_alpha_test_and_the_clip_planes_at_a_pixel() {
    let scene = load(&asset("fog.toml"));
    let text = ffvk_cli::explain::explain(&scene, 100, 70, LightingMode::Vertex).unwrap();
    for part in [
        "fog: GL_LINEAR = (end − c) / (end − start), start 2.5 end 9",
        "GL_FRAGMENT_DEPTH: c = |z_e|",
        "c at the pixel",
        "rgb = f · rgb + (1 − f) · fog color",
        "fogged",
    ] {
        assert!(text.contains(part), "{text}\nshould mention {part:?}");
    }
    // A pixel in the section's cut: the front of the teapot is clipped, its inside shows.
    let scene = load(&asset("section.toml"));
    let mut seen_clipped = false;
    for x in (16..112).step_by(4) {
        let Some(text) = ffvk_cli::explain::explain(&scene, x, 64, LightingMode::Fragment) else {
            continue;
        };
        assert!(text.contains("GL_CLIP_PLANE0"), "{text}");
        if text.contains("is clipped by GL_CLIP_PLANE0 (distance -") && text.contains("surface: mesh") {
            assert!(
                text.contains("back face"),
                "behind the cut the inside shows: {text}"
            );
            seen_clipped = true;
        }
    }
    assert!(
        seen_clipped,
        "no pixel of the section's row 64 shows a clipped surface"
    );
    let scene = load(&asset("foliage.toml"));
    let mut verdicts = (false, false);
    for x in (8..120).step_by(3) {
        let Some(text) = ffvk_cli::explain::explain(&scene, x, 40, LightingMode::Vertex) else {
            continue;
        };
        verdicts.0 |= text.contains("GL_GREATER reference 128 at 8 bits (GL_ALPHA_TEST_REF 0.5): kept");
        verdicts.1 |= text.contains("discarded by the alpha test: alpha 0 GL_GREATER reference 128 fails");
    }
    assert_eq!(
        verdicts,
        (true, true),
        "both verdicts along row 40 of the foliage"
    );
}
