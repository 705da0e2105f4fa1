//! aokit: the scenes, cameras and image output around the kernels in `aokit-shaders`, run on
//! the CPU (`aokit-cpu`) or on Vulkan (`aokit-vulkan`).

#[cfg(feature = "cli")]
pub mod cli;
pub mod export;
pub mod frame;
pub mod frontier;
pub mod metrics;
pub mod output;
pub mod path;
pub mod rays;
pub mod render;
pub mod report;
pub mod scene;
pub mod technique;
pub mod tune;
pub mod web;
