//! Gzip-compressed PLY: the input as a .ply.gz file; and the input gzip-compressed here, which
//! must load exactly as the input does as a plain .ply.
#![no_main]

#[path = "common.rs"]
mod common;

use aokit::scene::{Scene, SceneFormat, no_side_files};
use libfuzzer_sys::fuzz_target;
use std::io::Write;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let name = Path::new("fuzz.ply.gz");
    let _ = common::check("fuzz.ply.gz", Scene::from_bytes(SceneFormat::PlyGz, name, data, &no_side_files));

    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    gz.write_all(data).unwrap();
    let compressed = gz.finish().unwrap();
    let via_gz = common::check("fuzz.ply.gz", Scene::from_bytes(SceneFormat::PlyGz, name, &compressed, &no_side_files));
    let plain = common::check("fuzz.ply.gz", Scene::from_bytes(SceneFormat::Ply, name, data, &no_side_files));
    match (via_gz, plain) {
        (Ok(a), Ok(b)) => assert!(
            a.triangles.len() == b.triangles.len()
                && a.triangles
                    .iter()
                    .flatten()
                    .zip(b.triangles.iter().flatten())
                    .all(|(p, q)| p.to_array() == q.to_array())
        ),
        (Err(a), Err(b)) => assert_eq!(a, b),
        (a, b) => {
            panic!("gzip changed the outcome: {:?} vs {:?}", a.map(|s| s.triangles.len()), b.map(|s| s.triangles.len()))
        }
    }
});
