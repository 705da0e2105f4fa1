//! The pass graphs against the committed SPIR-V: every pass of every graph technique binds
//! exactly the slots its module declares, with the module's access (writable ⇔ the graph
//! writes), its push constants have the module's size, every entry point has a CPU kernel, and
//! the dual-depth variants read the second layer.

mod common;

use aokit::technique::{GroundTruthSettings, GtaoOptions, HybridOptions, RaymarchOptions, SdOptions, Technique};
use aokit_contract::manifest::Manifest;
use aokit_shaders::graph::{Access, Graph, PassKind, RtMode, inputs};
use aokit_shaders::groundtruth::settings::GROUNDTRUTH;
use aokit_shaders::gtao::settings::GTAO;
use aokit_shaders::hybrid::settings::HYBRID;
use aokit_shaders::raymarch::settings::RAYMARCH;
use aokit_shaders::svao::settings::{HBAO, HBAO_SD, RAYSD, RAYSVAO, SDSVAO};
use aokit_shaders::vao::settings::VAO;

/// Every registered technique at its defaults, plus the variants that change the graph.
fn techniques() -> Vec<Technique> {
    let registered = aokit::technique::TECHNIQUES.iter().map(|t| Technique::named(t.name()).unwrap());
    registered
        .chain([
            Technique::new(&VAO, SdOptions::default()),
            Technique::new(&VAO, SdOptions { dual: true, peel_separation: 0.5, ..Default::default() }),
            Technique::new(&HBAO, SdOptions { hbao: true, dual: false, peel_separation: 0.01, ..Default::default() }),
            Technique::new(&HBAO, SdOptions { hbao: true, dual: true, peel_separation: 0.01, ..Default::default() }),
            Technique::new(&RAYSD, SdOptions::default()),
            Technique::new(&HBAO_SD, SdOptions { dual: true, hbao: true, divisor: 2, layers: 8, ..Default::default() }),
            Technique::new(&SDSVAO, SdOptions { raster: true, ..Default::default() }),
            Technique::new(
                &RAYSVAO,
                SdOptions { cutoff: 6.0, dual: true, peel_separation: 0.01, ..Default::default() },
            ),
            Technique::new(&GROUNDTRUTH, GroundTruthSettings { spp: 4, uniform: false }),
            Technique::new(&HYBRID, HybridOptions::default()),
            Technique::new(&HYBRID, HybridOptions { denoise_passes: 0, ..HybridOptions::variant("world").unwrap() }),
            Technique::new(&GTAO, GtaoOptions::default()),
            Technique::new(&GTAO, GtaoOptions { normals_from_depth: true, denoise_passes: 3, ..Default::default() }),
            Technique::new(&RAYMARCH, RaymarchOptions::default()),
            Technique::new(&RAYMARCH, RaymarchOptions { denoise_passes: 2, ..Default::default() }),
        ])
        .collect()
}

fn graphs() -> Vec<(Technique, String, Graph)> {
    let (_, frame) = common::builtin_frame("cornell", 96, 64, 8);
    techniques()
        .into_iter()
        .map(|t| {
            let graph = t.graph(&frame.desc()).unwrap_or_else(|e| panic!("{t:?}: {e}"));
            (t.clone(), format!("{t:?}"), graph)
        })
        .collect()
}

/// Which slots a module declares and whether each is writable (any stage of a ray-tracing
/// pipeline counts).
fn module_slots(manifest: &Manifest, entries: &[&str]) -> Vec<(u32, bool)> {
    let mut slots: Vec<(u32, bool)> = Vec::new();
    for entry in entries {
        let m =
            manifest.modules.iter().find(|m| m.entry_point == *entry).unwrap_or_else(|| panic!("no module {entry}"));
        for b in &m.bindings {
            assert_eq!(b.set, 0, "{entry}: set {}", b.set);
            slots.push((b.binding, b.writable));
        }
    }
    slots.sort();
    slots
}

fn check(manifest: &Manifest, name: &str, graph: &Graph) -> Result<(), String> {
    graph.validate()?;
    for pass in &graph.passes {
        let entries = match pass.kind {
            PassKind::Compute => vec![pass.entry()],
            PassKind::RayTracing { miss, any_hit, .. } => vec![pass.entry(), miss.entry, any_hit.entry],
            PassKind::Raster { vertex } => vec![vertex.entry, pass.entry()],
        };
        // Every slot the module declares is bound with its access; a slot the module does not
        // declare (rust-gpu drops unused parameters) may be bound read-only.
        let want = module_slots(manifest, &entries);
        let mut got: Vec<(u32, bool)> = pass.bindings.iter().map(|b| (b.slot, b.access.writes())).collect();
        got.sort();
        let declared = |slot: u32| want.iter().any(|w| w.0 == slot);
        let extra_written = got.iter().any(|g| !declared(g.0) && g.1);
        let covered: Vec<_> = got.iter().filter(|g| declared(g.0)).copied().collect();
        if covered != want || extra_written {
            return Err(format!("{name}: pass {} binds {got:?}, module declares {want:?}", pass.entry()));
        }
        // The push constants of a pipeline: its largest block (a raster pass's vertex stage).
        let push = entries
            .iter()
            .map(|e| manifest.modules.iter().find(|m| m.entry_point == *e).expect("checked").push_constant_bytes)
            .max()
            .unwrap_or(0);
        if pass.push_constants.len() as u32 != push {
            return Err(format!(
                "{name}: pass {} pushes {} bytes, module takes {push}",
                pass.entry(),
                pass.push_constants.len()
            ));
        }
        if aokit_cpu::graph::cpu_driver(pass.kernel).is_none() {
            return Err(format!("{name}: no CPU kernel for {}", pass.entry()));
        }
    }
    Ok(())
}

#[test]
fn every_graph_matches_its_modules_and_has_cpu_kernels() {
    let manifest = Manifest::committed();
    let graphs = graphs();
    let mut queried = 0;
    for (_, name, graph) in &graphs {
        check(&manifest, name, graph).unwrap_or_else(|e| panic!("{e}"));
        // The ray-query variant: each ray-tracing pass as one compute kernel binding what the
        // ray-generation and any-hit shaders bound.
        let query = graph.clone().with_rt_mode(RtMode::Query);
        check(&manifest, &format!("{name} (ray queries)"), &query).unwrap_or_else(|e| panic!("{e}"));
        assert!(query.passes.iter().all(|p| !matches!(p.kind, PassKind::RayTracing { .. })));
        assert_eq!(query.traces_rays(), graph.traces_rays(), "{name}");
        queried += usize::from(query != *graph);
    }
    assert!(queried >= 5, "ray-query variants of raysd, raysvao, groundtruth, hybrid…: {queried}");
    // Dual depth binds the peeled layer; single depth never does.
    for (technique, name, graph) in &graphs {
        let reads_second = graph.inputs().contains(&inputs::SECOND_DEPTH);
        assert_eq!(reads_second, technique.second_layer().is_some(), "{name}");
    }
    assert!(graphs.iter().filter(|g| g.0.second_layer().is_some()).count() >= 3);
}

/// The check above can fail: a graph whose pass writes a slot the module only reads, or binds
/// one slot too few, or pushes the wrong constants, is refused.
#[test]
fn a_graph_that_disagrees_with_its_module_is_refused() {
    let manifest = Manifest::committed();
    let (_, name, graph) = graphs().remove(0);
    let mut wrong_access = graph.clone();
    wrong_access.passes[0].bindings[0].access = Access::Write;
    assert!(check(&manifest, &name, &wrong_access).is_err());
    let mut missing = graph.clone();
    missing.passes[0].bindings.pop();
    assert!(check(&manifest, &name, &missing).is_err());
    let mut push = graph.clone();
    push.passes[0].push_constants.pop();
    assert!(check(&manifest, &name, &push).is_err());
    let mut undeclared = graph.clone();
    undeclared.passes[1].bindings[0].resource = "no_such_resource";
    assert!(undeclared.validate().is_err());
    // vao_main reads linear_depth (slot 0) and writes ao (slot 2): binding ao at slot 0 too is
    // a written resource bound twice.
    let mut written_twice = graph;
    written_twice.passes[0].bindings[0].resource = "ao";
    assert!(written_twice.validate().is_err());
}
