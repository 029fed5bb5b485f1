//! A material's occlusion texture as GL's second texture unit samples it: the image as a
//! `GL_LUMINANCE` texture (glTF keeps occlusion in the R channel; in ORM-packed files the
//! image is the metallic-roughness one), `strength` baked into its texels, its sampler and
//! KHR_texture_transform as the base color's, read from `TEXCOORD_0` or `TEXCOORD_1`.
//!
//! The one deviation of the mapping: glTF's occlusion darkens only the indirect (ambient)
//! light, and GL's fixed function has no texture path that reaches the ambient term alone, so
//! the `GL_MODULATE` unit darkens the whole lit color.

use super::sampler::{sampling, transform_matrix, SampledTexture};
use super::{Context, LoadError, LoadErrorKind, LoadedMesh};
use crate::gl::texture::{BaseFormat, TextureImage};
use glam::Mat4;
use gltf::json::extensions::texture::TextureTransform;
use std::collections::HashMap;
use std::sync::Arc;

/// A material's occlusion texture, ready to sample on `GL_TEXTURE1` through `GL_MODULATE`.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct OcclusionTexture {
    /// The image as `GL_LUMINANCE`: each texel's R, with `strength` baked in
    /// (1 + strength × (R − 1)), in R, G and B, alpha 1, with its mipmaps; glTF's sampler;
    /// KHR_texture_transform as the GL_TEXTURE matrix of unit 1.
    pub texture: SampledTexture,
    /// The `TEXCOORD_n` set it reads, 0 or 1 (KHR_texture_transform's `texCoord` before the
    /// texture's own).
    pub tex_coord: u32,
    /// `occlusionTexture.strength` (1 without it), already in the texels.
    pub strength: f32,
}

/// The luminance copies made so far, by glTF image and strength (its bits): materials that
/// share both share the copy.
pub(super) type Copies = HashMap<(usize, u32), Arc<TextureImage>>;

/// `material 3 ("paint")`, or `material 3` without a name.
pub(super) fn material_label(cx: &Context, index: usize) -> String {
    match cx.name("materials", index) {
        Some(name) => format!("material {index} ({:?})", crate::scene::shorten(&name)),
        None => format!("material {index}"),
    }
}

/// The KHR_texture_transform object of material `index`'s occlusion texture, read from the
/// JSON (the `gltf` crate reads the extension on a plain textureInfo only).
fn transform(cx: &Context, index: usize) -> Result<Option<TextureTransform>, LoadError> {
    let Some(value) = cx
        .raw
        .get("materials")
        .and_then(|m| m.get(index))
        .and_then(|m| m.get("occlusionTexture"))
        .and_then(|o| o.get("extensions"))
        .and_then(|e| e.get("KHR_texture_transform"))
    else {
        return Ok(None);
    };
    gltf::json::deserialize::from_value::<TextureTransform>(value.clone())
        .map(Some)
        .map_err(|e| {
            cx.error(LoadErrorKind::InvalidValue {
                object: material_label(cx, index),
                field: "occlusionTexture.extensions.KHR_texture_transform",
                value: crate::scene::shorten(&format!("{value} ({e})")),
                expected:
                    "an object of offset [u, v], rotation, scale [s, t] (numbers) and texCoord (an integer)",
            })
        })
}

/// What glTF bounds of an occlusion texture: `strength` in [0, 1], and a KHR_texture_transform
/// object of the extension's types.
pub(super) fn check(cx: &Context, material: &gltf::Material) -> Result<(), LoadError> {
    let (Some(info), Some(index)) = (material.occlusion_texture(), material.index()) else {
        return Ok(());
    };
    let strength = info.strength();
    if !(0.0..=1.0).contains(&strength) {
        return Err(cx.error(LoadErrorKind::InvalidValue {
            object: material_label(cx, index),
            field: "occlusionTexture.strength",
            value: strength.to_string(),
            expected: "a number in [0, 1]",
        }));
    }
    transform(cx, index).map(|_| ())
}

/// The `TEXCOORD_n` set `material`'s occlusion texture reads (KHR_texture_transform's
/// `texCoord` first), `None` without one.
pub(super) fn coordinate_set(cx: &Context, material: &gltf::Material) -> Option<u32> {
    let info = material.occlusion_texture()?;
    let own = info.tex_coord();
    let index = material.index()?;
    Some(match transform(cx, index) {
        Ok(Some(t)) => t.tex_coord.unwrap_or(own),
        _ => own,
    })
}

/// `image`'s level 0 as a `GL_LUMINANCE` texture of R with `strength` baked in, rounded to
/// the nearest byte: 255 − strength × (255 − R); mipmaps generated from it.
pub(super) fn luminance(image: &TextureImage, strength: f32) -> Result<TextureImage, String> {
    let level = &image.levels()[0];
    let strength = f64::from(strength.clamp(0.0, 1.0));
    let texels: Vec<u8> = level
        .rgba()
        .chunks_exact(4)
        .flat_map(|t| {
            let l = (255.0 - strength * (255.0 - f64::from(t[0]))).round() as u8;
            [l, l, l, 255]
        })
        .collect();
    TextureImage::new(level.width(), level.height(), texels)
        .map(|t| t.with_mipmaps().with_base_format(BaseFormat::Luminance))
        .map_err(|e| e.to_string())
}

/// A texture's decoded image, `None` when it could not be read (a warning says why).
pub(super) type Decode<'a> = dyn FnMut(&gltf::Texture) -> Result<Option<Arc<TextureImage>>, LoadError> + 'a;

/// What [`sampled`] reads and charges through: the texture decoder of
/// [`material_textures`](super::textures::material_textures) (its image, `None` when it could
/// not be read), and the scene's texture budget for a copy of `width` × `height` of image
/// `image`.
pub(super) struct Readers<'a> {
    pub(super) decode: &'a mut Decode<'a>,
    pub(super) charge: &'a mut dyn FnMut(usize, u32, u32) -> Result<(), LoadError>,
}

/// `material`'s occlusion texture ready to sample, when it has one that can be read: from
/// `TEXCOORD_0` or `TEXCOORD_1` (another set is a warning, the occlusion left out), its
/// luminance copy made once per image and strength.
pub(super) fn sampled(
    cx: &Context,
    material: &gltf::Material,
    readers: Readers,
    copies: &mut Copies,
    warnings: &mut Vec<String>,
) -> Result<Option<OcclusionTexture>, LoadError> {
    let (Some(info), Some(index)) = (material.occlusion_texture(), material.index()) else {
        return Ok(None);
    };
    let set = coordinate_set(cx, material).unwrap_or_default();
    if set > 1 {
        warnings.push(format!(
            "{}: occlusionTexture.texCoord = {set}: ffvk reads TEXCOORD_0 and TEXCOORD_1 only, so the material is drawn without its occlusion",
            material_label(cx, index)
        ));
        return Ok(None);
    }
    let texture = info.texture();
    let Some(image) = (readers.decode)(&texture)? else {
        return Ok(None);
    };
    let image_index = texture.source().index();
    let strength = info.strength();
    let copy = match copies.get(&(image_index, strength.to_bits())) {
        Some(copy) => copy.clone(),
        None => {
            let level = &image.levels()[0];
            (readers.charge)(image_index, level.width(), level.height())?;
            let copy = match luminance(&image, strength) {
                Ok(copy) => Arc::new(copy),
                Err(why) => {
                    warnings.push(format!(
                        "{}: occlusionTexture (image {image_index}): {why}; drawn without its occlusion",
                        material_label(cx, index)
                    ));
                    return Ok(None);
                }
            };
            copies.insert((image_index, strength.to_bits()), copy.clone());
            copy
        }
    };
    let matrix = match transform(cx, index)? {
        Some(t) => transform_matrix(t.offset.0, t.rotation.0, t.scale.0),
        None => Mat4::IDENTITY,
    };
    Ok(Some(OcclusionTexture {
        texture: SampledTexture {
            image: copy,
            sampling: sampling(&texture.sampler()),
            matrix,
            image_index,
        },
        tex_coord: set,
        strength,
    }))
}

/// Leaves out the occlusion of each mesh whose primitive lacks the `TEXCOORD_n` its material's
/// occlusion texture reads (glTF: a primitive has the texture coordinates its material
/// reads), with a warning naming the mesh, the material, the field and the value.
pub(super) fn drop_unmapped(meshes: &mut [LoadedMesh], cx: &Context, warnings: &mut Vec<String>) {
    for mesh in meshes {
        let Some(material) = mesh.material.as_mut() else {
            continue;
        };
        let Some(occlusion) = &material.occlusion_sampled else {
            continue;
        };
        let set = occlusion.tex_coord;
        let has = match set {
            0 => mesh.texcoords,
            _ => !mesh.data.second_texcoords.is_empty(),
        };
        if !has {
            warnings.push(format!(
                "mesh {:?}: {} has occlusionTexture.texCoord = {set}, but the primitive has no TEXCOORD_{set}: expected the texture coordinates its material reads (glTF), so it is drawn without its occlusion",
                crate::scene::shorten(&mesh.name),
                material_label(cx, material.index.unwrap_or_default()),
            ));
            material.occlusion_sampled = None;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::texture::{MagFilter, MinFilter, Wrap};
    use crate::scene::gltf::testing::{message, scratch_dir, Asset};
    use crate::scene::gltf::{load_with, Loaded, MeshBudget, Textures};
    use crate::scene::Limits;
    use glam::Vec4;

    const TRIANGLE: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]];
    const ST0: [[f32; 2]; 3] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]];
    const ST1: [[f32; 2]; 3] = [[0.25, 0.75], [0.5, 0.5], [0.75, 0.25]];

    /// A 2×2 ORM-packed image: occlusion in R (255, 127, 1, 51), roughness and metalness in G
    /// and B, which the occlusion texture must not read.
    fn orm_png(dir: &std::path::Path) {
        let mut orm = image::RgbaImage::new(2, 2);
        for (k, r) in [255u8, 127, 1, 51].into_iter().enumerate() {
            orm.put_pixel(k as u32 % 2, k as u32 / 2, image::Rgba([r, 10, 200, 255]));
        }
        orm.save(dir.join("orm.png")).unwrap();
    }

    fn vec2s(a: &mut Asset, v: &[[f32; 2]]) -> usize {
        let bytes: Vec<u8> = v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
        a.accessor(&bytes, 5126, v.len(), "VEC2", "")
    }

    /// A file of one mesh whose primitives are `primitives` (JSON, each naming `{pos}`,
    /// `{st0}`, `{st1}` or `{normal}` for the triangle's accessors), its materials
    /// `materials`, one texture of `orm.png`.
    fn write(dir: &std::path::Path, name: &str, primitives: &[&str], materials: &str) -> std::path::PathBuf {
        orm_png(dir);
        let mut a = Asset::default();
        let pos = a.positions(&TRIANGLE);
        let st0 = vec2s(&mut a, &ST0);
        let st1 = vec2s(&mut a, &ST1);
        let normal = a.vec3s(&[[0.0, 0.0, 1.0]; 3]);
        let primitives: Vec<String> = primitives
            .iter()
            .map(|p| {
                p.replace("{pos}", &pos.to_string())
                    .replace("{st0}", &st0.to_string())
                    .replace("{st1}", &st1.to_string())
                    .replace("{normal}", &normal.to_string())
            })
            .collect();
        let body = format!(
            r#""scene": 0, "scenes": [ {{ "nodes": [0] }} ], "nodes": [ {{ "mesh": 0 }} ],
               "meshes": [ {{ "name": "thing", "primitives": [ {} ] }} ],
               "materials": [ {materials} ],
               "extensionsUsed": ["KHR_texture_transform"],
               "textures": [ {{ "source": 0 }} ], "images": [ {{ "uri": "orm.png" }} ],"#,
            primitives.join(", ")
        );
        a.write_gltf(dir, name, &body)
    }

    fn load_textured(path: &std::path::Path, textures: Textures) -> Result<Loaded, LoadError> {
        let limits = Limits::default();
        load_with(path, &limits, &mut MeshBudget::new(limits.mesh_bytes), textures)
    }

    /// The luminance texels of level 0, row by row.
    fn luminances(t: &OcclusionTexture) -> Vec<[u8; 4]> {
        let level = &t.texture.image.levels()[0];
        (0..4).map(|k| level.texel(k % 2, k / 2)).collect()
    }

    #[test]
    fn occlusion_textures_map_to_unit_1_as_luminance_from_either_texcoord_set_with_strength_baked() {
        let dir = scratch_dir("occlusion_mapped");
        let path = write(
            &dir,
            "orm",
            &[
                r#"{ "attributes": { "POSITION": {pos}, "TEXCOORD_0": {st0} }, "material": 0 }"#,
                r#"{ "attributes": { "POSITION": {pos}, "NORMAL": {normal}, "TEXCOORD_0": {st0}, "TEXCOORD_1": {st1} }, "material": 1 }"#,
            ],
            r#"{ "name": "plain", "occlusionTexture": { "index": 0 } },
               { "name": "orm", "occlusionTexture": { "index": 0, "texCoord": 1, "strength": 0.5,
                   "extensions": { "KHR_texture_transform": { "offset": [0.5, 0], "scale": [2, 2] } } },
                 "pbrMetallicRoughness": { "metallicRoughnessTexture": { "index": 0 } } }"#,
        );
        let loaded = load_textured(&path, Textures::Means).unwrap();
        // One warning, for the metallic-roughness texture: the occlusion textures are drawn.
        assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
        let warning = &loaded.warnings[0];
        assert!(
            warning.contains("1 material uses textures (material 1 (\"orm\"))")
                && warning.contains("metallic-roughness textures are ignored")
                && !warning.contains("occlusion textures are ignored"),
            "{warning}"
        );
        let [plain, orm] = &loaded.meshes[..] else {
            panic!("{} meshes", loaded.meshes.len())
        };

        // texCoord 0 (the default), strength 1 (the default): R as luminance, G and B unread.
        let o = plain
            .material
            .as_ref()
            .unwrap()
            .occlusion_sampled
            .clone()
            .unwrap();
        assert_eq!((o.tex_coord, o.strength), (0, 1.0));
        assert_eq!(o.texture.image.base_format, BaseFormat::Luminance);
        assert_eq!(
            luminances(&o),
            [255, 127, 1, 51].map(|l| [l, l, l, 255]),
            "GL_LUMINANCE of R"
        );
        assert_eq!(o.texture.image.levels().len(), 2, "with its mipmaps");
        assert_eq!(o.texture.matrix, Mat4::IDENTITY);
        assert_eq!(o.texture.image_index, 0);
        assert_eq!(
            (o.texture.sampling.mag_filter, o.texture.sampling.min_filter),
            (MagFilter::Linear, MinFilter::LinearMipmapLinear)
        );
        assert_eq!(
            (o.texture.sampling.wrap_s, o.texture.sampling.wrap_t),
            (Wrap::Repeat, Wrap::Repeat)
        );
        assert!(
            plain.data.second_texcoords.is_empty(),
            "TEXCOORD_1 is read only for occlusion from it"
        );

        // texCoord 1: the primitive's TEXCOORD_1 rides along as the mesh's second set.
        let o = orm.material.as_ref().unwrap().occlusion_sampled.clone().unwrap();
        assert_eq!((o.tex_coord, o.strength), (1, 0.5));
        assert_eq!(orm.data.second_texcoords, ST1);
        let st0: Vec<[f32; 2]> = orm.data.vertices.iter().map(|v| v.texcoord).collect();
        assert_eq!(st0, ST0);
        // glTF: occlusion = 1 + strength × (texel − 1); in bytes 255 − 0.5 × (255 − R).
        assert_eq!(
            luminances(&o),
            [255, 191, 128, 153].map(|l| [l, l, l, 255]),
            "strength baked into the texels"
        );
        // KHR_texture_transform: (u, v) → offset + scale × (u, v).
        let p = o.texture.matrix * Vec4::new(1.0, 1.0, 0.0, 1.0);
        assert!(p.abs_diff_eq(Vec4::new(2.5, 2.0, 0.0, 1.0), 1e-6), "{p}");

        // Textures not read: no occlusion, no second set, and the summary warning names it.
        let ignored = load_textured(&path, Textures::Ignore).unwrap();
        for m in &ignored.meshes {
            assert_eq!(m.material.as_ref().unwrap().occlusion_sampled, None);
            assert!(m.data.second_texcoords.is_empty());
        }
        assert!(
            ignored
                .warnings
                .iter()
                .any(|w| w.contains("material 0 (\"plain\")")),
            "{:?}",
            ignored.warnings
        );
    }

    #[test]
    fn a_texture_transforms_texcoord_chooses_the_set_before_the_textures_own() {
        let dir = scratch_dir("occlusion_transform_set");
        let path = write(
            &dir,
            "override",
            &[
                r#"{ "attributes": { "POSITION": {pos}, "TEXCOORD_0": {st0}, "TEXCOORD_1": {st1} }, "material": 0 }"#,
            ],
            r#"{ "occlusionTexture": { "index": 0, "texCoord": 0,
                 "extensions": { "KHR_texture_transform": { "texCoord": 1 } } } }"#,
        );
        let loaded = load_textured(&path, Textures::Means).unwrap();
        let mesh = &loaded.meshes[0];
        let o = mesh
            .material
            .as_ref()
            .unwrap()
            .occlusion_sampled
            .as_ref()
            .unwrap();
        assert_eq!(o.tex_coord, 1);
        assert_eq!(mesh.data.second_texcoords, ST1);
    }

    #[test]
    fn occlusion_texcoord_sets_the_primitive_lacks_or_ffvk_does_not_read_are_warnings_naming_material_field_and_value(
    ) {
        let dir = scratch_dir("occlusion_sets");
        let path = write(
            &dir,
            "sets",
            &[
                // texCoord 1 without TEXCOORD_1.
                r#"{ "attributes": { "POSITION": {pos}, "TEXCOORD_0": {st0} }, "material": 0 }"#,
                // texCoord 0 without TEXCOORD_0.
                r#"{ "attributes": { "POSITION": {pos} }, "material": 1 }"#,
                // texCoord 2: ffvk reads two sets.
                r#"{ "attributes": { "POSITION": {pos}, "TEXCOORD_0": {st0}, "TEXCOORD_1": {st1} }, "material": 2 }"#,
            ],
            r#"{ "name": "wants one", "occlusionTexture": { "index": 0, "texCoord": 1 } },
               { "name": "wants zero", "occlusionTexture": { "index": 0 } },
               { "name": "wants two", "occlusionTexture": { "index": 0, "texCoord": 2 } }"#,
        );
        let loaded = load_textured(&path, Textures::Means).unwrap();
        for m in &loaded.meshes {
            assert_eq!(m.material.as_ref().unwrap().occlusion_sampled, None, "{}", m.name);
            assert!(m.data.second_texcoords.is_empty(), "{}", m.name);
        }
        let warned = |parts: &[&str]| {
            assert!(
                loaded
                    .warnings
                    .iter()
                    .any(|w| parts.iter().all(|p| w.contains(p))),
                "no warning with {parts:?}: {:?}",
                loaded.warnings
            )
        };
        warned(&[
            "mesh \"thing[0]\"",
            "material 0 (\"wants one\")",
            "occlusionTexture.texCoord = 1",
            "no TEXCOORD_1",
            "without its occlusion",
        ]);
        warned(&[
            "mesh \"thing[1]\"",
            "material 1 (\"wants zero\")",
            "occlusionTexture.texCoord = 0",
            "no TEXCOORD_0",
        ]);
        warned(&[
            "material 2 (\"wants two\")",
            "occlusionTexture.texCoord = 2",
            "TEXCOORD_0 and TEXCOORD_1 only",
        ]);
    }

    #[test]
    fn an_occlusion_strength_outside_0_to_1_or_a_malformed_transform_is_refused_naming_the_field() {
        let dir = scratch_dir("occlusion_values");
        let primitive = [r#"{ "attributes": { "POSITION": {pos}, "TEXCOORD_0": {st0} }, "material": 0 }"#];
        let path = write(
            &dir,
            "strength",
            &primitive,
            r#"{ "name": "dark", "occlusionTexture": { "index": 0, "strength": 1.5 } }"#,
        );
        let text = message(load_textured(&path, Textures::Ignore).unwrap_err());
        for part in [
            "strength.gltf",
            "material 0 (\"dark\")",
            "occlusionTexture.strength = 1.5",
            "[0, 1]",
        ] {
            assert!(text.contains(part), "{text:?} should name {part:?}");
        }
        let path = write(
            &dir,
            "transform",
            &primitive,
            r#"{ "occlusionTexture": { "index": 0,
                 "extensions": { "KHR_texture_transform": { "offset": "far" } } } }"#,
        );
        let text = message(load_textured(&path, Textures::Means).unwrap_err());
        for part in [
            "transform.gltf",
            "material 0",
            "occlusionTexture.extensions.KHR_texture_transform",
            "far",
        ] {
            assert!(text.contains(part), "{text:?} should name {part:?}");
        }
    }

    #[test]
    fn a_texcoord_1_of_a_type_gltf_does_not_allow_is_refused_naming_the_attribute() {
        let dir = scratch_dir("occlusion_texcoord_1_type");
        orm_png(&dir);
        let mut a = Asset::default();
        let pos = a.positions(&TRIANGLE);
        let st0 = vec2s(&mut a, &ST0);
        let wrong = a.vec3s(&[[0.0; 3]; 3]);
        let body = format!(
            r#""scene": 0, "scenes": [ {{ "nodes": [0] }} ], "nodes": [ {{ "mesh": 0 }} ],
               "meshes": [ {{ "primitives": [ {{ "attributes": {{ "POSITION": {pos},
                   "TEXCOORD_0": {st0}, "TEXCOORD_1": {wrong} }}, "material": 0 }} ] }} ],
               "materials": [ {{ "occlusionTexture": {{ "index": 0, "texCoord": 1 }} }} ],
               "textures": [ {{ "source": 0 }} ], "images": [ {{ "uri": "orm.png" }} ],"#
        );
        let path = a.write_gltf(&dir, "vec3", &body);
        let text = message(load_textured(&path, Textures::Means).unwrap_err());
        assert!(
            text.contains(&format!("TEXCOORD_1 (accessor {wrong}) is FLOAT VEC3: expected"))
                && text.contains("VEC2"),
            "{text}"
        );
    }

    #[test]
    fn luminance_bakes_strength_as_gltf_defines_occlusion() {
        let image = TextureImage::new(
            4,
            1,
            [0u8, 51, 102, 255].iter().flat_map(|&r| [r, 0, 0, 0]).collect(),
        )
        .unwrap();
        // Strength 0: no occlusion at all; 1: the texel as is; 0.2: 1 + 0.2 × (r − 1).
        for (strength, want) in [
            (0.0, [255, 255, 255, 255]),
            (1.0, [0, 51, 102, 255]),
            (0.2, [204, 214, 224, 255]),
        ] {
            let l = luminance(&image, strength).unwrap();
            let got: Vec<u8> = (0..4).map(|i| l.levels()[0].texel(i, 0)[0]).collect();
            assert_eq!(got, want, "strength {strength}");
            assert_eq!(l.levels()[0].texel(1, 0)[3], 255, "alpha 1");
        }
    }
}
