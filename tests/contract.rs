//! The engine contract in `assets/`: the manifest (schema aokit-manifest/2), the C header and the
//! WGSL are what the xtask generates from the committed modules and the current shader sources
//! (a stale one fails here), a C11 compiler lays out every shared struct exactly as Rust does
//! (the header's `_Static_assert`s, compiled with `cc`), and the WGSL validates for WebGPU core.

use aokit_vulkan::manifest::{Manifest, reflect};
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
    let mut manifest = manifest.complete(&root().join("shader-crate/src")).unwrap();
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
        assert!(storage <= aokit_vulkan::wgsl::MAX_STORAGE_BUFFERS, "{file}: {storage} storage buffers");
    }
    // Every compute module but the two WebGPU core cannot express has one.
    let compute = manifest.modules.iter().filter(|m| m.stage == "compute").count();
    assert_eq!(sources.len(), compute - aokit_vulkan::manifest::NOT_WGSL.len());
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
    assert_eq!(manifest.schema, "aokit-manifest/2");
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
/// failure. `None` when there is no C compiler outside CI.
fn compile(source: &str, dir: &Path) -> Option<Result<(), String>> {
    let available = Command::new("cc").arg("--version").output().is_ok_and(|o| o.status.success());
    if !available {
        assert!(std::env::var_os("CI").is_none(), "CI must have a C compiler (apt-get install gcc)");
        eprintln!("no `cc`: skipping the C compile check");
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
    let cpp = Command::new("c++")
        .args(["-std=c++11", "-Wall", "-Werror", "-fsyntax-only", "-x", "c++", "-I"])
        .arg(&dir)
        .arg(dir.join("check.c"))
        .output();
    match cpp {
        Ok(out) => assert!(out.status.success(), "aokit.h in C++:\n{}", String::from_utf8_lossy(&out.stderr)),
        Err(e) => assert!(std::env::var_os("CI").is_none(), "no c++ in CI: {e}"),
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

/// A tiny evaluator of the manifest's size formulas: numbers, `W H w h`, `+`, `·`, `/`,
/// parentheses, `ceil(x)`, `floor(x)`, `max(a, b)` — what an engine implements from the schema.
fn eval(formula: &str, vars: &[(char, f64)]) -> f64 {
    struct P<'a> {
        s: Vec<char>,
        i: usize,
        vars: &'a [(char, f64)],
    }
    impl P<'_> {
        fn skip(&mut self) {
            while self.s.get(self.i) == Some(&' ') {
                self.i += 1;
            }
        }
        fn eat(&mut self, c: char) -> bool {
            self.skip();
            let hit = self.s.get(self.i) == Some(&c);
            self.i += hit as usize;
            hit
        }
        fn expr(&mut self) -> f64 {
            let mut v = self.term();
            while self.eat('+') {
                v += self.term();
            }
            v
        }
        fn term(&mut self) -> f64 {
            let mut v = self.atom();
            loop {
                if self.eat('·') {
                    v *= self.atom();
                } else if self.eat('/') {
                    v /= self.atom();
                } else {
                    return v;
                }
            }
        }
        fn atom(&mut self) -> f64 {
            self.skip();
            if self.eat('(') {
                let v = self.expr();
                assert!(self.eat(')'), "')' expected");
                return v;
            }
            let start = self.i;
            while self.s.get(self.i).is_some_and(|c| c.is_alphanumeric() || *c == '.') {
                self.i += 1;
            }
            let word: String = self.s[start..self.i].iter().collect();
            if let Ok(n) = word.parse::<f64>() {
                return n;
            }
            if let Some((_, v)) = self.vars.iter().find(|(c, _)| word.len() == 1 && word.starts_with(*c)) {
                return *v;
            }
            assert!(self.eat('('), "unknown word '{word}'");
            let a = self.expr();
            let v = match word.as_str() {
                "ceil" => a.ceil(),
                "floor" => a.floor(),
                "max" => {
                    assert!(self.eat(','));
                    a.max(self.expr())
                }
                other => panic!("unknown function {other}"),
            };
            assert!(self.eat(')'), "')' expected after {word}");
            v
        }
    }
    let mut p = P { s: formula.chars().collect(), i: 0, vars };
    let v = p.expr();
    p.skip();
    assert_eq!(p.i, p.s.len(), "trailing text in '{formula}'");
    v
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
        for (w, h, g) in [(1920, 1080, 64), (333, 197, 7), (64, 48, 0)] {
            let frame = aokit_vulkan::manifest::reference_frame(aokit_shaders::glam::UVec2::new(w, h), g);
            let graph = technique.graph(&frame).unwrap();
            let view = graph.view;
            let full = view.size();
            let vars = [('W', full.x as f64), ('H', full.y as f64), ('w', w as f64), ('h', h as f64)];
            assert_eq!(t.resources.len(), graph.resources.len(), "{}", t.name);
            for (m, r) in t.resources.iter().zip(&graph.resources) {
                assert_eq!(m.name, r.name);
                let v = eval(&m.size, &vars);
                assert_eq!(v, r.len(&view) as f64, "{} {}: '{}' at {w}×{h}+{g}", t.name, r.name, m.size);
                checked += 1;
            }
            let barriers = graph.barriers();
            assert_eq!(t.passes.len(), graph.passes.len(), "{}", t.name);
            for ((m, p), barrier) in t.passes.iter().zip(&graph.passes).zip(barriers) {
                assert_eq!((m.entry.as_str(), m.barrier_before), (p.entry, barrier));
                let n = p.invocations(&view);
                let got = [eval(&m.dispatch[0], &vars), eval(&m.dispatch[1], &vars)];
                assert_eq!(got, [n.x as f64, n.y as f64], "{} {}: {:?} at {w}×{h}+{g}", t.name, p.entry, m.dispatch);
                let bindings: Vec<_> = p.bindings.iter().map(|b| (b.slot, b.resource.to_string())).collect();
                let listed: Vec<_> = m.bindings.iter().map(|b| (b.0, b.1.clone())).collect();
                assert_eq!(bindings, listed, "{} {}", t.name, p.entry);
                checked += 1;
            }
        }
    }
    assert!(checked > 300, "{checked} formulas checked");
    // The evaluator itself: a formula of each shape, by hand.
    let vars = [('W', 2048.0), ('H', 1208.0), ('w', 1920.0), ('h', 1080.0)];
    assert_eq!(eval("(ceil(W/4) + 256)·(ceil(H/4) + 256)·4", &vars), (512.0 + 256.0) * (302.0 + 256.0) * 4.0);
    assert_eq!(eval("max(1, floor(W/16))·max(1, floor(H/16))", &vars), 128.0 * 75.0);
    assert_eq!(eval("w·h + 3", &vars), 1920.0 * 1080.0 + 3.0);
}
