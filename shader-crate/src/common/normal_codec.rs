//! Octahedral normal encoding into two snorm8 bytes (spec svao-raysd §1, Falcor's R16Uint
//! normal target). Quantizing through it matches the reference bit-for-bit.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use crate::common::lanes::{LaneVec3, Lanes};
use crate::common::math::{clamp, sign_nonzero};
use crate::glam::{Vec3, vec2};

/// Wrap of the lower hemisphere: `(1 − |p.yx|)·sign(p)`, sign of 0 = +1 (spec svao-raysd §1).
/// One point or `L::LANES`.
#[inline]
fn oct_wrap<L: Lanes>(x: L, y: L) -> (L, L) {
    ((-y.abs() + 1.0) * sign_nonzero(x), (-x.abs() + 1.0) * sign_nonzero(y))
}

/// snorm8 quantization `trunc(c·127 ± 0.5)` after clamping to [−1, 1], NaN → 0 (spec svao-raysd §1).
#[inline]
fn snorm8(c: f32) -> u32 {
    let c = if c.is_nan() { 0.0 } else { clamp(c, -1.0, 1.0) };
    let q = (c * 127.0 + 0.5 * sign_nonzero(c)) as i32; // `as` truncates toward zero
    (q as u32) & 0xFF
}

/// Encode a (not necessarily unit) normal: `p = n.xy/(|x|+|y|+|z|)`, wrapped when `n.z < 0`;
/// x in bits 0–7 and y in bits 8–15. Degenerate input encodes as +Z.
#[inline]
pub fn encode_normal(n: Vec3) -> u32 {
    let l1 = n.x.abs() + n.y.abs() + n.z.abs();
    let mut p = vec2(n.x / l1, n.y / l1);
    if n.z < 0.0 {
        let (x, y) = oct_wrap(p.x, p.y);
        p = vec2(x, y);
    }
    snorm8(p.x) | (snorm8(p.y) << 8)
}

/// Decode to a unit normal (spec svao-raysd §1).
#[inline]
pub fn decode_normal(code: u32) -> Vec3 {
    decode_normal_lanes::<f32>(code)
}

/// [`decode_normal`] per lane, branch-free (the CPU decodes a code per lane in vector registers):
/// the bytes sign-extended as floats (`b − 256` for b ≥ 128, exact), the lower hemisphere's
/// wrap chosen by a select.
#[inline]
pub fn decode_normal_lanes<L: Lanes>(code: L::Index) -> L::V3 {
    // Sign-extended snorm8 byte back to [−1, 1]: `max(b/127, −1)` (spec svao-raysd §1).
    let byte = |shift: u32| {
        let b = L::index_to_float((code >> shift) & L::index_splat(0xFF));
        let b = L::select(b.ge(L::splat(128.0)), b - 256.0, b);
        (b / 127.0).max(L::splat(-1.0))
    };
    let (x, y) = (byte(0), byte(8));
    let z = -x.abs() + 1.0 - y.abs();
    let below = z.lt(L::splat(0.0));
    let (wx, wy) = oct_wrap(x, y);
    L::V3::new(L::select(below, wx, x), L::select(below, wy, y), z).normalize()
}
