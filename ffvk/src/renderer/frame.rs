//! What a frame is made of and gives back: uploaded meshes ([`Mesh`]), draws ([`Draw`]),
//! frames ([`Frame`]), their measurements ([`FrameStats`], [`PipelineStats`]) and the pixels
//! read back ([`Pixels`]).

use ash::vk;
use glam::{Mat4, Vec4};

use super::texture::Texture;
use crate::draw::pipeline::{
    Blend, BlendColor, LineStipple, PolygonModes, PolygonOffset, PolygonStipple, RasterState, Stencil,
};
use crate::draw::record::Topology;
use crate::gl::state::{Face, FixedFunctionState};
use crate::gl::texture::MAX_TEXTURE_UNITS;
use crate::vk::Buffer;

#[cfg(doc)]
use super::Renderer;
#[cfg(doc)]
use crate::draw::lighting::Lighting;
#[cfg(doc)]
use crate::error::{Error, MeshError};
#[cfg(doc)]
use crate::mesh::MeshData;

/// A mesh uploaded to the renderer's device. Drawing it with another renderer is an error.
pub struct Mesh {
    pub(super) vertices: Buffer,
    pub(super) indices: Buffer,
    pub(super) index_count: u32,
    pub(super) vertex_count: u32,
    /// The second texture coordinates' buffer, when the mesh has them
    /// ([`MeshData::second_texcoords`]).
    pub(super) second: Option<Buffer>,
    /// `vertices` and `second` at offset 0, as a draw binds them (kept so draws can borrow
    /// them); the second is a null handle without `second`, never bound then.
    pub(super) vertex_bindings: [(vk::Buffer, u64); 2],
    /// How its indices make primitives.
    pub(super) topology: Topology,
    /// The least and greatest object-space position of its vertices (`None` without
    /// vertices): where the deferred path looks for a draw's pixels.
    pub(super) bounds: Option<(glam::Vec3, glam::Vec3)>,
}

impl Mesh {
    /// How the mesh's indices make primitives, as uploaded.
    pub fn topology(&self) -> Topology {
        self.topology
    }
    /// Indices uploaded.
    pub fn index_count(&self) -> u32 {
        self.index_count
    }
    /// Vertices uploaded.
    pub fn vertex_count(&self) -> u32 {
        self.vertex_count
    }
}

/// One draw: a mesh, its matrices (GL conventions) and the lighting state it captures.
#[derive(Clone, Copy)]
#[non_exhaustive]
pub struct Draw<'a> {
    /// Uploaded by the renderer that draws it, else [`MeshError::ForeignMesh`].
    pub mesh: &'a Mesh,
    /// Object to eye space. Eye space: viewer at the origin looking down -z, y up.
    pub modelview: Mat4,
    /// GL projection (clip z in [-w, w]); ffvk converts it to Vulkan's clip space.
    pub projection: Mat4,
    /// The lighting state, checked when the frame is drawn: a value GL would reject, a
    /// singular modelview with lighting on, or an enabled positional light with all three
    /// attenuations 0 fails the frame with [`Error::State`].
    pub state: FixedFunctionState,
    /// `GL_CULL_FACE` with `glCullFace(face)`: `None` (GL's default) draws both faces;
    /// `Some(Face::Back)` drops the triangles that are clockwise on screen.
    pub cull_face: Option<Face>,
    /// `glFrontFace`: `COUNTER_CLOCKWISE` (GL's `GL_CCW`, the default) or `CLOCKWISE`
    /// (`GL_CW`), in GL's window coordinates.
    pub front_face: vk::FrontFace,
    /// The texture bound to each unit's `GL_TEXTURE_2D` (uploaded by the same renderer),
    /// `GL_TEXTURE0` first: a unit's is sampled when its `enabled` is on and the texture is
    /// complete. `None`: GL's texture 0, which textures nothing.
    pub textures: [Option<&'a Texture>; MAX_TEXTURE_UNITS],
    /// The cube map bound to each unit's `GL_TEXTURE_CUBE_MAP`
    /// ([`Renderer::upload_cube_map`](super::Renderer::upload_cube_map)): sampled, before the
    /// unit's 2D texture, when its `cube_map` is on and the cube map is complete. `None`: GL's
    /// cube map 0, which textures nothing.
    pub cube_maps: [Option<&'a Texture>; MAX_TEXTURE_UNITS],
    /// The units 1-3 whose texture coordinates are the mesh's too, a bit each (bit i for unit
    /// i; as a GL program points `glClientActiveTexture(GL_TEXTUREi)`'s array at the same
    /// coordinates); the others take their current coordinates
    /// (`state.current_texcoords`, GL's `glMultiTexCoord`) or generate them. Unit 0's are
    /// always the mesh's. 0 by default.
    pub mesh_texcoords: u32,
    /// The units 1-3 whose texture coordinates are the mesh's second set
    /// ([`MeshData::second_texcoords`], glTF's `TEXCOORD_1`), a bit each (bit i for unit i);
    /// a unit named here and in [`Draw::mesh_texcoords`] reads the second set. A mesh uploaded
    /// without a second set fails the frame with [`MeshError::NoSecondTexcoords`]. 0 by
    /// default.
    pub second_texcoords: u32,
    /// How the mesh's indices make primitives: the mesh's own ([`MeshData::topology`]) unless
    /// [`Draw::with_topology`] says otherwise (see [`Topology`]).
    pub topology: Topology,
    /// `glPointSize` and `glLineWidth`, in pixels (1 and 1, GL's defaults; see
    /// [`RasterState::point_size`]).
    pub point_size: f32,
    /// `glLineWidth`, in pixels.
    pub line_width: f32,
    /// `GL_POLYGON_OFFSET_FILL` with `glPolygonOffset` (`None`: off, GL's default; see
    /// [`RasterState::polygon_offset`]).
    pub polygon_offset: Option<PolygonOffset>,
    /// `glColorMask` (R, G, B, A): all written by default.
    pub color_mask: [bool; 4],
    /// `GL_BLEND` with `glBlendFuncSeparate` and `glBlendEquationSeparate`: `None` (off) by
    /// default. Draws blend in the frame's order.
    pub blend: Option<Blend>,
    /// `glBlendColor`, each in [0, 1]; (0, 0, 0, 0) by default.
    pub blend_color: [f32; 4],
    /// `glPolygonMode`: both faces filled by default (see [`RasterState::polygon_mode`]).
    pub polygon_mode: PolygonModes,
    /// `GL_STENCIL_TEST` with its state: `None` (off) by default.
    pub stencil: Option<Stencil>,
    /// `GL_COLOR_LOGIC_OP` with `glLogicOp`: `None` (off) by default.
    pub logic_op: Option<vk::LogicOp>,
    /// `GL_LINE_STIPPLE` with `glLineStipple`: `None` (off) by default.
    pub line_stipple: Option<LineStipple>,
    /// `glDepthMask`: depth writes on (GL's default) or off; only while the frame tests depth.
    pub depth_write: bool,
    /// `GL_POLYGON_STIPPLE` with `glPolygonStipple(mask)`: `None` (off) by default; the mask
    /// as GL takes it ([`PolygonStipple::from_gl_mask`]), rows from the frame's bottom.
    pub polygon_stipple: Option<[u8; 128]>,
    /// `glDepthRange(near, far)`: (0, 1) by default; each clamped to [0, 1] as GL clamps it,
    /// near may exceed far. The viewport's depth: set between the draws where it changes.
    pub depth_range: [f32; 2],
}

impl<'a> Draw<'a> {
    /// A draw of `mesh` with both faces drawn (GL's default: culling off).
    pub fn new(mesh: &'a Mesh, modelview: Mat4, projection: Mat4, state: FixedFunctionState) -> Self {
        Draw {
            mesh,
            modelview,
            projection,
            state,
            cull_face: None,
            front_face: vk::FrontFace::COUNTER_CLOCKWISE,
            textures: [None; MAX_TEXTURE_UNITS],
            cube_maps: [None; MAX_TEXTURE_UNITS],
            mesh_texcoords: 0,
            second_texcoords: 0,
            topology: mesh.topology,
            point_size: 1.0,
            line_width: 1.0,
            polygon_offset: None,
            color_mask: [true; 4],
            blend: None,
            blend_color: [0.0; 4],
            polygon_mode: PolygonModes::FILL,
            stencil: None,
            logic_op: None,
            line_stipple: None,
            depth_range: [0.0, 1.0],
            depth_write: true,
            polygon_stipple: None,
        }
    }

    /// This draw with `GL_POLYGON_STIPPLE` on and `glPolygonStipple(mask)` (`None`: off).
    #[must_use]
    pub fn with_polygon_stipple(mut self, mask: Option<[u8; 128]>) -> Self {
        self.polygon_stipple = mask;
        self
    }

    /// This draw with `glDepthMask(on)`.
    #[must_use]
    pub fn with_depth_write(mut self, on: bool) -> Self {
        self.depth_write = on;
        self
    }

    /// This draw with `glDepthRange(near, far)`.
    #[must_use]
    pub fn with_depth_range(mut self, near: f32, far: f32) -> Self {
        self.depth_range = [near, far];
        self
    }

    /// The depth range as the viewport takes it: clamped to [0, 1], as GL clamps it.
    pub(super) fn clamped_depth_range(&self) -> [f32; 2] {
        self.depth_range.map(|d| d.clamp(0.0, 1.0))
    }

    /// This draw with `glPolygonMode` (both faces' modes).
    #[must_use]
    pub fn with_polygon_mode(mut self, modes: PolygonModes) -> Self {
        self.polygon_mode = modes;
        self
    }

    /// This draw with `GL_STENCIL_TEST` on and `stencil`'s state (`None`: off). A frame
    /// with such a draw has a stencil buffer, cleared to [`Frame::clear_stencil`].
    #[must_use]
    pub fn with_stencil(mut self, stencil: Option<Stencil>) -> Self {
        self.stencil = stencil;
        self
    }

    /// This draw with `GL_COLOR_LOGIC_OP` on and `glLogicOp(op)` (`None`: off).
    #[must_use]
    pub fn with_logic_op(mut self, op: Option<vk::LogicOp>) -> Self {
        self.logic_op = op;
        self
    }

    /// This draw with `GL_LINE_STIPPLE` on and `glLineStipple` (`None`: off).
    #[must_use]
    pub fn with_line_stipple(mut self, stipple: Option<LineStipple>) -> Self {
        self.line_stipple = stipple;
        self
    }

    /// This draw with `GL_BLEND` on and `blend`'s factors and equations (`None`: off).
    #[must_use]
    pub fn with_blend(mut self, blend: Option<Blend>) -> Self {
        self.blend = blend;
        self
    }

    /// This draw with `glBlendColor(r, g, b, a)`.
    #[must_use]
    pub fn with_blend_color(mut self, rgba: [f32; 4]) -> Self {
        self.blend_color = rgba;
        self
    }

    /// This draw with `glPolygonOffset(factor, units)` and `GL_POLYGON_OFFSET_FILL` on.
    #[must_use]
    pub fn with_polygon_offset(mut self, factor: f32, units: f32) -> Self {
        self.polygon_offset = Some(PolygonOffset::fill(factor, units));
        self
    }

    /// This draw with `glPolygonOffset` and the modes it is enabled for (`None`: all off).
    #[must_use]
    pub fn with_offset(mut self, offset: Option<PolygonOffset>) -> Self {
        self.polygon_offset = offset;
        self
    }

    /// This draw with `glColorMask(r, g, b, a)`.
    #[must_use]
    pub fn with_color_mask(mut self, mask: [bool; 4]) -> Self {
        self.color_mask = mask;
        self
    }

    /// This draw with `glPointSize(size)`.
    #[must_use]
    pub fn with_point_size(mut self, size: f32) -> Self {
        self.point_size = size;
        self
    }

    /// This draw with `glLineWidth(width)`.
    #[must_use]
    pub fn with_line_width(mut self, width: f32) -> Self {
        self.line_width = width;
        self
    }

    /// This draw with its mesh's indices read as `topology` (`GL_POINTS`, `GL_LINES`, …).
    #[must_use]
    pub fn with_topology(mut self, topology: Topology) -> Self {
        self.topology = topology;
        self
    }

    /// This draw with `glCullFace(face)` and `GL_CULL_FACE` on (`None`: off).
    #[must_use]
    pub fn with_cull_face(mut self, face: Option<Face>) -> Self {
        self.cull_face = face;
        self
    }

    /// This draw with `glFrontFace`: `CLOCKWISE` for `GL_CW`, `COUNTER_CLOCKWISE` for `GL_CCW`.
    #[must_use]
    pub fn with_front_face(mut self, winding: vk::FrontFace) -> Self {
        self.front_face = winding;
        self
    }

    /// This draw with `texture` bound to unit 0's `GL_TEXTURE_2D` (`None`: texture object 0).
    #[must_use]
    pub fn with_texture(mut self, texture: Option<&'a Texture>) -> Self {
        self.textures[0] = texture;
        self
    }

    /// This draw with the mesh's texture coordinates on units 1-3 too where `units` has their
    /// bit (bit i for unit i; bit 0 and bits past the units are ignored).
    #[must_use]
    pub fn with_mesh_texcoords(mut self, units: u32) -> Self {
        self.mesh_texcoords = units;
        self
    }

    /// This draw with the mesh's second texture coordinates on units 1-3 where `units` has
    /// their bit (see [`Draw::second_texcoords`]; bit 0 and bits past the units are ignored).
    #[must_use]
    pub fn with_second_texcoords(mut self, units: u32) -> Self {
        self.second_texcoords = units;
        self
    }

    /// This draw with each unit's texture, `GL_TEXTURE0` first.
    #[must_use]
    pub fn with_textures(mut self, textures: [Option<&'a Texture>; MAX_TEXTURE_UNITS]) -> Self {
        self.textures = textures;
        self
    }

    /// This draw with each unit's cube map, `GL_TEXTURE0` first.
    #[must_use]
    pub fn with_cube_maps(mut self, cube_maps: [Option<&'a Texture>; MAX_TEXTURE_UNITS]) -> Self {
        self.cube_maps = cube_maps;
        self
    }

    /// The units with a complete 2D texture bound, a bit each (GL's completeness, §3.8.10: an
    /// incomplete texture textures nothing).
    pub fn complete_units(&self) -> u32 {
        complete(&self.textures)
    }

    /// The units with a complete cube map bound, a bit each.
    pub fn complete_cube_maps(&self) -> u32 {
        complete(&self.cube_maps)
    }

    /// Whether this draw samples a texture: some unit enabled with a complete texture of the
    /// target it samples.
    pub fn textured(&self) -> bool {
        let (_, applied, _) = crate::gl::texture::units_applied(
            &self.state.texture_units,
            self.complete_units(),
            self.complete_cube_maps(),
        );
        applied != 0
    }

    /// The raster state of this draw in `frame`: GL's defaults, with the frame's depth test
    /// and the draw's culling.
    pub(super) fn raster(&self, frame: &Frame) -> RasterState {
        RasterState {
            depth_test: frame.depth_test,
            depth_write: self.depth_write,
            cull_mode: match self.cull_face {
                None => vk::CullModeFlags::NONE,
                Some(Face::Front) => vk::CullModeFlags::FRONT,
                Some(Face::Back) => vk::CullModeFlags::BACK,
                Some(Face::FrontAndBack) => vk::CullModeFlags::FRONT_AND_BACK,
            },
            front_face: self.front_face,
            polygon_offset: self.polygon_offset,
            polygon_mode: self.polygon_mode,
            stencil: self.stencil,
            logic_op: self.logic_op,
            line_stipple: self.line_stipple,
            polygon_stipple: self
                .polygon_stipple
                .map(|mask| PolygonStipple::from_gl_mask(&mask, frame.height)),
            blend: self.blend,
            blend_color: BlendColor(self.blend_color),
            color_mask: [
                vk::ColorComponentFlags::R,
                vk::ColorComponentFlags::G,
                vk::ColorComponentFlags::B,
                vk::ColorComponentFlags::A,
            ]
            .into_iter()
            .zip(self.color_mask)
            .filter(|(_, on)| *on)
            .fold(vk::ColorComponentFlags::empty(), |m, (c, _)| m | c),
            ..RasterState::default()
        }
        .with_point_size(self.point_size)
        .with_line_width(self.line_width)
    }
}

/// One image: its size, clear color, depth test and draws, in order.
#[derive(Clone)]
#[non_exhaustive]
pub struct Frame<'a> {
    /// Width in pixels, 1..=the device's `maxImageDimension2D` (else [`Error::InvalidSize`]).
    pub width: u32,
    /// Height in pixels, same range as `width`.
    pub height: u32,
    /// RGBA the image is cleared to before the draws; stored as 8-bit UNORM, so components
    /// are clamped to [0, 1]. [`Frame::new`] uses opaque black.
    pub clear_color: Vec4,
    /// GL_DEPTH_TEST with LESS against a depth buffer cleared to 1.
    pub depth_test: bool,
    /// Recorded in order; with `depth_test` off, later draws cover earlier ones.
    pub draws: Vec<Draw<'a>>,
    /// How the fragment mode's draws are lit: [`FragmentPath::Forward`] (the default) or,
    /// where the frame allows it, [`FragmentPath::Deferred`].
    pub fragment_path: FragmentPath,
    /// How the draws are recorded: as one run (the default), or one draw at a time as an
    /// embedder recording each GL draw as it comes would ([`Recording`]).
    pub recording: Recording,
    /// `glClearStencil`: what the stencil buffer is cleared to (0 by default), where a draw
    /// tests it ([`Frame::has_stencil`]). The buffer has 8 bits.
    pub clear_stencil: u32,
}

/// How a [`Frame`]'s draws are recorded into the command buffer. Both draw the same image; the
/// draw-by-draw form is there to measure what a caller of [`Lighting::draw`](crate::Lighting::draw)
/// pays (`ffvk bench`'s draws sweep).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Recording {
    /// [`Lighting::draw_run`](crate::Lighting::draw_run): the frame's draws staged together,
    /// consecutive draws of one geometry drawn as instances of one command.
    #[default]
    Run,
    /// [`Lighting::draw`](crate::Lighting::draw) per draw: each staged on its own (its state
    /// compared with the draw before's) and recorded as a command of its own, binding only
    /// what differs from what the draw before bound.
    DrawByDraw,
}

/// Where the fragment mode evaluates the equation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum FragmentPath {
    /// At every fragment of every draw, as the draw is rasterized: the reference path (the
    /// golden images are drawn with it).
    #[default]
    Forward,
    /// Once per pixel: a G-buffer pass, then a lighting pass with the same equation
    /// (`renderer/deferred.rs`): a full-screen triangle per lighting state (state block and
    /// projection) of the frame, each specialized for its state and scissored to its draws,
    /// up to [`MAX_DEFERRED_STATES`](crate::MAX_DEFERRED_STATES) states. A frame that cannot
    /// take it (a draw in another mode, blended, textured, fogged, alpha-tested or clipped,
    /// more states than that, no depth test) is drawn forward; [`FrameStats::deferred`] says
    /// which path a frame took.
    Deferred,
    /// Deferred where a fixed rule of the frame's vertices, pixels and lights and of the
    /// device's type says it is the faster path ([`FragmentPath::auto_picks_deferred`]),
    /// else forward. The rule's constants were measured once (`ffvk bench --sweep paths`) and
    /// are written in the code, so a frame's path never depends on timing; where the frame can
    /// take the deferred path, the two paths' images differ by 1/255 at most (the deferred
    /// path's G-buffer keeps the normal's direction in 16 bits a component).
    Auto,
}

impl FragmentPath {
    /// What [`FragmentPath::Auto`] takes for a frame the deferred path can draw: `true` for
    /// deferred. `cpu`: the device is a CPU (`VK_PHYSICAL_DEVICE_TYPE_CPU`, lavapipe);
    /// `vertices`: each draw's mesh vertex count (vertices uploaded, not index count), summed
    /// over the draws; `pixels`:
    /// the frame's width × height; `lights`: the enabled lights (in a frame of several
    /// lighting states, the fewest of any state).
    ///
    /// The constants come from `ffvk bench --sweep paths` on lavapipe (BENCHMARKS.md, "Which
    /// fragment path wins"). On a CPU the forward path shades every 4×4 block each triangle
    /// touches, the whole light loop each time, so it loses once triangles are small and
    /// lights many; the deferred path pays a G-buffer pass and a lighting pass per pixel. On
    /// a CPU it takes 4 or more lights at 0.008 or more vertices per pixel, or 8 at 0.002. On
    /// GPUs the forward path shades about once per pixel and the G-buffer's writes
    /// cost more than they save: forward always.
    pub fn auto_picks_deferred(cpu: bool, vertices: u64, pixels: u64, lights: usize) -> bool {
        let dense = |milli: u64| vertices.saturating_mul(1000) >= milli.saturating_mul(pixels);
        cpu && AUTO_DEFERRED
            .iter()
            .any(|&(fewest, milli)| lights >= fewest && dense(milli))
    }
}

/// [`FragmentPath::auto_picks_deferred`]'s rule on a CPU: the deferred path from this many
/// lights at this many thousandths of a vertex per pixel (or more of either). From two paths
/// runs after the lighting pass came to fetch the records as texels (BENCHMARKS.md, "Which
/// fragment path wins"), deferred ÷ forward: at 8 lights 0.41-0.87 from 0.002 vertices per
/// pixel (one 1.06), 1.05 at 0.001; at 4 lights 0.62-0.94 from 0.008 (one 1.07), 1.15-1.37
/// below; at 1 and 2 lights wins and losses of up to 15-28 % that changed places between the
/// runs. The rule agreed with the faster path (or within 5 % of it) at 69 of each run's 80
/// points.
const AUTO_DEFERRED: [(usize, u64); 2] = [(4, 8), (8, 2)];

impl<'a> Frame<'a> {
    /// An empty frame of `width` × `height` pixels, cleared to (0, 0, 0, 1), depth test on.
    /// The size is checked only when the frame is drawn.
    pub fn new(width: u32, height: u32) -> Self {
        Frame {
            width,
            height,
            clear_color: Vec4::new(0.0, 0.0, 0.0, 1.0),
            depth_test: true,
            draws: Vec::new(),
            fragment_path: FragmentPath::Forward,
            recording: Recording::Run,
            clear_stencil: 0,
        }
    }

    /// Whether a draw tests the stencil buffer: then the frame has one.
    pub fn has_stencil(&self) -> bool {
        self.draws.iter().any(|d| d.stencil.is_some())
    }
}

/// What one measured frame cost, from queries around its rendering pass (clears and draws;
/// not the readback copy).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct FrameStats {
    /// Device time between the timestamp written before the rendering pass and the one
    /// written after it, in nanoseconds; `None` when the queue has no timestamps. A deferred
    /// frame's is both its passes.
    pub gpu_ns: Option<f64>,
    /// A deferred frame's G-buffer pass alone (from the timestamp before it to one written
    /// after it), in nanoseconds; the rest of `gpu_ns` is its lighting pass. `None` for
    /// forward frames and without timestamps.
    pub gbuffer_ns: Option<f64>,
    /// Host time from `vkQueueSubmit` to the fence, in nanoseconds (with the readback copy
    /// when the frame has one).
    pub wall_ns: f64,
    /// The pipeline statistics of the rendering pass; `None` when the device lacks
    /// `pipelineStatisticsQuery`.
    pub pipeline: Option<PipelineStats>,
    /// Host time spent recording the frame's draws ([`Lighting::draw`] for each: state packed
    /// and written, pipeline found, binds and draw recorded), in nanoseconds. Pipelines are
    /// made before recording starts, so this is the warm cost.
    pub record_ns: f64,
    /// Whether the frame took the deferred path ([`FragmentPath::Deferred`]); its pipeline
    /// statistics are then the lighting pass's alone, not the G-buffer pass's.
    pub deferred: bool,
    /// A deferred frame measured with statistics: how many pixels its lighting pass
    /// evaluated the equation at, counted by the pass itself (an atomic add per lit pixel;
    /// lavapipe's statistics count whole 4×4 blocks, background included).
    pub evaluations: Option<u64>,
}

/// The counters of one pipeline-statistics query, summed over every draw of the pass.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub struct PipelineStats {
    /// Vertices the input assembler read (`INPUT_ASSEMBLY_VERTICES`).
    pub input_assembly_vertices: u64,
    /// Triangles it assembled (`INPUT_ASSEMBLY_PRIMITIVES`).
    pub input_assembly_primitives: u64,
    /// Vertex shader runs (`VERTEX_SHADER_INVOCATIONS`); may be fewer than the vertices read
    /// where the implementation reuses results for repeated indices.
    pub vertex_shader_invocations: u64,
    /// Primitives that reached the clipping stage (`CLIPPING_INVOCATIONS`).
    pub clipping_invocations: u64,
    /// Primitives that left it (`CLIPPING_PRIMITIVES`).
    pub clipping_primitives: u64,
    /// Fragment shader runs (`FRAGMENT_SHADER_INVOCATIONS`): where per-fragment lighting
    /// spends its time.
    pub fragment_shader_invocations: u64,
}

/// An image read back from the renderer: RGBA8, rows top to bottom, no padding.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Pixels {
    // Private: `rgba` holds exactly width × height × 4 bytes (read_image makes it so).
    pub(super) width: u32,
    pub(super) height: u32,
    pub(super) rgba: Vec<u8>,
}

impl Pixels {
    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// `width * height * 4` bytes, R, G, B, A per pixel, row 0 at the top of the view.
    pub fn rgba(&self) -> &[u8] {
        &self.rgba
    }

    /// The bytes of [`rgba`](Pixels::rgba), taken.
    pub fn into_rgba(self) -> Vec<u8> {
        self.rgba
    }

    /// The RGBA value at (x, y), from the top-left corner; `None` outside the image.
    pub fn pixel(&self, x: u32, y: u32) -> Option<[u8; 4]> {
        if x >= self.width || y >= self.height {
            return None;
        }
        let at = (y as usize * self.width as usize + x as usize) * 4;
        self.rgba.get(at..at + 4).map(|p| [p[0], p[1], p[2], p[3]])
    }
}

#[cfg(feature = "images")]
impl Pixels {
    /// The same pixels as an `image` crate buffer (feature `images`).
    #[allow(
        clippy::expect_used,
        reason = "Pixels' fields are private and read_image makes exactly width * height * 4 bytes"
    )]
    pub fn into_rgba_image(self) -> image::RgbaImage {
        image::RgbaImage::from_raw(self.width, self.height, self.rgba)
            .expect("Pixels holds width * height * 4 bytes")
    }
}

#[cfg(feature = "images")]
impl From<Pixels> for image::RgbaImage {
    fn from(p: Pixels) -> Self {
        p.into_rgba_image()
    }
}

/// The units of `textures` with a complete texture, a bit each.
fn complete(textures: &[Option<&Texture>; MAX_TEXTURE_UNITS]) -> u32 {
    (0..MAX_TEXTURE_UNITS)
        .filter(|&i| textures[i].is_some_and(Texture::is_complete))
        .fold(0, |mask, i| mask | 1 << i)
}
