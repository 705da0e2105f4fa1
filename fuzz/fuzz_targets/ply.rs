//! PLY, ascii or binary (the header says which).
#![no_main]

#[path = "common.rs"]
mod common;

use aokit::scene::{Scene, SceneFormat, no_side_files};
use libfuzzer_sys::fuzz_target;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let _ = common::check("fuzz.ply", Scene::from_bytes(SceneFormat::Ply, Path::new("fuzz.ply"), data, &no_side_files));
});
