//! Ray-cast G-buffer: one primary ray per pixel centre of the full target (spec svao-raysd §1),
//! the CPU counterpart of the raster pass in `aokit_shaders::gbuffer`.

use crate::{Progress, SceneBvh};
use aokit_shaders::common::camera::Camera;
use aokit_shaders::common::normal_codec::encode_normal;
use aokit_shaders::glam::{UVec2, Vec3};
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

/// Cast one primary ray per pixel centre. `face_normals[i]` is triangle `i`'s world face normal.
pub fn ray_cast_gbuffer(bvh: &SceneBvh, face_normals: &[Vec3], camera: &Camera, progress: Progress) -> GBufferImage {
    let size = camera.view.size();
    let eye = camera.eye();
    let far = camera.view.far;
    let mut depth = vec![far; (size.x * size.y) as usize];
    let mut normals = vec![0u32; depth.len()];
    depth
        .par_chunks_mut(size.x as usize)
        .zip(normals.par_chunks_mut(size.x as usize))
        .enumerate()
        .for_each(|(y, (depth_row, normal_row))| {
            for x in 0..size.x {
                let uv = camera.view.pixel_uv(UVec2::new(x, y as u32));
                let dir = camera.primary_ray_direction(uv);
                if let Some(hit) = bvh.closest_hit(eye, dir, 0.0, f32::INFINITY) {
                    let d = camera.linear_depth_of_hit(dir, hit.t);
                    if d < far {
                        depth_row[x as usize] = d;
                        let n = camera.world_to_view.transform_vector3(face_normals[hit.triangle as usize]);
                        normal_row[x as usize] = encode_normal(n);
                    }
                }
            }
            progress(1);
        });
    GBufferImage { width: size.x, height: size.y, depth, normals }
}
