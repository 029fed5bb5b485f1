//! The C API's layer example (ffvk-c/examples/layers.c), built through its Makefile and run
//! with the validation layer: one renderer, three vertex layouts in one frame (float normals,
//! GL_BYTE normals, a color array with a per-vertex emission and the current normal), a
//! viewport change between draws, one viewport not covering the image's height; its image
//! against Mesa's GL issuing the GL calls the example's comments name.

use std::process::Command;

use ffvk_cli::gl_reference::{raw, render_raw_gl};

use crate::c_api_example::{build_example, build_library, printed, profile_dir, read_ppm, LAVAPIPE_ICD};
use crate::support::{output_dir, save_for_inspection};

const SIZE: u32 = 96;
const QUAD: [[f32; 3]; 4] = [
    [-1.0, -1.0, 0.0],
    [1.0, -1.0, 0.0],
    [-1.0, 1.0, 0.0],
    [1.0, 1.0, 0.0],
];
const COLORS: [[u8; 4]; 4] = [
    [255, 0, 0, 255],
    [0, 255, 0, 255],
    [0, 0, 255, 255],
    [255, 255, 255, 255],
];
const EMISSIONS: [[f32; 4]; 4] = [
    [0.2, 0.0, 0.0, 1.0],
    [0.0, 0.0, 0.0, 1.0],
    [0.0, 0.0, 0.2, 1.0],
    [0.1, 0.1, 0.1, 1.0],
];

#[test]
fn a_c_layer_draws_three_vertex_layouts_current_normals_per_vertex_materials_and_viewports_as_mesa_does() {
    let profile = profile_dir();
    build_library(&profile);
    let layers = build_example(&profile).with_file_name("layers");
    let out = output_dir().join("c_api_layers");
    let _ = std::fs::remove_dir_all(&out);
    std::fs::create_dir_all(&out).expect("tests/output is writable");
    let mut run = Command::new(&layers);
    run.arg(&out)
        .env("FFVK_VALIDATION", "1")
        .env_remove("FFVK_DEVICE");
    if std::env::var_os("VK_DRIVER_FILES").is_none() {
        run.env("VK_DRIVER_FILES", LAVAPIPE_ICD);
    }
    let output = run.output().expect("the C example runs");
    assert!(
        output.status.success(),
        "{} failed (validation messages fail it too): {}",
        layers.display(),
        printed(&output)
    );
    let c_rgb = read_ppm(&out.join("layers.ppm"), SIZE);

    let third = (SIZE / 3) as i32;
    let mesa = render_raw_gl(SIZE, SIZE, |g| {
        // SAFETY: a context is current; the calls are those layers.c's comments name.
        unsafe {
            g.Enable(raw::LIGHTING);
            g.Enable(raw::LIGHT0);
            g.Viewport(0, 0, third, SIZE as i32);
            g.Begin(raw::TRIANGLE_STRIP);
            for p in QUAD {
                g.Normal3f(0.0, 0.0, 1.0);
                g.Vertex3f(p[0], p[1], p[2]);
            }
            g.End();
            g.Viewport(third, 0, third, SIZE as i32);
            g.Materialfv(
                raw::FRONT_AND_BACK,
                raw::DIFFUSE,
                [100.0f32, 50.0, 100.0, 1.0].as_ptr(),
            );
            g.Begin(raw::TRIANGLE_STRIP);
            for p in QUAD {
                // glNormal3b converts as GL 2.1 says (Mesa's BYTE_TO_FLOAT).
                g.Normal3b(0, 0, 0);
                g.Vertex3f(p[0], p[1], p[2]);
            }
            g.End();
            g.Viewport(2 * third, third / 2, third, SIZE as i32 - third);
            g.Enable(raw::COLOR_MATERIAL);
            g.Normal3f(0.0, 0.6, 0.8);
            g.Begin(raw::TRIANGLE_STRIP);
            for ((p, c), e) in QUAD.iter().zip(COLORS).zip(EMISSIONS) {
                g.Color4ub(c[0], c[1], c[2], c[3]);
                g.Materialfv(raw::FRONT_AND_BACK, raw::EMISSION, e.as_ptr());
                g.Vertex3f(p[0], p[1], p[2]);
            }
            g.End();
        }
    })
    .expect("Mesa's GL renders");
    let mesa_rgb: Vec<u8> = mesa.pixels().flat_map(|p| [p[0], p[1], p[2]]).collect();
    let c_image = image::RgbaImage::from_fn(SIZE, SIZE, |x, y| {
        let i = ((y * SIZE + x) * 3) as usize;
        image::Rgba([c_rgb[i], c_rgb[i + 1], c_rgb[i + 2], 255])
    });
    save_for_inspection(&c_image, "c_api_layers/ffvk");
    save_for_inspection(&mesa, "c_api_layers/mesa");
    let worst = c_rgb
        .iter()
        .zip(&mesa_rgb)
        .map(|(a, b)| a.abs_diff(*b))
        .max()
        .unwrap_or(0);
    assert!(
        worst <= 1,
        "the C layer's image and Mesa's differ by {worst}/255 (tests/output/c_api_layers)"
    );
    // Not two blank images: the third viewport leaves its rows below GL's y = third / 2 clear,
    // and covers the middle of its column.
    let at = |x: u32, y: u32| &c_rgb[((y * SIZE + x) * 3) as usize..][..3];
    assert_eq!(
        at(2 * SIZE / 3 + 4, SIZE - 2),
        [0, 0, 0],
        "below the third viewport"
    );
    assert_ne!(at(5 * SIZE / 6, SIZE / 2), [0, 0, 0], "inside the third viewport");
    assert_ne!(at(SIZE / 2, SIZE / 2), [0, 0, 0], "the byte normals' quad");
}
