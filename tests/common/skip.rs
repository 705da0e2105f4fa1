//! The one place that decides whether a test that needs a device or a tool may skip.
//!
//! A test that finds what it needs missing (a Vulkan driver, Chromium, `spirv-val`, a C or C++
//! compiler) calls [`cannot_run`]. The test then FAILS, naming itself and what it lacks, unless
//! the run allows that skip explicitly: `AOKIT_ALLOW_SKIP` is a comma-separated list of needs
//! ([`VULKAN`], [`CHROMIUM`], …) or test names (`binary::test` or just `test`). An allowed skip
//! returns `true` (the test returns early) and appends one line to the skip log
//! (`AOKIT_SKIP_LOG`, which `scripts/test.sh` sets and prints at the end as "N skipped: …").
//! Under `CI` nothing may skip, whatever the allow-list says.
#![allow(dead_code)]

use std::io::Write;

/// A Vulkan 1.3 driver (lavapipe: `mesa-vulkan-drivers` 25 from bookworm-backports) with the
/// Khronos validation layer (`vulkan-validationlayers`).
pub const VULKAN: &str = "vulkan";
/// Headless Chromium (`chromium`).
pub const CHROMIUM: &str = "chromium";
/// `spirv-val` (`spirv-tools`).
pub const SPIRV_VAL: &str = "spirv-val";
/// A C compiler `cc` (`gcc`) and the Vulkan headers (`libvulkan-dev`).
pub const C_COMPILER: &str = "cc";
/// A C++ compiler `c++` (`g++`).
pub const CXX_COMPILER: &str = "c++";

/// The running test's name, `binary::test`: libtest names each test's thread after the test,
/// and the binary is the executable's name without cargo's hash.
pub fn test_name() -> String {
    let exe = std::env::current_exe().ok();
    let stem = exe.as_ref().and_then(|p| p.file_stem()).map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let binary = stem.rsplit_once('-').map_or(stem.as_str(), |(b, _)| b).to_string();
    let test = std::thread::current().name().unwrap_or("main").to_string();
    format!("{binary}::{test}")
}

/// Does the allow-list `list` (comma-separated) allow `test` to skip for lack of `need`?
pub fn allowed(list: &str, need: &str, test: &str) -> bool {
    let short = test.rsplit_once("::").map_or(test, |(_, t)| t);
    list.split(',').map(str::trim).any(|entry| !entry.is_empty() && (entry == need || entry == test || entry == short))
}

/// The running test cannot run because `need` is missing (`reason`, with how to install it).
/// Fails the test unless the run allows the skip (see the module documentation); an allowed
/// skip is logged and returns `true`, so call it as `if skip::cannot_run(…) { return; }`.
pub fn cannot_run(need: &str, reason: &str) -> bool {
    let test = test_name();
    let reason = reason.replace('\n', " ");
    let list = std::env::var("AOKIT_ALLOW_SKIP").unwrap_or_default();
    let in_ci = std::env::var_os("CI").is_some_and(|v| !v.is_empty() && v != "false" && v != "0");
    if in_ci || !allowed(&list, need, &test) {
        let hint = if in_ci { "CI runs every test" } else { "to skip it, allow it: AOKIT_ALLOW_SKIP" };
        panic!("{test} cannot run without {need}: {reason} ({hint}={need} or ={test})");
    }
    let line = format!("{test} (no {need}: {reason})");
    eprintln!("SKIPPED {line}");
    let log = std::env::var_os("AOKIT_SKIP_LOG")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("aokit-skipped.log"));
    if let Ok(mut f) = std::fs::OpenOptions::new().create(true).append(true).open(&log) {
        let _ = writeln!(f, "{line}");
    }
    true
}

/// Is the command `program` on the PATH (`program --version` succeeds)?
pub fn has_tool(program: &str) -> bool {
    std::process::Command::new(program).arg("--version").output().is_ok_and(|o| o.status.success())
}

/// `true` (the test returns) when `program` is missing and its skip is allowed; panics when it
/// is missing and the skip is not allowed; `false` when it is there.
pub fn without_tool(need: &str, program: &str, install: &str) -> bool {
    !has_tool(program) && cannot_run(need, &format!("`{program}` not found ({install})"))
}

/// Headless Chromium's command, or `None` when the test must return (an allowed skip).
pub fn chromium() -> Option<&'static str> {
    let found = ["chromium", "chromium-browser", "google-chrome"].into_iter().find(|c| has_tool(c));
    if found.is_none()
        && cannot_run(CHROMIUM, "no chromium, chromium-browser or google-chrome (apt-get install chromium)")
    {
        return None;
    }
    found
}
