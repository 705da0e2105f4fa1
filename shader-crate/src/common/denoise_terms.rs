//! The input of XeGTAO's denoiser (spec gtao-raymarch-hybrid §2.6–§2.7), written by XeGTAO's
//! main pass, the ray march and the hybrid: AO terms stored as 0–255 and packed depth edges.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use crate::common::lanes::Lanes;
use crate::common::math::{f32_to_u32, sat, u32_to_f32};
use crate::glam::{Vec3, Vec4, vec4};

/// Round half to even (HLSL `round`, spec gtao-raymarch-hybrid §1.5): `RoundEven` on SPIR-V,
/// `f32::round_ties_even` natively (one `roundss` on x86-64-v3), the same value for every float
/// (−0 for x in [−0.5, −0], every |x| ≥ 2²³ unchanged).
#[inline]
pub fn round_even(x: f32) -> f32 {
    #[cfg(target_arch = "spirv")]
    #[allow(unused_unsafe)]
    // SAFETY: a pure float operation (GLSL.std.450 RoundEven).
    let r = unsafe { core::intrinsics::round_ties_even_f32(x) };
    #[cfg(not(target_arch = "spirv"))]
    let r = x.round_ties_even();
    r
}

/// Edge weights (L, R, T, B) of a pixel at depth `zc` from its 4-neighbours (spec gtao-raymarch-hybrid §2.6.1):
/// slope-corrected depth differences, `sat(1.25 − min(|Δ|, |Δ'|)/(0.011·zc))`, 1 = connected.
/// One pixel or `L::LANES` pixels.
#[inline]
pub fn edges<L: Lanes>(zc: L, zl: L, zr: L, zt: L, zb: L) -> EdgeWeights<L> {
    let (dl, dr, dt, db) = (zl - zc, zr - zc, zt - zc, zb - zc);
    let slope_lr = (dr - dl) * 0.5;
    let slope_tb = (db - dt) * 0.5;
    let scale = zc * 0.011;
    let weight = |d: L, adjusted: L| sat(-(d.abs().min(adjusted.abs()) / scale) + 1.25);
    EdgeWeights {
        l: weight(dl, dl + slope_lr),
        r: weight(dr, dr - slope_lr),
        t: weight(dt, dt + slope_tb),
        b: weight(db, db - slope_tb),
    }
}

/// Pack edges as XeGTAO's R8 value: `q = round(sat(e)·2.9)`, `64·qL + 16·qR + 4·qT + qB`.
#[inline]
pub fn pack_edges<L: Lanes>(e: EdgeWeights<L>) -> L::Index {
    // round(·) of [0, 2.9] is a whole number 0–3, which floor_index takes exactly.
    let q = |v: L| (sat(v) * 2.9).round_even().floor_index(L::index_splat(4));
    L::index_splat(64) * q(e.l) + L::index_splat(16) * q(e.r) + L::index_splat(4) * q(e.t) + q(e.b)
}

/// Edge weights (L, R, T, B) of a pixel per lane, 1 = connected.
#[derive(Copy, Clone, Debug)]
pub struct EdgeWeights<L: Lanes = f32> {
    pub l: L,
    pub r: L,
    pub t: L,
    pub b: L,
}

/// Unpack [`pack_edges`] per lane: each 2-bit field / 3, as a product with the rounded 1/3 (for
/// the fields 0–3 exactly the quotients, without four divisions per neighbour).
#[inline]
pub fn unpack_edges<L: Lanes>(p: L::Index) -> EdgeWeights<L> {
    let three = L::index_splat(3);
    let third = 1.0 / 3.0;
    EdgeWeights {
        l: L::index_to_float((p >> 6) & three) * third,
        r: L::index_to_float((p >> 4) & three) * third,
        t: L::index_to_float((p >> 2) & three) * third,
        b: L::index_to_float(p & three) * third,
    }
}

/// `uint(sat(vis/1.5)·255 + 0.5)` (spec gtao-raymarch-hybrid §2.6.4).
#[inline]
pub fn store_term(vis: f32) -> u32 {
    f32_to_u32(sat(vis / 1.5) * 255.0 + 0.5)
}

/// RGBA8 UNORM packing of a term with a bent normal, `uint(sat(c)·255 + 0.5)` per channel, r
/// in the low byte (spec gtao-raymarch-hybrid §2.6.5: rgb = b·0.5 + 0.5, a = vis/1.5).
#[inline]
pub fn pack_bent_term(c: Vec4) -> u32 {
    let q = |x: f32| f32_to_u32(sat(x) * 255.0 + 0.5);
    q(c.x) | (q(c.y) << 8) | (q(c.z) << 16) | (q(c.w) << 24)
}

/// A unit bent normal `n` and the channel `a` packed as [`pack_bent_term`] (rgb = n·0.5 + 0.5).
#[inline]
pub fn pack_bent_normal(n: Vec3, a: f32) -> u32 {
    let c = n * 0.5 + 0.5;
    pack_bent_term(vec4(c.x, c.y, c.z, a))
}

/// [`pack_bent_term`] back to four channels in [0, 1].
#[inline]
pub fn unpack_bent_term(p: u32) -> Vec4 {
    vec4(u32_to_f32(p & 0xFF), u32_to_f32((p >> 8) & 0xFF), u32_to_f32((p >> 16) & 0xFF), u32_to_f32(p >> 24)) / 255.0
}
