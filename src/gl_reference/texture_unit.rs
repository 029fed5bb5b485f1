//! The texture unit's GL calls: the bound texture object, glTexEnv (the classic modes and
//! `GL_COMBINE`), the `GL_TEXTURE` matrix, the `GL_TEXTURE_2D` enable and glTexGen.

use ffvk::gl::texture::{TexEnvMode, TextureUnit};

use super::bindings::types::{GLenum, GLint, GLuint};
use super::bindings::{self as gl, Gl};
use super::calls::set_enabled;

fn tex_env_enum(mode: TexEnvMode) -> GLenum {
    match mode {
        TexEnvMode::Modulate => gl::MODULATE,
        TexEnvMode::Replace => gl::REPLACE,
        TexEnvMode::Decal => gl::DECAL,
        TexEnvMode::Blend => gl::BLEND,
        TexEnvMode::Add => gl::ADD,
        TexEnvMode::Combine => gl::COMBINE,
        // As in wrap_enum: GL's INVALID_ENUM fails the render.
        _ => gl::NONE,
    }
}

/// The active texture unit: texture object `texture` bound (else object 0, which has no image), the
/// environment, the `GL_TEXTURE` matrix and the `GL_TEXTURE_2D` enable. Leaves the matrix mode
/// at `GL_MODELVIEW`.
pub(super) fn set_texture_unit(
    gl: &Gl,
    unit: &TextureUnit,
    (texture, cube_map): (Option<GLuint>, Option<GLuint>),
) {
    // SAFETY: a context is current on this thread; the names, when there are some, are
    // textures it made and has not deleted; the color has four components and the matrix 16,
    // column-major as both glam and GL store it.
    unsafe {
        gl.BindTexture(gl::TEXTURE_2D, texture.unwrap_or(0));
        // Cube maps only where some are used, as a program without them issues nothing.
        if cube_map.is_some() || unit.cube_map {
            gl.BindTexture(gl::TEXTURE_CUBE_MAP, cube_map.unwrap_or(0));
        }
        gl.TexEnvi(
            gl::TEXTURE_ENV,
            gl::TEXTURE_ENV_MODE,
            tex_env_enum(unit.env_mode) as GLint,
        );
        gl.TexEnvfv(
            gl::TEXTURE_ENV,
            gl::TEXTURE_ENV_COLOR,
            unit.env_color.to_array().as_ptr(),
        );
        gl.MatrixMode(gl::TEXTURE);
        gl.LoadMatrixf(unit.matrix.to_cols_array().as_ptr());
        gl.MatrixMode(gl::MODELVIEW);
        gl.TexEnvi(gl::POINT_SPRITE, gl::COORD_REPLACE, unit.coord_replace as GLint);
    }
    set_enabled(gl, gl::TEXTURE_2D, unit.enabled);
    if cube_map.is_some() || unit.cube_map {
        set_enabled(gl, gl::TEXTURE_CUBE_MAP, unit.cube_map);
    }
    // GL_COMBINE's parameters and a coordinate's generation only where they are used, as a
    // program issues them (the timed frames' anchor issues no call an application would not).
    if unit.env_mode == TexEnvMode::Combine {
        set_combine(gl, &unit.combine);
    }
    // Texture coordinate generation, with the modelview at identity (set_state's), so that
    // each eye plane, already in eye space, is stored as it is.
    let coords = [
        (gl::S, gl::TEXTURE_GEN_S),
        (gl::T, gl::TEXTURE_GEN_T),
        (gl::R, gl::TEXTURE_GEN_R),
        (gl::Q, gl::TEXTURE_GEN_Q),
    ];
    for ((coord, cap), g) in coords.into_iter().zip(&unit.texgen) {
        set_enabled(gl, cap, g.enabled);
        if !g.enabled {
            continue;
        }
        // SAFETY: a context is current on this thread; each plane has four components.
        unsafe {
            gl.TexGeni(coord, gl::TEXTURE_GEN_MODE, texgen_enum(g.mode) as GLint);
            gl.TexGenfv(coord, gl::OBJECT_PLANE, g.object_plane.to_array().as_ptr());
            gl.TexGenfv(coord, gl::EYE_PLANE, g.eye_plane.to_array().as_ptr());
        }
    }
}

/// glTexEnv's `GL_COMBINE` state, every parameter.
fn set_combine(gl: &Gl, c: &ffvk::gl::texture::Combine) {
    use ffvk::gl::texture::{AlphaOperand, CombineFunc, CombineSource, RgbOperand};
    let func = |f: CombineFunc| match f {
        CombineFunc::Replace => gl::REPLACE,
        CombineFunc::Modulate => gl::MODULATE,
        CombineFunc::Add => gl::ADD,
        CombineFunc::AddSigned => gl::ADD_SIGNED,
        CombineFunc::Interpolate => gl::INTERPOLATE,
        CombineFunc::Subtract => gl::SUBTRACT,
        CombineFunc::Dot3Rgb => gl::DOT3_RGB,
        CombineFunc::Dot3Rgba => gl::DOT3_RGBA,
        _ => gl::NONE,
    };
    let source = |s: CombineSource| match s {
        CombineSource::Texture => gl::TEXTURE,
        CombineSource::Constant => gl::CONSTANT,
        CombineSource::PrimaryColor => gl::PRIMARY_COLOR,
        CombineSource::Previous => gl::PREVIOUS,
        CombineSource::TextureUnit(n) => gl::TEXTURE0 + u32::from(n),
        _ => gl::NONE,
    };
    let rgb_operand = |o: RgbOperand| match o {
        RgbOperand::SrcColor => gl::SRC_COLOR,
        RgbOperand::OneMinusSrcColor => gl::ONE_MINUS_SRC_COLOR,
        RgbOperand::SrcAlpha => gl::SRC_ALPHA,
        RgbOperand::OneMinusSrcAlpha => gl::ONE_MINUS_SRC_ALPHA,
        _ => gl::NONE,
    };
    let alpha_operand = |o: AlphaOperand| match o {
        AlphaOperand::SrcAlpha => gl::SRC_ALPHA,
        AlphaOperand::OneMinusSrcAlpha => gl::ONE_MINUS_SRC_ALPHA,
        _ => gl::NONE,
    };
    let env = |pname: GLenum, value: GLenum| {
        // SAFETY: a context is current on this thread.
        unsafe { gl.TexEnvi(gl::TEXTURE_ENV, pname, value as GLint) };
    };
    env(gl::COMBINE_RGB, func(c.rgb));
    env(gl::COMBINE_ALPHA, func(c.alpha));
    for i in 0..3 {
        env(gl::SRC0_RGB + i as GLenum, source(c.rgb_sources[i]));
        env(gl::SRC0_ALPHA + i as GLenum, source(c.alpha_sources[i]));
        env(gl::OPERAND0_RGB + i as GLenum, rgb_operand(c.rgb_operands[i]));
        env(
            gl::OPERAND0_ALPHA + i as GLenum,
            alpha_operand(c.alpha_operands[i]),
        );
    }
    // SAFETY: a context is current on this thread.
    unsafe {
        gl.TexEnvf(gl::TEXTURE_ENV, gl::RGB_SCALE, c.rgb_scale);
        gl.TexEnvf(gl::TEXTURE_ENV, gl::ALPHA_SCALE, c.alpha_scale);
    }
}

/// GL's enum of a texture coordinate generation mode.
fn texgen_enum(mode: ffvk::gl::texture::TexGenMode) -> GLenum {
    use ffvk::gl::texture::TexGenMode;
    match mode {
        TexGenMode::ObjectLinear => gl::OBJECT_LINEAR,
        TexGenMode::EyeLinear => gl::EYE_LINEAR,
        TexGenMode::SphereMap => gl::SPHERE_MAP,
        TexGenMode::ReflectionMap => gl::REFLECTION_MAP,
        TexGenMode::NormalMap => gl::NORMAL_MAP,
        // As in tex_env_enum: GL's INVALID_ENUM fails the render.
        _ => gl::NONE,
    }
}
