//! Half resolution as a graph transform any technique can take (spec half-resolution): the
//! G-buffer's depth and normals reduced to half resolution by keeping one pixel of each 2×2
//! block ([`half_downsample()`], spec half-resolution §2), the technique run on that half-size
//! G-buffer, and its AO brought back to the full target by an upsample guided by the
//! full-resolution depth and normals ([`half_upsample()`], spec half-resolution §3).

#[cfg(not(target_arch = "spirv"))]
pub mod settings;

// f32 methods on SPIR-V (`abs`, `max`) come from `Lanes`.

use crate::common::ViewParams;
use crate::common::lanes::{LaneVec3, Lanes};
use crate::common::math::is_valid_depth;
use crate::common::normal_codec::decode_normal_lanes;
use crate::common::read::write;
use crate::glam::{UVec2, UVec3};
use spirv_std::spirv;

/// [`HalfParams::pick`]: the nearest pixel of the block on even texels (`(x + y)` even), the
/// farthest on odd ones (spec half-resolution §2).
pub const PICK_CHECKERBOARD: u32 = 0;
/// [`HalfParams::pick`]: always the nearest pixel of the block (spec half-resolution §2).
pub const PICK_NEAREST: u32 = 1;

/// Push constants of the downsample and the upsample.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct HalfParams {
    /// Projection of the full target `W×H` (both even; guard band `g` even).
    pub view: ViewParams,
    /// The same projection at half resolution: `res = (W/2, H/2)`, guard `g/2` (spec
    /// half-resolution §1).
    pub half: ViewParams,
    /// Which pixel of each 2×2 block the downsample keeps: [`PICK_CHECKERBOARD`] or
    /// [`PICK_NEAREST`].
    pub pick: u32,
    /// Plane tolerance `τ` of the upsample's depth weight, in pixel footprints `z·f` (`f = 2·ty/H`,
    /// the full target's pixel size at unit depth; spec half-resolution §3): a tap farther than
    /// `τ·z·f` from the pixel's tangent plane gets no weight.
    pub plane_tolerance: f32,
    pub _pad0: u32,
    pub _pad1: u32,
}

/// The full-target pixel that half-resolution texel `q` keeps (spec half-resolution §2): of the
/// 2×2 block `2q + {0, 1}²`, the one of least depth, or on the odd squares of a checkerboard
/// (`(q.x + q.y)` odd, with [`PICK_CHECKERBOARD`]) the one of greatest depth; ties go to the
/// first in row order.
#[inline]
pub fn kept_pixel(params: &HalfParams, depth: &[f32], q: UVec2) -> UVec2 {
    pick_in_block::<f32>(params, q, block_depths::<f32>(params, depth, q)).0
}

/// The depths of texel `q`'s block `2q + {0, 1}²`, in row order, read from the full target.
#[inline]
pub fn block_depths<L: Lanes>(params: &HalfParams, depth: &[f32], q: L::U2) -> [L; 4] {
    [
        block_depth::<L>(params, depth, q, 0, 0),
        block_depth::<L>(params, depth, q, 1, 0),
        block_depth::<L>(params, depth, q, 0, 1),
        block_depth::<L>(params, depth, q, 1, 1),
    ]
}

/// The depth of pixel `2q + (dx, dy)` (a function, not a closure: a closure capturing references
/// is a struct of references, which the SPIR-V back-end's validation refuses).
#[inline]
fn block_depth<L: Lanes>(params: &HalfParams, depth: &[f32], q: L::U2, dx: u32, dy: u32) -> L {
    let (x, y) = (L::texel_x(q), L::texel_y(q));
    let p = L::texel(x + x + L::index_splat(dx), y + y + L::index_splat(dy));
    L::gather_index(depth, params.view.index_lanes::<L>(p))
}

/// One step of [`pick_in_block`]: candidate `(x, y, d)` replaces `best` where it is better.
#[inline]
fn better_of<L: Lanes>(
    farthest: L::Mask,
    best: (L::Index, L::Index, L),
    x: L::Index,
    y: L::Index,
    d: L,
) -> (L::Index, L::Index, L) {
    let better = L::or(L::and(farthest, d.gt(best.2)), L::and(L::not(farthest), d.lt(best.2)));
    (L::index_select(better, x, best.0), L::index_select(better, y, best.1), L::select(better, d, best.2))
}

/// The pick rule of [`kept_pixel`] on the block's `depths` (row order, as [`block_depths`]
/// reads them): the kept pixel and its depth. Unrolled: an array indexed per step would be
/// indexed per invocation on the GPU.
#[inline]
pub fn pick_in_block<L: Lanes>(params: &HalfParams, q: L::U2, depths: [L; 4]) -> (L::U2, L) {
    let (qx, qy) = (L::texel_x(q), L::texel_y(q));
    let one = L::index_splat(1);
    let odd = L::index_eq((qx + qy) & one, one);
    let farthest = L::and(odd, L::mask_splat(params.pick == PICK_CHECKERBOARD));
    let [d0, d1, d2, d3] = depths;
    let (x0, y0) = (qx + qx, qy + qy);
    let (x1, y1) = (x0 + one, y0 + one);
    let best = (x0, y0, d0);
    let best = better_of::<L>(farthest, best, x1, y0, d1);
    let best = better_of::<L>(farthest, best, x0, y1, d2);
    let best = better_of::<L>(farthest, best, x1, y1, d3);
    (L::texel(best.0, best.1), best.2)
}

/// Largest relative change [`half_texel`] makes to the kept pixel's depth when it moves the point
/// along the kept pixel's tangent plane to the half texel's ray (spec half-resolution §2): beyond
/// it the plane runs almost along the ray, and the kept depth is used as it is.
pub const MAX_PLANE_SHIFT: f32 = 0.1;

/// Half texel `q`'s depth and encoded normal (spec half-resolution §2): [`kept_pixel`]'s normal,
/// and the depth at which the ray through `q`'s centre meets the kept pixel's tangent plane,
/// `d = (n·Xₖ)/(n·r)` with `Xₖ` the kept pixel's view position and `r` the ray at unit depth, so
/// that the technique's reconstruction of `q`'s position lies on the kept surface rather than up
/// to ½ pixel off it (below it, on a slope: a ray-traced technique would start inside the
/// geometry). The kept depth as it is where that moves it by more than [`MAX_PLANE_SHIFT`] or
/// the pixel is background.
#[inline]
pub fn half_texel(params: &HalfParams, depth: &[f32], normals: &[u32], q: UVec2) -> (f32, u32) {
    half_texel_of_block::<f32>(params, normals, q, block_depths::<f32>(params, depth, q))
}

/// `n.x·(ndc.x·tx)`: the column part of `n·r` for the ray `r = (ndc.x·tx, ndc.y·ty, −1)` through
/// column `c` of a target `width` wide (svao-raysd §1's uv→view at unit depth), shared by the
/// downsample's plane depth and the upsample's plane distance.
#[inline]
fn column_term<L: Lanes>(n: L::V3, tx: f32, c: L, width: f32) -> L {
    n.x() * ((c + 0.5) * (2.0 * tx / width) - tx)
}

/// `n.y·(ndc.y·ty)`: the row part of [`column_term`]'s `n·r`, for row `c` of a target `height`
/// high.
#[inline]
fn row_term<L: Lanes>(n: L::V3, ty: f32, c: L, height: f32) -> L {
    n.y() * (-((c + 0.5) * (2.0 * ty / height)) + ty)
}

/// [`half_texel`] from the block's depths (as [`block_depths`] reads them), for one texel
/// (`L = f32`, what the SPIR-V runs) or `L::LANES` texels, branch-free: cpu-sim calls it on its
/// lanes with the depths read straight from the block's two rows.
#[inline]
pub fn half_texel_of_block<L: Lanes>(params: &HalfParams, normals: &[u32], q: L::U2, depths: [L; 4]) -> (L, L::Index) {
    let (view, half) = (&params.view, &params.half);
    let (kept, d) = pick_in_block::<L>(params, q, depths);
    let code = L::gather_word(normals, view.index_lanes::<L>(kept));
    let n = decode_normal_lanes::<L>(code);
    // `n·r` for the ray `r = (ndc.x·tx, ndc.y·ty, −1)` through texel `t` of a target `res`
    // (svao-raysd §1's uv→view at unit depth): `Xₖ = d·rₖ`, so the plane's depth is
    // `d·(n·rₖ)/(n·r_q)`.
    let t = view.tan_half_fov;
    let ray_dot = |texel: L::U2, res: crate::glam::Vec2| {
        let (x, y) = (L::index_to_float(L::texel_x(texel)), L::index_to_float(L::texel_y(texel)));
        column_term::<L>(n, t.x, x, res.x) + row_term::<L>(n, t.y, y, res.y) - n.z()
    };
    let ratio = ray_dot(kept, view.res) / ray_dot(q, half.res);
    let keep_plane = L::and(is_valid_depth(d, view.far), (ratio - 1.0).abs().le(L::splat(MAX_PLANE_SHIFT)));
    (L::select(keep_plane, d * ratio, d), code)
}

/// The downsample, one invocation per texel of the half target: [`half_texel`]'s depth and
/// normal (one pixel's surface, never a mix).
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "half_downsample"))]
pub fn half_downsample(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &HalfParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] half_depth: &mut [f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] half_normals: &mut [u32],
) {
    let q = id.truncate();
    let size = params.half.size();
    if q.x >= size.x || q.y >= size.y {
        return;
    }
    let (d, n) = half_texel(params, depth, normals, q);
    let j = params.half.index(q);
    unsafe {
        write(half_depth, j, d);
        write(half_normals, j, n);
    }
}

/// The upsampled AO of full-target pixel `p` (spec half-resolution §3): over the 2×2 half texels
/// of `p`'s bilinear footprint, weights `bᵢ · max(0, 1 − dᵢ/(τ·z·f))` — `bᵢ` the bilinear weight,
/// `dᵢ = |n·(Xᵢ − X)|` the distance of tap `i`'s view position from `p`'s tangent plane (position
/// `X`, normal `n` from the full-resolution depth and normals), `z·f` the pixel's footprint —
/// normalized; a tap whose half texel is background gets weight 0. Where every weight is 0 (no
/// tap on `p`'s surface), the AO of the valid tap nearest the plane, or 1 (unoccluded) where
/// every tap is background. A background pixel takes its plain bilinear footprint.
#[inline]
pub fn upsample_pixel(
    params: &HalfParams,
    depth: &[f32],
    normals: &[u32],
    half_depth: &[f32],
    half_ao: &[f32],
    p: UVec2,
) -> f32 {
    upsample_lanes::<f32>(params, depth, normals, half_depth, half_ao, p)
}

/// [`upsample_pixel`] for one pixel (`L = f32`) or `L::LANES` pixels `p` (cpu-sim's
/// lanes), branch-free: every tap's weight and the nearest tap are chosen by selects.
#[inline]
pub fn upsample_lanes<L: Lanes>(
    params: &HalfParams,
    depth: &[f32],
    normals: &[u32],
    half_depth: &[f32],
    half_ao: &[f32],
    p: L::U2,
) -> L {
    let (view, half) = (&params.view, &params.half);
    let i = view.index_lanes::<L>(p);
    let z = L::gather_index(depth, i);
    let surface = is_valid_depth(z, view.far);
    let n = decode_normal_lanes::<L>(L::gather_word(normals, i));
    let (px, py) = (L::index_to_float(L::texel_x(p)), L::index_to_float(L::texel_y(p)));
    // The view position of a texel centre `c` at depth `d` is `d·r` with the ray
    // `r = (ndc.x·tx, ndc.y·ty, −1)` (svao-raysd §1), so the distance of a tap from p's plane,
    // `|n·(d·r − X)|`, is `|d·(n·r) − n·X|`; `n·r` splits into a column term, a row term and
    // `−n.z`, each computed once for the two tap columns and the two tap rows.
    let t = view.tan_half_fov;
    let column = |c: L, width: f32| column_term::<L>(n, t.x, c, width);
    let row = |c: L, height: f32| row_term::<L>(n, t.y, c, height);
    let plane_offset = z * (column(px, view.res.x) + row(py, view.res.y) - n.z());
    let footprint = 2.0 * t.y / view.res.y;
    let inverse_tolerance = L::splat(1.0) / (z * (params.plane_tolerance * footprint));
    // p's centre in half-texel units, texel centres at integers: (p + ½)/2 − ½.
    let (sx, sy) = (px * 0.5 - 0.25, py * 0.5 - 0.25);
    let (bx, by) = (sx.floor(), sy.floor());
    let (fx, fy) = (sx - bx, sy - by);
    // Taps clamped to the half inner image [g/2, W/2 − g/2 − 1]: its guard band holds no AO.
    let size = half.size();
    let g = half.guard as f32;
    let clamp =
        |b: L, d: f32, extent: u32| (b + d).clamp_between(L::splat(g), L::splat((extent - half.guard - 1) as f32));
    let columns = [clamp(bx, 0.0, size.x), clamp(bx, 1.0, size.x)];
    let rows = [clamp(by, 0.0, size.y), clamp(by, 1.0, size.y)];
    let column_terms = [column(columns[0], half.res.x), column(columns[1], half.res.x)];
    let row_terms = [row(rows[0], half.res.y), row(rows[1], half.res.y)];
    let (mut sum, mut weights) = (L::splat(0.0), L::splat(0.0));
    let (mut nearest, mut nearest_distance) = (L::splat(1.0), L::splat(f32::MAX));
    let mut k: usize = 0;
    while k < 4 {
        let (dx, dy) = (k & 1, k >> 1);
        let texel =
            L::texel(columns[dx].floor_index(L::index_splat(size.x)), rows[dy].floor_index(L::index_splat(size.y)));
        let j = half.index_lanes::<L>(texel);
        let a = L::gather_index(half_ao, j);
        let zt = L::gather_index(half_depth, j);
        let wx = if dx == 0 { -fx + 1.0 } else { fx };
        let wy = if dy == 0 { -fy + 1.0 } else { fy };
        let bilinear = wx * wy;
        let distance = (zt * (column_terms[dx] + row_terms[dy] - n.z()) - plane_offset).abs();
        let valid = is_valid_depth(zt, half.far);
        let plane = (-(distance * inverse_tolerance) + 1.0).max(L::splat(0.0));
        let w = L::select(surface, L::select(valid, bilinear * plane, L::splat(0.0)), bilinear);
        let closer = L::and(valid, distance.lt(nearest_distance));
        nearest = L::select(closer, a, nearest);
        nearest_distance = L::select(closer, distance, nearest_distance);
        sum = sum + w * a;
        weights = weights + w;
        k += 1;
    }
    L::select(weights.gt(L::splat(0.0)), sum / weights, nearest)
}

/// The upsample, one invocation per pixel of the full target's inner image:
/// `ao = upsample_pixel(…)`.
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "half_upsample"))]
pub fn half_upsample(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &HalfParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] half_depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] half_ao: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] ao: &mut [f32],
) {
    let p = id.truncate() + params.view.guard;
    if !params.view.is_inner(p) {
        return;
    }
    let value = upsample_pixel(params, depth, normals, half_depth, half_ao, p);
    unsafe { write(ao, params.view.index(p), value) };
}
