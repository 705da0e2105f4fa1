//! `aokit web`: a static WebGPU page that runs the screen-space techniques in a browser on a
//! frame's exported G-buffer, from the committed contract (`assets/spirv/manifest.json`,
//! `assets/wgsl/`) alone. The page is plain JS modules (`assets/web/`); this module writes it
//! with the export (`crate::export`), the manifest and WGSL, what the manifest does not carry
//! (the graphs of non-default settings, the `Init::Data` resources for every combination of the
//! settings they depend on, the presets' effects) and cpu-sim's AO of every screen-space
//! technique at its defaults as the page's reference. Formats in `docs/web.md`.

use crate::frame::Frame;
use crate::output::crop_inner;
use crate::scene::Scene;
use crate::technique::{Describe, Row, TECHNIQUES, Technique};
use aokit_contract::manifest::Manifest;
use aokit_cpu::GBufferImage;
use aokit_cpu::graph::{CpuExecutor, CpuInputs};
use aokit_shaders::graph::{Access, Elem, FrameDesc, Graph, Init, Lifetime, PassKind, inputs};
use aokit_shaders::technique::Kind;
use serde_json::{Value, json};
use std::collections::BTreeMap;
use std::path::Path;

/// The format written into `web.json`.
pub const FORMAT: &str = "aokit-web/1";

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

/// At most this many setting combinations are enumerated per technique (graphs or data).
const MAX_COMBINATIONS: usize = 4096;
/// A count setting with more values than this is never enumerated (kept at its default).
const MAX_COUNT_VALUES: u32 = 1024;

type Settings = Vec<(&'static str, String)>;

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

/// A graph in the manifest's technique format (`assets/README.md`): inputs, resources,
/// passes, output.
pub fn graph_json(graph: &Graph) -> Value {
    let access = |a: Access| match a {
        Access::Read => "read",
        Access::Write => "write",
        Access::ReadWrite => "read_write",
    };
    let resources: Vec<Value> = graph
        .resources
        .iter()
        .map(|r| {
            json!({
                "name": r.name,
                "elem": match r.elem { Elem::F32 => "f32", Elem::U32 => "u32" },
                "size": r.size.formula(),
                "lifetime": match r.lifetime { Lifetime::PerFrame => "per_frame", Lifetime::Persistent => "persistent" },
                "init": match &r.init {
                    Init::Fill(bits) => format!("fill {bits:#010x}"),
                    Init::Data(_) => "data".into(),
                    Init::Undefined => "undefined".into(),
                },
                "doc": r.doc,
            })
        })
        .collect();
    let passes: Vec<Value> = graph
        .passes
        .iter()
        .zip(graph.barriers())
        .map(|(p, barrier)| {
            let (kind, stages): (&str, Vec<&str>) = match p.kind {
                PassKind::Compute => ("compute", vec![]),
                PassKind::RayTracing { miss, any_hit, .. } => ("ray_tracing", vec![miss.entry, any_hit.entry]),
                PassKind::Raster { vertex } => ("raster", vec![vertex.entry]),
            };
            let mut pass = json!({
                "label": p.label,
                "entry": p.entry(),
                "kind": kind,
                "bindings": p.bindings.iter().map(|b| json!([b.slot, b.resource, access(b.access)])).collect::<Vec<_>>(),
                "dispatch": p.dispatch.formula(),
                "barrier_before": barrier,
            });
            if !stages.is_empty() {
                pass["stages"] = json!(stages);
            }
            pass
        })
        .collect();
    json!({ "inputs": graph.inputs(), "resources": resources, "passes": passes, "output": graph.output })
}

/// One configuration of a technique: its graph's structure and its data resources.
struct Probe {
    graph: Graph,
    /// [`graph_json`] without the sizes of data resources (those follow their data).
    shape: Value,
    data: BTreeMap<&'static str, Vec<u32>>,
}

/// `name` with `settings` applied in the order of its settings rows (a preset before its
/// slices), as `technique:key=value` does; `None` when the settings are refused.
fn configure(name: &str, settings: &[(&'static str, String)]) -> Option<Technique> {
    let mut t = Technique::named(name).ok()?;
    for row in t.rows() {
        if let Some((_, v)) = settings.iter().rev().find(|(k, _)| *k == row.key) {
            t.set(row.key, v).ok()?;
        }
    }
    Some(t)
}

fn probe(name: &str, settings: &[(&'static str, String)], frame: &FrameDesc) -> Option<Probe> {
    let graph = configure(name, settings)?.graph(frame).ok()?;
    let mut shape = graph_json(&graph);
    let mut data = BTreeMap::new();
    for (r, json) in graph.resources.iter().zip(shape["resources"].as_array_mut().expect("an array")) {
        if let Init::Data(words) = &r.init {
            data.insert(r.name, words.clone());
            json["size"] = "data".into();
        }
    }
    Some(Probe { graph, shape, data })
}

/// `values` without repetitions, in order.
fn distinct(mut values: Vec<String>) -> Vec<String> {
    let mut seen = Vec::new();
    values.retain(|v| {
        let new = !seen.contains(v);
        seen.push(v.clone());
        new
    });
    values
}

/// Values tried to find out what a setting changes: choices all, numbers and counts their
/// ends, default and a middle.
fn probe_values(row: &Row, default: &str) -> Vec<String> {
    let mut out = vec![default.to_string()];
    match row.kind {
        Kind::Choice(names) => out.extend(names.iter().map(|n| n.to_string())),
        Kind::Count { min, max } => {
            let top = if max == u32::MAX { min.saturating_mul(2).max(min + 8) } else { max };
            out.extend([min, min + 1, top, min + (top - min) / 2].iter().filter(|&&v| v <= top).map(u32::to_string));
        }
        Kind::Number { min, max } => {
            let top = if max == f32::MAX { default.parse::<f32>().unwrap_or(1.0) * 2.0 + 1.0 } else { max };
            out.extend([min, top, 0.5 * (min + top)].iter().map(f32::to_string));
        }
    }
    distinct(out)
}

/// Values of an already found setting around which the others are varied (interactions):
/// choices all, counts their default and two lowest, numbers their default and minimum (cheap
/// values: a count is often a problem size).
fn around_values(row: &Row, default: &str) -> Vec<String> {
    let mut out = vec![default.to_string()];
    match row.kind {
        Kind::Choice(names) => out.extend(names.iter().map(|n| n.to_string())),
        Kind::Count { min, max } => out.extend([min, min.saturating_add(1).min(max)].iter().map(u32::to_string)),
        Kind::Number { min, .. } => out.push(min.to_string()),
    }
    distinct(out)
}

/// Every value of a setting, when it has few enough to enumerate.
fn all_values(row: &Row) -> Option<Vec<String>> {
    match row.kind {
        Kind::Choice(names) => Some(names.iter().map(|n| n.to_string()).collect()),
        Kind::Count { min, max } if max - min < MAX_COUNT_VALUES => Some((min..=max).map(|v| v.to_string()).collect()),
        _ => None,
    }
}

/// Every combination of `values` (one list per key).
fn product(values: &[(&'static str, Vec<String>)]) -> Vec<Settings> {
    let mut out: Vec<Settings> = vec![Vec::new()];
    for (key, vs) in values {
        out = out.iter().flat_map(|s| vs.iter().map(move |v| [&s[..], &[(*key, v.clone())]].concat())).collect();
    }
    out
}

fn settings_json(settings: &[(&'static str, String)]) -> Value {
    Value::Object(settings.iter().map(|(k, v)| (k.to_string(), Value::String(v.clone()))).collect())
}

/// What the settings of technique `name` change besides the push constants: the keys its
/// graph's structure depends on and the keys its data resources depend on (each found by
/// varying one setting at a time around every combination of the keys found so far).
fn dependencies(
    name: &str,
    rows: &[Row],
    defaults: &Settings,
    frame: &FrameDesc,
) -> (Vec<&'static str>, Vec<&'static str>) {
    let default_of = |key: &str| defaults.iter().find(|(k, _)| *k == key).map_or(String::new(), |(_, v)| v.clone());
    let (mut structure, mut data): (Vec<&'static str>, Vec<&'static str>) = (Vec::new(), Vec::new());
    loop {
        let around: Vec<_> = rows
            .iter()
            .filter(|r| structure.contains(&r.key) || data.contains(&r.key))
            .map(|r| (r.key, around_values(r, &default_of(r.key))))
            .collect();
        let mut grew = false;
        for base_settings in product(&around) {
            let Some(base) = probe(name, &base_settings, frame) else { continue };
            for row in rows {
                // Structure and data are looked for separately: a setting can change both.
                let (mut shape_known, mut data_known) = (structure.contains(&row.key), data.contains(&row.key));
                for v in probe_values(row, &default_of(row.key)) {
                    if shape_known && data_known {
                        break;
                    }
                    let mut s = base_settings.clone();
                    s.push((row.key, v));
                    let Some(p) = probe(name, &s, frame) else { continue };
                    if !shape_known && p.shape != base.shape {
                        (shape_known, grew) = (true, true);
                        structure.push(row.key);
                    }
                    if !data_known && p.data != base.data {
                        (data_known, grew) = (true, true);
                        data.push(row.key);
                    }
                }
            }
        }
        if !grew {
            break;
        }
    }
    let order = |keys: &mut Vec<&'static str>| {
        *keys = rows.iter().map(|r| r.key).filter(|k| keys.contains(k)).collect();
    };
    order(&mut structure);
    order(&mut data);
    (structure, data)
}

fn io_err(e: String) -> std::io::Error {
    std::io::Error::other(e)
}

/// One screen-space technique's entry of `web.json`, writing its data files and reference.
fn technique_entry(
    dir: &Path,
    manifest: &Manifest,
    manifest_json: &Value,
    name: &'static str,
    frame: &FrameDesc,
    gbuffer: &GBufferImage,
    progress: aokit_cpu::Progress,
) -> std::io::Result<Value> {
    let t = Technique::named(name).map_err(io_err)?;
    let rows = t.rows();
    let defaults = set_values(&t);
    let (structure, data) = dependencies(name, &rows, &defaults, frame);
    // Settings the graph or its data depend on that cannot be enumerated: the page keeps them
    // at their defaults.
    let mut fixed = Vec::new();
    let mut enumerate = |keys: &[&'static str]| -> Vec<(&'static str, Vec<String>)> {
        let mut out = Vec::new();
        for key in keys {
            let row = rows.iter().find(|r| r.key == *key).expect("a row");
            match all_values(row) {
                Some(vs) => out.push((*key, vs)),
                None => fixed.push(json!({"key": key, "why": "the graph or its data depend on it and it has too many values to enumerate: the page keeps its default"})),
            }
        }
        out
    };
    let (structure_values, data_values) = (enumerate(&structure), enumerate(&data));
    let default_graph = graph_json(&t.graph(frame).map_err(io_err)?);
    let in_manifest = manifest_json["techniques"].as_array().and_then(|ts| ts.iter().find(|m| m["name"] == name));
    let matches_manifest = |g: &Value| {
        in_manifest.is_some_and(|m| ["inputs", "resources", "passes", "output"].iter().all(|k| m[*k] == g[*k]))
    };
    if !matches_manifest(&default_graph) {
        eprintln!("warning: {name}'s default graph differs from the embedded manifest's; web.json carries it");
    }
    let mut graphs = Vec::new();
    let combos = product(&structure_values);
    if combos.len() > MAX_COMBINATIONS {
        return Err(io_err(format!("{name}: {} graph combinations", combos.len())));
    }
    for combo in combos {
        let mut entry = json!({ "settings": settings_json(&combo) });
        match probe(name, &combo, frame) {
            None => entry["unsupported"] = "the technique refuses these settings".into(),
            Some(p) => match unsupported(manifest, &p.graph) {
                Some(why) => entry["unsupported"] = why.into(),
                None => {
                    let g = graph_json(&p.graph);
                    entry["graph"] = if matches_manifest(&g) { "manifest".into() } else { g };
                }
            },
        }
        graphs.push(entry);
    }
    let mut data_entries = Vec::new();
    let combos = product(&data_values);
    if combos.len() > MAX_COMBINATIONS {
        return Err(io_err(format!("{name}: {} data combinations", combos.len())));
    }
    for combo in combos {
        let Some(p) = probe(name, &combo, frame) else { continue };
        if unsupported(manifest, &p.graph).is_some() {
            continue;
        }
        let stem = match combo.is_empty() {
            true => "default".to_string(),
            false => combo.iter().map(|(k, v)| format!("{k}={v}")).collect::<Vec<_>>().join(","),
        };
        let mut files = serde_json::Map::new();
        for (resource, words) in &p.data {
            let rel = format!("data/{name}/{resource}/{stem}.u32");
            let path = dir.join(&rel);
            std::fs::create_dir_all(path.parent().expect("a parent"))?;
            crate::output::write_atomic_bytes(&path, bytemuck::cast_slice::<u32, u8>(words))?;
            files.insert(resource.to_string(), rel.into());
        }
        data_entries.push(json!({ "settings": settings_json(&combo), "files": files }));
    }
    let presets = presets(name, &rows);
    // cpu-sim's AO at the defaults: the page's reference.
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
    Ok(json!({
        "name": name,
        "graph_keys": structure,
        "graphs": graphs,
        "data_keys": data,
        "data": data_entries,
        "fixed": fixed,
        "presets": presets,
        "reference": { "file": reference, "settings": settings_json(&defaults), "mean": mean },
    }))
}

/// Choice settings that set other settings (XeGTAO's quality preset sets slices and steps): per
/// such setting, per choice, the values it sets — the settings that come out the same whatever
/// they were before (`custom` keeps them: an empty table).
fn presets(name: &str, rows: &[Row]) -> Value {
    let mut out = serde_json::Map::new();
    for row in rows {
        let Kind::Choice(names) = row.kind else { continue };
        // The state after each choice, from the defaults and from every other choice's state.
        let set = |from: Option<&str>, choice: &str| -> Option<Settings> {
            let mut t = Technique::named(name).ok()?;
            if let Some(f) = from {
                t.set(row.key, f).ok()?;
            }
            t.set(row.key, choice).ok()?;
            Some(set_values(&t).into_iter().filter(|(k, _)| *k != row.key).collect())
        };
        let starts: Vec<Option<&str>> = std::iter::once(None).chain(names.iter().map(|n| Some(*n))).collect();
        let Some(after) = names.iter().map(|c| set(None, c)).collect::<Option<Vec<_>>>() else { continue };
        // Settings some choice changes.
        let affected: Vec<&'static str> = rows
            .iter()
            .map(|r| r.key)
            .filter(|k| *k != row.key)
            .filter(|k| {
                let of = |s: &Settings| s.iter().find(|(sk, _)| sk == k).map(|(_, v)| v.clone());
                after.iter().any(|s| of(s) != of(&after[0]))
            })
            .collect();
        if affected.is_empty() {
            continue;
        }
        let mut table = serde_json::Map::new();
        for (choice, state) in names.iter().zip(&after) {
            let sets: Settings = state
                .iter()
                .filter(|(k, v)| {
                    affected.contains(k)
                        && starts
                            .iter()
                            .all(|f| set(*f, choice).is_some_and(|s| s.iter().any(|(sk, sv)| sk == k && sv == v)))
                })
                .cloned()
                .collect();
            table.insert(choice.to_string(), settings_json(&sets));
        }
        out.insert(row.key.to_string(), Value::Object(table));
    }
    Value::Object(out)
}

/// `(key, value)` of every setting `t` reads.
fn set_values(t: &Technique) -> Settings {
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
    for old in ["data", "reference", "wgsl"] {
        if dir.join(old).is_dir() {
            std::fs::remove_dir_all(dir.join(old))?;
        }
    }
    let manifest = Manifest::committed();
    let manifest_text = aokit_contract::MANIFEST_JSON;
    let manifest_json: Value = serde_json::from_str(manifest_text).map_err(|e| io_err(e.to_string()))?;
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
            None => {
                techniques.push(technique_entry(dir, &manifest, &manifest_json, t.name(), &desc, gbuffer, progress)?)
            }
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
