//! Raster G-buffer pass with dynamic rendering: linear depth (R32_SFLOAT) and encoded face
//! normal (R32_UINT) over the full target, copied into storage buffers for the compute passes.

use crate::compute::memory_barrier;
use crate::descriptors::{Descriptor, storage_bindings};
use crate::image::Image2d;
use crate::{Buffer, Gpu, GpuError, modules};
use aokit_shaders::common::alpha::AlphaMaskHeader;
use aokit_shaders::gbuffer::RasterParams;
use aokit_shaders::glam::UVec2;
use ash::vk;
use gpu_allocator::MemoryLocation;
use std::ffi::CStr;

/// One de-indexed vertex: world position, its triangle's world face normal (w unused), texture
/// coordinate and material index (for the alpha test).
#[repr(C)]
#[derive(Copy, Clone, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GBufferVertex {
    /// World-space position (`w` = 1).
    pub position: [f32; 4],
    /// The triangle's world-space face normal (`w` = 0).
    pub face_normal: [f32; 4],
    /// Texture coordinates (where the alpha mask is sampled).
    pub uv: [f32; 2],
    /// Material index (into the alpha-mask headers).
    pub material: u32,
    /// Padding to 16 bytes.
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
    /// Same pipeline with the depth-peeling fragment shader (spec svao-raysd §11).
    peel_pipeline: vk::Pipeline,
}

fn layout_barrier(
    gpu: &Gpu,
    cb: vk::CommandBuffer,
    image: &Image2d,
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
        .image(image.raw)
        .subresource_range(image.range());
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
    /// The G-buffer and peeling pipelines on `gpu`.
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

    /// The per-scene, per-size state of the raster passes: the scene's vertices and alpha masks
    /// on the device, render targets, the G-buffer and peeled-layer buffers, descriptor sets.
    pub fn frame_resources(
        &self,
        gpu: &Gpu,
        vertices: &[GBufferVertex],
        masks: &(Vec<AlphaMaskHeader>, Vec<f32>),
        size: UVec2,
    ) -> Result<RasterFrame, GpuError> {
        if size.x == 0 || size.y == 0 || vertices.is_empty() || masks.0.is_empty() || masks.1.is_empty() {
            return Err(GpuError::Input(format!(
                "empty raster input ({}×{}, {} vertices)",
                size.x,
                size.y,
                vertices.len()
            )));
        }
        let mut frame = RasterFrame { size, vertex_count: vertices.len() as u32, ..Default::default() };
        let made = (|| -> Result<(), GpuError> {
            let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
            frame.buffers.push(gpu.upload(vertices, vk::BufferUsageFlags::VERTEX_BUFFER)?);
            frame.buffers.push(gpu.upload(&masks.0, storage)?);
            frame.buffers.push(gpu.upload(&masks.1, storage)?);
            let output = storage | vk::BufferUsageFlags::TRANSFER_DST | vk::BufferUsageFlags::TRANSFER_SRC;
            for _ in 0..4 {
                let bytes = 4 * size.x as u64 * size.y as u64;
                frame.buffers.push(gpu.create_buffer(bytes, output, MemoryLocation::GpuOnly)?);
            }
            let color = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC;
            frame.targets.push(gpu.create_image_2d(DEPTH_FORMAT, size.x, size.y, color)?);
            frame.targets.push(gpu.create_image_2d(NORMAL_FORMAT, size.x, size.y, color)?);
            let z = vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT;
            frame.targets.push(gpu.create_image_2d(Z_FORMAT, size.x, size.y, z)?);
            frame.pool = gpu.descriptor_pool(2, &storage_bindings(3))?;
            let info = vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(3);
            frame.queries = unsafe { gpu.device.create_query_pool(&info, None)? };
            let [_, headers, texels, depth, ..] = &frame.buffers[..] else { unreachable!("pushed above") };
            // The first pass does not read binding 2; it gets the headers as a placeholder.
            for third in [headers, depth] {
                let descriptors = [headers, texels, third].map(Descriptor::Storage);
                frame.sets.push(gpu.descriptor_set(frame.pool, self.set_layout, &descriptors)?);
            }
            Ok(())
        })();
        match made {
            Ok(()) => Ok(frame),
            Err(e) => {
                frame.destroy(gpu);
                Err(e)
            }
        }
    }

    /// Record the G-buffer pass into `cb`: `frame`'s depth and normal buffers hold the full
    /// target afterwards (depth = far and normal code 0 where nothing was hit), visible to later
    /// compute, fragment and transfer reads. With `peel`, then also the depth-peeling pass of
    /// spec svao-raysd §11 into the second-layer buffers: only fragments beyond the first
    /// layer's depth + `params.peel_separation` survive. Earlier readers of these buffers on the
    /// queue finish first.
    /// Timestamps go to the frame ([`RasterFrame::pass_times`]).
    pub fn record(&self, gpu: &Gpu, cb: vk::CommandBuffer, frame: &RasterFrame, params: &RasterParams, peel: bool) {
        let d = &gpu.device;
        unsafe {
            d.cmd_reset_query_pool(cb, frame.queries, 0, 3);
            d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TOP_OF_PIPE, frame.queries, 0);
        }
        let out = [(self.pipeline, frame.sets[0], 3, 4), (self.peel_pipeline, frame.sets[1], 5, 6)];
        for (i, (pipeline, set, depth, normals)) in out[..1 + peel as usize].iter().enumerate() {
            let buffers = (&frame.buffers[*depth], &frame.buffers[*normals]);
            self.record_pass(gpu, cb, frame, params, (*pipeline, *set), buffers);
            unsafe { d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TRANSFER, frame.queries, 1 + i as u32) };
        }
        frame.peeled.set(peel);
    }

    fn record_pass(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        frame: &RasterFrame,
        params: &RasterParams,
        (pipeline, set): (vk::Pipeline, vk::DescriptorSet),
        (depth_buf, normal_buf): (&Buffer, &Buffer),
    ) {
        let d = &gpu.device;
        let extent = vk::Extent2D { width: frame.size.x, height: frame.size.y };
        let [depth_t, normal_t, z_t] = &frame.targets[..] else { unreachable!("three targets") };
        type S = vk::PipelineStageFlags;
        type A = vk::AccessFlags;
        unsafe {
            // Earlier transfers out of the targets (a previous pass) and reads of the buffers
            // finish first; the targets are cleared, so their old contents are discarded.
            let mut readers = S::TRANSFER | S::COMPUTE_SHADER | S::FRAGMENT_SHADER;
            if gpu.has_ray_tracing() {
                readers |= S::RAY_TRACING_SHADER_KHR;
            }
            let earlier = (readers, A::empty());
            let to_attachment = (vk::ImageLayout::UNDEFINED, vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL);
            let color_out = (S::COLOR_ATTACHMENT_OUTPUT, A::COLOR_ATTACHMENT_WRITE);
            for t in [depth_t, normal_t] {
                layout_barrier(gpu, cb, t, to_attachment, earlier, color_out);
            }
            let z_stages = S::EARLY_FRAGMENT_TESTS | S::LATE_FRAGMENT_TESTS;
            let z_access = A::DEPTH_STENCIL_ATTACHMENT_READ | A::DEPTH_STENCIL_ATTACHMENT_WRITE;
            let to_z = (vk::ImageLayout::UNDEFINED, vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL);
            layout_barrier(gpu, cb, z_t, to_z, (z_stages, A::empty()), (z_stages, z_access));
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
                .clear_value(vk::ClearValue { depth_stencil: vk::ClearDepthStencilValue { depth: 0.0, stencil: 0 } });
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
            d.cmd_bind_vertex_buffers(cb, 0, &[frame.buffers[0].raw], &[0]);
            d.cmd_draw(cb, frame.vertex_count, 1, 0, 0);
            d.cmd_end_rendering(cb);
            let to_src = (vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL, vk::ImageLayout::TRANSFER_SRC_OPTIMAL);
            let transfer = (S::TRANSFER, A::TRANSFER_READ);
            for (t, buf) in [(depth_t, depth_buf), (normal_t, normal_buf)] {
                layout_barrier(gpu, cb, t, to_src, color_out, transfer);
                d.cmd_copy_image_to_buffer(
                    cb,
                    t.raw,
                    vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                    buf.raw,
                    &[t.copy_region()],
                );
            }
            memory_barrier(gpu, cb, S::TRANSFER, S::COMPUTE_SHADER | S::FRAGMENT_SHADER | S::TRANSFER);
        }
    }

    /// Rasterize `vertices` (de-indexed triangles) into `(depth, normals)` storage buffers of the
    /// full target in a command buffer of its own (submits and waits); empty pixels hold depth =
    /// far and normal code 0. `masks` are the alpha masks per material (non-empty slices). With
    /// `first_layer`, the depth-peeling pass of spec svao-raysd §11 against that linear depth. Returns the
    /// buffers and the GPU time of the pass in milliseconds.
    pub fn render(
        &self,
        gpu: &Gpu,
        vertices: &[GBufferVertex],
        masks: &(Vec<AlphaMaskHeader>, Vec<f32>),
        params: &RasterParams,
        first_layer: Option<&Buffer>,
    ) -> Result<(Buffer, Buffer, f64), GpuError> {
        let mut frame = self.frame_resources(gpu, vertices, masks, params.view.size())?;
        let d = &gpu.device;
        let info = vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(2);
        let timed = unsafe { d.create_query_pool(&info, None) }.map_err(GpuError::from).and_then(|queries| {
            let submitted = gpu.submit(|cb| unsafe {
                d.cmd_reset_query_pool(cb, queries, 0, 2);
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TOP_OF_PIPE, queries, 0);
                if let Some(first) = first_layer {
                    // Peel against the given layer: copy it into the frame's first-layer buffer.
                    let region = [vk::BufferCopy::default().size(frame.buffers[3].size.min(first.size))];
                    d.cmd_copy_buffer(cb, first.raw, frame.buffers[3].raw, &region);
                    memory_barrier(gpu, cb, vk::PipelineStageFlags::TRANSFER, vk::PipelineStageFlags::FRAGMENT_SHADER);
                    let set = frame.sets[1];
                    let out = (&frame.buffers[5], &frame.buffers[6]);
                    self.record_pass(gpu, cb, &frame, params, (self.peel_pipeline, set), out);
                } else {
                    self.record(gpu, cb, &frame, params, false);
                }
                d.cmd_write_timestamp(cb, vk::PipelineStageFlags::TRANSFER, queries, 1);
            });
            let got = submitted.and_then(|_| gpu.timestamps_ms(queries, 2));
            unsafe { d.destroy_query_pool(queries, None) };
            got.map(|t| t[1])
        });
        let result = timed.map(|ms| {
            // Hand the output buffers to the caller (the higher index first); the frame frees the
            // rest.
            let (depth, normals) = if first_layer.is_some() { (5, 6) } else { (3, 4) };
            let normals_buf = frame.buffers.remove(normals);
            let depth_buf = frame.buffers.remove(depth);
            (depth_buf, normals_buf, ms)
        });
        frame.destroy(gpu);
        result
    }

    /// Destroy the pipelines and the timestamp pool.
    pub fn destroy(&self, gpu: &Gpu) {
        unsafe {
            gpu.device.destroy_pipeline(self.pipeline, None);
            gpu.device.destroy_pipeline(self.peel_pipeline, None);
            gpu.device.destroy_pipeline_layout(self.layout, None);
            gpu.device.destroy_descriptor_set_layout(self.set_layout, None);
        }
    }
}

/// What the raster passes keep per scene and target size (see
/// [`RasterGBuffer::frame_resources`]). Free it with [`RasterFrame::destroy`] once the device
/// finished with it.
#[derive(Default)]
pub struct RasterFrame {
    size: UVec2,
    vertex_count: u32,
    /// Vertices, mask headers, mask texels, then the outputs: depth, normals, second-layer
    /// depth, second-layer normals.
    buffers: Vec<Buffer>,
    /// Linear-depth, normal-code and Z render targets.
    targets: Vec<Image2d>,
    pool: vk::DescriptorPool,
    /// The first pass's and the peeling pass's descriptor sets.
    sets: Vec<vk::DescriptorSet>,
    /// Timestamps: before, after the G-buffer, after the peeled layer.
    queries: vk::QueryPool,
    peeled: std::cell::Cell<bool>,
}

impl RasterFrame {
    /// The G-buffer after [`RasterGBuffer::record`]: linear depth and normal codes.
    pub fn gbuffer(&self) -> (&Buffer, &Buffer) {
        (&self.buffers[3], &self.buffers[4])
    }

    /// The peeled second layer's linear depth after a `record` with `peel`.
    pub fn second_depth(&self) -> &Buffer {
        &self.buffers[5]
    }

    /// The scene as the graphs' raster passes draw it (the raster SD map).
    pub fn scene(&self) -> crate::RasterScene<'_> {
        crate::RasterScene {
            vertices: &self.buffers[0],
            vertex_count: self.vertex_count,
            mask_headers: &self.buffers[1],
            mask_texels: &self.buffers[2],
        }
    }

    /// The target size it was made for.
    pub fn size(&self) -> UVec2 {
        self.size
    }

    /// `("gbuffer", ms)` and, when the last record peeled, `("depth_peel", ms)` of the last
    /// recorded frame, once the device finished it.
    pub fn pass_times(&self, gpu: &Gpu) -> Result<Vec<(&'static str, f64)>, GpuError> {
        let peeled = self.peeled.get();
        let t = gpu.timestamps_ms(self.queries, 2 + peeled as usize)?;
        let mut out = vec![("gbuffer", t[1])];
        if peeled {
            out.push(("depth_peel", t[2] - t[1]));
        }
        Ok(out)
    }

    /// Free the frame's buffers.
    pub fn destroy(self, gpu: &Gpu) {
        if self.queries != vk::QueryPool::null() {
            unsafe { gpu.device.destroy_query_pool(self.queries, None) };
        }
        for b in self.buffers {
            gpu.free_buffer(b);
        }
        for t in self.targets {
            gpu.free_image(t);
        }
        if self.pool != vk::DescriptorPool::null() {
            unsafe { gpu.device.destroy_descriptor_pool(self.pool, None) };
        }
    }
}

/// A raster pass without attachments, as a graph declares it (`PassKind::Raster`): a vertex
/// shader over the scene's vertex stream, a fragment shader that writes storage buffers only
/// (e.g. the raster stochastic depth map's atomics, svao-raysd §8), a dynamic viewport, the
/// push constants to the vertex stage, every binding a storage buffer read by the fragment stage.
pub struct AttachmentlessPass {
    pub(crate) set_layout: vk::DescriptorSetLayout,
    /// Storage-buffer bindings of the fragment shader.
    pub(crate) bindings: u32,
    layout: vk::PipelineLayout,
    pipeline: vk::Pipeline,
}

impl AttachmentlessPass {
    /// The pass of `vertex` and `fragment` (SPIR-V, entry point) with `bindings` storage buffers
    /// and `push_bytes` of vertex push constants.
    pub(crate) fn new(
        gpu: &Gpu,
        vertex: (&[u8], &CStr),
        fragment: (&[u8], &CStr),
        bindings: u32,
        push_bytes: u32,
    ) -> Result<Self, GpuError> {
        let d = &gpu.device;
        unsafe {
            let push = [vk::PushConstantRange::default().stage_flags(vk::ShaderStageFlags::VERTEX).size(push_bytes)];
            let set_layout = gpu.set_layout(&storage_bindings(bindings), vk::ShaderStageFlags::FRAGMENT)?;
            let set_layouts = [set_layout];
            let ranges = if push_bytes == 0 { &[][..] } else { &push[..] };
            let layout = d.create_pipeline_layout(
                &vk::PipelineLayoutCreateInfo::default().set_layouts(&set_layouts).push_constant_ranges(ranges),
                None,
            )?;
            let vs = gpu.shader_module(vertex.0)?;
            let fs = gpu.shader_module(fragment.0)?;
            let stages = [
                vk::PipelineShaderStageCreateInfo::default()
                    .stage(vk::ShaderStageFlags::VERTEX)
                    .module(vs)
                    .name(vertex.1),
                vk::PipelineShaderStageCreateInfo::default()
                    .stage(vk::ShaderStageFlags::FRAGMENT)
                    .module(fs)
                    .name(fragment.1),
            ];
            let created = graphics_pipeline(d, layout, &stages, None);
            d.destroy_shader_module(vs, None);
            d.destroy_shader_module(fs, None);
            let pipeline = created?;
            Ok(AttachmentlessPass { set_layout, bindings, layout, pipeline })
        }
    }

    /// Record the pass over a viewport of `size` pixels: draw `count` vertices from `vertices`
    /// with descriptor set `set` and vertex push constants `push`.
    pub(crate) fn record(
        &self,
        gpu: &Gpu,
        cb: vk::CommandBuffer,
        set: vk::DescriptorSet,
        (vertices, count): (&Buffer, u32),
        push: &[u8],
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
            if !push.is_empty() {
                d.cmd_push_constants(cb, self.layout, vk::ShaderStageFlags::VERTEX, 0, push);
            }
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
