//! Wavefront OBJ (+MTL) through `tobj`. A missing or broken .mtl is not fatal: AO needs only
//! geometry, so materials fall back to the default.

use super::{Material, Scene, SceneError};
use aokit_shaders::glam::{Vec2, Vec3};
use std::path::Path;

pub(super) fn load(path: &Path) -> Result<Scene, SceneError> {
    let bytes = super::read_file(path)?;
    load_bytes(path, &bytes)
}

/// Parse OBJ text; `path` names the file in errors and locates `mtllib` files beside it.
pub(super) fn load_bytes(path: &Path, bytes: &[u8]) -> Result<Scene, SceneError> {
    let options = tobj::LoadOptions { triangulate: true, single_index: false, ..Default::default() };
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let (models, materials) =
        tobj::load_obj_buf(&mut std::io::Cursor::new(bytes), &options, |mtl| tobj::load_mtl(dir.join(mtl)))
            .map_err(|e| SceneError::malformed(path, "OBJ", e))?;
    let materials: Vec<Material> =
        materials.unwrap_or_default().into_iter().map(|m| Material { name: m.name, alpha_mask: None }).collect();
    let mut scene = Scene { name: path.display().to_string(), materials, ..Default::default() };
    for model in &models {
        let mesh = &model.mesh;
        let vertex = |i: u32| {
            let i = i as usize;
            Vec3::new(mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2])
        };
        let uv = |k: usize| {
            mesh.texcoord_indices.get(k).map_or(Vec2::ZERO, |&t| {
                let t = t as usize;
                Vec2::new(mesh.texcoords[2 * t], 1.0 - mesh.texcoords[2 * t + 1])
            })
        };
        let material = mesh.material_id.map_or(0, |m| m as u32);
        for (f, tri) in mesh.indices.chunks_exact(3).enumerate() {
            scene.triangles.push([vertex(tri[0]), vertex(tri[1]), vertex(tri[2])]);
            scene.triangle_materials.push(material);
            scene.triangle_uvs.push([uv(3 * f), uv(3 * f + 1), uv(3 * f + 2)]);
        }
    }
    Ok(scene)
}
