//! XeGTAO on Vulkan (spec gtao-raymarch-hybrid §2.3): PrefilterDepths level by level, optional
//! normals from depth, MainPass, and the denoise passes, each timed with timestamp queries.

use crate::descriptors::storage_bindings;
use crate::screen::{ComputeKernel, memory_barrier};
use crate::{Buffer, Gpu, GpuError, modules};
use aokit_shaders::gtao::{GtaoParams, MIP_LEVELS, mip_offset, mip_size};
use ash::vk;

const GROUP: u32 = 8; // threads(8, 8) in the shader crate

/// Host copies of one XeGTAO run.
pub struct GtaoOutput {
    /// Visibility per pixel of the full target after the last denoise pass.
    pub ao: Vec<f32>,
    /// The packed MIP chain, the main pass's terms and edges, and (pass 0) the normals.
    pub mips: Vec<f32>,
    pub terms: Vec<u32>,
    pub edges: Vec<u32>,
    pub normals: Option<Vec<u32>>,
    /// GPU time per pass in ms.
    pub pass_ms: Vec<(&'static str, f64)>,
}

/// The four XeGTAO compute pipelines.
pub struct GtaoPasses {
    prefilter: ComputeKernel,
    normals: ComputeKernel,
    main: ComputeKernel,
    denoise: ComputeKernel,
}

fn groups(size: aokit_shaders::glam::UVec2) -> [u32; 3] {
    [size.x.div_ceil(GROUP), size.y.div_ceil(GROUP), 1]
}

impl GtaoPasses {
    pub fn new(gpu: &Gpu) -> Result<Self, GpuError> {
        let push = size_of::<GtaoParams>() as u32;
        Ok(GtaoPasses {
            prefilter: ComputeKernel::new(gpu, modules::GTAO_PREFILTER, c"gtao_prefilter", 2, push)?,
            normals: ComputeKernel::new(gpu, modules::GTAO_NORMALS, c"gtao_normals", 2, push)?,
            main: ComputeKernel::new(gpu, modules::GTAO_MAIN, c"gtao_main", 4, push)?,
            denoise: ComputeKernel::new(gpu, modules::GTAO_DENOISE, c"gtao_denoise", 4, push)?,
        })
    }

    /// XeGTAO on a G-buffer on the device. `normals`: the G-buffer's encoded normals, or `None`
    /// to derive them from depth (pass 0).
    pub fn run(
        &self,
        gpu: &Gpu,
        params: &GtaoParams,
        depth: &Buffer,
        normals: Option<&Buffer>,
    ) -> Result<GtaoOutput, GpuError> {
        let full = params.view.size();
        let pixels = (full.x * full.y) as usize;
        if depth.size < 4 * pixels as u64 {
            return Err(GpuError::Input(format!("depth buffer smaller than the {}×{} target", full.x, full.y)));
        }
        let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
        let mut owned = Vec::new();
        let result = (|| -> Result<GtaoOutput, GpuError> {
            let mut make = |b: Result<Buffer, GpuError>| -> Result<usize, GpuError> {
                owned.push(b?);
                Ok(owned.len() - 1)
            };
            let mips = make(gpu.upload(&vec![0.0f32; mip_offset(full, MIP_LEVELS)], storage))?;
            let generated = make(gpu.upload(&vec![0u32; if normals.is_none() { pixels } else { 1 }], storage))?;
            let terms = make(gpu.upload(&vec![0u32; pixels], storage))?;
            let edges = make(gpu.upload(&vec![0u32; pixels], storage))?;
            let ping = make(gpu.upload(&vec![0u32; pixels], storage))?;
            let pong = make(gpu.upload(&vec![0u32; pixels], storage))?;
            let ao = make(gpu.upload(&vec![1.0f32; pixels], storage))?;
            let b = |i: usize| &owned[i];
            let denoise_passes = params.denoise_passes.max(1);
            let sets = MIP_LEVELS + 2 + denoise_passes;
            let d = &gpu.device;
            let pool = gpu.descriptor_pool(sets, &storage_bindings(4))?;
            let queries = unsafe {
                d.create_query_pool(
                    &vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(5),
                    None,
                )?
            };
            let compute = vk::PipelineStageFlags::COMPUTE_SHADER;
            let recorded = gpu.submit(|cb| -> Result<(), GpuError> {
                unsafe {
                    d.cmd_reset_query_pool(cb, queries, 0, 5);
                    d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TOP_OF_PIPE, queries, 0);
                }
                for level in 0..MIP_LEVELS {
                    let p = GtaoParams { pass: level, ..*params };
                    let bytes = bytemuck::bytes_of(&p);
                    self.prefilter.record(gpu, cb, pool, &[depth, b(mips)], bytes, groups(mip_size(full, level)))?;
                    memory_barrier(gpu, cb, compute, compute);
                }
                unsafe { d.cmd_write_timestamp(cb, compute, queries, 1) };
                let normals = match normals {
                    Some(n) => n,
                    None => {
                        let bytes = bytemuck::bytes_of(params);
                        self.normals.record(gpu, cb, pool, &[depth, b(generated)], bytes, groups(full))?;
                        memory_barrier(gpu, cb, compute, compute);
                        b(generated)
                    }
                };
                unsafe { d.cmd_write_timestamp(cb, compute, queries, 2) };
                let bytes = bytemuck::bytes_of(params);
                self.main.record(gpu, cb, pool, &[b(mips), normals, b(terms), b(edges)], bytes, groups(full))?;
                memory_barrier(gpu, cb, compute, compute | vk::PipelineStageFlags::TRANSFER);
                unsafe { d.cmd_write_timestamp(cb, compute, queries, 3) };
                // terms → ping → pong → ping; the main pass's terms stay intact for inspection.
                // The last pass also writes the visibility `ao`.
                let (mut from, mut to) = (terms, ping);
                for pass in 0..denoise_passes {
                    let p = GtaoParams { pass, ..*params };
                    let bufs = [b(from), b(edges), b(to), b(ao)];
                    self.denoise.record(gpu, cb, pool, &bufs, bytemuck::bytes_of(&p), groups(full))?;
                    memory_barrier(gpu, cb, compute, compute | vk::PipelineStageFlags::TRANSFER);
                    (from, to) = (to, if to == ping { pong } else { ping });
                }
                unsafe { d.cmd_write_timestamp(cb, compute, queries, 4) };
                Ok(())
            });
            let got = recorded.and_then(|r| r).and_then(|_| gpu.timestamps_ms(queries, 5));
            unsafe {
                d.destroy_query_pool(queries, None);
                d.destroy_descriptor_pool(pool, None);
            }
            let t = got?;
            let mut pass_ms = vec![("gtao_prefilter", t[1])];
            if normals.is_none() {
                pass_ms.push(("gtao_normals", t[2] - t[1]));
            }
            pass_ms.push(("gtao_main", t[3] - t[2]));
            pass_ms.push(("gtao_denoise", t[4] - t[3]));
            Ok(GtaoOutput {
                ao: gpu.download(b(ao))?,
                mips: gpu.download(b(mips))?,
                terms: gpu.download(b(terms))?,
                edges: gpu.download(b(edges))?,
                normals: if normals.is_none() { Some(gpu.download(b(generated))?) } else { None },
                pass_ms,
            })
        })();
        for buffer in owned {
            gpu.free_buffer(buffer);
        }
        result
    }

    /// The denoise passes alone on host terms and edges (for techniques that reuse XeGTAO's
    /// denoiser). Returns the visibility (full target) and the GPU time in ms.
    pub fn denoise(
        &self,
        gpu: &Gpu,
        params: &GtaoParams,
        terms: &[u32],
        edges: &[u32],
    ) -> Result<(Vec<f32>, f64), GpuError> {
        let full = params.view.size();
        let pixels = (full.x * full.y) as usize;
        if terms.len() != pixels || edges.len() != pixels {
            return Err(GpuError::Input("denoise input does not match the target size".into()));
        }
        let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
        let mut owned = Vec::new();
        let result = (|| -> Result<(Vec<f32>, f64), GpuError> {
            for data in [terms, edges, &vec![0u32; pixels], &vec![0u32; pixels]] {
                owned.push(gpu.upload(data, storage)?);
            }
            owned.push(gpu.upload(&vec![1.0f32; pixels], storage)?);
            let passes = params.denoise_passes.max(1);
            let d = &gpu.device;
            let pool = gpu.descriptor_pool(passes, &storage_bindings(4))?;
            let queries = unsafe {
                d.create_query_pool(
                    &vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(2),
                    None,
                )?
            };
            let compute = vk::PipelineStageFlags::COMPUTE_SHADER;
            let recorded = gpu.submit(|cb| -> Result<(), GpuError> {
                unsafe {
                    d.cmd_reset_query_pool(cb, queries, 0, 2);
                    d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TOP_OF_PIPE, queries, 0);
                }
                let (mut from, mut to) = (0, 2);
                for pass in 0..passes {
                    let p = GtaoParams { pass, ..*params };
                    let bufs = [&owned[from], &owned[1], &owned[to], &owned[4]];
                    self.denoise.record(gpu, cb, pool, &bufs, bytemuck::bytes_of(&p), groups(full))?;
                    memory_barrier(gpu, cb, compute, compute | vk::PipelineStageFlags::TRANSFER);
                    (from, to) = (to, if to == 2 { 3 } else { 2 });
                }
                unsafe { d.cmd_write_timestamp(cb, compute, queries, 1) };
                Ok(())
            });
            let got = recorded.and_then(|r| r).and_then(|_| gpu.timestamps_ms(queries, 2));
            unsafe {
                d.destroy_query_pool(queries, None);
                d.destroy_descriptor_pool(pool, None);
            }
            let ms = got?[1];
            Ok((gpu.download(&owned[4])?, ms))
        })();
        for buffer in owned {
            gpu.free_buffer(buffer);
        }
        result
    }

    pub fn destroy(&self, gpu: &Gpu) {
        for k in [&self.prefilter, &self.normals, &self.main, &self.denoise] {
            k.destroy(gpu);
        }
    }
}
