//! XeGTAO Denoise (spec gtao-raymarch-hybrid §2.7): an edge-aware 3×3 filter, repeated
//! `max(1, DenoisePasses)` times; the last pass rescales by the 1.5 headroom.

use super::GtaoParams;
use crate::common::denoise_terms::{EdgeWeights, pack_bent_normal, pack_bent_term, unpack_bent_term, unpack_edges};
use crate::common::lanes::Lanes;
use crate::common::math::{f32_to_u32, sat, u32_to_f32};
use crate::common::read::read;
use crate::common::screen_space::{neighbour_lanes, word_at};
use crate::glam::{UVec2, Vec4, vec3};
use core::ops::{Add, Mul};

/// Result of one denoise pass at a pixel.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Denoised {
    /// Stored term for the next pass, `uint(a·255 + 0.5)` (earlier passes), or the final
    /// `min(255, uint(a·1.5·255 + 0.5))` (last pass; the clamp is aokit's, spec gtao-raymarch-hybrid §7.5).
    pub term: u32,
    /// Whether this was the last pass.
    pub last: bool,
    /// The final visibility (last pass only): `term/255`, or the packed alpha with bent normals.
    pub visibility: f32,
}

/// Centre weight β: 1.2 in the last pass, 1.2/5 before it, 1e4 with denoising off (a copy).
#[inline]
fn centre_weight(params: &GtaoParams, last: bool) -> f32 {
    if params.denoise_passes == 0 {
        1.0e4
    } else if last {
        1.2
    } else {
        1.2 / 5.0
    }
}

/// Denoise pass `params.pass` at pixel `p` over the full-target AO terms `terms` (0–255) and
/// packed `edges` (spec gtao-raymarch-hybrid §2.7 steps 1–5).
#[inline]
pub fn denoise_pixel(params: &GtaoParams, terms: &[u32], edges: &[u32], p: UVec2) -> Denoised {
    let last = is_last_pass(params);
    if params.bent_normals == 0 {
        let (term, visibility) = denoise_lanes::<f32>(params, terms, edges, p);
        return Denoised { term, last, visibility };
    }
    // Bent normals (spec gtao-raymarch-hybrid §2.6.5): the four packed channels filtered alike; the last pass
    // normalizes the normal (returned in the G-buffer's right-handed space) and rescales.
    let n = Neighbourhood::<f32>::of(params.view.size(), p);
    let w = n.weights(params, edges);
    let value = combine::<f32, Vec4>(n.values(terms, params.view.size().x), &w) / w.total;
    if !last {
        return Denoised { term: pack_bent_term(value), last, visibility: 0.0 };
    }
    let n = vec3(value.x, value.y, value.z) * 2.0 - 1.0;
    let l = n.length();
    let n = if l > 0.0 { n / l } else { vec3(0.0, 0.0, -1.0) };
    let a = u32_to_f32(f32_to_u32(value.w * 1.5 * 255.0 + 0.5).min(255)) / 255.0;
    Denoised { term: pack_bent_normal(vec3(n.x, n.y, -n.z), a), last, visibility: a }
}

/// Is `params.pass` the last of the `max(1, DenoisePasses)` passes?
#[inline]
pub fn is_last_pass(params: &GtaoParams) -> bool {
    params.pass + 1 >= params.denoise_passes.max(1)
}

/// Denoise pass `params.pass` without bent normals at the pixels `p` (one or `L::LANES`): the
/// stored term and, in the last pass, the final visibility `term/255` (spec gtao-raymarch-hybrid §2.7 steps 1–5).
#[inline]
pub fn denoise_lanes<L: Lanes>(params: &GtaoParams, terms: &[u32], edges: &[u32], p: L::U2) -> (L::Index, L) {
    let n = Neighbourhood::<L>::of(params.view.size(), p);
    let w = n.weights(params, edges);
    finish_term(params, combine::<L, L>(n.values(terms, params.view.size().x), &w) / w.total)
}

/// Denoise pass `params.pass` without bent normals at the pixel pair `(2b.x, b.y)`,
/// `(2b.x + 1, b.y)`, as XeGTAO's denoiser takes two pixels an invocation: the union of the two
/// 3×3 neighbourhoods (4×3 terms, 8 edges) is read once, 20 reads instead of 28. Each pixel's
/// `(term, visibility)` is [`denoise_lanes`]'s, bit for bit (the same operations in the same
/// order; tested on the CPU); the second is meaningless where `2b.x + 1` lies beyond the target
/// (its reads clamp to the last column).
#[inline]
pub fn denoise_pair(params: &GtaoParams, terms: &[u32], edges: &[u32], b: UVec2) -> [(u32, f32); 2] {
    // Plain variables and functions, no closures over the buffers or arrays indexed at run
    // time: rust-gpu keeps those as pointers in the SPIR-V, which naga and spirv-val reject.
    let size = params.view.size();
    let x = 2 * b.x;
    // Columns x−1 … x+2 and rows y−1 … y+1, clamped to the target as neighbour_lanes clamps.
    let (c0, c1, c2, c3) = (
        f32::index_offset_clamped(x, -1, size.x),
        x,
        f32::index_offset_clamped(x, 1, size.x),
        f32::index_offset_clamped(x, 2, size.x),
    );
    let (r0, r1, r2) = (f32::index_offset_clamped(b.y, -1, size.y), b.y, f32::index_offset_clamped(b.y, 1, size.y));
    let (w, last) = (size.x, is_last_pass(params));
    let e_l = word(edges, w, c0, r1);
    let e_c0 = word(edges, w, c1, r1);
    let e_c1 = word(edges, w, c2, r1);
    let e_r = word(edges, w, c3, r1);
    let beta = centre_weight(params, last);
    let w0 = weights::<f32>(beta, e_c0, e_l, e_c1, word(edges, w, c1, r0), word(edges, w, c1, r2));
    let w1 = weights::<f32>(beta, e_c1, e_c0, e_r, word(edges, w, c2, r0), word(edges, w, c2, r2));
    let t = term_at;
    let (t00, t10, t20, t30) = (t(terms, w, c0, r0), t(terms, w, c1, r0), t(terms, w, c2, r0), t(terms, w, c3, r0));
    let (t01, t11, t21, t31) = (t(terms, w, c0, r1), t(terms, w, c1, r1), t(terms, w, c2, r1), t(terms, w, c3, r1));
    let (t02, t12, t22, t32) = (t(terms, w, c0, r2), t(terms, w, c1, r2), t(terms, w, c2, r2), t(terms, w, c3, r2));
    // Each pixel's nine terms in combine's order: centre, L, R, T, B, TL, TR, BL, BR.
    let v0 = combine::<f32, f32>([t11, t01, t21, t10, t12, t00, t20, t02, t22], &w0) / w0.total;
    let v1 = combine::<f32, f32>([t21, t11, t31, t20, t22, t10, t30, t12, t32], &w1) / w1.total;
    [finish_term(params, v0), finish_term(params, v1)]
}

/// The stored AO term at column `c`, row `r` as [`Term::load`] reads it (0–255 → /255).
#[inline]
fn term_at(terms: &[u32], width: u32, c: u32, r: u32) -> f32 {
    u32_to_f32(word(terms, width, c, r)) / 255.0
}

/// The word at column `c`, row `r` of a row-major image `width` wide.
#[inline]
fn word(data: &[u32], width: u32, c: u32, r: u32) -> u32 {
    unsafe { read(data, (r * width + c) as usize) }
}

/// The stored term of a pixel from its filtered AO `value` (the terms/255, spec
/// gtao-raymarch-hybrid §2.7 step 5) and the visibility `term/255`.
#[inline]
fn finish_term<L: Lanes>(params: &GtaoParams, value: L) -> (L::Index, L) {
    // uint(x + 0.5) of a value in [0, 1] (in [0, 1.5] after the last pass's rescale) is its
    // floor; the last pass clamps to 255 (aokit, spec gtao-raymarch-hybrid §7.5), the others cannot exceed it.
    let term = if is_last_pass(params) { value * 1.5 * 255.0 + 0.5 } else { value * 255.0 + 0.5 };
    let term = term.floor_index(L::index_splat(256));
    (term, L::index_to_float(term) / 255.0)
}

/// The 3×3 neighbourhood of a pixel (or of `L::LANES` pixels), clamped to the target.
struct Neighbourhood<L: Lanes> {
    p: L::U2,
    l: L::U2,
    r: L::U2,
    t: L::U2,
    b: L::U2,
    tl: L::U2,
    tr: L::U2,
    bl: L::U2,
    br: L::U2,
}

impl<L: Lanes> Neighbourhood<L> {
    #[inline]
    fn of(size: UVec2, p: L::U2) -> Self {
        Neighbourhood {
            p,
            l: neighbour_lanes::<L>(p, -1, 0, size),
            r: neighbour_lanes::<L>(p, 1, 0, size),
            t: neighbour_lanes::<L>(p, 0, -1, size),
            b: neighbour_lanes::<L>(p, 0, 1, size),
            tl: neighbour_lanes::<L>(p, -1, -1, size),
            tr: neighbour_lanes::<L>(p, 1, -1, size),
            bl: neighbour_lanes::<L>(p, -1, 1, size),
            br: neighbour_lanes::<L>(p, 1, 1, size),
        }
    }

    /// The stencil's weights of pass `params.pass` from the packed edges of the centre and its
    /// four neighbours.
    #[cfg_attr(target_arch = "spirv", inline)]
    #[cfg_attr(not(target_arch = "spirv"), inline(always))]
    fn weights(&self, params: &GtaoParams, edges: &[u32]) -> Weights<L> {
        let width = params.view.size().x;
        weights::<L>(
            centre_weight(params, is_last_pass(params)),
            word_at::<L>(edges, width, self.p),
            word_at::<L>(edges, width, self.l),
            word_at::<L>(edges, width, self.r),
            word_at::<L>(edges, width, self.t),
            word_at::<L>(edges, width, self.b),
        )
    }

    /// The nine terms, in [`combine`]'s order.
    #[cfg_attr(target_arch = "spirv", inline)]
    #[cfg_attr(not(target_arch = "spirv"), inline(always))]
    fn values<T: Term<L>>(&self, terms: &[u32], width: u32) -> [T; 9] {
        [
            T::load(terms, width, self.p),
            T::load(terms, width, self.l),
            T::load(terms, width, self.r),
            T::load(terms, width, self.t),
            T::load(terms, width, self.b),
            T::load(terms, width, self.tl),
            T::load(terms, width, self.tr),
            T::load(terms, width, self.bl),
            T::load(terms, width, self.br),
        ]
    }
}

/// The weights of a pixel's 3×3 stencil: β, the symmetrized edges C = (CL, CR, CT, CB), the
/// diagonal weights, and their sum (spec gtao-raymarch-hybrid §2.7 steps 1–4).
struct Weights<L: Lanes> {
    beta: f32,
    c: EdgeWeights<L>,
    w_tl: L,
    w_tr: L,
    w_bl: L,
    w_br: L,
    total: L,
}

/// The stencil's weights from the packed edges of the centre and of its left, right, top and
/// bottom neighbours (spec gtao-raymarch-hybrid §2.7 steps 1–3).
#[cfg_attr(target_arch = "spirv", inline)]
#[cfg_attr(not(target_arch = "spirv"), inline(always))]
fn weights<L: Lanes>(beta: f32, centre: L::Index, l: L::Index, r: L::Index, t: L::Index, b: L::Index) -> Weights<L> {
    let (edges_l, edges_r, edges_t, edges_b) =
        (unpack_edges::<L>(l), unpack_edges::<L>(r), unpack_edges::<L>(t), unpack_edges::<L>(b));
    let centre = unpack_edges::<L>(centre);
    // 1. Symmetrize with the neighbours' opposite edges.
    let c = EdgeWeights {
        l: centre.l * edges_l.r,
        r: centre.r * edges_r.l,
        t: centre.t * edges_t.b,
        b: centre.b * edges_b.t,
    };
    // 2. Leak: pixels with 3–4 edges get a little blur.
    let g = sat(-(c.l + c.r + c.t + c.b) + 1.5) * 0.5 / 1.5;
    let c = EdgeWeights { l: sat(c.l + g), r: sat(c.r + g), t: sat(c.t + g), b: sat(c.b + g) };
    // 3. Diagonal weights from the raw neighbour edges.
    let w_tl = (c.l * edges_l.t + c.t * edges_t.l) * 0.425;
    let w_tr = (c.t * edges_t.r + c.r * edges_r.t) * 0.425;
    let w_bl = (c.b * edges_b.l + c.l * edges_l.b) * 0.425;
    let w_br = (c.r * edges_r.b + c.b * edges_b.r) * 0.425;
    let total = L::splat(beta) + c.l + c.r + c.t + c.b + w_tl + w_tr + w_bl + w_br;
    Weights { beta, c, w_tl, w_tr, w_bl, w_br, total }
}

/// A stored denoiser term per lane: the AO value alone (0–255), or AO with a bent normal
/// (RGBA8, one pixel).
trait Term<L: Lanes>: Copy + Add<Output = Self> + Mul<L, Output = Self> {
    /// The term at pixel `q`, each channel in [0, 1] (the /1.5 domain for the AO).
    fn load(terms: &[u32], width: u32, q: L::U2) -> Self;
}

impl<L: Lanes> Term<L> for L {
    #[inline]
    fn load(terms: &[u32], width: u32, q: L::U2) -> L {
        L::index_to_float(word_at::<L>(terms, width, q)) / 255.0
    }
}

impl Term<f32> for Vec4 {
    #[inline]
    fn load(terms: &[u32], width: u32, q: UVec2) -> Vec4 {
        unpack_bent_term(unsafe { read(terms, (q.y * width + q.x) as usize) })
    }
}

/// `β·a_c + CL·a_L + CR·a_R + CT·a_T + CB·a_B + wTL·a_TL + wTR·a_TR + wBL·a_BL + wBR·a_BR`
/// (spec gtao-raymarch-hybrid §2.7 step 4's numerator) of the terms `v` (centre, L, R, T, B,
/// TL, TR, BL, BR), in the order the reference sums it.
#[cfg_attr(target_arch = "spirv", inline)]
#[cfg_attr(not(target_arch = "spirv"), inline(always))]
fn combine<L: Lanes, T: Term<L>>(v: [T; 9], w: &Weights<L>) -> T {
    v[0] * L::splat(w.beta)
        + v[1] * w.c.l
        + v[2] * w.c.r
        + v[3] * w.c.t
        + v[4] * w.c.b
        + v[5] * w.w_tl
        + v[6] * w.w_tr
        + v[7] * w.w_bl
        + v[8] * w.w_br
}
