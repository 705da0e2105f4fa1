//! XeGTAO MainPass (spec gtao-raymarch-hybrid §2.6): edges for the denoiser, then per slice the
//! two horizons found by stepping through the depth MIP chain, and the cosine-weighted arc
//! integral of the visible part of the slice. Also pass 0, normals from depth (§2.4).

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use super::{GtaoParams, mip_texel};
use crate::common::denoise_terms::{edges, pack_bent_normal, pack_edges, round_even, store_term};
use crate::common::math::{ceil, clamp, fast_acos, is_valid_depth, lerp, pow, rotate_minimal, sat};
use crate::common::noise::spatio_temporal_noise;
use crate::common::normal_codec::{decode_normal, encode_normal};
use crate::common::screen_space::{clamp_index, neighbour, view_pos};
use crate::glam::{UVec2, Vec2, Vec3, vec2, vec3};

/// Output of the main pass for one pixel: the working AO term `uint(sat(vis/1.5)·255 + 0.5)`
/// and the packed LRTB edges.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct GtaoPixel {
    pub term: u32,
    pub edges: u32,
}

/// Working-depth MIP 0 at pixel `p`.
#[inline]
fn depth0(params: &GtaoParams, mips: &[f32], p: UVec2) -> f32 {
    mips[(p.y * params.view.size().x + p.x) as usize]
}

/// The G-buffer's right-handed (−z forward) view normal in XeGTAO's +z-forward space.
#[inline]
fn to_gtao_space(n: Vec3) -> Vec3 {
    vec3(n.x, n.y, -n.z)
}

/// What the main pass knows about pixel `p` before its slices (spec §2.6.2): uv, the pulled
/// view position, the unit vector toward the camera, the normal facing it, the screen radius
/// in pixels, the minimum step and the noise. Shared by XeGTAO and VBAO (spec vbao §1).
#[derive(Copy, Clone, Debug)]
pub struct PixelSetup {
    pub uv: Vec2,
    pub pos: Vec3,
    /// Unit vector from the pixel toward the camera.
    pub v: Vec3,
    /// View normal in XeGTAO space, flipped to face the camera.
    pub n: Vec3,
    /// Effective radius `R = Radius·RadiusMultiplier` (world units).
    pub r: f32,
    /// Screen radius in pixels, `R / (z·2·tanX/W)`.
    pub r_px: f32,
    /// Minimum sample offset `1.3/r_px` (in units of the screen radius).
    pub min_s: f32,
    /// Spatio-temporal noise (slice, step).
    pub xi: Vec2,
}

/// The packed denoiser edges of pixel `p`, whether it has a usable depth (background has
/// none), and its [`PixelSetup`] (spec §2.6.1–§2.6.2).
#[inline]
pub fn pixel_setup(params: &GtaoParams, mips: &[f32], normals: &[u32], p: UVec2) -> (u32, bool, PixelSetup) {
    let view = &params.view;
    let size = view.size();
    let zc = depth0(params, mips, p);
    let e = edges(
        zc,
        depth0(params, mips, neighbour(p, -1, 0, size)),
        depth0(params, mips, neighbour(p, 1, 0, size)),
        depth0(params, mips, neighbour(p, 0, -1, size)),
        depth0(params, mips, neighbour(p, 0, 1, size)),
    );
    let packed = pack_edges(e);
    let uv = view.pixel_uv(p);
    // fp32 working depth: pull 0.99999 toward the camera (spec §2.6.2).
    let z = zc * 0.99999;
    let pos = view_pos(view, uv, z);
    let v = (-pos).normalize();
    let mut n = to_gtao_space(decode_normal(normals[(p.y * size.x + p.x) as usize]));
    if n.dot(v) < 0.0 {
        n = -n;
    }
    let r = params.effective_radius();
    // Screen radius in pixels: R / (z·2·tanX/W).
    let r_px = r / (z * 2.0 * view.tan_half_fov.x / view.res.x);
    let min_s = 1.3 / r_px;
    let xi = spatio_temporal_noise(p, params.noise_frame);
    (packed, is_valid_depth(zc, view.far), PixelSetup { uv, pos, v, n, r, r_px, min_s, xi })
}

/// MainPass for pixel `p` of the full target (spec §2.6.2–§2.6.4). `normals`: encoded
/// right-handed view normals (the G-buffer's or pass 0's). Pixels without a usable depth
/// (background) get visibility 1 [aokit choice: the reference has no background test].
#[inline]
pub fn gtao_pixel(params: &GtaoParams, mips: &[f32], normals: &[u32], p: UVec2) -> GtaoPixel {
    let (packed, valid, px) = pixel_setup(params, mips, normals, p);
    if !valid {
        // Background: visible, its bent normal toward the camera.
        let term =
            if params.bent_normals != 0 { pack_bent_normal(vec3(0.0, 0.0, -1.0), 1.0 / 1.5) } else { store_term(1.0) };
        return GtaoPixel { term, edges: packed };
    }
    let falloff_range = params.falloff_range * px.r;
    let mut vis = 0.5 * sat((10.0 - px.r_px) / 100.0);
    let mut bent = Vec3::ZERO;
    let slices = params.slices.max(1);
    let mut s = 0;
    while s < slices {
        let (slice_vis, slice_bent) = slice_visibility(params, mips, &px, s, falloff_range);
        vis += slice_vis;
        bent += slice_bent;
        s += 1;
    }
    vis /= slices as f32;
    let vis = final_visibility(vis, params.final_value_power);
    if params.bent_normals != 0 {
        let l = bent.length();
        let b = if l > 0.0 { bent / l } else { px.n };
        return GtaoPixel { term: pack_bent_normal(b, vis / 1.5), edges: packed };
    }
    GtaoPixel { term: store_term(vis), edges: packed }
}

/// One slice's bent-normal contribution, `L·M·(dir.x·t0, dir.y·t0, −t1)` (spec §2.6.5: the
/// cosine-weighted mean direction of the visible arc between the horizons h0, h1 in the slice
/// frame, rotated by the minimal rotation M taking (0, 0, −1) to v, weighted by the fudged L).
#[inline]
fn slice_bent_normal(sl: &SliceFrame, h0: f32, h1: f32, v: Vec3, len: f32) -> Vec3 {
    let g = sl.gamma;
    let t0 = (6.0 * (h0 - g).sin() - (3.0 * h0 - g).sin() + 6.0 * (h1 - g).sin() - (3.0 * h1 - g).sin()
        + 16.0 * g.sin()
        - 3.0 * ((h0 + g).sin() + (h1 + g).sin()))
        / 12.0;
    let t1 =
        (-(3.0 * h0 - g).cos() - (3.0 * h1 - g).cos() + 8.0 * g.cos() - 3.0 * ((h0 + g).cos() + (h1 + g).cos())) / 12.0;
    let local = vec3(sl.dir.x * t0, sl.dir.y * t0, -t1);
    rotate_minimal(vec3(0.0, 0.0, -1.0), v, local) * len
}

/// `max(V^p, 0.03)` (spec §2.6.4; VBAO finalises the same way, spec vbao §4).
#[inline]
pub fn final_visibility(vis: f32, power: f32) -> f32 {
    vis.powf(power).max(0.03)
}

/// Falloff weight `W(D) = sat((R − D)/falloffRange)` (spec §2.6.2; a step when the range is 0).
#[inline]
fn falloff(d: f32, r: f32, range: f32) -> f32 {
    if range > 0.0 {
        sat((r - d) / range)
    } else if d <= r {
        1.0
    } else {
        0.0
    }
}

/// The cosine-weighted visible arc of one side, `a(h) = (cos n + 2h·sin γ − cos(2h − γ))/4`
/// (spec §2.6.3 step 10; GTAO paper eq. 10).
#[inline]
pub fn arc_integral(h: f32, gamma: f32, cos_n: f32) -> f32 {
    (cos_n + 2.0 * h * gamma.sin() - (2.0 * h - gamma).cos()) * 0.25
}

/// One slice's frame (spec §2.6.3 steps 1–5): the screen step vector, the slice direction,
/// the projected normal, its length L, cos n and the signed normal angle γ.
#[derive(Copy, Clone, Debug)]
pub struct SliceFrame {
    /// Screen-space offset of a unit step (pixels), `(cos φ, −sin φ)·r_px`.
    pub omega: Vec2,
    /// Slice direction in view space, `(cos φ, sin φ, 0)`.
    pub dir: Vec3,
    /// `L = |projected|` (before the step-8 fudge).
    pub len: f32,
    pub cos_n: f32,
    /// The side of the projected normal: +1 toward side 0, −1 toward side 1 (0 if neither).
    pub sign: f32,
    /// γ = sgn·acos(cos n) with XeGTAO's fast acos, positive toward side 0.
    pub gamma: f32,
}

/// The frame of slice `s` of a pixel (spec §2.6.3 steps 1–5).
#[inline]
pub fn slice_frame(params: &GtaoParams, px: &PixelSetup, s: u32) -> SliceFrame {
    let slices = params.slices.max(1);
    let phi = core::f32::consts::PI * (s as f32 + px.xi.x) / slices as f32;
    let (sin_phi, cos_phi) = (phi.sin(), phi.cos());
    let omega = vec2(cos_phi, -sin_phi) * px.r_px;
    let dir = vec3(cos_phi, sin_phi, 0.0);
    let ortho = dir - px.v * dir.dot(px.v);
    let axis = ortho.cross(px.v).normalize();
    let projected = px.n - axis * px.n.dot(axis);
    let len = projected.length();
    let sign = if ortho.dot(projected) > 0.0 {
        1.0
    } else if ortho.dot(projected) < 0.0 {
        -1.0
    } else {
        0.0
    };
    let cos_n = sat(projected.dot(px.v) / len);
    let gamma = sign * fast_acos(cos_n);
    SliceFrame { omega, dir, len, cos_n, sign, gamma }
}

/// Step `k` of slice `s`: the view positions of the two samples, `Q0` at uv + offset (side 0)
/// and `Q1` at uv − offset (side 1), with the MIP level chosen from the offset length and the
/// offset rounded to whole pixels (spec §2.6.3 step 7).
#[inline]
pub fn sample_pair(
    params: &GtaoParams,
    mips: &[f32],
    px: &PixelSetup,
    slice: &SliceFrame,
    s: u32,
    k: u32,
) -> (Vec3, Vec3) {
    let view = &params.view;
    let full = view.size();
    let steps = params.steps.max(1);
    let t = crate::common::math::frac(px.xi.y + (s + k * steps) as f32 * 0.618_034);
    let u = pow((k as f32 + t) / steps as f32, params.sample_distribution_power) + px.min_s;
    let mut off = slice.omega * u;
    let lambda = clamp(off.length().log2() - params.depth_mip_sampling_offset, 0.0, 5.0);
    let level = clamp_index(ceil(lambda + 0.5) - 1.0, super::MIP_LEVELS);
    off = vec2(round_even(off.x), round_even(off.y));
    let off_uv = off / view.res;
    let uv0 = px.uv + off_uv;
    let uv1 = px.uv - off_uv;
    let q0 = view_pos(view, uv0, mips[mip_texel(full, level, uv0)]);
    let q1 = view_pos(view, uv1, mips[mip_texel(full, level, uv1)]);
    (q0, q1)
}

/// One slice's visibility `L·(a(h0) + a(h1))` (spec §2.6.3), and its bent-normal
/// contribution when `params.bent_normals` is set (else zero).
#[inline]
fn slice_visibility(params: &GtaoParams, mips: &[f32], px: &PixelSetup, s: u32, falloff_range: f32) -> (f32, Vec3) {
    let sl = slice_frame(params, px, s);
    let steps = params.steps.max(1);
    let half_pi = core::f32::consts::FRAC_PI_2;
    let low0 = (sl.gamma + half_pi).cos();
    let low1 = (sl.gamma - half_pi).cos();
    let (mut c0, mut c1) = (low0, low1);
    let thin = params.thin_occluder_compensation;
    let mut k = 0;
    while k < steps {
        let (q0, q1) = sample_pair(params, mips, px, &sl, s, k);
        let shc0 = horizon_cosine(q0 - px.pos, px.v, thin, px.r, falloff_range, low0);
        let shc1 = horizon_cosine(q1 - px.pos, px.v, thin, px.r, falloff_range, low1);
        c0 = c0.max(shc0);
        c1 = c1.max(shc1);
        k += 1;
    }
    let len = projected_length_fudge(sl.len);
    let h0 = -fast_acos(c1);
    let h1 = fast_acos(c0);
    let vis = len * (arc_integral(h0, sl.gamma, sl.cos_n) + arc_integral(h1, sl.gamma, sl.cos_n));
    let bent = if params.bent_normals != 0 { slice_bent_normal(&sl, h0, h1, px.v, len) } else { Vec3::ZERO };
    (vis, bent)
}

/// XeGTAO's fudge of the projected normal's length, `lerp(L, 1, 0.05)` (spec §2.6.3 step 8).
#[inline]
pub fn projected_length_fudge(len: f32) -> f32 {
    lerp(len, 1.0, 0.05)
}

/// Horizon cosine of one sample, faded toward the hemisphere fallback `low` with distance
/// (spec §2.6.3 step 7; thin-occluder compensation stretches z of the falloff distance).
#[inline]
fn horizon_cosine(delta: Vec3, v: Vec3, thin: f32, r: f32, range: f32, low: f32) -> f32 {
    let d = delta.length();
    let shc = (delta / d).dot(v);
    let stretched = vec3(delta.x, delta.y, delta.z * (1.0 + thin)).length();
    lerp(low, shc, falloff(stretched, r, range))
}

/// Pass 0 (spec §2.4): the view normal from depth at pixel `p` — four cross products of the
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
    let n = l.cross(t) * sat(e.x * e.z + 0.01)
        + t.cross(r) * sat(e.z * e.y + 0.01)
        + r.cross(b) * sat(e.y * e.w + 0.01)
        + b.cross(l) * sat(e.w * e.x + 0.01);
    let n = safe_normalize(n);
    encode_normal(vec3(n.x, n.y, -n.z))
}

/// View position and depth of pixel `q` from the linear G-buffer depth (unusable → far).
#[inline]
fn depth_point(params: &GtaoParams, depth: &[f32], q: UVec2) -> (Vec3, f32) {
    let view = &params.view;
    let mut z = depth[(q.y * view.size().x + q.x) as usize];
    if !is_valid_depth(z, view.far) {
        z = view.far;
    }
    (view_pos(view, view.pixel_uv(q), z), z)
}

/// `v/|v|`, or zero for a zero vector (glam's `normalize_or_zero` compares against infinity,
/// which naga rejects as a SPIR-V constant).
#[inline]
fn safe_normalize(v: Vec3) -> Vec3 {
    let l = v.length();
    if l > 0.0 { v / l } else { Vec3::ZERO }
}
