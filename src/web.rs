//! `aokit web`: a static WebGPU page that runs the screen-space techniques in a browser on a
//! frame's exported G-buffer, from the committed contract (`assets/spirv/manifest.json`,
//! `assets/wgsl/`) alone: graphs, data and constants for any settings come from the manifest.
//! The page is plain JS modules (`assets/web/`); this module writes it with the export
//! (`crate::export`), the manifest and WGSL, and cpu-sim's AO of every screen-space technique at
//! its defaults as the page's reference. Formats in `docs/web.md`.

use crate::frame::Frame;
use crate::output::crop_inner;
use crate::scene::Scene;
use crate::technique::{Describe, TECHNIQUES, Technique};
use aokit_contract::manifest::Manifest;
use aokit_cpu::GBufferImage;
use aokit_cpu::graph::{CpuExecutor, CpuInputs};
use aokit_shaders::graph::{FrameDesc, Graph, PassKind, inputs};
use serde_json::{Value, json};
use std::path::Path;

/// The format written into `web.json`.
pub const FORMAT: &str = "aokit-web/2";

/// The page's sources (`assets/web/`), written as they are.
const PAGE: [(&str, &str); 3] = [
    ("index.html", include_str!("../assets/web/index.html")),
    ("aokit.js", include_str!("../assets/web/aokit.js")),
    ("graph.js", include_str!("../assets/web/graph.js")),
];

// `WGSL`: every committed WGSL module (`assets/wgsl/`), written by build.rs; [`write`] refuses a
// manifest naming another.
include!(concat!(env!("OUT_DIR"), "/wgsl_files.rs"));

/// The inputs a browser page has: the exported G-buffer.
const PAGE_INPUTS: [&str; 2] = [inputs::LINEAR_DEPTH, inputs::VIEW_NORMALS];

/// Why the browser cannot run `graph`, if it cannot: every pass must be a compute module with
/// WGSL, and the graph may read only the exported depth and normals.
fn unsupported(manifest: &Manifest, graph: &Graph) -> Option<String> {
    for p in &graph.passes {
        if !matches!(p.kind, PassKind::Compute) {
            return Some(format!("pass '{}' ({}) is not a compute pass", p.label, p.entry()));
        }
        let module = manifest.modules.iter().find(|m| m.entry_point == p.entry());
        if module.is_none_or(|m| m.wgsl.is_none()) {
            return Some(format!("module {} has no WGSL", p.entry()));
        }
    }
    graph
        .inputs()
        .into_iter()
        .find(|i| !PAGE_INPUTS.contains(i))
        .map(|i| format!("reads input '{i}', which the export does not provide to the page"))
}

fn io_err(e: String) -> std::io::Error {
    std::io::Error::other(e)
}

/// One screen-space technique's entry of `web.json`: cpu-sim's AO at its defaults (the page's
/// reference), written into `reference/`.
fn technique_entry(
    dir: &Path,
    name: &'static str,
    frame: &FrameDesc,
    gbuffer: &GBufferImage,
    progress: aokit_cpu::Progress,
) -> std::io::Result<Value> {
    let t = Technique::named(name).map_err(io_err)?;
    let graph = t.graph(frame).map_err(io_err)?;
    let mut cpu = CpuExecutor::new();
    let cpu_inputs =
        CpuInputs { depth: &gbuffer.depth, normals: &gbuffer.normals, second_depth: None, scene: None, progress };
    cpu.run(&graph, &cpu_inputs).map_err(io_err)?;
    let ao = crop_inner(&graph.view, cpu.f32(graph.output).expect("the output resource"));
    let reference = format!("reference/{name}.f32");
    std::fs::create_dir_all(dir.join("reference"))?;
    crate::output::write_atomic_bytes(&dir.join(&reference), bytemuck::cast_slice::<f32, u8>(&ao))?;
    let mean = ao.iter().map(|&a| a as f64).sum::<f64>() / ao.len().max(1) as f64;
    let settings: serde_json::Map<String, Value> =
        set_values(&t).into_iter().map(|(k, v)| (k.into(), v.into())).collect();
    Ok(json!({ "name": name, "reference": { "file": reference, "settings": settings, "mean": mean } }))
}

/// `(key, value)` of every setting `t` reads.
fn set_values(t: &Technique) -> Vec<(&'static str, String)> {
    let described = t.describe();
    t.rows()
        .into_iter()
        .map(|r| {
            let v = &described[r.key.replace('-', "_")];
            (r.key, v.as_str().map_or_else(|| v.to_string(), str::to_string))
        })
        .collect()
}

/// Write the page for `scene` seen in `frame` with G-buffer `gbuffer` (full target) into `dir`:
/// the export (`crate::export::write`), the page, `manifest.json` and the WGSL it names,
/// `web.json` with its data files, and cpu-sim's AO of every screen-space technique at its
/// defaults. Returns `web.json`'s contents.
pub fn write(
    dir: &Path,
    scene: &Scene,
    frame: &Frame,
    gbuffer: &GBufferImage,
    backend: &str,
    progress: aokit_cpu::Progress,
) -> std::io::Result<Value> {
    let export = crate::export::write(dir, scene, frame, gbuffer, backend)?;
    // Files of an earlier page in the same folder would be stale.
    for old in ["reference", "wgsl"] {
        if dir.join(old).is_dir() {
            std::fs::remove_dir_all(dir.join(old))?;
        }
    }
    let manifest = Manifest::committed();
    let manifest_text = aokit_contract::MANIFEST_JSON;
    crate::output::write_atomic_bytes(&dir.join("manifest.json"), manifest_text.as_bytes())?;
    std::fs::create_dir_all(dir.join("wgsl"))?;
    for m in &manifest.modules {
        let Some(w) = &m.wgsl else { continue };
        let (_, text) = WGSL
            .iter()
            .find(|(f, _)| *f == w.file)
            .ok_or_else(|| io_err(format!("the manifest names {}, which aokit does not embed", w.file)))?;
        crate::output::write_atomic_bytes(&dir.join("wgsl").join(&w.file), text.as_bytes())?;
    }
    for (name, text) in PAGE {
        crate::output::write_atomic_bytes(&dir.join(name), text.as_bytes())?;
    }
    let desc = frame.desc();
    let (mut techniques, mut skipped) = (Vec::new(), Vec::new());
    for t in TECHNIQUES {
        let graph = Technique::named(t.name()).and_then(|c| c.graph(&desc)).map_err(io_err)?;
        match unsupported(&manifest, &graph) {
            Some(why) => skipped.push(json!({"name": t.name(), "why": why})),
            None => techniques.push(technique_entry(dir, t.name(), &desc, gbuffer, progress)?),
        }
    }
    let json = json!({
        "format": FORMAT,
        "scene": scene.name,
        "backend": backend,
        "image": export["image"],
        "target_size": export["target_size"],
        "files": {
            "export": "export.json",
            "manifest": "manifest.json",
            "wgsl": "wgsl/",
            "camera": "camera.bin",
            "depth": "gbuffer_depth.f32",
            "normals": "gbuffer_normals.u32",
        },
        "techniques": techniques,
        "skipped": skipped,
    });
    let text = serde_json::to_string_pretty(&json).expect("serializable") + "\n";
    crate::output::write_atomic_bytes(&dir.join("web.json"), text.as_bytes())?;
    Ok(json)
}
