//! Ray-query variant of the SD map (spec svao-raysd §7) for `VK_KHR_ray_query`: one compute
//! invocation per SD texel, the same ray as `raysd_rgen` and the same reservoir decision
//! ([`SdHits`]) over the candidate loop of `query_candidates` — no shader binding table.
//! Bindings are those of `raysd_rgen` and `raysd_ahit` together.

// On the host only the entry points' declarations exist (`#[kernel(spirv_only)]`).
#![cfg_attr(not(target_arch = "spirv"), allow(unused_imports))]

use super::{SdHits, SdPayload, sd_ray, store_layers};
use crate::common::alpha::{AlphaMaskHeader, AlphaTables};
#[cfg(target_arch = "spirv")]
use crate::common::any_hit::query_candidates;
use crate::common::atomics::count_rays;
use crate::common::gbuffer_read::GBufferSlices;
use crate::glam::{UVec3, Vec2};
use crate::svao::SvaoFrame;
use spirv_std::ray_tracing::{AccelerationStructure, RayFlags};
use spirv_std::spirv;

#[crate::kernel(spirv_only)]
#[spirv(compute(threads(8, 8), entry_point_name = "raysd_rq"))]
pub fn raysd_rq(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[SvaoFrame],
    #[spirv(descriptor_set = 0, binding = 1)] tlas: &AccelerationStructure,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] ray_min: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] ray_max: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 6)] sd_map: &mut [f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 7)] uvs: &[Vec2],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 8)] materials: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 9)] mask_headers: &[AlphaMaskHeader],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 10)] mask_texels: &[f32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 11)]
    mut ray_count: &mut [u32],
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
    let alpha = AlphaTables { uvs, materials, headers: mask_headers, texels: mask_texels };
    let mut hits = SdHits { payload: SdPayload::new(params, view.near, view.far, ray.cos_theta), alpha };
    if ray.traced() {
        count_rays(&mut ray_count, 1);
        query_candidates(tlas, RayFlags::NO_OPAQUE, ray.origin, ray.t_min, ray.direction, ray.t_max, &mut hits);
    }
    store_layers(sd_map, params, q, &hits.payload);
}
