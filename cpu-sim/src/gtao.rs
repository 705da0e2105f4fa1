//! XeGTAO's passes on the CPU (spec gtao-raymarch-hybrid §2.3–§2.7): the shader crate's
//! per-texel and per-pixel functions over whole buffers, in the GPU's dispatch order.

use aokit_shaders::glam::{UVec2, uvec2};
use aokit_shaders::gtao::{
    GtaoParams, MIP_LEVELS, denoise_pixel, gtao_pixel, mip_offset, mip_size, normal_from_depth, prefilter_texel,
};
use rayon::prelude::*;

/// Evaluate `f` for every pixel of a `size` image in parallel rows.
pub fn per_pixel<T: Send + Copy + Default>(size: UVec2, f: impl Fn(UVec2) -> T + Sync) -> Vec<T> {
    let mut out = vec![T::default(); (size.x * size.y) as usize];
    out.par_chunks_mut(size.x as usize).enumerate().for_each(|(y, row)| {
        for (x, v) in row.iter_mut().enumerate() {
            *v = f(uvec2(x as u32, y as u32));
        }
    });
    out
}

/// PrefilterDepths: the packed 5-level working-depth MIP chain.
pub fn run_prefilter(params: &GtaoParams, depth: &[f32]) -> Vec<f32> {
    let full = params.view.size();
    let mut mips = vec![0.0f32; mip_offset(full, MIP_LEVELS)];
    for level in 0..MIP_LEVELS {
        let p = GtaoParams { pass: level, ..*params };
        let level_texels = per_pixel(mip_size(full, level), |t| prefilter_texel(&p, depth, &mips, t));
        let at = mip_offset(full, level);
        mips[at..at + level_texels.len()].copy_from_slice(&level_texels);
    }
    mips
}

/// Pass 0: encoded view normals from depth.
pub fn run_normals(params: &GtaoParams, depth: &[f32]) -> Vec<u32> {
    per_pixel(params.view.size(), |p| normal_from_depth(params, depth, p))
}

/// MainPass: AO terms (0–255) and packed edges per pixel of the full target.
pub fn run_main(params: &GtaoParams, mips: &[f32], normals: &[u32]) -> (Vec<u32>, Vec<u32>) {
    let both = per_pixel(params.view.size(), |p| {
        let o = gtao_pixel(params, mips, normals, p);
        (o.term, o.edges)
    });
    both.into_iter().unzip()
}

/// The denoise passes; returns the visibility per pixel (full target).
pub fn run_denoise(params: &GtaoParams, terms: &[u32], edges: &[u32]) -> Vec<f32> {
    let mut current = terms.to_vec();
    for pass in 0..params.denoise_passes.max(1) {
        let p = GtaoParams { pass, ..*params };
        current = per_pixel(params.view.size(), |q| denoise_pixel(&p, &current, edges, q).term);
    }
    current.iter().map(|&t| t as f32 / 255.0).collect()
}
