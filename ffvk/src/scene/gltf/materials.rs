//! glTF metallic-roughness materials: their factors as read from the file, and mapped onto
//! GL's fixed-function material ([`gl_material`]).

use super::occlusion::OcclusionTexture;
use super::sampler::SampledTexture;
use super::textures::{TextureMean, Textures};
use super::Context;
use crate::gl::state::Material;
use glam::{Vec3, Vec4};

/// The factors of a glTF metallic-roughness material (textures are not read).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct PbrMaterial {
    /// The material's index in the file (`None` for glTF's default material).
    pub index: Option<usize>,
    /// The material's name, if the file gives one.
    pub name: Option<String>,
    /// baseColorFactor, linear RGBA.
    pub base_color_factor: Vec4,
    /// metallicFactor in [0, 1].
    pub metallic_factor: f32,
    /// roughnessFactor in [0, 1].
    pub roughness_factor: f32,
    /// emissiveFactor, linear RGB.
    pub emissive_factor: Vec3,
    /// KHR_materials_emissive_strength's emissiveStrength (1 without the extension).
    pub emissive_strength: f32,
    /// doubleSided, as the file gives it ([`gl_material`] does not use it).
    pub double_sided: bool,
    /// baseColorTexture, when the material has one (see [`TextureMean`]).
    pub base_color_texture: Option<TextureMean>,
    /// emissiveTexture, when the material has one.
    pub emissive_texture: Option<TextureMean>,
    /// The base color texture decoded for sampling (textures read, PNG or JPEG).
    pub base_color_sampled: Option<SampledTexture>,
    /// The occlusion texture decoded for sampling on `GL_TEXTURE1` (textures read, PNG or
    /// JPEG, from `TEXCOORD_0` or `TEXCOORD_1` where the primitive has it).
    pub occlusion_sampled: Option<OcclusionTexture>,
}

impl PbrMaterial {
    /// The material with its textures' means multiplied into the factors they scale, as glTF
    /// multiplies the texel into the factor: baseColorFactor × the base color texture's mean
    /// (RGBA), emissiveFactor × the emissive texture's mean (RGB). Unread textures count as
    /// white, so the factor stays as it is. A base color texture that is sampled is not
    /// averaged in: the texture environment multiplies it per fragment instead.
    pub fn with_texture_means(&self) -> PbrMaterial {
        let base = match self.base_color_sampled {
            Some(_) => Vec4::ONE,
            None => self.base_color_texture.map_or(Vec4::ONE, TextureMean::or_white),
        };
        let emissive = self.emissive_texture.map_or(Vec4::ONE, TextureMean::or_white);
        PbrMaterial {
            base_color_factor: self.base_color_factor * base,
            emissive_factor: self.emissive_factor * emissive.truncate(),
            ..self.clone()
        }
    }
}

impl Default for PbrMaterial {
    /// glTF's default material: white, fully metallic, fully rough, no emission.
    fn default() -> Self {
        PbrMaterial {
            index: None,
            name: None,
            base_color_factor: Vec4::ONE,
            metallic_factor: 1.0,
            roughness_factor: 1.0,
            emissive_factor: Vec3::ZERO,
            emissive_strength: 1.0,
            double_sided: false,
            base_color_texture: None,
            emissive_texture: None,
            base_color_sampled: None,
            occlusion_sampled: None,
        }
    }
}

/// GL's fixed-function material for a glTF metallic-roughness material.
///
/// With c = baseColorFactor.rgb, a = baseColorFactor.a, m = metallicFactor and
/// r = roughnessFactor (both clamped to [0, 1]):
///
/// * ambient = diffuse = (c, a);
/// * specular = (F0 · (1 − r), a) with F0 = mix(0.04, c, m), the Fresnel reflectance at
///   normal incidence of the metallic-roughness model (0.04 for dielectrics, the base color
///   for metals). The (1 − r) factor fades the highlight out as the lobe widens: at r = 1
///   GL's shininess is 0 and (n·h)^0 = 1 would otherwise add F0 uniformly to every lit point;
/// * shininess = clamp(2/α² − 2, 0, 128) with α = r², the Blinn-Phong exponent whose lobe
///   matches a GGX/Beckmann lobe of roughness α (r = 0.5 → 30, r ≤ 0.35 → 128, r = 1 → 0);
/// * emission = (emissiveFactor · emissiveStrength, a).
///
/// Every alpha is a; GL takes the lit alpha from the diffuse alpha alone. Textures are not
/// sampled. The result satisfies [`Material::validate`] for finite inputs.
pub fn gl_material(pbr: &PbrMaterial) -> Material {
    let c = pbr.base_color_factor.truncate();
    let a = pbr.base_color_factor.w;
    let metallic = pbr.metallic_factor.clamp(0.0, 1.0);
    let roughness = pbr.roughness_factor.clamp(0.0, 1.0);
    let f0 = Vec3::splat(0.04).lerp(c, metallic);
    let alpha = roughness * roughness;
    let shininess = if alpha * alpha <= 2.0 / 130.0 {
        128.0
    } else {
        (2.0 / (alpha * alpha) - 2.0).clamp(0.0, 128.0)
    };
    Material {
        ambient: c.extend(a),
        diffuse: c.extend(a),
        specular: (f0 * (1.0 - roughness)).extend(a),
        emission: (pbr.emissive_factor * pbr.emissive_strength).extend(a),
        shininess,
    }
}

/// The factors of a primitive's material; `None` for glTF's default material.
pub(super) fn pbr_material(cx: &Context, material: gltf::Material) -> Option<PbrMaterial> {
    let i = material.index()?;
    let pbr = material.pbr_metallic_roughness();
    Some(PbrMaterial {
        index: Some(i),
        name: cx.name("materials", i),
        base_color_factor: Vec4::from_array(pbr.base_color_factor()),
        metallic_factor: pbr.metallic_factor(),
        roughness_factor: pbr.roughness_factor(),
        emissive_factor: Vec3::from_array(material.emissive_factor()),
        emissive_strength: material.emissive_strength().unwrap_or(1.0),
        double_sided: material.double_sided(),
        // Filled in from the file's table of texture means after the walk.
        base_color_texture: None,
        emissive_texture: None,
        base_color_sampled: None,
        occlusion_sampled: None,
    })
}

/// One warning for all the materials that use textures ffvk does not sample: how many, the
/// first few by name, and what is done instead.
pub(super) fn texture_warnings(cx: &Context, document: &gltf::Document, textures: Textures) -> Vec<String> {
    let textured: Vec<String> = document
        .materials()
        .filter(|material| {
            let pbr = material.pbr_metallic_roughness();
            // Sampled base color and occlusion textures need no word here (an occlusion
            // texture that cannot be mapped has its own); the rest are left out or averaged.
            let sampled = textures == Textures::Means;
            ((pbr.base_color_texture().is_some() || material.occlusion_texture().is_some()) && !sampled)
                || pbr.metallic_roughness_texture().is_some()
                || material.normal_texture().is_some()
                || material.emissive_texture().is_some()
        })
        .map(|material| {
            let index = material.index().unwrap_or_default();
            match cx.name("materials", index) {
                Some(n) => format!("{index} ({:?})", crate::scene::shorten(&n)),
                None => index.to_string(),
            }
        })
        .collect();
    if textured.is_empty() {
        return Vec::new();
    }
    const SHOWN: usize = 4;
    let mut which = textured[..textured.len().min(SHOWN)].join(", ");
    if textured.len() > SHOWN {
        which.push_str(&format!(" and {} more", textured.len() - SHOWN));
    }
    let what = match textures {
        Textures::Ignore => "ffvk does not read them and uses the materials' factors",
        Textures::Means => {
            "emissive factors are multiplied by their texture's mean texel; normal and \
             metallic-roughness textures are ignored (base color textures are sampled on \
             GL_TEXTURE0 and occlusion textures on GL_TEXTURE1)"
        }
    };
    vec![format!(
        "{} material{} use{} textures (material {which}): {what}",
        textured.len(),
        if textured.len() == 1 { "" } else { "s" },
        if textured.len() == 1 { "s" } else { "" },
    )]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::gltf::load;
    use crate::scene::gltf::testing::{one_mesh_body, scratch_dir, Asset, QUAD};

    #[test]
    fn textures_are_reported_as_ignored() {
        let dir = scratch_dir("textures");
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }}, "material": 0 }}"#
        )) + r#""materials": [ { "name": "wood", "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 } } } ],
                 "textures": [ { "source": 0 } ], "images": [ { "uri": "wood.png" } ],"#;
        let loaded = load(&a.write_gltf(&dir, "textured", &body)).unwrap();
        assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
        assert!(
            loaded.warnings[0].contains("1 material uses textures")
                && loaded.warnings[0].contains("material 0 (\"wood\")")
                && loaded.warnings[0].contains("factors"),
            "{:?}",
            loaded.warnings
        );
        assert_eq!(
            loaded.meshes[0].material.as_ref().unwrap().base_color_texture,
            Some(TextureMean::Unread)
        );
        let pbr = loaded.meshes[0].material.clone().unwrap();
        assert_eq!(
            (pbr.base_color_factor, pbr.metallic_factor, pbr.roughness_factor),
            (Vec4::ONE, 1.0, 1.0)
        );
    }

    #[test]
    fn gl_material_follows_the_documented_rule() {
        let dielectric = PbrMaterial {
            base_color_factor: Vec4::new(0.8, 0.2, 0.1, 0.5),
            metallic_factor: 0.0,
            roughness_factor: 0.5,
            emissive_factor: Vec3::new(0.1, 0.2, 0.3),
            emissive_strength: 2.0,
            ..PbrMaterial::default()
        };
        let m = gl_material(&dielectric);
        assert_eq!(m.ambient, Vec4::new(0.8, 0.2, 0.1, 0.5));
        assert_eq!(m.diffuse, m.ambient);
        assert!(
            m.specular.abs_diff_eq(Vec4::new(0.02, 0.02, 0.02, 0.5), 1e-6),
            "{}",
            m.specular
        );
        assert!((m.shininess - 30.0).abs() < 1e-3, "{}", m.shininess);
        assert!(m.emission.abs_diff_eq(Vec4::new(0.2, 0.4, 0.6, 0.5), 1e-6));
        m.validate().unwrap();

        let polished_gold = PbrMaterial {
            base_color_factor: Vec4::new(1.0, 0.8, 0.3, 1.0),
            metallic_factor: 1.0,
            roughness_factor: 0.0,
            ..PbrMaterial::default()
        };
        let m = gl_material(&polished_gold);
        assert_eq!(m.specular, Vec4::new(1.0, 0.8, 0.3, 1.0));
        assert_eq!(m.shininess, 128.0);
        assert_eq!(m.emission, Vec4::new(0.0, 0.0, 0.0, 1.0));

        let m = gl_material(&PbrMaterial::default());
        assert_eq!(
            m.specular,
            Vec4::new(0.0, 0.0, 0.0, 1.0),
            "fully rough: no highlight"
        );
        assert_eq!(m.shininess, 0.0);

        for r in 0..=20 {
            let pbr = PbrMaterial {
                roughness_factor: r as f32 / 20.0,
                metallic_factor: 0.5,
                ..PbrMaterial::default()
            };
            gl_material(&pbr).validate().unwrap();
        }
        // Out-of-range factors are clamped, not propagated.
        let wild = PbrMaterial {
            metallic_factor: 3.0,
            roughness_factor: -1.0,
            ..PbrMaterial::default()
        };
        gl_material(&wild).validate().unwrap();
    }
}
