//! The `[texture]` table of a scene file (and a mesh's own `texture`, or each of its
//! `texture_units`): GL_TEXTURE_2D with a texture image from a PNG or JPEG file or a built-in
//! pattern and its base internal format, glTexParameter's filters and wraps, GL_GENERATE_MIPMAP,
//! glTexEnv (`GL_COMBINE`'s parameters in `combine.rs`), glTexGen, the GL_TEXTURE matrix and,
//! for units 1-3, where the unit's texture coordinates come from.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Arc;

use glam::{Mat4, Quat, Vec3, Vec4};

use super::file::{TexCoordGenSpec, TextureSpec};
use super::{shorten, Builder, SceneError};
use crate::gl::state::{Cap, GlState};
use crate::gl::texture::{
    BaseFormat, CubeImage, MagFilter, MinFilter, Sampling, TexCoordGen, TexEnvMode, TexGenMode, TextureImage,
    TextureUnit, Wrap, MAX_TEXTURE_SIZE, MAX_TEXTURE_UNITS,
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
    /// Where the unit's texture coordinates come from: unit 0's are the mesh's, units 1-3's
    /// the unit's current ones unless `coords = "mesh"` says otherwise.
    pub coords: TexCoords,
    /// Where the image came from, for messages: a file, a built-in pattern, a glTF image.
    pub source: String,
    /// The unit's GL_TEXTURE_CUBE_MAP texture (a `cube_map` table), sampled instead of
    /// `image` (`unit.cube_map` is on with it, GL's precedence); its sampling is `sampling`.
    /// A unit with a cube map and no image file or builtin has a 1x1 white `image`, never
    /// sampled.
    pub cube_map: Option<Arc<CubeImage>>,
    /// Where the cube map came from, for messages; empty without one.
    pub cube_source: String,
}

/// Where a texture unit's coordinates come from, before `texgen` replaces any it generates
/// (a unit's `coords` in a scene file).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum TexCoords {
    /// The mesh's texture coordinates: unit 0's always; units 1-3's with `coords = "mesh"` (as
    /// a GL program points `glClientActiveTexture(GL_TEXTUREi)`'s array at the same ones).
    Mesh,
    /// The unit's current texture coordinates (`glMultiTexCoord4f`), every vertex's: GL's
    /// (0, 0, 0, 1) for units 1-3 unless `coords` gives four numbers.
    Current(Vec4),
    /// The mesh's second set of texture coordinates
    /// ([`MeshData::second_texcoords`](crate::mesh::MeshData::second_texcoords), glTF's
    /// `TEXCOORD_1`), for units 1-3: a glTF occlusion texture read from `texCoord` 1.
    MeshSecond,
}

impl MeshTexture {
    /// Whether drawing with it textures anything (enabled, and complete for its min filter).
    pub fn applies(&self) -> bool {
        match &self.cube_map {
            // GL's precedence: the cube map, complete for the min filter, or nothing.
            Some(cube) => self.unit.enabled && self.sampling.is_complete(cube.has_mipmaps()),
            None => crate::gl::texture::texturing_applies(&self.unit, Some((&self.image, &self.sampling))),
        }
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
    /// A mesh's `texture_units` at `field`: one to [`MAX_TEXTURE_UNITS`] tables, `GL_TEXTURE0`
    /// first, each read as [`Builder::texture`] reads a `texture` table; a unit that is not
    /// `enabled` is `None`.
    pub(super) fn texture_units(
        &self,
        field: &str,
        specs: &[TextureSpec],
        view: Mat4,
        warnings: &mut Vec<String>,
    ) -> Result<[Option<MeshTexture>; MAX_TEXTURE_UNITS], SceneError> {
        if specs.is_empty() || specs.len() > MAX_TEXTURE_UNITS {
            return Err(self.field(
                field,
                format!(
                    "{} units: expected 1 to {MAX_TEXTURE_UNITS} (GL_TEXTURE0 first; GL_MAX_TEXTURE_UNITS is {MAX_TEXTURE_UNITS})",
                    specs.len()
                ),
            ));
        }
        let mut units: [Option<MeshTexture>; MAX_TEXTURE_UNITS] = Default::default();
        for (i, spec) in specs.iter().enumerate() {
            let at = format!("{field}[{i}]");
            units[i] = self.texture(&at, spec, (i, specs.len()), view, warnings)?;
        }
        Ok(units)
    }

    /// The texture a `texture` table at `field` describes for texture unit `index` of a mesh
    /// of `units` units (the `GL_TEXTUREn` sources its `combine` may name), or `None` when it
    /// is disabled; `warnings` gets a sentence when the
    /// texture is incomplete (it then textures nothing, as in GL). `view` is the camera's,
    /// which takes `texgen`'s eye planes to eye space.
    pub(super) fn texture(
        &self,
        field: &str,
        spec: &TextureSpec,
        (index, units): (usize, usize),
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
                let builtins = [("checker", 0), ("leaves", 1), ("disc", 2), ("lightmap", 3)];
                let image = match word(self, &f("builtin"), name, &builtins)? {
                    0 => TextureImage::checker(64, 8, [235, 235, 235, 255], [40, 90, 160, 255]),
                    1 => TextureImage::leaves(64),
                    2 => TextureImage::disc(32),
                    _ => TextureImage::lightmap(64),
                }
                .map_err(|e| self.field(f("builtin"), e.to_string()))?;
                (image, format!("builtin {name}"))
            }
            // A cube map alone: GL's 2D texture is never sampled then (GL's precedence).
            (None, None) if spec.cube_map.is_some() => (
                TextureImage::new(1, 1, vec![255; 4]).map_err(|e| self.field(field, e.to_string()))?,
                "none (the cube map is sampled)".to_string(),
            ),
            (None, None) => return Err(self.field(
                field,
                "no image: expected image = \"file.png\", builtin = \"checker\", \"leaves\", \"disc\" or \"lightmap\", or a cube_map table",
            )),
        };
        let mut image = image;
        image.srgb = spec.srgb.unwrap_or(false);
        image.base_format = self.base_format(field, spec)?;
        let mipmaps = spec.generate_mipmap.unwrap_or(false);
        if mipmaps {
            image = image.with_mipmaps();
        }
        let cube = match &spec.cube_map {
            Some(c) => Some(self.cube_map(&f("cube_map"), c, (image.srgb, image.base_format), mipmaps)?),
            None => None,
        };
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
        let modes: Vec<(&'static str, TexEnvMode)> = TexEnvMode::ALL
            .iter()
            .chain([&TexEnvMode::Combine])
            .map(|&m| (m.name(), m))
            .collect();
        let env_mode = spec
            .env
            .as_deref()
            .map_or(Ok(TexEnvMode::Modulate), |v| word(self, &f("env"), v, &modes))?;
        let combine = match (&spec.combine, env_mode) {
            (Some(c), TexEnvMode::Combine) => self.combine(&f("combine"), c, units)?,
            (Some(_), other) => {
                return Err(self.field(
                    f("combine"),
                    format!(
                        "is given with env {:?}, which reads no combine table: expected env = \"combine\" with it",
                        other.name()
                    ),
                ))
            }
            (None, _) => TextureUnit::default().combine,
        };
        let unit = TextureUnit {
            enabled: spec.enabled.unwrap_or(true),
            cube_map: cube.is_some(),
            combine,
            env_mode,
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
        let coords = self.coords(&f("coords"), spec.coords.as_ref(), index)?;
        if !unit.enabled {
            return Ok(None);
        }
        let texture = MeshTexture {
            image: Arc::new(image),
            sampling,
            unit,
            coords,
            source,
            cube_source: cube.as_ref().map_or(String::new(), |(_, s)| s.clone()),
            cube_map: cube.map(|(c, _)| Arc::new(c)),
        };
        if !texture.applies() {
            warnings.push(format!(
                "{field}: min_filter {:?} reads mipmaps and generate_mipmap is off, so the texture is incomplete and textures nothing, as in GL: expected generate_mipmap = true or min_filter = \"linear\" or \"nearest\"",
                sampling.min_filter.name()
            ));
        }
        Ok(Some(texture))
    }

    /// The `format` of the `texture` table at `field`: GL's base internal format in lowercase
    /// without `GL_`, `GL_RGBA` by default. GL 2.1 (EXT_texture_sRGB) has sRGB formats for
    /// RGB, RGBA, luminance and luminance-alpha only: `srgb = true` with "alpha" or
    /// "intensity" is refused.
    fn base_format(&self, field: &str, spec: &TextureSpec) -> Result<BaseFormat, SceneError> {
        let formats: Vec<(&'static str, BaseFormat)> =
            BaseFormat::ALL.iter().map(|&f| (f.name(), f)).collect();
        let at = format!("{field}.format");
        let format = spec
            .format
            .as_deref()
            .map_or(Ok(BaseFormat::Rgba), |v| word(self, &at, v, &formats))?;
        if spec.srgb == Some(true) && matches!(format, BaseFormat::Alpha | BaseFormat::Intensity) {
            return Err(self.field(
                format!("{field}.srgb"),
                format!(
                    "true with format {:?}: GL 2.1 has no sRGB {} format (EXT_texture_sRGB's are \
                     GL_SRGB8, GL_SRGB8_ALPHA8, GL_SLUMINANCE8 and GL_SLUMINANCE8_ALPHA8): expected \
                     srgb = false, or format \"rgba\", \"rgb\", \"luminance\" or \"luminance_alpha\"",
                    format.name(),
                    format.name()
                ),
            ));
        }
        Ok(format)
    }

    /// Unit `unit`'s `coords` at `field`: unit 0 takes the mesh's always; units 1-3 the
    /// mesh's ("mesh") or their current ones (4 finite numbers), GL's (0, 0, 0, 1) by default.
    fn coords(&self, field: &str, spec: Option<&toml::Value>, unit: usize) -> Result<TexCoords, SceneError> {
        const EXPECTED: &str = "expected \"mesh\" (the mesh's texture coordinates) or 4 numbers (s, t, r, q, as glMultiTexCoord4f)";
        let Some(spec) = spec else {
            return Ok(if unit == 0 {
                TexCoords::Mesh
            } else {
                TexCoords::Current(Vec4::W)
            });
        };
        if unit == 0 {
            return Err(self.field(
                field,
                "is given for unit 0, which always takes the mesh's texture coordinates: expected coords on units 1 to 3 only",
            ));
        }
        let number = |v: &toml::Value| match v {
            toml::Value::Integer(i) => Some(*i as f32),
            toml::Value::Float(x) => Some(*x as f32),
            _ => None,
        };
        match spec {
            toml::Value::String(w) if w == "mesh" => Ok(TexCoords::Mesh),
            toml::Value::String(w) => Err(self.field(field, format!("{:?}: {EXPECTED}", shorten(w)))),
            toml::Value::Array(items) => {
                let numbers: Option<Vec<f32>> = items.iter().map(number).collect();
                let Some(&[s, t, r, q]) = numbers.as_deref() else {
                    let what = match numbers {
                        Some(v) => format!("{} numbers", v.len()),
                        None => shorten(&spec.to_string()),
                    };
                    return Err(self.field(field, format!("{what}: {EXPECTED}")));
                };
                let c = Vec4::new(s, t, r, q);
                self.finite(field, &c.to_array())?;
                Ok(TexCoords::Current(c))
            }
            other => Err(self.field(field, format!("{}: {EXPECTED}", shorten(&other.to_string())))),
        }
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
    pub(super) fn texture_file(&self, field: &str, path: &Path) -> Result<TextureImage, SceneError> {
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
        // Charged as a glTF image is ([`super::Limits::texture_bytes`]): each unit's image and
        // cube face is decoded on its own, so one file named twice is charged twice.
        let bytes = super::gltf::mipmapped_bytes(width, height);
        let limit = self.limits.texture_bytes;
        self.budget
            .borrow_mut()
            .charge_texture(bytes, limit)
            .map_err(|used| {
                self.field(
                    field,
                    format!(
                        "{}: {width}x{height} texels take {bytes} bytes decoded (RGBA8 with mipmaps), \
                     which with the {used} bytes of the textures before it passes the scene's \
                     texture memory limit of {limit} bytes: expected fewer or smaller textures, \
                     or a higher limit (ffvk --max-texture-mib)",
                        full.display()
                    ),
                )
            })?;
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
