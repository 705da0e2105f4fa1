//! The committed SPIR-V is fresh against the shader sources, valid (spirv-val, naga) and
//! described correctly by its manifest. Needs no nightly; needs spirv-val (package spirv-tools)
//! unless the run allows its skip (tests/common/skip.rs).

mod common;

use aokit_contract::manifest::{Manifest, reflect};
use aokit_contract::spirv_hash::shader_source_hash;
use aokit_vulkan::modules;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn spirv_is_rebuilt_whenever_the_shader_sources_change() {
    let manifest = Manifest::committed();
    let now = shader_source_hash(&root().join("shader-crate")).unwrap();
    assert_eq!(
        manifest.source_hash, now,
        "shader-crate/ changed since assets/spirv/ was built: run `cargo run -p xtask -- build-spirv` and commit assets/spirv"
    );
}

#[test]
fn manifest_matches_naga_reflection_of_every_module() {
    let manifest = Manifest::committed();
    let names: Vec<_> = manifest.modules.iter().map(|m| m.entry_point.as_str()).collect();
    let embedded: Vec<_> = modules::ALL.iter().map(|m| m.0).collect();
    let mut sorted = embedded.clone();
    sorted.sort();
    assert_eq!(names, sorted, "manifest and embedded modules list the same entry points");
    for m in &manifest.modules {
        let bytes = std::fs::read(root().join("assets/spirv").join(&m.file)).unwrap();
        let embedded = modules::of(&m.entry_point).unwrap();
        assert_eq!(bytes, embedded, "{} embedded == on disk", m.file);
        let reflected = reflect::reflect_any(&m.file, &bytes).unwrap_or_else(|e| panic!("{}: {e}", m.file));
        // What the SPIR-V says; the Rust types and push-constant struct come from the sources
        // (tests/contract.rs regenerates those).
        let mut from_spirv = m.clone();
        from_spirv.push_constants = None;
        from_spirv.wgsl = None;
        from_spirv.bindings.iter_mut().for_each(|b| b.rust_type.clear());
        from_spirv.specialization.iter_mut().for_each(|c| c.name.clear());
        from_spirv.specialization.sort_by_key(|c| c.id);
        assert_eq!(reflected, from_spirv);
        // naga reads (and validates) everything but ray-tracing stages and ray-query kernels.
        if aokit_contract::manifest::words::is_ray_tracing(&bytes).unwrap() {
            assert!(m.stage != "vertex" && m.stage != "fragment", "{}", m.file);
        } else {
            assert!(["compute", "vertex", "fragment"].contains(&m.stage.as_str()), "{}", m.file);
            reflect::validate(&bytes).unwrap_or_else(|e| panic!("{}: {e}", m.file));
        }
    }
}

/// Needs `spirv-val` from the spirv-tools package (Debian/Ubuntu: `apt-get install spirv-tools`):
/// without it the test fails, unless the run allows its skip (tests/common/skip.rs).
#[test]
fn every_module_passes_spirv_val() {
    if common::skip::without_tool(common::skip::SPIRV_VAL, "spirv-val", "apt-get install spirv-tools") {
        return;
    }
    for m in &Manifest::committed().modules {
        let path = root().join("assets/spirv").join(&m.file);
        let out =
            std::process::Command::new("spirv-val").args(["--target-env", "vulkan1.2"]).arg(&path).output().unwrap();
        assert!(
            out.status.success(),
            "{}: {}{}",
            m.file,
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }
}
