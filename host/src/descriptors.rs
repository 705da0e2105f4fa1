//! Descriptor sets of storage buffers, the only kind of descriptor the passes use.

use crate::{Gpu, GpuError};
use ash::vk;

impl Gpu {
    /// Set layout with `count` storage-buffer bindings `0..count` visible to `stages`.
    pub(crate) fn storage_set_layout(
        &self,
        count: u32,
        stages: vk::ShaderStageFlags,
    ) -> Result<vk::DescriptorSetLayout, GpuError> {
        let bindings: Vec<_> = (0..count)
            .map(|b| {
                vk::DescriptorSetLayoutBinding::default()
                    .binding(b)
                    .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                    .descriptor_count(1)
                    .stage_flags(stages)
            })
            .collect();
        let info = vk::DescriptorSetLayoutCreateInfo::default().bindings(&bindings);
        Ok(unsafe { self.device.create_descriptor_set_layout(&info, None)? })
    }

    /// A pool for `sets` sets of up to `buffers_per_set` storage buffers.
    pub(crate) fn storage_pool(&self, sets: u32, buffers_per_set: u32) -> Result<vk::DescriptorPool, GpuError> {
        let sizes = [vk::DescriptorPoolSize::default()
            .ty(vk::DescriptorType::STORAGE_BUFFER)
            .descriptor_count(sets * buffers_per_set)];
        let info = vk::DescriptorPoolCreateInfo::default().max_sets(sets).pool_sizes(&sizes);
        Ok(unsafe { self.device.create_descriptor_pool(&info, None)? })
    }

    /// Allocate a set from `pool` and bind `buffers` (whole range) to bindings `0..n`.
    pub(crate) fn storage_set(
        &self,
        pool: vk::DescriptorPool,
        layout: vk::DescriptorSetLayout,
        buffers: &[vk::Buffer],
    ) -> Result<vk::DescriptorSet, GpuError> {
        let layouts = [layout];
        let info = vk::DescriptorSetAllocateInfo::default().descriptor_pool(pool).set_layouts(&layouts);
        let set = unsafe { self.device.allocate_descriptor_sets(&info)? }[0];
        let infos: Vec<_> =
            buffers.iter().map(|&b| [vk::DescriptorBufferInfo::default().buffer(b).range(vk::WHOLE_SIZE)]).collect();
        let writes: Vec<_> = infos
            .iter()
            .enumerate()
            .map(|(i, info)| {
                vk::WriteDescriptorSet::default()
                    .dst_set(set)
                    .dst_binding(i as u32)
                    .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                    .buffer_info(info)
            })
            .collect();
        unsafe { self.device.update_descriptor_sets(&writes, &[]) };
        Ok(set)
    }
}
