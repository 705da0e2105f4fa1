//! Raster G-buffer: linear view depth and the view-space face normal per pixel, over the full
//! target including the guard band (spec svao-raysd §1, pass 0 of svao-raysd §3).
//!
//! Triangles arrive de-indexed, each vertex carrying its triangle's face normal, so flat
//! interpolation yields the geometric normal the reference uses. Depth is written from the
//! perspective-correct view position rather than re-linearized from D32 (spec svao-raysd §1's `n·f/(…)`),
//! which is more precise; the hardware depth only resolves visibility (reverse-Z, infinite far).

use crate::common::ViewParams;
use crate::common::alpha::{AlphaMaskHeader, alpha_test_passes};
use crate::common::normal_codec::encode_normal;
use crate::glam::{Mat4, Vec2, Vec3, Vec4, vec4};
use spirv_std::spirv;

/// Push constants of the G-buffer raster pass.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct RasterParams {
    /// World → view (rigid transform).
    pub world_to_view: Mat4,
    /// Projection of the full target.
    pub view: ViewParams,
    /// Depth peeling (spec svao-raysd §11): the second layer keeps only fragments farther than the first
    /// layer's depth plus this separation [0.01]. Unused by the first pass.
    pub peel_separation: f32,
    pub _pad0: u32,
    pub _pad1: u32,
    pub _pad2: u32,
}

/// Vulkan clip position of a view-space point: `x/tx`, `−y/ty` (Vulkan's y points down, as the
/// spec's v does), reverse-Z `z_ndc = near/d` with `w = d`.
#[inline]
pub fn view_to_clip(view: &ViewParams, x: Vec3) -> Vec4 {
    vec4(x.x / view.tan_half_fov.x, -x.y / view.tan_half_fov.y, view.near, -x.z)
}

/// Vertex stage: world position (xyz), world face normal (xyz), texture coordinate and material
/// of a de-indexed triangle's corner.
#[crate::kernel]
#[spirv(vertex(entry_point_name = "gbuffer_vs"))]
pub fn gbuffer_vs(
    position: Vec4,
    face_normal: Vec4,
    uv: Vec2,
    material: u32,
    #[spirv(push_constant)] params: &RasterParams,
    #[spirv(position)] clip: &mut Vec4,
    view_position: &mut Vec3,
    #[spirv(flat)] view_normal: &mut Vec3,
    out_uv: &mut Vec2,
    #[spirv(flat)] out_material: &mut u32,
) {
    let v = params.world_to_view * position.truncate().extend(1.0);
    *view_position = v.truncate();
    *view_normal = (params.world_to_view * face_normal.truncate().extend(0.0)).truncate();
    *out_uv = uv;
    *out_material = material;
    *clip = view_to_clip(&params.view, v.truncate());
}

/// Fragment stage: alpha test, then linear depth (R32_SFLOAT) and encoded view normal (R32_UINT).
#[crate::kernel]
#[spirv(fragment(entry_point_name = "gbuffer_fs"))]
pub fn gbuffer_fs(
    view_position: Vec3,
    #[spirv(flat)] view_normal: Vec3,
    uv: Vec2,
    #[spirv(flat)] material: u32,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] mask_headers: &[AlphaMaskHeader],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] mask_texels: &[f32],
    linear_depth: &mut f32,
    normal_code: &mut u32,
) {
    if !alpha_test_passes(mask_headers, mask_texels, material, uv) {
        spirv_std::arch::kill();
    }
    *linear_depth = -view_position.z;
    *normal_code = encode_normal(view_normal);
}

/// Does a fragment at linear depth `d` belong to the peeled second layer: farther than the first
/// layer's depth `first` plus `separation` (spec svao-raysd §11; the first layer's background = nothing
/// left to peel).
#[inline]
pub fn beyond_first_layer(d: f32, first: f32, separation: f32) -> bool {
    d > first + separation
}

/// Fragment shader of the depth-peeling pass (spec svao-raysd §11): the G-buffer fragment shader plus a
/// discard of everything up to the first layer's depth + separation at this pixel.
#[crate::kernel]
#[spirv(fragment(entry_point_name = "gbuffer_peel_fs"))]
pub fn gbuffer_peel_fs(
    #[spirv(frag_coord)] frag_coord: Vec4,
    view_position: Vec3,
    #[spirv(flat)] view_normal: Vec3,
    uv: Vec2,
    #[spirv(flat)] material: u32,
    #[spirv(push_constant)] params: &RasterParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] mask_headers: &[AlphaMaskHeader],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] mask_texels: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] first_depth: &[f32],
    linear_depth: &mut f32,
    normal_code: &mut u32,
) {
    let size = params.view.size();
    let x = (frag_coord.x as u32).min(size.x - 1);
    let y = (frag_coord.y as u32).min(size.y - 1);
    let d = -view_position.z;
    if !beyond_first_layer(d, first_depth[(y * size.x + x) as usize], params.peel_separation) {
        spirv_std::arch::kill();
    }
    if !alpha_test_passes(mask_headers, mask_texels, material, uv) {
        spirv_std::arch::kill();
    }
    *linear_depth = d;
    *normal_code = encode_normal(view_normal);
}
