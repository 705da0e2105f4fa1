//! Import/export adapters between an engine's images (hardware depth, view-space normals, the AO
//! output image) and aokit's internal G-buffer layout (linear depth `f32`, octahedral `u32`
//! normals, full target with guard band).
//!
//! aokit's layout ([`crate::common::camera`]): every buffer covers the FULL target, the inner
//! image plus `view.guard` pixels on each side, row-major ([`ViewParams::index`]). Depth is the
//! linear view depth `d > 0` along −Z; `d >= view.far` is background (the kernels test
//! [`crate::common::math::is_valid_depth`]). Normals are unit VIEW-space normals (right-handed,
//! looking down −Z, y up) encoded by [`encode_normal`]. AO is `f32`, 1 = unoccluded.
//!
//! An engine's images cover the INNER image only (no guard band) with the same uv convention
//! (origin top-left, v down). The pure functions below do all the mapping and run on the CPU
//! (`aokit_cpu::adapters`) as well as inside the thin entry points:
//!
//! | entry point | set 0, binding 0 | binding 1 | push constants | invocations |
//! |---|---|---|---|---|
//! | `import_depth` | sampled image (depth or R32F) | storage buffer `f32` (written) | [`ImportParams`] | one per full-target pixel |
//! | `import_normals` | sampled image (RGBA unorm/float) | storage buffer `u32` (written) | [`ImportParams`] | one per full-target pixel |
//! | `export_ao_r32f` / `export_ao_r16f` / `export_ao_r8` | storage buffer `f32` (read) | storage image `r32f` / `r16f` / `r8` | [`ImportParams`] | one per engine texel |
//!
//! The input images are read with `OpImageFetch` (no sampler): a `D32_SFLOAT` depth image can
//! be sampled but not bound as a storage image. The export writes a storage image whose SPIR-V
//! format must match the view's (`R32_SFLOAT`, `R16_SFLOAT`, `R8_UNORM`), hence one entry point
//! per format rather than a format-less image (which would need the
//! `shaderStorageImageWriteWithoutFormat` feature); `r16f` and `r8` are "storage image extended
//! formats" (SPIR-V capability `StorageImageExtendedFormats`, unconditionally allowed in Vulkan:
//! Vulkan spec, appendix "Vulkan Environment for SPIR-V", capability table).

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use crate::common::ViewParams;
use crate::common::math::sat;
use crate::common::normal_codec::encode_normal;
use crate::glam::{UVec2, UVec3, Vec3};
use spirv_std::{Image, spirv};

#[cfg(not(target_arch = "spirv"))]
pub mod settings;

/// Depth conventions of the engine's depth image (`ImportParams::depth_convention`).
///
/// `z` below is the view depth (distance along −Z, > 0), `n`/`f` the ENGINE projection's near
/// and far planes, `d` the stored value. OpenGL's clip-space z ∈ [−1, 1] ends up in the depth
/// buffer as the same window depth `d ∈ [0, 1]` after the default `glDepthRange(0, 1)`
/// (OpenGL 4.6 core spec §13.8.1 "Controlling the Viewport"), and Vulkan's viewport transform
/// with `minDepth = 0, maxDepth = 1` stores `z_ndc ∈ [0, 1]` unchanged (Vulkan spec §"Controlling
/// the Viewport"), so one formula covers both APIs.
pub mod depth_convention {
    /// Hardware depth (e.g. `D32_SFLOAT`), standard perspective: `d = f·(z − n) / (z·(f − n))`,
    /// 0 at the near plane and 1 at the far plane. Inverse: `z = n·f / (f − d·(f − n))`.
    /// `d >= 1` (the cleared far plane) and NaN are background.
    pub const DEPTH_STANDARD: u32 = 0;
    /// Reversed Z with a finite far plane: `d = n·(f − z) / (z·(f − n))`, 1 at near, 0 at far.
    /// Inverse: `z = n·f / (n + d·(f − n))`. `d <= 0` (the cleared far plane) and NaN are
    /// background.
    pub const DEPTH_REVERSED: u32 = 1;
    /// Reversed Z with the far plane at infinity: `d = n / z`. Inverse: `z = n / d`; `f` is
    /// ignored. `d <= 0` (the cleared value, infinitely far) and NaN are background.
    pub const DEPTH_REVERSED_INFINITE: u32 = 2;
    /// The image (e.g. `R32_SFLOAT`) already holds the linear view depth: `z = d`. `d <= 0`,
    /// `d >= f`, NaN and ±∞ are background (pass `f = f32::MAX` when there is no far plane).
    pub const DEPTH_LINEAR: u32 = 3;
}

pub use depth_convention::*;

/// Returned by [`linear_depth`] for background (anything at or beyond the far plane, or
/// invalid); `>= view.far` for every view, so the kernels treat it as background.
pub const BACKGROUND_DEPTH: f32 = f32::MAX;

/// Push constants of every adapter entry point.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct ImportParams {
    /// aokit's full target (inner image + guard band) that the internal buffers cover.
    pub view: ViewParams,
    /// Size of the engine's images in texels (the inner image, no guard band; normally
    /// `view.size() − 2·view.guard`). Must be at least 1×1.
    pub engine_size: UVec2,
    /// One of [`depth_convention`] (import only).
    pub depth_convention: u32,
    /// Near plane of the ENGINE's projection (import only).
    pub near: f32,
    /// Far plane of the ENGINE's projection (import only; ignored by
    /// [`DEPTH_REVERSED_INFINITE`]). Choose `view.far <= far` so everything beyond the engine's
    /// far plane is background for aokit too.
    pub far: f32,
    pub _pad: u32,
}

/// Linear view depth `z` from a stored depth value `hw` (formulas in [`depth_convention`]);
/// background and invalid values give [`BACKGROUND_DEPTH`]. An unknown convention reads as
/// background everywhere.
#[inline]
pub fn linear_depth(hw: f32, convention: u32, near: f32, far: f32) -> f32 {
    // Each test fails for NaN, which so falls through to background.
    let z = if convention == DEPTH_STANDARD {
        if hw < 1.0 { near * far / (far - hw * (far - near)) } else { -1.0 }
    } else if convention == DEPTH_REVERSED {
        if hw > 0.0 { near * far / (near + hw * (far - near)) } else { -1.0 }
    } else if convention == DEPTH_REVERSED_INFINITE {
        if hw > 0.0 { near / hw } else { -1.0 }
    } else if convention == DEPTH_LINEAR {
        if hw < far { hw } else { -1.0 }
    } else {
        -1.0
    };
    // Non-positive or non-finite (a denominator rounded to ≤ 0, or `hw` out of range): background.
    if z > 0.0 && z < f32::MAX { z } else { BACKGROUND_DEPTH }
}

/// The engine texel that full-target pixel `p` reads: inner pixels map 1:1 (`p − guard`), guard
/// band pixels clamp to the nearest edge texel of the engine image (the engine renders no guard
/// band, so AO near the border sees the edge stretched outwards; with `guard = 0` the import is
/// exact).
#[inline]
pub fn engine_texel(params: &ImportParams, p: UVec2) -> UVec2 {
    let g = params.view.guard;
    let inner = p.max(UVec2::splat(g)) - g;
    inner.min(params.engine_size - 1)
}

/// Linear depth of full-target pixel `p` read through `fetch` (stored value of an engine
/// texel). Background is written as `view.far`, what aokit's own G-buffer stores there.
#[inline]
pub fn import_depth_pixel(params: &ImportParams, fetch: impl Fn(UVec2) -> f32, p: UVec2) -> f32 {
    let z = linear_depth(fetch(engine_texel(params, p)), params.depth_convention, params.near, params.far);
    if z < params.view.far { z } else { params.view.far }
}

/// Encoded normal from an engine texel holding a unit view-space normal as `n·0.5 + 0.5` in RGB
/// (decoded as `2c − 1`; not renormalized, [`encode_normal`] projects by the L1 norm anyway).
#[inline]
pub fn import_normal(rgb: Vec3) -> u32 {
    encode_normal(rgb * 2.0 - Vec3::ONE)
}

/// Encoded normal of full-target pixel `p` read through `fetch` (RGB of an engine texel), with
/// the guard band clamped like [`import_depth_pixel`].
#[inline]
pub fn import_normal_pixel(params: &ImportParams, fetch: impl Fn(UVec2) -> Vec3, p: UVec2) -> u32 {
    import_normal(fetch(engine_texel(params, p)))
}

/// Index in the full-target AO buffer of engine output texel `q`: the inner pixel `q + guard`
/// (clamped into the full target should `engine_size` exceed the inner image).
#[inline]
pub fn export_index(params: &ImportParams, q: UVec2) -> usize {
    params.view.index((q + params.view.guard).min(params.view.size() - 1))
}

/// Value of engine output texel `q`: the AO clamped to [0, 1] (NaN → 0, as [`sat`]).
#[inline]
pub fn export_texel(params: &ImportParams, ao: &[f32], q: UVec2) -> f32 {
    sat(ao[export_index(params, q)])
}

/// Is `p` inside a `size` grid (the bounds test of the rounded-up dispatches)?
#[inline]
fn inside(p: UVec2, size: UVec2) -> bool {
    p.x < size.x && p.y < size.y
}

/// Compute entry point: one invocation per FULL-target pixel; converts the engine's depth image
/// (binding 0, sampled, any convention of [`depth_convention`]) into the linear depth buffer
/// (binding 1).
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "import_depth"))]
pub fn import_depth(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &ImportParams,
    #[spirv(descriptor_set = 0, binding = 0)] engine_depth: &Image!(2D, type = f32, sampled),
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] depth: &mut [f32],
) {
    let p = id.truncate();
    if !inside(p, params.view.size()) {
        return;
    }
    depth[params.view.index(p)] = import_depth_pixel(params, |q| engine_depth.fetch(q.as_ivec2()).x, p);
}

/// Compute entry point: one invocation per FULL-target pixel; encodes the engine's view-space
/// normal image (binding 0, sampled, `n·0.5 + 0.5` in RGB) into the `u32` normal buffer
/// (binding 1).
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "import_normals"))]
pub fn import_normals(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &ImportParams,
    #[spirv(descriptor_set = 0, binding = 0)] engine_normals: &Image!(2D, type = f32, sampled),
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] normals: &mut [u32],
) {
    let p = id.truncate();
    if !inside(p, params.view.size()) {
        return;
    }
    normals[params.view.index(p)] = import_normal_pixel(params, |q| engine_normals.fetch(q.as_ivec2()).truncate(), p);
}

/// One export entry point per storage-image format: one invocation per engine texel, reading the
/// full-target AO buffer (binding 0) and writing the engine's AO image (binding 1).
macro_rules! export_entry_point {
    ($name:ident, $entry:tt, $format:ident) => {
        #[doc = concat!("Compute entry point: export the AO buffer into an `", stringify!($format), "` storage image.")]
        #[crate::kernel]
        #[spirv(compute(threads(8, 8), entry_point_name = $entry))]
        pub fn $name(
            #[spirv(global_invocation_id)] id: UVec3,
            #[spirv(push_constant)] params: &ImportParams,
            #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] ao: &[f32],
            #[spirv(descriptor_set = 0, binding = 1)] out: &Image!(2D, format = $format, sampled = false),
        ) {
            let q = id.truncate();
            if !inside(q, params.engine_size) {
                return;
            }
            unsafe { out.write(q, export_texel(params, ao, q)) };
        }
    };
}

export_entry_point!(export_ao_r32f, "export_ao_r32f", r32f);
export_entry_point!(export_ao_r16f, "export_ao_r16f", r16f);
export_entry_point!(export_ao_r8, "export_ao_r8", r8);
