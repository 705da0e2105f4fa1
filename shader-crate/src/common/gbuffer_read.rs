//! Read access to the G-buffer (linear depth + encoded view-space face normal), the resource
//! trait every screen-space kernel is written against.

use crate::common::lanes::{LaneVec3, Lanes, row_major_index};
use crate::common::normal_codec::decode_normal_lanes;
use crate::glam::{UVec2, Vec3};

/// What a screen-space kernel reads per pixel (spec svao-raysd §1 inputs).
pub trait GBuffer {
    /// Linear view depth at pixel `p` (may be NaN/∞/0 for broken input; kernels sanitize).
    #[inline]
    fn linear_depth(&self, p: UVec2) -> f32 {
        self.linear_depth_lanes::<f32>(p)
    }
    /// Unit view-space face normal at pixel `p`.
    #[inline]
    fn view_normal(&self, p: UVec2) -> Vec3 {
        self.view_normal_lanes::<f32>(p)
    }
    /// [`Self::linear_depth`] at each lane's pixel.
    fn linear_depth_lanes<L: Lanes>(&self, p: L::U2) -> L;
    /// [`Self::view_normal`] at each lane's pixel.
    fn view_normal_lanes<L: Lanes>(&self, p: L::U2) -> L::V3;
}

/// `depth[y·width + x]` per lane: a row-major depth buffer's gather.
#[inline]
fn row_major_lanes<L: Lanes>(depth: &[f32], width: u32, p: L::U2) -> L {
    L::gather_index(depth, row_major_index::<L>(p, width))
}

/// The decoded G-buffer normals (row-major octahedral codes, [`decode_normal_lanes`]) at each
/// lane's pixel.
#[inline]
pub fn decoded_normals<L: Lanes>(normals: &[u32], width: u32, p: L::U2) -> L::V3 {
    decode_normal_lanes::<L>(L::gather_word(normals, row_major_index::<L>(p, width)))
}

/// The G-buffer as two row-major storage buffers of the full target: `f32` linear depth and
/// octahedral-encoded normals ([`crate::common::normal_codec`]).
pub struct GBufferSlices<'a> {
    pub depth: &'a [f32],
    pub normals: &'a [u32],
    pub width: u32,
}

impl GBuffer for GBufferSlices<'_> {
    #[inline]
    fn linear_depth_lanes<L: Lanes>(&self, p: L::U2) -> L {
        row_major_lanes(self.depth, self.width, p)
    }
    #[inline]
    fn view_normal_lanes<L: Lanes>(&self, p: L::U2) -> L::V3 {
        decoded_normals::<L>(self.normals, self.width, p)
    }
}

/// Depth alone, for passes that never read normals (the raster SD map's first-layer test).
pub struct DepthSlice<'a> {
    pub depth: &'a [f32],
    pub width: u32,
}

impl GBuffer for DepthSlice<'_> {
    #[inline]
    fn linear_depth_lanes<L: Lanes>(&self, p: L::U2) -> L {
        row_major_lanes(self.depth, self.width, p)
    }
    #[inline]
    fn view_normal_lanes<L: Lanes>(&self, _p: L::U2) -> L::V3 {
        L::V3::new(L::splat(0.0), L::splat(0.0), L::splat(1.0))
    }
}
