//! ffvk: the OpenGL 2.1 fixed-function lighting equation, verbatim, on Vulkan.

pub mod gl;
pub mod mesh;
