//! Ray-generation entry point of the hybrid AO: per pixel of the full target, the shared
//! [`hybrid_pixel`] with its world rays traced through the TLAS. The pipeline reuses the ground
//! truth's miss and any-hit (alpha test) shaders, so the alpha buffers sit at their bindings 5–8.

use super::{HybridFrame, hybrid_pixel};
use crate::common::atomics::count_rays;
use crate::common::gbuffer_read::GBufferSlices;
use crate::glam::UVec3;
use crate::groundtruth::rt::TracedOcclusion;
use spirv_std::ray_tracing::AccelerationStructure;
use spirv_std::spirv;

#[crate::kernel]
#[spirv(ray_generation(entry_point_name = "hybrid_rgen"))]
pub fn hybrid_rgen(
    #[spirv(launch_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[HybridFrame],
    #[spirv(descriptor_set = 0, binding = 1)] tlas: &AccelerationStructure,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] ao: &mut [f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 9)] terms: &mut [u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 10)] edges: &mut [u32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 11)]
    mut ray_count: &mut [u32],
    #[spirv(ray_payload)] payload: &mut u32,
) {
    let frame = &frame[0];
    let view = &frame.camera.view;
    let size = view.size();
    let p = id.truncate();
    if p.x >= size.x || p.y >= size.y {
        return;
    }
    let gbuffer = GBufferSlices { depth, normals, width: size.x };
    let mut rays = TracedOcclusion { tlas, payload };
    let out = hybrid_pixel(&gbuffer, frame, p, &mut rays);
    count_rays(&mut ray_count, out.rays);
    let i = (p.y * size.x + p.x) as usize;
    ao[i] = out.ao;
    terms[i] = out.term;
    edges[i] = out.edges;
}
