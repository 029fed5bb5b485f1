//! The classic OpenGL material table: ambient, diffuse and specular reflectances and a
//! shininess coefficient for 24 named materials (gems, metals, plastics, rubbers), as widely
//! published for fixed-function GL (originally from "Advanced Graphics Programming Using
//! OpenGL").
//!
//! The table gives shininess as a coefficient in [0, 1]; GL's `GL_SHININESS` is that
//! coefficient × 128, which is what [`preset`] returns. Every preset has black emission and
//! alpha 1 in all four colors.

use crate::gl::state::Material;
use glam::Vec4;

/// One row of the table: name, ambient RGB, diffuse RGB, specular RGB, shininess coefficient.
struct Row {
    name: &'static str,
    ambient: [f32; 3],
    diffuse: [f32; 3],
    specular: [f32; 3],
    /// The table's coefficient; GL_SHININESS = coefficient × 128.
    shininess: f32,
}

const fn row(
    name: &'static str,
    ambient: [f32; 3],
    diffuse: [f32; 3],
    specular: [f32; 3],
    shininess: f32,
) -> Row {
    Row {
        name,
        ambient,
        diffuse,
        specular,
        shininess,
    }
}

/// The published table, digits as published (hence more than an f32 holds in two rows).
#[rustfmt::skip]
#[allow(clippy::excessive_precision)]
const TABLE: [Row; 24] = [
    row("emerald", [0.0215, 0.1745, 0.0215], [0.07568, 0.61424, 0.07568], [0.633, 0.727811, 0.633], 0.6),
    row("jade", [0.135, 0.2225, 0.1575], [0.54, 0.89, 0.63], [0.316228, 0.316228, 0.316228], 0.1),
    row("obsidian", [0.05375, 0.05, 0.06625], [0.18275, 0.17, 0.22525], [0.332741, 0.328634, 0.346435], 0.3),
    row("pearl", [0.25, 0.20725, 0.20725], [1.0, 0.829, 0.829], [0.296648, 0.296648, 0.296648], 0.088),
    row("ruby", [0.1745, 0.01175, 0.01175], [0.61424, 0.04136, 0.04136], [0.727811, 0.626959, 0.626959], 0.6),
    row("turquoise", [0.1, 0.18725, 0.1745], [0.396, 0.74151, 0.69102], [0.297254, 0.30829, 0.306678], 0.1),
    row("brass", [0.329412, 0.223529, 0.027451], [0.780392, 0.568627, 0.113725], [0.992157, 0.941176, 0.807843], 0.21794872),
    row("bronze", [0.2125, 0.1275, 0.054], [0.714, 0.4284, 0.18144], [0.393548, 0.271906, 0.166721], 0.2),
    row("chrome", [0.25, 0.25, 0.25], [0.4, 0.4, 0.4], [0.774597, 0.774597, 0.774597], 0.6),
    row("copper", [0.19125, 0.0735, 0.0225], [0.7038, 0.27048, 0.0828], [0.256777, 0.137622, 0.086014], 0.1),
    row("gold", [0.24725, 0.1995, 0.0745], [0.75164, 0.60648, 0.22648], [0.628281, 0.555802, 0.366065], 0.4),
    row("silver", [0.19225, 0.19225, 0.19225], [0.50754, 0.50754, 0.50754], [0.508273, 0.508273, 0.508273], 0.4),
    row("black_plastic", [0.0, 0.0, 0.0], [0.01, 0.01, 0.01], [0.5, 0.5, 0.5], 0.25),
    row("cyan_plastic", [0.0, 0.1, 0.06], [0.0, 0.50980392, 0.50980392], [0.50196078, 0.50196078, 0.50196078], 0.25),
    row("green_plastic", [0.0, 0.0, 0.0], [0.1, 0.35, 0.1], [0.45, 0.55, 0.45], 0.25),
    row("red_plastic", [0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [0.7, 0.6, 0.6], 0.25),
    row("white_plastic", [0.0, 0.0, 0.0], [0.55, 0.55, 0.55], [0.7, 0.7, 0.7], 0.25),
    row("yellow_plastic", [0.0, 0.0, 0.0], [0.5, 0.5, 0.0], [0.6, 0.6, 0.5], 0.25),
    row("black_rubber", [0.02, 0.02, 0.02], [0.01, 0.01, 0.01], [0.4, 0.4, 0.4], 0.078125),
    row("cyan_rubber", [0.0, 0.05, 0.05], [0.4, 0.5, 0.5], [0.04, 0.7, 0.7], 0.078125),
    row("green_rubber", [0.0, 0.05, 0.0], [0.4, 0.5, 0.4], [0.04, 0.7, 0.04], 0.078125),
    row("red_rubber", [0.05, 0.0, 0.0], [0.5, 0.4, 0.4], [0.7, 0.04, 0.04], 0.078125),
    row("white_rubber", [0.05, 0.05, 0.05], [0.5, 0.5, 0.5], [0.7, 0.7, 0.7], 0.078125),
    row("yellow_rubber", [0.05, 0.05, 0.0], [0.5, 0.5, 0.4], [0.7, 0.7, 0.04], 0.078125),
];

/// The canonical preset names, in table order (lower case, words joined by `_`).
pub const PRESET_NAMES: &[&str] = &[
    "emerald",
    "jade",
    "obsidian",
    "pearl",
    "ruby",
    "turquoise",
    "brass",
    "bronze",
    "chrome",
    "copper",
    "gold",
    "silver",
    "black_plastic",
    "cyan_plastic",
    "green_plastic",
    "red_plastic",
    "white_plastic",
    "yellow_plastic",
    "black_rubber",
    "cyan_rubber",
    "green_rubber",
    "red_rubber",
    "white_rubber",
    "yellow_rubber",
];

fn rgb1(c: [f32; 3]) -> Vec4 {
    Vec4::new(c[0], c[1], c[2], 1.0)
}

/// The GL material of a named preset, or `None` for an unknown name.
///
/// Names are matched case-insensitively, and a space or `-` is taken as `_`, so
/// `"black_plastic"`, `"Black Plastic"` and `"black-plastic"` are the same preset. Shininess is
/// the table's coefficient × 128; emission is black; every alpha is 1.
pub fn preset(name: &str) -> Option<Material> {
    let key: String = name
        .trim()
        .chars()
        .map(|c| match c {
            ' ' | '-' => '_',
            c => c.to_ascii_lowercase(),
        })
        .collect();
    TABLE.iter().find(|r| r.name == key).map(|r| Material {
        ambient: rgb1(r.ambient),
        diffuse: rgb1(r.diffuse),
        specular: rgb1(r.specular),
        emission: Vec4::new(0.0, 0.0, 0.0, 1.0),
        shininess: r.shininess * 128.0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_resolves_and_validates() {
        assert_eq!(PRESET_NAMES.len(), TABLE.len());
        for (name, row) in PRESET_NAMES.iter().zip(TABLE.iter()) {
            assert_eq!(
                *name, row.name,
                "PRESET_NAMES and the table are in the same order"
            );
            let m = preset(name).unwrap_or_else(|| panic!("preset {name} does not resolve"));
            assert!(
                (0.0..=128.0).contains(&m.shininess),
                "{name}: shininess {} outside [0, 128]",
                m.shininess
            );
            assert_eq!(m.emission, Vec4::new(0.0, 0.0, 0.0, 1.0), "{name}: emission");
            for c in [m.ambient, m.diffuse, m.specular] {
                assert_eq!(c.w, 1.0, "{name}: alpha");
                assert!(c.min_element() >= 0.0 && c.max_element() <= 1.0, "{name}: {c}");
            }
            m.validate().unwrap_or_else(|e| panic!("{name}: {e}"));
        }
    }

    #[test]
    fn emerald_matches_the_table() {
        let m = preset("emerald").unwrap();
        assert_eq!(m.ambient, Vec4::new(0.0215, 0.1745, 0.0215, 1.0));
        assert_eq!(m.diffuse, Vec4::new(0.07568, 0.61424, 0.07568, 1.0));
        assert_eq!(m.specular, Vec4::new(0.633, 0.727811, 0.633, 1.0));
        assert!((m.shininess - 76.8).abs() < 1e-4, "shininess {}", m.shininess);
    }

    #[test]
    fn spot_checks_of_other_rows() {
        let brass = preset("brass").unwrap();
        assert!((brass.shininess - 27.897436).abs() < 1e-3);
        let rubber = preset("white_rubber").unwrap();
        assert_eq!(rubber.shininess, 10.0);
        assert_eq!(preset("red_plastic").unwrap().shininess, 32.0);
        assert_eq!(
            preset("pearl").unwrap().diffuse,
            Vec4::new(1.0, 0.829, 0.829, 1.0)
        );
    }

    #[test]
    fn names_are_normalized_and_unknown_names_are_none() {
        assert_eq!(preset("Black Plastic"), preset("black_plastic"));
        assert_eq!(preset("black-plastic"), preset("black_plastic"));
        assert_eq!(preset(" GOLD "), preset("gold"));
        assert!(preset("black_plastic").is_some());
        assert!(preset("unobtainium").is_none());
        assert!(preset("").is_none());
    }
}
