//! Several texture units drawn through the C API, as a C layer draws them, against Mesa's GL
//! (the GL reference, `GlDraw::textures` and `GlDraw::mesh_texcoords`): a caller's device
//! (plain ash, lavapipe), its own images, samplers and buffers, and two draws in one scope.
//!
//! - The left quad: unit 0 a checker on the mesh's coordinates (`GL_MODULATE` with the vertex
//!   colors); unit 1 another texture on a second coordinate array (`texcoord1`, a binding of
//!   its own) through its own texture matrix (`GL_MODULATE`); unit 2 a third texture on its
//!   current coordinates (`ffvkMultiTexCoord2f`) in `GL_COMBINE`: `GL_INTERPOLATE` of
//!   `GL_TEXTURE0`, read through the crossbar, and `GL_PREVIOUS` by its own texel.
//! - The right quad, after the context changed: unit 0 in `GL_DECAL`, unit 1 a fourth
//!   texture on its current t and an `GL_OBJECT_LINEAR` s (the renderer's own layout: no array
//!   for unit 1), unit 2 disabled.
//!
//! Every pixel within 1/255 of Mesa's (the C API renders' tolerance, `c_api_layers.rs`); and the
//! comparison fails when the crossbar reads another unit.

use std::ffi::CStr;

use ffvk::ash::vk;
use ffvk::gl::state::{Cap, FixedFunctionState, GlState, TexEnvParam};
use ffvk::gl::texture::{
    CombineFunc, CombineSource, RgbOperand, Sampling, TexEnvMode, TexGenMode, TextureImage,
};
use ffvk::mesh::{MeshData, Vertex};
use ffvk_c::gl::*;
use ffvk_c::render::layout::*;
use ffvk_c::render::*;
use ffvk_c::result::{ffvkResultMessage, FfvkResult};
use ffvk_c::viewport::ffvkViewport;
use ffvk_cli::gl_reference::GlDraw;
use glam::{DVec4, Mat4, Vec4};
use image::RgbaImage;

use crate::embedding::PlainDevice;
use crate::support::{hashed_texels, mesa_image, save_for_inspection};

const SIZE: u32 = 64;
const CLEAR: [f32; 4] = [0.1, 0.1, 0.1, 1.0];
const FORMAT: vk::Format = vk::Format::R8G8B8A8_UNORM;

const GL_TEXTURE0: u32 = 0x84C0;
const GL_TEXTURE_2D: u32 = 0x0DE1;
const GL_TEXTURE_GEN_S: u32 = 0x0C60;
const GL_TEXTURE_ENV: u32 = 0x2300;
const GL_TEXTURE_ENV_MODE: u32 = 0x2200;
const GL_COMBINE: u32 = 0x8570;
const GL_COMBINE_RGB: u32 = 0x8571;
const GL_COMBINE_ALPHA: u32 = 0x8572;
const GL_SRC0_RGB: u32 = 0x8580;
const GL_SRC0_ALPHA: u32 = 0x8588;
const GL_OPERAND0_RGB: u32 = 0x8590;
const GL_INTERPOLATE: u32 = 0x8575;
const GL_REPLACE: u32 = 0x1E01;
const GL_DECAL: u32 = 0x2101;
const GL_PREVIOUS: u32 = 0x8578;
const GL_TEXTURE: u32 = 0x1702;
const GL_SRC_COLOR: u32 = 0x0300;
const GL_S: u32 = 0x2000;
const GL_TEXTURE_GEN_MODE: u32 = 0x2500;
const GL_OBJECT_PLANE: u32 = 0x2501;
const GL_OBJECT_LINEAR: u32 = 0x2401;
const GL_TRIANGLES: u32 = 0x0004;

pub(crate) fn message() -> String {
    // SAFETY: ffvkResultMessage never returns null; the string is valid until the next call.
    unsafe { CStr::from_ptr(ffvkResultMessage()) }
        .to_string_lossy()
        .into_owned()
}

/// Unit 1's texture matrix: s and t doubled, then moved by (1/64, 2/64): on the left quad's
/// 32 × 64 pixels, s is (4i + 3)/64 and t (2j + 3)/64 at pixel centers, never a multiple of
/// 4/64, where the 16 texels' edges lie (nor of 8/64 for the right quad's 8).
fn unit1_matrix() -> Mat4 {
    Mat4::from_cols_array(&[
        2.0,
        0.0,
        0.0,
        0.0,
        0.0,
        2.0,
        0.0,
        0.0,
        0.0,
        0.0,
        1.0,
        0.0,
        1.0 / 64.0,
        2.0 / 64.0,
        0.0,
        1.0,
    ])
}

/// Unit 2's current coordinates in the left quad: texel (0, 1) of its 2×2 texture.
const UNIT2_COORDS: [f32; 2] = [0.3, 0.7];
/// Unit 1's current coordinates in the right quad (s is generated).
const UNIT1_COORDS: [f32; 4] = [0.9, 0.2, 0.0, 1.0];

/// The four textures: a checker with two alphas (unit 0), hashed texels (unit 1, left), a
/// 2×2 of four colors (unit 2), hashed texels of another size (unit 1, right).
fn textures() -> [TextureImage; 4] {
    let checker = TextureImage::checker(8, 4, [250, 140, 20, 255], [30, 90, 230, 128]).unwrap();
    let corners = TextureImage::new(
        2,
        2,
        vec![
            200, 40, 40, 255, 40, 200, 40, 255, 64, 128, 192, 200, 230, 230, 30, 255,
        ],
    )
    .unwrap();
    [checker, hashed_texels(16), corners, hashed_texels(8)]
}

/// A quad over x in [x0, x0 + 1] (clip space, the whole height) as two triangles of six
/// vertices, with a color per corner and (s, t) over [0, 1].
fn quad(x0: f32) -> MeshData {
    let corner = |x: f32, y: f32| {
        let color = [0.4 + 0.6 * x, 0.5 + 0.5 * y, 0.9 - 0.5 * x, 1.0 - 0.25 * y];
        Vertex {
            position: [x0 + x, 2.0 * y - 1.0, 0.0],
            normal: [0.0, 0.0, 1.0],
            color,
            texcoord: [x, y],
        }
    };
    let vertices = vec![
        corner(0.0, 0.0),
        corner(1.0, 0.0),
        corner(1.0, 1.0),
        corner(0.0, 0.0),
        corner(1.0, 1.0),
        corner(0.0, 1.0),
    ];
    MeshData::new(vertices, (0..6).collect())
}

/// The GL state of each quad, made with the Rust state machine as the C calls make it.
fn gl_states(unit2_source: u8) -> [FixedFunctionState; 2] {
    let mut gl = GlState::new();
    let ok = |r: Result<(), ffvk::gl::state::StateError>| r.expect("a valid GL call");
    ok(gl.enable(Cap::Texture2D));
    ok(gl.active_texture(1));
    ok(gl.enable(Cap::Texture2D));
    ok(gl.load_texture_matrix(unit1_matrix()));
    ok(gl.active_texture(2));
    ok(gl.enable(Cap::Texture2D));
    for param in [
        TexEnvParam::Mode(TexEnvMode::Combine),
        TexEnvParam::CombineRgb(CombineFunc::Interpolate),
        TexEnvParam::SourceRgb(0, CombineSource::TextureUnit(unit2_source)),
        TexEnvParam::SourceRgb(1, CombineSource::Previous),
        TexEnvParam::SourceRgb(2, CombineSource::Texture),
        TexEnvParam::OperandRgb(2, RgbOperand::SrcColor),
        TexEnvParam::CombineAlpha(CombineFunc::Replace),
        TexEnvParam::SourceAlpha(0, CombineSource::Previous),
    ] {
        ok(gl.tex_env(param));
    }
    ok(gl.multi_tex_coord(2, Vec4::new(UNIT2_COORDS[0], UNIT2_COORDS[1], 0.0, 1.0)));
    let left = gl.lighting;
    ok(gl.disable(Cap::Texture2D));
    ok(gl.active_texture(1));
    ok(gl.enable(Cap::TextureGen(0)));
    ok(gl.tex_gen_mode(0, TexGenMode::ObjectLinear));
    ok(gl.tex_gen_object_plane(0, DVec4::new(1.0, 0.0, 0.0, 0.0)));
    ok(gl.multi_tex_coord(1, Vec4::from_array(UNIT1_COORDS)));
    ok(gl.active_texture(0));
    ok(gl.tex_env(TexEnvParam::Mode(TexEnvMode::Decal)));
    [left, gl.lighting]
}

/// Mesa's image of the two quads.
fn mesa(unit2_source: u8) -> RgbaImage {
    let [left_state, right_state] = gl_states(unit2_source);
    let (left, right) = (quad(-1.0), quad(0.0));
    let images = textures();
    let bound = |i: usize| Some((&images[i], Sampling::NEAREST));
    let mut a = GlDraw::new(&left, Mat4::IDENTITY, Mat4::IDENTITY, left_state);
    a.textures = [bound(0), bound(1), bound(2), None];
    a.mesh_texcoords = 1 << 1;
    let mut b = GlDraw::new(&right, Mat4::IDENTITY, Mat4::IDENTITY, right_state);
    b.textures = [bound(0), bound(3), None, None];
    mesa_image((SIZE, SIZE), CLEAR, false, vec![a, b])
}

/// A buffer or image of the caller's with its memory.
pub(crate) enum Owned {
    Buffer(vk::Buffer, vk::DeviceMemory),
    Image(vk::Image, vk::ImageView, vk::DeviceMemory),
    Sampler(vk::Sampler),
}

/// The caller's side of the frame on `plain`'s device: what it makes, and frees on drop.
pub(crate) struct Caller<'d> {
    pub(crate) plain: &'d PlainDevice,
    pub(crate) owned: Vec<Owned>,
    pub(crate) pool: vk::CommandPool,
}

impl Drop for Caller<'_> {
    fn drop(&mut self) {
        let d = &self.plain.device;
        // SAFETY: every submission was waited for; the objects are this caller's.
        unsafe {
            let _ = d.device_wait_idle();
            for o in self.owned.drain(..) {
                match o {
                    Owned::Buffer(b, m) => {
                        d.destroy_buffer(b, None);
                        d.free_memory(m, None);
                    }
                    Owned::Image(i, v, m) => {
                        d.destroy_image_view(v, None);
                        d.destroy_image(i, None);
                        d.free_memory(m, None);
                    }
                    Owned::Sampler(s) => d.destroy_sampler(s, None),
                }
            }
            d.destroy_command_pool(self.pool, None);
        }
    }
}

impl<'d> Caller<'d> {
    pub(crate) fn new(plain: &'d PlainDevice) -> Self {
        let info = vk::CommandPoolCreateInfo::default().queue_family_index(0);
        // SAFETY: a valid create info on a live device (queue family 0 is PlainDevice's).
        let pool = unsafe { plain.device.create_command_pool(&info, None) }.unwrap();
        Caller {
            plain,
            owned: Vec::new(),
            pool,
        }
    }

    pub(crate) fn memory(
        &self,
        req: vk::MemoryRequirements,
        flags: vk::MemoryPropertyFlags,
    ) -> vk::DeviceMemory {
        // SAFETY: a live instance and physical device.
        let props = unsafe {
            self.plain
                .instance
                .get_physical_device_memory_properties(self.plain.physical)
        };
        let index = (0..props.memory_type_count)
            .find(|&i| {
                req.memory_type_bits & (1 << i) != 0
                    && props.memory_types[i as usize].property_flags.contains(flags)
            })
            .expect("a memory type");
        let info = vk::MemoryAllocateInfo::default()
            .allocation_size(req.size)
            .memory_type_index(index);
        // SAFETY: a valid allocate info.
        unsafe { self.plain.device.allocate_memory(&info, None) }.unwrap()
    }

    /// A host-visible buffer holding `bytes` (or zeros up to `bytes.len()`).
    pub(crate) fn buffer(
        &mut self,
        bytes: &[u8],
        usage: vk::BufferUsageFlags,
    ) -> (vk::Buffer, vk::DeviceMemory) {
        let d = &self.plain.device;
        let info = vk::BufferCreateInfo::default()
            .size(bytes.len() as u64)
            .usage(usage);
        // SAFETY: a valid create info; the memory is fresh, bound once and filled through a
        // mapping of its whole size.
        unsafe {
            let buffer = d.create_buffer(&info, None).unwrap();
            let req = d.get_buffer_memory_requirements(buffer);
            let memory = self.memory(
                req,
                vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT,
            );
            d.bind_buffer_memory(buffer, memory, 0).unwrap();
            let ptr = d
                .map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                .unwrap();
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), ptr.cast::<u8>(), bytes.len());
            d.unmap_memory(memory);
            self.owned.push(Owned::Buffer(buffer, memory));
            (buffer, memory)
        }
    }

    /// A 2D image of `FORMAT` with one level, and its view.
    pub(crate) fn image(
        &mut self,
        width: u32,
        height: u32,
        usage: vk::ImageUsageFlags,
    ) -> (vk::Image, vk::ImageView) {
        let d = &self.plain.device;
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(FORMAT)
            .extent(vk::Extent3D {
                width,
                height,
                depth: 1,
            })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .usage(usage);
        // SAFETY: valid create infos; the memory is fresh and bound once.
        unsafe {
            let image = d.create_image(&info, None).unwrap();
            let req = d.get_image_memory_requirements(image);
            let memory = self.memory(req, vk::MemoryPropertyFlags::empty());
            d.bind_image_memory(image, memory, 0).unwrap();
            let view_info = vk::ImageViewCreateInfo::default()
                .image(image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(FORMAT)
                .subresource_range(color_range());
            let view = d.create_image_view(&view_info, None).unwrap();
            self.owned.push(Owned::Image(image, view, memory));
            (image, view)
        }
    }

    /// GL's `GL_NEAREST` with `GL_REPEAT`, no mipmaps (`Sampling::NEAREST`).
    fn nearest_sampler(&mut self) -> vk::Sampler {
        let info = vk::SamplerCreateInfo::default()
            .mag_filter(vk::Filter::NEAREST)
            .min_filter(vk::Filter::NEAREST)
            .mipmap_mode(vk::SamplerMipmapMode::NEAREST)
            .address_mode_u(vk::SamplerAddressMode::REPEAT)
            .address_mode_v(vk::SamplerAddressMode::REPEAT)
            .max_lod(0.25);
        // SAFETY: a valid create info.
        let sampler = unsafe { self.plain.device.create_sampler(&info, None) }.unwrap();
        self.owned.push(Owned::Sampler(sampler));
        sampler
    }
}

pub(crate) fn color_range() -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: vk::ImageAspectFlags::COLOR,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}

pub(crate) fn barrier(
    image: vk::Image,
    (old, new): (vk::ImageLayout, vk::ImageLayout),
    (src, dst): (vk::AccessFlags, vk::AccessFlags),
) -> vk::ImageMemoryBarrier<'static> {
    vk::ImageMemoryBarrier::default()
        .old_layout(old)
        .new_layout(new)
        .src_access_mask(src)
        .dst_access_mask(dst)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .image(image)
        .subresource_range(color_range())
}

/// One vertex of binding 0: position, normal, color, (s, t); 48 bytes.
pub(crate) fn interleaved(meshes: &[&MeshData]) -> Vec<u8> {
    let mut out = Vec::new();
    for v in meshes.iter().flat_map(|m| &m.vertices) {
        for x in v
            .position
            .iter()
            .chain(&v.normal)
            .chain(&v.color)
            .chain(&v.texcoord)
        {
            out.extend(x.to_ne_bytes());
        }
    }
    out
}

pub(crate) fn attribute(binding: u32, offset: u32, format: vk::Format) -> FfvkAttribute {
    FfvkAttribute {
        binding,
        offset,
        format,
    }
}

/// The two quads drawn through the C API on a caller's device, unit 2's `GL_SRC0_RGB`
/// `GL_TEXTURE0 + unit2_source`, read back top row first.
fn ffvk_image(unit2_source: u32) -> RgbaImage {
    let plain = PlainDevice::new();
    let mut caller = Caller::new(&plain);
    let d = &plain.device;
    let (left, right) = (quad(-1.0), quad(0.0));
    let (vertices, _) = caller.buffer(
        &interleaved(&[&left, &right]),
        vk::BufferUsageFlags::VERTEX_BUFFER,
    );
    // Unit 1's coordinates of the left quad: a second array, in a binding of its own.
    let second: Vec<u8> = left
        .vertices
        .iter()
        .flat_map(|v| v.texcoord)
        .flat_map(f32::to_ne_bytes)
        .collect();
    let (coords, _) = caller.buffer(&second, vk::BufferUsageFlags::VERTEX_BUFFER);
    let (readback, readback_memory) = caller.buffer(
        &vec![0; (SIZE * SIZE * 4) as usize],
        vk::BufferUsageFlags::TRANSFER_DST,
    );
    let (target, target_view) = caller.image(
        SIZE,
        SIZE,
        vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC,
    );
    let sampler = caller.nearest_sampler();
    let images = textures();
    let mut uploads = Vec::new();
    for t in &images {
        let level = &t.levels()[0];
        let (staging, _) = caller.buffer(level.rgba(), vk::BufferUsageFlags::TRANSFER_SRC);
        let (image, view) = caller.image(
            level.width(),
            level.height(),
            vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST,
        );
        uploads.push((staging, image, view, level.width(), level.height()));
    }

    let binding = |binding, stride| vk::VertexInputBindingDescription {
        binding,
        stride,
        input_rate: vk::VertexInputRate::VERTEX,
    };
    let bindings = [binding(0, 48), binding(1, 8)];
    let color = attribute(0, 24, vk::Format::R32G32B32A32_SFLOAT);
    let texcoord = attribute(0, 40, vk::Format::R32G32_SFLOAT);
    let texcoord1 = attribute(1, 0, vk::Format::R32G32_SFLOAT);
    // The renderer's own layout: binding 0 alone, no array for units 1 to 3.
    let info = FfvkRendererCreateInfo {
        struct_size: std::mem::size_of::<FfvkRendererCreateInfo>() as u32,
        get_instance_proc_addr: Some(plain.entry.static_fn().get_instance_proc_addr),
        instance: plain.instance.handle(),
        physical_device: plain.physical,
        device: d.handle(),
        enabled_features: FFVK_FEATURE_DYNAMIC_RENDERING,
        color_format: FORMAT,
        depth_format: vk::Format::UNDEFINED,
        samples: vk::SampleCountFlags::TYPE_1,
        bindings: bindings.as_ptr(),
        binding_count: 1,
        position: attribute(0, 0, vk::Format::R32G32B32_SFLOAT),
        normal: attribute(0, 12, vk::Format::R32G32B32_SFLOAT),
        color: &color,
        texcoord: &texcoord,
        frames_in_flight: 1,
        set_index: 0,
        pipeline_cache: vk::PipelineCache::null(),
    };
    let position = attribute(0, 0, vk::Format::R32G32B32_SFLOAT);
    let normal = attribute(0, 12, vk::Format::R32G32B32_SFLOAT);
    // The left quad's layout (version 2): unit 1's coordinates from binding 1.
    let layout_info = FfvkVertexLayoutInfo {
        struct_size: std::mem::size_of::<FfvkVertexLayoutInfo>() as u32,
        bindings: bindings.as_ptr(),
        binding_count: 2,
        position,
        normal: &normal,
        color: &color,
        texcoord: &texcoord,
        secondary_color: std::ptr::null(),
        fog_coord: std::ptr::null(),
        materials: std::ptr::null(),
        material_count: 0,
        texcoord1: &texcoord1,
        texcoord2: std::ptr::null(),
        texcoord3: std::ptr::null(),
    };

    let ctx = ffvkCreateContext();
    let mut r = std::ptr::null_mut();
    let mut layout = std::ptr::null_mut();
    let mut tex = [std::ptr::null_mut::<FfvkTexture>(); 4];
    // SAFETY: the create infos' handles and pointers are live for the calls; the outs are
    // writable; the textures name live views and the sampler.
    unsafe {
        let made = ffvkCreateRenderer(&info, &mut r);
        assert_eq!(made, FfvkResult::FFVK_SUCCESS, "{}", message());
        let made = ffvkCreateVertexLayout(r, &layout_info, &mut layout);
        assert_eq!(made, FfvkResult::FFVK_SUCCESS, "{}", message());
        for (t, (_, _, view, _, _)) in tex.iter_mut().zip(&uploads) {
            let made = ffvkCreateTexture(r, *view, sampler, t);
            assert_eq!(made, FfvkResult::FFVK_SUCCESS, "{}", message());
        }
    }

    // The left quad's state, as a layer forwards the application's GL calls.
    let plane = [1.0f32, 0.0, 0.0, 0.0];
    // SAFETY: a live context; every pointer points at as many values as its name takes.
    unsafe {
        ffvkEnable(ctx, GL_TEXTURE_2D);
        ffvkActiveTexture(ctx, GL_TEXTURE0 + 1);
        ffvkEnable(ctx, GL_TEXTURE_2D);
        ffvkLoadTextureMatrix(ctx, unit1_matrix().to_cols_array().as_ptr());
        ffvkActiveTexture(ctx, GL_TEXTURE0 + 2);
        ffvkEnable(ctx, GL_TEXTURE_2D);
        let env = |pname: u32, value: u32| ffvkTexEnvi(ctx, GL_TEXTURE_ENV, pname, value as i32);
        env(GL_TEXTURE_ENV_MODE, GL_COMBINE);
        env(GL_COMBINE_RGB, GL_INTERPOLATE);
        env(GL_SRC0_RGB, GL_TEXTURE0 + unit2_source);
        env(GL_SRC0_RGB + 1, GL_PREVIOUS);
        env(GL_SRC0_RGB + 2, GL_TEXTURE);
        env(GL_OPERAND0_RGB + 2, GL_SRC_COLOR);
        env(GL_COMBINE_ALPHA, GL_REPLACE);
        env(GL_SRC0_ALPHA, GL_PREVIOUS);
        ffvkMultiTexCoord2f(ctx, GL_TEXTURE0 + 2, UNIT2_COORDS[0], UNIT2_COORDS[1]);
        assert_eq!(ffvkGetError(ctx), 0, "{}", message());
    }

    let draw = |first: u32, buffers: &[vk::Buffer], layout: *const FfvkVertexLayout| {
        let mut raster = std::mem::MaybeUninit::<FfvkRaster>::uninit();
        // SAFETY: writable; ffvkRasterDefaults fills every field.
        let raster = unsafe {
            ffvkRasterDefaults(raster.as_mut_ptr());
            raster.assume_init()
        };
        FfvkDrawInfo {
            struct_size: std::mem::size_of::<FfvkDrawInfo>() as u32,
            mode: GL_TRIANGLES,
            vertex_buffers: buffers.as_ptr(),
            vertex_offsets: std::ptr::null(),
            vertex_buffer_count: buffers.len() as u32,
            index_buffer: vk::Buffer::null(),
            index_offset: 0,
            index_type: vk::IndexType::UINT32,
            first,
            count: 6,
            vertex_offset: 0,
            primitive_restart: 0,
            raster,
            texture: tex[0].cast_const(),
            layout,
            raster_source: FFVK_RASTER_SOURCE_DRAW,
            texture1: std::ptr::null(),
            texture2: std::ptr::null(),
            texture3: std::ptr::null(),
            cube_map: std::ptr::null(),
            cube_map1: std::ptr::null(),
            cube_map2: std::ptr::null(),
            cube_map3: std::ptr::null(),
        }
    };
    let two = [vertices, coords];
    let left_draw = FfvkDrawInfo {
        texture1: tex[1].cast_const(),
        texture2: tex[2].cast_const(),
        ..draw(0, &two, layout)
    };
    let one = [vertices];
    let right_draw = FfvkDrawInfo {
        texture1: tex[3].cast_const(),
        ..draw(6, &one, std::ptr::null())
    };

    let alloc = vk::CommandBufferAllocateInfo::default()
        .command_pool(caller.pool)
        .level(vk::CommandBufferLevel::PRIMARY)
        .command_buffer_count(1);
    // SAFETY: everything recorded is the caller's or ffvk's on this device, alive until the
    // fence wait below; the scope's rules (ffvk.h) are kept: viewport and scissor set inside the
    // rendering pass, nothing of the caller's recorded between ffvkBeginDraws and ffvkEndDraws.
    unsafe {
        let cmd = d.allocate_command_buffers(&alloc).unwrap()[0];
        d.begin_command_buffer(cmd, &vk::CommandBufferBeginInfo::default())
            .unwrap();
        let to_dst: Vec<_> = uploads
            .iter()
            .map(|u| {
                barrier(
                    u.1,
                    (vk::ImageLayout::UNDEFINED, vk::ImageLayout::TRANSFER_DST_OPTIMAL),
                    (vk::AccessFlags::empty(), vk::AccessFlags::TRANSFER_WRITE),
                )
            })
            .collect();
        d.cmd_pipeline_barrier(
            cmd,
            vk::PipelineStageFlags::TOP_OF_PIPE,
            vk::PipelineStageFlags::TRANSFER,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &to_dst,
        );
        for &(staging, image, _, width, height) in &uploads {
            let region = vk::BufferImageCopy {
                image_subresource: vk::ImageSubresourceLayers {
                    aspect_mask: vk::ImageAspectFlags::COLOR,
                    mip_level: 0,
                    base_array_layer: 0,
                    layer_count: 1,
                },
                image_extent: vk::Extent3D {
                    width,
                    height,
                    depth: 1,
                },
                ..Default::default()
            };
            d.cmd_copy_buffer_to_image(
                cmd,
                staging,
                image,
                vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                &[region],
            );
        }
        let mut to_read: Vec<_> = uploads
            .iter()
            .map(|u| {
                barrier(
                    u.1,
                    (
                        vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                        vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
                    ),
                    (vk::AccessFlags::TRANSFER_WRITE, vk::AccessFlags::SHADER_READ),
                )
            })
            .collect();
        to_read.push(barrier(
            target,
            (
                vk::ImageLayout::UNDEFINED,
                vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
            ),
            (vk::AccessFlags::empty(), vk::AccessFlags::COLOR_ATTACHMENT_WRITE),
        ));
        d.cmd_pipeline_barrier(
            cmd,
            vk::PipelineStageFlags::TRANSFER,
            vk::PipelineStageFlags::FRAGMENT_SHADER | vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &to_read,
        );
        let area = vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: SIZE,
                height: SIZE,
            },
        };
        let attachments = [vk::RenderingAttachmentInfo::default()
            .image_view(target_view)
            .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
            .load_op(vk::AttachmentLoadOp::CLEAR)
            .store_op(vk::AttachmentStoreOp::STORE)
            .clear_value(vk::ClearValue {
                color: vk::ClearColorValue { float32: CLEAR },
            })];
        let rendering = vk::RenderingInfo::default()
            .render_area(area)
            .layer_count(1)
            .color_attachments(&attachments);
        let mut viewport = vk::Viewport::default();
        ffvkViewport(0, 0, SIZE as i32, SIZE as i32, SIZE, 0.0, 1.0, &mut viewport);
        d.cmd_begin_rendering(cmd, &rendering);
        d.cmd_set_viewport(cmd, 0, &[viewport]);
        d.cmd_set_scissor(cmd, 0, &[area]);
        assert_eq!(ffvkBeginFrame(r, 0), FfvkResult::FFVK_SUCCESS, "{}", message());
        assert_eq!(
            ffvkBeginDraws(r, cmd, 0),
            FfvkResult::FFVK_SUCCESS,
            "{}",
            message()
        );
        assert_eq!(
            ffvkDraw(r, ctx, &left_draw),
            FfvkResult::FFVK_SUCCESS,
            "{}",
            message()
        );
        // The right quad's state: unit 2 off, unit 1 on its current t and a generated s,
        // unit 0 in GL_DECAL; the left draw kept the state it was added with.
        ffvkDisable(ctx, GL_TEXTURE_2D);
        ffvkActiveTexture(ctx, GL_TEXTURE0 + 1);
        ffvkEnable(ctx, GL_TEXTURE_GEN_S);
        ffvkTexGeni(ctx, GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as i32);
        ffvkTexGenfv(ctx, GL_S, GL_OBJECT_PLANE, plane.as_ptr());
        ffvkMultiTexCoord4fv(ctx, GL_TEXTURE0 + 1, UNIT1_COORDS.as_ptr());
        ffvkActiveTexture(ctx, GL_TEXTURE0);
        ffvkTexEnvi(ctx, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL as i32);
        assert_eq!(ffvkGetError(ctx), 0, "{}", message());
        assert_eq!(
            ffvkDraw(r, ctx, &right_draw),
            FfvkResult::FFVK_SUCCESS,
            "{}",
            message()
        );
        assert_eq!(ffvkEndDraws(r), FfvkResult::FFVK_SUCCESS, "{}", message());
        d.cmd_end_rendering(cmd);
        let to_copy = [barrier(
            target,
            (
                vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
            ),
            (
                vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
                vk::AccessFlags::TRANSFER_READ,
            ),
        )];
        d.cmd_pipeline_barrier(
            cmd,
            vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            vk::PipelineStageFlags::TRANSFER,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &to_copy,
        );
        let region = vk::BufferImageCopy {
            image_subresource: vk::ImageSubresourceLayers {
                aspect_mask: vk::ImageAspectFlags::COLOR,
                mip_level: 0,
                base_array_layer: 0,
                layer_count: 1,
            },
            image_extent: vk::Extent3D {
                width: SIZE,
                height: SIZE,
                depth: 1,
            },
            ..Default::default()
        };
        d.cmd_copy_image_to_buffer(
            cmd,
            target,
            vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
            readback,
            &[region],
        );
        let to_host = [vk::BufferMemoryBarrier::default()
            .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
            .dst_access_mask(vk::AccessFlags::HOST_READ)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .buffer(readback)
            .size(vk::WHOLE_SIZE)];
        d.cmd_pipeline_barrier(
            cmd,
            vk::PipelineStageFlags::TRANSFER,
            vk::PipelineStageFlags::HOST,
            vk::DependencyFlags::empty(),
            &[],
            &to_host,
            &[],
        );
        d.end_command_buffer(cmd).unwrap();
        let fence = d.create_fence(&vk::FenceCreateInfo::default(), None).unwrap();
        let cmds = [cmd];
        let submit = vk::SubmitInfo::default().command_buffers(&cmds);
        d.queue_submit(d.get_device_queue(0, 0), &[submit], fence)
            .unwrap();
        d.wait_for_fences(&[fence], true, u64::MAX).unwrap();
        d.destroy_fence(fence, None);
    }
    // SAFETY: host-visible, coherent memory the finished copy wrote; mapped only here.
    let pixels = unsafe {
        let ptr = d
            .map_memory(readback_memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
            .unwrap();
        let pixels = std::slice::from_raw_parts(ptr.cast::<u8>(), (SIZE * SIZE * 4) as usize).to_vec();
        d.unmap_memory(readback_memory);
        pixels
    };
    // SAFETY: the submission finished; ffvk's objects go before the caller's device.
    unsafe {
        for t in tex {
            ffvkDestroyTexture(t);
        }
        ffvkDestroyVertexLayout(layout);
        ffvkDestroyRenderer(r);
        ffvkDestroyContext(ctx);
    }
    drop(caller);
    RgbaImage::from_raw(SIZE, SIZE, pixels).unwrap()
}

/// The largest difference of any channel of any pixel, and how many pixels differ at all.
pub(crate) fn worst(a: &RgbaImage, b: &RgbaImage) -> (u8, usize) {
    let mut differing = 0;
    let mut worst = 0;
    for (p, q) in a.pixels().zip(b.pixels()) {
        let d = p.0.iter().zip(q.0).map(|(x, y)| x.abs_diff(y)).max().unwrap_or(0);
        differing += usize::from(d > 0);
        worst = worst.max(d);
    }
    (worst, differing)
}

#[test]
fn two_draws_of_several_texture_units_through_the_c_api_draw_mesas_pixels() {
    let ours = ffvk_image(0);
    let gl = mesa(0);
    save_for_inspection(&ours, "c_api_units_ffvk");
    save_for_inspection(&gl, "c_api_units_mesa");
    let (worst, differing) = worst(&ours, &gl);
    eprintln!(
        "{differing} of {} pixels differ, by at most {worst}/255",
        SIZE * SIZE
    );
    assert!(
        worst <= 1,
        "the C API's units and Mesa's differ by {worst}/255 ({differing} pixels; tests/output/c_api_units_*.png)"
    );
    // Not two blank images: each quad covers its half, and the units show: the left quad's
    // pixels take many colors (three textures over a gradient), the right quad's its checker.
    let colors = |x0: u32| {
        let mut seen: Vec<[u8; 4]> = Vec::new();
        for y in 0..SIZE {
            for x in x0..x0 + SIZE / 2 {
                let p = ours.get_pixel(x, y).0;
                if !seen.contains(&p) {
                    seen.push(p);
                }
            }
        }
        seen.len()
    };
    assert!(
        colors(0) > 64 && colors(SIZE / 2) > 16,
        "{} and {} colors",
        colors(0),
        colors(SIZE / 2)
    );

    // The comparison can fail: unit 2 reading GL_TEXTURE1 through the crossbar instead of
    // GL_TEXTURE0 draws other pixels than Mesa's GL_TEXTURE0 (and Mesa agrees with it again).
    let other = ffvk_image(1);
    let (moved, count) = self::worst(&other, &gl);
    assert!(
        moved > 16 && count > 100,
        "GL_TEXTURE1 as unit 2's source moved {count} pixels by {moved}/255"
    );
    let (again, _) = self::worst(&other, &mesa(1));
    assert!(again <= 1, "with GL_TEXTURE1 on both sides: {again}/255");
}
