//! The raster state a GL draw carries beyond culling, depth and blending (issue 50, item 2),
//! through the Renderer and Mesa's GL: glPolygonOffset with GL_POLYGON_OFFSET_FILL and
//! glColorMask.

use ffvk::gl::state::GlState;
use ffvk::mesh::{MeshData, Vertex};
use ffvk::{Draw, Frame, Renderer};
use ffvk_cli::gl_reference::{GlCall, GlDraw};
use glam::{Mat4, Vec3, Vec4};
use image::RgbaImage;

use crate::support::*;

const SIZE: u32 = 64;

/// A quad of one color, tilted about x so that its depth has a slope across the image.
fn quad(color: Vec4) -> MeshData {
    let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
    MeshData::new(
        corners
            .iter()
            .map(|&(x, y)| Vertex::new(Vec3::new(x, y, 0.0), Vec3::Z, color))
            .collect(),
        vec![0, 1, 2, 0, 2, 3],
    )
}

fn modelview() -> Mat4 {
    Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0)) * Mat4::from_rotation_x(-0.6)
}

fn projection() -> Mat4 {
    Mat4::perspective_rh_gl(50f32.to_radians(), 1.0, 1.0, 10.0)
}

/// A red quad, then the same quad green with `offset` and `mask`, depth test `GL_LESS`, by
/// ffvk and by Mesa's GL.
fn draw_both(r: &mut Renderer, offset: Option<(f32, f32)>, mask: [bool; 4]) -> (RgbaImage, RgbaImage) {
    let (red, green) = (
        quad(Vec4::new(1.0, 0.0, 0.0, 1.0)),
        quad(Vec4::new(0.0, 1.0, 0.0, 1.0)),
    );
    let state = GlState::new().lighting;
    let (a, b) = (r.upload(&red).unwrap(), r.upload(&green).unwrap());
    let mut frame = Frame::new(SIZE, SIZE);
    frame.clear_color = Vec4::new(0.2, 0.4, 0.6, 1.0);
    frame.depth_test = true;
    frame.draws.push(Draw::new(&a, modelview(), projection(), state));
    let mut second = Draw::new(&b, modelview(), projection(), state).with_color_mask(mask);
    if let Some((factor, units)) = offset {
        second = second.with_polygon_offset(factor, units);
    }
    frame.draws.push(second);
    let ours = r.render(&frame).unwrap().into_rgba_image();
    let first = GlDraw::new(&red, modelview(), projection(), state);
    let mut then = GlDraw::new(&green, modelview(), projection(), state);
    then.calls.push(GlCall::ColorMask(mask));
    if let Some((factor, units)) = offset {
        then.calls.push(GlCall::PolygonOffsetFill(factor, units));
    }
    let theirs = mesa_image((SIZE, SIZE), [0.2, 0.4, 0.6, 1.0], true, vec![first, then]);
    (ours, theirs)
}

/// Pixels of the quad (not the clear color) in both images that differ by more than 1/255.
fn differing(a: &RgbaImage, b: &RgbaImage) -> usize {
    a.pixels()
        .zip(b.pixels())
        .filter(|(p, q)| p.0.iter().zip(q.0).any(|(x, y)| x.abs_diff(y) > 1))
        .count()
}

/// GL 2.1 §3.5.5: a coplanar second quad fails `GL_LESS` unless offset toward the eye;
/// pushed away it fails everywhere. Units alone and the slope factor alone (the quad is
/// tilted) each bring it forward. As Mesa's GL draws them.
#[test]
fn polygon_offset_brings_a_coplanar_decal_forward_or_pushes_it_back_as_gl_does() {
    let mut r = renderer();
    let red = [255, 0, 0, 255];
    let green = [0, 255, 0, 255];
    for (offset, want, what) in [
        (None, red, "no offset: the coplanar quad fails GL_LESS"),
        (Some((-1.0, -1.0)), green, "(-1, -1): in front"),
        (Some((0.0, -4.0)), green, "units alone"),
        (
            Some((-2.0, 0.0)),
            green,
            "the slope factor alone on a tilted quad",
        ),
        (Some((1.0, 1.0)), red, "(1, 1): behind"),
    ] {
        let (ours, theirs) = draw_both(&mut r, offset, [true; 4]);
        let name = what.replace([' ', ':', '(', ')', ','], "_");
        let a = save_for_inspection(&ours, &format!("raster_offset_{name}_ffvk"));
        save_for_inspection(&theirs, &format!("raster_offset_{name}_gl"));
        assert_eq!(
            ours.get_pixel(SIZE / 2, SIZE / 2).0,
            want,
            "{what}: {}",
            a.display()
        );
        assert_eq!(theirs.get_pixel(SIZE / 2, SIZE / 2).0, want, "{what}: Mesa");
        let n = differing(&ours, &theirs);
        assert!(n <= 4, "{what}: {n} pixels differ from Mesa's; {}", a.display());
    }
    finish(r);
}

/// GL 2.1 §4.2.2: masked channels keep what the image held (here the red quad's, drawn
/// before) while the depth test still runs; as Mesa's GL draws it.
#[test]
fn the_color_mask_keeps_the_masked_channels_of_what_was_drawn_before() {
    let mut r = renderer();
    for (mask, want) in [
        ([true, true, true, true], [0, 255, 0, 255]),
        ([false, true, false, true], [255, 255, 0, 255]),
        ([true, false, true, false], [0, 0, 0, 255]),
        ([false, false, false, false], [255, 0, 0, 255]),
    ] {
        let (ours, theirs) = draw_both(&mut r, Some((-1.0, -1.0)), mask);
        let what = format!("mask {mask:?}");
        let a = save_for_inspection(
            &ours,
            &format!("raster_mask_{}", what.replace([' ', ',', '[', ']'], "_")),
        );
        assert_eq!(
            ours.get_pixel(SIZE / 2, SIZE / 2).0,
            want,
            "{what}: {}",
            a.display()
        );
        let n = differing(&ours, &theirs);
        assert!(n == 0, "{what}: {n} pixels differ from Mesa's; {}", a.display());
    }
    finish(r);
}

/// A color mask with bits beyond R, G, B and A, or an offset that is not finite, is refused
/// naming the field and the value.
#[test]
fn bad_color_masks_and_offsets_are_refused_naming_the_field() {
    use ffvk::ash::vk;
    use ffvk::{PolygonOffset, RasterState};
    let e = RasterState::default()
        .with_color_mask(vk::ColorComponentFlags::from_raw(0x1F))
        .validate()
        .unwrap_err()
        .to_string();
    assert!(e.contains("color_mask") && e.contains("0x1F"), "{e}");
    let e = RasterState::default()
        .with_polygon_offset(Some(PolygonOffset::fill(f32::NAN, 1.0)))
        .validate()
        .unwrap_err()
        .to_string();
    assert!(e.contains("polygon_offset") && e.contains("NaN"), "{e}");
    RasterState::default()
        .with_color_mask(vk::ColorComponentFlags::R | vk::ColorComponentFlags::A)
        .with_polygon_offset(Some(PolygonOffset::fill(-1.0, -1.0)))
        .validate()
        .unwrap();
}

/// The deferred path writes every channel, so a frame with a color mask in the fragment mode
/// stays forward, even asked for the deferred path: its image is the forward one.
#[test]
fn a_color_masked_frame_asked_for_the_deferred_path_draws_as_the_forward_path() {
    use ffvk::gl::state::{Cap, LightParam, LightingMode};
    let mut r = renderer();
    let mut gl = GlState::new();
    gl.lighting_mode(LightingMode::Fragment);
    gl.enable(Cap::Lighting).unwrap();
    gl.enable(Cap::Light(0)).unwrap();
    gl.light(0, LightParam::Position(Vec4::new(0.3, 0.4, 1.0, 0.0)))
        .unwrap();
    let (red, green) = (quad(Vec4::new(1.0, 0.0, 0.0, 1.0)), quad(Vec4::ONE));
    let (a, b) = (r.upload(&red).unwrap(), r.upload(&green).unwrap());
    let mut images = Vec::new();
    for (path, mask) in [
        (ffvk::FragmentPath::Forward, [false, true, false, true]),
        (ffvk::FragmentPath::Deferred, [false, true, false, true]),
        (ffvk::FragmentPath::Deferred, [true; 4]),
    ] {
        let mut frame = Frame::new(SIZE, SIZE);
        frame.depth_test = true;
        frame.fragment_path = path;
        frame
            .draws
            .push(Draw::new(&a, modelview(), projection(), gl.lighting));
        frame.draws.push(
            Draw::new(&b, modelview(), projection(), gl.lighting)
                .with_polygon_offset(-1.0, -1.0)
                .with_color_mask(mask),
        );
        let (pixels, stats) = r.render_measured(&frame).unwrap();
        images.push((pixels.into_rgba_image(), stats.deferred));
    }
    assert!(images[2].1, "the unmasked frame takes the deferred path");
    assert!(!images[1].1, "the masked frame stays forward");
    assert_eq!(
        differing(&images[0].0, &images[1].0),
        0,
        "the masked frame's image"
    );
    finish(r);
}

/// GL 1.4's blend equations and glBlendColor (GL 2.1 §4.1.8): a red quad, then a translucent
/// green one over it blended with each equation, its factors reading the constant color;
/// the pixel as GL's formula says, within the 8-bit buffer's 2/255, and every pixel as Mesa's
/// GL draws it.
#[test]
fn blend_equations_and_the_blend_color_blend_as_gl_says() {
    use ffvk::ash::vk::{BlendFactor as F, BlendOp as O};
    use ffvk::Blend;
    let mut r = renderer();
    let (dst, src) = (Vec4::new(0.8, 0.1, 0.3, 1.0), Vec4::new(0.2, 0.9, 0.5, 0.6));
    let color = [0.25f32, 0.5, 0.75, 0.4];
    let flat = GlState::new().lighting;
    let (under, over) = (quad(dst), quad(src));
    let (a, b) = (r.upload(&under).unwrap(), r.upload(&over).unwrap());
    let c = Vec4::from_array(color);
    for (op, sf, df) in [
        (O::ADD, F::CONSTANT_COLOR, F::ONE_MINUS_CONSTANT_COLOR),
        (O::SUBTRACT, F::ONE, F::CONSTANT_ALPHA),
        (O::REVERSE_SUBTRACT, F::SRC_ALPHA, F::ONE_MINUS_CONSTANT_ALPHA),
        (O::MIN, F::ONE, F::ONE),
        (O::MAX, F::ZERO, F::ZERO),
    ] {
        let blend = Blend::new(sf, df, op);
        let mut frame = Frame::new(SIZE, SIZE);
        frame.clear_color = Vec4::new(0.0, 0.0, 0.0, 1.0);
        // The second quad is coplanar: without a depth test it blends over the first.
        frame.depth_test = false;
        frame.draws.push(Draw::new(&a, modelview(), projection(), flat));
        frame.draws.push(
            Draw::new(&b, modelview(), projection(), flat)
                .with_blend(Some(blend))
                .with_blend_color(color),
        );
        let ours = r.render(&frame).unwrap().into_rgba_image();
        let mut then = GlDraw::new(&over, modelview(), projection(), flat);
        then.calls
            .extend([GlCall::Blend(blend), GlCall::BlendColor(color)]);
        let first = GlDraw::new(&under, modelview(), projection(), flat);
        let theirs = mesa_image((SIZE, SIZE), [0.0, 0.0, 0.0, 1.0], false, vec![first, then]);
        // GL's formula: the factors, then the equation (MIN and MAX ignore the factors),
        // clamped to [0, 1].
        let factor = |f: F| match f {
            F::ZERO => Vec4::ZERO,
            F::ONE => Vec4::ONE,
            F::CONSTANT_COLOR => c,
            F::ONE_MINUS_CONSTANT_COLOR => Vec4::ONE - c,
            F::CONSTANT_ALPHA => Vec4::splat(c.w),
            F::ONE_MINUS_CONSTANT_ALPHA => Vec4::splat(1.0 - c.w),
            F::SRC_ALPHA => Vec4::splat(src.w),
            _ => unreachable!(),
        };
        let (s, d) = (src * factor(sf), dst * factor(df));
        let want = match op {
            O::ADD => s + d,
            O::SUBTRACT => s - d,
            O::REVERSE_SUBTRACT => d - s,
            O::MIN => src.min(dst),
            _ => src.max(dst),
        }
        .clamp(Vec4::ZERO, Vec4::ONE);
        let what = format!("{op:?} {sf:?} {df:?}");
        let path = save_for_inspection(&ours, &format!("raster_blend_{op:?}"));
        let got = Vec4::from_array(ours.get_pixel(SIZE / 2, SIZE / 2).0.map(|v| v as f32 / 255.0));
        assert!(
            // Blending runs at the color buffer's 8 bits (the destination, the constant and
            // each product rounded there): within 2/255 of the real-number formula.
            (got - want).abs().max_element() <= 2.0 / 255.0 + 1e-6,
            "{what}: {got} vs GL's {want}; {}",
            path.display()
        );
        let n = differing(&ours, &theirs);
        assert!(
            n == 0,
            "{what}: {n} pixels differ from Mesa's; {}",
            path.display()
        );
    }
    finish(r);
}

/// A blend color outside [0, 1] is refused naming the field (GL clamps at glBlendColor; the
/// Vulkan-side state takes what a draw will use).
#[test]
fn a_blend_color_outside_0_1_is_refused_naming_the_field() {
    use ffvk::{BlendColor, RasterState};
    let e = RasterState::default()
        .with_blend_color(BlendColor([0.5, 1.5, 0.0, 1.0]))
        .validate()
        .unwrap_err()
        .to_string();
    assert!(e.contains("blend_color") && e.contains("1.5"), "{e}");
}
