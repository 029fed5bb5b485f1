//! The lighting states of a frame on the deferred path (`deferred.rs`): which draws the path
//! can draw, which state each is under (a lighting pass each), and the window rectangle each
//! state's pass is scissored to.

use ash::vk;

use super::frame::{Draw, FragmentPath, Frame};
use crate::draw::pipeline::Specialize;
use crate::gl::state::LightingMode;
use crate::gpu::layout::{SpecKey, StateKey, VK_FROM_GL_CLIP};

/// The most lighting states a deferred frame's draws may be under (a lighting pass each); a
/// frame of more is drawn forward.
pub const MAX_DEFERRED_STATES: usize = 64;

/// The lighting states of a frame the deferred path draws.
pub(super) struct States {
    /// Per draw, its state's index.
    of_draw: Vec<u32>,
    /// Per state: the lighting pass's specialization key and the state's first draw.
    first: Vec<(SpecKey, usize)>,
}

impl States {
    /// How many states the frame's draws are under.
    pub(super) fn len(&self) -> usize {
        self.first.len()
    }

    /// Per draw, its state's index.
    pub(super) fn of_draw(&self) -> &[u32] {
        &self.of_draw
    }

    /// Per state: the lighting pass's specialization key and the state's first draw.
    pub(super) fn first(&self) -> &[(SpecKey, usize)] {
        &self.first
    }

    /// Per state, the scissor of its lighting pass in `extent`: the union of its draws'
    /// window rectangles ([`window_bounds`]); `None` where they cover no pixel of it. One
    /// pass over `frame`'s draws.
    pub(super) fn scissors(&self, frame: &Frame, extent: vk::Extent2D) -> Vec<Option<vk::Rect2D>> {
        let none = [f32::INFINITY, f32::INFINITY, f32::NEG_INFINITY, f32::NEG_INFINITY];
        let mut rects = vec![none; self.first.len()];
        for (d, &s) in frame.draws.iter().zip(&self.of_draw) {
            if let (Some(b), Some(r)) = (window_bounds(d, extent), rects.get_mut(s as usize)) {
                *r = [r[0].min(b[0]), r[1].min(b[1]), r[2].max(b[2]), r[3].max(b[3])];
            }
        }
        rects.into_iter().map(|r| pixel_rect(r, extent)).collect()
    }
}

/// Whether `m` maps w = 1 to w = 1 (the last row is (0, 0, 0, 1)).
fn affine(m: &glam::Mat4) -> bool {
    m.row(3) == glam::Vec4::W
}

/// Whether `d` can take the deferred path: the passes give the forward path's image for it.
fn deferrable(d: &Draw, frame: &Frame) -> bool {
    let raster = d.raster(frame);
    d.state.mode == LightingMode::Fragment
        && raster.blend.is_none()
        // The passes write every channel: a masked draw stays forward.
        && raster.color_mask == ash::vk::ColorComponentFlags::RGBA
        // So do the stencil test, logic ops, outlines, points and stipples.
        && raster.only_fills_and_blends()
        && d.clamped_depth_range() == [0.0, 1.0]
        && d.depth_write
        && !d.textured()
        // Fog, the alpha test and an unlit color sum are forward-only stages.
        && !d.state.fragment.fog.enabled
        && d.state.clip.mask() == 0
        && d.state.fragment.alpha_test.effective_func() == crate::gl::state::CompareFunc::Always
        && (!d.state.fragment.color_sum || d.state.lighting)
}

/// The frame's lighting states, when `frame` can take the deferred path: each state's
/// specialization key is the one its draws' forward pipelines would use.
/// `cpu`: the device is a CPU ([`FragmentPath::Auto`]'s rule).
pub(super) fn eligible(frame: &Frame, specialize: Specialize, cpu: bool) -> Option<States> {
    // The lighting pass finds the drawn pixels by their depth: frames without a depth test
    // stay forward.
    if frame.fragment_path == FragmentPath::Forward || !frame.depth_test || frame.draws.is_empty() {
        return None;
    }
    // The states by key, each draw compared with the state of the draw before first.
    let mut keys: Vec<(StateKey, bool)> = Vec::new();
    let mut states = States {
        of_draw: Vec::with_capacity(frame.draws.len()),
        first: Vec::new(),
    };
    for (i, d) in frame.draws.iter().enumerate() {
        if !deferrable(d, frame) {
            return None;
        }
        let affine = affine(&d.modelview);
        let same = |(k, a): &(StateKey, bool)| *a == affine && k.matches(&d.state, d.projection);
        let last = states.of_draw.last().copied();
        let found = match last.filter(|&s| same(&keys[s as usize])) {
            Some(s) => Some(s),
            None => keys.iter().position(same).map(|s| s as u32),
        };
        let state = match found {
            Some(s) => s,
            None => {
                if keys.len() == MAX_DEFERRED_STATES {
                    return None;
                }
                keys.push((StateKey::new(&d.state, d.projection), affine));
                let key = match specialize {
                    Specialize::Never => SpecKey::UBER,
                    _ => SpecKey::for_state(&d.state).with_finite_vertices(affine),
                };
                states.first.push((key, i));
                (keys.len() - 1) as u32
            }
        };
        states.of_draw.push(state);
    }
    if frame.fragment_path == FragmentPath::Auto {
        let vertices = frame.draws.iter().map(|d| u64::from(d.mesh.vertex_count)).sum();
        let pixels = u64::from(frame.width) * u64::from(frame.height);
        // The fewest lights of any state: the deferred path wins with many lights.
        let lights = states
            .first
            .iter()
            .map(|&(_, i)| {
                let state = &frame.draws[i].state;
                if state.lighting {
                    state.enabled_lights().count()
                } else {
                    0
                }
            })
            .min()
            .unwrap_or(0);
        if !FragmentPath::auto_picks_deferred(cpu, vertices, pixels, lights) {
            return None;
        }
    }
    Some(states)
}

/// The window rectangle, in pixels of `extent` ([x0, y0, x1, y1]), that holds every pixel `d`
/// can cover (`None`: none): its mesh's bounds through its matrices, widened by a pixel and by half its
/// point size or line width; the whole extent where a corner of the bounds lies on or behind
/// the eye's plane (w ≤ 0 there: the projection of the box is not the box of the projected
/// corners) or a value is not finite.
fn window_bounds(d: &Draw, extent: vk::Extent2D) -> Option<[f32; 4]> {
    let (w, h) = (extent.width as f32, extent.height as f32);
    let whole = Some([0.0, 0.0, w, h]);
    // A mesh without vertices draws nothing.
    let (lo, hi) = d.mesh.bounds?;
    let to_clip = VK_FROM_GL_CLIP * d.projection * d.modelview;
    let mut out = [f32::INFINITY, f32::INFINITY, f32::NEG_INFINITY, f32::NEG_INFINITY];
    for corner in 0..8 {
        let p = glam::Vec3::select(
            glam::BVec3::new(corner & 1 != 0, corner & 2 != 0, corner & 4 != 0),
            hi,
            lo,
        );
        let clip = to_clip * p.extend(1.0);
        if !clip.is_finite() || clip.w <= f32::EPSILON {
            return whole;
        }
        let x = (clip.x / clip.w + 1.0) * 0.5 * w;
        let y = (clip.y / clip.w + 1.0) * 0.5 * h;
        out = [out[0].min(x), out[1].min(y), out[2].max(x), out[3].max(y)];
    }
    let margin = 1.0 + 0.5 * d.point_size.max(d.line_width);
    if !margin.is_finite() {
        return whole;
    }
    Some([out[0] - margin, out[1] - margin, out[2] + margin, out[3] + margin])
}

/// The pixels of `extent` inside the window rectangle `r` ([x0, y0, x1, y1]) widened to whole
/// pixels; `None` where there are none.
fn pixel_rect(r: [f32; 4], extent: vk::Extent2D) -> Option<vk::Rect2D> {
    let clamp = |v: f32, most: u32| v.clamp(0.0, most as f32) as u32;
    let (x0, y0) = (
        clamp(r[0].floor(), extent.width),
        clamp(r[1].floor(), extent.height),
    );
    let (x1, y1) = (
        clamp(r[2].ceil(), extent.width),
        clamp(r[3].ceil(), extent.height),
    );
    (x1 > x0 && y1 > y0).then(|| vk::Rect2D {
        offset: vk::Offset2D {
            x: x0 as i32,
            y: y0 as i32,
        },
        extent: vk::Extent2D {
            width: x1 - x0,
            height: y1 - y0,
        },
    })
}
