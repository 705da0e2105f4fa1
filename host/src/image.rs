//! 2D images with their memory and view: render targets, and engine-like images for tests and
//! tools.

use crate::{Gpu, GpuError};
use ash::vk;
use gpu_allocator::MemoryLocation;
use gpu_allocator::vulkan::{Allocation, AllocationCreateDesc, AllocationScheme};

/// A 2D image with one mip level and layer, its view (all aspects of a colour format, the depth
/// aspect of a depth format) and its memory: what tests and tools need to hand the adapters an
/// engine-like image. Free it with [`Gpu::free_image`].
pub struct Image2d {
    /// The image.
    pub raw: vk::Image,
    /// Its view.
    pub view: vk::ImageView,
    /// Its format.
    pub format: vk::Format,
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    allocation: Option<Allocation>,
}

impl Image2d {
    /// The aspect its view shows and copies read or write: `DEPTH` for a depth format (a
    /// depth/stencil format's depth), `COLOR` otherwise.
    pub fn aspect(&self) -> vk::ImageAspectFlags {
        aspect_of(self.format)
    }

    /// Every aspect of the image, for layout transitions: a combined depth/stencil format
    /// transitions both (Vulkan spec, VUID-VkImageMemoryBarrier-image-03320, without
    /// `separateDepthStencilLayouts`).
    pub fn range(&self) -> vk::ImageSubresourceRange {
        let aspect = if has_stencil(self.format) {
            vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL
        } else {
            self.aspect()
        };
        vk::ImageSubresourceRange::default().aspect_mask(aspect).level_count(1).layer_count(1)
    }

    /// A buffer ↔ image copy of the whole image's [`Image2d::aspect`], tightly packed from
    /// buffer offset 0.
    pub fn copy_region(&self) -> vk::BufferImageCopy {
        vk::BufferImageCopy::default()
            .image_subresource(vk::ImageSubresourceLayers::default().aspect_mask(self.aspect()).layer_count(1))
            .image_extent(vk::Extent3D { width: self.width, height: self.height, depth: 1 })
    }
}

/// A combined depth/stencil format.
fn has_stencil(format: vk::Format) -> bool {
    matches!(format, vk::Format::D16_UNORM_S8_UINT | vk::Format::D24_UNORM_S8_UINT | vk::Format::D32_SFLOAT_S8_UINT)
}

fn aspect_of(format: vk::Format) -> vk::ImageAspectFlags {
    match format {
        vk::Format::D32_SFLOAT
        | vk::Format::D16_UNORM
        | vk::Format::X8_D24_UNORM_PACK32
        | vk::Format::D16_UNORM_S8_UINT
        | vk::Format::D24_UNORM_S8_UINT
        | vk::Format::D32_SFLOAT_S8_UINT => vk::ImageAspectFlags::DEPTH,
        _ => vk::ImageAspectFlags::COLOR,
    }
}

impl Gpu {
    /// A device-local 2D image (optimal tiling, `UNDEFINED` layout) and its view.
    pub fn create_image_2d(
        &self,
        format: vk::Format,
        width: u32,
        height: u32,
        usage: vk::ImageUsageFlags,
    ) -> Result<Image2d, GpuError> {
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(vk::Extent3D { width, height, depth: 1 })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(usage)
            .initial_layout(vk::ImageLayout::UNDEFINED);
        let raw = unsafe { self.device.create_image(&info, None)? };
        let mut image = Image2d { raw, view: vk::ImageView::null(), format, width, height, allocation: None };
        let requirements = unsafe { self.device.get_image_memory_requirements(raw) };
        let desc = AllocationCreateDesc {
            name: "aokit image",
            requirements,
            location: MemoryLocation::GpuOnly,
            linear: false,
            allocation_scheme: AllocationScheme::GpuAllocatorManaged,
        };
        let created = (|| -> Result<(), GpuError> {
            let allocation = self.allocator.lock().unwrap_or_else(|e| e.into_inner()).allocate(&desc)?;
            let (memory, offset) = unsafe { (allocation.memory(), allocation.offset()) };
            image.allocation = Some(allocation);
            unsafe { self.device.bind_image_memory(raw, memory, offset)? };
            let view = vk::ImageViewCreateInfo::default()
                .image(raw)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(format)
                .subresource_range(image.range().aspect_mask(image.aspect()));
            image.view = unsafe { self.device.create_image_view(&view, None)? };
            Ok(())
        })();
        match created {
            Ok(()) => Ok(image),
            Err(e) => {
                self.free_image(image);
                Err(e)
            }
        }
    }

    /// Release an image, its view and its memory.
    pub fn free_image(&self, mut image: Image2d) {
        unsafe {
            self.device.destroy_image_view(image.view, None);
            self.device.destroy_image(image.raw, None);
        }
        if let Some(a) = image.allocation.take() {
            let _ = self.allocator.lock().unwrap_or_else(|e| e.into_inner()).free(a);
        }
    }
}
