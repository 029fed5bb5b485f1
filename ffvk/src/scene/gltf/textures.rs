//! What ffvk reads of a material's textures until it samples them: the mean texel of the base
//! color and emissive textures, decoded from sRGB (both are sRGB-encoded in glTF) to linear,
//! so that a textured material's factor is scaled by what its texture averages to rather than
//! drawn as if the texture were white.

use super::occlusion::{self, OcclusionTexture, Readers};
use super::sampler::{sampling, transform_matrix, SampledTexture};
use super::{Context, LoadError, LoadErrorKind, MAX_FILE_BYTES};
use crate::gl::texture::{TextureImage, MAX_TEXTURE_SIZE};
use glam::{Mat4, Vec4};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

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
#[non_exhaustive]
pub enum Textures {
    /// Textures are named, not read: every texture is [`TextureMean::Unread`].
    #[default]
    Ignore,
    /// Base color and emissive textures are decoded and averaged; the base color texture is
    /// sampled too ([`PbrMaterial::base_color_sampled`](super::PbrMaterial::base_color_sampled)),
    /// and the occlusion texture
    /// ([`PbrMaterial::occlusion_sampled`](super::PbrMaterial::occlusion_sampled)).
    Means,
}

/// The base color and emissive textures of one material.
#[derive(Debug, Clone, Default, PartialEq)]
pub(super) struct MaterialTextures {
    pub(super) base_color: Option<TextureMean>,
    pub(super) emissive: Option<TextureMean>,
    pub(super) base_color_sampled: Option<SampledTexture>,
    pub(super) occlusion: Option<OcclusionTexture>,
}

/// What one image decoded to: its linear mean and the texture with its mipmaps, or why it
/// could not be read (a warning).
type Decoded = Result<Texture, String>;

/// A decoded image's linear mean and its texture with mipmaps.
type Texture = (Vec4, Arc<TextureImage>);

/// One entry per material of the file. Each image is decoded at most once, and so is each
/// file or range of bytes however many images name it; each is charged to the scene's
/// texture limit (`budget`) from its header's size before it is decoded, and one past the
/// limit is an error. Images that cannot be read or decoded become warnings.
pub(super) fn material_textures(
    cx: &Context,
    document: &gltf::Document,
    buffers: &[gltf::buffer::Data],
    (limits, budget): (&crate::scene::Limits, &mut crate::scene::MeshBudget),
    textures: Textures,
    warnings: &mut Vec<String>,
) -> Result<Vec<MaterialTextures>, LoadError> {
    let roots = &limits.asset_roots[..];
    // Shared by the decoder and the occlusion textures' luminance copies.
    let budget = std::cell::RefCell::new(budget);
    let mut by_image: Vec<Option<Option<Texture>>> = vec![None; document.images().len()];
    let mut by_source: HashMap<ImageSource, Decoded> = HashMap::new();
    let mut decode = |texture: &gltf::Texture| -> Result<Option<Texture>, LoadError> {
        if textures == Textures::Ignore {
            return Ok(None);
        }
        let image = texture.source();
        let i = image.index();
        if let Some(done) = by_image.get(i).cloned().flatten() {
            return Ok(done);
        }
        let decoded = match image_source(cx, &image, roots) {
            Err(why) => Err(why),
            Ok(source) => match by_source.get(&source) {
                Some(decoded) => decoded.clone(),
                None => {
                    let decoded = decode_source(&source, buffers, &mut |width, height| {
                        let bytes = mipmapped_bytes(width, height);
                        budget
                            .borrow_mut()
                            .charge_texture(bytes, limits.texture_bytes)
                            .map_err(|used| {
                                cx.error(LoadErrorKind::TextureBudget {
                                    image: i,
                                    width,
                                    height,
                                    bytes,
                                    used,
                                    limit: limits.texture_bytes,
                                })
                            })
                    })?;
                    by_source.insert(source, decoded.clone());
                    decoded
                }
            },
        };
        let kept = match decoded {
            Ok(done) => Some(done),
            Err(why) => {
                warnings.push(format!(
                    "image {i}{}: {why}; the materials using it take their factors alone",
                    cx.name("images", i)
                        .map(|n| format!(" ({:?})", crate::scene::shorten(&n)))
                        .unwrap_or_default()
                ));
                None
            }
        };
        if let Some(slot) = by_image.get_mut(i) {
            *slot = Some(kept.clone());
        }
        Ok(kept)
    };
    let mean_of = |decoded: &Option<Texture>| match decoded {
        Some((mean, _)) => TextureMean::Mean(*mean),
        None => TextureMean::Unread,
    };
    let mut copies = occlusion::Copies::new();
    // Kept apart while the decoder holds `warnings`.
    let mut occlusion_warnings = Vec::new();
    let mut other_coords = Vec::new();
    let mut out = Vec::new();
    for m in document.materials() {
        let info = m.pbr_metallic_roughness().base_color_texture();
        let base_decoded = match &info {
            Some(t) => Some(decode(&t.texture())?),
            None => None,
        };
        let base_color = base_decoded.as_ref().map(mean_of);
        let emissive = match m.emissive_texture() {
            Some(t) => Some(mean_of(&decode(&t.texture())?)),
            None => None,
        };
        let base_color_sampled = info.and_then(|info| {
            let transform = info.texture_transform();
            let coords = transform
                .as_ref()
                .and_then(|t| t.tex_coord())
                .unwrap_or(info.tex_coord());
            if coords != 0 {
                other_coords.push(m.index().unwrap_or_default());
                return None;
            }
            let (_, image) = base_decoded.flatten()?;
            Some(SampledTexture {
                image,
                sampling: sampling(&info.texture().sampler()),
                matrix: transform.map_or(Mat4::IDENTITY, |t| {
                    transform_matrix(t.offset(), t.rotation(), t.scale())
                }),
                image_index: info.texture().source().index(),
            })
        });
        let occlusion = match textures {
            Textures::Ignore => None,
            Textures::Means => {
                let readers = Readers {
                    decode: &mut |t| Ok(decode(t)?.map(|(_, image)| image)),
                    charge: &mut |image, width, height| {
                        let bytes = mipmapped_bytes(width, height);
                        budget
                            .borrow_mut()
                            .charge_texture(bytes, limits.texture_bytes)
                            .map_err(|used| {
                                cx.error(LoadErrorKind::TextureBudget {
                                    image,
                                    width,
                                    height,
                                    bytes,
                                    used,
                                    limit: limits.texture_bytes,
                                })
                            })
                    },
                };
                occlusion::sampled(cx, &m, readers, &mut copies, &mut occlusion_warnings)?
            }
        };
        out.push(MaterialTextures {
            base_color,
            emissive,
            base_color_sampled,
            occlusion,
        });
    }
    warnings.append(&mut occlusion_warnings);
    if !other_coords.is_empty() {
        warnings.push(format!(
            "materials {other_coords:?}: the base color texture reads TEXCOORD_1 or later; ffvk reads TEXCOORD_0 only, so these take the texture's mean texel instead"
        ));
    }
    Ok(out)
}

/// The bytes an image of `width` × `height` takes as [`TextureImage`] stores it: RGBA8, with
/// every mipmap level down to 1 × 1 (about 4/3 of the base level).
pub(in crate::scene) fn mipmapped_bytes(width: u32, height: u32) -> u64 {
    let (mut w, mut h, mut bytes) = (u64::from(width.max(1)), u64::from(height.max(1)), 0u64);
    loop {
        bytes = bytes.saturating_add(w * h * 4);
        if w == 1 && h == 1 {
            return bytes;
        }
        (w, h) = ((w / 2).max(1), (h / 2).max(1));
    }
}

/// Where an image's encoded bytes are, as far as telling two images that name the same bytes
/// apart needs: a buffer's range, a data: URI, or a file (its path with every link resolved).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
enum ImageSource {
    View { buffer: usize, start: usize, end: usize },
    Data(String),
    File(PathBuf),
}

/// Where `image`'s bytes are: a bufferView, a data: URI or a file beside the glTF file.
fn image_source(cx: &Context, image: &gltf::Image, roots: &[PathBuf]) -> Result<ImageSource, String> {
    match image.source() {
        gltf::image::Source::View { view, .. } => Ok(ImageSource::View {
            buffer: view.buffer().index(),
            start: view.offset(),
            end: view.offset().saturating_add(view.length()),
        }),
        gltf::image::Source::Uri { uri, .. } if uri.starts_with("data:") => {
            Ok(ImageSource::Data(uri.to_owned()))
        }
        gltf::image::Source::Uri { uri, .. } => {
            let base = cx.path.parent().unwrap_or(Path::new(""));
            let file = super::uris::asset_file(base, uri, roots).ok_or_else(|| {
                format!(
                    "the URI {:?} leaves the asset's folder (ffvk --allow-root DIR widens that)",
                    crate::scene::shorten(uri)
                )
            })?;
            Ok(ImageSource::File(std::fs::canonicalize(&file).unwrap_or(file)))
        }
    }
}

/// The encoded bytes at `source`.
fn image_bytes(source: &ImageSource, buffers: &[gltf::buffer::Data]) -> Result<Vec<u8>, String> {
    match source {
        ImageSource::View { buffer, start, end } => {
            let data = buffers
                .get(*buffer)
                .ok_or_else(|| format!("its bufferView names buffer {buffer}, which is missing"))?;
            data.0
                .get(*start..*end)
                .map(<[u8]>::to_vec)
                .ok_or_else(|| format!("its bufferView (bytes {start}..{end}) lies outside buffer {buffer}"))
        }
        ImageSource::Data(uri) => gltf::buffer::Data::from_source(gltf::buffer::Source::Uri(uri), None)
            .map(|d| d.0)
            .map_err(|e| format!("bad data URI: {e}")),
        ImageSource::File(file) => crate::files::read_regular(file, MAX_FILE_BYTES).map_err(|e| {
            format!(
                "cannot read {}: {e}",
                crate::scene::shorten(&file.display().to_string())
            )
        }),
    }
}

/// The image at `source` decoded to RGBA8 as stored, with its linear mean and mipmaps, no
/// larger than a texture may be; `charge` is given its size from its header before it is
/// decoded, and its error ends the load. `Ok(Err)` is why the image could not be read (a
/// warning).
fn decode_source(
    source: &ImageSource,
    buffers: &[gltf::buffer::Data],
    charge: &mut dyn FnMut(u32, u32) -> Result<(), LoadError>,
) -> Result<Decoded, LoadError> {
    let bytes = match image_bytes(source, buffers) {
        Ok(bytes) => bytes,
        Err(why) => return Ok(Err(why)),
    };
    let reader = || {
        image::ImageReader::new(std::io::Cursor::new(&bytes[..]))
            .with_guessed_format()
            .map_err(|e| format!("cannot read: {e}"))
    };
    let dimensions = reader().and_then(|r| {
        r.into_dimensions()
            .map_err(|e| format!("cannot decode (ffvk reads PNG and JPEG): {e}"))
    });
    let (w, h) = match dimensions {
        Ok(size) => size,
        Err(why) => return Ok(Err(why)),
    };
    if w == 0 || h == 0 || w > MAX_TEXTURE_SIZE || h > MAX_TEXTURE_SIZE {
        return Ok(Err(format!(
            "{w}x{h} texels: expected each side in 1..={MAX_TEXTURE_SIZE}"
        )));
    }
    charge(w, h)?;
    let decoded = reader().and_then(|r| {
        r.decode()
            .map_err(|e| format!("cannot decode (ffvk reads PNG and JPEG): {e}"))
    });
    let decoded = match decoded {
        Ok(image) => image.into_rgba8(),
        Err(why) => return Ok(Err(why)),
    };
    let mean = mean_linear(&decoded);
    let (w, h) = decoded.dimensions();
    Ok(TextureImage::new(w, h, decoded.into_raw())
        .map(|texture| (mean, Arc::new(texture.with_mipmaps())))
        .map_err(|e| e.to_string()))
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
    use crate::gl::texture::{MagFilter, MinFilter, Sampling, Wrap};
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
    fn base_color_textures_are_sampled_with_their_sampler_transform_and_normalized_texcoords() {
        let dir = scratch_dir("texture_sampled");
        let mut checker = image::RgbaImage::new(2, 2);
        checker.put_pixel(0, 0, image::Rgba([255, 0, 0, 255]));
        checker.put_pixel(1, 1, image::Rgba([0, 0, 255, 255]));
        checker.save(dir.join("checker.png")).unwrap();
        let mut a = Asset::default();
        let pos = a.positions(&QUAD[..3]);
        // TEXCOORD_0 as normalized UNSIGNED_BYTE: 255 is 1.0.
        let uv = a.accessor(
            &[0, 0, 255, 0, 255, 255],
            5121,
            3,
            "VEC2",
            r#", "normalized": true"#,
        );
        let body = one_mesh_body(&format!(
            r#"{{ "attributes": {{ "POSITION": {pos}, "TEXCOORD_0": {uv} }}, "material": 0 }}"#
        )) + r#""materials": [ { "pbrMetallicRoughness": { "baseColorTexture": { "index": 0,
                   "extensions": { "KHR_texture_transform": { "offset": [0, 1], "rotation": 1.57079632679, "scale": [0.5, 0.5] } } } } } ],
                 "extensionsUsed": ["KHR_texture_transform"],
                 "samplers": [ { "magFilter": 9728, "minFilter": 9984, "wrapS": 33071, "wrapT": 33648 } ],
                 "textures": [ { "source": 0, "sampler": 0 } ],
                 "images": [ { "uri": "checker.png" } ],"#;
        let path = a.write_gltf(&dir, "sampled", &body);
        let limits = Limits::default();
        let mut budget = MeshBudget::new(limits.mesh_bytes);
        let loaded = load_with(&path, &limits, &mut budget, Textures::Means).unwrap();
        assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
        let mesh = &loaded.meshes[0];
        let st: Vec<[f32; 2]> = mesh.data.vertices.iter().map(|v| v.texcoord).collect();
        assert_eq!(st, [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]);
        let material = mesh.material.clone().unwrap();
        let sampled = material
            .base_color_sampled
            .clone()
            .expect("the base color texture is sampled");
        assert_eq!(
            sampled.sampling,
            Sampling {
                mag_filter: MagFilter::Nearest,
                min_filter: MinFilter::NearestMipmapNearest,
                wrap_s: Wrap::ClampToEdge,
                wrap_t: Wrap::MirroredRepeat,
            }
        );
        // Stored as is (no sRGB decode), with its mipmaps.
        assert_eq!(sampled.image.levels()[0].texel(0, 0), [255, 0, 0, 255]);
        assert_eq!(sampled.image.levels().len(), 2);
        // The extension's own example: the lower left quadrant, turned.
        let at = |u: f32, v: f32| {
            let p = sampled.matrix * Vec4::new(u, v, 0.0, 1.0);
            [p.x, p.y]
        };
        for (uv, want) in [
            ((0.0, 0.0), [0.0, 1.0]),
            ((1.0, 0.0), [0.0, 0.5]),
            ((1.0, 1.0), [0.5, 0.5]),
        ] {
            let got = at(uv.0, uv.1);
            assert!(
                (got[0] - want[0]).abs() < 1e-6 && (got[1] - want[1]).abs() < 1e-6,
                "{uv:?}: {got:?}"
            );
        }
        // Sampled, so the factor is not scaled by the mean.
        assert_eq!(material.with_texture_means().base_color_factor, Vec4::ONE);
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
