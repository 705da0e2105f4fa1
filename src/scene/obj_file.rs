//! Wavefront OBJ (+MTL) through `tobj`. A missing or broken .mtl is not fatal: AO needs only
//! geometry, so materials fall back to the default; of an .mtl only the `newmtl` names are read.
//!
//! Face indices are checked before `tobj` sees them: an index beyond anything the file could
//! hold, or a relative index before the first element, is an error naming the line (tobj's
//! index arithmetic would overflow on them).

use super::{Material, Scene, SceneError, SideFiles};
use aokit_shaders::glam::{Vec2, Vec3};
use std::path::Path;

/// Parse OBJ text; `path` names the file in errors, `side_files` reads its `mtllib` files.
pub(super) fn load_bytes(path: &Path, bytes: &[u8], side_files: SideFiles) -> Result<Scene, SceneError> {
    check_face_indices(bytes).map_err(|problem| SceneError::malformed(path, "OBJ", problem))?;
    let options = tobj::LoadOptions { triangulate: true, single_index: false, ..Default::default() };
    let (models, materials) =
        tobj::load_obj_buf(&mut std::io::Cursor::new(bytes), &options, |mtl| load_mtl(side_files, mtl))
            .map_err(|e| SceneError::malformed(path, "OBJ", e))?;
    let materials: Vec<Material> =
        materials.unwrap_or_default().into_iter().map(|m| Material { name: m.name, alpha_mask: None }).collect();
    let mut scene = Scene { name: path.display().to_string(), materials, ..Default::default() };
    for model in &models {
        let mesh = &model.mesh;
        // tobj's meshes are consistent (it checks every index); `get` keeps a broken one an error.
        let vertex = |i: u32| {
            let i = 3 * i as usize;
            mesh.positions.get(i..i + 3).map(|p| Vec3::new(p[0], p[1], p[2]))
        };
        let uv = |k: usize| {
            mesh.texcoord_indices.get(k).map_or(Vec2::ZERO, |&t| {
                let t = 2 * t as usize;
                mesh.texcoords.get(t..t + 2).map_or(Vec2::ZERO, |c| Vec2::new(c[0], 1.0 - c[1]))
            })
        };
        let material = mesh.material_id.map_or(0, |m| m as u32);
        for (f, tri) in mesh.indices.chunks_exact(3).enumerate() {
            let corners = [vertex(tri[0]), vertex(tri[1]), vertex(tri[2])];
            let [Some(a), Some(b), Some(c)] = corners else {
                return Err(SceneError::malformed(
                    path,
                    "OBJ",
                    format!("triangle {f} of '{}' has no vertex", model.name),
                ));
            };
            scene.triangles.push([a, b, c]);
            scene.triangle_materials.push(material);
            scene.triangle_uvs.push([uv(3 * f), uv(3 * f + 1), uv(3 * f + 2)]);
        }
    }
    Ok(scene)
}

/// The materials of an .mtl file, names only, through `tobj` (fed only the `newmtl` lines, so
/// malformed colour lines cannot upset it).
fn load_mtl(side_files: SideFiles, name: &Path) -> tobj::MTLLoadResult {
    let bytes = side_files(name).map_err(|_| tobj::LoadError::OpenFileFailed)?;
    let text = String::from_utf8_lossy(&bytes);
    let names: String = text
        .lines()
        .filter(|line| line.split_whitespace().next() == Some("newmtl"))
        .flat_map(|line| [line, "\n"])
        .collect();
    tobj::load_mtl_buf(&mut names.as_bytes())
}

/// Check every face (`f`, `l`) index the way tobj reads it (whitespace-separated `v/vt/vn`,
/// 1-based, negative = relative to the elements so far): a positive index may not exceed the
/// file's length in bytes (no file holds more elements than bytes), a negative one may not reach
/// before the first element.
fn check_face_indices(bytes: &[u8]) -> Result<(), String> {
    let mut counts = [0usize; 3]; // v, vt, vn so far
    const KINDS: [&str; 3] = ["vertex", "texture coordinate", "normal"];
    for (n, line) in bytes.split(|&b| b == b'\n').enumerate() {
        let Ok(line) = std::str::from_utf8(line) else {
            return Ok(()); // tobj refuses the line (and the file) itself
        };
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => counts[0] += 1,
            Some("vt") => counts[1] += 1,
            Some("vn") => counts[2] += 1,
            Some("f" | "l") => {
                for word in words {
                    for (k, part) in word.split('/').take(3).enumerate() {
                        let Ok(x) = part.parse::<isize>() else { continue };
                        if x > 0 && x.unsigned_abs() > bytes.len() {
                            return Err(format!(
                                "line {}: {} index {x} is out of range (the file has {} bytes)",
                                n + 1,
                                KINDS[k],
                                bytes.len()
                            ));
                        }
                        if x < 0 && x.unsigned_abs() > counts[k] {
                            return Err(format!(
                                "line {}: relative {} index {x} reaches before the first one ({} so far)",
                                n + 1,
                                KINDS[k],
                                counts[k]
                            ));
                        }
                    }
                }
            }
            _ => {}
        }
    }
    Ok(())
}
