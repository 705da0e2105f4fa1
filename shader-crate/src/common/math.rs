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
    x - x.floor()
}

/// Sign with `sign(0) = +1` (spec §1 octahedral codec, §4.2 `nz`).
#[inline]
pub fn sign_nonzero(x: f32) -> f32 {
    if x < 0.0 { -1.0 } else { 1.0 }
}

/// True for a usable linear depth: finite, positive and in front of the far plane.
#[inline]
pub fn is_valid_depth(d: f32, far: f32) -> bool {
    d > 0.0 && d < far
}
