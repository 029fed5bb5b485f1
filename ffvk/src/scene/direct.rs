//! A glTF file drawn without a scene file: the scene ffvk makes for it (a camera framing its
//! bounds from a chosen direction, or one of the file's cameras; its punctual lights or a
//! headlight; glTF's meaning; a background color), written as scene TOML so that `ffvk scene
//! FILE` prints exactly what `ffvk render FILE` draws.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use glam::{Mat4, Vec3};

use super::gltf::{CameraProjection, GltfLights, LoadError, Loaded, PlacedCamera, Textures};
use super::meaning::world_bounds;
use super::{shorten, Limits, MeshBudget, Scene, SceneError, SceneErrorKind, MAX_SIZE};

/// Which camera a glTF file is drawn from.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum CameraChoice {
    /// A camera framing the scene's bounds ([`DirectOptions::orbit`]), whatever the file
    /// holds: what glTF viewers show first (the file's cameras are offered on request).
    #[default]
    Frame,
    /// The file's first camera (in node order), else [`CameraChoice::Frame`].
    FirstInFile,
    /// The file's camera with this name, or this index in `cameras`.
    File(String),
}

/// Which lights a glTF file is drawn with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum LightChoice {
    /// The file's KHR_lights_punctual lights, else [`LightChoice::Headlight`].
    #[default]
    Auto,
    /// The file's lights only (none: only emission and ambient light show).
    File,
    /// One white directional light shining from the camera, the file's lights left out.
    Headlight,
}

/// How a glTF file drawn directly is set up; `Default` is what `ffvk render FILE.glb` does.
#[derive(Debug, Clone, PartialEq, Default)]
#[non_exhaustive]
pub struct DirectOptions {
    /// The camera the file is drawn from (`ffvk --camera`).
    pub camera: CameraChoice,
    /// The lights it is drawn with (`ffvk --lights`).
    pub lights: LightChoice,
    /// How the file's lights are drawn when they are: GL's mapping (the default) or glTF's
    /// own falloff and cones. [`GltfLights::Off`] leaves them out, as
    /// [`LightChoice::Headlight`] does.
    pub gltf_lights: GltfLights,
    /// GL light color per lux or candela; `None` is "auto" (see
    /// [`auto_exposure`](super::auto_exposure)).
    pub exposure: Option<f32>,
    /// The image size; `None`: 512 × 512, or 512 high with the camera's aspect ratio.
    pub size: Option<(u32, u32)>,
    /// Where the framing camera looks from and how near it comes.
    pub orbit: Orbit,
    /// The background (the clear color), RGBA; `None`: 0.2 grey, opaque.
    pub background: Option<[f32; 4]>,
}

/// The framing camera's place: a direction from the bounds' center and a zoom.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[non_exhaustive]
pub struct Orbit {
    /// Degrees about +Y from glTF's front (+Z), positive toward +X (the model turns to show
    /// its left side); `None`: the default direction's, front, right and above (about 24.2°,
    /// with an elevation of about 17.7°).
    pub azimuth: Option<f32>,
    /// Degrees above the horizontal plane, from −90 (below) to 90 (above).
    pub elevation: Option<f32>,
    /// How much nearer than the fit (all eight corners of the bounds inside 90 % of the
    /// image) the camera comes: 2 halves the distance; `None` is 1.
    pub zoom: Option<f32>,
}

with_fields!(Orbit {
    /// Sets [`azimuth`](Orbit::azimuth).
    with_azimuth => azimuth: Option<f32>,
    /// Sets [`elevation`](Orbit::elevation).
    with_elevation => elevation: Option<f32>,
    /// Sets [`zoom`](Orbit::zoom).
    with_zoom => zoom: Option<f32>,
});

impl Orbit {
    /// Whether anything differs from the default framing.
    pub fn is_default(&self) -> bool {
        *self == Orbit::default()
    }

    /// Azimuth and elevation in degrees, the defaults' where not given.
    pub fn degrees(&self) -> (f32, f32) {
        let default = FRAME_FROM.normalize();
        (
            self.azimuth.unwrap_or(default.x.atan2(default.z).to_degrees()),
            self.elevation.unwrap_or(default.y.asin().to_degrees()),
        )
    }

    /// The unit direction from the bounds' center to the camera.
    fn direction(&self) -> Vec3 {
        if self.azimuth.is_none() && self.elevation.is_none() {
            // Exactly the direction references were drawn from before the angles existed.
            return FRAME_FROM.normalize();
        }
        let (a, e) = self.degrees();
        let (a, e) = (a.to_radians(), e.to_radians());
        Vec3::new(e.cos() * a.sin(), e.sin(), e.cos() * a.cos())
    }

    /// Checks the values: a problem names the option, its value and what was expected.
    pub fn check(&self) -> Result<(), String> {
        if let Some(a) = self.azimuth.filter(|a| !a.is_finite()) {
            return Err(format!("azimuth {a}: expected a finite number of degrees"));
        }
        if let Some(e) = self.elevation.filter(|e| !(-90.0..=90.0).contains(e)) {
            return Err(format!("elevation {e}: expected degrees from -90 to 90"));
        }
        if let Some(z) = self.zoom.filter(|z| !(z.is_finite() && *z > 0.0)) {
            return Err(format!("zoom {z}: expected a number > 0"));
        }
        Ok(())
    }
}

with_fields!(DirectOptions {
    /// Sets [`camera`](DirectOptions::camera).
    with_camera => camera: CameraChoice,
    /// Sets [`lights`](DirectOptions::lights).
    with_lights => lights: LightChoice,
    /// Sets [`gltf_lights`](DirectOptions::gltf_lights).
    with_gltf_lights => gltf_lights: GltfLights,
    /// Sets [`exposure`](DirectOptions::exposure).
    with_exposure => exposure: Option<f32>,
    /// Sets [`size`](DirectOptions::size).
    with_size => size: Option<(u32, u32)>,
    /// Sets [`orbit`](DirectOptions::orbit).
    with_orbit => orbit: Orbit,
    /// Sets [`background`](DirectOptions::background).
    with_background => background: Option<[f32; 4]>,
});

/// The scene made for a glTF file, the TOML that makes it, and what was chosen.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct DirectScene {
    /// The scene [`toml`](DirectScene::toml) makes, ready to draw; its notes start with
    /// [`choices`](DirectScene::choices).
    pub scene: Scene,
    /// Scene TOML naming the glTF file as `gltf_ref` (see [`from_gltf`]).
    pub toml: String,
    /// One line per choice (camera, lights, glTF's meaning), for the user to see.
    pub choices: Vec<String>,
}

/// The side of the image made for a camera without an aspect ratio.
const SIDE: u32 = 512;
/// The vertical field of view of the framing camera, in degrees.
const FRAME_FOVY: f32 = 45.0;
/// The direction the framing camera looks from, seen from the scene's center: glTF's front
/// (+Z), raised and turned to the right a little, so that both the front and the top show.
const FRAME_FROM: Vec3 = Vec3::new(0.45, 0.35, 1.0);

/// The scene for the glTF file at `path` (see the module docs); the TOML names the file as
/// `gltf_ref`, which must lead to it from wherever the TOML is to be kept.
pub fn from_gltf(
    path: &Path,
    gltf_ref: &str,
    limits: &Limits,
    options: &DirectOptions,
) -> Result<DirectScene, SceneError> {
    let error = |kind| SceneError {
        path: path.to_path_buf(),
        kind,
    };
    let field = |field: &str, message: String| {
        error(SceneErrorKind::Field {
            field: field.to_owned(),
            message,
        })
    };
    let mut budget = MeshBudget::new(limits.mesh_bytes);
    let loaded =
        super::gltf::load_with(path, limits, &mut budget, Textures::Means).map_err(|e: LoadError| {
            error(SceneErrorKind::Gltf {
                field: "gltf".to_owned(),
                source: Box::new(e),
            })
        })?;
    let (lo, hi) = world_bounds(loaded.meshes.iter().map(|m| (&m.data, m.transform))).ok_or_else(|| {
        field(
            "meshes",
            "no meshes in the file's scene: expected something to draw".into(),
        )
    })?;
    let (center, radius) = ((lo + hi) / 2.0, ((hi - lo).length() / 2.0).max(1e-6));

    options.orbit.check().map_err(|m| field("--camera", m))?;
    if let Some(c) = options
        .background
        .filter(|c| !c.iter().all(|x| (0.0..=1.0).contains(x)))
    {
        return Err(field(
            "--background",
            format!("{c:?}: expected red, green, blue and alpha from 0 to 1"),
        ));
    }
    let mut choices = Vec::new();
    let camera = match &options.camera {
        CameraChoice::Frame => None,
        CameraChoice::FirstInFile => loaded.cameras.first(),
        CameraChoice::File(want) => Some(find_camera(&loaded, want).map_err(|m| field("--camera", m))?),
    };
    let view = match camera {
        Some(c) => {
            let view = file_view(c, center, lo, hi, options.size);
            choices.push(format!(
                "camera: {:?} (camera {}) from the file{}",
                shorten(&c.name),
                c.index,
                match options.size {
                    Some(_) => String::new(),
                    None => format!(
                        ", the image {} × {} for its aspect ratio",
                        view.size.0, view.size.1
                    ),
                }
            ));
            view
        }
        None => {
            let from = match options.orbit.is_default() {
                true => "from the front, right and above".to_owned(),
                false => {
                    let (a, e) = options.orbit.degrees();
                    format!(
                        "from azimuth {a:.1}°, elevation {e:.1}°{}",
                        options
                            .orbit
                            .zoom
                            .map_or(String::new(), |z| format!(", zoom {z}"))
                    )
                }
            };
            let offered = match loaded.cameras.len() {
                0 => String::new(),
                n => format!(
                    "; the file has {n} camera{} (--camera file, or a name or index: {})",
                    if n == 1 { "" } else { "s" },
                    loaded
                        .cameras
                        .iter()
                        .map(|c| format!("{} {:?}", c.index, shorten(&c.name)))
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            };
            choices.push(format!(
                "camera: {}framing the scene's bounds (center {}, radius {}) {from}{offered}",
                match loaded.cameras.is_empty() {
                    // Cameras left out say so in a warning of their own.
                    true if loaded
                        .warnings
                        .iter()
                        .any(|w| w.contains("the camera is not used")) =>
                    {
                        "no usable one in the file; "
                    }
                    true => "none in the file; ",
                    false => "",
                },
                fmt3(center),
                radius
            ));
            frame_view(lo, hi, options.size, &options.orbit)
        }
    };

    let headlight = match (options.lights, options.gltf_lights) {
        (LightChoice::Headlight, _) => true,
        (LightChoice::File, _) => false,
        (LightChoice::Auto, GltfLights::Off) => true,
        (LightChoice::Auto, _) => loaded.lights.is_empty(),
    };
    let mapping = match (headlight, options.gltf_lights) {
        (true, _) => GltfLights::Off,
        (false, GltfLights::Off) => GltfLights::Off,
        (false, m) => m,
    };
    let exposure = match options.exposure {
        Some(x) => format!("{x:?}"),
        None => "\"auto\"".to_owned(),
    };
    choices.push(if headlight {
        format!(
            "lights: {}one headlight (white at 0.75, directional, from the camera)",
            if loaded.lights.is_empty() {
                "none in the file; "
            } else {
                "the file's left out; "
            }
        )
    } else if mapping == GltfLights::Off && !loaded.lights.is_empty() {
        "lights: the file's left out (gltf_lights \"off\"), and no headlight asked for: only emission and ambient light show"
            .to_owned()
    } else if loaded.lights.is_empty() {
        "lights: none in the file, and no headlight asked for: only emission and ambient light show"
            .to_owned()
    } else {
        format!(
            "lights: {} KHR_lights_punctual light{} from the file, gltf_lights = \"{}\", gltf_exposure = {exposure}",
            loaded.lights.len(),
            if loaded.lights.len() == 1 { "" } else { "s" },
            mapping.name()
        )
    });
    choices.push("glTF's meaning (gltf_defaults = true): see docs/scene-files.md, \"glTF files\"".to_owned());

    check_view(&view, lo, hi, options.orbit.zoom.filter(|_| camera.is_none()))
        .map_err(|m| field("camera", m))?;
    let background = options.background.unwrap_or([0.2, 0.2, 0.2, 1.0]);
    let lights = (headlight, mapping, options.exposure);
    let toml = |gltf_ref: &str| {
        scene_toml(
            path,
            gltf_ref,
            &view,
            background,
            (headlight, mapping, &exposure),
            &choices,
        )
    };
    let base = path.parent().unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .ok_or_else(|| field("gltf", format!("{}: expected a file name", path.display())))?;
    // The scene is built from the values themselves: the text is for the user to read (and
    // reads back as the same scene), never parsed here, so that no value depends on how it is
    // printed.
    let table = scene_table(&name, &view, background, lights);
    let mut scene = Scene::from_table_preloaded(table, path, limits, budget, base.join(&name), loaded)?;
    let mut notes = choices.clone();
    notes.append(&mut scene.notes);
    scene.notes = notes;
    Ok(DirectScene {
        scene,
        toml: toml(gltf_ref),
        choices,
    })
}

/// `true` for the paths [`from_gltf`] reads: `.gltf` and `.glb` files.
pub fn is_gltf(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("gltf") || e.eq_ignore_ascii_case("glb"))
}

/// A camera as scene TOML writes it: look-at, and a perspective or an explicit projection.
struct View {
    eye: Vec3,
    target: Vec3,
    up: Vec3,
    size: (u32, u32),
    projection: ViewProjection,
}

enum ViewProjection {
    Perspective {
        fovy: f32,
        near: f32,
        far: f32,
    },
    /// Column-major, for orthographic cameras.
    Matrix(Mat4),
}

fn find_camera<'a>(loaded: &'a Loaded, want: &str) -> Result<&'a PlacedCamera, String> {
    // An index first, so that a camera named "1" cannot shadow camera 1; then a name.
    let by_index = want.parse::<usize>().ok();
    let cameras = &loaded.cameras;
    by_index
        .and_then(|i| cameras.iter().find(|c| c.index == i))
        .or_else(|| cameras.iter().find(|c| c.name == want))
        .ok_or_else(|| {
            let have: Vec<String> = loaded
                .cameras
                .iter()
                .map(|c| format!("{} ({:?})", c.index, shorten(&c.name)))
                .collect();
            format!(
                "{:?} names no camera of the file's scene: expected {}",
                shorten(want),
                if have.is_empty() {
                    "\"frame\" (the file has no usable camera)".to_owned()
                } else {
                    format!("\"frame\" or one of {}", have.join(", "))
                }
            )
        })
}

/// The size for an aspect ratio (width / height): 512 high, or 512 wide when taller than wide;
/// where the longer side would pass [`MAX_SIZE`], that side is `MAX_SIZE` and the shorter one
/// follows the ratio (a ratio past `MAX_SIZE`:1 is refused with the camera, see
/// [`super::gltf`]'s cameras).
fn size_for(aspect: f32) -> (u32, u32) {
    let side = |x: f32| (x.round() as u32).clamp(1, MAX_SIZE);
    let (long, short) = (aspect.max(1.0 / aspect), SIDE as f32);
    let (long, short) = if short * long > MAX_SIZE as f32 {
        (MAX_SIZE as f32, MAX_SIZE as f32 / long)
    } else {
        (short * long, short)
    };
    if aspect >= 1.0 {
        (side(long), side(short))
    } else {
        (side(short), side(long))
    }
}

/// The file's camera: where its node puts it, its projection.
fn file_view(c: &PlacedCamera, center: Vec3, lo: Vec3, hi: Vec3, size: Option<(u32, u32)>) -> View {
    let (eye, forward, up) = (c.eye(), c.forward(), c.up());
    let target = eye
        + forward
            * (center - eye)
                .dot(forward)
                .max((hi - lo).length() * 0.01)
                .max(1e-6);
    // The farthest corner of the bounds, for a far plane where the file gives none.
    let farthest = corners(lo, hi)
        .map(|p| (p - eye).dot(forward))
        .into_iter()
        .fold(0.0f32, f32::max);
    match c.projection {
        CameraProjection::Perspective {
            yfov,
            aspect_ratio,
            znear,
            zfar,
        } => View {
            eye,
            target,
            up,
            size: size.unwrap_or_else(|| aspect_ratio.map_or((SIDE, SIDE), size_for)),
            projection: ViewProjection::Perspective {
                fovy: yfov.to_degrees(),
                near: znear,
                far: zfar.unwrap_or((farthest * 2.0).max(znear * 2.0)),
            },
        },
        CameraProjection::Orthographic {
            xmag,
            ymag,
            znear,
            zfar,
        } => {
            let size = size.unwrap_or_else(|| size_for((xmag / ymag).abs()));
            // glTF 2.0's orthographic matrix, for the image's own aspect ratio.
            let aspect = size.0 as f32 / size.1 as f32;
            let x = ymag.abs() * aspect;
            View {
                eye,
                target,
                up,
                size,
                projection: ViewProjection::Matrix(Mat4::orthographic_rh_gl(
                    -x,
                    x,
                    -ymag.abs(),
                    ymag.abs(),
                    znear,
                    zfar,
                )),
            }
        }
    }
}

fn corners(lo: Vec3, hi: Vec3) -> [Vec3; 8] {
    std::array::from_fn(|i| {
        Vec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        )
    })
}

/// A camera in `orbit`'s direction from the bounds' center, as near as it can be with all
/// eight corners of the bounds inside 90 % of the image's height and width, then `zoom`
/// times nearer.
fn frame_view(lo: Vec3, hi: Vec3, size: Option<(u32, u32)>, orbit: &Orbit) -> View {
    let size = size.unwrap_or((SIDE, SIDE));
    let center = (lo + hi) / 2.0;
    let back = orbit.direction();
    // Straight above or below, "up" on screen is toward the front (−Z seen from above).
    let view_up = if back.y.abs() > 0.9999 {
        Vec3::new(0.0, 0.0, -back.y.signum())
    } else {
        Vec3::Y
    };
    let right = view_up.cross(back).normalize();
    let up = back.cross(right);
    let tan_y = (FRAME_FOVY.to_radians() / 2.0).tan() * 0.9;
    let tan_x = tan_y * size.0 as f32 / size.1 as f32;
    // Distance along `back` from the center so that each corner fits: depth d − z must be at
    // least |x| / tan_x and |y| / tan_y.
    let mut distance = 0.0f32;
    let mut nearest = f32::INFINITY;
    let mut farthest = 0.0f32;
    let relative = corners(lo, hi).map(|p| p - center);
    for p in relative {
        let (x, y, z) = (p.dot(right), p.dot(up), p.dot(back));
        distance = distance.max(z + x.abs() / tan_x).max(z + y.abs() / tan_y);
    }
    let radius = ((hi - lo).length() / 2.0).max(1e-6);
    distance = distance.max(radius * 1e-3);
    if let Some(zoom) = orbit.zoom {
        distance /= zoom;
    }
    for p in relative {
        let depth = distance - p.dot(back);
        nearest = nearest.min(depth);
        farthest = farthest.max(depth);
    }
    View {
        eye: center + back * distance,
        target: center,
        up: view_up,
        size,
        projection: ViewProjection::Perspective {
            fovy: FRAME_FOVY,
            // Zoomed in, the camera may stand inside the bounds: the near plane stays in front.
            near: (nearest * 0.5)
                .max(distance * 1e-4)
                .max(distance * 1e-2 * f32::from(nearest <= 0.0)),
            far: farthest * 2.0,
        },
    }
}

/// A vector as TOML writes it: each number with Rust's `{:?}`, which keeps the exponent of
/// very large and very small numbers (`1e38`, not 39 digits TOML reads as an integer).
fn fmt3(v: Vec3) -> String {
    format!("[{:?}, {:?}, {:?}]", v.x, v.y, v.z)
}

/// Checks that float32 can hold the camera: its numbers, its view and projection matrices and
/// their inverses finite, and the eye apart from the target; bounds near float32's range (or
/// far from the origin for their size), or a zoom that puts the camera that far, do not allow
/// it. The error names the bounds, the camera's values and the zoom.
fn check_view(view: &View, lo: Vec3, hi: Vec3, zoom: Option<f32>) -> Result<(), String> {
    let aspect = view.size.0 as f32 / view.size.1.max(1) as f32;
    let projection = match &view.projection {
        ViewProjection::Perspective { fovy, near, far } => {
            Mat4::perspective_rh_gl(fovy.to_radians(), aspect, *near, *far)
        }
        ViewProjection::Matrix(m) => *m,
    };
    let matrices = [Mat4::look_at_rh(view.eye, view.target, view.up), projection];
    let finite = [view.eye, view.target, view.up].iter().all(|v| v.is_finite())
        && matrices.iter().all(|m| m.is_finite() && m.inverse().is_finite());
    if finite && view.eye != view.target {
        return Ok(());
    }
    Err(format!(
        "the scene's bounds {} to {}{} put the camera's eye at {} looking at {}{}: float32 cannot \
         hold that camera's matrices: expected bounds whose size and distance from the origin are \
         well below {:e}{}, or one of the file's cameras (--camera)",
        fmt3(lo),
        fmt3(hi),
        zoom.map_or(String::new(), |z| format!(" at zoom {z:?}")),
        fmt3(view.eye),
        fmt3(view.target),
        match &view.projection {
            ViewProjection::Perspective { near, far, .. } => format!(", near {near:?} and far {far:?}"),
            ViewProjection::Matrix(_) => String::new(),
        },
        f32::MAX,
        if zoom.is_some() { ", a zoom nearer 1" } else { "" },
    ))
}

/// The scene [`scene_toml`] writes, as TOML values: what the scene is built from.
fn scene_table(
    gltf_ref: &str,
    view: &View,
    background: [f32; 4],
    (headlight, mapping, exposure): (bool, GltfLights, Option<f32>),
) -> toml::Table {
    use toml::Value;
    let float = |x: f32| Value::Float(f64::from(x));
    let floats = |xs: &[f32]| Value::Array(xs.iter().copied().map(float).collect());
    let table = |entries: Vec<(&str, Value)>| {
        Value::Table(entries.into_iter().map(|(k, v)| (k.to_owned(), v)).collect())
    };
    let mut camera = vec![
        ("eye", floats(&view.eye.to_array())),
        ("target", floats(&view.target.to_array())),
        ("up", floats(&view.up.to_array())),
    ];
    match &view.projection {
        ViewProjection::Perspective { fovy, near, far } => {
            camera.extend([
                ("fovy", float(*fovy)),
                ("near", float(*near)),
                ("far", float(*far)),
            ]);
        }
        ViewProjection::Matrix(m) => camera.push(("projection", floats(&m.to_cols_array()))),
    }
    let mut scene = vec![
        ("gltf_defaults", Value::Boolean(true)),
        ("gltf_lights", Value::String(mapping.name().to_owned())),
        (
            "gltf_exposure",
            exposure.map_or(Value::String("auto".to_owned()), float),
        ),
        (
            "image",
            table(vec![
                (
                    "size",
                    Value::Array(vec![
                        Value::Integer(i64::from(view.size.0)),
                        Value::Integer(i64::from(view.size.1)),
                    ]),
                ),
                ("clear_color", floats(&background)),
            ]),
        ),
        ("camera", table(camera)),
        (
            "meshes",
            Value::Array(vec![table(vec![("gltf", Value::String(gltf_ref.to_owned()))])]),
        ),
    ];
    if headlight {
        let toward = (view.eye - view.target).normalize_or(Vec3::Z);
        let k = super::meaning::KEY_LIGHT;
        scene.push((
            "lights",
            Value::Array(vec![table(vec![
                ("position", floats(&[toward.x, toward.y, toward.z, 0.0])),
                ("diffuse", floats(&[k, k, k])),
                ("specular", floats(&[k, k, k])),
            ])]),
        ));
    }
    scene.into_iter().map(|(k, v)| (k.to_owned(), v)).collect()
}

/// The scene TOML for `view` and the lights chosen.
fn scene_toml(
    path: &Path,
    gltf_ref: &str,
    view: &View,
    background: [f32; 4],
    (headlight, mapping, exposure): (bool, GltfLights, &str),
    choices: &[String],
) -> String {
    let mut t = String::new();
    let _ = writeln!(t, "# The scene ffvk draws for {} (ffvk scene).", path.display());
    for c in choices {
        let _ = writeln!(t, "# {c}");
    }
    let _ = writeln!(
        t,
        "gltf_defaults = true   # glTF's meaning: see docs/scene-files.md, \"glTF files\""
    );
    let _ = writeln!(
        t,
        "gltf_lights = \"{}\"   # the file's lights: \"off\", \"gl\" (GL's light each) or \"exact\" (glTF's falloff and cones)",
        mapping.name()
    );
    let _ = writeln!(
        t,
        "gltf_exposure = {exposure}   # GL light color per lux or candela, or \"auto\""
    );
    let _ = writeln!(
        t,
        "\n[image]\nsize = [{}, {}]\nclear_color = [{:?}, {:?}, {:?}, {:?}]",
        view.size.0, view.size.1, background[0], background[1], background[2], background[3]
    );
    let _ = writeln!(
        t,
        "\n[camera]\neye = {}\ntarget = {}\nup = {}",
        fmt3(view.eye),
        fmt3(view.target),
        fmt3(view.up)
    );
    match &view.projection {
        ViewProjection::Perspective { fovy, near, far } => {
            let _ = writeln!(t, "fovy = {fovy:?}\nnear = {near:?}\nfar = {far:?}");
        }
        ViewProjection::Matrix(m) => {
            let cols: Vec<String> = m.to_cols_array().iter().map(|x| format!("{x:?}")).collect();
            let _ = writeln!(t, "projection = [{}]", cols.join(", "));
        }
    }
    if headlight {
        let toward = (view.eye - view.target).normalize_or(Vec3::Z);
        let _ = writeln!(
            t,
            "\n[[lights]]   # the headlight\nposition = [{:?}, {:?}, {:?}, 0.0]\ndiffuse = [{k:?}, {k:?}, {k:?}]\nspecular = [{k:?}, {k:?}, {k:?}]",
            toward.x,
            toward.y,
            toward.z,
            k = super::meaning::KEY_LIGHT
        );
    }
    let quoted = toml::Value::String(gltf_ref.to_owned()).to_string();
    let _ = writeln!(t, "\n[[meshes]]\ngltf = {quoted}");
    t
}

/// The path to write into a scene file at `scene_file` so that it leads to `gltf`: relative to
/// the scene file's folder where both are below one folder, else absolute.
pub fn relative_ref(gltf: &Path, scene_file: Option<&Path>) -> PathBuf {
    let Some(scene_file) = scene_file else {
        return gltf.to_path_buf();
    };
    let absolute = |p: &Path| std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf());
    let (target, from) = (
        absolute(gltf),
        absolute(scene_file.parent().unwrap_or(Path::new("."))),
    );
    let (t, f): (Vec<_>, Vec<_>) = (target.components().collect(), from.components().collect());
    let common = t.iter().zip(&f).take_while(|(a, b)| a == b).count();
    if common == 0 {
        return target;
    }
    let mut out = PathBuf::new();
    for _ in common..f.len() {
        out.push("..");
    }
    for c in &t[common..] {
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::size_for;

    /// 512 high (or wide) with the camera's ratio; where that passes 16384 pixels, the longer
    /// side is 16384 and the ratio kept (it was clamped to 16384 × 512: 32:1 for 40:1).
    #[test]
    fn an_image_for_an_aspect_ratio_keeps_the_ratio_within_16384_pixels() {
        assert_eq!(size_for(1.5), (768, 512));
        assert_eq!(size_for(0.5), (512, 1024));
        assert_eq!(size_for(40.0), (16384, 410));
        assert_eq!(size_for(1.0 / 40.0), (410, 16384));
        assert_eq!(size_for(16384.0), (16384, 1));
    }
}
