//! What ffvk reads of a material's textures until it samples them: the mean texel of the base
//! color and emissive textures, decoded from sRGB (both are sRGB-encoded in glTF) to linear,
//! so that a textured material's factor is scaled by what its texture averages to rather than
//! drawn as if the texture were white.

use super::{Context, MAX_FILE_BYTES};
use glam::Vec4;
use std::path::{Path, PathBuf};

/// A texture a material names, as far as ffvk read it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TextureMean {
    /// Not read: the scene does not follow glTF's meaning, or the image could not be decoded
    /// (a warning says why). The material's factor is used alone.
    Unread,
    /// The mean of its texels: linear RGB (decoded from sRGB) and alpha.
    Mean(Vec4),
}

impl TextureMean {
    /// The mean, or white where the texture was not read.
    pub fn or_white(self) -> Vec4 {
        match self {
            TextureMean::Unread => Vec4::ONE,
            TextureMean::Mean(m) => m,
        }
    }
}

/// Whether [`load_with`](super::load_with) decodes textures for their means.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Textures {
    /// Textures are named, not read: every texture is [`TextureMean::Unread`].
    #[default]
    Ignore,
    /// Base color and emissive textures are decoded and averaged.
    Means,
}

/// The base color and emissive textures of one material.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct MaterialTextures {
    pub(super) base_color: Option<TextureMean>,
    pub(super) emissive: Option<TextureMean>,
}

/// One entry per material of the file; each image decoded at most once. Images that cannot be
/// read or decoded become warnings.
pub(super) fn material_textures(
    cx: &Context,
    document: &gltf::Document,
    buffers: &[gltf::buffer::Data],
    roots: &[PathBuf],
    textures: Textures,
    warnings: &mut Vec<String>,
) -> Vec<MaterialTextures> {
    let mut cache: Vec<Option<TextureMean>> = vec![None; document.images().len()];
    let mut mean_of = |texture: gltf::Texture| -> TextureMean {
        if textures == Textures::Ignore {
            return TextureMean::Unread;
        }
        let image = texture.source();
        let i = image.index();
        *cache[i].get_or_insert_with(|| match image_mean(cx, &image, buffers, roots) {
            Ok(mean) => TextureMean::Mean(mean),
            Err(why) => {
                warnings.push(format!(
                    "image {i}{}: {why}; the materials using it take their factors alone",
                    cx.name("images", i)
                        .map(|n| format!(" ({:?})", crate::scene::shorten(&n)))
                        .unwrap_or_default()
                ));
                TextureMean::Unread
            }
        })
    };
    document
        .materials()
        .map(|m| MaterialTextures {
            base_color: m
                .pbr_metallic_roughness()
                .base_color_texture()
                .map(|t| mean_of(t.texture())),
            emissive: m.emissive_texture().map(|t| mean_of(t.texture())),
        })
        .collect()
}

/// The image's encoded bytes: from a bufferView, a data: URI or a file beside the glTF file.
fn image_bytes(
    cx: &Context,
    image: &gltf::Image,
    buffers: &[gltf::buffer::Data],
    roots: &[PathBuf],
) -> Result<Vec<u8>, String> {
    match image.source() {
        gltf::image::Source::View { view, .. } => {
            let data = buffers
                .get(view.buffer().index())
                .ok_or_else(|| format!("bufferView {} names a missing buffer", view.index()))?;
            let range = view.offset()..view.offset().saturating_add(view.length());
            data.0
                .get(range)
                .map(<[u8]>::to_vec)
                .ok_or_else(|| format!("bufferView {} lies outside its buffer", view.index()))
        }
        gltf::image::Source::Uri { uri, .. } if uri.starts_with("data:") => {
            gltf::buffer::Data::from_source(gltf::buffer::Source::Uri(uri), None)
                .map(|d| d.0)
                .map_err(|e| format!("bad data URI: {e}"))
        }
        gltf::image::Source::Uri { uri, .. } => {
            let base = cx.path.parent().unwrap_or(Path::new(""));
            let file = super::read::asset_file(base, uri, roots).ok_or_else(|| {
                format!(
                    "the URI {:?} leaves the asset's folder (ffvk --allow-root DIR widens that)",
                    crate::scene::shorten(uri)
                )
            })?;
            crate::files::read_regular(&file, MAX_FILE_BYTES)
                .map_err(|e| format!("cannot read {}: {e}", file.display()))
        }
    }
}

/// The mean texel of `image`, linear.
fn image_mean(
    cx: &Context,
    image: &gltf::Image,
    buffers: &[gltf::buffer::Data],
    roots: &[PathBuf],
) -> Result<Vec4, String> {
    let bytes = image_bytes(cx, image, buffers, roots)?;
    let decoded = image::ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| format!("cannot read: {e}"))?
        .decode()
        .map_err(|e| format!("cannot decode (ffvk reads PNG and JPEG): {e}"))?
        .into_rgba8();
    Ok(mean_linear(&decoded))
}

/// The mean of `image`'s texels with RGB decoded from sRGB (alpha is linear already).
pub(super) fn mean_linear(image: &image::RgbaImage) -> Vec4 {
    let linear: [f32; 256] = std::array::from_fn(|i| srgb_to_linear(i as f32 / 255.0));
    let mut sum = [0f64; 4];
    for p in image.pixels() {
        for k in 0..3 {
            sum[k] += f64::from(linear[usize::from(p.0[k])]);
        }
        sum[3] += f64::from(p.0[3]) / 255.0;
    }
    let n = f64::from(image.width()) * f64::from(image.height());
    if n == 0.0 {
        return Vec4::ONE;
    }
    Vec4::from_array(sum.map(|s| (s / n) as f32))
}

/// The sRGB transfer function's inverse (IEC 61966-2-1).
fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::gltf::testing::{one_mesh_body, scratch_dir, Asset, QUAD};
    use crate::scene::gltf::{load_with, MeshBudget};
    use crate::scene::Limits;

    #[test]
    fn base_color_and_emissive_textures_enter_as_their_means_when_asked() {
        let dir = scratch_dir("texture_means");
        // A 2×2 emissive image: two opaque sRGB 188 texels (linear 0.5029), two transparent black.
        let mut glow = image::RgbaImage::new(2, 2);
        glow.put_pixel(0, 0, image::Rgba([188, 188, 188, 255]));
        glow.put_pixel(1, 1, image::Rgba([188, 188, 188, 255]));
        glow.save(dir.join("glow.png")).unwrap();
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos} }}, "material": 0 }}"#
        )) + r#""materials": [ { "emissiveFactor": [1, 1, 0.5], "emissiveTexture": { "index": 0 },
                                  "pbrMetallicRoughness": { "baseColorTexture": { "index": 1 } } } ],
                 "textures": [ { "source": 0 }, { "source": 1 } ],
                 "images": [ { "uri": "glow.png" }, { "name": "gone", "uri": "missing.png" } ],"#;
        let path = a.write_gltf(&dir, "textured", &body);
        let limits = Limits::default();
        let mut budget = MeshBudget::new(limits.mesh_bytes);
        let loaded = load_with(&path, &limits, &mut budget, Textures::Means).unwrap();
        let material = loaded.meshes[0].material.clone().unwrap();
        let Some(TextureMean::Mean(mean)) = material.emissive_texture else {
            panic!("{:?}", material.emissive_texture);
        };
        assert!(
            mean.abs_diff_eq(Vec4::new(0.2514, 0.2514, 0.2514, 0.5), 1e-3),
            "{mean}"
        );
        assert_eq!(material.base_color_texture, Some(TextureMean::Unread));
        assert!(
            loaded
                .warnings
                .iter()
                .any(|w| w.contains("image 1 (\"gone\")") && w.contains("missing.png")),
            "{:?}",
            loaded.warnings
        );
        let scaled = material.with_texture_means();
        assert!(scaled
            .emissive_factor
            .abs_diff_eq(glam::Vec3::new(0.2514, 0.2514, 0.1257), 1e-3));
        assert_eq!(
            scaled.base_color_factor,
            Vec4::ONE,
            "an unread texture leaves the factor"
        );

        // Ignored, nothing is decoded.
        let loaded = load_with(
            &path,
            &limits,
            &mut MeshBudget::new(limits.mesh_bytes),
            Textures::Ignore,
        )
        .unwrap();
        let material = loaded.meshes[0].material.clone().unwrap();
        assert_eq!(material.emissive_texture, Some(TextureMean::Unread));
        assert!(!loaded.warnings.iter().any(|w| w.contains("missing.png")));
    }

    #[test]
    fn the_mean_is_taken_after_srgb_decoding() {
        let mut image = image::RgbaImage::new(2, 1);
        image.put_pixel(0, 0, image::Rgba([255, 0, 188, 255]));
        image.put_pixel(1, 0, image::Rgba([0, 0, 188, 0]));
        let m = mean_linear(&image);
        // sRGB 188/255 is linear 0.5029; white and black average to 0.5 in linear light.
        assert!(m.abs_diff_eq(Vec4::new(0.5, 0.0, 0.5029, 0.5), 1e-3), "{m}");
        assert_eq!(srgb_to_linear(0.0), 0.0);
        assert!((srgb_to_linear(1.0) - 1.0).abs() < 1e-6);
    }
}
