//! How long a C caller's texture objects must live: an `FfvkTexture` names the caller's view
//! and sampler and is no Vulkan object, and `ffvkDraw` copies what it names, so the caller may
//! destroy it as soon as the draw is added. `ffvkEndDraws` records the draw `ffvkDraw` checked,
//! never whatever the freed memory holds by then (the texture unit's pixels show which).

use ffvk::ash::vk;
use ffvk_c::gl::*;
use ffvk_c::render::*;
use ffvk_c::result::FfvkResult;

use crate::c_api_boundary::{create_info, draw_info, message};
use crate::c_api_units::{barrier, Caller, Owned};
use crate::embedding::PlainDevice;

const SIZE: u32 = 4;
const GL_TEXTURE_2D: u32 = 0x0DE1;
const RED: [f32; 4] = [1.0, 0.0, 0.0, 1.0];
const GREEN: [f32; 4] = [0.0, 1.0, 0.0, 1.0];

/// A nearest sampler of the caller's.
fn sampler(caller: &mut Caller) -> vk::Sampler {
    let info = vk::SamplerCreateInfo::default().max_lod(0.25);
    // SAFETY: a valid create info on a live device.
    let sampler = unsafe { caller.plain.device.create_sampler(&info, None) }.unwrap();
    caller.owned.push(Owned::Sampler(sampler));
    sampler
}

/// A 1x1 image cleared to `color` by `cmd`, in `SHADER_READ_ONLY_OPTIMAL` after it, and its
/// view.
fn solid(caller: &mut Caller, cmd: vk::CommandBuffer, color: [f32; 4]) -> vk::ImageView {
    let usage = vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST;
    let (image, view) = caller.image(1, 1, usage);
    let d = &caller.plain.device;
    let range = crate::c_api_units::color_range();
    // SAFETY: cmd is recording; the image is the caller's, fresh.
    unsafe {
        let to_dst = barrier(
            image,
            (vk::ImageLayout::UNDEFINED, vk::ImageLayout::TRANSFER_DST_OPTIMAL),
            (vk::AccessFlags::empty(), vk::AccessFlags::TRANSFER_WRITE),
        );
        d.cmd_pipeline_barrier(
            cmd,
            vk::PipelineStageFlags::TOP_OF_PIPE,
            vk::PipelineStageFlags::TRANSFER,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &[to_dst],
        );
        let clear = vk::ClearColorValue { float32: color };
        d.cmd_clear_color_image(
            cmd,
            image,
            vk::ImageLayout::TRANSFER_DST_OPTIMAL,
            &clear,
            &[range],
        );
        let to_read = barrier(
            image,
            (
                vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
            ),
            (vk::AccessFlags::TRANSFER_WRITE, vk::AccessFlags::SHADER_READ),
        );
        d.cmd_pipeline_barrier(
            cmd,
            vk::PipelineStageFlags::TRANSFER,
            vk::PipelineStageFlags::FRAGMENT_SHADER,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &[to_read],
        );
    }
    view
}

#[test]
fn a_texture_destroyed_right_after_ffvk_draw_is_drawn_as_the_draw_named_it() {
    let plain = PlainDevice::new();
    let mut caller = Caller::new(&plain);
    let d = &plain.device;
    // One triangle over the whole viewport: positions and normals (create_info's layout).
    let floats: [f32; 18] = [
        -1., -1., 0., 0., 0., 1., 3., -1., 0., 0., 0., 1., -1., 3., 0., 0., 0., 1.,
    ];
    let bytes: Vec<u8> = floats.iter().flat_map(|f| f.to_ne_bytes()).collect();
    let (vertices, _) = caller.buffer(&bytes, vk::BufferUsageFlags::VERTEX_BUFFER);
    let (readback, readback_memory) = caller.buffer(
        &vec![0; (SIZE * SIZE * 4) as usize],
        vk::BufferUsageFlags::TRANSFER_DST,
    );
    let usage = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC;
    let (target, target_view) = caller.image(SIZE, SIZE, usage);
    let sampler = sampler(&mut caller);
    let info = FfvkRendererCreateInfo {
        depth_format: vk::Format::UNDEFINED,
        ..create_info(&plain)
    };
    let alloc = vk::CommandBufferAllocateInfo::default()
        .command_pool(caller.pool)
        .level(vk::CommandBufferLevel::PRIMARY)
        .command_buffer_count(1);
    let ctx = ffvkCreateContext();
    let mut r = std::ptr::null_mut();
    // SAFETY: every handle is plain's or the caller's, alive until the fence wait; the scope's
    // rules are kept (viewport and scissor set inside the rendering pass, nothing of the
    // caller's between ffvkBeginDraws and ffvkEndDraws); each FfvkTexture is destroyed once,
    // after the last ffvkDraw naming it, and its view and sampler outlive the submission.
    unsafe {
        assert_eq!(
            ffvkCreateRenderer(&info, &mut r),
            FfvkResult::FFVK_SUCCESS,
            "{}",
            message()
        );
        // Unlit, white, unit 0 on in GL_MODULATE at its current (0, 0): the texel's color.
        ffvkEnable(ctx, GL_TEXTURE_2D);
        let cmd = d.allocate_command_buffers(&alloc).unwrap()[0];
        d.begin_command_buffer(cmd, &vk::CommandBufferBeginInfo::default())
            .unwrap();
        let red_view = solid(&mut caller, cmd, RED);
        let green_view = solid(&mut caller, cmd, GREEN);
        let to_target = barrier(
            target,
            (
                vk::ImageLayout::UNDEFINED,
                vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
            ),
            (vk::AccessFlags::empty(), vk::AccessFlags::COLOR_ATTACHMENT_WRITE),
        );
        d.cmd_pipeline_barrier(
            cmd,
            vk::PipelineStageFlags::TOP_OF_PIPE,
            vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &[to_target],
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
            .store_op(vk::AttachmentStoreOp::STORE)];
        let rendering = vk::RenderingInfo::default()
            .render_area(area)
            .layer_count(1)
            .color_attachments(&attachments);
        d.cmd_begin_rendering(cmd, &rendering);
        let viewport = vk::Viewport {
            x: 0.0,
            y: 0.0,
            width: SIZE as f32,
            height: SIZE as f32,
            min_depth: 0.0,
            max_depth: 1.0,
        };
        d.cmd_set_viewport(cmd, 0, &[viewport]);
        d.cmd_set_scissor(cmd, 0, &[area]);

        let mut red = std::ptr::null_mut();
        let made = ffvkCreateTexture(r, red_view, sampler, &mut red);
        assert_eq!(made, FfvkResult::FFVK_SUCCESS, "{}", message());
        assert_eq!(ffvkBeginFrame(r, 0), FfvkResult::FFVK_SUCCESS, "{}", message());
        assert_eq!(
            ffvkBeginDraws(r, cmd, 0),
            FfvkResult::FFVK_SUCCESS,
            "{}",
            message()
        );
        let mut raster = std::mem::MaybeUninit::<FfvkRaster>::uninit();
        ffvkRasterDefaults(raster.as_mut_ptr());
        let draw = FfvkDrawInfo {
            texture: red,
            ..draw_info(&vertices, raster.assume_init())
        };
        assert_eq!(ffvkDraw(r, ctx, &draw), FfvkResult::FFVK_SUCCESS, "{}", message());
        // The draw is added: its texture may go. The memory it held is the allocator's again,
        // and the next binding of the same size most likely takes it.
        ffvkDestroyTexture(red);
        let mut green = std::ptr::null_mut();
        let made = ffvkCreateTexture(r, green_view, sampler, &mut green);
        assert_eq!(made, FfvkResult::FFVK_SUCCESS, "{}", message());
        assert_eq!(ffvkEndDraws(r), FfvkResult::FFVK_SUCCESS, "{}", message());
        d.cmd_end_rendering(cmd);

        let to_copy = barrier(
            target,
            (
                vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
            ),
            (
                vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
                vk::AccessFlags::TRANSFER_READ,
            ),
        );
        d.cmd_pipeline_barrier(
            cmd,
            vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            vk::PipelineStageFlags::TRANSFER,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &[to_copy],
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
        d.end_command_buffer(cmd).unwrap();
        let fence = d.create_fence(&vk::FenceCreateInfo::default(), None).unwrap();
        let cmds = [cmd];
        let submit = vk::SubmitInfo::default().command_buffers(&cmds);
        d.queue_submit(d.get_device_queue(0, 0), &[submit], fence)
            .unwrap();
        d.wait_for_fences(&[fence], true, u64::MAX).unwrap();
        d.destroy_fence(fence, None);
        ffvkDestroyTexture(green);
        ffvkDestroyRenderer(r);
        ffvkDestroyContext(ctx);
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
    drop(caller);
    for (i, p) in pixels.chunks(4).enumerate() {
        assert_eq!(
            p,
            [255, 0, 0, 255],
            "pixel {i}: the draw named the red texture, destroyed after ffvkDraw; green is the binding made after it"
        );
    }
}
