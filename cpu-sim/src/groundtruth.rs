//! Ground-truth AO on the CPU: `aokit_shaders::groundtruth::ground_truth_pixel`, with its
//! occlusion rays answered by the BVH (alpha test included), in parallel over rows.

use crate::gbuffer::{GBufferImage, Surfaces};
use crate::{Progress, SceneBvh};
use aokit_shaders::common::alpha::AlphaTables;
use aokit_shaders::common::gbuffer_read::GBufferSlices;
use aokit_shaders::glam::{Vec3, uvec2};
use aokit_shaders::groundtruth::{GroundTruthFrame, OcclusionQuery, ground_truth_pixel};
use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering};

/// BVH occlusion rays for the shared ground-truth kernel, the alpha test included
/// ([`Surfaces::alpha`]).
pub(crate) struct BvhOcclusion<'a> {
    pub(crate) bvh: &'a SceneBvh,
    pub(crate) alpha: AlphaTables<'a>,
}

impl OcclusionQuery for BvhOcclusion<'_> {
    fn occluded(&mut self, origin: Vec3, direction: Vec3, t_max: f32) -> bool {
        self.bvh.occluded(origin, direction, 0.0, t_max, |tri, b| self.alpha.passes(tri, b))
    }
}

/// Ground-truth AO for every inner pixel of the G-buffer (full-target buffer, guard band = 1)
/// and the rays traced (background pixels trace none).
pub fn run_ground_truth(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    frame: &GroundTruthFrame,
    gbuffer: &GBufferImage,
    progress: Progress,
) -> (Vec<f32>, u64) {
    let view = &frame.camera.view;
    let size = view.size();
    let guard = view.guard;
    let slices = GBufferSlices { depth: &gbuffer.depth, normals: &gbuffer.normals, width: size.x };
    let mut out = vec![1.0f32; (size.x * size.y) as usize];
    let total = AtomicU64::new(0);
    out.par_chunks_mut(size.x as usize).enumerate().for_each(|(y, row)| {
        let y = y as u32;
        if y < guard || y + guard >= size.y {
            return;
        }
        let mut rays = BvhOcclusion { bvh, alpha: surfaces.alpha() };
        let mut traced = 0;
        for x in guard..size.x - guard {
            let out = ground_truth_pixel(&slices, frame, uvec2(x, y), &mut rays);
            row[x as usize] = out.ao;
            traced += out.rays as u64;
        }
        total.fetch_add(traced, Ordering::Relaxed);
        progress(1);
    });
    (out, total.into_inner())
}
