//! Ray-tracing entry points of the SD map (spec svao-raysd §7): one ray-generation invocation
//! per SD texel, the reservoir any-hit ([`SdHits`]) on every triangle (the trace forces
//! non-opaque), and an empty miss shader.

use super::{SdHits, SdPayload, sd_ray, store_layers};
use crate::common::alpha::{AlphaMaskHeader, AlphaTables};
use crate::common::any_hit::{CandidateHit, IGNORE};
use crate::common::atomics::count_rays;
use crate::common::gbuffer_read::GBufferSlices;
use crate::glam::{UVec3, Vec2};
use crate::svao::SvaoFrame;
use spirv_std::ray_tracing::{AccelerationStructure, RayFlags};
use spirv_std::spirv;

#[crate::kernel]
#[spirv(ray_generation(entry_point_name = "raysd_rgen"))]
pub fn raysd_rgen(
    #[spirv(launch_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[SvaoFrame],
    #[spirv(descriptor_set = 0, binding = 1)] tlas: &AccelerationStructure,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] ray_min: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] ray_max: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 6)] sd_map: &mut [f32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 11)]
    mut ray_count: &mut [u32],
    #[spirv(ray_payload)] payload: &mut SdPayload,
) {
    let frame = &frame[0];
    let params = &frame.params;
    let view = &params.vao.view;
    let q = id.truncate();
    let size = params.sd_size();
    if q.x >= size.x || q.y >= size.y {
        return;
    }
    let gbuffer = GBufferSlices { depth, normals, width: view.size().x };
    let i = params.sd_index(q);
    let ray = sd_ray(&gbuffer, frame, q, ray_min[i], ray_max[i]);
    *payload = SdPayload::new(params, view.near, view.far, ray.cos_theta);
    if ray.traced() {
        count_rays(&mut ray_count, 1);
        unsafe {
            tlas.trace_ray(
                RayFlags::NO_OPAQUE | RayFlags::SKIP_CLOSEST_HIT_SHADER,
                0xff,
                0,
                0,
                0,
                ray.origin,
                ray.t_min,
                ray.direction,
                ray.t_max,
                payload,
            );
        }
    }
    store_layers(sd_map, params, q, payload);
}

#[crate::kernel]
#[spirv(miss(entry_point_name = "raysd_miss"))]
pub fn raysd_miss(#[spirv(incoming_ray_payload)] _payload: &mut SdPayload) {}

/// The reservoir any-hit; triangle `first + prim`'s corner texture coordinates are
/// `uvs[3·(first + prim) ..]`, `first` = the instance's custom index (see `crate::common::alpha`).
#[crate::kernel]
#[spirv(any_hit(entry_point_name = "raysd_ahit"))]
pub fn raysd_ahit(
    #[spirv(incoming_ray_payload)] payload: &mut SdPayload,
    #[spirv(hit_attribute)] bary: &Vec2,
    #[spirv(primitive_id)] prim: u32,
    #[spirv(instance_custom_index)] first_triangle: u32,
    #[spirv(ray_tmax)] t: f32,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 7)] uvs: &[Vec2],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 8)] materials: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 9)] mask_headers: &[AlphaMaskHeader],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 10)] mask_texels: &[f32],
) {
    let alpha = AlphaTables { uvs, materials, headers: mask_headers, texels: mask_texels };
    let mut hits = SdHits { payload: *payload, alpha };
    let decision = hits.decide(t, *bary, first_triangle + prim);
    *payload = hits.payload;
    if decision == IGNORE {
        unsafe { spirv_std::arch::ignore_intersection() };
    }
}
