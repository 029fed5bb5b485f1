//! What the GPU sees of the GL state: the std140 layout of the per-draw uniform block, the
//! specialization constants, and the SPIR-V of every shader variant.

pub mod layout;
pub mod shaders;
