//! aokit kernels — every formula written once, compiled to SPIR-V by rust-gpu and natively for
//! the CPU simulator (`aokit-cpu`).
//!
//! Folders mirror techniques: [`common`] (camera, hash, sequences, float-as-uint, normal codec),
//! [`vao`] (Volumetric AO, spec svao-raysd §4–§5), [`blur`] (cross-bilateral blur, svao-raysd §12) and
//! [`gbuffer`] (raster G-buffer entry points, svao-raysd §1), [`svao`] (the two-phase stenciled pipeline,
//! svao-raysd §3, §5, §9), [`raysd`] (ray-traced stochastic depth map, svao-raysd §7), [`raysvao`] (rays per flagged
//! sample, svao-raysd §10) and [`groundtruth`] (world-space ray-traced AO).
//!
//! Entry points are thin: they read storage-buffer slices and push constants and call pure
//! per-pixel functions, which the CPU simulator calls directly over the same slices.
#![cfg_attr(target_arch = "spirv", no_std)]
// `core::intrinsics::round_ties_even_f32`: GLSL.std.450 RoundEven (no stable `core` path).
#![cfg_attr(target_arch = "spirv", feature(core_intrinsics))]
#![cfg_attr(target_arch = "spirv", allow(internal_features))]
// `asm!`: GLSL.std.450 InverseSqrt and Fma (`Lanes::inverse_sqrt`, `Lanes::mul_add`), and
// `spirv_std::ray_query!` expands one in the ray-query variants.
#![cfg_attr(target_arch = "spirv", feature(asm_experimental_arch))]
#![allow(clippy::too_many_arguments)]

pub use spirv_std::glam;

/// Declares an entry point's interface from its signature ([`kernel`](mod@kernel)).
pub use aokit_contract_derive::kernel;

pub mod adapters;
pub mod blur;
pub mod common;
#[cfg(not(target_arch = "spirv"))]
pub mod contract;
#[cfg(not(target_arch = "spirv"))]
pub mod engine;
pub mod gbuffer;
#[cfg(not(target_arch = "spirv"))]
pub mod graph;
pub mod groundtruth;
pub mod gtao;
pub mod halfres;
pub mod hybrid;
#[cfg(not(target_arch = "spirv"))]
pub mod kernel;
pub mod rastersd;
pub mod raymarch;
pub mod raysd;
pub mod raysvao;
pub mod svao;
#[cfg(not(target_arch = "spirv"))]
pub mod technique;
#[cfg(not(target_arch = "spirv"))]
pub mod techniques;
pub mod temporal;
pub mod vao;
pub mod vbao;
pub mod vbaosd;
