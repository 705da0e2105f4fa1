//! Octahedral normal encoding into two snorm8 bytes (spec svao-raysd §1, Falcor's R16Uint
//! normal target). Quantizing through it matches the reference bit-for-bit.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use crate::common::math::{clamp, sign_nonzero};
use crate::glam::{Vec2, Vec3, vec2};

/// Wrap of the lower hemisphere: `(1 − |p.yx|)·sign(p)`, sign of 0 = +1 (spec svao-raysd §1).
#[inline]
fn oct_wrap(p: Vec2) -> Vec2 {
    vec2((1.0 - p.y.abs()) * sign_nonzero(p.x), (1.0 - p.x.abs()) * sign_nonzero(p.y))
}

/// snorm8 quantization `trunc(c·127 ± 0.5)` after clamping to [−1, 1], NaN → 0 (spec svao-raysd §1).
#[inline]
fn snorm8(c: f32) -> u32 {
    let c = if c.is_nan() { 0.0 } else { clamp(c, -1.0, 1.0) };
    let q = (c * 127.0 + 0.5 * sign_nonzero(c)) as i32; // `as` truncates toward zero
    (q as u32) & 0xFF
}

/// Sign-extended snorm8 byte back to [−1, 1]: `max(b/127, −1)` (spec svao-raysd §1).
#[inline]
fn unsnorm8(byte: u32) -> f32 {
    let b = ((byte << 24) as i32) >> 24;
    (b as f32 / 127.0).max(-1.0)
}

/// Encode a (not necessarily unit) normal: `p = n.xy/(|x|+|y|+|z|)`, wrapped when `n.z < 0`;
/// x in bits 0–7 and y in bits 8–15. Degenerate input encodes as +Z.
#[inline]
pub fn encode_normal(n: Vec3) -> u32 {
    let l1 = n.x.abs() + n.y.abs() + n.z.abs();
    let mut p = vec2(n.x / l1, n.y / l1);
    if n.z < 0.0 {
        p = oct_wrap(p);
    }
    snorm8(p.x) | (snorm8(p.y) << 8)
}

/// Decode to a unit normal (spec svao-raysd §1).
#[inline]
pub fn decode_normal(code: u32) -> Vec3 {
    let mut p = vec2(unsnorm8(code & 0xFF), unsnorm8((code >> 8) & 0xFF));
    let z = 1.0 - p.x.abs() - p.y.abs();
    if z < 0.0 {
        p = oct_wrap(p);
    }
    p.extend(z).normalize()
}
