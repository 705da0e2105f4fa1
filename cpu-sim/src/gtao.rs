//! XeGTAO's passes on the CPU (spec gtao-raymarch-hybrid §2.3–§2.7): the shader crate's
//! per-texel and per-pixel functions over whole buffers, in the GPU's dispatch order.

use crate::screen::lanes_of_run;
use aokit_shaders::common::lanes::{CPU_LANES, CpuLanes, Lanes};
use aokit_shaders::common::read::TexelBuffer;
use aokit_shaders::glam::{UVec2, vec3};
use aokit_shaders::gtao::denoise::{denoise_lanes, is_last_pass};
use aokit_shaders::gtao::main_pass::{final_visibility, finish_pixel, pixel_setup, slices_visibility};
use aokit_shaders::gtao::prefilter::{mip_falloff, mip_filter, prefilter_far, working_value};
use aokit_shaders::gtao::{
    GtaoParams, MIP_LEVELS, denoise_pixel, mip_offset, mip_size, normal_from_depth, prefilter_texel,
};
use aokit_shaders::svao::SvaoParams;
use aokit_shaders::vbao::VbaoParams;
use aokit_shaders::vbao::kernel::{ConstantThickness, Occupancy, vbao_term, visibility_with};
use aokit_shaders::vbaosd::{SdLayers, request_pixel};
use core::sync::atomic::AtomicU32;
use rayon::prelude::*;

/// Evaluate `f` for every pixel of a `size` image in parallel [`crate::screen::tiled`] bands.
pub fn per_pixel<T: Send + Copy + Default>(size: UVec2, f: impl Fn(UVec2) -> T + Sync) -> Vec<T> {
    let mut out = vec![T::default(); (size.x * size.y) as usize];
    crate::screen::tiled(&mut out, size.x, 0..size.x, 0..size.y, &crate::no_progress, |p, v| *v = f(p));
    out
}

/// PrefilterDepths: the packed 5-level working-depth MIP chain level by level (each level in
/// parallel [`crate::screen::tiled`] bands from the level before it), as [`prefilter_texel`]
/// defines it: the reference the two block dispatches of the GPU and of cpu-sim's graph
/// ([`prefilter_pass`]) are tested against.
pub fn run_prefilter(params: &GtaoParams, depth: &[f32]) -> Vec<f32> {
    let full = params.view.size();
    let mut mips = vec![0.0f32; mip_offset(full, MIP_LEVELS)];
    for k in 0..MIP_LEVELS {
        let size = mip_size(full, k);
        let (before, level) = mips.split_at_mut(mip_offset(full, k));
        let level = &mut level[..(size.x * size.y) as usize];
        crate::screen::tiled(level, size.x, 0..size.x, 0..size.y, &crate::no_progress, |t, v| {
            *v = prefilter_texel(params, depth, before, k, t)
        });
    }
    mips
}

/// Prefilter pass `params.pass` over the packed chain `mips` as the GPU dispatches it, block by
/// block: pass 0 [`CPU_LANES`] 2×2 blocks at a time ([`prefilter_near_row`], the lanes of the shader
/// crate's `prefilter_near`), pass 1 the shader crate's [`prefilter_far`]; each row of blocks on
/// a thread of its own, writing through relaxed atomics (the blocks write disjoint texels, as
/// the GPU's invocations do).
pub fn prefilter_pass(params: &GtaoParams, depth: &[f32], mips: &mut [f32]) {
    let divisor = aokit_shaders::gtao::PREFILTER_BLOCK[params.pass.min(1) as usize];
    let full = params.view.size();
    let blocks = UVec2::new(full.x.div_ceil(divisor), full.y.div_ceil(divisor));
    // The f32 texels as the u32 words of their bits (every bit pattern is valid for both).
    let shared = as_atomics(bytemuck::cast_slice_mut(mips));
    (0..blocks.y).into_par_iter().for_each(|y| {
        let mut out = shared;
        if params.pass == 0 {
            prefilter_near_row(params, depth, &mut out, y);
            return;
        }
        for x in 0..blocks.x {
            prefilter_far(params, &mut out, UVec2::new(x, y));
        }
    });
}

/// Pass 0 over a row `y` of 2×2 blocks, [`CPU_LANES`] blocks per call of the shader crate's
/// lane-generic [`working_value`] and [`mip_filter`]: what
/// [`aokit_shaders::gtao::prefilter::prefilter_near`] computes per block (whose MIP 0 reads clamp
/// to the target the same way).
pub fn prefilter_near_row(params: &GtaoParams, depth: &[f32], out: &mut &[AtomicU32], y: u32) {
    let full = params.view.size();
    let (size1, offset1) = (mip_size(full, 1), mip_offset(full, 1));
    let falloff = mip_falloff(params);
    let blocks = full.x.div_ceil(2);
    let rows = [(2 * y).min(full.y - 1), (2 * y + 1).min(full.y - 1)];
    for x0 in (0..blocks).step_by(CPU_LANES) {
        let at = |dx: u32, dy: usize| {
            let row = (rows[dy] * full.x) as usize;
            CpuLanes::from_lanes(|i| depth[row + (2 * (x0 + i as u32) + dx).min(full.x - 1) as usize])
        };
        // Written out, not `[…].map(…)`: at sixteen lanes the array map is not inlined.
        let working = |v| working_value(v, params.view.far);
        let d = [working(at(0, 0)), working(at(1, 0)), working(at(0, 1)), working(at(1, 1))];
        let m1 = mip_filter(d, &falloff);
        for i in 0..(CPU_LANES as u32).min(blocks - x0) {
            let b = x0 + i;
            for (k, (dx, dy)) in [(0, 0), (1, 0), (0, 1), (1, 1)].into_iter().enumerate() {
                let (px, py) = (2 * b + dx, 2 * y + dy);
                if px < full.x && py < full.y {
                    out.store((py * full.x + px) as usize, d[k].lane(i as usize));
                }
            }
            if b < size1.x && y < size1.y {
                out.store(offset1 + (y * size1.x + b) as usize, m1.lane(i as usize));
            }
        }
    }
}

/// Pass 0: encoded view normals from depth.
pub fn run_normals(params: &GtaoParams, depth: &[f32]) -> Vec<u32> {
    per_pixel(params.view.size(), |p| normal_from_depth(params, depth, p))
}

/// MainPass: AO terms (0–255) and packed edges per pixel of the full target, [`CPU_LANES`] pixels of a
/// row per call of the shader crate's lane-generic slices ([`main_pass_lanes`]).
pub fn run_main(params: &GtaoParams, mips: &[f32], normals: &[u32]) -> (Vec<u32>, Vec<u32>) {
    let size = params.view.size();
    let (mut terms, mut edges) = (vec![0; (size.x * size.y) as usize], vec![0; (size.x * size.y) as usize]);
    run_main_into(params, mips, normals, &mut terms, &mut edges);
    (terms, edges)
}

/// [`run_main`] into the caller's term and edge buffers.
pub fn run_main_into(params: &GtaoParams, mips: &[f32], normals: &[u32], terms: &mut [u32], edges: &mut [u32]) {
    let size = params.view.size();
    crate::screen::whole_image_lanes2(terms, edges, size, |p, t, e| main_pass_lanes(params, mips, normals, p, t, e));
}

/// XeGTAO's MainPass for `terms.len()` ≤ [`CPU_LANES`] consecutive pixels of a row from `first`: the
/// setup, the slices and the final power of [`aokit_shaders::gtao::gtao_pixel`] on [`CPU_LANES`] lanes
/// at once, the stored term per lane. Missing lanes repeat the last pixel; lanes without a
/// usable depth are computed and discarded, as on a GPU.
pub fn main_pass_lanes(
    params: &GtaoParams,
    mips: &[f32],
    normals: &[u32],
    first: UVec2,
    terms: &mut [u32],
    edges: &mut [u32],
) {
    let (packed, valid, px) = pixel_setup::<CpuLanes>(params, mips, normals, lanes_of_run(first, terms.len()));
    let (vis, bent) = slices_visibility(params, mips, &px);
    let vis = final_visibility(vis, params.final_value_power);
    for (i, (t, e)) in terms.iter_mut().zip(edges.iter_mut()).enumerate() {
        let b = vec3(bent.x.lane(i), bent.y.lane(i), bent.z.lane(i));
        let n = vec3(px.n.x.lane(i), px.n.y.lane(i), px.n.z.lane(i));
        *t = finish_pixel(params, CpuLanes::mask_lane(valid, i), vis.lane(i), b, n);
        *e = CpuLanes::index_lane(packed, i);
    }
}

/// VBAO's main pass into the caller's term and edge buffers, [`CPU_LANES`] pixels of a row per
/// call of the shader crate's lane-generic [`pixel_setup`], [`aokit_shaders::vbao::kernel::vbao_visibility`] and
/// [`final_visibility`] (the stored term per lane).
pub fn run_vbao_into(params: &VbaoParams, mips: &[f32], normals: &[u32], terms: &mut [u32], edges: &mut [u32]) {
    vbao_main_into(params, mips, normals, terms, edges, || ConstantThickness);
}

/// VBAO's main pass with each run's samples occupied as `occupancy()` says ([`visibility_with`]):
/// `vbao`'s constant thickness, or vbao-sd's layers.
fn vbao_main_into<O: Occupancy<CpuLanes>>(
    params: &VbaoParams,
    mips: &[f32],
    normals: &[u32],
    terms: &mut [u32],
    edges: &mut [u32],
    occupancy: impl Fn() -> O + Sync,
) {
    let size = params.gtao.view.size();
    crate::screen::whole_image_lanes2(terms, edges, size, |first, t, e| {
        let (packed, valid, px) = pixel_setup::<CpuLanes>(&params.gtao, mips, normals, lanes_of_run(first, t.len()));
        let vis = visibility_with(params, mips, &px, &mut occupancy());
        let vis = final_visibility(vis, params.gtao.final_value_power);
        for (i, (t, e)) in t.iter_mut().zip(e.iter_mut()).enumerate() {
            *t = vbao_term(CpuLanes::mask_lane(valid, i), vis.lane(i));
            *e = CpuLanes::index_lane(packed, i);
        }
    });
}

/// vbao-sd's phase 1 (spec vbao §8.1) over the full target, rows in parallel, [`CPU_LANES`] pixels per
/// call: every flagged sample widens its SD texel's ray interval in `ray_min` / `ray_max`
/// (cleared by the caller) by atomic min / max, as the GPU's invocations do.
pub fn run_vbao_sd_request_into(
    params: &VbaoParams,
    sd: &SvaoParams,
    mips: &[f32],
    normals: &[u32],
    ray_min: &mut [u32],
    ray_max: &mut [u32],
) {
    let size = params.gtao.view.size();
    let (ray_min, ray_max) = (as_atomics(ray_min), as_atomics(ray_max));
    (0..size.y).into_par_iter().for_each(|y| {
        let (mut lo, mut hi) = (ray_min, ray_max);
        for x in (0..size.x).step_by(CPU_LANES) {
            // A short last run repeats its last pixel: its requests again, which change nothing.
            let p = lanes_of_run(UVec2::new(x, y), (size.x - x).min(CPU_LANES as u32) as usize);
            request_pixel::<CpuLanes, _, _>(params, sd, mips, normals, p, &mut lo, &mut hi);
        }
    });
}

/// The words of an exclusively borrowed buffer as atomics, for passes whose invocations write it
/// concurrently (the prefilter's texels, vbao-sd's ray intervals).
fn as_atomics(words: &mut [u32]) -> &[AtomicU32] {
    const _: () = assert!(align_of::<AtomicU32>() == align_of::<u32>() && size_of::<AtomicU32>() == size_of::<u32>());
    // SAFETY: `AtomicU32` has the size and alignment of `u32` (asserted), and the exclusive
    // borrow keeps every other access out for the returned borrow's lifetime.
    unsafe { core::slice::from_raw_parts(words.as_mut_ptr() as *const AtomicU32, words.len()) }
}

/// vbao-sd's main pass (spec vbao §8.2) into the caller's terms and edges: [`CPU_LANES`] pixels
/// of a row per call of the shader crate's lane-generic occupancy ([`SdLayers`]), as
/// [`run_vbao_into`].
pub fn run_vbao_sd_into(
    params: &VbaoParams,
    sd: &SvaoParams,
    map: &[f32],
    mips: &[f32],
    normals: &[u32],
    terms: &mut [u32],
    edges: &mut [u32],
) {
    vbao_main_into(params, mips, normals, terms, edges, || SdLayers { map, sd, mips });
}

/// The first `out.len()` ≤ [`CPU_LANES`] of `lanes` into `out`: one store of the whole vector
/// for a full run instead of an extract and a store per lane.
#[inline(always)]
fn store_lanes<T: Copy>(out: &mut [T], lanes: [T; CPU_LANES]) {
    match <&mut [T; CPU_LANES]>::try_from(&mut *out) {
        Ok(full) => *full = lanes,
        Err(_) => out.copy_from_slice(&lanes[..out.len()]),
    }
}

/// The denoise passes; returns the visibility per pixel (full target).
pub fn run_denoise(params: &GtaoParams, terms: &[u32], edges: &[u32]) -> Vec<f32> {
    let mut current = terms.to_vec();
    let mut next = vec![0; current.len()];
    let mut ao = vec![0.0; current.len()];
    for pass in 0..params.denoise_passes.max(1) {
        let p = GtaoParams { pass, ..*params };
        denoise_into(&p, &current, edges, &mut next, &mut ao);
        core::mem::swap(&mut current, &mut next);
    }
    ao
}

/// Denoise pass `params.pass` into the caller's buffers: the terms for the next pass and, in
/// the last pass, the visibility. Without bent normals [`CPU_LANES`] pixels of a row per call of the
/// shader crate's lane-generic [`denoise_lanes`]; with them one pixel at a time.
pub fn denoise_into(params: &GtaoParams, terms_in: &[u32], edges: &[u32], terms_out: &mut [u32], ao: &mut [f32]) {
    let size = params.view.size();
    if params.bent_normals != 0 {
        crate::screen::tiled_lanes2(terms_out, ao, size.x, 0..size.x, 0..size.y, 1, &crate::no_progress, |q, t, a| {
            let o = denoise_pixel(params, terms_in, edges, q);
            t[0] = o.term;
            if o.last {
                a[0] = o.visibility;
            }
        });
        return;
    }
    let last = is_last_pass(params);
    crate::screen::whole_image_lanes2(terms_out, ao, size, |first, t, a| {
        let (term, visibility) = denoise_lanes::<CpuLanes>(params, terms_in, edges, lanes_of_run(first, t.len()));
        // Whole vectors stored at once (the terms are 0–255, so their i32 bits are the u32s).
        store_lanes(t, bytemuck::cast(term.to_array()));
        if last {
            store_lanes(a, visibility.0.to_array());
        }
    });
}
