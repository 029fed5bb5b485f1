//! C programs of the C API (ffvk-c/tests/c), compiled with gcc (`-Wall -Wextra -Werror
//! -pedantic`) and run with the validation layer on (any message fails them), each drawing a
//! scene that Mesa's GL draws too, with glViewport, glDepthRange and glScissor: the pixels
//! must be GL's.
//!
//! - `viewport.c` sets each draw's VkViewport and VkRect2D with ffvkViewport and ffvkScissor
//!   from GL's numbers (viewports off the target's edges, reversed and narrowed depth ranges,
//!   scissor boxes inside, across and outside the target), on a device made with
//!   ffvkDeviceRequirements.
//! - `raster.c` draws version 3 draws with `FFVK_RASTER_SOURCE_CONTEXT`, each taking the raster
//!   state set on the context with ffvkColorMask, ffvkStencilFunc and ffvkStencilOp,
//!   ffvkLogicOp and ffvkEnable, on a D24_UNORM_S8_UINT target and a device made with
//!   ffvkDeviceRequirements (logicOp from FFVK_FEATURE_LOGIC_OP).
//! - `abi_v1.c` is compiled against version 1 of the header (ffvk-c/tests/abi/ffvk_v1.h,
//!   frozen) and run with today's library: the ABI's promise that a program built against an
//!   older header keeps working.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use ffvk_c::abi::Versioned;
use ffvk_c::render::{FfvkDrawInfo, FfvkRendererCreateInfo};
use ffvk_cli::gl_reference::{raw, with_raw_gl};

use crate::c_api_example::{build_library, printed, profile_dir, workspace, LAVAPIPE_ICD};
use crate::support::{output_dir, save_for_inspection};

/// One draw: GL's viewport (x, y, width, height), depth range, scissor box, current color,
/// and a GL_TRIANGLE_FAN in clip coordinates (identity matrices, lighting off).
struct Draw {
    viewport: [i32; 4],
    depth_range: [f64; 2],
    scissor: [i32; 4],
    color: [f32; 4],
    fan: Vec<[f32; 3]>,
    /// The raster state set before it (raster.c; the other programs ignore it).
    raster: Raster,
}

/// GL's raster state of one draw, as GL's calls set it: glColorMask, glEnable(GL_STENCIL_TEST)
/// with glStencilFunc (function, reference, mask) and glStencilOp (sfail, dpfail, dppass),
/// glEnable(GL_COLOR_LOGIC_OP) with glLogicOp. GL's enums as numbers.
#[derive(Clone, Copy)]
struct Raster {
    color_mask: [bool; 4],
    stencil: Option<(u32, i32, u32, [u32; 3])>,
    logic_op: Option<u32>,
}

/// GL's initial raster state (tables 6.20 and 6.21).
const INITIAL: Raster = Raster {
    color_mask: [true; 4],
    stencil: None,
    logic_op: None,
};

impl Raster {
    /// The scene file's `raster` line.
    fn text(&self) -> String {
        let m = self.color_mask.map(u32::from);
        let (on, (func, reference, mask, ops)) = match self.stencil {
            Some(s) => (1, s),
            None => (0, (raw::ALWAYS, 0, !0, [raw::KEEP; 3])),
        };
        let (logic, op) = self.logic_op.map_or((0, raw::COPY), |op| (1, op));
        format!(
            "raster {} {} {} {} {on} {func} {reference} {mask} {} {} {} {logic} {op}",
            m[0], m[1], m[2], m[3], ops[0], ops[1], ops[2]
        )
    }

    /// Sets it on Mesa's context.
    ///
    /// # Safety
    ///
    /// A context is current on this thread.
    unsafe fn apply(&self, gl: &raw::Gl) {
        let [r, g, b, a] = self.color_mask.map(u8::from);
        let cap = |on: bool, cap| {
            // SAFETY: the caller's contract.
            unsafe {
                if on {
                    gl.Enable(cap)
                } else {
                    gl.Disable(cap)
                }
            }
        };
        // SAFETY: the caller's contract.
        unsafe {
            gl.ColorMask(r, g, b, a);
            cap(self.stencil.is_some(), raw::STENCIL_TEST);
            if let Some((func, reference, mask, [sfail, dpfail, dppass])) = self.stencil {
                gl.StencilFunc(func, reference, mask);
                gl.StencilOp(sfail, dpfail, dppass);
            }
            cap(self.logic_op.is_some(), raw::COLOR_LOGIC_OP);
            if let Some(op) = self.logic_op {
                gl.LogicOp(op);
            }
        }
    }
}

/// A frame: the target's size, its clear color and depth, the draws in order, with GL's
/// depth test on (GL_LESS).
struct Scene {
    width: u32,
    height: u32,
    clear: [f32; 4],
    clear_depth: f32,
    draws: Vec<Draw>,
}

impl Scene {
    /// The scene file harness.c reads.
    fn text(&self) -> String {
        let mut text = format!("target {} {}\n", self.width, self.height);
        let [r, g, b, a] = self.clear;
        writeln!(text, "clear {r} {g} {b} {a} {}", self.clear_depth).unwrap();
        for d in &self.draws {
            let [vx, vy, vw, vh] = d.viewport;
            let [near, far] = d.depth_range;
            let [sx, sy, sw, sh] = d.scissor;
            let [r, g, b, a] = d.color;
            write!(
                text,
                "draw {vx} {vy} {vw} {vh} {near} {far} {sx} {sy} {sw} {sh} {r} {g} {b} {a} {}",
                d.fan.len()
            )
            .unwrap();
            for [x, y, z] in &d.fan {
                write!(text, " {x} {y} {z}").unwrap();
            }
            text.push('\n');
            writeln!(text, "{}", d.raster.text()).unwrap();
        }
        text
    }

    /// The scene drawn by Mesa's GL: RGBA8, top row first (a depth-stencil buffer, the stencil
    /// cleared to 0).
    fn render_gl(&self) -> Vec<u8> {
        let (w, h) = (self.width as i32, self.height as i32);
        with_raw_gl(|gl| {
            let (mut framebuffer, mut renderbuffers) = (0, [0; 2]);
            let mut pixels = vec![0u8; (self.width * self.height * 4) as usize];
            // SAFETY: the context is current on this thread; the names are made here and
            // deleted before it returns; `pixels` holds width * height RGBA8 pixels with no row
            // padding (PACK_ALIGNMENT 1).
            let error = unsafe {
                gl.GenFramebuffers(1, &mut framebuffer);
                gl.GenRenderbuffers(2, renderbuffers.as_mut_ptr());
                gl.BindRenderbuffer(raw::RENDERBUFFER, renderbuffers[0]);
                gl.RenderbufferStorage(raw::RENDERBUFFER, raw::RGBA8, w, h);
                gl.BindRenderbuffer(raw::RENDERBUFFER, renderbuffers[1]);
                gl.RenderbufferStorage(raw::RENDERBUFFER, raw::DEPTH24_STENCIL8, w, h);
                gl.BindFramebuffer(raw::FRAMEBUFFER, framebuffer);
                gl.FramebufferRenderbuffer(
                    raw::FRAMEBUFFER,
                    raw::COLOR_ATTACHMENT0,
                    raw::RENDERBUFFER,
                    renderbuffers[0],
                );
                gl.FramebufferRenderbuffer(
                    raw::FRAMEBUFFER,
                    raw::DEPTH_STENCIL_ATTACHMENT,
                    raw::RENDERBUFFER,
                    renderbuffers[1],
                );
                assert_eq!(
                    gl.CheckFramebufferStatus(raw::FRAMEBUFFER),
                    raw::FRAMEBUFFER_COMPLETE,
                    "Mesa's framebuffer object"
                );
                let [r, g, b, a] = self.clear;
                gl.Viewport(0, 0, w, h);
                gl.Disable(raw::SCISSOR_TEST);
                gl.ClearColor(r, g, b, a);
                gl.ClearDepth(f64::from(self.clear_depth));
                gl.ClearStencil(0);
                gl.Clear(raw::COLOR_BUFFER_BIT | raw::DEPTH_BUFFER_BIT | raw::STENCIL_BUFFER_BIT);
                gl.Enable(raw::DEPTH_TEST);
                gl.DepthFunc(raw::LESS);
                gl.Enable(raw::SCISSOR_TEST);
                for d in &self.draws {
                    let [vx, vy, vw, vh] = d.viewport;
                    let [sx, sy, sw, sh] = d.scissor;
                    let [r, g, b, a] = d.color;
                    gl.Viewport(vx, vy, vw, vh);
                    gl.DepthRange(d.depth_range[0], d.depth_range[1]);
                    gl.Scissor(sx, sy, sw, sh);
                    gl.Color4f(r, g, b, a);
                    d.raster.apply(gl);
                    gl.Begin(raw::TRIANGLE_FAN);
                    for &[x, y, z] in &d.fan {
                        gl.Vertex3f(x, y, z);
                    }
                    gl.End();
                }
                INITIAL.apply(gl);
                gl.Finish();
                gl.PixelStorei(raw::PACK_ALIGNMENT, 1);
                gl.ReadPixels(
                    0,
                    0,
                    w,
                    h,
                    raw::RGBA,
                    raw::UNSIGNED_BYTE,
                    pixels.as_mut_ptr().cast(),
                );
                let error = gl.GetError();
                gl.BindFramebuffer(raw::FRAMEBUFFER, 0);
                gl.DeleteFramebuffers(1, &framebuffer);
                gl.DeleteRenderbuffers(2, renderbuffers.as_ptr());
                error
            };
            assert_eq!(
                error,
                raw::NO_ERROR,
                "Mesa's GL reported an error drawing the scene"
            );
            // glReadPixels returns the bottom row first.
            let row = (self.width * 4) as usize;
            pixels.chunks_exact(row).rev().flatten().copied().collect()
        })
        .expect("Mesa's GL through EGL (make test installs it)")
    }
}

/// A quad of the fan's corners (x0, y0) and (x1, y1) at depth z, counter-clockwise.
fn quad(x0: f32, y0: f32, x1: f32, y1: f32, z: f32) -> Vec<[f32; 3]> {
    vec![[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]]
}

/// Builds `name`.c with harness.c against the header in `include` and this profile's
/// library, which it finds at run time under its SONAME (a link to cargo's libffvk_c.so).
fn build_program(name: &str, include: &Path) -> PathBuf {
    let profile = profile_dir();
    build_library(&profile);
    let dir = profile.join("ffvk-c-test-programs");
    let runtime = dir.join("lib");
    std::fs::create_dir_all(&runtime).expect("a directory for the test programs");
    let soname = runtime.join("libffvk_c.so.0");
    let _ = std::fs::remove_file(&soname);
    std::os::unix::fs::symlink(profile.join("libffvk_c.so"), &soname).expect("a link to the library");
    let sources = workspace().join("ffvk-c/tests/c");
    let program = dir.join(name);
    let output = Command::new("gcc")
        .args([
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-pedantic",
            "-O1",
            "-o",
        ])
        .arg(&program)
        .arg("-I")
        .arg(include)
        .arg("-I")
        .arg(&sources)
        .arg(sources.join(format!("{name}.c")))
        .arg(sources.join("harness.c"))
        .arg(format!("-L{}", profile.display()))
        .arg(format!("-Wl,-rpath,{}", runtime.display()))
        .args(["-lffvk_c", "-lvulkan", "-lm"])
        .output()
        .expect("gcc runs");
    assert!(
        output.status.success(),
        "gcc {name}.c failed: {}",
        printed(&output)
    );
    program
}

/// Runs `program` on `scene` (lavapipe, validation on) and returns what it printed and its
/// image, RGB, top row first.
fn run_program(program: &Path, scene: &Scene, name: &str) -> (String, Vec<u8>) {
    let dir = output_dir().join("c_api_programs");
    std::fs::create_dir_all(&dir).expect("tests/output is writable");
    let scene_path = dir.join(format!("{name}.scene"));
    let image_path = dir.join(format!("{name}.ppm"));
    std::fs::write(&scene_path, scene.text()).expect("the scene file");
    let _ = std::fs::remove_file(&image_path);
    let mut run = Command::new(program);
    run.arg(&scene_path)
        .arg(&image_path)
        .env_remove("LD_LIBRARY_PATH");
    if std::env::var_os("VK_DRIVER_FILES").is_none() {
        run.env("VK_DRIVER_FILES", LAVAPIPE_ICD);
    }
    let output = run.output().expect("the program runs");
    assert!(
        output.status.success(),
        "{} failed (a validation message fails it too): {}",
        program.display(),
        printed(&output)
    );
    let bytes = std::fs::read(&image_path).expect("the program's image");
    let header = format!("P6\n{} {}\n255\n", scene.width, scene.height);
    assert!(
        bytes.starts_with(header.as_bytes()),
        "{} is not a {header:?} PPM",
        image_path.display()
    );
    let rgb = bytes[header.len()..].to_vec();
    assert_eq!(rgb.len(), (scene.width * scene.height * 3) as usize);
    (String::from_utf8_lossy(&output.stdout).into_owned(), rgb)
}

/// Fails unless the program's RGB pixels are GL's, naming the first that differs and saving
/// both images.
fn assert_gl_pixels(scene: &Scene, gl_rgba: &[u8], rgb: &[u8], name: &str) {
    let gl_rgb: Vec<u8> = gl_rgba.chunks(4).flat_map(|p| [p[0], p[1], p[2]]).collect();
    let differing: Vec<usize> = (0..gl_rgb.len() / 3)
        .filter(|&i| gl_rgb[i * 3..i * 3 + 3] != rgb[i * 3..i * 3 + 3])
        .collect();
    if let Some(&first) = differing.first() {
        let to_image = |rgb: &[u8]| {
            let rgba = rgb.chunks(3).flat_map(|p| [p[0], p[1], p[2], 255]).collect();
            image::RgbaImage::from_raw(scene.width, scene.height, rgba).expect("width * height pixels")
        };
        let gl_path = save_for_inspection(&to_image(&gl_rgb), &format!("c_api_programs/{name}_gl"));
        let ffvk_path = save_for_inspection(&to_image(rgb), &format!("c_api_programs/{name}_ffvk"));
        let (x, y) = (first as u32 % scene.width, first as u32 / scene.width);
        panic!(
            "{name}: {} of {} pixels differ from Mesa's GL; the first at ({x}, {y}) from the top: {:?} in GL, {:?} through ffvk (images {} and {})",
            differing.len(),
            scene.width * scene.height,
            &gl_rgb[first * 3..first * 3 + 3],
            &rgb[first * 3..first * 3 + 3],
            gl_path.display(),
            ffvk_path.display()
        );
    }
}

/// How many pixels of GL's image have `rgb`: the scene must show each draw it is about.
fn count(gl_rgba: &[u8], rgb: [u8; 3]) -> usize {
    gl_rgba.chunks(4).filter(|p| p[..3] == rgb).count()
}

const RED: [f32; 4] = [1.0, 0.0, 0.0, 1.0];
const GREEN: [f32; 4] = [0.0, 1.0, 0.0, 1.0];
const BLUE: [f32; 4] = [0.0, 0.0, 1.0, 1.0];
const YELLOW: [f32; 4] = [1.0, 1.0, 0.0, 1.0];
const MAGENTA: [f32; 4] = [1.0, 0.0, 1.0, 1.0];
const CYAN: [f32; 4] = [0.0, 1.0, 1.0, 1.0];
const WHITE: [f32; 4] = [1.0, 1.0, 1.0, 1.0];
const ORANGE: [f32; 4] = [1.0, 0.25, 0.0, 1.0];

/// Vertices are chosen so that every edge lands, in window coordinates, at least 1/16 pixel
/// from every pixel center: coverage does not depend on how a rasterizer breaks ties.
fn viewport_scene() -> Scene {
    let (width, height) = (64, 48);
    let whole = [0, 0, width, height];
    let draw = |viewport, depth_range, scissor, color, fan| Draw {
        viewport,
        depth_range,
        scissor,
        color,
        fan,
        raster: INITIAL,
    };
    Scene {
        width: width as u32,
        height: height as u32,
        clear: [0.0, 0.0, 0.0, 1.0],
        // Between the depths a correct and a wrong depth range give the draws below.
        clear_depth: 0.7,
        draws: vec![
            // The lower-left quadrant, depths narrowed to [0.5, 1]: the red triangle (its right
            // angle at GL's lower left) at 0.625 passes; the green quad at 0.75 does not.
            draw(
                [0, 0, 32, 24],
                [0.5, 1.0],
                whole,
                RED,
                vec![[-0.75, -0.75, -0.5], [0.75, -0.75, -0.5], [-0.75, 0.75, -0.5]],
            ),
            draw(
                [0, 0, 32, 24],
                [0.5, 1.0],
                whole,
                GREEN,
                quad(-0.75, -0.75, 0.75, 0.75, 0.0),
            ),
            // A viewport off the axes with the depth range reversed: the blue triangle (clip z
            // 0.5) lands at depth 0.25 and shows, the yellow quad (z -0.5) at 0.75 does not.
            draw(
                [36, 20, 24, 24],
                [1.0, 0.0],
                whole,
                BLUE,
                vec![[-0.75, 0.75, 0.5], [0.75, 0.75, 0.5], [0.75, -0.5, 0.5]],
            ),
            draw(
                [36, 20, 24, 24],
                [1.0, 0.0],
                whole,
                YELLOW,
                quad(-0.75, -0.75, 0.75, 0.75, -0.5),
            ),
            // A viewport past the target's top and right edges.
            draw(
                [48, 30, 20, 30],
                [0.0, 1.0],
                whole,
                MAGENTA,
                vec![
                    [0.0, -0.8, -0.9],
                    [0.8, 0.0, -0.9],
                    [0.0, 0.8, -0.9],
                    [-0.8, 0.0, -0.9],
                ],
            ),
            // A viewport past the target's bottom and left edges.
            draw(
                [-8, -6, 32, 16],
                [0.0, 1.0],
                whole,
                ORANGE,
                vec![[-0.75, -0.75, -0.8], [0.75, -0.25, -0.8], [-0.25, 0.75, -0.8]],
            ),
            // Scissor boxes: across the bottom-right corner, inside near the top, outside.
            draw(
                whole,
                [0.0, 1.0],
                [50, -5, 30, 12],
                CYAN,
                quad(-1.0, -1.0, 1.0, 1.0, -0.95),
            ),
            draw(
                whole,
                [0.0, 1.0],
                [4, 30, 10, 10],
                WHITE,
                quad(-1.0, -1.0, 1.0, 1.0, -0.99),
            ),
            draw(
                whole,
                [0.0, 1.0],
                [70, 0, 10, 10],
                GREEN,
                quad(-1.0, -1.0, 1.0, 1.0, -0.999),
            ),
        ],
    }
}

#[test]
fn gl_viewports_depth_ranges_and_scissor_boxes_set_through_ffvk_viewport_and_ffvk_scissor_draw_mesas_pixels()
{
    let scene = viewport_scene();
    let gl = scene.render_gl();
    // The scene shows what it is about, in GL: each visible draw, and no hidden one.
    for (color, what) in [
        ([255, 0, 0], "the red triangle"),
        ([0, 0, 255], "the blue triangle"),
        ([255, 0, 255], "the magenta diamond"),
        ([255, 64, 0], "the orange triangle"),
        ([0, 255, 255], "the cyan scissor box"),
        ([255, 255, 255], "the white scissor box"),
    ] {
        assert!(
            count(&gl, color) > 0,
            "GL shows no pixel of {what}: the scene is broken"
        );
    }
    assert_eq!(
        count(&gl, [0, 255, 0]),
        0,
        "GL shows the green draws the depth range and scissor hide"
    );
    assert_eq!(
        count(&gl, [255, 255, 0]),
        0,
        "GL shows the yellow quad the reversed depth range hides"
    );
    assert_eq!(
        count(&gl, [255, 255, 255]),
        100,
        "the white box is glScissor(4, 30, 10, 10)"
    );

    let program = build_program("viewport", &workspace().join("ffvk-c/include"));
    let (_, rgb) = run_program(&program, &scene, "viewport");
    assert_gl_pixels(&scene, &gl, &rgb, "viewport");
}

#[test]
fn a_program_built_against_version_1_of_the_header_draws_through_todays_library_as_mesa_draws() {
    let (width, height) = (64, 48);
    let whole = [0, 0, width, height];
    let draw = |color, fan| Draw {
        viewport: whole,
        depth_range: [0.0, 1.0],
        scissor: whole,
        color,
        fan,
        raster: INITIAL,
    };
    let scene = Scene {
        width: width as u32,
        height: height as u32,
        clear: [0.0, 0.0, 0.0, 1.0],
        clear_depth: 0.7,
        draws: vec![
            draw(
                RED,
                vec![[-0.75, -0.75, -0.5], [0.75, -0.75, -0.5], [-0.75, 0.75, -0.5]],
            ),
            draw(GREEN, quad(-0.75, -0.75, 0.75, 0.75, 0.5)),
            draw(BLUE, quad(0.25, 0.25, 0.75, 0.75, -0.9)),
        ],
    };
    let gl = scene.render_gl();
    assert!(count(&gl, [255, 0, 0]) > 0 && count(&gl, [0, 0, 255]) == 16 * 12);

    let program = build_program("abi_v1", &workspace().join("ffvk-c/tests/abi"));
    let (printed_sizes, rgb) = run_program(&program, &scene, "abi_v1");
    assert_gl_pixels(&scene, &gl, &rgb, "abi_v1");
    // The sizes the old header declares are version 1's in the library's table.
    for (name, versions) in [
        (
            "FfvkRendererCreateInfo",
            <FfvkRendererCreateInfo as Versioned>::VERSIONS,
        ),
        ("FfvkDrawInfo", <FfvkDrawInfo as Versioned>::VERSIONS),
    ] {
        let v1 = versions[0].size;
        let line = format!("sizeof({name}) {v1}");
        assert!(
            printed_sizes.lines().any(|l| l == line),
            "version 1's header declares {name} of another size than the library's version 1 ({v1}): {printed_sizes}"
        );
    }
}

/// GL's raster state from the context (FFVK_RASTER_SOURCE_CONTEXT), set with the C entry
/// points: a red quad; a green one over the left half with red masked off (§4.2.2: red stays as
/// it was, so yellow); a quad over the upper right with every color masked off writing stencil 1
/// (GL_ALWAYS, GL_REPLACE on depth pass); a blue quad over everything limited by GL_EQUAL 1 to
/// the upper right; a white square inside the lower right with GL_XOR (§4.1.11: red XOR white
/// is cyan). Each later draw is nearer, so GL_LESS passes it.
#[test]
fn version_3_draws_with_the_contexts_color_mask_stencil_and_logic_op_draw_mesas_pixels_and_the_specs() {
    let (width, height) = (64, 48);
    let whole = [0, 0, width, height];
    let draw = |color, fan, raster| Draw {
        viewport: whole,
        depth_range: [0.0, 1.0],
        scissor: whole,
        color,
        fan,
        raster,
    };
    let stencil = |func, reference, dppass| Some((func, reference, 0xFF, [raw::KEEP, raw::KEEP, dppass]));
    let scene = Scene {
        width: width as u32,
        height: height as u32,
        clear: [0.0, 0.0, 0.0, 1.0],
        clear_depth: 1.0,
        draws: vec![
            draw(RED, quad(-1.0, -1.0, 1.0, 1.0, 0.0), INITIAL),
            draw(
                GREEN,
                quad(-1.0, -1.0, 0.0, 1.0, -0.5),
                Raster {
                    color_mask: [false, true, true, true],
                    ..INITIAL
                },
            ),
            draw(
                WHITE,
                quad(0.0, 0.0, 1.0, 1.0, -0.6),
                Raster {
                    color_mask: [false; 4],
                    stencil: stencil(raw::ALWAYS, 1, raw::REPLACE),
                    ..INITIAL
                },
            ),
            draw(
                BLUE,
                quad(-1.0, -1.0, 1.0, 1.0, -0.9),
                Raster {
                    stencil: stencil(raw::EQUAL, 1, raw::KEEP),
                    ..INITIAL
                },
            ),
            draw(
                WHITE,
                quad(0.25, -0.75, 0.75, -0.25, -0.95),
                Raster {
                    logic_op: Some(raw::XOR),
                    ..INITIAL
                },
            ),
        ],
    };
    // What GL's spec gives, region by region (rows from the top): the left half yellow, the
    // upper right blue, a 16 x 12 cyan square in the lower right, the rest of it red.
    let spec = |x: u32, y: u32| -> [u8; 3] {
        if x < 32 {
            [255, 255, 0]
        } else if y < 24 {
            [0, 0, 255]
        } else if (40..56).contains(&x) && (30..42).contains(&y) {
            [0, 255, 255]
        } else {
            [255, 0, 0]
        }
    };
    let expected: Vec<u8> = (0..height as u32)
        .flat_map(|y| (0..width as u32).flat_map(move |x| spec(x, y)))
        .collect();

    let program = build_program("raster", &workspace().join("ffvk-c/include"));
    let (_, rgb) = run_program(&program, &scene, "raster");
    let differing = (0..expected.len() / 3)
        .filter(|&i| expected[i * 3..i * 3 + 3] != rgb[i * 3..i * 3 + 3])
        .count();
    assert_eq!(
        differing, 0,
        "pixels through ffvk differ from GL's spec (tests/output/c_api_programs/raster.ppm)"
    );

    let gl = scene.render_gl();
    let gl_rgb: Vec<u8> = gl.chunks(4).flat_map(|p| [p[0], p[1], p[2]]).collect();
    assert!(
        gl_rgb == expected,
        "Mesa's GL does not draw what the spec gives: the scene is broken"
    );
    assert_gl_pixels(&scene, &gl, &rgb, "raster");
}
