//! The core's error type. Library code returns these; only a program (the `ffvk` command of
//! the `ffvk-cli` crate, or the caller's) decides how to print them. Errors of the optional
//! layers (images, scenes) live with them and wrap this one; so do the tool crate's.

use ash::vk;

use crate::gl::errors::StateError;
pub use crate::gl::errors::UnknownName;

/// Everything that can go wrong in ffvk.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// `libvulkan.so.1` could not be opened, so no Vulkan call is possible on this machine;
    /// the string is the dynamic loader's reason.
    #[error("cannot load the Vulkan loader (libvulkan.so.1): {0}; install the Debian package libvulkan1")]
    NoLoader(String),

    #[error("no Vulkan device{requested}: available devices: {available}; install mesa-vulkan-drivers for lavapipe")]
    /// No physical device matched: there is none, or none has the requested name in it.
    /// Retrying with a name from `available` (or after installing lavapipe) can succeed.
    NoDevice {
        /// ` named "…"` (leading space included) when a name was asked for, else empty: it is
        /// spliced into the message as is.
        requested: String,
        /// Every enumerated device name, comma-separated, or `none`.
        available: String,
    },

    /// The chosen device lacks something ffvk cannot work without: Vulkan 1.3,
    /// `dynamicRendering` (and, for ffvk's own device, `synchronization2`), a graphics queue,
    /// `VK_EXT_provoking_vertex` with `provokingVertexLast`, or a suitable memory type; or an
    /// embedded shader variant is absent or not valid SPIR-V (a build defect). The string
    /// names what is missing. Another device may work; retrying this one will not.
    #[error("the device lacks {0}, which ffvk needs")]
    MissingFeature(String),

    /// The caller's device was not created with a feature ffvk needs, as its
    /// [`EnabledFeatures`](crate::vk::EnabledFeatures) says: create the device with it and
    /// set the flag.
    #[error("the caller's device was created without {feature} (EnabledFeatures::{flag} is false), which {needed_for}")]
    NotEnabled {
        /// The Vulkan feature.
        feature: &'static str,
        /// The field of `EnabledFeatures` that says it is enabled.
        flag: &'static str,
        /// What needs it.
        needed_for: &'static str,
    },

    /// `VK_ERROR_DEVICE_LOST` from the named call, or a frame asked of a renderer whose
    /// earlier submission failed. That renderer is unusable from then on: make a new one.
    #[error("the Vulkan device was lost during {0}")]
    DeviceLost(&'static str),

    #[error("out of {kind} memory during {call}")]
    /// `VK_ERROR_OUT_OF_HOST_MEMORY` or `VK_ERROR_OUT_OF_DEVICE_MEMORY`: smaller images or
    /// meshes may fit.
    OutOfMemory {
        /// `"host"` or `"device"`.
        kind: &'static str,
        /// The Vulkan entry point that failed, e.g. `"vkAllocateMemory"`.
        call: &'static str,
    },

    /// A host allocation ffvk sized from its input failed (see [`crate::alloc`]).
    #[error(transparent)]
    Alloc(#[from] crate::alloc::AllocError),

    /// One device allocation larger than the device's memory heap (or its
    /// `maxMemoryAllocationSize`), refused before asking the driver.
    #[error("{what}: {bytes} bytes of device memory asked for, more than the device's {limit_name} ({limit} bytes)")]
    TooLarge {
        /// What the memory was for, e.g. `"vertex buffer"`.
        what: &'static str,
        /// The size asked for.
        bytes: u64,
        /// The device's limit.
        limit: u64,
        /// Which limit: `"memory heap"` or `"maxMemoryAllocationSize"`.
        limit_name: &'static str,
    },

    /// gpu-allocator refused device memory ffvk asked for, usually because the memory is
    /// exhausted: smaller images or meshes may fit.
    #[error("cannot allocate {bytes} bytes of device memory ({location:?}) for the {what}: {source}")]
    DeviceMemory {
        /// What the memory was for, e.g. `"vertex buffer"`.
        what: &'static str,
        /// The resource's size.
        bytes: u64,
        /// The location its use asked for ([`MemoryUse::location`](crate::vk::MemoryUse::location)).
        location: gpu_allocator::MemoryLocation,
        /// gpu-allocator's error.
        source: gpu_allocator::AllocationError,
    },

    /// gpu-allocator could not be set up for the device.
    #[error("cannot set up {what}: {source}")]
    Allocator {
        /// What was being set up.
        what: &'static str,
        /// gpu-allocator's error.
        source: gpu_allocator::AllocationError,
    },

    /// [`Buffer::write`](crate::vk::Buffer::write) or a read of a buffer whose memory the host
    /// cannot see (device-local memory of a discrete GPU): a bug in the caller.
    #[error("the buffer's memory is not host-visible; fill it with a copy from a staging buffer")]
    NotMapped,

    /// [`Buffer::write`](crate::vk::Buffer::write) past the buffer's end: a bug in the caller.
    #[error("a write of {bytes} bytes at offset {offset} is outside the buffer of {size} bytes")]
    OutOfBounds {
        /// Where the write starts.
        offset: u64,
        /// Its length.
        bytes: u64,
        /// The buffer's size.
        size: u64,
    },

    /// [`Renderer::measure_frames`](crate::Renderer::measure_frames) was asked for no frames
    /// or more than one submission records.
    #[error("{count} frames asked of one measurement: expected 1..={max}")]
    TooManyFrames {
        /// The count asked for.
        count: u32,
        /// [`MAX_REPEAT`](crate::renderer::MAX_REPEAT).
        max: u32,
    },

    #[error("{call} failed: {result}")]
    /// Any other failing `VkResult`: unexpected, and not specific to the caller's input.
    Vulkan {
        /// The Vulkan entry point that failed.
        call: &'static str,
        /// What it returned.
        result: vk::Result,
    },

    #[error("image size {width}x{height} is invalid: expected each side in 1..={max} (the device's maxImageDimension2D)")]
    /// A frame's size is 0 or beyond the device's limit; nothing was drawn.
    InvalidSize {
        /// Requested width, in pixels.
        width: u32,
        /// Requested height, in pixels.
        height: u32,
        /// The device's `maxImageDimension2D`, the largest side allowed.
        max: u32,
    },

    /// ffvk found one of its own invariants broken (the string says which): a bug in ffvk,
    /// reported as an error rather than a panic. Please report it with the message.
    #[error("internal error: {0}; this is a bug in ffvk, please report it")]
    Internal(&'static str),

    /// [`Validation::Required`](crate::vk::Validation::Required) was asked for and the
    /// layer is not installed.
    #[error("the validation layer VK_LAYER_KHRONOS_validation is not installed (Debian package vulkan-validationlayers)")]
    NoValidationLayer,

    /// The validation layer reported errors, one message per entry, while the renderer was
    /// made or a frame was drawn: a bug in ffvk's use of Vulkan, reported instead of the
    /// frame's pixels. Warnings never cause it.
    #[error("the validation layer reported {} error(s):\n{}", .0.len(), .0.join("\n"))]
    Validation(Vec<String>),

    /// A [`Lighting`](crate::Lighting) setting or draw that cannot be used.
    #[error(transparent)]
    Lighting(#[from] LightingError),

    /// A mesh was rejected before anything was uploaded or drawn.
    #[error("invalid mesh: {0}")]
    Mesh(#[from] MeshError),

    /// A lighting state that GL would reject (`INVALID_VALUE`), or one that cannot be drawn:
    /// a singular modelview with lighting on, or an enabled positional light whose three
    /// attenuation factors are all 0.
    #[error(transparent)]
    State(#[from] StateError),
    /// A draw of a run ([`Lighting::draw_run`](crate::Lighting::draw_run)) failed: which one,
    /// and why. Nothing of the run was recorded.
    #[error("draw {index} of the run: {source}")]
    InRun {
        /// The draw's index in the run.
        index: usize,
        /// Why it failed.
        #[source]
        source: Box<Error>,
    },
}

/// Why a [`Lighting`](crate::Lighting) cannot be made as asked or cannot record a draw.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum LightingError {
    /// A draw's texture for one target is bound to the other's slot (a cube map among
    /// `LitDraw::textures`, or a 2D texture among `LitDraw::cube_maps`).
    #[error("unit {unit} of the draw's {field} holds a {given} binding: expected {expected}")]
    TextureTarget {
        /// `textures` or `cube_maps`.
        field: &'static str,
        /// The unit.
        unit: usize,
        /// The binding's target.
        given: &'static str,
        /// The target the slot takes.
        expected: &'static str,
    },
    /// A vertex binding appears twice in [`VertexInput::bindings`](crate::VertexInput).
    #[error("vertex binding {binding} is listed twice: expected each binding once")]
    DuplicateBinding {
        /// The binding number.
        binding: u32,
    },
    /// A binding steps per instance; GL's vertex arrays step per vertex.
    #[error(
        "vertex binding {binding} has input rate {rate:?}: expected VERTEX (GL's arrays are per vertex)"
    )]
    InputRate {
        /// The binding number.
        binding: u32,
        /// Its input rate.
        rate: ash::vk::VertexInputRate,
    },
    /// An attribute reads a binding the layout does not have.
    #[error("the {attribute} attribute reads binding {binding}: expected one of the bindings {available:?}")]
    UnknownBinding {
        /// `position`, `normal`, `color`, `texcoord` or a material array.
        attribute: String,
        /// The binding it names.
        binding: u32,
        /// The bindings the layout has.
        available: Vec<u32>,
    },
    /// An attribute's format is not one that attribute takes (GL's arrays of that kind).
    #[error("the {attribute} attribute has format VK_FORMAT_{format:?} ({raw}): expected one of {expected}", raw = format.as_raw())]
    AttributeFormat {
        /// `position`, `normal`, `color`, `texcoord` or a material array.
        attribute: String,
        /// The format given.
        format: ash::vk::Format,
        /// The formats it takes, by Vulkan's C names.
        expected: String,
    },
    /// The device cannot read an attribute's format from vertex buffers.
    #[error("the {attribute} attribute has format VK_FORMAT_{format:?}, which ffvk fetches as VK_FORMAT_{fetched:?}, but the device does not support that format for vertex buffers (VK_FORMAT_FEATURE_VERTEX_BUFFER_BIT): expected another format, e.g. a four-component one with padding for a three-component array of bytes or shorts")]
    VertexFormatUnsupported {
        /// The attribute.
        attribute: String,
        /// The format given.
        format: ash::vk::Format,
        /// The format ffvk fetches for it (the SSCALED twin of a signed normalized one).
        fetched: ash::vk::Format,
    },
    /// A fragment-mode draw whose layout gives materials per vertex.
    #[error("the vertex layout gives the {attribute} per vertex, but the draw is lit in the fragment mode, whose materials are the draw's: expected the vertex or flat mode (GL's), or a layout without material arrays")]
    MaterialArraysInFragmentMode {
        /// The first material array of the layout.
        attribute: String,
    },
    /// A draw names a vertex layout another `Lighting` made.
    #[error("the draw's vertex layout {layout} was made by another Lighting: expected one this Lighting made (Lighting::vertex_layout)")]
    ForeignLayout {
        /// The layout's number.
        layout: u32,
    },
    /// A draw tests depth but the target has no depth attachment.
    #[error("the draw tests depth, but the target has no depth format: expected RasterState::depth_test false or a Target::depth_format")]
    NoDepthAttachment,
    /// A draw tests the stencil buffer but the target's depth format has none.
    #[error("the draw tests the stencil buffer, but the target's depth format {format:?} has no stencil: expected RasterState::stencil None, or a Target::depth_format with stencil (e.g. D24_UNORM_S8_UINT)")]
    NoStencilAttachment {
        /// The target's depth format.
        format: ash::vk::Format,
    },
    /// A logic op on a color format that does not take one (Vulkan applies logic ops to
    /// integer and normalized formats only).
    #[error("the draw has a logic op (glLogicOp), but the target's color format {format:?} is not normalized: expected RasterState::logic_op None, or a UNORM color format")]
    LogicOpFormat {
        /// The target's color format.
        format: ash::vk::Format,
    },
    /// `frames_in_flight` is 0.
    #[error("frames_in_flight is 0: expected at least 1 frame slot")]
    NoFrameSlots,
    /// A frame slot past `frames_in_flight`.
    #[error("frame slot {slot} does not exist: expected 0..{slots} (frames_in_flight)")]
    FrameSlot {
        /// The slot given.
        slot: u32,
        /// How many there are.
        slots: u32,
    },
    /// The set index is past what the device can bind.
    #[error("set_index {index} leaves no room for the texture's and the draw records' sets after it within the device's maxBoundDescriptorSets: expected 0..={max}")]
    SetIndex {
        /// The index given.
        index: u32,
        /// `maxBoundDescriptorSets`.
        max: u32,
    },
    /// The device cannot take the caller's vertex bindings and ffvk's per-draw record beside
    /// them.
    #[error(
        "the vertex layout needs {needed} vertex {what} (the caller's and ffvk's per-draw record's), but the device's {limit} is {max}: expected a device with more, or fewer bindings"
    )]
    VertexInputLimit {
        /// `bindings` or `attribute locations`.
        what: &'static str,
        /// How many are needed.
        needed: u32,
        /// The limit's name.
        limit: &'static str,
        /// The device's limit.
        max: u32,
    },
    /// A point size or line width GL would refuse or the device cannot draw.
    #[error("{what} {size}: expected {expected}")]
    RasterSize {
        /// "point size" or "line width".
        what: &'static str,
        /// The size asked for, in pixels, as written.
        size: String,
        /// What was expected.
        expected: String,
    },
    /// Primitive restart on a list topology (Vulkan allows it only with a feature ffvk does
    /// not ask for, and GL's lists have nothing to restart).
    #[error("primitive restart is on for {topology}: expected GL_LINE_STRIP, GL_TRIANGLE_STRIP or GL_TRIANGLE_FAN, or restart off")]
    RestartOnList {
        /// GL's name of the draw's mode.
        topology: &'static str,
    },
    /// A draw's geometry that Vulkan would not draw as given: an index buffer offset not a
    /// multiple of the index size, an index type other than UINT16 or UINT32, or a range of
    /// indices or vertices past 2^32.
    #[error("the draw's {field} is {value}: expected {expected}")]
    Geometry {
        /// The geometry's field (`index offset`, `first + count`, `index type`).
        field: String,
        /// Its value, as given.
        value: String,
        /// What was expected.
        expected: &'static str,
    },
    /// A draw passes a different number of vertex buffers than the layout has bindings.
    #[error(
        "the draw passes {given} vertex buffer(s): expected {expected}, one per binding of the vertex layout"
    )]
    VertexBuffers {
        /// Buffers passed.
        given: usize,
        /// Bindings in the layout.
        expected: usize,
    },
    /// More frame slots than ffvk keeps ([`MAX_FRAMES_IN_FLIGHT`](crate::draw::lighting::MAX_FRAMES_IN_FLIGHT)).
    #[error("frames_in_flight is {count}: expected 1..={max} frame slots")]
    TooManyFrameSlots {
        /// The count given.
        count: u32,
        /// The most ffvk keeps.
        max: u32,
    },
    /// More vertex bindings than ffvk takes ([`MAX_VERTEX_BINDINGS`](crate::draw::pipeline::MAX_VERTEX_BINDINGS)).
    #[error("the vertex layout has {count} bindings: expected at most {max}")]
    TooManyBindings {
        /// The bindings given.
        count: usize,
        /// The most ffvk takes.
        max: u32,
    },
    /// An attribute that does not lie within one element of its binding.
    #[error("the {attribute} attribute at offset {offset} ({size} bytes of {format:?}) ends past the stride {stride} of binding {binding}: expected offset + {size} <= stride")]
    AttributeOffset {
        /// `position`, `normal`, `color`, `texcoord` or a material array.
        attribute: String,
        /// Its offset.
        offset: u32,
        /// Its format.
        format: ash::vk::Format,
        /// The format's size in bytes.
        size: u32,
        /// Its binding.
        binding: u32,
        /// The binding's stride.
        stride: u32,
    },
    /// The target's color format is not one ffvk renders to.
    #[error("color_format {format:?} ({raw}) is not a color format ffvk renders to: expected an uncompressed color format the shaders write as floats (UNORM, SNORM, SRGB or FLOAT, e.g. R8G8B8A8_UNORM), not UNDEFINED, a depth, integer or compressed format", raw = format.as_raw())]
    ColorFormat {
        /// The format given.
        format: ash::vk::Format,
    },
    /// The target's depth format is not a depth format.
    #[error("depth_format {format:?} ({raw}) is not a depth format: expected UNDEFINED (no depth attachment), D16_UNORM, X8_D24_UNORM_PACK32, D32_SFLOAT, D16_UNORM_S8_UINT, D24_UNORM_S8_UINT or D32_SFLOAT_S8_UINT", raw = format.as_raw())]
    DepthFormat {
        /// The format given.
        format: ash::vk::Format,
    },
    /// The target's samples are not one `VkSampleCountFlagBits` bit.
    #[error("samples {raw} (0x{raw:X}) is not one VkSampleCountFlagBits bit: expected 1, 2, 4, 8, 16, 32 or 64", raw = samples.as_raw())]
    Samples {
        /// The flags given.
        samples: ash::vk::SampleCountFlags,
    },
    /// The device cannot use a format as ffvk would.
    #[error("{field} {format:?} is not supported by the device as {feature}: expected a format whose features (vkGetPhysicalDeviceFormatProperties) include {feature}")]
    FormatUnsupported {
        /// What has the format: `color_format`, `depth_format` or an attribute's.
        field: &'static str,
        /// The format.
        format: ash::vk::Format,
        /// The `VkFormatFeatureFlags` bit it lacks.
        feature: &'static str,
    },
    /// The device cannot render the target's samples into one of its attachments.
    #[error("samples {samples} is not supported by the device for the {attachment}: expected one of {supported} (its {limit})")]
    SamplesUnsupported {
        /// The samples given.
        samples: u32,
        /// `color attachment`, `depth attachment` or `stencil of the depth attachment`.
        attachment: &'static str,
        /// The sample counts the device supports, e.g. `1, 4`.
        supported: String,
        /// The limit's name, e.g. `framebufferColorSampleCounts`.
        limit: &'static str,
    },
    /// A vertex layout value past a device limit.
    #[error("{what} is {value}: expected at most {max} (the device's {limit})")]
    VertexLimit {
        /// What, e.g. `the stride of binding 0`.
        what: String,
        /// Its value.
        value: u32,
        /// The limit's name.
        limit: &'static str,
        /// The device's limit.
        max: u32,
    },
    /// A raster state field that is not a value ffvk passes to Vulkan.
    #[error("{field} {value} is not accepted: expected {expected}")]
    RasterEnum {
        /// The field: `cull_mode`, `front_face`, `depth_compare`, `src_color`, ….
        field: &'static str,
        /// Its value as given.
        value: String,
        /// What was expected.
        expected: &'static str,
    },
    /// Blending into a color format the device cannot blend into.
    #[error("the draw blends, but the device cannot blend into color_format {format:?} (no COLOR_ATTACHMENT_BLEND): expected blending off, or a target whose color format blends")]
    BlendUnsupported {
        /// The target's color format.
        format: ash::vk::Format,
    },
    /// So many draws in one frame slot that a dynamic offset would pass 4 GiB.
    #[error(
        "{draws} draws in one frame slot put a uniform offset past 4 GiB: expected fewer draws per frame"
    )]
    TooManyDraws {
        /// Draws recorded in the slot so far.
        draws: u64,
    },
}

/// Why a mesh cannot be drawn or made.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum MeshError {
    #[error(
        "{count} indices is not a whole number of primitives of {topology}: expected a multiple of {per}"
    )]
    /// The index count is not a multiple of a list's primitive size (3 for triangles, 2 for
    /// lines).
    PartialPrimitive {
        /// Indices given.
        count: usize,
        /// GL's name of the mesh's mode.
        topology: &'static str,
        /// Indices per primitive.
        per: usize,
    },

    #[error("index {at} is {index}: expected a vertex index below {vertex_count} (the vertex count)")]
    /// An index points past the last vertex.
    IndexOutOfRange {
        /// Position of the first bad index in the index list.
        at: usize,
        /// Its value.
        index: u32,
        /// The number of vertices; valid indices are below it.
        vertex_count: usize,
    },

    #[error(
        "draw {draw}: the mesh was uploaded by another renderer: expected a mesh from this renderer's upload"
    )]
    /// A [`Mesh`](crate::Mesh) lives on another renderer's device; upload it again here.
    ForeignMesh {
        /// Position of the offending draw in [`Frame::draws`](crate::Frame::draws).
        draw: usize,
    },

    #[error(
        "draw {draw}: the texture was uploaded by another renderer: expected a texture from this renderer's upload_texture"
    )]
    /// A [`Texture`](crate::renderer::Texture) lives on another renderer's device.
    ForeignTexture {
        /// Position of the offending draw in [`Frame::draws`](crate::Frame::draws).
        draw: usize,
    },

    #[error(
        "{count} second texture coordinates for {vertex_count} vertices: expected one (s, t) per vertex, or none"
    )]
    /// A mesh whose [`MeshData::second_texcoords`](crate::mesh::MeshData::second_texcoords)
    /// is neither empty nor one per vertex.
    SecondTexcoordCount {
        /// Second coordinates given.
        count: usize,
        /// The number of vertices.
        vertex_count: usize,
    },

    #[error(
        "draw {draw}: units {units:#b} read the mesh's second texture coordinates, which it was uploaded without: expected a mesh with MeshData::second_texcoords, or those units' bits clear in Draw::second_texcoords"
    )]
    /// A draw whose [`Draw::second_texcoords`](crate::Draw::second_texcoords) names a unit
    /// while its mesh has no second set of texture coordinates.
    NoSecondTexcoords {
        /// Position of the offending draw in [`Frame::draws`](crate::Frame::draws).
        draw: usize,
        /// The units 1-3 of its `second_texcoords`, a bit each.
        units: u32,
    },

    #[error("teapot tessellation level {level} is out of range: expected 1..={max}")]
    /// The teapot's tessellation level is 0 or above the maximum.
    TeapotLevel {
        /// The level asked for.
        level: u32,
        /// [`MAX_LEVEL`](crate::mesh::teapot::MAX_LEVEL), the largest accepted.
        max: u32,
    },
}

/// Result with ffvk's [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// The one place where `vk::Result` codes become ffvk errors: device loss and memory
/// exhaustion get their own variants so callers can tell them apart; the rest keep the call.
pub(crate) fn vk_error(call: &'static str) -> impl Fn(vk::Result) -> Error {
    move |result| match result {
        vk::Result::ERROR_DEVICE_LOST => Error::DeviceLost(call),
        vk::Result::ERROR_OUT_OF_HOST_MEMORY => Error::OutOfMemory { kind: "host", call },
        vk::Result::ERROR_OUT_OF_DEVICE_MEMORY => Error::OutOfMemory { kind: "device", call },
        result => Error::Vulkan { call, result },
    }
}
