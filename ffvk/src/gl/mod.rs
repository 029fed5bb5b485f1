//! The GL side: the fixed-function lighting state with its GL entry points ([`state`]) and
//! the classic named materials ([`presets`]); the texture unit, texture images and sampling
//! ([`texture`]). Nothing here touches Vulkan.

pub mod errors;
pub mod presets;
pub mod state;
pub mod texture;
