//! Several texture units at one fragment (GL 2.1 §3.8.16), in the CPU reference: each unit's
//! coordinates (§2.11.4's sources and generation, then the unit's texture matrix), which units
//! sample and which apply (GL's enables and the cube map's precedence, through
//! [`units_applied`]), each unit's texel from its 2D texture or its cube map (§3.8.6, table
//! 3.19, non-seamless), and the units' environments in order, each on the one before's result.

use glam::{DVec2, DVec3, DVec4};

use super::texture::{lambda, project, sample, unit_env, UnitInputs};
use super::Bound;
use crate::gl::state::FixedFunctionState;
use crate::gl::texture::{units_applied, CubeFace, CubeImage, Sampling, MAX_TEXTURE_UNITS};

/// A cube map bound to a unit, with its sampling parameters.
pub type BoundCube<'a> = (&'a CubeImage, &'a Sampling);

/// What a draw binds for texturing, as the CPU reference reads it: each unit's 2D texture and
/// cube map, and the units 1-3 whose coordinates are the mesh's (a bit each, as
/// [`Draw::mesh_texcoords`](crate::Draw::mesh_texcoords) takes them) or the mesh's second set
/// ([`Draw::second_texcoords`](crate::Draw::second_texcoords)), with the triangle's second
/// coordinates. `Option<Bound>` converts to unit 0's texture alone.
#[derive(Debug, Clone, Copy, Default)]
pub struct DrawTextures<'a> {
    /// Each unit's `GL_TEXTURE_2D` texture.
    pub textures: [Option<Bound<'a>>; MAX_TEXTURE_UNITS],
    /// Each unit's `GL_TEXTURE_CUBE_MAP` texture.
    pub cube_maps: [Option<BoundCube<'a>>; MAX_TEXTURE_UNITS],
    /// Bits 1-3: the units whose coordinates are the mesh's; the others take the state's
    /// current coordinates. Unit 0's are always the mesh's.
    pub mesh_texcoords: u32,
    /// Bits 1-3: the units whose coordinates are the mesh's second set (a unit in both masks
    /// takes the second set).
    pub second_texcoords: u32,
    /// The second set's (s, t) at the triangle's three vertices, in the triangle's order
    /// ([`DrawTextures::for_triangle`]).
    pub triangle_second: [[f32; 2]; 3],
}

impl<'a> From<Option<Bound<'a>>> for DrawTextures<'a> {
    fn from(unit_0: Option<Bound<'a>>) -> Self {
        let mut textures = [None; MAX_TEXTURE_UNITS];
        textures[0] = unit_0;
        DrawTextures {
            textures,
            ..DrawTextures::default()
        }
    }
}

impl DrawTextures<'_> {
    /// These textures drawn on the triangle of `mesh`'s vertices `vertices`: its second
    /// coordinates read from the mesh's second set where it has one.
    #[must_use]
    pub fn for_triangle(mut self, mesh: &crate::mesh::MeshData, vertices: [usize; 3]) -> Self {
        if let Some(st) = vertices
            .iter()
            .map(|&i| mesh.second_texcoords.get(i).copied())
            .collect::<Option<Vec<_>>>()
        {
            self.triangle_second = [st[0], st[1], st[2]];
        }
        self
    }

    /// (sampled, applied, sampled as cube maps), a bit per unit, for `state`: a texture counts
    /// as bound when it is complete for its min filter (§3.8.10).
    pub fn units_applied(&self, state: &FixedFunctionState) -> (u32, u32, u32) {
        let bits = |present: &dyn Fn(usize) -> bool| {
            (0..MAX_TEXTURE_UNITS)
                .filter(|&i| present(i))
                .fold(0, |mask, i| mask | 1 << i)
        };
        let flat = bits(&|i| {
            self.textures[i].is_some_and(|(image, sampling)| sampling.is_complete(image.has_mipmaps()))
        });
        let cube = bits(&|i| {
            self.cube_maps[i].is_some_and(|(cube, sampling)| sampling.is_complete(cube.has_mipmaps()))
        });
        units_applied(&state.texture_units, flat, cube)
    }
}

/// Where one vertex's texture coordinates come from on units 1-3: the units reading the
/// mesh's coordinates and its second set (a bit each), and the vertex's second (s, t).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CoordSources {
    /// The units whose coordinates are the vertex's (s, t).
    pub mesh: u32,
    /// The units whose coordinates are the vertex's second (s, t).
    pub second: u32,
    /// The vertex's second (s, t).
    pub second_st: [f32; 2],
}

/// A vertex's (s, t, r, q) on every unit, not yet divided by q: the source (the vertex's (s,
/// t, 0, 1) on unit 0 and on the units `sources.mesh` names, its second (s, t, 0, 1) on those
/// `sources.second` names, else the unit's current coordinates), each coordinate whose
/// generation is on replaced ([`generated_coords`](super::texture::generated_coords)), through
/// the unit's texture matrix. `p_o`, `p_e` and `n_f` as `generated_coords` takes them.
pub fn unit_texcoords(
    state: &FixedFunctionState,
    sources: CoordSources,
    st: [f32; 2],
    (p_o, p_e, n_f): (DVec4, DVec4, DVec3),
) -> [DVec4; MAX_TEXTURE_UNITS] {
    let homogeneous = |st: [f32; 2]| DVec4::new(f64::from(st[0]), f64::from(st[1]), 0.0, 1.0);
    std::array::from_fn(|i| {
        let source = if i > 0 && sources.second & 1 << i != 0 {
            homogeneous(sources.second_st)
        } else if i == 0 || sources.mesh & 1 << i != 0 {
            homogeneous(st)
        } else {
            state.current_texcoords[i].as_dvec4()
        };
        let unit = &state.texture_units[i];
        unit.matrix.as_dmat4() * super::texture::generated_coords(unit, source, p_o, p_e, n_f)
    })
}

/// What one unit did at a fragment (what `ffvk explain` prints for each unit).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Textured {
    /// The interpolated (s, t, r, q) after the texture matrix.
    pub stq: DVec4,
    /// The cube map's face, for a unit that samples one (selected by (s, t, r); q is ignored).
    pub face: Option<CubeFace>,
    /// Where the texel is read: (s/q, t/q) in the 2D texture, or (s_face, t_face) in the face.
    pub st: DVec2,
    /// The level of detail λ = log2 ρ (−∞ where the coordinates do not change on screen).
    pub lambda: f64,
    /// The filtered texel C_s, A_s in the texture's base format ([`BaseFormat::texel`]).
    ///
    /// [`BaseFormat::texel`]: crate::gl::texture::BaseFormat::texel
    pub texel: DVec4,
    /// Whether the unit's environment applies: a sampled unit whose `GL_COMBINE` reads a unit
    /// that samples nothing passes the previous color through.
    pub applied: bool,
    /// The unit's result C_v, A_v (the previous unit's where it does not apply), before the
    /// secondary color is added.
    pub env: DVec4,
}

/// Every unit's texturing at one fragment of a draw: `stq[i]` unit i's interpolated (s, t, r,
/// q) at the fragment, one pixel to the right and one below (for λ); `c_pri` the fragment's
/// primary color. Returns each sampled unit's terms and the color texturing leaves (`c_pri`
/// where no unit applies).
pub fn texture_units(
    state: &FixedFunctionState,
    textures: &DrawTextures,
    stq: [[DVec4; 3]; MAX_TEXTURE_UNITS],
    c_pri: DVec4,
) -> ([Option<Textured>; MAX_TEXTURE_UNITS], DVec4) {
    let (sampled, applied, cube) = textures.units_applied(state);
    let mut terms: [Option<Textured>; MAX_TEXTURE_UNITS] = [None; MAX_TEXTURE_UNITS];
    let mut formats = [crate::gl::texture::BaseFormat::Rgba; MAX_TEXTURE_UNITS];
    for i in (0..MAX_TEXTURE_UNITS).filter(|&i| sampled & 1 << i != 0) {
        let (image, sampling, face, st, lambda) = if cube & 1 << i != 0 {
            let Some((cube_map, sampling)) = textures.cube_maps[i] else {
                continue;
            };
            let Some((face, st, lambda)) = cube_coords(cube_map, stq[i]) else {
                continue;
            };
            (cube_map.face(face), sampling, Some(face), st, lambda)
        } else {
            let Some((image, sampling)) = textures.textures[i] else {
                continue;
            };
            let [st, st_dx, st_dy] = stq[i].map(project);
            (image, sampling, None, st, lambda(image, st_dx - st, st_dy - st))
        };
        formats[i] = image.base_format;
        terms[i] = Some(Textured {
            stq: stq[i][0],
            face,
            st,
            lambda,
            texel: image.base_format.texel(sample(image, sampling, st, lambda)),
            applied: applied & 1 << i != 0,
            env: DVec4::ZERO,
        });
    }
    let c_s = terms.map(|t| t.map_or(DVec4::ZERO, |t| t.texel));
    let mut c_p = c_pri;
    for (i, term) in terms.iter_mut().enumerate() {
        let Some(term) = term else { continue };
        if term.applied {
            let v = UnitInputs {
                unit: i,
                c_f: c_pri,
                c_p,
                c_s,
                format: formats[i],
            };
            c_p = unit_env(&state.texture_units[i], &v);
        }
        term.env = c_p;
    }
    (terms, c_p)
}

/// A cube map's face, (s_face, t_face) and λ at a fragment whose direction is `stq`'s (s, t,
/// r) (at the fragment, one pixel right, one below): the face the fragment's direction selects,
/// its neighbours' coordinates on that same face for the derivatives (§3.8.6 then §3.8.8 on
/// the face's image). `None` for the zero direction.
fn cube_coords(cube: &CubeImage, stq: [DVec4; 3]) -> Option<(CubeFace, DVec2, f64)> {
    let [r, r_dx, r_dy] = stq.map(|c| c.truncate());
    let (face, st) = crate::gl::texture::cube_face(r)?;
    let on_face = |r: DVec3| face.coords(r).unwrap_or(st);
    let lambda = lambda(cube.face(face), on_face(r_dx) - st, on_face(r_dy) - st);
    Some((face, st, lambda))
}
