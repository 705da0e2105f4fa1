//! Ray-cast G-buffer: one primary ray per pixel centre of the full target (spec svao-raysd §1),
//! the CPU counterpart of the raster pass in `aokit_shaders::gbuffer`.

use crate::bvh::packet_tiles;
use crate::{Progress, SceneBvh};
use aokit_shaders::common::alpha::{AlphaMaskHeader, AlphaTables, triangle_alpha_passes};
use aokit_shaders::common::camera::Camera;
use aokit_shaders::common::normal_codec::encode_normal;
use aokit_shaders::glam::{UVec2, Vec2, Vec3};
use rayon::prelude::*;

/// A G-buffer over the full target: linear view depth (`far` where nothing was hit) and the
/// octahedral-encoded view-space face normal, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct GBufferImage {
    pub width: u32,
    pub height: u32,
    pub depth: Vec<f32>,
    pub normals: Vec<u32>,
}

/// Per-triangle surface data the G-buffer needs besides the geometry in the BVH.
pub struct Surfaces<'a> {
    /// World face normal of each triangle.
    pub face_normals: &'a [Vec3],
    /// Texture coordinates of each triangle's corners.
    pub uvs: &'a [[Vec2; 3]],
    /// Material index of each triangle.
    pub materials: &'a [u32],
    /// Alpha masks per material (`alpha_test_passes`).
    pub mask_headers: &'a [AlphaMaskHeader],
    pub mask_texels: &'a [f32],
}

impl Surfaces<'_> {
    /// The alpha tables the kernels' any-hit decisions read; empty where no material has a
    /// mask, so that a candidate's alpha test (which every triangle then passes) reads no
    /// memory: the per-triangle materials and uvs are scattered reads, a cache miss per
    /// candidate on a large scene. Take them once per pass, not per candidate.
    pub fn alpha(&self) -> AlphaTables<'_> {
        if !self.masked() {
            return AlphaTables { uvs: &[], materials: &[], headers: &[], texels: &[] };
        }
        AlphaTables {
            uvs: self.uvs.as_flattened(),
            materials: self.materials,
            headers: self.mask_headers,
            texels: self.mask_texels,
        }
    }

    /// Does any material have an alpha mask (a texture the alpha test reads; a header of zero
    /// width or height is opaque)?
    pub fn masked(&self) -> bool {
        self.mask_headers.iter().any(|h| h.width > 0 && h.height > 0)
    }

    /// Alpha test of triangle `tri` at barycentrics `b` (weights of its 2nd and 3rd corner).
    pub fn passes_alpha(&self, tri: u32, b: Vec2) -> bool {
        triangle_alpha_passes(self.uvs.as_flattened(), self.materials, self.mask_headers, self.mask_texels, tri, b)
    }
}

/// Cast one primary ray per pixel centre; alpha-masked surfaces are skipped where cut out.
pub fn ray_cast_gbuffer(bvh: &SceneBvh, surfaces: &Surfaces, camera: &Camera, progress: Progress) -> GBufferImage {
    let masked = surfaces.masked();
    let alpha = surfaces.alpha();
    let size = camera.view.size();
    let eye = camera.eye();
    let far = camera.view.far;
    let mut depth = vec![far; (size.x * size.y) as usize];
    let mut normals = vec![0u32; depth.len()];
    // Bands of two rows traced as 4×2 packets (the same hits as single rays); one band per
    // work item, so that both threads stay busy to the end.
    let band = 2 * size.x as usize;
    depth.par_chunks_mut(band).zip(normals.par_chunks_mut(band)).with_max_len(1).enumerate().for_each(
        |(b, (depth_band, normal_band))| {
            let rows = depth_band.len() / size.x as usize;
            let pixel = |i: usize| UVec2::new((i % size.x as usize) as u32, (2 * b + i / size.x as usize) as u32);
            for tile in packet_tiles(size.x as usize, rows) {
                let dirs = tile.map(|i| camera.primary_ray_direction(camera.view.pixel_uv(pixel(i))));
                let hits = if masked {
                    bvh.closest_accepted_hits(eye, &dirs, 0.0, f32::INFINITY, |tri, b| alpha.passes(tri, b))
                } else {
                    bvh.closest_hits(eye, &dirs, 0.0, f32::INFINITY)
                };
                for ((&i, dir), hit) in tile.iter().zip(dirs).zip(hits) {
                    if let Some(hit) = hit {
                        let d = camera.linear_depth_of_hit(dir, hit.t);
                        if d < far {
                            depth_band[i] = d;
                            let n =
                                camera.world_to_view.transform_vector3(surfaces.face_normals[hit.triangle as usize]);
                            normal_band[i] = encode_normal(n);
                        }
                    }
                }
            }
            progress(rows as u64);
        },
    );
    GBufferImage { width: size.x, height: size.y, depth, normals }
}

/// The depth-peeled second layer (spec svao-raysd §11): per pixel, the nearest surface (alpha test
/// included) whose linear depth exceeds the first layer's by more than `separation`; the far
/// plane where there is none or the first layer is background.
pub fn ray_cast_second_layer(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    camera: &Camera,
    first: &GBufferImage,
    separation: f32,
) -> Vec<f32> {
    let size = camera.view.size();
    let far = camera.view.far;
    let eye = camera.eye();
    let alpha = surfaces.alpha();
    let mut depth2 = vec![far; (size.x * size.y) as usize];
    depth2.par_chunks_mut(size.x as usize).enumerate().for_each(|(y, row)| {
        for (x, out) in row.iter_mut().enumerate() {
            let p = UVec2::new(x as u32, y as u32);
            let d1 = first.depth[(p.y * size.x + p.x) as usize];
            if !aokit_shaders::common::math::is_valid_depth(d1, far) {
                continue;
            }
            let dir = camera.primary_ray_direction(camera.view.pixel_uv(p));
            let cos = camera.linear_depth_of_hit(dir, 1.0);
            let t_min = (d1 + separation) / cos;
            let hit = bvh.closest_accepted_hit(eye, dir, t_min, f32::INFINITY, |tri, b| alpha.passes(tri, b));
            if let Some(h) = hit {
                let d = camera.linear_depth_of_hit(dir, h.t);
                if d < far {
                    *out = d;
                }
            }
        }
    });
    depth2
}
