//! The contract of `assets/`, for the xtask that writes it and the tests and CLI commands that
//! read it back: the SPIR-V manifest (`assets/spirv/manifest.json`) reflected from the modules
//! and completed from the kernels' declarations, the C header (`assets/include/aokit.h`), the
//! WGSL translations (`assets/wgsl/`), the hash of the shader sources the modules were built
//! from, and the atomic file writes all of it goes through.
//!
//! Nothing here is needed to run the kernels: an engine links `aokit-vulkan` (or reads
//! `assets/` directly), never this crate. Feature `reflect` adds what needs naga (reading the
//! SPIR-V, writing the WGSL): the xtask and the tests use it; the CLI reads the committed files
//! without it.

pub mod atomic_file;
pub mod c_constants;
pub mod constants;
pub mod expr;
pub mod graphs;
pub mod manifest;
pub mod spirv_hash;
#[cfg(feature = "reflect")]
pub mod wgsl;

/// The committed `assets/spirv/manifest.json`.
pub const MANIFEST_JSON: &str = include_str!("../../../assets/spirv/manifest.json");
