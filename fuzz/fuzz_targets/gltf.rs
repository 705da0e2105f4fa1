//! glTF 2.0, JSON or GLB (told apart by the magic). External files are missing.
#![no_main]

#[path = "common.rs"]
mod common;

use aokit::scene::{Scene, SceneFormat, no_side_files};
use libfuzzer_sys::fuzz_target;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let _ =
        common::check("fuzz.glb", Scene::from_bytes(SceneFormat::Gltf, Path::new("fuzz.glb"), data, &no_side_files));
});
