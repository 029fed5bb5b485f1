//! What a `VkFormat` value is, as far as ffvk's attachments care: a color format the shaders
//! write as floats, a depth format, or neither. Only Vulkan 1.0's core formats are known
//! (`VK_FORMAT_R4G4_UNORM_PACK8` = 1 .. `VK_FORMAT_ASTC_12x12_SRGB_BLOCK` = 184); any other
//! value is refused before it can reach Vulkan.

use ash::vk;

/// The last uncompressed color format, `E5B9G9R9_UFLOAT_PACK32` (compressed formats, 131 and
/// up, are never attachments).
const LAST_COLOR: i32 = 123;

/// Whether `format` is a core color format whose components the fragment shader writes as
/// floats: UNORM, SNORM, USCALED, SSCALED, SRGB or FLOAT, not UINT or SINT (ffvk's shaders
/// write `vec4`, which an integer attachment leaves undefined), not a depth or compressed one.
/// Whether the device can render to it is [`Target`](crate::Target)'s device check.
pub(crate) fn is_float_color(format: vk::Format) -> bool {
    let raw = format.as_raw();
    (1..=LAST_COLOR).contains(&raw) && !is_integer(raw)
}

/// Whether the color format `format` is normalized (UNORM or SNORM, not sRGB): the formats a
/// Vulkan logic op applies to among those ffvk renders into (it leaves float and sRGB ones
/// alone, where GL would apply it).
pub(crate) fn is_unorm_color(format: vk::Format) -> bool {
    let raw = format.as_raw();
    match raw {
        // R4G4 .. A1R5G5B5: the packed formats, all UNORM.
        1..=8 => true,
        9..=57 => matches!((raw - 9) % 7, 0 | 1),
        58..=69 => matches!((raw - 58) % 6, 0 | 1),
        70..=97 => matches!((raw - 70) % 7, 0 | 1),
        _ => false,
    }
}

/// Whether the core format `raw` (1 ..= 123) is UINT or SINT: in each family of formats
/// (R8, R8G8, …) the integer ones come at fixed places.
fn is_integer(raw: i32) -> bool {
    match raw {
        // R8 .. A8B8G8R8_PACK32: families of 7 (UNORM SNORM USCALED SSCALED UINT SINT SRGB).
        9..=57 => matches!((raw - 9) % 7, 4 | 5),
        // A2R10G10B10, A2B10G10R10: families of 6 (no SRGB).
        58..=69 => matches!((raw - 58) % 6, 4 | 5),
        // R16 .. R16G16B16A16: families of 7 (SFLOAT instead of SRGB).
        70..=97 => matches!((raw - 70) % 7, 4 | 5),
        // R32 .. R64G64B64A64: families of 3 (UINT SINT SFLOAT).
        98..=121 => matches!((raw - 98) % 3, 0 | 1),
        _ => false,
    }
}

/// The alpha channel's bits of a color format stored as unsigned normalized integers (what the
/// alpha test's fixed-point compare takes: GL 2.1 section 4.1.4), or 0 for any other (floats,
/// SNORM, formats without alpha): those compare as floats.
pub(crate) fn unorm_alpha_bits(format: vk::Format) -> u32 {
    use vk::Format as F;
    match format {
        F::R8G8B8A8_UNORM
        | F::B8G8R8A8_UNORM
        | F::A8B8G8R8_UNORM_PACK32
        | F::R8G8B8A8_SRGB
        | F::B8G8R8A8_SRGB
        | F::A8B8G8R8_SRGB_PACK32 => 8,
        F::A2B10G10R10_UNORM_PACK32 | F::A2R10G10B10_UNORM_PACK32 => 2,
        F::R16G16B16A16_UNORM => 16,
        F::R4G4B4A4_UNORM_PACK16 | F::B4G4R4A4_UNORM_PACK16 => 4,
        F::R5G5B5A1_UNORM_PACK16 | F::B5G5R5A1_UNORM_PACK16 | F::A1R5G5B5_UNORM_PACK16 => 1,
        _ => 0,
    }
}

/// The depth formats, in Vulkan's order (`S8_UINT`, which has no depth, left out).
pub(crate) const DEPTH_FORMATS: [vk::Format; 6] = [
    vk::Format::D16_UNORM,
    vk::Format::X8_D24_UNORM_PACK32,
    vk::Format::D32_SFLOAT,
    vk::Format::D16_UNORM_S8_UINT,
    vk::Format::D24_UNORM_S8_UINT,
    vk::Format::D32_SFLOAT_S8_UINT,
];

/// Whether `format` is one of [`DEPTH_FORMATS`].
pub(crate) fn is_depth(format: vk::Format) -> bool {
    DEPTH_FORMATS.contains(&format)
}

/// Whether the depth format `format` also has stencil (its samples then must be among the
/// device's `framebufferStencilSampleCounts` too).
pub(crate) fn has_stencil(format: vk::Format) -> bool {
    matches!(
        format,
        vk::Format::D16_UNORM_S8_UINT | vk::Format::D24_UNORM_S8_UINT | vk::Format::D32_SFLOAT_S8_UINT
    )
}

/// Whether `samples` is exactly one bit of `VkSampleCountFlagBits` (1 .. 64 samples).
pub(crate) fn is_sample_count(samples: vk::SampleCountFlags) -> bool {
    let raw = samples.as_raw();
    raw.is_power_of_two() && raw <= vk::SampleCountFlags::TYPE_64.as_raw()
}

/// The sample counts in `flags`, e.g. `1, 4`, for messages.
pub(crate) fn sample_counts(flags: vk::SampleCountFlags) -> String {
    let counts: Vec<String> = (0..7)
        .map(|bit| 1u32 << bit)
        .filter(|n| flags.as_raw() & n != 0)
        .map(|n| n.to_string())
        .collect();
    if counts.is_empty() {
        "none".to_owned()
    } else {
        counts.join(", ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_integer_formats_are_exactly_those_ash_names_uint_or_sint() {
        for raw in 1..=LAST_COLOR {
            let name = format!("{:?}", vk::Format::from_raw(raw));
            let integer = name.contains("_UINT") || name.contains("_SINT");
            let depth = name.starts_with('D') || name.starts_with("X8_D24") || name == "S8_UINT";
            assert!(!depth, "{name} ({raw}) is below the depth formats");
            assert_eq!(is_integer(raw), integer, "{name} ({raw})");
            assert_eq!(is_float_color(vk::Format::from_raw(raw)), !integer, "{name}");
        }
    }

    #[test]
    fn undefined_depth_compressed_and_unknown_formats_are_not_float_colors() {
        for raw in [0, 124, 126, 127, 130, 131, 184, 185, 1_000_340_000, -1, i32::MAX] {
            assert!(!is_float_color(vk::Format::from_raw(raw)), "{raw}");
        }
        assert!(is_float_color(vk::Format::R8G8B8A8_UNORM));
        assert!(is_float_color(vk::Format::B10G11R11_UFLOAT_PACK32));
    }

    #[test]
    fn depth_formats_are_the_six_with_depth_and_three_have_stencil() {
        for raw in 0..200 {
            let f = vk::Format::from_raw(raw);
            let name = format!("{f:?}");
            let depth = ["D16", "D24", "D32"].iter().any(|d| name.contains(d));
            assert_eq!(is_depth(f), depth, "{name}");
            assert_eq!(has_stencil(f), depth && name.contains("S8"), "{name}");
        }
    }

    #[test]
    fn a_sample_count_is_one_bit_from_1_to_64() {
        for n in [1, 2, 4, 8, 16, 32, 64] {
            assert!(is_sample_count(vk::SampleCountFlags::from_raw(n)), "{n}");
        }
        for n in [0, 3, 5, 6, 128, 0x41, u32::MAX] {
            assert!(!is_sample_count(vk::SampleCountFlags::from_raw(n)), "{n}");
        }
        assert_eq!(sample_counts(vk::SampleCountFlags::from_raw(0b101)), "1, 4");
        assert_eq!(sample_counts(vk::SampleCountFlags::empty()), "none");
    }
}
