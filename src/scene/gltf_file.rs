//! glTF 2.0 (.gltf with external or embedded buffers, .glb) through the `gltf` crate: the
//! default scene's node hierarchy is flattened to world space; `alphaMode: MASK` materials keep
//! the alpha channel of their base-colour texture (times the base-colour factor) and cutoff.

use super::{AlphaMask, Material, Scene, SceneError};
use aokit_shaders::glam::{Mat4, Vec2, Vec3};
use std::path::Path;

pub(super) fn load(path: &Path) -> Result<Scene, SceneError> {
    let (doc, buffers, images) = gltf::import(path).map_err(|e| SceneError::malformed(path, "glTF", e))?;
    let materials = doc.materials().map(|m| material(&m, &images)).collect();
    let mut scene = Scene { name: path.display().to_string(), materials, ..Default::default() };
    let root = doc.default_scene().or_else(|| doc.scenes().next());
    let Some(root) = root else {
        return Err(SceneError::malformed(path, "glTF", "no scene in the document"));
    };
    let mut stack: Vec<(gltf::Node, Mat4)> = root.nodes().map(|n| (n, Mat4::IDENTITY)).collect();
    while let Some((node, parent)) = stack.pop() {
        let world = parent * Mat4::from_cols_array_2d(&node.transform().matrix());
        if let Some(mesh) = node.mesh() {
            for prim in mesh.primitives() {
                add_primitive(path, &mut scene, &prim, &buffers, world)?;
            }
        }
        stack.extend(node.children().map(|c| (c, world)));
    }
    Ok(scene)
}

fn add_primitive(
    path: &Path,
    scene: &mut Scene,
    prim: &gltf::Primitive,
    buffers: &[gltf::buffer::Data],
    world: Mat4,
) -> Result<(), SceneError> {
    if prim.mode() != gltf::mesh::Mode::Triangles {
        return Ok(()); // points and lines have no surface to occlude
    }
    let reader = prim.reader(|b| buffers.get(b.index()).map(|d| &d.0[..]));
    let positions: Vec<Vec3> = reader
        .read_positions()
        .ok_or_else(|| SceneError::malformed(path, "glTF", "a triangle primitive has no POSITION"))?
        .map(|p| world.transform_point3(Vec3::from(p)))
        .collect();
    let uvs: Vec<Vec2> = match reader.read_tex_coords(0) {
        Some(t) => t.into_f32().map(Vec2::from).collect(),
        None => vec![Vec2::ZERO; positions.len()],
    };
    let indices: Vec<u32> = match reader.read_indices() {
        Some(i) => i.into_u32().collect(),
        None => (0..positions.len() as u32).collect(),
    };
    let material = prim.material().index().map_or(0, |m| m as u32);
    for tri in indices.chunks_exact(3) {
        let mut corners = [Vec3::ZERO; 3];
        let mut tex = [Vec2::ZERO; 3];
        for k in 0..3 {
            let i = tri[k] as usize;
            if i >= positions.len() {
                return Err(SceneError::malformed(
                    path,
                    "glTF",
                    format!("index {i} out of {} vertices", positions.len()),
                ));
            }
            corners[k] = positions[i];
            tex[k] = uvs.get(i).copied().unwrap_or(Vec2::ZERO);
        }
        scene.triangles.push(corners);
        scene.triangle_materials.push(material);
        scene.triangle_uvs.push(tex);
    }
    Ok(())
}

fn material(m: &gltf::Material, images: &[gltf::image::Data]) -> Material {
    let name = m.name().unwrap_or_default().to_string();
    if m.alpha_mode() != gltf::material::AlphaMode::Mask {
        return Material { name, alpha_mask: None };
    }
    let pbr = m.pbr_metallic_roughness();
    let factor = pbr.base_color_factor()[3];
    let cutoff = m.alpha_cutoff().unwrap_or(0.5);
    let alpha_mask = pbr.base_color_texture().and_then(|t| images.get(t.texture().source().index())).map(|img| {
        use gltf::image::Format;
        let channels = match img.format {
            Format::R8 => 1,
            Format::R8G8 => 2,
            Format::R8G8B8 => 3,
            Format::R8G8B8A8 => 4,
            _ => 0, // 16-bit and float textures: treated as opaque below
        };
        let texels = (img.width * img.height) as usize;
        let alpha = (0..texels)
            .map(|i| if channels == 4 { factor * img.pixels[4 * i + 3] as f32 / 255.0 } else { factor })
            .collect();
        AlphaMask { width: img.width, height: img.height, alpha, cutoff }
    });
    Material { name, alpha_mask }
}
