//! Ray-query variant of Ray-SVAO's pass 2 (spec svao-raysd §10) for `VK_KHR_ray_query`: one
//! compute invocation per inner pixel, each flagged sample's ray with the same decision
//! ([`SampleHits`]) over the candidate loop of `query_candidates`. Bindings are those of
//! `raysvao_rgen` and `raysvao_ahit` together.

// On the host only the entry points' declarations exist (`#[kernel(spirv_only)]`).
#![cfg_attr(not(target_arch = "spirv"), allow(unused_imports))]

use super::{SampleHits, SampleRay, SampleTracer, refine_by_ray};
use crate::common::alpha::{AlphaMaskHeader, AlphaTables};
#[cfg(target_arch = "spirv")]
use crate::common::any_hit::query_candidates;
use crate::common::atomics::count_rays;
use crate::common::camera::Camera;
use crate::common::gbuffer_read::GBufferSlices;
use crate::glam::{UVec3, Vec2};
use crate::svao::{Refine, Refined, SvaoFrame, SvaoParams, pass2_pixel};
use crate::vao::kernel::{LineSample, PixelFrame};
use spirv_std::ray_tracing::{AccelerationStructure, RayFlags};
use spirv_std::spirv;

/// Pass 2's source: every flagged sample's ray through a ray query.
#[cfg(target_arch = "spirv")]
struct QueryRefine<'a> {
    tlas: &'a AccelerationStructure,
    alpha: AlphaTables<'a>,
    camera: &'a Camera,
    params: &'a SvaoParams,
}

#[cfg(target_arch = "spirv")]
impl Refine for QueryRefine<'_> {
    fn refine(&mut self, frame: &PixelFrame, s: &LineSample, v: f32, z_primary: f32) -> Refined {
        let (camera, params) = (self.camera, self.params);
        refine_by_ray(camera, params, frame, s, v, z_primary, self)
    }
}

#[cfg(target_arch = "spirv")]
impl SampleTracer for QueryRefine<'_> {
    fn trace(&mut self, ray: &mut SampleRay) {
        let mut hits = SampleHits { state: ray.state, alpha: self.alpha };
        query_candidates(self.tlas, RayFlags::NO_OPAQUE, ray.origin, ray.t_min, ray.direction, ray.t_max, &mut hits);
        ray.state = hits.state;
    }
}

#[crate::kernel(spirv_only)]
#[spirv(compute(threads(8, 8), entry_point_name = "raysvao_rq"))]
pub fn raysvao_rq(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[SvaoFrame],
    #[spirv(descriptor_set = 0, binding = 1)] tlas: &AccelerationStructure,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] normals: &[u32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)]
    ao: &mut [f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] mask: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 6)] uvs: &[Vec2],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 7)] materials: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 8)] mask_headers: &[AlphaMaskHeader],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 9)] mask_texels: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 10)] depth2: &[f32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 11)]
    mut ray_count: &mut [u32],
) {
    let frame = &frame[0];
    let params = &frame.params;
    let view = &params.vao.view;
    let p = id.truncate() + view.guard;
    if !view.is_inner(p) {
        return;
    }
    let i = view.index(p);
    let gbuffer = GBufferSlices { depth, normals, width: view.size().x };
    let alpha = AlphaTables { uvs, materials, headers: mask_headers, texels: mask_texels };
    let mut source = QueryRefine { tlas, alpha, camera: &frame.camera, params };
    let out = pass2_pixel(&gbuffer, depth2, params, p, ao[i], mask[i], &mut source);
    ao[i] = out.ao;
    count_rays(&mut ray_count, out.rays);
}
