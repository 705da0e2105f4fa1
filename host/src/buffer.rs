//! Buffers with gpu-allocator memory, and host ↔ device transfers through staging buffers.

use crate::{Gpu, GpuError};
use ash::vk;
use gpu_allocator::MemoryLocation;
use gpu_allocator::vulkan::{Allocation, AllocationCreateDesc, AllocationScheme};

/// A `VkBuffer` and its memory. Free it with [`Gpu::free_buffer`].
pub struct Buffer {
    /// The Vulkan buffer.
    pub raw: vk::Buffer,
    /// Its size in bytes.
    pub size: u64,
    allocation: Option<Allocation>,
}

impl Buffer {
    /// Copy `bytes` into a host-visible buffer.
    pub(crate) fn write(&self, bytes: &[u8]) {
        let mapped = self.allocation.as_ref().and_then(|a| a.mapped_ptr()).expect("host-visible buffer");
        assert!(bytes.len() as u64 <= self.size);
        unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), mapped.as_ptr() as *mut u8, bytes.len()) };
    }
}

impl Gpu {
    /// Create a buffer of `size` bytes (at least 4) in `location`.
    pub fn create_buffer(
        &self,
        size: u64,
        usage: vk::BufferUsageFlags,
        location: MemoryLocation,
    ) -> Result<Buffer, GpuError> {
        let size = size.max(4);
        let raw = unsafe {
            self.device.create_buffer(
                &vk::BufferCreateInfo::default().size(size).usage(usage).sharing_mode(vk::SharingMode::EXCLUSIVE),
                None,
            )?
        };
        let requirements = unsafe { self.device.get_buffer_memory_requirements(raw) };
        let allocation = self.allocator.lock().unwrap_or_else(|e| e.into_inner()).allocate(&AllocationCreateDesc {
            name: "aokit buffer",
            requirements,
            location,
            linear: true,
            allocation_scheme: AllocationScheme::GpuAllocatorManaged,
        });
        let allocation = match allocation {
            Ok(a) => a,
            Err(e) => {
                unsafe { self.device.destroy_buffer(raw, None) };
                return Err(e.into());
            }
        };
        unsafe { self.device.bind_buffer_memory(raw, allocation.memory(), allocation.offset())? };
        Ok(Buffer { raw, size, allocation: Some(allocation) })
    }

    /// Release a buffer and its memory.
    pub fn free_buffer(&self, mut buffer: Buffer) {
        if let Some(a) = buffer.allocation.take() {
            let _ = self.allocator.lock().unwrap_or_else(|e| e.into_inner()).free(a);
        }
        unsafe { self.device.destroy_buffer(buffer.raw, None) };
    }

    /// A device-local storage buffer holding `data` (uploaded through a staging buffer).
    pub fn upload<T: bytemuck::Pod>(&self, data: &[T], usage: vk::BufferUsageFlags) -> Result<Buffer, GpuError> {
        let bytes: &[u8] = bytemuck::cast_slice(data);
        let staging =
            self.create_buffer(bytes.len() as u64, vk::BufferUsageFlags::TRANSFER_SRC, MemoryLocation::CpuToGpu)?;
        staging.write(bytes);
        let buffer = self.create_buffer(
            bytes.len() as u64,
            usage | vk::BufferUsageFlags::TRANSFER_DST | vk::BufferUsageFlags::TRANSFER_SRC,
            MemoryLocation::GpuOnly,
        )?;
        let copied = self.submit(|cb| unsafe {
            let region = vk::BufferCopy::default().size(bytes.len().max(4) as u64);
            self.device.cmd_copy_buffer(cb, staging.raw, buffer.raw, &[region]);
        });
        self.free_buffer(staging);
        copied?;
        Ok(buffer)
    }

    /// Read `buffer` back to the host.
    pub fn download<T: bytemuck::Pod>(&self, buffer: &Buffer) -> Result<Vec<T>, GpuError> {
        let staging = self.create_buffer(buffer.size, vk::BufferUsageFlags::TRANSFER_DST, MemoryLocation::GpuToCpu)?;
        let copied = self.submit(|cb| unsafe {
            self.device.cmd_copy_buffer(cb, buffer.raw, staging.raw, &[vk::BufferCopy::default().size(buffer.size)]);
        });
        let result = copied.map(|_| {
            let mapped = staging.allocation.as_ref().and_then(|a| a.mapped_ptr()).expect("GpuToCpu memory is mapped");
            let count = buffer.size as usize / std::mem::size_of::<T>();
            let mut out = vec![T::zeroed(); count];
            unsafe {
                std::ptr::copy_nonoverlapping(
                    mapped.as_ptr() as *const u8,
                    out.as_mut_ptr() as *mut u8,
                    count * std::mem::size_of::<T>(),
                )
            };
            out
        });
        self.free_buffer(staging);
        result
    }
}
