//! Compute pipelines and the memory barriers between passes.

use crate::descriptors::{Descriptor, SetSource};
use crate::{Gpu, GpuError};
use ash::vk;

/// A compute pipeline whose descriptor set 0 holds one descriptor of each of `types` (binding
/// order: storage buffers, images, …) and whose push constants are one `#[repr(C)]` struct.
pub(crate) struct ComputeKernel {
    set_layout: vk::DescriptorSetLayout,
    layout: vk::PipelineLayout,
    pipeline: vk::Pipeline,
    types: Vec<vk::DescriptorType>,
}

impl ComputeKernel {
    /// Pipeline for entry point `entry` of the module `spirv`; `push_size == 0`: no push constants;
    /// `specialization`: `(SpecId, 32-bit value)` of the module's specialization constants.
    pub(crate) fn new(
        gpu: &Gpu,
        spirv: &[u8],
        entry: &std::ffi::CStr,
        types: &[vk::DescriptorType],
        push_size: u32,
        specialization: &[(u32, u32)],
    ) -> Result<Self, GpuError> {
        let compute = vk::ShaderStageFlags::COMPUTE;
        let set_layout = gpu.set_layout(types, compute)?;
        let push = [vk::PushConstantRange::default().stage_flags(compute).size(push_size)];
        let set_layouts = [set_layout];
        let layout_info = vk::PipelineLayoutCreateInfo::default()
            .set_layouts(&set_layouts)
            .push_constant_ranges(&push[..usize::from(push_size > 0)]);
        let kernel = |layout: vk::PipelineLayout, pipeline: vk::Pipeline| ComputeKernel {
            set_layout,
            layout,
            pipeline,
            types: types.to_vec(),
        };
        let layout = unsafe { gpu.device.create_pipeline_layout(&layout_info, None)? };
        let module = gpu.shader_module(spirv)?;
        let map: Vec<vk::SpecializationMapEntry> = (0..)
            .zip(specialization)
            .map(|(i, &(id, _))| vk::SpecializationMapEntry { constant_id: id, offset: 4 * i, size: 4 })
            .collect();
        let data: Vec<u8> = specialization.iter().flat_map(|&(_, v)| v.to_le_bytes()).collect();
        let spec = vk::SpecializationInfo::default().map_entries(&map).data(&data);
        let mut stage = vk::PipelineShaderStageCreateInfo::default().stage(compute).module(module).name(entry);
        if !specialization.is_empty() {
            stage = stage.specialization_info(&spec);
        }
        let info = vk::ComputePipelineCreateInfo::default().stage(stage).layout(layout);
        let created = unsafe { gpu.device.create_compute_pipelines(vk::PipelineCache::null(), &[info], None) };
        unsafe { gpu.device.destroy_shader_module(module, None) };
        match created {
            Ok(pipelines) => Ok(kernel(layout, pipelines[0])),
            Err((_, e)) => {
                kernel(layout, vk::Pipeline::null()).destroy(gpu);
                Err(e.into())
            }
        }
    }

    /// Record a dispatch of `groups` workgroups over `descriptors` (binding order, the set from
    /// `sets`) with the push constants `push`.
    pub(crate) fn record(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        sets: &mut dyn SetSource,
        descriptors: &[Descriptor],
        push: &[u8],
        groups: [u32; 3],
    ) -> Result<(), GpuError> {
        let types: Vec<_> = descriptors.iter().map(Descriptor::ty).collect();
        assert_eq!(types, self.types, "descriptor types");
        let set = sets.set(gpu, self.set_layout, descriptors)?;
        self.record_set(gpu, cb, set, push, groups);
        Ok(())
    }

    pub(crate) fn record_set(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        set: vk::DescriptorSet,
        push: &[u8],
        groups: [u32; 3],
    ) {
        let d = &gpu.device;
        let compute = vk::PipelineBindPoint::COMPUTE;
        unsafe {
            d.cmd_bind_pipeline(cb, compute, self.pipeline);
            d.cmd_bind_descriptor_sets(cb, compute, self.layout, 0, &[set], &[]);
            if !push.is_empty() {
                d.cmd_push_constants(cb, self.layout, vk::ShaderStageFlags::COMPUTE, 0, push);
            }
            d.cmd_dispatch(cb, groups[0], groups[1], groups[2]);
        }
    }

    pub(crate) fn set_layout(&self) -> vk::DescriptorSetLayout {
        self.set_layout
    }

    /// Number of descriptors of set 0.
    pub(crate) fn bindings(&self) -> u32 {
        self.types.len() as u32
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
        dst_access |= A::TRANSFER_READ | A::TRANSFER_WRITE;
    }
    if dst.intersects(shader) {
        dst_access |= A::SHADER_READ | A::SHADER_WRITE;
    }
    let barrier = vk::MemoryBarrier::default().src_access_mask(src_access).dst_access_mask(dst_access);
    unsafe { gpu.device.cmd_pipeline_barrier(cb, src, dst, vk::DependencyFlags::empty(), &[barrier], &[], &[]) };
}
