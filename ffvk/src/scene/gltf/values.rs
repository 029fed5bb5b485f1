//! The values the glTF 2.0 specification bounds (asset version, material factors,
//! KHR_lights_punctual lights): each checked before anything is drawn with it, so that an
//! out-of-range value is an error naming the object and the value rather than a light that
//! subtracts or a color clamped without a word.

use super::{Context, LoadError, LoadErrorKind};
use std::f32::consts::FRAC_PI_2;

/// Checks the asset's version, every material's factors and every punctual light.
pub(super) fn check(cx: &Context, document: &gltf::Document) -> Result<(), LoadError> {
    check_version(cx, document)?;
    for material in document.materials() {
        check_material(cx, &material)?;
    }
    if let Some(lights) = document.lights() {
        for light in lights {
            check_light(cx, &light)?;
        }
    }
    Ok(())
}

/// The members glTF 2.0 types as integers: indices into the file's arrays, byte counts,
/// counts and GL enums (and, for `nodes`, `children`, `joints`, `attributes` and `targets`,
/// the integers inside them). The `gltf` crate reads these as `value as u32`, so 2³² + 1
/// would quietly become 1.
const INTEGER_MEMBERS: &[&str] = &[
    "attributes",
    "buffer",
    "bufferView",
    "byteLength",
    "byteOffset",
    "byteStride",
    "camera",
    "children",
    "componentType",
    "count",
    "index",
    "indices",
    "input",
    "inverseBindMatrices",
    "joints",
    "light",
    "magFilter",
    "material",
    "mesh",
    "minFilter",
    "mode",
    "node",
    "nodes",
    "output",
    "sampler",
    "scene",
    "skeleton",
    "skin",
    "source",
    "target",
    "targets",
    "texCoord",
    "wrapS",
    "wrapT",
];

/// Every number of the file's JSON that its type cannot hold, as `path: value: expectation`:
/// a float (glTF stores them as float32) past float32's range, which would become an infinity
/// in a transform, a factor or a texture transform and fail later without the field that
/// holds it; an integer member ([`INTEGER_MEMBERS`]) that is not one from 0 to 2³² − 1.
/// `extras` and the objects of extensions ffvk does not read are left alone: they are for
/// other readers.
pub(super) fn out_of_range_numbers(raw: &gltf::json::Value) -> Vec<String> {
    use gltf::json::Value;
    let mut problems = Vec::new();
    // (JSON path, value, the member whose value (or part of it) this is)
    let mut stack: Vec<(String, &Value, &str)> = vec![(String::new(), raw, "")];
    while let Some((path, value, member)) = stack.pop() {
        match value {
            // (An integer member in range falls through to the arms below and matches none.)
            Value::Number(n)
                if INTEGER_MEMBERS.contains(&member)
                    && n.as_u64().is_none_or(|i| i > u64::from(u32::MAX)) =>
            {
                problems.push(format!(
                    "{path}: {}: expected an integer from 0 to {}",
                    crate::scene::shorten(&n.to_string()),
                    u32::MAX
                ));
            }
            Value::Number(n) if n.as_f64().is_some_and(|x| x.abs() > f64::from(f32::MAX)) => {
                problems.push(format!(
                    "{path}: {}: expected a number float32 holds (magnitude at most {:e})",
                    crate::scene::shorten(&n.to_string()),
                    f32::MAX
                ));
            }
            Value::Array(items) => stack.extend(
                items
                    .iter()
                    .enumerate()
                    .rev()
                    .map(|(i, item)| (format!("{path}[{i}]"), item, member)),
            ),
            Value::Object(members) => {
                let in_extensions = member == "extensions";
                // The members of `attributes` (and of each morph target) are accessor indices.
                let inner =
                    |key: &'static str| (member == "attributes" || member == "targets").then_some(key);
                let mut children: Vec<(String, &Value, &str)> = members
                    .iter()
                    .filter(|(key, _)| key.as_str() != "extras")
                    .filter(|(key, _)| !in_extensions || super::SUPPORTED_EXTENSIONS.contains(&key.as_str()))
                    .map(|(key, item)| {
                        let name = crate::scene::shorten(key);
                        let path = if path.is_empty() {
                            name
                        } else {
                            format!("{path}.{name}")
                        };
                        (path, item, inner("attributes").unwrap_or(key.as_str()))
                    })
                    .collect();
                children.reverse();
                stack.extend(children);
            }
            _ => {}
        }
    }
    problems
}

/// An out-of-range value of `object`'s `field`.
fn invalid(
    cx: &Context,
    object: String,
    field: &'static str,
    value: String,
    expected: &'static str,
) -> LoadError {
    cx.error(LoadErrorKind::InvalidValue {
        object,
        field,
        value: crate::scene::shorten(&value),
        expected,
    })
}

/// glTF 2.0 files say `asset.version` "2.0" (any "2.x" is forward compatible); a `minVersion`
/// above 2.0 asks for a reader this one is not.
fn check_version(cx: &Context, document: &gltf::Document) -> Result<(), LoadError> {
    let asset = &document.as_json().asset;
    let major_minor = |text: &str| -> Option<(u32, u32)> {
        let (major, minor) = text.split_once('.')?;
        Some((major.parse().ok()?, minor.parse().ok()?))
    };
    match major_minor(&asset.version) {
        Some((2, _)) => {}
        _ => {
            return Err(invalid(
                cx,
                "asset".into(),
                "version",
                format!("{:?}", asset.version),
                "\"2.0\" (or another 2.x): this is a glTF 2.0 reader",
            ))
        }
    }
    if let Some(min) = &asset.min_version {
        if !matches!(major_minor(min), Some((2, 0))) {
            return Err(invalid(
                cx,
                "asset".into(),
                "minVersion",
                format!("{min:?}"),
                "\"2.0\" or none: this reader implements glTF 2.0",
            ));
        }
    }
    Ok(())
}

fn in_unit_range(values: &[f32]) -> Option<f32> {
    values.iter().copied().find(|x| !(0.0..=1.0).contains(x))
}

fn check_material(cx: &Context, material: &gltf::Material) -> Result<(), LoadError> {
    let object = || {
        let index = material.index().unwrap_or_default();
        match cx.name("materials", index) {
            Some(name) => format!("material {index} ({:?})", crate::scene::shorten(&name)),
            None => format!("material {index}"),
        }
    };
    let pbr = material.pbr_metallic_roughness();
    let base = pbr.base_color_factor();
    if in_unit_range(&base).is_some() {
        return Err(invalid(
            cx,
            object(),
            "pbrMetallicRoughness.baseColorFactor",
            format!("{base:?}"),
            "four numbers in [0, 1]",
        ));
    }
    for (field, value) in [
        ("pbrMetallicRoughness.metallicFactor", pbr.metallic_factor()),
        ("pbrMetallicRoughness.roughnessFactor", pbr.roughness_factor()),
    ] {
        if in_unit_range(&[value]).is_some() {
            return Err(invalid(
                cx,
                object(),
                field,
                value.to_string(),
                "a number in [0, 1]",
            ));
        }
    }
    let emissive = material.emissive_factor();
    if in_unit_range(&emissive).is_some() {
        return Err(invalid(
            cx,
            object(),
            "emissiveFactor",
            format!("{emissive:?}"),
            "three numbers in [0, 1]",
        ));
    }
    super::occlusion::check(cx, material)?;
    if let Some(strength) = material.emissive_strength() {
        if !(strength >= 0.0 && strength.is_finite()) {
            return Err(invalid(
                cx,
                object(),
                "extensions.KHR_materials_emissive_strength.emissiveStrength",
                strength.to_string(),
                "a finite number >= 0",
            ));
        }
    }
    Ok(())
}

fn check_light(cx: &Context, light: &gltf::khr_lights_punctual::Light) -> Result<(), LoadError> {
    let object = || {
        let index = light.index();
        match cx.light_name(index) {
            Some(name) => format!(
                "KHR_lights_punctual light {index} ({:?})",
                crate::scene::shorten(&name)
            ),
            None => format!("KHR_lights_punctual light {index}"),
        }
    };
    let color = light.color();
    if in_unit_range(&color).is_some() {
        return Err(invalid(
            cx,
            object(),
            "color",
            format!("{color:?}"),
            "three numbers in [0, 1] (linear RGB)",
        ));
    }
    let intensity = light.intensity();
    if !(intensity >= 0.0 && intensity.is_finite()) {
        return Err(invalid(
            cx,
            object(),
            "intensity",
            intensity.to_string(),
            "a finite number >= 0 (candela or lux)",
        ));
    }
    if let Some(range) = light.range() {
        if !(range > 0.0 && range.is_finite()) {
            return Err(invalid(
                cx,
                object(),
                "range",
                range.to_string(),
                "a finite number > 0, or no range",
            ));
        }
    }
    if let gltf::khr_lights_punctual::Kind::Spot {
        inner_cone_angle,
        outer_cone_angle,
    } = light.kind()
    {
        if !(outer_cone_angle > 0.0 && outer_cone_angle <= FRAC_PI_2) {
            return Err(invalid(
                cx,
                object(),
                "spot.outerConeAngle",
                outer_cone_angle.to_string(),
                "radians in (0, π/2]",
            ));
        }
        if !(inner_cone_angle >= 0.0 && inner_cone_angle < outer_cone_angle) {
            return Err(invalid(
                cx,
                object(),
                "spot.innerConeAngle",
                format!("{inner_cone_angle} (outerConeAngle {outer_cone_angle})"),
                "radians in [0, outerConeAngle)",
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use crate::scene::gltf::load;
    use crate::scene::gltf::testing::{message, one_mesh_body, scratch_dir, Asset, QUAD};

    /// Loads a one-triangle file with `extra` JSON members and returns the error message.
    fn error_with(test: &str, extra: &str) -> String {
        let dir = scratch_dir("values");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }}, "material": 0 }}"#
        )) + extra;
        message(load(&a.write_gltf(&dir, test, &body)).unwrap_err())
    }

    fn with_material(test: &str, material: &str) -> String {
        error_with(test, &format!(r#""materials": [ {material} ],"#))
    }

    fn with_light(test: &str, light: &str) -> String {
        error_with(
            test,
            &format!(
                r#""materials": [ {{}} ], "extensionsUsed": ["KHR_lights_punctual"],
                   "extensions": {{ "KHR_lights_punctual": {{ "lights": [ {light} ] }} }},"#
            ),
        )
    }

    #[track_caller]
    fn assert_names(text: &str, parts: &[&str]) {
        for part in parts {
            assert!(text.contains(part), "{part:?} missing from: {text}");
        }
    }

    #[test]
    fn material_factors_outside_zero_to_one_are_errors() {
        let t = with_material(
            "base_color",
            r#"{ "name": "paint", "pbrMetallicRoughness": { "baseColorFactor": [2, -1, 0, 1] } }"#,
        );
        assert_names(
            &t,
            &[
                "base_color.gltf",
                "material 0 (\"paint\")",
                "baseColorFactor",
                "[2.0, -1.0, 0.0, 1.0]",
                "[0, 1]",
            ],
        );
        let t = with_material(
            "roughness",
            r#"{ "pbrMetallicRoughness": { "roughnessFactor": -1 } }"#,
        );
        assert_names(&t, &["material 0", "roughnessFactor", "-1", "in [0, 1]"]);
        let t = with_material(
            "metallic",
            r#"{ "pbrMetallicRoughness": { "metallicFactor": 1.5 } }"#,
        );
        assert_names(&t, &["metallicFactor", "1.5"]);
        let t = with_material("emissive", r#"{ "emissiveFactor": [0, 0, 3] }"#);
        assert_names(&t, &["emissiveFactor", "3.0"]);
        let t = error_with(
            "strength",
            r#""extensionsUsed": ["KHR_materials_emissive_strength"],
               "materials": [ { "extensions": { "KHR_materials_emissive_strength": { "emissiveStrength": -2 } } } ],"#,
        );
        assert_names(&t, &["emissiveStrength", "-2", ">= 0"]);
    }

    #[test]
    fn light_values_outside_the_extension_schema_are_errors() {
        let t = with_light(
            "intensity",
            r#"{ "name": "lamp", "type": "point", "intensity": -5 }"#,
        );
        assert_names(&t, &["light 0 (\"lamp\")", "intensity", "-5", ">= 0"]);
        let t = with_light("color", r#"{ "type": "point", "color": [1, -0.5, 0] }"#);
        assert_names(&t, &["color", "-0.5", "[0, 1]"]);
        let t = with_light("range", r#"{ "type": "point", "range": 0 }"#);
        assert_names(&t, &["range", "= 0", "> 0"]);
        let spot = |inner: f32, outer: f32| {
            format!(
                r#"{{ "type": "spot", "spot": {{ "innerConeAngle": {inner}, "outerConeAngle": {outer} }} }}"#
            )
        };
        let t = with_light("inner_above_outer", &spot(0.8, 0.4));
        assert_names(
            &t,
            &[
                "spot.innerConeAngle",
                "0.8 (outerConeAngle 0.4)",
                "[0, outerConeAngle)",
            ],
        );
        let t = with_light("inner_negative", &spot(-0.1, 0.4));
        assert_names(&t, &["spot.innerConeAngle", "-0.1"]);
        let t = with_light("outer_wide", &spot(0.1, 2.0));
        assert_names(&t, &["spot.outerConeAngle", "2", "(0, π/2]"]);
    }

    #[test]
    fn a_version_other_than_two_is_an_error() {
        let dir = scratch_dir("values");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = one_mesh_body(&format!(r#"{{ "attributes": {{ "POSITION": {pos} }} }}"#));
        let path = a.write_gltf(&dir, "version", &body);
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(
            text.contains(r#""version": "2.0""#),
            "the test asset's version field moved"
        );
        for (version, ok) in [("3.0", false), ("1.0", false), ("two", false), ("2.1", true)] {
            std::fs::write(
                &path,
                text.replace(r#""version": "2.0""#, &format!(r#""version": "{version}""#)),
            )
            .unwrap();
            match load(&path) {
                Ok(_) => assert!(ok, "version {version} loaded"),
                Err(e) => {
                    assert!(!ok, "version {version}: {e}");
                    assert_names(&message(e), &["asset", "version", version, "2.0"]);
                }
            }
        }
    }
}
