//! XeGTAO MainPass (spec gtao-raymarch-hybrid §2.6): edges for the denoiser, then per slice the
//! two horizons found by stepping through the depth MIP chain, and the cosine-weighted arc
//! integral of the visible part of the slice. Also pass 0, normals from depth (§2.4).

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use super::{GtaoParams, mip_texel};
use crate::common::denoise_terms::{edges, pack_edges, round_even, store_term};
use crate::common::math::{clamp, fast_acos, is_valid_depth, lerp, sat};
use crate::common::noise::spatio_temporal_noise;
use crate::common::normal_codec::{decode_normal, encode_normal};
use crate::common::screen_space::{clamp_index, neighbour, view_pos};
use crate::glam::{UVec2, Vec2, Vec3, vec2, vec3};

/// Output of the main pass for one pixel: the working AO term `uint(sat(vis/1.5)·255 + 0.5)`
/// and the packed LRTB edges.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
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

/// MainPass for pixel `p` of the full target (spec §2.6.2–§2.6.4). `normals`: encoded
/// right-handed view normals (the G-buffer's or pass 0's). Pixels without a usable depth
/// (background) get visibility 1 [aokit choice: the reference has no background test].
#[inline]
pub fn gtao_pixel(params: &GtaoParams, mips: &[f32], normals: &[u32], p: UVec2) -> GtaoPixel {
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
    if !is_valid_depth(zc, view.far) {
        return GtaoPixel { term: store_term(1.0), edges: packed };
    }
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
    let falloff_range = params.falloff_range * r;
    // Screen radius in pixels: R / (z·2·tanX/W).
    let r_px = r / (z * 2.0 * view.tan_half_fov.x / view.res.x);
    let mut vis = 0.5 * sat((10.0 - r_px) / 100.0);
    let min_s = 1.3 / r_px;
    let xi = spatio_temporal_noise(p, params.noise_frame);
    let slices = params.slices.max(1);
    let mut s = 0;
    while s < slices {
        vis += slice_visibility(params, mips, uv, pos, v, n, s, xi, r_px, min_s, r, falloff_range);
        s += 1;
    }
    vis /= slices as f32;
    vis = vis.powf(params.final_value_power);
    vis = vis.max(0.03);
    GtaoPixel { term: store_term(vis), edges: packed }
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

/// One slice's visibility `L·(a(h0) + a(h1))` (spec §2.6.3).
#[inline]
fn slice_visibility(
    params: &GtaoParams,
    mips: &[f32],
    uv: Vec2,
    pos: Vec3,
    v: Vec3,
    n: Vec3,
    s: u32,
    xi: Vec2,
    r_px: f32,
    min_s: f32,
    r: f32,
    falloff_range: f32,
) -> f32 {
    let view = &params.view;
    let full = view.size();
    let slices = params.slices.max(1);
    let steps = params.steps.max(1);
    let phi = core::f32::consts::PI * (s as f32 + xi.x) / slices as f32;
    let (sin_phi, cos_phi) = (phi.sin(), phi.cos());
    let omega = vec2(cos_phi, -sin_phi) * r_px;
    let dir = vec3(cos_phi, sin_phi, 0.0);
    let ortho = dir - v * dir.dot(v);
    let axis = ortho.cross(v).normalize();
    let projected = n - axis * n.dot(axis);
    let mut len = projected.length();
    let sign = if ortho.dot(projected) > 0.0 {
        1.0
    } else if ortho.dot(projected) < 0.0 {
        -1.0
    } else {
        0.0
    };
    let cos_n = sat(projected.dot(v) / len);
    let gamma = sign * fast_acos(cos_n);
    let half_pi = core::f32::consts::FRAC_PI_2;
    let low0 = (gamma + half_pi).cos();
    let low1 = (gamma - half_pi).cos();
    let (mut c0, mut c1) = (low0, low1);
    let mut k = 0;
    while k < steps {
        let t = crate::common::math::frac(xi.y + (s + k * steps) as f32 * 0.618_034);
        let u = ((k as f32 + t) / steps as f32).powf(params.sample_distribution_power) + min_s;
        let mut off = omega * u;
        let lambda = clamp(off.length().log2() - params.depth_mip_sampling_offset, 0.0, 5.0);
        let level = clamp_index((lambda + 0.5).ceil() - 1.0, super::MIP_LEVELS);
        off = vec2(round_even(off.x), round_even(off.y));
        let off_uv = off / view.res;
        let uv0 = uv + off_uv;
        let uv1 = uv - off_uv;
        let q0 = view_pos(view, uv0, mips[mip_texel(full, level, uv0)]);
        let q1 = view_pos(view, uv1, mips[mip_texel(full, level, uv1)]);
        let shc0 = horizon_cosine(q0 - pos, v, params.thin_occluder_compensation, r, falloff_range, low0);
        let shc1 = horizon_cosine(q1 - pos, v, params.thin_occluder_compensation, r, falloff_range, low1);
        c0 = c0.max(shc0);
        c1 = c1.max(shc1);
        k += 1;
    }
    len = lerp(len, 1.0, 0.05);
    let h0 = -fast_acos(c1);
    let h1 = fast_acos(c0);
    len * (arc_integral(h0, gamma, cos_n) + arc_integral(h1, gamma, cos_n))
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
