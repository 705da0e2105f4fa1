//! PLY (ascii or binary, optionally gzip-compressed) through `ply-rs`: `vertex` elements with
//! x/y/z and `face` elements with a `vertex_indices` (or `vertex_index`) list; polygons are
//! fanned into triangles.

use super::{Scene, SceneError};
use aokit_shaders::glam::Vec3;
use ply_rs::parser::Parser;
use ply_rs::ply::{DefaultElement, Property};
use std::io::Read;
use std::path::Path;

fn scalar(p: &Property) -> Option<f64> {
    Some(match *p {
        Property::Char(v) => v as f64,
        Property::UChar(v) => v as f64,
        Property::Short(v) => v as f64,
        Property::UShort(v) => v as f64,
        Property::Int(v) => v as f64,
        Property::UInt(v) => v as f64,
        Property::Float(v) => v as f64,
        Property::Double(v) => v,
        _ => return None,
    })
}

fn index_list(p: &Property) -> Option<Vec<i64>> {
    Some(match p {
        Property::ListChar(v) => v.iter().map(|&i| i as i64).collect(),
        Property::ListUChar(v) => v.iter().map(|&i| i as i64).collect(),
        Property::ListShort(v) => v.iter().map(|&i| i as i64).collect(),
        Property::ListUShort(v) => v.iter().map(|&i| i as i64).collect(),
        Property::ListInt(v) => v.iter().map(|&i| i as i64).collect(),
        Property::ListUInt(v) => v.iter().map(|&i| i as i64).collect(),
        _ => return None,
    })
}

pub(super) fn load(path: &Path) -> Result<Scene, SceneError> {
    let mut bytes = super::read_file(path)?;
    if path.to_string_lossy().to_ascii_lowercase().ends_with(".gz") {
        let mut out = Vec::new();
        flate2::read::GzDecoder::new(&bytes[..])
            .read_to_end(&mut out)
            .map_err(|e| SceneError::malformed(path, "gzip", e))?;
        bytes = out;
    }
    let bad = |problem: String| SceneError::malformed(path, "PLY", problem);
    let ply = Parser::<DefaultElement>::new().read_ply(&mut &bytes[..]).map_err(|e| bad(e.to_string()))?;
    let vertices = ply.payload.get("vertex").ok_or_else(|| bad("no 'vertex' element".into()))?;
    let mut positions = Vec::with_capacity(vertices.len());
    for (i, v) in vertices.iter().enumerate() {
        let coord =
            |k: &str| v.get(k).and_then(scalar).ok_or_else(|| bad(format!("vertex {i} has no scalar property '{k}'")));
        positions.push(Vec3::new(coord("x")? as f32, coord("y")? as f32, coord("z")? as f32));
    }
    let faces = ply.payload.get("face").ok_or_else(|| bad("no 'face' element".into()))?;
    let mut scene = Scene { name: path.display().to_string(), ..Default::default() };
    for (f, face) in faces.iter().enumerate() {
        let list = face
            .get("vertex_indices")
            .or_else(|| face.get("vertex_index"))
            .and_then(index_list)
            .ok_or_else(|| bad(format!("face {f} has no integer list 'vertex_indices'")))?;
        let vertex = |i: i64| {
            usize::try_from(i)
                .ok()
                .and_then(|i| positions.get(i).copied())
                .ok_or_else(|| bad(format!("face {f} refers to vertex {i} of {}", positions.len())))
        };
        for k in 2..list.len() {
            scene.triangles.push([vertex(list[0])?, vertex(list[k - 1])?, vertex(list[k])?]);
        }
    }
    Ok(scene)
}
