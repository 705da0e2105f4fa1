//! Embeds the committed WGSL for `aokit web`: one `include_str!` per file of `assets/wgsl/` (the
//! xtask's output), so the list is the folder's, never typed by hand.

use std::fmt::Write as _;
use std::path::PathBuf;

fn main() {
    let dir = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets it")).join("assets/wgsl");
    println!("cargo::rerun-if-changed={}", dir.display());
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e} (the committed WGSL)", dir.display()))
        .filter_map(|e| {
            let path = e.ok()?.path();
            (path.extension()? == "wgsl").then(|| path.file_name()?.to_str().map(str::to_string))?
        })
        .collect();
    files.sort();
    let mut out = String::from("/// Every committed WGSL module (`assets/wgsl/`), by file name, sorted.\n");
    writeln!(out, "const WGSL: &[(&str, &str)] = &[").unwrap();
    for file in &files {
        writeln!(out, "    ({file:?}, include_str!({:?})),", dir.join(file).display().to_string()).unwrap();
    }
    writeln!(out, "];").unwrap();
    let dest = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets it")).join("wgsl_files.rs");
    std::fs::write(&dest, out).unwrap_or_else(|e| panic!("{}: {e}", dest.display()));
}
