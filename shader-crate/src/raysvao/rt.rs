//! Ray-tracing entry points of Ray-SVAO (spec svao-raysd §10): pass 2 as a ray-generation shader
//! over the inner image, one ray per flagged sample, the halo any-hit on every triangle.

use super::{ACCEPT_AND_END, IGNORE, SampleHits, SampleRay, SampleRayState, SampleTracer, refine_by_ray};
use crate::common::alpha::{AlphaMaskHeader, AlphaTables};
use crate::common::any_hit::CandidateHit;
use crate::common::atomics::count_rays;
use crate::common::camera::Camera;
use crate::common::gbuffer_read::GBufferSlices;
use crate::glam::{UVec3, Vec2};
use crate::svao::{Refine, Refined, SvaoParams};
use crate::svao::{SvaoFrame, pass2_pixel};
use crate::vao::kernel::{LineSample, PixelFrame};
use spirv_std::ray_tracing::{AccelerationStructure, RayFlags};
use spirv_std::spirv;

/// `trace_ray` with the sample state as payload. One flat struct that is both the tracer and
/// the pass-2 source: rust-gpu cannot legalize the payload pointer inside a nested struct
/// (`TracedRefine<TlasTracer>` fails spirv-val with "not a logical pointer").
struct TlasRefine<'a> {
    tlas: &'a AccelerationStructure,
    payload: &'a mut SampleRayState,
    camera: &'a Camera,
    params: &'a SvaoParams,
}

impl Refine for TlasRefine<'_> {
    fn refine(&mut self, frame: &PixelFrame, s: &LineSample, v: f32, z_primary: f32) -> Refined {
        let (camera, params) = (self.camera, self.params);
        refine_by_ray(camera, params, frame, s, v, z_primary, self)
    }
}

impl SampleTracer for TlasRefine<'_> {
    fn trace(&mut self, ray: &mut SampleRay) {
        *self.payload = ray.state;
        unsafe {
            self.tlas.trace_ray(
                RayFlags::NO_OPAQUE | RayFlags::SKIP_CLOSEST_HIT_SHADER,
                0xff,
                0,
                0,
                0,
                ray.origin,
                ray.t_min,
                ray.direction,
                ray.t_max,
                self.payload,
            );
        }
        ray.state = *self.payload;
    }
}

#[crate::kernel]
#[spirv(ray_generation(entry_point_name = "raysvao_rgen"))]
pub fn raysvao_rgen(
    #[spirv(launch_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[SvaoFrame],
    #[spirv(descriptor_set = 0, binding = 1)] tlas: &AccelerationStructure,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] normals: &[u32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)]
    ao: &mut [f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] mask: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 10)] depth2: &[f32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 11)]
    mut ray_count: &mut [u32],
    #[spirv(ray_payload)] payload: &mut SampleRayState,
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
    let mut source = TlasRefine { tlas, payload, camera: &frame.camera, params };
    let out = pass2_pixel(&gbuffer, depth2, params, p, ao[i], mask[i], &mut source);
    ao[i] = out.ao;
    count_rays(&mut ray_count, out.rays);
}

#[crate::kernel]
#[spirv(miss(entry_point_name = "raysvao_miss"))]
pub fn raysvao_miss(#[spirv(incoming_ray_payload)] _payload: &mut SampleRayState) {}

/// [`SampleHits`]: the alpha test, then the halo decision.
#[crate::kernel]
#[spirv(any_hit(entry_point_name = "raysvao_ahit"))]
pub fn raysvao_ahit(
    #[spirv(incoming_ray_payload)] payload: &mut SampleRayState,
    #[spirv(hit_attribute)] bary: &Vec2,
    #[spirv(primitive_id)] prim: u32,
    #[spirv(instance_custom_index)] first_triangle: u32,
    #[spirv(ray_tmax)] t: f32,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 6)] uvs: &[Vec2],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 7)] materials: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 8)] mask_headers: &[AlphaMaskHeader],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 9)] mask_texels: &[f32],
) {
    let alpha = AlphaTables { uvs, materials, headers: mask_headers, texels: mask_texels };
    let mut hits = SampleHits { state: *payload, alpha };
    let decision = hits.decide(t, *bary, first_triangle + prim);
    *payload = hits.state;
    if decision == IGNORE {
        unsafe { spirv_std::arch::ignore_intersection() };
    }
    if decision == ACCEPT_AND_END {
        unsafe { spirv_std::arch::terminate_ray() };
    }
}
