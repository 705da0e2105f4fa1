//! Visibility-bitmask AO (VBAO; Therrien, Levesque, Gilet 2023, spec vbao): XeGTAO's slices,
//! steps, MIP chain and denoiser, with the horizon of each slice replaced by a 32-bit mask of
//! angular sectors. Every depth sample occludes the sectors between its front angle and the
//! angle of the same sample pushed back by a thickness, so light passes behind thin occluders
//! (chair legs, railings, foliage) that horizon-based GTAO treats as infinitely thick walls.

pub mod kernel;
#[cfg(not(target_arch = "spirv"))]
pub mod settings;

pub use kernel::{SECTORS, sector_bits, vbao_pixel};

use crate::common::read::write;
use crate::glam::UVec3;
use crate::gtao::{GtaoFixed, GtaoParams};
use spirv_std::spirv;

/// `SectorRule::Paper` (spec vbao §3): start = ⌊N·lo⌋, count = ⌈N·(hi − lo)⌉.
pub const RULE_PAPER: u32 = 0;
/// `SectorRule::Touch` (spec vbao §3): every sector the interval touches, `[⌊N·lo⌋, ⌈N·hi⌉)`.
pub const RULE_TOUCH: u32 = 1;

/// `Weighting::Uniform` (spec vbao §4): `V_s = 1 − popcount(M)/N`, plain mean over slices.
pub const WEIGHT_UNIFORM: u32 = 0;
/// `Weighting::CosineBlender` (spec vbao §4): four groups of cos-weighted sectors, slices
/// weighted by the projected normal's length L.
pub const WEIGHT_COSINE_BLENDER: u32 = 1;
/// `Weighting::CosineExact` (spec vbao §4, aokit's): each free sector weighs the exact
/// cosine-weighted integral over its angles, the slice times L as in XeGTAO.
pub const WEIGHT_COSINE_EXACT: u32 = 2;

/// VBAO's push constants: XeGTAO's (slices, steps, radius, MIP offset, power, noise; the
/// falloff and thin-occluder fields are unread) plus the bitmask's own.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct VbaoParams {
    /// Thickness T of every depth sample along the view direction, world units (spec vbao §2.2).
    pub thickness: f32,
    /// Gate radius R_g (world units): samples farther than this from the pixel are skipped; 0
    /// keeps every sample (spec vbao §2.1).
    pub gate_radius: f32,
    /// [`WEIGHT_UNIFORM`], [`WEIGHT_COSINE_BLENDER`] or [`WEIGHT_COSINE_EXACT`].
    pub weighting: u32,
    /// [`RULE_PAPER`] or [`RULE_TOUCH`].
    pub sector_rule: u32,
    /// Last, at offset 16: a struct member must start on 16 bytes in a WGSL uniform block.
    pub gtao: GtaoParams,
}

impl VbaoParams {
    /// These constants with the specialization constants in place of the push constants when
    /// `specialized` is 1 (XeGTAO's fixed part, the weighting and the sector rule).
    #[inline]
    pub fn with_fixed(&self, specialized: u32, fixed: GtaoFixed, weighting: u32, sector_rule: u32) -> VbaoParams {
        VbaoParams {
            gtao: self.gtao.with_fixed(specialized, fixed),
            weighting: if specialized == 0 { self.weighting } else { weighting },
            sector_rule: if specialized == 0 { self.sector_rule } else { sector_rule },
            ..*self
        }
    }
}

/// VBAO's main pass, one invocation per pixel of the full target; the bindings are XeGTAO's
/// main pass's (spec vbao §1).
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "vbao_main"))]
#[allow(clippy::too_many_arguments)]
pub fn vbao_main(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &VbaoParams,
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
    let out = vbao_pixel(params, mips, normals, p);
    let i = (p.y * size.x + p.x) as usize;
    unsafe { write(terms, i, out.term) };
    unsafe { write(edges, i, out.edges) };
}
