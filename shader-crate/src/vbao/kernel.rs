//! VBAO's main pass per pixel (spec vbao §1–§4): XeGTAO's pixel set-up, slice frames and sample
//! positions (`crate::gtao::main_pass`), then per slice one mask of [`SECTORS`] angular
//! sectors over the half-circle around the projected normal, filled by every sample's
//! front–back interval, and the visible fraction of the mask.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use super::{RULE_TOUCH, VbaoParams, WEIGHT_COSINE_BLENDER, WEIGHT_COSINE_EXACT};
use crate::common::denoise_terms::store_term;
use crate::common::lanes::{LaneVec3, Lanes};
use crate::common::math::{ceil, clamp, precise_acos, sat, u32_to_f32};
use crate::glam::UVec2;
use crate::gtao::GtaoPixel;
use crate::gtao::main_pass::{
    PixelSetup, SliceFrame, arc_integral, final_visibility, pixel_setup, projected_length_fudge, sample_pair,
    slice_frame,
};

/// Sectors per slice mask, N (spec vbao §3: the paper and every public implementation but
/// Bevy's).
pub const SECTORS: u32 = 32;

/// The sectors of the interval `[lo, hi]` of the half-circle (both in [0, 1]) as mask bits
/// (spec vbao §3). `RULE_PAPER`: start = ⌊N·lo⌋, count = ⌈N·(hi − lo)⌉, bits =
/// `((1 ≪ count) − 1) ≪ start` with shifts of 32 or more giving 0 (count ≥ 32: every bit from
/// start). `RULE_TOUCH`: bits `[⌊N·lo⌋, min(⌈N·hi⌉, N))` when hi > lo.
#[inline]
pub fn sector_bits(lo: f32, hi: f32, rule: u32) -> u32 {
    sector_bits_lanes::<f32>(lo, hi, rule)
}

/// [`sector_bits`] per lane: start and count as whole floats (exact up to N), then the run of
/// bits ([`Lanes::index_bit_run`]: shifts of 32 or more give 0).
#[inline]
pub fn sector_bits_lanes<L: Lanes>(lo: L, hi: L, rule: u32) -> L::Index {
    let n = SECTORS as f32;
    let start = (lo * n).floor();
    let count = if rule == RULE_TOUCH {
        let end = ceil(hi * n).min(L::splat(n));
        L::select(hi.le(lo), L::splat(0.0), (end - start).max(L::splat(0.0)))
    } else {
        ceil((hi - lo) * n)
    };
    let whole = L::index_splat(SECTORS + 1);
    L::index_bit_run(start.floor_index(whole), count.floor_index(whole))
}

/// \[aokit\] Samples within this angle (radians) of the hemisphere's edge count as on it: every
/// angle is shifted by it toward the edge before the sectors are taken. The G-buffer's snorm8
/// octahedral normal is off by up to 0.0166 rad (measured over 400 000 random normals), so
/// flat ground rises up to that far into the half-circle and, with ⌈·⌉, sets a sector in about
/// every other slice side (spec vbao §5, artefact 1; Blender's angle bias does the same job by
/// scaling). 0.02 rad is 0.2 of a sector; in a slice whose projected normal has length L the
/// error, and the tolerance, is up to 1/L times larger.
pub const EDGE_TOLERANCE: f32 = 0.02;

/// The tolerance's cap for slices nearly perpendicular to the normal (small L): 2 sectors.
pub const MAX_EDGE_TOLERANCE: f32 = 2.0 * core::f32::consts::PI / SECTORS as f32;

/// Position of a slice angle θ on the half-circle around the projected normal at γ,
/// `x = clamp((θ − γ + π/2)/π, 0, 1)`: 0 is the edge on side 1, 1 the edge on side 0 (spec
/// vbao §2.4). Evaluated with the product by 1/π, not a division.
#[inline]
pub fn sector_coordinate<L: Lanes>(theta: L, gamma: L) -> L {
    sat((theta - gamma + core::f32::consts::FRAC_PI_2) * core::f32::consts::FRAC_1_PI)
}

/// The mask bits of one depth sample `delta_f = Q − P` on the slice side with sign `side` (+1
/// for side 0, −1 for side 1), spec vbao §2: the front angle, and the back angle of the sample
/// pushed `thickness` away from the camera along the centre pixel's view vector `v`, mapped to
/// the half-circle around the normal `n` and ordered into `[lo, hi]` (precise acos, spec vbao
/// §2.3 \[OWN\]).
///
/// \[aokit\] Each sample is measured in its own slice, the plane through v and the sample, with
/// that plane's projected normal (γ'), then placed on the nominal slice's half-circle: XeGTAO
/// rounds sample offsets to whole pixels, which turns the first steps' directions by up to 45°
/// off the nominal slice, and measured against the nominal slice's γ a sample on flat ground
/// then lies up to a quarter of the half-circle inside it (measured: 0.24 rad), setting
/// sectors on every plane (the spec's plane test, vbao §6.2). The sources use the nominal slice.
/// For a sample on the nominal slice both are the same.
#[inline]
pub fn sample_bits<L: Lanes>(delta_f: L::V3, v: L::V3, n: L::V3, side: f32, thickness: f32, rule: u32) -> L::Index {
    let own = own_slice::<L>(delta_f, v, n);
    interval_bits(&own, delta_f, delta_f - v * L::splat(thickness), v, side, rule)
}

/// A depth sample's own slice (see [`sample_bits`]): the plane through v and the sample, its
/// projected normal's signed angle γ' and the edge tolerance for that slice.
#[derive(Copy, Clone)]
pub struct OwnSlice<L: Lanes> {
    gamma: L,
    tolerance: L,
    /// The sample lies on the view ray: it has no own slice and sets no sector.
    degenerate: L::Mask,
}

/// The own slice of the sample `delta_f = Q − P` (spec vbao §2.3, see [`sample_bits`]).
#[inline]
pub fn own_slice<L: Lanes>(delta_f: L::V3, v: L::V3, n: L::V3) -> OwnSlice<L> {
    let zero = L::splat(0.0);
    // The sample's own slice: toward the sample across v, and that slice's projected normal.
    let toward = delta_f - v * delta_f.dot(v);
    // The normal minus its component along the slice's axis c = toward × v, with c unnormalised:
    // n − c·(n·c)/(c·c) (one division, no square root).
    let axis = toward.cross(v);
    let projected = n - axis * (n.dot(axis) / axis.dot(axis));
    let inv_len = projected.dot(projected).inverse_sqrt();
    let cos_n = sat(projected.dot(v) * inv_len);
    let angle = precise_acos(cos_n);
    let gamma = L::select(toward.dot(projected).lt(zero), -angle, angle);
    // A normal off by ε turns the slice's projected normal by up to ε/L.
    let tolerance = (inv_len * EDGE_TOLERANCE).min(L::splat(MAX_EDGE_TOLERANCE));
    // No own slice for a sample on the view ray (|toward|² = 0).
    OwnSlice { gamma, tolerance, degenerate: toward.dot(toward).le(zero) }
}

/// The mask bits of the occupied segment from `delta_a` to `delta_b` (both relative to P, both
/// in the sample's own slice `own`) on the slice side with sign `side` (spec vbao §2.2–§3): the
/// two angles mapped to the half-circle and ordered into `[lo, hi]`.
#[inline]
pub fn interval_bits<L: Lanes>(
    own: &OwnSlice<L>,
    delta_a: L::V3,
    delta_b: L::V3,
    v: L::V3,
    side: f32,
    rule: u32,
) -> L::Index {
    let x_f = sector_coordinate(angle_to::<L>(delta_a, v) + own.tolerance, own.gamma);
    let x_b = sector_coordinate(angle_to::<L>(delta_b, v) + own.tolerance, own.gamma);
    // In the own slice the sample's side is side 0; on the nominal side 1 that is mirrored.
    let (x_f, x_b) = if side > 0.0 { (x_f, x_b) } else { (-x_f + 1.0, -x_b + 1.0) };
    let bits = sector_bits_lanes(x_f.min(x_b), x_f.max(x_b), rule);
    L::index_select(own.degenerate, L::index_splat(0), bits)
}

/// The angle between `delta` and the unit vector `v` ([`precise_acos`]).
#[inline]
fn angle_to<L: Lanes>(delta: L::V3, v: L::V3) -> L {
    precise_acos(clamp(delta.dot(v) * delta.dot(delta).inverse_sqrt(), -1.0, 1.0))
}

/// The signed cosine-weighted arc from 0 to θ, `A(θ) = sgn(θ)·a(θ)` with XeGTAO's `a`: an
/// antiderivative of `cos(θ − γ)·|sin θ|` (spec vbao §4, `CosineExact`).
#[inline]
fn signed_arc<L: Lanes>(theta: L, gamma: L, cos_n: L) -> L {
    let a = arc_integral(theta, gamma, cos_n);
    L::select(theta.lt(L::splat(0.0)), -a, a)
}

/// `Σ_{i∉M} w_i` with `w_i = A(upper_i) − A(lower_i)` over sector i's angles
/// `[γ − π/2 + iπ/N, γ − π/2 + (i+1)π/N]` (spec vbao §4, `CosineExact`).
#[inline]
fn free_cosine_weight<L: Lanes>(mask: L::Index, gamma: L, cos_n: L) -> L {
    let width = core::f32::consts::PI / SECTORS as f32;
    let edge = gamma - core::f32::consts::FRAC_PI_2;
    let mut lower = signed_arc(edge, gamma, cos_n);
    let mut sum = L::splat(0.0);
    let mut i = 0;
    while i < SECTORS {
        let upper = signed_arc(edge + u32_to_f32(i + 1) * width, gamma, cos_n);
        let free = L::index_eq((mask >> i) & L::index_splat(1), L::index_splat(0));
        sum = L::select(free, sum + (upper - lower), sum);
        lower = upper;
        i += 1;
    }
    sum
}

/// Blender's cosine sector weights (spec vbao §4, `CosineBlender`): four mirror-symmetric
/// groups of bits with per-bit weights `cos α_i·π/(2N)`, α_i the sector centre's angle from n.
const BLENDER_GROUPS: [(u32, f32); 4] =
    [(0xF000_000F, 0.009_506_1), (0x0F00_00F0, 0.027_095_1), (0x00F0_0F00, 0.040_557_1), (0x000F_F000, 0.047_842_1)];

/// `clamp(1 − Σ_k popcount(M & mask_k)·w_k, 0, 1)` (spec vbao §4, `CosineBlender`).
#[inline]
fn blender_visibility<L: Lanes>(mask: L::Index) -> L {
    let mut occluded = L::splat(0.0);
    let mut k = 0;
    while k < 4 {
        let (group, w) = BLENDER_GROUPS[k];
        occluded = occluded + set_sectors::<L>(mask, group) * w;
        k += 1;
    }
    sat(-occluded + 1.0)
}

/// The number of sectors of `mask` within `group`, per lane.
#[inline]
fn set_sectors<L: Lanes>(mask: L::Index, group: u32) -> L {
    L::from_lanes(move |k| u32_to_f32((L::index_lane(mask, k) & group).count_ones()))
}

/// Where the occupied segments behind a depth sample come from: `vbao`'s constant thickness
/// ([`ConstantThickness`]) or `vbao-sd`'s stochastic-depth layers (`crate::vbaosd`).
pub trait Occupancy<L: Lanes> {
    /// The mask bits of sample `delta = Q − P` on the slice side with sign `side`.
    fn bits(&mut self, params: &VbaoParams, delta: L::V3, px: &PixelSetup<L>, side: f32) -> L::Index;
}

/// Every sample is a slab of the constant thickness T behind it (spec vbao §2.2), gated by R_g.
pub struct ConstantThickness;

impl<L: Lanes> Occupancy<L> for ConstantThickness {
    #[inline]
    fn bits(&mut self, params: &VbaoParams, delta: L::V3, px: &PixelSetup<L>, side: f32) -> L::Index {
        gated_bits(params, delta, px, side)
    }
}

/// One slice's mask: both sides' samples OR-ed into it (spec vbao §2–§3).
#[inline]
fn slice_mask<L: Lanes, O: Occupancy<L>>(
    params: &VbaoParams,
    mips: &[f32],
    px: &PixelSetup<L>,
    sl: &SliceFrame<L>,
    s: u32,
    occupancy: &mut O,
) -> L::Index {
    let g = &params.gtao;
    let steps = g.steps.max(1);
    let mut mask = L::index_splat(0);
    let mut k = 0;
    while k < steps {
        let (q0, q1) = sample_pair(g, mips, px, sl, s, k);
        mask = mask | occupancy.bits(params, q0 - px.pos, px, 1.0);
        mask = mask | occupancy.bits(params, q1 - px.pos, px, -1.0);
        k += 1;
    }
    mask
}

/// Does the point `delta` (relative to P) lie beyond the gate radius R_g (spec vbao §2.1)?
/// |Δ| > R_g as |Δ|² > R_g², no square root; never without a gate (R_g = 0).
#[inline]
pub fn beyond_gate<L: Lanes>(params: &VbaoParams, delta: L::V3) -> L::Mask {
    let gate = params.gate_radius;
    if gate > 0.0 { delta.dot(delta).gt(L::splat(gate * gate)) } else { L::mask_splat(false) }
}

/// [`sample_bits`] unless the sample lies beyond the gate radius R_g (spec vbao §2.1; no
/// falloff).
#[inline]
pub fn gated_bits<L: Lanes>(params: &VbaoParams, delta: L::V3, px: &PixelSetup<L>, side: f32) -> L::Index {
    let beyond = beyond_gate::<L>(params, delta);
    // Skip the sample's arithmetic when no lane needs it (always, for one pixel beyond R_g).
    if !L::any(L::not(beyond)) {
        return L::index_splat(0);
    }
    let bits = sample_bits::<L>(delta, px.v, px.n, side, params.thickness, params.sector_rule);
    L::index_select(beyond, L::index_splat(0), bits)
}

/// VBAO's main pass for pixel `p` (spec vbao §1–§4): the visibility of every slice's mask
/// under the chosen weighting, averaged, raised to FinalValuePower, clamped at 0.03 and
/// stored as XeGTAO's term with its edges. Background pixels get visibility 1 (as XeGTAO).
#[inline]
pub fn vbao_pixel(params: &VbaoParams, mips: &[f32], normals: &[u32], p: UVec2) -> GtaoPixel {
    let (packed, valid, px) = pixel_setup::<f32>(&params.gtao, mips, normals, p);
    let vis = if valid { vbao_visibility(params, mips, &px) } else { 1.0 };
    GtaoPixel { term: vbao_term(valid, final_visibility(vis, params.gtao.final_value_power)), edges: packed }
}

/// The stored term of a pixel from its visibility after the final power and the 0.03 clamp
/// ([`final_visibility`], spec vbao §4); background (`valid` false) is visible.
#[inline]
pub fn vbao_term(valid: bool, final_vis: f32) -> u32 {
    store_term(if valid { final_vis } else { 1.0 })
}

/// The average over the slices of their masks' visibility under the chosen weighting (spec
/// vbao §2–§4), of one pixel or of `L::LANES` pixels.
#[inline]
pub fn vbao_visibility<L: Lanes>(params: &VbaoParams, mips: &[f32], px: &PixelSetup<L>) -> L {
    visibility_with(params, mips, px, &mut ConstantThickness)
}

/// [`vbao_visibility`] with the samples' occupied segments from `occupancy`.
#[inline]
pub fn visibility_with<L: Lanes, O: Occupancy<L>>(
    params: &VbaoParams,
    mips: &[f32],
    px: &PixelSetup<L>,
    occupancy: &mut O,
) -> L {
    let g = &params.gtao;
    let zero = L::splat(0.0);
    let slices = g.slices.max(1);
    let (mut sum, mut weights) = (zero, zero);
    let mut s = 0;
    while s < slices {
        let mut sl = slice_frame(g, px, s);
        // γ with the precise acos: the fast one errs up to 0.055 rad (0.56 sector), which sets
        // sectors on a plane (spec vbao §2.3, artefact 1 of vbao §5).
        sl.gamma = sl.sign * precise_acos(sl.cos_n);
        let mask = slice_mask(params, mips, px, &sl, s, occupancy);
        if params.weighting == WEIGHT_COSINE_EXACT {
            sum = sum + projected_length_fudge(sl.len) * free_cosine_weight(mask, sl.gamma, sl.cos_n);
            weights = weights + 1.0;
        } else if params.weighting == WEIGHT_COSINE_BLENDER {
            sum = sum + sl.len * blender_visibility::<L>(mask);
            weights = weights + sl.len;
        } else {
            sum = sum + (-(set_sectors::<L>(mask, u32::MAX) / SECTORS as f32) + 1.0);
            weights = weights + 1.0;
        }
        s += 1;
    }
    L::select(weights.gt(zero), sum / weights, L::splat(1.0))
}
