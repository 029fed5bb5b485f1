//! The `[texture]` table of a scene file (and a mesh's own `texture`): GL_TEXTURE_2D with a
//! texture image from a PNG or JPEG file or a built-in pattern, glTexParameter's filters and
//! wraps, GL_GENERATE_MIPMAP, glTexEnv, glTexGen and the GL_TEXTURE matrix.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Arc;

use glam::{Mat4, Quat, Vec3, Vec4};

use super::file::{TexCoordGenSpec, TextureSpec};
use super::{shorten, Builder, SceneError};
use crate::gl::state::{Cap, GlState};
use crate::gl::texture::{
    MagFilter, MinFilter, Sampling, TexCoordGen, TexEnvMode, TexGenMode, TextureImage, TextureUnit, Wrap,
    MAX_TEXTURE_SIZE,
};

/// The largest image file read for a texture, in bytes.
const MAX_IMAGE_BYTES: u64 = 256 << 20;

/// The keys of a `texgen` table, S to Q (glTexGen's coordinates 0 to 3).
const COORDS: [&str; 4] = ["s", "t", "r", "q"];

/// A texture a mesh is drawn with: the image (shared between the meshes that name the same
/// one), GL's texture parameters and the texture unit's state.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct MeshTexture {
    /// The texture image, all its levels.
    pub image: Arc<TextureImage>,
    /// glTexParameter's filters and wraps.
    pub sampling: Sampling,
    /// GL_TEXTURE_2D, glTexEnv and the texture matrix for this mesh's draw.
    pub unit: TextureUnit,
    /// Where the image came from, for messages: a file, a built-in pattern, a glTF image.
    pub source: String,
}

impl MeshTexture {
    /// Whether drawing with it textures anything (enabled, and complete for its min filter).
    pub fn applies(&self) -> bool {
        crate::gl::texture::texturing_applies(&self.unit, Some((&self.image, &self.sampling)))
    }
}

/// A word of `valid`, or an error naming the field, the value and the choices.
fn word<T: Copy>(
    b: &Builder,
    field: &str,
    value: &str,
    valid: &[(&'static str, T)],
) -> Result<T, SceneError> {
    valid
        .iter()
        .find(|(name, _)| *name == value)
        .map(|&(_, v)| v)
        .ok_or_else(|| {
            let names: Vec<String> = valid.iter().map(|(n, _)| format!("{n:?}")).collect();
            b.field(
                field,
                format!("{:?}: expected one of {}", shorten(value), names.join(", ")),
            )
        })
}

impl Builder<'_> {
    /// The texture a `texture` table at `field` describes, or `None` when it is disabled;
    /// `warnings` gets a sentence when the texture is incomplete (it then textures nothing,
    /// as in GL). `view` is the camera's, which takes `texgen`'s eye planes to eye space.
    pub(super) fn texture(
        &self,
        field: &str,
        spec: &TextureSpec,
        view: Mat4,
        warnings: &mut Vec<String>,
    ) -> Result<Option<MeshTexture>, SceneError> {
        let f = |name: &str| format!("{field}.{name}");
        let (image, source) = match (&spec.image, &spec.builtin) {
            (Some(_), Some(_)) => {
                return Err(self.field(
                    f("image"),
                    "given with builtin: expected either an image file or a builtin",
                ))
            }
            (Some(path), None) => (self.texture_file(&f("image"), path)?, path.display().to_string()),
            (None, Some(name)) => {
                let builtins = [("checker", 0), ("leaves", 1), ("disc", 2)];
                let image = match word(self, &f("builtin"), name, &builtins)? {
                    0 => TextureImage::checker(64, 8, [235, 235, 235, 255], [40, 90, 160, 255]),
                    1 => TextureImage::leaves(64),
                    _ => TextureImage::disc(32),
                }
                .map_err(|e| self.field(f("builtin"), e.to_string()))?;
                (image, format!("builtin {name}"))
            }
            (None, None) => return Err(self.field(
                field,
                "no image: expected image = \"file.png\" or builtin = \"checker\", \"leaves\" or \"disc\"",
            )),
        };
        let mut image = image;
        image.srgb = spec.srgb.unwrap_or(false);
        if spec.generate_mipmap.unwrap_or(false) {
            image = image.with_mipmaps();
        }
        // The words are the enums' own names, so the file format and messages cannot drift.
        let wrap: Vec<(&'static str, Wrap)> = Wrap::ALL.iter().map(|&w| (w.name(), w)).collect();
        let min: Vec<(&'static str, MinFilter)> = MinFilter::ALL.iter().map(|&m| (m.name(), m)).collect();
        let mag = [("nearest", MagFilter::Nearest), ("linear", MagFilter::Linear)];
        let defaults = Sampling::default();
        let sampling = Sampling {
            min_filter: spec
                .min_filter
                .as_deref()
                .map_or(Ok(defaults.min_filter), |v| word(self, &f("min_filter"), v, &min))?,
            mag_filter: spec
                .mag_filter
                .as_deref()
                .map_or(Ok(defaults.mag_filter), |v| word(self, &f("mag_filter"), v, &mag))?,
            wrap_s: spec
                .wrap_s
                .as_deref()
                .map_or(Ok(defaults.wrap_s), |v| word(self, &f("wrap_s"), v, &wrap))?,
            wrap_t: spec
                .wrap_t
                .as_deref()
                .map_or(Ok(defaults.wrap_t), |v| word(self, &f("wrap_t"), v, &wrap))?,
        };
        let modes: Vec<(&'static str, TexEnvMode)> = TexEnvMode::ALL.iter().map(|&m| (m.name(), m)).collect();
        let unit = TextureUnit {
            enabled: spec.enabled.unwrap_or(true),
            cube_map: false,
            // Scene files have no GL_COMBINE yet: GL's initial combine state.
            combine: TextureUnit::default().combine,
            env_mode: spec
                .env
                .as_deref()
                .map_or(Ok(TexEnvMode::Modulate), |v| word(self, &f("env"), v, &modes))?,
            env_color: match &spec.env_color {
                Some(c) => self.color(&f("env_color"), c)?,
                None => Vec4::ZERO,
            },
            matrix: self.texture_matrix(field, spec)?,
            coord_replace: spec.coord_replace.unwrap_or(false),
            texgen: match &spec.texgen {
                Some(coords) => self.texgen(&f("texgen"), coords, view)?,
                None => TextureUnit::default().texgen,
            },
        };
        unit.validate().map_err(self.state(field))?;
        if !unit.enabled {
            return Ok(None);
        }
        let texture = MeshTexture {
            image: Arc::new(image),
            sampling,
            unit,
            source,
        };
        if !texture.applies() {
            warnings.push(format!(
                "{field}: min_filter {:?} reads mipmaps and generate_mipmap is off, so the texture is incomplete and textures nothing, as in GL: expected generate_mipmap = true or min_filter = \"linear\" or \"nearest\"",
                sampling.min_filter.name()
            ));
        }
        Ok(Some(texture))
    }

    /// The `texgen` table at `field`, set as a GL program's glTexGen calls would set it: each
    /// coordinate given generated (GL_TEXTURE_GEN_S .. on unless `enabled = false`) in its
    /// `mode`, GL's `eye_linear` by default, from its `plane`, GL's initial plane by default;
    /// an eye plane is given in world space and set with the view loaded, as
    /// glTexGen(GL_EYE_PLANE) after glLoadMatrix(view), so it is stored as p · view⁻¹.
    fn texgen(
        &self,
        field: &str,
        coords: &BTreeMap<String, TexCoordGenSpec>,
        view: Mat4,
    ) -> Result<[TexCoordGen; 4], SceneError> {
        if let Some(key) = coords.keys().find(|k| !COORDS.contains(&k.as_str())) {
            return Err(self.field(
                format!("{field}.{}", shorten(key)),
                "is not a texture coordinate: expected s, t, r or q (GL_S, GL_T, GL_R, GL_Q)",
            ));
        }
        let mut gl = GlState::new();
        gl.load_modelview(view).map_err(self.state("camera.view"))?;
        for (coord, name) in COORDS.into_iter().enumerate() {
            let Some(spec) = coords.get(name) else {
                continue;
            };
            let f = |part: &str| format!("{field}.{name}.{part}");
            let mode = match &spec.mode {
                Some(w) => self.texgen_mode(&f("mode"), coord, w)?,
                None => TexGenMode::EyeLinear,
            };
            gl.tex_gen_mode(coord, mode).map_err(self.state(f("mode")))?;
            if let Some(p) = &spec.plane {
                let &[a, b, c, d] = p.as_slice() else {
                    return Err(self.field(
                        f("plane"),
                        format!(
                            "{} values: expected exactly 4 (the plane's p1, p2, p3, p4)",
                            p.len()
                        ),
                    ));
                };
                if let Some(x) = p.iter().find(|x| !x.is_finite()) {
                    return Err(self.field(f("plane"), format!("{x} is not finite: expected finite numbers")));
                }
                let plane = glam::DVec4::new(a, b, c, d);
                match mode {
                    TexGenMode::ObjectLinear => gl.tex_gen_object_plane(coord, plane),
                    TexGenMode::EyeLinear => gl.tex_gen_eye_plane(coord, plane),
                    _ => {
                        return Err(self.field(
                            f("plane"),
                            format!(
                                "is given with mode {:?}, which reads no plane: expected a plane with \
                                 \"object_linear\" or \"eye_linear\" only",
                                mode.name()
                            ),
                        ))
                    }
                }
                .map_err(self.state(f("plane")))?;
            }
            gl.set_enabled(Cap::TextureGen(coord), spec.enabled.unwrap_or(true))
                .map_err(self.state(f("enabled")))?;
        }
        Ok(gl.lighting.texture_units[0].texgen)
    }

    /// A `texgen` coordinate's `mode` word for coordinate `coord` (0 S .. 3 Q): one of the
    /// modes GL accepts for it, a mode of the others refused saying which coordinates take it
    /// (GL's `GL_INVALID_ENUM`).
    fn texgen_mode(&self, field: &str, coord: usize, given: &str) -> Result<TexGenMode, SceneError> {
        let modes: Vec<(&'static str, TexGenMode)> = TexGenMode::ALL
            .iter()
            .filter(|m| m.allowed_for(coord))
            .map(|&m| (m.name(), m))
            .collect();
        let Some(&other) = TexGenMode::ALL
            .iter()
            .find(|m| m.name() == given && !m.allowed_for(coord))
        else {
            return word(self, field, given, &modes);
        };
        let names: Vec<String> = modes.iter().map(|(n, _)| format!("{n:?}")).collect();
        let takes = if other == TexGenMode::SphereMap {
            "S and T"
        } else {
            "S, T and R"
        };
        Err(self.field(
            field,
            format!(
                "{given:?} for {}: expected one of {} ({} generates {takes} only: GL_INVALID_ENUM)",
                COORDS[coord],
                names.join(", "),
                other.gl_name()
            ),
        ))
    }

    fn texture_matrix(&self, field: &str, spec: &TextureSpec) -> Result<Mat4, SceneError> {
        let f = |name: &str| format!("{field}.{name}");
        if let Some(m) = spec.matrix {
            if spec.scale.is_some() || spec.rotate.is_some() || spec.translate.is_some() {
                return Err(self.field(
                    f("matrix"),
                    "given with scale/rotate/translate: expected either a matrix or those",
                ));
            }
            self.finite(&f("matrix"), &m)?;
            return Ok(Mat4::from_cols_array(&m));
        }
        let s = spec.scale.unwrap_or([1.0, 1.0]);
        let r = spec.rotate.unwrap_or(0.0);
        let t = spec.translate.unwrap_or([0.0, 0.0]);
        self.finite(&f("scale"), &s)?;
        self.finite(&f("rotate"), &[r])?;
        self.finite(&f("translate"), &t)?;
        Ok(Mat4::from_translation(Vec3::new(t[0], t[1], 0.0))
            * Mat4::from_quat(Quat::from_rotation_z(r.to_radians()))
            * Mat4::from_scale(Vec3::new(s[0], s[1], 1.0)))
    }

    /// A PNG or JPEG file as an RGBA8 texture, rows as stored (the file's first row at t = 0).
    fn texture_file(&self, field: &str, path: &Path) -> Result<TextureImage, SceneError> {
        let full = self.path.parent().unwrap_or(Path::new("")).join(path);
        let bytes = crate::files::read_regular(&full, MAX_IMAGE_BYTES)
            .map_err(|e| self.field(field, format!("cannot read {}: {e}", full.display())))?;
        let reader = || {
            image::ImageReader::new(std::io::Cursor::new(&bytes[..]))
                .with_guessed_format()
                .map_err(|e| self.field(field, format!("{}: {e}", full.display())))
        };
        // The size first, from the header: a huge image is refused before it is decoded.
        let (width, height) = reader()?.into_dimensions().map_err(|e| {
            self.field(
                field,
                format!("{}: cannot decode (ffvk reads PNG and JPEG): {e}", full.display()),
            )
        })?;
        if width == 0 || height == 0 || width > MAX_TEXTURE_SIZE || height > MAX_TEXTURE_SIZE {
            return Err(self.field(
                field,
                format!(
                    "{}: {width}x{height} texels: expected each side in 1..={MAX_TEXTURE_SIZE}",
                    full.display()
                ),
            ));
        }
        let decoded = reader()?
            .decode()
            .map_err(|e| {
                self.field(
                    field,
                    format!("{}: cannot decode (ffvk reads PNG and JPEG): {e}", full.display()),
                )
            })?
            .into_rgba8();
        let (w, h) = decoded.dimensions();
        TextureImage::new(w, h, decoded.into_raw())
            .map_err(|e| self.field(field, format!("{}: {e}", full.display())))
    }
}
