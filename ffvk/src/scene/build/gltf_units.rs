//! A glTF material's sampled textures on GL's texture units, under glTF's meaning: the base
//! color texture on `GL_TEXTURE0` and the occlusion texture on `GL_TEXTURE1`, each through
//! `GL_MODULATE`.

use super::super::gltf::{PbrMaterial, SampledTexture};
use super::super::*;

/// What the scene's notes say of a scene with occlusion textures, once.
const OCCLUSION_NOTE: &str = "glTF: occlusion textures on GL_TEXTURE1 through \
     GL_MODULATE, as GL_LUMINANCE of their R channel: they darken the whole lit color, where \
     glTF's occlusion darkens only the indirect (ambient) light (GL's fixed function has no \
     texture path to the ambient term alone)";

/// A unit sampling `s` through GL_MODULATE from `coords`, its matrix the texture transform's.
fn modulate(s: &SampledTexture, coords: TexCoords, source: String) -> MeshTexture {
    MeshTexture {
        image: s.image.clone(),
        sampling: s.sampling,
        unit: crate::gl::texture::TextureUnit {
            enabled: true,
            matrix: s.matrix,
            ..Default::default()
        },
        coords,
        source,
        cube_map: None,
        cube_source: String::new(),
    }
}

/// The units `pbr`'s sampled textures take; each occlusion texture adds its notes (the
/// mapping's deviation, once; its strength when not 1) to `notes`.
pub(super) fn gltf_units(
    pbr: &PbrMaterial,
    notes: &mut Vec<String>,
) -> [Option<MeshTexture>; MAX_TEXTURE_UNITS] {
    let mut units: [Option<MeshTexture>; MAX_TEXTURE_UNITS] = Default::default();
    units[0] = pbr.base_color_sampled.as_ref().map(|s| {
        modulate(
            s,
            TexCoords::Mesh,
            format!("glTF image {} (base color, GL_MODULATE)", s.image_index),
        )
    });
    if let Some(o) = &pbr.occlusion_sampled {
        let coords = match o.tex_coord {
            0 => TexCoords::Mesh,
            _ => TexCoords::MeshSecond,
        };
        let source = format!(
            "glTF image {} (occlusion, TEXCOORD_{}, GL_LUMINANCE, GL_MODULATE)",
            o.texture.image_index, o.tex_coord
        );
        units[1] = Some(modulate(&o.texture, coords, source));
        let mut add = |note: String| {
            if !notes.contains(&note) {
                notes.push(note);
            }
        };
        add(OCCLUSION_NOTE.to_owned());
        if o.strength != 1.0 {
            let material = match (&pbr.index, &pbr.name) {
                (Some(i), Some(n)) => format!("material {i} ({:?})", shorten(n)),
                (Some(i), None) => format!("material {i}"),
                (None, _) => "the default material".to_owned(),
            };
            add(format!(
                "glTF: {material}'s occlusion strength {s} is baked into its texels (1 + {s} × (texel − 1))",
                s = o.strength
            ));
        }
    }
    units
}
