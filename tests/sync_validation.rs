//! The validation layer sees what the Vulkan tests rely on it to see. Every Vulkan test runs
//! under `VK_LAYER_KHRONOS_validation` with its synchronisation checks — aokit's own instance
//! (`GpuOptions::validation`) and the engine-owned one of tests/common/engine_device.rs — and
//! fails on any message. These tests are the positive controls: a deliberate defect (the
//! `testing` feature's `Sabotage`) must produce the message, on both instances, and the same
//! work without the defect must produce none.
//!
//! What lavapipe hides: it executes each dispatch to completion before the next, so a missing
//! barrier between two dispatches does not change a result there (the test shows the same AO
//! with and without it); a real GPU overlaps dispatches. On lavapipe only the layer's tracking
//! of the commands' accesses catches it, which is why it must be shown to fire. Frames in
//! flight are likewise usually finished by lavapipe before the next one is recorded, so a buffer
//! freed too early (while its frame is pending on a GPU) rarely meets live work here and the
//! layer seldom sees it; an engine-side use-after-free check (every free against the frames the
//! engine has waited for) catches it whatever the timing.

mod common;

use aokit_shaders::glam::{UVec2, uvec2};
use aokit_shaders::graph::Graph;
use aokit_vulkan::{AoContext, Buffer, Gpu, GpuInputs, GpuOptions, Sabotage};
use ash::vk;
use common::engine_device::{EngineDevice, EngineNeeds, RayTracing};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

/// The first pass of `graph` after a barrier: it reads what an earlier pass wrote.
fn pass_after_barrier(graph: &Graph) -> usize {
    let barriers = graph.barriers();
    (1..graph.passes.len()).find(|&i| barriers[i]).expect("a graph with a barrier between passes")
}

/// The vao graph (main pass + two blur passes) on the synthetic step G-buffer of `inner`.
fn vao_frame(inner: UVec2) -> (Graph, Vec<f32>, Vec<u32>) {
    let (frame, _, _, depth, normals) = common::step_gbuffer(inner);
    (aokit_shaders::vao::settings::graph(&frame), depth, normals)
}

/// Run `graph` once through a fresh context on `gpu` with `sabotage` (submitted and waited).
fn run_once(gpu: &Gpu, graph: &Graph, depth: &[f32], normals: &[u32], sabotage: Sabotage) -> Vec<f32> {
    let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
    let (d, n) = (gpu.upload(depth, storage).unwrap(), gpu.upload(normals, storage).unwrap());
    let out = {
        let mut ctx = AoContext::new(gpu);
        ctx.sabotage(sabotage);
        let inputs = GpuInputs { depth: &d, normals: &n, second_depth: None, scene: None, raster: None };
        ctx.run(graph, &inputs).unwrap();
        ctx.download::<f32>(graph.output).unwrap()
    };
    gpu.free_buffer(d);
    gpu.free_buffer(n);
    out
}

/// The synchronisation layer's hazard message for a read after an unsynchronised write.
fn is_read_after_write(message: &str) -> bool {
    message.contains("SYNC-HAZARD-READ-AFTER-WRITE") || message.contains("SYNC-HAZARD-READ_AFTER_WRITE")
}

#[test]
fn a_missing_barrier_is_reported_on_aokits_own_instance() {
    if common::vulkan().is_none() {
        return;
    }
    let gpu = Gpu::new(&GpuOptions { validation: true, ..Default::default() }).unwrap();
    let (graph, depth, normals) = vao_frame(uvec2(48, 40));
    let omitted = pass_after_barrier(&graph);
    let clean = run_once(&gpu, &graph, &depth, &normals, Sabotage::default());
    let messages = gpu.validation_messages();
    assert!(messages.is_empty(), "the intact graph:\n{}", messages.join("\n"));
    let broken =
        run_once(&gpu, &graph, &depth, &normals, Sabotage { omit_barrier_before: Some(omitted), ..Default::default() });
    let messages = gpu.validation_messages();
    eprintln!(
        "without the barrier before pass {omitted} ({}): {} messages",
        graph.passes[omitted].label,
        messages.len()
    );
    assert!(
        messages.iter().any(|m| is_read_after_write(m)),
        "no read-after-write hazard reported without the barrier before pass {omitted}:\n{}",
        messages.join("\n")
    );
    // What lavapipe hides: the result is the same without the barrier.
    assert_eq!(clean.len(), broken.len());
    eprintln!("results identical without the barrier: {}", clean == broken);
}

/// The engine's instance and device (compute queue, no ray tracing), its messages so far.
fn new_engine() -> Option<EngineDevice> {
    EngineDevice::new(&EngineNeeds {
        app_name: c"a sync-validation engine",
        queue_flags: vk::QueueFlags::COMPUTE,
        raster: false,
        ray_tracing: RayTracing::Off,
    })
}

#[test]
fn a_missing_barrier_is_reported_on_an_engine_owned_instance() {
    let Some(engine) = new_engine() else { return };
    let (graph, depth, normals) = vao_frame(uvec2(48, 40));
    let omitted = pass_after_barrier(&graph);
    {
        let gpu = Gpu::from_external(engine.external()).unwrap();
        run_once(&gpu, &graph, &depth, &normals, Sabotage::default());
        let messages = engine.messages.lock().unwrap().clone();
        assert!(messages.is_empty(), "the intact graph:\n{}", messages.join("\n"));
        run_once(&gpu, &graph, &depth, &normals, Sabotage { omit_barrier_before: Some(omitted), ..Default::default() });
    }
    let messages = engine.destroy_with(|_| {});
    assert!(
        messages.iter().any(|m| is_read_after_write(m)),
        "no read-after-write hazard reported on the engine's instance:\n{}",
        messages.join("\n")
    );
}

/// What the engine of [`frames_in_flight`] saw: every frame's AO, and each free of a resource
/// whose last frame it had not yet waited for (the use-after-free check).
struct Frames {
    ao: Vec<Vec<f32>>,
    /// `(frame index in the sequence whose record freed it, what)`.
    early_frees: Vec<(usize, String)>,
}

/// The engine's frames in flight: `ring` command buffers and fences it owns; frame F waits for
/// frame F − ring's fence before it records. Each frame runs the vao graph of the next size of
/// `sizes` through one context (a resize re-makes its buffers and retires the old ones, freed
/// FRAMES_IN_FLIGHT frames later) and copies its output into a buffer of the engine's.
///
/// The use-after-free check: aokit reports each retired resource it frees with the last frame
/// that may use it; the engine knows which frames it has waited for, so a free before that
/// frame's fence was waited is recorded, whether or not the device happened to be finished.
fn frames_in_flight(engine: &EngineDevice, ring: usize, sizes: &[UVec2], sabotage: Sabotage) -> Frames {
    let d = &engine.device;
    let gpu = Gpu::from_external(engine.external()).unwrap();
    let pool_info = vk::CommandPoolCreateInfo::default()
        .queue_family_index(engine.family)
        .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER);
    let pool = unsafe { d.create_command_pool(&pool_info, None) }.unwrap();
    let info = vk::CommandBufferAllocateInfo::default().command_pool(pool).command_buffer_count(ring as u32);
    let cmds = unsafe { d.allocate_command_buffers(&info) }.unwrap();
    let signalled = vk::FenceCreateInfo::default().flags(vk::FenceCreateFlags::SIGNALED);
    let fences: Vec<_> = (0..ring).map(|_| unsafe { d.create_fence(&signalled, None) }.unwrap()).collect();
    let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
    // The last frame (1-based, as aokit counts `record` calls) whose fence the engine waited for.
    let waited_through = Arc::new(AtomicU64::new(0));
    let early_frees = Arc::new(Mutex::new(Vec::new()));
    // The frame (index into `sizes`) being recorded, to say which record freed too early.
    let recording = Arc::new(AtomicU64::new(0));
    let mut ctx = AoContext::new(&gpu);
    ctx.sabotage(sabotage);
    let (waited, early, now) = (waited_through.clone(), early_frees.clone(), recording.clone());
    ctx.audit_frees(Box::new(move |last_used| {
        let waited = waited.load(Ordering::Relaxed);
        if last_used > waited {
            let f = now.load(Ordering::Relaxed) as usize;
            early.lock().unwrap().push((
                f,
                format!("a resource of frame {last_used} freed while the engine had waited only for frame {waited}"),
            ));
        }
    }));
    // Inputs per frame slot, freed once the slot's fence says the frame finished.
    let mut slots: Vec<Option<(Buffer, Buffer)>> = (0..ring).map(|_| None).collect();
    let mut outputs = Vec::new();
    for (f, &inner) in sizes.iter().enumerate() {
        let k = f % ring;
        unsafe { d.wait_for_fences(&[fences[k]], true, u64::MAX) }.unwrap();
        waited_through.store((f + 1).saturating_sub(ring) as u64, Ordering::Relaxed);
        recording.store(f as u64, Ordering::Relaxed);
        if let Some((a, b)) = slots[k].take() {
            gpu.free_buffer(a);
            gpu.free_buffer(b);
        }
        let (graph, depth, normals) = vao_frame(inner);
        let (dep, nor) = (gpu.upload(&depth, storage).unwrap(), gpu.upload(&normals, storage).unwrap());
        let pixels = graph.view.size().element_product() as usize;
        let copy = gpu.upload(&vec![0f32; pixels], storage).unwrap();
        unsafe {
            d.reset_fences(&[fences[k]]).unwrap();
            d.begin_command_buffer(cmds[k], &vk::CommandBufferBeginInfo::default()).unwrap();
        }
        let inputs = GpuInputs { depth: &dep, normals: &nor, second_depth: None, scene: None, raster: None };
        ctx.record(cmds[k], &graph, &inputs).unwrap();
        let output = ctx.buffer(graph.output).expect("the graph's output");
        assert_eq!(output.size, copy.size, "frame {f}: the output holds one f32 per pixel");
        let region = [vk::BufferCopy::default().size(copy.size)];
        let submit = [vk::SubmitInfo::default().command_buffers(&cmds[k..k + 1])];
        unsafe {
            d.cmd_copy_buffer(cmds[k], output.raw, copy.raw, &region);
            d.end_command_buffer(cmds[k]).unwrap();
            d.queue_submit(engine.queue, &submit, fences[k]).unwrap();
        }
        ctx.invalidate_bindings();
        slots[k] = Some((dep, nor));
        outputs.push(copy);
    }
    unsafe { d.device_wait_idle() }.unwrap();
    waited_through.store(sizes.len() as u64, Ordering::Relaxed);
    drop(ctx);
    let ao = outputs
        .into_iter()
        .map(|b| {
            let ao = gpu.download::<f32>(&b).unwrap();
            gpu.free_buffer(b);
            ao
        })
        .collect();
    for (a, b) in slots.into_iter().flatten() {
        gpu.free_buffer(a);
        gpu.free_buffer(b);
    }
    unsafe {
        for f in fences {
            d.destroy_fence(f, None);
        }
        d.destroy_command_pool(pool, None);
    }
    let early_frees = early_frees.lock().unwrap().clone();
    Frames { ao, early_frees }
}

/// A resize sequence (each resize re-makes the context's buffers while earlier frames may be
/// pending) that returns to earlier sizes.
const RESIZES: [UVec2; 6] = [uvec2(48, 40), uvec2(64, 48), uvec2(64, 48), uvec2(56, 40), uvec2(48, 40), uvec2(80, 56)];

/// 2 and 3 frames in flight through [`RESIZES`]: no validation message (core and
/// synchronisation), no resource freed before the engine waited for its frame, and EVERY
/// frame's AO agrees with cpu-sim's run of the same graph at that size.
#[test]
fn frames_in_flight_through_resizes_agree_with_cpu_sim() {
    for ring in [2, 3] {
        let Some(engine) = new_engine() else { return };
        let frames = frames_in_flight(&engine, ring, &RESIZES, Sabotage::default());
        let messages = engine.destroy_with(|_| {});
        assert!(messages.is_empty(), "{ring} frames in flight:\n{}", messages.join("\n"));
        assert!(frames.early_frees.is_empty(), "{ring} frames in flight: {:?}", frames.early_frees);
        assert_eq!(frames.ao.len(), RESIZES.len());
        for (f, (ao, &inner)) in frames.ao.iter().zip(&RESIZES).enumerate() {
            let (graph, depth, normals) = vao_frame(inner);
            let mut cpu = aokit_cpu::graph::CpuExecutor::new();
            let progress = &aokit_cpu::no_progress;
            let inputs = aokit_cpu::graph::CpuInputs {
                depth: &depth,
                normals: &normals,
                second_depth: None,
                scene: None,
                progress,
            };
            cpu.run(&graph, &inputs).unwrap();
            let agreement = common::agreement::inner(&graph.view, cpu.f32(graph.output).unwrap(), ao);
            let what = format!("{ring} in flight, frame {f} at {inner} vs cpu-sim");
            eprintln!("{}", agreement.line(&what));
            agreement.assert_exact(&what);
            assert!(agreement.occluded > 0.01, "{what}: the step must occlude");
        }
    }
}

/// The positive control of the use-after-free check: a context that frees what a resize
/// replaced at once (`Sabotage::free_retired_at_once`), while the frame that used it may be
/// pending, is caught in the record of EVERY frame that resizes, with 2 and 3 frames in flight.
/// The validation layer may also see it (VUID-vkDestroyBuffer-buffer-00922) when lavapipe has
/// not yet finished that frame; lavapipe usually has, so the layer's count is logged, not
/// asserted.
#[test]
fn a_resource_freed_before_its_frames_fence_is_caught() {
    let sabotage = Sabotage { free_retired_at_once: true, ..Default::default() };
    let resizing: Vec<usize> = (1..RESIZES.len()).filter(|&f| RESIZES[f] != RESIZES[f - 1]).collect();
    for ring in [2, 3] {
        let Some(engine) = new_engine() else { return };
        let frames = frames_in_flight(&engine, ring, &RESIZES, sabotage);
        let messages = engine.destroy_with(|_| {});
        eprintln!(
            "{ring} in flight, freed at once: {} early frees caught, {} validation messages",
            frames.early_frees.len(),
            messages.len()
        );
        for &f in &resizing {
            assert!(
                frames.early_frees.iter().any(|(at, _)| *at == f),
                "{ring} in flight: the resize in frame {f} ({}) freed nothing too early that the check saw: {:?}",
                RESIZES[f],
                frames.early_frees
            );
        }
    }
}
