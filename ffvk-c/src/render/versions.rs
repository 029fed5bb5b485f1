//! The published versions of the structs that grow, `FfvkRendererCreateInfo`, `FfvkDrawInfo`
//! and `FfvkVertexLayoutInfo` ([`crate::abi`] states the rule and reads them): a frozen copy
//! of each published version but the newest, the table of their sizes, and the defaults of the
//! fields a caller's older version lacks.

use std::mem::{offset_of, size_of};

use ffvk::ash::vk;

use super::layout::FfvkVertexLayout;
use super::layout::FfvkVertexLayoutInfo;
use super::{raster_defaults, FfvkAttribute, FfvkDrawInfo, FfvkRaster, FfvkRendererCreateInfo, FfvkTexture};
use crate::abi::{check_versions, frozen_version, Version, Versioned};
use crate::vk_types::*;

frozen_version! {
    /// `FfvkRendererCreateInfo` as version 1 of `ffvk.h` declared it.
    RendererCreateInfoV1 of FfvkRendererCreateInfo {
        struct_size: u32,
        get_instance_proc_addr: PFN_vkGetInstanceProcAddr,
        instance: VkInstance,
        physical_device: VkPhysicalDevice,
        device: VkDevice,
        enabled_features: u32,
        color_format: VkFormat,
        depth_format: VkFormat,
        samples: VkSampleCountFlagBits,
        bindings: *const VkVertexInputBindingDescription,
        binding_count: u32,
        position: FfvkAttribute,
        normal: FfvkAttribute,
        color: *const FfvkAttribute,
        texcoord: *const FfvkAttribute,
        frames_in_flight: u32,
        set_index: u32,
        pipeline_cache: VkPipelineCache,
    }
}

frozen_version! {
    /// `FfvkDrawInfo` as version 1 of `ffvk.h` declared it.
    DrawInfoV1 of FfvkDrawInfo {
        struct_size: u32,
        mode: u32,
        vertex_buffers: *const VkBuffer,
        vertex_offsets: *const VkDeviceSize,
        vertex_buffer_count: u32,
        index_buffer: VkBuffer,
        index_offset: VkDeviceSize,
        index_type: VkIndexType,
        first: u32,
        count: u32,
        vertex_offset: i32,
        primitive_restart: u8,
        raster: FfvkRaster,
        texture: *const FfvkTexture,
    }
}

// SAFETY: repr(C), struct_size its first field (checked below), and every field takes any bit
// pattern: integers, raw pointers, a nullable function pointer, Vulkan's handles and enums.
unsafe impl Versioned for FfvkRendererCreateInfo {
    const NAME: &'static str = "FfvkRendererCreateInfo";
    const VERSIONS: &'static [Version] = &[Version {
        size: size_of::<RendererCreateInfoV1>(),
        first_field: 0,
    }];
    fn defaults() -> Self {
        FfvkRendererCreateInfo {
            struct_size: size_of::<FfvkRendererCreateInfo>() as u32,
            get_instance_proc_addr: None,
            instance: vk::Instance::null(),
            physical_device: vk::PhysicalDevice::null(),
            device: vk::Device::null(),
            enabled_features: 0,
            color_format: vk::Format::UNDEFINED,
            depth_format: vk::Format::UNDEFINED,
            samples: vk::SampleCountFlags::TYPE_1,
            bindings: std::ptr::null(),
            binding_count: 0,
            position: FfvkAttribute {
                binding: 0,
                offset: 0,
                format: vk::Format::UNDEFINED,
            },
            normal: FfvkAttribute {
                binding: 0,
                offset: 0,
                format: vk::Format::UNDEFINED,
            },
            color: std::ptr::null(),
            texcoord: std::ptr::null(),
            frames_in_flight: 0,
            set_index: 0,
            pipeline_cache: vk::PipelineCache::null(),
        }
    }
}

frozen_version! {
    /// `FfvkDrawInfo` as version 2 of `ffvk.h` declared it.
    DrawInfoV2 of FfvkDrawInfo {
        struct_size: u32,
        mode: u32,
        vertex_buffers: *const VkBuffer,
        vertex_offsets: *const VkDeviceSize,
        vertex_buffer_count: u32,
        index_buffer: VkBuffer,
        index_offset: VkDeviceSize,
        index_type: VkIndexType,
        first: u32,
        count: u32,
        vertex_offset: i32,
        primitive_restart: u8,
        raster: FfvkRaster,
        texture: *const FfvkTexture,
        layout: *const FfvkVertexLayout,
    }
}

frozen_version! {
    /// `FfvkDrawInfo` as version 3 of `ffvk.h` declared it.
    DrawInfoV3 of FfvkDrawInfo {
        struct_size: u32,
        mode: u32,
        vertex_buffers: *const VkBuffer,
        vertex_offsets: *const VkDeviceSize,
        vertex_buffer_count: u32,
        index_buffer: VkBuffer,
        index_offset: VkDeviceSize,
        index_type: VkIndexType,
        first: u32,
        count: u32,
        vertex_offset: i32,
        primitive_restart: u8,
        raster: FfvkRaster,
        texture: *const FfvkTexture,
        layout: *const FfvkVertexLayout,
        raster_source: u32,
    }
}

frozen_version! {
    /// `FfvkDrawInfo` as version 4 of `ffvk.h` declared it.
    DrawInfoV4 of FfvkDrawInfo {
        struct_size: u32,
        mode: u32,
        vertex_buffers: *const VkBuffer,
        vertex_offsets: *const VkDeviceSize,
        vertex_buffer_count: u32,
        index_buffer: VkBuffer,
        index_offset: VkDeviceSize,
        index_type: VkIndexType,
        first: u32,
        count: u32,
        vertex_offset: i32,
        primitive_restart: u8,
        raster: FfvkRaster,
        texture: *const FfvkTexture,
        layout: *const FfvkVertexLayout,
        raster_source: u32,
        texture1: *const FfvkTexture,
        texture2: *const FfvkTexture,
        texture3: *const FfvkTexture,
    }
}

frozen_version! {
    /// `FfvkVertexLayoutInfo` as version 1 of `ffvk.h` declared it.
    VertexLayoutInfoV1 of FfvkVertexLayoutInfo {
        struct_size: u32,
        bindings: *const VkVertexInputBindingDescription,
        binding_count: u32,
        position: FfvkAttribute,
        normal: *const FfvkAttribute,
        color: *const FfvkAttribute,
        texcoord: *const FfvkAttribute,
        secondary_color: *const FfvkAttribute,
        fog_coord: *const FfvkAttribute,
        materials: *const super::layout::FfvkMaterialAttribute,
        material_count: u32,
    }
}

// SAFETY: as above; `raster` is all integers, floats and Vulkan enums.
unsafe impl Versioned for FfvkDrawInfo {
    const NAME: &'static str = "FfvkDrawInfo";
    const VERSIONS: &'static [Version] = &[
        Version {
            size: size_of::<DrawInfoV1>(),
            first_field: 0,
        },
        // Version 2: the draw's vertex layout.
        Version {
            size: size_of::<DrawInfoV2>(),
            first_field: offset_of!(FfvkDrawInfo, layout),
        },
        // Version 3: where the draw's raster state comes from.
        Version {
            size: size_of::<DrawInfoV3>(),
            first_field: offset_of!(FfvkDrawInfo, raster_source),
        },
        // Version 4: the textures of units 1 to 3.
        Version {
            size: size_of::<DrawInfoV4>(),
            first_field: offset_of!(FfvkDrawInfo, texture1),
        },
        // Version 5: each unit's cube map.
        Version {
            size: size_of::<FfvkDrawInfo>(),
            first_field: offset_of!(FfvkDrawInfo, cube_map),
        },
    ];
    fn defaults() -> Self {
        FfvkDrawInfo {
            struct_size: size_of::<FfvkDrawInfo>() as u32,
            mode: 0,
            vertex_buffers: std::ptr::null(),
            vertex_offsets: std::ptr::null(),
            vertex_buffer_count: 0,
            index_buffer: vk::Buffer::null(),
            index_offset: 0,
            index_type: vk::IndexType::UINT32,
            first: 0,
            count: 0,
            vertex_offset: 0,
            primitive_restart: 0,
            raster: raster_defaults(),
            texture: std::ptr::null(),
            layout: std::ptr::null(),
            raster_source: super::FFVK_RASTER_SOURCE_DRAW,
            texture1: std::ptr::null(),
            texture2: std::ptr::null(),
            texture3: std::ptr::null(),
            cube_map: std::ptr::null(),
            cube_map1: std::ptr::null(),
            cube_map2: std::ptr::null(),
            cube_map3: std::ptr::null(),
        }
    }
}

// SAFETY: as above: integers, raw pointers and Vulkan's formats.
unsafe impl Versioned for FfvkVertexLayoutInfo {
    const NAME: &'static str = "FfvkVertexLayoutInfo";
    const VERSIONS: &'static [Version] = &[
        Version {
            size: size_of::<VertexLayoutInfoV1>(),
            first_field: 0,
        },
        // Version 2: the coordinate arrays of texture units 1 to 3.
        Version {
            size: size_of::<FfvkVertexLayoutInfo>(),
            first_field: offset_of!(FfvkVertexLayoutInfo, texcoord1),
        },
    ];
    fn defaults() -> Self {
        let none = FfvkAttribute {
            binding: 0,
            offset: 0,
            format: vk::Format::UNDEFINED,
        };
        FfvkVertexLayoutInfo {
            struct_size: size_of::<FfvkVertexLayoutInfo>() as u32,
            bindings: std::ptr::null(),
            binding_count: 0,
            position: none,
            normal: std::ptr::null(),
            color: std::ptr::null(),
            texcoord: std::ptr::null(),
            secondary_color: std::ptr::null(),
            fog_coord: std::ptr::null(),
            materials: std::ptr::null(),
            material_count: 0,
            texcoord1: std::ptr::null(),
            texcoord2: std::ptr::null(),
            texcoord3: std::ptr::null(),
        }
    }
}

const _: () = {
    assert!(offset_of!(FfvkRendererCreateInfo, struct_size) == 0);
    assert!(offset_of!(FfvkDrawInfo, struct_size) == 0);
    check_versions::<FfvkRendererCreateInfo>();
    check_versions::<FfvkDrawInfo>();
    assert!(offset_of!(FfvkVertexLayoutInfo, struct_size) == 0);
    check_versions::<FfvkVertexLayoutInfo>();
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_struct_with_a_struct_size_has_its_published_versions_the_last_its_size_today() {
        assert_eq!(
            FfvkRendererCreateInfo::VERSIONS,
            [Version {
                size: size_of::<FfvkRendererCreateInfo>(),
                first_field: 0
            }]
        );
        // FfvkVertexLayoutInfo: version 1, and version 2, the units' coordinate arrays right
        // after version 1's end.
        assert_eq!(
            FfvkVertexLayoutInfo::VERSIONS,
            [
                Version {
                    size: size_of::<VertexLayoutInfoV1>(),
                    first_field: 0
                },
                Version {
                    size: size_of::<FfvkVertexLayoutInfo>(),
                    first_field: offset_of!(FfvkVertexLayoutInfo, texcoord1)
                }
            ]
        );
        assert_eq!(
            offset_of!(FfvkVertexLayoutInfo, texcoord1),
            size_of::<VertexLayoutInfoV1>()
        );
        // FfvkDrawInfo: version 1 (ffvk-c 0.1's first header), version 2, which appended the
        // layout right after version 1's end, version 3, the raster source after version 2's
        // end, version 4, the units' textures after version 3's, and version 5, the units' cube
        // maps after version 4's.
        assert_eq!(
            FfvkDrawInfo::VERSIONS,
            [
                Version {
                    size: size_of::<DrawInfoV1>(),
                    first_field: 0
                },
                Version {
                    size: size_of::<DrawInfoV2>(),
                    first_field: offset_of!(FfvkDrawInfo, layout)
                },
                Version {
                    size: size_of::<DrawInfoV3>(),
                    first_field: offset_of!(FfvkDrawInfo, raster_source)
                },
                Version {
                    size: size_of::<DrawInfoV4>(),
                    first_field: offset_of!(FfvkDrawInfo, texture1)
                },
                Version {
                    size: size_of::<FfvkDrawInfo>(),
                    first_field: offset_of!(FfvkDrawInfo, cube_map)
                }
            ]
        );
        assert_eq!(offset_of!(FfvkDrawInfo, layout), size_of::<DrawInfoV1>());
        assert_eq!(offset_of!(FfvkDrawInfo, raster_source), size_of::<DrawInfoV2>());
        assert_eq!(offset_of!(FfvkDrawInfo, texture1), size_of::<DrawInfoV3>());
        assert_eq!(offset_of!(FfvkDrawInfo, cube_map), size_of::<DrawInfoV4>());
    }

    #[test]
    fn a_version_1_draw_info_reads_every_field_the_caller_wrote_and_the_layout_as_null() {
        let mut info = FfvkDrawInfo::defaults();
        info.struct_size = size_of::<DrawInfoV1>() as u32;
        info.mode = 4;
        info.count = 36;
        info.raster.line_width = 2.0;
        // Where a version 1 caller's memory ends: not read.
        info.layout = std::ptr::dangling();
        // SAFETY: a whole current struct, aligned; struct_size covers less of it.
        let read = unsafe { crate::abi::read("test", &info) }.expect("version 1's size is accepted");
        assert_eq!((read.mode, read.count, read.raster.line_width), (4, 36, 2.0));
        assert!(
            read.layout.is_null(),
            "a version 1 draw's layout is the default, null"
        );
        assert_eq!(read.raster_source, crate::render::FFVK_RASTER_SOURCE_DRAW);
    }

    #[test]
    fn a_version_2_draw_info_reads_its_layout_and_takes_the_draws_raster_state() {
        let mut info = FfvkDrawInfo::defaults();
        info.struct_size = size_of::<DrawInfoV2>() as u32;
        info.layout = std::ptr::dangling();
        // Where a version 2 caller's memory ends: not read.
        info.raster_source = crate::render::FFVK_RASTER_SOURCE_CONTEXT;
        // SAFETY: a whole current struct, aligned; struct_size covers less of it.
        let read = unsafe { crate::abi::read("test", &info) }.expect("version 2's size is accepted");
        assert_eq!(read.layout, std::ptr::dangling());
        assert_eq!(
            read.raster_source,
            crate::render::FFVK_RASTER_SOURCE_DRAW,
            "a version 2 draw takes its raster state from its raster, the default"
        );
        info.struct_size = size_of::<DrawInfoV3>() as u32;
        // Where a version 3 caller's memory ends: not read.
        info.texture1 = std::ptr::dangling();
        // SAFETY: as above.
        let read = unsafe { crate::abi::read("test", &info) }.expect("version 3's size is accepted");
        assert_eq!(read.raster_source, crate::render::FFVK_RASTER_SOURCE_CONTEXT);
        assert!(
            read.texture1.is_null(),
            "a version 3 draw binds no texture to unit 1"
        );
        info.struct_size = size_of::<DrawInfoV4>() as u32;
        // Where a version 4 caller's memory ends: not read.
        info.cube_map = std::ptr::dangling();
        info.cube_map3 = std::ptr::dangling();
        // SAFETY: as above.
        let read = unsafe { crate::abi::read("test", &info) }.expect("version 4's size is accepted");
        assert_eq!(read.texture1, std::ptr::dangling());
        assert!(
            read.cube_map.is_null() && read.cube_map3.is_null(),
            "a version 4 draw binds no cube map"
        );
        info.struct_size = size_of::<FfvkDrawInfo>() as u32;
        // SAFETY: as above, struct_size covering all of it.
        let read = unsafe { crate::abi::read("test", &info) }.expect("version 5's size is accepted");
        assert_eq!(
            (read.cube_map, read.cube_map3),
            (std::ptr::dangling(), std::ptr::dangling())
        );
        assert!(read.cube_map1.is_null());
    }

    #[test]
    fn a_version_1_vertex_layout_info_reads_no_coordinate_arrays_of_units_1_to_3() {
        let mut info = FfvkVertexLayoutInfo::defaults();
        info.struct_size = size_of::<VertexLayoutInfoV1>() as u32;
        info.material_count = 3;
        // Where a version 1 caller's memory ends: not read.
        info.texcoord1 = std::ptr::dangling();
        info.texcoord3 = std::ptr::dangling();
        // SAFETY: a whole current struct, aligned; struct_size covers less of it.
        let read = unsafe { crate::abi::read("test", &info) }.expect("version 1's size is accepted");
        assert_eq!(read.material_count, 3);
        assert!(read.texcoord1.is_null() && read.texcoord2.is_null() && read.texcoord3.is_null());
        info.struct_size = size_of::<FfvkVertexLayoutInfo>() as u32;
        // SAFETY: as above, struct_size covering all of it.
        let read = unsafe { crate::abi::read("test", &info) }.expect("version 2's size is accepted");
        assert_eq!(
            (read.texcoord1, read.texcoord3),
            (std::ptr::dangling(), std::ptr::dangling())
        );
        assert!(read.texcoord2.is_null());
    }
}
