//! Ray-query variant of the ground truth for `VK_KHR_ray_query`: one compute invocation per
//! inner pixel, occlusion rays through `QueriedOcclusion`. Bindings are those of
//! `groundtruth_rgen` and `groundtruth_ahit` together.

// On the host only the entry points' declarations exist (`#[kernel(spirv_only)]`).
#![cfg_attr(not(target_arch = "spirv"), allow(unused_imports))]

use super::{GroundTruthFrame, OcclusionQuery, ground_truth_pixel};
use crate::common::alpha::{AlphaMaskHeader, AlphaTables};
#[cfg(target_arch = "spirv")]
use crate::common::any_hit::query_candidates;
use crate::common::atomics::count_rays;
use crate::common::gbuffer_read::GBufferSlices;
use crate::glam::{UVec3, Vec2, Vec3};
use spirv_std::ray_tracing::{AccelerationStructure, RayFlags};
use spirv_std::spirv;

/// An [`OcclusionQuery`] through a ray query: opaque triangles commit at once, masked ones when
/// they pass the alpha test ([`AlphaTables`]' decision), and the first commit ends the ray.
#[cfg(target_arch = "spirv")]
pub struct QueriedOcclusion<'a> {
    pub tlas: &'a AccelerationStructure,
    pub alpha: AlphaTables<'a>,
}

#[cfg(target_arch = "spirv")]
impl OcclusionQuery for QueriedOcclusion<'_> {
    fn occluded(&mut self, origin: Vec3, direction: Vec3, t_max: f32) -> bool {
        query_candidates(self.tlas, RayFlags::TERMINATE_ON_FIRST_HIT, origin, 0.0, direction, t_max, &mut self.alpha)
    }
}

#[crate::kernel(spirv_only)]
#[spirv(compute(threads(8, 8), entry_point_name = "groundtruth_rq"))]
pub fn groundtruth_rq(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[GroundTruthFrame],
    #[spirv(descriptor_set = 0, binding = 1)] tlas: &AccelerationStructure,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] ao: &mut [f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] uvs: &[Vec2],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 6)] materials: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 7)] mask_headers: &[AlphaMaskHeader],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 8)] mask_texels: &[f32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 9)]
    mut ray_count: &mut [u32],
) {
    let frame = &frame[0];
    let view = &frame.camera.view;
    let p = id.truncate() + view.guard;
    if !view.is_inner(p) {
        return;
    }
    let gbuffer = GBufferSlices { depth, normals, width: view.size().x };
    let alpha = AlphaTables { uvs, materials, headers: mask_headers, texels: mask_texels };
    let mut rays = QueriedOcclusion { tlas, alpha };
    let out = ground_truth_pixel(&gbuffer, frame, p, &mut rays);
    ao[view.index(p)] = out.ao;
    count_rays(&mut ray_count, out.rays);
}
