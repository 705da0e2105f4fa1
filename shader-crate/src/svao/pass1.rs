//! AO pass 1 (spec svao-raysd §5): VAO on the depth buffer, the per-sample refinement mask and,
//! for the SD map, the ray intervals through float-as-uint atomics.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use super::{Secondary, SvaoParams, unorm8};
use crate::common::atomics::AtomicU32Buffer;
use crate::common::float_order::ordered_bits;
use crate::common::gbuffer_read::GBuffer;
use crate::common::math::{clamp, sat};
use crate::glam::Vec3;
use crate::glam::{UVec2, Vec2};
use crate::vao::kernel::{
    KERNEL_HBAO, LineSample, PixelFrame, halo_visibility, hbao_occlusion, line_sample_of, object_z, setup_pixel,
    unoccluded_visibility,
};

/// Output of pass 1 for one pixel.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Pass1Pixel {
    /// Final AO when `mask == 0`; otherwise the un-exponentiated sum `A` as stored by a UNORM8
    /// target (spec §5), which pass 2 completes.
    pub ao: f32,
    /// Bit `i` set: sample `i` needs more depth.
    pub mask: u32,
}

/// "Requires more depth" (spec §4.4): the depth-buffer surface lies in front of the constant
/// area (VAO) or beyond `max(h, 0.1·R)` (HBAO+), and the sample is farther than the radius
/// cutoff on screen.
#[inline]
pub fn needs_refinement(z: f32, s: &LineSample, frame: &PixelFrame, params: &SvaoParams) -> bool {
    let threshold = if params.kernel == KERNEL_HBAO {
        s.half_chord.max(0.1 * frame.radius)
    } else {
        (1.0 + params.vao.thickness) * frame.radius
    };
    z > threshold && s.screen_distance > params.cutoff
}

/// Object-space z and visibility of sample `s` from the primary depth (spec §4.2–§4.3); with
/// dual depth (spec §11) a sample the first layer does not settle (it would need refinement)
/// also reads the depth-peeled second layer `depth2`, combined by min. Both AO passes call this,
/// so pass 2 subtracts exactly what pass 1 added — the reference's pass 2 skips the second layer
/// there, which breaks dual depth with a secondary source (spec §11 "Bug"); this is its fix.
#[inline]
pub fn primary_sample<G: GBuffer>(
    gbuffer: &G,
    depth2: &[f32],
    params: &SvaoParams,
    frame: &PixelFrame,
    s: &LineSample,
) -> (f32, f32) {
    let view = &params.vao.view;
    let (mut z, mut v) = depth_point_value(params, frame, s, texel_point(view, gbuffer.linear_depth(s.texel), s));
    if params.dual != 0 && needs_refinement(z, s, frame, params) {
        let (z2, v2) = depth_point_value(params, frame, s, texel_point(view, depth2[view.index(s.texel)], s));
        v = combine(params, v, v2);
        z = z.min(z2);
    }
    (z, v)
}

/// View point of the depth value `d` at the sample's raster texel (unusable depths read as far).
#[inline]
fn texel_point(view: &crate::common::ViewParams, d: f32, s: &LineSample) -> Vec3 {
    let d = if crate::common::math::is_valid_depth(d, view.far) { d } else { view.far };
    view.uv_to_view(view.texel_uv(s.texel), d)
}

/// Object-space z of a view point `d` and its per-sample value under the kernel: VAO
/// visibility (spec §4.3) or HBAO+ occlusion (spec §4.5, unclamped radius in the falloff).
#[inline]
pub fn depth_point_value(params: &SvaoParams, frame: &PixelFrame, s: &LineSample, d: Vec3) -> (f32, f32) {
    let z = object_z(frame, d);
    let value = if params.kernel == KERNEL_HBAO {
        hbao_occlusion(frame, s, d, params.vao.radius)
    } else {
        halo_visibility(z, s, frame.radius, params.vao.thickness)
    };
    (z, value)
}

/// Combine two depth points' values of one sample: min of visibility (VAO, spec §4.3) or max of
/// occlusion (HBAO+, spec §4.5).
#[inline]
pub fn combine(params: &SvaoParams, a: f32, b: f32) -> f32 {
    if params.kernel == KERNEL_HBAO { a.max(b) } else { a.min(b) }
}

/// A sample's value when nothing occludes it: the visible chord (VAO) or 0 (HBAO+); used for
/// same-pixel samples and for dropped out-of-screen ones (spec §4.2, §9).
#[inline]
pub fn unoccluded_value(params: &SvaoParams, s: &LineSample) -> f32 {
    if params.kernel == KERNEL_HBAO { 0.0 } else { unoccluded_visibility(s) }
}

/// Starting value of a dropped out-of-screen sample in pass 2 (spec §9): 1 (VAO, then min with
/// the SD values) or 0 (HBAO+, then max).
#[inline]
pub fn dropped_value(params: &SvaoParams) -> f32 {
    if params.kernel == KERNEL_HBAO { 0.0 } else { 1.0 }
}

/// The pixel accumulator from the samples' values: `A = (2/N)·Σv` (VAO, spec §4.3) or
/// `mean = (1/N)·Σo` (HBAO+, spec §4.5), `N` = 8, 16 or 32 samples; what pass 1 stores for
/// flagged pixels.
#[inline]
pub fn accumulate(params: &SvaoParams, sum: f32) -> f32 {
    let scale = if params.kernel == KERNEL_HBAO { 1.0 } else { 2.0 };
    scale / params.samples() as f32 * sum
}

/// Final AO from the accumulator: `sat(A)^exponent` (VAO) or `sat(1 − 2·mean)^exponent`
/// (HBAO+, spec §4.5).
#[inline]
pub fn finish(params: &SvaoParams, a: f32) -> f32 {
    let base = if params.kernel == KERNEL_HBAO { 1.0 - 2.0 * a } else { a };
    sat(base).powf(params.vao.exponent)
}

/// SD texel of an (unsnapped, unclamped) uv: `clamp(floor(uv·L) + sg, 0, L + 2sg − 1)` per axis
/// (spec §5 `SDpixel`).
#[inline]
pub fn sd_pixel(uv: Vec2, params: &SvaoParams) -> UVec2 {
    let low = params.sd_low_res.as_vec2();
    let sg = params.sd_guard as f32;
    let hi = params.sd_size() - 1;
    let x = clamp((uv.x * low.x).floor() + sg, 0.0, hi.x as f32);
    let y = clamp((uv.y * low.y).floor() + sg, 0.0, hi.y as f32);
    UVec2::new(x as u32, y as u32)
}

/// AO pass 1 of pixel `p` (spec §5; `depth2`: the second layer, read only with dual depth).
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
    let view = &vao.view;
    let frame = match setup_pixel(gbuffer, view, vao.radius, vao.max_screen_radius, p) {
        Some(f) => f,
        None => return Pass1Pixel { ao: 1.0, mask: 0 },
    };
    let sd = params.secondary == Secondary::StochasticDepth as u32;
    let traced = params.secondary == Secondary::Raytraced as u32;
    let distance = frame.position.length();
    let samples = params.samples();
    let mut sum = 0.0;
    let mut mask = 0u32;
    let mut i = 0;
    while i < samples {
        let s = line_sample_of(&frame, view, i, samples, params.kernel);
        if s.valid {
            if s.same_pixel {
                sum += unoccluded_value(params, &s);
            } else {
                let (mut z, v) = primary_sample(gbuffer, depth2, params, &frame, &s);
                sum += v;
                // Out-of-screen samples are always refined: Ray-SVAO traces them, the SD map
                // covers them with its guard band (spec §5 "force").
                let force = !s.in_screen && (traced || (sd && params.sd_guard > 0));
                if force && sd {
                    z = f32::MAX;
                }
                if params.secondary != Secondary::Disabled as u32 && (force || needs_refinement(z, &s, &frame, params))
                {
                    mask |= 1 << i;
                    if sd {
                        let q = params.sd_index(sd_pixel(s.uv, params));
                        if params.interval != 0 {
                            // Euclidean camera distances `|P| − z` (spec §5, uncorrected).
                            let far_end = if params.kernel == KERNEL_HBAO {
                                z.min(s.half_chord)
                            } else {
                                z.min((1.0 + vao.thickness) * frame.radius + s.half_chord)
                            };
                            ray_min.atomic_min(q, ordered_bits(distance - far_end));
                            ray_max.atomic_max(q, ordered_bits(distance - s.sphere_end));
                        } else {
                            ray_max.atomic_max(q, 1);
                        }
                    }
                }
            }
        }
        i += 1;
    }
    let a = accumulate(params, sum);
    if mask == 0 { Pass1Pixel { ao: finish(params, a), mask } } else { Pass1Pixel { ao: unorm8(a), mask } }
}
