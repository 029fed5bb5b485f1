//! Recording draws: what one lit draw binds and issues inside a rendering pass.

use ash::vk;

use super::raster::DynamicRaster;

/// How a draw's vertices make primitives: GL's primitive modes that Vulkan draws as they are.
/// GL's `GL_QUADS`, `GL_QUAD_STRIP`, `GL_POLYGON` and `GL_LINE_LOOP` become these through
/// [`gl_primitives`](crate::draw::gl_primitives), which keeps GL's provoking vertex.
///
/// Flat shading takes GL's provoking vertex (GL 2.1 §2.14.7, table 2.12), the last of each
/// primitive (pipelines use `VK_EXT_provoking_vertex`'s last-vertex mode): a line's second
/// vertex, a strip's or a fan's triangle's third (for a fan, vertex i + 2). Points and lines
/// are lit with the front material and take the front color, two-sided lighting or not:
/// facing is a polygon's property (Vulkan counts points and lines as front-facing).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Topology {
    /// `GL_POINTS`: one point per vertex, one pixel wide.
    PointList,
    /// `GL_LINES`: a segment per two vertices, one pixel wide.
    LineList,
    /// `GL_LINE_STRIP`: a segment from each vertex to the next.
    LineStrip,
    /// `GL_TRIANGLES`: a triangle per three vertices.
    #[default]
    TriangleList,
    /// `GL_TRIANGLE_STRIP`.
    TriangleStrip,
    /// `GL_TRIANGLE_FAN`.
    TriangleFan,
    /// GL's polygons with their edge flags (GL 2.1 §2.6.2; GL 3.2's `GL_TRIANGLES_ADJACENCY`
    /// as ffvk reads it): triangles, each given as six
    /// indices (c0, a0, c1, a1, c2, a2), a Vulkan triangle list with adjacency, where a_e
    /// repeats c_e when edge e (from corner e to corner e + 1) is a boundary edge and is
    /// c_(e+1) when it is not. Filled, they draw as [`Topology::TriangleList`] would; in
    /// `GL_LINE` or `GL_POINT` polygon mode, only the boundary edges (or the vertices that start
    /// one) are drawn, as GL draws them: a quad without its diagonal, a polygon without its fan.
    /// [`gl_primitives::edge_flagged`](crate::draw::gl_primitives::edge_flagged) and its
    /// siblings make the indices. Needs the device's `geometryShader`.
    EdgeFlaggedTriangles,
}

impl Topology {
    /// The Vulkan topology.
    pub fn vk(self) -> vk::PrimitiveTopology {
        match self {
            Topology::PointList => vk::PrimitiveTopology::POINT_LIST,
            Topology::LineList => vk::PrimitiveTopology::LINE_LIST,
            Topology::LineStrip => vk::PrimitiveTopology::LINE_STRIP,
            Topology::TriangleList => vk::PrimitiveTopology::TRIANGLE_LIST,
            Topology::TriangleStrip => vk::PrimitiveTopology::TRIANGLE_STRIP,
            Topology::TriangleFan => vk::PrimitiveTopology::TRIANGLE_FAN,
            Topology::EdgeFlaggedTriangles => vk::PrimitiveTopology::TRIANGLE_LIST_WITH_ADJACENCY,
        }
    }

    /// GL's name of the mode.
    pub fn gl_name(self) -> &'static str {
        match self {
            Topology::PointList => "GL_POINTS",
            Topology::LineList => "GL_LINES",
            Topology::LineStrip => "GL_LINE_STRIP",
            Topology::TriangleList => "GL_TRIANGLES",
            Topology::TriangleStrip => "GL_TRIANGLE_STRIP",
            Topology::TriangleFan => "GL_TRIANGLE_FAN",
            Topology::EdgeFlaggedTriangles => "GL_TRIANGLES_ADJACENCY",
        }
    }

    /// A list, strip or fan of triangles: filled polygons (what `GL_POLYGON_OFFSET_FILL`
    /// offsets).
    pub fn is_triangles(self) -> bool {
        matches!(
            self,
            Topology::TriangleList
                | Topology::TriangleStrip
                | Topology::TriangleFan
                | Topology::EdgeFlaggedTriangles
        )
    }

    /// A list or strip of lines.
    pub fn is_lines(self) -> bool {
        matches!(self, Topology::LineList | Topology::LineStrip)
    }

    /// A strip or a fan: the topologies primitive restart can cut (Vulkan allows it on lists
    /// only with a feature ffvk does not ask for).
    pub fn restartable(self) -> bool {
        matches!(
            self,
            Topology::LineStrip | Topology::TriangleStrip | Topology::TriangleFan
        )
    }
}

/// Which vertices a draw reads and how they make primitives: GL's `glDrawElements` or
/// `glDrawArrays` (`GL_TRIANGLES` unless [`Geometry::with_topology`] says otherwise).
///
/// ```
/// use ffvk::ash::vk;
/// use ffvk::Geometry;
///
/// // glDrawElementsBaseVertex(GL_TRIANGLES, 36, GL_UNSIGNED_SHORT, (void*)12, 100)
/// let index_buffer = vk::Buffer::null(); // the caller's
/// let cube = Geometry::indexed(index_buffer, vk::IndexType::UINT16, 36)
///     .with_first(6)
///     .with_vertex_offset(100);
/// assert!(matches!(
///     cube,
///     Geometry::Indexed { first_index: 6, index_count: 36, vertex_offset: 100, .. }
/// ));
/// // glDrawArrays(GL_TRIANGLES, 3, 6)
/// let two = Geometry::vertices(6).with_first(3);
/// assert!(matches!(two, Geometry::Vertices { first_vertex: 3, vertex_count: 6, .. }));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Geometry {
    /// Indexed vertices (`vkCmdDrawIndexed`): made by [`Geometry::indexed`].
    #[non_exhaustive]
    Indexed {
        /// The index buffer.
        buffer: vk::Buffer,
        /// Byte offset of index 0 in it.
        offset: u64,
        /// `UINT16` or `UINT32`.
        index_type: vk::IndexType,
        /// The first index read.
        first_index: u32,
        /// How many indices.
        index_count: u32,
        /// Added to every index before the vertex is fetched.
        vertex_offset: i32,
        /// How the vertices make primitives.
        topology: Topology,
        /// Primitive restart: the index of all ones (0xFFFF, 0xFFFFFFFF) starts a new strip
        /// or fan (`GL_PRIMITIVE_RESTART` with GL 4.3's fixed index).
        primitive_restart: bool,
    },
    /// Consecutive vertices (`vkCmdDraw`): made by [`Geometry::vertices`].
    #[non_exhaustive]
    Vertices {
        /// The first vertex.
        first_vertex: u32,
        /// How many vertices.
        vertex_count: u32,
        /// How the vertices make primitives.
        topology: Topology,
    },
}

impl Geometry {
    /// `index_count` indices of `index_type` from the start of `buffer`, each fetching that
    /// vertex of the bound vertex buffers: `glDrawElements(GL_TRIANGLES, index_count, type, 0)`.
    /// The `with_*` methods set the rest.
    pub fn indexed(buffer: vk::Buffer, index_type: vk::IndexType, index_count: u32) -> Self {
        Geometry::Indexed {
            buffer,
            offset: 0,
            index_type,
            first_index: 0,
            index_count,
            vertex_offset: 0,
            topology: Topology::TriangleList,
            primitive_restart: false,
        }
    }

    /// `vertex_count` consecutive vertices from the first: `glDrawArrays(GL_TRIANGLES, 0,
    /// vertex_count)`.
    pub fn vertices(vertex_count: u32) -> Self {
        Geometry::Vertices {
            first_vertex: 0,
            vertex_count,
            topology: Topology::TriangleList,
        }
    }

    /// Makes primitives of `mode` from the vertices (`GL_TRIANGLES` by default).
    #[must_use]
    pub fn with_topology(mut self, mode: Topology) -> Self {
        match &mut self {
            Geometry::Indexed { topology, .. } | Geometry::Vertices { topology, .. } => *topology = mode,
        }
        self
    }

    /// Indexed strips and fans: the index of all ones starts a new primitive (no effect on
    /// `vertices`; a list with restart on is refused when drawn).
    #[must_use]
    pub fn with_primitive_restart(mut self, on: bool) -> Self {
        if let Geometry::Indexed {
            primitive_restart, ..
        } = &mut self
        {
            *primitive_restart = on;
        }
        self
    }

    /// Starts at index `first` (indexed) or vertex `first` (`glDrawArrays`' `first`).
    #[must_use]
    pub fn with_first(mut self, first: u32) -> Self {
        match &mut self {
            Geometry::Indexed { first_index, .. } => *first_index = first,
            Geometry::Vertices { first_vertex, .. } => *first_vertex = first,
        }
        self
    }

    /// Indexed: index 0 lies `bytes` into the index buffer (no effect on `vertices`).
    #[must_use]
    pub fn with_buffer_offset(mut self, bytes: u64) -> Self {
        if let Geometry::Indexed { offset, .. } = &mut self {
            *offset = bytes;
        }
        self
    }

    /// Refuses what Vulkan would not draw as given (the draw checks it before anything is
    /// recorded): an index type other than `UINT16` or `UINT32`, an index buffer offset that
    /// is not a multiple of the index size, and a first index or vertex
    /// plus the count past 2^32.
    pub fn validate(&self) -> crate::error::Result<()> {
        let error = |field: &str, value: String, expected| {
            crate::error::LightingError::Geometry {
                field: field.to_owned(),
                value,
                expected,
            }
            .into()
        };
        let (first, count) = match *self {
            Geometry::Indexed {
                offset,
                index_type,
                first_index,
                index_count,
                ..
            } => {
                let size = match index_type {
                    vk::IndexType::UINT16 => 2,
                    vk::IndexType::UINT32 => 4,
                    other => {
                        return Err(error(
                            "index type",
                            other.as_raw().to_string(),
                            "VK_INDEX_TYPE_UINT16 or VK_INDEX_TYPE_UINT32",
                        ))
                    }
                };
                if offset % size != 0 {
                    return Err(error(
                        "index offset",
                        offset.to_string(),
                        "a multiple of the index size (2 bytes for UINT16, 4 for UINT32)",
                    ));
                }
                // Where the last index lies, in bytes: past 2^64 it wraps.
                let end = (u64::from(first_index) + u64::from(index_count))
                    .checked_mul(size)
                    .and_then(|bytes| bytes.checked_add(offset));
                if end.is_none() {
                    return Err(error(
                        "index offset + (first + count) × index size",
                        format!("{offset} + ({first_index} + {index_count}) × {size}"),
                        "at most 2^64 - 1 bytes",
                    ));
                }
                (first_index, index_count)
            }
            Geometry::Vertices {
                first_vertex,
                vertex_count,
                ..
            } => (first_vertex, vertex_count),
        };
        if first.checked_add(count).is_none() {
            return Err(error(
                "first + count",
                format!("{first} + {count}"),
                "at most 4294967295 (2^32 - 1)",
            ));
        }
        if self.assembly().0 == Topology::EdgeFlaggedTriangles && (count % 6 != 0 || first % 6 != 0) {
            return Err(error(
                "first, count",
                format!("{first}, {count}"),
                "multiples of 6 for GL_TRIANGLES_ADJACENCY (GL's polygons with their edge flags: six \
                 indices a triangle, as gl_primitives' _edge_flagged lists and ffvkEdgeFlaggedIndices \
                 make them)",
            ));
        }
        Ok(())
    }

    /// Indexed: `base` is added to every index before its vertex is fetched
    /// (`glDrawElementsBaseVertex`; no effect on `vertices`).
    #[must_use]
    pub fn with_vertex_offset(mut self, base: i32) -> Self {
        if let Geometry::Indexed { vertex_offset, .. } = &mut self {
            *vertex_offset = base;
        }
        self
    }
}

impl Geometry {
    /// How many vertices the draw fetches: its indices, or its vertices.
    pub(crate) fn fetched(&self) -> u32 {
        match *self {
            Geometry::Indexed { index_count, .. } => index_count,
            Geometry::Vertices { vertex_count, .. } => vertex_count,
        }
    }

    /// How the vertices make primitives, and whether primitive restart is on.
    pub fn assembly(&self) -> (Topology, bool) {
        match *self {
            Geometry::Indexed {
                topology,
                primitive_restart,
                ..
            } => (topology, primitive_restart),
            Geometry::Vertices { topology, .. } => (topology, false),
        }
    }
}

/// Everything one draw binds.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Bound<'a> {
    /// The pipeline for the draw's mode, state and raster state, and the raster state it
    /// takes as dynamic state.
    pub pipeline: (vk::Pipeline, DynamicRaster),
    /// The pipeline of a second pass over the same geometry, with its dynamic state: the back
    /// faces, where `glPolygonMode` gives them another mode than the front's
    /// ([`RasterState::face_passes`](crate::RasterState::face_passes)).
    pub second_pipeline: Option<(vk::Pipeline, DynamicRaster)>,
    /// The pipeline layout it was created with.
    pub layout: vk::PipelineLayout,
    /// The index of the state block's set in that layout.
    pub set_index: u32,
    /// The set (binding 0: the state block, `UNIFORM_BUFFER_DYNAMIC`).
    pub set: vk::DescriptorSet,
    /// Offset of the draw's state block, a multiple of `minUniformBufferOffsetAlignment`.
    pub uniform_offset: u32,
    /// The texture's set (binding 0: a combined image sampler), bound at `set_index + 1`,
    /// for a textured draw.
    pub texture_set: Option<vk::DescriptorSet>,
    /// The pipeline's vertex binding numbers (the caller's; the record's is `record_binding`).
    pub bindings: &'a [vk::VertexInputBindingDescription],
    /// One (buffer, byte offset) per entry of `bindings`.
    pub vertex_buffers: &'a [(vk::Buffer, u64)],
    /// The binding of the per-draw records.
    pub record_binding: u32,
    /// The buffer holding the draw's record, bound at offset 0.
    pub record_buffer: vk::Buffer,
    /// The index of the draw's record in it: the draw's `firstInstance`.
    pub first_record: u32,
    /// How many draws of the same geometry this one command draws, their records consecutive
    /// from `first_record`: instances of one draw.
    pub draws: u32,
    /// For a pipeline whose fragment stage reads the record as a uniform block (the fragment
    /// mode): the record chunk's set, bound at `set_index + 2`, and the record's offset in it.
    pub record_block: Option<(vk::DescriptorSet, u32)>,
}

/// What a run of draws last bound: a draw in the same run binds only what differs, since no
/// command of the caller's comes between them ([`Lighting::draw_run`]).
///
/// [`Lighting::draw_run`]: crate::Lighting::draw_run
#[derive(Debug, Default)]
pub(crate) struct RunState {
    pipeline: Option<vk::Pipeline>,
    /// The dynamic raster state set (all of it, or none yet).
    dynamic: Option<DynamicRaster>,
    state_block: Option<(vk::DescriptorSet, u32)>,
    record_block: Option<(vk::DescriptorSet, u32)>,
    texture_set: Option<vk::DescriptorSet>,
    vertex_buffers: Vec<(u32, vk::Buffer, u64)>,
    index_buffer: Option<(vk::Buffer, u64, vk::IndexType)>,
}

/// Binds `set` at `index` of `bound`'s pipeline layout, with its dynamic offsets.
///
/// # Safety
///
/// As [`record_in_run`]; `set` matches the layout's set `index` and `offsets` its dynamic
/// bindings.
unsafe fn bind_set(
    device: &ash::Device,
    cmd: vk::CommandBuffer,
    bound: &Bound,
    index: u32,
    set: vk::DescriptorSet,
    offsets: &[u32],
) {
    // SAFETY: the caller's contract above.
    unsafe {
        device.cmd_bind_descriptor_sets(
            cmd,
            vk::PipelineBindPoint::GRAPHICS,
            bound.layout,
            index,
            &[set],
            offsets,
        )
    };
}

/// Binds what of `bound` differs from what `run` says is bound and draws `geometry`, once
/// per draw of `bound` (as instances, each reading its own record).
///
/// # Safety
///
/// `cmd` is a command buffer of `device` in the recording state, inside a dynamic rendering
/// pass whose formats match the pipeline's, with viewport and scissor set; every handle
/// belongs to `device` and stays alive until the command buffer has finished executing; the
/// buffers hold what the geometry reads and the records `bound` names; what `run` records as
/// bound is bound in `cmd` (no command since the run's last draw changed it).
pub(crate) unsafe fn record_in_run(
    device: &ash::Device,
    cmd: vk::CommandBuffer,
    bound: &Bound,
    geometry: &Geometry,
    run: &mut RunState,
) {
    let (pipeline, dynamic) = bound.pipeline;
    if run.pipeline != Some(pipeline) {
        // SAFETY: the caller's contract above (it covers each call below too): `cmd` is
        // recording inside a rendering pass and the pipeline belongs to `device`.
        unsafe { device.cmd_bind_pipeline(cmd, vk::PipelineBindPoint::GRAPHICS, pipeline) };
        run.pipeline = Some(pipeline);
    }
    // SAFETY: as above; every ffvk pipeline takes these states as dynamic.
    unsafe { set_dynamic(device, cmd, &dynamic, run) };
    let state_block = (bound.set, bound.uniform_offset);
    if run.state_block != Some(state_block) {
        run.state_block = Some(state_block);
        // SAFETY: as above; the set is at its index in the layout, with one dynamic offset.
        unsafe {
            bind_set(
                device,
                cmd,
                bound,
                bound.set_index,
                bound.set,
                &[bound.uniform_offset],
            )
        };
    }
    if let Some((set, offset)) = bound
        .record_block
        .filter(|&block| run.record_block != Some(block))
    {
        run.record_block = Some((set, offset));
        // SAFETY: as above; the record's set is two after the block's, one dynamic offset.
        unsafe { bind_set(device, cmd, bound, bound.set_index + 2, set, &[offset]) };
    }
    if let Some(set) = bound.texture_set.filter(|&set| run.texture_set != Some(set)) {
        run.texture_set = Some(set);
        // SAFETY: as above; the texture's set is the one after the block's in the layout.
        unsafe { bind_set(device, cmd, bound, bound.set_index + 1, set, &[]) };
    }
    let caller = bound
        .bindings
        .iter()
        .map(|b| b.binding)
        .zip(bound.vertex_buffers.iter().copied());
    let record = std::iter::once((bound.record_binding, (bound.record_buffer, 0)));
    for (binding, (buffer, offset)) in caller.chain(record) {
        let now = (binding, buffer, offset);
        if run.vertex_buffers.contains(&now) {
            continue;
        }
        run.vertex_buffers.retain(|&(b, ..)| b != binding);
        run.vertex_buffers.push(now);
        // SAFETY: as above; one buffer per binding of the pipeline.
        unsafe { device.cmd_bind_vertex_buffers(cmd, binding, &[buffer], &[offset]) };
    }
    // SAFETY: the caller's contract above.
    unsafe { draw_geometry(device, cmd, bound, geometry, run) };
    if let Some((second, dynamic)) = bound.second_pipeline {
        run.pipeline = Some(second);
        // SAFETY: as above; the second pipeline has the first's layout, vertex input and
        // specialization, so everything bound stays valid for it.
        unsafe {
            device.cmd_bind_pipeline(cmd, vk::PipelineBindPoint::GRAPHICS, second);
            set_dynamic(device, cmd, &dynamic, run);
            draw_geometry(device, cmd, bound, geometry, run);
        }
    }
}

/// Sets the dynamic raster state `want` where it differs from what `run` set (all of it
/// where the run set none yet).
///
/// # Safety
///
/// As [`record_in_run`]: `cmd` is recording and a pipeline with these dynamic states is bound.
unsafe fn set_dynamic(
    device: &ash::Device,
    cmd: vk::CommandBuffer,
    want: &DynamicRaster,
    run: &mut RunState,
) {
    let had = run.dynamic;
    if had.as_ref() == Some(want) {
        return;
    }
    // Each setter runs where the value changed, or when nothing was set yet.
    let changed = |f: &dyn Fn(&DynamicRaster) -> bool| had.is_none_or(|h| !f(&h));
    // SAFETY: the caller's contract above (for every call below).
    unsafe {
        if changed(&|h| h.cull_mode == want.cull_mode) {
            device.cmd_set_cull_mode(cmd, want.cull_mode);
        }
        if changed(&|h| h.front_face == want.front_face) {
            device.cmd_set_front_face(cmd, want.front_face);
        }
        if changed(&|h| h.depth_test == want.depth_test) {
            device.cmd_set_depth_test_enable(cmd, want.depth_test);
        }
        if changed(&|h| h.depth_write == want.depth_write) {
            device.cmd_set_depth_write_enable(cmd, want.depth_write);
        }
        if changed(&|h| h.depth_compare == want.depth_compare) {
            device.cmd_set_depth_compare_op(cmd, want.depth_compare);
        }
        if changed(&|h| h.depth_bias.is_some() == want.depth_bias.is_some()) {
            device.cmd_set_depth_bias_enable(cmd, want.depth_bias.is_some());
        }
        // The values are set on a first set too, off or not, so that they always have one.
        if (had.is_none() || want.depth_bias.is_some()) && changed(&|h| h.depth_bias == want.depth_bias) {
            let (constant, slope) = want.depth_bias.unwrap_or((0.0, 0.0));
            device.cmd_set_depth_bias(cmd, constant, 0.0, slope);
        }
        if changed(&|h| h.stencil.is_some() == want.stencil.is_some()) {
            device.cmd_set_stencil_test_enable(cmd, want.stencil.is_some());
        }
        // The stencil's values are set whenever they may be read: a first set sets GL's
        // defaults where the test is off, so that every dynamic state has a value.
        let stencil = want.stencil.unwrap_or_default();
        let had_stencil = had.map(|h| h.stencil.unwrap_or_default());
        for (face, f, before) in [
            (
                vk::StencilFaceFlags::FRONT,
                stencil.front,
                had_stencil.map(|s| s.front),
            ),
            (
                vk::StencilFaceFlags::BACK,
                stencil.back,
                had_stencil.map(|s| s.back),
            ),
        ] {
            if before == Some(f) {
                continue;
            }
            device.cmd_set_stencil_op(cmd, face, f.fail, f.pass, f.depth_fail, f.func);
            device.cmd_set_stencil_compare_mask(cmd, face, f.value_mask);
            device.cmd_set_stencil_write_mask(cmd, face, f.write_mask);
            device.cmd_set_stencil_reference(cmd, face, f.reference);
        }
        if changed(&|h| h.line_width.to_bits() == want.line_width.to_bits()) {
            device.cmd_set_line_width(cmd, want.line_width);
        }
        if changed(&|h| h.blend_color == want.blend_color) {
            device.cmd_set_blend_constants(cmd, &want.blend_color);
        }
    }
    run.dynamic = Some(*want);
}

/// Binds `geometry`'s index buffer where it differs from the run's and draws it.
///
/// # Safety
///
/// As [`record_in_run`], with everything but the index buffer bound.
unsafe fn draw_geometry(
    device: &ash::Device,
    cmd: vk::CommandBuffer,
    bound: &Bound,
    geometry: &Geometry,
    run: &mut RunState,
) {
    let (instances, first_instance) = (bound.draws, bound.first_record);
    match *geometry {
        Geometry::Indexed {
            buffer,
            offset,
            index_type,
            first_index,
            index_count,
            vertex_offset,
            ..
        } => {
            if run.index_buffer != Some((buffer, offset, index_type)) {
                run.index_buffer = Some((buffer, offset, index_type));
                // SAFETY: as above.
                unsafe { device.cmd_bind_index_buffer(cmd, buffer, offset, index_type) };
            }
            // SAFETY: as above; the caller's indices address its vertices, and the records
            // from first_instance on are the draws'.
            unsafe {
                device.cmd_draw_indexed(
                    cmd,
                    index_count,
                    instances,
                    first_index,
                    vertex_offset,
                    first_instance,
                )
            };
        }
        Geometry::Vertices {
            first_vertex,
            vertex_count,
            ..
        } => {
            // SAFETY: as above.
            unsafe { device.cmd_draw(cmd, vertex_count, instances, first_vertex, first_instance) };
        }
    }
}
