//! Poisson-disk ray-marched SSAO on the CPU (spec gtao-raymarch-hybrid §3): the shader crate's
//! per-pixel function over the full target.

use aokit_shaders::glam::{Vec2, uvec2};
use aokit_shaders::raymarch::{RaymarchParams, raymarch_pixel};
use rayon::prelude::*;

/// Visibility, denoiser terms and packed edges per pixel of the full target.
pub fn run_raymarch(
    params: &RaymarchParams,
    depth: &[f32],
    normals: &[u32],
    kernel: &[Vec2],
) -> (Vec<f32>, Vec<u32>, Vec<u32>) {
    let size = params.view.size();
    let pixels: Vec<_> = (0..size.y)
        .into_par_iter()
        .flat_map_iter(|y| (0..size.x).map(move |x| uvec2(x, y)))
        .map(|p| raymarch_pixel(params, depth, normals, kernel, p))
        .collect();
    let ao = pixels.iter().map(|o| o.ao).collect();
    let terms = pixels.iter().map(|o| o.term).collect();
    let edges = pixels.iter().map(|o| o.edges).collect();
    (ao, terms, edges)
}
