//! An engine adopting aokit: the application owns the Vulkan instance, the device, the queue,
//! the command buffer, the depth and normal images (drawn by its own raster pass, WGSL shaders
//! compiled with naga at run time) and the AO image; aokit is one [`AoEffect`] that records its
//! passes into the engine's command buffer (see `main`: create, resize, record, drop).
//!
//! ```sh
//! cargo run --release --example engine_frame -- --scene sponza --technique raysd --width 640 --height 360 --out ao.png
//! ```
//!
//! Scene, camera preset and AO parameters mean what they mean for `aokit render`, with the same
//! defaults; there is no guard band (an engine renders none): compare with `aokit render …
//! --guard 0`, e.g. with `--compare cpu.png`.

use aokit::frame::{CameraChoice, Frame, FrameRequest};
use aokit::output::write_png;
use aokit::scene::{Scene, builtin};
use aokit_vulkan::glam::{Mat4, Vec4};
use aokit_vulkan::{AoEffect, AoFrame, AoImage, AoSettings, DepthConvention, EngineImage, ExternalDevice, Technique};
use ash::{ext, khr, vk};
use clap::{Parser, ValueEnum};
use std::error::Error;
use std::ffi::{CStr, c_void};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::Instant;

type Result<T, E = Box<dyn Error>> = std::result::Result<T, E>;

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";
const DEPTH_FORMAT: vk::Format = vk::Format::D32_SFLOAT;
const NORMAL_FORMAT: vk::Format = vk::Format::R8G8B8A8_UNORM;

/// The scene, camera and AO parameters of `aokit render` (same meanings and defaults).
#[derive(Parser)]
#[command(about = "Render a scene's depth and normals with a minimal engine raster pass, then AO with aokit")]
struct Args {
    /// A built-in scene (`aokit scenes`) or a scene file (OBJ, glTF, PLY).
    #[arg(long, default_value = "sponza")]
    scene: String,
    /// A camera preset of the built-in scene (default: its first), or `auto`.
    #[arg(long)]
    camera: Option<String>,
    #[arg(long, default_value_t = 640)]
    width: u32,
    #[arg(long, default_value_t = 360)]
    height: u32,
    /// World-space AO radius (default: the built-in scene's, else 2 % of the bounding box).
    #[arg(long)]
    radius: Option<f32>,
    #[arg(long, default_value_t = 2.0)]
    exponent: f32,
    #[arg(long, default_value_t = 0.0)]
    thickness: f32,
    /// A technique of `aokit techniques`, optionally with `:key=value` settings.
    #[arg(long, default_value = "vao")]
    technique: String,
    /// Output PNG (8-bit grey, 1 = unoccluded = white).
    #[arg(long, default_value = "ao.png")]
    out: PathBuf,
    /// The engine's AO image format.
    #[arg(long, value_enum, default_value = "r32f")]
    ao_format: AoFormat,
    /// Hand aokit no normal image: it derives normals from depth.
    #[arg(long)]
    no_normals: bool,
    /// Enable VK_LAYER_KHRONOS_validation on the engine's instance; any message fails the run.
    #[arg(long)]
    validation: bool,
    /// Frames to render (the first makes aokit's pipelines and buffers; later ones reuse them).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    frames: u32,
    /// A PNG of the same size (e.g. `aokit render … --guard 0`) to print the mean |Δ| against.
    #[arg(long)]
    compare: Option<PathBuf>,
}

#[derive(Copy, Clone, PartialEq, Eq, ValueEnum)]
enum AoFormat {
    R32f,
    R8,
}

impl AoFormat {
    fn vk(self) -> vk::Format {
        match self {
            AoFormat::R32f => vk::Format::R32_SFLOAT,
            AoFormat::R8 => vk::Format::R8_UNORM,
        }
    }

    fn texel_bytes(self) -> u64 {
        match self {
            AoFormat::R32f => 4,
            AoFormat::R8 => 1,
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The engine: instance, device, memory, its own raster pass.
// ---------------------------------------------------------------------------------------------

/// The engine's debug messenger callback: warnings and errors into its `Mutex<Vec>`.
unsafe extern "system" fn collect_messages(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    if !data.is_null() && !user.is_null() {
        // SAFETY: `user` is the engine's boxed Mutex, alive until the instance is destroyed.
        let (data, messages) = unsafe { (&*data, &*(user as *const Mutex<Vec<String>>)) };
        let text = unsafe { data.message_as_c_str() }.map(|m| m.to_string_lossy().into_owned()).unwrap_or_default();
        messages.lock().unwrap_or_else(|e| e.into_inner()).push(format!("{severity:?}: {text}"));
    }
    vk::FALSE
}

struct Engine {
    entry: ash::Entry,
    instance: ash::Instance,
    debug: Option<(ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
    /// Boxed: the messenger holds a pointer to it.
    messages: Box<Mutex<Vec<String>>>,
    physical_device: vk::PhysicalDevice,
    device: ash::Device,
    family: u32,
    queue: vk::Queue,
    ray_tracing: bool,
    memory: vk::PhysicalDeviceMemoryProperties,
    device_name: String,
}

impl Engine {
    /// Instance (+ validation) and a device with what the engine's raster pass and aokit need
    /// (see `ExternalDevice`): Vulkan 1.3, `vulkanMemoryModel(DeviceScope)`,
    /// `dynamicRendering`, `synchronization2`, a graphics+compute queue with timestamps, and the
    /// ray-tracing extensions and features where the device has them.
    fn new(validation: bool) -> Result<Engine> {
        let entry = unsafe { ash::Entry::load()? };
        let messages: Box<Mutex<Vec<String>>> = Box::default();
        let mut messenger_info = vk::DebugUtilsMessengerCreateInfoEXT::default()
            .message_severity(
                vk::DebugUtilsMessageSeverityFlagsEXT::WARNING | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR,
            )
            .message_type(
                vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                    | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                    | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE,
            )
            .pfn_user_callback(Some(collect_messages))
            .user_data(&*messages as *const Mutex<Vec<String>> as *mut c_void);
        let app = vk::ApplicationInfo::default().application_name(c"engine_frame").api_version(vk::API_VERSION_1_3);
        let (mut layers, mut extensions) = (Vec::new(), Vec::new());
        if validation {
            let available = unsafe { entry.enumerate_instance_layer_properties()? };
            if !available.iter().any(|l| l.layer_name_as_c_str() == Ok(VALIDATION_LAYER)) {
                return Err("--validation: VK_LAYER_KHRONOS_validation is not installed".into());
            }
            layers.push(VALIDATION_LAYER.as_ptr());
            extensions.push(ext::debug_utils::NAME.as_ptr());
        }
        let mut create = vk::InstanceCreateInfo::default()
            .application_info(&app)
            .enabled_layer_names(&layers)
            .enabled_extension_names(&extensions);
        if validation {
            create = create.push_next(&mut messenger_info); // also covers vkCreate/DestroyInstance
        }
        let instance = unsafe { entry.create_instance(&create, None)? };
        let debug = if validation {
            let loader = ext::debug_utils::Instance::new(&entry, &instance);
            let messenger = unsafe { loader.create_debug_utils_messenger(&messenger_info, None)? };
            Some((loader, messenger))
        } else {
            None
        };

        // A discrete GPU if there is one, else any Vulkan 1.3 device (lavapipe here).
        let props = |pd| unsafe { instance.get_physical_device_properties(pd) };
        let rank = |pd| match props(pd).device_type {
            vk::PhysicalDeviceType::DISCRETE_GPU => 0,
            vk::PhysicalDeviceType::INTEGRATED_GPU => 1,
            _ => 2,
        };
        let physical_device = unsafe { instance.enumerate_physical_devices()? }
            .into_iter()
            .filter(|&pd| props(pd).api_version >= vk::API_VERSION_1_3)
            .min_by_key(|&pd| rank(pd))
            .ok_or("no Vulkan 1.3 device")?;
        let device_name = props(physical_device).device_name_as_c_str()?.to_string_lossy().into_owned();
        let families = unsafe { instance.get_physical_device_queue_family_properties(physical_device) };
        let family = families
            .iter()
            .position(|q| {
                q.queue_flags.contains(vk::QueueFlags::GRAPHICS | vk::QueueFlags::COMPUTE) && q.timestamp_valid_bits > 0
            })
            .ok_or("no graphics+compute queue family with timestamps")? as u32;

        // Ray tracing where the device has all of it (aokit's ray-traced techniques need it).
        let available = unsafe { instance.enumerate_device_extension_properties(physical_device)? };
        let rt_extensions =
            [khr::acceleration_structure::NAME, khr::ray_tracing_pipeline::NAME, khr::deferred_host_operations::NAME];
        let has = |name: &CStr| available.iter().any(|e| e.extension_name_as_c_str() == Ok(name));
        let mut as_query = vk::PhysicalDeviceAccelerationStructureFeaturesKHR::default();
        let mut rt_query = vk::PhysicalDeviceRayTracingPipelineFeaturesKHR::default();
        let mut f12_query = vk::PhysicalDeviceVulkan12Features::default();
        let mut f13_query = vk::PhysicalDeviceVulkan13Features::default();
        let mut query = vk::PhysicalDeviceFeatures2::default()
            .push_next(&mut as_query)
            .push_next(&mut rt_query)
            .push_next(&mut f12_query)
            .push_next(&mut f13_query);
        unsafe { instance.get_physical_device_features2(physical_device, &mut query) };
        if f12_query.vulkan_memory_model == 0 || f12_query.vulkan_memory_model_device_scope == 0 {
            return Err(format!("{device_name} lacks vulkanMemoryModel(DeviceScope), which aokit's SPIR-V uses").into());
        }
        if f13_query.dynamic_rendering == 0 || f13_query.synchronization2 == 0 {
            return Err(format!("{device_name} lacks dynamicRendering / synchronization2").into());
        }
        let ray_tracing = rt_extensions.iter().all(|e| has(e))
            && as_query.acceleration_structure != 0
            && rt_query.ray_tracing_pipeline != 0
            && f12_query.buffer_device_address != 0;

        let priorities = [1.0];
        let queues = [vk::DeviceQueueCreateInfo::default().queue_family_index(family).queue_priorities(&priorities)];
        let mut f12 = vk::PhysicalDeviceVulkan12Features::default()
            .vulkan_memory_model(true)
            .vulkan_memory_model_device_scope(true)
            .buffer_device_address(ray_tracing);
        let mut f13 = vk::PhysicalDeviceVulkan13Features::default().dynamic_rendering(true).synchronization2(true);
        let mut as_enable = vk::PhysicalDeviceAccelerationStructureFeaturesKHR::default().acceleration_structure(true);
        let mut rt_enable = vk::PhysicalDeviceRayTracingPipelineFeaturesKHR::default().ray_tracing_pipeline(true);
        let rt_names = rt_extensions.map(CStr::as_ptr);
        let mut create =
            vk::DeviceCreateInfo::default().queue_create_infos(&queues).push_next(&mut f12).push_next(&mut f13);
        if ray_tracing {
            create = create.enabled_extension_names(&rt_names).push_next(&mut as_enable).push_next(&mut rt_enable);
        }
        let device = unsafe { instance.create_device(physical_device, &create, None)? };
        let queue = unsafe { device.get_device_queue(family, 0) };
        let memory = unsafe { instance.get_physical_device_memory_properties(physical_device) };
        Ok(Engine {
            entry,
            instance,
            debug,
            messages,
            physical_device,
            device,
            family,
            queue,
            ray_tracing,
            memory,
            device_name,
        })
    }

    /// The handles aokit gets (plain handles: aokit destroys none of them).
    fn external(&self) -> ExternalDevice {
        ExternalDevice {
            entry: self.entry.clone(),
            instance: self.instance.clone(),
            physical_device: self.physical_device,
            device: self.device.clone(),
            queue_family_index: self.family,
            queue: self.queue,
            ray_tracing: self.ray_tracing,
            // Not enabled here: the ray-query variants are exercised through aokit's own device.
            ray_query: false,
        }
    }

    /// Dedicated memory of a type with `flags` for `requirements` (an engine would use its
    /// allocator).
    fn allocate(
        &self,
        requirements: vk::MemoryRequirements,
        flags: vk::MemoryPropertyFlags,
    ) -> Result<vk::DeviceMemory> {
        let types = &self.memory.memory_types[..self.memory.memory_type_count as usize];
        let index = types
            .iter()
            .enumerate()
            .position(|(i, t)| requirements.memory_type_bits & (1 << i) != 0 && t.property_flags.contains(flags))
            .ok_or_else(|| format!("no memory type with {flags:?}"))?;
        let info = vk::MemoryAllocateInfo::default().allocation_size(requirements.size).memory_type_index(index as u32);
        Ok(unsafe { self.device.allocate_memory(&info, None)? })
    }

    /// A host-visible, coherent buffer holding `bytes` (`len` bytes when `bytes` is empty).
    fn host_buffer(&self, usage: vk::BufferUsageFlags, bytes: &[u8], len: u64) -> Result<HostBuffer> {
        let size = (bytes.len() as u64).max(len).max(4);
        let info = vk::BufferCreateInfo::default().size(size).usage(usage);
        let buffer = unsafe { self.device.create_buffer(&info, None)? };
        let requirements = unsafe { self.device.get_buffer_memory_requirements(buffer) };
        let flags = vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT;
        let memory = self.allocate(requirements, flags)?;
        unsafe {
            self.device.bind_buffer_memory(buffer, memory, 0)?;
            let mapped = self.device.map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())? as *mut u8;
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), mapped, bytes.len());
            Ok(HostBuffer { buffer, memory, mapped, size })
        }
    }

    /// A device-local 2D image of the frame's size and its view (depth aspect for a depth format).
    fn image(&self, format: vk::Format, width: u32, height: u32, usage: vk::ImageUsageFlags) -> Result<Image> {
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
        let image = unsafe { self.device.create_image(&info, None)? };
        let requirements = unsafe { self.device.get_image_memory_requirements(image) };
        let memory = self.allocate(requirements, vk::MemoryPropertyFlags::DEVICE_LOCAL)?;
        let aspect = if format == DEPTH_FORMAT { vk::ImageAspectFlags::DEPTH } else { vk::ImageAspectFlags::COLOR };
        let range = vk::ImageSubresourceRange::default().aspect_mask(aspect).level_count(1).layer_count(1);
        let view = unsafe {
            self.device.bind_image_memory(image, memory, 0)?;
            let info = vk::ImageViewCreateInfo::default()
                .image(image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(format)
                .subresource_range(range);
            self.device.create_image_view(&info, None)?
        };
        Ok(Image { image, memory, view, range })
    }

    /// Whether `format` can be used with `features` on optimal-tiling images.
    fn supports(&self, format: vk::Format, features: vk::FormatFeatureFlags) -> bool {
        let props = unsafe { self.instance.get_physical_device_format_properties(self.physical_device, format) };
        props.optimal_tiling_features.contains(features)
    }

    /// Destroy the device, the messenger and the instance; returns what the validation layer said.
    fn destroy(self) -> Vec<String> {
        unsafe {
            self.device.destroy_device(None);
            if let Some((loader, messenger)) = &self.debug {
                loader.destroy_debug_utils_messenger(*messenger, None);
            }
            self.instance.destroy_instance(None);
        }
        self.messages.into_inner().unwrap_or_else(|e| e.into_inner())
    }
}

struct HostBuffer {
    buffer: vk::Buffer,
    memory: vk::DeviceMemory,
    mapped: *mut u8,
    size: u64,
}

impl HostBuffer {
    fn destroy(self, device: &ash::Device) {
        unsafe {
            device.destroy_buffer(self.buffer, None);
            device.free_memory(self.memory, None);
        }
    }
}

struct Image {
    image: vk::Image,
    memory: vk::DeviceMemory,
    view: vk::ImageView,
    range: vk::ImageSubresourceRange,
}

impl Image {
    fn destroy(self, device: &ash::Device) {
        unsafe {
            device.destroy_image_view(self.view, None);
            device.destroy_image(self.image, None);
            device.free_memory(self.memory, None);
        }
    }
}

/// The engine's depth + normal pass. WebGPU conventions in WGSL (clip y up, z ∈ [0, 1]); naga's
/// SPIR-V back-end flips y for Vulkan (`WriterFlags::ADJUST_COORDINATE_SPACE`, on by default).
const RASTER_WGSL: &str = r#"
struct Params {
    world_to_view: mat4x4<f32>,
    // Reversed-Z perspective (depth 1 at near, 0 at far), right-handed view space.
    projection: mat4x4<f32>,
}
var<immediate> params: Params;

// aokit's packed alpha masks (`Scene::alpha_masks`): one header per material, width 0 = opaque.
struct MaskHeader { offset: u32, width: u32, height: u32, cutoff: f32 }
@group(0) @binding(0) var<storage, read> mask_headers: array<MaskHeader>;
@group(0) @binding(1) var<storage, read> mask_texels: array<f32>;

struct Varyings {
    @builtin(position) clip: vec4<f32>,
    @location(0) view_position: vec3<f32>,
    @location(1) uv: vec2<f32>,
    @location(2) @interpolate(flat) material: u32,
}

@vertex
fn raster_vs(@location(0) world: vec3<f32>, @location(1) uv: vec2<f32>, @location(2) material: u32) -> Varyings {
    let v = (params.world_to_view * vec4(world, 1.0)).xyz; // right-handed, looking down −Z
    var out: Varyings;
    out.clip = params.projection * vec4(v, 1.0);
    out.view_position = v;
    out.uv = uv;
    out.material = material;
    return out;
}

// glTF alpha mask: nearest texel, repeat wrapping (aokit's `alpha_test_passes`).
fn alpha_passes(material: u32, uv: vec2<f32>) -> bool {
    if material >= arrayLength(&mask_headers) { return true; }
    let h = mask_headers[material];
    if h.width == 0u || h.height == 0u { return true; }
    let f = uv - floor(uv);
    let x = min(u32(f.x * f32(h.width)), h.width - 1u);
    let y = min(u32(f.y * f32(h.height)), h.height - 1u);
    let i = h.offset + y * h.width + x;
    return i >= arrayLength(&mask_texels) || mask_texels[i] >= h.cutoff;
}

@fragment
fn raster_fs(in: Varyings) -> @location(0) vec4<f32> {
    // Face normal from the view position's screen derivatives (framebuffer x right, y down:
    // dy × dx faces the camera), before the discard so the derivatives stay in uniform control flow.
    let n = normalize(cross(dpdy(in.view_position), dpdx(in.view_position)));
    if !alpha_passes(in.material, in.uv) { discard; }
    return vec4(n * 0.5 + 0.5, 1.0);
}
"#;

/// Push constants of the raster pass (`Params` above).
#[repr(C)]
#[derive(Copy, Clone, bytemuck::Pod, bytemuck::Zeroable)]
struct RasterPush {
    world_to_view: Mat4,
    projection: Mat4,
}

/// A vertex of the de-indexed scene: world position, texture coordinate, material.
#[repr(C)]
#[derive(Copy, Clone, bytemuck::Pod, bytemuck::Zeroable)]
struct Vertex {
    position: [f32; 3],
    uv: [f32; 2],
    material: u32,
}

/// WGSL → SPIR-V words with naga.
fn compile_wgsl(source: &str) -> Result<Vec<u32>> {
    let module = naga::front::wgsl::parse_str(source).map_err(|e| e.emit_to_string(source))?;
    let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::IMMEDIATES)
        .validate(&module)
        .map_err(|e| e.emit_to_string(source))?;
    let options = naga::back::spv::Options { lang_version: (1, 3), ..Default::default() };
    Ok(naga::back::spv::write_vec(&module, &info, &options, None)?)
}

struct RasterPass {
    set_layout: vk::DescriptorSetLayout,
    layout: vk::PipelineLayout,
    pipeline: vk::Pipeline,
    pool: vk::DescriptorPool,
    set: vk::DescriptorSet,
}

impl RasterPass {
    fn new(device: &ash::Device, masks: (&HostBuffer, &HostBuffer)) -> Result<RasterPass> {
        let words = compile_wgsl(RASTER_WGSL)?;
        let module = unsafe { device.create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&words), None)? };
        let bindings = [0, 1].map(|b| {
            vk::DescriptorSetLayoutBinding::default()
                .binding(b)
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .descriptor_count(1)
                .stage_flags(vk::ShaderStageFlags::FRAGMENT)
        });
        let set_layout = unsafe {
            device
                .create_descriptor_set_layout(&vk::DescriptorSetLayoutCreateInfo::default().bindings(&bindings), None)?
        };
        let push = [vk::PushConstantRange::default()
            .stage_flags(vk::ShaderStageFlags::VERTEX)
            .size(size_of::<RasterPush>() as u32)];
        let set_layouts = [set_layout];
        let layout = unsafe {
            device.create_pipeline_layout(
                &vk::PipelineLayoutCreateInfo::default().set_layouts(&set_layouts).push_constant_ranges(&push),
                None,
            )?
        };
        let stages = [
            vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::VERTEX)
                .module(module)
                .name(c"raster_vs"),
            vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::FRAGMENT)
                .module(module)
                .name(c"raster_fs"),
        ];
        let vertex_bindings = [vk::VertexInputBindingDescription::default().stride(size_of::<Vertex>() as u32)];
        let attribute = |location, format, offset| {
            vk::VertexInputAttributeDescription::default().location(location).format(format).offset(offset)
        };
        let attributes = [
            attribute(0, vk::Format::R32G32B32_SFLOAT, 0),
            attribute(1, vk::Format::R32G32_SFLOAT, 12),
            attribute(2, vk::Format::R32_UINT, 20),
        ];
        let vertex_input = vk::PipelineVertexInputStateCreateInfo::default()
            .vertex_binding_descriptions(&vertex_bindings)
            .vertex_attribute_descriptions(&attributes);
        let assembly =
            vk::PipelineInputAssemblyStateCreateInfo::default().topology(vk::PrimitiveTopology::TRIANGLE_LIST);
        let viewport = vk::PipelineViewportStateCreateInfo::default().viewport_count(1).scissor_count(1);
        // No culling: aokit treats every surface as double-sided.
        let rasterization = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(vk::CullModeFlags::NONE)
            .line_width(1.0);
        let multisample =
            vk::PipelineMultisampleStateCreateInfo::default().rasterization_samples(vk::SampleCountFlags::TYPE_1);
        // Reversed Z: cleared to 0 (far), nearer = greater.
        let depth = vk::PipelineDepthStencilStateCreateInfo::default()
            .depth_test_enable(true)
            .depth_write_enable(true)
            .depth_compare_op(vk::CompareOp::GREATER);
        let blend_attachments =
            [vk::PipelineColorBlendAttachmentState::default().color_write_mask(vk::ColorComponentFlags::RGBA)];
        let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blend_attachments);
        let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
        let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic_states);
        let color_formats = [NORMAL_FORMAT];
        let mut rendering = vk::PipelineRenderingCreateInfo::default()
            .color_attachment_formats(&color_formats)
            .depth_attachment_format(DEPTH_FORMAT);
        let info = vk::GraphicsPipelineCreateInfo::default()
            .stages(&stages)
            .vertex_input_state(&vertex_input)
            .input_assembly_state(&assembly)
            .viewport_state(&viewport)
            .rasterization_state(&rasterization)
            .multisample_state(&multisample)
            .depth_stencil_state(&depth)
            .color_blend_state(&blend)
            .dynamic_state(&dynamic)
            .layout(layout)
            .push_next(&mut rendering);
        let pipeline = unsafe { device.create_graphics_pipelines(vk::PipelineCache::null(), &[info], None) };
        unsafe { device.destroy_shader_module(module, None) };
        let pipeline = pipeline.map_err(|(_, e)| e)?[0];

        let sizes = [vk::DescriptorPoolSize::default().ty(vk::DescriptorType::STORAGE_BUFFER).descriptor_count(2)];
        let pool = unsafe {
            device
                .create_descriptor_pool(&vk::DescriptorPoolCreateInfo::default().max_sets(1).pool_sizes(&sizes), None)?
        };
        let set = unsafe {
            device.allocate_descriptor_sets(
                &vk::DescriptorSetAllocateInfo::default().descriptor_pool(pool).set_layouts(&set_layouts),
            )?[0]
        };
        let infos =
            [masks.0, masks.1].map(|b| [vk::DescriptorBufferInfo::default().buffer(b.buffer).range(vk::WHOLE_SIZE)]);
        let writes = [0, 1].map(|i| {
            vk::WriteDescriptorSet::default()
                .dst_set(set)
                .dst_binding(i as u32)
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .buffer_info(&infos[i])
        });
        unsafe { device.update_descriptor_sets(&writes, &[]) };
        Ok(RasterPass { set_layout, layout, pipeline, pool, set })
    }

    fn destroy(self, device: &ash::Device) {
        unsafe {
            device.destroy_pipeline(self.pipeline, None);
            device.destroy_pipeline_layout(self.layout, None);
            device.destroy_descriptor_pool(self.pool, None);
            device.destroy_descriptor_set_layout(self.set_layout, None);
        }
    }
}

/// A layout transition of a whole image with the stages and accesses on either side.
fn image_barrier(
    image: &Image,
    (src_stage, src_access): (vk::PipelineStageFlags2, vk::AccessFlags2),
    (dst_stage, dst_access): (vk::PipelineStageFlags2, vk::AccessFlags2),
    (old, new): (vk::ImageLayout, vk::ImageLayout),
) -> vk::ImageMemoryBarrier2<'static> {
    vk::ImageMemoryBarrier2::default()
        .src_stage_mask(src_stage)
        .src_access_mask(src_access)
        .dst_stage_mask(dst_stage)
        .dst_access_mask(dst_access)
        .old_layout(old)
        .new_layout(new)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .image(image.image)
        .subresource_range(image.range)
}

/// The engine's images for one frame.
struct FrameImages {
    depth: Image,
    normals: Image,
    ao: Image,
    width: u32,
    height: u32,
}

/// Record the engine's frame: raster depth + normals, hand them to aokit, copy the AO out.
#[allow(clippy::too_many_arguments)]
fn record_frame(
    device: &ash::Device,
    cmd: vk::CommandBuffer,
    raster: &RasterPass,
    vertices: (&HostBuffer, u32),
    push: &RasterPush,
    images: &FrameImages,
    readback: &HostBuffer,
    ao_frame: impl FnOnce(vk::CommandBuffer) -> Result<()>,
) -> Result<()> {
    type S = vk::PipelineStageFlags2;
    type A = vk::AccessFlags2;
    type L = vk::ImageLayout;
    let barriers = |list: &[vk::ImageMemoryBarrier2]| unsafe {
        device.cmd_pipeline_barrier2(cmd, &vk::DependencyInfo::default().image_memory_barriers(list));
    };
    let fragment_tests = S::EARLY_FRAGMENT_TESTS | S::LATE_FRAGMENT_TESTS;
    let depth_rw = A::DEPTH_STENCIL_ATTACHMENT_READ | A::DEPTH_STENCIL_ATTACHMENT_WRITE;
    // 1. Attachments (contents discarded) and the AO image (storage, GENERAL) ready. No source
    //    stage: the host waited for the previous frame's fence. With frames in flight on the
    //    same images, wait here for their last readers (COMPUTE_SHADER for depth and normals,
    //    COPY for the AO image).
    barriers(&[
        image_barrier(
            &images.depth,
            (S::NONE, A::NONE),
            (fragment_tests, depth_rw),
            (L::UNDEFINED, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
        ),
        image_barrier(
            &images.normals,
            (S::NONE, A::NONE),
            (S::COLOR_ATTACHMENT_OUTPUT, A::COLOR_ATTACHMENT_WRITE),
            (L::UNDEFINED, L::COLOR_ATTACHMENT_OPTIMAL),
        ),
        image_barrier(
            &images.ao,
            (S::NONE, A::NONE),
            (S::COMPUTE_SHADER, A::SHADER_STORAGE_WRITE),
            (L::UNDEFINED, L::GENERAL),
        ),
    ]);
    // 2. The engine's depth/normal pass (dynamic rendering).
    let extent = vk::Extent2D { width: images.width, height: images.height };
    let color = [vk::RenderingAttachmentInfo::default()
        .image_view(images.normals.view)
        .image_layout(L::COLOR_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)
        .clear_value(vk::ClearValue { color: vk::ClearColorValue { float32: [0.5, 0.5, 1.0, 0.0] } })];
    let depth = vk::RenderingAttachmentInfo::default()
        .image_view(images.depth.view)
        .image_layout(L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)
        .clear_value(vk::ClearValue { depth_stencil: vk::ClearDepthStencilValue { depth: 0.0, stencil: 0 } });
    let rendering = vk::RenderingInfo::default()
        .render_area(vk::Rect2D::default().extent(extent))
        .layer_count(1)
        .color_attachments(&color)
        .depth_attachment(&depth);
    unsafe {
        device.cmd_begin_rendering(cmd, &rendering);
        device.cmd_bind_pipeline(cmd, vk::PipelineBindPoint::GRAPHICS, raster.pipeline);
        device.cmd_bind_descriptor_sets(cmd, vk::PipelineBindPoint::GRAPHICS, raster.layout, 0, &[raster.set], &[]);
        device.cmd_push_constants(cmd, raster.layout, vk::ShaderStageFlags::VERTEX, 0, bytemuck::bytes_of(push));
        device.cmd_bind_vertex_buffers(cmd, 0, &[vertices.0.buffer], &[0]);
        let viewport = vk::Viewport::default()
            .width(extent.width as f32)
            .height(extent.height as f32)
            .min_depth(0.0)
            .max_depth(1.0);
        device.cmd_set_viewport(cmd, 0, &[viewport]);
        device.cmd_set_scissor(cmd, 0, &[vk::Rect2D::default().extent(extent)]);
        device.cmd_draw(cmd, vertices.1, 1, 0, 0);
        device.cmd_end_rendering(cmd);
    }
    // 3. Depth and normals become compute-shader inputs (aokit samples them with OpImageFetch).
    barriers(&[
        image_barrier(
            &images.depth,
            (fragment_tests, A::DEPTH_STENCIL_ATTACHMENT_WRITE),
            (S::COMPUTE_SHADER, A::SHADER_SAMPLED_READ),
            (L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL, L::DEPTH_STENCIL_READ_ONLY_OPTIMAL),
        ),
        image_barrier(
            &images.normals,
            (S::COLOR_ATTACHMENT_OUTPUT, A::COLOR_ATTACHMENT_WRITE),
            (S::COMPUTE_SHADER, A::SHADER_SAMPLED_READ),
            (L::COLOR_ATTACHMENT_OPTIMAL, L::SHADER_READ_ONLY_OPTIMAL),
        ),
    ]);
    // 4. aokit: import, the technique's passes, export into the AO image.
    ao_frame(cmd)?;
    // 5. The AO image's compute writes → a copy into the host-visible buffer → the host.
    barriers(&[image_barrier(
        &images.ao,
        (S::COMPUTE_SHADER, A::SHADER_STORAGE_WRITE),
        (S::COPY, A::TRANSFER_READ),
        (L::GENERAL, L::TRANSFER_SRC_OPTIMAL),
    )]);
    let region = vk::BufferImageCopy::default()
        .image_subresource(
            vk::ImageSubresourceLayers::default().aspect_mask(vk::ImageAspectFlags::COLOR).layer_count(1),
        )
        .image_extent(vk::Extent3D { width: images.width, height: images.height, depth: 1 });
    let to_host = [vk::BufferMemoryBarrier2::default()
        .src_stage_mask(S::COPY)
        .src_access_mask(A::TRANSFER_WRITE)
        .dst_stage_mask(S::HOST)
        .dst_access_mask(A::HOST_READ)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .buffer(readback.buffer)
        .size(vk::WHOLE_SIZE)];
    unsafe {
        device.cmd_copy_image_to_buffer(cmd, images.ao.image, L::TRANSFER_SRC_OPTIMAL, readback.buffer, &[region]);
        device.cmd_pipeline_barrier2(cmd, &vk::DependencyInfo::default().buffer_memory_barriers(&to_host));
    }
    Ok(())
}

/// The engine's camera: `aokit render`'s for this scene, size and preset (no guard band).
fn engine_camera(args: &Args) -> Result<(Scene, Frame)> {
    let (scene, builtin) = match builtin::find(&args.scene) {
        Some(b) => (b.load()?, Some(b)),
        None => (Scene::load(Path::new(&args.scene))?, None),
    };
    let camera = match (args.camera.as_deref(), builtin) {
        (Some("auto"), _) | (_, None) => CameraChoice::Auto { fov_deg: 60.0 },
        (name, Some(_)) => CameraChoice::Preset { name: name.map(str::to_string), fov_deg: None },
    };
    let request = FrameRequest {
        width: args.width,
        height: args.height,
        guard: 0,
        camera,
        radius: args.radius,
        exponent: args.exponent,
        thickness: args.thickness,
    };
    let frame = Frame::resolve(&scene, builtin, &request)?;
    Ok((scene, frame))
}

/// A reversed-Z perspective projection (depth 1 at `near`, 0 at `far`) with these tangents of
/// the half field of view, right-handed, in WebGPU's clip space (y up, z ∈ [0, 1]).
fn reversed_z_projection(tan_half_fov: (f32, f32), near: f32, far: f32) -> Mat4 {
    Mat4::from_cols(
        Vec4::new(1.0 / tan_half_fov.0, 0.0, 0.0, 0.0),
        Vec4::new(0.0, 1.0 / tan_half_fov.1, 0.0, 0.0),
        Vec4::new(0.0, 0.0, near / (far - near), -1.0),
        Vec4::new(0.0, 0.0, near * far / (far - near), 0.0),
    )
}

fn main() -> Result<()> {
    let args = Args::parse();
    let technique = Technique::parse(&args.technique)?;
    let (scene, frame) = engine_camera(&args)?;
    let (width, height) = (frame.inner.x, frame.inner.y);
    let view = frame.camera.view;

    let engine = Engine::new(args.validation)?;
    let device = engine.device.clone();
    for (format, features, what) in [
        (
            DEPTH_FORMAT,
            vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT | vk::FormatFeatureFlags::SAMPLED_IMAGE,
            "depth",
        ),
        (NORMAL_FORMAT, vk::FormatFeatureFlags::COLOR_ATTACHMENT | vk::FormatFeatureFlags::SAMPLED_IMAGE, "normals"),
        (args.ao_format.vk(), vk::FormatFeatureFlags::STORAGE_IMAGE, "AO storage image"),
    ] {
        if !engine.supports(format, features) {
            return Err(format!("{}: {format:?} lacks {features:?} ({what})", engine.device_name).into());
        }
    }

    // The engine's scene: de-indexed triangles in world space, plus aokit's alpha masks so that
    // cut-out leaves are cut out of the depth as they are out of aokit's rays.
    let vertices: Vec<Vertex> = scene
        .triangles
        .iter()
        .zip(&scene.triangle_uvs)
        .zip(&scene.triangle_materials)
        .flat_map(|((t, uv), &material)| {
            (0..3).map(move |i| Vertex { position: t[i].to_array(), uv: uv[i].to_array(), material })
        })
        .collect();
    let tables = scene.corner_tables();
    let masks = &tables.masks;
    let vertex_buffer = engine.host_buffer(vk::BufferUsageFlags::VERTEX_BUFFER, bytemuck::cast_slice(&vertices), 0)?;
    let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
    let mask_headers = engine.host_buffer(storage, bytemuck::cast_slice(&masks.0), 0)?;
    let mask_texels = engine.host_buffer(storage, bytemuck::cast_slice(&masks.1), 0)?;
    let raster = RasterPass::new(&device, (&mask_headers, &mask_texels))?;
    let usage = vk::ImageUsageFlags::SAMPLED;
    let images = FrameImages {
        depth: engine.image(DEPTH_FORMAT, width, height, usage | vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT)?,
        normals: engine.image(NORMAL_FORMAT, width, height, usage | vk::ImageUsageFlags::COLOR_ATTACHMENT)?,
        ao: engine.image(
            args.ao_format.vk(),
            width,
            height,
            vk::ImageUsageFlags::STORAGE | vk::ImageUsageFlags::TRANSFER_SRC,
        )?,
        width,
        height,
    };
    let texel_bytes = args.ao_format.texel_bytes();
    let readback =
        engine.host_buffer(vk::BufferUsageFlags::TRANSFER_DST, &[], texel_bytes * u64::from(width * height))?;
    let pool = unsafe {
        device.create_command_pool(&vk::CommandPoolCreateInfo::default().queue_family_index(engine.family), None)?
    };
    let cmd = unsafe {
        device.allocate_command_buffers(
            &vk::CommandBufferAllocateInfo::default().command_pool(pool).command_buffer_count(1),
        )?[0]
    };
    let fence = unsafe { device.create_fence(&vk::FenceCreateInfo::default(), None)? };

    // The engine's camera: its view matrix and a reversed-Z projection (any near/far works).
    let projection = reversed_z_projection((view.tan_half_fov.x, view.tan_half_fov.y), view.near, view.far);
    let push = RasterPush { world_to_view: frame.camera.world_to_view, projection };

    // ---- aokit: create, size, (scene for ray-traced techniques), record per frame, drop. ----
    let settings = AoSettings::new(technique).radius(frame.radius).exponent(frame.exponent).thickness(frame.thickness);
    let mut effect = AoEffect::new(engine.external(), settings)?;
    effect.resize(width, height)?;
    let geometry = tables.geometry(&scene.triangle_materials);
    let rays = if effect.traces_rays()? { Some(effect.build_scene(&geometry)?) } else { None };
    let depth = EngineImage { view: images.depth.view, layout: vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL };
    let output = AoImage { view: images.ao.view, format: args.ao_format.vk() };
    let mut ao_frame = AoFrame::new(depth, DepthConvention::Reversed, output, projection, frame.camera.world_to_view);
    if !args.no_normals {
        let layout = vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL;
        ao_frame = ao_frame.normals(EngineImage { view: images.normals.view, layout });
    }
    if let Some(rays) = &rays {
        ao_frame = ao_frame.scene(rays);
    }

    // The frame loop (the camera stands still, frame index 0 as `aokit render`; a moving camera
    // is just another AoFrame, `.temporal(index, previous_view)` animates the noise).
    let vertex_count = vertices.len() as u32;
    for index in 0..args.frames {
        let record_start = Instant::now();
        unsafe {
            device.reset_command_pool(pool, vk::CommandPoolResetFlags::empty())?;
            let begin = vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
            device.begin_command_buffer(cmd, &begin)?;
        }
        let recorded =
            record_frame(&device, cmd, &raster, (&vertex_buffer, vertex_count), &push, &images, &readback, |cmd| {
                Ok(effect.record(cmd, &ao_frame)?)
            });
        let record_ms = record_start.elapsed().as_secs_f64() * 1e3;
        let submit_start = Instant::now();
        unsafe {
            device.end_command_buffer(cmd)?;
            if recorded.is_ok() {
                let cmds = [cmd];
                device.queue_submit(engine.queue, &[vk::SubmitInfo::default().command_buffers(&cmds)], fence)?;
                device.wait_for_fences(&[fence], true, u64::MAX)?;
                device.reset_fences(&[fence])?;
            }
        }
        let frame_ms = submit_start.elapsed().as_secs_f64() * 1e3;
        recorded?;
        let passes_ms: f64 = effect.pass_times()?.iter().map(|(_, ms)| ms).sum();
        println!(
            "frame {index}: recorded in {record_ms:.2} ms (host), submit→fence {frame_ms:.2} ms, aokit passes {passes_ms:.2} ms"
        );
    }

    // The AO image's texels, 1 = unoccluded.
    let count = (width * height) as usize;
    let ao: Vec<f32> = unsafe {
        match args.ao_format {
            AoFormat::R32f => std::slice::from_raw_parts(readback.mapped as *const f32, count).to_vec(),
            AoFormat::R8 => {
                std::slice::from_raw_parts(readback.mapped, count).iter().map(|&b| f32::from(b) / 255.0).collect()
            }
        }
    };
    assert!(readback.size >= texel_bytes * count as u64);
    write_png(&args.out, width, height, &ao)?;
    let mean = ao.iter().map(|&a| f64::from(a)).sum::<f64>() / count as f64;
    println!(
        "{} on {} ({} triangles) at {width}×{height}, {}: mean AO {mean:.4} → {}",
        effect.settings().technique.name(),
        scene.name,
        scene.triangles.len(),
        engine.device_name,
        args.out.display()
    );
    let passes = effect.pass_times()?;
    for (label, ms) in &passes {
        println!("  {label:<18} {ms:>9.2} ms");
    }
    let gpu_ms: f64 = passes.iter().map(|(_, ms)| ms).sum();
    println!("  sum                {gpu_ms:>9.2} ms (last frame's timestamps; aokit's import/export are not timed)");
    if let Some(path) = &args.compare {
        let reference = image::open(path)?.into_luma8();
        if reference.dimensions() != (width, height) {
            return Err(format!("{}: {:?}, expected {width}×{height}", path.display(), reference.dimensions()).into());
        }
        // Both quantised to 8 bits, as written.
        let ours = ao.iter().map(|&a| (a.clamp(0.0, 1.0) * 255.0).round());
        let diffs: Vec<f32> = ours.zip(reference.as_raw()).map(|(a, &b)| (a - f32::from(b)).abs() / 255.0).collect();
        let mean_diff = diffs.iter().map(|&d| f64::from(d)).sum::<f64>() / count as f64;
        let max = diffs.iter().copied().fold(0.0, f32::max);
        let over = diffs.iter().filter(|&&d| d > 0.1).count() as f64 / count as f64;
        println!(
            "  vs {}: mean |Δ| {mean_diff:.5}, max |Δ| {max:.3}, {:.3} % of pixels off by > 0.1",
            path.display(),
            100.0 * over
        );
    }

    // Teardown: the device finished (fence); aokit's objects first, then the engine's.
    drop(rays);
    drop(effect);
    unsafe {
        device.destroy_fence(fence, None);
        device.destroy_command_pool(pool, None);
    }
    raster.destroy(&device);
    for image in [images.depth, images.normals, images.ao] {
        image.destroy(&device);
    }
    for buffer in [vertex_buffer, mask_headers, mask_texels, readback] {
        buffer.destroy(&device);
    }
    let messages = engine.destroy();
    if !messages.is_empty() {
        return Err(format!("validation layer reported {} message(s):\n{}", messages.len(), messages.join("\n")).into());
    }
    Ok(())
}
