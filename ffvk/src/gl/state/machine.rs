//! [`GlState`]: GL's entry points over the lighting state (`glLight`, `glMaterial`,
//! `glLightModel`, `glColorMaterial`, `glColor`, `glShadeModel`, `glEnable`, `glTexEnv`, the
//! matrices), each checked as GL checks it before anything changes; the state and its types
//! are in [`state`](super).

use glam::{Mat3, Mat4, Vec3, Vec4};

use super::{
    check_light_scalar, finite_vec, in_range, Cap, ClipPlanes, ColorMaterialMode, CompareFunc, Face,
    FixedFunctionState, FogHint, FogParam, Light, LightModelParam, LightParam, LightingMode, Material,
    MaterialParam, PointParam, RasterGl, ShadeModel, StateError, TexEnvParam, MAX_LIGHTS,
};
use crate::gl::texture::{CombineSource, TexCoordGen, TexGenMode, TextureUnit, MAX_TEXTURE_UNITS};

/// The fixed-function state machine: the lighting state, the current modelview matrix and the
/// raster state, with GL's entry points (the raster state's are in `raster.rs`). Start from [`GlState::new`] for GL's initial state.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct GlState {
    /// The state a draw captures.
    pub lighting: FixedFunctionState,
    /// The modelview matrix in force (glLoadMatrix / glMultMatrix).
    pub modelview: Mat4,
    /// `GL_ACTIVE_TEXTURE`'s unit (glActiveTexture), 0 initially: the unit glTexEnv, glTexGen,
    /// the texture matrix and the `GL_TEXTURE_2D` and `GL_TEXTURE_GEN_*` enables act on.
    pub active_unit: usize,
    /// GL's raster and per-fragment state ([`RasterGl`]): what a draw's
    /// [`RasterState`](crate::RasterState) is made from ([`GlState::raster_state`]).
    pub raster: RasterGl,
}

impl Default for GlState {
    fn default() -> Self {
        Self::new()
    }
}

impl GlState {
    /// GL's initial state: identity modelview, every default of table 2.10.
    pub fn new() -> Self {
        GlState {
            lighting: FixedFunctionState::default(),
            modelview: Mat4::IDENTITY,
            active_unit: 0,
            raster: RasterGl::default(),
        }
    }

    /// glLoadMatrix on the MODELVIEW stack.
    pub fn load_modelview(&mut self, m: Mat4) -> Result<(), StateError> {
        finite_vec("modelview matrix", &m.to_cols_array())?;
        self.modelview = m;
        Ok(())
    }

    /// glMultMatrix on the MODELVIEW stack.
    pub fn mult_modelview(&mut self, m: Mat4) -> Result<(), StateError> {
        self.load_modelview(self.modelview * m)
    }

    fn light_mut(&mut self, index: usize) -> Result<&mut Light, StateError> {
        self.lighting.lights.get_mut(index).ok_or(StateError::LightIndex {
            index,
            max: MAX_LIGHTS,
        })
    }

    /// glLight: sets one parameter of light `index`. Positions and spot directions are
    /// transformed by the current modelview and stored in eye space, as GL does.
    pub fn light(&mut self, index: usize, param: LightParam) -> Result<(), StateError> {
        check_light_scalar(&param)?;
        let modelview = self.modelview;
        let light = self.light_mut(index)?;
        match param {
            LightParam::Ambient(c) => light.ambient = finite4("GL_AMBIENT", c)?,
            LightParam::Diffuse(c) => light.diffuse = finite4("GL_DIFFUSE", c)?,
            LightParam::Specular(c) => light.specular = finite4("GL_SPECULAR", c)?,
            LightParam::Position(p) => light.position = modelview * finite4("GL_POSITION", p)?,
            LightParam::SpotDirection(d) => {
                finite_vec("GL_SPOT_DIRECTION", &d.to_array())?;
                light.spot_direction = Mat3::from_mat4(modelview) * d;
            }
            LightParam::SpotExponent(v) => light.spot_exponent = v,
            LightParam::SpotCutoff(v) => light.spot_cutoff = v,
            LightParam::ConstantAttenuation(v) => light.constant_attenuation = v,
            LightParam::LinearAttenuation(v) => light.linear_attenuation = v,
            LightParam::QuadraticAttenuation(v) => light.quadratic_attenuation = v,
            LightParam::SpotEdge(edge) => light.spot_edge = edge,
            LightParam::Attenuation(a) => light.attenuation = a,
        }
        Ok(())
    }

    /// glMaterial on `face`. Parameters that track the current color (`GL_COLOR_MATERIAL`
    /// enabled, its face and mode naming them) keep that color.
    pub fn material(&mut self, face: Face, param: MaterialParam) -> Result<(), StateError> {
        let apply = |m: &mut Material| -> Result<(), StateError> {
            match param {
                MaterialParam::Ambient(c) => m.ambient = finite4("GL_AMBIENT", c)?,
                MaterialParam::Diffuse(c) => m.diffuse = finite4("GL_DIFFUSE", c)?,
                MaterialParam::Specular(c) => m.specular = finite4("GL_SPECULAR", c)?,
                MaterialParam::Emission(c) => m.emission = finite4("GL_EMISSION", c)?,
                MaterialParam::AmbientAndDiffuse(c) => {
                    let c = finite4("GL_AMBIENT_AND_DIFFUSE", c)?;
                    m.ambient = c;
                    m.diffuse = c;
                }
                MaterialParam::Shininess(s) => {
                    in_range("GL_SHININESS", s, 0.0, 128.0, "a value in [0, 128]")?;
                    m.shininess = s;
                }
            }
            Ok(())
        };
        if face.includes_front() {
            apply(&mut self.lighting.front)?;
        }
        if face.includes_back() {
            apply(&mut self.lighting.back)?;
        }
        // While COLOR_MATERIAL is on, the parameters it names track the current color (2.1,
        // section 2.14.3), so a glMaterial of one of them leaves it at that color, as in
        // Mesa's GL.
        self.track_current_color();
        Ok(())
    }

    /// glLightModel.
    pub fn light_model(&mut self, param: LightModelParam) -> Result<(), StateError> {
        let model = &mut self.lighting.model;
        match param {
            LightModelParam::Ambient(c) => model.ambient = finite4("GL_LIGHT_MODEL_AMBIENT", c)?,
            LightModelParam::LocalViewer(b) => model.local_viewer = b,
            LightModelParam::TwoSide(b) => model.two_side = b,
            LightModelParam::ColorControl(c) => model.color_control = c,
            LightModelParam::SpecularModel(m) => model.specular_model = m,
        }
        Ok(())
    }

    /// glColorMaterial.
    pub fn color_material(&mut self, face: Face, mode: ColorMaterialMode) {
        self.lighting.color_material.face = face;
        self.lighting.color_material.mode = mode;
        self.track_current_color();
    }

    /// glColor4f: sets the current color, which a draw without a color array gives every
    /// vertex. With `GL_COLOR_MATERIAL` enabled the color is also written into the tracked
    /// material parameters (section 2.14.3: they track the current color), where it stays
    /// after `glDisable(GL_COLOR_MATERIAL)`. Colors are not clamped here (GL clamps after
    /// lighting); a NaN or infinite component is an error.
    ///
    /// GL leaves the current color undefined after a draw that used a color array (2.1,
    /// section 2.8); this state keeps the last `glColor`, and callers that need Mesa's
    /// behaviour after such draws set it again.
    pub fn color(&mut self, color: Vec4) -> Result<(), StateError> {
        finite_vec("GL_CURRENT_COLOR", color.to_array().as_slice())?;
        self.lighting.current_color = color;
        self.track_current_color();
        Ok(())
    }

    /// glNormal: the current normal, every vertex's normal in draws whose layout has no normal
    /// array. Not normalized here (GL normalizes only under `GL_NORMALIZE`); a NaN or
    /// infinite component is an error.
    pub fn normal(&mut self, normal: Vec3) -> Result<(), StateError> {
        finite_vec("GL_CURRENT_NORMAL", normal.to_array().as_slice())?;
        self.lighting.current_normal = normal;
        Ok(())
    }

    /// glTexCoord4f: unit 0's current texture coordinates (glTexCoord2f is (s, t, 0, 1)),
    /// every vertex's in draws applying unit 0 whose layout has no texture coordinate array
    /// for it; a NaN or infinite component is an error.
    pub fn tex_coord(&mut self, texcoord: Vec4) -> Result<(), StateError> {
        self.multi_tex_coord(0, texcoord)
    }

    /// glMultiTexCoord4f(GL_TEXTURE0 + unit, …): unit `unit`'s current texture coordinates;
    /// a unit at or past [`MAX_TEXTURE_UNITS`] or a NaN or infinite component is an error.
    pub fn multi_tex_coord(&mut self, unit: usize, texcoord: Vec4) -> Result<(), StateError> {
        check_unit(unit)?;
        finite_vec("GL_CURRENT_TEXTURE_COORDS", texcoord.to_array().as_slice())?;
        self.lighting.current_texcoords[unit] = texcoord;
        Ok(())
    }

    /// glActiveTexture(GL_TEXTURE0 + unit): the unit later glTexEnv, glTexGen, texture matrix
    /// and texture enable calls act on; a unit at or past [`MAX_TEXTURE_UNITS`] is an error
    /// (GL's `GL_INVALID_ENUM`) and changes nothing.
    pub fn active_texture(&mut self, unit: usize) -> Result<(), StateError> {
        self.active_unit = check_unit(unit)?;
        Ok(())
    }

    /// The active texture unit's state.
    fn unit_mut(&mut self) -> &mut TextureUnit {
        let unit = self.active_unit.min(MAX_TEXTURE_UNITS - 1);
        &mut self.lighting.texture_units[unit]
    }

    /// While `GL_COLOR_MATERIAL` is enabled, writes the current color into the material
    /// parameters it tracks (glColor, glColorMaterial and glEnable do this in GL).
    fn track_current_color(&mut self) {
        let l = &mut self.lighting;
        let color = l.current_color;
        l.front = l.color_material.apply(&l.front, color, false);
        l.back = l.color_material.apply(&l.back, color, true);
    }

    /// glShadeModel: FLAT selects [`LightingMode::Flat`]; SMOOTH selects per-vertex lighting.
    pub fn shade_model(&mut self, model: ShadeModel) {
        self.lighting.mode = match model {
            ShadeModel::Flat => LightingMode::Flat,
            ShadeModel::Smooth => LightingMode::Vertex,
        };
    }

    /// ffvk's extension: where the equation is evaluated.
    pub fn lighting_mode(&mut self, mode: LightingMode) {
        self.lighting.mode = mode;
    }

    /// glEnable / glDisable.
    pub fn set_enabled(&mut self, cap: Cap, on: bool) -> Result<(), StateError> {
        match cap {
            Cap::Lighting => self.lighting.lighting = on,
            Cap::Light(i) => self.light_mut(i)?.enabled = on,
            Cap::ColorMaterial => {
                self.lighting.color_material.enabled = on;
                self.track_current_color();
            }
            Cap::Normalize => self.lighting.normalize = on,
            Cap::RescaleNormal => self.lighting.rescale_normal = on,
            Cap::Texture2D => self.unit_mut().enabled = on,
            Cap::TextureCubeMap => self.unit_mut().cube_map = on,
            Cap::ColorSum => self.lighting.fragment.color_sum = on,
            Cap::AlphaTest => self.lighting.fragment.alpha_test.enabled = on,
            Cap::Fog => self.lighting.fragment.fog.enabled = on,
            Cap::ClipPlane(i) => *self.clip_plane_mut(i)? = on,
            Cap::PointSprite => self.lighting.points.sprite = on,
            Cap::TextureGen(i) => self.texgen_mut(i)?.enabled = on,
            Cap::PolygonOffsetFill
            | Cap::PolygonOffsetLine
            | Cap::PolygonOffsetPoint
            | Cap::LineStipple
            | Cap::PolygonStipple
            | Cap::StencilTest
            | Cap::ColorLogicOp
            | Cap::Blend
            | Cap::DepthTest
            | Cap::CullFace => {
                if let Some(enabled) = self.raster.enabled_mut(cap) {
                    *enabled = on;
                }
            }
        }
        Ok(())
    }

    /// Coordinate `coord`'s generation (0 S, 1 T, 2 R, 3 Q); another index is an error.
    fn texgen_mut(&mut self, coord: usize) -> Result<&mut TexCoordGen, StateError> {
        self.unit_mut()
            .texgen
            .get_mut(coord)
            .ok_or(StateError::OutOfRange {
                parameter: "texture coordinate (GL_S, GL_T, GL_R, GL_Q)",
                value: coord as f32,
                valid: "0 (S), 1 (T), 2 (R) or 3 (Q)",
            })
    }

    /// glTexGen with `GL_TEXTURE_GEN_MODE`: coordinate `coord`'s (0 S .. 3 Q) mode. GL's
    /// `GL_INVALID_ENUM` for `GL_SPHERE_MAP` on R or Q and `GL_REFLECTION_MAP` or
    /// `GL_NORMAL_MAP` on Q ([`TexGenMode::allowed_for`]); nothing changes then.
    pub fn tex_gen_mode(&mut self, coord: usize, mode: TexGenMode) -> Result<(), StateError> {
        let gen = self.texgen_mut(coord)?;
        if !mode.allowed_for(coord) {
            return Err(StateError::NotAccepted {
                parameter: "GL_TEXTURE_GEN_MODE",
                value: mode.gl_name(),
                valid: "GL_OBJECT_LINEAR, GL_EYE_LINEAR or (S, T) GL_SPHERE_MAP, (S, T, R) GL_REFLECTION_MAP or GL_NORMAL_MAP",
            });
        }
        gen.mode = mode;
        Ok(())
    }

    /// glTexGen with `GL_OBJECT_PLANE`: coordinate `coord`'s object plane, kept as given.
    pub fn tex_gen_object_plane(&mut self, coord: usize, p: glam::DVec4) -> Result<(), StateError> {
        let components = p.to_array().map(|c| c as f32);
        finite_vec("GL_OBJECT_PLANE", &components)?;
        self.texgen_mut(coord)?.object_plane = p.as_vec4();
        Ok(())
    }

    /// glTexGen with `GL_EYE_PLANE`: coordinate `coord`'s eye plane, taken to eye space as GL
    /// does, (p1 p2 p3 p4) M⁻¹ with the modelview M in force now (as `glClipPlane`'s); a
    /// singular modelview is an error (ffvk's choice: GL's inverse does not exist).
    pub fn tex_gen_eye_plane(&mut self, coord: usize, p: glam::DVec4) -> Result<(), StateError> {
        self.texgen_mut(coord)?;
        let eye = self.plane_to_eye("GL_EYE_PLANE", p)?;
        self.texgen_mut(coord)?.eye_plane = eye;
        Ok(())
    }

    /// Plane `p` (object coordinates, parameter `parameter`) in eye space, p · M⁻¹ with the
    /// modelview current now: glClipPlane's and glTexGen(GL_EYE_PLANE)'s rule. Errors: a
    /// component, given or transformed, that is not finite; a singular modelview.
    fn plane_to_eye(&self, parameter: &'static str, p: glam::DVec4) -> Result<Vec4, StateError> {
        let components = p.to_array().map(|c| c as f32);
        finite_vec(parameter, &components)?;
        let eye = ClipPlanes::to_eye(p, self.modelview).ok_or(StateError::SingularClipModelview {
            determinant: self.modelview.as_dmat4().determinant(),
        })?;
        finite_vec(parameter, eye.to_array().as_slice())?;
        Ok(eye)
    }

    /// glAlphaFunc: the alpha test's function and reference, the reference clamped to [0, 1]
    /// as GL clamps it; a NaN reference is an error (ffvk's choice: GL leaves it undefined).
    pub fn alpha_func(&mut self, func: CompareFunc, reference: f32) -> Result<(), StateError> {
        if reference.is_nan() {
            return Err(StateError::NotFinite {
                parameter: "GL_ALPHA_TEST_REF",
                value: reference,
                valid: "a number (clamped to [0, 1])",
            });
        }
        let test = &mut self.lighting.fragment.alpha_test;
        test.func = func;
        test.reference = reference.clamp(0.0, 1.0);
        Ok(())
    }

    /// The enable of `GL_CLIP_PLANEi`, refusing i past [`MAX_CLIP_PLANES`](super::MAX_CLIP_PLANES).
    fn clip_plane_mut(&mut self, i: usize) -> Result<&mut bool, StateError> {
        self.lighting
            .clip
            .enabled
            .get_mut(i)
            .ok_or(StateError::OutOfRange {
                parameter: "GL_CLIP_PLANEi",
                value: i as f32,
                valid: "a plane index in 0..6 (GL_MAX_CLIP_PLANES)",
            })
    }

    /// glClipPlane(GL_CLIP_PLANEi, p): the plane stored in eye space, p · M⁻¹ with the
    /// modelview current now (§2.12); later modelview changes do not move it. Errors: i past
    /// [`MAX_CLIP_PLANES`](super::MAX_CLIP_PLANES), a component that is not finite, a singular modelview (GL leaves the
    /// plane undefined then).
    pub fn clip_plane(&mut self, i: usize, p: glam::DVec4) -> Result<(), StateError> {
        self.clip_plane_mut(i)?;
        let eye = self.plane_to_eye("GL_CLIP_PLANEi", p)?;
        self.lighting.clip.planes[i] = eye;
        Ok(())
    }

    /// glFog: GL's values and errors (a negative density is `GL_INVALID_VALUE`; the color is
    /// clamped to [0, 1]); a NaN or infinite value is an error (ffvk's choice).
    pub fn fog(&mut self, param: FogParam) -> Result<(), StateError> {
        let fog = &mut self.lighting.fragment.fog;
        match param {
            FogParam::Mode(mode) => fog.mode = mode,
            FogParam::Density(d) => {
                in_range("GL_FOG_DENSITY", d, 0.0, f32::MAX, "a value >= 0")?;
                fog.density = d;
            }
            FogParam::Start(s) => {
                finite_vec("GL_FOG_START", &[s])?;
                fog.start = s;
            }
            FogParam::End(e) => {
                finite_vec("GL_FOG_END", &[e])?;
                fog.end = e;
            }
            FogParam::Color(c) => {
                finite_vec("GL_FOG_COLOR", c.to_array().as_slice())?;
                fog.color = c.clamp(Vec4::ZERO, Vec4::ONE);
            }
            FogParam::CoordSrc(source) => fog.source = source,
        }
        Ok(())
    }

    /// glPointParameter: GL's values and errors (a negative minimum, maximum or fade threshold
    /// is `GL_INVALID_VALUE`); a NaN or infinite value is an error (ffvk's choice).
    pub fn point_parameter(&mut self, param: PointParam) -> Result<(), StateError> {
        let points = &mut self.lighting.points;
        match param {
            PointParam::SizeMin(v) => {
                in_range("GL_POINT_SIZE_MIN", v, 0.0, f32::MAX, "a value >= 0")?;
                points.size_min = v;
            }
            PointParam::SizeMax(v) => {
                in_range("GL_POINT_SIZE_MAX", v, 0.0, f32::MAX, "a value >= 0")?;
                points.size_max = v;
            }
            PointParam::FadeThresholdSize(v) => {
                in_range("GL_POINT_FADE_THRESHOLD_SIZE", v, 0.0, f32::MAX, "a value >= 0")?;
                points.fade_threshold = v;
            }
            PointParam::DistanceAttenuation(abc) => {
                finite_vec("GL_POINT_DISTANCE_ATTENUATION", abc.to_array().as_slice())?;
                points.distance_attenuation = abc;
            }
            PointParam::SpriteCoordOrigin(origin) => points.sprite_origin = origin,
        }
        Ok(())
    }

    /// glTexEnv(GL_POINT_SPRITE, GL_COORD_REPLACE, on): whether point sprites replace the
    /// texture unit's coordinates.
    pub fn coord_replace(&mut self, on: bool) {
        self.unit_mut().coord_replace = on;
    }

    /// glHint(GL_FOG_HINT): `GL_FASTEST` fogs per vertex, the others per fragment.
    pub fn fog_hint(&mut self, hint: FogHint) {
        self.lighting.fragment.fog.hint = hint;
    }

    /// glFogCoordf: the current fog coordinate, every vertex's in draws whose layout has no
    /// fog coordinate array; a NaN or infinite value is an error.
    pub fn fog_coord(&mut self, c: f32) -> Result<(), StateError> {
        finite_vec("GL_CURRENT_FOG_COORD", &[c])?;
        self.lighting.current_fog_coord = c;
        Ok(())
    }

    /// glSecondaryColor3f: the current secondary color (r, g, b, 1), every vertex's in draws
    /// whose layout has no secondary color array (summed with lighting off under
    /// `GL_COLOR_SUM`). Unclamped here, as GL clamps after lighting; a NaN or infinite
    /// component is an error.
    pub fn secondary_color(&mut self, rgb: Vec3) -> Result<(), StateError> {
        finite_vec("GL_CURRENT_SECONDARY_COLOR", rgb.to_array().as_slice())?;
        self.lighting.current_secondary_color = rgb.extend(1.0);
        Ok(())
    }

    /// glTexEnv on `GL_TEXTURE_ENV`.
    pub fn tex_env(&mut self, param: TexEnvParam) -> Result<(), StateError> {
        match param {
            TexEnvParam::Mode(mode) => self.unit_mut().env_mode = mode,
            TexEnvParam::Color(c) => {
                let c = finite4("GL_TEXTURE_ENV_COLOR", c)?;
                self.unit_mut().env_color = c.clamp(Vec4::ZERO, Vec4::ONE);
            }
            combine => self.tex_env_combine(combine)?,
        }
        Ok(())
    }

    /// glTexEnv's `GL_COMBINE` parameters, with GL's errors; nothing changes on one.
    fn tex_env_combine(&mut self, param: TexEnvParam) -> Result<(), StateError> {
        let argument = |n: usize| {
            if n < 3 {
                Ok(n)
            } else {
                Err(StateError::OutOfRange {
                    parameter: "the argument n of GL_SRCn_* or GL_OPERANDn_*",
                    value: n as f32,
                    valid: "0, 1 or 2",
                })
            }
        };
        let scale = |parameter: &'static str, s: f32| {
            if s == 1.0 || s == 2.0 || s == 4.0 {
                Ok(s)
            } else {
                Err(StateError::OutOfRange {
                    parameter,
                    value: s,
                    valid: "1.0, 2.0 or 4.0",
                })
            }
        };
        let source = |s: CombineSource| match s.unit() {
            Some(n) if n >= MAX_TEXTURE_UNITS => Err(StateError::OutOfRange {
                parameter: "GL_SRCn_RGB or GL_SRCn_ALPHA's GL_TEXTUREn",
                value: n as f32,
                valid: "a unit below GL_MAX_TEXTURE_UNITS (4)",
            }),
            _ => Ok(s),
        };
        let c = &mut self.unit_mut().combine;
        match param {
            TexEnvParam::CombineRgb(f) => c.rgb = f,
            TexEnvParam::CombineAlpha(f) if !f.is_alpha_function() => {
                return Err(StateError::NotAccepted {
                    parameter: "GL_COMBINE_ALPHA",
                    value: f.gl_name(),
                    valid: "GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE or GL_SUBTRACT",
                })
            }
            TexEnvParam::CombineAlpha(f) => c.alpha = f,
            TexEnvParam::SourceRgb(n, s) => c.rgb_sources[argument(n)?] = source(s)?,
            TexEnvParam::SourceAlpha(n, s) => c.alpha_sources[argument(n)?] = source(s)?,
            TexEnvParam::OperandRgb(n, o) => c.rgb_operands[argument(n)?] = o,
            TexEnvParam::OperandAlpha(n, o) => c.alpha_operands[argument(n)?] = o,
            TexEnvParam::RgbScale(s) => c.rgb_scale = scale("GL_RGB_SCALE", s)?,
            TexEnvParam::AlphaScale(s) => c.alpha_scale = scale("GL_ALPHA_SCALE", s)?,
            TexEnvParam::Mode(_) | TexEnvParam::Color(_) => {}
        }
        Ok(())
    }

    /// glLoadMatrix on the active unit's `GL_TEXTURE` stack.
    pub fn load_texture_matrix(&mut self, m: Mat4) -> Result<(), StateError> {
        finite_vec("GL_TEXTURE matrix", &m.to_cols_array())?;
        self.unit_mut().matrix = m;
        Ok(())
    }

    /// glEnable; fails only for a light index at or past [`MAX_LIGHTS`].
    pub fn enable(&mut self, cap: Cap) -> Result<(), StateError> {
        self.set_enabled(cap, true)
    }

    /// glDisable; fails only for a light index at or past [`MAX_LIGHTS`].
    pub fn disable(&mut self, cap: Cap) -> Result<(), StateError> {
        self.set_enabled(cap, false)
    }
}

/// `unit` when it is below [`MAX_TEXTURE_UNITS`], else GL's `GL_INVALID_ENUM` as an error.
fn check_unit(unit: usize) -> Result<usize, StateError> {
    if unit < MAX_TEXTURE_UNITS {
        Ok(unit)
    } else {
        Err(StateError::OutOfRange {
            parameter: "texture unit (GL_TEXTURE0 + i)",
            value: unit as f32,
            valid: "0 to 3 (GL_MAX_TEXTURE_UNITS is 4)",
        })
    }
}

fn finite4(parameter: &'static str, v: Vec4) -> Result<Vec4, StateError> {
    finite_vec(parameter, &v.to_array())?;
    Ok(v)
}
