//! OBJ (+MTL): the input is an OBJ file, optionally followed by `\0MTL\0` and the .mtl file that
//! every `mtllib` line reads.
#![no_main]

#[path = "common.rs"]
mod common;

use aokit::scene::{Scene, SceneFormat};
use libfuzzer_sys::fuzz_target;
use std::io;
use std::path::Path;

const SEPARATOR: &[u8] = b"\0MTL\0";

fuzz_target!(|data: &[u8]| {
    let (obj, mtl) = match data.windows(SEPARATOR.len()).position(|w| w == SEPARATOR) {
        Some(at) => (&data[..at], Some(&data[at + SEPARATOR.len()..])),
        None => (data, None),
    };
    let side = |_: &Path| mtl.map(<[u8]>::to_vec).ok_or_else(|| io::Error::from(io::ErrorKind::NotFound));
    let _ = common::check("fuzz.obj", Scene::from_bytes(SceneFormat::Obj, Path::new("fuzz.obj"), obj, &side));
});
