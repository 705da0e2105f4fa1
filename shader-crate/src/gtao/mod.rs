//! XeGTAO (Intel's ground-truth-based AO, spec gtao-raymarch-hybrid §2): a weighted depth MIP
//! chain (PrefilterDepths), horizon search over slices with the cosine-weighted arc integral
//! (MainPass), and an edge-aware 3×3 denoiser run 1–3 times. Optional pass 0 derives normals
//! from depth. View space here is XeGTAO's (+z forward); the G-buffer's right-handed normals are
//! converted by negating z (spec gtao-raymarch-hybrid §1.2).

pub mod denoise;
pub mod main_pass;
pub mod prefilter;
#[cfg(not(target_arch = "spirv"))]
pub mod settings;

pub use denoise::denoise_pixel;
pub use main_pass::{GtaoPixel, gtao_pixel, normal_from_depth};
pub use prefilter::prefilter_texel;

use crate::common::read::write;
#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use crate::common::ViewParams;
use crate::glam::{UVec2, uvec2};

/// Levels of the working-depth MIP chain (spec gtao-raymarch-hybrid §2.1).
pub const MIP_LEVELS: u32 = 5;

/// XeGTAO settings (spec gtao-raymarch-hybrid §2.1 defaults in brackets) plus the per-dispatch `pass` index.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct GtaoParams {
    /// Projection of the full target.
    pub view: ViewParams,
    /// Effect radius in world units [0.5; aokit: the scene's AO radius].
    pub radius: f32,
    /// [1.457]
    pub radius_multiplier: f32,
    /// [0.615]
    pub falloff_range: f32,
    /// [2.0]
    pub sample_distribution_power: f32,
    /// [0.0]
    pub thin_occluder_compensation: f32,
    /// [2.2]
    pub final_value_power: f32,
    /// [3.30]
    pub depth_mip_sampling_offset: f32,
    /// Slices per pixel (preset: Low 1, Medium 2, High 3, Ultra 9).
    pub slices: u32,
    /// Steps per side (Low/Medium 2, High/Ultra 3).
    pub steps: u32,
    /// Denoise passes 0–3 \[1\].
    pub denoise_passes: u32,
    /// Temporal noise frame (0 unless TAA + denoise, spec gtao-raymarch-hybrid §1.6).
    pub noise_frame: u32,
    /// Prefilter: 0 for MIPs 0–1, 1 for MIPs 2–4; denoise: the pass index.
    pub pass: u32,
    /// 1: the main pass also computes the bent normal and the terms are RGBA8 (spec gtao-raymarch-hybrid §2.6.5).
    pub bent_normals: u32,
    /// Pads the struct to a multiple of 8 bytes (ViewParams' vec2 alignment), so VbaoParams,
    /// which holds it, has the same layout in Rust and in SPIR-V.
    pub _pad: u32,
}

/// The settings a preset fixes, as the bits of the specialization constants of the same names
/// (`aokit_shaders::kernel::SpecConstantDecl`): a pipeline made with them lets the driver fold
/// the loop counts, the modes and the exponents, as XeGTAO's quality entry points fold their
/// compile-time constants.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct GtaoFixed {
    pub slices: u32,
    pub steps: u32,
    pub bent_normals: u32,
    pub thin_occluder_compensation: u32,
    pub sample_distribution_power: u32,
    pub final_value_power: u32,
    pub falloff_range: u32,
    pub radius_multiplier: u32,
    pub depth_mip_sampling_offset: u32,
}

impl GtaoParams {
    /// These parameters with [`GtaoFixed`]'s settings where `specialized` is 1 (an executor
    /// fixed them at pipeline creation, each equal to the pushed value); as pushed where it is 0.
    #[inline]
    pub fn with_fixed(&self, specialized: u32, fixed: GtaoFixed) -> GtaoParams {
        if specialized == 0 {
            return *self;
        }
        GtaoParams {
            slices: fixed.slices,
            steps: fixed.steps,
            bent_normals: fixed.bent_normals,
            thin_occluder_compensation: f32::from_bits(fixed.thin_occluder_compensation),
            sample_distribution_power: f32::from_bits(fixed.sample_distribution_power),
            final_value_power: f32::from_bits(fixed.final_value_power),
            falloff_range: f32::from_bits(fixed.falloff_range),
            radius_multiplier: f32::from_bits(fixed.radius_multiplier),
            depth_mip_sampling_offset: f32::from_bits(fixed.depth_mip_sampling_offset),
            ..*self
        }
    }

    /// `R = Radius·RadiusMultiplier` (spec gtao-raymarch-hybrid §2.6.2).
    #[inline]
    pub fn effective_radius(&self) -> f32 {
        self.radius * self.radius_multiplier
    }
}

/// Size of MIP `k` of the full target: `max(1, ⌊W/2^k⌋) × max(1, ⌊H/2^k⌋)` (spec gtao-raymarch-hybrid §1.5).
#[inline]
pub fn mip_size(full: UVec2, k: u32) -> UVec2 {
    use crate::common::lanes::Lanes;
    uvec2(f32::index_mip_extent(full.x, k), f32::index_mip_extent(full.y, k))
}

/// Offset of MIP `k` in the packed chain (levels one after another, row-major).
#[inline]
pub fn mip_offset(full: UVec2, k: u32) -> usize {
    let mut offset = 0;
    let mut j = 0;
    while j < k {
        let s = mip_size(full, j);
        offset += (s.x * s.y) as usize;
        j += 1;
    }
    offset
}

use crate::glam::UVec3;
use spirv_std::spirv;

/// PrefilterDepths in two dispatches (spec gtao-raymarch-hybrid §2.5): pass 0 makes MIPs 0–1,
/// one invocation per 2×2 block of MIP 0 (`⌈W/2⌉ × ⌈H/2⌉`, [`prefilter::prefilter_near`]); pass 1
/// makes MIPs 2–4, one invocation per 16×16 block of MIP 0 (`⌈W/16⌉ × ⌈H/16⌉`: a MIP 4 texel and
/// the MIP 2–3 texels over it; a partial last block has MIP 2–3 texels but no MIP 4 texel,
/// [`prefilter::prefilter_far`]).
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "gtao_prefilter"))]
pub fn gtao_prefilter(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &GtaoParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] depth: &[f32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)]
    mips: &mut [f32],
) {
    let b = id.truncate();
    let full = params.view.size();
    let mut mips = mips;
    if params.pass == 0 {
        let n = PREFILTER_BLOCK[0];
        if b.x < full.x.div_ceil(n) && b.y < full.y.div_ceil(n) {
            prefilter::prefilter_near(params, depth, &mut mips, b);
        }
    } else if b.x < full.x.div_ceil(PREFILTER_BLOCK[1]) && b.y < full.y.div_ceil(PREFILTER_BLOCK[1]) {
        prefilter::prefilter_far(params, &mut mips, b);
    }
}

/// The blocks of MIP 0 a prefilter invocation covers: pass 0 2×2 texels, pass 1 16×16 (dispatched
/// `⌈W/b⌉ × ⌈H/b⌉`).
pub const PREFILTER_BLOCK: [u32; 2] = [2, 16];

/// Pass 0: normals from depth, one invocation per pixel of the full target.
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "gtao_normals"))]
pub fn gtao_normals(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &GtaoParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] normals: &mut [u32],
) {
    let size = params.view.size();
    let p = id.truncate();
    if p.x >= size.x || p.y >= size.y {
        return;
    }
    unsafe { write(normals, (p.y * size.x + p.x) as usize, normal_from_depth(params, depth, p)) };
}

/// MainPass, one invocation per pixel of the full target.
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "gtao_main"))]
#[allow(clippy::too_many_arguments)]
pub fn gtao_main(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &GtaoParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] mips: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] terms: &mut [u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] edges: &mut [u32],
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
    let params = &params.with_fixed(specialized, fixed);
    let size = params.view.size();
    let p = id.truncate();
    if p.x >= size.x || p.y >= size.y {
        return;
    }
    let out = gtao_pixel(params, mips, normals, p);
    let i = (p.y * size.x + p.x) as usize;
    unsafe { write(terms, i, out.term) };
    unsafe { write(edges, i, out.edges) };
}

/// Denoise pass `params.pass`: terms in → terms out; the last pass also writes the visibility.
/// One invocation per pair of horizontally adjacent pixels (`⌈W/2⌉ × H`, as XeGTAO's
/// denoiser), whose shared neighbourhood is read once ([`denoise::denoise_pair`]).
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "gtao_denoise"))]
pub fn gtao_denoise(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &GtaoParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] terms_in: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] edges: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] terms_out: &mut [u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] ao: &mut [f32],
) {
    let size = params.view.size();
    let b = id.truncate();
    if b.x >= size.x.div_ceil(2) || b.y >= size.y {
        return;
    }
    let last = denoise::is_last_pass(params);
    let p = uvec2(2 * b.x, b.y);
    let second = p.x + 1 < size.x;
    let i = (p.y * size.x + p.x) as usize;
    if params.bent_normals != 0 {
        // One pixel at a time (a loop, so the module holds the RGBA8 filter once).
        let mut k = 0;
        while k < 1 + second as u32 {
            let out = denoise_pixel(params, terms_in, edges, uvec2(p.x + k, p.y));
            store_denoised(terms_out, ao, i + k as usize, out.term, out.visibility, last);
            k += 1;
        }
        return;
    }
    let [(t0, v0), (t1, v1)] = denoise::denoise_pair(params, terms_in, edges, b);
    store_denoised(terms_out, ao, i, t0, v0, last);
    if second {
        store_denoised(terms_out, ao, i + 1, t1, v1, last);
    }
}

/// A denoised pixel at index `i`: its term for the next pass and, in the last pass, its
/// visibility.
#[inline]
fn store_denoised(terms_out: &mut [u32], ao: &mut [f32], i: usize, term: u32, visibility: f32, last: bool) {
    unsafe { write(terms_out, i, term) };
    if last {
        unsafe { write(ao, i, visibility) };
    }
}
