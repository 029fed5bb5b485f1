//! glTF's meaning for a scene that asks for it (`gltf_defaults = true`, and every glTF
//! rendered directly): the GL state glTF's renderer requirements correspond to, per mesh and
//! per scene, and the light units. Scene files without the switch keep GL's defaults.

use glam::{Mat4, Vec3, Vec4};

use super::gltf::{gl_light, GltfLights, LightKind, PunctualLight};
use crate::gl::state::{ColorMaterialMode, Face, FixedFunctionState};
use crate::mesh::MeshData;

/// What glTF asks of one mesh primitive, beyond its material.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct GltfMeaning {
    /// The material's `doubleSided`: two-sided lighting and no culling; otherwise one-sided
    /// lighting with back faces culled.
    pub double_sided: bool,
    /// COLOR_0 multiplies the base color: the vertex colors hold COLOR_0 × baseColorFactor and
    /// color material (ambient and diffuse, both faces) takes them.
    pub color_material: bool,
}

impl GltfMeaning {
    /// `state` as glTF asks for this mesh.
    pub(super) fn apply(&self, state: &mut FixedFunctionState) {
        state.model.two_side = self.double_sided;
        if self.color_material {
            state.color_material.enabled = true;
            state.color_material.face = Face::FrontAndBack;
            state.color_material.mode = ColorMaterialMode::AmbientAndDiffuse;
        }
    }

    /// The faces culled: none for double-sided materials, back faces otherwise.
    pub fn cull_face(&self) -> Option<Face> {
        (!self.double_sided).then_some(Face::Back)
    }

    /// One line for `ffvk explain`.
    pub fn describe(&self) -> String {
        let sides = if self.double_sided {
            "doubleSided: two-sided lighting, no culling"
        } else {
            "single-sided: one-sided lighting, back faces culled"
        };
        if self.color_material {
            format!("{sides}; COLOR_0 × baseColorFactor through color material (ambient and diffuse)")
        } else {
            sides.to_owned()
        }
    }
}

/// Multiplies every vertex color by `base` (COLOR_0 × baseColorFactor, as glTF defines the
/// base color).
pub(super) fn multiply_colors(data: &mut MeshData, base: Vec4) {
    for v in &mut data.vertices {
        v.color = (Vec4::from_array(v.color) * base).to_array();
    }
}

/// The world-space box around every vertex of `meshes` (each under its model matrix), or
/// `None` when there are no vertices.
pub(crate) fn world_bounds<'a>(
    meshes: impl IntoIterator<Item = (&'a MeshData, Mat4)>,
) -> Option<(Vec3, Vec3)> {
    let mut lo = Vec3::splat(f32::INFINITY);
    let mut hi = Vec3::splat(f32::NEG_INFINITY);
    for (data, model) in meshes {
        for v in &data.vertices {
            let p = model.transform_point3(Vec3::from_array(v.position));
            lo = lo.min(p);
            hi = hi.max(p);
        }
    }
    (lo.cmple(hi).all() && lo.is_finite() && hi.is_finite()).then_some((lo, hi))
}

/// The illuminance `auto` exposure gives the center of the scene, and the headlight's color:
/// 0.75, so that a white surface facing the light, with GL's scene ambient of 0.2 added, stays
/// just under 1 instead of clipping.
pub const KEY_LIGHT: f32 = 0.75;

/// The exposure `auto` chooses: the scale of GL light color per glTF unit (lux, candela) that
/// makes the glTF lights, as [`gl_light`] maps them, together light the center of the scene's
/// bounds with an illuminance of `KEY_LIGHT` (0.75) (in GL units: 1 is a white light falling
/// head-on). Each light counts with
/// its brightest channel and GL's attenuation at its distance from the center; a point or spot
/// light counts at no less than half the bounds' radius, so that a lamp inside its own shade
/// does not darken the rest of the scene. Spot cones are not counted. 1 when nothing lights.
pub fn auto_exposure(lights: &[(PunctualLight, Mat4)], bounds: Option<(Vec3, Vec3)>) -> f32 {
    auto_exposure_for(lights, bounds, GltfLights::Gl)
}

/// [`auto_exposure`] for the lights as `mapping` draws them: with [`GltfLights::Exact`] each
/// point or spot light counts with glTF's falloff (1 / d² and its range window) instead of
/// GL's 1 / (1 + d²).
pub fn auto_exposure_for(
    lights: &[(PunctualLight, Mat4)],
    bounds: Option<(Vec3, Vec3)>,
    mapping: GltfLights,
) -> f32 {
    let (center, radius) = match bounds {
        Some((lo, hi)) => ((lo + hi) / 2.0, (hi - lo).length() / 2.0),
        None => (Vec3::ZERO, 0.0),
    };
    let mut total = 0.0f64;
    for (light, model) in lights {
        let gl = gl_light(light);
        let brightest = f64::from(gl.diffuse.truncate().max_element());
        let attenuation = match light.kind {
            LightKind::Directional => 1.0,
            LightKind::Point | LightKind::Spot { .. } => {
                let at = model.transform_point3(gl.position.truncate());
                let d = f64::from((at - center).length().max(radius / 2.0));
                let k = [
                    gl.constant_attenuation,
                    gl.linear_attenuation,
                    gl.quadratic_attenuation,
                ]
                .map(f64::from);
                match mapping {
                    GltfLights::Exact => crate::reference::gltf_inverse_square(d, light.range.map(f64::from)),
                    _ => 1.0 / (k[0] + k[1] * d + k[2] * d * d),
                }
            }
        };
        total += brightest * attenuation;
    }
    if total > 0.0 && total.is_finite() {
        (f64::from(KEY_LIGHT) / total) as f32
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn light(kind: LightKind, intensity: f32, at: Vec3) -> (PunctualLight, Mat4) {
        let light = PunctualLight {
            name: "l".into(),
            kind,
            color: Vec3::new(1.0, 0.5, 0.5),
            intensity,
            range: None,
            world_transform: Mat4::from_translation(at),
        };
        (light, Mat4::IDENTITY)
    }

    #[test]
    fn auto_exposure_lights_the_center_with_the_key_illuminance() {
        let bounds = Some((Vec3::splat(-1.0), Vec3::splat(1.0)));
        let key = KEY_LIGHT;
        // A 3 lux sun: 0.75 / 3.
        let sun = light(LightKind::Directional, 3.0, Vec3::ZERO);
        assert!((auto_exposure(std::slice::from_ref(&sun), bounds) - key / 3.0).abs() < 1e-6);
        // A 100 cd lamp 3 units from the center: GL's 1/(1 + d²) gives 10 lux there.
        let lamp = light(LightKind::Point, 100.0, Vec3::new(0.0, 3.0, 0.0));
        assert!((auto_exposure(std::slice::from_ref(&lamp), bounds) - key / 10.0).abs() < 1e-6);
        // Together: 13 lux.
        assert!((auto_exposure(&[sun, lamp], bounds) - key / 13.0).abs() < 1e-6);
        // A lamp at the center counts at half the radius (√3 / 2): 100 / (1 + 0.75) lux.
        let inside = light(LightKind::Point, 100.0, Vec3::ZERO);
        assert!((auto_exposure(&[inside], bounds) - key * 1.75 / 100.0).abs() < 1e-6);
        assert_eq!(auto_exposure(&[], bounds), 1.0);
        let dark = light(LightKind::Directional, 0.0, Vec3::ZERO);
        assert_eq!(auto_exposure(&[dark], bounds), 1.0);
    }

    #[test]
    fn bounds_cover_every_vertex_under_its_model_matrix() {
        let sphere = crate::mesh::MeshData::uv_sphere(16, 8);
        let model = Mat4::from_translation(Vec3::new(10.0, 0.0, 0.0)) * Mat4::from_scale(Vec3::splat(2.0));
        let (lo, hi) = world_bounds([(&sphere, model)]).unwrap();
        assert!(lo.abs_diff_eq(Vec3::new(8.0, -2.0, -2.0), 1e-5), "{lo}");
        assert!(hi.abs_diff_eq(Vec3::new(12.0, 2.0, 2.0), 1e-5), "{hi}");
        assert_eq!(world_bounds([]), None);
    }
}
