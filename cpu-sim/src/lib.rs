//! aokit's CPU simulator: runs the very kernel functions of `aokit-shaders` over whole images
//! with rayon (images as slices, atomics as `AtomicU32`), and casts rays through a CPU BVH
//! (obvhs' compressed wide BVH) where the GPU would rasterize or trace.

pub mod adapters;
pub mod bvh;
pub mod gbuffer;
pub mod graph;
pub mod groundtruth;
pub mod gtao;
pub mod hybrid;
pub mod raymarch;
pub mod screen;
pub mod svao;

pub use bvh::{AnyHit, SceneBvh};
pub use gbuffer::{GBufferImage, Surfaces, ray_cast_gbuffer, ray_cast_second_layer};
pub use groundtruth::run_ground_truth;
pub use screen::{run_blur, run_vao};

/// Called with the number of rows finished since the last call (drives a progress bar).
pub type Progress<'a> = &'a (dyn Fn(u64) + Sync);

/// A progress callback that ignores progress.
pub fn no_progress(_: u64) {}
