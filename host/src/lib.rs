//! aokit's Vulkan back-end: ash + gpu-allocator, on its own device or the caller's. Runs the
//! SPIR-V that the xtask built from `aokit-shaders` (committed under `assets/spirv/`), so no
//! Rust nightly is needed here.
//!
//! [`AoContext`] executes a technique's pass graph into a command buffer; the raster G-buffer
//! ([`RasterGBuffer`]), the acceleration structure ([`SceneAccel`]) and the engine adapters
//! ([`Adapters`]) feed it. Knows devices, memory, pipelines and barriers — never kernel math or
//! a technique's order of passes.

mod adapters;
pub mod atomic_file;
mod buffer;
mod compute;
mod context;
mod descriptors;
mod effect;
mod gbuffer;
mod graph;
mod image;
pub mod manifest;
pub mod modules;
mod raytracing;
pub mod spirv_hash;
#[cfg(feature = "reflect")]
pub mod wgsl;

pub use adapters::{Adapters, AoImage, EngineImage};
pub use aokit_shaders::glam;
pub use aokit_shaders::graph::RtMode;
pub use aokit_shaders::technique::Technique;
pub use aokit_shaders::temporal::settings::TemporalSettings;
pub use buffer::Buffer;
pub use context::{DeviceInfo, ExternalDevice, Gpu, GpuOptions, HIDE_EXTENSIONS_VAR};
pub use effect::{
    AoEffect, AoError, AoFrame, AoScene, AoSettings, DepthConvention, EngineCamera, SceneGeometry, engine_camera,
};
pub use gbuffer::{GBufferVertex, RasterFrame, RasterGBuffer};
pub use graph::{AoContext, EngineFrame, FRAMES_IN_FLIGHT, GpuInputs, RasterScene, check_device};
pub use image::Image2d;
pub use raytracing::SceneAccel;

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
        "no Vulkan driver: the Vulkan loader found no installable client driver (ICD). Install one, e.g. Mesa's lavapipe (`apt-get install mesa-vulkan-drivers`), or check VK_ICD_FILENAMES / VK_DRIVER_FILES"
    )]
    NoDriver,
    /// The device lacks what a technique needs (named in the message).
    #[error("{0}")]
    Missing(String),
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
