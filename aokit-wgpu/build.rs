//! Embeds the committed WGSL: one `include_str!` per module of `assets/wgsl/` (the xtask's
//! output), so the module list is the folder's, never typed by hand.

use std::fmt::Write as _;
use std::path::PathBuf;

fn main() {
    // `aokit-wgpu/wgsl` is a link to the repository's `assets/wgsl/`; a packaged crate holds the
    // files themselves there (cargo follows the link when it packages).
    let dir = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets it")).join("wgsl");
    println!("cargo::rerun-if-changed={}", dir.display());
    let mut entries: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e} (the committed WGSL)", dir.display()))
        .filter_map(|e| {
            let path = e.ok()?.path();
            (path.extension()? == "wgsl").then(|| path.file_stem()?.to_str().map(str::to_string))?
        })
        .collect();
    entries.sort();
    let mut out = String::from("/// Every committed WGSL module by entry point (its file name), sorted.\n");
    writeln!(out, "pub const ALL: &[(&str, &str)] = &[").unwrap();
    for entry in &entries {
        let path = dir.join(format!("{entry}.wgsl"));
        writeln!(out, "    ({entry:?}, include_str!({:?})),", path.display().to_string()).unwrap();
    }
    writeln!(out, "];").unwrap();
    let dest = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets it")).join("wgsl_modules.rs");
    std::fs::write(&dest, out).unwrap_or_else(|e| panic!("{}: {e}", dest.display()));
}
