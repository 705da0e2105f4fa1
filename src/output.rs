//! Cropping the full-target buffers to the output image and writing PNG / EXR.

use aokit_shaders::common::ViewParams;
use std::path::Path;

/// The inner image of a full-target buffer, row-major.
pub fn crop_inner(view: &ViewParams, full: &[f32]) -> Vec<f32> {
    let size = view.size();
    let g = view.guard;
    let mut out = Vec::with_capacity(((size.x - 2 * g) * (size.y - 2 * g)) as usize);
    for y in g..size.y - g {
        let row = (y * size.x) as usize;
        out.extend_from_slice(&full[row + g as usize..row + (size.x - g) as usize]);
    }
    out
}

/// 8-bit grey PNG of AO values (1 = unoccluded = white), rounded to nearest.
pub fn write_png(path: &Path, width: u32, height: u32, ao: &[f32]) -> Result<(), image::ImageError> {
    let bytes: Vec<u8> = ao.iter().map(|&a| (a.clamp(0.0, 1.0) * 255.0).round() as u8).collect();
    image::GrayImage::from_raw(width, height, bytes).expect("buffer matches size").save(path)
}

/// Raw float AO as a single-channel-equivalent (grey RGB) 32-bit EXR.
pub fn write_exr(path: &Path, width: u32, height: u32, ao: &[f32]) -> Result<(), image::ImageError> {
    let rgb: Vec<f32> = ao.iter().flat_map(|&a| [a, a, a]).collect();
    image::Rgb32FImage::from_raw(width, height, rgb).expect("buffer matches size").save(path)
}
