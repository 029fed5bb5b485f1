//! glGet's answers for the raster state of a context ([`ffvk::gl::state::RasterGl`]): enums as
//! GL's values, the depth range and blend color as colors (mapped linearly to integers), the
//! rest as GL 2.1's tables 6.12-6.21 type them.

use ffvk::gl::state::{Face, GlEnum, StencilGl};

use super::Answer;
use crate::enums::*;
use crate::gl::FfvkContext;

fn int<T: GlEnum>(value: T) -> Answer {
    Answer::Int(i64::from(value.gl()))
}

/// A stencil face's answer for `pname` relative to the front face's names.
fn stencil(s: &StencilGl, front_pname: u32) -> Option<Answer> {
    Some(match front_pname {
        GL_STENCIL_FUNC => int(s.func),
        GL_STENCIL_REF => Answer::Int(i64::from(s.clamped_reference())),
        GL_STENCIL_VALUE_MASK => Answer::Int(i64::from(s.value_mask)),
        GL_STENCIL_FAIL => int(s.fail),
        GL_STENCIL_PASS_DEPTH_FAIL => int(s.pass_depth_fail),
        GL_STENCIL_PASS_DEPTH_PASS => int(s.pass_depth_pass),
        GL_STENCIL_WRITEMASK => Answer::Int(i64::from(s.write_mask)),
        _ => return None,
    })
}

/// The answer for a raster state name; `None` for another name (the caps are answered with
/// the others').
pub(super) fn answer(c: &FfvkContext, pname: u32) -> Option<Answer> {
    let r = &c.gl.raster;
    let back = match pname {
        GL_STENCIL_BACK_FUNC => Some(GL_STENCIL_FUNC),
        GL_STENCIL_BACK_REF => Some(GL_STENCIL_REF),
        GL_STENCIL_BACK_VALUE_MASK => Some(GL_STENCIL_VALUE_MASK),
        GL_STENCIL_BACK_FAIL => Some(GL_STENCIL_FAIL),
        GL_STENCIL_BACK_PASS_DEPTH_FAIL => Some(GL_STENCIL_PASS_DEPTH_FAIL),
        GL_STENCIL_BACK_PASS_DEPTH_PASS => Some(GL_STENCIL_PASS_DEPTH_PASS),
        GL_STENCIL_BACK_WRITEMASK => Some(GL_STENCIL_WRITEMASK),
        _ => None,
    };
    if let Some(front_pname) = back {
        return stencil(&r.stencil_back, front_pname);
    }
    if let Some(a) = stencil(&r.stencil_front, pname) {
        return Some(a);
    }
    Some(match pname {
        GL_POLYGON_MODE => Answer::Ints(vec![
            i64::from(r.polygon_front.gl()),
            i64::from(r.polygon_back.gl()),
        ]),
        GL_POLYGON_OFFSET_FACTOR => Answer::Floats(vec![r.polygon_offset_factor]),
        GL_POLYGON_OFFSET_UNITS => Answer::Floats(vec![r.polygon_offset_units]),
        GL_EDGE_FLAG => Answer::Bool(r.edge_flag),
        GL_LINE_STIPPLE_PATTERN => Answer::Int(i64::from(r.line_stipple_pattern)),
        GL_LINE_STIPPLE_REPEAT => Answer::Int(i64::from(r.line_stipple_repeat)),
        GL_DEPTH_RANGE => Answer::Color(r.depth_range.map(|v| v as f32).to_vec()),
        GL_STENCIL_CLEAR_VALUE => Answer::Int(i64::from(r.stencil_clear)),
        GL_COLOR_WRITEMASK => Answer::Ints(r.color_mask.map(i64::from).to_vec()),
        GL_DEPTH_WRITEMASK => Answer::Bool(r.depth_mask),
        GL_DEPTH_FUNC => int(r.depth_func),
        GL_BLEND_SRC | GL_BLEND_SRC_RGB => int(r.blend_src_rgb),
        GL_BLEND_DST | GL_BLEND_DST_RGB => int(r.blend_dst_rgb),
        GL_BLEND_SRC_ALPHA => int(r.blend_src_alpha),
        GL_BLEND_DST_ALPHA => int(r.blend_dst_alpha),
        GL_BLEND_EQUATION_RGB => int(r.blend_equation_rgb),
        GL_BLEND_EQUATION_ALPHA => int(r.blend_equation_alpha),
        GL_BLEND_COLOR => Answer::Color(r.blend_color.to_array().to_vec()),
        GL_LOGIC_OP_MODE => int(r.logic_op),
        GL_CULL_FACE_MODE => Answer::Int(i64::from(match r.cull_face_mode {
            Face::Front => GL_FRONT,
            Face::Back => GL_BACK,
            Face::FrontAndBack => GL_FRONT_AND_BACK,
        })),
        GL_FRONT_FACE => int(r.front_face),
        GL_POINT_SIZE => Answer::Floats(vec![r.point_size]),
        GL_LINE_WIDTH => Answer::Floats(vec![r.line_width]),
        _ => return None,
    })
}
