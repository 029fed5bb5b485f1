//! Texture objects of the GL reference: a [`TextureImage`] or a [`CubeImage`] uploaded with
//! its parameters (`glTexImage2D` for every level of every face, `glTexParameter`), and a
//! draw's textures per unit.

use ffvk::gl::texture::{
    BaseFormat, CubeImage, MagFilter, MinFilter, Sampling, TextureImage, Wrap, MAX_TEXTURE_UNITS,
};

use super::bindings::types::{GLenum, GLint, GLsizei, GLuint};
use super::bindings::{self as gl, Gl};
use super::egl::check_draw;
use super::error::DrawError;
use super::GlDraw;

/// A texture object of the current context holding every level of a [`TextureImage`], with
/// its parameters set; deleted when dropped.
pub(super) struct GlTexture<'g> {
    gl: &'g Gl,
    name: GLuint,
}

impl<'g> GlTexture<'g> {
    /// glTexImage2D for every level (`GL_SRGB8_ALPHA8` for an sRGB image, else `GL_RGBA8`), and
    /// glTexParameter for the filters and wraps. A complete chain gets `GL_TEXTURE_MAX_LEVEL`
    /// = levels − 1; any other image keeps GL's default of 1000, so that GL, like ffvk
    /// ([`ffvk::gl::texture::texturing_applies`]), finds it incomplete under a mipmap filter
    /// rather than complete at its levels. Leaves the texture bound to `GL_TEXTURE_2D`.
    pub(super) fn upload(
        gl: &'g Gl,
        image: &TextureImage,
        sampling: &Sampling,
    ) -> Result<GlTexture<'g>, DrawError> {
        Self::upload_faces(gl, gl::TEXTURE_2D, &[(gl::TEXTURE_2D, image)], sampling)
    }

    /// [`GlTexture::upload`] for a cube map: each face on its target
    /// (`GL_TEXTURE_CUBE_MAP_POSITIVE_X` + i), the parameters on `GL_TEXTURE_CUBE_MAP`. Leaves
    /// it bound to `GL_TEXTURE_CUBE_MAP`.
    pub(super) fn upload_cube(
        gl: &'g Gl,
        cube: &CubeImage,
        sampling: &Sampling,
    ) -> Result<GlTexture<'g>, DrawError> {
        let faces: Vec<(GLenum, &TextureImage)> = (0..6u32)
            .map(|i| gl::TEXTURE_CUBE_MAP_POSITIVE_X + i)
            .zip(cube.faces())
            .collect();
        Self::upload_faces(gl, gl::TEXTURE_CUBE_MAP, &faces, sampling)
    }

    /// Every level of each `(image target, image)` of `faces` into one texture object bound to
    /// `target`, with its parameters.
    fn upload_faces(
        gl: &'g Gl,
        target: GLenum,
        faces: &[(GLenum, &TextureImage)],
        sampling: &Sampling,
    ) -> Result<GlTexture<'g>, DrawError> {
        let Some(&(_, image)) = faces.first() else {
            return Err(DrawError::TextureLevel {
                level: 0,
                width: 0,
                height: 0,
                bytes: 0,
            });
        };
        for (level, l) in faces.iter().flat_map(|(_, f)| f.levels().iter().enumerate()) {
            let fits = GLsizei::try_from(l.width()).is_ok() && GLsizei::try_from(l.height()).is_ok();
            if !fits || Some(l.rgba().len()) != (l.width() as usize).checked_mul(l.height() as usize * 4) {
                return Err(DrawError::TextureLevel {
                    level,
                    width: l.width(),
                    height: l.height(),
                    bytes: l.rgba().len(),
                });
            }
        }
        let mut texture = GlTexture { gl, name: 0 };
        let internal = internal_format(image);
        // SAFETY: a context is current on this thread; glGenTextures writes one name (owned by
        // `texture` from here on); each level's bytes were checked to be width * height * 4,
        // which glTexImage2D reads with UNPACK_ALIGNMENT 1 (no row padding) and no unpack
        // buffer bound.
        unsafe {
            gl.GenTextures(1, &mut texture.name);
            gl.BindTexture(target, texture.name);
            gl.PixelStorei(gl::UNPACK_ALIGNMENT, 1);
            let levels = faces
                .iter()
                .flat_map(|&(face, f)| f.levels().iter().enumerate().map(move |(i, l)| (face, i, l)));
            for (face, level, l) in levels {
                gl.TexImage2D(
                    face,
                    level as GLint,
                    internal as GLint,
                    l.width() as GLsizei,
                    l.height() as GLsizei,
                    0,
                    gl::RGBA,
                    gl::UNSIGNED_BYTE,
                    l.rgba().as_ptr().cast(),
                );
            }
            if image.has_mipmaps() {
                gl.TexParameteri(target, gl::TEXTURE_MAX_LEVEL, image.levels().len() as GLint - 1);
            }
            for (parameter, value) in [
                (gl::TEXTURE_MIN_FILTER, min_filter_enum(sampling.min_filter)),
                (gl::TEXTURE_MAG_FILTER, mag_filter_enum(sampling.mag_filter)),
                (gl::TEXTURE_WRAP_S, wrap_enum(sampling.wrap_s)),
                (gl::TEXTURE_WRAP_T, wrap_enum(sampling.wrap_t)),
            ] {
                gl.TexParameteri(target, parameter, value as GLint);
            }
        }
        check_draw(gl, "uploading the texture")?;
        Ok(texture)
    }
}

/// `glTexImage2D`'s `internalformat` for `image`: its base format (table 3.15; GL takes
/// luminance and intensity from the RGBA pixels' R, alpha from A, as ffvk reads them) at 8
/// bits, sRGB where GL has the format.
fn internal_format(image: &TextureImage) -> GLenum {
    match (image.base_format, image.srgb) {
        (BaseFormat::Rgb, false) => gl::RGB8,
        (BaseFormat::Rgb, true) => gl::SRGB8,
        (BaseFormat::Alpha, _) => gl::ALPHA8,
        (BaseFormat::Luminance, false) => gl::LUMINANCE8,
        (BaseFormat::Luminance, true) => gl::SLUMINANCE8,
        (BaseFormat::LuminanceAlpha, false) => gl::LUMINANCE8_ALPHA8,
        (BaseFormat::LuminanceAlpha, true) => gl::SLUMINANCE8_ALPHA8,
        (BaseFormat::Intensity, _) => gl::INTENSITY8,
        (_, true) => gl::SRGB8_ALPHA8,
        _ => gl::RGBA8,
    }
}

impl GlTexture<'_> {
    /// The texture object's name.
    pub(super) fn name(&self) -> GLuint {
        self.name
    }
}

impl Drop for GlTexture<'_> {
    fn drop(&mut self) {
        // SAFETY: the context that made the name is current (textures never outlive the
        // `render` or `time` call that made them, which runs inside its context).
        unsafe { self.gl.DeleteTextures(1, &self.name) };
    }
}

fn min_filter_enum(filter: MinFilter) -> GLenum {
    match filter {
        MinFilter::Nearest => gl::NEAREST,
        MinFilter::Linear => gl::LINEAR,
        MinFilter::NearestMipmapNearest => gl::NEAREST_MIPMAP_NEAREST,
        MinFilter::LinearMipmapNearest => gl::LINEAR_MIPMAP_NEAREST,
        MinFilter::NearestMipmapLinear => gl::NEAREST_MIPMAP_LINEAR,
        MinFilter::LinearMipmapLinear => gl::LINEAR_MIPMAP_LINEAR,
    }
}

fn mag_filter_enum(filter: MagFilter) -> GLenum {
    match filter {
        MagFilter::Nearest => gl::NEAREST,
        MagFilter::Linear => gl::LINEAR,
    }
}

fn wrap_enum(wrap: Wrap) -> GLenum {
    match wrap {
        Wrap::Repeat => gl::REPEAT,
        Wrap::ClampToEdge => gl::CLAMP_TO_EDGE,
        Wrap::MirroredRepeat => gl::MIRRORED_REPEAT,
        // A mode added to ffvk after this table: GL_NONE makes GL raise INVALID_ENUM, which
        // fails the render with GL's error rather than drawing another mode.
        _ => gl::NONE,
    }
}

/// Each unit's texture of `draw` uploaded (`None` where it has none).
pub(super) fn upload_textures<'g>(gl: &'g Gl, draw: &GlDraw) -> Result<UploadedUnits<'g>, DrawError> {
    let mut out: UploadedUnits<'g> = Default::default();
    for (slot, texture) in out.0.iter_mut().zip(&draw.textures) {
        *slot = texture
            .map(|(image, sampling)| GlTexture::upload(gl, image, &sampling))
            .transpose()?;
    }
    for (slot, cube) in out.1.iter_mut().zip(&draw.cube_maps) {
        *slot = cube
            .map(|(image, sampling)| GlTexture::upload_cube(gl, image, &sampling))
            .transpose()?;
    }
    Ok(out)
}

/// A draw's uploaded 2D textures and cube maps, a unit each.
pub(super) type UploadedUnits<'g> = (
    [Option<GlTexture<'g>>; MAX_TEXTURE_UNITS],
    [Option<GlTexture<'g>>; MAX_TEXTURE_UNITS],
);

/// A draw's uploaded textures, a unit each, and how many units the scene sets
/// ([`GlScene::units_used`](super::GlScene::units_used)).
#[derive(Clone, Copy)]
pub(super) struct DrawUnits<'t, 'g> {
    pub(super) textures: [Option<&'t GlTexture<'g>>; MAX_TEXTURE_UNITS],
    pub(super) cube_maps: [Option<&'t GlTexture<'g>>; MAX_TEXTURE_UNITS],
    pub(super) count: usize,
}

impl<'t, 'g> DrawUnits<'t, 'g> {
    pub(super) fn of(uploaded: &'t UploadedUnits<'g>, count: usize) -> Self {
        DrawUnits {
            textures: uploaded.0.each_ref().map(Option::as_ref),
            cube_maps: uploaded.1.each_ref().map(Option::as_ref),
            count,
        }
    }

    /// The units whose texture coordinate array is the mesh's: unit 0 when it has a texture,
    /// and the units `mesh_texcoords` names that have one.
    pub(super) fn texcoord_arrays(&self, mesh_texcoords: u32) -> u32 {
        (0..self.count.min(MAX_TEXTURE_UNITS))
            .filter(|&i| {
                let bound = self.textures[i].is_some() || self.cube_maps[i].is_some();
                bound && (i == 0 || mesh_texcoords & 1 << i != 0)
            })
            .fold(0, |mask, i| mask | 1 << i)
    }
}
