//! CPU ray casting, built once per scene over obvhs' CWBVH (Ylitie et al. 2017): closest-hit
//! (single rays and 4×2 packets), occlusion and any-hit queries through its wide re-layout
//! (`wide`); any-hit queries offer candidates in exactly obvhs' own traversal order (the
//! order the stochastic depth map's reservoir sees).

mod wide;

pub use wide::{OriginCut, PACKET};

use aokit_shaders::glam::{Vec2, Vec3, Vec3A};
use obvhs::BvhBuildParams;
use obvhs::cwbvh::CwBvh;
use obvhs::cwbvh::builder::build_cwbvh_from_tris;
use obvhs::ray::{Ray, RayHit};
use obvhs::triangle::Triangle;
use std::cell::RefCell;
use std::time::Duration;
use wide::WideBvh;

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
    /// The same tree laid out for closest-hit and occlusion rays.
    wide: WideBvh,
}

thread_local! {
    /// The cut of the last run of occlusion rays on this thread ([`SceneBvh::occluded`]).
    static CUT: RefCell<OriginCut> = RefCell::new(OriginCut::default());
}

impl SceneBvh {
    /// Build the BVH over `triangles` (world-space vertices).
    pub fn build(triangles: &[[Vec3; 3]]) -> Self {
        let tris: Vec<Triangle> =
            triangles.iter().map(|t| Triangle { v0: t[0].into(), v1: t[1].into(), v2: t[2].into() }).collect();
        let bvh = build_cwbvh_from_tris(&tris, BvhBuildParams::medium_build(), &mut Duration::default());
        let triangles: Vec<Triangle> = bvh.primitive_indices.iter().map(|&i| tris[i as usize]).collect();
        let wide = WideBvh::build(&bvh, &triangles);
        SceneBvh { bvh, triangles, wide }
    }

    /// Closest hit along `origin + t·direction` for `t ∈ (t_min, t_max)`, both ends exclusive as
    /// on lavapipe's hardware-style traversal; of triangles hit at the same distance, the lowest
    /// BVH primitive.
    pub fn closest_hit(&self, origin: Vec3, direction: Vec3, t_min: f32, t_max: f32) -> Option<Hit> {
        let found = self.wide.closest(Vec3A::from(origin), Vec3A::from(direction), t_min, t_max, |_, _| true);
        found.map(|(t, id)| Hit { t, triangle: self.bvh.primitive_indices[id] })
    }

    /// Closest hit that `accept(triangle, barycentrics)` accepts (an alpha test, say); the
    /// barycentrics are the weights of the triangle's second and third vertex. `accept` is
    /// asked about candidates in no particular order, only about those not farther than the
    /// closest accepted so far.
    pub fn closest_accepted_hit(
        &self,
        origin: Vec3,
        direction: Vec3,
        t_min: f32,
        t_max: f32,
        accept: impl Fn(u32, Vec2) -> bool,
    ) -> Option<Hit> {
        let (o, d) = (Vec3A::from(origin), Vec3A::from(direction));
        let found = self.wide.closest(o, d, t_min, t_max, |id, _| self.accepts(o, d, id, &accept));
        found.map(|(t, id)| Hit { t, triangle: self.bvh.primitive_indices[id] })
    }

    /// [`SceneBvh::closest_hit`] of [`PACKET`] rays from one origin over one interval (camera
    /// rays of a 4×2 pixel tile), traversed together (`wide::WideBvh::closest_packet`): per ray
    /// the same triangle and distance as `closest_hit` (of hits at one distance the lowest BVH
    /// primitive, in both).
    pub fn closest_hits(
        &self,
        origin: Vec3,
        directions: &[Vec3; PACKET],
        t_min: f32,
        t_max: f32,
    ) -> [Option<Hit>; PACKET] {
        let dirs = directions.map(Vec3A::from);
        let found = self.wide.closest_packet(Vec3A::from(origin), &dirs, t_min, t_max, |_, _, _| true);
        found.map(|f| f.map(|(t, id)| Hit { t, triangle: self.bvh.primitive_indices[id] }))
    }

    /// [`SceneBvh::closest_accepted_hit`] of a packet, as [`SceneBvh::closest_hits`].
    pub fn closest_accepted_hits(
        &self,
        origin: Vec3,
        directions: &[Vec3; PACKET],
        t_min: f32,
        t_max: f32,
        accept: impl Fn(u32, Vec2) -> bool,
    ) -> [Option<Hit>; PACKET] {
        let (o, dirs) = (Vec3A::from(origin), directions.map(Vec3A::from));
        let found =
            self.wide.closest_packet(o, &dirs, t_min, t_max, |ray, id, _| self.accepts(o, dirs[ray], id, &accept));
        found.map(|f| f.map(|(t, id)| Hit { t, triangle: self.bvh.primitive_indices[id] }))
    }

    /// Whether `accept` takes a hit of BVH primitive `id` (its barycentrics as the triangle test
    /// computes them).
    #[inline]
    fn accepts(&self, origin: Vec3A, direction: Vec3A, id: usize, accept: &impl Fn(u32, Vec2) -> bool) -> bool {
        accept(self.bvh.primitive_indices[id], wide::obvhs_barycentrics(&self.triangles[id], origin, direction))
    }

    /// Is anything that `accept` accepts hit along the ray for `t ∈ (t_min, t_max)`? Stops at
    /// the first accepted hit (shadow / AO rays); `accept` sees candidates in no particular
    /// order. Consecutive calls on a thread with the same origin and `t_max` (a pixel's AO
    /// rays) share an [`OriginCut`]: the second builds it, and from then on traversal starts
    /// below the tree's top levels (same answers).
    pub fn occluded(
        &self,
        origin: Vec3,
        direction: Vec3,
        t_min: f32,
        t_max: f32,
        accept: impl Fn(u32, Vec2) -> bool,
    ) -> bool {
        let (o, d) = (Vec3A::from(origin), Vec3A::from(direction));
        let test = |id, _| self.accepts(o, d, id, &accept);
        CUT.with(|cut| match cut.try_borrow_mut() {
            Ok(mut cut) => self.wide.occluded_cut(&mut cut, o, d, t_min, t_max, test),
            // Re-entered from `accept` (tracing inside an alpha test): no shared cut.
            Err(_) => self.wide.occluded(o, d, t_min, t_max, test),
        })
    }

    /// [`SceneBvh::occluded`] from the root, without the thread's shared cut.
    pub fn occluded_uncached(
        &self,
        origin: Vec3,
        direction: Vec3,
        t_min: f32,
        t_max: f32,
        accept: impl Fn(u32, Vec2) -> bool,
    ) -> bool {
        let (o, d) = (Vec3A::from(origin), Vec3A::from(direction));
        self.wide.occluded(o, d, t_min, t_max, |id, _| self.accepts(o, d, id, &accept))
    }

    /// obvhs' own occlusion traversal of the CWBVH (the implementation before the wide
    /// layout), for comparisons.
    pub fn occluded_cwbvh(
        &self,
        origin: Vec3,
        direction: Vec3,
        t_min: f32,
        t_max: f32,
        accept: impl Fn(u32, Vec2) -> bool,
    ) -> bool {
        let ray = Ray::new(Vec3A::from(origin), Vec3A::from(direction), t_min, t_max);
        !self.bvh.ray_traverse_miss(ray, |ray, id| {
            let tri = &self.triangles[id];
            let t = tri.intersect(ray);
            if !(t > ray.tmin && t < ray.tmax) {
                return f32::INFINITY;
            }
            if self.accepts(ray.origin, ray.direction, id, &accept) { t } else { f32::INFINITY }
        })
    }

    /// obvhs' own closest-hit traversal of the CWBVH, for comparisons.
    pub fn closest_hit_cwbvh(&self, origin: Vec3, direction: Vec3, t_min: f32, t_max: f32) -> Option<Hit> {
        let ray = Ray::new(Vec3A::from(origin), Vec3A::from(direction), t_min, t_max);
        let mut hit = RayHit::none();
        let found = self.bvh.ray_traverse(ray, &mut hit, |ray, id| {
            let t = self.triangles[id].intersect(ray);
            if t > ray.tmin && t < ray.tmax { t } else { f32::INFINITY }
        });
        found.then(|| Hit { t: hit.t, triangle: self.bvh.primitive_indices[hit.primitive_id as usize] })
    }
}

/// The pixels of a band of `rows` (1 or 2) rows of `width` pixels as 4×2 tiles for
/// [`SceneBvh::closest_hits`]: each item holds eight indices into the band (row-major, the
/// tile's top row first); a tile cut by the band's edge repeats its last pixel, whose answer is
/// then written twice.
pub fn packet_tiles(width: usize, rows: usize) -> impl Iterator<Item = [usize; PACKET]> {
    assert!((1..=2).contains(&rows), "a band is one or two rows");
    (0..width).step_by(4).map(move |x0| {
        let mut tile = [0; PACKET];
        for (i, slot) in tile.iter_mut().enumerate() {
            let (x, y) = ((x0 + i % 4).min(width - 1), (i / 4).min(rows - 1));
            *slot = y * width + x;
        }
        tile
    })
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

impl AnyHit {
    /// A kernel's [`CandidateHit`](aokit_shaders::common::any_hit::CandidateHit) answer
    /// (`IGNORE`, `ACCEPT`, `ACCEPT_AND_END`) as the traversal's.
    #[inline]
    pub fn from_decision(decision: u32) -> AnyHit {
        use aokit_shaders::common::any_hit::{ACCEPT, IGNORE};
        match decision {
            IGNORE => AnyHit::Ignore,
            ACCEPT => AnyHit::Accept,
            _ => AnyHit::AcceptAndEnd,
        }
    }
}

impl SceneBvh {
    /// Trace with any-hit semantics: `any_hit(t, triangle, barycentrics)` runs for EVERY
    /// triangle hit inside the current open interval `(t_min, t_max)`, in obvhs' CWBVH
    /// traversal order (depth first, ordered by the ray's octant, not sorted by distance;
    /// `wide::WideBvh::any_hit`), exactly once per triangle. Inlined into the caller's loop:
    /// left to the compiler it became a call of its own per ray, and Ray-SVAO's rays ran 15 %
    /// slower (tower, alternating runs).
    #[inline(always)]
    pub fn trace_any_hit(
        &self,
        origin: Vec3,
        direction: Vec3,
        t_min: f32,
        t_max: f32,
        mut any_hit: impl FnMut(f32, u32, Vec2) -> AnyHit,
    ) {
        let (o, d) = (Vec3A::from(origin), Vec3A::from(direction));
        self.wide.any_hit((&self.bvh, &self.triangles), o, d, t_min, t_max, |id, t, uv| {
            any_hit(t, self.bvh.primitive_indices[id], uv)
        })
    }

    /// [`SceneBvh::trace_any_hit`] of the first `count` (≤ [`PACKET`]) rays of a packet from one
    /// origin, each over its own interval, traced together (`wide::WideBvh::any_hit_packet`):
    /// `any_hit(ray, t, triangle, barycentrics)` gets each ray's candidates in the order
    /// `trace_any_hit` offers them (coherent rays, such as the SD map's, share most node tests).
    #[inline(always)]
    pub fn trace_any_hit_packet(
        &self,
        origin: Vec3,
        directions: &[Vec3; PACKET],
        (t_min, t_max): (&[f32; PACKET], &[f32; PACKET]),
        count: usize,
        mut any_hit: impl FnMut(usize, f32, u32, Vec2) -> AnyHit,
    ) {
        assert!(count <= PACKET, "at most {PACKET} rays per packet");
        let (o, dirs) = (Vec3A::from(origin), directions.map(Vec3A::from));
        let rays = (1u32 << count) - 1;
        self.wide.any_hit_packet((&self.bvh, &self.triangles), o, &dirs, t_min, t_max, rays, |ray, id, t, uv| {
            any_hit(ray, t, self.bvh.primitive_indices[id], uv)
        })
    }

    /// [`SceneBvh::trace_any_hit`] by obvhs' own CWBVH traversal, for comparisons.
    pub fn trace_any_hit_cwbvh(
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
            let b = wide::obvhs_barycentrics(tri, ray.origin, ray.direction);
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
                hits.push((
                    t,
                    self.bvh.primitive_indices[id],
                    wide::obvhs_barycentrics(tri, ray.origin, ray.direction),
                ));
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
