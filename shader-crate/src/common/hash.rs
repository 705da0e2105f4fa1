//! Wyman–McGuire 2D hash (spec svao-raysd §7.3; Ray-SD paper §3.1).

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use crate::common::math::frac;

/// `frac(1e4·sin(17u + 0.1v)·(0.1 + |sin(13v + u)|))` ∈ [0, 1) (Wyman & McGuire, "Hashed Alpha
/// Testing", 2017; spec svao-raysd §7.3).
#[inline]
pub fn wyman_hash(u: f32, v: f32) -> f32 {
    frac(1.0e4 * (17.0 * u + 0.1 * v).sin() * (0.1 + (13.0 * v + u).sin().abs()))
}
