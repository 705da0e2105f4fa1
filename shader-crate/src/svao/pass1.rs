//! AO pass 1 (spec svao-raysd §5): VAO on the depth buffer, the per-sample refinement mask and,
//! for the SD map, the ray intervals through float-as-uint atomics.

// f32 methods on SPIR-V (`floor`, `powf`, `min`, `max`, `sqrt`) come from `Lanes`.
use super::{Secondary, SvaoParams, unorm8};
use crate::common::atomics::AtomicU32Buffer;
use crate::common::float_order::ordered_bits;
use crate::common::gbuffer_read::GBuffer;
use crate::common::lanes::{LaneVec2, Lanes};
use crate::common::math::sat;
use crate::glam::{UVec2, Vec2};
use crate::vao::kernel::{
    KERNEL_HBAO, LineSample, PixelFrame, halo_visibility, hbao_occlusion, line_sample_of, object_z, setup_pixel,
    texel_point, unoccluded_visibility,
};

/// Output of pass 1 for one pixel.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Pass1Pixel {
    /// Final AO when `mask == 0`; otherwise the un-exponentiated sum `A` as stored by a UNORM8
    /// target (spec svao-raysd §5), which pass 2 completes.
    pub ao: f32,
    /// Bit `i` set: sample `i` needs more depth.
    pub mask: u32,
}

/// "Requires more depth" (spec svao-raysd §4.4): the depth-buffer surface lies in front of the constant
/// area (VAO) or beyond `max(h, 0.1·R)` (HBAO+), and the sample is farther than the radius
/// cutoff on screen.
#[inline]
pub fn needs_refinement<L: Lanes>(z: L, s: &LineSample<L>, frame: &PixelFrame<L>, params: &SvaoParams) -> L::Mask {
    let threshold = if params.kernel == KERNEL_HBAO {
        s.half_chord.max(frame.radius * 0.1)
    } else {
        frame.radius * (1.0 + params.vao.thickness)
    };
    L::and(z.gt(threshold), s.screen_distance.gt(L::splat(params.cutoff)))
}

/// Object-space z and visibility of sample `s` from the primary depth (spec svao-raysd §4.2–§4.3); with
/// dual depth (spec svao-raysd §11) a sample the first layer does not settle (it would need refinement)
/// also reads the depth-peeled second layer `depth2`, combined by min. Both AO passes call this,
/// so pass 2 subtracts exactly what pass 1 added — the reference's pass 2 skips the second layer
/// there, which breaks dual depth with a secondary source (spec svao-raysd §11 "Bug"); this is its fix.
#[inline]
pub fn primary_sample<G: GBuffer, L: Lanes>(
    gbuffer: &G,
    depth2: &[f32],
    params: &SvaoParams,
    frame: &PixelFrame<L>,
    s: &LineSample<L>,
) -> (L, L) {
    let view = &params.vao.view;
    let (z, v) = depth_point_value(params, frame, s, texel_point(view, gbuffer.linear_depth_lanes::<L>(s.texel), s));
    if params.dual == 0 {
        return (z, v);
    }
    let second = needs_refinement(z, s, frame, params);
    let d2 = L::gather_index(depth2, view.index_lanes::<L>(s.texel));
    let (z2, v2) = depth_point_value(params, frame, s, texel_point(view, d2, s));
    (L::select(second, z.min(z2), z), L::select(second, combine(params, v, v2), v))
}

/// Object-space z of a view point `d` and its per-sample value under the kernel: VAO
/// visibility (spec svao-raysd §4.3) or HBAO+ occlusion (spec svao-raysd §4.5, unclamped radius in the falloff).
#[inline]
pub fn depth_point_value<L: Lanes>(params: &SvaoParams, frame: &PixelFrame<L>, s: &LineSample<L>, d: L::V3) -> (L, L) {
    let z = object_z(frame, d);
    let value = if params.kernel == KERNEL_HBAO {
        hbao_occlusion(frame, s, d, params.vao.radius)
    } else {
        halo_visibility(z, s, frame.radius, params.vao.thickness)
    };
    (z, value)
}

/// Combine two depth points' values of one sample: min of visibility (VAO, spec svao-raysd §4.3) or max of
/// occlusion (HBAO+, spec svao-raysd §4.5).
#[inline]
pub fn combine<L: Lanes>(params: &SvaoParams, a: L, b: L) -> L {
    if params.kernel == KERNEL_HBAO { a.max(b) } else { a.min(b) }
}

/// A sample's value when nothing occludes it: the visible chord (VAO) or 0 (HBAO+); used for
/// same-pixel samples and for dropped out-of-screen ones (spec svao-raysd §4.2, §9).
#[inline]
pub fn unoccluded_value<L: Lanes>(params: &SvaoParams, s: &LineSample<L>) -> L {
    if params.kernel == KERNEL_HBAO { L::splat(0.0) } else { unoccluded_visibility(s) }
}

/// Starting value of a dropped out-of-screen sample in pass 2 (spec svao-raysd §9): 1 (VAO, then min with
/// the SD values) or 0 (HBAO+, then max).
#[inline]
pub fn dropped_value(params: &SvaoParams) -> f32 {
    if params.kernel == KERNEL_HBAO { 0.0 } else { 1.0 }
}

/// The pixel accumulator from the samples' values: `A = (2/N)·Σv` (VAO, spec svao-raysd §4.3) or
/// `mean = (1/N)·Σo` (HBAO+, spec svao-raysd §4.5), `N` = 8, 16 or 32 samples; what pass 1 stores for
/// flagged pixels.
#[inline]
pub fn accumulate(params: &SvaoParams, sum: f32) -> f32 {
    let scale = if params.kernel == KERNEL_HBAO { 1.0 } else { 2.0 };
    scale / params.samples() as f32 * sum
}

/// Final AO from the accumulator: `sat(A)^exponent` (VAO) or `sat(1 − 2·mean)^exponent`
/// (HBAO+, spec svao-raysd §4.5).
#[inline]
pub fn finish(params: &SvaoParams, a: f32) -> f32 {
    let base = if params.kernel == KERNEL_HBAO { 1.0 - 2.0 * a } else { a };
    sat(base).powf(params.vao.exponent)
}

/// SD texel of an (unsnapped, unclamped) uv: `clamp(floor(uv·L) + sg, 0, L + 2sg − 1)` per axis
/// (spec svao-raysd §5 `SDpixel`).
#[inline]
pub fn sd_pixel(uv: Vec2, params: &SvaoParams) -> UVec2 {
    let (x, y) = sd_pixel_lanes::<f32>(uv, params);
    UVec2::new(x, y)
}

/// [`sd_pixel`] per lane: `(x, y)`.
#[inline]
pub fn sd_pixel_lanes<L: Lanes>(uv: L::V2, params: &SvaoParams) -> (L::Index, L::Index) {
    let low = params.sd_low_res.as_vec2();
    let sg = params.sd_guard as f32;
    let size = params.sd_size();
    // floor_index clamps to [0, n − 1] and converts: SDpixel's clamp, bit for bit.
    let x = ((uv.x() * low.x).floor() + sg).floor_index(L::index_splat(size.x));
    let y = ((uv.y() * low.y).floor() + sg).floor_index(L::index_splat(size.y));
    (x, y)
}

/// AO pass 1 of pixel `p` (spec svao-raysd §5; `depth2`: the second layer, read only with dual depth).
/// `ray_min`/`ray_max` are the SD-size interval buffers
/// (only touched for [`Secondary::StochasticDepth`]); they must be cleared to
/// `RAY_MIN_CLEAR`/`RAY_MAX_CLEAR` before the pass.
#[inline]
pub fn pass1_pixel<G: GBuffer, A: AtomicU32Buffer, B: AtomicU32Buffer>(
    gbuffer: &G,
    depth2: &[f32],
    params: &SvaoParams,
    p: UVec2,
    ray_min: &mut A,
    ray_max: &mut B,
) -> Pass1Pixel {
    let vao = &params.vao;
    let frame = match setup_pixel(gbuffer, &vao.view, vao.radius, vao.max_screen_radius, p) {
        Some(f) => f,
        None => return Pass1Pixel { ao: 1.0, mask: 0 },
    };
    let distance = frame.position.length();
    let mut sum = 0.0;
    let mut mask = 0u32;
    let mut i = 0;
    while i < params.samples() {
        let r = pass1_sample(gbuffer, depth2, params, &frame, i);
        sum += r.value;
        if r.flagged {
            mask |= 1 << i;
            let s = &r.sample;
            record_interval(params, s.uv, r.z, s.half_chord, s.sphere_end, frame.radius, distance, ray_min, ray_max);
        }
        i += 1;
    }
    pass1_finish(params, sum, mask)
}

/// What pass 1 learns from sample `i` of one pixel or of `L::LANES` pixels (spec svao-raysd §5).
#[derive(Copy, Clone)]
pub struct Pass1Sample<L: Lanes = f32> {
    pub sample: LineSample<L>,
    /// Its term of the sum: the primary-depth value, the unoccluded value in the pixel itself,
    /// 0 when invalid.
    pub value: L,
    /// Object-space z of the primary depth (`f32::MAX` for a forced out-of-screen sample with
    /// the SD map).
    pub z: L,
    /// The sample needs more depth (a refinement-mask bit).
    pub flagged: L::Mask,
}

/// Sample `i` of pass 1 (spec svao-raysd §5): its value, and whether it is flagged. Out-of-screen samples
/// are always refined: Ray-SVAO traces them, the SD map covers them with its guard band (spec
/// svao-raysd §5 "force").
#[inline]
pub fn pass1_sample<G: GBuffer, L: Lanes>(
    gbuffer: &G,
    depth2: &[f32],
    params: &SvaoParams,
    frame: &PixelFrame<L>,
    i: u32,
) -> Pass1Sample<L> {
    let sd = params.secondary == Secondary::StochasticDepth as u32;
    let traced = params.secondary == Secondary::Raytraced as u32;
    let zero = L::splat(0.0);
    let s = line_sample_of(frame, &params.vao.view, i, params.samples(), params.kernel);
    let (z, v) = primary_sample(gbuffer, depth2, params, frame, &s);
    let value = L::select(s.valid, L::select(s.same_pixel, unoccluded_value(params, &s), v), zero);
    let force = L::and(L::not(s.in_screen), L::mask_splat(traced || (sd && params.sd_guard > 0)));
    let z = if sd { L::select(force, L::splat(f32::MAX), z) } else { z };
    let refine = L::and(
        L::mask_splat(params.secondary != Secondary::Disabled as u32),
        L::or(force, needs_refinement(z, &s, frame, params)),
    );
    let flagged = L::and(L::and(s.valid, L::not(s.same_pixel)), refine);
    Pass1Sample { sample: s, value, z, flagged }
}

/// A flagged sample's share of the SD map's ray interval at its SD texel (spec svao-raysd §5): with
/// intervals, the Euclidean camera distances `|P| − z` of the sample's far end and `|P| − end`
/// of its near end by atomic min / max (uncorrected); without, the texel is just marked.
/// Nothing for other secondary sources.
#[inline]
#[allow(clippy::too_many_arguments)]
pub fn record_interval<A: AtomicU32Buffer, B: AtomicU32Buffer>(
    params: &SvaoParams,
    uv: Vec2,
    z: f32,
    half_chord: f32,
    sphere_end: f32,
    radius: f32,
    distance: f32,
    ray_min: &mut A,
    ray_max: &mut B,
) {
    if params.secondary != Secondary::StochasticDepth as u32 {
        return;
    }
    let q = params.sd_index(sd_pixel(uv, params));
    if params.interval != 0 {
        let far_end = if params.kernel == KERNEL_HBAO {
            z.min(half_chord)
        } else {
            z.min((1.0 + params.vao.thickness) * radius + half_chord)
        };
        ray_min.atomic_min(q, ordered_bits(distance - far_end));
        ray_max.atomic_max(q, ordered_bits(distance - sphere_end));
    } else {
        ray_max.atomic_max(q, 1);
    }
}

/// A pixel's pass-1 output from its sum and mask: final AO when nothing is flagged, else the
/// accumulator as stored by a UNORM8 target (spec svao-raysd §5).
#[inline]
pub fn pass1_finish(params: &SvaoParams, sum: f32, mask: u32) -> Pass1Pixel {
    let a = accumulate(params, sum);
    if mask == 0 { Pass1Pixel { ao: finish(params, a), mask } } else { Pass1Pixel { ao: unorm8(a), mask } }
}
