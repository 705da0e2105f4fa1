//! The engine contract in `assets/`: the manifest (schema aokit-manifest/3), the C header and the
//! WGSL are what the xtask generates from the committed modules and the current shader sources
//! (a stale one fails here), a C11 compiler lays out every shared struct exactly as Rust does
//! (the header's `_Static_assert`s, compiled with `cc`), and the WGSL validates for WebGPU core.

mod common;

use aokit_contract::manifest::{Manifest, reflect};
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The manifest as the xtask writes it, from the committed `.spv` files.
fn regenerated() -> Manifest {
    let committed = Manifest::committed();
    let mut manifest =
        Manifest { modules: Vec::new(), structs: Vec::new(), schema: String::new(), ..committed.clone() };
    for m in &committed.modules {
        let bytes = std::fs::read(root().join("assets/spirv").join(&m.file)).unwrap();
        manifest.modules.push(reflect::reflect_any(&m.file, &bytes).unwrap());
    }
    let mut manifest = manifest.complete().unwrap();
    manifest.add_wgsl(&root().join("assets/spirv")).unwrap();
    manifest
}

#[test]
fn wgsl_is_what_the_modules_translate_to_and_validates_without_capabilities() {
    let mut manifest = regenerated();
    let sources = manifest.add_wgsl(&root().join("assets/spirv")).unwrap();
    assert_eq!(manifest, Manifest::committed(), "manifest.json's wgsl entries are stale");
    let mut files: Vec<_> =
        std::fs::read_dir(root().join("assets/wgsl")).unwrap().map(|e| e.unwrap().file_name()).collect();
    files.sort();
    assert_eq!(files.len(), sources.len(), "assets/wgsl holds exactly the generated files");
    for (file, source) in &sources {
        let committed = std::fs::read_to_string(root().join("assets/wgsl").join(file)).unwrap();
        assert!(&committed == source, "assets/wgsl/{file} is stale: run `cargo run -p xtask -- build-spirv`");
        // Browsers reject a decimal literal beyond f32::MAX (naga writes f32::MAX that way).
        assert!(!committed.contains("340282350000000000000000000000000000000"), "{file}: inexact f32::MAX");
        // WebGPU core: no push constants, no optional capability, default limits (re-checked
        // on the committed text by naga's WGSL front end).
        assert!(!committed.contains("var<immediate>") && !committed.contains("push_constant"), "{file}");
        let module = naga::front::wgsl::parse_str(&committed).unwrap_or_else(|e| panic!("{file}: {e}"));
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::empty())
            .validate(&module)
            .unwrap_or_else(|e| panic!("{file}: {:?}", e.into_inner()));
        let storage = module
            .global_variables
            .iter()
            .filter(|(_, v)| matches!(v.space, naga::AddressSpace::Storage { .. }))
            .count();
        assert!(storage <= aokit_contract::wgsl::MAX_STORAGE_BUFFERS, "{file}: {storage} storage buffers");
    }
    // Every compute module has one but the two WebGPU core cannot express and the ray-query
    // variants (naga reads no ray queries; WebGPU has none).
    let queries =
        |m: &&aokit_contract::manifest::ModuleManifest| m.bindings.iter().any(|b| b.kind == "acceleration_structure");
    let compute = manifest.modules.iter().filter(|m| m.stage == "compute").filter(|m| !queries(m)).count();
    assert_eq!(sources.len(), compute - aokit_contract::manifest::NOT_WGSL.len());
    assert_eq!(manifest.modules.iter().filter(|m| m.stage == "compute").filter(queries).count(), 4);
    assert!(sources.iter().any(|(f, _)| f == "vao_main.wgsl") && sources.iter().any(|(f, _)| f == "gtao_main.wgsl"));
}

#[test]
fn manifest_and_header_are_what_the_sources_generate() {
    let manifest = regenerated();
    let committed = Manifest::committed();
    assert_eq!(manifest, committed, "assets/spirv/manifest.json is stale: run `cargo run -p xtask -- build-spirv`");
    let header = std::fs::read_to_string(root().join("assets/include/aokit.h")).unwrap();
    assert!(header == manifest.c_header(), "assets/include/aokit.h is stale: run `cargo run -p xtask -- build-spirv`");

    // What an engine needs is named: every binding, every push-constant block of a module that
    // has one, and every struct's fields.
    assert_eq!(manifest.schema, "aokit-manifest/3");
    for m in &manifest.modules {
        for b in &m.bindings {
            assert!(!b.name.is_empty() && !b.rust_type.is_empty(), "{}: binding {} unnamed", m.entry_point, b.binding);
        }
        if m.push_constant_bytes > 0 {
            let name =
                m.push_constants.as_ref().unwrap_or_else(|| panic!("{}: no push-constant struct", m.entry_point));
            let s = manifest.structs.iter().find(|s| &s.name == name).unwrap();
            assert_eq!(s.size, m.push_constant_bytes, "{}", m.entry_point);
        }
    }
    let vao = manifest.modules.iter().find(|m| m.entry_point == "vao_main").unwrap();
    let names: Vec<_> = vao.bindings.iter().map(|b| (b.name.as_str(), b.rust_type.as_str(), b.writable)).collect();
    assert_eq!(names, [("depth", "[f32]", false), ("normals", "[u32]", false), ("ao", "[f32]", true)]);
    assert_eq!(vao.push_constants.as_deref(), Some("VaoParams"));
    let sd = manifest.modules.iter().find(|m| m.entry_point == "raysd_rgen").unwrap();
    assert!(sd.bindings.iter().any(|b| b.name == "frame" && b.rust_type == "[SvaoFrame]"), "{:?}", sd.bindings);
    for s in &manifest.structs {
        assert!(!s.doc.is_empty(), "{} has no doc comment", s.name);
        for f in s.fields.iter().filter(|f| !f.name.starts_with('_')) {
            assert!(!f.doc.is_empty(), "{}.{} has no doc comment", s.name, f.name);
        }
    }
}

/// Compile `source` (C11, including the committed header) with `cc`; the compiler's messages on
/// failure. `None` when there is no C compiler and the run allows the skip.
fn compile(source: &str, dir: &Path) -> Option<Result<(), String>> {
    if common::skip::without_tool(common::skip::C_COMPILER, "cc", "apt-get install gcc") {
        return None;
    }
    let file = dir.join("check.c");
    std::fs::write(&file, source).unwrap();
    let out = Command::new("cc")
        .args(["-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", "-fsyntax-only", "-I"])
        .arg(dir)
        .arg(&file)
        .output()
        .unwrap();
    Some(if out.status.success() { Ok(()) } else { Err(String::from_utf8_lossy(&out.stderr).into_owned()) })
}

#[test]
fn the_header_compiles_and_c_lays_out_every_struct_as_rust_does() {
    let dir = std::env::temp_dir().join(format!("aokit-header-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let header = std::fs::read_to_string(root().join("assets/include/aokit.h")).unwrap();
    std::fs::write(dir.join("aokit.h"), &header).unwrap();
    let use_it = "#include \"aokit.h\"\nint main(void) { aokit_VaoParams p = {0}; (void)p; return (int)AOKIT_VAO_MAIN_BINDING_AO; }\n";
    let Some(result) = compile(use_it, &dir) else { return };
    result.unwrap_or_else(|e| panic!("aokit.h does not compile:\n{e}"));
    let asserts = header.matches("_Static_assert(offsetof").count();
    assert!(asserts >= 80, "{asserts} offset assertions");

    // C++ engines include it too.
    if !common::skip::without_tool(common::skip::CXX_COMPILER, "c++", "apt-get install g++") {
        let out = Command::new("c++")
            .args(["-std=c++11", "-Wall", "-Werror", "-fsyntax-only", "-x", "c++", "-I"])
            .arg(&dir)
            .arg(dir.join("check.c"))
            .output()
            .unwrap();
        assert!(out.status.success(), "aokit.h in C++:\n{}", String::from_utf8_lossy(&out.stderr));
    }

    // The assertions bite: a header claiming another offset for one field is refused.
    let wrong =
        header.replacen("offsetof(aokit_VaoParams, radius) == ", "offsetof(aokit_VaoParams, radius) == 4 + ", 1);
    assert_ne!(wrong, header);
    std::fs::write(dir.join("aokit.h"), &wrong).unwrap();
    let e = compile(use_it, &dir).unwrap().expect_err("a wrong offset must not compile");
    assert!(e.contains("VaoParams.radius offset"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A size or dispatch expression of the manifest at the target `vars` (`W H w h`) with the
/// settings of `settings`, through the contract's evaluator.
fn eval(text: &str, vars: &[(char, f64)], settings: &aokit_contract::expr::Inputs) -> f64 {
    let mut inputs = settings.clone();
    for (name, v) in vars {
        inputs.names.insert(name.to_string(), aokit_contract::expr::Value::Int(*v as i64));
    }
    match aokit_contract::expr::eval(text, &inputs) {
        Ok(aokit_contract::expr::Value::Int(i)) => i as f64,
        other => panic!("'{text}': {other:?}, not a whole number"),
    }
}

/// The manifest's technique section: every size and dispatch formula evaluates, at several
/// frames (odd sizes, guard bands), to what both executors allocate and dispatch; the passes,
/// bindings and barriers are the graph's.
#[test]
fn technique_formulas_match_the_graphs_at_every_size() {
    use aokit::technique::Technique;
    let manifest = Manifest::committed();
    assert_eq!(manifest.techniques.len(), aokit::technique::TECHNIQUES.len());
    let mut checked = 0;
    for t in &manifest.techniques {
        let technique = Technique::named(&t.name).unwrap();
        assert_eq!(t.settings.len(), technique.rows().len(), "{}", t.name);
        let example = aokit_contract::constants::FrameInputs::examples()[0];
        let settings = aokit_contract::constants::inputs(&technique.rows(), &technique.values(), &example).unwrap();
        for (w, h, g) in [(1920, 1080, 64), (333, 197, 7), (64, 48, 0)] {
            let frame = aokit_contract::manifest::reference_frame(aokit_shaders::glam::UVec2::new(w, h), g);
            let graph = technique.graph(&frame).unwrap();
            let view = graph.view;
            let full = view.size();
            let vars = [('W', full.x as f64), ('H', full.y as f64), ('w', w as f64), ('h', h as f64)];
            assert_eq!(t.resources.len(), graph.resources.len(), "{}", t.name);
            for (m, r) in t.resources.iter().zip(&graph.resources) {
                assert_eq!(m.name, r.name);
                let v = eval(&m.size, &vars, &settings);
                assert_eq!(v, r.len(&view) as f64, "{} {}: '{}' at {w}×{h}+{g}", t.name, r.name, m.size);
                checked += 1;
            }
            let barriers = graph.barriers();
            assert_eq!(t.passes.len(), graph.passes.len(), "{}", t.name);
            for ((m, p), barrier) in t.passes.iter().zip(&graph.passes).zip(barriers) {
                assert_eq!((m.entry.as_str(), m.barrier_before), (p.entry(), barrier));
                let n = p.invocations(&view);
                let got = [eval(&m.dispatch[0], &vars, &settings), eval(&m.dispatch[1], &vars, &settings)];
                assert_eq!(got, [n.x as f64, n.y as f64], "{} {}: {:?} at {w}×{h}+{g}", t.name, p.entry(), m.dispatch);
                let bindings: Vec<_> = p.bindings.iter().map(|b| (b.slot, b.resource.to_string())).collect();
                let listed: Vec<_> = m.bindings.iter().map(|b| (b.0, b.1.clone())).collect();
                assert_eq!(bindings, listed, "{} {}", t.name, p.entry());
                checked += 1;
            }
        }
    }
    assert!(checked > 300, "{checked} formulas checked");
    // The evaluator on a size of each shape, by hand.
    let vars = [('W', 2048.0), ('H', 1208.0), ('w', 1920.0), ('h', 1080.0)];
    let none = aokit_contract::expr::Inputs::default();
    assert_eq!(
        eval("(div_ceil(W, 4) + 256) * (div_ceil(H, 4) + 256) * 4", &vars, &none),
        (512.0 + 256.0) * (302.0 + 256.0) * 4.0
    );
    assert_eq!(eval("max(1, div_floor(W, 16)) * max(1, div_floor(H, 16))", &vars, &none), 128.0 * 75.0);
    assert_eq!(eval("w * h + 3", &vars, &none), 1920.0 * 1080.0 + 3.0);
}

/// The manifest's `constants`: every field of every constants struct a technique's passes use
/// (push-constant blocks, records bound as storage buffers, the structs they hold) has a formula,
/// with the offset and type of `structs`; and the formulas are the code's. Built through the
/// registry with one setting changed, every field whose bytes change (decoded with the `structs`
/// offsets, per pass and per record) names that setting's key, and in the cases below exactly
/// the fields whose formulas name the key change. The frame's radius, exponent, thickness, eye
/// and field of view change exactly the fields whose formulas say so.
#[test]
fn constants_formulas_cover_every_field_and_name_the_settings_that_change_it() {
    use aokit_contract::manifest::constants::{pass_modules, values_tried};
    use aokit_contract::manifest::{StructManifest, TechniqueManifest};
    use aokit_shaders::common::camera::Camera;
    use aokit_shaders::glam::{UVec2, Vec3};
    use aokit_shaders::graph::{FrameDesc, Graph, Init};
    use std::collections::{BTreeMap, BTreeSet};

    /// A graph's constants: `(place, struct, field)` → bytes of every leaf field (`place`: a
    /// pass's entry and occurrence, or a record), and every struct they are in.
    struct Decoded {
        fields: BTreeMap<(String, String, String), Vec<u8>>,
        structs: BTreeSet<String>,
    }
    fn add(structs: &[StructManifest], place: &str, name: &str, bytes: &[u8], base: usize, out: &mut Decoded) {
        let s = structs.iter().find(|s| s.name == name).unwrap_or_else(|| panic!("{name} is not in structs"));
        assert!(bytes.len() >= base + s.size as usize, "{place}: {} bytes for {name}", bytes.len());
        out.structs.insert(name.to_string());
        for f in &s.fields {
            let at = base + f.offset as usize;
            if structs.iter().any(|s| s.name == f.ty) {
                add(structs, place, &f.ty, bytes, at, out);
            } else {
                let key = (place.to_string(), s.name.clone(), f.name.clone());
                out.fields.insert(key, bytes[at..at + f.size as usize].to_vec());
            }
        }
    }

    let manifest = regenerated();
    let structs = &manifest.structs[..];
    let decode = |graph: &Graph| {
        let mut out = Decoded { fields: BTreeMap::new(), structs: BTreeSet::new() };
        let module = |name: &str| manifest.modules.iter().find(|m| m.entry_point == name).unwrap();
        for (i, pass) in graph.passes.iter().enumerate() {
            let nth = graph.passes[..i].iter().filter(|p| p.entry() == pass.entry()).count();
            let place = format!("{}#{nth}", pass.entry());
            let modules: Vec<_> = pass_modules(pass).into_iter().map(module).collect();
            match modules.iter().find_map(|m| m.push_constants.as_deref()) {
                Some(name) => {
                    let size = structs.iter().find(|s| s.name == name).unwrap().size as usize;
                    assert_eq!(pass.push_constants.len(), size, "{place}: the push constants are {name}");
                    add(structs, &place, name, &pass.push_constants, 0, &mut out);
                }
                None => assert!(pass.push_constants.is_empty(), "{place} pushes bytes no module declares"),
            }
            for b in &pass.bindings {
                let Some(Init::Data(words)) = graph.resource(b.resource).map(|r| &r.init) else { continue };
                let ty = modules.iter().flat_map(|m| &m.bindings).find(|mb| mb.binding == b.slot);
                let element = ty.and_then(|mb| mb.rust_type.strip_prefix('[')?.strip_suffix(']'));
                let Some(name) = element.filter(|e| structs.iter().any(|s| s.name == *e)) else { continue };
                let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
                add(structs, &format!("record {}", b.resource), name, &bytes, 0, &mut out);
            }
        }
        out
    };
    let formula = |t: &TechniqueManifest, s: &str, f: &str| -> String {
        let c = t.constants.iter().find(|c| c.struct_name == s && c.field == f);
        c.unwrap_or_else(|| panic!("{}: its passes use {s}.{f}, which has no formula", t.name)).doc.clone()
    };
    // The leaf fields that differ between two graphs' passes and records present in both.
    let changed = |a: &Graph, b: &Graph| -> BTreeSet<(String, String)> {
        let (a, b) = (decode(a).fields, decode(b).fields);
        let differ = a.iter().filter(|(k, v)| b.get(*k).is_some_and(|w| w != *v));
        differ.map(|((_, s, f), _)| (s.clone(), f.clone())).collect()
    };
    let frame = aokit_contract::manifest::reference_frame(UVec2::new(1920, 1080), 64);
    // Each technique at its defaults, and with each setting at each value tried (refused
    // combinations skipped): `(key, value, graph)`.
    let variants = |name: &str| {
        let technique = aokit_shaders::techniques::find(name).unwrap();
        let defaults = technique.configure();
        let mut out = Vec::new();
        for r in technique.rows() {
            let current = defaults.values().into_iter().find(|(k, _)| *k == r.key).unwrap().1;
            for value in values_tried(r.kind, &current) {
                let mut c = technique.configure();
                if let Ok(g) = c.set(r.key, &value).and_then(|_| c.graph(&frame)) {
                    out.push((r.key, value, g));
                }
            }
        }
        (defaults.graph(&frame).unwrap(), out)
    };

    // Coverage: offsets and types are the structs'; every field of every struct any variant's
    // passes use has a formula.
    assert_eq!(manifest.techniques.len(), aokit_shaders::techniques::TECHNIQUES.len());
    let (mut graphs, mut compared) = (0, 0);
    for t in &manifest.techniques {
        for c in &t.constants {
            let s = structs.iter().find(|s| s.name == c.struct_name).unwrap();
            let f = s.fields.iter().find(|f| f.name == c.field).unwrap();
            assert_eq!((c.offset, c.ty.as_str()), (f.offset, f.ty.as_str()), "{} {}.{}", t.name, s.name, f.name);
            assert!(!c.doc.trim().is_empty(), "{} {}.{}", t.name, s.name, f.name);
        }
        let (base, variants) = variants(&t.name);
        for graph in std::iter::once(&base).chain(variants.iter().map(|v| &v.2)) {
            for name in decode(graph).structs {
                let s = structs.iter().find(|s| s.name == name).unwrap();
                s.fields.iter().for_each(|f| _ = formula(t, &s.name, &f.name));
            }
            graphs += 1;
        }
        // A setting changes only fields whose formulas name it.
        for (key, value, graph) in &variants {
            for (s, f) in changed(&base, graph) {
                let text = formula(t, &s, &f);
                assert!(
                    text.contains(&format!("`{key}`")),
                    "{}: {key}={value} changes {s}.{f}, whose formula does not name `{key}`: {text}",
                    t.name
                );
                compared += 1;
            }
        }
    }
    assert!(graphs > 100 && compared > 40, "{graphs} graphs decoded, {compared} changed fields checked");

    // Exactly the fields whose formulas name the key change (their values differ here).
    let cases = [
        ("raysd", "sd-res", "half"),
        ("raysd", "sd-guard", "256"),
        ("raysd", "max-count", "16"),
        ("raysd", "kernel", "hbao"),
        ("raysd", "sd-source", "raster"),
        ("raysd", "jitter", "paper"),
        ("raysd", "interval", "off"),
        ("raysvao", "cutoff", "3"),
        ("hbao", "primary", "dual"),
        ("gtao", "preset", "low"),
        ("gtao", "falloff-range", "0.3"),
        ("gtao", "mip-offset", "1"),
        ("raymarch", "contribution", "binary"),
        ("raymarch", "directions", "8"),
        ("hybrid", "variant", "world"),
        ("hybrid", "world-weight", "0.5"),
        ("hybrid", "screen-steps", "4"),
        ("groundtruth", "spp", "64"),
        ("groundtruth", "sampling", "uniform"),
    ];
    for (name, key, value) in cases {
        let t = manifest.techniques.iter().find(|t| t.name == name).unwrap();
        let technique = aokit_shaders::techniques::find(name).unwrap();
        let base = technique.configure().graph(&frame).unwrap();
        let mut c = technique.configure();
        c.set(key, value).unwrap();
        let graph = c.graph(&frame).unwrap();
        let (a, b) = (decode(&base).fields, decode(&graph).fields);
        let named: BTreeSet<_> = (a.keys().filter(|k| b.contains_key(*k)))
            .map(|(_, s, f)| (s.clone(), f.clone()))
            .filter(|(s, f)| formula(t, s, f).contains(&format!("`{key}`")))
            .collect();
        assert!(!named.is_empty(), "{name}: no formula names `{key}`");
        assert_eq!(changed(&base, &graph), named, "{name}: {key}={value}");
    }

    // The frame: its radius, exponent and thickness change the fields whose formulas name them
    // ("the frame's … AO radius"), its index only the noise fields ("the frame index"), the eye
    // only the view transforms, the field of view only the tangents.
    let look = |eye: Vec3, fov_y: f32| {
        Camera::look_at(eye, Vec3::ZERO, Vec3::Y, fov_y, UVec2::new(1920, 1080), 64, 0.1, 100.0)
    };
    assert_eq!(look(Vec3::new(0.0, 1.0, 5.0), 1.0), frame.camera);
    let frames: [(&str, FrameDesc, &[&str]); 6] = [
        ("radius", FrameDesc { radius: 0.7, ..frame }, &["AO radius"]),
        ("frame index", FrameDesc { frame_index: 5, ..frame }, &["frame index"]),
        ("exponent", FrameDesc { exponent: 3.0, ..frame }, &["AO exponent"]),
        ("thickness", FrameDesc { thickness: 0.1, ..frame }, &["VAO thickness"]),
        (
            "eye",
            FrameDesc { camera: look(Vec3::new(1.0, 2.0, 4.0), 1.0), ..frame },
            &["look-at", "Camera.view_to_world", "Camera.world_to_view"],
        ),
        ("fov", FrameDesc { camera: look(Vec3::new(0.0, 1.0, 5.0), 0.8), ..frame }, &["fov_y"]),
    ];
    for t in &manifest.techniques {
        let technique = aokit_shaders::techniques::find(&t.name).unwrap().configure();
        let base = technique.graph(&frame).unwrap();
        let fields: BTreeSet<_> = decode(&base).fields.into_keys().map(|(_, s, f)| (s, f)).collect();
        for (what, other, words) in &frames {
            let named: BTreeSet<_> =
                fields.iter().filter(|(s, f)| words.iter().any(|w| formula(t, s, f).contains(w))).cloned().collect();
            let graph = technique.graph(other).unwrap();
            assert_eq!(changed(&base, &graph), named, "{}: the frame's {what}", t.name);
        }
    }

    // assets/README.md's worked example: VAO's push constants from the reference camera.
    let vao = decode(&aokit_shaders::techniques::find("vao").unwrap().configure().graph(&frame).unwrap()).fields;
    let floats = |place: &str, s: &str, f: &str| -> Vec<f32> {
        let bytes = &vao[&(place.to_string(), s.to_string(), f.to_string())];
        bytes.chunks(4).map(|c| f32::from_le_bytes(c.try_into().unwrap())).collect()
    };
    let words = |place: &str, s: &str, f: &str| -> Vec<u32> {
        let bytes = &vao[&(place.to_string(), s.to_string(), f.to_string())];
        bytes.chunks(4).map(|c| u32::from_le_bytes(c.try_into().unwrap())).collect()
    };
    assert_eq!(floats("vao_main#0", "ViewParams", "res"), [2048.0, 1208.0]);
    let tan = floats("vao_main#0", "ViewParams", "tan_half_fov");
    assert!((tan[0] - 1.0359514).abs() < 1e-6 && (tan[1] - 0.6110495).abs() < 1e-6, "{tan:?}");
    assert_eq!(
        [floats("vao_main#0", "ViewParams", "near"), floats("vao_main#0", "ViewParams", "far")],
        [[0.1], [100.0]]
    );
    assert_eq!(words("vao_main#0", "ViewParams", "guard"), [64]);
    let rest =
        ["radius", "exponent", "thickness", "max_screen_radius"].map(|f| floats("vao_main#0", "VaoParams", f)[0]);
    assert_eq!(rest, [0.5, 2.0, 0.0, 512.0]);
    assert_eq!(
        [words("blur_main#0", "BlurParams", "direction"), words("blur_main#1", "BlurParams", "direction")],
        [[1, 0], [0, 1]]
    );
    assert_eq!(floats("blur_main#1", "BlurParams", "sharpness"), [16.0]);
}
