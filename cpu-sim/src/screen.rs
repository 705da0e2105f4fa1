//! Screen-space passes over whole images: each output pixel calls the same per-pixel kernel
//! function that the SPIR-V entry point calls.

use crate::Progress;
use aokit_shaders::blur::{BlurParams, blur_pixel};
use aokit_shaders::common::gbuffer_read::GBufferSlices;
use aokit_shaders::glam::{UVec2, uvec2};
use aokit_shaders::vao::{VaoParams, vao_pixel};
use rayon::prelude::*;

/// Run `kernel` for every inner pixel of a full-target image, in parallel over rows. Guard-band
/// pixels keep `fill`.
fn for_inner_pixels(
    size: UVec2,
    guard: u32,
    fill: f32,
    progress: Progress,
    kernel: impl Fn(UVec2) -> f32 + Sync,
) -> Vec<f32> {
    let mut out = vec![fill; (size.x * size.y) as usize];
    out.par_chunks_mut(size.x as usize).enumerate().for_each(|(y, row)| {
        let y = y as u32;
        if y < guard || y + guard >= size.y {
            return;
        }
        for x in guard..size.x - guard {
            row[x as usize] = kernel(uvec2(x, y));
        }
        progress(1);
    });
    out
}

/// Plain VAO (spec svao-raysd §4–§5) over the inner image. Returns the full-target AO buffer
/// (guard band = 1).
pub fn run_vao(params: &VaoParams, depth: &[f32], normals: &[u32], progress: Progress) -> Vec<f32> {
    let size = params.view.size();
    let gbuffer = GBufferSlices { depth, normals, width: size.x };
    for_inner_pixels(size, params.view.guard, 1.0, progress, |p| vao_pixel(&gbuffer, params, p))
}

/// One direction (`params.direction`) of the cross-bilateral blur (spec §12).
pub fn run_blur_direction(params: &BlurParams, ao: &[f32], depth: &[f32]) -> Vec<f32> {
    for_inner_pixels(params.view.size(), params.view.guard, 1.0, &crate::no_progress, |px| {
        blur_pixel(params, ao, depth, px)
    })
}

/// The two-pass cross-bilateral blur (spec §12): horizontal then vertical.
pub fn run_blur(params: &BlurParams, ao: &[f32], depth: &[f32]) -> Vec<f32> {
    let pass = |direction: UVec2, input: &[f32]| run_blur_direction(&BlurParams { direction, ..*params }, input, depth);
    let horizontal = pass(uvec2(1, 0), ao);
    pass(uvec2(0, 1), &horizontal)
}
