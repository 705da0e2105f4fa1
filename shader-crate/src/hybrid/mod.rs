//! Hybrid ray-traced AO (Bavoil, Liu, Shirley, McGuire; spec gtao-raymarch-hybrid §4): per pixel
//! one screen-space ray marched against the depth buffer and one world-space ray traced through
//! the scene, blended with weight 2/3 on the world ray, then XeGTAO's denoiser (3 passes). The
//! pure variants (2 screen rays, 2 world rays) are configurations of the same kernel.

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
use crate::common::denoise_terms::store_term;
use crate::common::gbuffer_read::GBufferSlices;
use crate::common::math::{frac, is_valid_depth};
use crate::common::noise::{hilbert_index, spatio_temporal_noise};
use crate::common::screen_space::view_pos;
use crate::glam::{UVec2, Vec2, vec2, vec3};
use crate::groundtruth::{OcclusionQuery, surface_point};
use crate::raymarch::{depth_edges, facing_normal, hemisphere_dir, march};

/// Hybrid parameters (spec gtao-raymarch-hybrid §4.1 defaults in brackets).
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct HybridParams {
    /// Ray length R [the ground truth's radius].
    pub radius: f32,
    /// Weight of the world rays' mean, `w_ws` [2/3].
    pub world_weight: f32,
    /// Relative depth bias κ of the screen march [0.0008].
    pub depth_bias: f32,
    /// Screen rays per pixel `n_ss` \[1\].
    pub screen_rays: u32,
    /// World rays per pixel `n_ws` \[1\].
    pub world_rays: u32,
    /// Steps of a screen ray `S_ss` \[16\].
    pub screen_steps: u32,
    /// Temporal noise frame \[0\].
    pub noise_frame: u32,
    pub _pad: u32,
}

/// The camera and hybrid parameters as one storage-buffer record.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct HybridFrame {
    /// The camera (view transform and projection) of the frame.
    pub camera: Camera,
    /// The hybrid AO's constants.
    pub params: HybridParams,
}

/// Unit-disk point of a uniform pair: `(√u₁ cos 2πu₂, √u₁ sin 2πu₂)` (Malley, spec gtao-raymarch-hybrid §4.2 step 2).
#[inline]
pub fn disk(u: Vec2) -> Vec2 {
    let r = u.x.sqrt();
    let a = 2.0 * core::f32::consts::PI * u.y;
    vec2(r * a.cos(), r * a.sin())
}

/// Output of one pixel before the denoiser.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct HybridPixel {
    /// `v = (1 − w)·mean(v_ss) + w·mean(v_ws)`.
    pub ao: f32,
    pub term: u32,
    pub edges: u32,
    /// World rays traced (0 on the background).
    pub rays: u32,
}

/// Hybrid AO of pixel `p` (spec gtao-raymarch-hybrid §4.2). Ray slot k uses `u_k = frac(ξ + k·(½, ½))`; world rays
/// take the first `n_ws` slots, screen rays the next `n_ss`, so the default pairs `u_ws = ξ` with
/// `u_ss = frac(ξ + ½)`. Screen rays march `S_ss` steps with jitter `frac(0.5 + i·0.618…)` (i the
/// noise index), Binary, no thickness, off-screen = miss; world rays are one ground-truth sample
/// each (`rays`: `trace_ray` on the GPU, the BVH on the CPU).
#[inline]
pub fn hybrid_pixel<Q: OcclusionQuery>(
    gbuffer: &GBufferSlices,
    frame: &HybridFrame,
    p: UVec2,
    rays: &mut Q,
) -> HybridPixel {
    let camera = &frame.camera;
    let params = &frame.params;
    let view = &camera.view;
    let edges = depth_edges(view, gbuffer.depth, p);
    let z = gbuffer.depth[(p.y * gbuffer.width + p.x) as usize];
    let surface = surface_point(gbuffer, camera, p, params.radius);
    if surface.background || !is_valid_depth(z, view.far) {
        return HybridPixel { ao: 1.0, term: store_term(1.0), edges, rays: 0 };
    }
    let pos = view_pos(view, view.pixel_uv(p), z);
    let n = facing_normal(gbuffer.normals, gbuffer.width, p, pos);
    let xi = spatio_temporal_noise(p, params.noise_frame);
    let index = (hilbert_index(p) + 288 * (params.noise_frame % 64)) as f32;
    let jitter = frac(0.5 + index * 0.618_034);
    let (mut world, mut screen, mut traced) = (0.0, 0.0, 0);
    let total = params.world_rays + params.screen_rays;
    let mut k = 0;
    while k < total {
        let u = vec2(frac(xi.x + 0.5 * k as f32), frac(xi.y + 0.5 * k as f32));
        let dir = hemisphere_dir::<f32>(disk(u), n);
        if k < params.world_rays {
            // XeGTAO space (+z forward) → right-handed view → world.
            let w = camera.view_to_world.transform_vector3(vec3(dir.x, dir.y, -dir.z)).normalize();
            traced += 1;
            if !rays.occluded(surface.origin, w, params.radius) {
                world += 1.0;
            }
        } else {
            let (r, steps, bias) = (params.radius, params.screen_steps, params.depth_bias);
            let m = march(view, gbuffer.depth, pos, dir, r, steps, jitter, bias, f32::MAX, p, gbuffer.normals);
            if !m.hit {
                screen += 1.0;
            }
        }
        k += 1;
    }
    let mean = |sum: f32, count: u32| if count > 0 { sum / count as f32 } else { 0.0 };
    let ao = (1.0 - params.world_weight) * mean(screen, params.screen_rays)
        + params.world_weight * mean(world, params.world_rays);
    HybridPixel { ao, term: store_term(ao), edges, rays: traced }
}
