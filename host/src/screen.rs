//! Screen-space compute passes: VAO then the two blur directions, timed with timestamp queries.

use crate::descriptors::{Descriptor, storage_bindings};
use crate::{Buffer, Gpu, GpuError, modules};
use aokit_shaders::blur::BlurParams;
use aokit_shaders::glam::uvec2;
use aokit_shaders::vao::VaoParams;
use ash::vk;

/// A compute pipeline whose descriptor set 0 holds `bindings` storage buffers and whose push
/// constants are one `#[repr(C)]` struct.
pub(crate) struct ComputeKernel {
    set_layout: vk::DescriptorSetLayout,
    layout: vk::PipelineLayout,
    pipeline: vk::Pipeline,
    bindings: u32,
}

impl ComputeKernel {
    pub(crate) fn new(
        gpu: &Gpu,
        spirv: &[u8],
        entry: &std::ffi::CStr,
        bindings: u32,
        push_size: u32,
    ) -> Result<Self, GpuError> {
        let d = &gpu.device;
        let set_layout = gpu.set_layout(&storage_bindings(bindings), vk::ShaderStageFlags::COMPUTE)?;
        unsafe {
            // `push_size == 0`: the kernel reads its parameters from a storage buffer.
            let push = [vk::PushConstantRange::default().stage_flags(vk::ShaderStageFlags::COMPUTE).size(push_size)];
            let ranges = if push_size == 0 { &push[..0] } else { &push[..] };
            let set_layouts = [set_layout];
            let layout = d.create_pipeline_layout(
                &vk::PipelineLayoutCreateInfo::default().set_layouts(&set_layouts).push_constant_ranges(ranges),
                None,
            )?;
            let module = gpu.shader_module(spirv)?;
            let stage = vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::COMPUTE)
                .module(module)
                .name(entry);
            let created = d.create_compute_pipelines(
                vk::PipelineCache::null(),
                &[vk::ComputePipelineCreateInfo::default().stage(stage).layout(layout)],
                None,
            );
            d.destroy_shader_module(module, None);
            let pipeline = created.map_err(|(_, e)| e)?[0];
            Ok(ComputeKernel { set_layout, layout, pipeline, bindings })
        }
    }

    /// Record a dispatch of `groups` workgroups over `buffers` (binding order) with `push`.
    pub(crate) fn record(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        pool: vk::DescriptorPool,
        buffers: &[&Buffer],
        push: &[u8],
        groups: [u32; 3],
    ) -> Result<(), GpuError> {
        assert_eq!(buffers.len() as u32, self.bindings, "binding count");
        let d = &gpu.device;
        let descriptors: Vec<_> = buffers.iter().map(|b| Descriptor::Storage(b)).collect();
        let set = gpu.descriptor_set(pool, self.set_layout, &descriptors)?;
        unsafe {
            d.cmd_bind_pipeline(cb, vk::PipelineBindPoint::COMPUTE, self.pipeline);
            d.cmd_bind_descriptor_sets(cb, vk::PipelineBindPoint::COMPUTE, self.layout, 0, &[set], &[]);
            if !push.is_empty() {
                d.cmd_push_constants(cb, self.layout, vk::ShaderStageFlags::COMPUTE, 0, push);
            }
            d.cmd_dispatch(cb, groups[0], groups[1], groups[2]);
        }
        Ok(())
    }

    pub(crate) fn destroy(&self, gpu: &Gpu) {
        unsafe {
            gpu.device.destroy_pipeline(self.pipeline, None);
            gpu.device.destroy_pipeline_layout(self.layout, None);
            gpu.device.destroy_descriptor_set_layout(self.set_layout, None);
        }
    }
}

/// Make shader writes of stage `src` visible to later compute reads and transfers.
pub(crate) fn compute_barrier(gpu: &Gpu, cb: vk::CommandBuffer, src: vk::PipelineStageFlags) {
    memory_barrier(gpu, cb, src, vk::PipelineStageFlags::COMPUTE_SHADER | vk::PipelineStageFlags::TRANSFER);
}

/// Make every write of stage `src` (shader or transfer) visible to reads and writes of `dst`.
pub(crate) fn memory_barrier(
    gpu: &Gpu,
    cb: vk::CommandBuffer,
    src: vk::PipelineStageFlags,
    dst: vk::PipelineStageFlags,
) {
    type S = vk::PipelineStageFlags;
    type A = vk::AccessFlags;
    let shader = S::COMPUTE_SHADER | S::RAY_TRACING_SHADER_KHR | S::FRAGMENT_SHADER;
    let mut src_access = A::empty();
    if src.intersects(S::TRANSFER) {
        src_access |= A::TRANSFER_WRITE;
    }
    if src.intersects(shader) {
        src_access |= A::SHADER_WRITE;
    }
    let mut dst_access = A::empty();
    if dst.intersects(S::TRANSFER) {
        dst_access |= A::TRANSFER_READ;
    }
    if dst.intersects(shader) {
        dst_access |= A::SHADER_READ | A::SHADER_WRITE;
    }
    let barrier = vk::MemoryBarrier::default().src_access_mask(src_access).dst_access_mask(dst_access);
    unsafe { gpu.device.cmd_pipeline_barrier(cb, src, dst, vk::DependencyFlags::empty(), &[barrier], &[], &[]) };
}

/// Output of [`ScreenPasses::run`].
pub struct ScreenOutput {
    /// VAO result before the blur (full target, guard band = 1).
    pub ao: Vec<f32>,
    /// After the cross-bilateral blur.
    pub ao_blurred: Vec<f32>,
    /// GPU time per pass in milliseconds: `[("vao", ms), ("blur", ms)]`.
    pub pass_ms: Vec<(&'static str, f64)>,
}

/// The VAO and blur pipelines.
pub struct ScreenPasses {
    vao: ComputeKernel,
    blur: ComputeKernel,
}

const GROUP: u32 = 8; // threads(8, 8) in the shader crate

impl ScreenPasses {
    pub fn new(gpu: &Gpu) -> Result<Self, GpuError> {
        Ok(ScreenPasses {
            vao: ComputeKernel::new(gpu, modules::VAO_MAIN, c"vao_main", 3, size_of::<VaoParams>() as u32)?,
            blur: ComputeKernel::new(gpu, modules::BLUR_MAIN, c"blur_main", 3, size_of::<BlurParams>() as u32)?,
        })
    }

    /// VAO over the inner image then the horizontal and vertical blur, on a G-buffer already on
    /// the device (`depth`: f32 per pixel, `normals`: encoded u32 per pixel, full target).
    pub fn run(
        &self,
        gpu: &Gpu,
        vao: &VaoParams,
        blur: &BlurParams,
        depth: &Buffer,
        normals: &Buffer,
    ) -> Result<ScreenOutput, GpuError> {
        let size = vao.view.size();
        let pixels = (size.x * size.y) as usize;
        if depth.size < 4 * pixels as u64 || normals.size < 4 * pixels as u64 {
            return Err(GpuError::Input(format!("G-buffer smaller than the {}×{} target", size.x, size.y)));
        }
        let usage = vk::BufferUsageFlags::STORAGE_BUFFER;
        let ones = vec![1.0f32; pixels];
        let ao = gpu.upload(&ones, usage)?;
        let tmp = gpu.upload(&ones, usage)?;
        let out = gpu.upload(&ones, usage)?;
        let inner = size - 2 * vao.view.guard;
        let groups = [inner.x.div_ceil(GROUP), inner.y.div_ceil(GROUP), 1];
        let d = &gpu.device;
        let result = (|| unsafe {
            // Three dispatches of three storage buffers each.
            let pool = gpu.descriptor_pool(3, &storage_bindings(3))?;
            let queries = d.create_query_pool(
                &vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(3),
                None,
            )?;
            let recorded = gpu.submit(|cb| -> Result<(), GpuError> {
                d.cmd_reset_query_pool(cb, queries, 0, 3);
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TOP_OF_PIPE, queries, 0);
                self.vao.record(gpu, cb, pool, &[depth, normals, &ao], bytemuck::bytes_of(vao), groups)?;
                compute_barrier(gpu, cb, vk::PipelineStageFlags::COMPUTE_SHADER);
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::COMPUTE_SHADER, queries, 1);
                self.record_blur(gpu, cb, pool, blur, [&ao, &tmp, &out], depth)?;
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::COMPUTE_SHADER, queries, 2);
                Ok(())
            });
            let got = recorded.and_then(|r| r).and_then(|_| gpu.timestamps_ms(queries, 3));
            d.destroy_query_pool(queries, None);
            d.destroy_descriptor_pool(pool, None);
            let t = got?;
            Ok(vec![("vao", t[1]), ("blur", t[2] - t[1])])
        })();
        let output = result
            .and_then(|pass_ms| Ok(ScreenOutput { ao: gpu.download(&ao)?, ao_blurred: gpu.download(&out)?, pass_ms }));
        for b in [ao, tmp, out] {
            gpu.free_buffer(b);
        }
        output
    }

    /// Horizontal then vertical blur pass (spec §12) from `bufs[0]` through `bufs[1]` into
    /// `bufs[2]`.
    fn record_blur(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        pool: vk::DescriptorPool,
        blur: &BlurParams,
        [input, tmp, out]: [&Buffer; 3],
        depth: &Buffer,
    ) -> Result<(), GpuError> {
        let inner = blur.view.size() - 2 * blur.view.guard;
        let groups = [inner.x.div_ceil(GROUP), inner.y.div_ceil(GROUP), 1];
        let horizontal = BlurParams { direction: uvec2(1, 0), ..*blur };
        self.blur.record(gpu, cb, pool, &[input, depth, tmp], bytemuck::bytes_of(&horizontal), groups)?;
        compute_barrier(gpu, cb, vk::PipelineStageFlags::COMPUTE_SHADER);
        let vertical = BlurParams { direction: uvec2(0, 1), ..*blur };
        self.blur.record(gpu, cb, pool, &[tmp, depth, out], bytemuck::bytes_of(&vertical), groups)?;
        compute_barrier(gpu, cb, vk::PipelineStageFlags::COMPUTE_SHADER);
        Ok(())
    }

    /// The blur alone on a host AO image (full target) and a device depth buffer. Returns the
    /// blurred AO and the GPU time in ms.
    pub fn blur(&self, gpu: &Gpu, blur: &BlurParams, ao: &[f32], depth: &Buffer) -> Result<(Vec<f32>, f64), GpuError> {
        let usage = vk::BufferUsageFlags::STORAGE_BUFFER;
        let input = gpu.upload(ao, usage)?;
        let tmp = gpu.upload(ao, usage)?;
        let out = gpu.upload(ao, usage)?;
        let d = &gpu.device;
        let result = (|| unsafe {
            let pool = gpu.descriptor_pool(2, &storage_bindings(3))?;
            let queries = d.create_query_pool(
                &vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(2),
                None,
            )?;
            let recorded = gpu.submit(|cb| -> Result<(), GpuError> {
                d.cmd_reset_query_pool(cb, queries, 0, 2);
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TOP_OF_PIPE, queries, 0);
                self.record_blur(gpu, cb, pool, blur, [&input, &tmp, &out], depth)?;
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::COMPUTE_SHADER, queries, 1);
                Ok(())
            });
            let got = recorded.and_then(|r| r).and_then(|_| gpu.timestamps_ms(queries, 2));
            d.destroy_query_pool(queries, None);
            d.destroy_descriptor_pool(pool, None);
            Ok(got?[1])
        })();
        let output = result.and_then(|ms| Ok((gpu.download(&out)?, ms)));
        for b in [input, tmp, out] {
            gpu.free_buffer(b);
        }
        output
    }

    pub fn destroy(&self, gpu: &Gpu) {
        self.vao.destroy(gpu);
        self.blur.destroy(gpu);
    }
}
