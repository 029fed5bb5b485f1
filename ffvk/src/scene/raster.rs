//! A mesh's raster state in scene files: `glPolygonMode`, `glPolygonOffset`, `glColorMask`,
//! the stencil test, `glLogicOp`, `glLineStipple`, blending and culling, each with GL's names
//! and GL's defaults, checked into the [`MeshRaster`] its draw is made with.

use super::file::{BlendSpec, MeshSpec, PolygonModeSpec, StencilSpec};
use super::{Builder, SceneError};
use crate::gl::state::Face;
use crate::{Blend, LineStipple, PolygonModes, PolygonOffset, Stencil, StencilFace};
use ash::vk;

/// The raster state one scene mesh is drawn with; `Default` is GL's initial state.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct MeshRaster {
    /// `GL_CULL_FACE` with `glCullFace` (`cull_face`): `None`, GL's default, leaves the choice
    /// to the glTF meaning ([`Scene::cull_face`](super::Scene::cull_face)).
    pub cull_face: Option<Face>,
    /// `glFrontFace` (`front_face`): `COUNTER_CLOCKWISE` (`"ccw"`, GL's default) or
    /// `CLOCKWISE` (`"cw"`).
    pub front_face: vk::FrontFace,
    /// `glPolygonMode` (`polygon_mode`).
    pub polygon_mode: PolygonModes,
    /// `glPolygonOffset` with its modes (`polygon_offset`); `None`: all three off.
    pub polygon_offset: Option<PolygonOffset>,
    /// `glColorMask` (`color_mask`), R, G, B, A.
    pub color_mask: [bool; 4],
    /// `GL_STENCIL_TEST` (`stencil`, `stencil_back`).
    pub stencil: Option<Stencil>,
    /// `GL_COLOR_LOGIC_OP` with `glLogicOp` (`logic_op`).
    pub logic_op: Option<vk::LogicOp>,
    /// `GL_LINE_STIPPLE` with `glLineStipple` (`line_stipple`).
    pub line_stipple: Option<LineStipple>,
    /// `GL_POLYGON_STIPPLE` with `glPolygonStipple` (`polygon_stipple`): the mask as GL takes
    /// it, 4 bytes a row from the bottom row up.
    pub polygon_stipple: Option<[u8; 128]>,
    /// `GL_BLEND` with its factors and equations (`blend`).
    pub blend: Option<Blend>,
    /// `glBlendColor` (`blend_color`).
    pub blend_color: [f32; 4],
    /// `glDepthRange(near, far)` (`depth_range`), finite; the renderer clamps each to
    /// [0, 1] as GL does.
    pub depth_range: [f32; 2],
    /// `glDepthMask` (`depth_mask`): depth writes on by default.
    pub depth_write: bool,
}

impl Default for MeshRaster {
    fn default() -> Self {
        MeshRaster {
            cull_face: None,
            front_face: vk::FrontFace::COUNTER_CLOCKWISE,
            polygon_mode: PolygonModes::FILL,
            polygon_offset: None,
            color_mask: [true; 4],
            stencil: None,
            logic_op: None,
            line_stipple: None,
            polygon_stipple: None,
            blend: None,
            blend_color: [0.0; 4],
            depth_range: [0.0, 1.0],
            depth_write: true,
        }
    }
}

impl MeshRaster {
    /// Whether this is GL's initial state.
    pub fn is_default(&self) -> bool {
        *self == MeshRaster::default()
    }
}

const COMPARE: &[(&str, vk::CompareOp)] = &[
    ("never", vk::CompareOp::NEVER),
    ("less", vk::CompareOp::LESS),
    ("equal", vk::CompareOp::EQUAL),
    ("lequal", vk::CompareOp::LESS_OR_EQUAL),
    ("greater", vk::CompareOp::GREATER),
    ("notequal", vk::CompareOp::NOT_EQUAL),
    ("gequal", vk::CompareOp::GREATER_OR_EQUAL),
    ("always", vk::CompareOp::ALWAYS),
];

const STENCIL_OP: &[(&str, vk::StencilOp)] = &[
    ("keep", vk::StencilOp::KEEP),
    ("zero", vk::StencilOp::ZERO),
    ("replace", vk::StencilOp::REPLACE),
    ("incr", vk::StencilOp::INCREMENT_AND_CLAMP),
    ("decr", vk::StencilOp::DECREMENT_AND_CLAMP),
    ("invert", vk::StencilOp::INVERT),
    ("incr_wrap", vk::StencilOp::INCREMENT_AND_WRAP),
    ("decr_wrap", vk::StencilOp::DECREMENT_AND_WRAP),
];

const LOGIC_OP: &[(&str, vk::LogicOp)] = &[
    ("clear", vk::LogicOp::CLEAR),
    ("and", vk::LogicOp::AND),
    ("and_reverse", vk::LogicOp::AND_REVERSE),
    ("copy", vk::LogicOp::COPY),
    ("and_inverted", vk::LogicOp::AND_INVERTED),
    ("noop", vk::LogicOp::NO_OP),
    ("xor", vk::LogicOp::XOR),
    ("or", vk::LogicOp::OR),
    ("nor", vk::LogicOp::NOR),
    ("equiv", vk::LogicOp::EQUIVALENT),
    ("invert", vk::LogicOp::INVERT),
    ("or_reverse", vk::LogicOp::OR_REVERSE),
    ("copy_inverted", vk::LogicOp::COPY_INVERTED),
    ("or_inverted", vk::LogicOp::OR_INVERTED),
    ("nand", vk::LogicOp::NAND),
    ("set", vk::LogicOp::SET),
];

const POLYGON_MODE: &[(&str, vk::PolygonMode)] = &[
    ("point", vk::PolygonMode::POINT),
    ("line", vk::PolygonMode::LINE),
    ("fill", vk::PolygonMode::FILL),
];

const BLEND_FACTOR: &[(&str, vk::BlendFactor)] = &[
    ("zero", vk::BlendFactor::ZERO),
    ("one", vk::BlendFactor::ONE),
    ("src_color", vk::BlendFactor::SRC_COLOR),
    ("one_minus_src_color", vk::BlendFactor::ONE_MINUS_SRC_COLOR),
    ("dst_color", vk::BlendFactor::DST_COLOR),
    ("one_minus_dst_color", vk::BlendFactor::ONE_MINUS_DST_COLOR),
    ("src_alpha", vk::BlendFactor::SRC_ALPHA),
    ("one_minus_src_alpha", vk::BlendFactor::ONE_MINUS_SRC_ALPHA),
    ("dst_alpha", vk::BlendFactor::DST_ALPHA),
    ("one_minus_dst_alpha", vk::BlendFactor::ONE_MINUS_DST_ALPHA),
    ("constant_color", vk::BlendFactor::CONSTANT_COLOR),
    (
        "one_minus_constant_color",
        vk::BlendFactor::ONE_MINUS_CONSTANT_COLOR,
    ),
    ("constant_alpha", vk::BlendFactor::CONSTANT_ALPHA),
    (
        "one_minus_constant_alpha",
        vk::BlendFactor::ONE_MINUS_CONSTANT_ALPHA,
    ),
    ("src_alpha_saturate", vk::BlendFactor::SRC_ALPHA_SATURATE),
];

const BLEND_EQUATION: &[(&str, vk::BlendOp)] = &[
    ("func_add", vk::BlendOp::ADD),
    ("func_subtract", vk::BlendOp::SUBTRACT),
    ("func_reverse_subtract", vk::BlendOp::REVERSE_SUBTRACT),
    ("min", vk::BlendOp::MIN),
    ("max", vk::BlendOp::MAX),
];

const FRONT_FACE: &[(&str, vk::FrontFace)] = &[
    ("ccw", vk::FrontFace::COUNTER_CLOCKWISE),
    ("cw", vk::FrontFace::CLOCKWISE),
];

const FACE: &[(&str, Face)] = &[
    ("front", Face::Front),
    ("back", Face::Back),
    ("front_and_back", Face::FrontAndBack),
];

impl Builder<'_> {
    /// `word` (if given) looked up in `table`, else `default`.
    fn word_or<T: Copy>(
        &self,
        field: &str,
        word: Option<&str>,
        table: &[(&str, T)],
        default: T,
    ) -> Result<T, SceneError> {
        word.map_or(Ok(default), |w| self.word(field, w, table))
    }

    /// An integer of `field` in `range`, or an error naming the field, the value and the
    /// range (`what` says what the range is).
    fn integer(
        &self,
        field: &str,
        value: i64,
        range: std::ops::RangeInclusive<i64>,
        what: &str,
    ) -> Result<i64, SceneError> {
        if range.contains(&value) {
            Ok(value)
        } else {
            Err(self.field(
                field,
                format!("{value}: expected {}..={} ({what})", range.start(), range.end()),
            ))
        }
    }

    /// The `[[meshes]]` table `field`'s raster state.
    pub(super) fn mesh_raster(&self, field: &str, spec: &MeshSpec) -> Result<MeshRaster, SceneError> {
        let at = |name: &str| format!("{field}.{name}");
        let mut raster = MeshRaster::default();
        if let Some(face) = &spec.cull_face {
            raster.cull_face = Some(self.word(&at("cull_face"), face, FACE)?);
        }
        if let Some(winding) = &spec.front_face {
            raster.front_face = self.word(&at("front_face"), winding, FRONT_FACE)?;
        }
        raster.polygon_mode = match &spec.polygon_mode {
            None => PolygonModes::FILL,
            Some(PolygonModeSpec::Both(mode)) => {
                PolygonModes::both(self.word(&at("polygon_mode"), mode, POLYGON_MODE)?)
            }
            Some(PolygonModeSpec::Faces(faces)) => PolygonModes {
                front: self.word_or(
                    &at("polygon_mode.front"),
                    faces.front.as_deref(),
                    POLYGON_MODE,
                    vk::PolygonMode::FILL,
                )?,
                back: self.word_or(
                    &at("polygon_mode.back"),
                    faces.back.as_deref(),
                    POLYGON_MODE,
                    vk::PolygonMode::FILL,
                )?,
            },
        };
        if let Some(o) = &spec.polygon_offset {
            let factor = o.factor.unwrap_or(0.0);
            let units = o.units.unwrap_or(0.0);
            self.finite(&at("polygon_offset.factor"), &[factor])?;
            self.finite(&at("polygon_offset.units"), &[units])?;
            let offset = PolygonOffset {
                fill: o.fill.unwrap_or(true),
                line: o.line.unwrap_or(false),
                point: o.point.unwrap_or(false),
                ..PolygonOffset::fill(factor, units)
            };
            raster.polygon_offset = (offset.fill || offset.line || offset.point).then_some(offset);
        }
        if let Some(mask) = spec.color_mask {
            raster.color_mask = mask;
        }
        if let Some(front) = &spec.stencil {
            let front = self.stencil_face(&at("stencil"), front)?;
            let back = match &spec.stencil_back {
                Some(back) => self.stencil_face(&at("stencil_back"), back)?,
                None => front,
            };
            raster.stencil = Some(Stencil { front, back });
        } else if spec.stencil_back.is_some() {
            return Err(self.field(
                at("stencil_back"),
                "is given without stencil: expected a stencil table too (GL_STENCIL_TEST is \
                 enabled for both faces at once)",
            ));
        }
        if let Some(op) = &spec.logic_op {
            raster.logic_op = Some(self.word(&at("logic_op"), op, LOGIC_OP)?);
        }
        if let Some(s) = &spec.line_stipple {
            let factor = self.integer(
                &at("line_stipple.factor"),
                s.factor.unwrap_or(1),
                1..=256,
                "glLineStipple's repeat factor",
            )?;
            let pattern = self.integer(
                &at("line_stipple.pattern"),
                s.pattern.unwrap_or(0xFFFF),
                0..=0xFFFF,
                "a 16-bit pattern",
            )?;
            raster.line_stipple = Some(LineStipple {
                factor: factor as u32,
                pattern: pattern as u16,
            });
        }
        if let Some(rows) = &spec.polygon_stipple {
            if rows.len() != 32 {
                return Err(self.field(
                    at("polygon_stipple"),
                    format!(
                        "{} rows: expected exactly 32 (the pattern's rows, the bottom one first)",
                        rows.len()
                    ),
                ));
            }
            let mut mask = [0u8; 128];
            for (i, (&row, bytes)) in rows.iter().zip(mask.chunks_exact_mut(4)).enumerate() {
                let row = self.integer(
                    &format!("{}[{i}]", at("polygon_stipple")),
                    row,
                    0..=0xFFFF_FFFF,
                    "a 32-bit row, the most significant bit the leftmost column",
                )?;
                bytes.copy_from_slice(&(row as u32).to_be_bytes());
            }
            raster.polygon_stipple = Some(mask);
        }
        if let Some(b) = &spec.blend {
            raster.blend = Some(self.blend(&at("blend"), b)?);
        }
        if let Some(c) = &spec.blend_color {
            // All four: glBlendColor has no implied alpha (a 3-value color would take 1).
            if c.len() != 4 {
                return Err(self.field(
                    at("blend_color"),
                    format!(
                        "{} values: expected exactly 4 (glBlendColor's red, green, blue and alpha)",
                        c.len()
                    ),
                ));
            }
            let c = self.color(&at("blend_color"), c)?;
            if c.to_array().iter().any(|x| !(0.0..=1.0).contains(x)) {
                return Err(self.field(
                    at("blend_color"),
                    format!("{c}: expected each in [0, 1] (glBlendColor clamps it there)"),
                ));
            }
            raster.blend_color = c.to_array();
        }
        if let Some(range) = spec.depth_range {
            self.finite(&at("depth_range"), &range)?;
            raster.depth_range = range;
        }
        if let Some(on) = spec.depth_mask {
            raster.depth_write = on;
        }
        Ok(raster)
    }

    fn stencil_face(&self, field: &str, s: &StencilSpec) -> Result<StencilFace, SceneError> {
        let at = |name: &str| format!("{field}.{name}");
        let default = StencilFace::default();
        let op = |name: &str, word: &Option<String>| {
            self.word_or(&at(name), word.as_deref(), STENCIL_OP, vk::StencilOp::KEEP)
        };
        let mask = |name: &str, value: Option<i64>| {
            value.map_or(Ok(u32::MAX), |v| {
                self.integer(&at(name), v, 0..=i64::from(u32::MAX), "a GLuint mask")
                    .map(|v| v as u32)
            })
        };
        let reference = match s.reference {
            None => 0,
            Some(r) => self.integer(
                &at("ref"),
                r,
                i64::from(i32::MIN)..=i64::from(i32::MAX),
                "a GLint; GL clamps it to [0, 255] for the 8-bit stencil buffer",
            )?,
        };
        Ok(StencilFace {
            func: self.word_or(&at("func"), s.func.as_deref(), COMPARE, default.func)?,
            // GL clamps the reference to [0, 2^s - 1]; below 0 is 0.
            reference: reference.max(0) as u32,
            value_mask: mask("value_mask", s.value_mask)?,
            fail: op("fail", &s.fail)?,
            depth_fail: op("depth_fail", &s.depth_fail)?,
            pass: op("pass", &s.pass)?,
            write_mask: mask("write_mask", s.write_mask)?,
        })
    }

    fn blend(&self, field: &str, b: &BlendSpec) -> Result<Blend, SceneError> {
        let at = |name: &str| format!("{field}.{name}");
        let factor = |name: &str, word: Option<&str>, default| {
            let f = self.word_or(&at(name), word, BLEND_FACTOR, default)?;
            if f == vk::BlendFactor::SRC_ALPHA_SATURATE && name.starts_with("dst") {
                return Err(self.field(
                    at(name),
                    "\"src_alpha_saturate\": expected a destination factor (GL 2.1 takes \
                     src_alpha_saturate as a source factor only)",
                ));
            }
            Ok(f)
        };
        let src = factor("src", b.src.as_deref(), vk::BlendFactor::ONE)?;
        let dst = factor("dst", b.dst.as_deref(), vk::BlendFactor::ZERO)?;
        let op = self.word_or(
            &at("equation"),
            b.equation.as_deref(),
            BLEND_EQUATION,
            vk::BlendOp::ADD,
        )?;
        Ok(Blend::separate(
            (src, dst, op),
            (
                factor("src_alpha", b.src_alpha.as_deref(), src)?,
                factor("dst_alpha", b.dst_alpha.as_deref(), dst)?,
                self.word_or(
                    &at("equation_alpha"),
                    b.equation_alpha.as_deref(),
                    BLEND_EQUATION,
                    op,
                )?,
            ),
        ))
    }

    /// `[image] clear_stencil`: glClearStencil, 0 by default.
    pub(super) fn clear_stencil(&self, value: Option<i64>) -> Result<u32, SceneError> {
        value.map_or(Ok(0), |v| {
            self.integer(
                "image.clear_stencil",
                v,
                0..=255,
                "the 8-bit stencil buffer's values",
            )
            .map(|v| v as u32)
        })
    }
}
