//! The frame's attachments as both passes record them (the forward pass in `record.rs`, the
//! deferred path's two in `deferred.rs`): the barriers into attachment layouts, the clears,
//! the render area and the viewport.

use ash::vk;

use super::{subresource, Frame, Targets};

/// The color and depth images' barrier into attachment layouts, after the last frame's
/// readback copy or rendering (a measured frame repeated in one submission).
pub(super) fn attachment_barriers(targets: &Targets) -> [vk::ImageMemoryBarrier2<'static>; 2] {
    let tests = vk::PipelineStageFlags2::EARLY_FRAGMENT_TESTS | vk::PipelineStageFlags2::LATE_FRAGMENT_TESTS;
    [
        vk::ImageMemoryBarrier2::default()
            .src_stage_mask(vk::PipelineStageFlags2::COPY | vk::PipelineStageFlags2::COLOR_ATTACHMENT_OUTPUT)
            .src_access_mask(vk::AccessFlags2::TRANSFER_READ | vk::AccessFlags2::COLOR_ATTACHMENT_WRITE)
            .dst_stage_mask(vk::PipelineStageFlags2::COLOR_ATTACHMENT_OUTPUT)
            .dst_access_mask(vk::AccessFlags2::COLOR_ATTACHMENT_WRITE)
            .old_layout(vk::ImageLayout::UNDEFINED)
            .new_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
            .image(targets.color.raw())
            .subresource_range(subresource(vk::ImageAspectFlags::COLOR)),
        // Early tests write depth too (the clear among them).
        vk::ImageMemoryBarrier2::default()
            .src_stage_mask(tests)
            .src_access_mask(vk::AccessFlags2::DEPTH_STENCIL_ATTACHMENT_WRITE)
            .dst_stage_mask(tests)
            .dst_access_mask(
                vk::AccessFlags2::DEPTH_STENCIL_ATTACHMENT_READ
                    | vk::AccessFlags2::DEPTH_STENCIL_ATTACHMENT_WRITE,
            )
            .old_layout(vk::ImageLayout::UNDEFINED)
            .new_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
            .image(targets.depth.raw())
            .subresource_range(subresource(depth_aspects(targets))),
    ]
}

/// The depth image's aspects: depth, and stencil where it has one.
pub(super) fn depth_aspects(targets: &Targets) -> vk::ImageAspectFlags {
    match targets.stencil {
        false => vk::ImageAspectFlags::DEPTH,
        true => vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL,
    }
}

/// The depth image as the frame's stencil attachment (the same view), cleared to the
/// frame's `glClearStencil`, where it has stencil.
pub(super) fn stencil_attachment<'a>(
    targets: &Targets,
    frame: &Frame,
) -> Option<vk::RenderingAttachmentInfo<'a>> {
    targets.stencil.then(|| {
        vk::RenderingAttachmentInfo::default()
            .image_view(targets.depth.view())
            .image_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
            .load_op(vk::AttachmentLoadOp::CLEAR)
            .store_op(vk::AttachmentStoreOp::DONT_CARE)
            .clear_value(vk::ClearValue {
                depth_stencil: vk::ClearDepthStencilValue {
                    depth: 1.0,
                    stencil: frame.clear_stencil,
                },
            })
    })
}

/// The color image as the frame's attachment, cleared to its clear color.
pub(super) fn color_attachment<'a>(targets: &Targets, frame: &Frame) -> vk::RenderingAttachmentInfo<'a> {
    let c = frame.clear_color;
    vk::RenderingAttachmentInfo::default()
        .image_view(targets.color.view())
        .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)
        .clear_value(vk::ClearValue {
            color: vk::ClearColorValue {
                float32: [c.x, c.y, c.z, c.w],
            },
        })
}

/// The depth image as an attachment cleared to 1, kept after the pass or not.
pub(super) fn depth_attachment<'a>(
    targets: &Targets,
    store: vk::AttachmentStoreOp,
) -> vk::RenderingAttachmentInfo<'a> {
    vk::RenderingAttachmentInfo::default()
        .image_view(targets.depth.view())
        .image_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(store)
        .clear_value(vk::ClearValue {
            depth_stencil: vk::ClearDepthStencilValue {
                depth: 1.0,
                stencil: 0,
            },
        })
}

/// The whole target as render area and viewport.
pub(super) fn area_and_viewport(extent: vk::Extent2D) -> (vk::Rect2D, vk::Viewport) {
    let area = vk::Rect2D {
        offset: vk::Offset2D { x: 0, y: 0 },
        extent,
    };
    let viewport = vk::Viewport {
        x: 0.0,
        y: 0.0,
        width: extent.width as f32,
        height: extent.height as f32,
        min_depth: 0.0,
        max_depth: 1.0,
    };
    (area, viewport)
}
