//! XeGTAO Denoise (spec gtao-raymarch-hybrid §2.7): an edge-aware 3×3 filter, repeated
//! `max(1, DenoisePasses)` times; the last pass rescales by the 1.5 headroom.

use super::GtaoParams;
use crate::common::denoise_terms::unpack_edges;
use crate::common::math::sat;
use crate::common::screen_space::neighbour;
use crate::glam::{UVec2, vec4};

/// Result of one denoise pass at a pixel.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Denoised {
    /// Stored term for the next pass, `uint(a·255 + 0.5)` (earlier passes), or the final
    /// `min(255, uint(a·1.5·255 + 0.5))` (last pass; the clamp is aokit's, spec §7.5).
    pub term: u32,
    /// Whether this was the last pass (then `term/255` is the visibility).
    pub last: bool,
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
    let weighted = beta * term_at(terms, w, p)
        + c.x * term_at(terms, w, l)
        + c.y * term_at(terms, w, r)
        + c.z * term_at(terms, w, t)
        + c.w * term_at(terms, w, b)
        + w_tl * term_at(terms, w, neighbour(p, -1, -1, size))
        + w_tr * term_at(terms, w, neighbour(p, 1, -1, size))
        + w_bl * term_at(terms, w, neighbour(p, -1, 1, size))
        + w_br * term_at(terms, w, neighbour(p, 1, 1, size));
    let total = beta + c.x + c.y + c.z + c.w + w_tl + w_tr + w_bl + w_br;
    let value = weighted / total;
    let term = if last { ((value * 1.5 * 255.0 + 0.5) as u32).min(255) } else { (value * 255.0 + 0.5) as u32 };
    Denoised { term, last }
}

/// Stored term at `q` as a value in the /1.5 domain.
#[inline]
fn term_at(terms: &[u32], width: u32, q: UVec2) -> f32 {
    terms[(q.y * width + q.x) as usize] as f32 / 255.0
}
