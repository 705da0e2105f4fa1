//! CPU ray casting through obvhs' CWBVH (Ylitie et al. 2017), built once per scene.

use aokit_shaders::glam::{Vec2, Vec3, Vec3A, vec2};
use obvhs::BvhBuildParams;
use obvhs::cwbvh::CwBvh;
use obvhs::cwbvh::builder::build_cwbvh_from_tris;
use obvhs::ray::{Ray, RayHit};
use obvhs::triangle::Triangle;
use std::time::Duration;

/// Closest-hit record of a ray.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Hit {
    /// Ray distance (direction is unit length, so world units).
    pub t: f32,
    /// Index of the triangle in the scene's triangle list.
    pub triangle: u32,
}

/// A triangle soup and its BVH. Triangles are stored in BVH order for cache-friendly tests.
pub struct SceneBvh {
    bvh: CwBvh,
    /// Triangles in BVH primitive order.
    triangles: Vec<Triangle>,
}

impl SceneBvh {
    /// Build the BVH over `triangles` (world-space vertices).
    pub fn build(triangles: &[[Vec3; 3]]) -> Self {
        let tris: Vec<Triangle> =
            triangles.iter().map(|t| Triangle { v0: t[0].into(), v1: t[1].into(), v2: t[2].into() }).collect();
        let bvh = build_cwbvh_from_tris(&tris, BvhBuildParams::medium_build(), &mut Duration::default());
        let triangles = bvh.primitive_indices.iter().map(|&i| tris[i as usize]).collect();
        SceneBvh { bvh, triangles }
    }

    /// Closest hit along `origin + t·direction` for `t ∈ (t_min, t_max)`, both ends exclusive as
    /// on lavapipe's hardware-style traversal.
    pub fn closest_hit(&self, origin: Vec3, direction: Vec3, t_min: f32, t_max: f32) -> Option<Hit> {
        self.closest_accepted_hit(origin, direction, t_min, t_max, |_, _| true)
    }

    /// Closest hit that `accept(triangle, barycentrics)` accepts (an alpha test, say); the
    /// barycentrics are the weights of the triangle's second and third vertex.
    pub fn closest_accepted_hit(
        &self,
        origin: Vec3,
        direction: Vec3,
        t_min: f32,
        t_max: f32,
        accept: impl Fn(u32, Vec2) -> bool,
    ) -> Option<Hit> {
        let ray = Ray::new(Vec3A::from(origin), Vec3A::from(direction), t_min, t_max);
        let mut hit = RayHit::none();
        let found = self.bvh.ray_traverse(ray, &mut hit, |ray, id| self.accepted_t(ray, id, &accept));
        found.then(|| Hit { t: hit.t, triangle: self.bvh.primitive_indices[hit.primitive_id as usize] })
    }
}

impl SceneBvh {
    /// Distance to BVH primitive `id` if the ray hits it inside its open interval and `accept`
    /// takes the hit; ∞ otherwise (obvhs' intersection-callback convention).
    fn accepted_t(&self, ray: &Ray, id: usize, accept: &impl Fn(u32, Vec2) -> bool) -> f32 {
        let tri = &self.triangles[id];
        let t = tri.intersect(ray);
        if !(t > ray.tmin && t < ray.tmax) {
            return f32::INFINITY;
        }
        let p = ray.origin + ray.direction * t;
        if accept(self.bvh.primitive_indices[id], barycentrics(p, tri)) { t } else { f32::INFINITY }
    }

    /// Is anything that `accept` accepts hit along the ray for `t ∈ (t_min, t_max)`? Stops at
    /// the first accepted hit (shadow / AO rays).
    pub fn occluded(
        &self,
        origin: Vec3,
        direction: Vec3,
        t_min: f32,
        t_max: f32,
        accept: impl Fn(u32, Vec2) -> bool,
    ) -> bool {
        let ray = Ray::new(Vec3A::from(origin), Vec3A::from(direction), t_min, t_max);
        !self.bvh.ray_traverse_miss(ray, |ray, id| self.accepted_t(ray, id, &accept))
    }
}

/// What an any-hit function decides about a candidate hit (DXR / Vulkan semantics).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum AnyHit {
    /// The hit does not count; traversal continues with the same interval.
    Ignore,
    /// Commit the hit: `tMax` shrinks to its distance, only nearer candidates follow.
    Accept,
    /// Commit the hit and end the search (`terminateRayEXT`).
    AcceptAndEnd,
}

impl SceneBvh {
    /// Trace with any-hit semantics: `any_hit(t, triangle, barycentrics)` runs for EVERY
    /// triangle hit inside the current open interval `(t_min, t_max)`, in the BVH's traversal
    /// order (front-to-back by node, not sorted by distance), exactly once per triangle.
    pub fn trace_any_hit(
        &self,
        origin: Vec3,
        direction: Vec3,
        t_min: f32,
        t_max: f32,
        mut any_hit: impl FnMut(f32, u32, Vec2) -> AnyHit,
    ) {
        let ray = Ray::new(Vec3A::from(origin), Vec3A::from(direction), t_min, t_max);
        let mut hit = RayHit::none();
        let mut ended = false;
        self.bvh.ray_traverse(ray, &mut hit, |ray, id| {
            if ended {
                return f32::INFINITY;
            }
            let tri = &self.triangles[id];
            let t = tri.intersect(ray);
            if !(t > ray.tmin && t < ray.tmax) {
                return f32::INFINITY;
            }
            let b = barycentrics(ray.origin + ray.direction * t, tri);
            match any_hit(t, self.bvh.primitive_indices[id], b) {
                AnyHit::Ignore => f32::INFINITY,
                AnyHit::Accept => t,
                AnyHit::AcceptAndEnd => {
                    ended = true;
                    t
                }
            }
        });
    }

    /// Every triangle hit `(t, triangle, barycentrics)` inside the open interval, in traversal
    /// order.
    pub fn all_hits(&self, origin: Vec3, direction: Vec3, t_min: f32, t_max: f32) -> Vec<(f32, u32, Vec2)> {
        let ray = Ray::new(Vec3A::from(origin), Vec3A::from(direction), t_min, t_max);
        let mut hits = Vec::new();
        self.bvh.ray_traverse_anyhit(ray, |ray, id| {
            let tri = &self.triangles[id];
            let t = tri.intersect(ray);
            if t > ray.tmin && t < ray.tmax {
                hits.push((t, self.bvh.primitive_indices[id], barycentrics(ray.origin + ray.direction * t, tri)));
            }
        });
        hits
    }
}

/// Replay candidate hits in the given order with any-hit semantics: a hit is offered only while
/// it lies inside the current interval, `Accept` shrinks `t_max`, `AcceptAndEnd` stops. This
/// emulates a traversal that reports hits in an arbitrary order (hardware gives no guarantee).
pub fn replay_any_hit(
    hits: &[(f32, u32, Vec2)],
    t_min: f32,
    mut t_max: f32,
    mut any_hit: impl FnMut(f32, u32, Vec2) -> AnyHit,
) {
    for &(t, tri, b) in hits {
        if !(t > t_min && t < t_max) {
            continue;
        }
        match any_hit(t, tri, b) {
            AnyHit::Ignore => {}
            AnyHit::Accept => t_max = t,
            AnyHit::AcceptAndEnd => return,
        }
    }
}

/// Barycentric weights `(b1, b2)` of `v1` and `v2` for a point `p` in the triangle's plane.
fn barycentrics(p: Vec3A, tri: &Triangle) -> Vec2 {
    let (e1, e2, d) = (tri.v1 - tri.v0, tri.v2 - tri.v0, p - tri.v0);
    let (d00, d01, d11) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
    let (d20, d21) = (d.dot(e1), d.dot(e2));
    let denom = d00 * d11 - d01 * d01;
    vec2(d11 * d20 - d01 * d21, d00 * d21 - d01 * d20) / denom
}
