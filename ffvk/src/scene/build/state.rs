//! The scene file's GL state: light model, lights (GL's and ffvk's variants), color material
//! and materials, set through [`GlState`]'s entry points.

use super::super::*;
use super::Builder;

impl Builder<'_> {
    pub(super) fn light_model(&self, gl: &mut GlState, m: &LightModelSpec) -> Result<(), SceneError> {
        if let Some(a) = &m.ambient {
            let a = self.color("light_model.ambient", a)?;
            gl.light_model(LightModelParam::Ambient(a))
                .map_err(self.state("light_model.ambient"))?;
        }
        if let Some(b) = m.local_viewer {
            gl.light_model(LightModelParam::LocalViewer(b))
                .map_err(self.state("light_model.local_viewer"))?;
        }
        if let Some(b) = m.two_side {
            gl.light_model(LightModelParam::TwoSide(b))
                .map_err(self.state("light_model.two_side"))?;
        }
        if let Some(c) = &m.color_control {
            let control = match c.as_str() {
                "single_color" => ColorControl::SingleColor,
                "separate_specular_color" => ColorControl::SeparateSpecularColor,
                other => {
                    return Err(self.field(
                        "light_model.color_control",
                        format!(
                            "{:?}: expected \"single_color\" or \"separate_specular_color\"",
                            shorten(other)
                        ),
                    ))
                }
            };
            gl.light_model(LightModelParam::ColorControl(control))
                .map_err(self.state("light_model.color_control"))?;
        }
        if let Some(m) = &m.specular_model {
            let model = match m.as_str() {
                "blinn_halfway" => SpecularModel::BlinnHalfway,
                "phong_reflect" => SpecularModel::PhongReflect,
                other => {
                    return Err(self.field(
                        "light_model.specular_model",
                        format!(
                            "{:?}: expected \"blinn_halfway\" (GL's) or \"phong_reflect\"",
                            shorten(other)
                        ),
                    ))
                }
            };
            gl.light_model(LightModelParam::SpecularModel(model))
                .map_err(self.state("light_model.specular_model"))?;
        }
        Ok(())
    }

    /// The spot edge and attenuation of a `[[lights]]` table (ffvk's extensions), checked
    /// against each other and against the light's cone.
    pub(super) fn light_variants(
        &self,
        gl: &mut GlState,
        field: &str,
        index: usize,
        l: &LightSpec,
    ) -> Result<(), SceneError> {
        let f = |name: &str| format!("{field}.{name}");
        let inner = l.spot_inner_cutoff;
        let edge = match (l.spot_edge.as_deref(), inner) {
            (None | Some("gl_exponent"), None) => None,
            (None | Some("gl_exponent"), Some(v)) => {
                return Err(self.field(
                    f("spot_inner_cutoff"),
                    format!("{v}: a soft spot edge's inner angle, but the light has GL's edge: expected spot_edge = \"linear_inner_outer\" or \"smoothstep_inner_outer\" with it"),
                ))
            }
            (Some(kind @ ("linear_inner_outer" | "smoothstep_inner_outer")), None) => {
                return Err(self.field(
                    f("spot_inner_cutoff"),
                    format!("missing: spot_edge = \"{kind}\" needs the inner cone's half-angle in degrees, in [0, spot_cutoff]"),
                ))
            }
            (Some("linear_inner_outer"), Some(v)) => Some(SpotEdge::LinearInnerOuter { inner_degrees: v }),
            (Some("smoothstep_inner_outer"), Some(v)) => Some(SpotEdge::SmoothstepInnerOuter { inner_degrees: v }),
            (Some(other), _) => {
                return Err(self.field(
                    f("spot_edge"),
                    format!(
                        "{:?}: expected \"gl_exponent\" (GL's), \"linear_inner_outer\" or \"smoothstep_inner_outer\"",
                        shorten(other)
                    ),
                ))
            }
        };
        if let Some(edge) = edge {
            gl.light(index, LightParam::SpotEdge(edge))
                .map_err(self.state(f("spot_inner_cutoff")))?;
            let outer = gl.lighting.lights[index].spot_cutoff;
            if let Some(inner) = edge.inner_degrees().filter(|&i| outer != 180.0 && i > outer) {
                return Err(self.field(
                    f("spot_inner_cutoff"),
                    format!("{inner}: wider than the outer cone, spot_cutoff = {outer}: expected an inner angle <= {outer}"),
                ));
            }
        }
        let attenuation = match (l.attenuation.as_deref(), l.range) {
            (None | Some("gl_k012"), None) => None,
            (None | Some("gl_k012"), Some(r)) => {
                return Err(self.field(
                    f("range"),
                    format!("{r}: glTF's range, but the light has GL's attenuation: expected attenuation = \"gltf_inverse_square\" with it"),
                ))
            }
            (Some("gltf_inverse_square"), range) => Some(Attenuation::GltfInverseSquare { range }),
            (Some(other), _) => {
                return Err(self.field(
                    f("attenuation"),
                    format!(
                        "{:?}: expected \"gl_k012\" (GL's) or \"gltf_inverse_square\"",
                        shorten(other)
                    ),
                ))
            }
        };
        if let Some(a) = attenuation {
            gl.light(index, LightParam::Attenuation(a))
                .map_err(self.state(f("range")))?;
        }
        Ok(())
    }

    pub(super) fn color_material(&self, gl: &mut GlState, cm: &ColorMaterialSpec) -> Result<(), SceneError> {
        let face = match cm.face.as_deref().unwrap_or("front_and_back") {
            "front" => Face::Front,
            "back" => Face::Back,
            "front_and_back" => Face::FrontAndBack,
            other => {
                return Err(self.field(
                    "color_material.face",
                    format!(
                        "{:?}: expected \"front\", \"back\" or \"front_and_back\"",
                        shorten(other)
                    ),
                ))
            }
        };
        let mode = match cm.mode.as_deref().unwrap_or("ambient_and_diffuse") {
            "emission" => ColorMaterialMode::Emission,
            "ambient" => ColorMaterialMode::Ambient,
            "diffuse" => ColorMaterialMode::Diffuse,
            "specular" => ColorMaterialMode::Specular,
            "ambient_and_diffuse" => ColorMaterialMode::AmbientAndDiffuse,
            other => {
                return Err(self.field(
                    "color_material.mode",
                    format!("{:?}: expected \"emission\", \"ambient\", \"diffuse\", \"specular\" or \"ambient_and_diffuse\"", shorten(other)),
                ))
            }
        };
        gl.color_material(face, mode);
        // A [color_material] table enables it unless it says otherwise.
        gl.set_enabled(Cap::ColorMaterial, cm.enabled.unwrap_or(true))
            .map_err(self.state("color_material.enabled"))
    }

    pub(super) fn light(
        &self,
        gl: &mut GlState,
        field: &str,
        index: usize,
        l: &LightSpec,
        warnings: &mut Vec<String>,
    ) -> Result<(), SceneError> {
        let f = |name: &str| format!("{field}.{name}");
        let idx_field = f("index");
        gl.set_enabled(Cap::Light(index), l.enabled.unwrap_or(true))
            .map_err(self.state(idx_field))?;
        let colors = [
            (
                "ambient",
                &l.ambient,
                LightParam::Ambient as fn(Vec4) -> LightParam,
            ),
            ("diffuse", &l.diffuse, LightParam::Diffuse),
            ("specular", &l.specular, LightParam::Specular),
        ];
        for (name, value, param) in colors {
            if let Some(c) = value {
                let c = self.color(&f(name), c)?;
                gl.light(index, param(c)).map_err(self.state(f(name)))?;
            }
        }
        if let Some(p) = l.position {
            if p[3] == 0.0 && p[..3] == [0.0; 3] {
                warnings.push(format!(
                    "{}: (0, 0, 0, 0) is a directional light with no direction: legal GL, but its diffuse and specular terms light nothing (expected a nonzero x, y or z)",
                    f("position")
                ));
            }
            gl.light(index, LightParam::Position(Vec4::from(p)))
                .map_err(self.state(f("position")))?;
        }
        if let Some(d) = l.spot_direction {
            if d == [0.0; 3] && l.spot_cutoff.is_some_and(|c| c != 180.0) {
                warnings.push(format!(
                    "{}: (0, 0, 0) with a spot cutoff below 180: legal GL, but a spotlight with no direction lights nothing (expected a nonzero direction)",
                    f("spot_direction")
                ));
            }
            gl.light(index, LightParam::SpotDirection(Vec3::from(d)))
                .map_err(self.state(f("spot_direction")))?;
        }
        let scalars = [
            (
                "spot_exponent",
                l.spot_exponent,
                LightParam::SpotExponent as fn(f32) -> LightParam,
            ),
            ("spot_cutoff", l.spot_cutoff, LightParam::SpotCutoff),
            (
                "constant_attenuation",
                l.constant_attenuation,
                LightParam::ConstantAttenuation,
            ),
            (
                "linear_attenuation",
                l.linear_attenuation,
                LightParam::LinearAttenuation,
            ),
            (
                "quadratic_attenuation",
                l.quadratic_attenuation,
                LightParam::QuadraticAttenuation,
            ),
        ];
        for (name, value, param) in scalars {
            if let Some(v) = value {
                gl.light(index, param(v)).map_err(self.state(f(name)))?;
            }
        }
        self.light_variants(gl, field, index, l)
    }

    pub(super) fn material(&self, field: &str, m: &MaterialSpec) -> Result<Material, SceneError> {
        let mut material = match &m.preset {
            Some(name) => presets::preset(name).ok_or_else(|| {
                self.field(
                    format!("{field}.preset"),
                    format!(
                        "{:?} is not a preset: expected one of {}",
                        shorten(name),
                        presets::PRESET_NAMES.join(", ")
                    ),
                )
            })?,
            None => Material::default(),
        };
        let f = |name: &str| format!("{field}.{name}");
        if let Some(c) = &m.ambient {
            material.ambient = self.color(&f("ambient"), c)?;
        }
        if let Some(c) = &m.diffuse {
            material.diffuse = self.color(&f("diffuse"), c)?;
        }
        if let Some(c) = &m.specular {
            material.specular = self.color(&f("specular"), c)?;
        }
        if let Some(c) = &m.emission {
            material.emission = self.color(&f("emission"), c)?;
        }
        if let Some(s) = m.shininess {
            material.shininess = s;
        }
        material.validate().map_err(self.state(field))?;
        Ok(material)
    }
}
