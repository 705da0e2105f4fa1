//! The two-phase SVAO pipeline on Vulkan (spec svao-raysd §3): clear the interval buffers, AO
//! pass 1 (compute), then either the ray-traced SD map (ray tracing, one ray per SD texel) and
//! AO pass 2 (compute), or Ray-SVAO's pass 2 as a ray-generation shader. Each pass is timed with
//! timestamp queries.

use crate::descriptors::{Descriptor, storage_bindings};
use crate::raytracing::{RtPipeline, SceneAccel};
use crate::screen::{ComputeKernel, memory_barrier};
use crate::{Buffer, Gpu, GpuError, RasterSdPass, modules};
use aokit_shaders::common::float_order::{RAY_MAX_CLEAR, RAY_MIN_CLEAR};
use aokit_shaders::gbuffer::RasterParams;
use aokit_shaders::svao::{Secondary, SvaoFrame};
use ash::vk;

const GROUP: u32 = 8; // threads(8, 8) in the shader crate

/// What one SVAO run leaves behind (host copies).
pub struct SvaoOutput {
    /// Final AO before the blur (full target, guard band = 1).
    pub ao: Vec<f32>,
    /// AO after pass 1 (final where `mask == 0`, the UNORM8-stored sum elsewhere).
    pub ao_pass1: Vec<f32>,
    /// Per-pixel refinement mask of pass 1.
    pub mask: Vec<u32>,
    /// Interval buffers after pass 1 (SD size; Ray-SVAO: one unused texel).
    pub ray_min: Vec<u32>,
    pub ray_max: Vec<u32>,
    /// SD map, `N` normalized depths per texel (empty for Ray-SVAO).
    pub sd_map: Vec<f32>,
    /// GPU time per pass in ms.
    pub pass_ms: Vec<(&'static str, f64)>,
}

/// What the raster SD map (spec §8) draws instead of tracing SD rays.
pub struct RasterSdInput<'a> {
    pub pass: &'a RasterSdPass,
    /// De-indexed scene vertices and their count.
    pub vertices: &'a Buffer,
    pub count: u32,
    pub params: RasterParams,
    /// Alpha-mask headers and texels.
    pub headers: &'a Buffer,
    pub texels: &'a Buffer,
}

/// Pipelines of Ray-SD and Ray-SVAO.
pub struct SvaoPipelines {
    pass1: ComputeKernel,
    pass2_sd: ComputeKernel,
    /// Ray-tracing pipelines, present where the device traces rays.
    sd_map: Option<RtPipeline>,
    sample_rays: Option<RtPipeline>,
}

fn rt_bindings(storage: usize) -> Vec<vk::DescriptorType> {
    let mut types = storage_bindings(storage as u32);
    types[1] = vk::DescriptorType::ACCELERATION_STRUCTURE_KHR;
    types
}

impl SvaoPipelines {
    pub fn new(gpu: &Gpu) -> Result<Self, GpuError> {
        let rt = gpu.has_ray_tracing();
        let sd_shaders = [
            (modules::RAYSD_RGEN, c"raysd_rgen"),
            (modules::RAYSD_MISS, c"raysd_miss"),
            (modules::RAYSD_AHIT, c"raysd_ahit"),
        ];
        let sample_shaders = [
            (modules::RAYSVAO_RGEN, c"raysvao_rgen"),
            (modules::RAYSVAO_MISS, c"raysvao_miss"),
            (modules::RAYSVAO_AHIT, c"raysvao_ahit"),
        ];
        Ok(SvaoPipelines {
            pass1: ComputeKernel::new(gpu, modules::SVAO_PASS1, c"svao_pass1", 8, 0)?,
            pass2_sd: ComputeKernel::new(gpu, modules::RAYSD_PASS2, c"raysd_pass2", 7, 0)?,
            // frame, TLAS, depth, normals, ray_min, ray_max, SD map + 4 alpha buffers.
            sd_map: if rt { Some(RtPipeline::new(gpu, sd_shaders, rt_bindings(11))?) } else { None },
            // frame, TLAS, depth, normals, ao, mask + 4 alpha buffers + the second depth layer.
            sample_rays: if rt { Some(RtPipeline::new(gpu, sample_shaders, rt_bindings(11))?) } else { None },
        })
    }

    /// Run Ray-SD (`frame.params.secondary` = StochasticDepth), Ray-SVAO (Raytraced) or pass 1
    /// alone (Disabled: plain VAO, e.g. with dual depth; `scene` unused) on a
    /// G-buffer already on the device: depth, normals and `depth2`, the depth-peeled second layer
    /// (read only when `frame.params.dual` is set; pass the depth buffer otherwise).
    pub fn run(
        &self,
        gpu: &Gpu,
        scene: Option<&SceneAccel>,
        frame: &SvaoFrame,
        [depth, normals, depth2]: [&Buffer; 3],
        raster: Option<RasterSdInput>,
    ) -> Result<SvaoOutput, GpuError> {
        let params = &frame.params;
        let view = &params.vao.view;
        let size = view.size();
        let pixels = (size.x * size.y) as usize;
        if depth.size < 4 * pixels as u64 || normals.size < 4 * pixels as u64 {
            return Err(GpuError::Input(format!("G-buffer smaller than the {}×{} target", size.x, size.y)));
        }
        let sd = params.secondary == Secondary::StochasticDepth as u32;
        let traced = params.secondary == Secondary::Raytraced as u32;
        let rt = if (sd && raster.is_none()) || traced {
            let scene = scene.ok_or_else(|| GpuError::Input("Ray-SD/Ray-SVAO need the scene's TLAS".into()))?;
            let pipeline = if sd { &self.sd_map } else { &self.sample_rays };
            let pipeline = pipeline.as_ref().ok_or_else(|| GpuError::NoDevice("ray tracing pipelines".into()))?;
            Some((scene, pipeline))
        } else {
            None
        };
        let sd_size = params.sd_size();
        let texels = (sd_size.x * sd_size.y) as usize;
        let storage = vk::BufferUsageFlags::STORAGE_BUFFER
            | vk::BufferUsageFlags::TRANSFER_DST
            | vk::BufferUsageFlags::TRANSFER_SRC;
        let mut owned = Vec::new();
        let result = (|| -> Result<SvaoOutput, GpuError> {
            let mut make = |buffer: Result<Buffer, GpuError>| -> Result<usize, GpuError> {
                owned.push(buffer?);
                Ok(owned.len() - 1)
            };
            let frame_buf = make(gpu.upload(std::slice::from_ref(frame), storage))?;
            let ao = make(gpu.upload(&vec![1.0f32; pixels], storage))?;
            let mask = make(gpu.upload(&vec![0u32; pixels], storage))?;
            let ray_min = make(gpu.upload(&vec![0u32; texels], storage))?;
            let ray_max = make(gpu.upload(&vec![0u32; texels], storage))?;
            let layers = if sd { texels * params.sd_layers as usize } else { 1 };
            let sd_map = make(gpu.upload(&vec![1.0f32; layers], storage))?;
            let ao_pass1 = make(gpu.upload(&vec![1.0f32; pixels], storage))?;
            let b = |i: usize| &owned[i];
            let inner = size - 2 * view.guard;
            let groups = [inner.x.div_ceil(GROUP), inner.y.div_ceil(GROUP), 1];
            let d = &gpu.device;
            let mut types = storage_bindings(8);
            types.extend(storage_bindings(crate::gbuffer::RASTER_SD_BINDINGS));
            types.extend(rt_bindings(11));
            let pool = gpu.descriptor_pool(3, &types)?;
            let queries = unsafe {
                d.create_query_pool(
                    &vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(4),
                    None,
                )?
            };
            let recorded = gpu.submit(|cb| -> Result<(), GpuError> {
                unsafe {
                    d.cmd_reset_query_pool(cb, queries, 0, 4);
                    d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TOP_OF_PIPE, queries, 0);
                    // Interval clears (spec §6), part of pass 1's time.
                    d.cmd_fill_buffer(cb, b(ray_min).raw, 0, vk::WHOLE_SIZE, RAY_MIN_CLEAR);
                    d.cmd_fill_buffer(cb, b(ray_max).raw, 0, vk::WHOLE_SIZE, RAY_MAX_CLEAR);
                }
                memory_barrier(gpu, cb, vk::PipelineStageFlags::TRANSFER, vk::PipelineStageFlags::COMPUTE_SHADER);
                let pass1_buffers = [b(frame_buf), depth, normals, b(ao), b(mask), b(ray_min), b(ray_max), depth2];
                self.pass1.record(gpu, cb, pool, &pass1_buffers, &[], groups)?;
                let rt_stage = vk::PipelineStageFlags::RAY_TRACING_SHADER_KHR;
                memory_barrier(
                    gpu,
                    cb,
                    vk::PipelineStageFlags::COMPUTE_SHADER,
                    rt_stage | vk::PipelineStageFlags::TRANSFER,
                );
                unsafe { d.cmd_write_timestamp(cb, vk::PipelineStageFlags::COMPUTE_SHADER, queries, 1) };
                // Keep pass 1's AO for diagnostics (not timed as a pass: it overlaps the trace).
                let whole = [vk::BufferCopy::default().size(4 * pixels as u64)];
                unsafe { d.cmd_copy_buffer(cb, b(ao).raw, b(ao_pass1).raw, &whole) };
                memory_barrier(
                    gpu,
                    cb,
                    vk::PipelineStageFlags::TRANSFER,
                    rt_stage | vk::PipelineStageFlags::COMPUTE_SHADER,
                );
                // AO pass 2 from the SD map (either source), then the last timestamp.
                let record_pass2 = |cb| -> Result<(), GpuError> {
                    let pass2_buffers = [b(frame_buf), depth, normals, b(ao), b(mask), b(sd_map), depth2];
                    self.pass2_sd.record(gpu, cb, pool, &pass2_buffers, &[], groups)?;
                    memory_barrier(
                        gpu,
                        cb,
                        vk::PipelineStageFlags::COMPUTE_SHADER,
                        vk::PipelineStageFlags::TRANSFER | vk::PipelineStageFlags::COMPUTE_SHADER,
                    );
                    unsafe { d.cmd_write_timestamp(cb, vk::PipelineStageFlags::COMPUTE_SHADER, queries, 3) };
                    Ok(())
                };
                if let (true, Some(r)) = (sd, &raster) {
                    // Raster SD map (spec §8), then pass 2 as for the ray-traced one.
                    let fragment = vk::PipelineStageFlags::FRAGMENT_SHADER;
                    memory_barrier(gpu, cb, vk::PipelineStageFlags::COMPUTE_SHADER, fragment);
                    let buffers = [r.headers, r.texels, b(frame_buf), depth, b(ray_min), b(ray_max), b(sd_map)];
                    let set = gpu.descriptor_set(pool, r.pass.set_layout, &buffers.map(Descriptor::Storage))?;
                    r.pass.record(gpu, cb, set, (r.vertices, r.count), &r.params, sd_size);
                    memory_barrier(gpu, cb, fragment, vk::PipelineStageFlags::COMPUTE_SHADER);
                    unsafe { d.cmd_write_timestamp(cb, vk::PipelineStageFlags::BOTTOM_OF_PIPE, queries, 2) };
                    record_pass2(cb)?;
                    return Ok(());
                }
                let Some((scene, pipeline)) = rt else {
                    memory_barrier(gpu, cb, vk::PipelineStageFlags::COMPUTE_SHADER, vk::PipelineStageFlags::TRANSFER);
                    for q in [2, 3] {
                        unsafe { d.cmd_write_timestamp(cb, vk::PipelineStageFlags::COMPUTE_SHADER, queries, q) };
                    }
                    return Ok(());
                };
                let mut descriptors = vec![
                    Descriptor::Storage(b(frame_buf)),
                    scene.tlas_descriptor(),
                    Descriptor::Storage(depth),
                    Descriptor::Storage(normals),
                ];
                if sd {
                    descriptors.extend([b(ray_min), b(ray_max), b(sd_map)].map(Descriptor::Storage));
                    descriptors.extend(scene.alpha_descriptors());
                    let set = gpu.descriptor_set(pool, pipeline.set_layout, &descriptors)?;
                    pipeline.record_trace(gpu, cb, set, sd_size.x, sd_size.y)?;
                    memory_barrier(gpu, cb, rt_stage, vk::PipelineStageFlags::COMPUTE_SHADER);
                    unsafe { d.cmd_write_timestamp(cb, rt_stage, queries, 2) };
                    record_pass2(cb)?;
                } else {
                    descriptors.extend([b(ao), b(mask)].map(Descriptor::Storage));
                    descriptors.extend(scene.alpha_descriptors());
                    descriptors.push(Descriptor::Storage(depth2));
                    let set = gpu.descriptor_set(pool, pipeline.set_layout, &descriptors)?;
                    pipeline.record_trace(gpu, cb, set, inner.x, inner.y)?;
                    memory_barrier(gpu, cb, rt_stage, vk::PipelineStageFlags::TRANSFER);
                    unsafe {
                        d.cmd_write_timestamp(cb, rt_stage, queries, 2);
                        d.cmd_write_timestamp(cb, rt_stage, queries, 3);
                    }
                }
                Ok(())
            });
            let got = recorded.and_then(|r| r).and_then(|_| gpu.timestamps_ms(queries, 4));
            unsafe {
                d.destroy_query_pool(queries, None);
                d.destroy_descriptor_pool(pool, None);
            }
            let t = got?;
            let pass_ms = if sd {
                let map = if raster.is_some() { "sd_map_raster" } else { "sd_map" };
                vec![("ao_pass1", t[1]), (map, t[2] - t[1]), ("ao_pass2", t[3] - t[2])]
            } else if traced {
                vec![("ao_pass1", t[1]), ("ao_pass2_rays", t[2] - t[1])]
            } else {
                vec![("ao_pass1", t[1])]
            };
            Ok(SvaoOutput {
                ao: gpu.download(b(ao))?,
                ao_pass1: gpu.download(b(ao_pass1))?,
                mask: gpu.download(b(mask))?,
                ray_min: gpu.download(b(ray_min))?,
                ray_max: gpu.download(b(ray_max))?,
                sd_map: if sd { gpu.download(b(sd_map))? } else { Vec::new() },
                pass_ms,
            })
        })();
        for buffer in owned {
            gpu.free_buffer(buffer);
        }
        result
    }

    pub fn destroy(self, gpu: &Gpu) {
        self.pass1.destroy(gpu);
        self.pass2_sd.destroy(gpu);
        for p in [self.sd_map, self.sample_rays].into_iter().flatten() {
            p.destroy(gpu);
        }
    }
}
