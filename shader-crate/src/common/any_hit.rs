//! What an any-hit decides about a candidate triangle (Vulkan `VK_KHR_ray_tracing_pipeline`
//! any-hit semantics, the same for the ray-query candidate loop of `VK_KHR_ray_query`), and the
//! candidate loop itself.
//!
//! Each ray-traced technique writes its decision once, as a [`CandidateHit`]: the any-hit shader
//! of its ray-tracing pipeline calls it and maps the answer to `ignoreIntersectionEXT` /
//! return / `terminateRayEXT`; the ray-query variant calls it from `query_candidates`
//! (`rayQueryConfirmIntersectionEXT` / skip / `rayQueryTerminateEXT`); the CPU simulator calls it
//! from its BVH traversal. A candidate is triangle `InstanceCustomIndex + PrimitiveId` at ray
//! distance `t` with barycentrics `bary` (weights of its second and third corner).

use crate::glam::Vec2;

/// The hit does not count; traversal continues over the same interval.
pub const IGNORE: u32 = 0;
/// Commit the hit: `tMax` shrinks to its distance, only nearer candidates follow.
pub const ACCEPT: u32 = 1;
/// Commit the hit and end the traversal.
pub const ACCEPT_AND_END: u32 = 2;

/// A technique's any-hit decision over the candidates of one ray.
pub trait CandidateHit {
    /// [`IGNORE`], [`ACCEPT`] or [`ACCEPT_AND_END`] for triangle `triangle` hit at `t`.
    fn decide(&mut self, t: f32, bary: Vec2, triangle: u32) -> u32;
}

/// Trace `origin + t·direction`, `t ∈ (t_min, t_max)`, through `tlas` with a ray query: every
/// candidate triangle goes to `hit.decide`, which confirms it ([`ACCEPT`]), skips it
/// ([`IGNORE`]) or confirms it and ends the query ([`ACCEPT_AND_END`]) — exactly what the
/// any-hit shader does in a ray-tracing pipeline, so an engine needs no shader binding table.
/// Triangles of opaque geometry (unless `flags` has `NO_OPAQUE`) are committed without a
/// candidate, as a pipeline commits them without running the any-hit. Returns whether a
/// triangle was committed.
#[cfg(all(target_arch = "spirv", feature = "rq"))]
#[inline]
pub fn query_candidates<H: CandidateHit>(
    tlas: &spirv_std::ray_tracing::AccelerationStructure,
    flags: spirv_std::ray_tracing::RayFlags,
    origin: crate::glam::Vec3,
    t_min: f32,
    direction: crate::glam::Vec3,
    t_max: f32,
    hit: &mut H,
) -> bool {
    use spirv_std::ray_tracing::{CommittedIntersection, RayQuery};
    unsafe {
        spirv_std::ray_query!(let mut query);
        query.initialize(tlas, flags, 0xff, origin, t_min, direction, t_max);
        while query.proceed() {
            let t = query.get_candidate_intersection_t();
            let bary = query.get_candidate_intersection_barycentrics();
            let triangle = query.get_candidate_intersection_instance_custom_index()
                + query.get_candidate_intersection_primitive_index();
            let decision = hit.decide(t, bary, triangle);
            if decision != IGNORE {
                query.confirm_intersection();
            }
            if decision == ACCEPT_AND_END {
                query.terminate();
            }
        }
        query.get_committed_intersection_type() == CommittedIntersection::Triangle
    }
}
