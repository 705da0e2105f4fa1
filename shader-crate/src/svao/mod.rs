//! The two-phase Stenciled VAO pipeline (SVAO paper §3; spec svao-raysd §3, §5, §9): AO pass 1
//! on the depth buffer flags the samples that need more depth and, for the stochastic depth map,
//! records the ray interval each SD texel must cover; AO pass 2 refines exactly those samples
//! from a secondary source ([`Refine`]): the ray-traced SD map (`crate::raysd`) or rays traced
//! per sample (Ray-SVAO, `crate::raysvao`).

pub mod pass1;
pub mod pass2;
#[cfg(not(target_arch = "spirv"))]
pub mod settings;

pub use pass1::{Pass1Pixel, pass1_pixel, primary_sample, sd_pixel, sd_pixel_lanes};
pub use pass2::{Pass2Pixel, Refine, Refined, pass2_pixel};

use crate::common::camera::Camera;
use crate::common::lanes::Lanes;
use crate::common::read::write;
use crate::glam::{UVec2, uvec2};
use crate::vao::VaoParams;

/// Secondary depth source of pass 2 (spec svao-raysd §2 "secondary depth mode").
#[repr(u32)]
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Secondary {
    /// Plain VAO: pass 1 finalizes every pixel.
    Disabled = 0,
    /// The ray-traced stochastic depth map (Ray-SD, spec svao-raysd §7).
    StochasticDepth = 1,
    /// Rays per flagged sample (Ray-SVAO, spec svao-raysd §10), the papers' reference.
    Raytraced = 2,
}

/// Parameters of the two AO passes and of the SD map (spec svao-raysd §2 defaults in brackets).
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct SvaoParams {
    /// The VAO/HBAO+ kernel constants of both AO passes.
    pub vao: VaoParams,
    /// [`Secondary`] as `u32`.
    pub secondary: u32,
    /// Ray-interval optimisation on (1) or off (0) \[on\].
    pub interval: u32,
    /// Radius cutoff `t` in full-res pixels \[6\]: closer samples are never refined (spec svao-raysd §4.4).
    pub cutoff: f32,
    /// SD guard band `sg` in SD texels [512/div] (spec svao-raysd §3); 0 for Ray-SVAO.
    pub sd_guard: u32,
    /// Low-res size `L = ceil(W/div) × ceil(H/div)` of the SD map without its guard band.
    pub sd_low_res: UVec2,
    /// Layers `N` of the SD map \[4\]; 1, 2, 4 or 8.
    pub sd_layers: u32,
    /// `MAX_COUNT` of the reservoir any-hit \[8\], ≥ N (spec svao-raysd §7.3).
    pub max_count: u32,
    /// SD jitter table (`crate::common::tables::JitterTable` as `u32`) \[scrambled\].
    pub jitter: u32,
    /// Primary depth mode: 0 single depth, 1 dual depth (a depth-peeled second layer, spec svao-raysd §11).
    pub dual: u32,
    /// AO kernel: `KERNEL_VAO` (0) or `KERNEL_HBAO` (1) of `crate::vao::kernel` (spec svao-raysd §4.5).
    pub kernel: u32,
    /// AO samples per pixel `N = 8·2^sample_set`: 0 → 8 \[default\], 1 → 16, 2 → 32 (spec svao-raysd §2;
    /// larger values read as 2). Zero is the reference's 8, so a zero-filled record is valid.
    pub sample_set: u32,
    /// The frame's index in a sequence (0 for a single frame: the reference's noise): the SD
    /// maps' randomness follows it — the reservoir hash and the raster coverage-mask hashes are
    /// rotated by `crate::common::noise::frame_rotation`, the jitter index is offset (svao-raysd §7.2, §7.3,
    /// svao-raysd §8). The VAO/HBAO+ kernels' 4×4 rotation (svao-raysd §4.1.1) is deterministic and does not.
    pub noise_frame: u32,
    pub _pad0: u32,
    pub _pad1: u32,
    pub _pad2: u32,
}

impl SvaoParams {
    /// AO samples per pixel `N` of both passes: 8, 16 or 32 (spec svao-raysd §2, §4.2; [`SvaoParams::sample_set`]).
    #[inline]
    pub fn samples(&self) -> u32 {
        crate::common::tables::AO_SAMPLES << self.sample_set.min(2)
    }

    /// SD-map size including its guard band: `L + 2·sg` (spec svao-raysd §3).
    #[inline]
    pub fn sd_size(&self) -> UVec2 {
        self.sd_low_res + uvec2(2 * self.sd_guard, 2 * self.sd_guard)
    }

    /// Row-major index of SD texel `q`.
    #[inline]
    pub fn sd_index(&self, q: UVec2) -> usize {
        self.sd_index_lanes::<f32>(q.x, q.y) as usize
    }

    /// [`SvaoParams::sd_index`] of SD texels `(x, y)` per lane.
    #[inline]
    pub fn sd_index_lanes<L: Lanes>(&self, x: L::Index, y: L::Index) -> L::Index {
        y * L::index_splat(self.sd_size().x) + x
    }
}

/// Everything the SVAO passes and their rays read: a storage-buffer record (too big for
/// guaranteed push-constant space). `camera.view` and `params.vao.view` are the same projection.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct SvaoFrame {
    /// The camera (view transform and projection) of the frame.
    pub camera: Camera,
    /// The stenciled pipeline's constants.
    pub params: SvaoParams,
}

/// UNORM8 store of the intermediate AO of a flagged pixel (spec svao-raysd §5: `round(sat(A)·255)/255`).
#[inline]
pub fn unorm8(a: f32) -> f32 {
    #[allow(unused_imports)]
    use spirv_std::num_traits::Float;
    (crate::common::math::sat(a) * 255.0).round() / 255.0
}

use crate::common::gbuffer_read::GBufferSlices;
use crate::glam::UVec3;
use spirv_std::spirv;

/// Compute entry point of AO pass 1 (one invocation per inner pixel, pixel = id + guard). The
/// interval buffers must hold their clear values (spec svao-raysd §6).
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "svao_pass1"))]
pub fn svao_pass1(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[SvaoFrame],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] ao: &mut [f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] mask: &mut [u32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)]
    mut ray_min: &mut [u32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 6)]
    mut ray_max: &mut [u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 7)] depth2: &[f32],
) {
    let params = &frame[0].params;
    let view = &params.vao.view;
    let p = id.truncate() + view.guard;
    if !view.is_inner(p) {
        return;
    }
    let gbuffer = GBufferSlices { depth, normals, width: view.size().x };
    let out = pass1_pixel(&gbuffer, depth2, params, p, &mut ray_min, &mut ray_max);
    let i = view.index(p);
    unsafe { write(ao, i, out.ao) };
    mask[i] = out.mask;
}
