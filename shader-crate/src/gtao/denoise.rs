//! XeGTAO Denoise (spec gtao-raymarch-hybrid §2.7): an edge-aware 3×3 filter, repeated
//! `max(1, DenoisePasses)` times; the last pass rescales by the 1.5 headroom.

use super::GtaoParams;
use crate::common::denoise_terms::{pack_bent_normal, pack_bent_term, unpack_bent_term, unpack_edges};
use crate::common::math::sat;
use crate::common::screen_space::neighbour;
use crate::glam::{UVec2, Vec4, vec3, vec4};
use core::ops::{Add, Mul};

/// Result of one denoise pass at a pixel.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Denoised {
    /// Stored term for the next pass, `uint(a·255 + 0.5)` (earlier passes), or the final
    /// `min(255, uint(a·1.5·255 + 0.5))` (last pass; the clamp is aokit's, spec §7.5).
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
/// packed `edges` (spec §2.7 steps 1–5).
#[inline]
pub fn denoise_pixel(params: &GtaoParams, terms: &[u32], edges: &[u32], p: UVec2) -> Denoised {
    let size = params.view.size();
    let passes = params.denoise_passes.max(1);
    let last = params.pass + 1 >= passes;
    let beta = centre_weight(params, last);
    let idx = |q: UVec2| (q.y * size.x + q.x) as usize;
    let (l, r, t, b) =
        (neighbour(p, -1, 0, size), neighbour(p, 1, 0, size), neighbour(p, 0, -1, size), neighbour(p, 0, 1, size));
    let edges_l = unpack_edges(edges[idx(l)]);
    let edges_r = unpack_edges(edges[idx(r)]);
    let edges_t = unpack_edges(edges[idx(t)]);
    let edges_b = unpack_edges(edges[idx(b)]);
    // 1. Symmetrize with the neighbours' opposite edges.
    let mut c = unpack_edges(edges[idx(p)]) * vec4(edges_l.y, edges_r.x, edges_t.w, edges_b.z);
    // 2. Leak: pixels with 3–4 edges get a little blur.
    let g = 0.5 * sat(1.5 - (c.x + c.y + c.z + c.w)) / 1.5;
    c = vec4(sat(c.x + g), sat(c.y + g), sat(c.z + g), sat(c.w + g));
    // 3. Diagonal weights from the raw neighbour edges.
    let w_tl = 0.425 * (c.x * edges_l.z + c.z * edges_t.x);
    let w_tr = 0.425 * (c.z * edges_t.y + c.y * edges_r.z);
    let w_bl = 0.425 * (c.w * edges_b.x + c.x * edges_l.w);
    let w_br = 0.425 * (c.y * edges_r.w + c.w * edges_b.y);
    let w = size.x;
    let stencil = Stencil {
        p,
        l,
        r,
        t,
        b,
        tl: neighbour(p, -1, -1, size),
        tr: neighbour(p, 1, -1, size),
        bl: neighbour(p, -1, 1, size),
        br: neighbour(p, 1, 1, size),
        beta,
        c,
        w_tl,
        w_tr,
        w_bl,
        w_br,
    };
    let total = beta + c.x + c.y + c.z + c.w + w_tl + w_tr + w_bl + w_br;
    if params.bent_normals != 0 {
        // Bent normals (spec §2.6.5): the four packed channels filtered alike; the last pass
        // normalizes the normal (returned in the G-buffer's right-handed space) and rescales.
        let value = weighted::<Vec4>(terms, w, &stencil) / total;
        if !last {
            return Denoised { term: pack_bent_term(value), last, visibility: 0.0 };
        }
        let n = vec3(value.x, value.y, value.z) * 2.0 - 1.0;
        let l = n.length();
        let n = if l > 0.0 { n / l } else { vec3(0.0, 0.0, -1.0) };
        let a = ((value.w * 1.5 * 255.0 + 0.5) as u32).min(255) as f32 / 255.0;
        return Denoised { term: pack_bent_normal(vec3(n.x, n.y, -n.z), a), last, visibility: a };
    }
    let value = weighted::<f32>(terms, w, &stencil) / total;
    let term = if last { ((value * 1.5 * 255.0 + 0.5) as u32).min(255) } else { (value * 255.0 + 0.5) as u32 };
    Denoised { term, last, visibility: term as f32 / 255.0 }
}

/// The 3×3 neighbourhood of a pixel (centre, L, R, T, B, TL, TR, BL, BR) and its weights:
/// β, the symmetrized edges C = (CL, CR, CT, CB) and the diagonal weights (spec §2.7).
struct Stencil {
    p: UVec2,
    l: UVec2,
    r: UVec2,
    t: UVec2,
    b: UVec2,
    tl: UVec2,
    tr: UVec2,
    bl: UVec2,
    br: UVec2,
    beta: f32,
    c: Vec4,
    w_tl: f32,
    w_tr: f32,
    w_bl: f32,
    w_br: f32,
}

/// A stored denoiser term: the AO value alone (0–255), or AO with a bent normal (RGBA8).
trait Term: Copy + Add<Output = Self> + Mul<f32, Output = Self> {
    /// The term at index `i`, each channel in [0, 1] (the /1.5 domain for the AO).
    fn load(terms: &[u32], i: usize) -> Self;
}

impl Term for f32 {
    #[inline]
    fn load(terms: &[u32], i: usize) -> f32 {
        terms[i] as f32 / 255.0
    }
}

impl Term for Vec4 {
    #[inline]
    fn load(terms: &[u32], i: usize) -> Vec4 {
        unpack_bent_term(terms[i])
    }
}

/// `β·a_c + CL·a_L + CR·a_R + CT·a_T + CB·a_B + wTL·a_TL + wTR·a_TR + wBL·a_BL + wBR·a_BR`
/// (spec §2.7 step 4's numerator), in the order the reference sums it.
#[inline]
fn weighted<T: Term>(terms: &[u32], width: u32, s: &Stencil) -> T {
    let i = |q: UVec2| (q.y * width + q.x) as usize;
    T::load(terms, i(s.p)) * s.beta
        + T::load(terms, i(s.l)) * s.c.x
        + T::load(terms, i(s.r)) * s.c.y
        + T::load(terms, i(s.t)) * s.c.z
        + T::load(terms, i(s.b)) * s.c.w
        + T::load(terms, i(s.tl)) * s.w_tl
        + T::load(terms, i(s.tr)) * s.w_tr
        + T::load(terms, i(s.bl)) * s.w_bl
        + T::load(terms, i(s.br)) * s.w_br
}
