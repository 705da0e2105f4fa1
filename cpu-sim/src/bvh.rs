//! CPU ray casting through obvhs' CWBVH (Ylitie et al. 2017), built once per scene.

use aokit_shaders::glam::{Vec3, Vec3A};
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
        let tris: Vec<Triangle> = triangles
            .iter()
            .map(|t| Triangle { v0: t[0].into(), v1: t[1].into(), v2: t[2].into() })
            .collect();
        let bvh = build_cwbvh_from_tris(&tris, BvhBuildParams::medium_build(), &mut Duration::default());
        let triangles = bvh.primitive_indices.iter().map(|&i| tris[i as usize]).collect();
        SceneBvh { bvh, triangles }
    }

    /// Closest hit along `origin + t·direction` for `t ∈ (t_min, t_max)`, both ends exclusive as
    /// on lavapipe's hardware-style traversal.
    pub fn closest_hit(&self, origin: Vec3, direction: Vec3, t_min: f32, t_max: f32) -> Option<Hit> {
        let ray = Ray::new(Vec3A::from(origin), Vec3A::from(direction), t_min, t_max);
        let mut hit = RayHit::none();
        let found = self.bvh.ray_traverse(ray, &mut hit, |ray, id| {
            let t = self.triangles[id].intersect(ray);
            if t > ray.tmin && t < ray.tmax { t } else { f32::INFINITY }
        });
        found.then(|| Hit { t: hit.t, triangle: self.bvh.primitive_indices[hit.primitive_id as usize] })
    }
}
