//! Poisson-disk ray-marched SSAO on the CPU (spec gtao-raymarch-hybrid §3): the shader crate's
//! per-pixel setup and finish per pixel, its directions' marches on `CPU_LANES` pixels at once.

use crate::screen::lane_pixel;
use aokit_shaders::common::lanes::{CPU_LANES, CpuLanes, Lanes};
use aokit_shaders::glam::{UVec2, Vec2};
use aokit_shaders::raymarch::{
    MarchOrigin, RaymarchParams, RaymarchPixel, raymarch_finish, raymarch_setup, raymarch_sum, unshaded,
};

/// Visibility, denoiser terms and packed edges per pixel of the full target.
pub fn run_raymarch(
    params: &RaymarchParams,
    depth: &[f32],
    normals: &[u32],
    kernel: &[Vec2],
) -> (Vec<f32>, Vec<u32>, Vec<u32>) {
    let size = params.view.size();
    let empty = RaymarchPixel { ao: 1.0, term: 0, edges: 0 };
    let mut pixels = vec![empty; (size.x * size.y) as usize];
    crate::screen::tiled_lanes(
        &mut pixels,
        size.x,
        0..size.x,
        0..size.y,
        CPU_LANES as u32,
        &crate::no_progress,
        |p, out| raymarch_lanes(params, depth, normals, kernel, p, out),
    );
    let ao = pixels.iter().map(|o| o.ao).collect();
    let terms = pixels.iter().map(|o| o.term).collect();
    let edges = pixels.iter().map(|o| o.edges).collect();
    (ao, terms, edges)
}

/// [`aokit_shaders::raymarch::raymarch_pixel`] for `out.len()` ≤ [`CPU_LANES`] consecutive pixels of a row
/// from `first`. Missing lanes repeat the last pixel; pixels without a usable depth borrow a
/// marching lane's origin and are discarded.
pub fn raymarch_lanes(
    params: &RaymarchParams,
    depth: &[f32],
    normals: &[u32],
    kernel: &[Vec2],
    first: UVec2,
    out: &mut [RaymarchPixel],
) {
    let setups: [(u32, Option<MarchOrigin>); CPU_LANES] =
        core::array::from_fn(|i| raymarch_setup(params, depth, normals, lane_pixel(first, i, out.len())));
    let any = setups.iter().find_map(|s| s.1);
    let sum = any.map(|any| {
        let lanes = MarchOrigin::<CpuLanes>::from_lanes(&setups.map(|s| s.1.unwrap_or(any)));
        raymarch_sum(params, depth, normals, kernel, &lanes)
    });
    for (i, o) in out.iter_mut().enumerate() {
        *o = match (setups[i], sum) {
            ((edges, Some(_)), Some(sum)) => raymarch_finish(params, kernel, edges, sum.lane(i)),
            ((edges, _), _) => unshaded(edges),
        };
    }
}
