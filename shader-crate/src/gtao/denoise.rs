//! XeGTAO Denoise (spec gtao-raymarch-hybrid §2.7): an edge-aware 3×3 filter, repeated
//! `max(1, DenoisePasses)` times; the last pass rescales by the 1.5 headroom.

use super::GtaoParams;
use crate::common::denoise_terms::{EdgeWeights, pack_bent_normal, pack_bent_term, unpack_bent_term, unpack_edges};
use crate::common::lanes::Lanes;
use crate::common::math::sat;
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
    let s = stencil::<f32>(params, edges, p);
    let value = weighted::<f32, Vec4>(terms, params.view.size().x, &s) / s.total;
    if !last {
        return Denoised { term: pack_bent_term(value), last, visibility: 0.0 };
    }
    let n = vec3(value.x, value.y, value.z) * 2.0 - 1.0;
    let l = n.length();
    let n = if l > 0.0 { n / l } else { vec3(0.0, 0.0, -1.0) };
    let a = ((value.w * 1.5 * 255.0 + 0.5) as u32).min(255) as f32 / 255.0;
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
    let s = stencil::<L>(params, edges, p);
    let value = weighted::<L, L>(terms, params.view.size().x, &s) / s.total;
    // uint(x + 0.5) of a value in [0, 1] (in [0, 1.5] after the last pass's rescale) is its
    // floor; the last pass clamps to 255 (aokit, spec gtao-raymarch-hybrid §7.5), the others cannot exceed it.
    let term = if is_last_pass(params) { value * 1.5 * 255.0 + 0.5 } else { value * 255.0 + 0.5 };
    let term = term.floor_index(L::index_splat(256));
    (term, L::index_to_float(term) / 255.0)
}

/// The 3×3 neighbourhood of a pixel (centre, L, R, T, B, TL, TR, BL, BR) and its weights:
/// β, the symmetrized edges C = (CL, CR, CT, CB), the diagonal weights, and their sum (spec
/// gtao-raymarch-hybrid §2.7 steps 1–4).
struct Stencil<L: Lanes> {
    p: L::U2,
    l: L::U2,
    r: L::U2,
    t: L::U2,
    b: L::U2,
    tl: L::U2,
    tr: L::U2,
    bl: L::U2,
    br: L::U2,
    beta: f32,
    c: EdgeWeights<L>,
    w_tl: L,
    w_tr: L,
    w_bl: L,
    w_br: L,
    total: L,
}

/// The stencil of pass `params.pass` at `p` from the packed edges (spec gtao-raymarch-hybrid §2.7 steps 1–3).
#[inline]
fn stencil<L: Lanes>(params: &GtaoParams, edges: &[u32], p: L::U2) -> Stencil<L> {
    let size = params.view.size();
    let beta = centre_weight(params, is_last_pass(params));
    let (l, r, t, b) = (
        neighbour_lanes::<L>(p, -1, 0, size),
        neighbour_lanes::<L>(p, 1, 0, size),
        neighbour_lanes::<L>(p, 0, -1, size),
        neighbour_lanes::<L>(p, 0, 1, size),
    );
    let edges_l = unpack_edges::<L>(word_at::<L>(edges, size.x, l));
    let edges_r = unpack_edges::<L>(word_at::<L>(edges, size.x, r));
    let edges_t = unpack_edges::<L>(word_at::<L>(edges, size.x, t));
    let edges_b = unpack_edges::<L>(word_at::<L>(edges, size.x, b));
    let centre = unpack_edges::<L>(word_at::<L>(edges, size.x, p));
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
    Stencil {
        p,
        l,
        r,
        t,
        b,
        tl: neighbour_lanes::<L>(p, -1, -1, size),
        tr: neighbour_lanes::<L>(p, 1, -1, size),
        bl: neighbour_lanes::<L>(p, -1, 1, size),
        br: neighbour_lanes::<L>(p, 1, 1, size),
        beta,
        c,
        w_tl,
        w_tr,
        w_bl,
        w_br,
        total,
    }
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
/// (spec gtao-raymarch-hybrid §2.7 step 4's numerator), in the order the reference sums it.
#[inline]
fn weighted<L: Lanes, T: Term<L>>(terms: &[u32], width: u32, s: &Stencil<L>) -> T {
    T::load(terms, width, s.p) * L::splat(s.beta)
        + T::load(terms, width, s.l) * s.c.l
        + T::load(terms, width, s.r) * s.c.r
        + T::load(terms, width, s.t) * s.c.t
        + T::load(terms, width, s.b) * s.c.b
        + T::load(terms, width, s.tl) * s.w_tl
        + T::load(terms, width, s.tr) * s.w_tr
        + T::load(terms, width, s.bl) * s.w_bl
        + T::load(terms, width, s.br) * s.w_br
}
