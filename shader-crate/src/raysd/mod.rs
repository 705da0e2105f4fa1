//! The ray-traced stochastic depth map (Ray-SD paper §3; spec svao-raysd §7, §9): one ray per
//! SD texel over the interval pass 1 requested, a reservoir any-hit that keeps `N` random depths
//! behind the first layer, and the pass-2 reader that refines flagged samples from it.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

// The ray-query entry points exist in SPIR-V only (built with the `rq` feature); their
// declarations (`#[kernel(spirv_only)]`) exist on the host too.
#[cfg(any(feature = "rq", not(target_arch = "spirv")))]
pub mod rq;
#[cfg(any(feature = "rt", not(target_arch = "spirv")))]
pub mod rt;

use crate::common::alpha::AlphaTables;
use crate::common::any_hit::{ACCEPT, CandidateHit, IGNORE};
use crate::common::float_order::from_ordered_bits;
use crate::common::gbuffer_read::GBuffer;
use crate::common::hash::wyman_hash;
// `Lanes` is named by path: imported, its `floor` would clash with `Float::floor` on SPIR-V.
use crate::common::lanes::LaneVec2;
use crate::common::math::{depth_or_far, sat};
use crate::common::noise::{frame_rotation, rotate};
use crate::common::tables::sd_jitter;
use crate::glam::{IVec2, UVec2, Vec2, Vec3};
use crate::svao::pass1::{combine, depth_point_value};
use crate::svao::{Refine, Refined, SvaoFrame, SvaoParams, sd_pixel};
use crate::vao::kernel::{LineSample, PixelFrame};

/// Most layers an SD map holds (spec svao-raysd §2: N ∈ {1, 2, 4, 8}).
pub const MAX_LAYERS: usize = 8;
/// [`reservoir_slot`]'s answer for a hit that does not enter the map.
pub const NO_SLOT: u32 = u32::MAX;

/// The any-hit payload of one SD ray (spec svao-raysd §7.3): `N` normalized depths (1 = far = empty) and
/// the hit count, plus what the any-hit needs to normalize a hit distance.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct SdPayload {
    pub depth: [f32; MAX_LAYERS],
    pub count: u32,
    pub layers: u32,
    pub max_count: u32,
    /// `cos θ` of the ray against the view axis: linear depth = `t·cos θ`.
    pub cos_theta: f32,
    pub near: f32,
    pub far: f32,
    /// The frame's rotation of the reservoir's random number (`frame_rotation(noise_frame).x`;
    /// 0 for a single frame).
    pub rotation: f32,
}

impl SdPayload {
    /// Empty payload: every layer at the far plane, no hits counted.
    #[inline]
    pub fn new(params: &SvaoParams, near: f32, far: f32, cos_theta: f32) -> Self {
        SdPayload {
            depth: [1.0; MAX_LAYERS],
            count: 0,
            layers: params.sd_layers,
            max_count: params.max_count,
            cos_theta,
            near,
            far,
            rotation: frame_rotation(params.noise_frame).x,
        }
    }
}

/// Reservoir step for one candidate (spec svao-raysd §7.3, Ray-SD paper Listing 1): `slot = count++`; past
/// `N` the slot is `floor(u·count)` with the incremented count; a slot ≥ N is rejected, and so is
/// a hit behind the depth already in its slot (z-cull). Returns the slot to write or
/// [`NO_SLOT`]. The count grows for every candidate, rejected or not.
#[inline]
pub fn reservoir_slot(payload: &mut SdPayload, u: f32, z: f32) -> u32 {
    let mut slot = payload.count;
    payload.count += 1;
    if payload.count > payload.layers {
        slot = (u * payload.count as f32) as u32;
    }
    if slot >= payload.layers || payload.depth[slot as usize] <= z {
        return NO_SLOT;
    }
    slot
}

/// First half of the SD any-hit (spec svao-raysd §7.3) for a hit at ray distance `t` with DXR barycentrics
/// `bary`: hash the barycentrics (rotated by the frame's [`SdPayload::rotation`]), normalize the
/// hit's linear depth and pick the reservoir slot.
/// Returns `(slot, z)`; only a hit with `slot != NO_SLOT` needs the alpha test.
#[inline]
pub fn reservoir_candidate(payload: &mut SdPayload, t: f32, bary: Vec2) -> (u32, f32) {
    let u = rotate(wyman_hash(bary.x, bary.y), payload.rotation);
    let z = sat((t * payload.cos_theta - payload.near) / (payload.far - payload.near));
    (reservoir_slot(payload, u, z), z)
}

/// Second half of the SD any-hit: store `z` if the slot is valid and the alpha test passed.
/// Returns true to ACCEPT the hit (DXR commits it: `tMax` shrinks to `t`) once
/// `count ≥ MAX_COUNT`, false to IGNORE it (traversal continues unchanged).
#[inline]
pub fn reservoir_commit(payload: &mut SdPayload, slot: u32, z: f32, alpha_passes: bool) -> bool {
    if slot != NO_SLOT && alpha_passes {
        payload.depth[slot as usize] = z;
    }
    payload.count >= payload.max_count
}

/// The whole SD any-hit: [`reservoir_candidate`], the alpha test only for hits that would be
/// stored, [`reservoir_commit`].
#[inline]
pub fn reservoir_any_hit(payload: &mut SdPayload, t: f32, bary: Vec2, alpha_passes: impl FnOnce() -> bool) -> bool {
    let (slot, z) = reservoir_candidate(payload, t, bary);
    let alpha = slot != NO_SLOT && alpha_passes();
    reservoir_commit(payload, slot, z, alpha)
}

/// The SD any-hit (spec svao-raysd §7.3) over one ray's candidates: [`reservoir_candidate`], the alpha
/// test only for hits that would be stored, [`reservoir_commit`] — ACCEPT once the count reaches
/// `MAX_COUNT`, IGNORE before. The any-hit shader and the ray-query loop both run it.
pub struct SdHits<'a> {
    pub payload: SdPayload,
    pub alpha: AlphaTables<'a>,
}

impl CandidateHit for SdHits<'_> {
    #[inline]
    fn decide(&mut self, t: f32, bary: Vec2, triangle: u32) -> u32 {
        let (slot, z) = reservoir_candidate(&mut self.payload, t, bary);
        let mut alpha = false;
        if slot != NO_SLOT {
            alpha = self.alpha.passes(triangle, bary);
        }
        if reservoir_commit(&mut self.payload, slot, z, alpha) { ACCEPT } else { IGNORE }
    }
}

/// One SD ray in world space; `t_min ≥ t_max` means "nothing requested": no trace.
#[derive(Copy, Clone, Debug)]
pub struct SdRay {
    pub origin: Vec3,
    pub direction: Vec3,
    pub t_min: f32,
    pub t_max: f32,
    pub cos_theta: f32,
}

impl SdRay {
    /// Does this texel trace a ray (a non-empty, finite interval)?
    #[inline]
    pub fn traced(&self) -> bool {
        self.t_min < self.t_max && self.t_max < f32::MAX
    }
}

/// Bilinear linear depth at uv (clamp to edge; unusable depths read as the far plane), as the
/// reference samples the primary depth at the SD texel centre (spec svao-raysd §7.1).
#[inline]
pub fn bilinear_depth<G: GBuffer>(gbuffer: &G, frame: &SvaoFrame, uv: Vec2) -> f32 {
    let view = &frame.params.vao.view;
    let size = view.size();
    let x = uv.x * view.res.x - 0.5;
    let y = uv.y * view.res.y - 0.5;
    let (x0, y0) = (x.floor(), y.floor());
    let (fx, fy) = (x - x0, y - y0);
    let clampi = |v: f32, n: u32| -> u32 {
        if v < 0.0 {
            0
        } else if v > (n - 1) as f32 {
            n - 1
        } else {
            v as u32
        }
    };
    let (xa, xb) = (clampi(x0, size.x), clampi(x0 + 1.0, size.x));
    let (ya, yb) = (clampi(y0, size.y), clampi(y0 + 1.0, size.y));
    let read = |px: u32, py: u32| -> f32 { depth_or_far(gbuffer.linear_depth(UVec2::new(px, py)), view.far) };
    let top = read(xa, ya) * (1.0 - fx) + read(xb, ya) * fx;
    let bottom = read(xa, yb) * (1.0 - fx) + read(xb, yb) * fx;
    top * (1.0 - fy) + bottom * fy
}

/// Signed low-res texel `q' = q − sg` of SD texel `q`.
#[inline]
fn low_res_texel(q: UVec2, params: &SvaoParams) -> IVec2 {
    q.as_ivec2() - IVec2::splat(params.sd_guard as i32)
}

/// The jittered low-res position `(q' + J(q))/L` SD texel `q`'s ray passes through, as a uv of
/// the full target (spec svao-raysd §7.1, §7.2); where pass 2 reconstructs the texel's layers.
#[inline]
pub fn texel_ray_uv(q: UVec2, params: &SvaoParams) -> Vec2 {
    texel_ray_uv_lanes::<f32>(q.x, q.y, params)
}

/// [`texel_ray_uv`] of SD texels `(x, y)` per lane.
#[inline]
pub fn texel_ray_uv_lanes<L: crate::common::lanes::Lanes>(x: L::Index, y: L::Index, params: &SvaoParams) -> L::V2 {
    let (table, frame) = (params.jitter, params.noise_frame);
    let jitter =
        L::v2_from_lanes(move |i| sd_jitter(UVec2::new(L::index_lane(x, i), L::index_lane(y, i)), table, frame));
    let low = params.sd_low_res.as_vec2();
    let sg = params.sd_guard as f32;
    // q − sg is exact in binary32 for any texel, as the integer difference it stands for.
    L::V2::new((L::index_to_float(x) - sg + jitter.x()) / low.x, (L::index_to_float(y) - sg + jitter.y()) / low.y)
}

/// The ray of SD texel `q` (spec svao-raysd §7.1): from the camera through the jittered low-res position
/// `(q' + J(q))/L`; `tMin = d_p/cos θ + 0.1·near` behind the (bilinear, un-jittered) primary
/// depth, `tMax = far/cos θ_centre`; with the interval optimisation both are clamped to the
/// `[rayMin, rayMax]` pass 1 recorded (0 = unset), so unrequested texels get an empty interval.
#[inline]
pub fn sd_ray<G: GBuffer>(gbuffer: &G, frame: &SvaoFrame, q: UVec2, ray_min: u32, ray_max: u32) -> SdRay {
    let params = &frame.params;
    let camera = &frame.camera;
    let view = &params.vao.view;
    let low = params.sd_low_res.as_vec2();
    let qp = low_res_texel(q, params);
    let p = texel_ray_uv(q, params);
    let direction = camera.primary_ray_direction(p);
    let cos_theta = -camera.world_to_view.transform_vector3(direction).z;
    let centre = (qp.as_vec2() + 0.5) / low;
    let cos_centre = -camera.world_to_view.transform_vector3(camera.primary_ray_direction(centre)).z;
    let inside = qp.x >= 0 && qp.y >= 0 && qp.x < params.sd_low_res.x as i32 && qp.y < params.sd_low_res.y as i32;
    let dp = if inside { bilinear_depth(gbuffer, frame, centre) } else { 0.0 };
    let mut t_min = dp / cos_theta + 0.1 * view.near;
    let mut t_max = view.far / cos_centre;
    if params.interval != 0 {
        if ray_min != 0 {
            t_min = t_min.max(from_ordered_bits(ray_min));
        }
        if ray_max != 0 {
            t_max = t_max.min(from_ordered_bits(ray_max));
        }
    }
    SdRay { origin: camera.eye(), direction, t_min, t_max, cos_theta }
}

/// Pass-2 source reading the SD map (spec svao-raysd §9): the flagged sample's SD texel `q`, reconstructed
/// at its jittered low-res position, every layer combined by `min`.
pub struct SdMapRefine<'a> {
    /// `N` normalized depths per SD texel, row-major over the SD size.
    pub map: &'a [f32],
    pub params: &'a SvaoParams,
}

impl Refine for SdMapRefine<'_> {
    #[inline]
    fn refine(&mut self, frame: &PixelFrame, s: &LineSample, v: f32, _z_primary: f32) -> Refined {
        let params = self.params;
        let view = &params.vao.view;
        let q = sd_pixel(s.uv, params);
        let uv = texel_ray_uv(q, params);
        let base = params.sd_index(q) * params.sd_layers as usize;
        let mut v = v;
        let mut k = 0;
        while k < params.sd_layers as usize {
            let d = self.map[base + k] * (view.far - view.near) + view.near;
            let (_, value) = depth_point_value(params, frame, s, view.uv_to_view(uv, d));
            v = combine(params, v, value);
            k += 1;
        }
        Refined { v, rays: 0 }
    }
}

/// The SD texel's layers after tracing, written to the map (`N` values at `q·N`).
#[inline]
pub fn store_layers(map: &mut [f32], params: &SvaoParams, q: UVec2, payload: &SdPayload) {
    let base = params.sd_index(q) * params.sd_layers as usize;
    let mut k = 0;
    while k < params.sd_layers as usize {
        map[base + k] = payload.depth[k];
        k += 1;
    }
}

use crate::common::gbuffer_read::GBufferSlices;
use crate::glam::UVec3;
use crate::svao::pass2_pixel;
use spirv_std::spirv;

/// Compute entry point of AO pass 2 from the SD map (spec svao-raysd §9), in place on `ao`.
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "raysd_pass2"))]
pub fn raysd_pass2(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[SvaoFrame],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] normals: &[u32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)]
    ao: &mut [f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] mask: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] sd_map: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 6)] depth2: &[f32],
) {
    let params = &frame[0].params;
    let view = &params.vao.view;
    let p = id.truncate() + view.guard;
    if !view.is_inner(p) {
        return;
    }
    let gbuffer = GBufferSlices { depth, normals, width: view.size().x };
    let i = view.index(p);
    let mut source = SdMapRefine { map: sd_map, params };
    ao[i] = pass2_pixel(&gbuffer, depth2, params, p, ao[i], mask[i], &mut source).ao;
}
