//! Points (GL 2.1 §3.3, ARB_point_parameters, ARB_point_sprite): sizes from the eye distance,
//! clamped and rounded, and sprites with GL_COORD_REPLACE, through ffvk and Mesa's GL.

use ffvk::gl::state::{Cap, GlState, PointParam, PointParameters, SpriteOrigin};
use ffvk::gl::texture::{MagFilter, MinFilter, Sampling, TextureImage};
use ffvk::mesh::{MeshData, Vertex};
use ffvk::{Draw, Frame, Renderer, Topology};
use ffvk_cli::gl_reference::{GlDraw, GlMode};
use glam::{Mat4, Vec2, Vec3, Vec4};
use image::RgbaImage;

use crate::support::*;

const SIZE: u32 = 256;

/// One white point at the object origin.
fn one_point() -> MeshData {
    MeshData::new(
        vec![Vertex::new(Vec3::ZERO, Vec3::Z, Vec4::ONE).with_texcoord(Vec2::ZERO)],
        vec![0],
    )
    .with_topology(Topology::PointList)
}

/// A point drawn at eye position `eye`, its window position moved to NDC `at` by a translation
/// after the projection (so that points on the view axis can stand side by side).
struct Spot {
    eye: Vec3,
    at: Vec2,
    size: f32,
}

fn projection(at: Vec2) -> Mat4 {
    Mat4::from_translation(at.extend(0.0)) * Mat4::perspective_rh_gl(40f32.to_radians(), 1.0, 0.5, 50.0)
}

/// The spots drawn by ffvk and by Mesa's GL with `gl`'s point state (lighting off).
fn draw_both(
    r: &mut Renderer,
    spots: &[Spot],
    gl: &GlState,
    texture: Option<(&TextureImage, Sampling)>,
) -> (RgbaImage, RgbaImage) {
    let data = one_point();
    let mesh = r.upload(&data).unwrap();
    let uploaded = texture.map(|(image, sampling)| r.upload_texture(image, &sampling).unwrap());
    let mut frame = Frame::new(SIZE, SIZE);
    frame.clear_color = Vec4::new(0.0, 0.0, 0.0, 1.0);
    let mut draws = Vec::new();
    for s in spots {
        let modelview = Mat4::from_translation(s.eye);
        frame.draws.push(
            Draw::new(&mesh, modelview, projection(s.at), gl.lighting)
                .with_point_size(s.size)
                .with_texture(uploaded.as_ref()),
        );
        let mut d = GlDraw::new(&data, modelview, projection(s.at), gl.lighting);
        d.mode = GlMode::Points;
        d.point_size = s.size;
        d.textures[0] = texture;
        draws.push(d);
    }
    let ours = r.render(&frame).unwrap().into_rgba_image();
    let theirs = mesa_image((SIZE, SIZE), [0.0, 0.0, 0.0, 1.0], false, draws);
    (ours, theirs)
}

/// The width of the point around NDC `at`: the run of lit pixels through the pixel there,
/// along its row (`None` where the column's run differs: not a square).
fn width_at(image: &RgbaImage, at: Vec2) -> Option<u32> {
    let cx = ((at.x + 1.0) / 2.0 * SIZE as f32) as i32;
    let cy = ((1.0 - at.y) / 2.0 * SIZE as f32) as i32;
    let lit = |x: i32, y: i32| {
        (0..SIZE as i32).contains(&x)
            && (0..SIZE as i32).contains(&y)
            && image.get_pixel(x as u32, y as u32).0[..3] != [0, 0, 0]
    };
    // The lit pixel nearest the point's center (a one-pixel point may land beside it).
    let near = (-2..=2)
        .flat_map(|dy| (-2..=2).map(move |dx| (dx, dy)))
        .filter(|&(dx, dy)| lit(cx + dx, cy + dy))
        .min_by_key(|&(dx, dy)| dx * dx + dy * dy);
    let Some((dx, dy)) = near else {
        return Some(0);
    };
    let (cx, cy) = (cx + dx, cy + dy);
    let run = |step: (i32, i32)| {
        let mut n = 1;
        for sign in [1, -1] {
            let mut k = 1;
            while lit(cx + sign * k * step.0, cy + sign * k * step.1) {
                n += 1;
                k += 1;
            }
        }
        n
    };
    let (row, column) = (run((1, 0)), run((0, 1)));
    (row == column).then_some(row as u32)
}

/// Spots on the view axis at increasing distances, side by side on screen.
fn receding(sizes: &[f32]) -> Vec<Spot> {
    let d = [2.0, 3.5, 5.0, 7.0, 10.0, 14.0, 20.0, 30.0];
    let mut spots = Vec::new();
    for (i, &z) in d.iter().enumerate() {
        for (j, &size) in sizes.iter().enumerate() {
            spots.push(Spot {
                eye: Vec3::new(0.0, 0.0, -z),
                at: Vec2::new(-0.8 + 0.22 * i as f32, 0.7 - 0.45 * j as f32),
                size,
            });
        }
    }
    spots
}

/// Attenuated points on the view axis (where the spec's distance and Mesa's |z_e| agree):
/// every width is GL 2.1's derived size, clamped and rounded, and Mesa's.
#[test]
fn attenuated_points_shrink_with_the_eye_distance_clamped_and_rounded_as_gl_says() {
    let mut r = renderer();
    let mut gl = GlState::new();
    gl.point_parameter(PointParam::DistanceAttenuation(Vec3::new(0.2, 0.1, 0.02)))
        .unwrap();
    gl.point_parameter(PointParam::SizeMin(2.0)).unwrap();
    gl.point_parameter(PointParam::SizeMax(14.0)).unwrap();
    let spots = receding(&[24.0, 9.0, 3.0, 1.0]);
    let (ours, theirs) = draw_both(&mut r, &spots, &gl, None);
    save_for_inspection(&ours, "points_attenuated_ffvk");
    save_for_inspection(&theirs, "points_attenuated_gl");
    let p = gl.lighting.points;
    let mut widths = std::collections::BTreeSet::new();
    for s in &spots {
        let spec = p.raster_width(p.derived_size(f64::from(s.size), f64::from(-s.eye.z)));
        let (a, b) = (width_at(&ours, s.at), width_at(&theirs, s.at));
        assert_eq!(
            (a, b),
            (Some(spec as u32), Some(spec as u32)),
            "size {} at d {}: ffvk {a:?}, Mesa {b:?}, GL 2.1 {spec}",
            s.size,
            -s.eye.z
        );
        widths.insert(spec as u32);
    }
    assert!(widths.len() >= 6, "the widths vary: {widths:?}");
    assert!(
        widths.contains(&2) && widths.contains(&14),
        "both clamps show: {widths:?}"
    );
    finish(r);
}

/// Points without attenuation are drawn at their size rounded to the nearest integer (at
/// least one pixel), as GL 2.1's aliased points are and Mesa draws them; sprites are not
/// rounded.
#[test]
fn aliased_points_are_rounded_to_whole_pixels_and_sprites_are_not() {
    let mut r = renderer();
    // No ties: GL says "nearest" and Mesa draws 2.5 as 2.
    let sizes = [1.4f32, 1.6, 2.4, 2.6, 3.49, 4.6];
    let spots: Vec<Spot> = sizes
        .iter()
        .enumerate()
        .map(|(i, &size)| Spot {
            eye: Vec3::new(0.0, 0.0, -3.0),
            at: Vec2::new(-0.75 + 0.3 * i as f32, 0.0),
            size,
        })
        .collect();
    let gl = GlState::new();
    let (ours, theirs) = draw_both(&mut r, &spots, &gl, None);
    for s in &spots {
        let (a, b) = (width_at(&ours, s.at), width_at(&theirs, s.at));
        let spec = PointParameters::default().raster_width(f64::from(s.size));
        assert_eq!(
            (a, b),
            (Some(spec as u32), Some(spec as u32)),
            "size {}: ffvk {a:?}, Mesa {b:?}",
            s.size
        );
    }
    // Sprites: the size as it is, wherever Mesa's squares fall.
    let mut gl = GlState::new();
    gl.enable(Cap::PointSprite).unwrap();
    let (ours, theirs) = draw_both(&mut r, &spots, &gl, None);
    for s in &spots {
        let (a, b) = (width_at(&ours, s.at), width_at(&theirs, s.at));
        assert_eq!(a, b, "sprite of size {}: ffvk {a:?}, Mesa {b:?}", s.size);
        // Drawn (a sprite of a fractional size may cover a rectangle: `None`).
        assert_ne!(a, Some(0), "sprite of size {}: drawn", s.size);
    }
    finish(r);
}

/// A textured point sprite with GL_COORD_REPLACE shows the whole texture, upright with
/// GL_UPPER_LEFT and flipped with GL_LOWER_LEFT, as Mesa's GL draws it.
#[test]
fn point_sprites_replace_the_texture_coordinates_from_either_origin_as_mesa_does() {
    let mut r = renderer();
    // Four quadrants: red, green / blue, white (texel row 0 first).
    let mut rgba = Vec::new();
    for j in 0..8u32 {
        for i in 0..8u32 {
            rgba.extend(match (i < 4, j < 4) {
                (true, true) => [255, 0, 0, 255],
                (false, true) => [0, 255, 0, 255],
                (true, false) => [0, 0, 255, 255],
                (false, false) => [255, 255, 255, 255],
            });
        }
    }
    let image = TextureImage::new(8, 8, rgba).unwrap();
    let sampling = Sampling::default()
        .with_min_filter(MinFilter::Nearest)
        .with_mag_filter(MagFilter::Nearest);
    for origin in [SpriteOrigin::UpperLeft, SpriteOrigin::LowerLeft] {
        let mut gl = GlState::new();
        gl.enable(Cap::Texture2D).unwrap();
        gl.enable(Cap::PointSprite).unwrap();
        gl.coord_replace(true);
        gl.point_parameter(PointParam::SpriteCoordOrigin(origin)).unwrap();
        let spots = [Spot {
            eye: Vec3::new(0.0, 0.0, -3.0),
            at: Vec2::ZERO,
            size: 32.0,
        }];
        let (ours, theirs) = draw_both(&mut r, &spots, &gl, Some((&image, sampling)));
        let what = format!("sprite_{origin:?}");
        let a = save_for_inspection(&ours, &format!("points_{what}_ffvk"));
        save_for_inspection(&theirs, &format!("points_{what}_gl"));
        let differing = ours
            .pixels()
            .zip(theirs.pixels())
            .filter(|(p, q)| p.0.iter().zip(q.0).any(|(x, y)| x.abs_diff(y) > 2))
            .count();
        assert!(
            differing <= 8,
            "{what}: {differing} pixels differ from Mesa's; image {}",
            a.display()
        );
        // The quadrant that shows top left: red from the upper left, blue from the lower left.
        let top_left = ours.get_pixel(SIZE / 2 - 12, SIZE / 2 - 12).0;
        let want = match origin {
            SpriteOrigin::UpperLeft => [255, 0, 0, 255],
            _ => [0, 0, 255, 255],
        };
        assert_eq!(top_left, want, "{what}");
        assert_eq!(width_at(&ours, Vec2::ZERO), Some(32), "{what}: the whole sprite");
    }
    finish(r);
}

/// GL's own distance is the eye distance |(x_e, y_e, z_e)|; Mesa takes |z_e| (its deviation,
/// pinned): a point at eye (3, 0, -4) of size 40 with attenuation (0, 0, 1) is 40 / 5 = 8
/// pixels wide in ffvk and 40 / 4 = 10 in Mesa's GL.
#[test]
fn the_attenuation_distance_is_the_eye_distance_where_mesa_takes_the_depth() {
    let mut r = renderer();
    let mut gl = GlState::new();
    gl.point_parameter(PointParam::DistanceAttenuation(Vec3::new(0.0, 0.0, 1.0)))
        .unwrap();
    let spot = Spot {
        eye: Vec3::new(3.0, 0.0, -4.0),
        at: Vec2::new(-1.6, 0.0),
        size: 40.0,
    };
    // Where the point lands: its projection, moved.
    let clip = projection(spot.at) * spot.eye.extend(1.0);
    let at = Vec2::new(clip.x / clip.w, clip.y / clip.w);
    let (ours, theirs) = draw_both(&mut r, &[spot], &gl, None);
    assert_eq!((width_at(&ours, at), width_at(&theirs, at)), (Some(8), Some(10)));
    finish(r);
}

/// Scene files take `[points]` with GL's names and defaults, and `coord_replace` on a texture;
/// bad values are refused naming the field.
#[test]
fn scene_files_take_the_points_and_refuse_bad_values_naming_the_field() {
    use ffvk::scene::Scene;
    use std::path::Path;
    let text = "[points]\nsize = 12.0\nsize_min = 2.0\nsize_max = 20.0\n\
                distance_attenuation = [0.0, 0.5, 0.25]\nfade_threshold_size = 3.0\nsprite = true\n\
                sprite_coord_origin = \"lower_left\"\n\
                [[meshes]]\nbuiltin = \"sphere\"\nprimitive = \"points\"\n\
                texture = { builtin = \"disc\", coord_replace = true }\n";
    let s = Scene::parse(text, Path::new("points.toml")).unwrap();
    assert_eq!(s.point_size, 12.0);
    let p = s.state.points;
    assert_eq!((p.size_min, p.size_max, p.fade_threshold), (2.0, 20.0, 3.0));
    assert_eq!(p.distance_attenuation, Vec3::new(0.0, 0.5, 0.25));
    assert!(p.sprite);
    assert_eq!(p.sprite_origin, SpriteOrigin::LowerLeft);
    let texture = s.meshes[0].texture().expect("a texture");
    assert!(texture.unit.coord_replace);
    // GL's defaults where left out.
    let s = Scene::parse(
        "[points]\n[[meshes]]\nbuiltin = \"sphere\"\n",
        Path::new("d.toml"),
    )
    .unwrap();
    assert_eq!((s.point_size, s.state.points), (1.0, PointParameters::default()));
    for (bad, field) in [
        ("[points]\nsize = 0.0", "points.size"),
        ("[points]\nsize_min = -1.0", "points.size_min"),
        ("[points]\nsize_max = -2.0", "points.size_max"),
        (
            "[points]\nfade_threshold_size = -0.5",
            "points.fade_threshold_size",
        ),
        (
            "[points]\nsprite_coord_origin = \"middle\"",
            "points.sprite_coord_origin",
        ),
        ("[points]\nsprite = 3", "sprite"),
    ] {
        let text = format!("{bad}\n[[meshes]]\nbuiltin = \"sphere\"\n");
        let e = Scene::parse(&text, Path::new("bad.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains(field), "{bad:?}: {e}");
    }
}
