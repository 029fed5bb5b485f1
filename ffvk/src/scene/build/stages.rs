//! The scene file's stages around lighting: `color_sum`, `[fog]`, `[alpha_test]` and
//! `[[clip_planes]]`, set on the state as a GL program's calls would, errors naming the field.

use super::*;
use crate::gl::state::{CompareFunc, FogHint, FogMode, FogParam, FogSource, PointParam, SpriteOrigin};
use crate::scene::file::{AlphaTestSpec, ClipPlaneSpec, FogSpec, PointsSpec};

impl Builder<'_> {
    /// A word of `choices` (GL's names in lowercase, without `GL_`), or an error naming the
    /// field and the words it takes.
    pub(in crate::scene) fn word<T: Copy>(
        &self,
        field: &str,
        given: &str,
        choices: &[(&str, T)],
    ) -> Result<T, SceneError> {
        choices
            .iter()
            .find(|(w, _)| *w == given)
            .map(|&(_, v)| v)
            .ok_or_else(|| {
                let words: Vec<String> = choices.iter().map(|(w, _)| format!("{w:?}")).collect();
                self.field(
                    field,
                    format!("{:?}: expected one of {}", shorten(given), words.join(", ")),
                )
            })
    }

    /// `color_sum`, `secondary_color`, `[fog]` and `[alpha_test]`.
    pub(super) fn fragment_stages(
        &self,
        gl: &mut GlState,
        color_sum: Option<bool>,
        secondary_color: Option<&[f32]>,
        fog: Option<&FogSpec>,
        alpha: Option<&AlphaTestSpec>,
    ) -> Result<(), SceneError> {
        gl.set_enabled(Cap::ColorSum, color_sum.unwrap_or(false))
            .map_err(self.state("color_sum"))?;
        if let Some(c) = secondary_color {
            let &[r, g, b] = c else {
                return Err(self.field(
                    "secondary_color",
                    format!(
                        "{c:?} has {} numbers: expected 3 (RGB, as glSecondaryColor3f)",
                        c.len()
                    ),
                ));
            };
            gl.secondary_color(glam::Vec3::new(r, g, b))
                .map_err(self.state("secondary_color"))?;
        }
        if let Some(f) = fog {
            if let Some(mode) = &f.mode {
                let modes = [
                    ("linear", FogMode::Linear),
                    ("exp", FogMode::Exp),
                    ("exp2", FogMode::Exp2),
                ];
                let mode = self.word("fog.mode", mode, &modes)?;
                gl.fog(FogParam::Mode(mode)).map_err(self.state("fog.mode"))?;
            }
            for (field, value, param) in [
                ("fog.density", f.density, FogParam::Density as fn(f32) -> FogParam),
                ("fog.start", f.start, FogParam::Start),
                ("fog.end", f.end, FogParam::End),
            ] {
                if let Some(v) = value {
                    gl.fog(param(v)).map_err(self.state(field))?;
                }
            }
            if let Some(c) = &f.color {
                let c = self.color("fog.color", c)?;
                gl.fog(FogParam::Color(c)).map_err(self.state("fog.color"))?;
            }
            if let Some(src) = &f.coord_src {
                let sources = [
                    ("fragment_depth", FogSource::FragmentDepth),
                    ("fog_coord", FogSource::FogCoord),
                ];
                let src = self.word("fog.coord_src", src, &sources)?;
                gl.fog(FogParam::CoordSrc(src))
                    .map_err(self.state("fog.coord_src"))?;
            }
            if let Some(c) = f.coord {
                gl.fog_coord(c).map_err(self.state("fog.coord"))?;
            }
            if let Some(hint) = &f.hint {
                let hints = [
                    ("dont_care", FogHint::DontCare),
                    ("fastest", FogHint::Fastest),
                    ("nicest", FogHint::Nicest),
                ];
                gl.fog_hint(self.word("fog.hint", hint, &hints)?);
            }
            gl.set_enabled(Cap::Fog, f.enabled.unwrap_or(true))
                .map_err(self.state("fog.enabled"))?;
        }
        if let Some(a) = alpha {
            let func = match &a.func {
                Some(func) => {
                    let names = CompareFunc::ALL.map(|f| (f.gl_name(), f));
                    let lower: Vec<(String, CompareFunc)> = names
                        .iter()
                        .map(|(n, f)| (n.trim_start_matches("GL_").to_lowercase(), *f))
                        .collect();
                    let choices: Vec<(&str, CompareFunc)> =
                        lower.iter().map(|(n, f)| (n.as_str(), *f)).collect();
                    self.word("alpha_test.func", func, &choices)?
                }
                None => CompareFunc::Always,
            };
            gl.alpha_func(func, a.reference.unwrap_or(0.0))
                .map_err(self.state("alpha_test.reference"))?;
            gl.set_enabled(Cap::AlphaTest, a.enabled.unwrap_or(true))
                .map_err(self.state("alpha_test.enabled"))?;
        }
        Ok(())
    }

    /// `[points]`: the point parameters on the state; returns glPointSize (1 by default).
    pub(super) fn points(&self, gl: &mut GlState, spec: Option<&PointsSpec>) -> Result<f32, SceneError> {
        let Some(p) = spec else {
            return Ok(1.0);
        };
        let size = p.size.unwrap_or(1.0);
        if !(size > 0.0 && size.is_finite()) {
            return Err(self.field(
                "points.size",
                format!("{size}: expected a finite size above 0 (GL_INVALID_VALUE in GL)"),
            ));
        }
        for (field, value, param) in [
            (
                "points.size_min",
                p.size_min,
                PointParam::SizeMin as fn(f32) -> PointParam,
            ),
            ("points.size_max", p.size_max, PointParam::SizeMax),
            (
                "points.fade_threshold_size",
                p.fade_threshold_size,
                PointParam::FadeThresholdSize,
            ),
        ] {
            if let Some(v) = value {
                gl.point_parameter(param(v)).map_err(self.state(field))?;
            }
        }
        if let Some(abc) = p.distance_attenuation {
            gl.point_parameter(PointParam::DistanceAttenuation(glam::Vec3::from_array(abc)))
                .map_err(self.state("points.distance_attenuation"))?;
        }
        if let Some(origin) = &p.sprite_coord_origin {
            let origins = [
                ("upper_left", SpriteOrigin::UpperLeft),
                ("lower_left", SpriteOrigin::LowerLeft),
            ];
            let origin = self.word("points.sprite_coord_origin", origin, &origins)?;
            gl.point_parameter(PointParam::SpriteCoordOrigin(origin))
                .map_err(self.state("points.sprite_coord_origin"))?;
        }
        gl.set_enabled(Cap::PointSprite, p.sprite.unwrap_or(false))
            .map_err(self.state("points.sprite"))?;
        Ok(size)
    }

    /// `[[clip_planes]]`, with the view loaded (world space), as lights are set.
    pub(super) fn clip_planes(&self, gl: &mut GlState, planes: &[ClipPlaneSpec]) -> Result<(), SceneError> {
        for (i, spec) in planes.iter().enumerate() {
            let field = |name: &str| format!("clip_planes[{i}].{name}");
            let index = spec.index.unwrap_or(i);
            let Some(e) = spec.equation else {
                return Err(self.field(
                    field("equation"),
                    "missing: expected [a, b, c, d], the plane a x + b y + c z + d w >= 0 kept",
                ));
            };
            gl.clip_plane(index, glam::DVec4::from_array(e))
                .map_err(self.state(field("equation")))?;
            gl.set_enabled(Cap::ClipPlane(index), spec.enabled.unwrap_or(true))
                .map_err(self.state(field("index")))?;
        }
        Ok(())
    }
}
