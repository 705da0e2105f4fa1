//! Ray-tracing entry points of the ground truth: one ray-generation invocation per inner pixel,
//! a miss shader that clears the "occluded" payload, and an any-hit shader for the alpha test.

use super::{GroundTruthFrame, OcclusionQuery, ground_truth_pixel};
use crate::common::alpha::{AlphaMaskHeader, AlphaTables};
use crate::common::any_hit::{CandidateHit, IGNORE};
use crate::common::atomics::count_rays;
use crate::common::gbuffer_read::GBufferSlices;
use crate::glam::{UVec3, Vec2, Vec3};
use spirv_std::ray_tracing::{AccelerationStructure, RayFlags};
use spirv_std::spirv;

/// `trace_ray` as an [`OcclusionQuery`]: the payload starts at 1 (occluded), the miss shader
/// sets 0; the first accepted hit ends the ray.
pub struct TracedOcclusion<'a> {
    pub tlas: &'a AccelerationStructure,
    pub payload: &'a mut u32,
}

impl OcclusionQuery for TracedOcclusion<'_> {
    fn occluded(&mut self, origin: Vec3, direction: Vec3, t_max: f32) -> bool {
        *self.payload = 1;
        unsafe {
            self.tlas.trace_ray(
                RayFlags::TERMINATE_ON_FIRST_HIT | RayFlags::SKIP_CLOSEST_HIT_SHADER,
                0xff,
                0,
                0,
                0,
                origin,
                0.0,
                direction,
                t_max,
                self.payload,
            );
        }
        *self.payload != 0
    }
}

#[crate::kernel]
#[spirv(ray_generation(entry_point_name = "groundtruth_rgen"))]
pub fn groundtruth_rgen(
    #[spirv(launch_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[GroundTruthFrame],
    #[spirv(descriptor_set = 0, binding = 1)] tlas: &AccelerationStructure,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] ao: &mut [f32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 9)]
    mut ray_count: &mut [u32],
    #[spirv(ray_payload)] payload: &mut u32,
) {
    let frame = &frame[0];
    let view = &frame.camera.view;
    let p = id.truncate() + view.guard;
    if !view.is_inner(p) {
        return;
    }
    let gbuffer = GBufferSlices { depth, normals, width: view.size().x };
    let mut rays = TracedOcclusion { tlas, payload };
    let out = ground_truth_pixel(&gbuffer, frame, p, &mut rays);
    ao[view.index(p)] = out.ao;
    count_rays(&mut ray_count, out.rays);
}

#[crate::kernel]
#[spirv(miss(entry_point_name = "groundtruth_miss"))]
pub fn groundtruth_miss(#[spirv(incoming_ray_payload)] payload: &mut u32) {
    *payload = 0;
}

/// Alpha test of masked triangles (only non-opaque geometry runs it). Triangle `first + prim`'s
/// corner texture coordinates are `uvs[3·(first + prim) ..]`, `first` = the instance's custom
/// index (see `crate::common::alpha`).
#[crate::kernel]
#[spirv(any_hit(entry_point_name = "groundtruth_ahit"))]
pub fn groundtruth_ahit(
    #[spirv(incoming_ray_payload)] _payload: &mut u32,
    #[spirv(hit_attribute)] bary: &Vec2,
    #[spirv(primitive_id)] prim: u32,
    #[spirv(instance_custom_index)] first_triangle: u32,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] uvs: &[Vec2],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 6)] materials: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 7)] mask_headers: &[AlphaMaskHeader],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 8)] mask_texels: &[f32],
) {
    let mut alpha = AlphaTables { uvs, materials, headers: mask_headers, texels: mask_texels };
    if alpha.decide(0.0, *bary, first_triangle + prim) == IGNORE {
        unsafe { spirv_std::arch::ignore_intersection() };
    }
}
