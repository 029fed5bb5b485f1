//! The benchmark harness, run once on a tiny sweep: every point runs, and the outputs (CSV,
//! JSON, Markdown, PNG plots) are written and well-formed. No timed assertions: times only
//! have to be positive numbers.

use ffvk::vk::Validation;
use ffvk::RendererOptions;
use ffvk_cli::bench::{
    crossover, points, run_sweep, write_outputs, Engine, Group, Spread, SweepConfig, Variant, CSV_COLUMNS,
};
use indicatif::ProgressBar;

use crate::support::output_dir;
use ffvk_cli::bench::draws::DrawShape;

/// Splits one CSV line, honouring double quotes (the device name has commas).
fn csv_fields(line: &str) -> Vec<String> {
    let mut fields = vec![String::new()];
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                chars.next();
                fields.last_mut().unwrap().push('"');
            }
            ('"', _) => quoted = !quoted,
            (',', false) => fields.push(String::new()),
            (c, _) => fields.last_mut().unwrap().push(c),
        }
    }
    fields
}

#[test]
fn a_tiny_sweep_runs_every_point_and_writes_csv_json_and_plots() {
    let config = SweepConfig::tiny();
    let options = RendererOptions::default()
        .with_device(None)
        .with_validation(Validation::Required);
    // Validation errors fail the frame that caused them, and so the sweep.
    let report = run_sweep(&config, &options, &ProgressBar::hidden()).unwrap();

    // Every point ran; the GL anchor is there (the tests need a GL driver, llvmpipe here).
    let expected = points(&config);
    assert_eq!(report.results.len(), expected.len(), "notes: {:?}", report.notes);
    assert!(report.results.iter().any(|r| r.point.engine == Engine::Gl));
    for r in &report.results {
        let s = &r.stats;
        assert_eq!((s.warmup, s.frames), (config.warmup, config.frames));
        assert!(s.time_ms > 0.0 && s.wall_ms.min > 0.0, "{r:?}");
        assert!(s.wall_ms.min <= s.wall_ms.median && s.wall_ms.median <= s.wall_ms.max);
        if r.point.engine == Engine::Ffvk {
            assert!(s.gpu_ms.is_some_and(|g| g.median > 0.0), "{r:?}");
            assert!(
                s.vs_invocations.is_some_and(|n| n >= r.point.vertices.min(3)),
                "{r:?}"
            );
            assert!(s.fs_invocations.is_some_and(|n| n > 0), "{r:?}");
        }
        // The fragment and paths sweeps count the pixels their sphere covers: some, not all.
        if matches!(r.point.group, Group::Fragment | Group::Paths) {
            assert!(
                s.covered_pixels.is_some_and(|c| c > 0 && c < r.point.pixels),
                "{r:?}"
            );
        } else {
            assert_eq!(s.covered_pixels, None, "{r:?}");
        }
        assert_eq!(r.device, report.env.device);
        assert!(!r.lp_num_threads.is_empty() && !r.mesa_version.is_empty());
    }
    assert!(report.env.device.contains("llvmpipe"), "{:?}", report.env);
    // The recording cost: per-draw host time, the packing part of it, a new key's pipeline.
    let d = report
        .draw_cost
        .as_ref()
        .expect("the sweep measures the recording cost");
    assert_eq!((d.draws, d.frames), (config.record_draws, config.frames));
    assert!(
        d.warm_us_per_draw.median > 0.0
            && d.modelview_only_us_per_draw.median > 0.0
            && d.pack_us_per_draw.median > 0.0,
        "{d:?}"
    );
    assert!(d.new_key_create_ms.median > 0.0, "{d:?}");
    let markdown = ffvk_cli::bench::markdown(&report);
    assert!(markdown.contains("### Recording draws (host)"));
    assert!(
        markdown.contains("### Fragment lighting on a dense mesh"),
        "{markdown}"
    );
    // The draws sweep: every count of both quad shapes, the spheres' frame and the dense
    // sphere, in every mode, ffvk and GL, each frame measured.
    assert_eq!(
        report.draws.len(),
        (2 * config.draw_counts.len() + 2) * 3 * 2,
        "{:?}",
        report.draws
    );
    for shape in DrawShape::ALL {
        assert!(
            report.draws.iter().any(|r| r.shape == shape),
            "no {shape:?} point"
        );
    }
    for r in &report.draws {
        assert!(r.frame_ms.min > 0.0 && r.frame_ms.min <= r.frame_ms.max, "{r:?}");
        if r.engine == Engine::Ffvk {
            assert!(r.record_us_per_draw.is_some_and(|us| us > 0.0), "{r:?}");
            assert!(r.device_us_per_draw.is_some_and(|us| us > 0.0), "{r:?}");
        }
    }
    assert!(ffvk_cli::bench::markdown(&report).contains("### Many draws, each with its own material"));
    // The stages sweep: every stage setting in every mode, specialized and uber, and GL's;
    // its table has a time in every ffvk cell.
    for stage in ffvk_cli::bench::Stage::ALL {
        let of_stage: Vec<_> = report
            .results
            .iter()
            .filter(|r| r.point.group == Group::Stages && r.point.stage == stage)
            .collect();
        assert_eq!(of_stage.len(), 4 * 2 + 3, "{stage:?}");
    }
    let markdown = ffvk_cli::bench::markdown(&report);
    let table = markdown
        .split("### The stages around lighting")
        .nth(1)
        .expect("the stages table");
    let all = table
        .lines()
        .find(|l| l.starts_with("| all of them |"))
        .expect("the row of all the stages");
    assert_eq!(all.matches('|').count(), 2 * 8 + 3, "{all}");
    assert!(!all.contains('–'), "{all}");
    // The floor: each frame class through every path that draws it (lavapipe has
    // VK_EXT_multi_draw), each frame measured, in the summary against GL.
    let classes = ffvk_cli::bench::floor::frame_classes(&config.draw_counts);
    let paths = |shape| {
        ffvk_cli::bench::floor::FloorPath::ALL
            .into_iter()
            .filter(move |p| p.draws_shape(shape))
    };
    let expected: Vec<_> = classes
        .iter()
        .flat_map(|&(shape, draws)| paths(shape).map(move |p| (p, shape, draws)))
        .collect();
    let floor: Vec<_> = report.floor.iter().map(|r| (r.path, r.shape, r.draws)).collect();
    assert_eq!(floor, expected, "notes: {:?}", report.notes);
    for r in &report.floor {
        assert!(r.frame_ms.min > 0.0 && r.frame_ms.min <= r.frame_ms.max, "{r:?}");
    }
    let markdown = ffvk_cli::bench::markdown(&report);
    let table = markdown
        .split("### Floor: the same frames in plain Vulkan")
        .nth(1)
        .expect("the floor's table");
    assert!(
        table.contains("| path | frame | draws | ms | ÷ GL | ÷ zink |"),
        "{table}"
    );
    assert!(
        table.contains("| push_constants | spheres, one mesh | 1024 |"),
        "{table}"
    );
    assert!(report.env.mesa_version.starts_with(|c: char| c.is_ascii_digit()));

    let dir = output_dir().join("bench");
    let _ = std::fs::remove_dir_all(&dir);
    let written = write_outputs(&report, &dir).unwrap();
    for name in [
        "results.csv",
        "results.json",
        "summary.md",
        "time_vs_vertices.png",
        "time_vs_pixels.png",
        "time_vs_lights.png",
    ] {
        assert!(
            written.contains(&dir.join(name)),
            "{name} not written: {written:?}"
        );
    }

    // CSV: the header, then one row per point with every column.
    let csv = std::fs::read_to_string(dir.join("results.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next().unwrap(), CSV_COLUMNS.join(","));
    let rows: Vec<Vec<String>> = lines.map(csv_fields).collect();
    assert_eq!(rows.len(), report.results.len());
    let column = |name: &str| CSV_COLUMNS.iter().position(|c| *c == name).unwrap();
    for row in &rows {
        assert_eq!(row.len(), CSV_COLUMNS.len(), "{row:?}");
        assert!(row[column("time_ms")].parse::<f64>().unwrap() > 0.0);
        assert!(row[column("device")].contains("llvmpipe"), "{row:?}");
        assert!(!row[column("lp_num_threads")].is_empty());
        assert!(!row[column("mesa_version")].is_empty());
    }

    // JSON: the same results, each with its environment.
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("results.json")).unwrap()).unwrap();
    let results = json["results"].as_array().unwrap();
    assert_eq!(results.len(), report.results.len());
    for r in results {
        for key in [
            "lp_num_threads",
            "device",
            "driver_info",
            "mesa_version",
            "mode",
            "variant",
        ] {
            assert!(r[key].is_string(), "{key} in {r}");
        }
        assert!(r["time_ms"].as_f64().unwrap() > 0.0);
        assert!(r["wall_ms"]["median"].is_number());
    }
    assert!(json["env"]["lp_num_threads"].is_string());
    assert!(json["summary"]["specialization_speedup"].is_object());
    let floor = json["floor"].as_array().unwrap();
    assert_eq!(floor.len(), report.floor.len());
    assert!(floor
        .iter()
        .all(|r| r["path"].is_string() && r["frame_ms"]["median"].is_number()));

    // Plots: PNGs of the plotters size with more than a background.
    for name in ["time_vs_vertices.png", "time_vs_pixels.png", "time_vs_lights.png"] {
        let image = image::open(dir.join(name)).unwrap().to_rgba8();
        assert_eq!(image.dimensions(), (1000, 640), "{name}");
        let background = image.get_pixel(0, 0);
        let drawn = image.pixels().filter(|p| *p != background).count();
        assert!(drawn > 5000, "{name}: only {drawn} pixels drawn");
    }
    let summary = std::fs::read_to_string(dir.join("summary.md")).unwrap();
    assert!(summary.contains("LP_NUM_THREADS") && summary.contains("Mesa"));
}

#[test]
fn sweeps_are_validated() {
    let options = RendererOptions::default();
    for bad in [
        SweepConfig {
            frames: 0,
            ..SweepConfig::tiny()
        },
        SweepConfig {
            light_counts: vec![17],
            ..SweepConfig::tiny()
        },
        SweepConfig {
            sizes: vec![0],
            ..SweepConfig::tiny()
        },
    ] {
        let err = run_sweep(&bad, &options, &ProgressBar::hidden()).unwrap_err();
        assert!(matches!(err, ffvk_cli::Error::Bench(_)), "{err}");
    }
}

#[test]
fn spreads_and_crossovers() {
    let s = Spread::of(&[4.0, 1.0, 3.0, 2.0, 5.0]).unwrap();
    assert_eq!((s.min, s.p25, s.median, s.p75, s.max), (1.0, 2.0, 3.0, 4.0, 5.0));
    assert_eq!(Spread::of(&[]), None);
    // a = x, b = 100 / x... on a log grid: equal at x = 10.
    let xs = [1.0, 4.0, 16.0, 64.0];
    let a: Vec<(f64, f64)> = xs.iter().map(|&x| (x, x)).collect();
    let b: Vec<(f64, f64)> = xs.iter().map(|&x| (x, 100.0 / x)).collect();
    let x = crossover(&a, &b).unwrap();
    assert!((x - 10.0).abs() < 1e-9, "{x}");
    // One always below the other: no crossing.
    let c: Vec<(f64, f64)> = xs.iter().map(|&x| (x, 2.0 * x)).collect();
    assert_eq!(crossover(&a, &c), None);
}

#[test]
fn a_batched_sweep_draws_every_point_several_times_and_fits_what_a_vertex_pixel_and_light_cost() {
    let config = SweepConfig::tiny_batched();
    let options = RendererOptions::default().with_validation(Validation::Required);
    let report = run_sweep(&config, &options, &ProgressBar::hidden()).unwrap();
    assert_eq!(
        report.results.len(),
        points(&config).len(),
        "notes: {:?}",
        report.notes
    );
    for r in &report.results {
        let s = &r.stats;
        assert_eq!(r.point.draws, config.draws);
        // Both engines report GPU time: ffvk's timestamps, llvmpipe's GL_TIME_ELAPSED.
        assert!(s.gpu_ms.is_some_and(|g| g.median > 0.0), "{r:?}");
        if matches!(r.point.variant, Variant::Deferred | Variant::DeferredUber) {
            // The deferred path's statistics are its lighting pass's; it lights every covered
            // pixel once, however many draws cover it.
            assert_eq!(s.evaluations, s.covered_pixels, "{r:?}");
        } else if r.point.engine == Engine::Ffvk {
            // Every draw lit in full: at least one vertex shader run per triangle corner that
            // the mesh has vertices for, times the draws.
            let vs = s.vs_invocations.expect("counted in a frame of their own");
            assert!(vs >= u64::from(config.draws) * r.point.vertices.min(3), "{r:?}");
        }
    }
    let costs = &report.summary.costs;
    let ffvk_vertex = costs
        .iter()
        .find(|c| c.engine == Engine::Ffvk && c.mode == ffvk_cli::bench::BenchMode::Vertex)
        .expect("ffvk's vertex mode ran every sweep");
    assert!(ffvk_vertex.ns_per_vertex.is_some() && ffvk_vertex.ns_per_pixel.is_some());
    assert!(ffvk_vertex.ns_per_light.is_some() && ffvk_vertex.ns_per_light_evaluation.is_some());
    assert!(costs.iter().any(|c| c.engine == Engine::Gl), "{costs:?}");
    let md = ffvk_cli::bench::markdown(&report);
    assert!(md.contains("### What a vertex, a pixel and a light cost"), "{md}");
    assert!(md.contains("3 draws of the mesh per frame"), "{md}");
    assert!(md.contains("GL_TIME_ELAPSED"), "{md}");
}

#[test]
fn a_least_squares_line_through_exact_points_is_that_line() {
    use ffvk_cli::bench::fit_line;
    let points: Vec<(f64, f64)> = [1.0, 2.0, 4.0, 8.0].iter().map(|&x| (x, 3.0 * x + 5.0)).collect();
    let (slope, intercept) = fit_line(&points).unwrap();
    assert!((slope - 3.0).abs() < 1e-12 && (intercept - 5.0).abs() < 1e-12);
    assert_eq!(
        fit_line(&[(2.0, 1.0), (2.0, 3.0)]),
        None,
        "one x value fits no line"
    );
    assert_eq!(fit_line(&[(2.0, 1.0)]), None);
}

#[test]
fn the_auto_sweep_is_the_gpu_sweep_on_gpus_and_the_standard_one_on_lavapipe() {
    use ffvk_cli::bench::is_gpu;
    assert!(is_gpu("DISCRETE_GPU") && is_gpu("INTEGRATED_GPU") && is_gpu("VIRTUAL_GPU"));
    assert!(!is_gpu("CPU") && !is_gpu("OTHER"));
    let gpu = SweepConfig::gpu();
    assert_eq!(gpu.sizes.last(), Some(&4096));
    assert_eq!(gpu.light_counts.last(), Some(&ffvk::gl::state::MAX_LIGHTS));
    assert!(gpu.batch && gpu.draws > 1);
}

#[test]
fn the_jobs_sweep_times_every_number_of_workers_on_a_suite_that_passes() {
    let dir = output_dir().join("bench_jobs");
    let _ = std::fs::remove_dir_all(&dir);
    let config = ffvk_cli::bench::SuiteConfig {
        scenes: 6,
        size: 32,
        jobs: vec![1, 2],
        runs: 2,
        lp_num_threads: None,
    };
    let options = RendererOptions::default().with_validation(Validation::Required);
    let program = std::path::Path::new(env!("CARGO_BIN_EXE_ffvk"));
    let report = ffvk_cli::bench::run_jobs_sweep(&config, &options, program, &dir, &mut |_| {}).unwrap();
    assert_eq!(report.points.iter().map(|p| p.jobs).collect::<Vec<_>>(), [1, 2]);
    for p in &report.points {
        assert_eq!(p.images, 6);
        assert_eq!(p.seconds.len(), 2);
        assert!(p.seconds.iter().all(|s| *s > 0.0) && p.images_per_second > 0.0);
        assert!(p.lp_num_threads.parse::<u32>().is_ok_and(|t| t >= 1), "{p:?}");
    }
    assert_eq!(report.points[0].speedup, 1.0);
    assert!(report.device.as_ref().is_some_and(|d| d.driver == "llvmpipe"));
    let markdown = std::fs::read_to_string(dir.join("jobs.md")).unwrap();
    assert!(
        markdown.contains("| workers |") && markdown.contains("Mesa"),
        "{markdown}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("jobs.json")).unwrap()).unwrap();
    assert_eq!(json["points"].as_array().unwrap().len(), 2);
}

/// The floor (a plain Vulkan program, no ffvk pipelines) draws the draws sweep's frame as ffvk
/// draws it, through every data path: each path's image equals ffvk's within 1/255 per channel
/// (both evaluate GL's equation in single precision in the same order, and on lavapipe agree to
/// the bit, but another driver may round a channel apart), and the paths agree with each other
/// exactly (the same shader but for where the record comes from).
#[test]
fn the_floor_draws_the_draws_sweeps_frames_as_ffvk_does_through_every_path() {
    use ffvk_cli::bench::draws::draws_frame;
    use ffvk_cli::bench::floor::{floor_images, FloorPath};
    use ffvk_cli::bench::BenchMode;

    let options = RendererOptions::default()
        .with_device(None)
        .with_validation(Validation::Required);
    let mut renderer = crate::support::renderer_from(options.clone());
    for (shape, draws, side) in [
        (DrawShape::Spheres, 16, 96),
        (DrawShape::OneQuadMesh, 16, 96),
        (DrawShape::QuadMeshEach, 9, 96),
        // More draws than lavapipe's maxMultiDrawCount (2,048): the multi-draw in batches.
        (DrawShape::QuadMeshEach, 2_100, 256),
    ] {
        let mesh = shape.mesh();
        let uploads = if shape == DrawShape::QuadMeshEach {
            draws
        } else {
            1
        };
        let meshes: Vec<_> = (0..uploads).map(|_| renderer.upload(&mesh).unwrap()).collect();
        let frame = draws_frame(shape, draws, BenchMode::Vertex, side, &meshes).unwrap();
        let ffvk = renderer.render(&frame).unwrap();
        let images = floor_images(&options, shape, draws, side).unwrap();

        // Lavapipe has VK_EXT_multi_draw: every path that draws the shape ran.
        let expected: Vec<FloorPath> = FloorPath::ALL
            .into_iter()
            .filter(|p| p.draws_shape(shape))
            .collect();
        let ran: Vec<FloorPath> = images.iter().map(|(p, _)| *p).collect();
        assert_eq!(ran, expected, "{shape:?}");

        // The clear color as stored: an empty frame's pixel.
        let mut empty = ffvk::Frame::new(side, side);
        empty.clear_color = frame.clear_color;
        let clear = renderer.render(&empty).unwrap().pixel(0, 0).unwrap();
        let drawn = ffvk.rgba().chunks(4).filter(|p| *p != clear).count();
        assert!(
            drawn > (side * side / 4) as usize,
            "{shape:?}: ffvk drew {drawn} pixels"
        );
        for (path, image) in &images {
            assert_eq!(image.len(), ffvk.rgba().len(), "{shape:?} {path:?}");
            let worst = image
                .iter()
                .zip(ffvk.rgba())
                .map(|(a, b)| a.abs_diff(*b))
                .max()
                .unwrap_or(0);
            let apart = image
                .chunks(4)
                .zip(ffvk.rgba().chunks(4))
                .filter(|(a, b)| a != b)
                .count();
            assert!(
                worst <= 1,
                "{shape:?} through {}: {apart} pixels differ from ffvk's, by up to {worst}/255",
                path.name()
            );
            assert_eq!(
                image,
                &images[0].1,
                "{shape:?}: {} and {} differ",
                path.name(),
                images[0].0.name()
            );
        }
    }
    crate::support::finish(renderer);
}

/// The stages sweep's texturing rows draw what Mesa's GL draws from the same calls, so that
/// the anchor does the work ffvk does: one unit, and four (a light map through GL_COMBINE, a
/// sphere map, a reflection-mapped cube map); and texturing changes the frame.
#[test]
fn the_bench_texturing_stages_draw_what_mesas_gl_draws() {
    use ffvk_cli::bench::{ffvk_frame, gl_scene, BenchMode, Stage, StageTextures};
    let config = SweepConfig::tiny();
    let mut r = crate::support::renderer();
    let point_of = |stage| {
        let mut p = points(&config)
            .into_iter()
            .find(|p| {
                (p.group, p.stage, p.engine, p.mode, p.variant)
                    == (
                        Group::Stages,
                        stage,
                        Engine::Ffvk,
                        BenchMode::Vertex,
                        Variant::Specialized,
                    )
            })
            .expect("the stage's point");
        (p.width, p.height, p.pixels) = (96, 96, 96 * 96);
        p.stacks = 16;
        p
    };
    let data = ffvk::mesh::MeshData::uv_sphere(32, 16);
    let mesh = r.upload(&data).unwrap();
    let draw = |r: &mut ffvk::Renderer, stage| {
        let point = point_of(stage);
        let textures = StageTextures::of(stage).unwrap();
        let uploaded = textures.upload(r).unwrap();
        let ours = r
            .render(&ffvk_frame(&mesh, &point, &uploaded).unwrap())
            .unwrap()
            .into_rgba_image();
        let theirs = ffvk_cli::gl_reference::render_gl(&gl_scene(&data, &point, &textures).unwrap()).unwrap();
        (ours, theirs)
    };
    let (plain, _) = draw(&mut r, Stage::Off);
    for stage in [Stage::Texture, Stage::Units4] {
        let (ours, theirs) = draw(&mut r, stage);
        let (n, worst) = crate::stage_scenes::differing(&ours, &theirs, 2);
        let name = format!("bench_stage_{stage:?}");
        let at = crate::support::save_for_inspection(&ours, &format!("{name}_ffvk"));
        crate::support::save_for_inspection(&theirs, &format!("{name}_gl"));
        assert!(
            n <= 96 * 96 / 100,
            "{name}: {n} pixels beyond 2/255 of Mesa's GL (worst {worst}); images beside {}",
            at.display()
        );
        let changed = crate::stage_scenes::differing(&ours, &plain, 8).0;
        assert!(
            changed > 96 * 96 / 10,
            "{name}: texturing changed only {changed} pixels"
        );
    }
    crate::support::finish(r);
}
