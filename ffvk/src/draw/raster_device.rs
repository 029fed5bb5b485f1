//! The checks of a [`RasterState`] against the device and target a pipeline is made for.

use ash::vk;

use super::formats;
use super::pipeline::{Pixels, RasterState, Target};
use crate::error::{Error, LightingError, Result};
use crate::vk::Device;

impl RasterState {
    /// Checks the state's values ([`RasterState::validate`]), then what it needs of `device`
    /// and `target` (its stencil form where `stencil_target`): blending into a format that
    /// blends (unless `blendable` is false only because the G-buffer pass, `gbuffer`, never
    /// blends), a depth attachment for the depth test, stencil for the stencil test,
    /// `fillModeNonSolid`, `logicOp` and a normalized color format, stippled lines, and
    /// point sizes and line widths in the device's ranges. Returns the pipeline's depth format
    /// and its polygon mode (the front's: passes have one mode for both faces).
    pub(crate) fn check_device(
        &self,
        device: &Device,
        target: Target,
        (stencil_target, gbuffer, blendable): (bool, bool, bool),
    ) -> Result<(vk::Format, vk::PolygonMode)> {
        self.validate()?;
        if self.blend.is_some() && !gbuffer && !blendable {
            return Err(LightingError::BlendUnsupported {
                format: target.color_format,
            }
            .into());
        }
        if self.depth_test && target.depth_format == vk::Format::UNDEFINED {
            return Err(LightingError::NoDepthAttachment.into());
        }
        let depth_format = if stencil_target {
            target.with_stencil().depth_format
        } else {
            target.depth_format
        };
        if self.stencil.is_some() && !formats::has_stencil(depth_format) {
            return Err(LightingError::NoStencilAttachment { format: depth_format }.into());
        }
        let mode = self.polygon_mode.front;
        if mode != vk::PolygonMode::FILL && !device.info.fill_mode_non_solid {
            return Err(Error::NotEnabled {
                feature: "fillModeNonSolid",
                flag: "fill_mode_non_solid",
                needed_for: "glPolygonMode's GL_LINE and GL_POINT need",
            });
        }
        if self.logic_op.is_some() && !gbuffer {
            if !device.info.logic_op {
                return Err(Error::NotEnabled {
                    feature: "logicOp",
                    flag: "logic_op",
                    needed_for: "glLogicOp (GL_COLOR_LOGIC_OP) needs",
                });
            }
            if !formats::is_unorm_color(target.color_format) {
                return Err(LightingError::LogicOpFormat {
                    format: target.color_format,
                }
                .into());
            }
        }
        if self.line_stipple.is_some() && !device.info.stippled_lines {
            return Err(Error::NotEnabled {
                feature: "VK_EXT_line_rasterization's bresenhamLines and stippledBresenhamLines",
                flag: "stippled_lines",
                needed_for: "glLineStipple (GL_LINE_STIPPLE) needs",
            });
        }
        for (what, Pixels(size), enabled, range, feature, flag) in [
            (
                "point size",
                self.point_size,
                device.info.large_points,
                device.info.point_size_range,
                "largePoints",
                "large_points",
            ),
            (
                "line width",
                self.line_width,
                device.info.wide_lines,
                device.info.line_width_range,
                "wideLines",
                "wide_lines",
            ),
        ] {
            if !(size > 0.0 && size.is_finite()) {
                return Err(LightingError::RasterSize {
                    what,
                    size: size.to_string(),
                    expected: "a finite size above 0 (GL_INVALID_VALUE in GL)".to_owned(),
                }
                .into());
            }
            if size != 1.0 && !enabled {
                return Err(Error::NotEnabled {
                    feature,
                    flag,
                    needed_for: if what == "point size" {
                        "a point size other than 1 needs"
                    } else {
                        "a line width other than 1 needs"
                    },
                });
            }
            if !(range[0]..=range[1]).contains(&size) {
                return Err(LightingError::RasterSize {
                    what,
                    size: size.to_string(),
                    expected: format!("{} to {}, the device's range", range[0], range[1]),
                }
                .into());
            }
        }
        Ok((depth_format, mode))
    }
}
