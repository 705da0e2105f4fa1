//! The engine adapters on Vulkan (`aokit_shaders::adapters`): import an engine's depth image
//! (hardware depth in any of the supported conventions, or linear) and view-space normal image
//! into aokit's full-target G-buffer buffers, and export an AO buffer into the engine's AO image.
//!
//! [`Adapters`] only RECORDS into the caller's command buffer: no submit, no wait. What the
//! caller provides:
//!
//! - **Input images** (`import`): 2D images of the inner size (`ImportParams::engine_size`) with
//!   `SAMPLED` usage, viewed with one mip level and layer (a depth view with the `DEPTH` aspect
//!   only), in the layout given in [`EngineImage::layout`]: `DEPTH_STENCIL_READ_ONLY_OPTIMAL`
//!   (or `DEPTH_READ_ONLY_OPTIMAL` where the device enables `separateDepthStencilLayouts`,
//!   `SHADER_READ_ONLY_OPTIMAL`, `GENERAL`) for depth, `SHADER_READ_ONLY_OPTIMAL` (or
//!   `GENERAL`) for normals, with the engine's writes made
//!   visible to `COMPUTE_SHADER` reads by the caller's barrier (the same one that changes the
//!   layout). Depth: `D32_SFLOAT`, `D16_UNORM`, `X8_D24_UNORM_PACK32`, `D24_UNORM_S8_UINT` (its depth
//!   aspect) or `R32_SFLOAT` (linear);
//!   normals: any format read as floats (`R8G8B8A8_UNORM`, `A2B10G10R10_UNORM_PACK32`,
//!   `R16G16B16A16_SFLOAT`, …) holding `n·0.5 + 0.5` in RGB.
//! - **Output image** (`export`): a 2D image of `engine_size` with `STORAGE` usage in `GENERAL`
//!   layout, format `R32_SFLOAT`, `R16_SFLOAT` or `R8_UNORM` (the view's format picks the entry
//!   point, whose SPIR-V format must match). After [`Adapters::record_export`] the caller's
//!   barrier makes the `COMPUTE_SHADER` writes visible to whatever reads the image next.
//! - **Buffers**: the full-target storage buffers of aokit (`f32` depth, `u32` normals, `f32`
//!   AO). `record_import` ends with a barrier that makes its writes visible to later compute
//!   shaders and transfers; `record_export` starts with one that makes earlier compute and
//!   transfer writes of the AO buffer visible to it.
//! - **Descriptor pool**: each `record_*` allocates its sets from the caller's pool
//!   ([`Adapters::create_descriptor_pool`]); reset or destroy it once the command buffer has
//!   completed.
//!
//! The layout rules are the Vulkan spec's (§"Descriptor Types": sampled images in
//! `SHADER_READ_ONLY_OPTIMAL`, `GENERAL` or a depth read-only layout; storage images in
//! `GENERAL`).

use crate::compute::{ComputeKernel, compute_barrier, memory_barrier};
use crate::descriptors::{Descriptor, SetSource};
use crate::image::Image2d;
use crate::{Buffer, Gpu, GpuError, modules};
use aokit_shaders::adapters::{DEPTH_LINEAR, DEPTH_REVERSED_INFINITE, ImportParams};
use ash::vk;
use gpu_allocator::MemoryLocation;
use std::ffi::CStr;

const GROUP: u32 = 8; // threads(8, 8) in the shader crate

/// An engine image aokit reads: a 2D image of the engine's size (`AoEffect::resize`) with
/// `SAMPLED` usage, viewed with one mip level and layer (a depth view with the `DEPTH` aspect
/// only), whose writes the engine made visible to `COMPUTE_SHADER` reads before the recorded
/// commands.
///
/// * Depth: `D32_SFLOAT`, `D16_UNORM`, `X8_D24_UNORM_PACK32`, `D24_UNORM_S8_UINT` (a view of
///   its depth aspect), or `R32_SFLOAT` holding linear view depth; in `DEPTH_STENCIL_READ_ONLY_OPTIMAL` (or `DEPTH_READ_ONLY_OPTIMAL` with
///   `separateDepthStencilLayouts`, `SHADER_READ_ONLY_OPTIMAL`, `GENERAL`).
/// * Normals: any format read as floats (`R8G8B8A8_UNORM`, `A2B10G10R10_UNORM_PACK32`,
///   `R16G16B16A16_SFLOAT`, …) holding the view-space normal `n·0.5 + 0.5` in RGB; in
///   `SHADER_READ_ONLY_OPTIMAL` or `GENERAL`.
#[derive(Copy, Clone, Debug)]
pub struct EngineImage {
    /// A 2D view of the image's first mip level and layer.
    pub view: vk::ImageView,
    /// The layout the image is in while the recorded commands execute.
    pub layout: vk::ImageLayout,
}

/// The engine's AO output image: a 2D image of the engine's size with `STORAGE` usage, in
/// `GENERAL` layout while the recorded commands run, format `R32_SFLOAT`, `R16_SFLOAT` or
/// `R8_UNORM` (one export kernel each, whose storage image format matches the view's; another
/// format is refused before anything is recorded). The engine's barrier after `record` makes
/// the `COMPUTE_SHADER` writes visible to whatever reads it next.
#[derive(Copy, Clone, Debug)]
pub struct AoImage {
    /// A 2D view of the image's first mip level and layer, with storage usage.
    pub view: vk::ImageView,
    /// The view's format.
    pub format: vk::Format,
}

/// The adapter pipelines: `import_depth`, `import_normals` and one `export_ao_*` per output
/// format.
pub struct Adapters {
    import_depth: ComputeKernel,
    import_normals: ComputeKernel,
    /// One per entry of [`Adapters::EXPORT_FORMATS`].
    exports: Vec<ComputeKernel>,
}

/// Binding types of the import entry points: sampled image, storage buffer.
const IMPORT_TYPES: [vk::DescriptorType; 2] = [vk::DescriptorType::SAMPLED_IMAGE, vk::DescriptorType::STORAGE_BUFFER];
/// Binding types of the export entry points: storage buffer, storage image.
const EXPORT_TYPES: [vk::DescriptorType; 2] = [vk::DescriptorType::STORAGE_BUFFER, vk::DescriptorType::STORAGE_IMAGE];

impl Adapters {
    /// The AO output formats and the export entry point (and module) for each: the SPIR-V image
    /// format of the entry point's storage image matches the view format (Vulkan spec,
    /// "Compatibility Between SPIR-V Image Formats and Vulkan Formats").
    pub const EXPORT_FORMATS: [(vk::Format, &'static CStr, &'static [u8]); 3] = [
        (vk::Format::R32_SFLOAT, c"export_ao_r32f", modules::EXPORT_AO_R32F),
        (vk::Format::R16_SFLOAT, c"export_ao_r16f", modules::EXPORT_AO_R16F),
        (vk::Format::R8_UNORM, c"export_ao_r8", modules::EXPORT_AO_R8),
    ];

    /// The import and export pipelines on `gpu`.
    pub fn new(gpu: &Gpu) -> Result<Self, GpuError> {
        let push = size_of::<ImportParams>() as u32;
        let kernel =
            |spirv, entry, types: &[vk::DescriptorType]| ComputeKernel::new(gpu, spirv, entry, types, push, &[]);
        let exports = Self::EXPORT_FORMATS.iter().map(|&(_, entry, spirv)| kernel(spirv, entry, &EXPORT_TYPES));
        Ok(Adapters {
            import_depth: kernel(modules::IMPORT_DEPTH, c"import_depth", &IMPORT_TYPES)?,
            import_normals: kernel(modules::IMPORT_NORMALS, c"import_normals", &IMPORT_TYPES)?,
            exports: exports.collect::<Result<_, _>>()?,
        })
    }

    /// A descriptor pool for `records` calls of `record_import` (two sets each) or
    /// `record_export` (one set each). Destroy it with [`Adapters::destroy_descriptor_pool`].
    pub fn create_descriptor_pool(&self, gpu: &Gpu, records: u32) -> Result<vk::DescriptorPool, GpuError> {
        let types =
            [vk::DescriptorType::SAMPLED_IMAGE, vk::DescriptorType::STORAGE_BUFFER, vk::DescriptorType::STORAGE_IMAGE];
        gpu.descriptor_pool(2 * records.max(1), &types)
    }

    /// Destroy a pool of [`Adapters::create_descriptor_pool`].
    pub fn destroy_descriptor_pool(&self, gpu: &Gpu, pool: vk::DescriptorPool) {
        unsafe { gpu.device.destroy_descriptor_pool(pool, None) };
    }

    /// Record the import: the `depth` image (stored values in `params.depth_convention`) into
    /// its buffer (linear `f32`, full target) and, when given, the `normals` image into its
    /// buffer (encoded `u32`, full target); one invocation per full-target pixel each.
    pub fn record_import(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        mut pool: vk::DescriptorPool,
        params: &ImportParams,
        depth: (EngineImage, &Buffer),
        normals: Option<(EngineImage, &Buffer)>,
    ) -> Result<(), GpuError> {
        self.record_import_from(gpu, cb, &mut pool, params, depth, normals)
    }

    /// [`Adapters::record_import`] with the descriptor sets from `sets`.
    pub(crate) fn record_import_from(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        sets: &mut dyn SetSource,
        params: &ImportParams,
        depth: (EngineImage, &Buffer),
        normals: Option<(EngineImage, &Buffer)>,
    ) -> Result<(), GpuError> {
        check_params(params)?;
        if params.depth_convention > DEPTH_LINEAR {
            return Err(GpuError::Input(format!("unknown depth convention {}", params.depth_convention)));
        }
        let infinite = params.depth_convention == DEPTH_REVERSED_INFINITE;
        let planes_ok = params.near > 0.0 && (infinite || params.far > params.near);
        if !planes_ok {
            return Err(GpuError::Input(format!("need 0 < near < far, got {} and {}", params.near, params.far)));
        }
        let size = params.view.size();
        let bytes = 4 * u64::from(size.x) * u64::from(size.y);
        if std::iter::once(depth).chain(normals).any(|(_, b)| b.size < bytes) {
            return Err(GpuError::Input(format!("an output buffer is smaller than the {}×{} target", size.x, size.y)));
        }
        let groups = [size.x.div_ceil(GROUP), size.y.div_ceil(GROUP), 1];
        let push = bytemuck::bytes_of(params);
        // Earlier readers of the output buffers (a previous frame's passes, a download) finish first.
        type S = vk::PipelineStageFlags;
        memory_barrier(gpu, cb, S::COMPUTE_SHADER | S::TRANSFER, S::COMPUTE_SHADER);
        let input =
            |image: EngineImage, out| [Descriptor::SampledImage(image.view, image.layout), Descriptor::Storage(out)];
        self.import_depth.record(gpu, cb, sets, &input(depth.0, depth.1), push, groups)?;
        if let Some((image, out)) = normals {
            self.import_normals.record(gpu, cb, sets, &input(image, out), push, groups)?;
        }
        compute_barrier(gpu, cb, vk::PipelineStageFlags::COMPUTE_SHADER);
        Ok(())
    }

    /// Record the export of the full-target AO buffer `ao` into the engine's storage image
    /// `out` (`GENERAL` layout, `params.engine_size` texels): the inner image, clamped to
    /// [0, 1]; one invocation per output texel.
    pub fn record_export(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        mut pool: vk::DescriptorPool,
        params: &ImportParams,
        ao: &Buffer,
        out: AoImage,
    ) -> Result<(), GpuError> {
        self.record_export_from(gpu, cb, &mut pool, params, ao, out)
    }

    /// [`Adapters::record_export`] with the descriptor set from `sets`.
    pub(crate) fn record_export_from(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        sets: &mut dyn SetSource,
        params: &ImportParams,
        ao: &Buffer,
        out: AoImage,
    ) -> Result<(), GpuError> {
        check_params(params)?;
        let Some(k) = Self::EXPORT_FORMATS.iter().position(|e| e.0 == out.format) else {
            let f = out.format;
            return Err(GpuError::Input(format!("AO export to {f:?}: use R32_SFLOAT, R16_SFLOAT or R8_UNORM")));
        };
        let size = params.view.size();
        if ao.size < 4 * u64::from(size.x) * u64::from(size.y) {
            return Err(GpuError::Input(format!("AO buffer smaller than the {}×{} target", size.x, size.y)));
        }
        let e = params.engine_size;
        let groups = [e.x.div_ceil(GROUP), e.y.div_ceil(GROUP), 1];
        type S = vk::PipelineStageFlags;
        memory_barrier(gpu, cb, S::COMPUTE_SHADER | S::TRANSFER, S::COMPUTE_SHADER);
        let descriptors = [Descriptor::Storage(ao), Descriptor::StorageImage(out.view)];
        self.exports[k].record(gpu, cb, sets, &descriptors, bytemuck::bytes_of(params), groups)
    }

    /// Destroy the pipelines (after the device finished every frame that used them).
    pub fn destroy(&self, gpu: &Gpu) {
        for k in [&self.import_depth, &self.import_normals].into_iter().chain(&self.exports) {
            k.destroy(gpu);
        }
    }
}

/// The checks the kernels rely on: a non-empty engine image and a full target that holds it.
fn check_params(params: &ImportParams) -> Result<(), GpuError> {
    let (e, size, g) = (params.engine_size, params.view.size(), params.view.guard);
    if e.x == 0 || e.y == 0 || size.x <= 2 * g || size.y <= 2 * g {
        return Err(GpuError::Input(format!(
            "engine image {}×{}, target {}×{} with guard {g}: both must be non-empty",
            e.x, e.y, size.x, size.y
        )));
    }
    Ok(())
}

impl Gpu {
    /// Record a layout transition of the whole image that also makes every earlier write
    /// visible to every later access (a full barrier: for setup and tests, not for frames).
    pub fn record_image_layout(
        &self,
        cb: vk::CommandBuffer,
        image: &Image2d,
        old: vk::ImageLayout,
        new: vk::ImageLayout,
    ) {
        let all = vk::AccessFlags::MEMORY_READ | vk::AccessFlags::MEMORY_WRITE;
        let barrier = vk::ImageMemoryBarrier::default()
            .src_access_mask(all)
            .dst_access_mask(all)
            .old_layout(old)
            .new_layout(new)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .image(image.raw)
            .subresource_range(image.range());
        let stages = vk::PipelineStageFlags::ALL_COMMANDS;
        unsafe {
            self.device.cmd_pipeline_barrier(cb, stages, stages, vk::DependencyFlags::empty(), &[], &[], &[barrier])
        };
    }

    /// Fill the image with `bytes` (tightly packed texels of its format; for a depth format, the
    /// depth aspect) through a staging buffer, leaving it in `layout`. Submits and waits.
    pub fn upload_image(&self, image: &Image2d, bytes: &[u8], layout: vk::ImageLayout) -> Result<(), GpuError> {
        let staging =
            self.create_buffer(bytes.len() as u64, vk::BufferUsageFlags::TRANSFER_SRC, MemoryLocation::CpuToGpu)?;
        staging.write(bytes);
        let copied = self.submit(|cb| unsafe {
            let dst = vk::ImageLayout::TRANSFER_DST_OPTIMAL;
            self.record_image_layout(cb, image, vk::ImageLayout::UNDEFINED, dst);
            self.device.cmd_copy_buffer_to_image(cb, staging.raw, image.raw, dst, &[image.copy_region()]);
            self.record_image_layout(cb, image, dst, layout);
        });
        self.free_buffer(staging);
        copied
    }

    /// Read the image (in `layout`, where it is left) back as tightly packed texels. Submits and
    /// waits.
    pub fn download_image(
        &self,
        image: &Image2d,
        layout: vk::ImageLayout,
        texel_bytes: u64,
    ) -> Result<Vec<u8>, GpuError> {
        let size = texel_bytes * u64::from(image.width) * u64::from(image.height);
        let usage = vk::BufferUsageFlags::TRANSFER_DST | vk::BufferUsageFlags::TRANSFER_SRC;
        let buffer = self.create_buffer(size, usage, MemoryLocation::GpuOnly)?;
        let copied = self.submit(|cb| unsafe {
            let src = vk::ImageLayout::TRANSFER_SRC_OPTIMAL;
            self.record_image_layout(cb, image, layout, src);
            self.device.cmd_copy_image_to_buffer(cb, image.raw, src, buffer.raw, &[image.copy_region()]);
            self.record_image_layout(cb, image, src, layout);
        });
        let bytes = copied.and_then(|_| self.download::<u8>(&buffer));
        self.free_buffer(buffer);
        bytes.map(|mut b| {
            b.truncate(size as usize);
            b
        })
    }

    /// Record commands into a fresh command buffer, submit it and wait: for tests and tools that
    /// drive the `record_*` functions themselves.
    pub fn run_commands<R>(&self, record: impl FnOnce(vk::CommandBuffer) -> R) -> Result<R, GpuError> {
        self.submit(record)
    }

    /// Record a whole-buffer copy of `src` into `dst` (`dst` at least as large).
    pub fn record_copy_buffer(&self, cb: vk::CommandBuffer, src: &Buffer, dst: &Buffer) {
        assert!(dst.size >= src.size, "copy into a smaller buffer");
        unsafe { self.device.cmd_copy_buffer(cb, src.raw, dst.raw, &[vk::BufferCopy::default().size(src.size)]) };
    }
}
