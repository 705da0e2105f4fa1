//! Visibility-bitmask AO over the ray-traced stochastic depth map (`vbao-sd`, spec vbao §8):
//! `vbao`'s slices, samples, sector masks and denoiser, with each sample's occupied segments
//! read from the surface layers the SD map (`crate::raysd`) holds behind it instead of one
//! constant thickness.
//!
//! Two phases, as Ray-SD (spec svao-raysd §3): [`vbao_sd_request()`] flags the samples whose
//! sectors depend on what lies behind them and records, per SD texel, the ray interval they
//! need (spec svao-raysd §6); the SD map is traced only there; [`vbao_sd_main()`] builds the
//! masks, reading the map for the flagged samples (spec vbao §8.2).

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

#[cfg(not(target_arch = "spirv"))]
pub mod settings;

use crate::common::ViewParams;
use crate::common::atomics::AtomicU32Buffer;
use crate::common::float_order::ordered_bits;
use crate::common::lanes::{LaneVec3, Lanes, select_v3};
use crate::common::read::write;
use crate::common::screen_space::view_pos;
use crate::glam::{UVec2, UVec3};
use crate::gtao::main_pass::{PixelSetup, final_visibility, pixel_setup, sample_pair, slice_frame};
use crate::gtao::{GtaoFixed, GtaoPixel};
use crate::raysd::{MAX_LAYERS, texel_ray_uv_lanes};
use crate::svao::{SvaoFrame, SvaoParams, sd_pixel_lanes};
use crate::vbao::VbaoParams;
use crate::vbao::kernel::{
    EDGE_TOLERANCE, Occupancy, OwnSlice, beyond_gate, interval_bits, own_slice, vbao_term, visibility_with,
};
use spirv_std::spirv;

/// A sample counts as flagged when it lies above P's tangent plane by more than this fraction
/// of its distance, `(Q − P)·n > FLAG_SLOPE·|Q − P|` (spec vbao §8.1). In the sample's own slice
/// `(Q − P)·n = |Q − P|·L·sin β`, β its angle above the half-circle's edge, and a sector is set
/// only for β above the edge tolerance min(0.02/L, 2π/32) ([`EDGE_TOLERANCE`]): in every slice
/// with L ≥ 0.1 that needs `(Q − P)·n ≥ 0.0195·|Q − P|` (0.0199 for L ≥ 0.102, 0.0195 at the
/// cap, L = 0.1). 0.018 leaves margin for rounding and stays above the G-buffer normal's error
/// (0.0166), so a plane flags nothing.
pub const FLAG_SLOPE: f32 = 0.9 * EDGE_TOLERANCE;

/// Layers closer than this fraction of the sample's depth behind it are the sample's own
/// surface, not a layer behind it (spec vbao §8.2).
pub const SAME_SURFACE: f32 = 1e-3;

/// Is sample `delta = Q − P` flagged (spec vbao §8.1): within the gate and above the tangent
/// plane by [`FLAG_SLOPE`]? Only such samples can set sectors (in slices with L ≥ 0.1),
/// whatever lies behind them; the others keep `vbao`'s bits. Per lane.
#[inline]
pub fn flagged<L: Lanes>(params: &VbaoParams, delta: L::V3, px: &PixelSetup<L>) -> L::Mask {
    let above = delta.dot(px.n).gt(delta.dot(delta).sqrt() * FLAG_SLOPE);
    L::and(L::not(beyond_gate::<L>(params, delta)), above)
}

/// How far behind a flagged sample its SD texel's ray must reach, world units (spec vbao
/// §8.1): `2·R_g` (R_g = the effective radius without a gate), the longest chord behind a
/// sample inside the gate sphere.
#[inline]
pub fn reach(params: &VbaoParams, effective_radius: f32) -> f32 {
    2.0 * if params.gate_radius > 0.0 { params.gate_radius } else { effective_radius }
}

/// Phase 1 for one pixel, or `L::LANES` pixels (spec vbao §8.1): every flagged sample widens
/// its SD texel's ray interval to `[|Q|, |Q| + reach]` (Euclidean camera distances, by atomic
/// min / max of their ordered bits); the texels no sample asks for are not traced.
#[inline]
pub fn request_pixel<L: Lanes, A: AtomicU32Buffer, B: AtomicU32Buffer>(
    params: &VbaoParams,
    sd: &SvaoParams,
    mips: &[f32],
    normals: &[u32],
    p: L::U2,
    ray_min: &mut A,
    ray_max: &mut B,
) {
    let g = &params.gtao;
    let (_, valid, px) = pixel_setup::<L>(g, mips, normals, p);
    if !L::any(valid) {
        return;
    }
    let reach = reach(params, px.r);
    let mut s = 0;
    while s < g.slices.max(1) {
        let sl = slice_frame(g, &px, s);
        let mut k = 0;
        while k < g.steps.max(1) {
            let (q0, q1) = sample_pair(g, mips, &px, &sl, s, k);
            request_sample::<L, A, B>(params, sd, &px, valid, q0, reach, ray_min, ray_max);
            request_sample::<L, A, B>(params, sd, &px, valid, q1, reach, ray_min, ray_max);
            k += 1;
        }
        s += 1;
    }
}

/// One sample's request (spec vbao §8.1), per lane where `valid` and [`flagged`].
#[inline]
fn request_sample<L: Lanes, A: AtomicU32Buffer, B: AtomicU32Buffer>(
    params: &VbaoParams,
    sd: &SvaoParams,
    px: &PixelSetup<L>,
    valid: L::Mask,
    q: L::V3,
    reach: f32,
    ray_min: &mut A,
    ray_max: &mut B,
) {
    let flag = L::and(valid, flagged::<L>(params, q - px.pos, px));
    if !L::any(flag) {
        return;
    }
    let (x, y) = sample_sd_texel::<L>(q, sd);
    let texel = sd.sd_index_lanes::<L>(x, y);
    let t = q.length();
    let mut i = 0;
    while i < L::LANES {
        if L::mask_lane(flag, i) {
            let at = L::index_lane(texel, i) as usize;
            // Neighbouring pixels ask the same texels: an atomic only where it widens.
            let (lo, hi) = (ordered_bits(t.lane(i)), ordered_bits(t.lane(i) + reach));
            if ray_min.peek(at) > lo {
                ray_min.atomic_min(at, lo);
            }
            if ray_max.peek(at) < hi {
                ray_max.atomic_max(at, hi);
            }
        }
        i += 1;
    }
}

/// Layer `k` of the `n` at `map[base..]` as a view depth if it lies deeper than `after`, else
/// (and for k ≥ n, reading the last) the far plane; per lane.
#[inline]
fn layer_at<L: Lanes>(map: &[f32], view: &ViewParams, base: L::Index, n: u32, k: u32, after: L) -> L {
    let z = L::gather_index(map, base + L::index_splat(k.min(n - 1)));
    let d = z * (view.far - view.near) + view.near;
    let kept = L::and(L::mask_splat(k < n), L::and(z.lt(L::splat(1.0)), d.gt(after)));
    L::select(kept, d, L::splat(view.far))
}

/// The view depths of the layers at `map[base..]` (N = `n`) deeper than `after`, ascending, the
/// far plane for the missing ones: [`MAX_LAYERS`] reads clamped to N, sorted by a network of
/// min/max pairs on eight values (no array indexed per invocation, no branch).
#[inline]
fn layers_behind<L: Lanes>(map: &[f32], view: &ViewParams, base: L::Index, n: u32, after: L) -> [L; MAX_LAYERS] {
    let (mut l0, mut l1, mut l2, mut l3) = (
        layer_at(map, view, base, n, 0, after),
        layer_at(map, view, base, n, 1, after),
        layer_at(map, view, base, n, 2, after),
        layer_at(map, view, base, n, 3, after),
    );
    // Four more only for N = 8 (the same branch in every invocation).
    let far = L::splat(view.far);
    let (mut l4, mut l5, mut l6, mut l7) = if n > 4 {
        (
            layer_at(map, view, base, n, 4, after),
            layer_at(map, view, base, n, 5, after),
            layer_at(map, view, base, n, 6, after),
            layer_at(map, view, base, n, 7, after),
        )
    } else {
        (far, far, far, far)
    };
    // Batcher's odd–even merge sort of 8, written out: rust-gpu emits loops as written, and a
    // loop over an array indexes it per invocation.
    macro_rules! exchange {
        ($($a:ident $b:ident),*) => {
            $( let (lo, hi) = ($a.min($b), $a.max($b)); $a = lo; $b = hi; )*
        };
    }
    exchange!(l0 l1, l2 l3, l4 l5, l6 l7, l0 l2, l1 l3, l4 l6, l5 l7, l1 l2, l5 l6);
    exchange!(l0 l4, l1 l5, l2 l6, l3 l7, l2 l4, l3 l5, l1 l2, l3 l4, l5 l6);
    [l0, l1, l2, l3, l4, l5, l6, l7]
}

/// The SD texel `(x, y)` under a sample at view point `q` (XeGTAO's +z-forward space) per lane:
/// `SDpixel` of its uv (spec svao-raysd §5, [`sd_pixel_lanes`]).
#[inline]
fn sample_sd_texel<L: Lanes>(q: L::V3, sd: &SvaoParams) -> (L::Index, L::Index) {
    // The right-handed view space (−z forward) gives the uv.
    sd_pixel_lanes::<L>(sd.vao.view.view_to_uv_lanes::<L>(L::V3::new(q.x(), q.y(), -q.z())), sd)
}

/// The occupied segments behind a sample from the SD map (spec vbao §8.2): the layers of the
/// sample's SD texel behind it, sorted by depth, read as exits and entries of closed surfaces —
/// the sample's own solid reaches the first (at least T deep), the next two bound a hidden
/// solid, and so on; an entry without an exit, and a sample without any layer behind it, get
/// `vbao`'s constant thickness. Samples that are not [`flagged`] are `vbao`'s. One pixel, or
/// `L::LANES` pixels (cpu-sim).
pub struct SdLayers<'a> {
    /// `N` normalized depths per SD texel (1 = empty), row-major over the SD size.
    pub map: &'a [f32],
    pub sd: &'a SvaoParams,
    /// The working-depth MIP chain; its MIP 0 gives the surface the texel's ray enters.
    pub mips: &'a [f32],
}

impl<L: Lanes> Occupancy<L> for SdLayers<'_> {
    #[inline]
    fn bits(&mut self, params: &VbaoParams, delta: L::V3, px: &PixelSetup<L>, side: f32) -> L::Index {
        let none = L::index_splat(0);
        let beyond = beyond_gate::<L>(params, delta);
        if !L::any(L::not(beyond)) {
            return none;
        }
        let t = params.thickness;
        // `vbao`'s slab behind Q unless the map says Q's solid reaches farther; one own slice
        // and one code path for every sample.
        let mut back = delta - px.v * L::splat(t);
        let mut hidden = none;
        let own = own_slice::<L>(delta, px.v, px.n);
        let rule = params.sector_rule;
        let flag = flagged::<L>(params, delta, px);
        if L::any(flag) {
            let sd = self.sd;
            let view = &sd.vao.view;
            let q = px.pos + delta;
            let (x, y) = sample_sd_texel::<L>(q, sd);
            let uv = texel_ray_uv_lanes::<L>(x, y, sd);
            // The texel's ray must enter Q's own surface (within T of Q's depth): at ¼
            // resolution and jittered it may pass beside a thin object and describe what lies
            // behind another. Then the layers behind Q, in depth order.
            let entered = L::gather_index(self.mips, view.index_lanes::<L>(view.texel_of_uv_lanes::<L>(uv)));
            let same_surface = L::and(flag, (entered - q.z()).abs().le(L::splat(t)));
            // Behind both Q and the surface the ray enters: the trace starts behind the
            // texel centre's depth, so on a slope the entered surface itself can be a layer.
            let after = L::select(same_surface, q.z().max(entered) * (1.0 + SAME_SURFACE), L::splat(f32::MAX));
            let n = sd.sd_layers;
            let base = sd.sd_index_lanes::<L>(x, y) * L::index_splat(n);
            let layers = layers_behind::<L>(self.map, view, base, n, after);
            // Q's own solid reaches its first exit, but never less far than T: T also stands
            // for the occluders the sparse samples miss (thinner measured backs raised the
            // error on Sponza and the kitchen, spec vbao §8.3).
            let far = L::splat(view.far);
            let deeper = L::and(layers[0].lt(far), layers[0].gt(q.z() + t));
            back = select_v3::<L>(deeper, view_pos::<L>(view, uv, layers[0]) - px.pos, back);
            // Hidden solids: (entry, exit) pairs of the following layers, an entry without its
            // exit as thick as T (written out, as the sort).
            hidden = hidden_bits::<L>(params, px, &own, uv, side, layers[1], layers[2])
                | hidden_bits::<L>(params, px, &own, uv, side, layers[3], layers[4])
                | hidden_bits::<L>(params, px, &own, uv, side, layers[5], layers[6])
                | hidden_bits::<L>(params, px, &own, uv, side, layers[7], far);
        }
        let bits = interval_bits(&own, delta, back, px.v, side, rule) | hidden;
        L::index_select(beyond, none, bits)
    }
}

/// The bits of a hidden solid (spec vbao §8.2) entered at view depth `entry` and left at `exit`
/// along the SD texel's ray through `uv` (no entry: the far plane; no exit: T deep), measured in
/// the flagged sample's own slice `own`, where its entry is inside the gate; per lane.
#[inline]
fn hidden_bits<L: Lanes>(
    params: &VbaoParams,
    px: &PixelSetup<L>,
    own: &OwnSlice<L>,
    uv: L::V2,
    side: f32,
    entry: L,
    exit: L,
) -> L::Index {
    let view = &params.gtao.view;
    let far = L::splat(view.far);
    let front = view_pos::<L>(view, uv, entry) - px.pos;
    let counted = L::and(entry.lt(far), L::not(beyond_gate::<L>(params, front)));
    if !L::any(counted) {
        return L::index_splat(0);
    }
    let back =
        select_v3::<L>(exit.lt(far), view_pos::<L>(view, uv, exit) - px.pos, front - px.v * L::splat(params.thickness));
    let bits = interval_bits(own, front, back, px.v, side, params.sector_rule);
    L::index_select(counted, bits, L::index_splat(0))
}

/// Phase 2 for one pixel (spec vbao §8.2): `vbao`'s pixel with [`SdLayers`] as the samples'
/// occupancy.
#[inline]
pub fn vbao_sd_pixel(
    params: &VbaoParams,
    sd: &SvaoParams,
    map: &[f32],
    mips: &[f32],
    normals: &[u32],
    p: UVec2,
) -> GtaoPixel {
    let (packed, valid, px) = pixel_setup::<f32>(&params.gtao, mips, normals, p);
    let vis = if valid { visibility_with(params, mips, &px, &mut SdLayers { map, sd, mips }) } else { 1.0 };
    GtaoPixel { term: vbao_term(valid, final_visibility(vis, params.gtao.final_value_power)), edges: packed }
}

/// Phase 1 (spec vbao §8.1), one invocation per pixel of the full target: the SD texels'
/// ray intervals for the flagged samples.
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "vbao_sd_request"))]
#[allow(clippy::too_many_arguments)]
pub fn vbao_sd_request(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &VbaoParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[SvaoFrame],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] mips: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] normals: &[u32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)]
    mut ray_min: &mut [u32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)]
    mut ray_max: &mut [u32],
    #[spirv(spec_constant(id = 0))] specialized: u32,
    #[spirv(spec_constant(id = 1))] slices: u32,
    #[spirv(spec_constant(id = 2))] steps: u32,
    #[spirv(spec_constant(id = 3))] bent_normals: u32,
    #[spirv(spec_constant(id = 4))] thin_occluder_compensation: u32,
    #[spirv(spec_constant(id = 5))] sample_distribution_power: u32,
    #[spirv(spec_constant(id = 6))] final_value_power: u32,
    #[spirv(spec_constant(id = 7))] falloff_range: u32,
    #[spirv(spec_constant(id = 8))] radius_multiplier: u32,
    #[spirv(spec_constant(id = 9))] depth_mip_sampling_offset: u32,
) {
    let fixed = GtaoFixed {
        slices,
        steps,
        bent_normals,
        thin_occluder_compensation,
        sample_distribution_power,
        final_value_power,
        falloff_range,
        radius_multiplier,
        depth_mip_sampling_offset,
    };
    // Specialized like the main pass (the slice and step loops get constant bounds); the
    // request reads no weighting or sector rule.
    let params = &params.with_fixed(specialized, fixed, params.weighting, params.sector_rule);
    let size = params.gtao.view.size();
    let p = id.truncate();
    if p.x >= size.x || p.y >= size.y {
        return;
    }
    request_pixel::<f32, _, _>(params, &frame[0].params, mips, normals, p, &mut ray_min, &mut ray_max);
}

/// Phase 2 (spec vbao §8.2), one invocation per pixel of the full target: `vbao_main` with the
/// flagged samples' segments from the SD map; XeGTAO's main-pass outputs (terms and edges).
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "vbao_sd_main"))]
#[allow(clippy::too_many_arguments)]
pub fn vbao_sd_main(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &VbaoParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[SvaoFrame],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] mips: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] sd_map: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] terms: &mut [u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] edges: &mut [u32],
    #[spirv(spec_constant(id = 0))] specialized: u32,
    #[spirv(spec_constant(id = 1))] slices: u32,
    #[spirv(spec_constant(id = 2))] steps: u32,
    #[spirv(spec_constant(id = 3))] bent_normals: u32,
    #[spirv(spec_constant(id = 4))] thin_occluder_compensation: u32,
    #[spirv(spec_constant(id = 5))] sample_distribution_power: u32,
    #[spirv(spec_constant(id = 6))] final_value_power: u32,
    #[spirv(spec_constant(id = 7))] falloff_range: u32,
    #[spirv(spec_constant(id = 8))] radius_multiplier: u32,
    #[spirv(spec_constant(id = 9))] depth_mip_sampling_offset: u32,
    #[spirv(spec_constant(id = 10))] weighting: u32,
    #[spirv(spec_constant(id = 11))] sector_rule: u32,
) {
    let fixed = GtaoFixed {
        slices,
        steps,
        bent_normals,
        thin_occluder_compensation,
        sample_distribution_power,
        final_value_power,
        falloff_range,
        radius_multiplier,
        depth_mip_sampling_offset,
    };
    let params = &params.with_fixed(specialized, fixed, weighting, sector_rule);
    let size = params.gtao.view.size();
    let p = id.truncate();
    if p.x >= size.x || p.y >= size.y {
        return;
    }
    let out = vbao_sd_pixel(params, &frame[0].params, sd_map, mips, normals, p);
    let i = (p.y * size.x + p.x) as usize;
    unsafe { write(terms, i, out.term) };
    unsafe { write(edges, i, out.edges) };
}
