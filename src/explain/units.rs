//! `ffvk explain`'s texturing: each texture unit's coordinates, texel, inputs and result at the
//! pixel, in unit order (GL 2.1 §3.8.16), from the CPU reference's [`units::texture_units`].

use std::fmt::Write as _;

use ffvk::gl::texture::{Combine, TexEnvMode, TextureUnit};
use ffvk::reference::PixelTerms;
use ffvk::scene::{MeshTexture, SceneMesh, TexCoords};

use super::{bytes, rgba};

/// Writes every unit of `mesh` that has a texture: what it samples, where, what it reads and
/// what it leaves; then the secondary color added after texturing.
pub(super) fn texture_terms(out: &mut String, mesh: &SceneMesh, pixel: &PixelTerms) {
    if mesh.textures.iter().all(Option::is_none) {
        return;
    }
    let mut c_p = pixel.c_pri;
    for (i, t) in mesh.textures.iter().enumerate() {
        let Some(t) = t else { continue };
        let Some(tex) = &pixel.units[i] else {
            let _ = writeln!(out, "GL_TEXTURE{i} textures nothing ({})", why_not(t));
            continue;
        };
        let _ = writeln!(out, "GL_TEXTURE{i}: {}", described(t));
        let _ = writeln!(
            out,
            "  coordinates: {}; (s, t, r, q) after the texture matrix {}",
            coords(i, t),
            rgba(tex.stq)
        );
        let image = match tex.face {
            Some(face) => {
                let _ = write!(out, "  direction (s, t, r) selects {}, ", face.gl_name());
                t.cube_map.as_ref().map_or(&*t.image, |c| c.face(face))
            }
            None => {
                let _ = write!(out, "  ");
                &*t.image
            }
        };
        let _ = writeln!(
            out,
            "({}) ({:.4}, {:.4}), texel ({:.2}, {:.2}) of level 0, λ {:.3}",
            if tex.face.is_some() {
                "s_face, t_face"
            } else {
                "s/q, t/q"
            },
            tex.st.x,
            tex.st.y,
            tex.st.x * f64::from(image.width()),
            tex.st.y * f64::from(image.height()),
            tex.lambda
        );
        let _ = writeln!(
            out,
            "  C_s, A_s (filtered texel, {})  {} = {}",
            image.base_format.gl_name(),
            rgba(tex.texel),
            bytes(tex.texel)
        );
        let previous = if i == 0 || c_p == pixel.c_pri {
            "C_p = C_f (c_pri)"
        } else {
            "C_p (previous unit)"
        };
        let _ = writeln!(out, "  {previous:<26} {}", rgba(c_p));
        if tex.applied {
            let _ = writeln!(out, "  C_v, A_v ({})  {}", environment(&t.unit), rgba(tex.env));
        } else {
            let _ = writeln!(
                out,
                "  not applied: its GL_COMBINE reads a GL_TEXTUREn that samples nothing, so C_p passes (ARB_texture_env_crossbar)"
            );
        }
        c_p = tex.env;
    }
    let _ = writeln!(out, "after texturing              {}", rgba(pixel.textured));
    let _ = writeln!(out, "c_sec, added after texturing {}", rgba(pixel.c_sec));
}

/// The unit's texture: its source, size, levels, format and sampling, and its environment.
fn described(t: &MeshTexture) -> String {
    let s = &t.sampling;
    let image = match &t.cube_map {
        Some(cube) => format!(
            "{} ({}² cube map faces, {} level(s){})",
            t.cube_source,
            cube.size(),
            cube.level_count(),
            if cube.srgb() { ", sRGB" } else { "" }
        ),
        None => format!(
            "{} ({}x{}, {} level(s){})",
            t.source,
            t.image.width(),
            t.image.height(),
            t.image.levels().len(),
            if t.image.srgb { ", sRGB" } else { "" }
        ),
    };
    format!(
        "{image}, min {} mag {}, wrap {} {}, env {}",
        s.min_filter.name(),
        s.mag_filter.name(),
        s.wrap_s.name(),
        s.wrap_t.name(),
        t.unit.env_mode.name()
    )
}

/// Why a unit with a texture samples nothing: its enables, or an incomplete texture.
fn why_not(t: &MeshTexture) -> String {
    match &t.cube_map {
        Some(_) => format!(
            "its cube map {}: GL_TEXTURE_CUBE_MAP off, or incomplete: min filter {} without mipmaps",
            t.cube_source,
            t.sampling.min_filter.name()
        ),
        None => format!(
            "{}: GL_TEXTURE_2D off, or incomplete: min filter {} without mipmaps",
            t.source,
            t.sampling.min_filter.name()
        ),
    }
}

/// Where unit `i`'s coordinates come from: the mesh's, the current ones, and those generated.
fn coords(i: usize, t: &MeshTexture) -> String {
    let source = match t.coords {
        TexCoords::Mesh => "the mesh's (s, t, 0, 1)".to_string(),
        TexCoords::MeshSecond => "the mesh's second set (s, t, 0, 1)".to_string(),
        TexCoords::Current(c) => format!("current {}", rgba(c.as_dvec4())),
        _ => "the mesh's".to_string(),
    };
    let source = if i == 0 {
        "the mesh's (s, t, 0, 1)".to_string()
    } else {
        source
    };
    let generated: Vec<String> = ["S", "T", "R", "Q"]
        .iter()
        .zip(&t.unit.texgen)
        .filter(|(_, g)| g.enabled)
        .map(|(name, g)| format!("{name} by {}", g.mode.gl_name()))
        .collect();
    if generated.is_empty() {
        source
    } else {
        format!("{source}, {} generated", generated.join(", "))
    }
}

/// The environment: its mode, and for `GL_COMBINE` the functions with their arguments.
fn environment(unit: &TextureUnit) -> String {
    if unit.env_mode != TexEnvMode::Combine {
        return unit.env_mode.name().to_string();
    }
    let c: &Combine = &unit.combine;
    let rgb: Vec<String> = (0..c.rgb.arguments())
        .map(|n| format!("{} {}", c.rgb_sources[n].gl_name(), c.rgb_operands[n].gl_name()))
        .collect();
    let alpha: Vec<String> = (0..c.alpha.arguments())
        .map(|n| {
            format!(
                "{} {}",
                c.alpha_sources[n].gl_name(),
                c.alpha_operands[n].gl_name()
            )
        })
        .collect();
    format!(
        "GL_COMBINE: RGB {}({}) × {}, alpha {}({}) × {}",
        c.rgb.gl_name(),
        rgb.join(", "),
        c.rgb_scale,
        c.alpha.gl_name(),
        alpha.join(", "),
        c.alpha_scale
    )
}
