//! aokit's Vulkan back-end: ambient occlusion as one effect on an engine's own Vulkan device, in
//! four verbs — [`AoEffect::new`], [`AoEffect::resize`], [`AoEffect::set_settings`] and
//! [`AoEffect::record`] — and one settings struct, [`AoSettings`] (a [`Technique`] at one of its
//! presets first).
//!
//! The engine hands its depth image with its convention, optionally its view-space normals, the
//! AO output image, and its projection and view matrices ([`AoFrame`]); the effect derives
//! aokit's camera from the matrices, rebuilds the technique's pass graph (a few small vectors)
//! only when the settings, the size or the frame's camera or index changed (a moving camera is
//! just a new frame), keeps its pipelines and buffers across frames and records everything into
//! the engine's command buffer: no submit, no wait, no host round trip. Everything it made is
//! freed when it is dropped: drop it (and every [`AoScene`]) once the device finished the frames
//! it recorded, and before the engine destroys the device.
//!
//! ```no_run
//! use aokit_vulkan::glam::Mat4;
//! use aokit_vulkan::{AoEffect, AoFrame, AoImage, AoSettings, DepthConvention, EngineImage, ExternalDevice, Technique};
//! use ash::vk;
//!
//! # struct Engine { device: ExternalDevice, cmd: vk::CommandBuffer, depth_view: vk::ImageView, ao_view: vk::ImageView }
//! // `projection`: e.g. glam's `Mat4::perspective_infinite_reverse_rh` with Y flipped;
//! // `view`: world → view, e.g. `Mat4::look_at_rh`.
//! // Once: a technique at one of its presets, on the engine's device and queue.
//! fn setup(device: ExternalDevice) -> Result<AoEffect, Box<dyn std::error::Error>> {
//!     let settings = AoSettings::new(Technique::preset("gtao", "high")?).radius(0.5);
//!     let mut ao = AoEffect::new(device, settings)?;
//!     ao.resize(1920, 1080)?;
//!     Ok(ao)
//! }
//!
//! // Every frame, after the depth pass, into the engine's command buffer (which the engine then
//! // submits; `ao` lives on across frames).
//! fn frame(ao: &mut AoEffect, engine: &Engine, projection: Mat4, view: Mat4) -> Result<(), Box<dyn std::error::Error>> {
//!     let Engine { cmd, depth_view, ao_view, .. } = *engine;
//!     let depth = EngineImage { view: depth_view, layout: vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL };
//!     let output = AoImage { view: ao_view, format: vk::Format::R8_UNORM };
//!     ao.record(cmd, &AoFrame::new(depth, DepthConvention::ReversedInfinite, output, projection, view))?;
//!     Ok(())
//! }
//! ```
//!
//! The images' formats, usages and layouts and the barriers around `record` are in
//! `docs/vulkan.md` and on [`EngineImage`] / [`AoImage`]; the device's extensions and features
//! on [`ExternalDevice`]; ray-traced techniques take the scene as an [`AoScene`]
//! ([`AoEffect::build_scene`], or the engine's own TLAS with [`AoEffect::scene_from_tlas`]).
//!
//! It runs the SPIR-V that the xtask built from `aokit-shaders` (committed under
//! `assets/spirv/` and embedded here), so depending on this crate needs no Rust nightly.
//!
//! # Features
//!
//! * `harness`: aokit's own executor underneath the effect — a headless device (`Gpu`),
//!   pass graphs on aokit's buffers (`AoContext`), its raster G-buffer and acceleration
//!   structures. The `aokit` command-line tool and the tests use it; an engine never needs it.
//! * `testing`: hooks for aokit's own tests (descriptor-pool counts, a provoked validation
//!   error), on top of `harness`.
#![warn(missing_docs)]
#![cfg_attr(not(feature = "harness"), allow(dead_code))]

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
pub use aokit_shaders::technique::{Resolution, Technique};
pub use aokit_shaders::temporal::settings::TemporalSettings;
/// The ash (Vulkan bindings) this crate's signatures use: 0.38.
pub use ash;
pub use context::ExternalDevice;
pub use effect::{AoEffect, AoError, AoFrame, AoScene, AoSettings, DepthConvention, SceneGeometry};
pub use graph::FRAMES_IN_FLIGHT;
#[cfg(feature = "harness")]
pub use graph::{ENGINE_DEPTH, ENGINE_NORMALS};
#[cfg(feature = "testing")]
pub use graph::{FreeAudit, Sabotage};

/// What feature `harness` makes public; the effect uses it either way.
#[cfg_attr(not(feature = "harness"), allow(unused_imports))]
mod harness {
    pub use crate::adapters::Adapters;
    pub use crate::buffer::Buffer;
    pub use crate::context::{DeviceInfo, Gpu, GpuOptions, HIDE_EXTENSIONS_VAR, MAX_STORAGE_BUFFER_RANGE_VAR};
    pub use crate::effect::{EngineCamera, engine_camera};
    pub use crate::gbuffer::{GBufferVertex, RasterFrame, RasterGBuffer};
    pub use crate::graph::{AoContext, EngineFrame, GpuInputs, RasterScene, check_device};
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
    /// gpu-allocator could not allocate (its message).
    #[error("GPU memory allocation failed: {0}")]
    Alloc(String),
    /// An argument aokit cannot use (named in the message).
    #[error("invalid input: {0}")]
    Input(String),
}

impl From<gpu_allocator::AllocationError> for GpuError {
    fn from(e: gpu_allocator::AllocationError) -> GpuError {
        GpuError::Alloc(e.to_string())
    }
}
