//! Instance, device selection (discrete GPU first, lavapipe as the fallback), queue, allocator,
//! one-shot command submission and validation-layer message capture; or, for an engine, the
//! same on a device the application created ([`ExternalDevice`]).

use crate::GpuError;
use ash::{ext, khr, vk};
use gpu_allocator::vulkan::{Allocator, AllocatorCreateDesc};
use std::ffi::{CStr, c_void};
use std::mem::ManuallyDrop;
use std::sync::Mutex;

/// How to open the device.
#[derive(Clone, Debug, Default)]
pub struct GpuOptions {
    /// Enable `VK_LAYER_KHRONOS_validation` with its synchronisation checks (hazards between
    /// commands a missing barrier leaves) and record its warnings and errors.
    pub validation: bool,
    /// Device extensions to treat as absent, e.g. `VK_KHR_ray_tracing_pipeline`: how aokit
    /// behaves on a device without them, on one that has them. The environment variable
    /// [`HIDE_EXTENSIONS_VAR`] (comma-separated names) adds to this list.
    pub hidden_extensions: Vec<String>,
}

/// `AOKIT_HIDE_EXTENSIONS=VK_KHR_ray_tracing_pipeline,…`: see [`GpuOptions::hidden_extensions`].
pub const HIDE_EXTENSIONS_VAR: &str = "AOKIT_HIDE_EXTENSIONS";

/// `AOKIT_MAX_STORAGE_BUFFER_RANGE=<bytes>`: treat the device's `maxStorageBufferRange` as at
/// most this many bytes (how aokit refuses a target too large for a smaller device, on a device
/// with a larger range).
pub const MAX_STORAGE_BUFFER_RANGE_VAR: &str = "AOKIT_MAX_STORAGE_BUFFER_RANGE";

/// The device's `maxStorageBufferRange`, lowered by [`MAX_STORAGE_BUFFER_RANGE_VAR`].
fn storage_buffer_range(device: u32) -> u64 {
    let cap = std::env::var(MAX_STORAGE_BUFFER_RANGE_VAR).ok().and_then(|v| v.trim().parse::<u64>().ok());
    cap.map_or(device as u64, |c| c.min(device as u64))
}

impl GpuOptions {
    /// The extensions to hide: the option's and the environment variable's.
    fn hidden(&self) -> Vec<String> {
        let from_env = std::env::var(HIDE_EXTENSIONS_VAR).unwrap_or_default();
        let names = from_env.split(',').map(str::trim).filter(|n| !n.is_empty()).map(str::to_string);
        self.hidden_extensions.iter().cloned().chain(names).collect()
    }
}

/// What `aokit info` prints.
#[derive(Clone, Debug)]
#[cfg_attr(feature = "harness", derive(serde::Serialize))]
pub struct DeviceInfo {
    /// `deviceName`.
    pub name: String,
    /// `deviceType`, e.g. `CPU` for lavapipe.
    pub device_type: String,
    /// `apiVersion` as `major.minor.patch`.
    pub api_version: String,
    /// `driverVersion` as the driver encodes it.
    pub driver_version: u32,
    /// Ray-tracing related extensions and whether the device has them (a hidden one counts as
    /// absent).
    pub ray_tracing_extensions: Vec<(String, bool)>,
    /// Extensions hidden by [`GpuOptions::hidden_extensions`].
    pub hidden_extensions: Vec<String>,
}

const RT_EXTENSIONS: [&CStr; 4] = [
    khr::acceleration_structure::NAME,
    khr::ray_tracing_pipeline::NAME,
    khr::ray_query::NAME,
    khr::deferred_host_operations::NAME,
];

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";

/// Shader-binding-table and scratch alignments of a ray-tracing device.
#[derive(Copy, Clone, Debug)]
pub(crate) struct RayTracingLimits {
    pub handle_size: u32,
    pub handle_alignment: u32,
    pub base_alignment: u32,
    pub scratch_alignment: u32,
}

/// Acceleration-structure entry points (present when the device builds acceleration
/// structures for ray-tracing pipelines or ray queries) and the ray-tracing-pipeline ones (when it
/// runs ray-tracing pipelines).
pub(crate) struct RayTracing {
    pub limits: RayTracingLimits,
    pub acceleration: khr::acceleration_structure::Device,
    pub pipelines: Option<khr::ray_tracing_pipeline::Device>,
}

/// A Vulkan device that the application created itself (a game engine, say), for
/// [`AoEffect::new`](crate::AoEffect::new).
///
/// These are plain handles: dropping them destroys nothing. aokit never destroys any of them,
/// so keep a clone (`ExternalDevice` is `Clone`, as are the ash loaders) to destroy the device
/// and the instance yourself after dropping the effect.
///
/// # What the device must have been created with
///
/// * Vulkan 1.3: the instance's `apiVersion` and the physical device's.
/// * Always: the Vulkan 1.2 features `vulkanMemoryModel` and `vulkanMemoryModelDeviceScope`
///   (every kernel's SPIR-V uses the Vulkan memory model that rust-gpu emits), and a queue
///   family with compute and timestamps (every pass is timed with timestamp queries). This
///   is all that the screen-space techniques need.
/// * For aokit's own raster passes (its G-buffer and the raster SD map, feature `harness`;
///   the effect runs none) also: a graphics queue, the Vulkan 1.3 feature `dynamicRendering`,
///   the core feature `fragmentStoresAndAtomics` (the raster SD map's atomic min) and, where
///   the device has it, `maintenance4` (the raster SD fragment shader does not read every
///   vertex output).
/// * For ray tracing (`external.ray_tracing == true`): the extensions
///   `VK_KHR_acceleration_structure`, `VK_KHR_ray_tracing_pipeline` and
///   `VK_KHR_deferred_host_operations`, and the features `accelerationStructure`,
///   `rayTracingPipeline` and `bufferDeviceAddress` (Vulkan 1.2). The allocator then
///   allocates all memory with `VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT`.
/// * For ray queries (`external.ray_query == true`, with or without `ray_tracing`):
///   `VK_KHR_ray_query`, `VK_KHR_acceleration_structure` and
///   `VK_KHR_deferred_host_operations`, and the features `rayQuery`,
///   `accelerationStructure` and `bufferDeviceAddress`.
///
/// aokit cannot read back which features were enabled: it checks what the *physical* device
/// supports (a clear error when it lacks the memory model, when the queue family lacks
/// compute or timestamps, or when `ray_tracing` is set but the device cannot ray trace) and
/// trusts the caller for the rest; the validation layer reports a missing feature.
///
/// # Rules for the caller
///
/// * aokit makes its own command pool and allocator on the device and destroys only those.
///   Calls that submit (building an [`AoScene`](crate::AoScene)) wait for their own
///   submissions before returning; `record` submits nothing.
/// * Drop the effect and its scenes after the device finished the frames they recorded, and
///   before destroying the device and the instance.
/// * Don't use `queue` from another thread while an aokit call runs (Vulkan's external
///   synchronisation of queues).
/// * aokit installs no debug messenger on the engine's instance: install your own to see
///   validation messages.
#[derive(Clone)]
pub struct ExternalDevice {
    /// The loader `instance` was created from; aokit keeps it so the Vulkan library stays loaded
    /// while the effect lives.
    pub entry: ash::Entry,
    /// The instance, created with `apiVersion` 1.3 or later (aokit cannot check this one).
    pub instance: ash::Instance,
    /// The physical device `device` was created on.
    pub physical_device: vk::PhysicalDevice,
    /// The logical device, created with the features and extensions listed above.
    pub device: ash::Device,
    /// The family of `queue`: it must support compute and timestamps (`timestampValidBits > 0`);
    /// the command buffers given to `record` come from a pool of this family.
    pub queue_family_index: u32,
    /// The queue aokit submits to. Vulkan requires host access to a queue to be externally
    /// synchronised: while an aokit call runs, no other thread may submit to (or wait idle on)
    /// this queue. Give aokit a queue of its own to avoid the question.
    pub queue: vk::Queue,
    /// Whether the device was created with the ray-tracing extensions
    /// (`VK_KHR_acceleration_structure`, `VK_KHR_ray_tracing_pipeline`,
    /// `VK_KHR_deferred_host_operations`) and the `accelerationStructure`,
    /// `rayTracingPipeline` and `bufferDeviceAddress` features enabled. aokit cannot query what
    /// was enabled, so it trusts this flag; `false` makes aokit behave as on a device without
    /// ray tracing.
    pub ray_tracing: bool,
    /// Whether the device was created with `VK_KHR_ray_query` and the `rayQuery` feature, and
    /// with `VK_KHR_acceleration_structure`, `VK_KHR_deferred_host_operations`,
    /// `accelerationStructure` and `bufferDeviceAddress` (the ray-query variants of the
    /// ray-traced passes, [`RtMode::Query`]; no ray-tracing pipeline needed).
    ///
    /// [`RtMode::Query`]: aokit_shaders::graph::RtMode::Query
    pub ray_query: bool,
}

/// What `Gpu::new` created besides the pool and the allocator, and so destroys on drop.
struct OwnedDevice {
    debug: Option<(ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
}

impl OwnedDevice {
    /// Destroy `device` (once created), the messenger and `instance`.
    unsafe fn destroy(&self, device: Option<&ash::Device>, instance: &ash::Instance) {
        unsafe {
            if let Some(device) = device {
                device.destroy_device(None);
            }
            if let Some((loader, messenger)) = &self.debug {
                loader.destroy_debug_utils_messenger(*messenger, None);
            }
            instance.destroy_instance(None);
        }
    }
}

/// An open Vulkan device with everything the passes need: aokit's own instance and device
/// ([`Gpu::new`]) or the application's ([`Gpu::from_external`]).
pub struct Gpu {
    pub(crate) ray_tracing: Option<RayTracing>,
    /// Ray queries enabled (only with `ray_tracing`).
    ray_query: bool,
    pub(crate) device: ash::Device,
    pub(crate) queue: vk::Queue,
    queue_family_index: u32,
    /// Whether the queue family has graphics (fragment-stage barriers are valid on it).
    graphics: bool,
    pub(crate) pool: vk::CommandPool,
    pub(crate) allocator: ManuallyDrop<Mutex<Allocator>>,
    pub(crate) timestamp_period_ns: f32,
    /// `maxStorageBufferRange`: the largest storage buffer a descriptor may bind, in bytes.
    pub(crate) max_storage_buffer_range: u64,
    info: DeviceInfo,
    /// `Some` when `Gpu::new` created the instance and device (and destroys them), `None` for an
    /// [`ExternalDevice`].
    owned: Option<OwnedDevice>,
    /// Validation warnings and errors; boxed so the callback's pointer stays valid.
    messages: Box<Mutex<Vec<String>>>,
    instance: ash::Instance,
    physical_device: vk::PhysicalDevice,
    entry: ash::Entry,
}

/// What aokit reads from a physical device: the same for a device it opens and an external one.
struct DeviceProbe {
    info: DeviceInfo,
    timestamp_period_ns: f32,
    max_storage_buffer_range: u64,
    /// The limits, when the physical device builds acceleration structures
    /// (`VK_KHR_acceleration_structure`, `VK_KHR_deferred_host_operations`,
    /// `accelerationStructure`, `bufferDeviceAddress`) and can use them (`pipelines` or
    /// `ray_query`).
    ray_tracing: Option<RayTracingLimits>,
    /// `VK_KHR_ray_tracing_pipeline` and `rayTracingPipeline`, besides `ray_tracing`.
    pipelines: bool,
    /// `VK_KHR_ray_query` and `rayQuery`, besides `ray_tracing`.
    ray_query: bool,
}

impl DeviceProbe {
    /// What `pd` offers, with the extensions named in `hidden` treated as absent.
    fn new(instance: &ash::Instance, pd: vk::PhysicalDevice, hidden: &[String]) -> Result<DeviceProbe, GpuError> {
        let props = unsafe { instance.get_physical_device_properties(pd) };
        let available = unsafe { instance.enumerate_device_extension_properties(pd)? };
        let visible = |name: &CStr| !hidden.iter().any(|h| name.to_bytes() == h.as_bytes());
        let has = |name: &CStr| visible(name) && available.iter().any(|e| e.extension_name_as_c_str() == Ok(name));
        let info = DeviceInfo {
            name: props.device_name_as_c_str().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default(),
            device_type: format!("{:?}", props.device_type),
            api_version: format!(
                "{}.{}.{}",
                vk::api_version_major(props.api_version),
                vk::api_version_minor(props.api_version),
                vk::api_version_patch(props.api_version)
            ),
            driver_version: props.driver_version,
            ray_tracing_extensions: RT_EXTENSIONS.iter().map(|e| (e.to_string_lossy().into_owned(), has(e))).collect(),
            hidden_extensions: hidden.to_vec(),
        };
        // Ray tracing (pipelines + acceleration structures) when the device has all of it.
        let mut as_features = vk::PhysicalDeviceAccelerationStructureFeaturesKHR::default();
        let mut rt_features = vk::PhysicalDeviceRayTracingPipelineFeaturesKHR::default();
        let mut rq_features = vk::PhysicalDeviceRayQueryFeaturesKHR::default();
        let mut f12_query = vk::PhysicalDeviceVulkan12Features::default();
        let mut f2 = vk::PhysicalDeviceFeatures2::default()
            .push_next(&mut as_features)
            .push_next(&mut rt_features)
            .push_next(&mut rq_features)
            .push_next(&mut f12_query);
        unsafe { instance.get_physical_device_features2(pd, &mut f2) };
        let accel = has(khr::acceleration_structure::NAME)
            && has(khr::deferred_host_operations::NAME)
            && as_features.acceleration_structure != 0
            && f12_query.buffer_device_address != 0;
        let pipelines = accel && has(khr::ray_tracing_pipeline::NAME) && rt_features.ray_tracing_pipeline != 0;
        let ray_query = accel && has(khr::ray_query::NAME) && rq_features.ray_query != 0;
        let limits = (pipelines || ray_query).then(|| {
            let mut rt_props = vk::PhysicalDeviceRayTracingPipelinePropertiesKHR::default();
            let mut as_props = vk::PhysicalDeviceAccelerationStructurePropertiesKHR::default();
            let mut p2 = vk::PhysicalDeviceProperties2::default().push_next(&mut rt_props).push_next(&mut as_props);
            unsafe { instance.get_physical_device_properties2(pd, &mut p2) };
            RayTracingLimits {
                handle_size: rt_props.shader_group_handle_size,
                handle_alignment: rt_props.shader_group_handle_alignment,
                base_alignment: rt_props.shader_group_base_alignment,
                scratch_alignment: as_props.min_acceleration_structure_scratch_offset_alignment,
            }
        });
        Ok(DeviceProbe {
            info,
            timestamp_period_ns: props.limits.timestamp_period,
            max_storage_buffer_range: storage_buffer_range(props.limits.max_storage_buffer_range),
            ray_tracing: limits,
            pipelines,
            ray_query,
        })
    }
}

/// The Vulkan 1.3 core support aokit looks at on a physical device.
struct CoreSupport {
    /// `apiVersion` ≥ 1.3.
    vulkan_1_3: bool,
    /// `vulkanMemoryModel` and `vulkanMemoryModelDeviceScope`: every kernel's SPIR-V uses the
    /// Vulkan memory model (rust-gpu emits it).
    memory_model: bool,
    /// `dynamicRendering`: the raster passes render without render-pass objects.
    dynamic_rendering: bool,
    /// `maintenance4`: relaxed vertex→fragment interface matching (the raster SD fragment shader
    /// does not read the G-buffer vertex shader's normal output).
    maintenance4: bool,
}

impl CoreSupport {
    fn new(instance: &ash::Instance, pd: vk::PhysicalDevice) -> CoreSupport {
        let props = unsafe { instance.get_physical_device_properties(pd) };
        let mut f12 = vk::PhysicalDeviceVulkan12Features::default();
        let mut f13 = vk::PhysicalDeviceVulkan13Features::default();
        let mut f2 = vk::PhysicalDeviceFeatures2::default().push_next(&mut f12).push_next(&mut f13);
        unsafe { instance.get_physical_device_features2(pd, &mut f2) };
        CoreSupport {
            vulkan_1_3: props.api_version >= vk::API_VERSION_1_3,
            memory_model: f12.vulkan_memory_model != 0 && f12.vulkan_memory_model_device_scope != 0,
            dynamic_rendering: f13.dynamic_rendering != 0,
            maintenance4: f13.maintenance4 != 0,
        }
    }
}

/// Does queue family `q` run the compute passes and their timestamp queries?
fn timed_compute(q: &vk::QueueFamilyProperties) -> bool {
    q.queue_flags.contains(vk::QueueFlags::COMPUTE) && q.timestamp_valid_bits > 0
}

unsafe extern "system" fn debug_callback(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    let relevant = vk::DebugUtilsMessageSeverityFlagsEXT::WARNING | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR;
    if severity.intersects(relevant) && !data.is_null() && !user.is_null() {
        // SAFETY: Vulkan passes valid callback data; `user` is the boxed Mutex owned by `Gpu`,
        // which destroys the messenger before dropping the box.
        let (data, messages) = unsafe { (&*data, &*(user as *const Mutex<Vec<String>>)) };
        let text = unsafe { data.message_as_c_str() }.map(|m| m.to_string_lossy().into_owned()).unwrap_or_default();
        messages.lock().unwrap_or_else(|e| e.into_inner()).push(format!("{severity:?}: {text}"));
    }
    vk::FALSE
}

fn device_rank(t: vk::PhysicalDeviceType) -> u32 {
    match t {
        vk::PhysicalDeviceType::DISCRETE_GPU => 0,
        vk::PhysicalDeviceType::INTEGRATED_GPU => 1,
        vk::PhysicalDeviceType::VIRTUAL_GPU => 2,
        vk::PhysicalDeviceType::CPU => 3,
        _ => 4,
    }
}

impl Gpu {
    /// Open the best device: a discrete GPU if there is one, else integrated, virtual, and
    /// finally a CPU implementation such as lavapipe. Requires Vulkan 1.3 (dynamic rendering)
    /// and the Vulkan memory model that rust-gpu emits.
    pub fn new(options: &GpuOptions) -> Result<Gpu, GpuError> {
        let entry = unsafe { ash::Entry::load() }.map_err(|e| GpuError::Loader(e.to_string()))?;
        let mut layers = Vec::new();
        let mut extensions = Vec::new();
        if options.validation {
            let available = unsafe { entry.enumerate_instance_layer_properties()? };
            if !available.iter().any(|l| l.layer_name_as_c_str() == Ok(VALIDATION_LAYER)) {
                return Err(GpuError::NoValidationLayer);
            }
            layers.push(VALIDATION_LAYER.as_ptr());
            extensions.push(ext::debug_utils::NAME.as_ptr());
        }
        let app = vk::ApplicationInfo::default().application_name(c"aokit").api_version(vk::API_VERSION_1_3);
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
            .pfn_user_callback(Some(debug_callback))
            .user_data(&*messages as *const Mutex<Vec<String>> as *mut c_void);
        let sync = [vk::ValidationFeatureEnableEXT::SYNCHRONIZATION_VALIDATION];
        let mut features = vk::ValidationFeaturesEXT::default().enabled_validation_features(&sync);
        let mut create = vk::InstanceCreateInfo::default()
            .application_info(&app)
            .enabled_layer_names(&layers)
            .enabled_extension_names(&extensions);
        if options.validation {
            // The messenger also covers instance creation.
            create = create.push_next(&mut messenger_info).push_next(&mut features);
        }
        let instance = unsafe { entry.create_instance(&create, None) }.map_err(|e| match e {
            vk::Result::ERROR_INCOMPATIBLE_DRIVER => GpuError::NoDriver,
            e => e.into(),
        })?;
        let debug = if options.validation {
            let loader = ext::debug_utils::Instance::new(&entry, &instance);
            match unsafe { loader.create_debug_utils_messenger(&messenger_info, None) } {
                Ok(messenger) => Some((loader, messenger)),
                Err(e) => {
                    unsafe { instance.destroy_instance(None) };
                    return Err(e.into());
                }
            }
        } else {
            None
        };
        let owned = OwnedDevice { debug };
        let (physical_device, device, queue_family_index, probe) = match Self::open_device(&instance, &options.hidden())
        {
            Ok(opened) => opened,
            Err(e) => {
                unsafe { owned.destroy(None, &instance) };
                return Err(e);
            }
        };
        let queue = unsafe { device.get_device_queue(queue_family_index, 0) };
        let (ray_tracing, ray_query) = (probe.pipelines, probe.ray_query);
        let handles = ExternalDevice {
            entry,
            instance,
            physical_device,
            device,
            queue_family_index,
            queue,
            ray_tracing,
            ray_query,
        };
        Self::assemble(handles, probe, Some(owned), messages)
    }

    /// Run aokit on a device the application created itself (an engine integration). The
    /// `Gpu` creates its own command pool and gpu-allocator `Allocator` on `external.device`
    /// and destroys only those; the device and the instance stay the caller's.
    ///
    /// The device must have been created as [`ExternalDevice`] lists.
    ///
    /// # Rules for the caller
    ///
    /// * Every aokit call waits for its own submissions before returning, so nothing of aokit's
    ///   is in flight between calls and dropping the `Gpu` does not wait for the device (that
    ///   would stall the engine's own work). Before dropping it, free every [`Buffer`](crate::Buffer)
    ///   and destroy every pass object made through it, and make sure none of your own pending
    ///   command buffers still uses them.
    /// * Drop the `Gpu` before destroying the device and the instance.
    /// * Don't use `external.queue` from another thread while an aokit call runs (Vulkan's
    ///   external synchronisation of queues).
    /// * There is no debug messenger of aokit's on an external instance:
    ///   [`Gpu::validation_messages`] is always empty; install your own messenger.
    pub fn from_external(external: ExternalDevice) -> Result<Gpu, GpuError> {
        let ExternalDevice { ref instance, physical_device, queue_family_index, ray_tracing, ray_query, .. } = external;
        let probe = DeviceProbe::new(instance, physical_device, &[])?;
        let core = CoreSupport::new(instance, physical_device);
        let name = &probe.info.name;
        if !core.vulkan_1_3 || !core.memory_model {
            return Err(GpuError::NoDevice(format!(
                "vulkanMemoryModel and vulkanMemoryModelDeviceScope: the external device '{name}' (Vulkan {}) lacks them",
                probe.info.api_version
            )));
        }
        let families = unsafe { instance.get_physical_device_queue_family_properties(physical_device) };
        let Some(family) = families.get(queue_family_index as usize) else {
            return Err(GpuError::Input(format!(
                "external queue family {queue_family_index} does not exist ('{name}' has {})",
                families.len()
            )));
        };
        if !timed_compute(family) {
            return Err(GpuError::NoDevice(format!(
                "compute and timestamps: queue family {queue_family_index} of the external device '{name}' lacks them"
            )));
        }
        if ray_tracing && !probe.pipelines {
            return Err(GpuError::NoDevice(format!(
                "ray tracing: ExternalDevice::ray_tracing is set but '{name}' lacks VK_KHR_ray_tracing_pipeline / VK_KHR_acceleration_structure / VK_KHR_deferred_host_operations / bufferDeviceAddress"
            )));
        }
        if ray_query && !probe.ray_query {
            return Err(GpuError::NoDevice(format!(
                "ray queries: ExternalDevice::ray_query is set but '{name}' lacks VK_KHR_ray_query / VK_KHR_acceleration_structure / VK_KHR_deferred_host_operations / rayQuery / bufferDeviceAddress"
            )));
        }
        Self::assemble(external, probe, None, Box::default())
    }

    /// What a `Gpu` adds to any device, its own or an external one: the command pool, the
    /// allocator and the ray-tracing entry points (when `handles.ray_tracing`, which requires
    /// `probe.ray_tracing`). On failure it destroys what it made and, when `owned`, the device
    /// and the instance as well.
    fn assemble(
        handles: ExternalDevice,
        probe: DeviceProbe,
        owned: Option<OwnedDevice>,
        messages: Box<Mutex<Vec<String>>>,
    ) -> Result<Gpu, GpuError> {
        let ExternalDevice {
            entry,
            instance,
            physical_device,
            device,
            queue_family_index,
            queue,
            ray_tracing,
            ray_query,
        } = handles;
        let (pipelines, ray_query) = (ray_tracing && probe.pipelines, ray_query && probe.ray_query);
        let limits = probe.ray_tracing.filter(|_| pipelines || ray_query);
        let fail = |e: GpuError| {
            if let Some(owned) = &owned {
                unsafe { owned.destroy(Some(&device), &instance) };
            }
            e
        };
        let pool = unsafe {
            device.create_command_pool(
                &vk::CommandPoolCreateInfo::default()
                    .queue_family_index(queue_family_index)
                    .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER),
                None,
            )
        }
        .map_err(|e| fail(e.into()))?;
        let allocator = Allocator::new(&AllocatorCreateDesc {
            instance: instance.clone(),
            device: device.clone(),
            physical_device,
            debug_settings: Default::default(),
            buffer_device_address: limits.is_some(),
            allocation_sizes: Default::default(),
        });
        let allocator = match allocator {
            Ok(a) => a,
            Err(e) => {
                unsafe { device.destroy_command_pool(pool, None) };
                return Err(fail(e.into()));
            }
        };
        let ray_tracing = limits.map(|limits| RayTracing {
            limits,
            acceleration: khr::acceleration_structure::Device::new(&instance, &device),
            pipelines: pipelines.then(|| khr::ray_tracing_pipeline::Device::new(&instance, &device)),
        });
        let families = unsafe { instance.get_physical_device_queue_family_properties(physical_device) };
        let graphics =
            families.get(queue_family_index as usize).is_some_and(|q| q.queue_flags.contains(vk::QueueFlags::GRAPHICS));
        Ok(Gpu {
            ray_tracing,
            ray_query,
            device,
            queue,
            queue_family_index,
            graphics,
            pool,
            allocator: ManuallyDrop::new(Mutex::new(allocator)),
            timestamp_period_ns: probe.timestamp_period_ns,
            max_storage_buffer_range: probe.max_storage_buffer_range,
            info: probe.info,
            owned,
            messages,
            instance,
            physical_device,
            entry,
        })
    }

    fn open_device(
        instance: &ash::Instance,
        hidden: &[String],
    ) -> Result<(vk::PhysicalDevice, ash::Device, u32, DeviceProbe), GpuError> {
        let mut candidates = Vec::new();
        for pd in unsafe { instance.enumerate_physical_devices()? } {
            let core = CoreSupport::new(instance, pd);
            if !core.vulkan_1_3 || !core.memory_model || !core.dynamic_rendering {
                continue;
            }
            let props = unsafe { instance.get_physical_device_properties(pd) };
            let families = unsafe { instance.get_physical_device_queue_family_properties(pd) };
            let Some(family) =
                families.iter().position(|q| q.queue_flags.contains(vk::QueueFlags::GRAPHICS) && timed_compute(q))
            else {
                continue;
            };
            candidates.push((device_rank(props.device_type), pd, core, family as u32));
        }
        candidates.sort_by_key(|c| c.0);
        let Some((_, pd, core, family)) = candidates.into_iter().next() else {
            return Err(GpuError::NoDevice(
                "vulkanMemoryModel, vulkanMemoryModelDeviceScope, dynamicRendering and a graphics+compute queue with timestamps".into(),
            ));
        };
        let probe = DeviceProbe::new(instance, pd, hidden)?;
        let accel = probe.ray_tracing.is_some();
        let priorities = [1.0];
        let queues = [vk::DeviceQueueCreateInfo::default().queue_family_index(family).queue_priorities(&priorities)];
        let mut f12 = vk::PhysicalDeviceVulkan12Features::default()
            .vulkan_memory_model(true)
            .vulkan_memory_model_device_scope(true)
            .buffer_device_address(accel);
        let mut f13 =
            vk::PhysicalDeviceVulkan13Features::default().dynamic_rendering(true).maintenance4(core.maintenance4);
        let mut as_enable = vk::PhysicalDeviceAccelerationStructureFeaturesKHR::default().acceleration_structure(true);
        let mut rt_enable = vk::PhysicalDeviceRayTracingPipelineFeaturesKHR::default().ray_tracing_pipeline(true);
        let mut rq_enable = vk::PhysicalDeviceRayQueryFeaturesKHR::default().ray_query(true);
        let mut names = Vec::new();
        if accel {
            names.extend([khr::acceleration_structure::NAME.as_ptr(), khr::deferred_host_operations::NAME.as_ptr()]);
        }
        if probe.pipelines {
            names.push(khr::ray_tracing_pipeline::NAME.as_ptr());
        }
        if probe.ray_query {
            names.push(khr::ray_query::NAME.as_ptr());
        }
        // Fragment-shader atomics: the raster SD map writes its samples with atomic min.
        let supported = unsafe { instance.get_physical_device_features(pd) };
        let core_features = vk::PhysicalDeviceFeatures::default()
            .fragment_stores_and_atomics(supported.fragment_stores_and_atomics != 0);
        let mut create = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .enabled_features(&core_features)
            .push_next(&mut f12)
            .push_next(&mut f13);
        create = create.enabled_extension_names(&names);
        if accel {
            create = create.push_next(&mut as_enable);
        }
        if probe.pipelines {
            create = create.push_next(&mut rt_enable);
        }
        if probe.ray_query {
            create = create.push_next(&mut rq_enable);
        }
        let device = unsafe { instance.create_device(pd, &create, None)? };
        Ok((pd, device, family, probe))
    }

    /// The device's handles as an [`ExternalDevice`], for a tool that records work of its own
    /// beside aokit's on the same queue (a benchmark of another implementation on the same
    /// device; `AoEffect::new` on the same device). The `Gpu` keeps owning what it created:
    /// drop everything made through the handles before the `Gpu`.
    pub fn external(&self) -> ExternalDevice {
        ExternalDevice {
            entry: self.entry.clone(),
            instance: self.instance.clone(),
            physical_device: self.physical_device,
            device: self.device.clone(),
            queue_family_index: self.queue_family_index,
            queue: self.queue,
            ray_tracing: self.has_ray_tracing(),
            ray_query: self.ray_query,
        }
    }

    /// Does the device run ray-tracing pipelines (`VK_KHR_ray_tracing_pipeline` and
    /// `VK_KHR_acceleration_structure`, enabled at creation)?
    pub fn has_ray_tracing(&self) -> bool {
        self.ray_tracing.as_ref().is_some_and(|rt| rt.pipelines.is_some())
    }

    /// Does the device run ray-query kernels (`VK_KHR_ray_query`, `rayQuery` and the
    /// acceleration structures, enabled at creation; no ray-tracing pipeline needed)?
    pub fn has_ray_query(&self) -> bool {
        self.ray_query
    }

    /// `maxStorageBufferRange` in bytes: the largest buffer a pass can bind.
    pub fn max_storage_buffer_range(&self) -> u64 {
        self.max_storage_buffer_range
    }

    /// Can the device trace rays the way `mode` says? Otherwise an error naming the extensions
    /// (or features) it lacks — for callers to check before they record any GPU work.
    pub fn require_rays(&self, mode: aokit_shaders::graph::RtMode) -> Result<(), GpuError> {
        use aokit_shaders::graph::RtMode;
        let (ok, needed) = match mode {
            RtMode::Pipeline => (self.has_ray_tracing(), [0, 1, 3]),
            RtMode::Query => (self.has_ray_query(), [0, 2, 3]),
        };
        if ok {
            return Ok(());
        }
        let info = &self.info;
        let missing: Vec<&str> = needed
            .iter()
            .map(|&i| &info.ray_tracing_extensions[i])
            .filter(|(_, has)| !has)
            .map(|(name, _)| name.as_str())
            .collect();
        let lacks = if missing.is_empty() {
            "the features accelerationStructure, rayTracingPipeline/rayQuery or bufferDeviceAddress (or the caller did not enable them)".to_string()
        } else {
            missing.join(", ")
        };
        let hidden = if info.hidden_extensions.is_empty() {
            String::new()
        } else {
            format!(" (hidden: {})", info.hidden_extensions.join(", "))
        };
        let other = match mode {
            RtMode::Pipeline if self.has_ray_query() => "; ray queries (RtMode::Query) would work instead",
            RtMode::Query if self.has_ray_tracing() => "; ray-tracing pipelines (RtMode::Pipeline) would work instead",
            _ => "",
        };
        let what = match mode {
            RtMode::Pipeline => "ray-tracing pipelines",
            RtMode::Query => "ray queries",
        };
        let needs = needed.iter().map(|&i| info.ray_tracing_extensions[i].0.as_str()).collect::<Vec<_>>().join(" + ");
        Err(GpuError::Missing(format!(
            "tracing rays with {what} needs {needs}; '{}' lacks {lacks}{hidden}{other}",
            info.name
        )))
    }

    /// The acceleration-structure entry points, or a clear error naming what the device lacks.
    pub(crate) fn ray_tracing(&self) -> Result<&RayTracing, GpuError> {
        self.ray_tracing.as_ref().ok_or_else(|| {
            GpuError::NoDevice(format!(
                "acceleration structures: '{}' lacks VK_KHR_acceleration_structure / VK_KHR_deferred_host_operations / bufferDeviceAddress, or both VK_KHR_ray_tracing_pipeline and VK_KHR_ray_query",
                self.info.name
            ))
        })
    }

    /// The ray-tracing-pipeline entry points, or a clear error naming what the device lacks.
    pub(crate) fn ray_pipelines(&self) -> Result<(&RayTracing, &khr::ray_tracing_pipeline::Device), GpuError> {
        let rt = self.ray_tracing()?;
        let pipelines = rt.pipelines.as_ref().ok_or_else(|| {
            GpuError::NoDevice(format!("ray-tracing pipelines: '{}' lacks VK_KHR_ray_tracing_pipeline", self.info.name))
        })?;
        Ok((rt, pipelines))
    }

    /// The chosen device.
    pub fn info(&self) -> &DeviceInfo {
        &self.info
    }

    /// The logical device aokit runs on (its own, or the caller's for [`Gpu::from_external`]).
    pub fn device(&self) -> &ash::Device {
        &self.device
    }

    /// Whether the queue family has graphics (raster passes, fragment-stage barriers).
    pub fn has_graphics_queue(&self) -> bool {
        self.graphics
    }

    /// The queue family of the queue aokit submits to.
    pub fn queue_family_index(&self) -> u32 {
        self.queue_family_index
    }

    /// Bytes currently allocated by this `Gpu`'s gpu-allocator: the sum of its live allocations
    /// (buffers, images, acceleration structures), not the capacity of the memory blocks they
    /// are carved from. gpu-allocator counts the padding that aligned an allocation in its
    /// block as part of it, so the same allocations placed differently may differ by up to the
    /// alignment each. Flat across frames when nothing leaks.
    pub fn allocated_bytes(&self) -> u64 {
        self.allocator.lock().unwrap_or_else(|e| e.into_inner()).generate_report().total_allocated_bytes
    }

    /// How many allocations are live (for leak checks that must not depend on placement).
    #[cfg(feature = "testing")]
    pub fn live_allocations(&self) -> usize {
        self.allocator.lock().unwrap_or_else(|e| e.into_inner()).generate_report().allocations.len()
    }

    /// Validation-layer warnings and errors reported so far: empty without validation, and
    /// always empty for a [`Gpu::from_external`] device (aokit installs no messenger on the
    /// caller's instance; install your own).
    pub fn validation_messages(&self) -> Vec<String> {
        self.messages.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    /// Deliberately misuse the API once (a sampler with anisotropy although the
    /// `samplerAnisotropy` feature was not enabled) so tests can prove that validation messages
    /// reach [`Gpu::validation_messages`]. Harmless to the driver.
    #[cfg(feature = "testing")]
    pub fn provoke_validation_error(&self) -> Result<(), GpuError> {
        let info = vk::SamplerCreateInfo::default().anisotropy_enable(true).max_anisotropy(4.0);
        let sampler = unsafe { self.device.create_sampler(&info, None)? };
        unsafe { self.device.destroy_sampler(sampler, None) };
        Ok(())
    }

    /// Record commands into a fresh command buffer, submit, and wait for completion.
    pub(crate) fn submit<R>(&self, record: impl FnOnce(vk::CommandBuffer) -> R) -> Result<R, GpuError> {
        let info = vk::CommandBufferAllocateInfo::default()
            .command_pool(self.pool)
            .level(vk::CommandBufferLevel::PRIMARY)
            .command_buffer_count(1);
        let cb = unsafe { self.device.allocate_command_buffers(&info)? }[0];
        let result = unsafe {
            self.device.begin_command_buffer(
                cb,
                &vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
            )?;
            let r = record(cb);
            self.device.end_command_buffer(cb)?;
            let fence = self.device.create_fence(&vk::FenceCreateInfo::default(), None)?;
            let cbs = [cb];
            let submit = vk::SubmitInfo::default().command_buffers(&cbs);
            let waited = self
                .device
                .queue_submit(self.queue, &[submit], fence)
                .and_then(|_| self.device.wait_for_fences(&[fence], true, u64::MAX));
            self.device.destroy_fence(fence, None);
            self.device.free_command_buffers(self.pool, &cbs);
            waited?;
            r
        };
        Ok(result)
    }

    /// Read `count` 64-bit timestamps of `queries` (waiting for them) as milliseconds after the
    /// first (also for tools that time work of their own on the device).
    pub fn timestamps_ms(&self, queries: vk::QueryPool, count: usize) -> Result<Vec<f64>, GpuError> {
        let mut stamps = vec![0u64; count];
        let flags = vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT;
        unsafe { self.device.get_query_pool_results(queries, 0, &mut stamps, flags)? };
        let period_ms = self.timestamp_period_ns as f64 * 1e-6;
        Ok(stamps.iter().map(|&s| s.saturating_sub(stamps[0]) as f64 * period_ms).collect())
    }

    /// Create a shader module from SPIR-V bytes.
    pub(crate) fn shader_module(&self, spirv: &[u8]) -> Result<vk::ShaderModule, GpuError> {
        let words = crate::modules::words(spirv);
        Ok(unsafe { self.device.create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&words), None)? })
    }
}

impl Drop for Gpu {
    /// Destroys the allocator and the command pool, and for [`Gpu::new`] also waits for the
    /// device and destroys the device, the messenger and the instance. An external device is
    /// neither waited for nor destroyed (see [`Gpu::from_external`]).
    fn drop(&mut self) {
        unsafe {
            if self.owned.is_some() {
                let _ = self.device.device_wait_idle();
            }
            ManuallyDrop::drop(&mut self.allocator);
            self.device.destroy_command_pool(self.pool, None);
            if let Some(owned) = &self.owned {
                owned.destroy(Some(&self.device), &self.instance);
            }
        }
    }
}
