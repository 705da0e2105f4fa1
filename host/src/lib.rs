//! aokit's Vulkan back-end: ambient occlusion as one effect on an engine's own Vulkan device.
//!
//! An engine uses [`AoEffect`]: made from its device ([`ExternalDevice`]) and [`AoSettings`]
//! (a [`Technique`] at a preset first), then `resize`, `set_settings` and `record` into the
//! engine's command buffer with the frame's images and matrices ([`AoFrame`]); see
//! [`effect`](AoEffect) for the whole integration and `docs/vulkan.md` for the barriers. It runs
//! the SPIR-V that the xtask built from `aokit-shaders` (committed under `assets/spirv/` and
//! embedded here), so depending on this crate needs no Rust nightly.
//!
//! # Features
//!
//! * `harness`: aokit's own executor underneath the effect — a headless device (`Gpu`),
//!   pass graphs on aokit's buffers (`AoContext`), its raster G-buffer and acceleration
//!   structures. The `aokit` command-line tool and the tests use it; an engine never needs it.
//! * `testing`: hooks for aokit's own tests (descriptor-pool counts, a provoked validation
//!   error), on top of `harness`.
#![warn(missing_docs)]
#![cfg_attr(not(feature = "harness"), allow(dead_code, unused_imports))]

mod adapters;
mod buffer;
mod compute;
mod context;
mod descriptors;
mod effect;
mod gbuffer;
mod graph;
mod image;
/// The committed SPIR-V, embedded (for aokit's own tests).
#[cfg(feature = "testing")]
pub mod modules;
#[cfg(not(feature = "testing"))]
mod modules;
mod raytracing;

pub use adapters::{AoImage, EngineImage};
pub use aokit_shaders::common::alpha::AlphaMaskHeader;
pub use aokit_shaders::glam;
pub use aokit_shaders::graph::RtMode;
pub use aokit_shaders::technique::Technique;
pub use aokit_shaders::temporal::settings::TemporalSettings;
pub use context::ExternalDevice;
pub use effect::{AoEffect, AoError, AoFrame, AoScene, AoSettings, DepthConvention, SceneGeometry};

/// What feature `harness` makes public; the effect uses it either way.
mod harness {
    pub use crate::adapters::Adapters;
    pub use crate::buffer::Buffer;
    pub use crate::context::{DeviceInfo, Gpu, GpuOptions, HIDE_EXTENSIONS_VAR};
    pub use crate::effect::{EngineCamera, engine_camera};
    pub use crate::gbuffer::{GBufferVertex, RasterFrame, RasterGBuffer};
    pub use crate::graph::{AoContext, EngineFrame, FRAMES_IN_FLIGHT, GpuInputs, RasterScene, check_device};
    pub use crate::image::Image2d;
    pub use crate::raytracing::SceneAccel;
}
#[cfg(feature = "harness")]
pub use harness::*;
#[cfg(not(feature = "harness"))]
#[allow(unused_imports)]
pub(crate) use harness::*;

/// Errors of the Vulkan back-end.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    #[error(
        "cannot load the Vulkan loader (libvulkan.so.1): {0}. Install a Vulkan driver, e.g. Mesa's lavapipe (`apt-get install mesa-vulkan-drivers libvulkan1`)"
    )]
    /// The Vulkan loader library could not be loaded.
    Loader(String),
    /// No device, or not the device, has what was asked for (named in the message).
    #[error("no Vulkan device found that supports Vulkan 1.3 with {0}")]
    NoDevice(String),
    #[error(
        "no Vulkan driver: the Vulkan loader found no installable client driver (ICD). Install one, e.g. Mesa's lavapipe (`apt-get install mesa-vulkan-drivers`), or check VK_ICD_FILENAMES / VK_DRIVER_FILES"
    )]
    /// The loader found no Vulkan driver.
    NoDriver,
    /// The device lacks what a technique needs (named in the message).
    #[error("{0}")]
    Missing(String),
    #[error(
        "the Khronos validation layer was requested but is not installed (`apt-get install vulkan-validationlayers`)"
    )]
    /// Validation was requested but the Khronos layer is not installed.
    NoValidationLayer,
    /// A Vulkan call returned an error.
    #[error("Vulkan call failed: {0}")]
    Vk(#[from] ash::vk::Result),
    /// gpu-allocator could not allocate.
    #[error("GPU memory allocation failed: {0}")]
    Alloc(#[from] gpu_allocator::AllocationError),
    /// An argument aokit cannot use (named in the message).
    #[error("invalid input: {0}")]
    Input(String),
}
