//! The fuzz harness: generated scene files, glTF JSON, GLB bytes and command lines, each
//! asserting what hostile input may never do: panic, hang, take memory without bound, or
//! (on the command line) die by a signal, exit with another code than 0, 1 or 2, or write a
//! file it was not asked to. glTF files also hold images, samplers, textures, sparse accessors
//! and extensions, valid and not: one loaded although those make it invalid fails, and the
//! run prints how often each family was generated and loaded (each must load at least once).
//! A mesh's generated `texture_units` load and draw, or are refused naming one of their fields.
//!
//! Bounded for CI (a few hundred cases, under a minute); `FFVK_FUZZ_SCALE=N` multiplies every
//! case count, e.g. `FFVK_FUZZ_SCALE=100 cargo test --release --test suite fuzz` (see
//! docs/regression.md); `FFVK_FUZZ_VERBOSE=1` prints each command line's exit code. A failure prints the generated input; proptest shrinks it first and keeps it in
//! `tests/suite/proptest-regressions/` for the next runs.

use std::cell::{Cell, RefCell};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::sync::mpsc;
use std::time::{Duration, Instant};

use ffvk::scene::{Limits, Scene};
use proptest::prelude::*;
use proptest::test_runner::{Config, FileFailurePersistence, TestCaseError, TestRunner};

use crate::support::{ffvk_command, finish, output_dir, renderer};

/// The case count `base` scaled by `FFVK_FUZZ_SCALE` (default 1).
pub(crate) fn cases(base: u32) -> u32 {
    let scale = std::env::var("FFVK_FUZZ_SCALE")
        .ok()
        .and_then(|s| s.parse::<u32>().ok())
        .unwrap_or(1)
        .max(1);
    base.saturating_mul(scale)
}

pub(crate) fn runner(base: u32) -> TestRunner {
    TestRunner::new(Config {
        cases: cases(base),
        // Shrinking a slow input can take long; a short bound keeps CI's time predictable.
        max_shrink_time: 60_000,
        // The runner is used directly (not through the proptest! macro), so the file is named.
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/suite/proptest-regressions/fuzz.txt"
        )))),
        ..Config::default()
    })
}

/// Runs `f` on a thread of its own and fails when it takes longer than `limit`: a hang is a
/// failure, not a stuck test run. (The thread is left behind when it hangs.)
fn within<T: Send + 'static>(
    limit: Duration,
    what: &str,
    f: impl FnOnce() -> T + Send + 'static,
) -> Result<T, TestCaseError> {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)));
    });
    match rx.recv_timeout(limit) {
        Ok(Ok(value)) => Ok(value),
        Ok(Err(panic)) => {
            let message = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default();
            Err(TestCaseError::fail(format!("{what} panicked: {message}")))
        }
        Err(_) => Err(TestCaseError::fail(format!("{what} took more than {limit:?}"))),
    }
}

fn sandbox(name: &str) -> PathBuf {
    let dir = output_dir().join("fuzz").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

// ---------------------------------------------------------------------------------------------
// Values

/// Numbers as a file would write them: ordinary, boundary, non-finite, out of every range.
fn number() -> BoxedStrategy<String> {
    prop_oneof![
        4 => (-4.0f64..4.0).prop_map(|x| format!("{x:?}")),
        2 => (0u32..300).prop_map(|x| x.to_string()),
        1 => prop::sample::select(vec![
            "0", "-0.0", "1", "-1", "0.5", "90", "180", "128", "129", "1e30", "-1e30", "1e-40",
            "16384", "16385", "65536", "4294967296", "-2147483649", "9223372036854775807",
        ])
        .prop_map(str::to_owned),
    ]
    .boxed()
}

/// Strings ffvk knows, strings it does not, and hostile ones.
fn text() -> BoxedStrategy<String> {
    prop_oneof![
        3 => prop::sample::select(vec![
            "vertex", "fragment", "flat", "teapot", "sphere", "plane", "front", "back",
            "front_and_back", "emission", "ambient", "diffuse", "specular", "ambient_and_diffuse",
            "single_color", "separate_specular_color", "emerald", "gold", "thing", "node 0",
            "tri.gltf", "tri.glb", "bad.gltf", "../tri.gltf", "/dev/zero", "missing.gltf", "",
        ])
        .prop_map(str::to_owned),
        1 => "[a-z_]{0,12}".prop_map(|s| s),
        1 => (0usize..5000).prop_map(|n| "x".repeat(n)),
        1 => Just("é∂\u{202e}\\u0000\\t".to_owned()),
    ]
    .boxed()
}

/// An array of `len` numbers, usually of a length some field takes.
fn numbers() -> BoxedStrategy<String> {
    prop_oneof![
        3 => prop::sample::select(vec![2usize, 3, 4, 16]),
        1 => 0usize..20,
    ]
    .prop_flat_map(|len| prop::collection::vec(number(), len))
    .prop_map(|v| format!("[{}]", v.join(", ")))
    .boxed()
}

// ---------------------------------------------------------------------------------------------
// Scene files

/// A TOML value of any kind a scene file might hold.
fn toml_value() -> BoxedStrategy<String> {
    prop_oneof![
        3 => number(),
        3 => numbers(),
        2 => text().prop_map(|s| format!("{s:?}")),
        1 => any::<bool>().prop_map(|b| b.to_string()),
        1 => Just("nan".to_owned()),
        1 => Just("-inf".to_owned()),
        1 => Just("{ a = 1 }".to_owned()),
    ]
    .boxed()
}

const TOP_KEYS: &[&str] = &["lighting", "normalize", "rescale_normal", "gltf_lights", "bogus"];
const TABLES: &[(&str, &[&str])] = &[
    ("[image]", &["size", "clear_color", "lighting_mode", "depth_test"]),
    (
        "[camera]",
        &["eye", "target", "up", "fovy", "near", "far", "view", "projection"],
    ),
    (
        "[light_model]",
        &["ambient", "local_viewer", "two_side", "color_control"],
    ),
    (
        "[[lights]]",
        &[
            "index",
            "enabled",
            "ambient",
            "diffuse",
            "specular",
            "position",
            "spot_direction",
            "spot_exponent",
            "spot_cutoff",
            "constant_attenuation",
            "linear_attenuation",
            "quadratic_attenuation",
        ],
    ),
    (
        "[material]",
        &[
            "preset",
            "ambient",
            "diffuse",
            "specular",
            "emission",
            "shininess",
        ],
    ),
    ("[back_material]", &["preset", "diffuse", "shininess"]),
    ("[color_material]", &["enabled", "face", "mode"]),
    (
        "[[meshes]]",
        &[
            "gltf",
            "node",
            "mesh",
            "builtin",
            "level",
            "color",
            "translate",
            "rotate",
            "scale",
            "matrix",
            "texture_units",
        ],
    ),
];

/// A mesh's `texture_units`: one to five unit tables (four at most are taken) of builtin
/// images, base formats, environments, coordinates and `combine` tables, mostly values the
/// fields take and sometimes ones GL refuses (a dot product for alpha, a scale of 3,
/// GL_TEXTURE4, coords on unit 0, a format spelled as GL's enum), each field sometimes left out.
fn texture_units() -> BoxedStrategy<String> {
    // `words` (TOML values) with probability `p`, else the field left out.
    let pick = |p: f64, words: Vec<&'static str>| prop::option::weighted(p, prop::sample::select(words));
    let source = prop::sample::select(vec![
        "\"texture\"",
        "\"previous\"",
        "\"constant\"",
        "\"primary_color\"",
        "\"texture0\"",
        "\"texture0\"",
        "\"texture1\"",
        "\"texture3\"",
        "\"texture4\"",
    ]);
    let sources = prop::option::weighted(
        0.4,
        prop::collection::vec(source, 1..4).prop_map(|v| format!("[{}]", v.join(", "))),
    );
    let combine = (
        pick(
            0.5,
            vec![
                "\"modulate\"",
                "\"interpolate\"",
                "\"add\"",
                "\"subtract\"",
                "\"dot3_rgba\"",
                "\"nope\"",
            ],
        ),
        pick(
            0.3,
            vec!["\"replace\"", "\"add_signed\"", "\"modulate\"", "\"dot3_rgb\""],
        ),
        (sources.clone(), sources),
        pick(
            0.3,
            vec![
                "[\"src_color\", \"one_minus_src_alpha\"]",
                "[\"one_minus_src_color\"]",
                "[\"alpha\"]",
            ],
        ),
        pick(
            0.2,
            vec![
                "[\"one_minus_src_alpha\"]",
                "[\"src_alpha\", \"src_alpha\"]",
                "[\"src_color\"]",
            ],
        ),
        pick(0.3, vec!["1", "2", "4.0", "2.0", "3"]),
        pick(0.2, vec!["1", "4", "0.5"]),
    )
        .prop_map(
            |(
                rgb,
                alpha,
                (rgb_sources, alpha_sources),
                rgb_operands,
                alpha_operands,
                rgb_scale,
                alpha_scale,
            )| {
                let fields = [
                    ("rgb", rgb.map(str::to_owned)),
                    ("alpha", alpha.map(str::to_owned)),
                    ("rgb_sources", rgb_sources),
                    ("alpha_sources", alpha_sources),
                    ("rgb_operands", rgb_operands.map(str::to_owned)),
                    ("alpha_operands", alpha_operands.map(str::to_owned)),
                    ("rgb_scale", rgb_scale.map(str::to_owned)),
                    ("alpha_scale", alpha_scale.map(str::to_owned)),
                ];
                inline_table(fields)
            },
        );
    let builtin = pick(
        0.97,
        vec![
            "\"checker\"",
            "\"lightmap\"",
            "\"disc\"",
            "\"leaves\"",
            "\"checker\"",
            "\"lightmap\"",
            "\"nope\"",
        ],
    );
    let coords = pick(
        0.2,
        vec!["\"mesh\"", "\"mesh\"", "[0.5, 0.5, 0.0, 1.0]", "[1, 2]", "true"],
    );
    let min_filter = pick(0.8, vec!["\"linear\"", "\"nearest\""]);
    // The base internal formats, and GL's spelling (refused: the files take lowercase names).
    let format = pick(
        0.4,
        vec![
            "\"rgb\"",
            "\"alpha\"",
            "\"luminance\"",
            "\"luminance_alpha\"",
            "\"intensity\"",
            "\"GL_LUMINANCE\"",
        ],
    );
    // Mostly a combine table only with env = "combine" (another environment refuses one);
    // sometimes any.
    let env_and_combine = prop_oneof![
        5 => pick(0.5, vec!["\"modulate\"", "\"decal\"", "\"add\"", "\"blend\"", "\"nope\""]).prop_map(|e| (e, None)),
        4 => combine.clone().prop_map(|c| (Some("\"combine\""), Some(c))),
        1 => (pick(0.5, vec!["\"modulate\"", "\"combine\""]), prop::option::of(combine)),
    ];
    let unit = (builtin, env_and_combine, coords, min_filter, format).prop_map(
        |(builtin, (env, combine), coords, min_filter, format)| {
            let fields = [
                ("builtin", builtin.map(str::to_owned)),
                ("env", env.map(str::to_owned)),
                ("coords", coords.map(str::to_owned)),
                ("combine", combine),
                ("min_filter", min_filter.map(str::to_owned)),
                ("format", format.map(str::to_owned)),
            ];
            inline_table(fields)
        },
    );
    prop_oneof![8 => 1usize..5, 1 => Just(5usize)]
        .prop_flat_map(move |n| prop::collection::vec(unit.clone(), n))
        .prop_map(|units| format!("[{}]", units.join(", ")))
        .boxed()
}

/// An inline TOML table of the `fields` given.
fn inline_table<const N: usize>(fields: [(&str, Option<String>); N]) -> String {
    let given: Vec<String> = fields
        .into_iter()
        .filter_map(|(k, v)| v.map(|v| format!("{k} = {v}")))
        .collect();
    format!("{{ {} }}", given.join(", "))
}

/// A value for scene-file key `key`: mostly one the field could take, sometimes anything.
fn scene_value(key: &str) -> BoxedStrategy<String> {
    let unit = |n: usize| array(n, 0.0, 1.0);
    let words = |w: Vec<&'static str>| prop::sample::select(w).prop_map(|w| format!("{w:?}")).boxed();
    let float = |lo: f64, hi: f64| (lo..hi).prop_map(|x| format!("{x:?}")).boxed();
    let plausible = match key {
        "size" => (1u32..40, 1u32..40)
            .prop_map(|(w, h)| format!("[{w}, {h}]"))
            .boxed(),
        "clear_color" | "ambient" | "diffuse" | "specular" | "emission" | "color" => {
            prop_oneof![unit(3), unit(4)].boxed()
        }
        "lighting_mode" => words(vec!["vertex", "fragment", "flat"]),
        "eye" | "target" | "up" | "translate" | "rotate" | "scale" | "spot_direction" => array(3, -5.0, 5.0),
        "view" | "projection" | "matrix" => array(16, -2.0, 2.0),
        "position" => array(4, -3.0, 3.0),
        "fovy" => float(1.0, 179.0),
        "near" => float(0.01, 1.0),
        "far" => float(1.0, 100.0),
        "color_control" => words(vec!["single_color", "separate_specular_color"]),
        "index" => (0u32..18).prop_map(|i| i.to_string()).boxed(),
        "spot_exponent" | "shininess" => float(0.0, 128.0),
        "spot_cutoff" => prop_oneof![float(0.0, 90.0), Just("180".to_owned())].boxed(),
        "constant_attenuation" | "linear_attenuation" | "quadratic_attenuation" => float(0.0, 2.0),
        "preset" => words(vec!["emerald", "gold", "chrome", "pearl", "ruby"]),
        "face" => words(vec!["front", "back", "front_and_back"]),
        "mode" => words(vec![
            "emission",
            "ambient",
            "diffuse",
            "specular",
            "ambient_and_diffuse",
        ]),
        "gltf" => words(vec!["tri.gltf", "tri.glb", "bad.gltf", "missing.gltf"]),
        "node" => words(vec!["node 0", "node 9"]),
        "mesh" => words(vec!["thing", "other"]),
        "builtin" => words(vec!["teapot", "sphere", "plane", "cube"]),
        "level" => (1u32..12).prop_map(|l| l.to_string()).boxed(),
        "texture_units" => texture_units(),
        _ => any::<bool>().prop_map(|b| b.to_string()).boxed(),
    };
    prop_oneof![8 => plausible, 1 => toml_value()].boxed()
}

/// A scene file: top-level keys, then tables with keys they know (and some they do not),
/// every value drawn from [`toml_value`]; sometimes cut or spliced afterwards.
fn scene_text() -> BoxedStrategy<String> {
    let keys = |names: &'static [&'static str]| {
        prop::collection::vec(
            prop::sample::select(names).prop_flat_map(|key| (Just(key), scene_value(key))),
            0..5,
        )
    };
    let table = (0..TABLES.len()).prop_flat_map(move |t| (Just(t), keys(TABLES[t].1)));
    let plausible_mesh = prop::sample::select(vec![
        "[[meshes]]\nbuiltin = \"sphere\"\nlevel = 8\n",
        "[[meshes]]\nbuiltin = \"teapot\"\nlevel = 2\n",
        "[[meshes]]\ngltf = \"tri.gltf\"\n",
        "[[meshes]]\ngltf = \"tri.glb\"\n",
        "",
    ]);
    (
        keys(TOP_KEYS),
        prop::collection::vec(table, 0..6),
        plausible_mesh,
        prop::option::weighted(
            0.2,
            (
                any::<prop::sample::Index>(),
                any::<prop::sample::Index>(),
                any::<u8>(),
            ),
        ),
    )
        .prop_map(|(top, tables, mesh, splice)| {
            let mut text = String::new();
            for (key, value) in top {
                text += &format!("{key} = {value}\n");
            }
            let mut seen = Vec::new();
            for (t, entries) in tables {
                // A table given twice is a TOML error; one such case in many is enough.
                if !TABLES[t].0.starts_with("[[") && seen.contains(&t) && entries.len() % 4 != 0 {
                    continue;
                }
                seen.push(t);
                text += &format!("{}\n", TABLES[t].0);
                if TABLES[t].0 == "[[meshes]]" {
                    text += "builtin = \"sphere\"\n";
                }
                for (key, value) in entries {
                    text += &format!("{key} = {value}\n");
                }
            }
            text += mesh;
            if let Some((at, len, byte)) = splice {
                // Cut a piece out and put one byte in its place: broken syntax, stray quotes.
                let bytes = text.as_bytes();
                let start = at.index(bytes.len() + 1);
                let end = (start + len.index(8)).min(bytes.len());
                let mut spliced = bytes[..start].to_vec();
                spliced.push(byte);
                spliced.extend_from_slice(&bytes[end..]);
                text = String::from_utf8_lossy(&spliced).into_owned();
            }
            text
        })
        .boxed()
}

/// The files generated scenes and command lines refer to.
fn write_assets(dir: &Path) {
    let floats: [f32; 18] = [
        0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 1., 0., 0., 1.,
    ];
    let bin = bytemuck::cast_slice::<f32, u8>(&floats).to_vec();
    let json = |uri: &str| {
        format!(
            r#"{{"asset": {{"version": "2.0"}}, "buffers": [{{{uri}"byteLength": 72}}],
  "bufferViews": [{{"buffer": 0, "byteLength": 36}}, {{"buffer": 0, "byteOffset": 36, "byteLength": 36}}],
  "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}},
                {{"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"}}],
  "meshes": [{{"name": "thing", "primitives": [{{"attributes": {{"POSITION": 0, "NORMAL": 1}}}}]}}],
  "nodes": [{{"name": "node 0", "mesh": 0}}], "scenes": [{{"nodes": [0]}}], "scene": 0}}"#
        )
    };
    std::fs::write(dir.join("tri.bin"), &bin).unwrap();
    std::fs::write(dir.join("tri.gltf"), json(r#""uri": "tri.bin", "#)).unwrap();
    std::fs::write(dir.join("tri.glb"), glb(json("").as_bytes(), Some(&bin))).unwrap();
    std::fs::write(dir.join("bad.gltf"), "{ \"asset\": ").unwrap();
}

#[test]
fn generated_scene_files_load_or_fail_with_an_error_and_render_without_panicking() {
    let dir = sandbox("scenes");
    write_assets(&dir);
    let path = dir.join("scene.toml");
    let limits = Limits::default().with_mesh_bytes(64 << 20);
    let r = RefCell::new(Some(renderer()));
    let (loaded, refused) = (Cell::new(0), Cell::new(0));
    runner(1000)
        .run(&scene_text(), |text| {
            let (p, l) = (path.clone(), limits.clone());
            let scene = within(Duration::from_secs(20), "Scene::parse_with", move || {
                Scene::parse_with(&text, &p, &l).map_err(|e| e.to_string())
            })?;
            match scene {
                Err(message) => {
                    refused.set(refused.get() + 1);
                    prop_assert!(message.len() < 4096, "a {} byte message", message.len());
                }
                Ok(mut scene) => {
                    loaded.set(loaded.get() + 1);
                    scene.set_size(16, 16);
                    // A renderer whose frame failed stays usable; one that panicked is gone.
                    let mut renderer = r
                        .borrow_mut()
                        .take()
                        .expect("the renderer survived the last case");
                    let (renderer, _result) = within(Duration::from_secs(60), "render_scene", move || {
                        let result = ffvk::scene::render_scene(&mut renderer, &scene, None).map(|_| ());
                        (renderer, result.map_err(|e| e.to_string()))
                    })?;
                    *r.borrow_mut() = Some(renderer);
                }
            }
            Ok(())
        })
        .unwrap();
    finish(r.into_inner().unwrap());
    // Both sides were reached: the generator is neither all garbage nor all valid.
    let (loaded, refused) = (loaded.get(), refused.get());
    eprintln!("{loaded} loaded, {refused} refused");
    assert!(loaded > 0 && refused > 0, "{loaded} loaded, {refused} refused");
}

/// A plane's generated `texture_units` (see [`texture_units`]): each scene loads and draws, or
/// is refused naming a field of the units, never a panic; some of several units draw.
#[test]
fn generated_texture_units_load_or_are_refused_by_field_and_draw_without_panicking() {
    let path = sandbox("units").join("scene.toml");
    let r = RefCell::new(Some(renderer()));
    let (loaded, several, refused) = (Cell::new(0), Cell::new(0), Cell::new(0));
    runner(300)
        .run(&texture_units(), |units| {
            let text = format!(
                "[image]\nsize = [16, 16]\n[[meshes]]\nbuiltin = \"plane\"\ntexture_units = {units}\n"
            );
            match Scene::parse(&text, &path) {
                Err(e) => {
                    refused.set(refused.get() + 1);
                    let message = e.to_string();
                    prop_assert!(message.contains("meshes[0].texture_units"), "{message}\n{text}");
                }
                Ok(scene) => {
                    loaded.set(loaded.get() + 1);
                    let units = scene.meshes[0].textures.iter().flatten().count();
                    several.set(several.get() + usize::from(units > 1));
                    let mut renderer = r
                        .borrow_mut()
                        .take()
                        .expect("the renderer survived the last case");
                    let (renderer, result) = within(Duration::from_secs(60), "render_scene", move || {
                        let result = ffvk::scene::render_scene(&mut renderer, &scene, None).map(|_| ());
                        (renderer, result.map_err(|e| e.to_string()))
                    })?;
                    *r.borrow_mut() = Some(renderer);
                    prop_assert!(result.is_ok(), "{result:?}\n{text}");
                }
            }
            Ok(())
        })
        .unwrap();
    finish(r.into_inner().unwrap());
    let (loaded, several, refused) = (loaded.get(), several.get(), refused.get());
    eprintln!("{loaded} loaded ({several} of several units), {refused} refused");
    assert!(
        several > 0 && refused > 0,
        "{loaded} loaded ({several} of several units), {refused} refused"
    );
}

// ---------------------------------------------------------------------------------------------
// glTF and GLB

/// A GLB container of `json` and an optional BIN chunk.
fn glb(json: &[u8], bin: Option<&[u8]>) -> Vec<u8> {
    let pad = |bytes: &[u8], with: u8| {
        let mut v = bytes.to_vec();
        while !v.len().is_multiple_of(4) {
            v.push(with);
        }
        v
    };
    let json = pad(json, b' ');
    let bin = bin.map(|b| pad(b, 0));
    let total = 12 + 8 + json.len() + bin.as_ref().map_or(0, |b| 8 + b.len());
    let mut out = b"glTF".to_vec();
    out.extend(2u32.to_le_bytes());
    out.extend((total as u32).to_le_bytes());
    out.extend((json.len() as u32).to_le_bytes());
    out.extend(0x4E4F_534Au32.to_le_bytes());
    out.extend(&json);
    if let Some(bin) = bin {
        out.extend((bin.len() as u32).to_le_bytes());
        out.extend(0x004E_4942u32.to_le_bytes());
        out.extend(&bin);
    }
    out
}

fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::new();
    for chunk in bytes.chunks(3) {
        let n = chunk
            .iter()
            .enumerate()
            .fold(0u32, |n, (i, &b)| n | (b as u32) << (16 - 8 * i));
        for k in 0..=chunk.len() {
            out.push(ALPHABET[(n >> (18 - 6 * k) & 63) as usize] as char);
        }
        out.extend(std::iter::repeat_n('=', 3 - chunk.len()));
    }
    out
}

/// An index into a glTF array: usually a small valid one, sometimes none that exists.
fn index() -> BoxedStrategy<String> {
    prop_oneof![
        80 => prop::sample::select(vec![0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 2]).prop_map(|i: u32| i.to_string()),
        1 => prop::sample::select(vec!["-1", "4294967296", "1.5", "\"0\"", "null"]).prop_map(str::to_owned),
    ]
    .boxed()
}

/// Mostly `good`, sometimes `bad`: deep enough into the loader to matter, hostile enough to
/// find what it misses.
fn mostly(good: BoxedStrategy<String>, bad: BoxedStrategy<String>) -> BoxedStrategy<String> {
    prop_oneof![60 => good, 1 => bad].boxed()
}

/// `len` numbers in [lo, hi), sometimes another length or out-of-range numbers.
fn array(len: usize, lo: f64, hi: f64) -> BoxedStrategy<String> {
    let good = prop::collection::vec(lo..hi, len)
        .prop_map(|v| {
            format!(
                "[{}]",
                v.iter().map(|x| format!("{x:?}")).collect::<Vec<_>>().join(", ")
            )
        })
        .boxed();
    mostly(good, numbers())
}

/// An integer in `range`, sometimes any number.
fn int(range: std::ops::Range<u32>) -> BoxedStrategy<String> {
    mostly(range.prop_map(|i| i.to_string()).boxed(), number())
}

/// One of `choices`, sometimes any number.
fn one_of(choices: Vec<&'static str>) -> BoxedStrategy<String> {
    mostly(
        prop::sample::select(choices).prop_map(str::to_owned).boxed(),
        number(),
    )
}

fn indices() -> BoxedStrategy<String> {
    prop::collection::vec(index(), 0..4)
        .prop_map(|v| format!("[{}]", v.join(", ")))
        .boxed()
}

/// `"key": value` members, each present with probability `p`; keys written `key!` are the
/// schema's required ones, always present (their values are what may be wrong).
fn members(entries: Vec<(&'static str, BoxedStrategy<String>)>, p: f64) -> BoxedStrategy<String> {
    weighted_members(entries.into_iter().map(|(key, value)| (key, p, value)).collect())
}

/// [`members`] with a probability of its own for each key.
fn weighted_members(entries: Vec<(&'static str, f64, BoxedStrategy<String>)>) -> BoxedStrategy<String> {
    entries
        .into_iter()
        .map(|(key, p, value)| {
            let (key, value) = match key.strip_suffix('!') {
                Some(required) => (required, value.prop_map(Some).boxed()),
                None => (key, prop::option::weighted(p, value).boxed()),
            };
            value.prop_map(move |v| v.map(|v| format!("\"{key}\": {v}")))
        })
        .collect::<Vec<_>>()
        .prop_map(|v| v.into_iter().flatten().collect::<Vec<_>>().join(", "))
        .boxed()
}

/// A JSON array: `first` (left out where empty), then up to `max - 1` objects of `member`.
fn objects(first: &'static str, member: BoxedStrategy<String>, max: usize) -> BoxedStrategy<String> {
    objects_after(Just(first.to_owned()).boxed(), member, max)
}

/// [`objects`] with a generated first element.
fn objects_after(
    first: BoxedStrategy<String>,
    member: BoxedStrategy<String>,
    max: usize,
) -> BoxedStrategy<String> {
    (first, prop::collection::vec(member, 0..max))
        .prop_map(|(first, v)| {
            let generated = v.iter().map(|m| format!("{{{m}}}"));
            let all: Vec<String> = std::iter::once(first)
                .filter(|f| !f.is_empty())
                .chain(generated)
                .collect();
            format!("[{}]", all.join(", "))
        })
        .boxed()
}

/// A 2×2 RGBA PNG, encoded once with the `image` crate: what every valid image source holds
/// (a data URI, `t.png` beside the asset, buffer view 2).
fn png() -> &'static [u8] {
    static PNG: std::sync::OnceLock<Vec<u8>> = std::sync::OnceLock::new();
    PNG.get_or_init(|| {
        let image = image::RgbaImage::from_fn(2, 2, |x, y| {
            image::Rgba([(x * 200) as u8, 90, (y * 200) as u8, 255])
        });
        let mut bytes = std::io::Cursor::new(Vec::new());
        image.write_to(&mut bytes, image::ImageFormat::Png).unwrap();
        bytes.into_inner()
    })
}

/// Buffer view 1's length: the sparse indices [`tail`] starts with.
const SPARSE_INDEX_BYTES: usize = 12;

/// What follows the generated bytes of buffer 0, from a 4-byte boundary: buffer view 1, strictly
/// increasing sparse indices (UNSIGNED_BYTE 0, 1, 2, 3, then UNSIGNED_SHORT 0, 1, 2, 3 from
/// byte 4), and buffer view 2, the PNG.
fn tail() -> Vec<u8> {
    let mut bytes = vec![0u8, 1, 2, 3];
    bytes.extend((0u16..4).flat_map(u16::to_le_bytes));
    bytes.extend_from_slice(png());
    bytes
}

/// The members of an image in each form a file may give one and several it may not: the PNG
/// as a data URI, as `t.png` beside the asset or in buffer view 2 (also under a mimeType no
/// one knows); a missing file, a data URI or view that holds no PNG, bad base64, a URI that
/// leaves the folder or is no percent-encoding; both sources, neither, a mimeType alone, a
/// view without its mimeType, a view that may not exist.
fn image_object() -> BoxedStrategy<String> {
    let data = |bytes: &[u8]| format!("\"uri\": \"data:image/png;base64,{}\"", base64(bytes));
    let readable = prop::sample::select(vec![
        data(png()),
        "\"uri\": \"t.png\"".to_owned(),
        "\"bufferView\": 2, \"mimeType\": \"image/png\"".to_owned(),
        "\"bufferView\": 2, \"mimeType\": \"image/x-unknown\"".to_owned(),
    ]);
    let unreadable = prop::sample::select(vec![
        "\"uri\": \"missing.png\"".to_owned(),
        data(b"GIF89a, and no PNG after it"),
        "\"uri\": \"data:image/png;base64,@@@\"".to_owned(),
        "\"uri\": \"../t.png\"".to_owned(),
        "\"uri\": \"%zz\"".to_owned(),
        "\"bufferView\": 0, \"mimeType\": \"image/jpeg\"".to_owned(),
    ]);
    let malformed = prop_oneof![
        prop::sample::select(vec![
            "\"uri\": \"t.png\", \"bufferView\": 2, \"mimeType\": \"image/png\"",
            "",
            "\"mimeType\": \"image/png\"",
            "\"bufferView\": 2",
        ])
        .prop_map(str::to_owned),
        index().prop_map(|i| format!("\"bufferView\": {i}, \"mimeType\": \"image/png\"")),
    ];
    prop_oneof![10 => readable, 3 => unreadable, 1 => malformed].boxed()
}

/// The members of a sampler: each field's GL enums, sometimes another field's, one GL does not
/// have, one 2^32 above a valid one, or no integer at all.
fn sampler() -> BoxedStrategy<String> {
    let gl = |valid: Vec<&'static str>| {
        prop_oneof![
            30 => prop::sample::select(valid).prop_map(str::to_owned),
            1 => prop::sample::select(vec![
                "0", "9730", "9984", "10497", "33071", "-1", "1.5", "\"9729\"", "null",
                // 2^32 + 9728, 9729 and 10497: the enums again once a u32 wraps.
                "4294977024", "4294977025", "4294977793",
            ])
            .prop_map(str::to_owned),
        ]
        .boxed()
    };
    let wrap = vec!["33071", "33648", "10497"];
    members(
        vec![
            ("magFilter", gl(vec!["9728", "9729"])),
            (
                "minFilter",
                gl(vec!["9728", "9729", "9984", "9985", "9986", "9987"]),
            ),
            ("wrapS", gl(wrap.clone())),
            ("wrapT", gl(wrap)),
        ],
        0.6,
    )
}

/// Any JSON value, as an extension ffvk does not know may hold.
fn unknown_value() -> BoxedStrategy<String> {
    prop::sample::select(vec![
        "{}",
        "{\"bar\": [1, 2, 3]}",
        "{\"a\": {\"b\": [null, true, \"c\", 1e39]}}",
        "1",
        "\"text\"",
        "null",
        "[]",
    ])
    .prop_map(str::to_owned)
    .boxed()
}

/// An `extensions` object naming one extension ffvk does not know.
fn unknown_extensions() -> BoxedStrategy<String> {
    (
        prop::sample::select(vec!["X_foo", "KHR_materials_unlit", "EXT_unknown"]),
        unknown_value(),
    )
        .prop_map(|(name, value)| format!("{{\"{name}\": {value}}}"))
        .boxed()
}

/// The members of a texture: its image (sometimes none), its sampler, both possibly past the
/// end of their arrays, sometimes an extension ffvk does not know.
fn texture() -> BoxedStrategy<String> {
    weighted_members(vec![
        ("source", 0.97, mostly(Just("0".to_owned()).boxed(), index())),
        ("sampler", 0.3, index()),
        ("extensions", 0.1, unknown_extensions()),
    ])
}

/// A textureInfo (`baseColorTexture`, `emissiveTexture`): a texture index in or out of range,
/// a texCoord, and sometimes KHR_texture_transform with numbers up to past f32's range (JSON
/// has no infinity or NaN; 1e39 reads as an f32 infinity).
fn texture_info() -> BoxedStrategy<String> {
    let extreme = || {
        prop::sample::select(vec!["1e39", "-1e39", "3.4028235e38", "1e-45", "0", "-0.0"])
            .prop_map(str::to_owned)
            .boxed()
    };
    let pair = || {
        prop_oneof![
            4 => array(2, -2.0, 2.0),
            1 => (extreme(), extreme()).prop_map(|(a, b)| format!("[{a}, {b}]")),
        ]
        .boxed()
    };
    let transform = members(
        vec![
            ("offset", pair()),
            (
                "rotation",
                prop_oneof![4 => (-7.0f64..7.0).prop_map(|x| format!("{x:?}")), 1 => extreme()].boxed(),
            ),
            ("scale", pair()),
            ("texCoord", one_of(vec!["0", "0", "1"])),
        ],
        0.7,
    )
    .prop_map(|m| format!("{{\"KHR_texture_transform\": {{{m}}}}}"))
    .boxed();
    weighted_members(vec![
        ("index!", 1.0, index()),
        ("texCoord", 0.3, one_of(vec!["0", "0", "1"])),
        ("extensions", 0.5, transform),
    ])
    .prop_map(|m| format!("{{{m}}}"))
    .boxed()
}

/// A material's `extensions`: KHR_materials_emissive_strength (mostly a strength in range,
/// sometimes a negative one, one past f32's range or a string) and one ffvk does not know.
fn material_extensions() -> BoxedStrategy<String> {
    let strength = prop_oneof![
        8 => (0.0f64..10.0).prop_map(|x| format!("{x:?}")),
        1 => prop::sample::select(vec!["-1", "1e39", "-1e39", "\"2\"", "0"]).prop_map(str::to_owned),
    ]
    .prop_map(|s| format!("{{\"emissiveStrength\": {s}}}"))
    .boxed();
    weighted_members(vec![
        ("KHR_materials_emissive_strength", 0.8, strength),
        ("X_foo", 0.3, unknown_value()),
    ])
    .prop_map(|m| format!("{{{m}}}"))
    .boxed()
}

/// A sparse substitution as any accessor may carry: counts from none to past any accessor,
/// index types valid and not, views and offsets anywhere (view 1 holds valid indices, view 0
/// floats, view 2 the PNG).
fn sparse() -> BoxedStrategy<String> {
    (
        prop_oneof![6 => (0u32..6).prop_map(|c| c.to_string()), 1 => number()],
        prop_oneof![2 => Just("1".to_owned()), 1 => index()],
        prop_oneof![
            8 => prop::sample::select(vec!["5121", "5123", "5125"]),
            // FLOAT, BYTE, none, and UNSIGNED_BYTE again once a u32 wraps (2^32 + 5121).
            1 => prop::sample::select(vec!["5126", "5120", "0", "4294972417"]),
        ],
        int(0..8),
        index(),
        int(0..16),
    )
        .prop_map(|(count, indices, kind, indices_at, values, values_at)| {
            format!(
                r#"{{"count": {count}, "indices": {{"bufferView": {indices}, "componentType": {kind}, "byteOffset": {indices_at}}}, "values": {{"bufferView": {values}, "byteOffset": {values_at}}}}}"#
            )
        })
        .boxed()
}

/// Accessor 0, the triangle every document starts from: plain, or with a sparse substitution
/// of 1 to 3 of its elements (indices from buffer view 1, values from view 0) over its own data
/// or over zeros (no bufferView); sometimes one that cannot hold: no elements, more than the
/// accessor has, UNSIGNED_INT indices past its count (0x03020100 and 0x10000), values past
/// their view.
fn first_accessor() -> BoxedStrategy<String> {
    let plain = r#""componentType": 5126, "count": 3, "type": "VEC3", "min": [-2, -2, -2], "max": [2, 2, 2]"#;
    let sparse = (
        prop_oneof![8 => 1u32..=3, 1 => Just(0u32), 1 => Just(4u32)],
        prop_oneof![
            4 => prop::sample::select(vec![("5121", 0), ("5121", 1), ("5123", 4), ("5123", 6)]),
            1 => prop::sample::select(vec![("5125", 0), ("5125", 4)]),
        ],
        prop_oneof![4 => Just(0u32), 1 => Just(12u32)],
        any::<bool>(),
    )
        .prop_map(move |(count, (kind, indices_at), values_at, with_view)| {
            let view = if with_view { "\"bufferView\": 0, " } else { "" };
            format!(
                r#"{{{view}{plain}, "sparse": {{"count": {count}, "indices": {{"bufferView": 1, "componentType": {kind}, "byteOffset": {indices_at}}}, "values": {{"bufferView": 0, "byteOffset": {values_at}}}}}}}"#
            )
        });
    prop_oneof![3 => Just(format!("{{\"bufferView\": 0, {plain}}}")), 2 => sparse].boxed()
}

/// The materials with the images, samplers and textures they may name. In a textured document
/// (most) image 0, texture 0 (showing image 0, with sampler 0 where there is one) and material
/// 0's base color or emissive texture are there to be read; in the others any may be missing,
/// and everywhere indices may point past them. Returns the materials array and the
/// `"images": [...], ` members (none for an empty array).
fn texturing(material: BoxedStrategy<String>) -> BoxedStrategy<(String, String)> {
    prop::bool::weighted(0.6)
        .prop_flat_map(move |textured| {
            let first_material = if textured {
                prop::sample::select(vec![
                    r#"{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}"#,
                    r#"{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}"#,
                    r#"{"emissiveFactor": [1, 1, 1], "emissiveTexture": {"index": 0}}"#,
                ])
                .prop_map(str::to_owned)
                .boxed()
            } else {
                Just("{}".to_owned()).boxed()
            };
            (
                objects_after(first_material, material.clone(), 2),
                prop::collection::vec(image_object(), usize::from(textured)..3),
                prop::option::weighted(0.75, prop::collection::vec(sampler(), 1..3))
                    .prop_map(Option::unwrap_or_default),
                prop::collection::vec(texture(), 0..2),
                Just(textured),
            )
        })
        .prop_map(|(materials, images, samplers, mut textures, textured)| {
            if textured {
                let first = if samplers.is_empty() {
                    "\"source\": 0"
                } else {
                    "\"source\": 0, \"sampler\": 0"
                };
                textures.insert(0, first.to_owned());
            }
            let mut arrays = String::new();
            for (key, list) in [("images", images), ("samplers", samplers), ("textures", textures)] {
                if !list.is_empty() {
                    let objects: Vec<String> = list.iter().map(|m| format!("{{{m}}}")).collect();
                    arrays += &format!("\"{key}\": [{}], ", objects.join(", "));
                }
            }
            (materials, arrays)
        })
        .boxed()
}

/// A glTF document around `buffer` (the members of buffer 0, whose bytes from `tail_at` are
/// [`tail`]'s): every part present or not, indices valid or dangling, values in and out of the
/// specification's ranges; images, samplers, textures, sparse accessors and extensions among
/// them.
fn gltf_json(buffer: String, tail_at: usize) -> BoxedStrategy<String> {
    let accessor = weighted_members(vec![
        ("bufferView", 0.95, index()),
        ("byteOffset", 0.8, int(0..16)),
        (
            "componentType!",
            1.0,
            one_of(vec![
                "5120", "5121", "5122", "5123", "5125", "5126", "5126", "5126",
            ]),
        ),
        ("count!", 1.0, int(0..40)),
        (
            "type!",
            1.0,
            one_of(vec![
                "\"SCALAR\"",
                "\"VEC2\"",
                "\"VEC3\"",
                "\"VEC3\"",
                "\"VEC4\"",
                "\"MAT4\"",
            ]),
        ),
        (
            "normalized",
            0.3,
            any::<bool>().prop_map(|b| b.to_string()).boxed(),
        ),
        ("min!", 1.0, array(3, -2.0, 0.0)),
        ("max!", 1.0, array(3, 0.0, 2.0)),
        ("sparse", 0.25, sparse()),
    ]);
    let view = members(
        vec![
            ("buffer!", mostly(Just("0".to_owned()).boxed(), index())),
            ("byteOffset", int(0..80)),
            ("byteLength!", int(0..160)),
            ("byteStride", one_of(vec!["12", "16", "13"])),
        ],
        0.8,
    );
    let primitive = members(
        vec![
            (
                "attributes!",
                members(
                    vec![
                        ("POSITION!", index()),
                        ("NORMAL", index()),
                        ("COLOR_0", index()),
                        ("TEXCOORD_0", index()),
                    ],
                    0.6,
                )
                .prop_map(|m| format!("{{{m}}}"))
                .boxed(),
            ),
            ("indices", index()),
            ("mode", int(0..8)),
            ("material", index()),
        ],
        0.7,
    );
    let mesh = objects("", primitive, 3)
        .prop_map(|p| format!("\"primitives\": {p}"))
        .boxed();
    let light_of_node = || index().prop_map(|i| format!("\"KHR_lights_punctual\": {{\"light\": {i}}}"));
    // Matrices mostly affine (a last row of 0, 0, 0, 1), rotations mostly unit quaternions:
    // glTF 2.0 refuses the others, and the rest of the node should be reached.
    let affine = (array(12, -2.0, 2.0), prop::bool::weighted(0.9))
        .prop_map(
            |(m, affine)| match m.strip_prefix('[').and_then(|m| m.strip_suffix(']')) {
                Some(inner) if affine && inner.split(", ").count() == 12 => {
                    let v: Vec<&str> = inner.split(", ").collect();
                    format!(
                        "[{}, 0, {}, 0, {}, 0, {}, 1]",
                        v[0..3].join(", "),
                        v[3..6].join(", "),
                        v[6..9].join(", "),
                        v[9..12].join(", ")
                    )
                }
                _ => m,
            },
        )
        .boxed();
    let unit = prop::collection::vec(-1.0f64..1.0, 4)
        .prop_map(|q| {
            let length = q.iter().map(|c| c * c).sum::<f64>().sqrt().max(1e-3);
            format!(
                "[{}]",
                q.iter()
                    .map(|c| format!("{:?}", c / length))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        })
        .boxed();
    let node = weighted_members(vec![
        ("mesh", 0.4, index()),
        ("children", 0.4, indices()),
        ("matrix", 0.15, affine),
        ("translation", 0.4, array(3, -2.0, 2.0)),
        (
            "rotation",
            0.4,
            prop_oneof![6 => unit, 1 => array(4, -1.0, 1.0)].boxed(),
        ),
        ("scale", 0.4, array(3, -2.0, 2.0)),
        (
            "extensions",
            0.4,
            prop_oneof![
                3 => light_of_node().prop_map(|l| format!("{{{l}}}")),
                1 => (light_of_node(), unknown_value())
                    .prop_map(|(l, v)| format!("{{{l}, \"X_foo\": {v}}}")),
                1 => unknown_extensions(),
            ]
            .boxed(),
        ),
    ]);
    let factor = || mostly((0.0f64..1.0).prop_map(|x| format!("{x:?}")).boxed(), number());
    let material = weighted_members(vec![
        (
            "pbrMetallicRoughness",
            0.6,
            weighted_members(vec![
                ("baseColorFactor", 0.6, array(4, 0.0, 1.0)),
                ("metallicFactor", 0.6, factor()),
                ("roughnessFactor", 0.6, factor()),
                ("baseColorTexture", 0.25, texture_info()),
            ])
            .prop_map(|m| format!("{{{m}}}"))
            .boxed(),
        ),
        ("emissiveFactor", 0.6, array(3, 0.0, 1.0)),
        ("emissiveTexture", 0.15, texture_info()),
        (
            "doubleSided",
            0.6,
            any::<bool>().prop_map(|b| b.to_string()).boxed(),
        ),
        ("extensions", 0.4, material_extensions()),
    ]);
    let light = members(
        vec![
            ("type!", one_of(vec!["\"point\"", "\"spot\"", "\"directional\""])),
            ("color", array(3, 0.0, 1.0)),
            (
                "intensity",
                mostly((0.0f64..10.0).prop_map(|x| format!("{x:?}")).boxed(), number()),
            ),
            ("range", number()),
            (
                "spot",
                (number(), number())
                    .prop_map(|(i, o)| format!("{{\"innerConeAngle\": {i}, \"outerConeAngle\": {o}}}"))
                    .boxed(),
            ),
        ],
        0.7,
    );
    let used = prop::sample::subsequence(
        vec![
            "\"KHR_lights_punctual\"",
            "\"KHR_draco_mesh_compression\"",
            "\"KHR_materials_emissive_strength\"",
            "\"KHR_texture_transform\"",
            "\"KHR_mesh_quantization\"",
            "\"EXT_meshopt_compression\"",
            "\"KHR_materials_unlit\"",
            "\"X_foo\"",
        ],
        0..=8,
    )
    .prop_map(|v| v.join(", "))
    .boxed();
    // Mostly none; then extensions ffvk supports; rarely one it neither supports nor may ignore.
    let required = prop_oneof![
        30 => Just(""),
        6 => Just("\"KHR_texture_transform\""),
        2 => Just("\"KHR_materials_emissive_strength\", \"KHR_texture_transform\""),
        1 => prop::sample::select(vec![
            "\"KHR_draco_mesh_compression\"",
            "\"KHR_lights_punctual\"",
            "\"KHR_mesh_quantization\"",
            "\"EXT_meshopt_compression\"",
            "\"KHR_materials_unlit\"",
            "\"X_foo\"",
        ]),
    ]
    .prop_map(str::to_owned)
    .boxed();
    let root_extension = prop::option::weighted(0.3, unknown_value())
        .prop_map(|v| v.map(|v| format!(", \"X_foo\": {v}")).unwrap_or_default())
        .boxed();
    // Buffer views 0 (the triangle's floats), 1 (sparse indices) and 2 (the PNG).
    let first_views = format!(
        r#"{{"buffer": 0, "byteLength": 36}}, {{"buffer": 0, "byteOffset": {tail_at}, "byteLength": {SPARSE_INDEX_BYTES}}},
    {{"buffer": 0, "byteOffset": {}, "byteLength": {}}}"#,
        tail_at + SPARSE_INDEX_BYTES,
        png().len()
    );
    (
        mostly(Just("\"2.0\"".to_owned()).boxed(), prop::sample::select(vec!["\"3.0\"", "2", "\"2.1\""]).prop_map(str::to_owned).boxed()),
        // A first element of each that loads (a triangle at the start of the buffer, placed by
        // node 0), so that the generated rest reaches past the parser and validator.
        objects_after(first_accessor(), accessor, 3),
        objects_after(Just(first_views).boxed(), view, 2),
        objects(r#"{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}"#, mesh, 2),
        objects(r#"{"mesh": 0}"#, node, 3),
        mostly(Just("[0]".to_owned()).boxed(), indices()),
        texturing(material),
        objects(r#"{"type": "point", "intensity": 2}"#, light, 2),
        (used, required, root_extension),
    )
        .prop_map(move |(version, accessors, views, meshes, nodes, roots, (materials, textures), lights, (used, required, root_extension))| {
            format!(
                r#"{{"asset": {{"version": {version}}}, "buffers": [{{{buffer}}}], "bufferViews": {views},
  "accessors": {accessors}, "meshes": {meshes}, "nodes": {nodes}, "scenes": [{{"nodes": {roots}}}], "scene": 0,
  "materials": {materials}, {textures}"extensionsUsed": [{used}], "extensionsRequired": [{required}],
  "extensions": {{"KHR_lights_punctual": {{"lights": {lights}}}{root_extension}}}}}"#
            )
        })
        .boxed()
}

/// What a generated asset is written as; `json` is its document as generated, before a GLB's
/// damage.
#[derive(Debug, Clone)]
enum Asset {
    /// `.gltf` with the buffer in `f.bin` (or a data URI, or a URI that leaves the folder).
    Gltf { json: String, bin: Vec<u8> },
    /// `.glb` bytes, sometimes with damaged header or chunk lengths.
    Glb { json: String, bytes: Vec<u8> },
}

/// What is done to a GLB's bytes.
#[derive(Debug, Clone)]
enum Damage {
    /// One byte anywhere in the first 40 (headers and the start of the JSON).
    Byte(usize, u8),
    /// A header word replaced: at 4 (version), 8 (length) or 12 (JSON chunk length).
    Word(usize, u32),
    /// The file cut short.
    Cut(usize),
}

fn damage() -> BoxedStrategy<Damage> {
    prop_oneof![
        (0usize..40, any::<u8>()).prop_map(|(at, b)| Damage::Byte(at, b)),
        (
            prop::sample::select(vec![4usize, 8, 12]),
            prop_oneof![
                prop::sample::select(vec![0u32, 1, 2, 3, 11, 12, 19, 20, 21, u32::MAX]),
                any::<u32>()
            ],
        )
            .prop_map(|(at, v)| Damage::Word(at, v)),
        (0usize..200).prop_map(Damage::Cut),
    ]
    .boxed()
}

fn asset() -> BoxedStrategy<Asset> {
    let bin = prop_oneof![
        // Floats in [-2, 2] with some NaN: positions and normals that mean something.
        3 => prop::collection::vec(prop_oneof![30 => -2.0f32..2.0, 1 => Just(f32::NAN)], 9..40)
            .prop_map(|v| bytemuck::cast_slice::<f32, u8>(&v).to_vec()),
        1 => prop::collection::vec(any::<u8>(), 0..200),
    ];
    let uri = prop::sample::select(vec![
        "\"uri\": \"f.bin\"",
        "\"uri\": \"f.bin\"",
        "\"uri\": \"f.bin\"",
        "\"uri\": \"f.bin\"",
        "\"uri\": \"../f.bin\"",
        "\"uri\": \"%zz\"",
        "\"uri\": \"missing.bin\"",
        "DATA",
        "DATA",
        "",
    ]);
    // Mostly the bin's own length.
    let length = prop::option::weighted(0.15, number());
    (
        bin,
        uri,
        length,
        any::<bool>(),
        prop::option::weighted(0.15, damage()),
    )
        .prop_flat_map(|(mut bin, uri, length, as_glb, damage)| {
            // Buffer views 1 and 2 read what follows the generated bytes.
            let tail_at = bin.len().next_multiple_of(4);
            bin.resize(tail_at, 0);
            bin.extend(tail());
            let length = length.unwrap_or_else(|| bin.len().to_string());
            // A GLB's buffer 0 is its BIN chunk, named by leaving the URI out.
            let uri = if as_glb && uri == "\"uri\": \"f.bin\"" {
                ""
            } else {
                uri
            };
            let uri = if uri == "DATA" {
                format!(
                    "\"uri\": \"data:application/octet-stream;base64,{}\"",
                    base64(&bin)
                )
            } else {
                uri.to_owned()
            };
            let buffer = if uri.is_empty() {
                format!("\"byteLength\": {length}")
            } else {
                format!("{uri}, \"byteLength\": {length}")
            };
            gltf_json(buffer, tail_at).prop_map(move |json| {
                if as_glb {
                    let mut bytes = glb(json.as_bytes(), Some(&bin));
                    match damage {
                        None => {}
                        Some(Damage::Byte(at, byte)) => {
                            let at = at % bytes.len();
                            bytes[at] = byte;
                        }
                        // The header's version (4), its length (8) or the JSON chunk's (12).
                        Some(Damage::Word(at, value)) => {
                            bytes[at..at + 4].copy_from_slice(&value.to_le_bytes())
                        }
                        Some(Damage::Cut(at)) => bytes.truncate(at % (bytes.len() + 1)),
                    }
                    Asset::Glb { json, bytes }
                } else {
                    Asset::Gltf {
                        json,
                        bin: bin.clone(),
                    }
                }
            })
        })
        .boxed()
}

/// The parts of a document the reach table counts, in its order.
const FAMILIES: [&str; 5] = ["images", "samplers", "textures", "sparse", "extensions"];

/// Extension names the extension family writes (as objects, or in extensionsUsed and
/// extensionsRequired).
const NEW_EXTENSIONS: &[&str] = &[
    "KHR_materials_emissive_strength",
    "KHR_texture_transform",
    "KHR_mesh_quantization",
    "EXT_meshopt_compression",
    "KHR_materials_unlit",
    "X_foo",
    "EXT_unknown",
];

/// The elements of the root's array `key` (none where there is none).
fn elements<'a>(root: &'a serde_json::Value, key: &str) -> &'a [serde_json::Value] {
    root.get(key)
        .and_then(serde_json::Value::as_array)
        .map(Vec::as_slice)
        .unwrap_or_default()
}

/// Which of [`FAMILIES`] the document `json` holds: a non-empty images, samplers or textures
/// array (or, for textures, a material that names one), an accessor with `sparse`, a name
/// from [`NEW_EXTENSIONS`].
fn families(json: &str) -> [bool; 5] {
    let Ok(root) = serde_json::from_str::<serde_json::Value>(json) else {
        return [false; 5];
    };
    let names_texture = elements(&root, "materials").iter().any(|m| {
        m.get("emissiveTexture").is_some() || m.pointer("/pbrMetallicRoughness/baseColorTexture").is_some()
    });
    [
        !elements(&root, "images").is_empty(),
        !elements(&root, "samplers").is_empty(),
        !elements(&root, "textures").is_empty() || names_texture,
        elements(&root, "accessors")
            .iter()
            .any(|a| a.get("sparse").is_some()),
        NEW_EXTENSIONS.iter().any(|e| json.contains(&format!("\"{e}\""))),
    ]
}

/// Why the document `json` must not load, judged on the parts the families add (`None` where
/// those hold nothing the specification forbids and ffvk checks; the rest may still be wrong):
/// an image without exactly one of uri and bufferView, or in a view without its mimeType; a
/// sampler enum GL does not have for its field; a texture without an image; an index past its
/// array (a texture's source and sampler, a textureInfo's, an image's or a sparse part's view);
/// sparse indices of another type than UNSIGNED_BYTE, SHORT or INT; an emissiveStrength that is
/// not a finite f32 ≥ 0; a required extension ffvk neither supports nor may ignore. An index
/// is a JSON integer below the array's length: 2^32 + i is not i.
fn must_refuse(json: &str) -> Option<String> {
    use serde_json::Value;
    let root: Value = serde_json::from_str(json).ok()?;
    let names = |index: Option<&Value>, array: &str| {
        index
            .and_then(Value::as_u64)
            .is_some_and(|i| i < elements(&root, array).len() as u64)
    };
    // serde reads null as absent for the optional members.
    let given = |object: &Value, key: &str| object.get(key).filter(|v| !v.is_null()).cloned();
    for (i, image) in elements(&root, "images").iter().enumerate() {
        let valid = match (given(image, "uri"), given(image, "bufferView")) {
            (Some(_), None) => true,
            (None, Some(view)) => given(image, "mimeType").is_some() && names(Some(&view), "bufferViews"),
            _ => false,
        };
        if !valid {
            return Some(format!("images[{i}] is {image}"));
        }
    }
    const MAG: &[u64] = &[9728, 9729];
    const MIN: &[u64] = &[9728, 9729, 9984, 9985, 9986, 9987];
    const WRAP: &[u64] = &[33071, 33648, 10497];
    for (i, sampler) in elements(&root, "samplers").iter().enumerate() {
        // The filters are optional (null is none); the wrap modes have defaults, not null.
        for (key, valid, optional) in [
            ("magFilter", MAG, true),
            ("minFilter", MIN, true),
            ("wrapS", WRAP, false),
            ("wrapT", WRAP, false),
        ] {
            let value = if optional {
                given(sampler, key)
            } else {
                sampler.get(key).cloned()
            };
            if let Some(value) = value {
                if !value.as_u64().is_some_and(|v| valid.contains(&v)) {
                    return Some(format!("samplers[{i}].{key} is {value}"));
                }
            }
        }
    }
    for (i, texture) in elements(&root, "textures").iter().enumerate() {
        if !names(texture.get("source"), "images") {
            return Some(format!("textures[{i}] is {texture}: its source names no image"));
        }
        if given(texture, "sampler").is_some_and(|s| !names(Some(&s), "samplers")) {
            return Some(format!("textures[{i}] is {texture}: its sampler names none"));
        }
    }
    for (i, material) in elements(&root, "materials").iter().enumerate() {
        for pointer in ["/pbrMetallicRoughness/baseColorTexture", "/emissiveTexture"] {
            if let Some(info) = material.pointer(pointer) {
                if !names(info.get("index"), "textures") {
                    return Some(format!("materials[{i}]{pointer} is {info}: it names no texture"));
                }
            }
        }
        let strength = "/extensions/KHR_materials_emissive_strength/emissiveStrength";
        if let Some(s) = material.pointer(strength) {
            if !s.as_f64().is_some_and(|x| x >= 0.0 && (x as f32).is_finite()) {
                return Some(format!("materials[{i}]{strength} is {s}"));
            }
        }
    }
    for (i, accessor) in elements(&root, "accessors").iter().enumerate() {
        let Some(sparse) = accessor.get("sparse") else {
            continue;
        };
        let kind = sparse.pointer("/indices/componentType").and_then(Value::as_u64);
        if !kind.is_some_and(|k| [5121, 5123, 5125].contains(&k)) {
            return Some(format!(
                "accessors[{i}].sparse is {sparse}: its index type is none"
            ));
        }
        for view in ["/indices/bufferView", "/values/bufferView"] {
            if !names(sparse.pointer(view), "bufferViews") {
                return Some(format!("accessors[{i}].sparse is {sparse}: {view} names no view"));
            }
        }
    }
    if let Some(why) = breaks_node_or_accessor_rules(&root) {
        return Some(why);
    }
    use ffvk::scene::gltf::{SUPPORTED_EXTENSIONS, TEXTURE_EXTENSIONS};
    for name in elements(&root, "extensionsRequired")
        .iter()
        .filter_map(Value::as_str)
    {
        if !SUPPORTED_EXTENSIONS.contains(&name) && !TEXTURE_EXTENSIONS.contains(&name) {
            return Some(format!("extensionsRequired names {name}"));
        }
    }
    None
}

/// What glTF 2.0 asks of nodes, accessors and extensions that the document breaks, if
/// anything: `normalized` on FLOAT or UNSIGNED_INT data or on indices; a node's matrix with
/// TRS, one whose last row is not (0, 0, 0, 1), a rotation of length off 1 by more than 0.01;
/// a node listed as a child twice in all, a node its own ancestor, a scene root that is a
/// child; an extension ffvk reads that `extensionsUsed` leaves out.
fn breaks_node_or_accessor_rules(root: &serde_json::Value) -> Option<String> {
    use serde_json::Value;
    let accessors = elements(root, "accessors");
    for (i, a) in accessors.iter().enumerate() {
        let kind = a.get("componentType").and_then(Value::as_u64);
        if a.get("normalized") == Some(&Value::Bool(true)) && matches!(kind, Some(5125 | 5126)) {
            return Some(format!("accessors[{i}] is normalized {kind:?} data"));
        }
    }
    for mesh in elements(root, "meshes") {
        for p in mesh
            .get("primitives")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
        {
            let indices = p
                .get("indices")
                .and_then(Value::as_u64)
                .and_then(|i| accessors.get(i as usize));
            if indices.is_some_and(|a| a.get("normalized") == Some(&Value::Bool(true))) {
                return Some(format!("the indices of {p} are normalized"));
            }
        }
    }
    let numbers = |v: Option<&Value>, len: usize| {
        let v: Vec<f64> = v?.as_array()?.iter().filter_map(Value::as_f64).collect();
        (v.len() == len).then_some(v)
    };
    let nodes = elements(root, "nodes");
    let mut parent: Vec<Option<usize>> = vec![None; nodes.len()];
    for (i, node) in nodes.iter().enumerate() {
        let given = |key: &str| node.get(key).is_some_and(|v| !v.is_null());
        if given("matrix") && (given("translation") || given("rotation") || given("scale")) {
            return Some(format!("nodes[{i}] has a matrix and TRS"));
        }
        if let Some(m) = numbers(node.get("matrix"), 16) {
            if [m[3], m[7], m[11], m[15]] != [0.0, 0.0, 0.0, 1.0] {
                return Some(format!("nodes[{i}].matrix is projective"));
            }
        }
        if let Some(q) = numbers(node.get("rotation"), 4) {
            let length = q.iter().map(|c| (*c as f32).powi(2)).sum::<f32>().sqrt();
            if (length - 1.0).abs() > 0.0101 {
                return Some(format!("nodes[{i}].rotation has length {length}"));
            }
        }
        for c in node
            .get("children")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
        {
            if let Some(c) = c.as_u64().map(|c| c as usize).filter(|&c| c < nodes.len()) {
                if parent[c].replace(i).is_some() {
                    return Some(format!("node {c} is listed as a child twice"));
                }
            }
        }
    }
    for start in 0..nodes.len() {
        let (mut at, mut steps) = (parent[start], 0);
        while let Some(p) = at {
            if p == start || steps > nodes.len() {
                return Some(format!("node {start} is its own ancestor"));
            }
            (at, steps) = (parent[p], steps + 1);
        }
    }
    for scene in elements(root, "scenes") {
        let roots: Vec<u64> = scene
            .get("nodes")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
            .filter_map(Value::as_u64)
            .collect();
        for (k, &r) in roots.iter().enumerate() {
            if parent.get(r as usize).copied().flatten().is_some() || roots[..k].contains(&r) {
                return Some(format!("scene root {r} is a child or listed twice"));
            }
        }
    }
    let used: Vec<&str> = elements(root, "extensionsUsed")
        .iter()
        .filter_map(Value::as_str)
        .collect();
    let mut stack = vec![root];
    while let Some(value) = stack.pop() {
        match value {
            Value::Array(items) => stack.extend(items),
            Value::Object(members) => {
                for (key, item) in members {
                    match (key.as_str(), item) {
                        ("extras", _) => {}
                        ("extensions", Value::Object(extensions)) => {
                            for (name, object) in extensions {
                                if ffvk::scene::gltf::SUPPORTED_EXTENSIONS.contains(&name.as_str())
                                    && !used.contains(&name.as_str())
                                {
                                    return Some(format!("{name} is used and not listed in extensionsUsed"));
                                }
                                stack.push(object);
                            }
                        }
                        _ => stack.push(item),
                    }
                }
            }
            _ => {}
        }
    }
    None
}

/// How often a family was generated, and loaded.
#[derive(Debug, Clone, Copy, Default)]
struct Reach {
    cases: u32,
    loaded: u32,
}

#[test]
fn generated_gltf_and_glb_files_load_or_fail_with_an_error() {
    use ffvk::scene::gltf::{load, load_with, TextureMean, Textures};
    let dir = sandbox("gltf");
    let asset_dir = dir.join("asset");
    std::fs::create_dir_all(&asset_dir).unwrap();
    std::fs::write(dir.join("f.bin"), [0u8; 64]).unwrap();
    // The image the documents' "t.png" names; the one above is what "../t.png" would read.
    std::fs::write(asset_dir.join("t.png"), png()).unwrap();
    std::fs::write(dir.join("t.png"), png()).unwrap();
    let (loaded, refused, decoded) = (Cell::new(0), Cell::new(0), Cell::new(0));
    let reach = RefCell::new([Reach::default(); FAMILIES.len()]);
    // After a failure the runner only shrinks it: those runs are not counted.
    let failed = Cell::new(false);
    let result = runner(1000).run(&asset(), |asset| {
        let (path, json) = match &asset {
            Asset::Gltf { json, bin } => {
                std::fs::write(asset_dir.join("f.bin"), bin).unwrap();
                std::fs::write(asset_dir.join("a.gltf"), json).unwrap();
                (asset_dir.join("a.gltf"), json)
            }
            Asset::Glb { json, bytes } => {
                std::fs::write(asset_dir.join("a.glb"), bytes).unwrap();
                (asset_dir.join("a.glb"), json)
            }
        };
        // As the tool loads it (textures named, not read), then with every base color and
        // emissive texture decoded for its mean, which may warn but never refuse.
        let outcome = within(Duration::from_secs(20), "gltf::load", move || {
            let plain = load(&path).map(|l| l.meshes.len()).map_err(|e| e.to_string());
            let limits = Limits::default();
            let mut budget = ffvk::scene::MeshBudget::new(limits.mesh_bytes);
            let means = load_with(&path, &limits, &mut budget, Textures::Means)
                .map(|l| {
                    let read = |t: Option<TextureMean>| matches!(t, Some(TextureMean::Mean(_)));
                    let decoded = l
                        .meshes
                        .iter()
                        .filter_map(|m| m.material.as_ref())
                        .any(|m| read(m.base_color_texture) || read(m.emissive_texture));
                    (l.meshes.len(), decoded)
                })
                .map_err(|e| e.to_string());
            (plain, means)
        });
        let (plain, means) = match outcome {
            Ok(outcome) => outcome,
            Err(panic_or_hang) => {
                failed.set(true);
                return Err(panic_or_hang);
            }
        };
        if !failed.get() {
            let counter = if plain.is_ok() { &loaded } else { &refused };
            counter.set(counter.get() + 1);
            if matches!(means, Ok((_, true))) {
                decoded.set(decoded.get() + 1);
            }
            for (reach, present) in reach.borrow_mut().iter_mut().zip(families(json)) {
                reach.cases += u32::from(present);
                reach.loaded += u32::from(present && plain.is_ok());
            }
        }
        let check = || -> Result<(), TestCaseError> {
            match &plain {
                Ok(meshes) => {
                    prop_assert_eq!(
                        means.as_ref().map(|(m, _)| *m).map_err(String::as_str),
                        Ok(*meshes),
                        "reading textures changed what loads"
                    );
                    if let Some(why) = must_refuse(json) {
                        return Err(TestCaseError::fail(format!("loaded although {why}")));
                    }
                }
                Err(message) => {
                    prop_assert!(message.contains("a.gl"), "names the file: {message}");
                    prop_assert!(
                        !message.contains("../f.bin") || message.contains("leaves the asset's folder"),
                        "{message}"
                    );
                    prop_assert_eq!(
                        means.as_ref().map(|_| ()).map_err(String::as_str),
                        Err(message.as_str()),
                        "reading textures changed the error"
                    );
                }
            }
            Ok(())
        };
        let checked = check();
        failed.set(failed.get() || checked.is_err());
        checked
    });
    let (loaded, refused, decoded) = (loaded.get(), refused.get(), decoded.get());
    let reach = reach.into_inner();
    // The reach table: how often each family was generated, and how often a file with it
    // loaded (so the generator gets past the loader's refusals, not only into them).
    eprintln!("glTF/GLB cases: {loaded} loaded, {refused} refused; {decoded} read a texture's image");
    eprintln!("  {:<10} {:>6} {:>7}", "family", "cases", "loaded");
    for (name, r) in FAMILIES.iter().zip(&reach) {
        eprintln!("  {name:<10} {:>6} {:>7}", r.cases, r.loaded);
    }
    result.unwrap();
    assert!(loaded > 0 && refused > 0, "{loaded} loaded, {refused} refused");
    for (name, r) in FAMILIES.iter().zip(&reach) {
        assert!(r.loaded > 0, "no file with {name} loaded ({} generated)", r.cases);
    }
    assert!(decoded > 0, "no load read a texture's image");
}

// ---------------------------------------------------------------------------------------------
// Node graphs and texture counts

/// A generated node graph and the textures its materials name: what a file can make the loader
/// walk and decode.
#[derive(Debug, Clone)]
struct Graph {
    /// Each node's children, as written (duplicates and indices of any node allowed).
    children: Vec<Vec<usize>>,
    /// Which nodes place the mesh.
    meshes: Vec<bool>,
    /// Scene 0's nodes.
    roots: Vec<usize>,
    /// The mesh's primitives (each one placement per node that places the mesh).
    primitives: usize,
    /// Each image's source: 0 `a.png`, 1 `./a.png` (the same file), 2 `b.png` (a copy), 3 a
    /// data URI of the same PNG.
    images: Vec<usize>,
    /// Each material's base color and emissive texture (texture i shows image i).
    materials: Vec<(Option<usize>, Option<usize>)>,
}

/// Forests (each node given a parent before it or none, the parentless ones the roots), some
/// then broken: an edge added (a second parent, a child listed twice, a cycle, a root made a
/// child), a root listed again or one that is a child, or children drawn at random.
fn graph() -> BoxedStrategy<Graph> {
    let nodes = 1usize..24;
    (
        nodes,
        prop::collection::vec((0u8..4, any::<prop::sample::Index>()), 24),
        prop::collection::vec(prop::bool::weighted(0.6), 24),
        prop::collection::vec(prop::collection::vec(0usize..24, 0..3), 24),
        (
            0u8..10,
            any::<prop::sample::Index>(),
            any::<prop::sample::Index>(),
        ),
        1usize..4,
        prop::collection::vec(0usize..4, 0..30),
        prop::collection::vec(
            (
                prop::option::weighted(0.7, any::<prop::sample::Index>()),
                prop::option::weighted(0.3, any::<prop::sample::Index>()),
            ),
            0..12,
        ),
    )
        .prop_map(
            |(n, parents, meshes, random, (change, a, b), primitives, images, materials)| {
                let mut children = vec![Vec::new(); n];
                let mut has_parent = vec![false; n];
                for i in 1..n {
                    // One in four nodes is a root; the others hang below an earlier node.
                    let (root, parent) = parents[i];
                    if root != 0 {
                        children[parent.index(i)].push(i);
                        has_parent[i] = true;
                    }
                }
                let mut roots: Vec<usize> = (0..n).filter(|&i| !has_parent[i]).collect();
                match change {
                    // An edge from any node to any: a second parent, a child twice, a cycle, a
                    // root made a child (or, by chance, an edge that keeps a forest).
                    0 | 1 => children[a.index(n)].push(b.index(n)),
                    2 => roots.push(a.index(n)),
                    3 => {
                        children = random
                            .into_iter()
                            .take(n)
                            .map(|c| c.into_iter().filter(|&i| i < n).collect())
                            .collect()
                    }
                    _ => {}
                }
                let textures = images.len();
                let pick =
                    |i: Option<prop::sample::Index>| i.filter(|_| textures > 0).map(|i| i.index(textures));
                Graph {
                    children,
                    meshes: meshes[..n].to_vec(),
                    roots,
                    primitives,
                    images,
                    materials: materials.into_iter().map(|(b, e)| (pick(b), pick(e))).collect(),
                }
            },
        )
        .boxed()
}

impl Graph {
    fn json(&self) -> String {
        let nodes: Vec<String> = self
            .children
            .iter()
            .zip(&self.meshes)
            .map(|(children, &mesh)| {
                let children: Vec<String> = children.iter().map(usize::to_string).collect();
                let mesh = if mesh { r#""mesh": 0, "# } else { "" };
                format!(r#"{{{mesh}"children": [{}]}}"#, children.join(", "))
            })
            .collect();
        let primitives: Vec<String> = (0..self.primitives)
            .map(|p| match self.materials.len() {
                0 => r#"{"attributes": {"POSITION": 0}, "indices": 1}"#.to_owned(),
                m => format!(
                    r#"{{"attributes": {{"POSITION": 0}}, "indices": 1, "material": {}}}"#,
                    p % m
                ),
            })
            .collect();
        let info = |t: Option<usize>| t.map(|t| format!(r#"{{"index": {t}}}"#));
        let materials: Vec<String> = self
            .materials
            .iter()
            .map(|&(base, emissive)| {
                let mut members = Vec::new();
                if let Some(b) = info(base) {
                    members.push(format!(r#""pbrMetallicRoughness": {{"baseColorTexture": {b}}}"#));
                }
                if let Some(e) = info(emissive) {
                    members.push(format!(r#""emissiveTexture": {e}"#));
                }
                format!("{{{}}}", members.join(", "))
            })
            .collect();
        let sources = [
            r#""uri": "a.png""#.to_owned(),
            r#""uri": "./a.png""#.to_owned(),
            r#""uri": "b.png""#.to_owned(),
            format!(r#""uri": "data:image/png;base64,{}""#, base64(png())),
        ];
        let images: Vec<String> = self
            .images
            .iter()
            .map(|&s| format!("{{{}}}", sources[s]))
            .collect();
        let textures: Vec<String> = (0..self.images.len())
            .map(|i| format!(r#"{{"source": {i}}}"#))
            .collect();
        let roots: Vec<String> = self.roots.iter().map(usize::to_string).collect();
        format!(
            r#"{{"asset": {{"version": "2.0"}},
  "buffers": [{{"uri": "quad.bin", "byteLength": 60}}],
  "bufferViews": [{{"buffer": 0, "byteLength": 48}}, {{"buffer": 0, "byteOffset": 48, "byteLength": 12}}],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]}},
    {{"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}}],
  "meshes": [{{"primitives": [{}]}}], "materials": [{}], "textures": [{}], "images": [{}],
  "nodes": [{}], "scenes": [{{"nodes": [{}]}}], "scene": 0}}"#,
            primitives.join(", "),
            materials.join(", "),
            textures.join(", "),
            images.join(", "),
            nodes.join(", "),
            roots.join(", ")
        )
    }

    /// Whether the hierarchy is what glTF 2.0 asks: every node listed as a child at most
    /// once in all, no node its own ancestor, scene roots parentless and listed once.
    fn is_forest(&self) -> bool {
        let n = self.children.len();
        let mut parent = vec![None; n];
        for (p, children) in self.children.iter().enumerate() {
            for &c in children {
                if parent[c].replace(p).is_some() {
                    return false;
                }
            }
        }
        let acyclic = (0..n).all(|start| {
            let (mut at, mut steps) = (parent[start], 0);
            while let Some(p) = at {
                if p == start || steps > n {
                    return false;
                }
                (at, steps) = (parent[p], steps + 1);
            }
            true
        });
        let roots_ok = self
            .roots
            .iter()
            .enumerate()
            .all(|(k, &r)| parent[r].is_none() && !self.roots[..k].contains(&r));
        acyclic && roots_ok
    }

    /// The placements of a forest: the primitives of each node below a root that places
    /// the mesh, and what they count against the limit (each the nodes on its path).
    fn placements(&self) -> (usize, usize) {
        let mut stack: Vec<(usize, usize)> = self.roots.iter().map(|&r| (r, 1)).collect();
        let (mut count, mut weight) = (0, 0);
        while let Some((node, depth)) = stack.pop() {
            let placed = usize::from(self.meshes[node]) * self.primitives;
            count += placed;
            weight += placed * depth;
            stack.extend(self.children[node].iter().map(|&c| (c, depth + 1)));
        }
        (count, weight)
    }

    /// The images decoded: the distinct files or data the materials' textures show.
    fn decoded(&self) -> usize {
        let mut sources: Vec<usize> = self
            .materials
            .iter()
            .flat_map(|&(b, e)| [b, e])
            .flatten()
            .map(|t| match self.images[t] {
                1 => 0,
                s => s,
            })
            .collect();
        sources.sort_unstable();
        sources.dedup();
        sources.len()
    }
}

/// Generated node graphs (forests, and graphs with shared children, children listed twice,
/// cycles reached or not, roots that are children) and texture counts (up to 30 images over
/// three files and a data URI), loaded with small limits: a graph that is not a forest is
/// refused naming nodes, a forest past the placement limit names --max-placements, textures
/// past the texture limit (an image decoded once however many images name it) name
/// --max-texture-mib, and anything else loads; never a panic, a hang or an unbounded walk.
#[test]
fn generated_node_graphs_and_texture_counts_load_or_are_refused_within_their_limits() {
    use ffvk::scene::gltf::{load_with, Textures};
    let dir = sandbox("graphs");
    let corners: [f32; 12] = [-1., -1., 0., 1., -1., 0., 1., 1., 0., -1., 1., 0.];
    let mut bin = bytemuck::cast_slice::<f32, u8>(&corners).to_vec();
    bin.extend(bytemuck::cast_slice::<u16, u8>(&[0, 1, 2, 0, 2, 3]));
    std::fs::write(dir.join("quad.bin"), bin).unwrap();
    std::fs::write(dir.join("a.png"), png()).unwrap();
    std::fs::write(dir.join("b.png"), png()).unwrap();
    // Placements count the nodes on their paths. A 2×2 image takes 20 bytes with its
    // mipmaps: two fit, a third does not.
    const PLACEMENTS: usize = 60;
    let limits = Limits::default()
        .with_placements(PLACEMENTS as u64)
        .with_texture_bytes(40);
    let counts = RefCell::new([0u32; 4]);
    let result = runner(300).run(&graph(), |graph| {
        let path = dir.join("g.gltf");
        std::fs::write(&path, graph.json()).unwrap();
        let limits = limits.clone();
        let outcome = within(Duration::from_secs(20), "gltf::load_with", move || {
            let mut budget = ffvk::scene::MeshBudget::new(limits.mesh_bytes);
            load_with(&path, &limits, &mut budget, Textures::Means)
                .map(|l| l.meshes.len())
                .map_err(|e| e.to_string())
        })?;
        let (expected, slot) = if !graph.is_forest() {
            ("a forest", 0)
        } else if graph.placements().1 > PLACEMENTS {
            ("--max-placements", 1)
        } else if graph.decoded() > 2 {
            ("--max-texture-mib", 2)
        } else {
            ("", 3)
        };
        counts.borrow_mut()[slot] += 1;
        match (&outcome, expected) {
            (Ok(meshes), "") => prop_assert_eq!(*meshes, graph.placements().0),
            (Err(e), "a forest") => prop_assert!(
                e.contains("g.gltf") && (e.contains("disjoint trees") || e.contains("scenes[0].nodes[")),
                "{}",
                e
            ),
            (Err(e), words) if !words.is_empty() => {
                prop_assert!(e.contains(words), "expected {}: {}", words, e)
            }
            _ => {
                return Err(TestCaseError::fail(format!(
                    "expected {expected:?}, got {outcome:?}"
                )))
            }
        }
        Ok(())
    });
    let counts = counts.into_inner();
    eprintln!(
        "node graphs: {} not forests, {} past the placements, {} past the textures, {} loaded",
        counts[0], counts[1], counts[2], counts[3]
    );
    result.unwrap();
    assert!(counts.iter().all(|&c| c > 0), "every outcome reached: {counts:?}");
}

// ---------------------------------------------------------------------------------------------
// Command lines

fn token() -> BoxedStrategy<String> {
    prop::sample::select(vec![
        "render",
        "explain",
        "compare",
        "teapot",
        "info",
        "bogus",
        "--out",
        "-o",
        "--lighting",
        "--size",
        "--check",
        "--bless",
        "--threshold",
        "--max-share",
        "--max-flip",
        "--pixel",
        "--level",
        "--diff",
        "--device",
        "--max-mesh-mib",
        "--allow-root",
        "--validate",
        "scene.toml",
        "broken.toml",
        "img.png",
        "img2.png",
        "out",
        "out/a.png",
        "out/a.gltf",
        "refs",
        ".",
        "16x16",
        "0x0",
        "99999x1",
        "vertex,flat",
        "phong",
        "1,1",
        "9999,9999",
        "0",
        "-1",
        "nan",
        "0.5",
        "2",
        "1e9",
        "",
    ])
    .prop_map(str::to_owned)
    .boxed()
}

/// A flag and its value, from `choices`, as separate arguments.
fn flags(choices: Vec<(&'static str, Vec<&'static str>)>) -> BoxedStrategy<Vec<String>> {
    let flag = prop::sample::select(choices).prop_flat_map(|(flag, values)| {
        let value = if values.is_empty() {
            Just(None).boxed()
        } else {
            prop::sample::select(values).prop_map(Some).boxed()
        };
        value.prop_map(move |v| {
            std::iter::once(flag)
                .chain(v)
                .map(str::to_owned)
                .collect::<Vec<_>>()
        })
    });
    prop::collection::vec(flag, 0..4).prop_map(|v| v.concat()).boxed()
}

/// A command line: a subcommand with its usual arguments and flags (values in and out of
/// range), sometimes with one token anywhere in it.
fn command_line() -> BoxedStrategy<Vec<String>> {
    let tolerance = || {
        vec![
            ("--threshold", vec!["0", "0.01", "2", "nan", "-1"]),
            ("--max-share", vec!["0", "0.5", "1.5"]),
            ("--max-flip", vec!["0", "0.1", "inf"]),
        ]
    };
    let sizes = vec!["16x16", "8x24", "0x0", "99999x1", "16x", "x"];
    let modes = vec!["vertex", "fragment", "flat", "vertex,flat", "phong", ""];
    let scenes = prop::sample::select(vec![
        "scene.toml",
        "broken.toml",
        ".",
        "refs",
        "missing.toml",
        "img.png",
    ]);
    let mut render = vec![
        (
            "--out",
            vec!["out", "out/a.png", "img.png", "scene.toml", "refs", "/dev/null"],
        ),
        ("--lighting", modes.clone()),
        ("--size", sizes.clone()),
        ("--check", vec!["refs", ".", "out"]),
        ("--bless", vec![]),
        ("--max-mesh-mib", vec!["1", "0", "64"]),
    ];
    render.extend(tolerance());
    let render = (scenes.clone(), flags(render))
        .prop_map(|(scene, f)| [vec!["render".to_owned(), scene.to_owned()], f].concat());
    let explain = (
        scenes,
        prop::sample::select(vec!["1,1", "15,15", "16,0", "9999,9999", "a,b"]),
        flags(vec![("--lighting", modes), ("--size", sizes)]),
    )
        .prop_map(|(scene, pixel, f)| {
            [
                vec![
                    "explain".to_owned(),
                    scene.to_owned(),
                    "--pixel".to_owned(),
                    pixel.to_owned(),
                ],
                f,
            ]
            .concat()
        });
    let mut compare = vec![("--diff", vec!["out/d.png", "img.png", "out/d.txt"])];
    compare.extend(tolerance());
    let images = prop::sample::select(vec!["img.png", "img2.png", "scene.toml", "missing.png"]);
    let compare = (images.clone(), images, flags(compare))
        .prop_map(|(a, b, f)| [vec!["compare".to_owned(), a.to_owned(), b.to_owned()], f].concat());
    let teapot = flags(vec![
        ("--level", vec!["1", "2", "0", "65", "-3"]),
        ("--out", vec!["out/t.gltf", "out/t.png", "img.png"]),
    ])
    .prop_map(|f| [vec!["teapot".to_owned()], f].concat());
    (
        prop_oneof![4 => render, 2 => explain, 2 => compare, 1 => teapot, 1 => Just(vec!["info".to_owned()])],
        prop::option::weighted(0.2, (any::<prop::sample::Index>(), token())),
    )
        .prop_map(|(mut args, extra)| {
            if let Some((at, token)) = extra {
                let at = at.index(args.len() + 1);
                args.insert(at, token);
            }
            args
        })
        .boxed()
}

/// Every regular file below `dir` with its contents.
fn snapshot(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut files = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).into_iter().flatten().flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
            } else {
                files.insert(path.clone(), std::fs::read(&path).unwrap_or_default());
            }
        }
    }
    files
}

/// Whether the command line `args` asked for `changed` to be written: a path it names (or a
/// file below one), or, for a file that did not exist before, an image or `teapot`'s glTF
/// written where the command writes them by default. An existing file no argument names
/// must never change.
fn asked_for(dir: &Path, args: &[String], changed: &Path, existed: bool) -> bool {
    let relative = changed.strip_prefix(dir).unwrap_or(changed);
    let named = args
        .iter()
        .filter(|a| !a.is_empty() && a.as_str() != ".")
        .any(|a| {
            let a = Path::new(a.as_str());
            relative == a || relative.starts_with(a)
        });
    if named {
        return true;
    }
    !existed
        && (relative.extension().is_some_and(|e| e == "png") || relative == Path::new("assets/teapot.gltf"))
}

#[test]
fn generated_command_lines_exit_0_1_or_2_and_write_only_what_they_name() {
    // A folder of its own inside one of its own, so that nothing else writes next to it.
    let outside = output_dir().join("fuzz-cli");
    let dir = outside.join("sandbox");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    write_assets(&dir);
    std::fs::write(
        dir.join("scene.toml"),
        "[image]\nsize = [16, 16]\n[[lights]]\n[[meshes]]\ngltf = \"tri.gltf\"\n",
    )
    .unwrap();
    std::fs::write(dir.join("broken.toml"), "[[lights]]\nspot_cutoff = 100\n").unwrap();
    let image = image::RgbaImage::from_pixel(16, 16, image::Rgba([10, 20, 30, 255]));
    image.save(dir.join("img.png")).unwrap();
    image::RgbaImage::from_pixel(16, 16, image::Rgba([12, 20, 30, 255]))
        .save(dir.join("img2.png"))
        .unwrap();
    std::fs::create_dir_all(dir.join("refs")).unwrap();
    let outside_before: Vec<PathBuf> = std::fs::read_dir(&outside)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .collect();
    runner(60)
        .run(&command_line(), |args| {
            let before = snapshot(&dir);
            let mut child = ffvk_command(&[])
                .args(&args)
                .current_dir(&dir)
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn()
                .unwrap();
            let start = Instant::now();
            let status = loop {
                if let Some(status) = child.try_wait().unwrap() {
                    break status;
                }
                if start.elapsed() > Duration::from_secs(120) {
                    let _ = child.kill();
                    let _ = child.wait();
                    return Err(TestCaseError::fail(format!("ffvk {args:?} ran past 120 s")));
                }
                std::thread::sleep(Duration::from_millis(20));
            };
            prop_assert!(
                matches!(status.code(), Some(0..=2)),
                "ffvk {args:?} ended with {status} (a signal or another code)"
            );
            if std::env::var_os("FFVK_FUZZ_VERBOSE").is_some() {
                eprintln!("{:?} {args:?}", status.code());
            }
            let after = snapshot(&dir);
            for (path, contents) in &after {
                if before.get(path) != Some(contents) {
                    let existed = before.contains_key(path);
                    prop_assert!(
                        asked_for(&dir, &args, path, existed),
                        "ffvk {args:?} wrote {}",
                        path.display()
                    );
                }
            }
            // Put the sandbox back as it was for the next case.
            for (path, contents) in &before {
                if after.get(path) != Some(contents) {
                    std::fs::write(path, contents).unwrap();
                }
            }
            for path in after.keys().filter(|p| !before.contains_key(*p)) {
                std::fs::remove_file(path).unwrap();
            }
            Ok(())
        })
        .unwrap();
    let outside_after: Vec<PathBuf> = std::fs::read_dir(&outside)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .collect();
    assert_eq!(
        outside_before, outside_after,
        "nothing was written next to the sandbox"
    );
}
