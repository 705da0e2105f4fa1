//! The import/export adapters of `aokit_shaders::adapters` over whole images: the same pure
//! functions the `import_depth`, `import_normals` and `export_ao_*` entry points call, with the
//! engine's images as row-major slices of `params.engine_size` texels.

use aokit_shaders::adapters::{ImportParams, export_texel, import_depth_pixel, import_normal_pixel};
use aokit_shaders::glam::{UVec2, Vec3, uvec2};
use rayon::prelude::*;

/// `f(p)` for every pixel of a `size` grid, row-major, in parallel over rows.
fn map_grid<T: Send + Copy + Default>(size: UVec2, f: impl Fn(UVec2) -> T + Sync) -> Vec<T> {
    let mut out = vec![T::default(); (size.x * size.y) as usize];
    out.par_chunks_mut(size.x as usize).enumerate().for_each(|(y, row)| {
        for (x, v) in row.iter_mut().enumerate() {
            *v = f(uvec2(x as u32, y as u32));
        }
    });
    out
}

/// Texel `q` of a row-major engine image.
fn texel<T: Copy>(params: &ImportParams, image: &[T], q: UVec2) -> T {
    image[(q.y * params.engine_size.x + q.x) as usize]
}

fn check_engine_image(params: &ImportParams, len: usize) {
    let e = params.engine_size;
    assert!(e.x > 0 && e.y > 0, "empty engine image");
    assert_eq!(len, (e.x * e.y) as usize, "engine image is not {}×{}", e.x, e.y);
}

/// The engine's depth image (stored values, `params.depth_convention`) → aokit's full-target
/// linear depth buffer (background = `view.far`, guard band clamped to the edge).
pub fn import_depth(params: &ImportParams, engine_depth: &[f32]) -> Vec<f32> {
    check_engine_image(params, engine_depth.len());
    map_grid(params.view.size(), |p| import_depth_pixel(params, |q| texel(params, engine_depth, q), p))
}

/// The engine's view-space normal image (RGB = `n·0.5 + 0.5`) → aokit's full-target encoded
/// normal buffer.
pub fn import_normals(params: &ImportParams, rgb: &[[f32; 3]]) -> Vec<u32> {
    check_engine_image(params, rgb.len());
    map_grid(params.view.size(), |p| import_normal_pixel(params, |q| Vec3::from(texel(params, rgb, q)), p))
}

/// aokit's full-target AO buffer → the engine's AO image (`engine_size`, values in [0, 1]).
pub fn export_ao(params: &ImportParams, ao: &[f32]) -> Vec<f32> {
    let size = params.view.size();
    assert_eq!(ao.len(), (size.x * size.y) as usize, "AO buffer is not the full target");
    map_grid(params.engine_size, |q| export_texel(params, ao, q))
}
