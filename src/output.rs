//! Cropping the full-target buffers to the output image and writing PNG / EXR. Every file aokit
//! writes goes through [`write_atomic`] (a temporary file in the same directory, `fsync`, then
//! rename): a run killed or failing half-way leaves the old file or none, never a truncated one.

use aokit_shaders::common::ViewParams;
use std::io;
use std::path::Path;

pub use aokit_contract::atomic_file::{is_temp_name, write_atomic, write_atomic_bytes};

/// The inner image of a full-target buffer, row-major.
pub fn crop_inner<T: Copy>(view: &ViewParams, full: &[T]) -> Vec<T> {
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
    save_image(&image::GrayImage::from_raw(width, height, bytes).expect("buffer matches size"), path)
        .map_err(image::ImageError::IoError)
}

/// Bent normals as an RGB PNG: the packed RGBA8 words' rgb bytes (the normal ·0.5 + 0.5).
pub fn write_bent_png(path: &Path, width: u32, height: u32, bent: &[u32]) -> Result<(), image::ImageError> {
    let bytes: Vec<u8> = bent.iter().flat_map(|&w| [w as u8, (w >> 8) as u8, (w >> 16) as u8]).collect();
    save_image(&image::RgbImage::from_raw(width, height, bytes).expect("buffer matches size"), path)
        .map_err(image::ImageError::IoError)
}

/// Raw float AO as a single-channel-equivalent (grey RGB) 32-bit EXR.
pub fn write_exr(path: &Path, width: u32, height: u32, ao: &[f32]) -> Result<(), image::ImageError> {
    let rgb: Vec<f32> = ao.iter().flat_map(|&a| [a, a, a]).collect();
    save_image(&image::Rgb32FImage::from_raw(width, height, rgb).expect("buffer matches size"), path)
        .map_err(image::ImageError::IoError)
}

/// `img` into `path` atomically ([`write_atomic`]), in the format of the path's extension (as
/// `ImageBuffer::save`). Errors are one line naming `path`.
pub fn save_image<P, C>(img: &image::ImageBuffer<P, C>, path: &Path) -> io::Result<()>
where
    P: image::PixelWithColorType,
    [P::Subpixel]: image::EncodableLayout,
    C: std::ops::Deref<Target = [P::Subpixel]>,
{
    let format =
        image::ImageFormat::from_path(path).map_err(|e| io::Error::other(format!("{}: {e}", path.display())))?;
    write_atomic(path, |w| {
        img.write_to(w, format).map_err(|e| match e {
            image::ImageError::IoError(e) => e,
            e => io::Error::other(e),
        })
    })
}
