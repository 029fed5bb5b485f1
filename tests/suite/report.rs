//! The HTML regression report (`render --check --report DIR`, `ffvk results report`), opened
//! in a real headless Chromium (tests/suite/browser.rs): the failing image's entry shows its
//! reference, actual image and both difference maps with the figures the test computes from
//! the PNGs itself, the toggle flips reference and actual in place (read back from the
//! browser's own screenshot), nothing is fetched from outside the report's folder, and a page
//! of 1,000 entries loads only the images in view. Screenshots go to tests/output/report/.

use std::path::{Path, PathBuf};
use std::process::Output;

use ffvk::images::{load_image, save_png};
use ffvk_cli::bench::generate_scenes;
use image::{Rgba, RgbaImage};

use crate::browser::Browser;
use crate::support::{ffvk_command, output_dir};

/// The check's default threshold: a channel must differ by more to count.
const THRESHOLD: u8 = 2;

fn scratch(name: &str) -> PathBuf {
    let dir = output_dir().join("report").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn ffvk(args: &[&dyn AsRef<std::ffi::OsStr>]) -> Output {
    ffvk_command(args)
        .env("FFVK_VALIDATION", "1")
        .output()
        .expect("the ffvk binary runs")
}

fn assert_exit(out: &Output, code: i32) {
    assert_eq!(
        out.status.code(),
        Some(code),
        "stdout:\n{}\nstderr:\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// A suite of `count` generated scenes of `size`² in `dir/scenes`, rendered into `dir/out`
/// and blessed into `dir/refs`.
fn blessed_suite(dir: &Path, count: usize, size: u32) -> (PathBuf, PathBuf, PathBuf) {
    let (scenes, out, refs) = (dir.join("scenes"), dir.join("out"), dir.join("refs"));
    generate_scenes(&scenes, count, size).unwrap();
    let blessed = ffvk(&[&"render", &scenes, &"--out", &out, &"--check", &refs, &"--bless"]);
    assert_exit(&blessed, 0);
    (scenes, out, refs)
}

/// Paints `color` over the `w`×`h` block at (`x`, `y`) of the reference `path`.
fn change_reference(path: &Path, (x, y, w, h): (u32, u32, u32, u32), color: [u8; 4]) {
    let mut image = load_image(path).unwrap();
    for yy in y..y + h {
        for xx in x..x + w {
            image.put_pixel(xx, yy, Rgba(color));
        }
    }
    save_png(&image, path).unwrap();
}

/// The figures a report must show for `reference` against `actual`, computed here: the
/// largest difference per channel, the first pixel (row by row) over the threshold, and how
/// many pixels are over it.
fn expected_figures(reference: &RgbaImage, actual: &RgbaImage) -> ([u8; 4], (u32, u32), usize) {
    let mut max = [0u8; 4];
    let mut first = None;
    let mut over = 0;
    for (x, y, r) in reference.enumerate_pixels() {
        let a = actual.get_pixel(x, y);
        let d: [u8; 4] = std::array::from_fn(|c| r.0[c].abs_diff(a.0[c]));
        for c in 0..4 {
            max[c] = max[c].max(d[c]);
        }
        if d.iter().any(|&v| v > THRESHOLD) {
            over += 1;
            first.get_or_insert((x, y));
        }
    }
    (max, first.expect("the images differ past the threshold"), over)
}

fn rgba(p: &Rgba<u8>) -> String {
    format!("({}, {}, {}, {})", p.0[0], p.0[1], p.0[2], p.0[3])
}

/// JavaScript: the entry of image `name`.
fn entry(name: &str) -> String {
    format!("document.querySelector('section.entry[data-name=\"{name}\"]')")
}

/// Waits until every image of the entry `e` has loaded and decoded.
fn wait_for_images(browser: &mut Browser, e: &str) {
    browser.wait_for(&format!(
        "[...{e}.querySelectorAll('img')].every(i => i.complete && i.naturalWidth > 0)"
    ));
}

/// Scrolls the entry `e` into view and waits for its (lazily loaded) images.
fn scroll_to_and_load(browser: &mut Browser, e: &str) {
    browser.eval(&format!("{e}.scrollIntoView()"));
    wait_for_images(browser, e);
}

/// Which image the browser shows at the center of `slot`'s place in the entry (the topmost
/// visible element there): its `data-kind`.
fn shown_in(browser: &mut Browser, entry: &str, slot: &str) -> String {
    let kind = browser.eval(&format!(
        "(() => {{ const r = {entry}.querySelector('.slot.{slot} .stack').getBoundingClientRect();
                  const e = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
                  return e && e.dataset.kind ? e.dataset.kind : String(e && e.tagName); }})()"
    ));
    kind.as_str().unwrap().to_owned()
}

/// The screenshot pixel showing image pixel (`x`, `y`) in `slot`'s place, at `zoom` screen
/// pixels per image pixel.
fn screen_pixel(
    browser: &mut Browser,
    shot: &RgbaImage,
    entry: &str,
    slot: &str,
    zoom: f64,
    (x, y): (u32, u32),
) -> Rgba<u8> {
    let rect = browser.eval(&format!(
        "(() => {{ const r = {entry}.querySelector('.slot.{slot} .stack').getBoundingClientRect(); return [r.left, r.top]; }})()"
    ));
    let (left, top) = (rect[0].as_f64().unwrap(), rect[1].as_f64().unwrap());
    let sx = (left + (f64::from(x) + 0.5) * zoom).floor() as u32;
    let sy = (top + (f64::from(y) + 0.5) * zoom).floor() as u32;
    *shot.get_pixel(sx, sy)
}

/// The text of figure `key` in the entry `e`.
fn figure(browser: &mut Browser, e: &str, key: &str) -> String {
    browser
        .eval(&format!(
            "{e}.querySelector('tr[data-figure=\"{key}\"] td').textContent"
        ))
        .as_str()
        .unwrap_or_else(|| panic!("no figure {key}"))
        .to_owned()
}

#[test]
fn a_failing_image_shows_its_reference_actual_image_difference_maps_and_figures_and_the_toggle_flips_them() {
    let dir = scratch("one_failure");
    let (scenes, out, refs) = blessed_suite(&dir, 3, 32);
    let name = "scene_001";
    let reference_path = refs.join(format!("{name}.png"));
    let painted = [250, 10, 200, 255];
    let before = load_image(&out.join(format!("{name}.png"))).unwrap();
    assert!(
        (0..4).any(|c| before.get_pixel(5, 7).0[c].abs_diff(painted[c]) > THRESHOLD),
        "the painted block must differ from the image"
    );
    change_reference(&reference_path, (5, 7, 4, 3), painted);
    let report = dir.join("report");
    let checked = ffvk(&[
        &"render",
        &scenes,
        &"--out",
        &out,
        &"--check",
        &refs,
        &"--report",
        &report,
    ]);
    assert_exit(&checked, 1);

    let reference = load_image(&reference_path).unwrap();
    let actual = load_image(&out.join(format!("{name}.png"))).unwrap();
    let (max, first, over) = expected_figures(&reference, &actual);
    assert_eq!(first, (5, 7));

    let mut browser = Browser::launch(&dir.join("browser"), 1400, 1000);
    browser.open(&report.join("index.html"));
    let e = entry(name);
    assert_eq!(
        browser.eval("document.querySelectorAll('section.entry').length"),
        1
    );
    assert_eq!(browser.eval(&format!("{e}.dataset.status")), "fail");
    scroll_to_and_load(&mut browser, &e);
    // The four places, each showing a 32² PNG the browser decoded.
    let images = browser.eval(&format!(
        "[...{e}.querySelectorAll('.stack > a.a img, .stack > a.only img')].map(i => [i.closest('figure').classList[1], i.naturalWidth * i.naturalHeight])"
    ));
    assert_eq!(
        images,
        serde_json::json!([
            ["reference", 1024],
            ["actual", 1024],
            ["channels", 1024],
            ["flip", 1024]
        ])
    );

    // The figures, as the page states them, against those computed here.
    assert_eq!(
        figure(&mut browser, &e, "max-diff"),
        format!("{}, {}, {}, {} (of 255)", max[0], max[1], max[2], max[3])
    );
    assert_eq!(
        figure(&mut browser, &e, "first-over"),
        format!(
            "(5, 7): reference {}, actual {}",
            rgba(reference.get_pixel(5, 7)),
            rgba(actual.get_pixel(5, 7))
        )
    );
    assert_eq!(
        figure(&mut browser, &e, "over"),
        format!("{over} pixel(s), {:.4} %", over as f64 / 1024.0 * 100.0)
    );
    let flip = figure(&mut browser, &e, "flip");
    let flip_value: f64 = flip.split(' ').next().unwrap().parse().unwrap();
    assert!(
        flip_value > 0.0 && flip.ends_with("(pixels over the threshold)"),
        "{flip}"
    );

    // Everything the page loads or links to lies in the report's folder (links within the
    // page aside), and its style sheet was applied.
    let base = format!("file://{}/", report.canonicalize().unwrap().display());
    let urls = browser.eval(
        "[...document.querySelectorAll('[src], [href]')].map(e => e.src || e.href)
           .filter(u => !u.startsWith(location.href.split('#')[0] + '#'))",
    );
    assert!(urls.as_array().unwrap().len() > 8, "{urls}");
    for u in urls.as_array().unwrap() {
        assert!(u.as_str().unwrap().starts_with(&base), "{u} is outside {base}");
    }
    assert_eq!(
        browser.eval(&format!("getComputedStyle({e}).borderLeftWidth")),
        "6px"
    );

    // The toggle, clicked as a user does: the two places swap images, which the browser's
    // own screenshot shows pixel for pixel.
    let width = browser.eval(&format!(
        "{e}.querySelector('.slot.reference .stack').getBoundingClientRect().width"
    ));
    let zoom = width.as_f64().unwrap() / 32.0;
    assert!(
        zoom >= 2.0 && zoom.fract() == 0.0,
        "small images are enlarged whole: {zoom}"
    );
    let shot = browser.screenshot(false);
    save_png(&shot, &dir.join("before_toggle.png")).unwrap();
    assert_eq!(shown_in(&mut browser, &e, "reference"), "reference");
    assert_eq!(shown_in(&mut browser, &e, "actual"), "actual");
    let at = |browser: &mut Browser, shot: &RgbaImage, slot: &str, p: (u32, u32)| {
        screen_pixel(browser, shot, &e, slot, zoom, p)
    };
    assert_eq!(at(&mut browser, &shot, "reference", (5, 7)).0, painted);
    assert_eq!(at(&mut browser, &shot, "actual", (5, 7)), *actual.get_pixel(5, 7));
    assert_eq!(
        at(&mut browser, &shot, "reference", (20, 20)),
        *reference.get_pixel(20, 20)
    );

    let label = browser.eval(&format!(
        "(() => {{ const r = {e}.querySelector('label.flip-button').getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2]; }})()"
    ));
    let (lx, ly) = (label[0].as_f64().unwrap(), label[1].as_f64().unwrap());
    browser.click(lx, ly);
    assert_eq!(
        browser.eval(&format!("{e}.querySelector('input.flip').checked")),
        true
    );
    assert_eq!(shown_in(&mut browser, &e, "reference"), "actual");
    assert_eq!(shown_in(&mut browser, &e, "actual"), "reference");
    let shot = browser.screenshot(false);
    save_png(&shot, &dir.join("after_toggle.png")).unwrap();
    assert_eq!(
        at(&mut browser, &shot, "reference", (5, 7)),
        *actual.get_pixel(5, 7)
    );
    assert_eq!(at(&mut browser, &shot, "actual", (5, 7)).0, painted);
    let caption = browser.eval(&format!(
        "[...{e}.querySelectorAll('.slot.reference figcaption span')].filter(s => getComputedStyle(s).visibility === 'visible').map(s => s.textContent)"
    ));
    assert_eq!(caption, serde_json::json!(["actual (flipped)"]));

    browser.click(lx, ly);
    assert_eq!(shown_in(&mut browser, &e, "reference"), "reference");

    browser.eval("window.scrollTo(0, 0)");
    let page = browser.screenshot(true);
    let saved = dir.join("report.png");
    save_png(&page, &saved).unwrap();
    eprintln!("screenshot of the report: {}", saved.display());
}

/// The report's page as text.
fn page(report: &Path) -> String {
    std::fs::read_to_string(report.join("index.html")).unwrap()
}

#[test]
fn large_images_are_shown_as_thumbnails_linking_to_the_full_png_and_keep_a_single_differing_pixel() {
    let dir = scratch("large");
    let (scenes, out, refs) = (dir.join("scenes"), dir.join("out"), dir.join("refs"));
    generate_scenes(&scenes, 1, 32).unwrap();
    let size: &[&dyn AsRef<std::ffi::OsStr>] = &[&"--size", &"1300x700"];
    let bless = [
        &[
            &"render" as &dyn AsRef<_>,
            &scenes,
            &"--out",
            &out,
            &"--check",
            &refs,
            &"--bless",
        ],
        size,
    ]
    .concat();
    assert_exit(&ffvk(&bless), 0);
    // One pixel off: the strictest tolerance fails it.
    change_reference(&refs.join("scene_000.png"), (1000, 600, 1, 1), [255, 0, 255, 255]);
    let report = dir.join("report");
    let strict: &[&dyn AsRef<std::ffi::OsStr>] =
        &[&"--threshold", &"0", &"--max-share", &"0", &"--max-flip", &"0"];
    let check = [
        &[
            &"render" as &dyn AsRef<_>,
            &scenes,
            &"--out",
            &out,
            &"--check",
            &refs,
            &"--report",
            &report,
        ],
        size,
        strict,
    ]
    .concat();
    assert_exit(&ffvk(&check), 1);

    let html = page(&report);
    for kind in ["reference", "actual", "channels", "flip"] {
        let (thumb, full) = (
            format!("images/1-{kind}.thumb.png"),
            format!("images/1-{kind}.png"),
        );
        assert!(
            html.contains(&format!("href=\"{full}\"")) && html.contains(&format!("src=\"{thumb}\"")),
            "{kind}: no thumbnail linking to the full image"
        );
        let thumbnail = load_image(&report.join(&thumb)).unwrap();
        assert_eq!(thumbnail.dimensions(), (640, 345), "{kind}");
        assert_eq!(
            load_image(&report.join(&full)).unwrap().dimensions(),
            (1300, 700),
            "{kind}"
        );
    }
    // The full images are the run's own files.
    assert_eq!(
        std::fs::read(report.join("images/1-actual.png")).unwrap(),
        std::fs::read(out.join("scene_000.png")).unwrap()
    );
    // The one differing pixel, (1000, 600), lies in one block of the thumbnail (blocks
    // split the image at ⌊i·1300/640⌋ and ⌊i·700/345⌋): the per-channel map's thumbnail
    // keeps it at full strength, and nothing else is lit.
    let block = |p: u32, side: u32, thumb: u32| (0..thumb).rfind(|&i| i * side / thumb <= p).unwrap();
    let (bx, by) = (block(1000, 1300, 640), block(600, 700, 345));
    assert_eq!((bx, by), (492, 296));
    let channels = load_image(&report.join("images/1-channels.thumb.png")).unwrap();
    let lit: Vec<(u32, u32)> = channels
        .enumerate_pixels()
        .filter(|(_, _, p)| p.0[..3] != [0, 0, 0])
        .map(|(x, y, _)| (x, y))
        .collect();
    assert_eq!(lit, [(bx, by)]);
    assert_eq!(channels.get_pixel(bx, by).0[..3].iter().max(), Some(&255));
}

/// `ffvk render` of `scenes` checked against `refs` for shard `k` of 2, its results in
/// `dir/shard_K.json`.
fn shard(dir: &Path, scenes: &Path, refs: &Path, k: u32) -> PathBuf {
    let json = dir.join(format!("shard_{k}.json"));
    let out = dir.join(format!("out_{k}"));
    let partition = format!("{k}/2");
    let run = ffvk(&[
        &"render",
        &scenes,
        &"--out",
        &out,
        &"--check",
        &refs,
        &"--partition",
        &partition,
        &"--json",
        &json,
    ]);
    assert!(run.status.code().is_some_and(|c| c <= 1));
    json
}

#[test]
fn the_shards_of_a_run_make_one_report_and_a_folder_that_is_not_a_report_is_never_written_into() {
    let dir = scratch("shards");
    let (scenes, _, refs) = blessed_suite(&dir, 6, 24);
    change_reference(&refs.join("scene_004.png"), (0, 0, 24, 2), [255, 255, 0, 255]);
    let shards = [shard(&dir, &scenes, &refs, 1), shard(&dir, &scenes, &refs, 2)];
    let report = dir.join("report");
    let made = ffvk(&[&"results", &"report", &shards[0], &shards[1], &"--out", &report]);
    assert_exit(&made, 1);
    let html = page(&report);
    assert_eq!(html.matches("<section class=\"entry").count(), 1);
    assert!(html.contains("data-name=\"scene_004\" data-status=\"fail\""));
    assert!(html.contains("<td>shard 1/2</td>") && html.contains("<td>shard 2/2</td>"));
    assert!(html.contains("data-count=\"pass\">5 passed") && html.contains("data-count=\"fail\">1 failed"));
    assert!(html.contains("<summary>5 image(s) passed or rendered</summary>"));

    // A second report into the same folder replaces the first, images and all.
    let stale = report.join("images/99-flip.png");
    std::fs::write(&stale, "an image of an earlier report").unwrap();
    assert_exit(
        &ffvk(&[&"results", &"report", &shards[0], &shards[1], &"--out", &report]),
        1,
    );
    assert!(report.join("images/1-flip.png").is_file() && !stale.exists());

    // A folder with other files in it is refused and left as it was.
    let foreign = dir.join("foreign");
    std::fs::create_dir_all(&foreign).unwrap();
    std::fs::write(foreign.join("notes.txt"), "mine").unwrap();
    let refused = ffvk(&[&"results", &"report", &shards[0], &shards[1], &"--out", &foreign]);
    assert_exit(&refused, 2);
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(
        stderr.contains(&foreign.display().to_string()) && stderr.contains("holds no earlier ffvk report"),
        "{stderr}"
    );
    let left: Vec<_> = std::fs::read_dir(&foreign)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, ["notes.txt"]);
    // And so is a folder inside the references.
    let inside = ffvk(&[
        &"results",
        &"report",
        &shards[0],
        &shards[1],
        &"--out",
        &refs.join("report"),
    ]);
    assert_exit(&inside, 2);
    assert!(!refs.join("report").exists());
}

#[test]
fn a_blessed_image_is_shown_against_the_reference_it_replaced() {
    let dir = scratch("blessed");
    let (scenes, out, refs) = blessed_suite(&dir, 2, 24);
    let changed = refs.join("scene_001.png");
    change_reference(&changed, (3, 3, 5, 5), [0, 0, 255, 255]);
    let old = std::fs::read(&changed).unwrap();
    let report = dir.join("report");
    let blessed = ffvk(&[
        &"render",
        &scenes,
        &"--out",
        &out,
        &"--check",
        &refs,
        &"--bless",
        &"--report",
        &report,
    ]);
    assert_exit(&blessed, 0);
    let html = page(&report);
    assert!(html.contains("data-name=\"scene_001\" data-status=\"blessed\""));
    assert!(html.contains("previous reference") && html.contains("actual (the new reference)"));
    // The report's previous reference is the painted one; the reference is now the image.
    assert_eq!(
        load_image(&report.join("images/1-reference.png")).unwrap(),
        image::load_from_memory(&old).unwrap().into_rgba8()
    );
    assert_eq!(
        std::fs::read(&changed).unwrap(),
        std::fs::read(out.join("scene_001.png")).unwrap()
    );
    assert!(out.join("scene_001.replaced.png").is_file());
}

#[test]
fn a_page_of_a_thousand_entries_loads_only_the_images_in_view() {
    let dir = scratch("thousand");
    let (scenes, out, refs) = blessed_suite(&dir, 1, 64);
    change_reference(&refs.join("scene_000.png"), (10, 10, 20, 20), [255, 0, 0, 255]);
    let json = dir.join("one.json");
    assert_exit(
        &ffvk(&[
            &"render", &scenes, &"--out", &out, &"--check", &refs, &"--json", &json,
        ]),
        1,
    );
    // The one failing row, a thousand times over, each with its own copies of the images
    // (a report shows a file met twice once).
    let mut results: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let run = &mut results["runs"][0];
    let row = run["rows"][0].clone();
    let copies = dir.join("copies");
    std::fs::create_dir_all(&copies).unwrap();
    let rows: Vec<serde_json::Value> = (0..1000)
        .map(|i| {
            let mut r = row.clone();
            r["name"] = format!("image_{i:04}").into();
            r["index"] = i.into();
            for field in ["output", "reference", "diff", "channels"] {
                let copy = copies.join(format!("{i:04}-{field}.png"));
                std::fs::copy(r[field].as_str().unwrap(), &copy).unwrap();
                r[field] = copy.to_str().unwrap().into();
            }
            r
        })
        .collect();
    run["rows"] = rows.into();
    run["info"]["scenes"] = 1000.into();
    run["info"]["suite_scenes"] = 1000.into();
    let big = dir.join("thousand.json");
    std::fs::write(&big, serde_json::to_string(&results).unwrap()).unwrap();
    let report = dir.join("report");
    assert_exit(&ffvk(&[&"results", &"report", &big, &"--out", &report]), 1);

    let mut browser = Browser::launch(&dir.join("browser"), 1400, 1000);
    browser.open(&report.join("index.html"));
    assert_eq!(
        browser.eval("document.querySelectorAll('section.entry').length"),
        1000
    );
    wait_for_images(&mut browser, &entry("image_0000"));
    let (loaded, total) = (
        browser.eval("[...document.images].filter(i => i.naturalWidth > 0).length"),
        browser.eval("document.images.length"),
    );
    assert_eq!(total, 6000);
    let loaded = loaded.as_u64().unwrap();
    assert!(
        (6..200).contains(&loaded),
        "{loaded} of 6000 images loaded up front"
    );
    // The far end of the page, once scrolled to, loads too.
    scroll_to_and_load(&mut browser, &entry("image_0999"));
    eprintln!(
        "1000 entries: {loaded} images loaded up front; load event after {} ms",
        browser.eval("performance.getEntriesByType('navigation')[0].loadEventEnd")
    );
}

#[test]
fn a_symlinked_reference_is_copied_as_a_file_and_images_gone_since_the_run_are_named_in_their_place() {
    let dir = scratch("links");
    let (scenes, out, refs) = blessed_suite(&dir, 3, 24);
    // The reference of scene_001 lives elsewhere, behind a symbolic link, and differs.
    let elsewhere = dir.join("elsewhere");
    std::fs::create_dir_all(&elsewhere).unwrap();
    let real = elsewhere.join("scene_001.png");
    std::fs::rename(refs.join("scene_001.png"), &real).unwrap();
    change_reference(&real, (0, 0, 6, 6), [0, 255, 0, 255]);
    std::os::unix::fs::symlink(&real, refs.join("scene_001.png")).unwrap();
    // The results file goes into the report's own folder.
    let report = dir.join("report");
    let json = report.join("results.json");
    let checked = ffvk(&[
        &"render",
        &scenes,
        &"--out",
        &out,
        &"--check",
        &refs,
        &"--json",
        &json,
        &"--report",
        &report,
    ]);
    assert_exit(&checked, 1);
    let shown = report.join("images/1-reference.png");
    let kind = std::fs::symlink_metadata(&shown).unwrap().file_type();
    assert!(kind.is_file() && !kind.is_symlink(), "{kind:?}");
    assert_eq!(std::fs::read(&shown).unwrap(), std::fs::read(&real).unwrap());

    // The actual image and its maps are gone when the report is made again.
    for file in ["scene_001.png", "scene_001.diff.png", "scene_001.channels.png"] {
        std::fs::remove_file(out.join(file)).unwrap();
    }
    let again = dir.join("again");
    let made = ffvk(&[&"results", &"report", &json, &"--out", &again]);
    assert_exit(&made, 1);
    let stderr = String::from_utf8_lossy(&made.stderr);
    let gone = out.join("scene_001.png").display().to_string();
    assert!(
        stderr.contains(&gone) && stderr.contains("cannot read the image"),
        "{stderr}"
    );
    let html = page(&again);
    assert!(
        html.contains(&format!("{gone}: cannot read the image")),
        "no placeholder naming {gone}"
    );
    assert!(again.join("images/1-reference.png").is_file());
}

#[test]
fn a_scene_that_would_write_over_another_scenes_difference_map_is_refused() {
    let dir = scratch("clash");
    let scenes = dir.join("scenes");
    let files = generate_scenes(&scenes, 1, 16).unwrap();
    std::fs::copy(&files[0], scenes.join("scene_000.channels.toml")).unwrap();
    let refused = ffvk(&[
        &"render",
        &scenes,
        &"--out",
        &dir.join("out"),
        &"--check",
        &dir.join("refs"),
    ]);
    assert_exit(&refused, 2);
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(
        stderr.contains("would both write the image scene_000.channels.png"),
        "{stderr}"
    );
    assert!(!dir.join("out").exists());
}

/// The results of `dir`'s one-scene suite with its one failing row repeated `count` times
/// (other names, the same image files), written to `dir/NAME.json`.
fn repeated_failure(dir: &Path, size: &[&dyn AsRef<std::ffi::OsStr>], count: usize) -> PathBuf {
    let (scenes, out, refs) = (dir.join("scenes"), dir.join("out"), dir.join("refs"));
    generate_scenes(&scenes, 1, 32).unwrap();
    let bless = [
        &[
            &"render" as &dyn AsRef<_>,
            &scenes,
            &"--out",
            &out,
            &"--check",
            &refs,
            &"--bless",
        ],
        size,
    ]
    .concat();
    assert_exit(&ffvk(&bless), 0);
    change_reference(&refs.join("scene_000.png"), (2, 2, 8, 8), [255, 0, 0, 255]);
    let json = dir.join("one.json");
    let check = [
        &[
            &"render" as &dyn AsRef<_>,
            &scenes,
            &"--out",
            &out,
            &"--check",
            &refs,
            &"--json",
            &json,
        ],
        size,
        &[&"--threshold", &"0", &"--max-share", &"0", &"--max-flip", &"0"],
    ]
    .concat();
    assert_exit(&ffvk(&check), 1);
    let mut results: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let run = &mut results["runs"][0];
    let row = run["rows"][0].clone();
    run["rows"] = (0..count)
        .map(|i| {
            let mut r = row.clone();
            r["name"] = format!("image_{i}").into();
            r["index"] = i.into();
            r
        })
        .collect::<Vec<_>>()
        .into();
    run["info"]["scenes"] = count.into();
    run["info"]["suite_scenes"] = count.into();
    let path = dir.join(format!("repeated_{count}.json"));
    std::fs::write(&path, serde_json::to_string(&results).unwrap()).unwrap();
    path
}

/// One reference behind many failing rows was linked into the report once per row (and
/// copied once the file system's link limit was reached: 872 MB for 100,000 rows); each file
/// is now shown from one copy, however many entries show it.
#[test]
fn an_image_behind_many_entries_is_copied_into_the_report_once() {
    use std::os::unix::fs::MetadataExt;
    let dir = scratch("shared");
    let results = repeated_failure(&dir, &[], 50);
    let report = dir.join("report");
    assert_exit(&ffvk(&[&"results", &"report", &results, &"--out", &report]), 1);
    let mut files: Vec<String> = std::fs::read_dir(report.join("images"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    assert_eq!(
        files,
        ["1-actual.png", "1-channels.png", "1-flip.png", "1-reference.png"]
    );
    let html = page(&report);
    // Fifty entries, each showing the four files of the first.
    assert_eq!(html.matches("<section class=\"entry").count(), 50, "{html}");
    assert!(!html.contains("images/2-"));
    // The reference itself, and its one link in the report.
    let reference = dir.join("refs/scene_000.png");
    assert_eq!(std::fs::metadata(&reference).unwrap().nlink(), 2);
}

/// A fault while the report's images are staged (here a file-size limit the thumbnail passes,
/// as a full disk would stop it) left a part-written staging folder; now nothing of the
/// failed report stays, and the earlier report, page and images, is whole.
#[test]
fn a_report_that_fails_while_staging_its_images_leaves_the_earlier_report_whole() {
    use std::os::unix::process::CommandExt;
    let dir = scratch("staging-fault");
    let size: &[&dyn AsRef<std::ffi::OsStr>] = &[&"--size", &"1300x700"];
    let results = repeated_failure(&dir, size, 2);
    let report = dir.join("report");
    assert_exit(&ffvk(&[&"results", &"report", &results, &"--out", &report]), 1);
    let snapshot = |report: &Path| -> Vec<(PathBuf, Vec<u8>)> {
        let mut files = vec![(
            PathBuf::from("index.html"),
            std::fs::read(report.join("index.html")).unwrap(),
        )];
        for e in std::fs::read_dir(report.join("images")).unwrap() {
            let e = e.unwrap();
            files.push((e.path(), std::fs::read(e.path()).unwrap()));
        }
        files.sort();
        files
    };
    let before = snapshot(&report);
    assert!(before.iter().any(|(p, _)| p.ends_with("1-actual.thumb.png")));

    let mut command = ffvk_command(&[&"results", &"report", &results, &"--out", &report]);
    // SAFETY: between fork and exec only an async-signal-safe call: setrlimit. (SIGXFSZ keeps
    // its default: ffvk itself ignores it, so that the write fails instead of killing it.)
    unsafe {
        command.pre_exec(|| {
            let limit = libc::rlimit {
                rlim_cur: 4096,
                rlim_max: 4096,
            };
            if libc::setrlimit(libc::RLIMIT_FSIZE, &limit) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let failed = command.output().unwrap();
    assert_exit(&failed, 2);
    let stderr = String::from_utf8_lossy(&failed.stderr);
    assert!(stderr.contains("thumb.png"), "{stderr}");
    let left: Vec<String> = std::fs::read_dir(&report)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('.') && n != ".ffvk-report")
        .collect();
    assert!(left.is_empty(), "left behind: {left:?}");
    assert!(snapshot(&report) == before, "the earlier report changed");
}
