//! The core's error type. Library code returns these; only the binary decides how to print
//! them. Errors of the optional layers (images, scenes, tools) live with them and wrap this one.

use ash::vk;

use crate::gl::state::StateError;

/// Everything that can go wrong in ffvk.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    #[error("cannot load the Vulkan loader (libvulkan.so.1): {0}; install the Debian package libvulkan1")]
    NoLoader(String),

    #[error("no Vulkan device{requested}: available devices: {available}; install mesa-vulkan-drivers for lavapipe")]
    NoDevice { requested: String, available: String },

    #[error("the device lacks {0}, which ffvk needs")]
    MissingFeature(String),

    #[error("the Vulkan device was lost during {0}")]
    DeviceLost(&'static str),

    #[error("out of {kind} memory during {call}")]
    OutOfMemory { kind: &'static str, call: &'static str },

    #[error("{call} failed: {result}")]
    Vulkan { call: &'static str, result: vk::Result },

    #[error("image size {width}x{height} is invalid: expected each side in 1..={max} (the device's maxImageDimension2D)")]
    InvalidSize { width: u32, height: u32, max: u32 },

    #[error("the validation layer VK_LAYER_KHRONOS_validation is not installed (Debian package vulkan-validationlayers)")]
    NoValidationLayer,

    #[error("the validation layer reported {} error(s):\n{}", .0.len(), .0.join("\n"))]
    Validation(Vec<String>),

    #[error("invalid mesh: {0}")]
    Mesh(#[from] MeshError),

    #[error(transparent)]
    State(#[from] StateError),
}

/// Why a mesh cannot be drawn or made.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MeshError {
    #[error("{count} indices is not a whole number of triangles: expected a multiple of 3")]
    NotTriangles { count: usize },

    #[error("index {at} is {index}: expected a vertex index below {vertex_count} (the vertex count)")]
    IndexOutOfRange {
        at: usize,
        index: u32,
        vertex_count: usize,
    },

    #[error(
        "draw {draw}: the mesh was uploaded by another renderer: expected a mesh from this renderer's upload"
    )]
    ForeignMesh { draw: usize },

    #[error("teapot tessellation level {level} is out of range: expected 1..={max}")]
    TeapotLevel { level: u32, max: u32 },
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
