//! AO pass 2 (spec svao-raysd §9, §10): refine the samples flagged in pass 1 from a secondary
//! depth source and finish the pixel.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use super::SvaoParams;
use crate::common::gbuffer_read::GBuffer;
use crate::glam::UVec2;
use crate::vao::kernel::{LineSample, PixelFrame, line_sample_of, setup_pixel};

/// A flagged sample's refined visibility and the rays traced for it.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Refined {
    pub v: f32,
    pub rays: u32,
}

/// A secondary depth source: the SD map (spec svao-raysd §9) or traced rays (spec svao-raysd §10).
pub trait Refine {
    /// Value of flagged sample `s` given its starting value `v` (the primary-depth value in
    /// screen; for a dropped out-of-screen sample 1 with VAO, 0 with HBAO+) and the primary
    /// depth's object-space `z_primary`. Sources combine with the kernel's `combine`: `min` of
    /// visibility for VAO (spec svao-raysd §4.3 `a_i = min_j a_ij`), `max` of occlusion for HBAO+ (svao-raysd §4.5).
    fn refine(&mut self, frame: &PixelFrame, s: &LineSample, v: f32, z_primary: f32) -> Refined;
}

/// A pixel after pass 2, and the rays its refinements traced.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Pass2Pixel {
    pub ao: f32,
    pub rays: u32,
}

/// AO pass 2 of pixel `p` (spec svao-raysd §9): for every flagged sample, subtract its pass-1 (primary)
/// visibility and add the refined one; `A = AO_stored + (2/N)·Δ`, clamped to [0, 1] before the
/// exponent (spec svao-raysd §9: `A` may dip below 0 through the UNORM8 store). Pixels without flags keep
/// their pass-1 value.
#[inline]
pub fn pass2_pixel<G: GBuffer, R: Refine>(
    gbuffer: &G,
    depth2: &[f32],
    params: &SvaoParams,
    p: UVec2,
    stored: f32,
    mask: u32,
    source: &mut R,
) -> Pass2Pixel {
    let unchanged = Pass2Pixel { ao: stored, rays: 0 };
    if mask == 0 {
        return unchanged;
    }
    let vao = &params.vao;
    let view = &vao.view;
    let frame = match setup_pixel(gbuffer, view, vao.radius, vao.max_screen_radius, p) {
        Some(f) => f,
        None => return unchanged,
    };
    let samples = params.samples();
    let (mut delta, mut rays) = (0.0, 0);
    let mut i = 0;
    while i < samples {
        if mask & (1 << i) != 0 {
            let s = line_sample_of(&frame, view, i, samples, params.kernel);
            let (z, v) = super::primary_sample(gbuffer, depth2, params, &frame, &s);
            delta -= v;
            // Out of screen the clamped border texel is dropped (spec svao-raysd §9, §15.8).
            let start = if s.in_screen { v } else { super::pass1::dropped_value(params) };
            let refined = source.refine(&frame, &s, start, z);
            delta += refined.v;
            rays += refined.rays;
        }
        i += 1;
    }
    Pass2Pixel { ao: super::pass1::finish(params, stored + super::pass1::accumulate(params, delta)), rays }
}
