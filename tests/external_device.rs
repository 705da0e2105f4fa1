//! `Gpu::from_external`: aokit on a device the application created with plain ash, as a game
//! engine would — under the application's own validation messenger, which must stay silent
//! through aokit's work, aokit's drop and the application's own destruction of the device and
//! the instance (a double destroy or a leaked aokit object would be reported there).

use aokit::output::crop_inner;
use aokit_cpu::no_progress;
use aokit_shaders::blur::BlurParams;
use aokit_shaders::common::camera::Camera;
use aokit_shaders::common::normal_codec::encode_normal;
use aokit_shaders::glam::{Vec3, uvec2};
use aokit_shaders::graph::FrameDesc;
use aokit_shaders::vao::VaoParams;
use aokit_vulkan::{AoContext, ExternalDevice, Gpu, GpuError, GpuInputs};
use ash::{ext, khr, vk};
use std::ffi::{CStr, c_void};
use std::sync::Mutex;

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";

/// The application's debug-messenger callback: warnings and errors into its `Mutex<Vec>`.
unsafe extern "system" fn collect(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    if !data.is_null() && !user.is_null() {
        // SAFETY: `user` is the engine's boxed Mutex, alive until after the instance is destroyed.
        let (data, messages) = unsafe { (&*data, &*(user as *const Mutex<Vec<String>>)) };
        let text = unsafe { data.message_as_c_str() }.map(|m| m.to_string_lossy().into_owned()).unwrap_or_default();
        messages.lock().unwrap().push(format!("{severity:?}: {text}"));
    }
    vk::FALSE
}

/// What the application ("engine") owns: instance, messenger, device.
struct Engine {
    entry: ash::Entry,
    instance: ash::Instance,
    debug: ext::debug_utils::Instance,
    messenger: vk::DebugUtilsMessengerEXT,
    /// Boxed: the messenger holds a pointer to it.
    messages: Box<Mutex<Vec<String>>>,
    physical_device: vk::PhysicalDevice,
    device: ash::Device,
    family: u32,
    queue: vk::Queue,
    /// The device was created with the ray-tracing extensions and features.
    ray_tracing: bool,
}

impl Engine {
    /// An engine's instance (validation layer + messenger) and device on lavapipe (or the first
    /// Vulkan 1.3 device when there is no lavapipe). `full`: everything aokit can use (raster
    /// features, ray tracing where supported); otherwise only what the compute passes need.
    /// `None` when AOKIT_SKIP_VULKAN=1.
    fn new(full: bool) -> Option<Engine> {
        if std::env::var_os("AOKIT_SKIP_VULKAN").is_some_and(|v| v == "1") {
            eprintln!("AOKIT_SKIP_VULKAN=1: skipping a Vulkan test");
            return None;
        }
        let skip_hint = "set AOKIT_SKIP_VULKAN=1 to skip";
        let entry = unsafe { ash::Entry::load() }.unwrap_or_else(|e| panic!("no Vulkan loader ({e}); {skip_hint}"));
        let layers = unsafe { entry.enumerate_instance_layer_properties() }.unwrap();
        assert!(
            layers.iter().any(|l| l.layer_name_as_c_str() == Ok(VALIDATION_LAYER)),
            "this test needs {VALIDATION_LAYER:?}; {skip_hint}"
        );
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
            .pfn_user_callback(Some(collect))
            .user_data(&*messages as *const Mutex<Vec<String>> as *mut c_void);
        let app = vk::ApplicationInfo::default().application_name(c"some engine").api_version(vk::API_VERSION_1_3);
        let layer_names = [VALIDATION_LAYER.as_ptr()];
        let extension_names = [ext::debug_utils::NAME.as_ptr()];
        let create = vk::InstanceCreateInfo::default()
            .application_info(&app)
            .enabled_layer_names(&layer_names)
            .enabled_extension_names(&extension_names)
            .push_next(&mut messenger_info); // covers vkCreateInstance and vkDestroyInstance
        let instance = unsafe { entry.create_instance(&create, None) }.unwrap();
        let debug = ext::debug_utils::Instance::new(&entry, &instance);
        let messenger = unsafe { debug.create_debug_utils_messenger(&messenger_info, None) }.unwrap();

        let devices = unsafe { instance.enumerate_physical_devices() }.unwrap();
        let props = |pd| unsafe { instance.get_physical_device_properties(pd) };
        let name = |pd| props(pd).device_name_as_c_str().unwrap().to_string_lossy().into_owned();
        let physical_device = devices
            .iter()
            .copied()
            .find(|&pd| name(pd).contains("llvmpipe"))
            .or_else(|| devices.iter().copied().find(|&pd| props(pd).api_version >= vk::API_VERSION_1_3))
            .unwrap_or_else(|| panic!("no Vulkan 1.3 device; {skip_hint}"));
        let families = unsafe { instance.get_physical_device_queue_family_properties(physical_device) };
        let family = families
            .iter()
            .position(|q| {
                q.queue_flags.contains(vk::QueueFlags::GRAPHICS | vk::QueueFlags::COMPUTE) && q.timestamp_valid_bits > 0
            })
            .expect("a graphics+compute queue family with timestamps") as u32;

        // What the physical device supports, to enable what aokit can use.
        let available = unsafe { instance.enumerate_device_extension_properties(physical_device) }.unwrap();
        let rt_names = [
            khr::acceleration_structure::NAME.as_ptr(),
            khr::ray_tracing_pipeline::NAME.as_ptr(),
            khr::deferred_host_operations::NAME.as_ptr(),
        ];
        let has_extensions = rt_names.iter().all(|&n| {
            let n = unsafe { CStr::from_ptr(n) };
            available.iter().any(|e| e.extension_name_as_c_str() == Ok(n))
        });
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
        let core_supported = query.features;
        let ray_tracing = full
            && has_extensions
            && as_query.acceleration_structure != 0
            && rt_query.ray_tracing_pipeline != 0
            && f12_query.buffer_device_address != 0;
        let maintenance4 = full && f13_query.maintenance4 != 0;
        eprintln!("engine device: {} (ray tracing enabled: {ray_tracing})", name(physical_device));

        let priorities = [1.0];
        let queues = [vk::DeviceQueueCreateInfo::default().queue_family_index(family).queue_priorities(&priorities)];
        let mut f12 = vk::PhysicalDeviceVulkan12Features::default()
            .vulkan_memory_model(true)
            .vulkan_memory_model_device_scope(true)
            .buffer_device_address(ray_tracing);
        let mut f13 = vk::PhysicalDeviceVulkan13Features::default().dynamic_rendering(full).maintenance4(maintenance4);
        let core = vk::PhysicalDeviceFeatures::default()
            .fragment_stores_and_atomics(full && core_supported.fragment_stores_and_atomics != 0);
        let mut as_enable = vk::PhysicalDeviceAccelerationStructureFeaturesKHR::default().acceleration_structure(true);
        let mut rt_enable = vk::PhysicalDeviceRayTracingPipelineFeaturesKHR::default().ray_tracing_pipeline(true);
        let mut create = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .enabled_features(&core)
            .push_next(&mut f12)
            .push_next(&mut f13);
        if ray_tracing {
            create = create.enabled_extension_names(&rt_names).push_next(&mut as_enable).push_next(&mut rt_enable);
        }
        let device = unsafe { instance.create_device(physical_device, &create, None) }.unwrap();
        let queue = unsafe { device.get_device_queue(family, 0) };
        Some(Engine {
            entry,
            instance,
            debug,
            messenger,
            messages,
            physical_device,
            device,
            family,
            queue,
            ray_tracing,
        })
    }

    /// The handles aokit gets.
    fn external(&self) -> ExternalDevice {
        ExternalDevice {
            entry: self.entry.clone(),
            instance: self.instance.clone(),
            physical_device: self.physical_device,
            device: self.device.clone(),
            queue_family_index: self.family,
            queue: self.queue,
            ray_tracing: self.ray_tracing,
        }
    }

    /// Prove the device is still alive and ours, destroy it, the messenger and the instance,
    /// and return everything the validation layer said.
    fn destroy(self) -> Vec<String> {
        unsafe {
            self.device.device_wait_idle().expect("the engine's device survives aokit");
            let fence = self.device.create_fence(&vk::FenceCreateInfo::default(), None).unwrap();
            self.device.destroy_fence(fence, None);
            self.device.destroy_device(None);
            self.debug.destroy_debug_utils_messenger(self.messenger, None);
            self.instance.destroy_instance(None);
        }
        self.messages.into_inner().unwrap()
    }
}

/// A synthetic G-buffer: a fronto-parallel wall at depth 10 with a raised block at depth 9,
/// both facing the camera, the frame for it and the VAO/blur parameters.
fn step_gbuffer() -> (FrameDesc, VaoParams, BlurParams, Vec<f32>, Vec<u32>) {
    let (inner, guard) = (uvec2(48, 40), 8);
    let camera = Camera::look_at(Vec3::ZERO, -Vec3::Z, Vec3::Y, 60f32.to_radians(), inner, guard, 0.01, 100.0);
    let view = camera.view;
    let size = view.size();
    let mut depth = vec![10.0f32; (size.x * size.y) as usize];
    for y in 20..36 {
        for x in 24..40 {
            depth[(y * size.x + x) as usize] = 9.0;
        }
    }
    let normals = vec![encode_normal(Vec3::Z); depth.len()];
    let frame = FrameDesc { camera, radius: 2.0, exponent: 2.0, thickness: 0.0 };
    let vao = VaoParams { view, radius: 2.0, exponent: 2.0, thickness: 0.0, max_screen_radius: 512.0 };
    let blur = BlurParams { view, direction: uvec2(1, 0), sharpness: 16.0, _pad: 0 };
    (frame, vao, blur, depth, normals)
}

/// Upload/download roundtrip with `allocated_bytes` accounting, then VAO + blur (the vao pass
/// graph through an `AoContext` on the external device) twice on the synthetic G-buffer against
/// cpu-sim, with allocated bytes flat across the two frames and back to the start once the
/// context is dropped.
fn exercise(gpu: &Gpu) -> Result<(), GpuError> {
    let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
    let base = gpu.allocated_bytes();
    let data: Vec<f32> = (0..4096).map(|i| i as f32 * 0.5).collect();
    let buffer = gpu.upload(&data, storage)?;
    let with_buffer = gpu.allocated_bytes();
    assert!(with_buffer >= base + 4 * 4096, "allocated {base} → {with_buffer} after a 16 KiB upload");
    assert_eq!(gpu.download::<f32>(&buffer)?, data);
    gpu.free_buffer(buffer);
    assert_eq!(gpu.allocated_bytes(), base, "free_buffer returns the bytes");

    let (frame, vao, blur, depth, normals) = step_gbuffer();
    let cpu_ao = aokit_cpu::run_vao(&vao, &depth, &normals, &no_progress);
    let cpu_blurred = aokit_cpu::run_blur(&blur, &cpu_ao, &depth);
    let graph = aokit_shaders::vao::settings::graph(&frame);
    let mut ctx = AoContext::new(gpu);
    let mut after_frames = Vec::new();
    for _frame in 0..2 {
        let depth_buffer = gpu.upload(&depth, storage)?;
        let normal_buffer = gpu.upload(&normals, storage)?;
        let inputs =
            GpuInputs { depth: &depth_buffer, normals: &normal_buffer, second_depth: None, scene: None, raster: None };
        let ran = ctx.run(&graph, &inputs);
        let out = ran.and_then(|_| Ok((ctx.download::<f32>(graph.raw_output)?, ctx.download::<f32>(graph.output)?)));
        // The inputs go; a later buffer may reuse their handles.
        ctx.invalidate_bindings();
        gpu.free_buffer(depth_buffer);
        gpu.free_buffer(normal_buffer);
        let (ao, ao_blurred) = out?;
        for (name, cpu, on_gpu) in [("vao", &cpu_ao, &ao), ("vao+blur", &cpu_blurred, &ao_blurred)] {
            let (cpu, on_gpu) = (crop_inner(&vao.view, cpu), crop_inner(&vao.view, on_gpu));
            let occluded = cpu.iter().filter(|&&a| a < 0.9).count();
            assert!(occluded >= 20, "{name}: only {occluded} occluded pixels: the input does not test much");
            let max = cpu.iter().zip(&on_gpu).map(|(a, b)| (a - b).abs()).fold(0.0, f32::max);
            let within = cpu.iter().zip(&on_gpu).filter(|(a, b)| (*a - *b).abs() <= 1.0 / 255.0).count();
            assert!(max <= 4.0 / 255.0, "{name}: max |cpu − gpu| = {max}");
            assert!(within * 1000 >= cpu.len() * 999, "{name}: only {within}/{} within 1/255", cpu.len());
        }
        after_frames.push(gpu.allocated_bytes());
    }
    assert_eq!(after_frames[0], after_frames[1], "allocated bytes flat across frames");
    assert!(after_frames[0] > base, "the context keeps its resources between frames");
    drop(ctx);
    assert_eq!(gpu.allocated_bytes(), base, "the context frees everything it allocated");
    Ok(())
}

fn run_on(engine: &Engine) {
    let gpu = Gpu::from_external(engine.external()).unwrap();
    assert_eq!(gpu.device().handle(), engine.device.handle());
    assert_eq!(gpu.queue_family_index(), engine.family);
    assert_eq!(gpu.has_ray_tracing(), engine.ray_tracing);
    exercise(&gpu).unwrap();
    assert!(gpu.validation_messages().is_empty(), "no messenger of aokit's on an external instance");
    drop(gpu); // must destroy only its pool and allocator
}

#[test]
fn engine_device_with_everything_runs_aokit_and_outlives_it() {
    let Some(engine) = Engine::new(true) else { return };
    run_on(&engine);
    // A second Gpu on the same device after the first was dropped.
    run_on(&engine);
    let messages = engine.destroy();
    assert!(messages.is_empty(), "validation layer reported:\n{}", messages.join("\n"));
}

#[test]
fn compute_only_engine_device_runs_a_compute_graph() {
    let Some(engine) = Engine::new(false) else { return };
    assert!(!engine.ray_tracing);
    run_on(&engine);
    // A queue family that does not exist is the caller's mistake, reported as such.
    let wrong = ExternalDevice { queue_family_index: 99, ..engine.external() };
    assert!(matches!(Gpu::from_external(wrong), Err(GpuError::Input(_))));
    let messages = engine.destroy();
    assert!(messages.is_empty(), "validation layer reported:\n{}", messages.join("\n"));
}
