//! Poisson-disk ray-marched SSAO (Sourimant, Gautron, Marvie; spec gtao-raymarch-hybrid §3):
//! per pixel, N Poisson-disk points rotated by the pixel's noise angle, lifted onto the
//! hemisphere toward the camera and rotated around the normal (cosine-distributed directions),
//! each marched in S uniform steps against the depth buffer; the occluder distance from the
//! linear crossing of Eq. 1, the accessibility of Eq. 2 with contrast exponent α.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

#[cfg(not(target_arch = "spirv"))]
pub mod kernel;
#[cfg(not(target_arch = "spirv"))]
pub mod settings;

use crate::common::ViewParams;
use crate::common::denoise_terms::{edges, pack_edges, store_term};
use crate::common::math::{is_valid_depth, rotate_minimal, sat};
use crate::common::noise::spatio_temporal_noise;
use crate::common::normal_codec::decode_normal;
use crate::common::screen_space::{clamp_index, neighbour, view_pos};
use crate::glam::{UVec2, UVec3, Vec2, Vec3, vec2, vec3};
use spirv_std::spirv;

/// Most Poisson-disk directions a kernel may hold.
pub const MAX_DIRECTIONS: u32 = 64;

/// How a hit direction contributes (spec §3.4 step 8, aokit's two readings of Eq. 2).
#[repr(u32)]
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Contribution {
    /// `c = sat(Δ̃/R)`: visible free distance over R (obscurance with linear falloff) [default].
    Linear = 0,
    /// `c = 0` on any hit: in expectation the cosine-weighted ground truth of §5.
    Binary = 1,
}

/// Ray-marched SSAO parameters (push constants; spec §3.2 defaults in brackets).
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct RaymarchParams {
    /// Projection of the full target.
    pub view: ViewParams,
    /// March distance R in world units [the ground truth's radius].
    pub radius: f32,
    /// Contrast exponent α of Eq. 2 [1].
    pub alpha: f32,
    /// Relative depth bias κ [0.0008].
    pub depth_bias: f32,
    /// Thickness T_max of depth-buffer surfaces [a huge number: a pure height field].
    pub thickness: f32,
    /// Directions N (8/16/24) [16], at most [`MAX_DIRECTIONS`].
    pub directions: u32,
    /// Steps S per direction [8].
    pub steps: u32,
    /// [`Contribution`] as `u32`.
    pub contribution: u32,
    /// Temporal noise frame [0].
    pub noise_frame: u32,
}

/// XeGTAO-space (+z forward) uv of a view point: the inverse of [`view_pos`].
#[inline]
fn project(view: &ViewParams, s: Vec3) -> Vec2 {
    vec2(0.5 + 0.5 * s.x / (view.tan_half_fov.x * s.z), 0.5 - 0.5 * s.y / (view.tan_half_fov.y * s.z))
}

/// Linear depth at a uv (point sampling, clamp-to-edge; unusable depths read as far).
#[inline]
pub fn depth_at(view: &ViewParams, depth: &[f32], uv: Vec2) -> f32 {
    let size = view.size();
    let x = clamp_index((uv.x * view.res.x).floor(), size.x);
    let y = clamp_index((uv.y * view.res.y).floor(), size.y);
    let d = depth[(y * size.x + x) as usize];
    if is_valid_depth(d, view.far) { d } else { view.far }
}

/// Result of marching one direction: the occluder distance Δ̃ (Eq. 1) or none.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct March {
    pub hit: bool,
    pub distance: f32,
}

/// March `steps` uniform steps from `pos` along unit `dir` (XeGTAO view space) with step jitter
/// `jitter`: `t_j = R·(j − jitter)/S`. A step is free while it is nearer than the depth buffer
/// (`S.z < z·(1+κ)`) or more than `thickness` behind it; the first other step is the hit, and
/// Eq. 1 interpolates the crossing from the gaps `δ = |S − T|` of it and the step before
/// (`t_0 = δ_0 = 0`). Leaving the screen ends the march without a hit (spec §3.4 steps 6–7).
/// A step that projects into the shaded pixel `home` is free [aokit: its only depth is the
/// pixel's own centre, so on a tilted surface every step moving away from the camera would
/// otherwise hit the surface it starts on].
#[inline]
pub fn march(
    view: &ViewParams,
    depth: &[f32],
    pos: Vec3,
    dir: Vec3,
    radius: f32,
    steps: u32,
    jitter: f32,
    depth_bias: f32,
    thickness: f32,
    home: UVec2,
    normals: &[u32],
) -> March {
    let (mut t_prev, mut gap_prev) = (0.0f32, 0.0f32);
    let mut j = 1;
    while j <= steps {
        let t = radius * (j as f32 - jitter) / steps as f32;
        let s = pos + dir * t;
        if s.z <= 0.0 {
            break;
        }
        let uv = project(view, s);
        if !(uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0) {
            break;
        }
        let z = depth_at(view, depth, uv);
        let gap = (s - view_pos(view, uv, z)).length();
        let q = view.texel_of_uv(uv);
        let zp = plane_depth(view, normals, q, z, uv);
        let free = q == home || s.z < zp * (1.0 + depth_bias) || s.z - zp > thickness;
        if !free {
            let sum = gap_prev + gap;
            let distance = if sum < 1e-6 { t_prev } else { t_prev + gap_prev * (t - t_prev) / sum };
            return March { hit: true, distance };
        }
        t_prev = t;
        gap_prev = gap;
        j += 1;
    }
    March { hit: false, distance: radius }
}

/// The G-buffer's right-handed normal at `p` in XeGTAO space, turned toward the camera at `pos`.
#[inline]
pub fn facing_normal(normals: &[u32], width: u32, p: UVec2, pos: Vec3) -> Vec3 {
    let n = decode_normal(normals[(p.y * width + p.x) as usize]);
    let n = vec3(n.x, n.y, -n.z);
    if n.dot(-pos) < 0.0 { -n } else { n }
}

/// Direction for disk point `d` (unit disk) lifted toward the camera and rotated to the normal
/// (spec §3.4 steps 4–5; §4.2 step 2): Malley's method, cosine-distributed around `n`.
#[inline]
pub fn hemisphere_dir(d: Vec2, n: Vec3) -> Vec3 {
    let lifted = vec3(d.x, d.y, -(1.0 - d.x * d.x - d.y * d.y).max(0.0).sqrt());
    rotate_minimal::<f32>(vec3(0.0, 0.0, -1.0), n, lifted)
}

/// Depth where the view ray through `uv` meets the tangent plane of texel `q` (centre depth `z`,
/// G-buffer normal), the texel's centre depth where that plane is seen edge-on.
#[inline]
fn plane_depth(view: &ViewParams, normals: &[u32], q: UVec2, z: f32, uv: Vec2) -> f32 {
    let c = view_pos(view, view.texel_uv(q), z);
    let n = decode_normal(normals[(q.y * view.size().x + q.x) as usize]);
    let n = vec3(n.x, n.y, -n.z);
    let r = view_pos(view, uv, 1.0);
    let denom = n.dot(r);
    if denom.abs() < 1e-3 { z } else { n.dot(c) / denom }
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
    let d = depth[(q.y * view.size().x + q.x) as usize];
    if is_valid_depth(d, view.far) { d } else { view.far }
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

/// Ray-marched AO of pixel `p` (spec §3.4); `kernel` holds the N unit-disk points.
#[inline]
pub fn raymarch_pixel(
    params: &RaymarchParams,
    depth: &[f32],
    normals: &[u32],
    kernel: &[Vec2],
    p: UVec2,
) -> RaymarchPixel {
    let view = &params.view;
    let edges = depth_edges(view, depth, p);
    let zc = depth[(p.y * view.size().x + p.x) as usize];
    if !is_valid_depth(zc, view.far) {
        return RaymarchPixel { ao: 1.0, term: store_term(1.0), edges };
    }
    let pos = view_pos(view, view.pixel_uv(p), zc);
    let n = facing_normal(normals, view.size().x, p, pos);
    let xi = spatio_temporal_noise(p, params.noise_frame);
    let theta = 2.0 * core::f32::consts::PI * xi.x;
    let (sin_t, cos_t) = (theta.sin(), theta.cos());
    let count = params.directions.min(MAX_DIRECTIONS).min(kernel.len() as u32).max(1);
    let mut sum = 0.0;
    let mut i = 0;
    while i < count {
        let k = kernel[i as usize];
        let d = vec2(cos_t * k.x - sin_t * k.y, sin_t * k.x + cos_t * k.y);
        let dir = hemisphere_dir(d, n);
        let steps = params.steps.max(1);
        let m =
            march(view, depth, pos, dir, params.radius, steps, xi.y, params.depth_bias, params.thickness, p, normals);
        sum += if !m.hit {
            1.0
        } else if params.contribution == Contribution::Binary as u32 {
            0.0
        } else {
            sat(m.distance / params.radius)
        };
        i += 1;
    }
    let ao = (sum / count as f32).powf(params.alpha);
    RaymarchPixel { ao, term: store_term(ao), edges }
}

/// Compute entry point, one invocation per pixel of the full target.
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
