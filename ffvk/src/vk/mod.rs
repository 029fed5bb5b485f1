//! A thin, owned layer over `ash`: every object holds an `Arc` of what it was made from and
//! frees itself in `Drop`, so a child can never outlive its device or instance.

pub mod device;
pub mod instance;
pub mod memory;
pub mod objects;
pub mod resources;
mod supported;

pub use device::{Device, DeviceInfo, EnabledFeatures, MemoryChoice};
pub use instance::{Instance, Validation, ValidationSink};
pub use memory::{MemoryUsage, MemoryUse};
pub use resources::{Buffer, Image};
