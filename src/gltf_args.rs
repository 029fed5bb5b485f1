//! The options of `ffvk render`, `explain` and `scene` for a glTF file drawn without a scene
//! file: which camera (a framing one from a chosen direction, or the file's), which lights,
//! which exposure, which background.

use std::path::PathBuf;

use ffvk::scene::direct::{is_gltf, CameraChoice, DirectOptions, LightChoice, Orbit};
use ffvk::scene::gltf::GltfLights;

/// How a glTF file given without a scene file is drawn.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct GltfArgs {
    /// glTF files only: "frame" (the default: a camera framing the scene's bounds, as glTF
    /// viewers open a file), "file" (the file's first camera, else framing), or one of the
    /// file's cameras by NAME or INDEX.
    #[arg(long, value_name = "frame|file|NAME|INDEX", allow_hyphen_values = true)]
    pub camera: Option<String>,
    /// glTF files only: the framing camera's direction about the vertical axis, in degrees
    /// from the model's front (glTF's +Z), positive toward its left side (+X); default: about
    /// 24.
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true, value_parser = parse_azimuth)]
    pub azimuth: Option<f32>,
    /// glTF files only: the framing camera's height, in degrees above the horizontal from
    /// -90 (below) to 90 (above); default: about 18.
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true)]
    pub elevation: Option<f32>,
    /// glTF files only: how much nearer than the fit (the bounds inside 90 % of the image)
    /// the framing camera comes: 2 is twice as near, 0.5 twice as far; default 1.
    #[arg(long, allow_negative_numbers = true, value_parser = parse_zoom)]
    pub zoom: Option<f32>,
    /// glTF files only: the background, as R,G,B or R,G,B,A from 0 to 1, or #RRGGBB;
    /// default: 0.2 grey.
    #[arg(long, value_name = "COLOR", value_parser = parse_color, allow_hyphen_values = true)]
    pub background: Option<[f32; 4]>,
    /// glTF files only: "file" (its KHR_lights_punctual lights), "headlight" (one white light
    /// from the camera) or "auto" (the file's, else the headlight; the default).
    #[arg(long, value_parser = ["auto", "file", "headlight"])]
    pub lights: Option<String>,
    /// glTF files only: how the file's lights are drawn: "gl" (GL's light for each, the
    /// default), "exact" (glTF's inverse-square falloff with its range, and its smooth cone)
    /// or "off" (left out); "true" and "false" are "gl" and "off".
    #[arg(long, value_name = "off|gl|exact", value_parser = parse_gltf_lights)]
    pub gltf_lights: Option<GltfLights>,
    /// glTF files only: GL light color per lux or candela, or "auto" (the default: the scale
    /// at which the file's lights together light the center of the scene's bounds with
    /// illuminance 0.75, where 1 is a white light falling head-on; the scale is printed).
    #[arg(long, value_parser = parse_exposure, allow_negative_numbers = true)]
    pub exposure: Option<Exposure>,
}

/// `--exposure`.
#[derive(Debug, Clone, Copy)]
pub enum Exposure {
    /// "auto".
    Auto,
    /// GL light color per lux or candela.
    Scale(f32),
}

fn parse_gltf_lights(s: &str) -> Result<GltfLights, String> {
    s.parse::<GltfLights>()
        .map_err(|_| format!("{s:?}: expected \"off\", \"gl\" or \"exact\" (or true/false)"))
}

fn parse_exposure(s: &str) -> Result<Exposure, String> {
    if s == "auto" {
        return Ok(Exposure::Auto);
    }
    match s.parse::<f32>() {
        Ok(x) if x > 0.0 && x.is_finite() => Ok(Exposure::Scale(x)),
        _ => Err(format!("{s:?}: expected \"auto\" or a number > 0")),
    }
}

/// `R,G,B`, `R,G,B,A` (0 to 1) or `#RRGGBB`.
fn parse_color(s: &str) -> Result<[f32; 4], String> {
    let expected = || format!("{s:?}: expected R,G,B or R,G,B,A from 0 to 1, or #RRGGBB");
    if let Some(hex) = s.strip_prefix('#') {
        if hex.len() != 6 || !hex.is_ascii() {
            return Err(expected());
        }
        let byte = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).map_err(|_| expected());
        return Ok([
            f32::from(byte(0)?) / 255.0,
            f32::from(byte(2)?) / 255.0,
            f32::from(byte(4)?) / 255.0,
            1.0,
        ]);
    }
    let parts: Vec<f32> = s
        .split(',')
        .map(|p| p.trim().parse::<f32>().map_err(|_| expected()))
        .collect::<Result<_, _>>()?;
    if !parts.iter().all(|x| (0.0..=1.0).contains(x)) {
        return Err(expected());
    }
    match parts.as_slice() {
        [r, g, b] => Ok([*r, *g, *b, 1.0]),
        [r, g, b, a] => Ok([*r, *g, *b, *a]),
        _ => Err(expected()),
    }
}

impl GltfArgs {
    fn given(&self) -> bool {
        self.camera.is_some()
            || self.lights.is_some()
            || self.gltf_lights.is_some()
            || self.exposure.is_some()
            || self.moves_framing()
            || self.background.is_some()
    }

    fn moves_framing(&self) -> bool {
        self.azimuth.is_some() || self.elevation.is_some() || self.zoom.is_some()
    }

    /// The options these flags ask for.
    pub fn options(&self) -> DirectOptions {
        let mut options = DirectOptions::default();
        options.camera = match self.camera.as_deref() {
            None | Some("frame") => CameraChoice::Frame,
            Some("file") => CameraChoice::FirstInFile,
            Some(name) => CameraChoice::File(name.to_owned()),
        };
        options.orbit = Orbit::default()
            .with_azimuth(self.azimuth)
            .with_elevation(self.elevation)
            .with_zoom(self.zoom);
        options.background = self.background;
        options.lights = match self.lights.as_deref() {
            Some("file") => LightChoice::File,
            Some("headlight") => LightChoice::Headlight,
            _ => LightChoice::Auto,
        };
        options.gltf_lights = self.gltf_lights.unwrap_or_default();
        options.exposure = match self.exposure {
            Some(Exposure::Scale(x)) => Some(x),
            _ => None,
        };
        options
    }

    /// Refuses the flags for inputs none of which is a glTF file (a scene file sets its
    /// own), and a framing direction or zoom with a camera of the file.
    pub fn check(&self, inputs: &[PathBuf]) -> crate::Result<()> {
        let first = || inputs.first().cloned().unwrap_or_default();
        if self.given() && !inputs.iter().any(|p| is_gltf(p)) {
            return Err(crate::Error::Path {
                path: first(),
                problem: "--camera, --azimuth, --elevation, --zoom, --background, --lights, --gltf-lights and \
                          --exposure apply to .gltf and .glb inputs: expected one, or the camera, clear_color, \
                          lights, gltf_lights and gltf_exposure set in the scene file",
            });
        }
        if self.moves_framing() && !matches!(self.camera.as_deref(), None | Some("frame")) {
            return Err(crate::Error::Path {
                path: first(),
                problem:
                    "--azimuth, --elevation and --zoom move the framing camera: expected --camera frame \
                          (the default), not one of the file's cameras",
            });
        }
        if let Err(problem) = self.options().orbit.check() {
            return Err(crate::Error::Argument(format!("--{problem}")));
        }
        Ok(())
    }
}

/// `--azimuth`: degrees, a finite number from -360 to 360 (past that a float32 angle loses the
/// precision the framing needs, and every direction is already reached).
fn parse_azimuth(s: &str) -> Result<f32, String> {
    match s.trim().parse::<f64>() {
        Ok(x) if (-360.0..=360.0).contains(&x) => Ok(x as f32),
        _ => Err(format!("{s:?}: expected degrees from -360 to 360")),
    }
}

/// `--zoom`: a number > 0 that a float32 holds as such (1e-300 would become 0).
fn parse_zoom(s: &str) -> Result<f32, String> {
    match s.trim().parse::<f64>() {
        Ok(x) if x > 0.0 && (x as f32).is_normal() => Ok(x as f32),
        _ => Err(format!(
            "{s:?}: expected a number > 0 within float32's range ({:e} to {:e})",
            f32::MIN_POSITIVE,
            f32::MAX
        )),
    }
}
