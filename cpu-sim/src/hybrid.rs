//! Hybrid screen + world-ray AO on the CPU (spec gtao-raymarch-hybrid §4): the shader crate's
//! per-pixel function with its world rays answered by the BVH (alpha test included).

use crate::groundtruth::BvhOcclusion;
use crate::{SceneBvh, Surfaces};
use aokit_shaders::common::gbuffer_read::GBufferSlices;
use aokit_shaders::glam::uvec2;
use aokit_shaders::hybrid::{HybridFrame, hybrid_pixel};
use rayon::prelude::*;

/// Blended visibility, denoiser terms and packed edges per pixel of the full target, and the
/// world rays traced.
pub fn run_hybrid(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    frame: &HybridFrame,
    depth: &[f32],
    normals: &[u32],
) -> (Vec<f32>, Vec<u32>, Vec<u32>, u64) {
    let size = frame.camera.view.size();
    let gbuffer = GBufferSlices { depth, normals, width: size.x };
    let pixels: Vec<_> = (0..size.y)
        .into_par_iter()
        .flat_map_iter(|y| (0..size.x).map(move |x| uvec2(x, y)))
        .map_init(|| BvhOcclusion { bvh, alpha: surfaces.alpha() }, |rays, p| hybrid_pixel(&gbuffer, frame, p, rays))
        .collect();
    let ao = pixels.iter().map(|o| o.ao).collect();
    let terms = pixels.iter().map(|o| o.term).collect();
    let edges = pixels.iter().map(|o| o.edges).collect();
    let rays = pixels.iter().map(|o| o.rays as u64).sum();
    (ao, terms, edges, rays)
}
