//! Base internal formats through the C API (`ffvkCreateTextureWithFormat`,
//! `ffvkCreateCubeMapWithFormat`), as a C layer stores a legacy program's textures: one or two
//! channels a texel, the view's swizzle putting alpha in A, against Mesa's GL uploading the
//! same texels as RGBA pixels with the format as glTexImage2D's internal format (GL 2.1 table
//! 3.15 takes luminance and intensity from R, alpha from A).
//!
//! Four quads, a quadrant each, vertex colors over them, in one scope:
//!
//! - `GL_LUMINANCE` from a `VK_FORMAT_R8_UNORM` view, `GL_MODULATE`: the color scaled by L, the
//!   alpha kept.
//! - `GL_ALPHA` from an `R8_UNORM` view whose `components.a` is R, `GL_MODULATE`: the color
//!   kept, the alpha scaled.
//! - `GL_LUMINANCE_ALPHA` from an `R8G8_UNORM` view whose `components.a` is G, `GL_BLEND`
//!   towards the environment color.
//! - A `GL_INTENSITY` cube map from an `R8_UNORM` cube view, `GL_MODULATE`, its +Z face read at
//!   (2s − 1, 2t − 1, 1) through the texture matrix.
//!
//! Every channel of every pixel within 1/255 of Mesa's (c_api_units.rs's tolerance); and the
//! same views bound as `ffvkCreateTexture` binds them (`GL_RGBA`) draw other pixels. A bad
//! `internalformat` is refused naming the function, the parameter, the value and the six
//! accepted, as the renderer refuses any enum it does not take.

use ffvk::ash::vk;
use ffvk::gl::state::{Cap, FixedFunctionState, GlState, TexEnvParam};
use ffvk::gl::texture::{BaseFormat, CubeImage, Sampling, TexEnvMode, TextureImage};
use ffvk::mesh::{MeshData, Vertex};
use ffvk_c::gl::*;
use ffvk_c::render::*;
use ffvk_c::result::FfvkResult;
use ffvk_c::viewport::ffvkViewport;
use ffvk_cli::gl_reference::GlDraw;
use glam::{Mat4, Vec4};
use image::RgbaImage;

use crate::c_api_units::{attribute, barrier, color_range, interleaved, message, worst, Caller, Owned};
use crate::embedding::PlainDevice;
use crate::support::{hashed_texels, mesa_image, save_for_inspection};

const SIZE: u32 = 64;
const CLEAR: [f32; 4] = [0.1, 0.1, 0.1, 1.0];
const TARGET: vk::Format = vk::Format::R8G8B8A8_UNORM;
/// The textures' side in texels: over a quad's 32 pixels, pixel centers never fall on a
/// texel's edge (s = (i + 0.5)/32, edges at multiples of 1/8).
const SIDE: u32 = 8;

const GL_ALPHA: u32 = 0x1906;
const GL_RGBA: u32 = 0x1908;
const GL_LUMINANCE: u32 = 0x1909;
const GL_LUMINANCE_ALPHA: u32 = 0x190A;
const GL_INTENSITY: u32 = 0x8049;
const GL_TEXTURE_2D: u32 = 0x0DE1;
const GL_TEXTURE_CUBE_MAP: u32 = 0x8513;
const GL_TEXTURE_ENV: u32 = 0x2300;
const GL_TEXTURE_ENV_MODE: u32 = 0x2200;
const GL_TEXTURE_ENV_COLOR: u32 = 0x2201;
const GL_BLEND: u32 = 0x0BE2;
const GL_MODULATE: u32 = 0x2100;
const GL_TRIANGLES: u32 = 0x0004;

/// The environment color of the `GL_BLEND` quad.
const ENV_COLOR: [f32; 4] = [0.2, 0.9, 0.4, 0.5];

/// The cube quad's texture matrix: (s, t, 0, 1) to (2s − 1, 2t − 1, 1, 1), inside the +Z face.
fn cube_matrix() -> Mat4 {
    Mat4::from_cols_array(&[
        2.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, -1.0, 1.0, 1.0,
    ])
}

/// The quad over the clip-space square from (x0, y0), a color per corner, (s, t) over [0, 1].
fn quad(x0: f32, y0: f32) -> MeshData {
    let corner = |x: f32, y: f32| Vertex {
        position: [x0 + x, y0 + y, 0.0],
        normal: [0.0, 0.0, 1.0],
        color: [0.4 + 0.6 * x, 0.5 + 0.5 * y, 0.9 - 0.5 * x, 1.0 - 0.4 * y],
        texcoord: [x, y],
    };
    let c = [
        corner(0.0, 0.0),
        corner(1.0, 0.0),
        corner(1.0, 1.0),
        corner(0.0, 1.0),
    ];
    MeshData::new(vec![c[0], c[1], c[2], c[0], c[2], c[3]], (0..6).collect())
}

/// The quads in draw order: luminance (upper left), alpha (upper right), luminance-alpha
/// (lower left), the intensity cube map (lower right).
fn quads() -> [MeshData; 4] {
    [quad(-1.0, 0.0), quad(0.0, 0.0), quad(-1.0, -1.0), quad(0.0, -1.0)]
}

/// Each quad's texels as RGBA pixels: hashed texels (R and A both varying), another
/// arrangement for each.
fn images() -> [TextureImage; 3] {
    let turned = |t: TextureImage| {
        let l = &t.levels()[0];
        let mut rgba = l.rgba().to_vec();
        rgba.reverse();
        // Reversed whole: each texel's bytes now read A, B, G, R; put them back.
        for texel in rgba.chunks_mut(4) {
            texel.reverse();
        }
        TextureImage::new(l.width(), l.height(), rgba).unwrap()
    };
    [
        hashed_texels(SIDE),
        turned(hashed_texels(SIDE)),
        hashed_texels(SIDE * 2),
    ]
}

/// The cube map's faces: hashed texels, each face turned further.
fn cube_faces() -> [TextureImage; 6] {
    std::array::from_fn(|i| {
        let t = hashed_texels(SIDE);
        let l = &t.levels()[0];
        let n = l.rgba().len();
        let mut rgba = l.rgba().to_vec();
        rgba.rotate_left((i * 4 * 5) % n);
        TextureImage::new(SIDE, SIDE, rgba).unwrap()
    })
}

/// The GL state of each draw, made with the Rust state machine as the C calls below make it.
fn gl_states() -> [FixedFunctionState; 4] {
    let mut gl = GlState::new();
    let ok = |r: Result<(), ffvk::gl::state::StateError>| r.expect("a valid GL call");
    ok(gl.enable(Cap::Texture2D));
    let modulate = gl.lighting;
    ok(gl.tex_env(TexEnvParam::Mode(TexEnvMode::Blend)));
    ok(gl.tex_env(TexEnvParam::Color(Vec4::from_array(ENV_COLOR))));
    let blend = gl.lighting;
    ok(gl.tex_env(TexEnvParam::Mode(TexEnvMode::Modulate)));
    ok(gl.enable(Cap::TextureCubeMap));
    ok(gl.load_texture_matrix(cube_matrix()));
    [modulate, modulate, blend, gl.lighting]
}

/// Mesa's image of the four quads, each texture uploaded as RGBA pixels with its format.
fn mesa() -> RgbaImage {
    let states = gl_states();
    let meshes = quads();
    let [l, a, la] = images();
    let textures = [
        l.with_base_format(BaseFormat::Luminance),
        a.with_base_format(BaseFormat::Alpha),
        la.with_base_format(BaseFormat::LuminanceAlpha),
    ];
    let cube = CubeImage::new(cube_faces().map(|f| f.with_base_format(BaseFormat::Intensity))).unwrap();
    let draws = (0..4)
        .map(|i| {
            let mut d = GlDraw::new(&meshes[i], Mat4::IDENTITY, Mat4::IDENTITY, states[i]);
            match textures.get(i) {
                Some(t) => d.textures[0] = Some((t, Sampling::NEAREST)),
                None => d.cube_maps[0] = Some((&cube, Sampling::NEAREST)),
            }
            d
        })
        .collect();
    mesa_image((SIZE, SIZE), CLEAR, false, draws)
}

/// One of the caller's sampled images: `layers` layers of `side`² texels of `format`, its view
/// (a cube view of six layers, or 2D) with `alpha` as its A component, and the texels' bytes
/// (tightly packed, layer after layer) in a staging buffer.
struct Sampled {
    image: vk::Image,
    view: vk::ImageView,
    staging: vk::Buffer,
    side: u32,
    layers: u32,
}

fn sampled(
    caller: &mut Caller,
    (format, alpha): (vk::Format, vk::ComponentSwizzle),
    side: u32,
    bytes: &[u8],
    layers: u32,
) -> Sampled {
    let (staging, _) = caller.buffer(bytes, vk::BufferUsageFlags::TRANSFER_SRC);
    let d = &caller.plain.device;
    let flags = if layers == 6 {
        vk::ImageCreateFlags::CUBE_COMPATIBLE
    } else {
        vk::ImageCreateFlags::empty()
    };
    let info = vk::ImageCreateInfo::default()
        .flags(flags)
        .image_type(vk::ImageType::TYPE_2D)
        .format(format)
        .extent(vk::Extent3D {
            width: side,
            height: side,
            depth: 1,
        })
        .mip_levels(1)
        .array_layers(layers)
        .samples(vk::SampleCountFlags::TYPE_1)
        .usage(vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST);
    // SAFETY: valid create infos; the memory is fresh and bound once.
    unsafe {
        let image = d.create_image(&info, None).unwrap();
        let req = d.get_image_memory_requirements(image);
        let memory = caller.memory(req, vk::MemoryPropertyFlags::empty());
        d.bind_image_memory(image, memory, 0).unwrap();
        let view_info = vk::ImageViewCreateInfo::default()
            .image(image)
            .view_type(if layers == 6 {
                vk::ImageViewType::CUBE
            } else {
                vk::ImageViewType::TYPE_2D
            })
            .format(format)
            .components(vk::ComponentMapping {
                r: vk::ComponentSwizzle::IDENTITY,
                g: vk::ComponentSwizzle::IDENTITY,
                b: vk::ComponentSwizzle::IDENTITY,
                a: alpha,
            })
            .subresource_range(vk::ImageSubresourceRange {
                layer_count: layers,
                ..color_range()
            });
        let view = d.create_image_view(&view_info, None).unwrap();
        caller.owned.push(Owned::Image(image, view, memory));
        Sampled {
            image,
            view,
            staging,
            side,
            layers,
        }
    }
}

/// The channels `pick` takes of each texel of `image`, packed.
fn channels(image: &TextureImage, pick: &[usize]) -> Vec<u8> {
    image.levels()[0]
        .rgba()
        .chunks(4)
        .flat_map(|t| pick.iter().map(|&c| t[c]))
        .collect()
}

/// The four quads drawn through the C API on a caller's device, each texture bound with its
/// base format (`with_formats`) or as `ffvkCreateTexture` binds it; read back top row first.
fn ffvk_image(with_formats: bool) -> RgbaImage {
    let plain = PlainDevice::new();
    let mut caller = Caller::new(&plain);
    let d = &plain.device;
    let meshes = quads();
    let all: Vec<&MeshData> = meshes.iter().collect();
    let (vertices, _) = caller.buffer(&interleaved(&all), vk::BufferUsageFlags::VERTEX_BUFFER);
    let (readback, readback_memory) = caller.buffer(
        &vec![0; (SIZE * SIZE * 4) as usize],
        vk::BufferUsageFlags::TRANSFER_DST,
    );
    let (target, target_view) = caller.image(
        SIZE,
        SIZE,
        vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC,
    );
    use vk::ComponentSwizzle as Swizzle;
    use vk::Format as F;
    let [l, a, la] = images();
    let faces: Vec<u8> = cube_faces().iter().flat_map(|f| channels(f, &[0])).collect();
    // L and I as R; A as R read through the swizzle; L and A as R and G.
    let uploads = [
        sampled(
            &mut caller,
            (F::R8_UNORM, Swizzle::IDENTITY),
            SIDE,
            &channels(&l, &[0]),
            1,
        ),
        sampled(
            &mut caller,
            (F::R8_UNORM, Swizzle::R),
            SIDE,
            &channels(&a, &[3]),
            1,
        ),
        sampled(
            &mut caller,
            (F::R8G8_UNORM, Swizzle::G),
            SIDE * 2,
            &channels(&la, &[0, 3]),
            1,
        ),
        sampled(&mut caller, (F::R8_UNORM, Swizzle::IDENTITY), SIDE, &faces, 6),
    ];
    let sampler_info = vk::SamplerCreateInfo::default()
        .mag_filter(vk::Filter::NEAREST)
        .min_filter(vk::Filter::NEAREST)
        .mipmap_mode(vk::SamplerMipmapMode::NEAREST)
        .address_mode_u(vk::SamplerAddressMode::REPEAT)
        .address_mode_v(vk::SamplerAddressMode::REPEAT)
        .address_mode_w(vk::SamplerAddressMode::REPEAT)
        .max_lod(0.25);
    // SAFETY: a valid create info on a live device.
    let sampler = unsafe { d.create_sampler(&sampler_info, None) }.unwrap();
    caller.owned.push(Owned::Sampler(sampler));

    let binding = vk::VertexInputBindingDescription {
        binding: 0,
        stride: 48,
        input_rate: vk::VertexInputRate::VERTEX,
    };
    let color = attribute(0, 24, vk::Format::R32G32B32A32_SFLOAT);
    let texcoord = attribute(0, 40, vk::Format::R32G32_SFLOAT);
    let info = FfvkRendererCreateInfo {
        struct_size: std::mem::size_of::<FfvkRendererCreateInfo>() as u32,
        get_instance_proc_addr: Some(plain.entry.static_fn().get_instance_proc_addr),
        instance: plain.instance.handle(),
        physical_device: plain.physical,
        device: d.handle(),
        enabled_features: FFVK_FEATURE_DYNAMIC_RENDERING,
        color_format: TARGET,
        depth_format: vk::Format::UNDEFINED,
        samples: vk::SampleCountFlags::TYPE_1,
        bindings: &binding,
        binding_count: 1,
        position: attribute(0, 0, vk::Format::R32G32B32_SFLOAT),
        normal: attribute(0, 12, vk::Format::R32G32B32_SFLOAT),
        color: &color,
        texcoord: &texcoord,
        frames_in_flight: 1,
        set_index: 0,
        pipeline_cache: vk::PipelineCache::null(),
    };
    let ctx = ffvkCreateContext();
    let mut r = std::ptr::null_mut();
    let mut tex = [std::ptr::null_mut::<FfvkTexture>(); 4];
    let formats = [GL_LUMINANCE, GL_ALPHA, GL_LUMINANCE_ALPHA, GL_INTENSITY];
    // SAFETY: the create info's handles and pointers are live for the calls; the outs are
    // writable; the bindings name live views and the sampler.
    unsafe {
        let made = ffvkCreateRenderer(&info, &mut r);
        assert_eq!(made, FfvkResult::FFVK_SUCCESS, "{}", message());
        for (i, (t, u)) in tex.iter_mut().zip(&uploads).enumerate() {
            let made = match (i, with_formats) {
                (3, true) => ffvkCreateCubeMapWithFormat(r, u.view, sampler, formats[i], t),
                (3, false) => ffvkCreateCubeMap(r, u.view, sampler, t),
                (_, true) => ffvkCreateTextureWithFormat(r, u.view, sampler, formats[i], t),
                (_, false) => ffvkCreateTexture(r, u.view, sampler, t),
            };
            assert_eq!(made, FfvkResult::FFVK_SUCCESS, "{}", message());
        }
        ffvkEnable(ctx, GL_TEXTURE_2D);
        assert_eq!(ffvkGetError(ctx), 0, "{}", message());
    }

    let buffers = [vertices];
    let draw = |i: usize| {
        let mut raster = std::mem::MaybeUninit::<FfvkRaster>::uninit();
        // SAFETY: writable; ffvkRasterDefaults fills every field.
        let raster = unsafe {
            ffvkRasterDefaults(raster.as_mut_ptr());
            raster.assume_init()
        };
        let (texture, cube_map) = if i == 3 {
            (std::ptr::null(), tex[i].cast_const())
        } else {
            (tex[i].cast_const(), std::ptr::null())
        };
        FfvkDrawInfo {
            struct_size: std::mem::size_of::<FfvkDrawInfo>() as u32,
            mode: GL_TRIANGLES,
            vertex_buffers: buffers.as_ptr(),
            vertex_offsets: std::ptr::null(),
            vertex_buffer_count: 1,
            index_buffer: vk::Buffer::null(),
            index_offset: 0,
            index_type: vk::IndexType::UINT32,
            first: 6 * i as u32,
            count: 6,
            vertex_offset: 0,
            primitive_restart: 0,
            raster,
            texture,
            layout: std::ptr::null(),
            raster_source: FFVK_RASTER_SOURCE_DRAW,
            texture1: std::ptr::null(),
            texture2: std::ptr::null(),
            texture3: std::ptr::null(),
            cube_map,
            cube_map1: std::ptr::null(),
            cube_map2: std::ptr::null(),
            cube_map3: std::ptr::null(),
        }
    };

    let alloc = vk::CommandBufferAllocateInfo::default()
        .command_pool(caller.pool)
        .level(vk::CommandBufferLevel::PRIMARY)
        .command_buffer_count(1);
    let range = |u: &Sampled| vk::ImageSubresourceRange {
        layer_count: u.layers,
        ..color_range()
    };
    // SAFETY: everything recorded is the caller's or ffvk's on this device, alive until the
    // fence wait below; the scope's rules (ffvk.h) are kept: viewport and scissor set inside the
    // rendering pass, nothing of the caller's recorded between ffvkBeginDraws and ffvkEndDraws;
    // the context is live and every pointer points at as many values as its name takes.
    unsafe {
        let cmd = d.allocate_command_buffers(&alloc).unwrap()[0];
        d.begin_command_buffer(cmd, &vk::CommandBufferBeginInfo::default())
            .unwrap();
        let to_dst: Vec<_> = uploads
            .iter()
            .map(|u| {
                barrier(
                    u.image,
                    (vk::ImageLayout::UNDEFINED, vk::ImageLayout::TRANSFER_DST_OPTIMAL),
                    (vk::AccessFlags::empty(), vk::AccessFlags::TRANSFER_WRITE),
                )
                .subresource_range(range(u))
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
        for u in &uploads {
            let region = vk::BufferImageCopy {
                image_subresource: vk::ImageSubresourceLayers {
                    aspect_mask: vk::ImageAspectFlags::COLOR,
                    mip_level: 0,
                    base_array_layer: 0,
                    layer_count: u.layers,
                },
                image_extent: vk::Extent3D {
                    width: u.side,
                    height: u.side,
                    depth: 1,
                },
                ..Default::default()
            };
            d.cmd_copy_buffer_to_image(
                cmd,
                u.staging,
                u.image,
                vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                &[region],
            );
        }
        let mut to_read: Vec<_> = uploads
            .iter()
            .map(|u| {
                barrier(
                    u.image,
                    (
                        vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                        vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
                    ),
                    (vk::AccessFlags::TRANSFER_WRITE, vk::AccessFlags::SHADER_READ),
                )
                .subresource_range(range(u))
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
        let add = |i: usize| {
            assert_eq!(
                ffvkDraw(r, ctx, &draw(i)),
                FfvkResult::FFVK_SUCCESS,
                "draw {i}: {}",
                message()
            );
        };
        // GL_MODULATE (GL's default) for the luminance and alpha quads.
        add(0);
        add(1);
        // GL_BLEND towards the environment color.
        ffvkTexEnvi(ctx, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND as i32);
        ffvkTexEnvfv(ctx, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ENV_COLOR.as_ptr());
        add(2);
        // The cube map, GL_MODULATE again, through the texture matrix.
        ffvkTexEnvi(ctx, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
        ffvkEnable(ctx, GL_TEXTURE_CUBE_MAP);
        ffvkLoadTextureMatrix(ctx, cube_matrix().to_cols_array().as_ptr());
        assert_eq!(ffvkGetError(ctx), 0, "{}", message());
        add(3);
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
        ffvkDestroyRenderer(r);
        ffvkDestroyContext(ctx);
    }
    drop(caller);
    RgbaImage::from_raw(SIZE, SIZE, pixels).unwrap()
}

#[test]
fn luminance_alpha_and_luminance_alpha_textures_and_an_intensity_cube_map_through_the_c_api_draw_mesas_pixels(
) {
    let ours = ffvk_image(true);
    let gl = mesa();
    save_for_inspection(&ours, "c_api_formats_ffvk");
    save_for_inspection(&gl, "c_api_formats_mesa");
    let (worst, differing) = worst(&ours, &gl);
    eprintln!(
        "{differing} of {} pixels differ, by at most {worst}/255",
        SIZE * SIZE
    );
    assert!(
        worst <= 1,
        "the C API's base formats and Mesa's differ by {worst}/255 ({differing} pixels; tests/output/c_api_formats_*.png)"
    );
    // Each quadrant drawn, its texels showing: many colors in each.
    let colors = |x0: u32, y0: u32| {
        let mut seen: Vec<[u8; 4]> = Vec::new();
        for y in y0..y0 + SIZE / 2 {
            for x in x0..x0 + SIZE / 2 {
                let p = ours.get_pixel(x, y).0;
                if !seen.contains(&p) {
                    seen.push(p);
                }
            }
        }
        seen.len()
    };
    let half = SIZE / 2;
    for (x0, y0) in [(0, 0), (half, 0), (0, half), (half, half)] {
        assert!(colors(x0, y0) > 16, "{} colors at ({x0}, {y0})", colors(x0, y0));
    }

    // The comparison can fail: the same views bound as GL_RGBA textures (R8's green and blue
    // read 0) draw other pixels than Mesa's.
    let rgba = ffvk_image(false);
    let (moved, count) = self::worst(&rgba, &gl);
    assert!(
        moved > 32 && count > 1000,
        "GL_RGBA bindings moved {count} pixels by {moved}/255"
    );
}

#[test]
fn a_bad_internalformat_is_refused_naming_the_function_the_parameter_the_value_and_the_six_accepted() {
    let plain = PlainDevice::new();
    let info = crate::c_api_boundary::create_info(&plain);
    let mut r = std::ptr::null_mut();
    // SAFETY: the create info's handles are a live PlainDevice's; out is writable.
    let made = unsafe { ffvkCreateRenderer(&info, &mut r) };
    assert_eq!(made, FfvkResult::FFVK_SUCCESS, "{}", message());
    // Never drawn: a binding names the handles without using them.
    let (view, sampler) = {
        use ffvk::ash::vk::Handle;
        (vk::ImageView::from_raw(0x10), vk::Sampler::from_raw(0x20))
    };
    let accepted = "expected GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_INTENSITY, GL_RGB or GL_RGBA (GL 2.1 table 3.15)";
    type Create = unsafe extern "C" fn(
        *mut FfvkRenderer,
        vk::ImageView,
        vk::Sampler,
        u32,
        *mut *mut FfvkTexture,
    ) -> FfvkResult;
    let entries: [(&str, Create); 2] = [
        ("ffvkCreateTextureWithFormat", ffvkCreateTextureWithFormat),
        ("ffvkCreateCubeMapWithFormat", ffvkCreateCubeMapWithFormat),
    ];
    for (name, create) in entries {
        let call = |format: u32, handles: (vk::ImageView, vk::Sampler)| {
            let mut out = std::ptr::NonNull::<FfvkTexture>::dangling().as_ptr();
            // SAFETY: a live renderer; out is writable; a binding made is destroyed at once.
            let result = unsafe { create(r, handles.0, handles.1, format, &mut out) };
            let text = message();
            assert_eq!(
                out.is_null(),
                result != FfvkResult::FFVK_SUCCESS,
                "{name}: the out pointer and the result disagree: {result:?} {text}"
            );
            // SAFETY: null or a binding just made.
            unsafe { ffvkDestroyTexture(out) };
            (result, text)
        };
        for (format, given, hint) in [
            (
                0x8040,
                "GL_LUMINANCE8 (0x8040)",
                Some("give its base format, GL_LUMINANCE"),
            ),
            (
                0x8C43,
                "GL_SRGB8_ALPHA8 (0x8C43)",
                Some("give its base format, GL_RGBA"),
            ),
            (
                0x804B,
                "GL_INTENSITY8 (0x804B)",
                Some("give its base format, GL_INTENSITY"),
            ),
            (
                2,
                "2",
                Some("GL 1.0's component count: give its base format, GL_LUMINANCE_ALPHA"),
            ),
            (0x0DE1, "GL_TEXTURE_2D (0x0DE1)", None),
            (0x1902, "0x1902", None),
            (0, "0x0000", None),
            (0xFFFF_FFFF, "0xFFFFFFFF", None),
        ] {
            let (result, text) = call(format, (view, sampler));
            assert_eq!(
                result,
                FfvkResult::FFVK_ERROR_INVALID_ARGUMENT,
                "{name} {given}: {text}"
            );
            let expected =
                format!("{name}: internalformat {given} is not a base internal format: {accepted}");
            assert!(text.starts_with(&expected), "{text:?} should start {expected:?}");
            if let Some(hint) = hint {
                assert!(text.contains(hint), "{text:?} should say {hint:?}");
            }
            // The enum is checked before the handles: a null view is not what is named.
            let (_, text) = call(format, (vk::ImageView::null(), sampler));
            assert!(text.contains("internalformat"), "{text}");
        }
        // Each of the six is taken; a null handle with a good format is named as
        // ffvkCreateTexture names it.
        for format in [
            GL_ALPHA,
            0x1907,
            GL_RGBA,
            GL_LUMINANCE,
            GL_LUMINANCE_ALPHA,
            GL_INTENSITY,
        ] {
            let (result, text) = call(format, (view, sampler));
            assert_eq!(result, FfvkResult::FFVK_SUCCESS, "{name} 0x{format:04X}: {text}");
            let (result, text) = call(format, (view, vk::Sampler::null()));
            assert_eq!(result, FfvkResult::FFVK_ERROR_INVALID_ARGUMENT);
            assert!(
                text.starts_with(&format!("{name}: view or sampler is VK_NULL_HANDLE")),
                "{text}"
            );
        }
    }
    // SAFETY: the renderer just made; nothing was submitted.
    unsafe { ffvkDestroyRenderer(r) };
}
