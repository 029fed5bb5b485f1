//! The calls a draw replays before it is drawn ([`GlCall`]): GL's raster state and the few
//! lighting calls whose rules GL applies itself, with the conversions of ffvk's Vulkan enums
//! to GL's names.

use ffvk::gl::state::{Cap, ColorMaterialMode, Face};

use super::bindings::types::{GLenum, GLint};
use super::bindings::{self as gl, Gl};
use super::GlCall;

fn cap_enum(cap: Cap) -> GLenum {
    match cap {
        Cap::Lighting => gl::LIGHTING,
        Cap::Light(i) => gl::LIGHT0 + i as GLenum,
        Cap::ColorMaterial => gl::COLOR_MATERIAL,
        Cap::Normalize => gl::NORMALIZE,
        Cap::RescaleNormal => gl::RESCALE_NORMAL,
        Cap::Texture2D => gl::TEXTURE_2D,
        Cap::TextureCubeMap => gl::TEXTURE_CUBE_MAP,
        // As in wrap_enum: GL's INVALID_ENUM fails the render.
        _ => gl::NONE,
    }
}

/// Makes one replayed call.
pub(super) fn replay(gl: &Gl, call: GlCall) {
    match call {
        // SAFETY: a context is current on this thread; the color has four components.
        GlCall::Color(c) => unsafe { gl.Color4fv(c.to_array().as_ptr()) },
        GlCall::Enable(cap) => set_enabled(gl, cap_enum(cap), true),
        GlCall::Disable(cap) => set_enabled(gl, cap_enum(cap), false),
        // SAFETY: a context is current on this thread.
        GlCall::ColorMaterial(face, mode) => unsafe {
            gl.ColorMaterial(face_enum(face), color_material_enum(mode))
        },
        GlCall::PolygonOffsetFill(factor, units) => {
            set_enabled(gl, gl::POLYGON_OFFSET_FILL, true);
            // SAFETY: a context is current on this thread.
            unsafe { gl.PolygonOffset(factor, units) };
        }
        // SAFETY: a context is current on this thread.
        GlCall::ColorMask([r, g, b, a]) => unsafe { gl.ColorMask(r as u8, g as u8, b as u8, a as u8) },
        GlCall::Blend(b) => {
            set_enabled(gl, gl::BLEND, true);
            // SAFETY: a context is current on this thread.
            unsafe {
                gl.BlendFuncSeparate(
                    blend_factor(b.src_color),
                    blend_factor(b.dst_color),
                    blend_factor(b.src_alpha),
                    blend_factor(b.dst_alpha),
                );
                gl.BlendEquationSeparate(blend_op(b.color_op), blend_op(b.alpha_op));
            }
        }
        // SAFETY: a context is current on this thread.
        GlCall::BlendColor([r, g, b, a]) => unsafe { gl.BlendColor(r, g, b, a) },
        GlCall::PolygonOffset(o) => {
            set_enabled(gl, gl::POLYGON_OFFSET_FILL, o.fill);
            set_enabled(gl, gl::POLYGON_OFFSET_LINE, o.line);
            set_enabled(gl, gl::POLYGON_OFFSET_POINT, o.point);
            // SAFETY: a context is current on this thread.
            unsafe { gl.PolygonOffset(o.factor, o.units) };
        }
        // SAFETY: a context is current on this thread.
        GlCall::PolygonMode(m) => unsafe {
            gl.PolygonMode(gl::FRONT, polygon_mode(m.front));
            gl.PolygonMode(gl::BACK, polygon_mode(m.back));
        },
        GlCall::Stencil(s) => {
            set_enabled(gl, gl::STENCIL_TEST, true);
            for (face, f) in [(gl::FRONT, s.front), (gl::BACK, s.back)] {
                // SAFETY: a context is current on this thread.
                unsafe {
                    gl.StencilFuncSeparate(face, compare_func(f.func), f.reference as GLint, f.value_mask);
                    gl.StencilOpSeparate(
                        face,
                        stencil_op(f.fail),
                        stencil_op(f.depth_fail),
                        stencil_op(f.pass),
                    );
                    gl.StencilMaskSeparate(face, f.write_mask);
                }
            }
        }
        GlCall::LogicOp(op) => {
            set_enabled(gl, gl::COLOR_LOGIC_OP, true);
            // SAFETY: a context is current on this thread; CLEAR + op is GL's order of the
            // sixteen, Vulkan's too.
            unsafe { gl.LogicOp(gl::CLEAR + op.as_raw() as GLenum) };
        }
        // SAFETY: a context is current on this thread.
        GlCall::DepthRange(near, far) => unsafe { gl.DepthRange(near, far) },
        // SAFETY: a context is current on this thread.
        GlCall::DepthMask(on) => unsafe { gl.DepthMask(u8::from(on)) },
        GlCall::PolygonStipple(mask) => {
            set_enabled(gl, gl::POLYGON_STIPPLE, true);
            // SAFETY: a context is current on this thread; the mask is GL's 32 × 32 bits.
            unsafe { gl.PolygonStipple(mask.as_ptr()) };
        }
        GlCall::CullFace(face) => {
            set_enabled(gl, gl::CULL_FACE, true);
            // SAFETY: a context is current on this thread.
            unsafe { gl.CullFace(face_enum(face)) };
        }
        GlCall::FrontFace(winding) => {
            let mode = if winding == ash::vk::FrontFace::CLOCKWISE {
                gl::CW
            } else {
                gl::CCW
            };
            // SAFETY: a context is current on this thread.
            unsafe { gl.FrontFace(mode) };
        }
        GlCall::LineStipple(l) => {
            set_enabled(gl, gl::LINE_STIPPLE, true);
            // SAFETY: a context is current on this thread.
            unsafe { gl.LineStipple(l.factor as GLint, l.pattern) };
        }
    }
}

/// The calls that set a scene mesh's raster state ([`ffvk::scene::MeshRaster`]) on GL's
/// defaults (what each draw starts from): those of the state that differs from them.
pub fn mesh_raster_calls(r: &ffvk::scene::MeshRaster) -> Vec<GlCall> {
    let mut calls = Vec::new();
    if let Some(face) = r.cull_face {
        calls.push(GlCall::CullFace(face));
    }
    if r.front_face != ash::vk::FrontFace::COUNTER_CLOCKWISE {
        calls.push(GlCall::FrontFace(r.front_face));
    }
    if r.polygon_mode != ffvk::PolygonModes::FILL {
        calls.push(GlCall::PolygonMode(r.polygon_mode));
    }
    calls.extend(r.polygon_offset.map(GlCall::PolygonOffset));
    if r.color_mask != [true; 4] {
        calls.push(GlCall::ColorMask(r.color_mask));
    }
    calls.extend(r.stencil.map(GlCall::Stencil));
    calls.extend(r.logic_op.map(GlCall::LogicOp));
    calls.extend(r.line_stipple.map(GlCall::LineStipple));
    calls.extend(r.polygon_stipple.map(GlCall::PolygonStipple));
    calls.extend(r.blend.map(GlCall::Blend));
    if r.blend_color != [0.0; 4] {
        calls.push(GlCall::BlendColor(r.blend_color));
    }
    if r.depth_range != [0.0, 1.0] {
        calls.push(GlCall::DepthRange(
            r.depth_range[0].into(),
            r.depth_range[1].into(),
        ));
    }
    if !r.depth_write {
        calls.push(GlCall::DepthMask(false));
    }
    calls
}

/// GL's name of a Vulkan polygon mode.
fn polygon_mode(m: ash::vk::PolygonMode) -> GLenum {
    match m {
        ash::vk::PolygonMode::LINE => gl::LINE,
        ash::vk::PolygonMode::POINT => gl::POINT,
        _ => gl::FILL,
    }
}

/// GL's name of a Vulkan compare op (`NEVER` + the op: the same order).
fn compare_func(op: ash::vk::CompareOp) -> GLenum {
    gl::NEVER + op.as_raw() as GLenum
}

/// GL's name of a Vulkan stencil op.
fn stencil_op(op: ash::vk::StencilOp) -> GLenum {
    use ash::vk::StencilOp as S;
    match op {
        S::ZERO => gl::ZERO,
        S::REPLACE => gl::REPLACE,
        S::INCREMENT_AND_CLAMP => gl::INCR,
        S::DECREMENT_AND_CLAMP => gl::DECR,
        S::INVERT => gl::INVERT,
        S::INCREMENT_AND_WRAP => gl::INCR_WRAP,
        S::DECREMENT_AND_WRAP => gl::DECR_WRAP,
        _ => gl::KEEP,
    }
}

/// GL's name of a Vulkan blend factor (the fifteen GL 2.1 has).
fn blend_factor(f: ash::vk::BlendFactor) -> GLenum {
    use ash::vk::BlendFactor as F;
    match f {
        F::ZERO => gl::ZERO,
        F::ONE => gl::ONE,
        F::SRC_COLOR => gl::SRC_COLOR,
        F::ONE_MINUS_SRC_COLOR => gl::ONE_MINUS_SRC_COLOR,
        F::DST_COLOR => gl::DST_COLOR,
        F::ONE_MINUS_DST_COLOR => gl::ONE_MINUS_DST_COLOR,
        F::SRC_ALPHA => gl::SRC_ALPHA,
        F::ONE_MINUS_SRC_ALPHA => gl::ONE_MINUS_SRC_ALPHA,
        F::DST_ALPHA => gl::DST_ALPHA,
        F::ONE_MINUS_DST_ALPHA => gl::ONE_MINUS_DST_ALPHA,
        F::CONSTANT_COLOR => gl::CONSTANT_COLOR,
        F::ONE_MINUS_CONSTANT_COLOR => gl::ONE_MINUS_CONSTANT_COLOR,
        F::CONSTANT_ALPHA => gl::CONSTANT_ALPHA,
        F::ONE_MINUS_CONSTANT_ALPHA => gl::ONE_MINUS_CONSTANT_ALPHA,
        _ => gl::SRC_ALPHA_SATURATE,
    }
}

/// GL's name of a Vulkan blend equation (GL 2.1's five).
fn blend_op(op: ash::vk::BlendOp) -> GLenum {
    use ash::vk::BlendOp as O;
    match op {
        O::SUBTRACT => gl::FUNC_SUBTRACT,
        O::REVERSE_SUBTRACT => gl::FUNC_REVERSE_SUBTRACT,
        O::MIN => gl::MIN,
        O::MAX => gl::MAX,
        _ => gl::FUNC_ADD,
    }
}

pub(super) fn face_enum(face: Face) -> GLenum {
    match face {
        Face::Front => gl::FRONT,
        Face::Back => gl::BACK,
        Face::FrontAndBack => gl::FRONT_AND_BACK,
    }
}

pub(super) fn color_material_enum(mode: ColorMaterialMode) -> GLenum {
    match mode {
        ColorMaterialMode::Emission => gl::EMISSION,
        ColorMaterialMode::Ambient => gl::AMBIENT,
        ColorMaterialMode::Diffuse => gl::DIFFUSE,
        ColorMaterialMode::Specular => gl::SPECULAR,
        ColorMaterialMode::AmbientAndDiffuse => gl::AMBIENT_AND_DIFFUSE,
    }
}

pub(super) fn set_enabled(gl: &Gl, cap: GLenum, on: bool) {
    // SAFETY: a context is current on this thread.
    unsafe {
        if on {
            gl.Enable(cap)
        } else {
            gl.Disable(cap)
        }
    }
}
