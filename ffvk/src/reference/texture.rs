//! Texturing in the CPU reference (GL 2.1 sections 3.8.8 and 3.13), written from the spec
//! pages: texture coordinates through the texture matrix, the level of detail λ from their
//! screen-space derivatives, wrapping, nearest and linear filtering within a level and between
//! levels, and the texture environment of table 3.22. `glsl/texture.glsl` is the GPU's copy of
//! the environment; sampling there is the device's.

use glam::{DVec2, DVec3, DVec4};

use crate::gl::texture::{
    AlphaOperand, BaseFormat, Combine, CombineFunc, CombineSource, MagFilter, RgbOperand, Sampling,
    TexEnvMode, TexGenMode, TextureImage, TextureUnit, Wrap, MAX_TEXTURE_UNITS,
};

/// What unit `unit` of a fragment's texturing reads (GL 2.1 §3.8.13): the fragment's primary
/// color `c_f` (`GL_PRIMARY_COLOR`), the previous unit's result `c_p` (`GL_PREVIOUS`; `c_f`
/// for unit 0) and every unit's texel `c_s` (`GL_TEXTURE`, and `GL_TEXTUREn` of the crossbar).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnitInputs {
    /// The unit's index.
    pub unit: usize,
    /// The primary color.
    pub c_f: DVec4,
    /// The previous unit's result.
    pub c_p: DVec4,
    /// Each unit's texel (zero for a unit not sampled), in its texture's base format
    /// ([`BaseFormat::texel`]).
    pub c_s: [DVec4; MAX_TEXTURE_UNITS],
    /// The base internal format of this unit's texture: which of table 3.22's columns applies.
    pub format: BaseFormat,
}

/// Table 3.22 for an RGBA texture: the fragment color `c_f` (the primary color) combined with
/// the texel `c_s` in `mode`, `c_c` the environment color; `GL_COMBINE` as `combine` says
/// ([`combine`]): unit 0 of [`unit_env`]. Every result is in [0, 1].
pub fn tex_env(mode: TexEnvMode, combine_state: &Combine, c_f: DVec4, c_s: DVec4, c_c: DVec4) -> DVec4 {
    let mut texels = [DVec4::ZERO; MAX_TEXTURE_UNITS];
    texels[0] = c_s;
    let v = UnitInputs {
        unit: 0,
        c_f,
        c_p: c_f,
        c_s: texels,
        format: BaseFormat::Rgba,
    };
    env_of(mode, combine_state, &v, c_c)
}

/// Unit `v.unit`'s environment (table 3.22 for an RGBA texture, or `GL_COMBINE`) on the
/// previous unit's result, clamped to [0, 1] as GL clamps every unit's result.
pub fn unit_env(unit: &TextureUnit, v: &UnitInputs) -> DVec4 {
    env_of(unit.env_mode, &unit.combine, v, unit.env_color.as_dvec4())
}

/// Table 3.22 by the texture's base format: a format without color (`GL_ALPHA`) keeps C_p, one
/// without alpha (`GL_LUMINANCE`, `GL_RGB`) keeps A_p, `GL_INTENSITY` blends and adds its
/// alpha as its color (`GL_DECAL`, undefined but for RGB and RGBA, takes the RGBA row).
fn env_of(mode: TexEnvMode, combine_state: &Combine, v: &UnitInputs, c_c: DVec4) -> DVec4 {
    let c_s = v.c_s[v.unit];
    let (cp, cs, cc) = (v.c_p.truncate(), c_s.truncate(), c_c.truncate());
    let (ap, a_s) = (v.c_p.w, c_s.w);
    let (color, alpha) = (v.format.has_color(), v.format.has_alpha());
    let intensity = v.format == BaseFormat::Intensity;
    let keep_color = |c: DVec3| if color { c } else { cp };
    let times_alpha = if alpha { ap * a_s } else { ap };
    let c_v = match mode {
        TexEnvMode::Combine => combine_unit(combine_state, v, c_c),
        TexEnvMode::Replace => keep_color(cs).extend(if alpha { a_s } else { ap }),
        TexEnvMode::Modulate => keep_color(cp * cs).extend(times_alpha),
        TexEnvMode::Decal => (cp * (1.0 - a_s) + cs * a_s).extend(ap),
        TexEnvMode::Blend => keep_color(cp * (DVec3::ONE - cs) + cc * cs).extend(if intensity {
            ap * (1.0 - a_s) + c_c.w * a_s
        } else {
            times_alpha
        }),
        TexEnvMode::Add => keep_color(cp + cs).extend(if intensity { ap + a_s } else { times_alpha }),
    };
    c_v.clamp(DVec4::ZERO, DVec4::ONE)
}

/// §3.8.16: the units `applied` names (a bit each) in order, each on the one before's result,
/// from the primary color `c_f`; `c_s` holds each sampled unit's texel in its texture's base
/// format, `formats` each unit's format.
pub fn textured_color(
    units: &[TextureUnit; MAX_TEXTURE_UNITS],
    (applied, formats): (u32, [BaseFormat; MAX_TEXTURE_UNITS]),
    c_f: DVec4,
    c_s: [DVec4; MAX_TEXTURE_UNITS],
) -> DVec4 {
    (0..MAX_TEXTURE_UNITS)
        .filter(|&i| applied & 1 << i != 0)
        .fold(c_f, |c_p, unit| {
            let v = UnitInputs {
                unit,
                c_f,
                c_p,
                c_s,
                format: formats[unit],
            };
            unit_env(&units[unit], &v)
        })
}

/// GL 2.1 §3.8.13, `GL_COMBINE` (table 3.24) for the one unit: [`combine_unit`] of unit 0,
/// whose `GL_PREVIOUS` is the primary color `c_f`.
pub fn combine(c: &Combine, c_f: DVec4, c_s: DVec4, c_c: DVec4) -> DVec4 {
    let mut texels = [DVec4::ZERO; MAX_TEXTURE_UNITS];
    texels[0] = c_s;
    let v = UnitInputs {
        unit: 0,
        c_f,
        c_p: c_f,
        c_s: texels,
        format: BaseFormat::Rgba,
    };
    combine_unit(c, &v, c_c)
}

/// GL 2.1 §3.8.13, `GL_COMBINE` (table 3.24) for unit `v.unit`: the arguments from the sources,
/// the function of them for RGB and for alpha (`GL_DOT3_RGBA` puts the dot product in alpha
/// too), each result scaled and clamped to [0, 1]. The copy of `glsl/texture.glsl`'s `combine`.
pub fn combine_unit(c: &Combine, v: &UnitInputs, c_c: DVec4) -> DVec4 {
    let source = |s: CombineSource| match s {
        CombineSource::Texture => v.c_s[v.unit],
        CombineSource::TextureUnit(n) => v.c_s.get(usize::from(n)).copied().unwrap_or(DVec4::ZERO),
        CombineSource::Constant => c_c,
        CombineSource::PrimaryColor => v.c_f,
        _ => v.c_p,
    };
    let rgb_arg = |i: usize| {
        let v = source(c.rgb_sources[i]);
        match c.rgb_operands[i] {
            RgbOperand::SrcColor => v.truncate(),
            RgbOperand::OneMinusSrcColor => DVec3::ONE - v.truncate(),
            RgbOperand::SrcAlpha => DVec3::splat(v.w),
            _ => DVec3::splat(1.0 - v.w),
        }
    };
    let alpha_arg = |i: usize| {
        let a = source(c.alpha_sources[i]).w;
        match c.alpha_operands[i] {
            AlphaOperand::SrcAlpha => a,
            _ => 1.0 - a,
        }
    };
    let [a0, a1, a2] = [0, 1, 2].map(rgb_arg);
    let dot = 4.0 * (a0 - 0.5).dot(a1 - 0.5);
    let rgb = match c.rgb {
        CombineFunc::Replace => a0,
        CombineFunc::Modulate => a0 * a1,
        CombineFunc::Add => a0 + a1,
        CombineFunc::AddSigned => a0 + a1 - 0.5,
        CombineFunc::Interpolate => a0 * a2 + a1 * (DVec3::ONE - a2),
        CombineFunc::Subtract => a0 - a1,
        _ => DVec3::splat(dot),
    };
    let [b0, b1, b2] = [0, 1, 2].map(alpha_arg);
    let alpha = match (c.rgb, c.alpha) {
        (CombineFunc::Dot3Rgba, _) => dot,
        (_, CombineFunc::Replace) => b0,
        (_, CombineFunc::Add) => b0 + b1,
        (_, CombineFunc::AddSigned) => b0 + b1 - 0.5,
        (_, CombineFunc::Interpolate) => b0 * b2 + b1 * (1.0 - b2),
        (_, CombineFunc::Subtract) => b0 - b1,
        _ => b0 * b1,
    };
    let rgb = (rgb * f64::from(c.rgb_scale)).clamp(DVec3::ZERO, DVec3::ONE);
    rgb.extend((alpha * f64::from(c.alpha_scale)).clamp(0.0, 1.0))
}

/// GL 2.1 §2.11.4, texture coordinate generation: `c` with each coordinate whose generation
/// is on replaced by its mode's value of the vertex, `p_o` in object coordinates, `p_e` in eye
/// coordinates, `n_f` the eye-space normal as lighting takes it. The copy of
/// `glsl/texgen.glsl`'s `generated_coords`.
pub fn generated_coords(unit: &TextureUnit, c: DVec4, p_o: DVec4, p_e: DVec4, n_f: DVec3) -> DVec4 {
    // u: the unit vector from the eye to the vertex; r: its reflection about n_f.
    let u = p_e.truncate().normalize();
    let r = u - 2.0 * n_f * n_f.dot(u);
    let m = 2.0 * (r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0)).sqrt();
    let sphere = [r.x / m + 0.5, r.y / m + 0.5, 0.0, 0.0];
    let mut g = c.to_array();
    for (i, gen) in unit.texgen.iter().enumerate().filter(|(_, gen)| gen.enabled) {
        g[i] = match gen.mode {
            TexGenMode::ObjectLinear => gen.object_plane.as_dvec4().dot(p_o),
            TexGenMode::EyeLinear => gen.eye_plane.as_dvec4().dot(p_e),
            TexGenMode::SphereMap => sphere[i],
            TexGenMode::ReflectionMap => r.extend(0.0)[i],
            TexGenMode::NormalMap => n_f.extend(0.0)[i],
        };
    }
    DVec4::from_array(g)
}

/// (s, t, r, q) → (s/q, t/q).
pub fn project(stq: DVec4) -> DVec2 {
    DVec2::new(stq.x / stq.w, stq.y / stq.w)
}

/// λ from the derivatives of (s, t) along window x and y (GL's ρ: the larger of the two
/// lengths of (∂u/∂x, ∂v/∂x) and (∂u/∂y, ∂v/∂y) in texels of level 0).
pub fn lambda(image: &TextureImage, d_dx: DVec2, d_dy: DVec2) -> f64 {
    let size = DVec2::new(image.width() as f64, image.height() as f64);
    let rho = (d_dx * size).length().max((d_dy * size).length());
    rho.log2()
}

/// A texel coordinate wrapped into 0..size (Vulkan's and GL 4's integer form of the wrap
/// modes, which GL 2.1's clamped coordinates agree with).
pub fn wrap_index(i: i64, size: u32, wrap: Wrap) -> u32 {
    let n = i64::from(size);
    let w = match wrap {
        Wrap::Repeat => i.rem_euclid(n),
        Wrap::ClampToEdge => i.clamp(0, n - 1),
        Wrap::MirroredRepeat => {
            let m = i.rem_euclid(2 * n) - n;
            let mirror = if m >= 0 { m } else { -(1 + m) };
            (n - 1) - mirror
        }
    };
    w as u32
}

/// One texel as [0, 1] floats, decoded from sRGB when the image is.
fn fetch(image: &TextureImage, level: usize, i: u32, j: u32) -> DVec4 {
    let raw = image.levels()[level].texel(i, j);
    let c = DVec4::from(raw.map(|v| f64::from(v) / 255.0));
    if image.srgb {
        let decode = |v: f64| {
            if v <= 0.04045 {
                v / 12.92
            } else {
                ((v + 0.055) / 1.055).powf(2.4)
            }
        };
        DVec4::new(decode(c.x), decode(c.y), decode(c.z), c.w)
    } else {
        c
    }
}

/// Samples one level at (s, t) with `filter`.
pub fn sample_level(
    image: &TextureImage,
    level: usize,
    st: DVec2,
    filter: MagFilter,
    sampling: &Sampling,
) -> DVec4 {
    let l = &image.levels()[level];
    let (u, v) = (st.x * l.width() as f64, st.y * l.height() as f64);
    match filter {
        MagFilter::Nearest => {
            let i = wrap_index(u.floor() as i64, l.width(), sampling.wrap_s);
            let j = wrap_index(v.floor() as i64, l.height(), sampling.wrap_t);
            fetch(image, level, i, j)
        }
        MagFilter::Linear => {
            let (u, v) = (u - 0.5, v - 0.5);
            // `as` saturates a coordinate past i64's range (s/q with q = 0 is ∞), so the second
            // texel saturates too rather than overflowing past i64::MAX.
            let (i0, j0) = (u.floor() as i64, v.floor() as i64);
            let (a, b) = (u - u.floor(), v - v.floor());
            let i = [i0, i0.saturating_add(1)].map(|i| wrap_index(i, l.width(), sampling.wrap_s));
            let j = [j0, j0.saturating_add(1)].map(|j| wrap_index(j, l.height(), sampling.wrap_t));
            fetch(image, level, i[0], j[0]) * (1.0 - a) * (1.0 - b)
                + fetch(image, level, i[1], j[0]) * a * (1.0 - b)
                + fetch(image, level, i[0], j[1]) * (1.0 - a) * b
                + fetch(image, level, i[1], j[1]) * a * b
        }
    }
}

/// The filtered texel at (s, t) with level of detail `lambda` (section 3.8.8): magnified
/// (λ ≤ 0) with the mag filter, else minified with the min filter, choosing and blending
/// levels as it says.
pub fn sample(image: &TextureImage, sampling: &Sampling, st: DVec2, lambda: f64) -> DVec4 {
    if lambda <= 0.0 || lambda.is_nan() {
        return sample_level(image, 0, st, sampling.mag_filter, sampling);
    }
    let min = sampling.min_filter;
    let within = min.within_level();
    if !min.uses_mipmaps() {
        return sample_level(image, 0, st, within, sampling);
    }
    let q = (image.levels().len() - 1) as f64;
    if min.between_levels_linear() {
        let d1 = lambda.floor().min(q);
        let d2 = (d1 + 1.0).min(q);
        let frac = if lambda >= q { 0.0 } else { lambda - lambda.floor() };
        sample_level(image, d1 as usize, st, within, sampling) * (1.0 - frac)
            + sample_level(image, d2 as usize, st, within, sampling) * frac
    } else {
        let d = if lambda <= 0.5 {
            0.0
        } else {
            ((lambda + 0.5).ceil() - 1.0).min(q)
        };
        sample_level(image, d as usize, st, within, sampling)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::texture::MinFilter;

    fn c(r: f64, g: f64, b: f64, a: f64) -> DVec4 {
        DVec4::new(r, g, b, a)
    }

    #[test]
    fn table_3_22_for_rgba_textures() {
        let (f, s, cc) = (
            c(0.5, 0.25, 1.0, 0.8),
            c(0.5, 1.0, 0.0, 0.25),
            c(1.0, 0.0, 0.5, 1.0),
        );
        assert_eq!(tex_env(TexEnvMode::Replace, &Combine::default(), f, s, cc), s);
        assert_eq!(
            tex_env(TexEnvMode::Modulate, &Combine::default(), f, s, cc),
            c(0.25, 0.25, 0.0, 0.2)
        );
        // Decal: C_f (1 − A_s) + C_s A_s, alpha A_f.
        assert_eq!(
            tex_env(TexEnvMode::Decal, &Combine::default(), f, s, cc),
            c(0.5, 0.4375, 0.75, 0.8)
        );
        // Blend: C_f (1 − C_s) + C_c C_s, alpha A_f A_s.
        assert_eq!(
            tex_env(TexEnvMode::Blend, &Combine::default(), f, s, cc),
            c(0.75, 0.0, 1.0, 0.2)
        );
        // Add clamps.
        assert_eq!(
            tex_env(TexEnvMode::Add, &Combine::default(), f, s, cc),
            c(1.0, 1.0, 1.0, 0.2)
        );
    }

    #[test]
    fn wrap_modes_fold_texel_indices() {
        let idx = |w| (-5..9).map(|i| wrap_index(i, 4, w)).collect::<Vec<_>>();
        assert_eq!(idx(Wrap::Repeat), [3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0]);
        assert_eq!(idx(Wrap::ClampToEdge), [0, 0, 0, 0, 0, 0, 1, 2, 3, 3, 3, 3, 3, 3]);
        assert_eq!(
            idx(Wrap::MirroredRepeat),
            [3, 3, 2, 1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0]
        );
    }

    #[test]
    fn linear_filtering_weighs_the_four_nearest_texels() {
        // A 2x1 texture, black then white: halfway between the texel centers is grey.
        let image = TextureImage::new(2, 1, vec![0, 0, 0, 255, 255, 255, 255, 255]).unwrap();
        let s = Sampling {
            mag_filter: MagFilter::Linear,
            wrap_s: Wrap::ClampToEdge,
            ..Sampling::NEAREST
        };
        let mid = sample(&image, &s, DVec2::new(0.5, 0.5), -1.0);
        assert!((mid.x - 0.5).abs() < 1e-12, "{mid}");
        let at_center = sample(&image, &s, DVec2::new(0.25, 0.5), -1.0);
        assert_eq!(at_center.x, 0.0);
        // Nearest picks the texel whose square holds the point.
        let n = sample(&image, &Sampling::NEAREST, DVec2::new(0.49, 0.5), -1.0);
        assert_eq!(n.x, 0.0);
    }

    #[test]
    fn minification_walks_the_mipmap_chain() {
        let image = TextureImage::checker(8, 8, [255; 4], [0, 0, 0, 255])
            .unwrap()
            .with_mipmaps();
        let s = Sampling {
            min_filter: MinFilter::NearestMipmapNearest,
            ..Sampling::NEAREST
        };
        // λ = 3: the 1x1 level, the checker's mean.
        let t = sample(&image, &s, DVec2::new(0.3, 0.3), 3.0);
        assert!((t.x - 128.0 / 255.0).abs() < 1e-12, "{t}");
        // λ = 0.4 ≤ 1/2: level 0 still.
        assert_eq!(sample(&image, &s, DVec2::new(0.01, 0.01), 0.4).x, 1.0);
        let lin = Sampling {
            min_filter: MinFilter::NearestMipmapLinear,
            ..Sampling::NEAREST
        };
        // λ = 2.5 blends levels 2 (a 2x2 checker of 4x4 cells... here all 1-texel cells, so
        // level 1 onward are grey) equally.
        let t = sample(&image, &lin, DVec2::new(0.3, 0.3), 2.5);
        assert!((t.x - 128.0 / 255.0).abs() < 1e-12, "{t}");
        assert_eq!(lambda(&image, DVec2::new(0.5, 0.0), DVec2::new(0.0, 0.25)), 2.0);
    }

    #[test]
    fn srgb_textures_decode_rgb_but_not_alpha() {
        let mut image = TextureImage::new(1, 1, vec![128, 0, 255, 128]).unwrap();
        image.srgb = true;
        let t = sample(&image, &Sampling::NEAREST, DVec2::ZERO, 0.0);
        assert!((t.x - 0.2158605).abs() < 1e-6, "{t}");
        assert_eq!((t.y, t.z), (0.0, 1.0));
        assert!((t.w - 128.0 / 255.0).abs() < 1e-12);
    }
}
