//! Screen-space helpers shared by the techniques that read depth buffers (XeGTAO, the ray
//! march, the hybrid): clamp-to-edge indexing and XeGTAO's +z-forward view position (spec
//! gtao-raymarch-hybrid §1.4–§1.5).

use crate::common::ViewParams;
use crate::common::lanes::{LaneVec2, LaneVec3, Lanes};
use crate::common::math::{f32_to_u32, u32_to_f32};
use crate::glam::UVec2;

/// `clamp(v, 0, n − 1)` of a float coordinate as an index (NaN → 0), branch-free: the float
/// is clamped first by compares and selects (a NaN fails `v > 0`), so the conversion needs no
/// saturation ([`f32_to_u32`]: on SPIR-V no conversion instruction at all, not Rust's
/// saturating cast with its compares and selects). `n` ≤ 2²³.
#[inline]
pub fn clamp_index(v: f32, n: u32) -> u32 {
    f32_to_u32(v.clamp_between(0.0, u32_to_f32(n - 1)))
}

/// `viewPos(uv, z) = ((2u−1)·tanX·z, (1−2v)·tanY·z, z)` in XeGTAO's +z-forward view space
/// (spec gtao-raymarch-hybrid §1.4).
#[inline]
pub fn view_pos<L: Lanes>(view: &ViewParams, uv: L::V2, z: L) -> L::V3 {
    L::V3::new((uv.x() * 2.0 - 1.0) * view.tan_half_fov.x * z, (-(uv.y() * 2.0) + 1.0) * view.tan_half_fov.y * z, z)
}

/// Pixel `p` clamped into the full target after adding `(dx, dy)` (clamp-to-edge reads).
#[inline]
pub fn neighbour(p: UVec2, dx: i32, dy: i32, size: UVec2) -> UVec2 {
    neighbour_lanes::<f32>(p, dx, dy, size)
}

/// [`neighbour`] per lane.
#[inline]
pub fn neighbour_lanes<L: Lanes>(p: L::U2, dx: i32, dy: i32, size: UVec2) -> L::U2 {
    L::texel(L::index_offset_clamped(L::texel_x(p), dx, size.x), L::index_offset_clamped(L::texel_y(p), dy, size.y))
}

/// `data[p.y·width + p.x]` per lane, for buffers of words (AO terms, packed edges).
#[inline]
pub fn word_at<L: Lanes>(data: &[u32], width: u32, p: L::U2) -> L::Index {
    L::gather_word(data, crate::common::lanes::row_major_index::<L>(p, width))
}
