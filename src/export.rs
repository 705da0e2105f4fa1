//! `aokit export`: a frame's G-buffer and scene as plain files for consumers that share no code
//! with aokit (a C sample, a browser page): what an engine would hand the kernels. Formats in
//! `docs/export.md`; every struct is the byte image of a `#[repr(C)]` struct of
//! `assets/include/aokit.h`, every array little-endian and tightly packed.

use crate::frame::Frame;
use crate::output::crop_inner;
use crate::scene::Scene;
use aokit_cpu::GBufferImage;
use aokit_shaders::adapters::{DEPTH_REVERSED, ImportParams};
use aokit_shaders::common::normal_codec::decode_normal;
use aokit_shaders::glam::Vec3;
use std::path::Path;

/// The format written into `export.json`.
pub const FORMAT: &str = "aokit-export/1";

/// Reversed-Z hardware depth (`D32_SFLOAT`, 1 at the near plane, 0 at the far plane and for
/// background) of linear view depth `z`, computed in f64: `d = n·(f − z) / (z·(f − n))`.
pub fn reversed_z(z: f32, near: f32, far: f32) -> f32 {
    let (z, n, f) = (z as f64, near as f64, far as f64);
    // Background (at or beyond the far plane, or NaN) is the cleared value 0.
    if z < f { (n * (f - z) / (z * (f - n))) as f32 } else { 0.0 }
}

/// What the export holds besides the files: the import parameters an engine passes.
pub fn import_params(frame: &Frame) -> ImportParams {
    let view = frame.camera.view;
    let engine = aokit_shaders::adapters::settings::AdapterSettings {
        convention: DEPTH_REVERSED,
        near: view.near,
        far: view.far,
    };
    engine.params(&frame.desc())
}

/// Write the export of `scene` seen in `frame` with G-buffer `gbuffer` (full target) into `dir`;
/// returns `export.json`'s contents.
pub fn write(
    dir: &Path,
    scene: &Scene,
    frame: &Frame,
    gbuffer: &GBufferImage,
    backend: &str,
) -> std::io::Result<serde_json::Value> {
    std::fs::create_dir_all(dir)?;
    let view = frame.camera.view;
    let put = |name: &str, bytes: &[u8]| crate::output::write_atomic_bytes(&dir.join(name), bytes);
    put("camera.bin", bytemuck::bytes_of(&frame.camera))?;
    let import = import_params(frame);
    put("import.bin", bytemuck::bytes_of(&import))?;
    // The engine's images: the inner image only.
    let depth: Vec<f32> =
        crop_inner(&view, &gbuffer.depth).iter().map(|&z| reversed_z(z, view.near, view.far)).collect();
    put("depth.d32", bytemuck::cast_slice(&depth))?;
    let full = view.size();
    let g = view.guard;
    let mut rgba8 = Vec::with_capacity(4 * depth.len());
    for y in g..full.y - g {
        for x in g..full.x - g {
            let c = (decode_normal(gbuffer.normals[(y * full.x + x) as usize]) * 0.5 + Vec3::splat(0.5)) * 255.0;
            rgba8.extend([c.x.round() as u8, c.y.round() as u8, c.z.round() as u8, 255]);
        }
    }
    put("normals.rgba8", &rgba8)?;
    // aokit's internal G-buffer of the full target.
    put("gbuffer_depth.f32", bytemuck::cast_slice(&gbuffer.depth))?;
    put("gbuffer_normals.u32", bytemuck::cast_slice(&gbuffer.normals))?;
    // The scene for ray tracing: corners, texture coordinates, materials, alpha masks.
    let corners: Vec<f32> = scene.triangles.iter().flatten().flat_map(|v| v.to_array()).collect();
    put("triangles.f32", bytemuck::cast_slice(&corners))?;
    let uvs: Vec<f32> = scene.triangle_uvs.iter().flatten().flat_map(|v| v.to_array()).collect();
    put("uvs.f32", bytemuck::cast_slice(&uvs))?;
    put("materials.u32", bytemuck::cast_slice(&scene.triangle_materials))?;
    let (headers, texels) = scene.alpha_masks();
    put("mask_headers.bin", bytemuck::cast_slice(&headers))?;
    put("mask_texels.f32", bytemuck::cast_slice(&texels))?;
    let mut json = frame.describe();
    json["format"] = FORMAT.into();
    json["scene"] = scene.name.clone().into();
    json["backend"] = backend.into();
    json["triangles"] = scene.triangles.len().into();
    json["files"] = serde_json::json!({
        "camera.bin": "aokit_Camera (aokit.h): view transforms and the full target's ViewParams",
        "import.bin": "aokit_ImportParams: the engine images' import (reversed Z, near, far, inner size)",
        "depth.d32": format!("{}×{} f32 reversed-Z hardware depth of the inner image (0 = background)", frame.inner.x, frame.inner.y),
        "normals.rgba8": format!("{}×{} RGBA8 view-space normals n·0.5 + 0.5 of the inner image", frame.inner.x, frame.inner.y),
        "gbuffer_depth.f32": format!("{}×{} f32 linear view depth of the full target (>= far: background)", full.x, full.y),
        "gbuffer_normals.u32": format!("{}×{} u32 octahedral view normals of the full target", full.x, full.y),
        "triangles.f32": "9 f32 per triangle: world-space corners",
        "uvs.f32": "6 f32 per triangle: corner texture coordinates",
        "materials.u32": "1 u32 per triangle: index into mask_headers.bin",
        "mask_headers.bin": "aokit_AlphaMaskHeader per material (width 0: opaque)",
        "mask_texels.f32": "alpha texels of every mask, row-major, one after another",
    });
    let text = serde_json::to_string_pretty(&json).expect("serializable") + "\n";
    crate::output::write_atomic_bytes(&dir.join("export.json"), text.as_bytes())?;
    Ok(json)
}
