//! Float-as-uint ordering for the ray-interval atomics (spec svao-raysd §5, §16).

/// Bits of a non-negative float whose unsigned-integer order equals the float order.
/// Negative values, −0.0 and NaN map to the bits of +0.0 (spec svao-raysd §16: clamp before atomics).
#[inline]
pub fn ordered_bits(x: f32) -> u32 {
    if x > 0.0 { x.to_bits() } else { 0 }
}

/// Inverse of [`ordered_bits`] for values it produced.
#[inline]
pub fn from_ordered_bits(bits: u32) -> f32 {
    f32::from_bits(bits)
}

/// `rayMin` clear value: the bits of `FLT_MAX` (spec svao-raysd §6).
pub const RAY_MIN_CLEAR: u32 = 0x7F7F_FFFF;
/// `rayMax` clear value: 0, which also means "no SD sample requested" (spec svao-raysd §6).
pub const RAY_MAX_CLEAR: u32 = 0;
