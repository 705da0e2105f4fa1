//! Raster G-buffer: linear view depth and the view-space face normal per pixel, over the full
//! target including the guard band (spec svao-raysd §1, pass 0 of §3).
//!
//! Triangles arrive de-indexed, each vertex carrying its triangle's face normal, so flat
//! interpolation yields the geometric normal the reference uses. Depth is written from the
//! perspective-correct view position rather than re-linearized from D32 (spec §1's `n·f/(…)`),
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
pub struct RasterParams {
    /// World → view (rigid transform).
    pub world_to_view: Mat4,
    pub view: ViewParams,
}

/// Vulkan clip position of a view-space point: `x/tx`, `−y/ty` (Vulkan's y points down, as the
/// spec's v does), reverse-Z `z_ndc = near/d` with `w = d`.
#[inline]
pub fn view_to_clip(view: &ViewParams, x: Vec3) -> Vec4 {
    vec4(x.x / view.tan_half_fov.x, -x.y / view.tan_half_fov.y, view.near, -x.z)
}

/// Vertex stage: world position (xyz), world face normal (xyz), texture coordinate and material
/// of a de-indexed triangle's corner.
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
