//! The generated WGSL (`assets/wgsl/`) run through wgpu — a consumer that shares no code with
//! aokit's executors: every pass of a technique's graph (from the manifest's module entries:
//! WGSL file, bindings, the uniform block's binding) dispatched on wgpu's Vulkan back-end, and
//! the final AO compared with cpu-sim on the same G-buffer, for vao+blur, gtao and raymarch.

mod common;

use aokit::render::CpuRenderer;
use aokit::technique::Technique;
use aokit_contract::manifest::Manifest;
use aokit_cpu::graph::{CpuExecutor, CpuInputs, CpuScene};
use aokit_cpu::no_progress;
use aokit_shaders::graph::{Graph, Init, inputs};
use std::collections::HashMap;
use wgpu::util::DeviceExt;

/// wgpu's device on the Vulkan back-end; `None` when AOKIT_SKIP_VULKAN=1.
fn device() -> Option<(wgpu::Device, wgpu::Queue, String)> {
    if std::env::var_os("AOKIT_SKIP_VULKAN").is_some_and(|v| v == "1") {
        eprintln!("AOKIT_SKIP_VULKAN=1: skipping the wgpu test");
        return None;
    }
    let instance =
        wgpu::Instance::new(&wgpu::InstanceDescriptor { backends: wgpu::Backends::VULKAN, ..Default::default() });
    let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
        .expect("a Vulkan adapter for wgpu (lavapipe: apt-get install mesa-vulkan-drivers)");
    let name = adapter.get_info().name;
    // WebGPU's default limits: what a browser gives.
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default())).unwrap();
    Some((device, queue, name))
}

/// Run `graph` through wgpu from the WGSL files; returns the output resource as `f32`.
fn run_on_wgpu(
    (device, queue): (&wgpu::Device, &wgpu::Queue),
    manifest: &Manifest,
    graph: &Graph,
    depth: &[f32],
    normals: &[u32],
) -> Vec<f32> {
    let usage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST;
    let mut buffers: HashMap<&str, wgpu::Buffer> = HashMap::new();
    let init = |label: &str, words: &[u32]| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(words),
            usage,
        })
    };
    buffers.insert(inputs::LINEAR_DEPTH, init("depth", bytemuck::cast_slice(depth)));
    buffers.insert(inputs::VIEW_NORMALS, init("normals", normals));
    for r in &graph.resources {
        let len = r.len(&graph.view);
        let mut words = vec![0u32; len];
        match &r.init {
            Init::Fill(bits) => words.fill(*bits),
            Init::Data(d) => words[..d.len()].copy_from_slice(d),
            Init::Undefined => {}
        }
        buffers.insert(r.name, init(r.name, &words));
    }
    let mut encoder = device.create_command_encoder(&Default::default());
    for pass in &graph.passes {
        let module = manifest.modules.iter().find(|m| m.entry_point == pass.entry()).expect("a module");
        let wgsl = module.wgsl.as_ref().unwrap_or_else(|| panic!("{} has no WGSL", pass.entry()));
        let source =
            std::fs::read_to_string(format!("{}/assets/wgsl/{}", env!("CARGO_MANIFEST_DIR"), wgsl.file)).unwrap();
        let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(pass.entry()),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(pass.entry()),
            layout: None,
            module: &shader,
            entry_point: Some(pass.entry()),
            compilation_options: Default::default(),
            cache: None,
        });
        // The push constants as a uniform buffer (16-byte multiple), at the manifest's binding.
        let mut bytes = pass.push_constants.clone();
        bytes.resize(bytes.len().next_multiple_of(16).max(16), 0);
        let constants = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("constants"),
            contents: &bytes,
            usage: wgpu::BufferUsages::UNIFORM,
        });
        // Bind only the slots the module declares (the graph may bind unread extra slots).
        let mut entries: Vec<wgpu::BindGroupEntry> = pass
            .bindings
            .iter()
            .filter(|b| module.bindings.iter().any(|m| m.binding == b.slot))
            .map(|b| wgpu::BindGroupEntry { binding: b.slot, resource: buffers[b.resource].as_entire_binding() })
            .collect();
        if let Some(binding) = wgsl.constants_binding {
            entries.push(wgpu::BindGroupEntry { binding, resource: constants.as_entire_binding() });
        }
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(pass.entry()),
            layout: &pipeline.get_bind_group_layout(0),
            entries: &entries,
        });
        let size = pass.invocations(&graph.view);
        let workgroup = module.workgroup_size.expect("a compute module");
        let mut cpass = encoder.begin_compute_pass(&Default::default());
        cpass.set_pipeline(&pipeline);
        cpass.set_bind_group(0, &group, &[]);
        cpass.dispatch_workgroups(size.x.div_ceil(workgroup[0]), size.y.div_ceil(workgroup[1]), 1);
    }
    let output = &buffers[graph.output];
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: output.size(),
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    encoder.copy_buffer_to_buffer(output, 0, &readback, 0, output.size());
    queue.submit([encoder.finish()]);
    readback.slice(..).map_async(wgpu::MapMode::Read, |r| r.expect("mapped"));
    device.poll(wgpu::PollType::wait_indefinitely()).unwrap();
    bytemuck::cast_slice(&readback.slice(..).get_mapped_range()).to_vec()
}

#[test]
fn vao_gtao_and_raymarch_from_wgsl_on_wgpu_agree_with_cpu_sim() {
    let Some((device, queue, name)) = device() else { return };
    let manifest = Manifest::committed();
    let (scene, frame) = common::builtin_frame("sponza", 160, 96, 16);
    let renderer = CpuRenderer::new(&scene);
    let (g, _) = renderer.gbuffer(&frame, &no_progress);
    let surfaces = renderer.surfaces();
    for technique in ["vao", "gtao", "raymarch"] {
        let graph = Technique::named(technique).unwrap().graph(&frame.desc()).unwrap();
        let on_wgpu = run_on_wgpu((&device, &queue), &manifest, &graph, &g.depth, &g.normals);
        let inputs = CpuInputs {
            depth: &g.depth,
            normals: &g.normals,
            second_depth: None,
            scene: Some(CpuScene { bvh: renderer.bvh(), surfaces: &surfaces }),
            progress: &no_progress,
        };
        let mut cpu = CpuExecutor::new();
        cpu.run(&graph, &inputs).unwrap();
        let view = graph.view;
        let (a, b) = (
            aokit::output::crop_inner(&view, cpu.f32(graph.output).unwrap()),
            aokit::output::crop_inner(&view, &on_wgpu),
        );
        assert_eq!(a.len(), b.len());
        let within = a.iter().zip(&b).filter(|(x, y)| (*x - *y).abs() <= 1.0 / 255.0).count() as f64 / a.len() as f64;
        let mse = a.iter().zip(&b).map(|(x, y)| ((x - y) as f64).powi(2)).sum::<f64>() / a.len() as f64;
        let occluded = a.iter().filter(|&&v| v < 0.9).count() as f64 / a.len() as f64;
        eprintln!(
            "{technique} on wgpu ({name}) vs cpu-sim: {:.3} % within 1/255, MSE {mse:.2e}, occluded {:.1} %",
            100.0 * within,
            100.0 * occluded
        );
        assert!(occluded > 0.02, "{technique}: the image must show occlusion");
        // The agreement the Vulkan tests hold these techniques to (tests/vulkan_agreement.rs,
        // tests/gtao.rs, tests/screen_rays.rs).
        assert!(within >= 0.999 || mse <= 1e-5, "{technique}: {:.3} % within 1/255, MSE {mse:.2e}", 100.0 * within);
    }
}
