//! `cargo bench -p ffvk --features images --bench compare`: reading and comparing two differing 8192² PNGs, the way
//! `ffvk compare` and `render --check` do, in time and peak memory.
//!
//! Two cases: images that differ in a block (the per-channel check decides: FLIP is not
//! needed) and images that differ in a few pixels only (within the share: FLIP decides, in
//! tiles). Each measurement runs in a fresh process (this program re-run with `--child`), so
//! its peak resident memory (VmHWM) is its own; the medians of 3 runs are printed.

// A measurement harness, run by hand: a failure ends it with the panic's message, as a
// test's would.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use ffvk::images::compare::{compare, Tolerance};
use ffvk::images::{load_image, save_png};
use image::{Rgba, RgbaImage};

const SIDE: u32 = 8192;

/// A lit-looking gradient with some texture, so that the PNGs are not trivially small.
fn base() -> RgbaImage {
    RgbaImage::from_fn(SIDE, SIDE, |x, y| {
        let r = ((x * 255) / SIDE) as u8;
        let g = ((y * 255) / SIDE) as u8;
        let b = ((x ^ y) & 0x3f) as u8;
        Rgba([r, g, b.wrapping_add(r / 2), 255])
    })
}

fn inputs(dir: &Path) -> [(String, PathBuf, PathBuf); 3] {
    let a = dir.join("a.png");
    let block = dir.join("block.png");
    let few = dir.join("few.png");
    let all = dir.join("all.png");
    if !(a.exists() && block.exists() && few.exists() && all.exists()) {
        std::fs::create_dir_all(dir).unwrap();
        let image = base();
        save_png(&image, &a).unwrap();
        let mut changed = image.clone();
        for y in 1000..1512 {
            for x in 3000..3512 {
                changed.put_pixel(x, y, Rgba([255, 0, 0, 255]));
            }
        }
        save_png(&changed, &block).unwrap();
        let mut shifted = image.clone();
        for p in shifted.pixels_mut() {
            p.0[2] = p.0[2].saturating_add(1);
        }
        save_png(&shifted, &all).unwrap();
        let mut changed = image;
        for k in 0..500u32 {
            let (x, y) = ((k * 7919) % SIDE, (k * 104_729) % SIDE);
            let p = changed.get_pixel(x, y).0;
            changed.put_pixel(x, y, Rgba([p[0].wrapping_add(9), p[1], p[2], 255]));
        }
        save_png(&changed, &few).unwrap();
    }
    [
        ("a 512² block differs (FLIP not needed)".into(), a.clone(), block),
        (
            "500 pixels differ by 9/255 (FLIP around them)".into(),
            a.clone(),
            few,
        ),
        ("every pixel differs by 1/255 (FLIP everywhere)".into(), a, all),
    ]
}

/// Peak resident memory of this process so far, in MiB.
fn peak_mib() -> f64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<f64>().ok())
        .map_or(f64::NAN, |kb| kb / 1024.0)
}

fn child(expected: &Path, actual: &Path) {
    let start = Instant::now();
    let e = load_image(expected).unwrap();
    let a = load_image(actual).unwrap();
    let decoded = start.elapsed().as_secs_f64();
    let c = compare(&e, &a, &Tolerance::default()).unwrap();
    let total = start.elapsed().as_secs_f64();
    println!(
        "{total} {decoded} {} {}",
        peak_mib(),
        c.passes(&Tolerance::default())
    );
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let Some(i) = args.iter().position(|a| a == "--child") {
        child(Path::new(&args[i + 1]), Path::new(&args[i + 2]));
        return;
    }
    // `cargo bench` passes --bench; `cargo test --all-targets` runs this binary without it,
    // and a test run should not spend minutes measuring.
    if !args.iter().any(|a| a == "--bench") {
        println!("compare benchmark: run it with `cargo bench --bench compare`");
        return;
    }
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/bench-compare");
    println!("comparing two {SIDE}² PNGs, decoding included; medians of 3 runs, each its own process");
    println!("| case | total s | decoding s | peak MiB | passes |");
    println!("| --- | ---: | ---: | ---: | --- |");
    for (name, a, b) in inputs(&dir) {
        let mut totals = Vec::new();
        let mut decodes = Vec::new();
        let mut peaks = Vec::new();
        let mut passes = String::new();
        for _ in 0..3 {
            let out = Command::new(&args[0])
                .args(["--child".as_ref(), a.as_os_str(), b.as_os_str()])
                .output()
                .unwrap();
            let text = String::from_utf8_lossy(&out.stdout);
            let fields: Vec<&str> = text.split_whitespace().collect();
            assert_eq!(
                fields.len(),
                4,
                "child said: {text}{}",
                String::from_utf8_lossy(&out.stderr)
            );
            totals.push(fields[0].parse().unwrap());
            decodes.push(fields[1].parse().unwrap());
            peaks.push(fields[2].parse().unwrap());
            passes = fields[3].to_string();
        }
        println!(
            "| {name} | {:.2} | {:.2} | {:.0} | {passes} |",
            median(totals),
            median(decodes),
            median(peaks)
        );
    }
}
