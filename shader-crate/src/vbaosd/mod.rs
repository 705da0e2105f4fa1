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
use crate::common::read::{read, write};
use crate::common::screen_space::view_pos;
use crate::glam::{UVec2, UVec3, Vec2, Vec3, vec3};
use crate::gtao::main_pass::{PixelSetup, final_visibility, pixel_setup, sample_pair, slice_frame};
use crate::gtao::{GtaoFixed, GtaoPixel};
use crate::raysd::{MAX_LAYERS, texel_ray_uv};
use crate::svao::{SvaoFrame, SvaoParams, sd_pixel};
use crate::vbao::VbaoParams;
use crate::vbao::kernel::{EDGE_TOLERANCE, Occupancy, OwnSlice, interval_bits, own_slice, vbao_term, visibility_with};
use spirv_std::spirv;

/// A sample counts as flagged when it lies above P's tangent plane by more than this fraction
/// of its distance, `(Q − P)·n > FLAG_SLOPE·|Q − P|` (spec vbao §8.1). In the sample's own slice
/// `(Q − P)·n = |Q − P|·L·sin β`, β its angle above the half-circle's edge, and a sector is set
/// only for β above the edge tolerance min(0.02/L, 2π/32) ([`EDGE_TOLERANCE`]): in every slice
/// with L ≥ 0.1 that needs `(Q − P)·n ≥ 0.0199·|Q − P|`. 0.9 of it leaves margin for rounding
/// and stays above the G-buffer normal's error (0.0166), so a plane flags nothing.
pub const FLAG_SLOPE: f32 = 0.9 * EDGE_TOLERANCE;

/// Layers closer than this fraction of the sample's depth behind it are the sample's own
/// surface, not a layer behind it (spec vbao §8.2).
pub const SAME_SURFACE: f32 = 1e-3;

/// Is sample `delta = Q − P` flagged (spec vbao §8.1): within the gate and above the tangent
/// plane by [`FLAG_SLOPE`]? Only such samples can set sectors (in slices with L ≥ 0.1),
/// whatever lies behind them; the others keep `vbao`'s bits.
#[inline]
pub fn flagged(params: &VbaoParams, delta: Vec3, px: &PixelSetup) -> bool {
    let len_sq = delta.dot(delta);
    let gate = params.gate_radius;
    let inside = gate <= 0.0 || len_sq <= gate * gate;
    inside && delta.dot(px.n) > FLAG_SLOPE * len_sq.sqrt()
}

/// How far behind a flagged sample its SD texel's ray must reach, world units (spec vbao
/// §8.1): `2·R_g` (R_g = the effective radius without a gate), the longest chord behind a
/// sample inside the gate sphere.
#[inline]
pub fn reach(params: &VbaoParams, px: &PixelSetup) -> f32 {
    2.0 * if params.gate_radius > 0.0 { params.gate_radius } else { px.r }
}

/// The uv of a point in XeGTAO's view space (+z forward): the camera's `view_to_uv` of the same
/// point in the right-handed view space.
#[inline]
fn uv_of(sd: &SvaoParams, q: Vec3) -> crate::glam::Vec2 {
    sd.vao.view.view_to_uv(vec3(q.x, q.y, -q.z))
}

/// Phase 1 for one pixel (spec vbao §8.1): every flagged sample widens its SD texel's ray
/// interval to `[|Q|, |Q| + reach]` (Euclidean camera distances, by atomic min / max of their
/// ordered bits); the texels no sample asks for are not traced.
#[inline]
pub fn request_pixel<A: AtomicU32Buffer, B: AtomicU32Buffer>(
    params: &VbaoParams,
    sd: &SvaoParams,
    mips: &[f32],
    normals: &[u32],
    p: UVec2,
    ray_min: &mut A,
    ray_max: &mut B,
) {
    let g = &params.gtao;
    let (_, valid, px) = pixel_setup::<f32>(g, mips, normals, p);
    if !valid {
        return;
    }
    let reach = reach(params, &px);
    let mut s = 0;
    while s < g.slices.max(1) {
        let sl = slice_frame(g, &px, s);
        let mut k = 0;
        while k < g.steps.max(1) {
            let (q0, q1) = sample_pair(g, mips, &px, &sl, s, k);
            let mut side = 0;
            while side < 2 {
                let q = if side == 0 { q0 } else { q1 };
                if flagged(params, q - px.pos, &px) {
                    let i = sd.sd_index(sd_pixel(uv_of(sd, q), sd));
                    let t = q.length();
                    // Neighbouring pixels ask the same texels: an atomic only where it widens.
                    let (lo, hi) = (ordered_bits(t), ordered_bits(t + reach));
                    if ray_min.peek(i) > lo {
                        ray_min.atomic_min(i, lo);
                    }
                    if ray_max.peek(i) < hi {
                        ray_max.atomic_max(i, hi);
                    }
                }
                side += 1;
            }
            k += 1;
        }
        s += 1;
    }
}

/// The occupied segments behind a sample from the SD map (spec vbao §8.2): the layers of the
/// sample's SD texel behind it, sorted by depth, read as exits and entries of closed surfaces —
/// the sample's own solid reaches the first (at least T deep), the next two bound a hidden
/// solid, and so on; an entry without an exit, and a sample without any layer behind it, get
/// `vbao`'s constant thickness. Samples that are not [`flagged`] are `vbao`'s.
pub struct SdLayers<'a> {
    /// `N` normalized depths per SD texel (1 = empty), row-major over the SD size.
    pub map: &'a [f32],
    pub sd: &'a SvaoParams,
    /// The working-depth MIP chain; its MIP 0 gives the surface the texel's ray enters.
    pub mips: &'a [f32],
}

/// Layer `k` of the `n` at `map[base..]` as a view depth if it lies deeper than `after`, else
/// (and for k ≥ n, reading the last) the far plane.
#[inline]
fn layer_at(map: &[f32], view: &ViewParams, base: usize, n: usize, k: usize, after: f32) -> f32 {
    // SAFETY: `base` is the first layer of a texel inside the map (`sd_pixel` clamps it) and
    // the index stays below its `n`.
    let z = unsafe { read(map, base + k.min(n - 1)) };
    let d = z * (view.far - view.near) + view.near;
    if k < n && z < 1.0 && d > after { d } else { view.far }
}

impl SdLayers<'_> {
    /// The view depths of SD texel `texel`'s layers deeper than `after`, ascending, the far
    /// plane for the missing ones: [`MAX_LAYERS`] reads clamped to the texel's `N`, sorted by a
    /// network of min/max pairs on eight scalars (no array indexed per invocation, no branch).
    #[inline]
    fn layers_behind(&self, texel: UVec2, after: f32) -> [f32; MAX_LAYERS] {
        let sd = self.sd;
        let view = &sd.vao.view;
        let n = sd.sd_layers as usize;
        let base = sd.sd_index(texel) * n;
        // A function, not a closure: a closure over `self` leaves a struct of pointers in the
        // SPIR-V that naga rejects.
        let map = self.map;
        let (mut l0, mut l1, mut l2, mut l3) = (
            layer_at(map, view, base, n, 0, after),
            layer_at(map, view, base, n, 1, after),
            layer_at(map, view, base, n, 2, after),
            layer_at(map, view, base, n, 3, after),
        );
        // Four more only for N = 8 (the same branch in every invocation).
        let (mut l4, mut l5, mut l6, mut l7) = if n > 4 {
            (
                layer_at(map, view, base, n, 4, after),
                layer_at(map, view, base, n, 5, after),
                layer_at(map, view, base, n, 6, after),
                layer_at(map, view, base, n, 7, after),
            )
        } else {
            (view.far, view.far, view.far, view.far)
        };
        // Batcher's odd–even merge sort of 8, written out: rust-gpu emits loops as written, and
        // a loop over an array indexes it per invocation.
        macro_rules! exchange {
            ($($a:ident $b:ident),*) => {
                $( let (lo, hi) = ($a.min($b), $a.max($b)); $a = lo; $b = hi; )*
            };
        }
        exchange!(l0 l1, l2 l3, l4 l5, l6 l7, l0 l2, l1 l3, l4 l6, l5 l7, l1 l2, l5 l6);
        exchange!(l0 l4, l1 l5, l2 l6, l3 l7, l2 l4, l3 l5, l1 l2, l3 l4, l5 l6);
        [l0, l1, l2, l3, l4, l5, l6, l7]
    }
}

impl Occupancy<f32> for SdLayers<'_> {
    #[inline]
    fn bits(&mut self, params: &VbaoParams, delta: Vec3, px: &PixelSetup, side: f32) -> u32 {
        let gate = params.gate_radius;
        if gate > 0.0 && delta.dot(delta) > gate * gate {
            return 0;
        }
        // `vbao`'s slab behind Q unless the map says Q's solid reaches farther; one own slice
        // and one code path for every sample (no second copy of `vbao`'s bits to branch to).
        let mut back = delta - px.v * params.thickness;
        let mut hidden = 0;
        let own = own_slice::<f32>(delta, px.v, px.n);
        let rule = params.sector_rule;
        if flagged(params, delta, px) {
            let sd = self.sd;
            let view = &sd.vao.view;
            let q = px.pos + delta;
            let texel = sd_pixel(uv_of(sd, q), sd);
            let uv = texel_ray_uv(texel, sd);
            // The texel's ray must enter Q's own surface (within T of Q's depth): at ¼
            // resolution and jittered it may pass beside a thin object and describe what lies
            // behind another. Then the layers behind Q, in depth order.
            // SAFETY: `texel_of_uv` clamps into the target, whose MIP 0 leads the chain.
            let entered = unsafe { read(self.mips, view.index(view.texel_of_uv(uv))) };
            let same_surface = (entered - q.z).abs() <= params.thickness;
            let after = if same_surface { q.z * (1.0 + SAME_SURFACE) } else { f32::MAX };
            let layers = self.layers_behind(texel, after);
            let first = layers[0];
            // Q's own solid reaches its first exit, but never less far than T: T also stands
            // for the occluders the sparse samples miss (thinner measured backs raised the
            // error on Sponza and the kitchen, spec vbao §8.3).
            if first < view.far && first > q.z + params.thickness {
                back = view_pos(view, uv, first) - px.pos;
            }
            // Hidden solids: (entry, exit) pairs of the following layers, an entry without
            // its exit as thick as T (written out, as the sort).
            hidden = hidden_bits(params, px, &own, uv, side, layers[1], layers[2])
                | hidden_bits(params, px, &own, uv, side, layers[3], layers[4])
                | hidden_bits(params, px, &own, uv, side, layers[5], layers[6])
                | hidden_bits(params, px, &own, uv, side, layers[7], view.far);
        }
        interval_bits(&own, delta, back, px.v, side, rule) | hidden
    }
}

/// The bits of a hidden solid (spec vbao §8.2) entered at view depth `entry` and left at `exit`
/// along the SD texel's ray through `uv` (no entry: the far plane; no exit: T deep), measured in
/// the flagged sample's own slice `own`, if its entry is inside the gate.
#[inline]
fn hidden_bits(
    params: &VbaoParams,
    px: &PixelSetup,
    own: &OwnSlice<f32>,
    uv: Vec2,
    side: f32,
    entry: f32,
    exit: f32,
) -> u32 {
    let view = &params.gtao.view;
    if entry >= view.far {
        return 0;
    }
    let front = view_pos(view, uv, entry) - px.pos;
    let back = if exit < view.far { view_pos(view, uv, exit) - px.pos } else { front - px.v * params.thickness };
    let gate = params.gate_radius;
    if gate > 0.0 && front.dot(front) > gate * gate {
        return 0;
    }
    interval_bits(own, front, back, px.v, side, params.sector_rule)
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
    request_pixel(params, &frame[0].params, mips, normals, p, &mut ray_min, &mut ray_max);
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
