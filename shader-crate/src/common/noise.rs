//! XeGTAO's spatio-temporal noise (spec gtao-raymarch-hybrid §1.6): a Hilbert-curve index over
//! a 64×64 tile drives the R2 low-discrepancy sequence, so neighbouring pixels get well spread
//! samples. Used by XeGTAO, the Poisson-disk ray-marched SSAO and the hybrid AO.

use crate::common::math::{frac, u32_to_f32};
use crate::glam::{UVec2, Vec2, vec2};

/// Hilbert index of `p` in a 64×64 tile (6 levels; only the low 6 bits of x and y count),
/// spec gtao-raymarch-hybrid §1.6: for b = 32…1, `idx += b²·((3·rx) ^ ry)`, then rotate the quadrant.
/// The six levels are written out and the rotation is chosen by selects: straight-line code on
/// the GPU, no loop or divergent branch per pixel.
#[inline]
#[allow(unused_assignments)] // the last level's rotation is not read
pub fn hilbert_index(p: UVec2) -> u32 {
    let (mut x, mut y) = (p.x & 63, p.y & 63);
    let mut index = 0;
    macro_rules! level {
        ($b:expr) => {
            let rx = ((x & $b) != 0) as u32;
            let ry = ((y & $b) != 0) as u32;
            index += $b * $b * ((3 * rx) ^ ry);
            // ry = 0: reflect when rx = 1, then swap x and y.
            let flip = (ry == 0) & (rx == 1);
            let (fx, fy) = (63 - x, 63 - y);
            let fx = if flip { fx } else { x };
            let fy = if flip { fy } else { y };
            let swap = ry == 0;
            x = if swap { fy } else { fx };
            y = if swap { fx } else { fy };
        };
    }
    level!(32);
    level!(16);
    level!(8);
    level!(4);
    level!(2);
    level!(1);
    index
}

/// R2 constants `1/ρ`, `1/ρ²` of the plastic number ρ = 1.32471795… (spec gtao-raymarch-hybrid §1.6).
pub const R2: [f32; 2] = [0.754_877_7, 0.569_840_3];

/// The noise `ξ = frac(0.5 + i·(1/ρ, 1/ρ²))` of pixel `p` with `i = hilbert(p) + 288·(frame mod
/// 64)`, in f32 in XeGTAO's order (spec gtao-raymarch-hybrid §1.6). `ξ.x` drives slice/rotation angles, `ξ.y` steps.
#[inline]
pub fn spatio_temporal_noise(p: UVec2, frame: u32) -> Vec2 {
    let i = u32_to_f32(hilbert_index(p) + 288 * (frame % 64));
    vec2(frac(0.5 + i * R2[0]), frac(0.5 + i * R2[1]))
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
