//! Small scalar helpers that compile identically for SPIR-V and the CPU.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

/// `saturate(x)`: clamp to [0, 1]. NaN maps to 0.
#[inline]
pub fn sat(x: f32) -> f32 {
    clamp(x, 0.0, 1.0)
}

/// Clamp without `f32::clamp`'s panic path (rust-gpu friendly). NaN maps to `lo`.
#[inline]
pub fn clamp(x: f32, lo: f32, hi: f32) -> f32 {
    if x > lo { if x < hi { x } else { hi } } else { lo }
}

/// Fractional part `x − floor(x)` ∈ [0, 1) (HLSL `frac`).
#[inline]
pub fn frac(x: f32) -> f32 {
    x - floor(x)
}

/// `floor(x)`, bit for bit (−0 stays −0, NaN and ±∞ pass through). SPIR-V: `OpExtInst Floor`.
/// CPU without SSE4.1's `roundss` (the x86-64 baseline): `f32::floor` is an out-of-line libm
/// call, so truncate through `i32` instead, inline (every |x| ≥ 2²³ is already integral).
#[inline]
pub fn floor(x: f32) -> f32 {
    #[cfg(any(target_arch = "spirv", target_feature = "sse4.1", not(target_arch = "x86_64")))]
    {
        x.floor()
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
/// it may differ from `x·x` in the last bit).
#[inline]
pub fn pow(x: f32, p: f32) -> f32 {
    if p == 2.0 { x * x } else { x.powf(p) }
}

/// `ceil(x) = −floor(−x)`, bit for bit (see [`floor`]).
#[inline]
pub fn ceil(x: f32) -> f32 {
    -floor(-x)
}

/// Sign with `sign(0) = +1` (spec svao-raysd §1 octahedral codec, §4.2 `nz`).
#[inline]
pub fn sign_nonzero(x: f32) -> f32 {
    if x < 0.0 { -1.0 } else { 1.0 }
}

/// True for a usable linear depth: finite, positive and in front of the far plane.
#[inline]
pub fn is_valid_depth(d: f32, far: f32) -> bool {
    d > 0.0 && d < far
}

/// XeGTAO's `fastSqrt` (spec gtao-raymarch-hybrid §1.7): the float with bits
/// `0x1fbd1df5 + (bits(x) >> 1)`, for x ≥ 0.
#[inline]
pub fn fast_sqrt(x: f32) -> f32 {
    f32::from_bits(0x1fbd_1df5u32.wrapping_add(((x.to_bits() as i32) >> 1) as u32))
}

/// XeGTAO's `fastAcos` (spec §1.7) with its literal 7-digit constants:
/// `r = (−0.156583·|x| + 1.570796)·fastSqrt(1 − |x|)`, `π − r` for negative x.
#[inline]
#[allow(clippy::approx_constant)] // XeGTAO's literal constants, kept for parity (spec §1.7)
pub fn fast_acos(x: f32) -> f32 {
    let a = x.abs();
    let r = (-0.156_583 * a + 1.570_796) * fast_sqrt(1.0 - a);
    if x >= 0.0 { r } else { 3.141_593 - r }
}

/// `a + (b − a)·t` (HLSL `lerp`).
#[inline]
pub fn lerp(a: f32, b: f32, t: f32) -> f32 {
    a + (b - a) * t
}

/// Möller–Hughes minimal rotation taking unit `from` to unit `to`, applied to `v` (spec
/// gtao-raymarch-hybrid §2.6.5): identity when `from·to > 0.9997`; for near-opposite vectors
/// the rotation by π about `from`'s orthogonal x axis, `diag(1, −1, −1)` for `from = (0,0,−1)`
/// (spec §3.4 step 5).
#[inline]
pub fn rotate_minimal(from: crate::glam::Vec3, to: crate::glam::Vec3, v: crate::glam::Vec3) -> crate::glam::Vec3 {
    let e = from.dot(to);
    if e > 0.9997 {
        return v;
    }
    if e < -0.9997 {
        return crate::glam::vec3(v.x, -v.y, -v.z);
    }
    let w = from.cross(to);
    let h = 1.0 / (1.0 + e);
    crate::glam::vec3(
        (e + h * w.x * w.x) * v.x + (h * w.x * w.y - w.z) * v.y + (h * w.x * w.z + w.y) * v.z,
        (h * w.x * w.y + w.z) * v.x + (e + h * w.y * w.y) * v.y + (h * w.y * w.z - w.x) * v.z,
        (h * w.x * w.z - w.y) * v.x + (h * w.y * w.z + w.x) * v.y + (e + h * w.z * w.z) * v.z,
    )
}
