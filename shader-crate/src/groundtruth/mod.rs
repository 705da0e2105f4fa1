//! World-space ray-traced ambient occlusion, the library's ground truth (spec
//! gtao-raymarch-hybrid §5): from the G-buffer point, offset along its face normal, rays over the
//! hemisphere (cosine-weighted by default, uniform optionally) bounded by the AO radius, binary
//! visibility, a reproducible low-discrepancy sequence per pixel. 1 = unoccluded.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

// The ray-query entry points exist in SPIR-V only (built with the `rq` feature); their
// declarations (`#[kernel(spirv_only)]`) exist on the host too.
#[cfg(any(feature = "rq", not(target_arch = "spirv")))]
pub mod rq;
#[cfg(any(feature = "rt", not(target_arch = "spirv")))]
pub mod rt;
#[cfg(not(target_arch = "spirv"))]
pub mod settings;

use crate::common::camera::Camera;
use crate::common::gbuffer_read::GBuffer;
use crate::common::math::{frac, is_valid_depth};
use crate::common::noise::{frame_rotation, rotate};
use crate::glam::{UVec2, Vec2, Vec3, vec2, vec3};

/// Ground-truth parameters.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct GroundTruthParams {
    /// World-space ray length (the AO radius).
    pub radius: f32,
    /// Exponent applied to the visible fraction, as for every technique (1 = raw visibility).
    pub exponent: f32,
    /// Samples per pixel (512 by default).
    pub samples: u32,
    /// 0: cosine-weighted hemisphere; 1: uniform hemisphere (visibility weighted by cos θ).
    pub uniform: u32,
}

/// PCG-style 32-bit integer hash (O'Neill's PCG output permutation), exact on CPU and GPU.
#[inline]
pub fn pcg_hash(v: u32) -> u32 {
    let state = v.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    let word = ((state >> ((state >> 28) + 4)) ^ state).wrapping_mul(277_803_737);
    (word >> 22) ^ word
}

/// Plastic-constant R2 sequence (Roberts 2018), `frac(0.5 + k·(1/g, 1/g²))`, g = 1.3247179…,
/// Cranley–Patterson-rotated per pixel by a hash so neighbouring pixels decorrelate.
#[inline]
pub fn sample_2d(k: u32, pixel: UVec2) -> Vec2 {
    const A1: f32 = 0.754_877_7; // 1/g
    const A2: f32 = 0.569_840_3; // 1/g²
    let h = pcg_hash(pixel.x ^ pcg_hash(pixel.y));
    let shift = vec2((h & 0xFFFF) as f32 / 65536.0, (h >> 16) as f32 / 65536.0);
    // k·a computed as frac(k·a) in two steps keeps precision for large k.
    let kf = k as f32;
    vec2(frac(0.5 + frac(kf * A1) + shift.x), frac(0.5 + frac(kf * A2) + shift.y))
}

/// Orthonormal basis around unit `n` (Duff et al. 2017, "Building an Orthonormal Basis,
/// Revisited").
#[inline]
pub fn basis(n: Vec3) -> (Vec3, Vec3) {
    let sign = if n.z < 0.0 { -1.0 } else { 1.0 };
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), vec3(b, sign + n.y * n.y * a, -n.y))
}

/// Direction over the hemisphere around `n` for the uniform sample `u`: cosine-weighted
/// (Malley: disc radius `sqrt(u.x)`, `cos θ = sqrt(1 − u.x)`) or uniform (`cos θ = u.x`).
#[inline]
pub fn hemisphere_direction(n: Vec3, u: Vec2, uniform: bool) -> Vec3 {
    let cos_theta = if uniform { u.x } else { (1.0 - u.x).max(0.0).sqrt() };
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    let phi = 2.0 * core::f32::consts::PI * u.y;
    let (t, b) = basis(n);
    (t * (sin_theta * phi.cos()) + b * (sin_theta * phi.sin()) + n * cos_theta).normalize()
}

/// Contribution of one ray to the visible fraction: 1 when unoccluded for the cosine-weighted
/// estimator; `2·cos θ` for the uniform one (its pdf is 1/2π, the cosine integral π).
#[inline]
pub fn visibility_weight(n: Vec3, dir: Vec3, uniform: bool) -> f32 {
    if uniform { 2.0 * n.dot(dir).max(0.0) } else { 1.0 }
}

/// Final AO from the summed visibility weights of `samples` rays: `sat(mean)^exponent`.
#[inline]
pub fn finalize(visible: f32, params: &GroundTruthParams) -> f32 {
    crate::common::math::sat(visible / params.samples as f32).powf(params.exponent)
}

/// Answers "is this ray blocked before `t_max`?": `trace_ray` on the GPU, the BVH on the CPU.
pub trait OcclusionQuery {
    fn occluded(&mut self, origin: Vec3, direction: Vec3, t_max: f32) -> bool;
}

/// Everything a ground-truth pixel needs besides the G-buffer (a storage-buffer record: too big
/// for guaranteed push-constant space).
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct GroundTruthFrame {
    /// The camera (view transform and projection) of the frame.
    pub camera: Camera,
    /// The ground truth's constants.
    pub params: GroundTruthParams,
    /// The frame's index in a sequence: every sample is Cranley–Patterson-rotated by its
    /// `crate::common::noise::frame_rotation` (0 for a single frame: no rotation).
    pub noise_frame: u32,
    pub _pad0: u32,
    pub _pad1: u32,
    pub _pad2: u32,
}

/// Where world-space AO rays of a pixel start.
#[derive(Copy, Clone, Debug)]
pub struct SurfacePoint {
    /// No usable depth (the pixel is sky).
    pub background: bool,
    /// The G-buffer point, offset along the normal by `1e-4·(t + R)`.
    pub origin: Vec3,
    /// World face normal turned toward the camera ray.
    pub normal: Vec3,
}

/// The G-buffer point of pixel `p` in the world, pushed off the surface along its camera-facing
/// face normal by `1e-4·(t + R)` (t: camera distance) so AO rays of length R do not hit it.
#[inline]
pub fn surface_point<G: GBuffer>(gbuffer: &G, camera: &Camera, p: UVec2, radius: f32) -> SurfacePoint {
    let d = gbuffer.linear_depth(p);
    if !is_valid_depth(d, camera.view.far) {
        return SurfacePoint { background: true, origin: Vec3::ZERO, normal: Vec3::Z };
    }
    let dir = camera.primary_ray_direction(camera.view.pixel_uv(p));
    let t = d / -camera.world_to_view.transform_vector3(dir).z;
    let mut n = camera.view_to_world.transform_vector3(gbuffer.view_normal(p));
    if n.dot(dir) > 0.0 {
        n = -n;
    }
    SurfacePoint { background: false, origin: camera.eye() + dir * t + n * (1e-4 * (t + radius)), normal: n }
}

/// One pixel's ground truth and the rays it traced.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct GroundTruthPixel {
    pub ao: f32,
    /// Rays traced: `samples`, 0 on the background.
    pub rays: u32,
}

/// Ground-truth AO of pixel `p`: rays from the G-buffer point, offset along its camera-facing
/// face normal by `1e-4·(t + R)`, `samples` directions from [`sample_2d`] rotated by the
/// frame's [`frame_rotation`], visible fraction through [`finalize`]. Background pixels are 1.
#[inline]
pub fn ground_truth_pixel<G: GBuffer, Q: OcclusionQuery>(
    gbuffer: &G,
    frame: &GroundTruthFrame,
    p: UVec2,
    rays: &mut Q,
) -> GroundTruthPixel {
    let params = &frame.params;
    let surface = surface_point(gbuffer, &frame.camera, p, params.radius);
    if surface.background {
        return GroundTruthPixel { ao: 1.0, rays: 0 };
    }
    let (origin, n) = (surface.origin, surface.normal);
    let uniform = params.uniform != 0;
    let rotation = frame_rotation(frame.noise_frame);
    let mut visible = 0.0;
    let mut k = 0;
    while k < params.samples {
        let u = sample_2d(k, p);
        let w = hemisphere_direction(n, vec2(rotate(u.x, rotation.x), rotate(u.y, rotation.y)), uniform);
        if !rays.occluded(origin, w, params.radius) {
            visible += visibility_weight(n, w, uniform);
        }
        k += 1;
    }
    GroundTruthPixel { ao: finalize(visible, params), rays: k }
}
