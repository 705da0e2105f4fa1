//! The application ("engine") side of the tests that run aokit on a device it did not create
//! (tests/external_device.rs, tests/engine_context.rs): an instance with the Khronos validation
//! layer and the engine's own debug messenger, and a device with one queue, all plain ash, as a
//! game engine would make them.
#![allow(dead_code)]

use super::skip;
use aokit_vulkan::ExternalDevice;
use ash::{ext, khr, vk};
use std::ffi::{CStr, c_void};
use std::sync::Mutex;

pub const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";

/// The engine's debug-messenger callback: warnings and errors into its `Mutex<Vec>`.
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

/// Ray tracing on the engine's device.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum RayTracing {
    /// Not enabled.
    Off,
    /// Enabled where the device has the extensions and the features.
    WhereSupported,
    /// The device must have the extensions (asserted); always enabled.
    Required,
    /// Ray queries (`VK_KHR_ray_query`) and acceleration structures only, no ray-tracing
    /// pipeline: the device must have them.
    QueriesOnly,
}

/// What the engine makes its instance and device with.
pub struct EngineNeeds {
    /// The application name the instance is created with.
    pub app_name: &'static CStr,
    /// What the queue family must support (besides timestamps).
    pub queue_flags: vk::QueueFlags,
    /// The raster features aokit can use: dynamic rendering, and maintenance4 and fragment stores
    /// and atomics where supported. Without them only what the compute passes need (the Vulkan
    /// memory model).
    pub raster: bool,
    pub ray_tracing: RayTracing,
}

/// What the application ("engine") owns: instance, messenger, device, queue.
pub struct EngineDevice {
    pub entry: ash::Entry,
    pub instance: ash::Instance,
    pub debug: ext::debug_utils::Instance,
    pub messenger: vk::DebugUtilsMessengerEXT,
    /// Boxed: the messenger holds a pointer to it.
    pub messages: Box<Mutex<Vec<String>>>,
    pub physical_device: vk::PhysicalDevice,
    pub device: ash::Device,
    pub family: u32,
    pub queue: vk::Queue,
    /// The device was created with the ray-tracing pipeline extensions and features.
    pub ray_tracing: bool,
    /// The device was created with `VK_KHR_ray_query` and `rayQuery` (and no pipeline).
    pub ray_query: bool,
}

impl EngineDevice {
    /// The engine's instance (validation layer + messenger for warnings and errors) and device
    /// on lavapipe (or the first Vulkan 1.3 device when there is no lavapipe) with `needs`.
    /// `None` when there is no such device and the run allows the skip ([`skip::cannot_run`]).
    pub fn new(needs: &EngineNeeds) -> Option<EngineDevice> {
        let cannot_run = |reason: String| {
            skip::cannot_run(skip::VULKAN, &reason);
            None
        };
        let entry = match unsafe { ash::Entry::load() } {
            Ok(entry) => entry,
            Err(e) => return cannot_run(format!("no Vulkan loader ({e}; apt-get install libvulkan1)")),
        };
        let layers = unsafe { entry.enumerate_instance_layer_properties() }.unwrap_or_default();
        if !layers.iter().any(|l| l.layer_name_as_c_str() == Ok(VALIDATION_LAYER)) {
            return cannot_run(format!("no {VALIDATION_LAYER:?} (apt-get install vulkan-validationlayers)"));
        }
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
        let app = vk::ApplicationInfo::default().application_name(needs.app_name).api_version(vk::API_VERSION_1_3);
        let layer_names = [VALIDATION_LAYER.as_ptr()];
        let extension_names = [ext::debug_utils::NAME.as_ptr()];
        let enables = [vk::ValidationFeatureEnableEXT::SYNCHRONIZATION_VALIDATION];
        let mut features = vk::ValidationFeaturesEXT::default().enabled_validation_features(&enables);
        let mut create = vk::InstanceCreateInfo::default()
            .application_info(&app)
            .enabled_layer_names(&layer_names)
            .enabled_extension_names(&extension_names)
            .push_next(&mut messenger_info); // covers vkCreateInstance and vkDestroyInstance
        // Synchronisation validation as well as the core checks, always: on lavapipe a missing
        // barrier rarely changes a result, so the layer's hazard tracking is what checks them.
        create = create.push_next(&mut features);
        let instance = match unsafe { entry.create_instance(&create, None) } {
            Ok(instance) => instance,
            Err(e) => return cannot_run(format!("vkCreateInstance: {e} (apt-get install mesa-vulkan-drivers)")),
        };
        let debug = ext::debug_utils::Instance::new(&entry, &instance);
        let messenger = unsafe { debug.create_debug_utils_messenger(&messenger_info, None) }.unwrap();

        let devices = unsafe { instance.enumerate_physical_devices() }.unwrap_or_default();
        let props = |pd| unsafe { instance.get_physical_device_properties(pd) };
        let name = |pd| props(pd).device_name_as_c_str().unwrap().to_string_lossy().into_owned();
        let physical_device = devices
            .iter()
            .copied()
            .find(|&pd| name(pd).contains("llvmpipe"))
            .or_else(|| devices.iter().copied().find(|&pd| props(pd).api_version >= vk::API_VERSION_1_3));
        let Some(physical_device) = physical_device else {
            return cannot_run("no Vulkan 1.3 device (apt-get install mesa-vulkan-drivers)".into());
        };
        let families = unsafe { instance.get_physical_device_queue_family_properties(physical_device) };
        let family = families
            .iter()
            .position(|q| q.queue_flags.contains(needs.queue_flags) && q.timestamp_valid_bits > 0)
            .unwrap_or_else(|| {
                let kind =
                    if needs.queue_flags.contains(vk::QueueFlags::GRAPHICS) { "graphics+compute" } else { "compute" };
                panic!("a {kind} queue family with timestamps")
            }) as u32;

        // What the physical device supports, to enable what aokit can use.
        let available = unsafe { instance.enumerate_device_extension_properties(physical_device) }.unwrap();
        let rt_names = [
            khr::acceleration_structure::NAME.as_ptr(),
            khr::ray_tracing_pipeline::NAME.as_ptr(),
            khr::deferred_host_operations::NAME.as_ptr(),
        ];
        let missing: Vec<_> = rt_names
            .iter()
            .map(|&n| unsafe { CStr::from_ptr(n) })
            .filter(|n| !available.iter().any(|e| e.extension_name_as_c_str() == Ok(*n)))
            .collect();
        if needs.ray_tracing == RayTracing::Required && !missing.is_empty() {
            return cannot_run(format!("device '{}' lacks {missing:?}", name(physical_device)));
        }
        let query_names = [
            khr::acceleration_structure::NAME.as_ptr(),
            khr::ray_query::NAME.as_ptr(),
            khr::deferred_host_operations::NAME.as_ptr(),
        ];
        let ray_query = needs.ray_tracing == RayTracing::QueriesOnly;
        let lacks = |n: &CStr| !available.iter().any(|e| e.extension_name_as_c_str() == Ok(n));
        if ray_query && query_names.iter().any(|&n| lacks(unsafe { CStr::from_ptr(n) })) {
            return cannot_run(format!("device '{}' lacks VK_KHR_ray_query", name(physical_device)));
        }
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
        let ray_tracing = match needs.ray_tracing {
            RayTracing::Off => false,
            RayTracing::WhereSupported => {
                missing.is_empty()
                    && as_query.acceleration_structure != 0
                    && rt_query.ray_tracing_pipeline != 0
                    && f12_query.buffer_device_address != 0
            }
            RayTracing::Required => true,
            RayTracing::QueriesOnly => false,
        };
        let raster = needs.raster;
        let maintenance4 = raster && f13_query.maintenance4 != 0;
        eprintln!(
            "engine device: {} (ray-tracing pipeline enabled: {ray_tracing}, ray queries only: {ray_query})",
            name(physical_device)
        );

        let priorities = [1.0];
        let queues = [vk::DeviceQueueCreateInfo::default().queue_family_index(family).queue_priorities(&priorities)];
        let mut f12 = vk::PhysicalDeviceVulkan12Features::default()
            .vulkan_memory_model(true)
            .vulkan_memory_model_device_scope(true)
            .buffer_device_address(ray_tracing || ray_query);
        let mut f13 =
            vk::PhysicalDeviceVulkan13Features::default().dynamic_rendering(raster).maintenance4(maintenance4);
        let core = vk::PhysicalDeviceFeatures::default()
            .fragment_stores_and_atomics(raster && core_supported.fragment_stores_and_atomics != 0);
        let mut as_enable = vk::PhysicalDeviceAccelerationStructureFeaturesKHR::default().acceleration_structure(true);
        let mut rt_enable = vk::PhysicalDeviceRayTracingPipelineFeaturesKHR::default().ray_tracing_pipeline(true);
        let mut rq_enable = vk::PhysicalDeviceRayQueryFeaturesKHR::default().ray_query(true);
        let mut create = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .enabled_features(&core)
            .push_next(&mut f12)
            .push_next(&mut f13);
        if ray_tracing {
            create = create.enabled_extension_names(&rt_names).push_next(&mut as_enable).push_next(&mut rt_enable);
        } else if ray_query {
            create = create.enabled_extension_names(&query_names).push_next(&mut as_enable).push_next(&mut rq_enable);
        }
        let device = unsafe { instance.create_device(physical_device, &create, None) }.unwrap();
        let queue = unsafe { device.get_device_queue(family, 0) };
        Some(EngineDevice {
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
            ray_query,
        })
    }

    /// The handles aokit gets.
    pub fn external(&self) -> ExternalDevice {
        ExternalDevice {
            entry: self.entry.clone(),
            instance: self.instance.clone(),
            physical_device: self.physical_device,
            device: self.device.clone(),
            queue_family_index: self.family,
            queue: self.queue,
            ray_tracing: self.ray_tracing,
            ray_query: self.ray_query,
        }
    }

    /// Wait for the device (it must survive aokit), run `before_device` on it (the engine's own
    /// last work and the destruction of its other objects), destroy the device, the messenger and
    /// the instance, and return everything the validation layer said (device and instance
    /// destruction included).
    pub fn destroy_with(self, before_device: impl FnOnce(&ash::Device)) -> Vec<String> {
        unsafe { self.device.device_wait_idle() }.expect("the engine's device survives aokit");
        before_device(&self.device);
        unsafe {
            self.device.destroy_device(None);
            self.debug.destroy_debug_utils_messenger(self.messenger, None);
            self.instance.destroy_instance(None);
        }
        self.messages.into_inner().unwrap()
    }
}
