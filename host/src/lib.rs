//! aokit's Vulkan back-end: ash + gpu-allocator, headless. Runs the SPIR-V that the xtask built
//! from `aokit-shaders` (committed under `assets/spirv/`), so no Rust nightly is needed here.
//!
//! Knows devices, memory, pipelines and dispatch order — never kernel math.

mod buffer;
mod context;
mod descriptors;
mod gbuffer;
mod gtao;
pub mod manifest;
pub mod modules;
mod raytracing;
mod screen;
pub mod spirv_hash;
mod ssao;
mod svao;

pub use buffer::Buffer;
pub use context::{DeviceInfo, Gpu, GpuOptions};
pub use gbuffer::{GBufferVertex, RasterGBuffer, RasterSdPass};
pub use gtao::{GtaoOutput, GtaoPasses};
pub use raytracing::{GroundTruthPipeline, SceneAccel};
pub use screen::{ScreenOutput, ScreenPasses};
pub use ssao::{ScreenRayOutput, SsaoPipelines};
pub use svao::{RasterSdInput, SvaoOutput, SvaoPipelines};

/// Errors of the Vulkan back-end.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    #[error(
        "cannot load the Vulkan loader (libvulkan.so.1): {0}. Install a Vulkan driver, e.g. Mesa's lavapipe (`apt-get install mesa-vulkan-drivers libvulkan1`)"
    )]
    Loader(String),
    #[error("no Vulkan device found that supports Vulkan 1.3 with {0}")]
    NoDevice(String),
    #[error(
        "the Khronos validation layer was requested but is not installed (`apt-get install vulkan-validationlayers`)"
    )]
    NoValidationLayer,
    #[error("Vulkan call failed: {0}")]
    Vk(#[from] ash::vk::Result),
    #[error("GPU memory allocation failed: {0}")]
    Alloc(#[from] gpu_allocator::AllocationError),
    #[error("invalid input: {0}")]
    Input(String),
}
