//! Separable depth-aware cross-bilateral blur, HBAO+ style (spec svao-raysd §12).

#[cfg(not(target_arch = "spirv"))]
pub mod graph;

// f32 methods on SPIR-V (`abs`, `exp2`) come from `Lanes`.

use crate::common::ViewParams;
use crate::common::lanes::Lanes;
use crate::common::math::is_valid_depth;
use crate::common::read::write;
use crate::glam::{IVec2, UVec2, UVec3};
use spirv_std::spirv;

/// Kernel radius `K` (spec svao-raysd §12).
pub const BLUR_RADIUS: i32 = 4;
/// Gaussian falloff `φ = 1/(2σ²)` with `σ = (K+1)/2 = 2.5` (spec svao-raysd §12).
pub const BLUR_FALLOFF: f32 = 0.08;

/// Push constants of one blur pass.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct BlurParams {
    /// Projection of the full target.
    pub view: ViewParams,
    /// Pass direction: (1, 0) horizontal, (0, 1) vertical.
    pub direction: UVec2,
    /// Depth sharpness (spec svao-raysd §12: 16).
    pub sharpness: f32,
    pub _pad: u32,
}

/// Sample coordinate clamped to the inner image, `[g, res − g − 1]` per axis (spec svao-raysd §12 clamps
/// the uv to the inner pixel-centre rectangle).
#[inline]
fn clamp_inner(view: &ViewParams, p: IVec2) -> UVec2 {
    let g = view.guard as i32;
    let size = view.size().as_ivec2();
    UVec2::new(p.x.max(g).min(size.x - g - 1) as u32, p.y.max(g).min(size.y - g - 1) as u32)
}

/// One output pixel of one blur direction (spec svao-raysd §12): slope-corrected depth differences
/// `Δ = |z_d − s·d − z0|·sharpness·12/z0`, weights `w = 2^(−d²·φ − Δ²)`, result
/// `(a0 + Σ w·a_d)/(1 + Σ w)`; the slope is the smaller-magnitude one-sided difference, negated
/// for the negative side ("better slope").
#[inline]
pub fn blur_pixel(params: &BlurParams, ao: &[f32], depth: &[f32], p: UVec2) -> f32 {
    blur_lanes::<f32>(params, ao, depth, p)
}

/// [`blur_pixel`] for one pixel (`L = f32`) or `L::LANES` pixels (lane `i` at `p + i·(1, 0)`,
/// clamped to the inner image).
#[inline]
pub fn blur_lanes<L: Lanes>(params: &BlurParams, ao: &[f32], depth: &[f32], p: UVec2) -> L {
    let view = params.view;
    let dir = params.direction.as_ivec2();
    let at = move |offset: i32| {
        move |lane: usize| view.index(clamp_inner(&view, p.as_ivec2() + IVec2::new(lane as i32, 0) + dir * offset))
    };
    let a0 = L::gather(ao, at(0));
    let z0 = L::gather(depth, at(0));
    let slope_left = z0 - L::gather(depth, at(-1));
    let slope_right = L::gather(depth, at(1)) - z0;
    let slope = L::select(slope_left.abs().lt(slope_right.abs()), slope_left, slope_right);
    let scale = L::splat(params.sharpness * 12.0) / z0;
    let mut sum = a0;
    let mut weights = L::splat(1.0);
    let mut d = 1;
    while d <= BLUR_RADIUS {
        let df = d as f32;
        let mut side = -1;
        while side <= 1 {
            let offset = side * d;
            let delta = (L::gather(depth, at(offset)) - slope * (side as f32) * df - z0).abs() * scale;
            let w = (L::splat(-df * df * BLUR_FALLOFF) - delta * delta).exp2();
            let take = w.gt(L::splat(0.0));
            sum = L::select(take, sum + w * L::gather(ao, at(offset)), sum);
            weights = L::select(take, weights + w, weights);
            side += 2;
        }
        d += 1;
    }
    L::select(is_valid_depth(z0, view.far), sum / weights, a0)
}

#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "blur_main"))]
pub fn blur_main(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &BlurParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] ao_in: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] ao_out: &mut [f32],
) {
    let p = id.truncate() + params.view.guard;
    if !params.view.is_inner(p) {
        return;
    }
    unsafe { write(ao_out, params.view.index(p), blur_pixel(params, ao_in, depth, p)) };
}
