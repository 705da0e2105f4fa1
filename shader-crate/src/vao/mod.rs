//! Volumetric Ambient Occlusion (Szirmay-Kalos et al. 2010, as used by the SVAO paper), single
//! depth: spec svao-raysd §4.1–§4.4 and the plain-VAO case of svao-raysd §5.

pub mod kernel;
#[cfg(not(target_arch = "spirv"))]
pub mod settings;

pub use kernel::{VaoParams, vao_pixel};

use crate::common::gbuffer_read::GBufferSlices;
use crate::common::read::write;
use crate::glam::UVec3;
use spirv_std::spirv;

/// Compute entry point: one invocation per inner pixel (pixel = id + guard). Writes the final
/// AO (1 = unoccluded) into the full-target `ao` buffer; guard-band texels are left untouched.
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "vao_main"))]
pub fn vao_main(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(push_constant)] params: &VaoParams,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] normals: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] ao: &mut [f32],
) {
    let p = id.truncate() + params.view.guard;
    if !params.view.is_inner(p) {
        return;
    }
    let gbuffer = GBufferSlices { depth, normals, width: params.view.size().x };
    unsafe { write(ao, params.view.index(p), vao_pixel(&gbuffer, params, p)) };
}
