//! What the pipelines draw into: the caller's attachments ([`Target`]), checked against the
//! device.

use ash::vk;

use super::formats;
use crate::error::{LightingError, Result};
use crate::vk::Device;

/// The color image's format: 8 bits per channel, linear UNORM (no sRGB encoding), so a
/// color component c in [0, 1] is stored as c × 255, as in a default GL framebuffer.
pub const COLOR_FORMAT: vk::Format = vk::Format::R8G8B8A8_UNORM;
/// The depth buffer's format: 32-bit float, cleared to 1 and tested with LESS.
pub const DEPTH_FORMAT: vk::Format = vk::Format::D32_SFLOAT;

/// The caller's attachments, which every pipeline renders into (dynamic rendering).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct Target {
    /// The one color attachment's format.
    pub color_format: vk::Format,
    /// The depth attachment's format; `UNDEFINED` for none (then no draw may test depth).
    pub depth_format: vk::Format,
    /// Samples per pixel of both attachments.
    pub samples: vk::SampleCountFlags,
}

impl Target {
    /// A target of one sample per pixel with these attachment formats (`depth_format`
    /// `UNDEFINED` for no depth attachment); set [`samples`](Target::samples) for more.
    pub fn new(color_format: vk::Format, depth_format: vk::Format) -> Self {
        Target {
            color_format,
            depth_format,
            samples: vk::SampleCountFlags::TYPE_1,
        }
    }

    /// ffvk's offscreen target: [`COLOR_FORMAT`], [`DEPTH_FORMAT`], one sample.
    pub const OFFSCREEN: Target = Target {
        color_format: COLOR_FORMAT,
        depth_format: DEPTH_FORMAT,
        samples: vk::SampleCountFlags::TYPE_1,
    };
}

impl Target {
    /// This target with a stencil buffer: its depth format with 8 stencil bits beside
    /// (`D32_SFLOAT` becomes `D32_SFLOAT_S8_UINT`, `D16_UNORM` `D16_UNORM_S8_UINT`,
    /// `X8_D24_UNORM_PACK32` `D24_UNORM_S8_UINT`); a format with stencil, or none, stays.
    pub fn with_stencil(mut self) -> Self {
        self.depth_format = match self.depth_format {
            vk::Format::D32_SFLOAT => vk::Format::D32_SFLOAT_S8_UINT,
            vk::Format::D16_UNORM => vk::Format::D16_UNORM_S8_UINT,
            vk::Format::X8_D24_UNORM_PACK32 => vk::Format::D24_UNORM_S8_UINT,
            other => other,
        };
        self
    }

    /// Checks the values themselves, before any device is asked: the color format is one the
    /// shaders write as floats, the depth format is `UNDEFINED` or a depth format, and the
    /// samples are one `VkSampleCountFlagBits` bit. Errors name the field and its value.
    pub fn validate(&self) -> std::result::Result<(), LightingError> {
        if !formats::is_float_color(self.color_format) {
            return Err(LightingError::ColorFormat {
                format: self.color_format,
            });
        }
        if self.depth_format != vk::Format::UNDEFINED && !formats::is_depth(self.depth_format) {
            return Err(LightingError::DepthFormat {
                format: self.depth_format,
            });
        }
        if !formats::is_sample_count(self.samples) {
            return Err(LightingError::Samples {
                samples: self.samples,
            });
        }
        Ok(())
    }

    /// Checks that `device` can render into the target: the color format has
    /// `COLOR_ATTACHMENT`, the depth format `DEPTH_STENCIL_ATTACHMENT`, and the samples are
    /// among the device's framebuffer sample counts for each attachment. Returns whether the
    /// color format can be blended into (`COLOR_ATTACHMENT_BLEND`). Call after
    /// [`Target::validate`]: only known formats are asked about.
    pub(super) fn check_device(&self, device: &Device) -> Result<bool> {
        let features = |format| {
            let p = device.format_properties(format);
            p.optimal_tiling_features | p.linear_tiling_features
        };
        let color = features(self.color_format);
        if !color.contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT) {
            return Err(LightingError::FormatUnsupported {
                field: "color_format",
                format: self.color_format,
                feature: "COLOR_ATTACHMENT",
            }
            .into());
        }
        let limits = &device.limits;
        let mut counts = vec![(
            "color attachment",
            limits.framebuffer_color_sample_counts,
            "framebufferColorSampleCounts",
        )];
        if self.depth_format != vk::Format::UNDEFINED {
            if !features(self.depth_format).contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT) {
                return Err(LightingError::FormatUnsupported {
                    field: "depth_format",
                    format: self.depth_format,
                    feature: "DEPTH_STENCIL_ATTACHMENT",
                }
                .into());
            }
            counts.push((
                "depth attachment",
                limits.framebuffer_depth_sample_counts,
                "framebufferDepthSampleCounts",
            ));
            if formats::has_stencil(self.depth_format) {
                counts.push((
                    "stencil of the depth attachment",
                    limits.framebuffer_stencil_sample_counts,
                    "framebufferStencilSampleCounts",
                ));
            }
        }
        for (attachment, supported, limit) in counts {
            if !supported.contains(self.samples) {
                return Err(LightingError::SamplesUnsupported {
                    samples: self.samples.as_raw(),
                    attachment,
                    supported: formats::sample_counts(supported),
                    limit,
                }
                .into());
            }
        }
        Ok(color.contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT_BLEND))
    }
}
