//! Hash of the shader crate's sources, recorded beside the committed SPIR-V by the xtask and
//! re-checked by a stable test, so SPIR-V that is stale against its sources cannot go unnoticed.

use sha2::{Digest, Sha256};
use std::path::{Path, PathBuf};

fn collect(dir: &Path, out: &mut Vec<PathBuf>) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        if path.is_dir() {
            collect(&path, out)?;
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
    Ok(())
}

/// SHA-256 over `Cargo.toml` and every `.rs` file below `src/` of `shader_crate`, and the same of
/// its `derive/` crate (whose `#[kernel]` rewrites every entry point in the SPIR-V build too), in
/// sorted relative-path order, each as `path\0contents\0` (line endings normalized to `\n`).
pub fn shader_source_hash(shader_crate: &Path) -> std::io::Result<String> {
    let mut files = vec![shader_crate.join("Cargo.toml"), shader_crate.join("derive/Cargo.toml")];
    collect(&shader_crate.join("src"), &mut files)?;
    collect(&shader_crate.join("derive/src"), &mut files)?;
    let mut rel: Vec<(String, PathBuf)> = files
        .into_iter()
        .map(|p| (p.strip_prefix(shader_crate).unwrap_or(&p).to_string_lossy().replace('\\', "/"), p))
        .collect();
    rel.sort();
    let mut hasher = Sha256::new();
    for (name, path) in rel {
        let text = std::fs::read_to_string(&path)?.replace("\r\n", "\n");
        hasher.update(name.as_bytes());
        hasher.update([0]);
        hasher.update(text.as_bytes());
        hasher.update([0]);
    }
    Ok(hasher.finalize().iter().map(|b| format!("{b:02x}")).collect())
}
