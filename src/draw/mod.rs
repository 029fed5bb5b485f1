//! Pipelines per lighting mode and specialization key, and the recording of draws.

pub mod pipeline;
pub mod record;
