//! Pipelines per lighting mode, specialization key and raster state; the per-draw state
//! memory; the recording of draws; the texture a draw samples ([`texture`]); and
//! [`lighting::Lighting`], which puts them together for
//! a caller's device and command buffers.

mod formats;
pub mod gl_primitives;
pub mod lighting;
mod lit;
mod options;
pub mod pipeline;
pub(crate) mod pipeline_constants;
mod raster;
mod raster_device;
pub mod record;
mod ring;
mod stipple;
mod target;
pub mod texture;
mod variants;
mod vertex_input;
pub mod viewport;
