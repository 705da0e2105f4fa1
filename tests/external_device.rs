//! `Gpu::from_external`: aokit on a device the application created with plain ash, as a game
//! engine would — under the application's own validation messenger, which must stay silent
//! through aokit's work, aokit's drop and the application's own destruction of the device and
//! the instance (a double destroy or a leaked aokit object would be reported there).

use aokit::output::crop_inner;
use aokit_cpu::no_progress;
use aokit_shaders::glam::uvec2;
use aokit_vulkan::{AoContext, ExternalDevice, Gpu, GpuError, GpuInputs};
use ash::vk;

mod common;

use common::engine_device::{EngineDevice as Engine, EngineNeeds, RayTracing};

/// An engine's instance (validation layer + messenger) and device on lavapipe (or the first
/// Vulkan 1.3 device when there is no lavapipe), with a graphics+compute queue. `full`:
/// everything aokit can use (raster features, ray tracing where supported); otherwise only what
/// the compute passes need. `None` when the run allows its skip (tests/common/skip.rs).
fn new_engine(full: bool) -> Option<Engine> {
    Engine::new(&EngineNeeds {
        app_name: c"some engine",
        queue_flags: vk::QueueFlags::GRAPHICS | vk::QueueFlags::COMPUTE,
        raster: full,
        ray_tracing: if full { RayTracing::WhereSupported } else { RayTracing::Off },
    })
}

/// Prove the device is still alive and ours, destroy it, the messenger and the instance,
/// and return everything the validation layer said.
fn destroy(engine: Engine) -> Vec<String> {
    engine.destroy_with(|device| unsafe {
        let fence = device.create_fence(&vk::FenceCreateInfo::default(), None).unwrap();
        device.destroy_fence(fence, None);
    })
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

    let (frame, vao, blur, depth, normals) = common::step_gbuffer(uvec2(48, 40));
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
            let within = cpu.iter().zip(&on_gpu).filter(|(a, b)| (*a - *b).abs() <= common::agreement::STEP).count();
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
    let Some(engine) = new_engine(true) else { return };
    run_on(&engine);
    // A second Gpu on the same device after the first was dropped.
    run_on(&engine);
    let messages = destroy(engine);
    assert!(messages.is_empty(), "validation layer reported:\n{}", messages.join("\n"));
}

#[test]
fn compute_only_engine_device_runs_a_compute_graph() {
    let Some(engine) = new_engine(false) else { return };
    assert!(!engine.ray_tracing);
    run_on(&engine);
    // A queue family that does not exist is the caller's mistake, reported as such.
    let wrong = ExternalDevice { queue_family_index: 99, ..engine.external() };
    assert!(matches!(Gpu::from_external(wrong), Err(GpuError::Input(_))));
    let messages = destroy(engine);
    assert!(messages.is_empty(), "validation layer reported:\n{}", messages.join("\n"));
}
