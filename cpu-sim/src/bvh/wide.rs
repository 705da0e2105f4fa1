//! The traversal structure behind [`SceneBvh`](super::SceneBvh)'s closest-hit and occlusion
//! queries (the goal: CPU rays at Embree's pace). The topology is obvhs' CWBVH (Ylitie et al.
//! 2017: its PLOC BVH2 collapsed into an 8-wide tree by their SAH dynamic programme, at most
//! three triangles per leaf); only the layout differs:
//!
//! - a node holds its eight children's exact float boxes in SoA lanes (no 8-bit quantisation to
//!   undo per test), tested 8 at a time with AVX where the CPU has it, two 4-lane halves
//!   otherwise — the same IEEE operations, so the same answers;
//! - a leaf is one SoA block of up to four triangles holding what obvhs' Möller–Trumbore test
//!   computes per triangle (`e1 = v0 − v1`, `e2 = v2 − v0`, `n = e1 × e2`), tested 4 at a time
//!   by the very same arithmetic (Möller & Trumbore 1997, in the form of
//!   `obvhs::triangle::Triangle::intersect`): a hit is where that test hits;
//! - closest-hit traversal visits children nearest first and drops stack entries beyond the
//!   best hit; occlusion traversal stops at the first accepted hit; any-hit traversal offers
//!   candidates in obvhs' order, one ray at a time or as a packet of rays from one origin;
//! - [`OriginCut`]: rays that share an origin and a length (a pixel's AO rays) start below the
//!   BVH's top levels.

use aokit_shaders::glam::{Vec2, Vec3A};
use obvhs::cwbvh::CwBvh;
use obvhs::triangle::Triangle;
use std::mem::MaybeUninit;

/// Four-lane f32 vector: SSE on x86-64, an array elsewhere, with the same IEEE operations (no
/// fused multiply-add), so both give the same answers.
mod lanes {
    #[cfg(target_arch = "x86_64")]
    use std::arch::x86_64::*;

    #[cfg(target_arch = "x86_64")]
    #[derive(Copy, Clone)]
    pub struct F4(__m128);

    // SAFETY (every `unsafe` below): SSE and SSE2 are part of the x86-64 baseline.
    #[cfg(target_arch = "x86_64")]
    impl F4 {
        #[inline(always)]
        pub fn splat(x: f32) -> F4 {
            F4(unsafe { _mm_set1_ps(x) })
        }
        #[inline(always)]
        pub fn load(a: &[f32; 4]) -> F4 {
            F4(unsafe { _mm_loadu_ps(a.as_ptr()) })
        }
        #[inline(always)]
        pub fn add(self, b: F4) -> F4 {
            F4(unsafe { _mm_add_ps(self.0, b.0) })
        }
        #[inline(always)]
        pub fn sub(self, b: F4) -> F4 {
            F4(unsafe { _mm_sub_ps(self.0, b.0) })
        }
        #[inline(always)]
        pub fn mul(self, b: F4) -> F4 {
            F4(unsafe { _mm_mul_ps(self.0, b.0) })
        }
        #[inline(always)]
        pub fn div(self, b: F4) -> F4 {
            F4(unsafe { _mm_div_ps(self.0, b.0) })
        }
        /// `c − a·b` as glam 0.34's `m128_neg_mul_sub` computes it (inside `Vec3A::cross`):
        /// one rounding (`vfnmadd`) where the build targets FMA, two otherwise.
        #[inline(always)]
        pub fn neg_mul_sub(a: F4, b: F4, c: F4) -> F4 {
            #[cfg(target_feature = "fma")]
            let out = F4(unsafe { _mm_fnmadd_ps(a.0, b.0, c.0) });
            #[cfg(not(target_feature = "fma"))]
            let out = c.sub(a.mul(b));
            out
        }
        /// `if a < b { a } else { b }` per lane.
        #[inline(always)]
        pub fn min(self, b: F4) -> F4 {
            F4(unsafe { _mm_min_ps(self.0, b.0) })
        }
        /// `if a > b { a } else { b }` per lane.
        #[inline(always)]
        pub fn max(self, b: F4) -> F4 {
            F4(unsafe { _mm_max_ps(self.0, b.0) })
        }
        /// Bit `i` set where lane `i` has `a <= b`.
        #[inline(always)]
        pub fn le(self, b: F4) -> u32 {
            unsafe { _mm_movemask_ps(_mm_cmple_ps(self.0, b.0)) as u32 }
        }
        /// Bit `i` set where lane `i` has `a < b`.
        #[inline(always)]
        pub fn lt(self, b: F4) -> u32 {
            unsafe { _mm_movemask_ps(_mm_cmplt_ps(self.0, b.0)) as u32 }
        }
        /// Bit `i` set where lane `i` has `a != b` (true for NaN, as Rust's `!=`).
        #[inline(always)]
        pub fn ne(self, b: F4) -> u32 {
            unsafe { _mm_movemask_ps(_mm_cmpneq_ps(self.0, b.0)) as u32 }
        }
        /// Bit `i` set where any of `a`, `b`, `c` has its sign bit set in lane `i`.
        #[inline(always)]
        pub fn any_sign(a: F4, b: F4, c: F4) -> u32 {
            unsafe { _mm_movemask_ps(_mm_or_ps(a.0, _mm_or_ps(b.0, c.0))) as u32 }
        }
        #[inline(always)]
        pub fn to_array(self) -> [f32; 4] {
            let mut out = [0.0; 4];
            unsafe { _mm_storeu_ps(out.as_mut_ptr(), self.0) };
            out
        }
    }

    #[cfg(not(target_arch = "x86_64"))]
    #[derive(Copy, Clone)]
    pub struct F4([f32; 4]);

    #[cfg(not(target_arch = "x86_64"))]
    impl F4 {
        #[inline(always)]
        fn zip(self, b: F4, f: impl Fn(f32, f32) -> f32) -> F4 {
            F4(std::array::from_fn(|i| f(self.0[i], b.0[i])))
        }
        #[inline(always)]
        fn bits(self, b: F4, f: impl Fn(f32, f32) -> bool) -> u32 {
            (0..4).fold(0, |m, i| m | ((f(self.0[i], b.0[i]) as u32) << i))
        }
        #[inline(always)]
        pub fn splat(x: f32) -> F4 {
            F4([x; 4])
        }
        #[inline(always)]
        pub fn load(a: &[f32; 4]) -> F4 {
            F4(*a)
        }
        #[inline(always)]
        pub fn add(self, b: F4) -> F4 {
            self.zip(b, |x, y| x + y)
        }
        #[inline(always)]
        pub fn sub(self, b: F4) -> F4 {
            self.zip(b, |x, y| x - y)
        }
        #[inline(always)]
        pub fn mul(self, b: F4) -> F4 {
            self.zip(b, |x, y| x * y)
        }
        #[inline(always)]
        pub fn div(self, b: F4) -> F4 {
            self.zip(b, |x, y| x / y)
        }
        #[inline(always)]
        pub fn min(self, b: F4) -> F4 {
            self.zip(b, |x, y| if x < y { x } else { y })
        }
        #[inline(always)]
        pub fn max(self, b: F4) -> F4 {
            self.zip(b, |x, y| if x > y { x } else { y })
        }
        #[inline(always)]
        pub fn le(self, b: F4) -> u32 {
            self.bits(b, |x, y| x <= y)
        }
        #[inline(always)]
        pub fn lt(self, b: F4) -> u32 {
            self.bits(b, |x, y| x < y)
        }
        #[inline(always)]
        pub fn ne(self, b: F4) -> u32 {
            self.bits(b, |x, y| x != y)
        }
        #[inline(always)]
        pub fn any_sign(a: F4, b: F4, c: F4) -> u32 {
            (0..4).fold(0, |m, i| m | (((a.0[i].to_bits() | b.0[i].to_bits() | c.0[i].to_bits()) >> 31) << i))
        }
        #[inline(always)]
        pub fn to_array(self) -> [f32; 4] {
            self.0
        }
    }
}

use lanes::F4;

/// Marks a child reference as a leaf (a block index) rather than a node index.
const LEAF: u32 = 1 << 31;

/// Eight children: boxes as SoA lanes (`bounds[axis][0]` the minima, `[1]` the maxima; an empty
/// slot holds the empty box (+∞, −∞), which no ray enters) and references (a node index, or
/// `LEAF | block`). 224 bytes.
#[repr(C, align(32))]
#[derive(Clone, Copy)]
struct Node {
    bounds: [[[f32; 8]; 2]; 3],
    child: [u32; 8],
}

/// obvhs' order of a node's children (`CwBvh::ray_traverse`), which the any-hit traversals
/// keep: first the leaves, highest primitive first — a later slot holds later primitives
/// (checked at build), so slots downward, each block's lanes downward — then the inner children
/// by `slot ^ octant` (obvhs' hit bit 24 + that), highest first.
impl Node {
    /// The leaves among the children `slots` (a bit per slot), in that order: slot and block.
    #[inline(always)]
    fn leaves_in_order(&self, slots: u32) -> impl Iterator<Item = (usize, u32)> + '_ {
        bits_downward(slots)
            .map(|slot| (slot, self.child[slot]))
            .filter(|c| c.1 & LEAF != 0)
            .map(|(s, c)| (s, c & !LEAF))
    }

    /// Push the inner children among `slots` onto the stack above `sp`, lowest first, so that
    /// they pop in that order.
    #[inline(always)]
    fn push_inner_in_order(&self, slots: u32, octant: u32, stack: &mut [MaybeUninit<u32>; STACK], sp: &mut usize) {
        for k in 0..8 {
            let slot = (k ^ octant) as usize;
            let child = self.child[slot];
            if slots & (1 << slot) != 0 && child & LEAF == 0 {
                stack[*sp].write(child);
                *sp += 1;
            }
        }
    }
}

/// The set bits of `mask`, highest first.
#[inline(always)]
fn bits_downward(mut mask: u32) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        (mask != 0).then(|| {
            let bit = 31 - mask.leading_zeros() as usize;
            mask &= !(1 << bit);
            bit
        })
    })
}

const EMPTY_NODE: Node = Node { bounds: [[[f32::INFINITY; 8], [f32::NEG_INFINITY; 8]]; 3], child: [0; 8] };

/// Up to four triangles as SoA lanes: a corner and the values obvhs' test derives from the
/// corners; `prim` the triangles' BVH-order indices; `valid` the lanes in use.
#[repr(C, align(16))]
#[derive(Clone, Copy)]
struct Block {
    v0: [[f32; 4]; 3],
    e1: [[f32; 4]; 3],
    e2: [[f32; 4]; 3],
    n: [[f32; 4]; 3],
    prim: [u32; 4],
    valid: u32,
}

/// A ray prepared for slab and triangle tests.
struct RayPre {
    origin: [f32; 3],
    /// obvhs' safe reciprocal of the direction.
    inv: [f32; 3],
    /// 1 where the ray runs toward −axis (its near plane is the box's maximum), by the
    /// reciprocal's sign (a direction component of −0 has a reciprocal of −1/ε).
    neg: [usize; 3],
    o4: [F4; 3],
    d4: [F4; 3],
    inv4: [F4; 3],
}

/// obvhs' `safe_inverse`: `1/x`, or `±1/ε` where `|x| ≤ ε`, so slab tests meet no infinity.
#[inline(always)]
fn safe_inverse(x: f32) -> f32 {
    if x.abs() <= f32::EPSILON { x.signum() / f32::EPSILON } else { 1.0 / x }
}

impl RayPre {
    #[inline(always)]
    fn new(origin: Vec3A, direction: Vec3A) -> RayPre {
        let inv = [safe_inverse(direction.x), safe_inverse(direction.y), safe_inverse(direction.z)];
        let origin = origin.to_array();
        let direction = direction.to_array();
        RayPre {
            origin,
            inv,
            neg: inv.map(|i| (i < 0.0) as usize),
            o4: origin.map(F4::splat),
            d4: direction.map(F4::splat),
            inv4: inv.map(F4::splat),
        }
    }
}

/// The slab test of a node's eight boxes against `[t_min, t_max]`: the children entered (a bit
/// per slot) and their entry distances. Per lane and axis `(plane − origin)·(1/direction)`,
/// entry = max of the near planes' and `t_min`, exit = min of the far planes' and `t_max`,
/// entered where entry ≤ exit.
trait NodeTest {
    fn intersect(node: &Node, ray: &RayPre, t_min: f32, t_max: f32) -> (u32, [f32; 8]);
    /// The entered children over two intervals at once (one slab computation).
    fn intersect2(node: &Node, ray: &RayPre, a: (f32, f32), b: (f32, f32)) -> (u32, u32);
}

/// Two 4-lane halves: the x86-64 baseline (SSE), or the portable lanes.
struct Halves;

impl NodeTest for Halves {
    #[inline(always)]
    fn intersect(node: &Node, ray: &RayPre, t_min: f32, t_max: f32) -> (u32, [f32; 8]) {
        let mut mask = 0;
        let mut near = [0.0f32; 8];
        let (t_min, t_max) = (F4::splat(t_min), F4::splat(t_max));
        for half in 0..2 {
            let slab = |axis: usize, side: usize| {
                let planes: &[f32; 4] = node.bounds[axis][side][4 * half..4 * half + 4].try_into().expect("4 lanes");
                F4::load(planes).sub(ray.o4[axis]).mul(ray.inv4[axis])
            };
            let entry = slab(0, ray.neg[0]).max(slab(1, ray.neg[1])).max(slab(2, ray.neg[2]).max(t_min));
            let exit = slab(0, 1 - ray.neg[0]).min(slab(1, 1 - ray.neg[1])).min(slab(2, 1 - ray.neg[2]).min(t_max));
            mask |= entry.le(exit) << (4 * half);
            near[4 * half..4 * half + 4].copy_from_slice(&entry.to_array());
        }
        (mask, near)
    }

    #[inline(always)]
    fn intersect2(node: &Node, ray: &RayPre, a: (f32, f32), b: (f32, f32)) -> (u32, u32) {
        let (mut mask_a, mut mask_b) = (0, 0);
        for half in 0..2 {
            let slab = |axis: usize, side: usize| {
                let planes: &[f32; 4] = node.bounds[axis][side][4 * half..4 * half + 4].try_into().expect("4 lanes");
                F4::load(planes).sub(ray.o4[axis]).mul(ray.inv4[axis])
            };
            let entry = slab(0, ray.neg[0]).max(slab(1, ray.neg[1])).max(slab(2, ray.neg[2]));
            let exit = slab(0, 1 - ray.neg[0]).min(slab(1, 1 - ray.neg[1])).min(slab(2, 1 - ray.neg[2]));
            let within = |(lo, hi): (f32, f32)| entry.max(F4::splat(lo)).le(exit.min(F4::splat(hi)));
            mask_a |= within(a) << (4 * half);
            mask_b |= within(b) << (4 * half);
        }
        (mask_a, mask_b)
    }
}

/// All eight lanes at once with AVX (the same operations as [`Halves`]).
#[cfg(target_arch = "x86_64")]
struct Avx;

#[cfg(target_arch = "x86_64")]
impl NodeTest for Avx {
    #[inline(always)]
    fn intersect(node: &Node, ray: &RayPre, t_min: f32, t_max: f32) -> (u32, [f32; 8]) {
        // SAFETY: `Avx` is only used by the `#[target_feature(enable = "avx")]` entry points,
        // which run only where the CPU has AVX (`WideBvh::avx`).
        unsafe { avx_node(node, ray, t_min, t_max) }
    }

    #[inline(always)]
    fn intersect2(node: &Node, ray: &RayPre, a: (f32, f32), b: (f32, f32)) -> (u32, u32) {
        // SAFETY: as `intersect`.
        unsafe { avx_node2(node, ray, a, b) }
    }
}

/// [`avx_node`] over two intervals: the same slab values, each clamped to each interval.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
#[inline]
fn avx_node2(node: &Node, ray: &RayPre, a: (f32, f32), b: (f32, f32)) -> (u32, u32) {
    use std::arch::x86_64::*;
    let slab = |axis: usize, side: usize| {
        // SAFETY: as in `avx_node`.
        let planes = unsafe { _mm256_load_ps(node.bounds[axis][side].as_ptr()) };
        _mm256_mul_ps(_mm256_sub_ps(planes, _mm256_set1_ps(ray.origin[axis])), _mm256_set1_ps(ray.inv[axis]))
    };
    let entry = _mm256_max_ps(_mm256_max_ps(slab(0, ray.neg[0]), slab(1, ray.neg[1])), slab(2, ray.neg[2]));
    let exit = _mm256_min_ps(_mm256_min_ps(slab(0, 1 - ray.neg[0]), slab(1, 1 - ray.neg[1])), slab(2, 1 - ray.neg[2]));
    let within = |(lo, hi): (f32, f32)| {
        let (e, x) = (_mm256_max_ps(entry, _mm256_set1_ps(lo)), _mm256_min_ps(exit, _mm256_set1_ps(hi)));
        _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(e, x)) as u32
    };
    (within(a), within(b))
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
#[inline]
fn avx_node(node: &Node, ray: &RayPre, t_min: f32, t_max: f32) -> (u32, [f32; 8]) {
    use std::arch::x86_64::*;
    let slab = |axis: usize, side: usize| {
        // SAFETY: `Node` is 32-byte aligned and every `[f32; 8]` of `bounds` sits at a multiple
        // of 32 bytes in it.
        let planes = unsafe { _mm256_load_ps(node.bounds[axis][side].as_ptr()) };
        _mm256_mul_ps(_mm256_sub_ps(planes, _mm256_set1_ps(ray.origin[axis])), _mm256_set1_ps(ray.inv[axis]))
    };
    let entry = _mm256_max_ps(
        _mm256_max_ps(slab(0, ray.neg[0]), slab(1, ray.neg[1])),
        _mm256_max_ps(slab(2, ray.neg[2]), _mm256_set1_ps(t_min)),
    );
    let exit = _mm256_min_ps(
        _mm256_min_ps(slab(0, 1 - ray.neg[0]), slab(1, 1 - ray.neg[1])),
        _mm256_min_ps(slab(2, 1 - ray.neg[2]), _mm256_set1_ps(t_max)),
    );
    let mask = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(entry, exit)) as u32;
    let mut near = [0.0f32; 8];
    // SAFETY: `near` holds eight f32.
    unsafe { _mm256_storeu_ps(near.as_mut_ptr(), entry) };
    (mask, near)
}

impl Block {
    /// obvhs' `Triangle::intersect` on the four lanes, kept to the open interval
    /// `(t_min, t_max)`: the lanes hit and their distances. Per lane: `c = v0 − o`,
    /// `r = d × c`, `1/det = 1/(n·d)`, `u = (r·e2)/det`, `v = (r·e1)/det`, `w = 1 − u − v`,
    /// `t = (n·c)/det`; a hit where `1/det ≠ 0`, none of `u`, `v`, `w` has its sign bit set and
    /// `t_min < t < t_max`.
    #[inline(always)]
    fn intersect(&self, ray: &RayPre, t_min: F4, t_max: F4) -> (u32, [f32; 4]) {
        let (hit, t, _) = self.intersect_with::<false>(ray, t_min, t_max);
        (hit, t)
    }

    /// [`Block::intersect`] with `r = d × c` rounded exactly as glam's `Vec3A::cross` rounds it
    /// on x86-64 (`r.x = d.y·c.z − c.y·d.z` by [`F4::neg_mul_sub`], fused where the build
    /// targets FMA; the other terms, glam's `dot` (`(x + y) + z`), `1/det`, `w` and `t` are the
    /// same IEEE operations already): per lane bit for bit what obvhs' `Triangle::intersect`
    /// (as compiled here) answers, so the any-hit traversal can test four triangles at once and
    /// keep obvhs' decisions on edges. Also the hits' barycentrics `(u, v)` ([`obvhs_barycentrics`]).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn intersect_obvhs(&self, ray: &RayPre, t_min: F4, t_max: F4) -> (u32, [f32; 4], [[f32; 4]; 2]) {
        self.intersect_with::<true>(ray, t_min, t_max)
    }

    /// The test of [`Block::intersect`], and `u`, `v`; `GLAM_CROSS`: `r` as
    /// [`Block::intersect_obvhs`] rounds it.
    #[inline(always)]
    fn intersect_with<const GLAM_CROSS: bool>(
        &self,
        ray: &RayPre,
        t_min: F4,
        t_max: F4,
    ) -> (u32, [f32; 4], [[f32; 4]; 2]) {
        let load = |a: &[[f32; 4]; 3]| [F4::load(&a[0]), F4::load(&a[1]), F4::load(&a[2])];
        let (v0, e1, e2, n) = (load(&self.v0), load(&self.e1), load(&self.e2), load(&self.n));
        let dot = |a: [F4; 3], b: [F4; 3]| a[0].mul(b[0]).add(a[1].mul(b[1])).add(a[2].mul(b[2]));
        let (o, d) = (ray.o4, ray.d4);
        let c = [v0[0].sub(o[0]), v0[1].sub(o[1]), v0[2].sub(o[2])];
        // `a·b − e·f`, the first product rounded.
        let cross_term = |a: F4, b: F4, e: F4, f: F4| {
            #[cfg(target_arch = "x86_64")]
            if GLAM_CROSS {
                return F4::neg_mul_sub(e, f, a.mul(b));
            }
            a.mul(b).sub(e.mul(f))
        };
        let r = [
            cross_term(d[1], c[2], d[2], c[1]),
            cross_term(d[2], c[0], d[0], c[2]),
            cross_term(d[0], c[1], d[1], c[0]),
        ];
        let inv_det = F4::splat(1.0).div(dot(n, d));
        let u = dot(r, e2).mul(inv_det);
        let v = dot(r, e1).mul(inv_det);
        let w = F4::splat(1.0).sub(u).sub(v);
        let t = dot(n, c).mul(inv_det);
        let hit = inv_det.ne(F4::splat(0.0)) & !F4::any_sign(u, v, w) & t_min.lt(t) & t.lt(t_max) & self.valid;
        (hit, t.to_array(), [u.to_array(), v.to_array()])
    }
}

/// Entries of an [`OriginCut`].
const CUT: usize = 16;

/// The cut of the tree that every ray from one origin with one length passes through: the
/// children whose boxes meet the cube of half-size `t_max` around the origin, expanded from the
/// root while at most `CUT` of them remain, packed as two virtual nodes. Every node such a
/// ray enters lies below one of them (its box and all its ancestors' meet the segment, which
/// lies in the cube), so starting there finds the same hits while skipping the top levels.
#[derive(Clone)]
pub struct OriginCut {
    /// The BVH it was built for ([`WideBvh::id`]).
    bvh: u64,
    origin: Vec3A,
    t_max: f32,
    /// The key was seen once (that ray traced from the root) or the cut is built.
    built: bool,
    nodes: [Node; CUT / 8],
    count: usize,
}

impl Default for OriginCut {
    fn default() -> Self {
        OriginCut { bvh: 0, origin: Vec3A::NAN, t_max: f32::NAN, built: false, nodes: [EMPTY_NODE; CUT / 8], count: 0 }
    }
}

/// Direction lengths up to which a cut applies (the cube is widened by this factor).
const UNIT: f32 = 1.0 + 1e-4;

/// Traversal stack depth: the CWBVH is at most 32 levels deep (obvhs validates it) and a node
/// leaves at most 7 entries on the stack.
const STACK: usize = 32 * 7 + 1;

/// See the module documentation.
pub struct WideBvh {
    nodes: Vec<Node>,
    blocks: Vec<Block>,
    /// The root reference (a node, or a leaf for a one-leaf tree); `None` for no triangles.
    root: Option<u32>,
    /// 8-lane node tests (the CPU has AVX).
    avx: bool,
    /// Unique per build, so that an [`OriginCut`] is never applied to another tree.
    id: u64,
}

impl WideBvh {
    /// The wide layout of `bvh` over `triangles` in BVH primitive order (`primitive_indices`
    /// applied): block lanes report indices into `triangles`.
    pub fn build(bvh: &CwBvh, triangles: &[Triangle]) -> WideBvh {
        static NEXT_ID: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);
        let mut wide = WideBvh {
            nodes: Vec::new(),
            blocks: Vec::new(),
            root: None,
            avx: has_avx(),
            id: NEXT_ID.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
        };
        if !bvh.nodes.is_empty() && !triangles.is_empty() {
            wide.nodes = vec![EMPTY_NODE; bvh.nodes.len()];
            wide.convert(bvh, triangles, 0);
            wide.root = Some(0);
        }
        wide
    }

    /// Fill node `index` and its subtree from the CWBVH; returns the subtree's box.
    fn convert(&mut self, bvh: &CwBvh, triangles: &[Triangle], index: usize) -> (Vec3A, Vec3A) {
        let src = bvh.nodes[index];
        let mut node = EMPTY_NODE;
        let (mut lo, mut hi) = (Vec3A::INFINITY, Vec3A::NEG_INFINITY);
        let mut next_start = 0;
        for slot in 0..8 {
            if src.is_child_empty(slot) {
                continue;
            }
            let (child_lo, child_hi, child) = if src.is_leaf(slot) {
                let (start, count) = src.child_primitives(slot);
                // [`WideBvh::any_hit`] relies on it: a later slot's leaf holds later primitives.
                assert!(start >= next_start, "CWBVH leaves are laid out in slot order");
                next_start = start + count;
                let (block, block_lo, block_hi) = Block::new(triangles, start, count);
                self.blocks.push(block);
                (block_lo, block_hi, LEAF | (self.blocks.len() - 1) as u32)
            } else {
                let child = src.child_node_index(slot) as usize;
                let (child_lo, child_hi) = self.convert(bvh, triangles, child);
                (child_lo, child_hi, child as u32)
            };
            for axis in 0..3 {
                node.bounds[axis][0][slot] = child_lo[axis];
                node.bounds[axis][1][slot] = child_hi[axis];
            }
            node.child[slot] = child;
            lo = lo.min(child_lo);
            hi = hi.max(child_hi);
        }
        self.nodes[index] = node;
        (lo, hi)
    }

    /// Is any triangle that `accept(primitive, t)` takes hit inside `(t_min, t_max)`? Stops at
    /// the first; `accept` sees the candidates in no particular order.
    #[inline]
    pub fn occluded(
        &self,
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        accept: impl FnMut(usize, f32) -> bool,
    ) -> bool {
        self.occluded_from(None, origin, direction, t_min, t_max, accept)
    }

    /// [`WideBvh::occluded`] for runs of rays from one origin with one `t_max` and directions of
    /// length ≤ 1: the first ray of a run traces from the root, the second builds the run's
    /// cut into `cut`, and it and the later ones start from the cut.
    #[inline]
    pub fn occluded_cut(
        &self,
        cut: &mut OriginCut,
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        accept: impl FnMut(usize, f32) -> bool,
    ) -> bool {
        if cut.bvh != self.id || cut.origin != origin || cut.t_max != t_max {
            (cut.bvh, cut.origin, cut.t_max, cut.built) = (self.id, origin, t_max, false);
            return self.occluded(origin, direction, t_min, t_max, accept);
        }
        let root_is_node = self.root.is_some_and(|r| r & LEAF == 0);
        if !root_is_node || !t_max.is_finite() || direction.length_squared() > UNIT {
            return self.occluded(origin, direction, t_min, t_max, accept);
        }
        if !cut.built {
            self.build_cut(cut);
        }
        self.occluded_from(Some(cut), origin, direction, t_min, t_max, accept)
    }

    #[inline(always)]
    fn occluded_from(
        &self,
        cut: Option<&OriginCut>,
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        accept: impl FnMut(usize, f32) -> bool,
    ) -> bool {
        #[cfg(target_arch = "x86_64")]
        if self.avx {
            // SAFETY: `avx` is set only where the CPU has AVX.
            return unsafe { self.occluded_avx(cut, origin, direction, t_min, t_max, accept) };
        }
        self.occluded_halves(cut, origin, direction, t_min, t_max, accept)
    }

    #[inline(never)]
    fn occluded_halves(
        &self,
        cut: Option<&OriginCut>,
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        accept: impl FnMut(usize, f32) -> bool,
    ) -> bool {
        self.occluded_with::<Halves>(cut, origin, direction, t_min, t_max, accept)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn occluded_avx(
        &self,
        cut: Option<&OriginCut>,
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        accept: impl FnMut(usize, f32) -> bool,
    ) -> bool {
        self.occluded_with::<Avx>(cut, origin, direction, t_min, t_max, accept)
    }

    /// Depth-first, any order; leaves are tested as soon as their node is.
    #[inline(always)]
    fn occluded_with<N: NodeTest>(
        &self,
        cut: Option<&OriginCut>,
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        mut accept: impl FnMut(usize, f32) -> bool,
    ) -> bool {
        let Some(root) = self.root else { return false };
        let ray = RayPre::new(origin, direction);
        let (t_min4, t_max4) = (F4::splat(t_min), F4::splat(t_max));
        let mut stack = [MaybeUninit::<u32>::uninit(); STACK];
        let mut sp = 0;
        match cut {
            Some(cut) => {
                for node in &cut.nodes[..cut.count] {
                    if self.visit::<N>(node, &ray, (t_min, t_max), (t_min4, t_max4), &mut stack, &mut sp, &mut accept) {
                        return true;
                    }
                }
            }
            None if root & LEAF != 0 => return self.leaf_any(root, &ray, t_min4, t_max4, &mut accept),
            None => {
                stack[0].write(root);
                sp = 1;
            }
        }
        while sp > 0 {
            sp -= 1;
            // SAFETY: the entries below `sp` were written; only node references are stacked.
            let node = &self.nodes[unsafe { stack[sp].assume_init() } as usize];
            if self.visit::<N>(node, &ray, (t_min, t_max), (t_min4, t_max4), &mut stack, &mut sp, &mut accept) {
                return true;
            }
        }
        false
    }

    /// A node's children for [`WideBvh::occluded_with`]: leaves tested at once (true: an
    /// accepted hit), nodes stacked.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn visit<N: NodeTest>(
        &self,
        node: &Node,
        ray: &RayPre,
        (t_min, t_max): (f32, f32),
        (t_min4, t_max4): (F4, F4),
        stack: &mut [MaybeUninit<u32>; STACK],
        sp: &mut usize,
        accept: &mut impl FnMut(usize, f32) -> bool,
    ) -> bool {
        let (mut mask, _) = N::intersect(node, ray, t_min, t_max);
        while mask != 0 {
            let slot = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            let child = node.child[slot];
            if child & LEAF != 0 {
                if self.leaf_any(child, ray, t_min4, t_max4, accept) {
                    return true;
                }
            } else {
                stack[*sp].write(child);
                *sp += 1;
            }
        }
        false
    }

    /// Does leaf `leaf` hold a triangle hit inside `(t_min, t_max)` that `accept` takes?
    #[inline(always)]
    fn leaf_any(
        &self,
        leaf: u32,
        ray: &RayPre,
        t_min: F4,
        t_max: F4,
        accept: &mut impl FnMut(usize, f32) -> bool,
    ) -> bool {
        let block = &self.blocks[(leaf & !LEAF) as usize];
        let (mut hit, t) = block.intersect(ray, t_min, t_max);
        while hit != 0 {
            let lane = hit.trailing_zeros() as usize;
            hit &= hit - 1;
            if accept(block.prim[lane] as usize, t[lane]) {
                return true;
            }
        }
        false
    }

    /// Fill `cut` (whose origin and `t_max` are set) with the children meeting the cube of
    /// half-size `t_max·UNIT` around the origin, expanded first come first served while at
    /// most [`CUT`] remain.
    fn build_cut(&self, cut: &mut OriginCut) {
        let reach = Vec3A::splat(cut.t_max * UNIT);
        let (lo, hi) = ((cut.origin - reach).to_array(), (cut.origin + reach).to_array());
        // (node, slot) of the children meeting the cube: the cut so far, then a node's expansion.
        let mut entries = [(0u32, 0u32); CUT + 8];
        let mut len = 0;
        let meeting = |node: u32, out: &mut [(u32, u32); CUT + 8], len: &mut usize| {
            let b = &self.nodes[node as usize].bounds;
            let meets = |slot: usize| (0..3).all(|a| b[a][0][slot] <= hi[a] && b[a][1][slot] >= lo[a]);
            for slot in (0..8).filter(|&slot| meets(slot)) {
                out[*len] = (node, slot as u32);
                *len += 1;
            }
        };
        let child = |(node, slot): (u32, u32)| self.nodes[node as usize].child[slot as usize];
        meeting(self.root.expect("built only for a tree with a root node"), &mut entries, &mut len);
        let mut i = 0;
        while i < len {
            let node = child(entries[i]);
            if node & LEAF == 0 {
                // Expand behind the cut; keep the expansion if the cut still fits.
                let mut grown = len;
                meeting(node, &mut entries, &mut grown);
                if grown - 1 <= CUT {
                    entries[i] = entries[grown - 1];
                    len = grown - 1;
                    continue;
                }
            }
            i += 1;
        }
        cut.nodes = [EMPTY_NODE; CUT / 8];
        for (k, &(node, slot)) in entries[..len].iter().enumerate() {
            let (src, dst, lane) = (&self.nodes[node as usize], &mut cut.nodes[k / 8], k % 8);
            for a in 0..3 {
                dst.bounds[a][0][lane] = src.bounds[a][0][slot as usize];
                dst.bounds[a][1][lane] = src.bounds[a][1][slot as usize];
            }
            dst.child[lane] = src.child[slot as usize];
        }
        cut.count = len.div_ceil(8);
        cut.built = true;
    }

    /// The nearest triangle hit inside `(t_min, t_max)` that `accept(primitive, t)` takes:
    /// `(t, primitive)`. `accept` sees candidates not farther than the best so far, in no
    /// particular order; of accepted hits at the same distance the lowest primitive wins
    /// ([`replaces`]), so the answer does not depend on the traversal order.
    #[inline]
    pub fn closest(
        &self,
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        accept: impl FnMut(usize, f32) -> bool,
    ) -> Option<(f32, usize)> {
        #[cfg(target_arch = "x86_64")]
        if self.avx {
            // SAFETY: `avx` is set only where the CPU has AVX.
            return unsafe { self.closest_avx(origin, direction, t_min, t_max, accept) };
        }
        self.closest_halves(origin, direction, t_min, t_max, accept)
    }

    #[inline(never)]
    fn closest_halves(
        &self,
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        accept: impl FnMut(usize, f32) -> bool,
    ) -> Option<(f32, usize)> {
        self.closest_with::<Halves>(origin, direction, t_min, t_max, accept)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn closest_avx(
        &self,
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        accept: impl FnMut(usize, f32) -> bool,
    ) -> Option<(f32, usize)> {
        self.closest_with::<Avx>(origin, direction, t_min, t_max, accept)
    }

    /// Nearest child first: a node's entered children go onto the stack sorted by entry
    /// distance, farthest at the bottom; a popped entry beyond the best hit (and its
    /// [`with_margin`]) is dropped.
    #[inline(always)]
    fn closest_with<N: NodeTest>(
        &self,
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        mut accept: impl FnMut(usize, f32) -> bool,
    ) -> Option<(f32, usize)> {
        let mut current = self.root?;
        let ray = RayPre::new(origin, direction);
        let t_min4 = F4::splat(t_min);
        let mut best_t = t_max;
        let mut best = None;
        let mut stack = [MaybeUninit::<(u32, f32)>::uninit(); STACK];
        let mut sp = 0;
        loop {
            if current & LEAF == 0 {
                let node = &self.nodes[current as usize];
                let (mask, near) = N::intersect(node, &ray, t_min, with_margin(best_t));
                if let Some(child) = enter_nearest_first(node, mask, &near, &mut stack, &mut sp) {
                    current = child;
                    continue;
                }
            } else {
                let block = &self.blocks[(current & !LEAF) as usize];
                // Once a hit is held, hits at its very distance are tested too (the tie rule).
                let bound = if best.is_some() { best_t.next_up() } else { best_t };
                let (mut hit, t) = block.intersect(&ray, t_min4, F4::splat(bound));
                while hit != 0 {
                    let lane = hit.trailing_zeros() as usize;
                    hit &= hit - 1;
                    let prim = block.prim[lane] as usize;
                    if replaces((t[lane], prim), (best_t, best)) && accept(prim, t[lane]) {
                        best_t = t[lane];
                        best = Some(prim);
                    }
                }
            }
            // The nearest stacked entry still in front of the best hit.
            loop {
                if sp == 0 {
                    return best.map(|p| (best_t, p));
                }
                sp -= 1;
                // SAFETY: the entries below `sp` were written.
                let (child, near) = unsafe { stack[sp].assume_init() };
                if near <= with_margin(best_t) {
                    current = child;
                    break;
                }
            }
        }
    }
}

impl WideBvh {
    /// Any-hit traversal in exactly obvhs' CWBVH order (`CwBvh::ray_traverse`, Ylitie et al.
    /// 2017), so that an order-dependent any-hit (the SD map's reservoir) decides exactly as it
    /// did on obvhs' traversal: `cwbvh` is the tree this layout was built from, whose quantized
    /// node test (`CwBvhNode::intersect_ray`, against the current `t_max`) picks the children,
    /// as in obvhs — exact boxes round differently and, measured on the kitchen, enter a box
    /// obvhs skips or skip one it enters. Depth first from the root; at a node, first the
    /// triangles of its entered leaves, highest primitive first, then its entered inner children
    /// by `slot ^ octant`, highest first (the octant has bit 2 / 1 / 0 set where the direction's
    /// x / y / z is not negative). Children whose exact box ends before `t_min` are skipped
    /// (obvhs visits them: its test ignores `t_min`), which makes long rays that start deep in
    /// the scene (SD and Ray-SVAO rays start at the eye) several times cheaper and offers the
    /// same candidates. Triangles are tested by obvhs' `Triangle::intersect` on `triangles`
    /// (BVH order), one at a time. Every triangle hit inside the current interval
    /// `(t_min, t_max)` goes to `any_hit(primitive, t)`, once: `Accept` shrinks `t_max` to `t`,
    /// `AcceptAndEnd` ends the search.
    #[inline]
    pub fn any_hit(
        &self,
        (cwbvh, triangles): (&CwBvh, &[Triangle]),
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        any_hit: impl FnMut(usize, f32, Vec2) -> super::AnyHit,
    ) {
        #[cfg(target_arch = "x86_64")]
        if self.avx {
            // SAFETY: `avx` is set only where the CPU has AVX.
            return unsafe { self.any_hit_avx((cwbvh, triangles), origin, direction, t_min, t_max, any_hit) };
        }
        self.any_hit_with::<Halves>((cwbvh, triangles), origin, direction, t_min, t_max, any_hit)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn any_hit_avx(
        &self,
        (cwbvh, triangles): (&CwBvh, &[Triangle]),
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        any_hit: impl FnMut(usize, f32, Vec2) -> super::AnyHit,
    ) {
        self.any_hit_with::<Avx>((cwbvh, triangles), origin, direction, t_min, t_max, any_hit)
    }

    #[inline(always)]
    fn any_hit_with<N: NodeTest>(
        &self,
        (cwbvh, triangles): (&CwBvh, &[Triangle]),
        origin: Vec3A,
        direction: Vec3A,
        t_min: f32,
        t_max: f32,
        mut any_hit: impl FnMut(usize, f32, Vec2) -> super::AnyHit,
    ) {
        if self.root.is_none() {
            return;
        }
        let mut ray = obvhs::ray::Ray::new(origin, direction, t_min, t_max);
        let pre = RayPre::new(origin, direction);
        // The blocks carry the triangles (on x86-64 they are tested there).
        #[cfg(target_arch = "x86_64")]
        let _ = triangles;
        let octant = octant(direction);
        let mut stack = [MaybeUninit::<u32>::uninit(); STACK];
        stack[0].write(0);
        let mut sp = 1;
        while sp > 0 {
            sp -= 1;
            // SAFETY: the entries below `sp` were written.
            let index = unsafe { stack[sp].assume_init() } as usize;
            let node = &self.nodes[index];
            // The children to enter: those obvhs' quantized test enters, less those whose exact
            // box ends before `t_min` (obvhs' test clamps entries at its ε, not at `t_min`, so it
            // enters every box between the origin and `t_min`; they hold no hit inside the
            // interval). The exact boxes settle most children without obvhs' test: `maybe`
            // (exact box met over the interval widened by a rounding margin) holds every child
            // either test enters and that can hold a hit; `surely` (met over the interval
            // narrowed by the margin, and beyond obvhs' ε) only children obvhs' larger boxes
            // surely enter too. obvhs' own test runs only where they differ.
            let lo = below_margin(t_min);
            let (maybe, surely) = N::intersect2(
                node,
                &pre,
                (lo, with_margin(ray.tmax)),
                (lo.max(OBVHS_EPSILON * (1.0 + MARGIN)), below_margin(ray.tmax)),
            );
            if maybe == 0 {
                continue;
            }
            let beyond = if surely == maybe {
                maybe
            } else {
                let quantized = cwbvh.nodes[index].intersect_ray(&ray, octant * 0x0101_0101);
                let mut entered = 0;
                for slot in 0..8 {
                    let child = node.child[slot];
                    let bit = if child & LEAF != 0 {
                        let block = &self.blocks[(child & !LEAF) as usize];
                        block.prim[0] - cwbvh.nodes[index].primitive_base_idx
                    } else {
                        24 + (slot as u32 ^ octant)
                    };
                    if child != 0 && quantized & (1 << bit) != 0 {
                        entered |= 1 << slot;
                    }
                }
                surely | (maybe & entered)
            };
            if beyond == 0 {
                continue;
            }
            for (_, leaf) in node.leaves_in_order(beyond) {
                let block = &self.blocks[leaf as usize];
                // On x86-64 the block's four triangles at once, by obvhs' arithmetic to the bit
                // (`Block::intersect_obvhs`): the lanes hit in `(t_min, t_max)` with their
                // distances, re-checked against `t_max` as it shrinks; elsewhere obvhs' own
                // test, one at a time.
                #[cfg(target_arch = "x86_64")]
                let (lanes, hits, [us, vs]) = block.intersect_obvhs(&pre, F4::splat(ray.tmin), F4::splat(ray.tmax));
                #[cfg(not(target_arch = "x86_64"))]
                let lanes = block.valid;
                for lane in bits_downward(lanes) {
                    let id = block.prim[lane] as usize;
                    #[cfg(target_arch = "x86_64")]
                    let (t, uv) = (hits[lane], Vec2::new(us[lane], vs[lane]));
                    #[cfg(not(target_arch = "x86_64"))]
                    let (t, uv) =
                        (triangles[id].intersect(&ray), obvhs_barycentrics(&triangles[id], origin, direction));
                    if t > ray.tmin && t < ray.tmax {
                        match any_hit(id, t, uv) {
                            super::AnyHit::Ignore => {}
                            super::AnyHit::Accept => ray.tmax = t,
                            super::AnyHit::AcceptAndEnd => return,
                        }
                    }
                }
            }
            node.push_inner_in_order(beyond, octant, &mut stack, &mut sp);
        }
    }
}

/// Rays per packet of `WideBvh::closest_packet`.
pub const PACKET: usize = 8;

impl WideBvh {
    /// [`WideBvh::closest`] for [`PACKET`] rays from one origin over one interval (camera rays of
    /// a 4×2 pixel tile), traversed together: `accept(ray, primitive, t)`; answers per ray. The
    /// packet visits every node whose box any of its rays may enter (interval bounds over the
    /// rays' reciprocal directions, which float rounding cannot undercut: `(plane − o)·x` rounds
    /// monotonically in `x`), nearest first by the packet's entry bound, dropping entries beyond
    /// every ray's best hit (per-ray `t_max` culling, the packet's largest); a leaf's triangles
    /// are tested against all eight rays at once by the arithmetic of [`Block::intersect`] (so
    /// the same distances), each ray keeping its own best hit by the same tie rule
    /// ([`replaces`]), both entering boxes up to [`with_margin`] beyond the best hit. So each
    /// ray gets the hit [`WideBvh::closest`] finds for it, unless a triangle's Möller–Trumbore
    /// distance lies beyond its own leaf box's slab entry by more than that margin through
    /// rounding (then the single ray may miss it where the packet, visiting more boxes, does
    /// not).
    #[inline]
    pub fn closest_packet(
        &self,
        origin: Vec3A,
        directions: &[Vec3A; PACKET],
        t_min: f32,
        t_max: f32,
        mut accept: impl FnMut(usize, usize, f32) -> bool,
    ) -> [Option<(f32, usize)>; PACKET] {
        #[cfg(target_arch = "x86_64")]
        if self.avx {
            // SAFETY: `avx` is set only where the CPU has AVX.
            return unsafe { self.closest_packet_avx(origin, directions, t_min, t_max, accept) };
        }
        std::array::from_fn(|i| self.closest(origin, directions[i], t_min, t_max, |p, t| accept(i, p, t)))
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn closest_packet_avx(
        &self,
        origin: Vec3A,
        directions: &[Vec3A; PACKET],
        t_min: f32,
        t_max: f32,
        mut accept: impl FnMut(usize, usize, f32) -> bool,
    ) -> [Option<(f32, usize)>; PACKET] {
        use std::arch::x86_64::*;
        let mut best_t = [t_max; PACKET];
        let mut best = [None::<usize>; PACKET];
        let Some(mut current) = self.root else { return [None; PACKET] };
        let rays = PacketRays::new(origin, directions, 0xff);
        let t_min8 = _mm256_set1_ps(t_min);
        let bound_of = |best_t: &[f32; PACKET]| best_t.iter().copied().fold(f32::NEG_INFINITY, f32::max);
        let mut bound = with_margin(t_max);
        let mut stack = [MaybeUninit::<(u32, f32)>::uninit(); STACK];
        let mut sp = 0;
        loop {
            if current & LEAF == 0 {
                let node = &self.nodes[current as usize];
                let (mask, entries) = rays.node_test(node, t_min, bound);
                let mut near = [0.0f32; 8];
                // SAFETY: `near` holds eight f32.
                unsafe { _mm256_storeu_ps(near.as_mut_ptr(), entries) };
                if let Some(child) = enter_nearest_first(node, mask, &near, &mut stack, &mut sp) {
                    current = child;
                    continue;
                }
            } else {
                let block = &self.blocks[(current & !LEAF) as usize];
                let mut lanes = block.valid;
                while lanes != 0 {
                    let k = lanes.trailing_zeros() as usize;
                    lanes &= lanes - 1;
                    let Some(([t, _, _], valid)) = rays.triangle::<false>(block, k, 0xff) else { continue };
                    // SAFETY: `best_t` holds eight f32.
                    let best8 = unsafe { _mm256_loadu_ps(best_t.as_ptr()) };
                    let bits = |m: __m256| _mm256_movemask_ps(m) as u32;
                    let mut hit = valid
                        & bits(_mm256_cmp_ps::<_CMP_LT_OQ>(t_min8, t))
                        & bits(_mm256_cmp_ps::<_CMP_LE_OQ>(t, best8));
                    if hit == 0 {
                        continue;
                    }
                    let mut ts = [0.0f32; 8];
                    // SAFETY: `ts` holds eight f32.
                    unsafe { _mm256_storeu_ps(ts.as_mut_ptr(), t) };
                    let prim = block.prim[k] as usize;
                    while hit != 0 {
                        let ray = hit.trailing_zeros() as usize;
                        hit &= hit - 1;
                        if replaces((ts[ray], prim), (best_t[ray], best[ray])) && accept(ray, prim, ts[ray]) {
                            best_t[ray] = ts[ray];
                            best[ray] = Some(prim);
                        }
                    }
                }
                bound = with_margin(bound_of(&best_t));
            }
            // The nearest stacked entry still in front of some ray's best hit.
            loop {
                if sp == 0 {
                    return std::array::from_fn(|i| best[i].map(|p| (best_t[i], p)));
                }
                sp -= 1;
                // SAFETY: the entries below `sp` were written.
                let (child, near) = unsafe { stack[sp].assume_init() };
                if near <= bound {
                    current = child;
                    break;
                }
            }
        }
    }
}

/// A packet of up to [`PACKET`] rays from one origin, prepared for the packet traversals: the
/// directions as AVX lanes and, per axis, the range of the reciprocals of the rays in `rays`
/// (a bit per ray).
#[cfg(target_arch = "x86_64")]
struct PacketRays {
    origin: [f32; 3],
    directions: [std::arch::x86_64::__m256; 3],
    /// Per ray, obvhs' safe reciprocal of the direction.
    inv: [std::arch::x86_64::__m256; 3],
    inv_lo: [f32; 3],
    inv_hi: [f32; 3],
}

#[cfg(target_arch = "x86_64")]
impl PacketRays {
    #[target_feature(enable = "avx")]
    #[inline]
    fn new(origin: Vec3A, directions: &[Vec3A; PACKET], rays: u32) -> PacketRays {
        use std::arch::x86_64::*;
        let axis = |a: usize| {
            let lanes: [f32; PACKET] = std::array::from_fn(|i| directions[i][a]);
            // SAFETY: `lanes` holds eight f32.
            unsafe { _mm256_loadu_ps(lanes.as_ptr()) }
        };
        let inv: [[f32; PACKET]; 3] = std::array::from_fn(|a| directions.map(|d| safe_inverse(d[a])));
        let (mut inv_lo, mut inv_hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for i in (0..PACKET).filter(|i| rays & (1 << i) != 0) {
            for a in 0..3 {
                inv_lo[a] = inv_lo[a].min(inv[a][i]);
                inv_hi[a] = inv_hi[a].max(inv[a][i]);
            }
        }
        PacketRays {
            origin: origin.to_array(),
            directions: [axis(0), axis(1), axis(2)],
            // SAFETY: each row holds eight f32.
            inv: inv.map(|lanes| unsafe { _mm256_loadu_ps(lanes.as_ptr()) }),
            inv_lo,
            inv_hi,
        }
    }

    /// The packet's slab test of a node's eight boxes over `[near, far]`: the children some
    /// ray may enter, and a lower bound of every ray's entry distance. Interval bounds over the
    /// reciprocals, which rounding cannot undercut (`(plane − o)·x` rounds monotonically in
    /// `x`): a box a ray of the packet enters (by [`avx_node`]'s arithmetic) is entered here.
    /// Empty slots (lo > hi) are never entered.
    #[target_feature(enable = "avx")]
    #[inline]
    fn node_test(&self, node: &Node, near: f32, far: f32) -> (u32, std::arch::x86_64::__m256) {
        use std::arch::x86_64::*;
        let (mut near, mut far) = (_mm256_set1_ps(near), _mm256_set1_ps(far));
        let mut valid = 0xff;
        for a in 0..3 {
            let oa = _mm256_set1_ps(self.origin[a]);
            let (ia, ib) = (_mm256_set1_ps(self.inv_lo[a]), _mm256_set1_ps(self.inv_hi[a]));
            // SAFETY: `Node` is 32-byte aligned and every `[f32; 8]` of `bounds` sits at a
            // multiple of 32 bytes in it.
            let (lo, hi) =
                unsafe { (_mm256_load_ps(node.bounds[a][0].as_ptr()), _mm256_load_ps(node.bounds[a][1].as_ptr())) };
            if a == 0 {
                valid = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(lo, hi)) as u32;
            }
            let (lo, hi) = (_mm256_sub_ps(lo, oa), _mm256_sub_ps(hi, oa));
            let (p0, p1, p2, p3) =
                (_mm256_mul_ps(lo, ia), _mm256_mul_ps(lo, ib), _mm256_mul_ps(hi, ia), _mm256_mul_ps(hi, ib));
            near = _mm256_max_ps(near, _mm256_min_ps(_mm256_min_ps(p0, p1), _mm256_min_ps(p2, p3)));
            far = _mm256_min_ps(far, _mm256_max_ps(_mm256_max_ps(p0, p1), _mm256_max_ps(p2, p3)));
        }
        (_mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(near, far)) as u32 & valid, near)
    }

    /// The rays (a bit per ray) whose own slab test enters child `slot`'s box of `node` over
    /// their own intervals `[near, far]` (lanes): per ray the values [`avx_node`] computes for
    /// it (the same subtractions and products; of a slab's two distances the smaller is the one
    /// it takes as the near plane's).
    #[target_feature(enable = "avx")]
    #[inline]
    fn box_rays(
        &self,
        node: &Node,
        slot: usize,
        mut near: std::arch::x86_64::__m256,
        mut far: std::arch::x86_64::__m256,
    ) -> u32 {
        use std::arch::x86_64::*;
        for a in 0..3 {
            let (lo, hi) = (node.bounds[a][0][slot] - self.origin[a], node.bounds[a][1][slot] - self.origin[a]);
            let (p, q) =
                (_mm256_mul_ps(_mm256_set1_ps(lo), self.inv[a]), _mm256_mul_ps(_mm256_set1_ps(hi), self.inv[a]));
            near = _mm256_max_ps(near, _mm256_min_ps(p, q));
            far = _mm256_min_ps(far, _mm256_max_ps(p, q));
        }
        _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(near, far)) as u32
    }

    /// Triangle `k` of `block` against the eight rays by [`Block::intersect_with`]'s arithmetic
    /// (`GLAM_CROSS` as there), so the same distances as the single-ray tests: per ray `t`, and
    /// the rays whose hit stands before the interval check (`1/det ≠ 0`, no sign bit in `u`,
    /// `v`, `w`). `None` where none of the rays `rays` (a bit per ray) can hit it: `u = (r·e2)/det`
    /// takes its sign bit from `r·e2` and `det` (IEEE multiplication, zeros and underflow
    /// included), so a ray whose `u` or `v` is negative by those signs misses before the
    /// division.
    #[target_feature(enable = "avx")]
    #[inline]
    fn triangle<const GLAM_CROSS: bool>(
        &self,
        block: &Block,
        k: usize,
        rays: u32,
    ) -> Option<([std::arch::x86_64::__m256; 3], u32)> {
        use std::arch::x86_64::*;
        let s = |x: f32| _mm256_set1_ps(x);
        let (add, sub, mul) = (|a, b| _mm256_add_ps(a, b), |a, b| _mm256_sub_ps(a, b), |a, b| _mm256_mul_ps(a, b));
        let (o, d) = (self.origin, self.directions);
        let c = [s(block.v0[0][k] - o[0]), s(block.v0[1][k] - o[1]), s(block.v0[2][k] - o[2])];
        let n = [s(block.n[0][k]), s(block.n[1][k]), s(block.n[2][k])];
        let e1 = [s(block.e1[0][k]), s(block.e1[1][k]), s(block.e1[2][k])];
        let e2 = [s(block.e2[0][k]), s(block.e2[1][k]), s(block.e2[2][k])];
        let dot = |a: [__m256; 3], b: [__m256; 3]| add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2]));
        // `a·b − e·f`, the first product rounded (fused as `F4::neg_mul_sub` where asked).
        let cross_term = |a: __m256, b: __m256, e: __m256, f: __m256| {
            #[cfg(target_feature = "fma")]
            if GLAM_CROSS {
                // SAFETY: the build targets FMA (`cfg(target_feature = "fma")`).
                return unsafe { _mm256_fnmadd_ps(e, f, mul(a, b)) };
            }
            sub(mul(a, b), mul(e, f))
        };
        let r = [
            cross_term(d[1], c[2], d[2], c[1]),
            cross_term(d[2], c[0], d[0], c[2]),
            cross_term(d[0], c[1], d[1], c[0]),
        ];
        let det = dot(n, d);
        let (u_num, v_num) = (dot(r, e2), dot(r, e1));
        let bits = |m: __m256| _mm256_movemask_ps(m) as u32;
        let negative = bits(_mm256_or_ps(_mm256_xor_ps(u_num, det), _mm256_xor_ps(v_num, det)));
        if rays & !negative == 0 {
            return None;
        }
        let inv_det = _mm256_div_ps(s(1.0), det);
        let u = mul(u_num, inv_det);
        let v = mul(v_num, inv_det);
        let w = sub(sub(s(1.0), u), v);
        let t = mul(dot(n, c), inv_det);
        Some((
            [t, u, v],
            bits(_mm256_cmp_ps::<_CMP_NEQ_UQ>(inv_det, s(0.0))) & !bits(_mm256_or_ps(u, _mm256_or_ps(v, w))),
        ))
    }
}

impl WideBvh {
    /// [`WideBvh::any_hit`] for up to [`PACKET`] rays from one origin (`rays`: a bit per ray in
    /// use), each over its own interval `(t_min[i], t_max[i])`, traversed together:
    /// `any_hit(ray, primitive, t)`. Rays whose directions share an octant go down the tree as
    /// one packet in the single ray's order (depth first; at a node its entered leaves, slots
    /// and lanes downward, then its inner children by `slot ^ octant`, highest first), entering
    /// every box that any of them may enter ([`PacketRays::node_test`] over the packet's widest
    /// interval); a leaf's triangles are tested against the rays whose own slab test enters the
    /// leaf's box ([`PacketRays::box_rays`]) at once, by obvhs' arithmetic
    /// ([`PacketRays::triangle`]), and each ray gets the triangles it hits inside its current
    /// interval. So a ray's candidates come in the order [`WideBvh::any_hit`] offers
    /// them: both follow the same fixed order of the tree's leaves, and both offer every
    /// triangle hit inside the interval — unless rounding at a box boundary made the single
    /// ray's (obvhs') box test skip a box holding such a hit, which this wider test enters
    /// (tests/any_hit_order.rs finds no such ray among the SD map's rays of sponza and the
    /// kitchen, nor among camera rays with mixed intervals and answers). Each candidate comes
    /// with its barycentrics as the triangle test computes them ([`obvhs_barycentrics`]).
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub fn any_hit_packet(
        &self,
        (cwbvh, triangles): (&CwBvh, &[Triangle]),
        origin: Vec3A,
        directions: &[Vec3A; PACKET],
        t_min: &[f32; PACKET],
        t_max: &[f32; PACKET],
        rays: u32,
        mut any_hit: impl FnMut(usize, usize, f32, Vec2) -> super::AnyHit,
    ) {
        #[cfg(target_arch = "x86_64")]
        if self.avx {
            let mut left = rays & 0xff;
            while left != 0 {
                let first = octant(directions[left.trailing_zeros() as usize]);
                let group = (0..PACKET).filter(|&i| left & (1 << i) != 0 && octant(directions[i]) == first);
                let group = group.fold(0, |m, i| m | 1 << i);
                left &= !group;
                // SAFETY: `avx` is set only where the CPU has AVX.
                unsafe { self.any_hit_group_avx(origin, directions, t_min, t_max, (group, first), &mut any_hit) };
            }
            return;
        }
        for i in (0..PACKET).filter(|&i| rays & (1 << i) != 0) {
            self.any_hit((cwbvh, triangles), origin, directions[i], t_min[i], t_max[i], |p, t, uv| {
                any_hit(i, p, t, uv)
            });
        }
    }

    /// [`WideBvh::any_hit_packet`] of the rays `group` (a bit per ray), whose directions all lie
    /// in `octant`.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn any_hit_group_avx(
        &self,
        origin: Vec3A,
        directions: &[Vec3A; PACKET],
        t_min: &[f32; PACKET],
        t_max: &[f32; PACKET],
        (group, octant): (u32, u32),
        any_hit: &mut impl FnMut(usize, usize, f32, Vec2) -> super::AnyHit,
    ) {
        use std::arch::x86_64::*;
        if self.root.is_none() {
            return;
        }
        let rays = PacketRays::new(origin, directions, group);
        let mut t_max = *t_max;
        // SAFETY: `t_min` holds eight f32.
        let t_min8 = unsafe { _mm256_loadu_ps(t_min.as_ptr()) };
        let mut alive = group;
        let in_group = |m: u32| (0..PACKET).filter(move |&i| m & (1 << i) != 0);
        // Per ray, its interval widened by the rounding margin as the single ray's `maybe` test
        // (as lanes, for the leaves' boxes), and the packet's widest such interval, for the
        // nodes' boxes (both margins round monotonically, so the widest is the widened one).
        let near = t_min.map(below_margin);
        let lo = in_group(group).map(|i| near[i]).fold(f32::INFINITY, f32::min);
        // SAFETY: `near` holds eight f32.
        let near8 = unsafe { _mm256_loadu_ps(near.as_ptr()) };
        let widen = |t_max: &[f32; PACKET], alive: u32| {
            let far = t_max.map(with_margin);
            // SAFETY: `far` holds eight f32.
            (in_group(alive).map(|i| far[i]).fold(lo, f32::max), unsafe { _mm256_loadu_ps(far.as_ptr()) })
        };
        let (mut hi, mut ray_far) = widen(&t_max, alive);
        let mut stack = [MaybeUninit::<u32>::uninit(); STACK];
        stack[0].write(0);
        let mut sp = 1;
        while sp > 0 {
            sp -= 1;
            // SAFETY: the entries below `sp` were written.
            let node = &self.nodes[unsafe { stack[sp].assume_init() } as usize];
            let (mut entered, _) = rays.node_test(node, lo, hi);
            // A leaf is tested only by the rays whose own slab test enters its box (the
            // packet's bounds enter more boxes than any of its rays; the lone ray's `maybe` test,
            // so no box the lone ray enters is missed), and not at all where none does; the
            // memory of the children to visit is fetched at once, not miss after miss.
            let mut leaf_rays = [0u32; 8];
            let mut fetch = entered;
            while fetch != 0 {
                let slot = fetch.trailing_zeros() as usize;
                fetch &= fetch - 1;
                let child = node.child[slot];
                if child & LEAF == 0 {
                    prefetch(&self.nodes[child as usize]);
                    continue;
                }
                leaf_rays[slot] = rays.box_rays(node, slot, near8, ray_far) & alive;
                if leaf_rays[slot] == 0 {
                    entered &= !(1 << slot);
                } else {
                    prefetch(&self.blocks[(child & !LEAF) as usize]);
                }
            }
            for (slot, leaf) in node.leaves_in_order(entered) {
                let block = &self.blocks[leaf as usize];
                for lane in bits_downward(block.valid) {
                    let testing = leaf_rays[slot] & alive;
                    let Some(([t, u, v], valid)) = rays.triangle::<true>(block, lane, testing) else { continue };
                    // SAFETY: `t_max` holds eight f32.
                    let t_max8 = unsafe { _mm256_loadu_ps(t_max.as_ptr()) };
                    let within =
                        _mm256_and_ps(_mm256_cmp_ps::<_CMP_LT_OQ>(t_min8, t), _mm256_cmp_ps::<_CMP_LT_OQ>(t, t_max8));
                    let mut hit = valid & testing & _mm256_movemask_ps(within) as u32;
                    if hit == 0 {
                        continue;
                    }
                    let (mut ts, mut us, mut vs) = ([0.0f32; 8], [0.0f32; 8], [0.0f32; 8]);
                    // SAFETY: each holds eight f32.
                    unsafe { (_mm256_storeu_ps(ts.as_mut_ptr(), t), _mm256_storeu_ps(us.as_mut_ptr(), u)) };
                    // SAFETY: as above.
                    unsafe { _mm256_storeu_ps(vs.as_mut_ptr(), v) };
                    let prim = block.prim[lane] as usize;
                    while hit != 0 {
                        let ray = hit.trailing_zeros() as usize;
                        hit &= hit - 1;
                        match any_hit(ray, prim, ts[ray], Vec2::new(us[ray], vs[ray])) {
                            super::AnyHit::Ignore => continue,
                            super::AnyHit::Accept => t_max[ray] = ts[ray],
                            super::AnyHit::AcceptAndEnd => alive &= !(1 << ray),
                        }
                        (hi, ray_far) = widen(&t_max, alive);
                    }
                }
            }
            if alive == 0 {
                return;
            }
            node.push_inner_in_order(entered, octant, &mut stack, &mut sp);
        }
    }
}

/// The barycentrics `(u, v)` of a hit of `tri` (the weights of its second and third corner) as
/// obvhs' `Triangle::intersect` computes them on the way to the distance (Möller & Trumbore
/// 1997, with `e1 = v0 − v1`, `e2 = v2 − v0`: `u = ((d × c)·e2)/(n·d)`, `v = ((d × c)·e1)/(n·d)`,
/// `c = v0 − o`), bit for bit what the block and packet tests report.
#[inline]
pub fn obvhs_barycentrics(tri: &Triangle, origin: Vec3A, direction: Vec3A) -> Vec2 {
    let (e1, e2) = (tri.v0 - tri.v1, tri.v2 - tri.v0);
    let n = e1.cross(e2);
    let r = direction.cross(tri.v0 - origin);
    let inv_det = 1.0 / n.dot(direction);
    Vec2::new(r.dot(e2) * inv_det, r.dot(e1) * inv_det)
}

/// Ask the CPU to bring `value`'s cache lines into its caches (a hint; nothing on other
/// architectures).
#[inline(always)]
fn prefetch<T>(value: &T) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        let start = value as *const T as *const i8;
        for line in (0..std::mem::size_of::<T>()).step_by(64) {
            // SAFETY: a prefetch never faults; the address lies inside `value`.
            unsafe { _mm_prefetch::<_MM_HINT_T0>(start.wrapping_add(line)) };
        }
    }
}

/// obvhs' `ray_get_octant_inv4`: bit 2 / 1 / 0 set where the direction's x / y / z is not
/// `< 0.0` (−0 counts as positive).
#[inline(always)]
fn octant(direction: Vec3A) -> u32 {
    [direction.x, direction.y, direction.z].iter().fold(0, |o, &d| o << 1 | u32::from(d.is_nan() || d >= 0.0))
}

/// How far beyond the best hit so far the closest-hit traversals still enter boxes: a relative
/// 2⁻¹⁶. A triangle's Möller–Trumbore distance can round past its own box's slab entry by a few
/// ulps; the margin lets single rays and packets both find every triangle hit at the best
/// distance (for the tie rule) unless rounding moves it more than 2⁻¹⁶ (measured on sponza at
/// 2048×1208 without a margin: 1 ray of 2.2 M found a tie in a box that the single ray dropped).
#[inline(always)]
fn with_margin(best_t: f32) -> f32 {
    best_t + best_t.abs() * MARGIN
}

/// `t` less the relative margin of [`with_margin`]: the other end of a widened interval.
#[inline(always)]
fn below_margin(t: f32) -> f32 {
    t - t.abs() * MARGIN
}

/// Enter the children `mask` of `node` nearest first: with a single child, return it (the
/// traversal goes straight into it); otherwise push them above `sp`, sorted by their entry
/// distances `near` with the farthest lowest, so that the nearest pops first.
#[inline(always)]
fn enter_nearest_first(
    node: &Node,
    mut mask: u32,
    near: &[f32; 8],
    stack: &mut [MaybeUninit<(u32, f32)>; STACK],
    sp: &mut usize,
) -> Option<u32> {
    if mask != 0 && mask & (mask - 1) == 0 {
        return Some(node.child[mask.trailing_zeros() as usize]);
    }
    let base = *sp;
    while mask != 0 {
        let slot = mask.trailing_zeros() as usize;
        mask &= mask - 1;
        let entry = (node.child[slot], near[slot]);
        let mut k = *sp;
        // SAFETY (both): the entries below `sp` were written.
        while k > base && unsafe { stack[k - 1].assume_init() }.1 < entry.1 {
            stack[k] = stack[k - 1];
            k -= 1;
        }
        stack[k].write(entry);
        *sp += 1;
    }
    None
}

/// The relative margin of [`with_margin`].
const MARGIN: f32 = 1.0 / 65536.0;

/// obvhs' CWBVH node test clamps box entries at this distance (`EPSILON` in obvhs 0.4's
/// `cwbvh/node.rs`, crate-private there).
const OBVHS_EPSILON: f32 = 1e-4;

/// The tie rule of the closest-hit traversals: a candidate `(t, primitive)` replaces the best
/// so far `(best_t, best)` (none yet: `best_t` is the interval's end, which the triangle test
/// already excluded) if it is nearer, or as near with a lower primitive index. Single rays and
/// packets visit triangles in different orders; with this rule both keep the same hit.
#[inline(always)]
fn replaces((t, prim): (f32, usize), (best_t, best): (f32, Option<usize>)) -> bool {
    t < best_t || (t == best_t && best.is_some_and(|b| prim < b))
}

impl Block {
    /// The block of `count` (≤ 4) triangles from `start`, and their box.
    fn new(triangles: &[Triangle], start: u32, count: u32) -> (Block, Vec3A, Vec3A) {
        assert!(count <= 4, "a CWBVH leaf holds at most 3 triangles");
        let mut block =
            Block { v0: [[0.0; 4]; 3], e1: [[0.0; 4]; 3], e2: [[0.0; 4]; 3], n: [[0.0; 4]; 3], prim: [0; 4], valid: 0 };
        let (mut lo, mut hi) = (Vec3A::INFINITY, Vec3A::NEG_INFINITY);
        for lane in 0..count as usize {
            let prim = start + lane as u32;
            let t = &triangles[prim as usize];
            // As `Triangle::intersect` derives them.
            let (e1, e2) = (t.v0 - t.v1, t.v2 - t.v0);
            let n = e1.cross(e2);
            for axis in 0..3 {
                block.v0[axis][lane] = t.v0[axis];
                block.e1[axis][lane] = e1[axis];
                block.e2[axis][lane] = e2[axis];
                block.n[axis][lane] = n[axis];
            }
            block.prim[lane] = prim;
            block.valid |= 1 << lane;
            lo = lo.min(t.v0).min(t.v1).min(t.v2);
            hi = hi.max(t.v0).max(t.v1).max(t.v2);
        }
        (block, lo, hi)
    }
}

/// Whether the CPU runs AVX (8-lane node tests).
fn has_avx() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        is_x86_feature_detected!("avx")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use obvhs::BvhBuildParams;
    use obvhs::cwbvh::builder::build_cwbvh_from_tris;
    use std::time::Duration;

    /// xorshift32 in [0, 1).
    struct Rng(u32);

    impl Rng {
        fn next(&mut self) -> f32 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 17;
            self.0 ^= self.0 << 5;
            (self.0 >> 8) as f32 / (1 << 24) as f32
        }
        fn vec(&mut self, lo: f32, hi: f32) -> Vec3A {
            Vec3A::new(self.next(), self.next(), self.next()) * (hi - lo) + Vec3A::splat(lo)
        }
        fn unit(&mut self) -> Vec3A {
            loop {
                let v = self.vec(-1.0, 1.0);
                if v.length_squared() > 1e-4 && v.length_squared() <= 1.0 {
                    return v.normalize();
                }
            }
        }
    }

    /// The per-triangle predicate of [`Block::intersect`] in scalar arithmetic (the same IEEE
    /// operations in the same order): the distance of a hit inside `(t_min, t_max)`.
    fn reference_hit(tri: &Triangle, o: Vec3A, d: Vec3A, t_min: f32, t_max: f32) -> Option<f32> {
        let (e1, e2) = (tri.v0 - tri.v1, tri.v2 - tri.v0);
        let n = e1.cross(e2);
        let dot = |a: Vec3A, b: Vec3A| a.x * b.x + a.y * b.y + a.z * b.z;
        let c = tri.v0 - o;
        let r = Vec3A::new(d.y * c.z - d.z * c.y, d.z * c.x - d.x * c.z, d.x * c.y - d.y * c.x);
        let inv_det = 1.0 / dot(n, d);
        let u = dot(r, e2) * inv_det;
        let v = dot(r, e1) * inv_det;
        let w = 1.0 - u - v;
        let t = dot(n, c) * inv_det;
        let signs = (u.to_bits() | v.to_bits() | w.to_bits()) >> 31;
        (inv_det != 0.0 && signs == 0 && t_min < t && t < t_max).then_some(t)
    }

    /// A soup of `count` random triangles of random sizes in the unit cube (in BVH order) and
    /// its two layouts.
    fn scene(count: usize, seed: u32) -> (Vec<Triangle>, WideBvh) {
        let mut rng = Rng(seed);
        let tris: Vec<Triangle> = (0..count)
            .map(|_| {
                let c = rng.vec(0.0, 1.0);
                let size = 0.01 + 0.2 * rng.next() * rng.next();
                Triangle { v0: c + rng.vec(-size, size), v1: c + rng.vec(-size, size), v2: c + rng.vec(-size, size) }
            })
            .collect();
        let bvh = build_cwbvh_from_tris(&tris, BvhBuildParams::medium_build(), &mut Duration::default());
        let ordered: Vec<Triangle> = bvh.primitive_indices.iter().map(|&i| tris[i as usize]).collect();
        let wide = WideBvh::build(&bvh, &ordered);
        (ordered, wide)
    }

    /// Random rays through the cube (some from inside, some axis-aligned with ±0 components),
    /// with finite and infinite lengths.
    fn rays(count: usize, seed: u32) -> Vec<(Vec3A, Vec3A, f32, f32)> {
        let mut rng = Rng(seed);
        (0..count)
            .map(|i| {
                let o = rng.vec(-0.5, 1.5);
                let mut d = rng.unit();
                if i % 7 == 0 {
                    d = [Vec3A::X, Vec3A::NEG_Y, Vec3A::new(0.0, -0.0, 1.0)][i % 3];
                }
                let t_max = if i % 3 == 0 { f32::INFINITY } else { 0.05 + 0.5 * rng.next() };
                let t_min = if i % 5 == 0 { 0.02 } else { 0.0 };
                (o, d, t_min, t_max)
            })
            .collect()
    }

    /// Both node tests (AVX where the CPU has it, and the 4-lane halves).
    fn layouts(wide: &WideBvh) -> Vec<WideBvh> {
        let copy =
            |avx| WideBvh { nodes: wide.nodes.clone(), blocks: wide.blocks.clone(), root: wide.root, avx, id: wide.id };
        [false, has_avx()].into_iter().map(copy).collect()
    }

    #[test]
    fn closest_and_occluded_match_brute_force() {
        for (count, seed) in [(1, 3), (3, 5), (40, 7), (3000, 11)] {
            let (tris, wide) = scene(count, seed);
            // Accept every triangle, or only even-numbered ones (an alpha test's shape).
            let filters: [fn(usize) -> bool; 2] = [|_| true, |p| p % 2 == 0];
            for w in layouts(&wide) {
                let (mut hits, mut occluded) = (0, 0);
                for (o, d, t_min, t_max) in rays(4000, seed * 31) {
                    for accept in filters {
                        let expect = tris
                            .iter()
                            .enumerate()
                            .filter(|&(p, _)| accept(p))
                            .filter_map(|(p, tri)| reference_hit(tri, o, d, t_min, t_max).map(|t| (t, p)))
                            .min_by(|a, b| a.0.total_cmp(&b.0));
                        let got = w.closest(o, d, t_min, t_max, |p, _| accept(p));
                        // The distance is exact; the triangle too unless two share it.
                        assert_eq!(got.map(|g| g.0), expect.map(|e| e.0), "{count} triangles, ray {o} {d}");
                        if let (Some(g), Some(e)) = (got, expect)
                            && g.1 != e.1
                        {
                            assert_eq!(reference_hit(&tris[g.1], o, d, t_min, t_max), Some(e.0));
                        }
                        let any = w.occluded(o, d, t_min, t_max, |p, t| {
                            assert_eq!(reference_hit(&tris[p], o, d, t_min, t_max), Some(t), "reported hit is real");
                            accept(p)
                        });
                        assert_eq!(any, expect.is_some(), "{count} triangles, ray {o} {d} [{t_min}, {t_max}]");
                        hits += expect.is_some() as u32;
                        occluded += any as u32;
                    }
                }
                assert!(count < 3000 || hits > 1000, "the rays must hit often enough to test something: {hits}");
                assert_eq!(hits, occluded);
            }
        }
    }

    #[test]
    fn packets_answer_as_single_rays() {
        for (count, seed) in [(1, 3), (40, 7), (3000, 11)] {
            let (tris, wide) = scene(count, seed);
            let mut rng = Rng(seed * 77);
            for w in layouts(&wide) {
                let mut hits = 0;
                for packet in 0..600 {
                    let o = rng.vec(-0.5, 1.5);
                    // Coherent packets (a narrow cone, as a pixel tile's camera rays), wide ones,
                    // and axis-aligned rays with ±0 components.
                    let axis = rng.unit();
                    let spread = [0.01, 0.3, 2.0][packet % 3];
                    let dirs: [Vec3A; PACKET] = std::array::from_fn(|i| {
                        if packet % 11 == 0 && i < 3 {
                            return [Vec3A::X, Vec3A::NEG_Y, Vec3A::new(0.0, -0.0, 1.0)][i];
                        }
                        (axis + rng.unit() * spread).normalize()
                    });
                    let (t_min, t_max) = if packet % 4 == 0 { (0.02, 0.7) } else { (0.0, f32::INFINITY) };
                    let filters: [fn(usize) -> bool; 2] = [|_| true, |p| p % 2 == 0];
                    for accept in filters {
                        let got = w.closest_packet(o, &dirs, t_min, t_max, |ray, p, t| {
                            assert_eq!(
                                reference_hit(&tris[p], o, dirs[ray], t_min, t_max),
                                Some(t),
                                "reported hit is real"
                            );
                            accept(p)
                        });
                        for (i, d) in dirs.iter().enumerate() {
                            let single = w.closest(o, *d, t_min, t_max, |p, _| accept(p));
                            assert_eq!(got[i], single, "{count} triangles, packet {packet} ray {i}: {o} {d}");
                            hits += single.is_some() as u32;
                        }
                    }
                }
                assert!(count < 3000 || hits > 1000, "the rays must hit often enough to test something: {hits}");
            }
        }
    }

    #[test]
    fn ties_go_to_the_lowest_primitive() {
        // Two copies of one triangle, and two triangles sharing an edge the ray passes through.
        let a =
            Triangle { v0: Vec3A::new(0.0, 0.0, 1.0), v1: Vec3A::new(1.0, 0.0, 1.0), v2: Vec3A::new(0.0, 1.0, 1.0) };
        let b =
            Triangle { v0: Vec3A::new(1.0, 0.0, 1.0), v1: Vec3A::new(1.0, 1.0, 1.0), v2: Vec3A::new(0.0, 1.0, 1.0) };
        let tris = [a, b, a, b, a];
        let bvh = build_cwbvh_from_tris(&tris, BvhBuildParams::medium_build(), &mut Duration::default());
        let ordered: Vec<Triangle> = bvh.primitive_indices.iter().map(|&i| tris[i as usize]).collect();
        let wide = WideBvh::build(&bvh, &ordered);
        for w in layouts(&wide) {
            let o = Vec3A::new(0.5, 0.5, 0.0);
            let dirs: [Vec3A; PACKET] =
                std::array::from_fn(|i| (Vec3A::new(0.25 * (i % 4) as f32 - 0.3, 0.0, 1.0)).normalize());
            let packet = w.closest_packet(o, &dirs, 0.0, f32::INFINITY, |_, _, _| true);
            for (i, d) in dirs.iter().enumerate() {
                let all: Vec<(f32, usize)> = (0..tris.len())
                    .filter_map(|p| reference_hit(&ordered[p], o, *d, 0.0, f32::INFINITY).map(|t| (t, p)))
                    .collect();
                let nearest = all.iter().map(|h| h.0).fold(f32::INFINITY, f32::min);
                let lowest = all.iter().filter(|h| h.0 == nearest).map(|h| h.1).min();
                assert!(all.len() >= 2, "ray {i} hits the stacked copies");
                assert_eq!(w.closest(o, *d, 0.0, f32::INFINITY, |_, _| true), lowest.map(|p| (nearest, p)), "ray {i}");
                assert_eq!(packet[i], lowest.map(|p| (nearest, p)), "ray {i}");
            }
        }
    }

    #[test]
    fn a_cut_answers_as_the_root_does() {
        let (_, wide) = scene(3000, 13);
        let mut rng = Rng(99);
        for w in layouts(&wide) {
            let mut cut = OriginCut::default();
            let mut built = 0;
            for pixel in 0..300 {
                // A run of rays from one origin with one length, as a pixel's AO rays.
                let o = rng.vec(0.0, 1.0);
                let t_max = 0.02 + 0.2 * rng.next();
                for _ in 0..24 {
                    let d = rng.unit();
                    let filter = |p: usize, _| p % 3 != pixel % 3;
                    assert_eq!(
                        w.occluded_cut(&mut cut, o, d, 0.0, t_max, filter),
                        w.occluded(o, d, 0.0, t_max, filter),
                        "ray {o} {d} {t_max}"
                    );
                }
                built += cut.built as u32;
                assert!(cut.count <= CUT / 8);
            }
            assert_eq!(built, 300, "every run builds its cut");
            // A cut of another tree is never used.
            let (_, other) = scene(50, 17);
            let o = rng.vec(0.0, 1.0);
            let d = rng.unit();
            for _ in 0..3 {
                assert_eq!(
                    other.occluded_cut(&mut cut, o, d, 0.0, 0.3, |_, _| true),
                    other.occluded(o, d, 0.0, 0.3, |_, _| true)
                );
            }
        }
    }

    /// `Block::intersect_obvhs` answers per lane bit for bit as obvhs' `Triangle::intersect`
    /// (kept to the open interval), on rays aimed at edges and corners where rounding decides.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn block_test_is_obvhs_to_the_bit() {
        let (tris, _) = scene(400, 23);
        let mut rng = Rng(41);
        let (mut hits, mut plain_differs) = (0, 0);
        for chunk in tris.chunks(4) {
            let (block, _, _) = Block::new(chunk, 0, chunk.len() as u32);
            for k in 0..200 {
                // A point on an edge, at a corner or inside a triangle of the block, from a
                // random origin.
                let tri = &chunk[k % chunk.len()];
                let s = if k % 5 == 0 { 0.0 } else { rng.next() };
                let target = match k % 3 {
                    0 => tri.v0 + (tri.v1 - tri.v0) * s,
                    1 => tri.v1 + (tri.v2 - tri.v1) * s,
                    _ => tri.v2 + (tri.v0 - tri.v2) * s * rng.next(),
                };
                let o = rng.vec(-0.5, 1.5);
                let d = (target - o).normalize();
                let (t_min, t_max) = if k % 4 == 0 { (0.01, 1.2) } else { (0.0, f32::INFINITY) };
                let pre = RayPre::new(o, d);
                let (mask, ts, [us, vs]) = block.intersect_obvhs(&pre, F4::splat(t_min), F4::splat(t_max));
                let (plain, _) = block.intersect(&pre, F4::splat(t_min), F4::splat(t_max));
                plain_differs += (plain != mask) as u32;
                for (lane, tri) in chunk.iter().enumerate() {
                    let t = tri.intersect(&obvhs::ray::Ray::new(o, d, t_min, t_max));
                    let expect = (t > t_min && t < t_max).then_some(t.to_bits());
                    let got = (mask & 1 << lane != 0).then_some(ts[lane].to_bits());
                    assert_eq!(got, expect, "lane {lane}, ray {o} {d} [{t_min}, {t_max}]");
                    if expect.is_some() {
                        // The barycentrics come from the same arithmetic, and weigh the corners
                        // to the hit point.
                        let uv = obvhs_barycentrics(tri, o, d);
                        assert_eq!((us[lane].to_bits(), vs[lane].to_bits()), (uv.x.to_bits(), uv.y.to_bits()));
                        let p = tri.v0 * (1.0 - uv.x - uv.y) + tri.v1 * uv.x + tri.v2 * uv.y;
                        let scale = 1.0 + tri.v0.abs().max(tri.v1.abs()).max(tri.v2.abs()).max_element();
                        assert!((p - (o + d * t)).length() < 1e-3 * scale, "weights of v0, v1, v2: {uv}");
                    }
                    hits += expect.is_some() as u32;
                }
            }
        }
        assert!(hits > 5_000, "the rays must hit often enough to test something: {hits}");
        // With FMA glam's cross rounds once per component; the plain test then decides some
        // edges otherwise, which these rays must be sharp enough to show.
        #[cfg(target_feature = "fma")]
        assert!(plain_differs > 0, "the rays never reach the edges' rounding");
        let _ = plain_differs;
    }

    #[test]
    fn empty_and_degenerate_inputs() {
        let bvh = build_cwbvh_from_tris(&[], BvhBuildParams::medium_build(), &mut Duration::default());
        let empty = WideBvh::build(&bvh, &[]);
        assert_eq!(empty.closest(Vec3A::ZERO, Vec3A::X, 0.0, f32::INFINITY, |_, _| true), None);
        assert!(!empty.occluded_cut(&mut OriginCut::default(), Vec3A::ZERO, Vec3A::X, 0.0, 1.0, |_, _| true));
        // One triangle, a ray through its middle; an empty interval finds nothing.
        let tri =
            Triangle { v0: Vec3A::new(0.0, 0.0, 1.0), v1: Vec3A::new(1.0, 0.0, 1.0), v2: Vec3A::new(0.0, 1.0, 1.0) };
        let bvh = build_cwbvh_from_tris(&[tri], BvhBuildParams::medium_build(), &mut Duration::default());
        let one = WideBvh::build(&bvh, &[tri]);
        let o = Vec3A::new(0.25, 0.25, 0.0);
        assert_eq!(one.closest(o, Vec3A::Z, 0.0, f32::INFINITY, |_, _| true), Some((1.0, 0)));
        assert_eq!(one.closest(o, Vec3A::Z, 0.0, 1.0, |_, _| true), None, "t_max is exclusive");
        assert_eq!(one.closest(o, Vec3A::Z, 1.0, 2.0, |_, _| true), None, "t_min is exclusive");
        assert!(one.occluded(o, Vec3A::Z, 0.5, 1.5, |_, _| true));
        assert!(!one.occluded(o, -Vec3A::Z, 0.0, 5.0, |_, _| true));
        let mut cut = OriginCut::default();
        for _ in 0..3 {
            assert!(one.occluded_cut(&mut cut, o, Vec3A::Z, 0.0, 2.0, |_, _| true));
        }
    }
}
