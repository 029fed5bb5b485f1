//! ffvk: the OpenGL 2.1 fixed-function lighting equation, verbatim, on Vulkan.
//!
//! The core (always built) follows the data: GL state ([`gl`]) → its GPU layout and the
//! SPIR-V of the shaders ([`gpu`]) → pipelines and draw recording ([`draw`]) over an owned
//! Vulkan layer ([`vk`]) → the offscreen renderer ([`renderer`]); beside them the CPU
//! reference of the same equation ([`reference`](mod@reference)) and host meshes ([`mesh`]).
//! It depends on ash, glam, bytemuck and thiserror only, never prints, reads arguments or sets
//! environment variables.
//!
//! # Two ways in
//!
//! - [`Renderer`] opens its own device and draws [`Frame`]s offscreen into images: what the
//!   `ffvk` command, the tests and regression renders use.
//! - [`Lighting`] records GL's lighting into a caller's own device, command buffers and
//!   render targets ([`vk::Device::from_caller`]); see its module, [`draw::lighting`], for
//!   what it owns and records, and `ffvk/examples/embed.rs` (in the repository) for a complete
//!   program with plain `ash`. [`Renderer`] is built on it.
//!
//! Renderers that build their own pipelines take the pieces: the SPIR-V ([`gpu::shaders`]),
//! the uniform block's layout and the specialization constants ([`gpu::layout`]).
//!
//! Features add the rest: `images` (PNG files and image comparison) and `scene` (TOML scene
//! files and glTF). The `ffvk` command (bench, demo, explain, regression runs, the GL
//! reference) is another crate of the repository's workspace, `ffvk-cli`: a plain dependency
//! on this one builds none of it.
//!
//! `ash` and `glam` are part of the API and re-exported as [`ash`] and [`glam`]: take them from
//! here, so a caller's handles and matrices are always of the versions ffvk was built with.
//!
//! # Growing without breaking
//!
//! Options, descriptions and errors are `#[non_exhaustive]`: callers build them with their
//! constructors or `Default`, then set fields or chain the `with_*` methods, and match them
//! with a `_` arm, so that a field or variant added later breaks no caller.
//!
//! ```
//! use ffvk::ash::vk;
//! use ffvk::glam::Mat4;
//! use ffvk::gl::state::GlState;
//! use ffvk::{Geometry, LitDraw, RasterState};
//!
//! let gl = GlState::new();
//! let buffers = [(vk::Buffer::null(), 0)];
//! let draw = LitDraw::new(&gl.lighting, Mat4::IDENTITY, Mat4::IDENTITY, &buffers, Geometry::vertices(3))
//!     .with_raster(RasterState::default().with_depth_test(true));
//! assert!(draw.raster.depth_test && draw.textures[0].is_none());
//! ```

/// `with_*` methods for a `#[non_exhaustive]` options struct: callers outside the crate cannot
/// write its literal, so they start from its constructor or `Default` and chain these, and a
/// field added later breaks nobody.
macro_rules! with_fields {
    ($ty:ident $(<$lt:lifetime>)? { $( $(#[$doc:meta])* $method:ident => $field:ident : $t:ty ),* $(,)? }) => {
        impl $(<$lt>)? $ty $(<$lt>)? {
            $(
                $(#[$doc])*
                #[must_use]
                pub fn $method(mut self, value: $t) -> Self {
                    self.$field = value;
                    self
                }
            )*
        }
    };
}

pub mod alloc;
pub mod draw;
pub mod error;
#[cfg(feature = "images")]
pub mod files;
pub mod gl;
pub mod gpu;
#[cfg(feature = "images")]
pub mod images;
pub mod mesh;
pub mod reference;
pub mod renderer;
#[cfg(feature = "scene")]
pub mod scene;
pub mod shaders;
pub mod vk;

/// The `ash` ffvk is built with: its Vulkan types are part of ffvk's API ([`Target`],
/// [`VertexInput`], [`LitDraw`] take `ash::vk` handles and formats), so a caller's handles must
/// come from this very version. Use `ffvk::ash` (or pin the same version) to be sure.
pub use ash;
/// The `glam` ffvk is built with: matrices and colors ([`Mat4`](glam::Mat4),
/// [`Vec4`](glam::Vec4), the reference's `DVec`s) are `glam` types in ffvk's API, so a caller's
/// must come from this very version. Use `ffvk::glam` (or pin the same version) to be sure.
pub use glam;
/// gpu-allocator, the version ffvk allocates its device memory with: an embedder that shares
/// its allocator (feature `shared-allocator`) makes it with this one, so the versions match.
pub use gpu_allocator;
/// The `image` ffvk is built with (feature `images`): [`images::save_png`] and the
/// comparisons take its `RgbaImage`, so a caller holding raw RGBA bytes builds one from this
/// very version (`ffvk::image::RgbaImage::from_raw`).
#[cfg(feature = "images")]
pub use image;

/// The README's Rust snippets, compiled (and those that can run, run) by `cargo test --doc`.
#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
pub struct ReadmeDoctests;

/// The guides' Rust snippets (docs/, the README's sections once), compiled the same way: one
/// item per file, so a failing snippet is named by its guide. `tests/suite/docs.rs` checks
/// that every Markdown file with a Rust snippet is listed here.
#[cfg(doctest)]
pub mod guide_doctests {
    /// docs/embedding-rust.md: the library, and `Lighting` in a caller's renderer.
    #[doc = include_str!("../../docs/embedding-rust.md")]
    pub struct EmbeddingRust;
    /// docs/c-api.md.
    #[doc = include_str!("../../docs/c-api.md")]
    pub struct CApi;
    /// docs/scene-files.md.
    #[doc = include_str!("../../docs/scene-files.md")]
    pub struct SceneFiles;
    /// docs/pipeline.md.
    #[doc = include_str!("../../docs/pipeline.md")]
    pub struct Pipeline;
    /// docs/conformance.md.
    #[doc = include_str!("../../docs/conformance.md")]
    pub struct Conformance;
    /// docs/regression.md.
    #[doc = include_str!("../../docs/regression.md")]
    pub struct Regression;
    /// docs/architecture.md.
    #[doc = include_str!("../../docs/architecture.md")]
    pub struct Architecture;
    /// docs/shader-library.md.
    #[doc = include_str!("../../docs/shader-library.md")]
    pub struct ShaderLibrary;
    /// CHANGELOG.md.
    #[doc = include_str!("../../CHANGELOG.md")]
    pub struct Changelog;
}

pub use draw::lighting::{
    DrawValues, Lighting, LightingOptions, LitDraw, StagedDraw, VertexLayout, MAX_FRAMES_IN_FLIGHT,
};
pub use draw::pipeline::{
    Attribute, Blend, BlendColor, FaceArrays, LineStipple, MaterialArray, PolygonModes, PolygonOffset,
    PolygonStipple, RasterState, Specialize, Stencil, StencilFace, Target, VertexInput, MAX_VERTEX_BINDINGS,
};
pub use draw::pipeline_constants::PipelineConstants;
pub use draw::record::{Geometry, Topology};
pub use draw::texture::TextureBinding;
pub use draw::viewport::{gl_scissor, gl_viewport, ViewportError};
pub use error::{Error, LightingError, MeshError, Result, UnknownName};
pub use renderer::{
    Draw, FragmentPath, Frame, FrameStats, Mesh, PipelineStats, Pixels, Recording, Renderer, RendererOptions,
    Texture, Upload, MAX_DEFERRED_STATES,
};
