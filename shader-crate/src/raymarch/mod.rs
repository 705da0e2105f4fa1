//! Poisson-disk ray-marched SSAO (Sourimant, Gautron, Marvie; spec gtao-raymarch-hybrid §3):
//! per pixel, N Poisson-disk points rotated by the pixel's noise angle, lifted onto the
//! hemisphere toward the camera and rotated around the normal (cosine-distributed directions),
//! each marched in S uniform steps against the depth buffer; the occluder distance from the
//! linear crossing of Eq. 1, the accessibility of Eq. 2 with contrast exponent α.

// f32 methods on SPIR-V (`sin`, `cos`, `powf`, `sqrt`, `max`) come from `Lanes`.
#[cfg(not(target_arch = "spirv"))]
pub mod kernel;
#[cfg(not(target_arch = "spirv"))]
pub mod settings;

use crate::common::ViewParams;
use crate::common::denoise_terms::{edges, pack_edges, store_term};
use crate::common::gbuffer_read::decoded_normals;
use crate::common::lanes::{LaneVec2, LaneVec3, Lanes, texel_eq};
use crate::common::math::{depth_or_far, is_valid_depth, rotate_minimal, sat};
use crate::common::noise::spatio_temporal_noise;
use crate::common::normal_codec::decode_normal;
use crate::common::read::read;
use crate::common::screen_space::{neighbour, view_pos};
use crate::glam::{UVec2, UVec3, Vec2, Vec3, vec3};
use spirv_std::spirv;

/// Most Poisson-disk directions a kernel may hold.
pub const MAX_DIRECTIONS: u32 = 64;

/// How a hit direction contributes (spec gtao-raymarch-hybrid §3.4 step 8, aokit's two readings of Eq. 2).
#[repr(u32)]
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Contribution {
    /// `c = sat(Δ̃/R)`: visible free distance over R (obscurance with linear falloff) \[default\].
    Linear = 0,
    /// `c = 0` on any hit: in expectation the cosine-weighted ground truth of gtao-raymarch-hybrid §5.
    Binary = 1,
}

/// Ray-marched SSAO parameters (push constants; spec gtao-raymarch-hybrid §3.2 defaults in brackets).
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct RaymarchParams {
    /// Projection of the full target.
    pub view: ViewParams,
    /// March distance R in world units [the ground truth's radius].
    pub radius: f32,
    /// Contrast exponent α of Eq. 2 \[1\].
    pub alpha: f32,
    /// Relative depth bias κ [0.0008].
    pub depth_bias: f32,
    /// Thickness T_max of depth-buffer surfaces [a huge number: a pure height field].
    pub thickness: f32,
    /// Directions N (8/16/24) \[16\], at most [`MAX_DIRECTIONS`].
    pub directions: u32,
    /// Steps S per direction \[8\].
    pub steps: u32,
    /// [`Contribution`] as `u32`.
    pub contribution: u32,
    /// Temporal noise frame \[0\].
    pub noise_frame: u32,
}

/// XeGTAO-space (+z forward) uv of a view point: the inverse of [`view_pos`].
#[inline]
fn project<L: Lanes>(view: &ViewParams, s: L::V3) -> L::V2 {
    L::V2::new(s.x() * 0.5 / (s.z() * view.tan_half_fov.x) + 0.5, -(s.y() * 0.5 / (s.z() * view.tan_half_fov.y)) + 0.5)
}

/// Linear depth at a uv (point sampling, clamp-to-edge; unusable depths read as far).
#[inline]
pub fn depth_at<L: Lanes>(view: &ViewParams, depth: &[f32], uv: L::V2) -> L {
    let size = view.size();
    let w = L::index_splat(size.x);
    let x = (uv.x() * view.res.x).floor_index(w);
    let y = (uv.y() * view.res.y).floor_index(L::index_splat(size.y));
    let d = L::gather_index(depth, y * w + x);
    depth_or_far(d, view.far)
}

/// Result of marching one direction: the occluder distance Δ̃ (Eq. 1) or none (then the
/// distance is R).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct March<L: Lanes = f32> {
    pub hit: L::Mask,
    pub distance: L,
}

/// March `steps` uniform steps from `pos` along unit `dir` (XeGTAO view space) with step jitter
/// `jitter`: `t_j = R·(j − jitter)/S`. A step is free while it is nearer than the depth buffer
/// (`S.z < z·(1+κ)`) or more than `thickness` behind it; the first other step is the hit, and
/// Eq. 1 interpolates the crossing from the gaps `δ = |S − T|` of it and the step before
/// (`t_0 = δ_0 = 0`). Leaving the screen ends the march without a hit (spec gtao-raymarch-hybrid §3.4 steps 6–7).
/// A step that projects into the shaded pixel `home` is free [aokit: its only depth is the
/// pixel's own centre, so on a tilted surface every step moving away from the camera would
/// otherwise hit the surface it starts on]. Per lane: a lane stops at its hit or when it leaves
/// the screen; the loop ends when no lane marches.
#[inline]
#[allow(clippy::too_many_arguments)]
pub fn march<L: Lanes>(
    view: &ViewParams,
    depth: &[f32],
    pos: L::V3,
    dir: L::V3,
    radius: f32,
    steps: u32,
    jitter: L,
    depth_bias: f32,
    thickness: f32,
    home: L::U2,
    normals: &[u32],
) -> March<L> {
    let zero = L::splat(0.0);
    let (mut t_prev, mut gap_prev) = (zero, zero);
    let mut marching = L::mask_splat(true);
    let mut hit = L::mask_splat(false);
    let mut distance = L::splat(radius);
    let mut j = 1;
    while j <= steps {
        let t = (-jitter + j as f32) * radius / steps as f32;
        let s = pos + dir * t;
        let uv = project::<L>(view, s);
        let (x, y) = (uv.x(), uv.y());
        let on_screen = L::and(L::and(x.ge(zero), x.le(L::splat(1.0))), L::and(y.ge(zero), y.le(L::splat(1.0))));
        marching = L::and(marching, L::and(s.z().gt(zero), on_screen));
        if !L::any(marching) {
            break;
        }
        let z = depth_at::<L>(view, depth, uv);
        let gap = (s - view_pos(view, uv, z)).length();
        let q = view.texel_of_uv_lanes::<L>(uv);
        let zp = plane_depth(view, normals, q, z, uv);
        let free = L::or(
            texel_eq::<L>(q, home),
            L::or(s.z().lt(zp * (1.0 + depth_bias)), L::gt(s.z() - zp, L::splat(thickness))),
        );
        let hit_now = L::and(marching, L::not(free));
        let sum = gap_prev + gap;
        let crossing = L::select(sum.lt(L::splat(1e-6)), t_prev, t_prev + gap_prev * (t - t_prev) / sum);
        distance = L::select(hit_now, crossing, distance);
        hit = L::or(hit, hit_now);
        marching = L::and(marching, free);
        if !L::any(marching) {
            break;
        }
        t_prev = t;
        gap_prev = gap;
        j += 1;
    }
    March { hit, distance }
}

/// The G-buffer's right-handed normal at `p` in XeGTAO space, turned toward the camera at `pos`.
#[inline]
pub fn facing_normal(normals: &[u32], width: u32, p: UVec2, pos: Vec3) -> Vec3 {
    let n = decode_normal(unsafe { read(normals, (p.y * width + p.x) as usize) });
    let n = vec3(n.x, n.y, -n.z);
    if n.dot(-pos) < 0.0 { -n } else { n }
}

/// Direction for disk point `d` (unit disk) lifted toward the camera and rotated to the normal
/// (spec gtao-raymarch-hybrid §3.4 steps 4–5, §4.2 step 2): Malley's method, cosine-distributed around `n`.
#[inline]
pub fn hemisphere_dir<L: Lanes>(d: L::V2, n: L::V3) -> L::V3 {
    let (x, y) = (d.x(), d.y());
    let lifted = L::V3::new(x, y, -(-(x * x) + 1.0 - y * y).max(L::splat(0.0)).sqrt());
    let zero = L::splat(0.0);
    rotate_minimal::<L>(L::V3::new(zero, zero, L::splat(-1.0)), n, lifted)
}

/// Depth where the view ray through `uv` meets the tangent plane of texel `q` (centre depth `z`,
/// G-buffer normal), the texel's centre depth where that plane is seen edge-on.
#[inline]
fn plane_depth<L: Lanes>(view: &ViewParams, normals: &[u32], q: L::U2, z: L, uv: L::V2) -> L {
    let c = view_pos(view, view.texel_uv_lanes::<L>(q), z);
    let n = decoded_normals::<L>(normals, view.size().x, q);
    let n = L::V3::new(n.x(), n.y(), -n.z());
    let r = view_pos(view, uv, L::splat(1.0));
    let denom = n.dot(r);
    L::select(denom.abs().lt(L::splat(1e-3)), z, n.dot(c) / denom)
}

/// Output of one pixel: visibility `A = (mean c)^α`, its denoiser term and packed edges.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct RaymarchPixel {
    pub ao: f32,
    pub term: u32,
    pub edges: u32,
}

/// Linear depth of pixel `q` (unusable depths read as far).
#[inline]
fn depth_px(view: &ViewParams, depth: &[f32], q: UVec2) -> f32 {
    depth_or_far(unsafe { read(depth, (q.y * view.size().x + q.x) as usize) }, view.far)
}

/// Packed XeGTAO edges of pixel `p` from the linear depth (for the optional denoiser).
#[inline]
pub fn depth_edges(view: &ViewParams, depth: &[f32], p: UVec2) -> u32 {
    let size = view.size();
    pack_edges(edges(
        depth_px(view, depth, p),
        depth_px(view, depth, neighbour(p, -1, 0, size)),
        depth_px(view, depth, neighbour(p, 1, 0, size)),
        depth_px(view, depth, neighbour(p, 0, -1, size)),
        depth_px(view, depth, neighbour(p, 0, 1, size)),
    ))
}

/// Ray-marched AO of pixel `p` (spec gtao-raymarch-hybrid §3.4); `kernel` holds the N unit-disk points.
#[inline]
pub fn raymarch_pixel(
    params: &RaymarchParams,
    depth: &[f32],
    normals: &[u32],
    kernel: &[Vec2],
    p: UVec2,
) -> RaymarchPixel {
    let (edges, setup) = raymarch_setup(params, depth, normals, p);
    match setup {
        Some(setup) => raymarch_finish(params, kernel, edges, raymarch_sum(params, depth, normals, kernel, &setup)),
        None => unshaded(edges),
    }
}

/// A pixel without a usable depth: visible.
#[inline]
pub fn unshaded(edges: u32) -> RaymarchPixel {
    RaymarchPixel { ao: 1.0, term: store_term(1.0), edges }
}

/// What pixel `p` marches from (spec gtao-raymarch-hybrid §3.4 steps 1–3), per lane in [`raymarch_sum`].
#[derive(Copy, Clone, Debug)]
pub struct MarchOrigin<L: Lanes = f32> {
    pub pixel: L::U2,
    /// View position (XeGTAO space) and the normal facing the camera.
    pub pos: L::V3,
    pub n: L::V3,
    /// The noise's rotation of the disk, `θ = 2π·ξ.x`, as sine and cosine.
    pub sin_t: L,
    pub cos_t: L,
    /// Step jitter `ξ.y`.
    pub jitter: L,
}

#[cfg(not(target_arch = "spirv"))]
impl MarchOrigin<crate::common::lanes::CpuLanes> {
    /// The origins of cpu-sim's [`CPU_LANES`](crate::common::lanes::CPU_LANES) pixels side by
    /// side (lane `i` from `each[i]`).
    pub fn from_lanes(each: &[MarchOrigin; crate::common::lanes::CPU_LANES]) -> Self {
        use crate::common::lanes::{CpuLanes, v3_from_lanes};
        MarchOrigin {
            pixel: <CpuLanes as Lanes>::U2::from_texels(&each.map(|o| o.pixel)),
            pos: v3_from_lanes::<CpuLanes>(|i| each[i].pos),
            n: v3_from_lanes::<CpuLanes>(|i| each[i].n),
            sin_t: CpuLanes::from_lanes(|i| each[i].sin_t),
            cos_t: CpuLanes::from_lanes(|i| each[i].cos_t),
            jitter: CpuLanes::from_lanes(|i| each[i].jitter),
        }
    }
}

/// The packed edges of pixel `p` and where it marches from; `None` without a usable depth.
#[inline]
pub fn raymarch_setup(params: &RaymarchParams, depth: &[f32], normals: &[u32], p: UVec2) -> (u32, Option<MarchOrigin>) {
    let view = &params.view;
    let edges = depth_edges(view, depth, p);
    let zc = unsafe { read(depth, (p.y * view.size().x + p.x) as usize) };
    if !is_valid_depth(zc, view.far) {
        return (edges, None);
    }
    let pos = view_pos(view, view.pixel_uv(p), zc);
    let n = facing_normal(normals, view.size().x, p, pos);
    let xi = spatio_temporal_noise(p, params.noise_frame);
    let theta = 2.0 * core::f32::consts::PI * xi.x;
    let origin = MarchOrigin { pixel: p, pos, n, sin_t: theta.sin(), cos_t: theta.cos(), jitter: xi.y };
    (edges, Some(origin))
}

/// `Σ c` over the directions (spec gtao-raymarch-hybrid §3.4 steps 4–8): each disk point rotated by the noise,
/// lifted to the hemisphere, marched; `c` = 1 without a hit, else 0 (binary) or `sat(Δ̃/R)`.
#[inline]
pub fn raymarch_sum<L: Lanes>(
    params: &RaymarchParams,
    depth: &[f32],
    normals: &[u32],
    kernel: &[Vec2],
    o: &MarchOrigin<L>,
) -> L {
    let count = direction_count(params, kernel);
    let steps = params.steps.max(1);
    let mut sum = L::splat(0.0);
    let mut i = 0;
    while i < count {
        let k = kernel[i as usize];
        let d = L::V2::new(o.cos_t * k.x - o.sin_t * k.y, o.sin_t * k.x + o.cos_t * k.y);
        let dir = hemisphere_dir::<L>(d, o.n);
        let m = march(
            &params.view,
            depth,
            o.pos,
            dir,
            params.radius,
            steps,
            o.jitter,
            params.depth_bias,
            params.thickness,
            o.pixel,
            normals,
        );
        let c = if params.contribution == Contribution::Binary as u32 {
            L::splat(0.0)
        } else {
            sat(m.distance / params.radius)
        };
        sum = sum + L::select(m.hit, c, L::splat(1.0));
        i += 1;
    }
    sum
}

/// Directions marched: `N`, at most [`MAX_DIRECTIONS`] and the kernel's length, at least 1.
#[inline]
pub fn direction_count(params: &RaymarchParams, kernel: &[Vec2]) -> u32 {
    params.directions.min(MAX_DIRECTIONS).min(kernel.len() as u32).max(1)
}

/// The pixel's output from `Σ c`: visibility `A = (Σc/N)^α` (Eq. 2) and its denoiser term.
#[inline]
pub fn raymarch_finish(params: &RaymarchParams, kernel: &[Vec2], edges: u32, sum: f32) -> RaymarchPixel {
    let count = direction_count(params, kernel);
    let ao = Lanes::powf(sum / count as f32, params.alpha);
    RaymarchPixel { ao, term: store_term(ao), edges }
}

/// Compute entry point, one invocation per pixel of the full target.
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "raymarch_main"))]
pub fn raymarch_main(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &RaymarchParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] kernel: &[Vec2],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] ao: &mut [f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] terms: &mut [u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] edges: &mut [u32],
) {
    let size = params.view.size();
    let p = id.truncate();
    if p.x >= size.x || p.y >= size.y {
        return;
    }
    let out = raymarch_pixel(params, depth, normals, kernel, p);
    let i = (p.y * size.x + p.x) as usize;
    ao[i] = out.ao;
    terms[i] = out.term;
    edges[i] = out.edges;
}
