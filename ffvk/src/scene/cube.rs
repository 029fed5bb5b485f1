//! A texture unit's `cube_map` table: GL_TEXTURE_CUBE_MAP's texture from six face files, GL's
//! order (+X, -X, +Y, -Y, +Z, -Z), or the built-in cube "faces", each face one color of its
//! own. The unit's `srgb`, `format` and `generate_mipmap` apply to each face.

use super::file::CubeMapSpec;
use super::{shorten, Builder, SceneError};
use crate::gl::texture::{BaseFormat, CubeImage, TextureImage};

/// The faces' names in GL's order, for messages.
const FACES: [&str; 6] = ["+X", "-X", "+Y", "-Y", "+Z", "-Z"];

/// The built-in cube's side in texels.
const BUILTIN_SIZE: u32 = 16;

/// The built-in cube's colors, GL's face order: +X red, -X cyan, +Y green, -Y magenta, +Z
/// blue, -Z yellow (each axis's two faces complementary).
const BUILTIN_FACE_COLORS: [[u8; 4]; 6] = [
    [230, 40, 40, 255],
    [40, 220, 220, 255],
    [40, 200, 60, 255],
    [210, 50, 210, 255],
    [50, 70, 230, 255],
    [235, 215, 40, 255],
];

impl Builder<'_> {
    /// The cube map a `cube_map` table at `field` describes, its faces sRGB when `srgb`, of
    /// base internal format `format` and with their mipmap chains when `mipmaps`; and where it
    /// came from, for messages.
    pub(super) fn cube_map(
        &self,
        field: &str,
        spec: &CubeMapSpec,
        (srgb, format): (bool, BaseFormat),
        mipmaps: bool,
    ) -> Result<(CubeImage, String), SceneError> {
        let (cube, source) = match (&spec.faces, &spec.builtin) {
            (Some(_), Some(_)) => {
                return Err(self.field(
                    format!("{field}.faces"),
                    "given with builtin: expected either six face files or a builtin",
                ))
            }
            (Some(paths), None) => (self.cube_faces(&format!("{field}.faces"), paths)?, {
                let names: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
                format!("cube map {}", names.join(", "))
            }),
            (None, Some(name)) if name == "faces" => (
                CubeImage::solid(BUILTIN_SIZE, BUILTIN_FACE_COLORS)
                    .map_err(|e| self.field(format!("{field}.builtin"), e.to_string()))?,
                "builtin cube map faces".to_string(),
            ),
            (None, Some(name)) => {
                return Err(self.field(
                    format!("{field}.builtin"),
                    format!("{:?}: expected \"faces\"", shorten(name)),
                ))
            }
            (None, None) => return Err(self.field(
                field,
                "no faces: expected faces = [six image files, +X, -X, +Y, -Y, +Z, -Z] or builtin = \"faces\"",
            )),
        };
        let faces = cube.faces().clone().map(|mut face| {
            face.srgb = srgb;
            face.base_format = format;
            face
        });
        let cube = CubeImage::new(faces).map_err(|e| self.field(field, e.to_string()))?;
        Ok((if mipmaps { cube.with_mipmaps() } else { cube }, source))
    }

    /// Six face files at `field`, GL's order: each read as a `texture`'s image, square and of
    /// the first face's size.
    fn cube_faces(&self, field: &str, paths: &[std::path::PathBuf]) -> Result<CubeImage, SceneError> {
        if paths.len() != 6 {
            return Err(self.field(
                field,
                format!(
                    "{} files: expected exactly 6, one a face in GL's order ({})",
                    paths.len(),
                    FACES.join(", ")
                ),
            ));
        }
        let mut faces: Vec<TextureImage> = Vec::with_capacity(6);
        for (i, path) in paths.iter().enumerate() {
            let at = format!("{field}[{i}]");
            let face = self.texture_file(&at, path)?;
            let (w, h) = (face.width(), face.height());
            if w != h {
                return Err(self.field(
                    at,
                    format!(
                        "{} ({} face): {w}x{h} texels: expected a square face (GL's cube completeness)",
                        path.display(),
                        FACES[i]
                    ),
                ));
            }
            if let Some(first) = faces.first() {
                if w != first.width() {
                    return Err(self.field(
                        at,
                        format!(
                            "{} ({} face): {w}x{h} texels: expected {size}x{size}, the size of faces[0] ({})",
                            path.display(),
                            FACES[i],
                            paths[0].display(),
                            size = first.width(),
                        ),
                    ));
                }
            }
            faces.push(face);
        }
        let faces: [TextureImage; 6] = faces
            .try_into()
            .map_err(|_| self.field(field, "expected exactly 6 faces"))?;
        CubeImage::new(faces).map_err(|e| self.field(field, e.to_string()))
    }
}
