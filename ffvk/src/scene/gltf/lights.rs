//! KHR_lights_punctual lights: read from the nodes that place them, and mapped onto GL's
//! fixed-function light ([`gl_light`]).

use super::Context;
use crate::gl::state::{Attenuation, Light, SpotEdge};
use glam::{Mat4, Vec3, Vec4};

/// A KHR_lights_punctual light type. Cone angles are in radians from the spot axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LightKind {
    /// Shines along the node's -Z from infinitely far away.
    Directional,
    /// Shines in every direction from the node's origin.
    Point,
    /// Shines from the node's origin along its -Z, within `outer_cone` of that axis.
    Spot {
        /// Where the falloff starts.
        inner_cone: f32,
        /// Where the light ends.
        outer_cone: f32,
    },
}

/// A KHR_lights_punctual light as placed by one node.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct PunctualLight {
    /// The light's name (or `light N`).
    pub name: String,
    /// Directional, point or spot (with its cones).
    pub kind: LightKind,
    /// Linear RGB.
    pub color: Vec3,
    /// Lux for directional lights, candela for point and spot lights.
    pub intensity: f32,
    /// The distance where the light's intensity may be taken as zero (ignored by [`gl_light`]).
    pub range: Option<f32>,
    /// The node's world transform; the light sits at its origin and shines along its -Z.
    pub world_transform: Mat4,
}

/// The GL spot exponent that makes GL's spot factor (cos θ)^e fall to one half halfway (in
/// cosine) between a glTF spot light's inner and outer cone, where glTF's own falloff,
/// linear in cos θ from 1 at the inner cone to 0 at the outer, is one half:
/// e = ln ½ / ln((cos inner + cos outer) / 2), clamped to [0, 128].
pub fn spot_exponent(inner_cone: f32, outer_cone: f32) -> f32 {
    let outer = outer_cone.clamp(0.0, std::f32::consts::FRAC_PI_2);
    let inner = inner_cone.clamp(0.0, outer);
    let half = (inner.cos() + outer.cos()) / 2.0;
    if half >= 1.0 - 1e-7 {
        return 128.0;
    }
    if half <= 0.0 {
        return 0.0;
    }
    (0.5f32.ln() / half.ln()).clamp(0.0, 128.0)
}

/// GL's fixed-function light for a KHR_lights_punctual light, in WORLD coordinates: GL keeps
/// light positions and spot directions in eye space, so the caller transforms `position` and
/// `spot_direction` by its view matrix (e.g. by setting them through `GlState::light` with
/// the view as the modelview).
///
/// * enabled; ambient black; diffuse = specular = (color · intensity, 1). Intensity is taken
///   as-is, one GL unit per lux (directional) or per candela (point, spot: with the
///   attenuation below this is lux at distance ≫ 1); physically scaled files need an
///   exposure scale by the caller;
/// * directional: position = (d, 0) with d the unit direction *toward* the light, the node's
///   +Z axis (the light shines along its -Z); no attenuation;
/// * point: position = (node origin, 1); attenuation k0 = 1, k1 = 0, k2 = 1, i.e.
///   1 / (1 + d²): glTF's inverse square law, kept finite at the light (within 1 % of 1/d²
///   beyond d = 10). `range` is ignored: GL has no cutoff distance;
/// * spot: as point, plus spot direction = the node's -Z axis (unit), cutoff = the outer
///   cone in degrees (clamped to [0, 90]) and the exponent of [`spot_exponent`].
pub fn gl_light(light: &PunctualLight) -> Light {
    let w = light.world_transform;
    let color = (light.color * light.intensity).extend(1.0);
    let mut gl = Light::gl_default(1);
    gl.enabled = true;
    gl.ambient = Vec4::new(0.0, 0.0, 0.0, 1.0);
    gl.diffuse = color;
    gl.specular = color;
    match light.kind {
        LightKind::Directional => {
            let toward = w.transform_vector3(Vec3::Z).normalize_or(Vec3::Z);
            gl.position = toward.extend(0.0);
        }
        LightKind::Point | LightKind::Spot { .. } => {
            gl.position = w.transform_point3(Vec3::ZERO).extend(1.0);
            gl.constant_attenuation = 1.0;
            gl.linear_attenuation = 0.0;
            gl.quadratic_attenuation = 1.0;
        }
    }
    if let LightKind::Spot {
        inner_cone,
        outer_cone,
    } = light.kind
    {
        gl.spot_direction = w.transform_vector3(Vec3::NEG_Z).normalize_or(Vec3::NEG_Z);
        gl.spot_cutoff = outer_cone.to_degrees().clamp(0.0, 90.0);
        gl.spot_exponent = spot_exponent(inner_cone, outer_cone);
    }
    gl
}

/// How a scene draws the KHR_lights_punctual lights of its glTF files (`gltf_lights`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum GltfLights {
    /// Left out.
    Off,
    /// Mapped onto GL's light ([`gl_light`]): GL's 1 / (1 + d²) attenuation and a spot
    /// exponent for the cone. The default.
    #[default]
    Gl,
    /// glTF's own falloff ([`exact_light`]): inverse square with the range window, and the
    /// smooth inner/outer cone (ffvk's lighting variants).
    Exact,
}

impl GltfLights {
    /// The word scene files and the command line use.
    pub fn name(self) -> &'static str {
        match self {
            GltfLights::Off => "off",
            GltfLights::Gl => "gl",
            GltfLights::Exact => "exact",
        }
    }
}

impl std::str::FromStr for GltfLights {
    type Err = crate::error::UnknownName;

    /// Reads "off", "gl", "exact", or "true" (gl) and "false" (off) as earlier versions wrote.
    fn from_str(word: &str) -> Result<Self, Self::Err> {
        match word {
            "off" | "false" => Ok(GltfLights::Off),
            "gl" | "true" => Ok(GltfLights::Gl),
            "exact" => Ok(GltfLights::Exact),
            _ => Err(crate::error::UnknownName::new(
                "glTF light mapping",
                word,
                "off, gl or exact (or true/false)",
            )),
        }
    }
}

/// [`gl_light`] with glTF's own falloff instead of GL's: attenuation
/// [`Attenuation::GltfInverseSquare`] with the light's range (1 / d², the range window), and
/// for a spot [`SpotEdge::SmoothstepInnerOuter`] between the inner and the outer cone (the
/// outer as `GL_SPOT_CUTOFF`); color, position and direction as [`gl_light`] sets them.
pub fn exact_light(light: &PunctualLight) -> Light {
    let mut gl = gl_light(light);
    if light.kind != LightKind::Directional {
        gl.attenuation = Attenuation::GltfInverseSquare { range: light.range };
    }
    if let LightKind::Spot { inner_cone, .. } = light.kind {
        let inner = inner_cone.to_degrees().clamp(0.0, gl.spot_cutoff);
        gl.spot_edge = SpotEdge::SmoothstepInnerOuter { inner_degrees: inner };
    }
    gl
}

/// The light `light` as placed by a node with world transform `world`.
pub(super) fn punctual_light(
    cx: &Context,
    light: gltf::khr_lights_punctual::Light,
    world: Mat4,
) -> PunctualLight {
    let l = light.index();
    let kind = match light.kind() {
        gltf::khr_lights_punctual::Kind::Directional => LightKind::Directional,
        gltf::khr_lights_punctual::Kind::Point => LightKind::Point,
        gltf::khr_lights_punctual::Kind::Spot {
            inner_cone_angle,
            outer_cone_angle,
        } => LightKind::Spot {
            inner_cone: inner_cone_angle,
            outer_cone: outer_cone_angle,
        },
    };
    PunctualLight {
        name: cx.light_name(l).unwrap_or_else(|| format!("light {l}")),
        kind,
        color: Vec3::from_array(light.color()),
        intensity: light.intensity(),
        range: light.range(),
        world_transform: world,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::gltf::load;
    use crate::scene::gltf::testing::{scratch_dir, Asset, QUAD};
    use std::f32::consts::{FRAC_PI_2, FRAC_PI_4, FRAC_PI_8};

    #[test]
    fn punctual_lights_are_placed_by_their_nodes() {
        let dir = scratch_dir("lights");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        // Nodes 1 and 3 turn -Z (the shine direction) to -Y: -90° about x.
        let s = std::f32::consts::FRAC_1_SQRT_2;
        let body = format!(
            r#""extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength"],
               "extensions": {{ "KHR_lights_punctual": {{ "lights": [
                 {{ "name": "sun", "type": "directional", "color": [1, 0.5, 0.25], "intensity": 2 }},
                 {{ "type": "point", "intensity": 10, "range": 4 }},
                 {{ "name": "torch", "type": "spot", "spot": {{ "innerConeAngle": {FRAC_PI_8}, "outerConeAngle": {FRAC_PI_4} }} }}
               ] }} }},
               "scene": 0, "scenes": [ {{ "nodes": [0, 1, 2] }} ],
               "nodes": [
                 {{ "mesh": 0 }},
                 {{ "rotation": [-{s}, 0, 0, {s}], "extensions": {{ "KHR_lights_punctual": {{ "light": 0 }} }} }},
                 {{ "translation": [0, 3, 0], "children": [3], "extensions": {{ "KHR_lights_punctual": {{ "light": 1 }} }} }},
                 {{ "translation": [1, 0, 0], "rotation": [-{s}, 0, 0, {s}], "extensions": {{ "KHR_lights_punctual": {{ "light": 2 }} }} }}
               ],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }}, "material": 0 }} ] }} ],
               "materials": [ {{ "emissiveFactor": [1, 0.5, 0], "extensions": {{ "KHR_materials_emissive_strength": {{ "emissiveStrength": 4 }} }} }} ],"#
        );
        let loaded = load(&a.write_gltf(&dir, "lights", &body)).unwrap();
        assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
        assert_eq!(loaded.meshes[0].material.as_ref().unwrap().emissive_strength, 4.0);
        let [sun, bulb, torch] = [0, 1, 2].map(|k| loaded.lights[k].clone());
        assert_eq!((sun.name.as_str(), sun.kind), ("sun", LightKind::Directional));
        assert_eq!(
            (sun.color, sun.intensity, sun.range),
            (Vec3::new(1.0, 0.5, 0.25), 2.0, None)
        );
        assert_eq!(
            (bulb.name.as_str(), bulb.kind, bulb.range),
            ("light 1", LightKind::Point, Some(4.0))
        );
        assert_eq!((bulb.color, bulb.intensity), (Vec3::ONE, 10.0));
        assert_eq!(
            torch.kind,
            LightKind::Spot {
                inner_cone: FRAC_PI_8,
                outer_cone: FRAC_PI_4
            }
        );
        assert_eq!(torch.intensity, 1.0);

        let gl = gl_light(&sun);
        assert!(gl.enabled);
        assert!(
            gl.position.abs_diff_eq(Vec4::new(0.0, 1.0, 0.0, 0.0), 1e-6),
            "toward the light: {}",
            gl.position
        );
        assert_eq!(gl.diffuse, Vec4::new(2.0, 1.0, 0.5, 1.0));
        assert_eq!(gl.specular, gl.diffuse);
        assert_eq!(gl.ambient, Vec4::new(0.0, 0.0, 0.0, 1.0));
        assert_eq!(
            (gl.constant_attenuation, gl.quadratic_attenuation, gl.spot_cutoff),
            (1.0, 0.0, 180.0)
        );

        let gl = gl_light(&bulb);
        assert_eq!(gl.position, Vec4::new(0.0, 3.0, 0.0, 1.0));
        assert_eq!(gl.diffuse, Vec4::new(10.0, 10.0, 10.0, 1.0));
        assert_eq!(
            (
                gl.constant_attenuation,
                gl.linear_attenuation,
                gl.quadratic_attenuation
            ),
            (1.0, 0.0, 1.0)
        );
        assert_eq!(gl.spot_cutoff, 180.0);

        let gl = gl_light(&torch);
        assert!(
            gl.position.abs_diff_eq(Vec4::new(1.0, 3.0, 0.0, 1.0), 1e-6),
            "{}",
            gl.position
        );
        assert!(
            gl.spot_direction.abs_diff_eq(Vec3::NEG_Y, 1e-6),
            "{}",
            gl.spot_direction
        );
        assert!((gl.spot_cutoff - 45.0).abs() < 1e-4);
        assert!((gl.spot_exponent - spot_exponent(FRAC_PI_8, FRAC_PI_4)).abs() < 1e-6);
        for l in [&sun, &bulb, &torch] {
            let mut state = crate::gl::state::FixedFunctionState::default();
            state.lights[0] = gl_light(l);
            state.validate().unwrap();
        }
    }

    #[test]
    fn the_exact_mapping_keeps_the_files_range_and_cones() {
        let spot = PunctualLight {
            name: "spot".into(),
            kind: LightKind::Spot {
                inner_cone: FRAC_PI_8,
                outer_cone: FRAC_PI_4,
            },
            color: Vec3::ONE,
            intensity: 10.0,
            range: Some(4.5),
            world_transform: Mat4::IDENTITY,
        };
        let l = exact_light(&spot);
        assert_eq!(l.attenuation, Attenuation::GltfInverseSquare { range: Some(4.5) });
        assert_eq!(l.spot_cutoff, 45.0);
        assert_eq!(
            l.spot_edge,
            SpotEdge::SmoothstepInnerOuter { inner_degrees: 22.5 }
        );
        // Colors, position and direction as GL's mapping sets them.
        let gl = gl_light(&spot);
        assert_eq!(
            (l.diffuse, l.position, l.spot_direction),
            (gl.diffuse, gl.position, gl.spot_direction)
        );
        // A directional light keeps GL's (it is never attenuated), whatever its range.
        let sun = PunctualLight {
            kind: LightKind::Directional,
            ..spot
        };
        assert_eq!(exact_light(&sun), gl_light(&sun));
        assert_eq!("true".parse(), Ok(GltfLights::Gl));
        assert_eq!("false".parse(), Ok(GltfLights::Off));
        assert_eq!(
            "physical".parse::<GltfLights>().map_err(|e| e.to_string()),
            Err(r#"unknown glTF light mapping "physical": expected off, gl or exact (or true/false)"#.into())
        );
    }

    #[test]
    fn spot_exponent_halves_the_spot_factor_midway_between_the_cones() {
        for (inner, outer) in [
            (0.0, FRAC_PI_4),
            (FRAC_PI_8, FRAC_PI_4),
            (0.2, 1.2),
            (0.0, FRAC_PI_2),
        ] {
            let e = spot_exponent(inner, outer);
            let half_cos = (f32::cos(inner) + f32::cos(outer)) / 2.0;
            assert!(
                (half_cos.powf(e) - 0.5).abs() < 1e-4,
                "inner {inner} outer {outer}: e = {e}"
            );
            assert!((0.0..=128.0).contains(&e));
        }
        assert_eq!(spot_exponent(0.0, 0.0), 128.0);
        assert_eq!(spot_exponent(0.01, 0.01), 128.0, "clamped");
    }
}
