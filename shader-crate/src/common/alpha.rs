//! Alpha test of `alphaMode: MASK` materials (glTF 2.0 §3.9.4): nearest texel with repeat
//! wrapping, cut out below the material's cutoff. The raster G-buffer discards such fragments;
//! CPU rays skip such hits.
//!
//! The tables are per triangle: `uvs[3·i ..]` (corners), `materials[i]`. A GPU any-hit looks up
//! triangle `i = InstanceCustomIndex + PrimitiveId`: aokit's own TLAS has one instance with
//! custom index 0; an engine's own TLAS gives every instance the index of its geometry's first
//! triangle in the tables (one geometry per BLAS, instances of one BLAS share the index; the
//! custom index has 24 bits). A triangle beyond the tables is opaque.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use crate::glam::Vec2;

/// Where a material's alpha texels live in the packed texel buffer. `width == 0`: opaque.
#[repr(C)]
#[derive(Copy, Clone, Debug, Default, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct AlphaMaskHeader {
    /// Index of the first texel in the texel buffer.
    pub offset: u32,
    /// Mask width in texels (0: opaque material).
    pub width: u32,
    /// Mask height in texels.
    pub height: u32,
    /// Texels with alpha below this are cut out.
    pub cutoff: f32,
}

/// Does the surface of `material` at texture coordinate `uv` survive the alpha test?
#[inline]
pub fn alpha_test_passes(headers: &[AlphaMaskHeader], texels: &[f32], material: u32, uv: Vec2) -> bool {
    if material as usize >= headers.len() {
        return true;
    }
    let h = headers[material as usize];
    if h.width == 0 || h.height == 0 {
        return true;
    }
    let u = uv.x - uv.x.floor();
    let v = uv.y - uv.y.floor();
    let x = ((u * h.width as f32) as u32).min(h.width - 1);
    let y = ((v * h.height as f32) as u32).min(h.height - 1);
    let i = (h.offset + y * h.width + x) as usize;
    i >= texels.len() || texels[i] >= h.cutoff
}

/// Alpha test of triangle `prim` at hit barycentrics `bary` (weights of its second and third
/// corner): the corner texture coordinates `uvs[3·prim ..]` interpolated, then
/// [`alpha_test_passes`] with the triangle's material. What every any-hit shader and the CPU's
/// BVH callbacks run.
#[inline]
pub fn triangle_alpha_passes(
    uvs: &[Vec2],
    materials: &[u32],
    headers: &[AlphaMaskHeader],
    texels: &[f32],
    prim: u32,
    bary: Vec2,
) -> bool {
    // A triangle outside the tables (an engine instance without alpha data) is opaque.
    let i = 3 * prim as usize;
    if prim as usize >= materials.len() || i + 2 >= uvs.len() {
        return true;
    }
    let uv = uvs[i] * (1.0 - bary.x - bary.y) + uvs[i + 1] * bary.x + uvs[i + 2] * bary.y;
    alpha_test_passes(headers, texels, materials[prim as usize], uv)
}

/// The per-triangle alpha tables a ray's candidates are tested against (the scene's `uvs`,
/// `materials`, `mask_headers` and `mask_texels` bindings).
#[derive(Copy, Clone)]
pub struct AlphaTables<'a> {
    pub uvs: &'a [Vec2],
    pub materials: &'a [u32],
    pub headers: &'a [AlphaMaskHeader],
    pub texels: &'a [f32],
}

impl AlphaTables<'_> {
    /// [`triangle_alpha_passes`] over these tables.
    #[inline]
    pub fn passes(&self, triangle: u32, bary: Vec2) -> bool {
        triangle_alpha_passes(self.uvs, self.materials, self.headers, self.texels, triangle, bary)
    }
}

/// An occlusion ray's decision: the first candidate that survives the alpha test ends the ray.
impl crate::common::any_hit::CandidateHit for AlphaTables<'_> {
    #[inline]
    fn decide(&mut self, _t: f32, bary: Vec2, triangle: u32) -> u32 {
        use crate::common::any_hit::{ACCEPT_AND_END, IGNORE};
        if self.passes(triangle, bary) { ACCEPT_AND_END } else { IGNORE }
    }
}
