//! Texture coordinate generation's state (GL 2.1 §2.11.4, glTexGen): a mode per coordinate
//! and its planes. The shaders' copy is `glsl/texgen.glsl`, the CPU reference's
//! `reference::texture::generated_coords`.

use glam::Vec4;

/// `GL_TEXTURE_GEN_MODE` (GL 2.1 §2.11.4): how a texture coordinate is generated from the
/// vertex, when its `GL_TEXTURE_GEN_S` (`_T`, `_R`, `_Q`) is enabled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum TexGenMode {
    /// `GL_OBJECT_LINEAR`: g = p1 x_o + p2 y_o + p3 z_o + p4 w_o, the object plane.
    ObjectLinear,
    /// `GL_EYE_LINEAR` (GL's default): g = p1' x_e + p2' y_e + p3' z_e + p4' w_e, the eye plane
    /// (given in object coordinates, taken to eye space by the modelview's inverse then).
    #[default]
    EyeLinear,
    /// `GL_SPHERE_MAP` (S and T only): r = u − 2 n_f (n_f · u), m = 2 √(r_x² + r_y² + (r_z + 1)²),
    /// s = r_x / m + ½, t = r_y / m + ½, u the unit vector from the eye to the vertex, n_f the
    /// eye-space normal.
    SphereMap,
    /// `GL_REFLECTION_MAP` (S, T and R): r's x, y, z.
    ReflectionMap,
    /// `GL_NORMAL_MAP` (S, T and R): n_f's x, y, z.
    NormalMap,
}

impl TexGenMode {
    /// Every mode.
    pub const ALL: [TexGenMode; 5] = [
        TexGenMode::ObjectLinear,
        TexGenMode::EyeLinear,
        TexGenMode::SphereMap,
        TexGenMode::ReflectionMap,
        TexGenMode::NormalMap,
    ];

    /// Lowercase name, as scene files write it (`object_linear`, …).
    pub fn name(self) -> &'static str {
        match self {
            TexGenMode::ObjectLinear => "object_linear",
            TexGenMode::EyeLinear => "eye_linear",
            TexGenMode::SphereMap => "sphere_map",
            TexGenMode::ReflectionMap => "reflection_map",
            TexGenMode::NormalMap => "normal_map",
        }
    }

    /// GL's name (`GL_OBJECT_LINEAR`, …).
    pub fn gl_name(self) -> &'static str {
        match self {
            TexGenMode::ObjectLinear => "GL_OBJECT_LINEAR",
            TexGenMode::EyeLinear => "GL_EYE_LINEAR",
            TexGenMode::SphereMap => "GL_SPHERE_MAP",
            TexGenMode::ReflectionMap => "GL_REFLECTION_MAP",
            TexGenMode::NormalMap => "GL_NORMAL_MAP",
        }
    }

    /// The value the shaders' `TEXGEN_*` take (`glsl/texgen.glsl`): 1 to 5; 0 is "not
    /// generated".
    pub fn code(self) -> u32 {
        match self {
            TexGenMode::ObjectLinear => 1,
            TexGenMode::EyeLinear => 2,
            TexGenMode::SphereMap => 3,
            TexGenMode::ReflectionMap => 4,
            TexGenMode::NormalMap => 5,
        }
    }

    /// Whether GL accepts the mode for coordinate `coord` (0 S, 1 T, 2 R, 3 Q): `GL_SPHERE_MAP`
    /// for S and T only, `GL_REFLECTION_MAP` and `GL_NORMAL_MAP` for S, T and R (§2.11.4's
    /// `GL_INVALID_ENUM`).
    pub fn allowed_for(self, coord: usize) -> bool {
        match self {
            TexGenMode::SphereMap => coord < 2,
            TexGenMode::ReflectionMap | TexGenMode::NormalMap => coord < 3,
            _ => coord < 4,
        }
    }
}

/// One texture coordinate's generation (`GL_TEXTURE_GEN_S` .. `_Q` with glTexGen's state).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct TexCoordGen {
    /// `GL_TEXTURE_GEN_S` (`_T`, `_R`, `_Q`); off by default: the coordinate is the vertex's.
    pub enabled: bool,
    /// `GL_TEXTURE_GEN_MODE`; `GL_EYE_LINEAR` by default.
    pub mode: TexGenMode,
    /// `GL_OBJECT_PLANE`, as given.
    pub object_plane: Vec4,
    /// `GL_EYE_PLANE` in eye space: (p1 p2 p3 p4) M⁻¹ with M the modelview when it was set.
    pub eye_plane: Vec4,
}

impl TexCoordGen {
    /// GL's initial state of coordinate `coord` (0 S, 1 T, 2 R, 3 Q): both planes (1, 0, 0, 0)
    /// for S, (0, 1, 0, 0) for T, zero for R and Q (table 6.15), the eye plane as set with the
    /// identity modelview.
    pub fn initial(coord: usize) -> TexCoordGen {
        let plane = match coord {
            0 => Vec4::X,
            1 => Vec4::Y,
            _ => Vec4::ZERO,
        };
        TexCoordGen {
            enabled: false,
            mode: TexGenMode::EyeLinear,
            object_plane: plane,
            eye_plane: plane,
        }
    }

    /// The shader's code for this coordinate: 0 when it is not generated, else the mode's.
    pub fn code(&self) -> u32 {
        if self.enabled {
            self.mode.code()
        } else {
            0
        }
    }

    /// The plane the mode reads (object or eye), zero for the others.
    pub fn plane(&self) -> Vec4 {
        match self.mode {
            TexGenMode::ObjectLinear => self.object_plane,
            TexGenMode::EyeLinear => self.eye_plane,
            _ => Vec4::ZERO,
        }
    }
}
