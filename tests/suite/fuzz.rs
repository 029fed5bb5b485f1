//! The fuzz harness: generated scene files, glTF JSON, GLB bytes and command lines, each
//! asserting what hostile input may never do: panic, hang, take memory without bound, or
//! (on the command line) die by a signal, exit with another code than 0, 1 or 2, or write a
//! file it was not asked to.
//!
//! Bounded for CI (a few hundred cases, under a minute); `FFVK_FUZZ_SCALE=N` multiplies every
//! case count, e.g. `FFVK_FUZZ_SCALE=100 cargo test --release --test suite fuzz` (see the
//! README); `FFVK_FUZZ_VERBOSE=1` prints each command line's exit code. A failure prints the generated input; proptest shrinks it first and keeps it in
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
fn cases(base: u32) -> u32 {
    let scale = std::env::var("FFVK_FUZZ_SCALE")
        .ok()
        .and_then(|s| s.parse::<u32>().ok())
        .unwrap_or(1)
        .max(1);
    base.saturating_mul(scale)
}

fn runner(base: u32) -> TestRunner {
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
        ],
    ),
];

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

// ---------------------------------------------------------------------------------------------
// glTF and GLB

/// A GLB container of `json` and an optional BIN chunk.
fn glb(json: &[u8], bin: Option<&[u8]>) -> Vec<u8> {
    let pad = |bytes: &[u8], with: u8| {
        let mut v = bytes.to_vec();
        while v.len() % 4 != 0 {
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
/// schema's required ones, present but for a rare case.
fn members(entries: Vec<(&'static str, BoxedStrategy<String>)>, p: f64) -> BoxedStrategy<String> {
    entries
        .into_iter()
        .map(|(key, value)| {
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

fn objects(first: &'static str, member: BoxedStrategy<String>, max: usize) -> BoxedStrategy<String> {
    prop::collection::vec(member, 0..max)
        .prop_map(move |v| {
            let generated = v.iter().map(|m| format!("{{{m}}}"));
            let all: Vec<String> = std::iter::once(first.to_owned())
                .filter(|f| !f.is_empty())
                .chain(generated)
                .collect();
            format!("[{}]", all.join(", "))
        })
        .boxed()
}

/// A glTF document around `buffer` (the members of buffer 0): every part present or not,
/// indices valid or dangling, values in and out of the specification's ranges.
fn gltf_json(buffer: String) -> BoxedStrategy<String> {
    let accessor = members(
        vec![
            ("bufferView!", index()),
            ("byteOffset", int(0..16)),
            (
                "componentType!",
                one_of(vec![
                    "5120", "5121", "5122", "5123", "5125", "5126", "5126", "5126",
                ]),
            ),
            ("count!", int(0..40)),
            (
                "type!",
                one_of(vec![
                    "\"SCALAR\"",
                    "\"VEC2\"",
                    "\"VEC3\"",
                    "\"VEC3\"",
                    "\"VEC4\"",
                    "\"MAT4\"",
                ]),
            ),
            ("normalized", any::<bool>().prop_map(|b| b.to_string()).boxed()),
            ("min!", array(3, -2.0, 0.0)),
            ("max!", array(3, 0.0, 2.0)),
        ],
        0.8,
    );
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
    let node = members(
        vec![
            ("mesh", index()),
            ("children", indices()),
            ("matrix", array(16, -2.0, 2.0)),
            ("translation", array(3, -2.0, 2.0)),
            ("rotation", array(4, -1.0, 1.0)),
            ("scale", array(3, -2.0, 2.0)),
            (
                "extensions",
                index()
                    .prop_map(|i| format!("{{\"KHR_lights_punctual\": {{\"light\": {i}}}}}"))
                    .boxed(),
            ),
        ],
        0.4,
    );
    let material = members(
        vec![
            (
                "pbrMetallicRoughness",
                members(
                    vec![
                        ("baseColorFactor", array(4, 0.0, 1.0)),
                        (
                            "metallicFactor",
                            mostly((0.0f64..1.0).prop_map(|x| format!("{x:?}")).boxed(), number()),
                        ),
                        (
                            "roughnessFactor",
                            mostly((0.0f64..1.0).prop_map(|x| format!("{x:?}")).boxed(), number()),
                        ),
                    ],
                    0.6,
                )
                .prop_map(|m| format!("{{{m}}}"))
                .boxed(),
            ),
            ("emissiveFactor", array(3, 0.0, 1.0)),
            ("doubleSided", any::<bool>().prop_map(|b| b.to_string()).boxed()),
        ],
        0.6,
    );
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
        ],
        0..=3,
    )
    .prop_map(|v| v.join(", "))
    .boxed();
    let required = mostly(
        Just(String::new()).boxed(),
        prop::sample::select(vec!["\"KHR_draco_mesh_compression\"", "\"KHR_lights_punctual\""])
            .prop_map(str::to_owned)
            .boxed(),
    );
    (
        mostly(Just("\"2.0\"".to_owned()).boxed(), prop::sample::select(vec!["\"3.0\"", "2", "\"2.1\""]).prop_map(str::to_owned).boxed()),
        // A first element of each that loads (a triangle at the start of the buffer, placed by
        // node 0), so that the generated rest reaches past the parser and validator.
        objects(
            r#"{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [-2, -2, -2], "max": [2, 2, 2]}"#,
            accessor,
            3,
        ),
        objects(r#"{"buffer": 0, "byteLength": 36}"#, view, 2),
        objects(r#"{"primitives": [{"attributes": {"POSITION": 0}}]}"#, mesh, 2),
        objects(r#"{"mesh": 0}"#, node, 3),
        mostly(Just("[0]".to_owned()).boxed(), indices()),
        objects("{}", material, 2),
        objects(r#"{"type": "point", "intensity": 2}"#, light, 2),
        (used, required),
    )
        .prop_map(move |(version, accessors, views, meshes, nodes, roots, materials, lights, (used, required))| {
            format!(
                r#"{{"asset": {{"version": {version}}}, "buffers": [{{{buffer}}}], "bufferViews": {views},
  "accessors": {accessors}, "meshes": {meshes}, "nodes": {nodes}, "scenes": [{{"nodes": {roots}}}], "scene": 0,
  "materials": {materials}, "extensionsUsed": [{used}], "extensionsRequired": [{required}],
  "extensions": {{"KHR_lights_punctual": {{"lights": {lights}}}}}}}"#
            )
        })
        .boxed()
}

/// What a generated asset is written as.
#[derive(Debug, Clone)]
enum Asset {
    /// `.gltf` with the buffer in `f.bin` (or a data URI, or a URI that leaves the folder).
    Gltf { json: String, bin: Vec<u8> },
    /// `.glb` bytes, sometimes with damaged header or chunk lengths.
    Glb(Vec<u8>),
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
        .prop_flat_map(|(bin, uri, length, as_glb, damage)| {
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
            gltf_json(buffer).prop_map(move |json| {
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
                    Asset::Glb(bytes)
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

#[test]
fn generated_gltf_and_glb_files_load_or_fail_with_an_error() {
    let dir = sandbox("gltf");
    let asset_dir = dir.join("asset");
    std::fs::create_dir_all(&asset_dir).unwrap();
    std::fs::write(dir.join("f.bin"), [0u8; 64]).unwrap();
    let (loaded, refused) = (Cell::new(0), Cell::new(0));
    runner(1000)
        .run(&asset(), |asset| {
            let path = match &asset {
                Asset::Gltf { json, bin } => {
                    std::fs::write(asset_dir.join("f.bin"), bin).unwrap();
                    std::fs::write(asset_dir.join("a.gltf"), json).unwrap();
                    asset_dir.join("a.gltf")
                }
                Asset::Glb(bytes) => {
                    std::fs::write(asset_dir.join("a.glb"), bytes).unwrap();
                    asset_dir.join("a.glb")
                }
            };
            let result = within(Duration::from_secs(20), "gltf::load", move || {
                ffvk::scene::gltf::load(&path)
                    .map(|l| l.meshes.len())
                    .map_err(|e| e.to_string())
            })?;
            match result {
                Ok(_) => loaded.set(loaded.get() + 1),
                Err(message) => {
                    refused.set(refused.get() + 1);
                    prop_assert!(message.contains("a.gl"), "names the file: {message}");
                    prop_assert!(
                        !message.contains("../f.bin") || message.contains("leaves the asset's folder"),
                        "{message}"
                    );
                }
            }
            Ok(())
        })
        .unwrap();
    let (loaded, refused) = (loaded.get(), refused.get());
    eprintln!("{loaded} loaded, {refused} refused");
    assert!(loaded > 0 && refused > 0, "{loaded} loaded, {refused} refused");
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
