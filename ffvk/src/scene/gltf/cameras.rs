//! glTF cameras, as placed by the nodes that use them. A camera looks down its node's −Z with
//! +Y up, so its view matrix is the inverse of the node's world transform (glTF 2.0, 3.10).

use super::Context;
use glam::{Mat4, Vec3};

/// A glTF camera's projection, with the file's values (angles in radians).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CameraProjection {
    /// `perspective`: `zfar` absent means an infinite projection.
    Perspective {
        /// The vertical field of view, in radians (0 < yfov < π).
        yfov: f32,
        /// Width over height; `None` leaves it to the image's size.
        aspect_ratio: Option<f32>,
        /// The distance to the near clip plane (> 0).
        znear: f32,
        /// The distance to the far clip plane; `None` for an infinite projection.
        zfar: Option<f32>,
    },
    /// `orthographic`: half the view's width and height, and the clip planes.
    Orthographic {
        /// Half the view's width, in the camera's space (non-zero).
        xmag: f32,
        /// Half the view's height, in the camera's space (non-zero).
        ymag: f32,
        /// The distance to the near clip plane (≥ 0).
        znear: f32,
        /// The distance to the far clip plane (> znear).
        zfar: f32,
    },
}

/// A glTF camera as placed by one node.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct PlacedCamera {
    /// The camera's name, else `camera N`.
    pub name: String,
    /// Its index in the file's `cameras`.
    pub index: usize,
    /// Its projection, its values checked against the ranges glTF allows.
    pub projection: CameraProjection,
    /// The node's world transform: the camera sits at its origin, looks down its −Z, +Y up.
    pub world_transform: Mat4,
}

impl PlacedCamera {
    /// Where the camera is, in world space.
    pub fn eye(&self) -> Vec3 {
        self.world_transform.transform_point3(Vec3::ZERO)
    }

    /// The unit direction it looks in, in world space.
    pub fn forward(&self) -> Vec3 {
        self.world_transform
            .transform_vector3(Vec3::NEG_Z)
            .normalize_or(Vec3::NEG_Z)
    }

    /// Its unit up direction, in world space, made perpendicular to [`PlacedCamera::forward`]
    /// (a node transform with shear would tilt it otherwise).
    pub fn up(&self) -> Vec3 {
        let f = self.forward();
        let up = self.world_transform.transform_vector3(Vec3::Y);
        (up - f * up.dot(f)).normalize_or(f.any_orthonormal_vector())
    }
}

/// The camera `camera` as placed by a node with world transform `world`, or why it cannot be
/// used (a value outside what glTF allows): the caller warns and leaves it out.
pub(super) fn placed_camera(cx: &Context, camera: gltf::Camera, world: Mat4) -> Result<PlacedCamera, String> {
    let index = camera.index();
    let name = cx.name("cameras", index);
    let label = match &name {
        Some(n) => format!("camera {index} ({:?})", crate::scene::shorten(n)),
        None => format!("camera {index}"),
    };
    let projection = match camera.projection() {
        gltf::camera::Projection::Perspective(p) => {
            let (yfov, znear, zfar, aspect_ratio) = (p.yfov(), p.znear(), p.zfar(), p.aspect_ratio());
            if !(yfov > 0.0 && yfov < std::f32::consts::PI) {
                return Err(format!(
                    "{label}: yfov = {yfov}: expected radians in (0, π); the camera is not used"
                ));
            }
            if !(znear > 0.0 && znear.is_finite()) || zfar.is_some_and(|f| !(f > znear && f.is_finite())) {
                return Err(format!(
                    "{label}: znear = {znear}, zfar = {zfar:?}: expected 0 < znear < zfar; the camera is not used"
                ));
            }
            // The image keeps the ratio with each side in 1..=MAX_SIZE.
            let most = crate::scene::MAX_SIZE as f32;
            if let Some(a) = aspect_ratio.filter(|a| !(*a >= 1.0 / most && *a <= most)) {
                return Err(format!(
                    "{label}: aspectRatio = {a}: expected 1/{most} to {most} (an image's sides are \
                     1 to {most} pixels); the camera is not used"
                ));
            }
            CameraProjection::Perspective {
                yfov,
                aspect_ratio,
                znear,
                zfar,
            }
        }
        gltf::camera::Projection::Orthographic(o) => {
            let (xmag, ymag, znear, zfar) = (o.xmag(), o.ymag(), o.znear(), o.zfar());
            if !(xmag != 0.0 && ymag != 0.0 && xmag.is_finite() && ymag.is_finite()) {
                return Err(format!(
                    "{label}: xmag = {xmag}, ymag = {ymag}: expected non-zero finite values; the camera is not used"
                ));
            }
            let (most, ratio) = (crate::scene::MAX_SIZE as f32, (xmag / ymag).abs());
            if !(ratio >= 1.0 / most && ratio <= most) {
                return Err(format!(
                    "{label}: xmag / ymag = {ratio}: expected 1/{most} to {most} (the image's \
                     aspect ratio; its sides are 1 to {most} pixels); the camera is not used"
                ));
            }
            if !(znear >= 0.0 && zfar > znear && zfar.is_finite()) {
                return Err(format!(
                    "{label}: znear = {znear}, zfar = {zfar}: expected 0 ≤ znear < zfar; the camera is not used"
                ));
            }
            CameraProjection::Orthographic {
                xmag,
                ymag,
                znear,
                zfar,
            }
        }
    };
    if world.determinant() == 0.0 || !world.is_finite() {
        return Err(format!(
            "{label}: its node's transform is singular; the camera is not used"
        ));
    }
    Ok(PlacedCamera {
        name: name.unwrap_or_else(|| format!("camera {index}")),
        index,
        projection,
        world_transform: world,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::gltf::load;
    use crate::scene::gltf::testing::{scratch_dir, Asset, QUAD};

    #[test]
    fn cameras_are_placed_by_their_nodes_and_bad_ones_left_out_with_a_warning() {
        let dir = scratch_dir("cameras");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = format!(
            r#""scene": 0, "scenes": [ {{ "nodes": [0, 1, 2, 3] }} ],
               "nodes": [ {{ "mesh": 0 }},
                          {{ "camera": 0, "translation": [0, 0, 5] }},
                          {{ "camera": 1, "translation": [0, 10, 0], "rotation": [-0.70710677, 0, 0, 0.70710677] }},
                          {{ "camera": 2 }} ],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }} }} ] }} ],
               "cameras": [ {{ "name": "front", "type": "perspective", "perspective": {{ "yfov": 0.8, "znear": 0.1, "aspectRatio": 1.5 }} }},
                            {{ "type": "orthographic", "orthographic": {{ "xmag": 2, "ymag": 1, "znear": 0, "zfar": 20 }} }},
                            {{ "type": "perspective", "perspective": {{ "yfov": 0.8, "znear": 2, "zfar": 1 }} }} ],"#
        );
        let loaded = load(&a.write_gltf(&dir, "cameras", &body)).unwrap();
        assert_eq!(loaded.cameras.len(), 2, "{:?}", loaded.cameras);
        let front = &loaded.cameras[0];
        assert_eq!((front.name.as_str(), front.index), ("front", 0));
        assert_eq!(
            front.projection,
            CameraProjection::Perspective {
                yfov: 0.8,
                aspect_ratio: Some(1.5),
                znear: 0.1,
                zfar: None
            }
        );
        assert_eq!(front.eye(), Vec3::new(0.0, 0.0, 5.0));
        assert!(front.forward().abs_diff_eq(Vec3::NEG_Z, 1e-6));
        let top = &loaded.cameras[1];
        assert_eq!(top.name, "camera 1");
        assert!(top.forward().abs_diff_eq(Vec3::NEG_Y, 1e-6), "{}", top.forward());
        assert!(top.up().abs_diff_eq(Vec3::NEG_Z, 1e-6), "{}", top.up());
        assert!(
            loaded
                .warnings
                .iter()
                .any(|w| w.contains("camera 2") && w.contains("znear = 2")),
            "{:?}",
            loaded.warnings
        );
    }

    /// An aspect ratio no image of at most 16384 pixels a side can keep (it was clamped, so
    /// the image's ratio was not the camera's) leaves the camera out with a warning.
    #[test]
    fn an_aspect_ratio_past_16384_to_1_leaves_the_camera_out() {
        let dir = scratch_dir("camera_aspect");
        for (name, projection) in [
            (
                "wide",
                r#""type": "perspective", "perspective": { "yfov": 0.8, "znear": 0.1, "aspectRatio": 1e6 }"#,
            ),
            (
                "tall",
                r#""type": "perspective", "perspective": { "yfov": 0.8, "znear": 0.1, "aspectRatio": 1e-5 }"#,
            ),
            (
                "ortho",
                r#""type": "orthographic", "orthographic": { "xmag": 20000, "ymag": 1, "znear": 0, "zfar": 20 }"#,
            ),
        ] {
            let mut a = Asset::default();
            let pos = a.positions(&QUAD[..3]);
            let body = format!(
                r#""scene": 0, "scenes": [ {{ "nodes": [0, 1] }} ],
                   "nodes": [ {{ "mesh": 0 }}, {{ "camera": 0, "translation": [0, 0, 5] }} ],
                   "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos} }} }} ] }} ],
                   "cameras": [ {{ {projection} }} ],"#
            );
            let loaded = load(&a.write_gltf(&dir, name, &body)).unwrap();
            assert!(loaded.cameras.is_empty(), "{name}");
            assert!(
                loaded
                    .warnings
                    .iter()
                    .any(|w| w.contains("camera 0") && w.contains("expected 1/16384 to 16384")),
                "{name}: {:?}",
                loaded.warnings
            );
        }
    }
}
