//! Cube map textures (GL 2.1 §3.8.6, ARB_texture_cube_map): six square faces of one size,
//! sampled in the direction (s, t, r); the face is the one the direction's largest component
//! points at, and the direction's other two components, divided by that one, give the texel
//! within it (table 3.19). The CPU reference's copy of the selection is [`cube_face`]; the
//! device's is Vulkan's (the same table), and the shaders' `texture(samplerCube, …)`.

use glam::{DVec2, DVec3};

use super::{TextureError, TextureImage};

/// A face of a cube map, in GL's order (`GL_TEXTURE_CUBE_MAP_POSITIVE_X` first, the order of
/// Vulkan's array layers too).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CubeFace {
    /// `GL_TEXTURE_CUBE_MAP_POSITIVE_X`.
    PositiveX,
    /// `GL_TEXTURE_CUBE_MAP_NEGATIVE_X`.
    NegativeX,
    /// `GL_TEXTURE_CUBE_MAP_POSITIVE_Y`.
    PositiveY,
    /// `GL_TEXTURE_CUBE_MAP_NEGATIVE_Y`.
    NegativeY,
    /// `GL_TEXTURE_CUBE_MAP_POSITIVE_Z`.
    PositiveZ,
    /// `GL_TEXTURE_CUBE_MAP_NEGATIVE_Z`.
    NegativeZ,
}

impl CubeFace {
    /// The six faces in GL's order.
    pub const ALL: [CubeFace; 6] = [
        CubeFace::PositiveX,
        CubeFace::NegativeX,
        CubeFace::PositiveY,
        CubeFace::NegativeY,
        CubeFace::PositiveZ,
        CubeFace::NegativeZ,
    ];

    /// The face's index in [`CubeFace::ALL`] (its array layer).
    pub fn index(self) -> usize {
        self as usize
    }

    /// GL's name of the face's target.
    pub fn gl_name(self) -> &'static str {
        match self {
            CubeFace::PositiveX => "GL_TEXTURE_CUBE_MAP_POSITIVE_X",
            CubeFace::NegativeX => "GL_TEXTURE_CUBE_MAP_NEGATIVE_X",
            CubeFace::PositiveY => "GL_TEXTURE_CUBE_MAP_POSITIVE_Y",
            CubeFace::NegativeY => "GL_TEXTURE_CUBE_MAP_NEGATIVE_Y",
            CubeFace::PositiveZ => "GL_TEXTURE_CUBE_MAP_POSITIVE_Z",
            CubeFace::NegativeZ => "GL_TEXTURE_CUBE_MAP_NEGATIVE_Z",
        }
    }
}

/// A cube map's six faces ([`CubeFace::ALL`]'s order), each a [`TextureImage`] whose rows are in
/// upload order (row 0 is t_face = 0, as `glTexImage2D` on the face's target takes them).
#[derive(Debug, Clone, PartialEq)]
pub struct CubeImage {
    // Private: square faces of one size, with as many levels and one sRGB flag (see `new`).
    faces: [TextureImage; 6],
}

impl CubeImage {
    /// A cube map of `faces`: each square, all of one size, with as many levels and the same
    /// `srgb` flag (GL's cube completeness, §3.8.10); the first face that is not is an error.
    pub fn new(faces: [TextureImage; 6]) -> Result<Self, TextureError> {
        let first = &faces[0];
        for (face, image) in CubeFace::ALL.into_iter().zip(&faces) {
            let (width, height) = (image.width(), image.height());
            if width != height {
                return Err(TextureError::CubeFaceNotSquare {
                    face: face.gl_name(),
                    width,
                    height,
                });
            }
            let same = width == first.width()
                && image.levels().len() == first.levels().len()
                && (image.srgb, image.base_format) == (first.srgb, first.base_format);
            if !same {
                return Err(TextureError::CubeFacesDiffer {
                    face: face.gl_name(),
                    size: width,
                    levels: image.levels().len(),
                    expected: (first.width(), first.levels().len()),
                });
            }
        }
        Ok(CubeImage { faces })
    }

    /// One face of the same `size` for each of `colors` (RGBA8), in GL's face order: the test
    /// and demo cube whose faces tell apart at a glance.
    pub fn solid(size: u32, colors: [[u8; 4]; 6]) -> Result<Self, TextureError> {
        let face = |c: [u8; 4]| TextureImage::new(size, size, c.repeat((size * size) as usize));
        let [a, b, c, d, e, f] = colors.map(face);
        CubeImage::new([a?, b?, c?, d?, e?, f?])
    }

    /// The faces, in GL's order.
    pub fn faces(&self) -> &[TextureImage; 6] {
        &self.faces
    }

    /// One face.
    pub fn face(&self, face: CubeFace) -> &TextureImage {
        &self.faces[face.index()]
    }

    /// Level 0's side in texels.
    pub fn size(&self) -> u32 {
        self.faces[0].width()
    }

    /// How many levels each face has.
    pub fn level_count(&self) -> usize {
        self.faces[0].levels().len()
    }

    /// Whether every face has its complete mipmap chain.
    pub fn has_mipmaps(&self) -> bool {
        self.faces.iter().all(TextureImage::has_mipmaps)
    }

    /// Every face with its mipmap chain made ([`TextureImage::with_mipmaps`]).
    #[must_use]
    pub fn with_mipmaps(self) -> Self {
        CubeImage {
            faces: self.faces.map(TextureImage::with_mipmaps),
        }
    }

    /// Whether the faces are sRGB (`GL_SRGB8_ALPHA8`).
    pub fn srgb(&self) -> bool {
        self.faces[0].srgb
    }
}

/// §3.8.6, table 3.19: the face direction `r` = (r_x, r_y, r_z) selects (the largest magnitude;
/// ties go to x before y before z, as Mesa's and lavapipe's samplers break them), and
/// (s_face, t_face) within it ([`CubeFace::coords`]). `None` for the zero vector, which selects
/// no face.
pub fn cube_face(r: DVec3) -> Option<(CubeFace, DVec2)> {
    let a = r.abs();
    let face = if a.x >= a.y && a.x >= a.z {
        if r.x >= 0.0 {
            CubeFace::PositiveX
        } else {
            CubeFace::NegativeX
        }
    } else if a.y >= a.z {
        if r.y >= 0.0 {
            CubeFace::PositiveY
        } else {
            CubeFace::NegativeY
        }
    } else if r.z >= 0.0 {
        CubeFace::PositiveZ
    } else {
        CubeFace::NegativeZ
    };
    face.coords(r).map(|st| (face, st))
}

impl CubeFace {
    /// Table 3.19 on this face: (s_face, t_face) = ((s_c / |m_a| + 1) / 2, (t_c / |m_a| + 1) / 2)
    /// for direction `r`, m_a its component along the face's axis. Also for a direction the
    /// face does not select (the neighbours of a fragment's direction, for the level of
    /// detail). `None` where m_a is zero or not finite.
    pub fn coords(self, r: DVec3) -> Option<DVec2> {
        let (sc, tc, ma) = match self {
            CubeFace::PositiveX => (-r.z, -r.y, r.x),
            CubeFace::NegativeX => (r.z, -r.y, r.x),
            CubeFace::PositiveY => (r.x, r.z, r.y),
            CubeFace::NegativeY => (r.x, -r.z, r.y),
            CubeFace::PositiveZ => (r.x, -r.y, r.z),
            CubeFace::NegativeZ => (-r.x, -r.y, r.z),
        };
        let ma = ma.abs();
        if ma == 0.0 || !ma.is_finite() {
            return None;
        }
        Some(DVec2::new((sc / ma + 1.0) / 2.0, (tc / ma + 1.0) / 2.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_axis_selects_its_face_at_the_faces_center() {
        let axes = [
            (DVec3::X, CubeFace::PositiveX),
            (-DVec3::X, CubeFace::NegativeX),
            (DVec3::Y, CubeFace::PositiveY),
            (-DVec3::Y, CubeFace::NegativeY),
            (DVec3::Z, CubeFace::PositiveZ),
            (-DVec3::Z, CubeFace::NegativeZ),
        ];
        for (r, face) in axes {
            assert_eq!(cube_face(r * 3.0), Some((face, DVec2::splat(0.5))));
        }
        assert_eq!(cube_face(DVec3::ZERO), None);
    }

    /// Table 3.19's s_c and t_c: on +X, s grows toward −z and t toward −y; on +Y, s toward +x
    /// and t toward +z; on −Z, s toward −x and t toward −y.
    #[test]
    fn the_faces_are_oriented_as_table_3_19_says() {
        let (face, st) = cube_face(DVec3::new(1.0, -0.5, -0.5)).unwrap();
        assert_eq!((face, st), (CubeFace::PositiveX, DVec2::new(0.75, 0.75)));
        let (face, st) = cube_face(DVec3::new(0.5, 1.0, 0.5)).unwrap();
        assert_eq!((face, st), (CubeFace::PositiveY, DVec2::new(0.75, 0.75)));
        let (face, st) = cube_face(DVec3::new(-0.5, 0.5, -1.0)).unwrap();
        assert_eq!((face, st), (CubeFace::NegativeZ, DVec2::new(0.75, 0.25)));
        let (face, st) = cube_face(DVec3::new(-1.0, 0.0, 0.5)).unwrap();
        assert_eq!((face, st), (CubeFace::NegativeX, DVec2::new(0.75, 0.5)));
    }

    #[test]
    fn faces_that_are_not_square_or_not_alike_are_refused_naming_the_face() {
        let square = |side: u32| TextureImage::new(side, side, vec![0; (side * side * 4) as usize]).unwrap();
        let mut faces = std::array::from_fn(|_| square(4));
        faces[3] = TextureImage::new(4, 2, vec![0; 32]).unwrap();
        assert_eq!(
            CubeImage::new(faces),
            Err(TextureError::CubeFaceNotSquare {
                face: "GL_TEXTURE_CUBE_MAP_NEGATIVE_Y",
                width: 4,
                height: 2
            })
        );
        let mut faces: [TextureImage; 6] = std::array::from_fn(|_| square(4));
        faces[5] = square(8);
        assert!(matches!(
            CubeImage::new(faces),
            Err(TextureError::CubeFacesDiffer {
                face: "GL_TEXTURE_CUBE_MAP_NEGATIVE_Z",
                size: 8,
                ..
            })
        ));
        let faces: [TextureImage; 6] = std::array::from_fn(|i| {
            if i == 2 {
                square(4).with_mipmaps()
            } else {
                square(4)
            }
        });
        assert!(CubeImage::new(faces).is_err());
        let cube = CubeImage::solid(4, [[255, 0, 0, 255]; 6]).unwrap().with_mipmaps();
        assert!(cube.has_mipmaps());
        assert_eq!((cube.size(), cube.level_count()), (4, 3));
    }
}
