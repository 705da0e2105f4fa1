//! The two-phase SVAO pipeline on the CPU (spec svao-raysd §3): AO pass 1 with `AtomicU32`
//! interval buffers, the ray-traced SD map with the shared reservoir any-hit driven by the BVH,
//! AO pass 2 from the SD map, and Ray-SVAO's per-sample rays. Every per-pixel and per-hit
//! function is the shader crate's.

use crate::bvh::{AnyHit, PACKET};
use crate::gbuffer::Surfaces;
use crate::screen::lanes_of_run;
use crate::{Progress, SceneBvh};
use aokit_shaders::common::alpha::AlphaTables;
use aokit_shaders::common::float_order::{RAY_MAX_CLEAR, RAY_MIN_CLEAR};
use aokit_shaders::common::gbuffer_read::{DepthSlice, GBufferSlices};
use aokit_shaders::common::lanes::{CPU_LANES, CpuLanes, LaneVec3, Lanes};
use aokit_shaders::glam::{UVec2, uvec2, vec2};
use aokit_shaders::rastersd::raster_fragment;
use aokit_shaders::raysd::{SdMapRefine, SdPayload, SdRay, reservoir_any_hit, sd_ray, store_layers};
use aokit_shaders::raysvao::{ACCEPT, ACCEPT_AND_END, SampleRay, SampleTracer, refine_by_ray, sample_any_hit};
use aokit_shaders::svao::pass1::{pass1_finish, pass1_sample, record_interval};
use aokit_shaders::svao::{Refine, Refined, SvaoFrame, SvaoParams, pass2_pixel};
use aokit_shaders::vao::kernel::{LineSample, PixelFrame, setup_lanes};
use rayon::prelude::*;
use std::sync::atomic::{AtomicU32, AtomicU64, Ordering};

/// Outputs of AO pass 1 over the full target (guard band: AO 1, mask 0) and the SD-size
/// interval buffers.
#[derive(Clone, Debug)]
pub struct Pass1 {
    pub ao: Vec<f32>,
    pub mask: Vec<u32>,
    pub ray_min: Vec<u32>,
    pub ray_max: Vec<u32>,
}

impl Pass1 {
    /// Number of flagged samples (set mask bits).
    pub fn refined_samples(&self) -> u64 {
        self.mask.iter().map(|m| m.count_ones() as u64).sum()
    }
}

/// AO pass 1 (spec svao-raysd §5) over the inner image, interval atomics as `AtomicU32`.
/// `depth2`: the depth-peeled second layer, read only when `params.dual` is set.
pub fn run_pass1(params: &SvaoParams, depth: &[f32], normals: &[u32], depth2: &[f32], progress: Progress) -> Pass1 {
    let view = &params.vao.view;
    let size = view.size();
    let pixels = (size.x * size.y) as usize;
    let sd = params.sd_size();
    let texels = (sd.x * sd.y) as usize;
    let ray_min: Vec<AtomicU32> = (0..texels).map(|_| AtomicU32::new(RAY_MIN_CLEAR)).collect();
    let ray_max: Vec<AtomicU32> = (0..texels).map(|_| AtomicU32::new(RAY_MAX_CLEAR)).collect();
    let (mut ao, mut mask) = (vec![1.0f32; pixels], vec![0u32; pixels]);
    let gbuffer = GBufferSlices { depth, normals, width: size.x };
    let g = view.guard;
    let (xs, ys) = (g..size.x - g, g..size.y - g);
    crate::screen::tiled_lanes2(&mut ao, &mut mask, size.x, xs, ys, CPU_LANES as u32, progress, |p, ao, mask| {
        pass1_lanes(&gbuffer, depth2, params, p, ao, mask, (&ray_min, &ray_max))
    });
    let unwrap = |v: Vec<AtomicU32>| v.into_iter().map(AtomicU32::into_inner).collect::<Vec<u32>>();
    Pass1 { ao, mask, ray_min: unwrap(ray_min), ray_max: unwrap(ray_max) }
}

/// [`aokit_shaders::svao::pass1_pixel`] for `ao.len()` ≤ [`CPU_LANES`] consecutive pixels of a row from `first`: the per-pixel setup,
/// the mask bits, the interval atomics and the final store per lane, the samples' arithmetic on
/// all lanes at once. Missing lanes repeat the last pixel; unshaded pixels borrow a shaded
/// lane's frame and are discarded.
fn pass1_lanes(
    gbuffer: &GBufferSlices,
    depth2: &[f32],
    params: &SvaoParams,
    first: UVec2,
    ao: &mut [f32],
    mask_out: &mut [u32],
    (mut ray_min, mut ray_max): (&[AtomicU32], &[AtomicU32]),
) {
    let vao = &params.vao;
    let n = ao.len();
    let p = lanes_of_run(first, n);
    let (shaded, lanes) = setup_lanes::<_, CpuLanes>(gbuffer, &vao.view, vao.radius, vao.max_screen_radius, p);
    if !CpuLanes::any(shaded) {
        return;
    }
    let shaded: [bool; CPU_LANES] = core::array::from_fn(|k| CpuLanes::mask_lane(shaded, k));
    let distance = lanes.position.length();
    let (mut sum, mut mask) = (CpuLanes::splat(0.0), [0u32; CPU_LANES]);
    for i in 0..params.samples() {
        let r = pass1_sample(gbuffer, depth2, params, &lanes, i);
        sum = sum + r.value;
        for (k, m) in mask.iter_mut().enumerate().take(n) {
            if shaded[k] && CpuLanes::mask_lane(r.flagged, k) {
                *m |= 1 << i;
                let s = &r.sample;
                let uv = vec2(s.uv.x.lane(k), s.uv.y.lane(k));
                let (z, h, end, radius) =
                    (r.z.lane(k), s.half_chord.lane(k), s.sphere_end.lane(k), lanes.radius.lane(k));
                record_interval(params, uv, z, h, end, radius, distance.lane(k), &mut ray_min, &mut ray_max);
            }
        }
    }
    for (k, (a, m)) in ao.iter_mut().zip(mask_out.iter_mut()).enumerate() {
        if shaded[k] {
            let out = pass1_finish(params, sum.lane(k), mask[k]);
            (*a, *m) = (out.ao, out.mask);
        }
    }
}

/// The ray-traced SD map (spec svao-raysd §7) and the number of rays traced.
#[derive(Clone, Debug)]
pub struct SdMap {
    /// `N` normalized depths per SD texel (1 = empty), row-major over the SD size.
    pub layers: Vec<f32>,
    pub rays: u64,
}

/// How the CPU reports candidate hits to the any-hit function.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum HitOrder {
    /// The BVH's traversal order.
    Traversal,
    /// All candidates shuffled with this seed (per texel), then replayed: an adversarial
    /// stand-in for the unspecified hardware order.
    Shuffled(u64),
}

/// The SD map's ray packets are cut from tiles of this many texels (x, y), a column of tiles
/// per band of `SD_TILE.y` rows: of the tile shapes of 8 texels, 2×4 left the fewest boxes to
/// test per ray (single-thread SD rays, min of 3 runs: kitchen 16.7 ms as 2×4 tiles, 18.0 as
/// 4×2, 17.2 as 1×8, 20.0 as 8×1 runs of a row; tower 4.6 / 4.9 / 4.6 / 5.2 ms).
pub const SD_TILE: UVec2 = uvec2(2, 4);

/// The texels of a band of `rows` (≤ `SD_TILE.y`) rows of `width` texels in the order the SD
/// map traces them: tile by tile left to right, each tile row by row; band coordinates.
pub fn sd_band_order(width: u32, rows: u32) -> impl Iterator<Item = UVec2> {
    (0..width)
        .step_by(SD_TILE.x as usize)
        .flat_map(move |x0| (0..rows).flat_map(move |y| (x0..(x0 + SD_TILE.x).min(width)).map(move |x| uvec2(x, y))))
}

/// Trace one SD ray per SD texel (spec svao-raysd §7.1) with the shared reservoir any-hit (spec svao-raysd §7.3),
/// alpha test included: a band's traced rays, in [`sd_band_order`], in packets of [`PACKET`]
/// consecutive ones ([`SceneBvh::trace_any_hit_packet`]: each ray's candidates come as a lone
/// ray's would).
pub fn run_sd_map(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    frame: &SvaoFrame,
    depth: &[f32],
    normals: &[u32],
    pass1: &Pass1,
    order: HitOrder,
) -> SdMap {
    let params = &frame.params;
    let view = &params.vao.view;
    let sd = params.sd_size();
    let n = params.sd_layers as usize;
    let gbuffer = GBufferSlices { depth, normals, width: view.size().x };
    let alpha = surfaces.alpha();
    let rays = AtomicU64::new(0);
    let mut layers = vec![1.0f32; (sd.x * sd.y) as usize * n];
    let band_len = (sd.x * SD_TILE.y) as usize * n;
    layers.par_chunks_mut(band_len).with_max_len(1).enumerate().for_each(|(b, band)| {
        let rows = (band.len() / (sd.x as usize * n)) as u32;
        // `store_layers` indexes the whole map; this band's slice is a map of `rows` rows.
        let band_params = SvaoParams { sd_low_res: uvec2(sd.x, rows), sd_guard: 0, ..*params };
        let texel = |q: UVec2| q + uvec2(0, b as u32 * SD_TILE.y);
        let texels: Vec<UVec2> = sd_band_order(sd.x, rows).collect();
        let texel_rays: Vec<SdRay> = texels
            .iter()
            .map(|&q| {
                let i = params.sd_index(texel(q));
                sd_ray(&gbuffer, frame, texel(q), pass1.ray_min[i], pass1.ray_max[i])
            })
            .collect();
        let mut payloads: Vec<SdPayload> =
            texel_rays.iter().map(|r| SdPayload::new(params, view.near, view.far, r.cos_theta)).collect();
        let traced: Vec<usize> = (0..texel_rays.len()).filter(|&k| texel_rays[k].traced()).collect();
        match order {
            // The band's rays (all from the eye) in packets of PACKET consecutive ones.
            HitOrder::Traversal => {
                for run in traced.chunks(PACKET) {
                    let ray = |k: usize| texel_rays[run[k.min(run.len() - 1)]];
                    let packet: [SdRay; PACKET] = std::array::from_fn(ray);
                    let origin = packet[0].origin;
                    debug_assert!(packet.iter().all(|r| r.origin == origin), "SD rays start at the eye");
                    let interval = (&packet.map(|r| r.t_min), &packet.map(|r| r.t_max));
                    let directions = packet.map(|r| r.direction);
                    bvh.trace_any_hit_packet(origin, &directions, interval, run.len(), |k, t, tri, b| {
                        let accept = reservoir_any_hit(&mut payloads[run[k]], t, b, || alpha.passes(tri, b));
                        if accept { AnyHit::Accept } else { AnyHit::Ignore }
                    });
                }
            }
            HitOrder::Shuffled(seed) => {
                for &k in &traced {
                    let (ray, i) = (texel_rays[k], params.sd_index(texel(texels[k])));
                    let mut hits = bvh.all_hits(ray.origin, ray.direction, ray.t_min, ray.t_max);
                    shuffle(&mut hits, seed ^ (i as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
                    crate::bvh::replay_any_hit(&hits, ray.t_min, ray.t_max, |t, tri, b| {
                        let accept = reservoir_any_hit(&mut payloads[k], t, b, || alpha.passes(tri, b));
                        if accept { AnyHit::Accept } else { AnyHit::Ignore }
                    });
                }
            }
        }
        for (&q, payload) in texels.iter().zip(&payloads) {
            store_layers(band, &band_params, q, payload);
        }
        rays.fetch_add(traced.len() as u64, Ordering::Relaxed);
    });
    SdMap { layers, rays: rays.into_inner() }
}

/// Fisher–Yates with SplitMix64.
fn shuffle<T>(v: &mut [T], seed: u64) {
    let mut state = seed;
    let mut next = || {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    };
    for i in (1..v.len()).rev() {
        let j = (next() % (i as u64 + 1)) as usize;
        v.swap(i, j);
    }
}

/// AO pass 2 (spec svao-raysd §9) with any [`Refine`] source made per row.
fn run_pass2<R: Refine>(
    params: &SvaoParams,
    depth: &[f32],
    normals: &[u32],
    depth2: &[f32],
    pass1: &Pass1,
    progress: Progress,
    source: impl Fn() -> R + Sync,
) -> Vec<f32> {
    let mut out = pass1.ao.clone();
    run_pass2_into(params, (depth, normals, depth2), &mut out, &pass1.mask, progress, source);
    out
}

/// [`run_pass2`] in place: `ao` holds pass 1's AO and receives pass 2's (each pixel reads only
/// its own stored value, as on the GPU), `mask` pass 1's refinement bits; the G-buffer is
/// `(depth, normals, depth2)`.
fn run_pass2_into<R: Refine>(
    params: &SvaoParams,
    (depth, normals, depth2): (&[f32], &[u32], &[f32]),
    ao: &mut [f32],
    mask: &[u32],
    progress: Progress,
    source: impl Fn() -> R + Sync,
) {
    let view = &params.vao.view;
    let size = view.size();
    let gbuffer = GBufferSlices { depth, normals, width: size.x };
    let g = view.guard;
    ao.par_chunks_mut(size.x as usize).enumerate().for_each(|(y, row)| {
        let y = y as u32;
        if y < g || y + g >= size.y {
            return;
        }
        let mut refine = source();
        for x in g..size.x - g {
            let p = uvec2(x, y);
            let i = view.index(p);
            row[x as usize] = pass2_pixel(&gbuffer, depth2, params, p, row[x as usize], mask[i], &mut refine).ao;
        }
        progress(1);
    });
}

/// AO pass 2 from the SD map (spec svao-raysd §9).
pub fn run_pass2_sd(
    params: &SvaoParams,
    depth: &[f32],
    normals: &[u32],
    depth2: &[f32],
    pass1: &Pass1,
    map: &SdMap,
) -> Vec<f32> {
    run_pass2(params, depth, normals, depth2, pass1, &crate::no_progress, || SdMapRefine { map: &map.layers, params })
}

/// [`run_pass2_sd`] in place on pass 1's AO `ao` and bits `mask`, from the map's layers `map`
/// (what the graph's pass binds: no copies).
pub fn run_pass2_sd_into(
    params: &SvaoParams,
    gbuffer: (&[f32], &[u32], &[f32]),
    ao: &mut [f32],
    mask: &[u32],
    map: &[f32],
) {
    run_pass2_into(params, gbuffer, ao, mask, &crate::no_progress, || SdMapRefine { map, params })
}

/// BVH tracing for Ray-SVAO samples: every hit goes through the alpha test, then the shared
/// any-hit (every triangle counts as facing: no culling, as on the GPU path). Counts its rays
/// into `rays` when dropped.
struct BvhRefine<'a> {
    bvh: &'a SceneBvh,
    alpha: AlphaTables<'a>,
    frame: &'a SvaoFrame,
    traced: u64,
    rays: &'a AtomicU64,
}

impl SampleTracer for BvhRefine<'_> {
    fn trace(&mut self, ray: &mut SampleRay) {
        self.traced += 1;
        let state = &mut ray.state;
        let alpha = self.alpha;
        self.bvh.trace_any_hit(ray.origin, ray.direction, ray.t_min, ray.t_max, |t, tri, b| {
            if !alpha.passes(tri, b) {
                return AnyHit::Ignore;
            }
            match sample_any_hit(state, t) {
                ACCEPT => AnyHit::Accept,
                ACCEPT_AND_END => AnyHit::AcceptAndEnd,
                _ => AnyHit::Ignore,
            }
        });
    }
}

impl Refine for BvhRefine<'_> {
    fn refine(&mut self, pixel: &PixelFrame, s: &LineSample, v: f32, z_primary: f32) -> Refined {
        let frame = self.frame;
        refine_by_ray(&frame.camera, &frame.params, pixel, s, v, z_primary, self)
    }
}

impl Drop for BvhRefine<'_> {
    fn drop(&mut self) {
        self.rays.fetch_add(self.traced, Ordering::Relaxed);
    }
}

/// Ray-SVAO pass 2 (spec svao-raysd §10): one traced ray per flagged sample. Returns the AO and the rays
/// traced.
pub fn run_raysvao_pass2(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    frame: &SvaoFrame,
    depth: &[f32],
    normals: &[u32],
    depth2: &[f32],
    pass1: &Pass1,
) -> (Vec<f32>, u64) {
    let mut ao = pass1.ao.clone();
    let rays = run_raysvao_pass2_into(bvh, surfaces, frame, (depth, normals, depth2), &mut ao, &pass1.mask);
    (ao, rays)
}

/// [`run_raysvao_pass2`] in place on pass 1's AO `ao` and bits `mask`; returns the rays traced.
pub fn run_raysvao_pass2_into(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    frame: &SvaoFrame,
    gbuffer: (&[f32], &[u32], &[f32]),
    ao: &mut [f32],
    mask: &[u32],
) -> u64 {
    let rays = AtomicU64::new(0);
    run_pass2_into(&frame.params, gbuffer, ao, mask, &crate::no_progress, || BvhRefine {
        bvh,
        alpha: surfaces.alpha(),
        frame,
        traced: 0,
        rays: &rays,
    });
    rays.into_inner()
}

/// The raster SD map on the CPU (spec svao-raysd §8): for every requested SD texel, every surface along the
/// ray through the texel centre (what rasterization at SD resolution produces there) becomes a
/// fragment for the shader crate's [`raster_fragment`] — alpha test, first-layer and interval
/// discards, coverage mask — and each covered sample keeps the nearest depth (depth test LESS).
/// `rays` counts the texels rasterized.
pub fn run_raster_sd_map(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    frame: &SvaoFrame,
    depth: &[f32],
    pass1: &Pass1,
) -> SdMap {
    let params = &frame.params;
    let camera = &frame.camera;
    let sd = params.sd_size();
    let n = params.sd_layers as usize;
    let gbuffer = DepthSlice { depth, width: params.vao.view.size().x };
    let texels = AtomicU64::new(0);
    let mut layers = vec![1.0f32; (sd.x * sd.y) as usize * n];
    layers.par_chunks_mut(sd.x as usize * n).enumerate().for_each(|(y, row)| {
        let mut rasterized = 0;
        for x in 0..sd.x {
            let q = uvec2(x, y as u32);
            let i = params.sd_index(q);
            if pass1.ray_max[i] == 0 {
                continue;
            }
            rasterized += 1;
            let uv = (q.as_vec2() + 0.5) / params.sd_low_res.as_vec2();
            let dir = camera.primary_ray_direction(uv);
            let eye = camera.eye();
            for (t, tri, b) in bvh.all_hits(eye, dir, 0.0, f32::INFINITY) {
                if !surfaces.passes_alpha(tri, b) {
                    continue;
                }
                let d = camera.linear_depth_of_hit(dir, t);
                let pos_w = eye + dir * t;
                let (mask, z) = raster_fragment(&gbuffer, frame, q, d, pos_w, t, pass1.ray_min[i], pass1.ray_max[i]);
                for k in 0..n {
                    if mask & (1 << k) != 0 {
                        let slot = &mut row[x as usize * n + k];
                        *slot = slot.min(z);
                    }
                }
            }
        }
        texels.fetch_add(rasterized, Ordering::Relaxed);
    });
    SdMap { layers, rays: texels.into_inner() }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every texel of a band once, tile after tile: each run of 8 consecutive texels of a full
    /// band is one 2×4 tile.
    #[test]
    fn sd_band_order_visits_each_texel_once_by_tiles() {
        for (width, rows) in [(1, 1), (7, 4), (10, 3), (512, 4)] {
            let order: Vec<UVec2> = sd_band_order(width, rows).collect();
            let mut seen = vec![0; (width * rows) as usize];
            for q in &order {
                seen[(q.y * width + q.x) as usize] += 1;
            }
            assert!(seen.iter().all(|&s| s == 1), "{width}×{rows}");
            if rows == SD_TILE.y && width % SD_TILE.x == 0 {
                for tile in order.chunks(8) {
                    let (lo, hi) =
                        (tile.iter().fold(tile[0], |a, &b| a.min(b)), tile.iter().fold(tile[0], |a, &b| a.max(b)));
                    assert_eq!(hi - lo + 1, SD_TILE, "{tile:?}");
                }
            }
        }
    }
}
