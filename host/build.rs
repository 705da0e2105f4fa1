//! Embeds the committed SPIR-V: one `include_bytes!` per module of `assets/spirv/` (the xtask's
//! output), so the module list is the folder's, never typed by hand.

use std::fmt::Write as _;
use std::path::PathBuf;

fn main() {
    // `host/spirv` is a link to the repository's `assets/spirv/`; a packaged crate holds the
    // files themselves there (cargo follows the link when it packages).
    let dir = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets it")).join("spirv");
    println!("cargo::rerun-if-changed={}", dir.display());
    let mut entries: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e} (the committed SPIR-V)", dir.display()))
        .filter_map(|e| {
            let path = e.ok()?.path();
            (path.extension()? == "spv").then(|| path.file_stem()?.to_str().map(str::to_string))?
        })
        .collect();
    entries.sort();
    let mut out = String::new();
    for entry in &entries {
        let path = dir.join(format!("{entry}.spv"));
        let konst = entry.to_uppercase();
        writeln!(out, "/// The SPIR-V module of entry point `{entry}`.").unwrap();
        writeln!(out, "pub const {konst}: &[u8] = include_bytes!({:?});", path.display().to_string()).unwrap();
    }
    writeln!(out, "/// Every module by entry-point name, sorted by name.").unwrap();
    writeln!(out, "pub const ALL: &[(&str, &[u8])] = &[").unwrap();
    for entry in &entries {
        writeln!(out, "    ({entry:?}, {}),", entry.to_uppercase()).unwrap();
    }
    writeln!(out, "];").unwrap();
    let dest = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets it")).join("modules.rs");
    std::fs::write(&dest, out).unwrap_or_else(|e| panic!("{}: {e}", dest.display()));
}
