//! The Poisson-disk ray-marched SSAO (compute) and the hybrid screen + world-ray AO (ray-tracing
//! pipeline reusing the ground truth's miss and alpha-test any-hit shaders) on Vulkan
//! (spec gtao-raymarch-hybrid §3, §4). Both leave terms and edges for XeGTAO's denoiser.

use crate::descriptors::{Descriptor, storage_bindings};
use crate::raytracing::{RtPipeline, SceneAccel};
use crate::screen::{ComputeKernel, memory_barrier};
use crate::{Buffer, Gpu, GpuError, modules};
use aokit_shaders::glam::Vec2;
use aokit_shaders::hybrid::HybridFrame;
use aokit_shaders::raymarch::RaymarchParams;
use ash::vk;

/// Visibility, denoiser terms and packed edges per pixel of the full target, and the GPU time.
pub struct ScreenRayOutput {
    pub ao: Vec<f32>,
    pub terms: Vec<u32>,
    pub edges: Vec<u32>,
    pub ms: f64,
}

/// The ray-marched SSAO kernel and the hybrid AO pipeline.
pub struct SsaoPipelines {
    raymarch: ComputeKernel,
    hybrid: Option<RtPipeline>,
}

/// Upload buffers, record `work` between two timestamps, download (ao, terms, edges).
fn run_timed(
    gpu: &Gpu,
    pixels: usize,
    sets: (u32, &[vk::DescriptorType]),
    work: impl FnOnce(vk::CommandBuffer, vk::DescriptorPool, [&Buffer; 3]) -> Result<(), GpuError>,
    stage: vk::PipelineStageFlags,
) -> Result<ScreenRayOutput, GpuError> {
    let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
    let mut owned = Vec::new();
    let result = (|| -> Result<ScreenRayOutput, GpuError> {
        owned.push(gpu.upload(&vec![1.0f32; pixels], storage)?);
        owned.push(gpu.upload(&vec![0u32; pixels], storage)?);
        owned.push(gpu.upload(&vec![0u32; pixels], storage)?);
        let (ao, terms, edges) = (&owned[0], &owned[1], &owned[2]);
        let d = &gpu.device;
        let pool = gpu.descriptor_pool(sets.0, sets.1)?;
        let queries = unsafe {
            d.create_query_pool(
                &vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(2),
                None,
            )?
        };
        let recorded = gpu.submit(|cb| -> Result<(), GpuError> {
            unsafe {
                d.cmd_reset_query_pool(cb, queries, 0, 2);
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TOP_OF_PIPE, queries, 0);
            }
            work(cb, pool, [ao, terms, edges])?;
            memory_barrier(gpu, cb, stage, vk::PipelineStageFlags::TRANSFER);
            unsafe { d.cmd_write_timestamp(cb, stage, queries, 1) };
            Ok(())
        });
        let got = recorded.and_then(|r| r).and_then(|_| gpu.timestamps_ms(queries, 2));
        unsafe {
            d.destroy_query_pool(queries, None);
            d.destroy_descriptor_pool(pool, None);
        }
        let ms = got?[1];
        Ok(ScreenRayOutput { ao: gpu.download(ao)?, terms: gpu.download(terms)?, edges: gpu.download(edges)?, ms })
    })();
    for b in owned {
        gpu.free_buffer(b);
    }
    result
}

impl SsaoPipelines {
    /// The hybrid pipeline is made only where ray tracing is available.
    pub fn new(gpu: &Gpu) -> Result<Self, GpuError> {
        let push = size_of::<RaymarchParams>() as u32;
        let raymarch = ComputeKernel::new(gpu, modules::RAYMARCH_MAIN, c"raymarch_main", 6, push)?;
        let hybrid = if gpu.has_ray_tracing() {
            let shaders = [
                (modules::HYBRID_RGEN, c"hybrid_rgen"),
                (modules::GROUNDTRUTH_MISS, c"groundtruth_miss"),
                (modules::GROUNDTRUTH_AHIT, c"groundtruth_ahit"),
            ];
            let mut types = storage_bindings(11);
            types[1] = vk::DescriptorType::ACCELERATION_STRUCTURE_KHR;
            Some(RtPipeline::new(gpu, shaders, types)?)
        } else {
            None
        };
        Ok(SsaoPipelines { raymarch, hybrid })
    }

    /// Ray-marched SSAO over the full target.
    pub fn raymarch(
        &self,
        gpu: &Gpu,
        params: &RaymarchParams,
        depth: &Buffer,
        normals: &Buffer,
        kernel: &[Vec2],
    ) -> Result<ScreenRayOutput, GpuError> {
        let size = params.view.size();
        let pixels = (size.x * size.y) as usize;
        let points = gpu.upload(kernel, vk::BufferUsageFlags::STORAGE_BUFFER)?;
        let types = storage_bindings(6);
        let out = run_timed(
            gpu,
            pixels,
            (1, &types),
            |cb, pool, [ao, terms, edges]| {
                let bufs = [depth, normals, &points, ao, terms, edges];
                let groups = [size.x.div_ceil(8), size.y.div_ceil(8), 1];
                self.raymarch.record(gpu, cb, pool, &bufs, bytemuck::bytes_of(params), groups)
            },
            vk::PipelineStageFlags::COMPUTE_SHADER,
        );
        gpu.free_buffer(points);
        out
    }

    /// Hybrid AO over the full target (needs ray tracing).
    pub fn hybrid(
        &self,
        gpu: &Gpu,
        scene: &SceneAccel,
        frame: &HybridFrame,
        depth: &Buffer,
        normals: &Buffer,
    ) -> Result<ScreenRayOutput, GpuError> {
        let pipeline = self.hybrid.as_ref().ok_or_else(|| GpuError::NoDevice("ray tracing (hybrid AO)".into()))?;
        let size = frame.camera.view.size();
        let pixels = (size.x * size.y) as usize;
        let frame_buf = gpu.upload(std::slice::from_ref(frame), vk::BufferUsageFlags::STORAGE_BUFFER)?;
        let out = run_timed(
            gpu,
            pixels,
            (1, &pipeline.bindings.clone()),
            |cb, pool, [ao, terms, edges]| {
                let mut descriptors = vec![
                    Descriptor::Storage(&frame_buf),
                    scene.tlas_descriptor(),
                    Descriptor::Storage(depth),
                    Descriptor::Storage(normals),
                    Descriptor::Storage(ao),
                ];
                descriptors.extend(scene.alpha_descriptors());
                descriptors.extend([Descriptor::Storage(terms), Descriptor::Storage(edges)]);
                let set = gpu.descriptor_set(pool, pipeline.set_layout, &descriptors)?;
                pipeline.record_trace(gpu, cb, set, size.x, size.y)
            },
            vk::PipelineStageFlags::RAY_TRACING_SHADER_KHR,
        );
        gpu.free_buffer(frame_buf);
        out
    }

    pub fn destroy(self, gpu: &Gpu) {
        self.raymarch.destroy(gpu);
        if let Some(h) = self.hybrid {
            h.destroy(gpu);
        }
    }
}
