//! ffvk: the OpenGL 2.1 fixed-function lighting equation, verbatim, on Vulkan.
//!
//! Modules follow the data: GL state ([`gl`]), its GPU layout ([`layout`]), shaders and
//! pipelines ([`shaders`], [`pipeline`]), the render path ([`vk`], [`renderer`]), and the
//! CPU reference of the same equation ([`reference`]).

pub mod bench;
pub mod compare;
pub mod demo;
pub mod error;
pub mod explain;
pub mod gl;
#[cfg(feature = "osmesa")]
pub mod gl_reference;
pub mod gltf_load;
pub mod images;
pub mod layout;
pub mod mesh;
pub mod pipeline;
pub mod presets;
pub mod reference;
pub mod regress;
pub mod renderer;
pub mod scene;
pub mod shaders;
pub mod teapot;
pub mod vk;

pub use error::{Error, Result};
pub use pipeline::Specialize;
pub use renderer::{Draw, Frame, FrameStats, Mesh, PipelineStats, Renderer, RendererOptions};
