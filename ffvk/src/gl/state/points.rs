//! GL's point parameters (2.1 §3.3, ARB_point_parameters, ARB_point_sprite): a point's size
//! from its eye-space distance, clamped, and point sprites.

use glam::Vec3;

/// `GL_POINT_SPRITE_COORD_ORIGIN`: where a point sprite's t = 0 lies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum SpriteOrigin {
    /// `GL_UPPER_LEFT` (the default): t runs from 0 at the sprite's top row to 1 at its bottom.
    #[default]
    UpperLeft,
    /// `GL_LOWER_LEFT`: t runs from 0 at the bottom to 1 at the top.
    LowerLeft,
}

/// The point state a draw of points reads beside `glPointSize` (which is the draw's raster
/// state, [`RasterState::point_size`](crate::RasterState::point_size)).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct PointParameters {
    /// `GL_POINT_SIZE_MIN`, ≥ 0; 0 by default.
    pub size_min: f32,
    /// `GL_POINT_SIZE_MAX`, ≥ 0; `f32::MAX` by default: GL's default is the implementation's
    /// largest size, and the device's `pointSizeRange` clamps what the shader writes.
    pub size_max: f32,
    /// `GL_POINT_DISTANCE_ATTENUATION` (a, b, c); (1, 0, 0) by default: no attenuation.
    pub distance_attenuation: Vec3,
    /// `GL_POINT_FADE_THRESHOLD_SIZE`, ≥ 0; 1 by default. GL fades points below it only with
    /// multisampling, which ffvk's targets do not have: kept for queries.
    pub fade_threshold: f32,
    /// `GL_POINT_SPRITE`; off by default. On, points are drawn at their derived size without
    /// rounding, and texture units with `GL_COORD_REPLACE` take the sprite's coordinates.
    pub sprite: bool,
    /// `GL_POINT_SPRITE_COORD_ORIGIN`.
    pub sprite_origin: SpriteOrigin,
}

impl Default for PointParameters {
    fn default() -> Self {
        PointParameters {
            size_min: 0.0,
            size_max: f32::MAX,
            distance_attenuation: Vec3::X,
            fade_threshold: 1.0,
            sprite: false,
            sprite_origin: SpriteOrigin::UpperLeft,
        }
    }
}

impl PointParameters {
    /// Whether the size depends on the distance: (a, b, c) ≠ (1, 0, 0).
    pub fn attenuated(&self) -> bool {
        self.distance_attenuation != Vec3::X
    }

    /// GL 2.1's derived size (§3.3) of a point of size `size` at eye-space distance `d` from
    /// the eye: size · √(1 / (a + b d + c d²)), clamped to [`size_min`, `size_max`] (the max
    /// first, so that a minimum above the maximum wins, as GL leaves undefined).
    ///
    /// [`size_min`]: PointParameters::size_min
    /// [`size_max`]: PointParameters::size_max
    pub fn derived_size(&self, size: f64, d: f64) -> f64 {
        let [a, b, c] = self.distance_attenuation.as_dvec3().to_array();
        let attenuated = size * (1.0 / (a + b * d + c * d * d)).sqrt();
        attenuated
            .min(f64::from(self.size_max))
            .max(f64::from(self.size_min))
    }

    /// The width a point of derived size `derived` is rasterized at: a sprite's as it is; an
    /// aliased point's rounded to the nearest integer, and 1 where that gives 0 (§3.3.1).
    pub fn raster_width(&self, derived: f64) -> f64 {
        if self.sprite {
            derived
        } else {
            (derived + 0.5).floor().max(1.0)
        }
    }
}

/// Parameters of glPointParameter.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum PointParam {
    /// `GL_POINT_SIZE_MIN`: a negative value is `GL_INVALID_VALUE`.
    SizeMin(f32),
    /// `GL_POINT_SIZE_MAX`: a negative value is `GL_INVALID_VALUE`.
    SizeMax(f32),
    /// `GL_POINT_FADE_THRESHOLD_SIZE`: a negative value is `GL_INVALID_VALUE`.
    FadeThresholdSize(f32),
    /// `GL_POINT_DISTANCE_ATTENUATION` (a, b, c): any finite values.
    DistanceAttenuation(Vec3),
    /// `GL_POINT_SPRITE_COORD_ORIGIN`.
    SpriteCoordOrigin(SpriteOrigin),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_derived_size_falls_with_the_distance_and_is_clamped_then_rounded_unless_a_sprite() {
        let mut p = PointParameters::default();
        assert!(!p.attenuated());
        assert_eq!(p.derived_size(3.0, 10.0), 3.0);
        p.distance_attenuation = Vec3::new(0.0, 0.0, 1.0);
        // size / d.
        assert_eq!(p.derived_size(20.0, 4.0), 5.0);
        p.size_max = 4.0;
        assert_eq!(p.derived_size(20.0, 4.0), 4.0);
        p.size_min = 6.0;
        assert_eq!(p.derived_size(20.0, 4.0), 6.0, "a minimum above the maximum wins");
        assert_eq!(p.raster_width(2.5), 3.0);
        assert_eq!(p.raster_width(0.2), 1.0);
        p.sprite = true;
        assert_eq!(p.raster_width(2.5), 2.5);
    }
}
