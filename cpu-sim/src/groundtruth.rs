//! Ground-truth AO on the CPU: the kernel functions of `aokit_shaders::groundtruth` with rays
//! cast through the BVH, in parallel over rows.

use crate::gbuffer::{GBufferImage, Surfaces};
use crate::{Progress, SceneBvh};
use aokit_shaders::common::camera::Camera;
use aokit_shaders::common::math::is_valid_depth;
use aokit_shaders::common::normal_codec::decode_normal;
use aokit_shaders::glam::uvec2;
use aokit_shaders::groundtruth::{GroundTruthParams, finalize, hemisphere_direction, sample_2d, visibility_weight};
use rayon::prelude::*;

/// Ground-truth AO for every inner pixel of the G-buffer (full-target buffer, guard band = 1).
/// Each ray starts at the G-buffer point offset along its camera-facing face normal by a small
/// epsilon relative to the hit distance and the radius.
pub fn run_ground_truth(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    camera: &Camera,
    gbuffer: &GBufferImage,
    params: &GroundTruthParams,
    progress: Progress,
) -> Vec<f32> {
    let view = &camera.view;
    let size = view.size();
    let guard = view.guard;
    let eye = camera.eye();
    let uniform = params.uniform != 0;
    let mut out = vec![1.0f32; (size.x * size.y) as usize];
    out.par_chunks_mut(size.x as usize).enumerate().for_each(|(y, row)| {
        let y = y as u32;
        if y < guard || y + guard >= size.y {
            return;
        }
        for x in guard..size.x - guard {
            let p = uvec2(x, y);
            let d = gbuffer.depth[view.index(p)];
            if !is_valid_depth(d, view.far) {
                continue;
            }
            let dir = camera.primary_ray_direction(view.pixel_uv(p));
            let t = d / -camera.world_to_view.transform_vector3(dir).z;
            let mut n = camera.view_to_world.transform_vector3(decode_normal(gbuffer.normals[view.index(p)]));
            if n.dot(dir) > 0.0 {
                n = -n;
            }
            let origin = eye + dir * t + n * (1e-4 * (t + params.radius));
            let mut visible = 0.0;
            for k in 0..params.samples {
                let w = hemisphere_direction(n, sample_2d(k, p), uniform);
                if !bvh.occluded(origin, w, 0.0, params.radius, |tri, b| surfaces.passes_alpha(tri, b)) {
                    visible += visibility_weight(n, w, uniform);
                }
            }
            row[x as usize] = finalize(visible, params);
        }
        progress(1);
    });
    out
}
