//! `cargo run -p xtask -- build-spirv`: compile `shader-crate/` to SPIR-V with rust-gpu 0.11
//! (cargo-gpu-install fetches the pinned nightly and builds the codegen backend once, cached
//! under ~/.cache/rust-gpu), validate every module with `spirv-val` and naga, and write
//! `assets/spirv/{entry}.spv` plus `manifest.json` (schema aokit-manifest/3: modules with named
//! bindings, push-constant structs, the shared structs' layouts, the hash of the sources) and
//! the C header `assets/include/aokit.h` generated from it.
//!
//! Runs on stable; nothing else in the workspace needs the nightly.

use aokit_contract::atomic_file::write_atomic_bytes;
use aokit_contract::manifest::{Manifest, reflect};
use aokit_contract::spirv_hash::shader_source_hash;
use cargo_gpu_install::install::Install;
use cargo_gpu_install::spirv_builder::{Capability, ModuleResult, SpirvMetadata};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

const TARGET: &str = "spirv-unknown-vulkan1.2";

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("workspace root").to_path_buf()
}

/// Run Khronos `spirv-val` for the Vulkan 1.2 environment.
pub fn spirv_val(path: &Path) -> Result<(), String> {
    let out = Command::new("spirv-val")
        .args(["--target-env", "vulkan1.2"])
        .arg(path)
        .output()
        .map_err(|e| format!("cannot run spirv-val (apt-get install spirv-tools): {e}"))?;
    if out.status.success() {
        Ok(())
    } else {
        Err(format!(
            "spirv-val {}: {}{}",
            path.display(),
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ))
    }
}

fn build_spirv() -> Result<(), String> {
    let root = root();
    let shader_crate = root.join("shader-crate");
    let out_dir = root.join("assets/spirv");
    let backend =
        Install::from_shader_crate(shader_crate.clone()).run().map_err(|e| format!("installing rust-gpu: {e:?}"))?;
    let build = |feature: Option<&str>| -> Result<BTreeMap<String, PathBuf>, String> {
        let mut builder = backend
            .to_spirv_builder(&shader_crate, TARGET)
            .release(true)
            .multimodule(true)
            .spirv_metadata(SpirvMetadata::NameVariables)
            .capability(Capability::VulkanMemoryModelDeviceScope)
            // The AO export's `r16f`/`r8` storage images (shader-crate `adapters`). Vulkan allows
            // this capability unconditionally (spec appendix "Vulkan Environment for SPIR-V",
            // capability table: VK_VERSION_1_0), so declaring it in every module costs nothing.
            .capability(Capability::StorageImageExtendedFormats);
        match feature {
            Some("rt") => {
                builder = builder
                    .capability(Capability::RayTracingKHR)
                    .extension("SPV_KHR_ray_tracing")
                    .shader_crate_features(["rt".to_string()]);
            }
            Some("rq") => {
                builder = builder
                    .capability(Capability::RayQueryKHR)
                    .extension("SPV_KHR_ray_query")
                    .shader_crate_features(["rq".to_string()]);
            }
            _ => {}
        }
        let result = builder.build().map_err(|e| format!("rust-gpu build: {e}"))?;
        match result.module {
            ModuleResult::MultiModule(modules) => Ok(modules),
            ModuleResult::SingleModule(_) => Err("expected one module per entry point".into()),
        }
    };
    // Three passes: a capability applies to every module of a build, and compute/raster modules
    // must neither require ray tracing or ray queries nor lose naga's validation; the
    // ray-tracing pipelines' modules must not require ray queries (nor the other way round).
    let mut modules = build(None)?;
    let plain: Vec<String> = modules.keys().cloned().collect();
    for feature in ["rt", "rq"] {
        for (entry, path) in build(Some(feature))? {
            if !plain.contains(&entry) {
                modules.insert(entry, path);
            }
        }
    }
    std::fs::create_dir_all(&out_dir).map_err(|e| e.to_string())?;
    let mut manifest = Manifest {
        schema: String::new(),
        source_hash: shader_source_hash(&shader_crate).map_err(|e| e.to_string())?,
        target: TARGET.into(),
        rust_gpu: "0.11.0".into(),
        modules: Vec::new(),
        structs: Vec::new(),
        techniques: Vec::new(),
        tables: Vec::new(),
        adapters: None,
        half_resolution: None,
        temporal: None,
    };
    for (entry, path) in &modules {
        let file = format!("{entry}.spv");
        let dest = out_dir.join(&file);
        // Every output through a temporary file and a rename: a build killed half-way leaves
        // the old file or the new one, never a truncated one.
        let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
        write_atomic_bytes(&dest, &bytes).map_err(|e| e.to_string())?;
        spirv_val(&dest)?;
        let module = reflect::reflect_any(&file, &bytes).map_err(|e| format!("{file}: {e}"))?;
        println!(
            "  {file}: {} bytes, {} stage, {} bindings, {} push-constant bytes",
            bytes.len(),
            module.stage,
            module.bindings.len(),
            module.push_constant_bytes
        );
        manifest.modules.push(module);
    }
    let mut manifest = manifest.complete()?;
    let wgsl_dir = root.join("assets/wgsl");
    std::fs::create_dir_all(&wgsl_dir).map_err(|e| e.to_string())?;
    let mut written = Vec::new();
    for (file, source) in manifest.add_wgsl(&out_dir)? {
        write_atomic_bytes(&wgsl_dir.join(&file), source.as_bytes()).map_err(|e| e.to_string())?;
        written.push(std::ffi::OsString::from(file));
    }
    // WGSL of modules that are gone, removed once the new files are in place.
    for entry in std::fs::read_dir(&wgsl_dir).map_err(|e| format!("{}: {e}", wgsl_dir.display()))? {
        let entry = entry.map_err(|e| e.to_string())?;
        if !written.contains(&entry.file_name()) {
            let stale = entry.path();
            std::fs::remove_file(&stale).map_err(|e| format!("{}: {e}", stale.display()))?;
        }
    }
    let json = serde_json::to_string_pretty(&manifest).map_err(|e| e.to_string())? + "\n";
    write_atomic_bytes(&out_dir.join("manifest.json"), json.as_bytes()).map_err(|e| e.to_string())?;
    let include = root.join("assets/include");
    std::fs::create_dir_all(&include).map_err(|e| e.to_string())?;
    write_atomic_bytes(&include.join("aokit.h"), manifest.c_header().as_bytes()).map_err(|e| e.to_string())?;
    let constants = manifest.c_constants_header()?;
    write_atomic_bytes(&include.join("aokit_constants.h"), constants.as_bytes()).map_err(|e| e.to_string())?;
    println!("wrote {} modules and manifest.json (source hash {})", manifest.modules.len(), manifest.source_hash);
    Ok(())
}

fn main() -> ExitCode {
    match std::env::args().nth(1).as_deref() {
        Some("build-spirv") => match build_spirv() {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::FAILURE
            }
        },
        _ => {
            eprintln!("usage: cargo run -p xtask -- build-spirv");
            ExitCode::FAILURE
        }
    }
}
