//! GL's checks of light values: each light's ranges, and the cones of the enabled ones.

use super::{check_light_scalar, finite_vec, Light, LightParam, StateError, MAX_LIGHTS};

/// The lights' part of [`FixedFunctionState::validate`]: every light's values, and the cones of the
/// enabled ones (a disabled light may be half set up: its cones count once it is enabled).
pub(super) fn validate_lights(lights: &[Light; MAX_LIGHTS]) -> Result<(), StateError> {
    for (index, light) in lights.iter().enumerate() {
        validate_light(light)?;
        if light.enabled {
            check_cone(index, light)?;
        }
    }
    Ok(())
}

/// Checks one light's values against GL's ranges and that every value is finite.
pub fn validate_light(l: &Light) -> Result<(), StateError> {
    for (name, c) in [
        ("GL_AMBIENT", l.ambient),
        ("GL_DIFFUSE", l.diffuse),
        ("GL_SPECULAR", l.specular),
        ("GL_POSITION", l.position),
    ] {
        finite_vec(name, c.to_array().as_slice())?;
    }
    finite_vec("GL_SPOT_DIRECTION", l.spot_direction.to_array().as_slice())?;
    check_light_scalar(&LightParam::SpotExponent(l.spot_exponent))?;
    check_light_scalar(&LightParam::SpotCutoff(l.spot_cutoff))?;
    check_light_scalar(&LightParam::ConstantAttenuation(l.constant_attenuation))?;
    check_light_scalar(&LightParam::LinearAttenuation(l.linear_attenuation))?;
    check_light_scalar(&LightParam::QuadraticAttenuation(l.quadratic_attenuation))?;
    check_light_scalar(&LightParam::SpotEdge(l.spot_edge))?;
    check_light_scalar(&LightParam::Attenuation(l.attenuation))
}

/// A soft edge's inner cone must fit in the outer one (`GL_SPOT_CUTOFF`; no cone at 180).
fn check_cone(index: usize, l: &Light) -> Result<(), StateError> {
    match l.spot_edge.inner_degrees() {
        Some(inner) if l.spot_cutoff != 180.0 && inner > l.spot_cutoff => Err(StateError::SpotCone {
            light: index,
            inner,
            outer: l.spot_cutoff,
        }),
        _ => Ok(()),
    }
}
