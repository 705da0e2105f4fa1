//! Embeds the committed WGSL and SPIR-V: one `include_str!` per module of `assets/wgsl/` and one
//! `include_bytes!` per module of `assets/spirv/` (the xtask's output), so the module lists are
//! the folders', never typed by hand.

use std::fmt::Write as _;
use std::path::PathBuf;

/// The sorted file stems of `dir`'s files ending in `.extension`.
fn stems(dir: &std::path::Path, extension: &str) -> Vec<String> {
    println!("cargo::rerun-if-changed={}", dir.display());
    let mut stems: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e} (the committed modules)", dir.display()))
        .filter_map(|e| {
            let path = e.ok()?.path();
            (path.extension()? == extension).then(|| path.file_stem()?.to_str().map(str::to_string))?
        })
        .collect();
    stems.sort();
    stems
}

fn main() {
    // `aokit-wgpu/wgsl` and `aokit-wgpu/spirv` are links to the repository's `assets/wgsl/` and
    // `assets/spirv/`; a packaged crate holds the files themselves there (cargo follows the
    // links when it packages).
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets it"));
    let mut out = String::from("/// Every committed WGSL module by entry point (its file name), sorted.\n");
    writeln!(out, "pub const WGSL: &[(&str, &str)] = &[").unwrap();
    for entry in stems(&root.join("wgsl"), "wgsl") {
        let path = root.join("wgsl").join(format!("{entry}.wgsl"));
        writeln!(out, "    ({entry:?}, include_str!({:?})),", path.display().to_string()).unwrap();
    }
    writeln!(out, "];\n/// Every committed SPIR-V module by entry point (its file name), sorted.").unwrap();
    writeln!(out, "pub const SPIRV: &[(&str, &[u8])] = &[").unwrap();
    for entry in stems(&root.join("spirv"), "spv") {
        let path = root.join("spirv").join(format!("{entry}.spv"));
        writeln!(out, "    ({entry:?}, include_bytes!({:?})),", path.display().to_string()).unwrap();
    }
    writeln!(out, "];").unwrap();
    let dest = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets it")).join("modules.rs");
    std::fs::write(&dest, out).unwrap_or_else(|e| panic!("{}: {e}", dest.display()));
}
