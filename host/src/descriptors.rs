//! Descriptor sets: storage buffers, the TLAS of the ray-tracing passes, and the engine images of
//! the adapters (sampled images read with `OpImageFetch`, storage images). Binding `i` of a set
//! holds the `i`-th descriptor.

use crate::{Buffer, Gpu, GpuError};
use ash::vk;

/// One descriptor to bind.
pub(crate) enum Descriptor<'a> {
    Storage(&'a Buffer),
    Tlas(vk::AccelerationStructureKHR),
    /// A sampled image (no sampler) in the given layout.
    SampledImage(vk::ImageView, vk::ImageLayout),
    /// A storage image, in `GENERAL` layout.
    StorageImage(vk::ImageView),
}

impl Descriptor<'_> {
    pub(crate) fn ty(&self) -> vk::DescriptorType {
        match self {
            Descriptor::Storage(_) => vk::DescriptorType::STORAGE_BUFFER,
            Descriptor::Tlas(_) => vk::DescriptorType::ACCELERATION_STRUCTURE_KHR,
            Descriptor::SampledImage(..) => vk::DescriptorType::SAMPLED_IMAGE,
            Descriptor::StorageImage(_) => vk::DescriptorType::STORAGE_IMAGE,
        }
    }

    /// The image info of an image descriptor (a default one otherwise).
    fn image_info(&self) -> vk::DescriptorImageInfo {
        match *self {
            Descriptor::SampledImage(view, layout) => {
                vk::DescriptorImageInfo::default().image_view(view).image_layout(layout)
            }
            Descriptor::StorageImage(view) => {
                vk::DescriptorImageInfo::default().image_view(view).image_layout(vk::ImageLayout::GENERAL)
            }
            _ => vk::DescriptorImageInfo::default(),
        }
    }
}

/// `count` storage-buffer bindings.
pub(crate) fn storage_bindings(count: u32) -> Vec<vk::DescriptorType> {
    vec![vk::DescriptorType::STORAGE_BUFFER; count as usize]
}

impl Gpu {
    /// Set layout whose binding `i` is one descriptor of `types[i]`, visible to `stages`.
    pub(crate) fn set_layout(
        &self,
        types: &[vk::DescriptorType],
        stages: vk::ShaderStageFlags,
    ) -> Result<vk::DescriptorSetLayout, GpuError> {
        let bindings: Vec<_> = types
            .iter()
            .enumerate()
            .map(|(b, &ty)| {
                vk::DescriptorSetLayoutBinding::default()
                    .binding(b as u32)
                    .descriptor_type(ty)
                    .descriptor_count(1)
                    .stage_flags(stages)
            })
            .collect();
        let info = vk::DescriptorSetLayoutCreateInfo::default().bindings(&bindings);
        Ok(unsafe { self.device.create_descriptor_set_layout(&info, None)? })
    }

    /// A pool for `sets` sets of the binding `types`.
    pub(crate) fn descriptor_pool(
        &self,
        sets: u32,
        types: &[vk::DescriptorType],
    ) -> Result<vk::DescriptorPool, GpuError> {
        let sizes: Vec<_> =
            types.iter().map(|&ty| vk::DescriptorPoolSize::default().ty(ty).descriptor_count(sets)).collect();
        let info = vk::DescriptorPoolCreateInfo::default().max_sets(sets).pool_sizes(&sizes);
        Ok(unsafe { self.device.create_descriptor_pool(&info, None)? })
    }

    /// Allocate a set from `pool` and write `descriptors[i]` (buffers whole-range) to binding `i`.
    pub(crate) fn descriptor_set(
        &self,
        pool: vk::DescriptorPool,
        layout: vk::DescriptorSetLayout,
        descriptors: &[Descriptor],
    ) -> Result<vk::DescriptorSet, GpuError> {
        let layouts = [layout];
        let info = vk::DescriptorSetAllocateInfo::default().descriptor_pool(pool).set_layouts(&layouts);
        let set = unsafe { self.device.allocate_descriptor_sets(&info)? }[0];
        let buffer_infos: Vec<[vk::DescriptorBufferInfo; 1]> = descriptors
            .iter()
            .map(|d| match d {
                Descriptor::Storage(b) => [vk::DescriptorBufferInfo::default().buffer(b.raw).range(vk::WHOLE_SIZE)],
                _ => [vk::DescriptorBufferInfo::default()],
            })
            .collect();
        let image_infos: Vec<[vk::DescriptorImageInfo; 1]> = descriptors.iter().map(|d| [d.image_info()]).collect();
        let tlases: Vec<[vk::AccelerationStructureKHR; 1]> = descriptors
            .iter()
            .map(|d| match d {
                Descriptor::Tlas(t) => [*t],
                _ => [vk::AccelerationStructureKHR::null()],
            })
            .collect();
        let mut tlas_writes: Vec<_> = tlases
            .iter()
            .map(|t| vk::WriteDescriptorSetAccelerationStructureKHR::default().acceleration_structures(t))
            .collect();
        let writes: Vec<_> = descriptors
            .iter()
            .zip(&buffer_infos)
            .zip(&mut tlas_writes)
            .zip(&image_infos)
            .enumerate()
            .map(|(i, (((d, buffer), tlas), image))| {
                let write =
                    vk::WriteDescriptorSet::default().dst_set(set).dst_binding(i as u32).descriptor_type(d.ty());
                match d {
                    Descriptor::Storage(_) => write.buffer_info(buffer),
                    // `push_next` does not set the count (lavapipe-rt.md).
                    Descriptor::Tlas(_) => write.descriptor_count(1).push_next(tlas),
                    Descriptor::SampledImage(..) | Descriptor::StorageImage(_) => write.image_info(image),
                }
            })
            .collect();
        unsafe { self.device.update_descriptor_sets(&writes, &[]) };
        Ok(set)
    }
}

/// Where a `record_*` call takes its descriptor sets from.
pub(crate) trait SetSource {
    fn set(
        &mut self,
        gpu: &Gpu,
        layout: vk::DescriptorSetLayout,
        descriptors: &[Descriptor],
    ) -> Result<vk::DescriptorSet, GpuError>;
}

/// A fresh set from the caller's pool on every call.
impl SetSource for vk::DescriptorPool {
    fn set(
        &mut self,
        gpu: &Gpu,
        layout: vk::DescriptorSetLayout,
        descriptors: &[Descriptor],
    ) -> Result<vk::DescriptorSet, GpuError> {
        gpu.descriptor_set(*self, layout, descriptors)
    }
}

/// Descriptor sets kept across frames, one per layout and bound descriptors, each in a pool of
/// its own; the least recently used beyond `capacity` are evicted (their pools wait in
/// [`KeptSets::evicted`] for the caller to retire once no frame in flight uses them).
pub(crate) struct KeptSets {
    entries: Vec<KeptSet>,
    capacity: usize,
    /// The frame being recorded (for least-recently-used eviction).
    pub(crate) frame: u64,
    pub(crate) evicted: Vec<vk::DescriptorPool>,
    /// Sets made so far.
    pub(crate) made: u64,
}

struct KeptSet {
    layout: vk::DescriptorSetLayout,
    key: Vec<u64>,
    pool: vk::DescriptorPool,
    set: vk::DescriptorSet,
    used: u64,
}

/// A descriptor as comparable numbers: kind, handle, and the layout of a sampled image.
fn descriptor_key(d: &Descriptor) -> [u64; 3] {
    use ash::vk::Handle;
    match *d {
        Descriptor::Storage(b) => [0, b.raw.as_raw(), 0],
        Descriptor::Tlas(t) => [1, t.as_raw(), 0],
        Descriptor::SampledImage(view, layout) => [2, view.as_raw(), layout.as_raw() as u64],
        Descriptor::StorageImage(view) => [3, view.as_raw(), 0],
    }
}

impl KeptSets {
    pub(crate) fn new(capacity: usize) -> KeptSets {
        KeptSets { entries: Vec::new(), capacity, frame: 0, evicted: Vec::new(), made: 0 }
    }

    /// Evict the sets that bind the object with this raw handle (destroyed: a new object may
    /// reuse the handle).
    pub(crate) fn forget(&mut self, raw: u64) {
        // Keys are [kind, handle, layout] per descriptor: compare the handles.
        let binds = |e: &KeptSet| e.key.chunks(3).any(|d| d[1] == raw);
        let (stale, kept) = std::mem::take(&mut self.entries).into_iter().partition(binds);
        self.entries = kept;
        self.evicted.extend(stale.into_iter().map(|e| e.pool));
    }

    /// Evict every set.
    pub(crate) fn clear(&mut self) {
        self.evicted.extend(std::mem::take(&mut self.entries).into_iter().map(|e| e.pool));
    }

    /// The pools of every set, kept and evicted (to destroy when the device is idle).
    pub(crate) fn drain(&mut self) -> Vec<vk::DescriptorPool> {
        self.clear();
        std::mem::take(&mut self.evicted)
    }
}

impl SetSource for KeptSets {
    fn set(
        &mut self,
        gpu: &Gpu,
        layout: vk::DescriptorSetLayout,
        descriptors: &[Descriptor],
    ) -> Result<vk::DescriptorSet, GpuError> {
        let key: Vec<u64> = descriptors.iter().flat_map(descriptor_key).collect();
        if let Some(e) = self.entries.iter_mut().find(|e| e.layout == layout && e.key == key) {
            e.used = self.frame;
            return Ok(e.set);
        }
        let types: Vec<_> = descriptors.iter().map(Descriptor::ty).collect();
        let pool = gpu.descriptor_pool(1, &types)?;
        let set = match gpu.descriptor_set(pool, layout, descriptors) {
            Ok(set) => set,
            Err(e) => {
                unsafe { gpu.device.destroy_descriptor_pool(pool, None) };
                return Err(e);
            }
        };
        if self.entries.len() >= self.capacity {
            let oldest = (0..self.entries.len()).min_by_key(|&i| self.entries[i].used).expect("not empty");
            self.evicted.push(self.entries.remove(oldest).pool);
        }
        self.entries.push(KeptSet { layout, key, pool, set, used: self.frame });
        self.made += 1;
        Ok(set)
    }
}
