//! The engine API (`AoEffect`) driven exactly as a game engine would drive it: the engine owns
//! the ash instance (Khronos validation layer, its own debug messenger), the device, the command
//! pool, the command buffers, the fences, the staging/readback memory and the images (hardware
//! depth, view normals, an AO image, in every format the adapters take) and hands its
//! projection and view matrices;
//! aokit only records into the engine's command buffer.
//!
//! 1. `effect_frames_agree_with_cpu_sim`: the engine's images are made from the CPU ray-cast
//!    G-buffer (reversed and standard Z, with and without a normal image, and a depth-peeled
//!    second layer); vao, gtao, raysd and dual-depth vao through the effect must agree with
//!    cpu-sim run on the SAME engine arrays through `aokit_cpu::adapters` (import →
//!    `CpuExecutor` → export) with the camera the effect derives from the matrices.
//!    `every_engine_format_through_the_effect_agrees_with_cpu_sim`: each depth format (D16,
//!    D24S8, X8_D24, D32) and convention (reversed, standard, OpenGL-style, infinite reversed),
//!    each normal format (RGBA16F, A2B10G10R10, RGBA8) and AO format (R16F, R8, R32F); the
//!    import checked over the whole target, guard band (clamp path) included.
//!    `ray_queries_on_an_engine_device_agree_with_the_pipelines_and_cpu_sim`: an engine device
//!    with ray queries and no pipeline. raysd everywhere through `check_raysd` (pass 2 exact on
//!    the device's own SD map).
//! 2. `soak_300_frames_two_resolutions`: 300 engine frames, raysd and gtao alternating
//!    (`set_settings`), through two resizes: no validation message, the effect's live allocations
//!    back to what they were at the same resolution and frame parity, and the same AO images
//!    before and after the round trip through the other resolution.
//! 3. `the_engines_own_tlas_with_instances_and_custom_indices`: the engine builds its own BLASes
//!    (one opaque, one alpha-tested and placed by its instance transform) and TLAS; ground truth
//!    and raysd on it through `AoEffect::scene_from_tlas` agree with cpu-sim, and breaking the
//!    custom-index convention breaks the ground truth's agreement.
//! 4. `wgpu_effect_frames_agree_with_cpu_sim` (`engine_context/wgpu_effect.rs`): the same
//!    engine arrays through the wgpu effect (`aokit_wgpu`), every screen-space technique, a
//!    resize and two frames in flight.

mod common;
#[path = "engine_context/wgpu_effect.rs"]
mod wgpu_effect;

use aokit::frame::Frame;
use aokit::output::crop_inner;
use aokit::render::CpuRenderer;
use aokit::scene::Scene;
use aokit::technique::{GtaoOptions, SdOptions, Technique};
use aokit_cpu::graph::{CpuExecutor, CpuInputs, CpuScene};
use aokit_cpu::{GBufferImage, no_progress};
use aokit_shaders::adapters::ImportParams;
use aokit_shaders::common::ViewParams;
use aokit_shaders::common::camera::Camera;
use aokit_shaders::common::normal_codec::decode_normal;
use aokit_shaders::glam::{Mat4, UVec2, Vec3, Vec4};
use aokit_shaders::graph::{Executed, FrameDesc, Graph, Refinement, RtMode};
use aokit_shaders::gtao::GtaoParams;
use aokit_shaders::gtao::settings::GTAO;
use aokit_shaders::svao::Secondary;
use aokit_shaders::svao::settings::RAYSD;
use aokit_shaders::vao::settings::VAO;
use aokit_vulkan::{
    AoEffect, AoError, AoFrame, AoImage, AoScene, AoSettings, DepthConvention, EngineImage, FRAMES_IN_FLIGHT, Gpu,
    Image2d, engine_camera,
};
use ash::vk;
use common::engine_device::{EngineDevice, EngineNeeds, RayTracing};
use common::mse_of as mse;
use std::ops::Deref;
use std::time::Instant;

/// Unit roundoff of f32.
const U: f64 = 1.0 / (1u64 << 24) as f64;

// ---------------------------------------------------------------------------------------------
// The engine: instance + messenger + device + queue + command pool + fence, all plain ash.

/// The engine's device (tests/common/engine_device.rs) with its command pool and fence.
struct Engine {
    base: EngineDevice,
    pool: vk::CommandPool,
    fence: vk::Fence,
}

impl Deref for Engine {
    type Target = EngineDevice;

    fn deref(&self) -> &EngineDevice {
        &self.base
    }
}

impl Engine {
    /// Instance with the validation layer and a messenger (warnings and errors), device on
    /// lavapipe (or the first Vulkan 1.3 device) with what aokit's compute and ray-tracing graphs
    /// need. `None` when the run allows its skip (tests/common/skip.rs).
    fn new() -> Option<Engine> {
        // raysd traces rays: the device must have the ray-tracing pipeline.
        Engine::with(RayTracing::Required)
    }

    /// [`Engine::new`] with `ray_tracing` instead of the required pipeline.
    fn with(ray_tracing: RayTracing) -> Option<Engine> {
        let base = EngineDevice::new(&EngineNeeds {
            app_name: c"an engine",
            queue_flags: vk::QueueFlags::COMPUTE,
            raster: false,
            ray_tracing,
        })?;
        let pool_info = vk::CommandPoolCreateInfo::default()
            .queue_family_index(base.family)
            .flags(vk::CommandPoolCreateFlags::TRANSIENT);
        let pool = unsafe { base.device.create_command_pool(&pool_info, None) }.unwrap();
        let fence = unsafe { base.device.create_fence(&vk::FenceCreateInfo::default(), None) }.unwrap();
        Some(Engine { base, pool, fence })
    }

    /// A primary command buffer of the engine's pool, recording.
    fn begin(&self) -> vk::CommandBuffer {
        let info = vk::CommandBufferAllocateInfo::default()
            .command_pool(self.pool)
            .level(vk::CommandBufferLevel::PRIMARY)
            .command_buffer_count(1);
        let cmd = unsafe { self.device.allocate_command_buffers(&info) }.unwrap()[0];
        let begin = vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
        unsafe { self.device.begin_command_buffer(cmd, &begin) }.unwrap();
        cmd
    }

    /// End `cmd`, submit it with the engine's fence, wait, free it.
    fn submit_and_wait(&self, cmd: vk::CommandBuffer) {
        let d = &self.device;
        let cmds = [cmd];
        unsafe {
            d.end_command_buffer(cmd).unwrap();
            d.queue_submit(self.queue, &[vk::SubmitInfo::default().command_buffers(&cmds)], self.fence).unwrap();
            d.wait_for_fences(&[self.fence], true, u64::MAX).unwrap();
            d.reset_fences(&[self.fence]).unwrap();
            d.free_command_buffers(self.pool, &cmds);
        }
    }

    /// Wait for the device, destroy everything of the engine's and return what the validation
    /// layer said (device and instance destruction included).
    fn destroy(self) -> Vec<String> {
        let (pool, fence) = (self.pool, self.fence);
        self.base.destroy_with(|device| unsafe {
            device.destroy_fence(fence, None);
            device.destroy_command_pool(pool, None);
        })
    }
}

/// A host-visible, coherent memory type `req` allows.
fn host_memory_type(engine: &Engine, req: &vk::MemoryRequirements) -> u32 {
    let props = unsafe { engine.instance.get_physical_device_memory_properties(engine.physical_device) };
    let want = vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT;
    (0..props.memory_type_count)
        .find(|&i| req.memory_type_bits & (1 << i) != 0 && props.memory_types[i as usize].property_flags.contains(want))
        .expect("host-visible coherent memory")
}

/// A host-visible, coherent buffer of the engine's own (staging and readback), plain Vulkan
/// memory outside aokit's allocator.
struct HostBuffer {
    buffer: vk::Buffer,
    memory: vk::DeviceMemory,
    size: u64,
}

impl HostBuffer {
    fn new(engine: &Engine, size: u64, usage: vk::BufferUsageFlags) -> HostBuffer {
        let d = &engine.device;
        let info = vk::BufferCreateInfo::default().size(size).usage(usage).sharing_mode(vk::SharingMode::EXCLUSIVE);
        let buffer = unsafe { d.create_buffer(&info, None) }.unwrap();
        let req = unsafe { d.get_buffer_memory_requirements(buffer) };
        let type_index = host_memory_type(engine, &req);
        let alloc = vk::MemoryAllocateInfo::default().allocation_size(req.size).memory_type_index(type_index);
        let memory = unsafe { d.allocate_memory(&alloc, None) }.unwrap();
        unsafe { d.bind_buffer_memory(buffer, memory, 0) }.unwrap();
        HostBuffer { buffer, memory, size }
    }

    fn write(&self, engine: &Engine, offset: u64, bytes: &[u8]) {
        assert!(offset + bytes.len() as u64 <= self.size);
        let d = &engine.device;
        unsafe {
            let ptr = d.map_memory(self.memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty()).unwrap() as *mut u8;
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), ptr.add(offset as usize), bytes.len());
            d.unmap_memory(self.memory);
        }
    }

    fn read_bytes(&self, engine: &Engine, len: usize) -> Vec<u8> {
        assert!(len as u64 <= self.size);
        let d = &engine.device;
        let mut out = vec![0u8; len];
        unsafe {
            let ptr = d.map_memory(self.memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty()).unwrap() as *const u8;
            std::ptr::copy_nonoverlapping(ptr, out.as_mut_ptr(), len);
            d.unmap_memory(self.memory);
        }
        out
    }

    fn read_f32(&self, engine: &Engine, count: usize) -> Vec<f32> {
        bytemuck::pod_collect_to_vec(&self.read_bytes(engine, 4 * count))
    }

    /// `count` texels of an AO image of `format` copied here, as the values a shader samples.
    fn read_ao(&self, engine: &Engine, format: vk::Format, count: usize) -> Vec<f32> {
        let bytes = self.read_bytes(engine, texel_bytes(format) * count);
        match format {
            vk::Format::R32_SFLOAT => bytemuck::pod_collect_to_vec(&bytes),
            vk::Format::R16_SFLOAT => {
                bytes.chunks(2).map(|h| common::f16_to_f32(u16::from_le_bytes([h[0], h[1]]))).collect()
            }
            vk::Format::R8_UNORM => bytes.iter().map(|&b| b as f32 / 255.0).collect(),
            _ => unreachable!("AO format {format:?}"),
        }
    }

    fn destroy(self, engine: &Engine) {
        unsafe {
            engine.device.destroy_buffer(self.buffer, None);
            engine.device.free_memory(self.memory, None);
        }
    }
}

#[allow(clippy::too_many_arguments)]
fn image_barrier(
    engine: &Engine,
    cmd: vk::CommandBuffer,
    image: &Image2d,
    (old, new): (vk::ImageLayout, vk::ImageLayout),
    (src_stage, src_access): (vk::PipelineStageFlags, vk::AccessFlags),
    (dst_stage, dst_access): (vk::PipelineStageFlags, vk::AccessFlags),
) {
    let barrier = vk::ImageMemoryBarrier::default()
        .src_access_mask(src_access)
        .dst_access_mask(dst_access)
        .old_layout(old)
        .new_layout(new)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .image(image.raw)
        .subresource_range(image.range());
    unsafe {
        engine.device.cmd_pipeline_barrier(
            cmd,
            src_stage,
            dst_stage,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &[barrier],
        )
    };
}

/// Bytes per texel of a buffer ↔ image copy of `format` (the depth aspect's for depth formats:
/// D24 depth travels in 32 bits, Vulkan spec §"Copying Data Between Buffers and Images").
fn texel_bytes(format: vk::Format) -> usize {
    match format {
        vk::Format::R8_UNORM => 1,
        vk::Format::R16_SFLOAT | vk::Format::D16_UNORM => 2,
        vk::Format::R16G16B16A16_SFLOAT => 8,
        _ => 4,
    }
}

fn copy_region(image: &Image2d, buffer_offset: u64) -> vk::BufferImageCopy {
    image.copy_region().buffer_offset(buffer_offset)
}

type S = vk::PipelineStageFlags;
type A = vk::AccessFlags;
const DEPTH_LAYOUT: vk::ImageLayout = vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL;
const NORMAL_LAYOUT: vk::ImageLayout = vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL;

// ---------------------------------------------------------------------------------------------
// The engine's G-buffer images.

/// The formats of the engine's images and its depth convention.
#[derive(Clone, Copy, Debug)]
struct EngineFormats {
    depth: vk::Format,
    convention: DepthConvention,
    normals: vk::Format,
    output: vk::Format,
}

impl EngineFormats {
    /// D32 depth in `convention`, RGBA8 normals, an R32F AO image.
    fn d32(convention: DepthConvention) -> EngineFormats {
        EngineFormats {
            depth: vk::Format::D32_SFLOAT,
            convention,
            normals: vk::Format::R8G8B8A8_UNORM,
            output: vk::Format::R32_SFLOAT,
        }
    }
}

/// Is `convention`'s stored depth the standard `f·(z − n)/(z·(f − n))`, whose inverse has
/// the condition number κ = z·(f − n)/(n·f)?
fn is_standard(convention: DepthConvention) -> bool {
    matches!(convention, DepthConvention::Standard | DepthConvention::NegativeOneToOne)
}

/// What the engine renders: the inner image's hardware depth and view normals.
struct EngineGBuffer {
    size: UVec2,
    formats: EngineFormats,
    /// The depth image's texels as the sampler returns them (UNORM formats: `u/(2^b − 1)`), for
    /// the CPU import.
    depth: Vec<f32>,
    /// The depth image's stored texels (the copy's layout of its depth aspect).
    depth_bytes: Vec<u8>,
    /// Stored D32 values of the depth-peeled second layer, for dual-depth graphs.
    second: Option<Vec<f32>>,
    /// The normal image's stored texels.
    normal_bytes: Vec<u8>,
    /// The normals as the sampler returns them, for the CPU import.
    rgb: Vec<[f32; 3]>,
    params: ImportParams,
}

/// Stored bytes of the hardware depths `hw` (in [0, 1]) in `format`, and what the sampler
/// returns for them: UNORM depth `u = round(d·(2^b − 1))` reads back as `u/(2^b − 1)` (Vulkan
/// spec, "Fixed-Point Data Conversions"); D24 travels in the low 24 bits of 32.
fn depth_texels(format: vk::Format, hw: &[f32]) -> (Vec<u8>, Vec<f32>) {
    let unorm = |bits: u32| {
        let max = ((1u64 << bits) - 1) as f64;
        let stored: Vec<u32> = hw.iter().map(|&d| (d as f64 * max).round() as u32).collect();
        let sampled = stored.iter().map(|&u| (u as f64 / max) as f32).collect();
        (stored, sampled)
    };
    match format {
        vk::Format::D32_SFLOAT => (bytemuck::cast_slice(hw).to_vec(), hw.to_vec()),
        vk::Format::D16_UNORM => {
            let (stored, sampled) = unorm(16);
            (stored.iter().flat_map(|&u| (u as u16).to_le_bytes()).collect(), sampled)
        }
        vk::Format::X8_D24_UNORM_PACK32 | vk::Format::D24_UNORM_S8_UINT => {
            let (stored, sampled) = unorm(24);
            (bytemuck::cast_slice(&stored).to_vec(), sampled)
        }
        _ => unreachable!("depth format {format:?}"),
    }
}

/// Stored bytes of the encoded normals `c = n·0.5 + 0.5` in `format` (RGB, alpha 1), and what
/// the sampler returns for them.
fn normal_texels(format: vk::Format, c: &[Vec3]) -> (Vec<u8>, Vec<[f32; 3]>) {
    match format {
        vk::Format::R8G8B8A8_UNORM => {
            let q: Vec<[u8; 4]> = c.iter().map(|c| [c.x, c.y, c.z, 1.0].map(|v| (v * 255.0).round() as u8)).collect();
            let rgb = q.iter().map(|q| [q[0], q[1], q[2]].map(|v| v as f32 / 255.0)).collect();
            (q.concat(), rgb)
        }
        vk::Format::R16G16B16A16_SFLOAT => {
            let q: Vec<[u16; 4]> = c.iter().map(|c| [c.x, c.y, c.z, 1.0].map(common::f32_to_f16)).collect();
            let rgb = q.iter().map(|q| [q[0], q[1], q[2]].map(common::f16_to_f32)).collect();
            (q.iter().flatten().flat_map(|h| h.to_le_bytes()).collect(), rgb)
        }
        vk::Format::A2B10G10R10_UNORM_PACK32 => {
            let q: Vec<[u32; 3]> = c.iter().map(|c| [c.x, c.y, c.z].map(|v| (v * 1023.0).round() as u32)).collect();
            let words: Vec<u32> = q.iter().map(|q| q[0] | (q[1] << 10) | (q[2] << 20) | (3 << 30)).collect();
            let rgb = q.iter().map(|q| q.map(|v| v as f32 / 1023.0)).collect();
            (bytemuck::cast_slice(&words).to_vec(), rgb)
        }
        _ => unreachable!("normal format {format:?}"),
    }
}

/// The engine's depth buffer of the CPU ray-cast G-buffer (inner image) in `formats`: depth in
/// its convention with the camera projection's near/far planes, computed in f64 and stored in
/// its format; background (`>= view.far`) is the cleared value. Normals: `n·0.5 + 0.5` of the
/// decoded G-buffer normals in the normal format.
fn engine_gbuffer(view: &ViewParams, gbuffer: &GBufferImage, formats: EngineFormats) -> EngineGBuffer {
    let size = view.size() - 2 * view.guard;
    let (depth_bytes, depth) = depth_texels(formats.depth, &engine_depth(view, &gbuffer.depth, formats.convention));
    let encoded: Vec<Vec3> =
        crop_inner(view, &gbuffer.normals).iter().map(|&n| decode_normal(n) * 0.5 + Vec3::splat(0.5)).collect();
    let (normal_bytes, rgb) = normal_texels(formats.normals, &encoded);
    let params = ImportParams {
        view: *view,
        engine_size: size,
        depth_convention: formats.convention.code(),
        near: view.near,
        far: view.far,
        _pad: 0,
    };
    EngineGBuffer { size, formats, depth, depth_bytes, second: None, normal_bytes, rgb, params }
}

/// The inner image of a full-target linear depth as the engine's D32 depth buffer in
/// `convention` (see [`engine_gbuffer`]).
fn engine_depth(view: &ViewParams, linear: &[f32], convention: DepthConvention) -> Vec<f32> {
    let linear = crop_inner(view, linear);
    let (n, f) = (view.near as f64, view.far as f64);
    let standard = is_standard(convention);
    linear
        .iter()
        .map(|&z| {
            let z = z as f64;
            match convention {
                _ if standard && z >= f => 1.0,
                // OpenGL's window depth 0.5·z_ndc + 0.5 is this same value.
                _ if standard => (f * (z - n) / (z * (f - n))) as f32,
                DepthConvention::Reversed | DepthConvention::ReversedInfinite if z >= f => 0.0,
                DepthConvention::Reversed => (n * (f - z) / (z * (f - n))) as f32,
                DepthConvention::ReversedInfinite => (n / z) as f32,
                _ => unreachable!("convention {convention:?}"),
            }
        })
        .collect()
}

/// The engine's images in `EngineGBuffer::formats`: depth (sampled, a depth attachment),
/// normals (sampled) and the AO output (storage).
struct Targets {
    depth: Image2d,
    normals: Image2d,
    /// The second depth layer, where the engine G-buffer has one.
    second: Option<Image2d>,
    output: Image2d,
    size: UVec2,
}

impl Targets {
    /// Create the images and upload `g` through the engine's staging buffer in the engine's
    /// command buffer: depth left in DEPTH_STENCIL_READ_ONLY_OPTIMAL, normals in
    /// SHADER_READ_ONLY_OPTIMAL, both visible to compute-shader reads.
    fn new(engine: &Engine, gpu: &Gpu, g: &EngineGBuffer) -> Targets {
        let (w, h) = (g.size.x, g.size.y);
        let sampled = vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST;
        let depth_usage = sampled | vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT;
        let out_usage = vk::ImageUsageFlags::STORAGE | vk::ImageUsageFlags::TRANSFER_SRC;
        let f = g.formats;
        let targets = Targets {
            depth: gpu.create_image_2d(f.depth, w, h, depth_usage).unwrap(),
            normals: gpu.create_image_2d(f.normals, w, h, sampled).unwrap(),
            second: g.second.as_ref().map(|_| gpu.create_image_2d(vk::Format::D32_SFLOAT, w, h, depth_usage).unwrap()),
            output: gpu.create_image_2d(f.output, w, h, out_usage).unwrap(),
            size: g.size,
        };
        let (depth_bytes, normal_bytes) = (&g.depth_bytes, &g.normal_bytes);
        let second_bytes: &[u8] = g.second.as_deref().map_or(&[], bytemuck::cast_slice);
        let staging_size = (depth_bytes.len() + normal_bytes.len() + second_bytes.len()).max(4) as u64;
        let staging = HostBuffer::new(engine, staging_size, vk::BufferUsageFlags::TRANSFER_SRC);
        staging.write(engine, 0, depth_bytes);
        staging.write(engine, depth_bytes.len() as u64, normal_bytes);
        staging.write(engine, (depth_bytes.len() + normal_bytes.len()) as u64, second_bytes);
        let cmd = engine.begin();
        let dst = vk::ImageLayout::TRANSFER_DST_OPTIMAL;
        let mut regions =
            vec![(&targets.depth, 0, DEPTH_LAYOUT), (&targets.normals, depth_bytes.len() as u64, NORMAL_LAYOUT)];
        if let Some(second) = &targets.second {
            regions.push((second, (depth_bytes.len() + normal_bytes.len()) as u64, DEPTH_LAYOUT));
        }
        for (image, offset, layout) in regions {
            let none = (S::TOP_OF_PIPE, A::empty());
            image_barrier(
                engine,
                cmd,
                image,
                (vk::ImageLayout::UNDEFINED, dst),
                none,
                (S::TRANSFER, A::TRANSFER_WRITE),
            );
            let region = [copy_region(image, offset)];
            unsafe { engine.device.cmd_copy_buffer_to_image(cmd, staging.buffer, image.raw, dst, &region) };
            let read = (S::COMPUTE_SHADER, A::SHADER_READ);
            image_barrier(engine, cmd, image, (dst, layout), (S::TRANSFER, A::TRANSFER_WRITE), read);
        }
        engine.submit_and_wait(cmd);
        staging.destroy(engine);
        targets
    }

    fn destroy(self, gpu: &Gpu) {
        for image in [self.depth, self.normals, self.output].into_iter().chain(self.second) {
            gpu.free_image(image);
        }
    }
}

/// What the engine hands the effect for `frame`'s camera with depth stored in `convention`,
/// and what the effect derives from it: the CPU reference
/// runs on exactly that camera and those import parameters.
struct EngineView {
    projection: Mat4,
    world_to_view: Mat4,
    convention: DepthConvention,
    camera: Camera,
    params: ImportParams,
}

fn engine_view(frame: &Frame, convention: DepthConvention) -> EngineView {
    let view = frame.camera.view;
    let projection = engine_projection(&view, convention);
    let inner = view.size() - 2 * view.guard;
    let world_to_view = frame.camera.world_to_view;
    let derived = engine_camera(projection, world_to_view, inner, view.guard, convention).unwrap();
    let mut camera = derived.camera;
    if convention == DepthConvention::ReversedInfinite {
        // No far plane: background from 1e5 × near on (`AoSettings::background_depth`'s default).
        camera.view.far = derived.near * 1e5;
    }
    assert!((camera.view.tan_half_fov - view.tan_half_fov).abs().max_element() < 1e-5 * view.tan_half_fov.x);
    // The planes come back from the f32 matrix: a standard-Z P₂₂ = f/(n − f) keeps f only to
    // 8U·f/n (1 + P₂₂ cancels), reversed Z and the near plane to a few U.
    // An infinite projection has no far plane to read back.
    let far_bound = if is_standard(convention) { 8.0 * U * (view.far / view.near) as f64 } else { 8.0 * U };
    assert!((derived.near as f64 / view.near as f64 - 1.0).abs() <= 8.0 * U, "near {}", derived.near);
    if convention == DepthConvention::ReversedInfinite {
        assert_eq!(derived.far, f32::MAX);
    } else {
        assert!((derived.far as f64 / view.far as f64 - 1.0).abs() <= far_bound, "far {}", derived.far);
    }
    let params = ImportParams {
        view: camera.view,
        engine_size: inner,
        depth_convention: convention.code(),
        near: derived.near,
        far: derived.far,
        _pad: 0,
    };
    EngineView { projection, world_to_view, convention, camera, params }
}

/// The effect's settings for technique `t` at `frame`'s AO parameters.
fn effect_settings(t: &Technique, frame: &Frame) -> AoSettings {
    AoSettings::new(t.clone())
        .radius(frame.radius)
        .exponent(frame.exponent)
        .thickness(frame.thickness)
        .guard(frame.camera.view.guard)
}

/// The frame the engine hands the effect: its images in `targets` (normals only `with_normals`,
/// the second layer where `targets` has one), its matrices and the scene (for techniques that
/// trace rays).
fn effect_frame<'a>(targets: &Targets, v: &EngineView, with_normals: bool, scene: Option<&'a AoScene>) -> AoFrame<'a> {
    let output = AoImage { view: targets.output.view, format: targets.output.format };
    let depth = EngineImage { view: targets.depth.view, layout: DEPTH_LAYOUT };
    let mut frame = AoFrame::new(depth, v.convention, output, v.projection, v.world_to_view);
    if let Some(scene) = scene {
        frame = frame.scene(scene);
    }
    if let Some(second) = &targets.second {
        frame = frame.second_depth(EngineImage { view: second.view, layout: DEPTH_LAYOUT });
    }
    if with_normals {
        frame = frame.normals(EngineImage { view: targets.normals.view, layout: NORMAL_LAYOUT });
    }
    frame
}

/// Record one engine frame into `cmd`: the AO image to GENERAL (its old contents discarded; the
/// previous frame's export and copy finish first), `AoEffect::record`, then, with `readback`,
/// the AO image copied into the engine's host buffer and made visible to the host.
fn record_frame(
    engine: &Engine,
    effect: &mut AoEffect,
    cmd: vk::CommandBuffer,
    targets: &Targets,
    frame: &AoFrame,
    readback: Option<&HostBuffer>,
) -> Result<(), AoError> {
    let general = vk::ImageLayout::GENERAL;
    let previous = (S::COMPUTE_SHADER | S::TRANSFER, A::empty());
    let write = (S::COMPUTE_SHADER, A::SHADER_WRITE);
    image_barrier(engine, cmd, &targets.output, (vk::ImageLayout::UNDEFINED, general), previous, write);
    effect.record(cmd, frame)?;
    if let Some(buffer) = readback {
        let src = vk::ImageLayout::TRANSFER_SRC_OPTIMAL;
        image_barrier(engine, cmd, &targets.output, (general, src), write, (S::TRANSFER, A::TRANSFER_READ));
        let region = [copy_region(&targets.output, 0)];
        unsafe { engine.device.cmd_copy_image_to_buffer(cmd, targets.output.raw, src, buffer.buffer, &region) };
        let host = vk::MemoryBarrier::default().src_access_mask(A::TRANSFER_WRITE).dst_access_mask(A::HOST_READ);
        let flags = vk::DependencyFlags::empty();
        unsafe { engine.device.cmd_pipeline_barrier(cmd, S::TRANSFER, S::HOST, flags, &[host], &[], &[]) };
    }
    Ok(())
}

/// No validation message (core and synchronization validation).
fn assert_validation_clean(test: &str, messages: Vec<String>) {
    eprintln!("{test}: {} validation messages", messages.len());
    assert!(messages.is_empty(), "validation layer reported:\n{}", messages.join("\n"));
}

// ---------------------------------------------------------------------------------------------
// 1. Engine frames against cpu-sim on the same engine arrays.

/// What the CPU computes from the engine arrays: the imported linear depth and normals (the
/// normals derived from depth by XeGTAO's pass 0 when the engine gives no normal image, as
/// `AoFrame::normals` documents), then the graph, then the export into the engine's image.
fn cpu_reference(renderer: &CpuRenderer, graph: &Graph, g: &EngineGBuffer, with_normals: bool) -> CpuFrame {
    let depth = aokit_cpu::adapters::import_depth(&g.params, &g.depth);
    let normals = if with_normals {
        aokit_cpu::adapters::import_normals(&g.params, &g.rgb)
    } else {
        let params = GtaoParams { view: g.params.view, ..bytemuck::Zeroable::zeroed() };
        aokit_cpu::gtao::run_normals(&params, &depth)
    };
    let second = g.second.as_ref().map(|d| aokit_cpu::adapters::import_depth(&g.params, d));
    let surfaces = renderer.surfaces();
    let inputs = CpuInputs {
        depth: &depth,
        normals: &normals,
        second_depth: second.as_deref(),
        scene: Some(CpuScene { bvh: renderer.bvh(), surfaces: &surfaces }),
        progress: &no_progress,
    };
    let mut executor = CpuExecutor::new();
    executor.run(graph, &inputs).unwrap();
    let ao = aokit_cpu::adapters::export_ao(&g.params, executor.f32(graph.output).expect("the graph's output"));
    let raw = executor.f32(graph.raw_output).expect("the graph's raw output").to_vec();
    let words = |name: &str| executor.words(name).map(<[u32]>::to_vec);
    let run = Executed { words: &words, depth: &depth, normals: &normals };
    let refinement = graph.diagnostics.refinement.map(|decoder| (decoder.decode)(&run));
    CpuFrame { ao, depth, normals, raw, refinement }
}

/// cpu-sim's run of a graph on the engine's arrays ([`cpu_reference`]).
struct CpuFrame {
    /// The AO exported into the engine's image (inner size).
    ao: Vec<f32>,
    /// The imported linear depth over the whole target.
    depth: Vec<f32>,
    /// The imported (or derived) normal codes over the whole target.
    normals: Vec<u32>,
    /// The graph's raw output (before the denoiser), whole target.
    raw: Vec<f32>,
    /// A stenciled technique's pass-1 AO, mask and SD map.
    refinement: Option<Refinement>,
}

/// raysd through the effect against cpu-sim. Its SD map depends on the device's ray
/// intersections and any-hit order, and a hit distance one ulp apart can flip a line sample
/// lying on the recorded surface (measured on Sponza 96×64 with a 12-pixel guard band: 141 SD
/// values one to three ulps apart move the pass-2 AO by up to 40/255, MSE 1.9e-5), so the
/// comparison separates what must be exact from what may differ:
/// - the pass-1 mask: identical (a deterministic kernel);
/// - the SD map: ≥ 99 % of its values identical (most of the rest an ulp or three apart, a few
///   texels keeping other hits where the any-hit order differs; vulkan_svao.rs checks the
///   reservoir property of the device's map);
/// - pass 2 on the DEVICE's SD map: cpu-sim's pass 2 (`common::pass2_refining`) run on it
///   reproduces the device's pass-2 AO within the deterministic bounds (common::agreement);
///   a pass 2 that leaves 1 in 50 flagged samples unrefined, made the same way, is shown to be
///   far outside them;
/// - the exported final AO within 1/10 of the MSE a pass 2 missing 1 in 10 flagged samples gives
///   before the blur (cpu-sim's own buffers; the blur only lowers it): a sanity bound on the
///   whole chain. Pass-2 defects themselves are caught by the exact check on the device's map.
///   (The old bound, final MSE ≤ 1e-4, let a pass 2 refining only half the samples pass.)
fn check_raysd(
    name: &str,
    desc: &FrameDesc,
    cpu: &CpuFrame,
    (gpu, gpu_raw): (&Refinement, &[f32]),
    gpu_ao: &[f32],
) -> String {
    let view = desc.camera.view;
    let size = view.size();
    let svao = SdOptions::default().frame(desc, Secondary::StochasticDepth);
    let g = GBufferImage { width: size.x, height: size.y, depth: cpu.depth.clone(), normals: cpu.normals.clone() };
    let refinement = cpu.refinement.as_ref().expect("raysd's refinement buffers");
    assert!(refinement.mask.iter().any(|&m| m != 0), "{name}: the frame must flag samples");
    assert!(gpu.mask == refinement.mask, "{name}: pass-1 masks differ");
    common::assert_same_len(&gpu.sd_map, &refinement.sd_map, name);
    let identical = gpu.sd_map.iter().zip(&refinement.sd_map).filter(|(a, b)| a == b).count();
    let worst =
        gpu.sd_map.iter().zip(&refinement.sd_map).map(|(a, b)| (a - b).abs() / b.abs().max(1e-30)).fold(0.0, f32::max);
    let values = refinement.sd_map.len();
    assert!(identical as f64 >= 0.99 * values as f64, "{name}: only {identical}/{values} SD values identical");
    // Pass 2 on the device's map, and the defect the exact bounds must catch.
    let on_gpu_map =
        common::pass2_refining(&svao.params, &g, (&refinement.ao_pass1, &refinement.mask), &gpu.sd_map, |_| true);
    let pass2 = common::agreement::inner(&view, &on_gpu_map, gpu_raw);
    let defect = common::pass2_defects(&svao.params, &g, refinement, &cpu.raw);
    let missing = |every: u64| common::agreement::inner(&view, &cpu.raw, &defect(&|k| k % every != 0));
    let (m10, m50) = (missing(10), missing(50));
    let final_bound = m10.mse / 10.0;
    let line = format!(
        "{name}: SD map {identical}/{values} values identical, worst {worst:.1e} relative; {}; {}; final-AO bound MSE ≤ {final_bound:.2e}",
        pass2.line("pass 2 on the device's map"),
        m50.line("pass 2 missing 1 in 50"),
    );
    eprintln!("{line}");
    assert!(m50.mse > 10.0 * common::agreement::MAX_MSE, "{name}: the 1-in-50 defect must exceed the exact bound");
    pass2.assert_exact(&format!("{name}: pass 2 on the device's SD map"));
    let m = mse(&cpu.ao, gpu_ao);
    assert!(m <= final_bound, "{name}: final AO MSE {m:.2e} above {final_bound:.2e}");
    format!("{line}; {}", check_agreement(name, &cpu.ao, gpu_ao))
}

/// The frame the effect just recorded for `graph` (its exported AO `gpu_ao`) against cpu-sim's
/// `cpu`: raysd through [`check_raysd`] (its pass-2 AO read from the effect's context), the
/// others through [`check_agreement`].
fn check_frame(
    name: &str,
    effect: &AoEffect,
    (graph, desc): (&Graph, &FrameDesc),
    cpu: &CpuFrame,
    gpu_ao: &[f32],
) -> String {
    if name.starts_with("raysd") {
        let gpu_raw: Vec<f32> = effect.context().download(graph.raw_output).unwrap();
        let words = |name: &str| graph.resource(name).and_then(|_| effect.context().download::<u32>(name).ok());
        let run = Executed { words: &words, depth: &cpu.depth, normals: &cpu.normals };
        let decoder = graph.diagnostics.refinement.expect("raysd decodes its refinement");
        let gpu = (decoder.decode)(&run);
        check_raysd(name, desc, cpu, (&gpu, &gpu_raw), gpu_ao)
    } else {
        check_agreement(name, &cpu.ao, gpu_ao)
    }
}

/// The agreement each technique must reach (from the existing CPU ≡ Vulkan tests).
fn check_agreement(name: &str, cpu: &[f32], gpu: &[f32]) -> String {
    let common::agreement::Agreement { within, mse: m, max, occluded, .. } = common::agreement::of(cpu, gpu);
    let line = format!(
        "{name}: {:.3} % within 1/255, max |Δ| {max:.2e} ({:.2}/255), MSE {m:.2e}, occluded (< 0.9) {:.1} %",
        100.0 * within,
        max * 255.0,
        100.0 * occluded
    );
    eprintln!("{line}");
    // Real occlusion, or the comparison means little.
    assert!(occluded >= 0.02, "{name}: only {:.2} % of pixels occluded", 100.0 * occluded);
    assert!(gpu.iter().all(|a| (0.0..=1.0).contains(a)), "{name}: exported AO outside [0, 1]");
    if name.starts_with("vao") || name.starts_with("gtao") {
        // Deterministic kernels (common::agreement): ≥ 99.9 % within one 8-bit step, MSE ≤ 1e-6
        // (a few one-step flips give ~1e-8; a wrong term or a missing pass ≥ 1e-5). gtao's
        // 0–255 AO terms may differ by one step where the f32 math rounds differently, which the
        // denoiser spreads, still far inside both.
        assert!(within >= common::agreement::MIN_WITHIN, "{line}");
        assert!(m <= common::agreement::MAX_MSE, "{line}");
        if name.starts_with("vao") {
            // tests/vulkan_agreement.rs: nothing beyond four steps.
            assert!(max <= 4.0 / 255.0, "{line}");
        }
    } else if name.starts_with("groundtruth") {
        // Each pixel's AO is the fraction of its fixed rays that escape: the same hit/miss
        // decisions give the same value; only a ray grazing a shared edge may decide otherwise
        // (watertightness), moving a pixel by 1/spp. Allow that at 0.1 % of the pixels.
        assert!(within >= common::agreement::MIN_WITHIN, "{line}");
    } else {
        // raysd: its own bounds, derived per frame (check_raysd), which calls this for the rest.
        assert!(name.starts_with("raysd"), "{name}: no agreement bound for this technique");
    }
    line
}

/// The engine's projection of `view`'s inner image: right-handed, clip depth in [0, 1] with
/// `convention`'s near/far mapping (what `engine_depth` stored; OpenGL's clip depth in [−1, 1]
/// for NegativeOneToOne), Y flipped so row 0 is the top.
fn engine_projection(view: &ViewParams, convention: DepthConvention) -> Mat4 {
    let inner = (view.size() - 2 * view.guard).as_vec2();
    let tan = view.tan_half_fov * inner / view.res;
    let (n, f) = (view.near, view.far);
    // d = a + b/z: standard d(n) = 0, d(f) = 1; reversed d(n) = 1, d(f) = 0; reversed
    // infinite d = n/z; OpenGL (gluPerspective) z_ndc(n) = −1, z_ndc(f) = 1.
    let (p22, p32) = match convention {
        DepthConvention::Standard => (f / (n - f), n * f / (n - f)),
        DepthConvention::Reversed => (n / (f - n), n * f / (f - n)),
        DepthConvention::ReversedInfinite => (0.0, n),
        DepthConvention::NegativeOneToOne => ((f + n) / (n - f), 2.0 * f * n / (n - f)),
        DepthConvention::Linear => unreachable!("linear depth"),
    };
    Mat4::from_cols(
        Vec4::new(1.0 / tan.x, 0.0, 0.0, 0.0),
        Vec4::new(0.0, -1.0 / tan.y, 0.0, 0.0),
        Vec4::new(0.0, 0.0, p22, -1.0),
        Vec4::new(0.0, 0.0, p32, 0.0),
    )
}

#[test]
fn effect_frames_agree_with_cpu_sim() {
    let Some(engine) = Engine::new() else { return };
    let start = Instant::now();
    let (scene, frame): (Scene, Frame) = common::builtin_frame("sponza", 160, 96, 16);
    let view = frame.camera.view;
    let renderer = CpuRenderer::new(&scene);
    let (gbuffer, _) = renderer.gbuffer(&frame, &no_progress);
    let techniques = [
        ("vao", Technique::new(&VAO, SdOptions::default())),
        ("gtao", Technique::preset("gtao", "high").unwrap()),
        ("raysd", Technique::new(&RAYSD, SdOptions::default())),
        // Dual depth: the engine gives the depth-peeled second layer as a second depth image.
        ("vao-dual", Technique::new(&VAO, SdOptions { dual: true, peel_separation: 0.5, ..Default::default() })),
    ];
    let separation = techniques[3].1.second_layer().expect("dual depth");
    let surfaces = renderer.surfaces();
    let depth2 = aokit_cpu::ray_cast_second_layer(renderer.bvh(), &surfaces, &frame.camera, &gbuffer, separation);
    // The engine's own images go through a Gpu of its own on the same device.
    let images = Gpu::from_external(engine.external()).unwrap();
    let mut effect = AoEffect::new(engine.external(), effect_settings(&techniques[0].1, &frame)).unwrap();
    let inner = view.size() - 2 * view.guard;
    let rays = effect.build_scene(&scene.corner_tables().geometry(&scene.triangle_materials)).unwrap();
    let mut report = Vec::new();
    for (convention_name, convention, with_normals) in [
        ("reversed-Z", DepthConvention::Reversed, true),
        ("standard-Z", DepthConvention::Standard, true),
        ("reversed-Z", DepthConvention::Reversed, false),
    ] {
        let v = engine_view(&frame, convention);
        let exact = EngineGBuffer {
            second: Some(engine_depth(&view, &depth2, convention)),
            ..engine_gbuffer(&view, &gbuffer, EngineFormats::d32(convention))
        };
        // The stored depths hold the G-buffer's: the CPU import with the exact planes recovers
        // the linear depth within the bound of tests/adapters.rs (8U·(1 + κ), κ = z·(f − n)/(n·f)
        // for standard Z).
        let imported = crop_inner(&view, &aokit_cpu::adapters::import_depth(&exact.params, &exact.depth));
        let original = crop_inner(&view, &gbuffer.depth);
        let (n, f) = (view.near as f64, view.far as f64);
        let mut worst = 0.0f64;
        for (&got, &want) in imported.iter().zip(&original) {
            let (got, want) = (got as f64, want as f64);
            let kappa = if is_standard(convention) { want * (f - n) / (n * f) } else { 0.0 };
            let rel = (got - want).abs() / want;
            assert!(rel <= 8.0 * U * (1.0 + kappa), "{convention_name}: depth {want} imported as {got}");
            worst = worst.max(rel);
        }
        // The CPU reference imports with what the effect derived from the matrices.
        let g = EngineGBuffer { params: v.params, ..exact };
        let texels = (g.size.x * g.size.y) as usize;
        let normals_name = if with_normals { "RGBA8 normals" } else { "normals from depth" };
        eprintln!(
            "{convention_name}, {normals_name}: {}×{} engine image, worst relative depth error after import {worst:.2e}",
            g.size.x, g.size.y
        );
        let targets = Targets::new(&engine, &images, &g);
        let readback = HostBuffer::new(&engine, 4 * texels as u64, vk::BufferUsageFlags::TRANSFER_DST);
        effect.resize(inner.x, inner.y).unwrap();
        let ao_frame = effect_frame(&targets, &v, with_normals, Some(&rays));
        for (name, technique) in &techniques {
            effect.set_settings(effect_settings(technique, &frame)).unwrap();
            let cmd = engine.begin();
            record_frame(&engine, &mut effect, cmd, &targets, &ao_frame, Some(&readback)).unwrap();
            engine.submit_and_wait(cmd);
            let on_gpu = readback.read_f32(&engine, texels);
            let desc = FrameDesc::new(v.camera, frame.radius, frame.exponent, frame.thickness);
            let graph = technique.graph(&desc).unwrap();
            let on_cpu = cpu_reference(&renderer, &graph, &g, with_normals);
            let label = format!("{name} ({convention_name}, {normals_name})");
            report.push(check_frame(&label, &effect, (&graph, &desc), &on_cpu, &on_gpu));
        }
        readback.destroy(&engine);
        targets.destroy(&images);
    }
    // A technique whose graph rasterizes the scene itself is refused by set_settings, on one
    // line naming it, and the effect keeps the settings it had.
    let before = effect.settings().technique.name();
    let refused = effect.set_settings(effect_settings(&Technique::named("sdsvao").unwrap(), &frame));
    let e = refused.expect_err("sdsvao through the engine API").to_string();
    assert!(e.contains("sdsvao") && e.contains("raster") && !e.contains('\n'), "{e}");
    assert_eq!(effect.settings().technique.name(), before);
    // An output format without an export kernel is refused before anything is recorded: the
    // command buffer stays empty (null views would otherwise be written into descriptor sets,
    // which the validation layer reports).
    effect.set_settings(effect_settings(&techniques[0].1, &frame)).unwrap();
    let cmd = engine.begin();
    let output = AoImage { view: vk::ImageView::null(), format: vk::Format::R8G8B8A8_UNORM };
    let depth = EngineImage { view: vk::ImageView::null(), layout: DEPTH_LAYOUT };
    let v = engine_view(&frame, DepthConvention::Reversed);
    let refused = effect.record(cmd, &AoFrame::new(depth, v.convention, output, v.projection, v.world_to_view));
    let e = refused.expect_err("an RGBA8 AO image").to_string();
    assert!(e.contains("R8G8B8A8_UNORM") && e.contains("R8_UNORM") && !e.contains('\n'), "{e}");
    engine.submit_and_wait(cmd);
    drop(rays);
    drop(effect); // the engine waited for every frame
    drop(images);
    eprintln!("effect_frames_agree_with_cpu_sim: {:.1} s", start.elapsed().as_secs_f64());
    let messages = engine.destroy();
    assert_validation_clean("effect_frames_agree_with_cpu_sim", messages);
    assert_eq!(report.len(), 12);
}

// ---------------------------------------------------------------------------------------------
// 1b. Every engine format and depth convention through the effect.

/// Can `format` be a sampled, optimally tiled image with `features` on the engine's device?
fn supports(engine: &Engine, format: vk::Format, features: vk::FormatFeatureFlags) -> bool {
    let props = unsafe { engine.instance.get_physical_device_format_properties(engine.physical_device, format) };
    props.optimal_tiling_features.contains(features | vk::FormatFeatureFlags::SAMPLED_IMAGE)
}

/// Each depth format (D16, D24S8's depth aspect, X8_D24, D32) in each convention (reversed,
/// standard, OpenGL-style [−1, 1] clip depth, infinite reversed), each normal format (RGBA16F,
/// A2B10G10R10, RGBA8) and each AO format (R16F, R8, R32F) through `AoEffect`, one frame each,
/// against cpu-sim on the same stored texels (what the sampler returns for them):
/// - the effect's imported linear depth over the WHOLE target, guard band included (the engine
///   image is the inner image, smaller than aokit's target: the guard band is filled by clamping
///   to the nearest edge texel), within the adapter bound 8U·(1 + κ) relative (tests/adapters.rs);
///   its normal codes ≥ 99.9 % identical;
/// - the exported AO within vao's bound (check_agreement) of cpu-sim's export stored in the same
///   format (rounded to R8's 255 steps or to half precision).
///
/// A projection read with the wrong convention gives other planes (the OpenGL matrix read as
/// [0, 1] clip depth: another near plane), which `engine_view`'s check of the planes the effect
/// derives against the frame's catches at once (the import check cannot: both imports use the
/// derived planes).
#[test]
fn every_engine_format_through_the_effect_agrees_with_cpu_sim() {
    let Some(engine) = Engine::new() else { return };
    let (scene, frame) = common::builtin_frame("sponza", 96, 64, 12);
    let view = frame.camera.view;
    let renderer = CpuRenderer::new(&scene);
    let (gbuffer, _) = renderer.gbuffer(&frame, &no_progress);
    let technique = Technique::new(&VAO, SdOptions::default());
    let cases = [
        (vk::Format::D16_UNORM, DepthConvention::Reversed, vk::Format::R16G16B16A16_SFLOAT, vk::Format::R16_SFLOAT),
        (
            vk::Format::D24_UNORM_S8_UINT,
            DepthConvention::Standard,
            vk::Format::A2B10G10R10_UNORM_PACK32,
            vk::Format::R8_UNORM,
        ),
        (
            vk::Format::X8_D24_UNORM_PACK32,
            DepthConvention::NegativeOneToOne,
            vk::Format::R8G8B8A8_UNORM,
            vk::Format::R32_SFLOAT,
        ),
        (vk::Format::D32_SFLOAT, DepthConvention::ReversedInfinite, vk::Format::R8G8B8A8_UNORM, vk::Format::R32_SFLOAT),
    ];
    let images = Gpu::from_external(engine.external()).unwrap();
    let mut effect = AoEffect::new(engine.external(), effect_settings(&technique, &frame)).unwrap();
    let inner = view.size() - 2 * view.guard;
    effect.resize(inner.x, inner.y).unwrap();
    let mut report = Vec::new();
    for (depth, convention, normals, output) in cases {
        let formats = EngineFormats { depth, convention, normals, output };
        let name = format!("vao ({depth:?} {convention:?}, {normals:?} normals, {output:?} AO)");
        let attachment = vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT;
        assert!(supports(&engine, depth, attachment), "{name}: the device cannot sample {depth:?} depth");
        assert!(supports(&engine, normals, vk::FormatFeatureFlags::empty()), "{name}: {normals:?}");
        assert!(supports(&engine, output, vk::FormatFeatureFlags::STORAGE_IMAGE), "{name}: {output:?} storage");
        let v = engine_view(&frame, convention);
        let g = EngineGBuffer { params: v.params, ..engine_gbuffer(&view, &gbuffer, formats) };
        let texels = (g.size.x * g.size.y) as usize;
        let targets = Targets::new(&engine, &images, &g);
        let readback =
            HostBuffer::new(&engine, (texel_bytes(output) * texels) as u64, vk::BufferUsageFlags::TRANSFER_DST);
        let ao_frame = effect_frame(&targets, &v, true, None);
        let cmd = engine.begin();
        record_frame(&engine, &mut effect, cmd, &targets, &ao_frame, Some(&readback)).unwrap();
        engine.submit_and_wait(cmd);
        let on_gpu = readback.read_ao(&engine, output, texels);
        let desc = FrameDesc::new(v.camera, frame.radius, frame.exponent, frame.thickness);
        let graph = technique.graph(&desc).unwrap();
        let CpuFrame { ao: on_cpu, depth: cpu_depth, normals: cpu_normals, .. } =
            cpu_reference(&renderer, &graph, &g, true);
        // The import over the whole target, guard band included.
        let ctx = effect.context();
        let gpu_depth: Vec<f32> = ctx.download(aokit_vulkan::ENGINE_DEPTH).unwrap();
        let gpu_normals: Vec<u32> = ctx.download(aokit_vulkan::ENGINE_NORMALS).unwrap();
        common::assert_same_len(&gpu_depth, &cpu_depth, &name);
        common::assert_same_len(&gpu_normals, &cpu_normals, &name);
        assert_eq!(cpu_depth.len(), view.size().element_product() as usize, "{name}: the whole target");
        let (n, far) = (v.params.near as f64, v.params.far as f64);
        let mut background = 0;
        for (i, (&got, &want)) in gpu_depth.iter().zip(&cpu_depth).enumerate() {
            let (got, want) = (got as f64, want as f64);
            if want >= v.camera.view.far as f64 {
                assert_eq!(got, want, "{name}: background pixel {i}");
                background += 1;
                continue;
            }
            let kappa = if is_standard(convention) { want * (far - n) / (n * far) } else { 0.0 };
            let rel = (got - want).abs() / want;
            assert!(rel <= 8.0 * U * (1.0 + kappa), "{name}: pixel {i} depth {got} vs cpu-sim {want}");
        }
        assert!(background < cpu_depth.len() / 2, "{name}: {background} background pixels");
        let same = gpu_normals.iter().zip(&cpu_normals).filter(|(a, b)| a == b).count();
        assert!(same as f64 >= 0.999 * cpu_normals.len() as f64, "{name}: {same}/{} normal codes", cpu_normals.len());
        // The engine's image stores cpu-sim's AO in its format too (R8: to the nearest of 255
        // steps, whose rounding alone is MSE (1/255)²/12 ≈ 1.3e-6; R16F: to the nearest half).
        let stored: Vec<f32> = match output {
            vk::Format::R8_UNORM => on_cpu.iter().map(|a| (a * 255.0).round() / 255.0).collect(),
            vk::Format::R16_SFLOAT => on_cpu.iter().map(|&a| common::f16_to_f32(common::f32_to_f16(a))).collect(),
            _ => on_cpu,
        };
        report.push(check_agreement(&name, &stored, &on_gpu));
        readback.destroy(&engine);
        targets.destroy(&images);
    }
    drop(effect);
    drop(images);
    assert_validation_clean("every_engine_format_through_the_effect_agrees_with_cpu_sim", engine.destroy());
    assert_eq!(report.len(), 4);
}

/// The final AO images of `specs` through the effect on an engine device with `ray_tracing`
/// (reversed-Z D32 depth, RGBA8 normals), each checked against cpu-sim ([`check_frame`]).
fn ray_traced_frames(ray_tracing: RayTracing, specs: &[&str], against_cpu: bool) -> Option<Vec<Vec<f32>>> {
    let engine = Engine::with(ray_tracing)?;
    let (scene, frame) = common::builtin_frame("sponza", 96, 64, 12);
    let view = frame.camera.view;
    let renderer = CpuRenderer::new(&scene);
    let (gbuffer, _) = renderer.gbuffer(&frame, &no_progress);
    let images = Gpu::from_external(engine.external()).unwrap();
    let first = Technique::parse(specs[0]).unwrap();
    let mut effect = AoEffect::new(engine.external(), effect_settings(&first, &frame)).unwrap();
    if ray_tracing == RayTracing::QueriesOnly {
        // The pipelines the device lacks are refused on one line naming what is missing.
        let pipeline = effect_settings(&first, &frame).rt_mode(RtMode::Pipeline);
        let e = effect.set_settings(pipeline).expect_err("ray-tracing pipelines on a query-only device").to_string();
        assert!(e.contains("VK_KHR_ray_tracing_pipeline") && !e.contains('\n'), "{e}");
    }
    let inner = view.size() - 2 * view.guard;
    effect.resize(inner.x, inner.y).unwrap();
    let rays = effect.build_scene(&scene.corner_tables().geometry(&scene.triangle_materials)).unwrap();
    let v = engine_view(&frame, DepthConvention::Reversed);
    let g = EngineGBuffer { params: v.params, ..engine_gbuffer(&view, &gbuffer, EngineFormats::d32(v.convention)) };
    let texels = (g.size.x * g.size.y) as usize;
    let targets = Targets::new(&engine, &images, &g);
    let readback = HostBuffer::new(&engine, 4 * texels as u64, vk::BufferUsageFlags::TRANSFER_DST);
    let ao_frame = effect_frame(&targets, &v, true, Some(&rays));
    let mut out = Vec::new();
    for spec in specs {
        let technique = Technique::parse(spec).unwrap();
        effect.set_settings(effect_settings(&technique, &frame)).unwrap();
        let cmd = engine.begin();
        record_frame(&engine, &mut effect, cmd, &targets, &ao_frame, Some(&readback)).unwrap();
        engine.submit_and_wait(cmd);
        let on_gpu = readback.read_f32(&engine, texels);
        if against_cpu {
            let desc = FrameDesc::new(v.camera, frame.radius, frame.exponent, frame.thickness);
            let graph = technique.graph(&desc).unwrap();
            let on_cpu = cpu_reference(&renderer, &graph, &g, true);
            let name = format!("{spec} on a {ray_tracing:?} engine device");
            check_frame(&name, &effect, (&graph, &desc), &on_cpu, &on_gpu);
        }
        out.push(on_gpu);
    }
    readback.destroy(&engine);
    targets.destroy(&images);
    drop(rays);
    drop(effect);
    drop(images);
    assert_validation_clean(&format!("{ray_tracing:?} engine device"), engine.destroy());
    Some(out)
}

/// Ray queries on an engine-owned device: a device made with `VK_KHR_ray_query` and no
/// ray-tracing pipeline (`ExternalDevice::ray_query`) runs raysd and ground truth through the
/// effect as compute kernels with ray queries (its default there; the pipelines are refused on
/// one line). They must agree with the same frame through the pipelines on an engine device
/// that has them like two runs of one kernel — the same any-hit decisions over the same
/// traversal (tests/ray_query.rs): ≥ 99.9 % within 1/255 — and with cpu-sim as the pipelines do
/// (`check_frame`). A kernel that traced nothing (AO 1) fails both: the frame is ≥ 2 %
/// occluded.
#[test]
fn ray_queries_on_an_engine_device_agree_with_the_pipelines_and_cpu_sim() {
    let specs = ["raysd", "groundtruth:spp=16"];
    let Some(queries) = ray_traced_frames(RayTracing::QueriesOnly, &specs, true) else { return };
    let Some(pipelines) = ray_traced_frames(RayTracing::Required, &specs, true) else { return };
    for ((spec, query), pipeline) in specs.iter().zip(&queries).zip(&pipelines) {
        common::assert_same_len(query, pipeline, spec);
        let within = common::fraction_within(query, pipeline, common::agreement::STEP);
        eprintln!("{spec}: ray queries vs pipelines on engine devices: {:.3} % within 1/255", 100.0 * within);
        assert!(
            within >= common::agreement::MIN_WITHIN,
            "{spec}: ray queries vs pipelines only {:.3} % within 1/255",
            100.0 * within
        );
    }
}

// ---------------------------------------------------------------------------------------------
// 2. The soak.

const SOAK_SCENE: &str = "sponza";

/// Inner size and frame count of each phase. Each phase alternates raysd (even frames) and gtao
/// (odd frames) from raysd on; the first two phases have an odd count, so the frame before each
/// resize is raysd as well: the same graph on both sides of the resize, which must not run on
/// descriptor sets of the previous resolution's buffers.
const PHASES: [(u32, u32, usize); 3] = [(96, 64, 99), (128, 80, 101), (96, 64, 100)];

#[test]
fn soak_300_frames_two_resolutions() {
    let Some(engine) = Engine::new() else { return };
    let start = Instant::now();
    // The engine's own images go through a Gpu of its own on the same device.
    let images = Gpu::from_external(engine.external()).unwrap();
    let techniques = [Technique::new(&RAYSD, SdOptions::default()), Technique::new(&GTAO, GtaoOptions::default())];
    let (scene, first_frame) = common::builtin_frame(SOAK_SCENE, 96, 64, 8);
    let renderer = CpuRenderer::new(&scene);
    let mut effect = AoEffect::new(engine.external(), effect_settings(&techniques[0], &first_frame)).unwrap();
    let rays = effect.build_scene(&scene.corner_tables().geometry(&scene.triangle_materials)).unwrap();
    // The effect's live allocations (count, bytes) and the descriptor pools it made so far,
    // after each frame, per phase.
    let mut allocated: Vec<Vec<(usize, u64)>> = Vec::new();
    let mut pools: Vec<Vec<u64>> = Vec::new();
    // Per phase: the AO image of its first frame (raysd, right after the resize) and of its last
    // raysd and last gtao frame.
    let mut first_images = Vec::new();
    let mut last_images: Vec<[Vec<f32>; 2]> = Vec::new();
    let mut frame_ms = Vec::new();
    for &(w, h, frames) in &PHASES {
        let (_, frame) = common::builtin_frame(SOAK_SCENE, w, h, 8);
        let (gbuffer, _) = renderer.gbuffer(&frame, &no_progress);
        let g = engine_gbuffer(&frame.camera.view, &gbuffer, EngineFormats::d32(DepthConvention::Reversed));
        let v = engine_view(&frame, DepthConvention::Reversed);
        // An engine re-creates its render targets on a resize (after waiting for its frames).
        let targets = Targets::new(&engine, &images, &g);
        effect.resize(targets.size.x, targets.size.y).unwrap();
        let ao_frame = effect_frame(&targets, &v, true, Some(&rays));
        let texels = (targets.size.x * targets.size.y) as usize;
        let host = || HostBuffer::new(&engine, 4 * texels as u64, vk::BufferUsageFlags::TRANSFER_DST);
        let (first, last) = (host(), [host(), host()]);
        let mut bytes = Vec::with_capacity(frames);
        let mut made = Vec::with_capacity(frames);
        for i in 0..frames {
            let k = i % 2; // 0: raysd, 1: gtao
            let read = match i {
                0 => Some(&first),
                i if i + 2 >= frames => Some(&last[k]),
                _ => None,
            };
            let t = Instant::now();
            effect.set_settings(effect_settings(&techniques[k], &frame)).unwrap();
            let cmd = engine.begin();
            record_frame(&engine, &mut effect, cmd, &targets, &ao_frame, read).unwrap();
            engine.submit_and_wait(cmd);
            frame_ms.push(t.elapsed().as_secs_f64() * 1e3);
            let gpu = effect.context().gpu();
            bytes.push((gpu.live_allocations(), gpu.allocated_bytes()));
            made.push(effect.context().descriptor_pools_made());
        }
        allocated.push(bytes);
        pools.push(made);
        first_images.push(first.read_f32(&engine, texels));
        last_images.push(last.each_ref().map(|b| b.read_f32(&engine, texels)));
        // Every resolution of the resize sequence against cpu-sim: the phase's last gtao frame
        // (deterministic; raysd's frames are checked against its first frame below).
        let desc = FrameDesc::new(v.camera, frame.radius, frame.exponent, frame.thickness);
        let on_cpu = cpu_reference(&renderer, &techniques[1].graph(&desc).unwrap(), &g, true);
        let gtao = &last_images[last_images.len() - 1][1];
        check_agreement(&format!("gtao, last frame at {w}×{h} after the resizes"), &on_cpu.ao, gtao);
        for b in last.into_iter().chain([first]) {
            b.destroy(&engine);
        }
        targets.destroy(&images);
    }
    let seconds = start.elapsed().as_secs_f64();
    frame_ms.sort_by(f64::total_cmp);
    eprintln!(
        "soak ({SOAK_SCENE}): {} frames in {seconds:.1} s (median frame {:.1} ms, max {:.1} ms)",
        frame_ms.len(),
        frame_ms[frame_ms.len() / 2],
        frame_ms[frame_ms.len() - 1]
    );
    for (bytes, (w, h, _)) in allocated.iter().zip(PHASES) {
        let mut runs = bytes.clone();
        runs.dedup();
        eprintln!("{w}×{h}: live allocations (count, bytes) after each frame, runs of equal values: {runs:?}");
    }

    // Live allocations. A resource replaced on a size change (or re-made because the alternating
    // graphs declared it with other lengths) is retired, not freed, and freed FRAMES_IN_FLIGHT
    // frames later; the first two frames at a resolution also make the graphs' resources (raysd's
    // in frame 0, gtao's in frame 1). So compare from frame 2·FRAMES_IN_FLIGHT of a phase on, when
    // every buffer of the previous resolution has been freed: after each such frame of the third
    // phase (the first phase's resolution) the live allocations equal those after the same frame
    // of the first phase — same graph, same size, nothing leaked over 200 frames and two resizes —
    // and within each phase they repeat with the alternation (flat).
    //
    // The count compares exactly. The bytes include the padding gpu-allocator counts as part of
    // an allocation to align it in its block (below the alignment, ≤ 256 B for aokit's storage
    // buffers), which depends on where the re-made buffers landed: between phases they agree
    // within 256 B per allocation, far below one leaked or mis-sized target buffer (≥ 4·96·64 B);
    // within a phase nothing moves, so exactly.
    let same_live = |a: (usize, u64), b: (usize, u64), what: &str| {
        assert_eq!(a.0, b.0, "{what}: live allocations {a:?} vs {b:?}");
        assert!(a.1.abs_diff(b.1) <= 256 * a.0 as u64, "{what}: allocated bytes {a:?} vs {b:?}");
    };
    let warm = 2 * FRAMES_IN_FLIGHT as usize;
    let (first_phase, last_phase) = (&allocated[0], &allocated[2]);
    for i in warm..first_phase.len().min(last_phase.len()) {
        same_live(last_phase[i], first_phase[i], &format!("after frame {i} of the third phase vs the first"));
    }
    for (p, live) in allocated.iter().enumerate() {
        for i in warm..live.len() - 2 {
            assert_eq!(live[i], live[i + 2], "phase {p}: live allocations change after frame {i}");
        }
    }
    // "After the last frame as after the first one at that resolution", in the terms above: the
    // last frame (gtao, 96×64) against the first gtao frame of the first phase after the warm-up.
    same_live(last_phase[last_phase.len() - 1], first_phase[warm + 1], "after the last frame");
    assert!(allocated[1][warm].1 > first_phase[warm].1 + 4 * 96 * 64, "the larger resolution must allocate more");
    // Descriptor sets are kept per graph and per engine images: after the first frame of each
    // graph at a resolution, alternating the two graphs makes no descriptor pool.
    for (p, made) in pools.iter().enumerate() {
        eprintln!(
            "phase {p}: descriptor pools made by the context so far, first and last frame: {} → {}",
            made[0],
            made[made.len() - 1]
        );
        assert_eq!(made[1], made[made.len() - 1], "phase {p}: descriptor pools made after the first frames");
    }

    // The AO images. Right after each resize raysd must produce what it produces at the end of
    // that phase (same inputs), and the last images of the third phase those of the first.
    // gtao is deterministic; raysd may store other SD layers where the any-hit order differs, so
    // it agrees within MSE 1e-4 (tests/vulkan_svao.rs).
    let same = |what: &str, a: &[f32], b: &[f32], exact: bool| {
        assert_eq!(a.len(), b.len(), "{what}");
        let m = mse(a, b);
        let occluded = a.iter().filter(|&&v| v < 0.9).count() as f64 / a.len() as f64;
        eprintln!("{what}: MSE {m:.2e}, occluded (< 0.9) {:.1} %", 100.0 * occluded);
        assert!(occluded >= 0.02, "{what}: the soak's images must contain occlusion");
        if exact {
            assert_eq!(a, b, "{what}");
        } else {
            assert!(m <= 1e-4, "{what}: MSE {m}");
        }
    };
    for (p, (w, h, _)) in PHASES.into_iter().enumerate() {
        same(&format!("{w}×{h} raysd: first frame vs last"), &first_images[p], &last_images[p][0], false);
    }
    same("raysd: last frame of phase 1 vs phase 3", &last_images[0][0], &last_images[2][0], false);
    same("gtao: last frame of phase 1 vs phase 3", &last_images[0][1], &last_images[2][1], true);

    drop(rays);
    drop(effect); // the engine waited for every frame
    drop(images);
    assert_validation_clean("soak_300_frames_two_resolutions", engine.destroy());
}

// ---------------------------------------------------------------------------------------------
// 3. The engine's own TLAS (`AoEffect::scene_from_tlas`).

/// A host-visible buffer of the engine's own with a device address (acceleration-structure
/// inputs, storage and scratch).
struct AddressBuffer {
    buffer: vk::Buffer,
    memory: vk::DeviceMemory,
    address: u64,
}

impl AddressBuffer {
    fn new(engine: &Engine, size: u64, usage: vk::BufferUsageFlags, data: &[u8]) -> AddressBuffer {
        let d = &engine.device;
        let usage = usage | vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS;
        let info = vk::BufferCreateInfo::default().size(size).usage(usage).sharing_mode(vk::SharingMode::EXCLUSIVE);
        let buffer = unsafe { d.create_buffer(&info, None) }.unwrap();
        let req = unsafe { d.get_buffer_memory_requirements(buffer) };
        let type_index = host_memory_type(engine, &req);
        let mut flags = vk::MemoryAllocateFlagsInfo::default().flags(vk::MemoryAllocateFlags::DEVICE_ADDRESS);
        let alloc = vk::MemoryAllocateInfo::default()
            .allocation_size(req.size)
            .memory_type_index(type_index)
            .push_next(&mut flags);
        let memory = unsafe { d.allocate_memory(&alloc, None) }.unwrap();
        unsafe { d.bind_buffer_memory(buffer, memory, 0) }.unwrap();
        if !data.is_empty() {
            unsafe {
                let ptr = d.map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty()).unwrap() as *mut u8;
                std::ptr::copy_nonoverlapping(data.as_ptr(), ptr, data.len());
                d.unmap_memory(memory);
            }
        }
        let address = unsafe { d.get_buffer_device_address(&vk::BufferDeviceAddressInfo::default().buffer(buffer)) };
        AddressBuffer { buffer, memory, address }
    }

    fn destroy(self, engine: &Engine) {
        unsafe {
            engine.device.destroy_buffer(self.buffer, None);
            engine.device.free_memory(self.memory, None);
        }
    }
}

/// One mesh of the engine: its triangles in object space, whether its geometry is opaque, its
/// instance transform (row-major 3×4) and the instance's custom index.
struct EngineMesh {
    corners: Vec<[f32; 3]>,
    opaque: bool,
    transform: [f32; 12],
    custom_index: u32,
}

/// The engine's acceleration structures: a BLAS per mesh and a TLAS with one instance each,
/// built with the engine's own ash calls in its own command buffer.
struct EngineAccel {
    loader: ash::khr::acceleration_structure::Device,
    structures: Vec<(vk::AccelerationStructureKHR, AddressBuffer)>,
    tlas: vk::AccelerationStructureKHR,
}

impl EngineAccel {
    fn build(engine: &Engine, meshes: &[EngineMesh]) -> EngineAccel {
        let loader = ash::khr::acceleration_structure::Device::new(&engine.instance, &engine.device);
        let input = vk::BufferUsageFlags::ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_KHR;
        let mut inputs = Vec::new();
        let mut structures = Vec::new();
        let cmd = engine.begin();
        // Build one structure from one geometry into `cmd`; the scratch stays until the wait.
        let build = |ty, geometry: vk::AccelerationStructureGeometryKHR, count: u32, inputs: &mut Vec<_>| {
            let geometries = [geometry];
            let mut info = vk::AccelerationStructureBuildGeometryInfoKHR::default()
                .ty(ty)
                .flags(vk::BuildAccelerationStructureFlagsKHR::PREFER_FAST_TRACE)
                .mode(vk::BuildAccelerationStructureModeKHR::BUILD)
                .geometries(&geometries);
            let mut sizes = vk::AccelerationStructureBuildSizesInfoKHR::default();
            unsafe {
                loader.get_acceleration_structure_build_sizes(
                    vk::AccelerationStructureBuildTypeKHR::DEVICE,
                    &info,
                    &[count],
                    &mut sizes,
                )
            };
            let storage = AddressBuffer::new(
                engine,
                sizes.acceleration_structure_size,
                vk::BufferUsageFlags::ACCELERATION_STRUCTURE_STORAGE_KHR,
                &[],
            );
            let create = vk::AccelerationStructureCreateInfoKHR::default()
                .buffer(storage.buffer)
                .size(sizes.acceleration_structure_size)
                .ty(ty);
            let handle = unsafe { loader.create_acceleration_structure(&create, None) }.unwrap();
            // Scratch aligned generously (lavapipe asks for little; 256 covers common GPUs).
            let scratch =
                AddressBuffer::new(engine, sizes.build_scratch_size + 256, vk::BufferUsageFlags::STORAGE_BUFFER, &[]);
            info = info
                .dst_acceleration_structure(handle)
                .scratch_data(vk::DeviceOrHostAddressKHR { device_address: scratch.address.next_multiple_of(256) });
            let range = [vk::AccelerationStructureBuildRangeInfoKHR::default().primitive_count(count)];
            unsafe { loader.cmd_build_acceleration_structures(cmd, &[info], &[&range[..]]) };
            let barrier = vk::MemoryBarrier::default()
                .src_access_mask(A::ACCELERATION_STRUCTURE_WRITE_KHR)
                .dst_access_mask(A::ACCELERATION_STRUCTURE_READ_KHR);
            let stage = S::ACCELERATION_STRUCTURE_BUILD_KHR;
            unsafe {
                engine.device.cmd_pipeline_barrier(
                    cmd,
                    stage,
                    stage | S::RAY_TRACING_SHADER_KHR,
                    vk::DependencyFlags::empty(),
                    &[barrier],
                    &[],
                    &[],
                )
            };
            inputs.push(scratch);
            (handle, storage)
        };
        let mut instances = Vec::new();
        for mesh in meshes {
            let vertices =
                AddressBuffer::new(engine, 12 * mesh.corners.len() as u64, input, bytemuck::cast_slice(&mesh.corners));
            let triangles = vk::AccelerationStructureGeometryTrianglesDataKHR::default()
                .vertex_format(vk::Format::R32G32B32_SFLOAT)
                .vertex_data(vk::DeviceOrHostAddressConstKHR { device_address: vertices.address })
                .vertex_stride(12)
                .max_vertex(mesh.corners.len() as u32 - 1)
                .index_type(vk::IndexType::NONE_KHR);
            let flags = if mesh.opaque { vk::GeometryFlagsKHR::OPAQUE } else { vk::GeometryFlagsKHR::empty() };
            let geometry = vk::AccelerationStructureGeometryKHR::default()
                .geometry_type(vk::GeometryTypeKHR::TRIANGLES)
                .geometry(vk::AccelerationStructureGeometryDataKHR { triangles })
                .flags(flags);
            let count = mesh.corners.len() as u32 / 3;
            let blas = build(vk::AccelerationStructureTypeKHR::BOTTOM_LEVEL, geometry, count, &mut inputs);
            inputs.push(vertices);
            let address = unsafe {
                loader.get_acceleration_structure_device_address(
                    &vk::AccelerationStructureDeviceAddressInfoKHR::default().acceleration_structure(blas.0),
                )
            };
            instances.push(vk::AccelerationStructureInstanceKHR {
                transform: vk::TransformMatrixKHR { matrix: mesh.transform },
                instance_custom_index_and_mask: vk::Packed24_8::new(mesh.custom_index, 0xff),
                instance_shader_binding_table_record_offset_and_flags: vk::Packed24_8::new(0, 0),
                acceleration_structure_reference: vk::AccelerationStructureReferenceKHR { device_handle: address },
            });
            structures.push(blas);
        }
        let bytes = unsafe {
            std::slice::from_raw_parts(
                instances.as_ptr() as *const u8,
                instances.len() * size_of::<vk::AccelerationStructureInstanceKHR>(),
            )
        };
        let instance_buffer = AddressBuffer::new(engine, bytes.len() as u64, input, bytes);
        let data = vk::AccelerationStructureGeometryInstancesDataKHR::default()
            .data(vk::DeviceOrHostAddressConstKHR { device_address: instance_buffer.address });
        let geometry = vk::AccelerationStructureGeometryKHR::default()
            .geometry_type(vk::GeometryTypeKHR::INSTANCES)
            .geometry(vk::AccelerationStructureGeometryDataKHR { instances: data });
        let tlas = build(vk::AccelerationStructureTypeKHR::TOP_LEVEL, geometry, meshes.len() as u32, &mut inputs);
        inputs.push(instance_buffer);
        engine.submit_and_wait(cmd);
        inputs.into_iter().for_each(|b| b.destroy(engine));
        let handle = tlas.0;
        structures.push(tlas);
        EngineAccel { loader, structures, tlas: handle }
    }

    fn destroy(self, engine: &Engine) {
        for (handle, storage) in self.structures.into_iter().rev() {
            unsafe { self.loader.destroy_acceleration_structure(handle, None) };
            storage.destroy(engine);
        }
    }
}

/// A floor and a back wall (opaque, triangles 0–3) and, in front of the wall, three upright
/// quads whose alpha mask cuts out vertical stripes (triangles 4–9), seen from the front.
fn fence_scene() -> (Scene, Frame) {
    use aokit::frame::{CameraChoice, FrameRequest};
    use aokit::scene::procedural::push_quad;
    use aokit::scene::{AlphaMask, Material};
    use aokit_shaders::glam::{Vec2, vec2, vec3};
    let mut s = Scene::default();
    push_quad(&mut s, vec3(-4.0, 0.0, 2.0), vec3(4.0, 0.0, 2.0), vec3(4.0, 0.0, -2.0), vec3(-4.0, 0.0, -2.0));
    push_quad(&mut s, vec3(-4.0, 0.0, -2.0), vec3(4.0, 0.0, -2.0), vec3(4.0, 3.0, -2.0), vec3(-4.0, 3.0, -2.0));
    s.triangle_uvs = vec![[Vec2::ZERO; 3]; 4];
    s.triangle_materials = vec![0; 4];
    for (i, x) in [-1.6f32, -0.4, 0.8].into_iter().enumerate() {
        let z = -1.7 + 0.1 * i as f32;
        let (a, b, c, d) = (vec3(x, 0.0, z), vec3(x + 1.0, 0.0, z), vec3(x + 1.0, 1.2, z), vec3(x, 1.2, z));
        push_quad(&mut s, a, b, c, d);
        let uv = |p: Vec3| vec2(p.x - x, 1.0 - p.y / 1.2);
        let n = s.triangles.len();
        s.triangle_uvs.extend([s.triangles[n - 2].map(uv), s.triangles[n - 1].map(uv)]);
        s.triangle_materials.extend([1, 1]);
    }
    // Alpha 0.1 (cut out) on two of every four texel columns.
    let alpha = (0..64).map(|i| if (i % 8) % 4 < 2 { 0.1 } else { 0.9 }).collect();
    s.materials = vec![
        Material { name: "wall".into(), alpha_mask: None },
        Material { name: "fence".into(), alpha_mask: Some(AlphaMask { width: 8, height: 8, alpha, cutoff: 0.5 }) },
    ];
    let scene = s.validated(std::path::Path::new("fence")).unwrap();
    let eye = vec3(0.3, 1.4, 3.0);
    let req = FrameRequest {
        width: 128,
        height: 80,
        guard: 8,
        camera: CameraChoice::Explicit { eye, target: vec3(0.0, 0.6, -1.8), up: Vec3::Y, fov_deg: 50.0 },
        radius: Some(0.6),
        exponent: 2.0,
        thickness: 0.0,
    };
    let frame = Frame::resolve(&scene, None, &req).unwrap();
    (scene, frame)
}

/// The engine's meshes of the fence scene: floor + wall as one opaque mesh (custom index 0), the
/// fence as a second, alpha-tested mesh stored 5 units below its place and lifted by its
/// instance transform; its custom index is the fence's first triangle (4), or `fence_index`.
fn fence_meshes(scene: &Scene, fence_index: u32) -> Vec<EngineMesh> {
    let corners = |tris: &[[Vec3; 3]], dy: f32| -> Vec<[f32; 3]> {
        tris.iter().flatten().map(|v| [v.x, v.y + dy, v.z]).collect()
    };
    let identity = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0];
    let lift = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 5.0, 0.0, 0.0, 1.0, 0.0];
    vec![
        EngineMesh { corners: corners(&scene.triangles[..4], 0.0), opaque: true, transform: identity, custom_index: 0 },
        EngineMesh {
            corners: corners(&scene.triangles[4..], -5.0),
            opaque: false,
            transform: lift,
            custom_index: fence_index,
        },
    ]
}

#[test]
fn the_engines_own_tlas_with_instances_and_custom_indices() {
    let Some(engine) = Engine::new() else { return };
    let (scene, frame) = fence_scene();
    let view = frame.camera.view;
    let renderer = CpuRenderer::new(&scene);
    let (gbuffer, _) = renderer.gbuffer(&frame, &no_progress);
    let v = engine_view(&frame, DepthConvention::Reversed);
    let g = EngineGBuffer {
        params: v.params,
        ..engine_gbuffer(&view, &gbuffer, EngineFormats::d32(DepthConvention::Reversed))
    };
    let texels = (g.size.x * g.size.y) as usize;
    let images = Gpu::from_external(engine.external()).unwrap();
    let targets = Targets::new(&engine, &images, &g);
    let readback = HostBuffer::new(&engine, 4 * texels as u64, vk::BufferUsageFlags::TRANSFER_DST);
    let tables = scene.corner_tables();
    let geometry = tables.geometry(&scene.triangle_materials);
    let techniques = [
        ("groundtruth", Technique::parse("groundtruth:spp=32").unwrap()),
        ("raysd", Technique::new(&RAYSD, SdOptions::default())),
    ];
    let desc = FrameDesc::new(v.camera, frame.radius, frame.exponent, frame.thickness);
    let mut effect = AoEffect::new(engine.external(), effect_settings(&techniques[0].1, &frame)).unwrap();
    effect.resize(targets.size.x, targets.size.y).unwrap();
    // Run every graph on the engine's TLAS built with the fence's custom index `fence_index`;
    // returns the MSE against cpu-sim per graph (the agreement is asserted for the right index).
    let mut run = |fence_index: u32| -> Vec<f64> {
        let accel = EngineAccel::build(&engine, &fence_meshes(&scene, fence_index));
        let engine_scene = effect.scene_from_tlas(accel.tlas, &geometry).unwrap();
        let ao_frame = effect_frame(&targets, &v, true, Some(&engine_scene));
        let mut mses = Vec::new();
        for (name, technique) in &techniques {
            effect.set_settings(effect_settings(technique, &frame)).unwrap();
            let cmd = engine.begin();
            record_frame(&engine, &mut effect, cmd, &targets, &ao_frame, Some(&readback)).unwrap();
            engine.submit_and_wait(cmd);
            let on_gpu = readback.read_f32(&engine, texels);
            let graph = technique.graph(&desc).unwrap();
            let on_cpu = cpu_reference(&renderer, &graph, &g, true);
            let label = format!("{name} on the engine's TLAS (fence custom index {fence_index})");
            if fence_index == 4 {
                check_frame(&label, &effect, (&graph, &desc), &on_cpu, &on_gpu);
            }
            let m = mse(&on_cpu.ao, &on_gpu);
            eprintln!("{label}: MSE vs cpu-sim {m:.2e}");
            mses.push(m);
        }
        drop(engine_scene); // aokit's tables only: the TLAS stays the engine's
        accel.destroy(&engine);
        mses
    };
    let right = run(4);
    // The convention matters (the test can fail): with custom index 0 the fence's triangles read
    // the wall's (opaque) table entries, so its cut-out stripes occlude the ground truth's rays.
    // (Here Ray-SD refines no sample whose SD texel sees the stripes: its image is unchanged.)
    let wrong = run(0);
    assert!(wrong[0] > 10.0 * right[0].max(1e-6), "custom index 0 gives the ground truth MSE {:.2e}", wrong[0]);
    readback.destroy(&engine);
    targets.destroy(&images);
    drop(effect);
    drop(images);
    assert_validation_clean("the_engines_own_tlas_with_instances_and_custom_indices", engine.destroy());
}
