//! The generated WGSL (`assets/wgsl/`) run through wgpu by a consumer that follows the manifest
//! alone — as an engine without Rust would: the technique's graph for the settings is the
//! manifest's variant (`techniques[].variants`), its sizes and dispatches the variant's
//! expressions, its data the `contents` (tables, records), its push constants the constants'
//! expressions (`aokit_contract::expr`, the grammar of `assets/README.md`); nothing comes from
//! the Rust `Graph`. Every WebGPU-capable technique at its defaults and at non-default settings
//! runs on wgpu's Vulkan back-end with WebGPU's default limits, and its AO is compared with
//! cpu-sim (which runs the Rust graph) on the same G-buffer: ≥ 99.9 % of the inner pixels within
//! 1/255 and MSE ≤ 1e-6, the conformance bar of `assets/README.md`. Four of them also run at half
//! resolution, built as `assets/README.md` ("Half resolution") tells from `half_resolution` around
//! the published variant, against cpu-sim's half-resolution graph; and gtao with the temporal
//! accumulation built from `temporal` runs a three-frame orbit, its history kept in persistent
//! buffers.

mod common;

use aokit::render::CpuRenderer;
use aokit::technique::Technique;
use aokit_contract::constants::{FrameInputs, evaluate_struct, inputs};
use aokit_contract::expr::{Inputs, Value, eval};
use aokit_contract::graphs::data_words;
use aokit_contract::manifest::{
    HalfResolutionManifest, Manifest, ModuleManifest, PassManifest, ResourceManifest, TechniqueManifest,
    TemporalManifest, VariantManifest,
};
use aokit_cpu::graph::{CpuExecutor, CpuInputs};
use aokit_cpu::no_progress;
use aokit_shaders::halfres::settings::Resolution;
use aokit_shaders::technique::Registered;
use std::collections::HashMap;
use wgpu::util::DeviceExt;

/// Every technique the browser and wgpu run (compute passes with WGSL on depth and normals),
/// at its defaults and at these settings (at least three each, graph-changing ones included).
const RUNS: [&str; 21] = [
    "vao",
    "vao:kernel=hbao",
    "vao:ao-samples=16",
    "vao:kernel=hbao:ao-samples=32",
    "hbao",
    "hbao:ao-samples=16",
    "hbao:ao-samples=32",
    "hbao:peel-separation=0.2:ao-samples=16",
    "gtao",
    "gtao:preset=low:denoise=2",
    "gtao:preset=ultra:normals=depth",
    "gtao:bent-normals=on:denoise=0:falloff-range=0.3",
    "vbao",
    "vbao:denoise=0",
    "vbao:normals=depth:sectors=touch",
    "vbao:weighting=cosine-exact:gate=radius:thickness=0.3",
    "raymarch",
    "raymarch:directions=8:kernel=vogel:denoise=1",
    "raymarch:directions=24:steps=4:contribution=binary",
    "raymarch:alpha=2:denoise=3",
    "raymarch:directions=61:kernel=vogel",
];

/// Techniques that also run at half resolution, built from the manifest's `half_resolution`
/// around their published variant.
const HALF_RUNS: [&str; 4] = ["vao", "gtao", "vbao:weighting=cosine-exact", "raymarch"];

/// wgpu's device on the Vulkan back-end; `None` when there is none and the run allows the skip.
fn device() -> Option<(wgpu::Device, wgpu::Queue, String)> {
    let adapter = common::wgpu_adapter::vulkan()?;
    let name = adapter.get_info().name;
    // WebGPU's default limits: what a browser gives.
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default())).unwrap();
    Some((device, queue, name))
}

fn count(text: &str, inputs: &Inputs) -> u32 {
    match eval(text, inputs) {
        Ok(Value::Int(n)) if n >= 0 => n as u32,
        other => panic!("'{text}' = {other:?}, not a count"),
    }
}

/// What a consumer runs, built from the manifest alone: resources and passes, each with the
/// inputs its expressions are evaluated with and the declaration whose constants it pushes.
struct Plan<'a> {
    resources: Vec<(ResourceManifest, &'a Inputs, &'static dyn Registered)>,
    passes: Vec<(PassManifest, &'a Inputs, &'static dyn Registered)>,
    output: String,
}

/// `variant` of `t` as it is published, every expression with `inputs`.
fn full_plan<'a>(t: &'static dyn Registered, variant: &VariantManifest, inputs: &'a Inputs) -> Plan<'a> {
    Plan {
        resources: variant.resources.iter().map(|r| (r.clone(), inputs, t)).collect(),
        passes: variant.passes.iter().map(|p| (p.clone(), inputs, t)).collect(),
        output: variant.output.clone(),
    }
}

/// `variant` of `t` at half resolution, as `assets/README.md` ("Half resolution") tells a
/// consumer to build it from `half_resolution`: the variant with the half frame's names
/// (`halved`) and its inputs renamed, between `before` and `after` (with the full frame's names
/// and the transform's settings, `transform`).
fn half_plan<'a>(
    half: &HalfResolutionManifest,
    (t, variant): (&'static dyn Registered, &VariantManifest),
    halved: &'a Inputs,
    full: &'a Inputs,
    transform: &'a Inputs,
) -> Plan<'a> {
    let ht: &'static dyn Registered = &aokit_shaders::halfres::settings::HALF_RESOLUTION;
    Plan {
        resources: variant
            .resources
            .iter()
            .map(|r| (r.clone(), halved, t))
            .chain(half.resources.iter().map(|r| (r.clone(), full, ht)))
            .collect(),
        passes: half
            .before
            .iter()
            .map(|p| (p.clone(), transform, ht))
            .chain(variant.passes.iter().map(|p| (p.bound(&variant.output, &half.renamed_inputs), halved, t)))
            .chain(half.after.iter().map(|p| (p.bound(&variant.output, &[]), transform, ht)))
            .collect(),
        output: half.output.clone(),
    }
}

/// `variant` of `t` followed by the temporal accumulation, as `assets/README.md` ("Temporal
/// accumulation") tells a consumer to build it from `temporal`: the variant with `inputs`, then
/// `after`, its record and constants from `transform` (the accumulation's settings, the frame
/// and the previous frame's camera).
fn temporal_plan<'a>(
    temporal: &TemporalManifest,
    (t, variant): (&'static dyn Registered, &VariantManifest),
    inputs: &'a Inputs,
    transform: &'a Inputs,
) -> Plan<'a> {
    let tt: &'static dyn Registered = &aokit_shaders::temporal::settings::TEMPORAL;
    let mut plan = full_plan(t, variant, inputs);
    plan.resources.extend(temporal.resources.iter().map(|r| (r.clone(), transform, tt)));
    plan.passes.extend(temporal.after.iter().map(|p| (p.bound(&variant.output, &[]), transform, tt)));
    plan.output = temporal.output.clone();
    plan
}

/// Run `plan` through wgpu from the WGSL files, everything from the manifest; returns the
/// output resource as `f32`.
fn run_on_wgpu(
    (device, queue): (&wgpu::Device, &wgpu::Queue),
    manifest: &Manifest,
    plan: &Plan,
    depth: &[f32],
    normals: &[u32],
    persistent: &mut HashMap<String, wgpu::Buffer>,
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
    buffers.insert("linear_depth", init("depth", bytemuck::cast_slice(depth)));
    buffers.insert("view_normals", init("normals", normals));
    for (r, inputs, t) in &plan.resources {
        // A persistent resource keeps its buffer (and contents) from the last run.
        if let Some(kept) = persistent.get(&r.name).filter(|_| r.lifetime == "persistent") {
            buffers.insert(&r.name, kept.clone());
            continue;
        }
        let mut words = vec![0u32; count(&r.size, inputs) as usize];
        if let Some(bits) = r.init.strip_prefix("fill 0x") {
            words.fill(u32::from_str_radix(bits, 16).unwrap());
        } else if r.init == "data" {
            let data = data_words(*t, r.contents.as_ref().expect("contents"), inputs, &manifest.tables).unwrap();
            assert_eq!(data.len(), words.len(), "{}: contents and size", r.name);
            words = data;
        }
        buffers.insert(&r.name, init(&r.name, &words));
        if r.lifetime == "persistent" {
            persistent.insert(r.name.clone(), buffers[r.name.as_str()].clone());
        }
    }
    let mut encoder = device.create_command_encoder(&Default::default());
    let mut seen: HashMap<&str, i64> = HashMap::new();
    for (pass, inputs, t) in &plan.passes {
        let mut inputs = (*inputs).clone();
        let module = manifest.modules.iter().find(|m| m.entry_point == pass.entry).expect("a module");
        let wgsl = module.wgsl.as_ref().unwrap_or_else(|| panic!("{} has no WGSL", pass.entry));
        let source =
            std::fs::read_to_string(format!("{}/assets/wgsl/{}", env!("CARGO_MANIFEST_DIR"), wgsl.file)).unwrap();
        let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(&pass.entry),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        // The push constants from the expressions (`pass`: this pass's index among its
        // module's), as a uniform buffer (16-byte multiple) at the manifest's binding.
        let index = seen.entry(&pass.entry).or_insert(0);
        inputs.names.insert("pass".into(), Value::Int(*index));
        *index += 1;
        let push = module.push_constants.as_ref().map(|name| evaluate_struct(*t, name, &inputs).unwrap());
        // Specialized as the manifest says (the Vulkan executor does the same).
        let specialization = specialization(manifest, module, push.as_deref().unwrap_or(&[]));
        let overrides: Vec<(&str, f64)> = specialization.iter().map(|(id, v)| (id.as_str(), *v)).collect();
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(&pass.entry),
            layout: None,
            module: &shader,
            entry_point: Some(wgsl.entry_point.as_deref().unwrap_or(&pass.entry)),
            compilation_options: wgpu::PipelineCompilationOptions { constants: &overrides, ..Default::default() },
            cache: None,
        });
        let mut entries: Vec<wgpu::BindGroupEntry> = pass
            .bindings
            .iter()
            .filter(|b| module.bindings.iter().any(|m| m.binding == b.0))
            .map(|b| wgpu::BindGroupEntry { binding: b.0, resource: buffers[b.1.as_str()].as_entire_binding() })
            .collect();
        let constants;
        if let (Some(mut bytes), Some(binding)) = (push, wgsl.constants_binding) {
            bytes.resize(bytes.len().next_multiple_of(16), 0);
            constants = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("constants"),
                contents: &bytes,
                usage: wgpu::BufferUsages::UNIFORM,
            });
            entries.push(wgpu::BindGroupEntry { binding, resource: constants.as_entire_binding() });
        }
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(&pass.entry),
            layout: &pipeline.get_bind_group_layout(0),
            entries: &entries,
        });
        let [x, y] = [count(&pass.dispatch[0], &inputs), count(&pass.dispatch[1], &inputs)];
        let workgroup = module.workgroup_size.expect("a compute module");
        let mut cpass = encoder.begin_compute_pass(&Default::default());
        cpass.set_pipeline(&pipeline);
        cpass.set_bind_group(0, &group, &[]);
        cpass.dispatch_workgroups(x.div_ceil(workgroup[0]), y.div_ceil(workgroup[1]), 1);
    }
    let output = &buffers[plan.output.as_str()];
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
    bytemuck::cast_slice(&readback.slice(..).get_mapped_range().expect("mapped range")).to_vec()
}

/// The variant of `t` whose `when` holds `values`.
fn variant_of<'a>(t: &'a TechniqueManifest, values: &[(&str, String)]) -> &'a VariantManifest {
    let hits = aokit_contract::graphs::matching(&t.variants, values);
    assert_eq!(hits.len(), 1, "{}: {} variants match {values:?}", t.name, hits.len());
    hits[0]
}

#[test]
fn every_webgpu_technique_from_the_manifest_alone_on_wgpu_agrees_with_cpu_sim() {
    let Some((device, queue, name)) = device() else { return };
    let manifest = Manifest::committed();
    let mut failures = Vec::new();
    for scene_name in ["sponza", "kitchen"] {
        let (scene, frame) = common::builtin_frame(scene_name, 160, 96, 16);
        let renderer = CpuRenderer::new(&scene);
        let (g, _) = renderer.gbuffer(&frame, &no_progress);
        let camera = FrameInputs {
            eye: frame.eye,
            target: frame.target,
            up: frame.up,
            fov_y: frame.fov_deg.to_radians(),
            inner: frame.inner,
            guard: frame.camera.view.guard,
            near: frame.camera.view.near,
            far: frame.camera.view.far,
            radius: frame.radius,
            exponent: frame.exponent,
            thickness: frame.thickness,
            frame_index: 0,
            previous: None,
        };
        let half = manifest.half_resolution.as_ref().expect("the manifest's half_resolution");
        let ht: &'static dyn Registered = &aokit_shaders::halfres::settings::HALF_RESOLUTION;
        let runs = RUNS.iter().map(|s| (*s, false)).chain(HALF_RUNS.iter().map(|s| (*s, true)));
        for (spec, at_half) in runs {
            let mut technique = Technique::parse(spec).unwrap();
            let registered = aokit_shaders::techniques::find(technique.name()).unwrap();
            let listed = manifest.techniques.iter().find(|t| t.name == technique.name()).unwrap();
            let values = technique.values();
            let variant = variant_of(listed, &values);
            let ins = inputs(&registered.rows(), &values, &camera).unwrap();
            let on_wgpu = if at_half {
                technique = technique.with_resolution(Resolution::half());
                // The half frame's names from `half_names`, each from the full frame's values.
                let mut halved = ins.clone();
                for (name, text) in &half.half_names {
                    halved.names.insert(name.clone(), eval(text, &ins).unwrap());
                }
                let transform = inputs(&ht.rows(), &ht.configure().values(), &camera).unwrap();
                let plan = half_plan(half, (registered, variant), &halved, &ins, &transform);
                run_on_wgpu((&device, &queue), &manifest, &plan, &g.depth, &g.normals, &mut HashMap::new())
            } else {
                let plan = full_plan(registered, variant, &ins);
                run_on_wgpu((&device, &queue), &manifest, &plan, &g.depth, &g.normals, &mut HashMap::new())
            };
            let spec = if at_half { format!("{spec} (half resolution)") } else { spec.to_string() };
            // cpu-sim runs the Rust graph.
            let graph = technique.graph(&frame.desc()).unwrap();
            let cpu_inputs = CpuInputs {
                depth: &g.depth,
                normals: &g.normals,
                second_depth: None,
                scene: None,
                progress: &no_progress,
            };
            let mut cpu = CpuExecutor::new();
            cpu.run(&graph, &cpu_inputs).unwrap();
            let view = graph.view;
            let (a, b) = (
                aokit::output::crop_inner(&view, cpu.f32(graph.output).unwrap()),
                aokit::output::crop_inner(&view, &on_wgpu),
            );
            assert_eq!((a.len(), b.len()), (160 * 96, 160 * 96), "{spec}: inner image lengths");
            let n = a.len() as f64;
            let within =
                a.iter().zip(&b).filter(|(x, y)| (*x - *y).abs() <= common::agreement::STEP).count() as f64 / n;
            let mse = a.iter().zip(&b).map(|(x, y)| ((x - y) as f64).powi(2)).sum::<f64>() / n;
            let occluded = a.iter().filter(|&&v| v < 0.9).count() as f64 / n;
            eprintln!(
                "{scene_name:8} {spec:52} wgpu ({name}) vs cpu-sim: {:7.3} % within 1/255, MSE {mse:.2e}, occluded {:.1} %",
                100.0 * within,
                100.0 * occluded
            );
            if occluded <= 0.02 {
                failures
                    .push(format!("{scene_name} {spec}: the image must show occlusion ({:.1} %)", 100.0 * occluded));
            }
            if within < common::agreement::MIN_WITHIN || mse > common::agreement::MAX_MSE {
                failures.push(format!("{scene_name} {spec}: {:.3} % within 1/255, MSE {mse:.2e}", 100.0 * within));
            }
        }
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

/// The temporal accumulation from the manifest alone (`temporal`) over a three-frame orbit with
/// animated noise, the history in persistent buffers from run to run: gtao's accumulated last
/// frame on wgpu agrees with cpu-sim's (the Rust graph, one executor) within the conformance bar,
/// and on both it differs from the frame without accumulation on ≥ 20 % of the inner pixels (the
/// history was read).
#[test]
fn the_temporal_accumulation_from_the_manifest_alone_agrees_with_cpu_sim() {
    use aokit::path::{Noise, PathKind, PathSpec, path_frames};
    use aokit_contract::constants::PreviousView;
    use aokit_shaders::temporal::settings::TemporalSettings;
    let Some((device, queue, name)) = device() else { return };
    let manifest = Manifest::committed();
    let temporal = manifest.temporal.as_ref().expect("the manifest's temporal");
    let tt: &'static dyn Registered = &aokit_shaders::temporal::settings::TEMPORAL;
    let (scene, base) = common::builtin_frame("sponza", 160, 96, 16);
    let renderer = CpuRenderer::new(&scene);
    let spec = PathSpec { kind: PathKind::Orbit, frames: 3, step: 0.5 };
    let frames = path_frames(&base, &spec, Noise::Animated, Some(TemporalSettings::default()));
    let technique = Technique::named("gtao").unwrap();
    let registered = aokit_shaders::techniques::find("gtao").unwrap();
    let listed = manifest.techniques.iter().find(|t| t.name == "gtao").unwrap();
    let values = technique.values();
    let variant = variant_of(listed, &values);
    let mut executor = CpuExecutor::new();
    let mut history = HashMap::new();
    let (mut on_cpu, mut on_wgpu, mut gbuffer) = (Vec::new(), Vec::new(), None);
    let inputs_of = |f: &aokit::frame::Frame, previous: Option<&aokit::frame::Frame>| FrameInputs {
        eye: f.eye,
        target: f.target,
        up: f.up,
        fov_y: f.fov_deg.to_radians(),
        inner: f.inner,
        guard: f.camera.view.guard,
        near: f.camera.view.near,
        far: f.camera.view.far,
        radius: f.radius,
        exponent: f.exponent,
        thickness: f.thickness,
        frame_index: f.frame_index,
        previous: previous.map(|p| PreviousView {
            eye: p.eye,
            target: p.target,
            up: p.up,
            fov_y: p.fov_deg.to_radians(),
            near: p.camera.view.near,
            far: p.camera.view.far,
        }),
    };
    for (i, frame) in frames.iter().enumerate() {
        let (g, _) = renderer.gbuffer(frame, &no_progress);
        let camera = inputs_of(frame, i.checked_sub(1).map(|p| &frames[p]));
        let ins = inputs(&registered.rows(), &values, &camera).unwrap();
        let transform = inputs(&tt.rows(), &tt.configure().values(), &camera).unwrap();
        let plan = temporal_plan(temporal, (registered, variant), &ins, &transform);
        on_wgpu = run_on_wgpu((&device, &queue), &manifest, &plan, &g.depth, &g.normals, &mut history);
        on_cpu = renderer.run_with(&mut executor, frame, &g, &technique, &no_progress).ao_final;
        gbuffer = Some(g);
    }
    let last = aokit::frame::Frame { temporal: None, ..frames[2].clone() };
    let plain = renderer.run(&last, gbuffer.as_ref().unwrap(), &technique, &no_progress).ao_final;
    let view = base.camera.view;
    let within = common::inner_within(&view, &on_cpu, &on_wgpu, common::agreement::STEP);
    let used_cpu = 1.0 - common::inner_within(&view, &on_cpu, &plain, common::agreement::STEP);
    let used_wgpu = 1.0 - common::inner_within(&view, &on_wgpu, &plain, common::agreement::STEP);
    eprintln!(
        "temporal gtao from the manifest, wgpu ({name}) vs cpu-sim: {:.3} % within 1/255; history changed {:.1} % \
         (cpu-sim), {:.1} % (wgpu)",
        100.0 * within,
        100.0 * used_cpu,
        100.0 * used_wgpu
    );
    assert!(within >= common::agreement::MIN_WITHIN, "{within}");
    assert!(used_cpu > 0.2 && used_wgpu > 0.2, "{used_cpu} {used_wgpu}");
}

/// A module's WGSL overrides for push-constant bytes `push`, as `assets/README.md` tells a consumer
/// to derive them from the manifest: `specialized` 1, every other constant the 4 bytes of the
/// push-constant field of its name (found in nested structs too), keyed by `@id`.
fn specialization(manifest: &Manifest, module: &ModuleManifest, push: &[u8]) -> Vec<(String, f64)> {
    fn offset(manifest: &Manifest, ty: &str, name: &str) -> Option<usize> {
        let s = manifest.structs.iter().find(|s| s.name == ty)?;
        s.fields.iter().find_map(|f| {
            if f.name == name && f.size == 4 {
                Some(f.offset as usize)
            } else {
                offset(manifest, &f.ty, name).map(|o| f.offset as usize + o)
            }
        })
    }
    module
        .specialization
        .iter()
        .map(|c| {
            let value = if c.name == "specialized" {
                1
            } else {
                let at = offset(manifest, module.push_constants.as_deref().expect("push constants"), &c.name)
                    .unwrap_or_else(|| panic!("spec constant {} names no push-constant field", c.name));
                u32::from_le_bytes(push[at..at + 4].try_into().unwrap())
            };
            (c.id.to_string(), f64::from(value))
        })
        .collect()
}
