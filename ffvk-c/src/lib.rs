//! ffvk's C API (`include/ffvk.h`): for fixed-function emulation layers written in C or C++.
//!
//! Two objects:
//!
//! - [`FfvkContext`](gl::FfvkContext): GL's lighting state with GL's entry points, enums and
//!   errors (`ffvkLightfv`, `ffvkMaterialfv`, `ffvkGetError`, …). No Vulkan: a layer hands
//!   the application's calls on unchanged, and queries answer as GL does.
//! - [`FfvkRenderer`](render::FfvkRenderer): ffvk's pipelines on the caller's Vulkan device
//!   (loaded through the caller's `vkGetInstanceProcAddr`), recording a context's state as
//!   draws into the caller's command buffer. It never submits or waits.
//!
//! Every entry point catches panics (none unwinds into C), checks its pointers for null and
//! alignment (a misaligned pointer is refused as a null one is), and either sets GL's error
//! (state entry points, which return nothing in GL) or returns an
//! [`FfvkResult`](result::FfvkResult) with a message from `ffvkResultMessage`.

pub mod abi;
pub mod enums;
pub mod gl;
pub mod mesh;
pub mod query;
pub mod render;
/// Vertex layouts (a part of the renderer's API, `render::layout`).
pub use render::layout;
pub mod result;
pub mod setup;
pub mod shaders;
pub mod viewport;

/// Aliases that spell Vulkan's C types for the header. cbindgen does not emit them (the
/// header takes them from `<vulkan/vulkan.h>`); each is ABI-identical to the C type: ash's
/// handles and enums are `#[repr(transparent)]` over the C representation.
#[allow(non_camel_case_types)]
pub mod vk_types {
    use ffvk::ash::vk;
    /// `VkInstance`.
    pub type VkInstance = vk::Instance;
    /// `VkPhysicalDevice`.
    pub type VkPhysicalDevice = vk::PhysicalDevice;
    /// `VkDevice`.
    pub type VkDevice = vk::Device;
    /// `VkCommandBuffer`.
    pub type VkCommandBuffer = vk::CommandBuffer;
    /// `VkBuffer`.
    pub type VkBuffer = vk::Buffer;
    /// `VkImageView`.
    pub type VkImageView = vk::ImageView;
    /// `VkSampler`.
    pub type VkSampler = vk::Sampler;
    /// `VkPipelineCache`.
    pub type VkPipelineCache = vk::PipelineCache;
    /// `VkFormat`.
    pub type VkFormat = vk::Format;
    /// `VkSampleCountFlagBits`.
    pub type VkSampleCountFlagBits = vk::SampleCountFlags;
    /// `VkCullModeFlags`.
    pub type VkCullModeFlags = vk::CullModeFlags;
    /// `VkFrontFace`.
    pub type VkFrontFace = vk::FrontFace;
    /// `VkCompareOp`.
    pub type VkCompareOp = vk::CompareOp;
    /// `VkBlendFactor`.
    pub type VkBlendFactor = vk::BlendFactor;
    /// `VkBlendOp`.
    pub type VkBlendOp = vk::BlendOp;
    /// `VkIndexType`.
    pub type VkIndexType = vk::IndexType;
    /// `VkDeviceSize`.
    pub type VkDeviceSize = vk::DeviceSize;
    /// `VkPhysicalDeviceFeatures2`.
    pub type VkPhysicalDeviceFeatures2 = vk::PhysicalDeviceFeatures2<'static>;
    /// `VkViewport`.
    pub type VkViewport = vk::Viewport;
    /// `VkRect2D`.
    pub type VkRect2D = vk::Rect2D;
    /// `VkVertexInputBindingDescription`.
    pub type VkVertexInputBindingDescription = vk::VertexInputBindingDescription;
    /// `PFN_vkGetInstanceProcAddr` (nullable here, so a null one is refused, not called).
    pub type PFN_vkGetInstanceProcAddr = Option<vk::PFN_vkGetInstanceProcAddr>;
}
