//! What the GPU sees of the GL state: the std140 layout of the state block, the per-draw
//! record read as vertex attributes, the specialization constants, and the SPIR-V of every
//! shader variant.
//!
//! This is the lower tier of the embedding API, for renderers that build their own pipelines
//! from ffvk's shaders. **It may change before 1.0**: the other lighting models will extend
//! the block and the variants.
//!
//! The interface of every variant in [`shaders::VARIANTS`]:
//! - entry point `main` in both stages;
//! - vertex inputs: location 0 position (`vec4`), 1 normal (`vec3`), 2 color (`vec4`), in the
//!   `*_textured` variants 3 texture coordinates (`vec4`), each the caller's array or the
//!   record's current value ([`crate::VertexInput::attributes`] says which); locations 4-18 the
//!   draw's [`layout::DrawRecord`] matrices and materials (`vec4`s) and 19-20 its shininesses
//!   (`float`s), read per instance: ffvk binds one buffer of records
//!   ([`layout::record_stride`] apart) and names a draw's by its `firstInstance`;
//! - one uniform block, [`layout::StateBlock`], at descriptor set 0, binding 0, read by both
//!   stages ([`crate::draw::pipeline::set_descriptor_set`] rewrites the set of a module);
//!   ffvk binds it as `UNIFORM_BUFFER_DYNAMIC`, a plain `UNIFORM_BUFFER` works the same;
//! - in the `*_textured` variants, a `sampler2D` (combined image sampler) at set 1, binding 0,
//!   read by the fragment stage (moved with the block: set_descriptor_set adds its offset);
//! - in the `fragment` variants (and their `_textured` builds), the
//!   draw's [`layout::DrawRecord`] again, as a std140 uniform block `Record` at set 2, binding
//!   0, read by the fragment stage (its materials; ffvk binds the record buffer there as
//!   `UNIFORM_BUFFER_DYNAMIC` at the record's offset); the `fragment_small` variants have no
//!   set 2 and pass the materials from the vertex stage as flat varyings (locations 5-13), for
//!   draws of fewer than [`crate::draw::pipeline::SMALL_DRAW_VERTICES`] vertices;
//! - no push constants;
//! - the specialization constants of [`layout::SpecConstant`] (`int`, constant_id 0-14, -1 =
//!   read the uniform); [`layout::SpecKey::for_state`] gives a state's values;
//! - the `flat` variants need the last-vertex provoking convention
//!   (`VK_EXT_provoking_vertex`), as GL's flat shading takes each triangle's last vertex;
//! - the projection in the block is GL's premultiplied by [`layout::VK_FROM_GL_CLIP`], which
//!   flips y, so GL's counter-clockwise front faces are Vulkan's `COUNTER_CLOCKWISE`.

pub mod layout;
pub mod shaders;
