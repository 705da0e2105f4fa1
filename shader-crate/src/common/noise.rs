//! XeGTAO's spatio-temporal noise (spec gtao-raymarch-hybrid §1.6): a Hilbert-curve index over
//! a 64×64 tile drives the R2 low-discrepancy sequence, so neighbouring pixels get well spread
//! samples. Used by XeGTAO, the Poisson-disk ray-marched SSAO and the hybrid AO.

use crate::common::lanes::{LaneVec2, Lanes};
use crate::common::math::{frac, u32_to_f32};
use crate::glam::{UVec2, Vec2, vec2};

/// Hilbert index of `p` in a 64×64 tile (6 levels; only the low 6 bits of x and y count),
/// spec gtao-raymarch-hybrid §1.6: for b = 32…1, `idx += b²·((3·rx) ^ ry)`, then rotate the
/// quadrant ([`hilbert_index_lanes`] with one lane).
#[inline]
pub fn hilbert_index(p: UVec2) -> u32 {
    hilbert_index_lanes::<f32>(p.x, p.y)
}

/// [`hilbert_index`] of the texels `(x, y)` per lane, in integer arithmetic only: the six levels
/// written out, the quadrant's reflection `(63 − x, 63 − y)` as `x ^ 63` on six bits, and the
/// reflection and the swap applied by XOR with a value that is zero where they do not apply.
/// Straight-line code on the GPU and on the CPU's lanes (no branch or select per pixel).
#[inline]
#[allow(unused_assignments)] // the last level's rotation is not read
pub fn hilbert_index_lanes<L: Lanes>(x: L::Index, y: L::Index) -> L::Index {
    let (one, six_bits) = (L::index_splat(1), L::index_splat(63));
    let (mut x, mut y) = (x & six_bits, y & six_bits);
    let mut index = L::index_splat(0);
    macro_rules! level {
        ($shift:expr) => {
            // b = 2^shift: rx = (x & b) ≠ 0, ry = (y & b) ≠ 0.
            let rx = (x >> $shift) & one;
            let ry = (y >> $shift) & one;
            index = index + ((rx * L::index_splat(3)) ^ ry) * L::index_splat(1 << (2 * $shift));
            // ry = 0: reflect when rx = 1, then swap x and y.
            let not_ry = ry ^ one;
            let reflect = (rx & not_ry) * six_bits;
            let (fx, fy) = (x ^ reflect, y ^ reflect);
            let swap = (fx ^ fy) * not_ry;
            x = fx ^ swap;
            y = fy ^ swap;
        };
    }
    level!(5);
    level!(4);
    level!(3);
    level!(2);
    level!(1);
    level!(0);
    index
}

/// R2 constants `1/ρ`, `1/ρ²` of the plastic number ρ = 1.32471795… (spec gtao-raymarch-hybrid §1.6).
pub const R2: [f32; 2] = [0.754_877_7, 0.569_840_3];

/// The noise `ξ = frac(0.5 + i·(1/ρ, 1/ρ²))` of pixel `p` with `i = hilbert(p) + 288·(frame mod
/// 64)`, in f32 in XeGTAO's order (spec gtao-raymarch-hybrid §1.6). `ξ.x` drives slice/rotation angles, `ξ.y` steps.
#[inline]
pub fn spatio_temporal_noise(p: UVec2, frame: u32) -> Vec2 {
    spatio_temporal_noise_lanes::<f32>(p, frame)
}

/// [`spatio_temporal_noise`] of each lane's pixel.
#[inline]
pub fn spatio_temporal_noise_lanes<L: Lanes>(p: L::U2, frame: u32) -> L::V2 {
    let hilbert = hilbert_index_lanes::<L>(L::texel_x(p), L::texel_y(p));
    let i = L::index_to_float(hilbert + L::index_splat(288 * (frame % 64)));
    L::V2::new(frac(i * R2[0] + 0.5), frac(i * R2[1] + 0.5))
}

/// The frame's Cranley–Patterson offset for the random numbers that have no temporal index of
/// their own (the ray-traced techniques' hashes and per-pixel sequences): the R2 point of the
/// frame, `r(f) = frac((f mod 64)·(1/ρ, 1/ρ²))` — spec gtao-raymarch-hybrid §1.6's sequence and 64-frame period,
/// without its 0.5 start so that `r(0) = (0, 0)`.
#[inline]
pub fn frame_rotation(frame: u32) -> Vec2 {
    let f = u32_to_f32(frame % 64);
    vec2(frac(f * R2[0]), frac(f * R2[1]))
}

/// Cranley–Patterson rotation of a uniform number `u` ∈ [0, 1) by `r`: `frac(u + r)`, uniform
/// again. With `r = 0` (frame 0, [`frame_rotation`]) it returns `u` bit for bit, so a single
/// frame keeps the techniques' original noise.
#[inline]
pub fn rotate(u: f32, r: f32) -> f32 {
    frac(u + r)
}
