//! Raster G-buffer pass with dynamic rendering: linear depth (R32_SFLOAT) and encoded face
//! normal (R32_UINT) over the full target, copied into storage buffers for the compute passes.

use crate::descriptors::{Descriptor, storage_bindings};
use crate::{Buffer, Gpu, GpuError, modules};
use aokit_shaders::common::alpha::AlphaMaskHeader;
use aokit_shaders::gbuffer::RasterParams;
use ash::vk;
use gpu_allocator::MemoryLocation;
use gpu_allocator::vulkan::{Allocation, AllocationCreateDesc, AllocationScheme};

/// One de-indexed vertex: world position, its triangle's world face normal (w unused), texture
/// coordinate and material index (for the alpha test).
#[repr(C)]
#[derive(Copy, Clone, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GBufferVertex {
    pub position: [f32; 4],
    pub face_normal: [f32; 4],
    pub uv: [f32; 2],
    pub material: u32,
    pub _pad: u32,
}

const DEPTH_FORMAT: vk::Format = vk::Format::R32_SFLOAT;
const NORMAL_FORMAT: vk::Format = vk::Format::R32_UINT;
const Z_FORMAT: vk::Format = vk::Format::D32_SFLOAT;

/// The G-buffer raster pipeline.
pub struct RasterGBuffer {
    set_layout: vk::DescriptorSetLayout,
    layout: vk::PipelineLayout,
    pipeline: vk::Pipeline,
    /// Same pipeline with the depth-peeling fragment shader (spec §11).
    peel_pipeline: vk::Pipeline,
}

struct Target {
    image: vk::Image,
    view: vk::ImageView,
    allocation: Allocation,
}

impl Gpu {
    fn create_target(
        &self,
        format: vk::Format,
        extent: vk::Extent2D,
        usage: vk::ImageUsageFlags,
        aspect: vk::ImageAspectFlags,
    ) -> Result<Target, GpuError> {
        let d = &self.device;
        unsafe {
            let image = d.create_image(
                &vk::ImageCreateInfo::default()
                    .image_type(vk::ImageType::TYPE_2D)
                    .format(format)
                    .extent(extent.into())
                    .mip_levels(1)
                    .array_layers(1)
                    .samples(vk::SampleCountFlags::TYPE_1)
                    .tiling(vk::ImageTiling::OPTIMAL)
                    .usage(usage)
                    .initial_layout(vk::ImageLayout::UNDEFINED),
                None,
            )?;
            let allocation =
                self.allocator.lock().unwrap_or_else(|e| e.into_inner()).allocate(&AllocationCreateDesc {
                    name: "aokit render target",
                    requirements: d.get_image_memory_requirements(image),
                    location: MemoryLocation::GpuOnly,
                    linear: false,
                    allocation_scheme: AllocationScheme::GpuAllocatorManaged,
                })?;
            d.bind_image_memory(image, allocation.memory(), allocation.offset())?;
            let view = d.create_image_view(
                &vk::ImageViewCreateInfo::default()
                    .image(image)
                    .view_type(vk::ImageViewType::TYPE_2D)
                    .format(format)
                    .subresource_range(
                        vk::ImageSubresourceRange::default().aspect_mask(aspect).level_count(1).layer_count(1),
                    ),
                None,
            )?;
            Ok(Target { image, view, allocation })
        }
    }

    fn destroy_target(&self, t: Target) {
        unsafe {
            self.device.destroy_image_view(t.view, None);
            self.device.destroy_image(t.image, None);
        }
        let _ = self.allocator.lock().unwrap_or_else(|e| e.into_inner()).free(t.allocation);
    }
}

fn layout_barrier(
    gpu: &Gpu,
    cb: vk::CommandBuffer,
    image: vk::Image,
    aspect: vk::ImageAspectFlags,
    (old, new): (vk::ImageLayout, vk::ImageLayout),
    (src_stage, src_access): (vk::PipelineStageFlags, vk::AccessFlags),
    (dst_stage, dst_access): (vk::PipelineStageFlags, vk::AccessFlags),
) {
    let barrier = vk::ImageMemoryBarrier::default()
        .old_layout(old)
        .new_layout(new)
        .src_access_mask(src_access)
        .dst_access_mask(dst_access)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .image(image)
        .subresource_range(vk::ImageSubresourceRange::default().aspect_mask(aspect).level_count(1).layer_count(1));
    unsafe {
        gpu.device.cmd_pipeline_barrier(cb, src_stage, dst_stage, vk::DependencyFlags::empty(), &[], &[], &[barrier])
    };
}

/// Viewport and scissor covering `area` (both are dynamic state of every raster pipeline here).
unsafe fn set_viewport(d: &ash::Device, cb: vk::CommandBuffer, area: vk::Rect2D) {
    let viewport = vk::Viewport {
        x: 0.0,
        y: 0.0,
        width: area.extent.width as f32,
        height: area.extent.height as f32,
        min_depth: 0.0,
        max_depth: 1.0,
    };
    unsafe {
        d.cmd_set_viewport(cb, 0, &[viewport]);
        d.cmd_set_scissor(cb, 0, &[area]);
    }
}

/// A graphics pipeline drawing de-indexed [`GBufferVertex`] triangles without culling, viewport
/// and scissor dynamic. `targets`: the G-buffer's colour formats and depth format (reverse-Z
/// depth test, writes), or `None` for a pass without attachments (the raster SD map).
unsafe fn graphics_pipeline(
    d: &ash::Device,
    layout: vk::PipelineLayout,
    stages: &[vk::PipelineShaderStageCreateInfo],
    targets: Option<(&[vk::Format], vk::Format)>,
) -> Result<vk::Pipeline, GpuError> {
    let bindings = [vk::VertexInputBindingDescription::default()
        .binding(0)
        .stride(size_of::<GBufferVertex>() as u32)
        .input_rate(vk::VertexInputRate::VERTEX)];
    // (location, format, offset) of GBufferVertex's fields.
    let attributes = [
        (0, vk::Format::R32G32B32A32_SFLOAT, 0),
        (1, vk::Format::R32G32B32A32_SFLOAT, 16),
        (2, vk::Format::R32G32_SFLOAT, 32),
        (3, vk::Format::R32_UINT, 40),
    ]
    .map(|(location, format, offset)| {
        vk::VertexInputAttributeDescription::default().location(location).binding(0).format(format).offset(offset)
    });
    let vertex_input = vk::PipelineVertexInputStateCreateInfo::default()
        .vertex_binding_descriptions(&bindings)
        .vertex_attribute_descriptions(&attributes);
    let assembly = vk::PipelineInputAssemblyStateCreateInfo::default().topology(vk::PrimitiveTopology::TRIANGLE_LIST);
    let viewport = vk::PipelineViewportStateCreateInfo::default().viewport_count(1).scissor_count(1);
    // No culling: primary rays on the CPU also take the first surface whatever its winding.
    let raster = vk::PipelineRasterizationStateCreateInfo::default()
        .polygon_mode(vk::PolygonMode::FILL)
        .cull_mode(vk::CullModeFlags::NONE)
        .front_face(vk::FrontFace::COUNTER_CLOCKWISE)
        .line_width(1.0);
    let multisample =
        vk::PipelineMultisampleStateCreateInfo::default().rasterization_samples(vk::SampleCountFlags::TYPE_1);
    // Reverse-Z: nearer is greater.
    let depth = match targets {
        Some(_) => vk::PipelineDepthStencilStateCreateInfo::default()
            .depth_test_enable(true)
            .depth_write_enable(true)
            .depth_compare_op(vk::CompareOp::GREATER),
        None => vk::PipelineDepthStencilStateCreateInfo::default(),
    };
    let blend_attachments =
        [vk::PipelineColorBlendAttachmentState::default().color_write_mask(vk::ColorComponentFlags::R); 2];
    let colours = targets.map_or(0, |(f, _)| f.len());
    let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blend_attachments[..colours]);
    let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
    let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic_states);
    let mut rendering = match targets {
        Some((formats, z)) => {
            vk::PipelineRenderingCreateInfo::default().color_attachment_formats(formats).depth_attachment_format(z)
        }
        None => vk::PipelineRenderingCreateInfo::default(),
    };
    let info = vk::GraphicsPipelineCreateInfo::default()
        .stages(stages)
        .vertex_input_state(&vertex_input)
        .input_assembly_state(&assembly)
        .viewport_state(&viewport)
        .rasterization_state(&raster)
        .multisample_state(&multisample)
        .depth_stencil_state(&depth)
        .color_blend_state(&blend)
        .dynamic_state(&dynamic)
        .layout(layout)
        .push_next(&mut rendering);
    let created = unsafe { d.create_graphics_pipelines(vk::PipelineCache::null(), &[info], None) };
    Ok(created.map_err(|(_, e)| e)?[0])
}

/// The raster pass's push constants are read by the vertex and (peeling) fragment shaders.
const PUSH_STAGES: vk::ShaderStageFlags =
    vk::ShaderStageFlags::from_raw(vk::ShaderStageFlags::VERTEX.as_raw() | vk::ShaderStageFlags::FRAGMENT.as_raw());

impl RasterGBuffer {
    pub fn new(gpu: &Gpu) -> Result<Self, GpuError> {
        let d = &gpu.device;
        unsafe {
            let push =
                [vk::PushConstantRange::default().stage_flags(PUSH_STAGES).size(size_of::<RasterParams>() as u32)];
            // Fragment-stage storage buffers: alpha-mask headers and texels, and (peeling only)
            // the first layer's depth.
            let set_layout = gpu.set_layout(&storage_bindings(3), vk::ShaderStageFlags::FRAGMENT)?;
            let set_layouts = [set_layout];
            let layout = d.create_pipeline_layout(
                &vk::PipelineLayoutCreateInfo::default().set_layouts(&set_layouts).push_constant_ranges(&push),
                None,
            )?;
            let vs = gpu.shader_module(modules::GBUFFER_VS)?;
            let fs = gpu.shader_module(modules::GBUFFER_FS)?;
            let peel_fs = gpu.shader_module(modules::GBUFFER_PEEL_FS)?;
            let stages = |fs: vk::ShaderModule, name: &'static std::ffi::CStr| {
                [
                    vk::PipelineShaderStageCreateInfo::default()
                        .stage(vk::ShaderStageFlags::VERTEX)
                        .module(vs)
                        .name(c"gbuffer_vs"),
                    vk::PipelineShaderStageCreateInfo::default()
                        .stage(vk::ShaderStageFlags::FRAGMENT)
                        .module(fs)
                        .name(name),
                ]
            };
            let (first_stages, peel_stages) = (stages(fs, c"gbuffer_fs"), stages(peel_fs, c"gbuffer_peel_fs"));
            let formats = [DEPTH_FORMAT, NORMAL_FORMAT];
            let targets = Some((&formats[..], Z_FORMAT));
            let first = graphics_pipeline(d, layout, &first_stages, targets);
            let peel = graphics_pipeline(d, layout, &peel_stages, targets);
            for m in [vs, fs, peel_fs] {
                d.destroy_shader_module(m, None);
            }
            let pipelines = [first?, peel?];
            Ok(RasterGBuffer { set_layout, layout, pipeline: pipelines[0], peel_pipeline: pipelines[1] })
        }
    }

    /// Rasterize `vertices` (de-indexed triangles) into `(depth, normals)` storage buffers of the
    /// full target; empty pixels hold depth = far and normal code 0. `masks` are the alpha masks
    /// per material (non-empty slices). Returns the buffers and the GPU time of the pass in
    /// milliseconds.
    ///
    /// With `first_layer` (a linear-depth buffer of the full target) this is the depth-peeling
    /// pass of spec §11: only fragments beyond that depth + `params.peel_separation` survive.
    pub fn render(
        &self,
        gpu: &Gpu,
        vertices: &[GBufferVertex],
        masks: &(Vec<AlphaMaskHeader>, Vec<f32>),
        params: &RasterParams,
        first_layer: Option<&Buffer>,
    ) -> Result<(Buffer, Buffer, f64), GpuError> {
        let size = params.view.size();
        if size.x == 0 || size.y == 0 || vertices.is_empty() || masks.0.is_empty() || masks.1.is_empty() {
            return Err(GpuError::Input(format!(
                "empty raster input ({}×{}, {} vertices)",
                size.x,
                size.y,
                vertices.len()
            )));
        }
        let storage_in = vk::BufferUsageFlags::STORAGE_BUFFER;
        let headers = gpu.upload(&masks.0, storage_in)?;
        let texels = gpu.upload(&masks.1, storage_in)?;
        let d = &gpu.device;
        let pool = gpu.descriptor_pool(1, &storage_bindings(3))?;
        // The first pass does not read binding 2; it gets the headers as a placeholder.
        let third = first_layer.unwrap_or(&headers);
        let set = gpu.descriptor_set(
            pool,
            self.set_layout,
            &[Descriptor::Storage(&headers), Descriptor::Storage(&texels), Descriptor::Storage(third)],
        )?;
        let pipeline = if first_layer.is_some() { self.peel_pipeline } else { self.pipeline };
        let extent = vk::Extent2D { width: size.x, height: size.y };
        let pixels = (size.x * size.y) as u64;
        let vbuf = gpu.upload(vertices, vk::BufferUsageFlags::VERTEX_BUFFER)?;
        let color = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC;
        let depth_t = gpu.create_target(DEPTH_FORMAT, extent, color, vk::ImageAspectFlags::COLOR)?;
        let normal_t = gpu.create_target(NORMAL_FORMAT, extent, color, vk::ImageAspectFlags::COLOR)?;
        let z_t = gpu.create_target(
            Z_FORMAT,
            extent,
            vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
            vk::ImageAspectFlags::DEPTH,
        )?;
        let storage = vk::BufferUsageFlags::STORAGE_BUFFER
            | vk::BufferUsageFlags::TRANSFER_DST
            | vk::BufferUsageFlags::TRANSFER_SRC;
        let depth_buf = gpu.create_buffer(4 * pixels, storage, MemoryLocation::GpuOnly)?;
        let normal_buf = gpu.create_buffer(4 * pixels, storage, MemoryLocation::GpuOnly)?;
        let timed = unsafe {
            d.create_query_pool(
                &vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(2),
                None,
            )
        };
        let result = timed.map_err(GpuError::from).and_then(|queries| {
            let submitted = gpu.submit(|cb| unsafe {
                d.cmd_reset_query_pool(cb, queries, 0, 2);
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TOP_OF_PIPE, queries, 0);
                let to_attachment = (vk::ImageLayout::UNDEFINED, vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL);
                let none = (vk::PipelineStageFlags::TOP_OF_PIPE, vk::AccessFlags::empty());
                let color_out =
                    (vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT, vk::AccessFlags::COLOR_ATTACHMENT_WRITE);
                for t in [&depth_t, &normal_t] {
                    layout_barrier(gpu, cb, t.image, vk::ImageAspectFlags::COLOR, to_attachment, none, color_out);
                }
                layout_barrier(
                    gpu,
                    cb,
                    z_t.image,
                    vk::ImageAspectFlags::DEPTH,
                    (vk::ImageLayout::UNDEFINED, vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL),
                    none,
                    (
                        vk::PipelineStageFlags::EARLY_FRAGMENT_TESTS | vk::PipelineStageFlags::LATE_FRAGMENT_TESTS,
                        vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_READ
                            | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
                    ),
                );
                let colors = [
                    vk::RenderingAttachmentInfo::default()
                        .image_view(depth_t.view)
                        .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
                        .load_op(vk::AttachmentLoadOp::CLEAR)
                        .store_op(vk::AttachmentStoreOp::STORE)
                        .clear_value(vk::ClearValue {
                            color: vk::ClearColorValue { float32: [params.view.far, 0.0, 0.0, 0.0] },
                        }),
                    vk::RenderingAttachmentInfo::default()
                        .image_view(normal_t.view)
                        .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
                        .load_op(vk::AttachmentLoadOp::CLEAR)
                        .store_op(vk::AttachmentStoreOp::STORE)
                        .clear_value(vk::ClearValue { color: vk::ClearColorValue { uint32: [0; 4] } }),
                ];
                let z = vk::RenderingAttachmentInfo::default()
                    .image_view(z_t.view)
                    .image_layout(vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL)
                    .load_op(vk::AttachmentLoadOp::CLEAR)
                    .store_op(vk::AttachmentStoreOp::DONT_CARE)
                    .clear_value(vk::ClearValue {
                        depth_stencil: vk::ClearDepthStencilValue { depth: 0.0, stencil: 0 },
                    });
                let area = vk::Rect2D { offset: vk::Offset2D::default(), extent };
                d.cmd_begin_rendering(
                    cb,
                    &vk::RenderingInfo::default()
                        .render_area(area)
                        .layer_count(1)
                        .color_attachments(&colors)
                        .depth_attachment(&z),
                );
                d.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, pipeline);
                d.cmd_bind_descriptor_sets(cb, vk::PipelineBindPoint::GRAPHICS, self.layout, 0, &[set], &[]);
                set_viewport(d, cb, area);
                d.cmd_push_constants(cb, self.layout, PUSH_STAGES, 0, bytemuck::bytes_of(params));
                d.cmd_bind_vertex_buffers(cb, 0, &[vbuf.raw], &[0]);
                d.cmd_draw(cb, vertices.len() as u32, 1, 0, 0);
                d.cmd_end_rendering(cb);
                let to_src = (vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL, vk::ImageLayout::TRANSFER_SRC_OPTIMAL);
                let transfer = (vk::PipelineStageFlags::TRANSFER, vk::AccessFlags::TRANSFER_READ);
                for (t, buf) in [(&depth_t, &depth_buf), (&normal_t, &normal_buf)] {
                    layout_barrier(gpu, cb, t.image, vk::ImageAspectFlags::COLOR, to_src, color_out, transfer);
                    let region = vk::BufferImageCopy::default()
                        .image_subresource(
                            vk::ImageSubresourceLayers::default()
                                .aspect_mask(vk::ImageAspectFlags::COLOR)
                                .layer_count(1),
                        )
                        .image_extent(extent.into());
                    d.cmd_copy_image_to_buffer(cb, t.image, vk::ImageLayout::TRANSFER_SRC_OPTIMAL, buf.raw, &[region]);
                }
                let barrier = vk::MemoryBarrier::default()
                    .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
                    .dst_access_mask(vk::AccessFlags::SHADER_READ | vk::AccessFlags::TRANSFER_READ);
                d.cmd_pipeline_barrier(
                    cb,
                    vk::PipelineStageFlags::TRANSFER,
                    vk::PipelineStageFlags::COMPUTE_SHADER | vk::PipelineStageFlags::TRANSFER,
                    vk::DependencyFlags::empty(),
                    &[barrier],
                    &[],
                    &[],
                );
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TRANSFER, queries, 1);
            });
            let got = submitted.and_then(|_| gpu.timestamps_ms(queries, 2));
            unsafe { d.destroy_query_pool(queries, None) };
            got.map(|t| t[1])
        });
        gpu.free_buffer(vbuf);
        gpu.free_buffer(headers);
        gpu.free_buffer(texels);
        unsafe { d.destroy_descriptor_pool(pool, None) };
        for t in [depth_t, normal_t, z_t] {
            gpu.destroy_target(t);
        }
        match result {
            Ok(ms) => Ok((depth_buf, normal_buf, ms)),
            Err(e) => {
                gpu.free_buffer(depth_buf);
                gpu.free_buffer(normal_buf);
                Err(e)
            }
        }
    }

    pub fn destroy(&self, gpu: &Gpu) {
        unsafe {
            gpu.device.destroy_pipeline(self.pipeline, None);
            gpu.device.destroy_pipeline(self.peel_pipeline, None);
            gpu.device.destroy_pipeline_layout(self.layout, None);
            gpu.device.destroy_descriptor_set_layout(self.set_layout, None);
        }
    }
}

/// The raster stochastic-depth pass (spec svao-raysd §8): the G-buffer's vertex shader and the
/// coverage-mask fragment shader at SD resolution, no attachments (samples are written with
/// atomics to a storage buffer).
pub struct RasterSdPass {
    pub(crate) set_layout: vk::DescriptorSetLayout,
    layout: vk::PipelineLayout,
    pipeline: vk::Pipeline,
}

/// Storage buffers of the raster SD fragment shader, in binding order.
pub const RASTER_SD_BINDINGS: u32 = 7;

impl RasterSdPass {
    pub fn new(gpu: &Gpu) -> Result<Self, GpuError> {
        let d = &gpu.device;
        unsafe {
            let push = [vk::PushConstantRange::default()
                .stage_flags(vk::ShaderStageFlags::VERTEX)
                .size(size_of::<RasterParams>() as u32)];
            let set_layout = gpu.set_layout(&storage_bindings(RASTER_SD_BINDINGS), vk::ShaderStageFlags::FRAGMENT)?;
            let set_layouts = [set_layout];
            let layout = d.create_pipeline_layout(
                &vk::PipelineLayoutCreateInfo::default().set_layouts(&set_layouts).push_constant_ranges(&push),
                None,
            )?;
            let vs = gpu.shader_module(modules::GBUFFER_VS)?;
            let fs = gpu.shader_module(modules::RASTERSD_FS)?;
            let stages = [
                vk::PipelineShaderStageCreateInfo::default()
                    .stage(vk::ShaderStageFlags::VERTEX)
                    .module(vs)
                    .name(c"gbuffer_vs"),
                vk::PipelineShaderStageCreateInfo::default()
                    .stage(vk::ShaderStageFlags::FRAGMENT)
                    .module(fs)
                    .name(c"rastersd_fs"),
            ];
            let created = graphics_pipeline(d, layout, &stages, None);
            d.destroy_shader_module(vs, None);
            d.destroy_shader_module(fs, None);
            let pipeline = created?;
            Ok(RasterSdPass { set_layout, layout, pipeline })
        }
    }

    /// Record the pass over `size` SD texels: draw `count` vertices from `vertices` with
    /// descriptor set `set` (headers, texels, frame, depth, rayMin, rayMax, SD sample bits).
    pub(crate) fn record(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        set: vk::DescriptorSet,
        (vertices, count): (&Buffer, u32),
        params: &RasterParams,
        size: aokit_shaders::glam::UVec2,
    ) {
        let d = &gpu.device;
        let extent = vk::Extent2D { width: size.x, height: size.y };
        let area = vk::Rect2D { offset: vk::Offset2D::default(), extent };
        unsafe {
            d.cmd_begin_rendering(cb, &vk::RenderingInfo::default().render_area(area).layer_count(1));
            d.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, self.pipeline);
            d.cmd_bind_descriptor_sets(cb, vk::PipelineBindPoint::GRAPHICS, self.layout, 0, &[set], &[]);
            set_viewport(d, cb, area);
            d.cmd_push_constants(cb, self.layout, vk::ShaderStageFlags::VERTEX, 0, bytemuck::bytes_of(params));
            d.cmd_bind_vertex_buffers(cb, 0, &[vertices.raw], &[0]);
            d.cmd_draw(cb, count, 1, 0, 0);
            d.cmd_end_rendering(cb);
        }
    }

    pub fn destroy(&self, gpu: &Gpu) {
        unsafe {
            gpu.device.destroy_pipeline(self.pipeline, None);
            gpu.device.destroy_pipeline_layout(self.layout, None);
            gpu.device.destroy_descriptor_set_layout(self.set_layout, None);
        }
    }
}
