//! GL's user clip planes (2.1 §2.12): `glClipPlane` and `GL_CLIP_PLANEi`.

use glam::{DMat4, DVec4, Vec4};

/// How many user clip planes ffvk has (`GL_MAX_CLIP_PLANES`, GL's minimum).
pub const MAX_CLIP_PLANES: usize = 6;

/// The user clip planes: each kept in eye space, as `glClipPlane` stores it (p · M⁻¹ with the
/// modelview M current at the call), and enabled apart. A vertex at eye position e is kept
/// where p_eye · e ≥ 0 for every enabled plane.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct ClipPlanes {
    /// `GL_CLIP_PLANEi`'s equation in eye space; (0, 0, 0, 0) by default.
    pub planes: [Vec4; MAX_CLIP_PLANES],
    /// `GL_CLIP_PLANEi` enabled; all off by default.
    pub enabled: [bool; MAX_CLIP_PLANES],
}

impl Default for ClipPlanes {
    fn default() -> Self {
        ClipPlanes {
            planes: [Vec4::ZERO; MAX_CLIP_PLANES],
            enabled: [false; MAX_CLIP_PLANES],
        }
    }
}

impl ClipPlanes {
    /// The enabled planes, a bit each (bit i: `GL_CLIP_PLANEi`): the shaders'
    /// `SPEC_CLIP_PLANES`.
    pub fn mask(&self) -> u32 {
        self.enabled
            .iter()
            .enumerate()
            .filter(|(_, &on)| on)
            .fold(0, |mask, (i, _)| mask | 1 << i)
    }

    /// A plane `p` given in object coordinates under `modelview`, in eye space: p · M⁻¹ (GL
    /// 2.1 §2.12), computed in double precision as GL takes the equation; `None` for a singular
    /// modelview (GL leaves the plane undefined).
    pub fn to_eye(p: DVec4, modelview: glam::Mat4) -> Option<Vec4> {
        let m = DMat4::from_cols_array(&modelview.to_cols_array().map(f64::from));
        let det = m.determinant();
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        // A row vector times M⁻¹ is (M⁻¹)ᵀ times the column vector.
        Some((m.inverse().transpose() * p).as_vec4())
    }
}
