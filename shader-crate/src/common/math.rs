//! Small helpers that compile identically for SPIR-V and the CPU. Those generic over
//! [`Lanes`] take `f32` (one pixel) or the CPU's lane vectors alike.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use crate::common::lanes::{LaneVec3, Lanes};

/// `x as f32` for `x < 2³¹` (the indices, texel coordinates, bytes and counts the kernels
/// convert), through a signed conversion, which gives the same float. Unsigned conversions
/// have no vector instruction before AVX-512: LLVM — lavapipe's compiler and the CPU build —
/// expands an unsigned one into several instructions per vector, a signed one is
/// `vcvtdq2ps`.
#[inline]
pub fn u32_to_f32(x: u32) -> f32 {
    x as i32 as f32
}

/// `x as u32` (truncation) for a finite `x` in [0, 2²³) (a clamped coordinate, a rounded
/// byte). On SPIR-V without any conversion instruction ([`f32_to_u32_bits`]): lavapipe compiles
/// every float-to-integer conversion, signed or not, to eight scalar saturating conversions per
/// vector (about six instructions each); this is three vector instructions. Natively Rust's
/// `as i32`, the same integer on that range (checked in debug builds).
#[inline]
pub fn f32_to_u32(x: f32) -> u32 {
    #[cfg(target_arch = "spirv")]
    let i = f32_to_u32_bits(x);
    #[cfg(not(target_arch = "spirv"))]
    let i = {
        debug_assert!((0.0..8_388_608.0).contains(&x), "f32_to_u32({x}): outside [0, 2²³)");
        x as i32 as u32
    };
    i
}

/// `⌊x⌋` for a finite `x` in [0, 2²³) from bits alone: `⌊x⌋ + 2²³` is exact, and its bits are
/// `0x4B00_0000 + ⌊x⌋` ([`f32_to_u32`]'s SPIR-V form; `tests/exhaustive.rs` checks it against
/// `as u32` on every float of the range).
#[inline]
pub fn f32_to_u32_bits(x: f32) -> u32 {
    (floor(x) + 8_388_608.0).to_bits() - 0x4B00_0000
}

/// `saturate(x)`: clamp to [0, 1]. NaN maps to 0.
#[inline]
pub fn sat<L: Lanes>(x: L) -> L {
    clamp(x, 0.0, 1.0)
}

/// Clamp without `f32::clamp`'s panic path (rust-gpu friendly). NaN maps to `lo`.
/// Requires `lo < hi`, or both +0 (every caller's bounds are constants that are): with those
/// the CPU's lanes clamp in two instructions ([`Lanes::clamp_between`]); for other bounds use
/// [`clamp_lanes`].
#[inline]
pub fn clamp<L: Lanes>(x: L, lo: f32, hi: f32) -> L {
    x.clamp_between(L::splat(lo), L::splat(hi))
}

/// [`clamp`] with bounds that differ per lane (any `lo ≤ hi`, signed zeros kept as the
/// compares choose them).
#[inline]
pub fn clamp_lanes<L: Lanes>(x: L, lo: L, hi: L) -> L {
    L::select(x.gt(lo), L::select(x.lt(hi), x, hi), lo)
}

/// Fractional part `x − floor(x)` ∈ [0, 1) (HLSL `frac`).
#[inline]
pub fn frac<L: Lanes>(x: L) -> L {
    x - x.floor()
}

/// `floor(x)`, bit for bit (−0 stays −0, NaN and ±∞ pass through). SPIR-V: `OpExtInst Floor`.
/// CPU without SSE4.1's `roundss` (the x86-64 baseline): `f32::floor` is an out-of-line libm
/// call, so truncate through `i32` instead, inline (every |x| ≥ 2²³ is already integral).
#[inline]
pub fn floor(x: f32) -> f32 {
    #[cfg(any(target_arch = "spirv", target_feature = "sse4.1", not(target_arch = "x86_64")))]
    {
        Float::floor(x)
    }
    #[cfg(not(any(target_arch = "spirv", target_feature = "sse4.1", not(target_arch = "x86_64"))))]
    {
        if x.is_nan() || x.abs() >= 8_388_608.0 {
            return x;
        }
        let t = x as i32 as f32;
        let r = if t > x { t - 1.0 } else { t };
        r.copysign(x)
    }
}

/// `x^p`, with the default `p = 2` (XeGTAO's SampleDistributionPower, spec
/// gtao-raymarch-hybrid §2.6.3 step 7) as the correctly rounded product `x·x` rather than a
/// `powf` call per sample (`exp2(p·log2 x)` on the GPU; glibc's `powf` is within 0.82 ulp, so
/// it may differ from `x·x` in the last bit), and `p = 1` (VBAO's FinalValuePower) as `x`.
#[inline]
pub fn pow<L: Lanes>(x: L, p: f32) -> L {
    if p == 2.0 {
        x * x
    } else if p == 1.0 {
        x
    } else {
        x.powf(p)
    }
}

/// `ceil(x) = −floor(−x)`, bit for bit (see [`floor`]).
#[inline]
pub fn ceil<L: Lanes>(x: L) -> L {
    -(-x).floor()
}

/// Sign with `sign(0) = +1` (spec svao-raysd §1 octahedral codec, §4.2 `nz`).
#[inline]
pub fn sign_nonzero<L: Lanes>(x: L) -> L {
    L::select(x.lt(L::splat(0.0)), L::splat(-1.0), L::splat(1.0))
}

/// True for a usable linear depth: finite, positive and in front of the far plane (per lane).
#[inline]
pub fn is_valid_depth<L: Lanes>(d: L, far: f32) -> L::Mask {
    L::and(d.gt(L::splat(0.0)), d.lt(L::splat(far)))
}

/// A depth as the kernels read it: unusable depths (NaN, ±∞, ≤ 0, ≥ far) read as the far plane,
/// where nothing occludes.
#[inline]
pub fn depth_or_far<L: Lanes>(d: L, far: f32) -> L {
    L::select(is_valid_depth(d, far), d, L::splat(far))
}

/// XeGTAO's `fastSqrt` (spec gtao-raymarch-hybrid §1.7): the float with bits
/// `0x1fbd1df5 + (bits(x) >> 1)`, for x ≥ 0.
#[inline]
pub fn fast_sqrt<L: Lanes>(x: L) -> L {
    x.map_bits(|b| 0x1fbd_1df5u32.wrapping_add(((b as i32) >> 1) as u32))
}

/// XeGTAO's `fastAcos` (spec gtao-raymarch-hybrid §1.7) with its literal 7-digit constants:
/// `r = (−0.156583·|x| + 1.570796)·fastSqrt(1 − |x|)`, `π − r` for negative x.
#[inline]
#[allow(clippy::approx_constant)] // XeGTAO's literal constants, kept for parity (spec gtao-raymarch-hybrid §1.7)
pub fn fast_acos<L: Lanes>(x: L) -> L {
    let a = x.abs();
    let r = (a * -0.156_583 + 1.570_796) * fast_sqrt(-a + 1.0);
    L::select(x.ge(L::splat(0.0)), r, -r + 3.141_593)
}

/// `acos(x)` for `x ∈ [−1, 1]` as one fixed sequence of binary32 operations, so every back-end
/// computes the same value up to the GPU's choice to fuse or not (the platforms' own `acos`
/// differ by several ulp: libm, `wide`'s lanes, a GPU driver's lowering): Abramowitz & Stegun 4.4.46,
/// `acos(a) = sqrt(1 − a)·(c0 + c1·a + … + c7·a⁷)` for `a = |x|` (|error| ≤ 2·10⁻⁸ rad in exact
/// arithmetic; ≤ 5·10⁻⁷ rad in binary32, `tests/kernel_math.rs`), Horner order with fused
/// multiply-adds ([`Lanes::mul_add`]: seven instructions, each rounded once on the CPU), and
/// `π − acos(|x|)` for negative x.
#[inline]
#[allow(clippy::approx_constant)] // c0 is A&S's 1.5707963050, not π/2 rounded
pub fn precise_acos<L: Lanes>(x: L) -> L {
    let a = x.abs();
    // Horner, written out (rust-gpu compiles no slice iterators): p ← p·a + c_k.
    let c = L::splat;
    let p = c(-0.001_262_491_1).mul_add(a, c(0.006_670_09));
    let p = p.mul_add(a, c(-0.017_088_126));
    let p = p.mul_add(a, c(0.030_891_88));
    let p = p.mul_add(a, c(-0.050_174_303));
    let p = p.mul_add(a, c(0.088_978_99));
    let p = p.mul_add(a, c(-0.214_598_8));
    let p = p.mul_add(a, c(1.570_796_3));
    let r = p * (-a + 1.0).sqrt();
    L::select(x.ge(L::splat(0.0)), r, -r + core::f32::consts::PI)
}

/// `a + (b − a)·t` (HLSL `lerp`).
#[inline]
pub fn lerp<L: Lanes>(a: L, b: L, t: L) -> L {
    a + (b - a) * t
}

/// Möller–Hughes minimal rotation taking unit `from` to unit `to`, applied to `v` (spec
/// gtao-raymarch-hybrid §2.6.5): identity when `from·to > 0.9997`; for near-opposite vectors
/// the rotation by π about `from`'s orthogonal x axis, `diag(1, −1, −1)` for `from = (0,0,−1)`
/// (spec gtao-raymarch-hybrid §3.4 step 5).
#[inline]
pub fn rotate_minimal<L: Lanes>(from: L::V3, to: L::V3, v: L::V3) -> L::V3 {
    let e = from.dot(to);
    let w = from.cross(to);
    let h = L::splat(1.0) / (e + 1.0);
    let (wx, wy, wz) = (w.x(), w.y(), w.z());
    let (vx, vy, vz) = (v.x(), v.y(), v.z());
    let general = L::V3::new(
        (e + h * wx * wx) * vx + (h * wx * wy - wz) * vy + (h * wx * wz + wy) * vz,
        (h * wx * wy + wz) * vx + (e + h * wy * wy) * vy + (h * wy * wz - wx) * vz,
        (h * wx * wz - wy) * vx + (h * wy * wz + wx) * vy + (e + h * wz * wz) * vz,
    );
    let opposite = L::V3::new(vx, -vy, -vz);
    select3::<L>(e.gt(L::splat(0.9997)), v, select3::<L>(e.lt(L::splat(-0.9997)), opposite, general))
}

/// `if m { a } else { b }` per lane, for three-component vectors.
#[inline]
pub fn select3<L: Lanes>(m: L::Mask, a: L::V3, b: L::V3) -> L::V3 {
    L::V3::new(L::select(m, a.x(), b.x()), L::select(m, a.y(), b.y()), L::select(m, a.z(), b.z()))
}
