//! Each binding declared once: the entry points' signatures (`#[kernel]`,
//! `aokit_shaders::kernel`) are what the graphs bind, what the committed SPIR-V holds and what
//! the CPU runs.
//!
//! - every committed module has exactly one declaration, and every declaration a module;
//! - a pass that binds other than what its kernel declares (an access, a missing or an extra
//!   slot) or runs a kernel of the wrong stage is refused by `Graph::validate`, which both
//!   executors call;
//! - the generated CPU drivers (the entry point itself, once per invocation) reproduce this
//!   crate's whole-image runners on real frames — so a slot the runners read from the wrong
//!   binding, or a driver binding buffers out of order, shows as a difference.

mod common;

use aokit::render::CpuRenderer;
use aokit::technique::Technique;
use aokit_contract::manifest::Manifest;
use aokit_cpu::graph::{CpuExecutor, CpuInputs, CpuScene};
use aokit_shaders::graph::{Access, Binding, Graph, PassKind};
use aokit_shaders::kernel::Kernel;

#[test]
fn every_committed_module_is_declared_once() {
    let declared: Vec<&str> = Kernel::all().iter().map(|k| k.entry).collect();
    let mut unique = declared.clone();
    unique.dedup();
    assert_eq!(unique, declared, "entry names are unique");
    let mut committed: Vec<String> = Manifest::committed().modules.iter().map(|m| m.entry_point.clone()).collect();
    committed.sort();
    assert_eq!(committed, declared, "the committed modules are the declared entry points");
    assert_eq!(declared.len(), aokit_vulkan::modules::ALL.len(), "every module is embedded");
    // The Vulkan executor sizes descriptor-set layouts, push-constant ranges and dispatches from
    // the declarations: they must be the modules' own (reflected from the SPIR-V).
    for m in &Manifest::committed().modules {
        let k = Kernel::find(&m.entry_point).unwrap();
        assert_eq!(k.push_constant_bytes(), m.push_constant_bytes, "{}: push-constant bytes", k.entry);
        let slots = m.bindings.iter().map(|b| b.binding + 1).max().unwrap_or(0);
        assert_eq!(k.slot_count(), slots, "{}: descriptor slots", k.entry);
        if let Some(workgroup) = m.workgroup_size {
            assert_eq!(k.threads, workgroup, "{}: workgroup size", k.entry);
        }
    }
    // The generated CPU drivers: every compute kernel of plain storage buffers has one.
    let drivable: Vec<&str> = Kernel::all().iter().filter(|k| k.cpu.is_some()).map(|k| k.entry).collect();
    for entry in ["vao_main", "blur_main", "gtao_main", "gtao_denoise", "vbao_main", "raymarch_main", "temporal_store"]
    {
        assert!(drivable.contains(&entry), "{entry} has a generated CPU driver: {drivable:?}");
    }
    for entry in ["raysd_rgen", "raysd_rq", "gbuffer_fs", "import_depth"] {
        assert!(!drivable.contains(&entry), "{entry} cannot have one");
    }
}

fn vao_graph() -> Graph {
    let (_, frame) = common::builtin_frame("cornell", 48, 32, 4);
    Technique::named("vao").unwrap().graph(&frame.desc()).unwrap()
}

#[test]
fn a_pass_binds_exactly_what_its_kernel_declares() {
    let graph = vao_graph();
    graph.validate().expect("the declared graph");
    assert_eq!(graph.passes[0].entry(), "vao_main");

    let mut wrong_access = graph.clone();
    wrong_access.passes[0].bindings[2].access = Access::ReadWrite;
    let e = wrong_access.validate().unwrap_err();
    assert!(e.contains("slot 2 (ao)") && e.contains("declares Write"), "{e}");

    let mut missing = graph.clone();
    missing.passes[0].bindings.remove(1);
    let e = missing.validate().unwrap_err();
    assert!(e.contains("leaves slot 1 (normals) unbound"), "{e}");

    let mut extra = graph.clone();
    extra.passes[0].bindings.push(Binding { slot: 7, resource: "ao", access: Access::Read });
    let e = extra.validate().unwrap_err();
    assert!(e.contains("binds slot 7, which the kernel does not declare"), "{e}");

    // A compute kernel run as a raster pass's fragment shader.
    let mut wrong_stage = graph.clone();
    wrong_stage.passes[0].kind = PassKind::Raster { vertex: &aokit_shaders::gbuffer::gbuffer_vs::ENTRY };
    let e = wrong_stage.validate().unwrap_err();
    assert!(e.contains("vao_main is a compute kernel where the pass needs a fragment one"), "{e}");
}

/// `technique` on a Cornell-box frame through the runners and through the generated drivers:
/// the largest difference of the output over the inner image, and how many passes the generated
/// drivers ran.
fn runners_vs_generated(technique: &str) -> (f32, usize) {
    let (scene, frame) = common::builtin_frame("cornell", 96, 64, 8);
    let renderer = CpuRenderer::new(&scene);
    let surfaces = renderer.surfaces();
    let (gbuffer, _) = renderer.gbuffer(&frame, &aokit_cpu::no_progress);
    let graph = Technique::named(technique).unwrap().graph(&frame.desc()).unwrap();
    let inputs = CpuInputs {
        depth: &gbuffer.depth,
        normals: &gbuffer.normals,
        second_depth: None,
        scene: Some(CpuScene { bvh: renderer.bvh(), surfaces: &surfaces }),
        progress: &aokit_cpu::no_progress,
    };
    let mut runners = CpuExecutor::new();
    runners.run(&graph, &inputs).unwrap();
    let mut generated = CpuExecutor::generated_drivers_first();
    generated.run(&graph, &inputs).unwrap();
    let (a, b) = (runners.f32(graph.output).unwrap(), generated.f32(graph.output).unwrap());
    let (a, b) = common::inner_pair(&graph.view, a, b);
    let occluded = a.iter().filter(|&&v| v < 0.9).count();
    assert!(occluded * 20 >= a.len(), "{technique}: the frame must show occlusion ({occluded} of {})", a.len());
    let max = a.iter().zip(&b).map(|(x, y)| (x - y).abs()).fold(0.0, f32::max);
    let driven = graph.passes.iter().filter(|p| p.kernel.cpu.is_some()).count();
    (max, driven)
}

/// The runners evaluate the same per-pixel functions over 16-pixel lanes, so the two agree to
/// float rounding; a binding read from the wrong slot changes the AO by far more than 1/255.
#[test]
fn generated_cpu_drivers_reproduce_the_runners() {
    for technique in ["vao", "hbao", "gtao", "vbao", "vbao-sd", "raymarch"] {
        let (max, driven) = runners_vs_generated(technique);
        eprintln!("{technique}: {driven} passes through generated drivers, max |Δ| {max:.2e}");
        assert!(driven >= 1, "{technique}: {driven} generated passes");
        assert!(max <= 1e-5, "{technique}: runners and generated drivers differ by {max}");
    }
}
