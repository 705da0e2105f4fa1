//! Ray-query variant of the hybrid AO for `VK_KHR_ray_query`: per pixel of the full target, the
//! shared [`hybrid_pixel`] with its world rays through the ground truth's `QueriedOcclusion`.
//! Bindings are those of `hybrid_rgen` and the ground truth's any-hit together.

// On the host only the entry points' declarations exist (`#[kernel(spirv_only)]`).
#![cfg_attr(not(target_arch = "spirv"), allow(unused_imports))]

use super::{HybridFrame, hybrid_pixel};
use crate::common::alpha::{AlphaMaskHeader, AlphaTables};
use crate::common::atomics::count_rays;
use crate::common::gbuffer_read::GBufferSlices;
use crate::glam::{UVec3, Vec2};
#[cfg(target_arch = "spirv")]
use crate::groundtruth::rq::QueriedOcclusion;
use spirv_std::ray_tracing::AccelerationStructure;
use spirv_std::spirv;

#[crate::kernel(spirv_only)]
#[spirv(compute(threads(8, 8), entry_point_name = "hybrid_rq"))]
pub fn hybrid_rq(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[HybridFrame],
    #[spirv(descriptor_set = 0, binding = 1)] tlas: &AccelerationStructure,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] ao: &mut [f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] uvs: &[Vec2],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 6)] materials: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 7)] mask_headers: &[AlphaMaskHeader],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 8)] mask_texels: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 9)] terms: &mut [u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 10)] edges: &mut [u32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 11)]
    mut ray_count: &mut [u32],
) {
    let frame = &frame[0];
    let view = &frame.camera.view;
    let size = view.size();
    let p = id.truncate();
    if p.x >= size.x || p.y >= size.y {
        return;
    }
    let gbuffer = GBufferSlices { depth, normals, width: size.x };
    let alpha = AlphaTables { uvs, materials, headers: mask_headers, texels: mask_texels };
    let mut rays = QueriedOcclusion { tlas, alpha };
    let out = hybrid_pixel(&gbuffer, frame, p, &mut rays);
    count_rays(&mut ray_count, out.rays);
    let i = (p.y * size.x + p.x) as usize;
    ao[i] = out.ao;
    terms[i] = out.term;
    edges[i] = out.edges;
}
