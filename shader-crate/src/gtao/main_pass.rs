//! XeGTAO MainPass (spec gtao-raymarch-hybrid §2.6): edges for the denoiser, then per slice the
//! two horizons found by stepping through the depth MIP chain, and the cosine-weighted arc
//! integral of the visible part of the slice. Also pass 0, normals from depth (gtao-raymarch-hybrid §2.4).

use crate::common::read::read;
#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use super::{GtaoParams, MIP_LEVELS, mip_size};
use crate::common::ViewParams;
use crate::common::denoise_terms::{edges, pack_bent_normal, pack_edges, store_term};
use crate::common::gbuffer_read::decoded_normals;
use crate::common::lanes::{LaneVec2, LaneVec3, Lanes, select_v3};
use crate::common::math::{depth_or_far, fast_acos, is_valid_depth, lerp, pow, rotate_minimal, sat, u32_to_f32};
use crate::common::noise::spatio_temporal_noise_lanes;
use crate::common::normal_codec::encode_normal;
use crate::common::screen_space::{neighbour, neighbour_lanes, view_pos};
use crate::glam::{UVec2, Vec3, vec3};

/// Output of the main pass for one pixel: the working AO term `uint(sat(vis/1.5)·255 + 0.5)`
/// and the packed LRTB edges.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct GtaoPixel {
    pub term: u32,
    pub edges: u32,
}

/// What the main pass knows about pixel `p` before its slices (spec gtao-raymarch-hybrid §2.6.2): uv, the pulled
/// view position, the unit vector toward the camera, the normal facing it, the screen radius
/// in pixels, the minimum step and the noise. Shared by XeGTAO and VBAO (spec vbao §1). `L`:
/// one pixel (`f32`) or several ([`Lanes`]).
#[derive(Copy, Clone, Debug)]
pub struct PixelSetup<L: Lanes = f32> {
    pub uv: L::V2,
    pub pos: L::V3,
    /// Unit vector from the pixel toward the camera.
    pub v: L::V3,
    /// View normal in XeGTAO space, flipped to face the camera.
    pub n: L::V3,
    /// Effective radius `R = Radius·RadiusMultiplier` (world units; the same for every pixel).
    pub r: f32,
    /// Screen radius in pixels, `R / (z·2·tanX/W)`.
    pub r_px: L,
    /// Minimum sample offset `1.3/r_px` (in units of the screen radius).
    pub min_s: L,
    /// Spatio-temporal noise (slice, step).
    pub xi: L::V2,
    /// `|off|²` beyond which a sample reads MIP 1 or coarser ([`mip_threshold`]).
    pub mip_threshold: f32,
}

/// The first of the MIP thresholds on a sample offset's squared length,
/// `2^(1 + 2·DepthMIPSamplingOffset)`: MIP k ≥ 1 is read beyond `4^(k−1)` times it (spec
/// gtao-raymarch-hybrid §1.5 and §2.6.3 step 7 without a logarithm per sample; `MipLevel::of`).
#[inline]
pub fn mip_threshold(params: &GtaoParams) -> f32 {
    Float::exp2(2.0 * params.depth_mip_sampling_offset + 1.0)
}

/// Working-depth MIP 0 at texels `q` (row-major over the full target).
#[inline]
fn depth0<L: Lanes>(mips: &[f32], view: &ViewParams, q: L::U2) -> L {
    L::gather_index(mips, view.index_lanes::<L>(q))
}

/// The packed denoiser edges of pixel `p` (one or `L::LANES`), whether it has a usable depth
/// (background has none), and its [`PixelSetup`] (spec gtao-raymarch-hybrid §2.6.1–§2.6.2).
#[cfg_attr(target_arch = "spirv", inline)]
#[cfg_attr(not(target_arch = "spirv"), inline(always))]
pub fn pixel_setup<L: Lanes>(
    params: &GtaoParams,
    mips: &[f32],
    normals: &[u32],
    p: L::U2,
) -> (L::Index, L::Mask, PixelSetup<L>) {
    let view = &params.view;
    let size = view.size();
    // Working-depth MIP 0 (the first level of the chain, row-major over the full target). A
    // function, not a closure: a closure over `mips` and a local `params` leaves a struct of
    // pointers in the SPIR-V that naga rejects.
    let zc = depth0::<L>(mips, view, p);
    let e = edges(
        zc,
        depth0::<L>(mips, view, neighbour_lanes::<L>(p, -1, 0, size)),
        depth0::<L>(mips, view, neighbour_lanes::<L>(p, 1, 0, size)),
        depth0::<L>(mips, view, neighbour_lanes::<L>(p, 0, -1, size)),
        depth0::<L>(mips, view, neighbour_lanes::<L>(p, 0, 1, size)),
    );
    let packed = pack_edges(e);
    let uv = view.pixel_uv_lanes::<L>(p);
    // fp32 working depth: pull 0.99999 toward the camera (spec gtao-raymarch-hybrid §2.6.2).
    let z = zc * 0.99999;
    let pos = view_pos(view, uv, z);
    let v = (-pos).normalize();
    // The G-buffer's right-handed (−z forward) normal in XeGTAO's +z-forward space, facing the
    // camera.
    let n = decoded_normals::<L>(normals, size.x, p);
    let n = L::V3::new(n.x(), n.y(), -n.z());
    let n = select_v3::<L>(n.dot(v).lt(L::splat(0.0)), -n, n);
    let r = params.effective_radius();
    // Screen radius in pixels: R / (z·2·tanX/W).
    let r_px = L::splat(r) / (z * 2.0 * view.tan_half_fov.x / view.res.x);
    let min_s = L::splat(1.3) / r_px;
    let frame = params.noise_frame;
    let xi = spatio_temporal_noise_lanes::<L>(p, frame);
    let mip_threshold = mip_threshold(params);
    (packed, is_valid_depth(zc, view.far), PixelSetup { uv, pos, v, n, r, r_px, min_s, xi, mip_threshold })
}

/// MainPass for pixel `p` of the full target (spec gtao-raymarch-hybrid §2.6.2–§2.6.4). `normals`: encoded
/// right-handed view normals (the G-buffer's or pass 0's). Pixels without a usable depth
/// (background) get visibility 1 [aokit choice: the reference has no background test].
#[inline]
pub fn gtao_pixel(params: &GtaoParams, mips: &[f32], normals: &[u32], p: UVec2) -> GtaoPixel {
    let (packed, valid, px) = pixel_setup::<f32>(params, mips, normals, p);
    let (vis, bent) = if valid { slices_visibility(params, mips, &px) } else { (1.0, Vec3::ZERO) };
    let vis = final_visibility(vis, params.final_value_power);
    GtaoPixel { term: finish_pixel(params, valid, vis, bent, px.n), edges: packed }
}

/// The stored term of a pixel from its visibility after the final power ([`final_visibility`]
/// of the slices' average) and the slices' bent-normal sum (spec gtao-raymarch-hybrid
/// §2.6.4–§2.6.5): with bent normals also the normalised direction. Background (`valid`
/// false): visible, its bent normal toward the camera.
#[inline]
pub fn finish_pixel(params: &GtaoParams, valid: bool, vis: f32, bent: Vec3, n: Vec3) -> u32 {
    if !valid {
        return if params.bent_normals != 0 {
            pack_bent_normal(vec3(0.0, 0.0, -1.0), 1.0 / 1.5)
        } else {
            store_term(1.0)
        };
    }
    if params.bent_normals != 0 {
        let l = bent.length();
        let b = if l > 0.0 { bent / l } else { n };
        return pack_bent_normal(b, vis / 1.5);
    }
    store_term(vis)
}

/// The slices of a pixel (or of `L::LANES` pixels): the average visibility before the final
/// power, `(0.5·sat((10 − r_px)/100) + Σ L·(a(h0) + a(h1)))/slices` (spec gtao-raymarch-hybrid §2.6.2–§2.6.4), and
/// the sum of the slices' bent-normal contributions when `params.bent_normals` is set (else
/// zero).
#[inline]
pub fn slices_visibility<L: Lanes>(params: &GtaoParams, mips: &[f32], px: &PixelSetup<L>) -> (L, L::V3) {
    let falloff = Falloff::new(px.r, params.falloff_range * px.r);
    let zero = L::splat(0.0);
    let mut vis = sat((-px.r_px + 10.0) / 100.0) * 0.5;
    let mut bent = L::V3::new(zero, zero, zero);
    let slices = params.slices.max(1);
    let mut s = 0;
    while s < slices {
        let sl = slice_frame(params, px, s);
        let (h0, h1) = slice_horizons(params, mips, px, &sl, s, &falloff);
        let len = projected_length_fudge(sl.len);
        vis = vis + (arc_integral(h0, sl.gamma, sl.cos_n) + arc_integral(h1, sl.gamma, sl.cos_n)) * len;
        if params.bent_normals != 0 {
            bent = bent + slice_bent_normal(&sl, h0, h1, px.v, len);
        }
        s += 1;
    }
    (vis / u32_to_f32(slices), bent)
}

/// One slice's bent-normal contribution, `L·M·(dir.x·t0, dir.y·t0, −t1)` (spec gtao-raymarch-hybrid §2.6.5: the
/// cosine-weighted mean direction of the visible arc between the horizons h0, h1 in the slice
/// frame, rotated by the minimal rotation M taking (0, 0, −1) to v, weighted by the fudged L).
#[inline]
fn slice_bent_normal<L: Lanes>(sl: &SliceFrame<L>, h0: L, h1: L, v: L::V3, len: L) -> L::V3 {
    let g = sl.gamma;
    let t0 = ((h0 - g).sin() * 6.0 - (h0 * 3.0 - g).sin() + (h1 - g).sin() * 6.0 - (h1 * 3.0 - g).sin()
        + g.sin() * 16.0
        - ((h0 + g).sin() + (h1 + g).sin()) * 3.0)
        / 12.0;
    let t1 =
        (-(h0 * 3.0 - g).cos() - (h1 * 3.0 - g).cos() + g.cos() * 8.0 - ((h0 + g).cos() + (h1 + g).cos()) * 3.0) / 12.0;
    let local = L::V3::new(sl.dir.x() * t0, sl.dir.y() * t0, -t1);
    let zero = L::splat(0.0);
    rotate_minimal::<L>(L::V3::new(zero, zero, L::splat(-1.0)), v, local) * len
}

/// `max(V^p, 0.03)` (spec gtao-raymarch-hybrid §2.6.4; VBAO finalises the same way, spec vbao
/// §4), of one pixel or of `L::LANES` pixels.
#[inline]
pub fn final_visibility<L: Lanes>(vis: L, power: f32) -> L {
    pow(vis, power).max(L::splat(0.03))
}

/// Falloff weight `W(D) = sat((R − D)/falloffRange)` (spec gtao-raymarch-hybrid §2.6.2) as XeGTAO
/// evaluates it, `sat(D·mul + add)` with `mul = −1/falloffRange`, `add = R/falloffRange` made
/// once per pixel ([`Falloff::new`]); a step `D ≤ R` when the range is 0.
#[derive(Copy, Clone, Debug)]
pub struct Falloff {
    mul: f32,
    add: f32,
    r: f32,
    step: bool,
}

impl Falloff {
    /// The weight for effective radius `r` and falloff range `range` (world units).
    #[inline]
    pub fn new(r: f32, range: f32) -> Falloff {
        let step = range <= 0.0;
        let inv = if step { 0.0 } else { 1.0 / range };
        Falloff { mul: -inv, add: r * inv, r, step }
    }

    /// `W(d)` per lane.
    #[inline]
    pub fn weight<L: Lanes>(&self, d: L) -> L {
        if self.step {
            L::select(d.le(L::splat(self.r)), L::splat(1.0), L::splat(0.0))
        } else {
            sat(d * self.mul + self.add)
        }
    }
}

/// The cosine-weighted visible arc of one side, `a(h) = (cos n + 2h·sin γ − cos(2h − γ))/4`
/// (spec gtao-raymarch-hybrid §2.6.3 step 10; GTAO paper eq. 10).
#[inline]
pub fn arc_integral<L: Lanes>(h: L, gamma: L, cos_n: L) -> L {
    (cos_n + h * 2.0 * gamma.sin() - (h * 2.0 - gamma).cos()) * 0.25
}

/// One slice's frame (spec gtao-raymarch-hybrid §2.6.3 steps 1–5): the screen step vector, the slice direction,
/// the projected normal, its length L, cos n and the signed normal angle γ.
#[derive(Copy, Clone, Debug)]
pub struct SliceFrame<L: Lanes = f32> {
    /// Screen-space offset of a unit step (pixels), `(cos φ, −sin φ)·r_px`.
    pub omega: L::V2,
    /// Slice direction in view space, `(cos φ, sin φ, 0)`.
    pub dir: L::V3,
    /// `L = |projected|` (before the step-8 fudge).
    pub len: L,
    pub cos_n: L,
    /// The side of the projected normal: +1 toward side 0, −1 toward side 1 (0 if neither).
    pub sign: L,
    /// γ = sgn·acos(cos n) with XeGTAO's fast acos, positive toward side 0.
    pub gamma: L,
}

/// The frame of slice `s` of a pixel (spec gtao-raymarch-hybrid §2.6.3 steps 1–5).
#[inline]
pub fn slice_frame<L: Lanes>(params: &GtaoParams, px: &PixelSetup<L>, s: u32) -> SliceFrame<L> {
    let slices = params.slices.max(1);
    let phi = (px.xi.x() + u32_to_f32(s)) * core::f32::consts::PI / u32_to_f32(slices);
    let (sin_phi, cos_phi) = phi.sin_cos();
    let omega = L::V2::new(cos_phi, -sin_phi) * px.r_px;
    let dir = L::V3::new(cos_phi, sin_phi, L::splat(0.0));
    let ortho = dir - px.v * dir.dot(px.v);
    let axis = ortho.cross(px.v).normalize();
    let projected = px.n - axis * px.n.dot(axis);
    let len = projected.length();
    let side = ortho.dot(projected);
    let zero = L::splat(0.0);
    let sign = L::select(side.gt(zero), L::splat(1.0), L::select(side.lt(zero), L::splat(-1.0), zero));
    let cos_n = sat(projected.dot(px.v) / len);
    let gamma = sign * fast_acos(cos_n);
    SliceFrame { omega, dir, len, cos_n, sign, gamma }
}

/// Step `k` of slice `s`: the view positions of the two samples, `Q0` at uv + offset (side 0)
/// and `Q1` at uv − offset (side 1), with the MIP level chosen from the offset length and the
/// offset rounded to whole pixels (spec gtao-raymarch-hybrid §2.6.3 step 7).
#[cfg_attr(target_arch = "spirv", inline)]
#[cfg_attr(not(target_arch = "spirv"), inline(always))]
pub fn sample_pair<L: Lanes>(
    params: &GtaoParams,
    mips: &[f32],
    px: &PixelSetup<L>,
    slice: &SliceFrame<L>,
    s: u32,
    k: u32,
) -> (L::V3, L::V3) {
    let view = &params.view;
    let full = view.size();
    let steps = params.steps.max(1);
    let t = crate::common::math::frac(px.xi.y() + u32_to_f32(s + k * steps) * 0.618_034);
    let u = pow((t + u32_to_f32(k)) * (1.0 / u32_to_f32(steps)), params.sample_distribution_power) + px.min_s;
    let off = slice.omega * u;
    let level = MipLevel::<L>::of(full, off.x() * off.x() + off.y() * off.y(), px.mip_threshold);
    // Whole pixels times the pixel size: the sample lands on a texel centre either way.
    let off_uv = L::V2::new(off.x().round_even() * (1.0 / view.res.x), off.y().round_even() * (1.0 / view.res.y));
    let uv0 = px.uv + off_uv;
    let uv1 = px.uv - off_uv;
    let q0 = view_pos(view, uv0, level.sample(mips, uv0));
    let q1 = view_pos(view, uv1, level.sample(mips, uv1));
    (q0, q1)
}

/// The MIP level a sample offset reads, per lane: its extent and where it starts in the packed
/// chain.
struct MipLevel<L: Lanes> {
    /// Width and height in texels.
    w: L::Index,
    h: L::Index,
    /// Offset of the level's first texel in the chain.
    at: L::Index,
}

impl<L: Lanes> MipLevel<L> {
    /// The nearest level `ceil(λ + 0.5) − 1` of `λ = clamp(log2|off| − offset, 0, 5)`, clamped to
    /// MIP 4 (spec gtao-raymarch-hybrid §1.5, §2.6.3 step 7), from `len_sq = |off|²` without a
    /// logarithm: for k ≥ 1 the level is at least k exactly when λ > k − 1/2, that is when
    /// `|off|² > 2^(2k − 1 + 2·offset)`: `first` ([`mip_threshold`]) times 1, 4, 16, 64. A NaN
    /// offset reads MIP 0, as the clamp makes it. Branch-free, the same for one lane as for
    /// several: each level reached takes that level's offset (the same for every pixel) and
    /// index by a select, its extent is `max(full ≫ k, 1)` ([`mip_size`]).
    #[inline]
    fn of(full: UVec2, len_sq: L, first: f32) -> Self {
        let mut k = L::index_splat(0);
        let mut at = L::index_splat(0);
        let mut start = 0u32;
        // Levels 1–4 written out: straight-line code on the GPU (rust-gpu emits loops as written).
        const _: () = assert!(MIP_LEVELS == 5, "MipLevel chooses among exactly five levels");
        macro_rules! level {
            ($k:expr) => {
                let above = mip_size(full, $k - 1);
                start += above.x * above.y;
                let reached = len_sq.gt(L::splat(first * (1u32 << (2 * ($k - 1))) as f32));
                k = L::index_select(reached, L::index_splat($k), k);
                at = L::index_select(reached, L::index_splat(start), at);
            };
        }
        level!(1);
        level!(2);
        level!(3);
        level!(4);
        MipLevel { w: L::index_mip_extent(full.x, k), h: L::index_mip_extent(full.y, k), at }
    }

    /// Point sample at `uv`: the texel `clamp(⌊uv·size⌋, 0, size − 1)` of the level (spec
    /// gtao-raymarch-hybrid §1.5).
    #[inline]
    fn sample(&self, mips: &[f32], uv: L::V2) -> L {
        let x = (uv.x() * L::index_to_float(self.w)).floor_index(self.w);
        let y = (uv.y() * L::index_to_float(self.h)).floor_index(self.h);
        L::gather_index(mips, self.at + y * self.w + x)
    }
}

/// One slice's horizon angles `(h0, h1)` (spec gtao-raymarch-hybrid §2.6.3 steps 6–9): the largest horizon cosine
/// per side over the steps, starting at the hemisphere's edge, as angles.
#[inline]
fn slice_horizons<L: Lanes>(
    params: &GtaoParams,
    mips: &[f32],
    px: &PixelSetup<L>,
    sl: &SliceFrame<L>,
    s: u32,
    falloff: &Falloff,
) -> (L, L) {
    let steps = params.steps.max(1);
    // cos(γ ± π/2) = ∓sin γ (spec gtao-raymarch-hybrid §2.6.3 step 6).
    let low1 = sl.gamma.sin();
    let low0 = -low1;
    let (mut c0, mut c1) = (low0, low1);
    let thin = params.thin_occluder_compensation;
    let mut k = 0;
    while k < steps {
        let (q0, q1) = sample_pair(params, mips, px, sl, s, k);
        let shc0 = horizon_cosine(q0 - px.pos, px.v, thin, falloff, low0);
        let shc1 = horizon_cosine(q1 - px.pos, px.v, thin, falloff, low1);
        c0 = c0.max(shc0);
        c1 = c1.max(shc1);
        k += 1;
    }
    (-fast_acos(c1), fast_acos(c0))
}

/// XeGTAO's fudge of the projected normal's length, `lerp(L, 1, 0.05)` (spec gtao-raymarch-hybrid §2.6.3 step 8).
#[inline]
pub fn projected_length_fudge<L: Lanes>(len: L) -> L {
    lerp(len, L::splat(1.0), L::splat(0.05))
}

/// Horizon cosine of one sample, faded toward the hemisphere fallback `low` with distance
/// (spec gtao-raymarch-hybrid §2.6.3 step 7; thin-occluder compensation stretches z of the falloff distance).
/// `dot(Δ/|Δ|, v)` is evaluated as `dot(Δ, v)·(1/|Δ|)` and `|Δ|` as `|Δ|²·(1/|Δ|)`, one inverse
/// square root for both ([`Lanes::inverse_sqrt`]), and the stretched length only when the
/// compensation is on.
#[inline]
fn horizon_cosine<L: Lanes>(delta: L::V3, v: L::V3, thin: f32, falloff: &Falloff, low: L) -> L {
    let len_sq = delta.dot(delta);
    let inv_len = len_sq.inverse_sqrt();
    let d = len_sq * inv_len;
    let shc = delta.dot(v) * inv_len;
    let stretched = if thin == 0.0 { d } else { L::V3::new(delta.x(), delta.y(), delta.z() * (1.0 + thin)).length() };
    lerp(low, shc, falloff.weight(stretched))
}

/// Pass 0 (spec gtao-raymarch-hybrid §2.4): the view normal from depth at pixel `p` — four cross products of the
/// neighbour directions weighted by edge connectivity `sat(e_a·e_b + 0.01)` — encoded as the
/// G-buffer's right-handed octahedral normal.
#[inline]
pub fn normal_from_depth(params: &GtaoParams, depth: &[f32], p: UVec2) -> u32 {
    let view = &params.view;
    let size = view.size();
    let (pc, zc) = depth_point(params, depth, neighbour(p, 0, 0, size));
    let (pl, zl) = depth_point(params, depth, neighbour(p, -1, 0, size));
    let (pr, zr) = depth_point(params, depth, neighbour(p, 1, 0, size));
    let (pt, zt) = depth_point(params, depth, neighbour(p, 0, -1, size));
    let (pb, zb) = depth_point(params, depth, neighbour(p, 0, 1, size));
    let e = edges(zc, zl, zr, zt, zb);
    let dir = |q: Vec3| safe_normalize(q - pc);
    let (l, r, t, b) = (dir(pl), dir(pr), dir(pt), dir(pb));
    let n = l.cross(t) * sat(e.l * e.t + 0.01)
        + t.cross(r) * sat(e.t * e.r + 0.01)
        + r.cross(b) * sat(e.r * e.b + 0.01)
        + b.cross(l) * sat(e.b * e.l + 0.01);
    let n = safe_normalize(n);
    encode_normal(vec3(n.x, n.y, -n.z))
}

/// View position and depth of pixel `q` from the linear G-buffer depth (unusable → far).
#[inline]
fn depth_point(params: &GtaoParams, depth: &[f32], q: UVec2) -> (Vec3, f32) {
    let view = &params.view;
    let z = depth_or_far(unsafe { read(depth, (q.y * view.size().x + q.x) as usize) }, view.far);
    (view_pos(view, view.pixel_uv(q), z), z)
}

/// `v/|v|`, or zero for a zero vector (glam's `normalize_or_zero` compares against infinity,
/// which naga rejects as a SPIR-V constant).
#[inline]
fn safe_normalize(v: Vec3) -> Vec3 {
    let l = v.length();
    if l > 0.0 { v / l } else { Vec3::ZERO }
}
