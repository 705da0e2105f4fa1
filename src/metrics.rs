//! Image-quality metrics over the inner image (guard band excluded) and an optional mask:
//! MSE, PSNR and SSIM (Wang, Bovik, Sheikh & Simoncelli 2004: 11×11 Gaussian window, σ = 1.5,
//! K1 = 0.01, K2 = 0.03, dynamic range L = 1; the mean of the SSIM map over every window that
//! lies completely inside the image, i.e. MATLAB `ssim_index`'s 'valid' filtering;
//! spec gtao-raymarch-hybrid §6.1–§6.2), and FLIP, NVIDIA's perceptual difference of the images
//! as displayed (spec gtao-raymarch-hybrid §6.4).

/// A single-channel image, row-major.
#[derive(Copy, Clone, Debug)]
pub struct ImageRef<'a> {
    /// Pixels per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// `width · height` values, row-major.
    pub pixels: &'a [f32],
}

impl ImageRef<'_> {
    fn at(&self, x: usize, y: usize) -> f64 {
        self.pixels[y * self.width + x] as f64
    }
}

fn check_same_size(a: &ImageRef, b: &ImageRef) {
    assert_eq!((a.width, a.height), (b.width, b.height), "metric inputs differ in size");
    assert_eq!(a.pixels.len(), a.width * a.height, "pixel count");
    assert_eq!(b.pixels.len(), b.width * b.height, "pixel count");
}

/// Mean squared error over the pixels where `mask` (if any) is true; `None` if none counts.
pub fn mse(a: ImageRef, b: ImageRef, mask: Option<&[bool]>) -> Option<f64> {
    check_same_size(&a, &b);
    let (mut sum, mut n) = (0.0f64, 0usize);
    for i in 0..a.pixels.len() {
        if mask.is_none_or(|m| m[i]) {
            let d = a.pixels[i] as f64 - b.pixels[i] as f64;
            sum += d * d;
            n += 1;
        }
    }
    (n > 0).then(|| sum / n as f64)
}

/// Peak signal-to-noise ratio in dB for peak 1: `10·log10(1/MSE)` (∞ for identical images).
pub fn psnr(mse: f64) -> f64 {
    10.0 * (1.0 / mse).log10()
}

const WINDOW: usize = 11;
const SIGMA: f64 = 1.5;
const C1: f64 = 0.01 * 0.01;
const C2: f64 = 0.03 * 0.03;

fn gaussian_window() -> [[f64; WINDOW]; WINDOW] {
    let mut w = [[0.0; WINDOW]; WINDOW];
    let c = (WINDOW / 2) as f64;
    let mut total = 0.0;
    for (y, row) in w.iter_mut().enumerate() {
        for (x, v) in row.iter_mut().enumerate() {
            let (dx, dy) = (x as f64 - c, y as f64 - c);
            *v = (-(dx * dx + dy * dy) / (2.0 * SIGMA * SIGMA)).exp();
            total += *v;
        }
    }
    w.iter_mut().flatten().for_each(|v| *v /= total);
    w
}

/// Mean SSIM over the windows whose centre pixel is in `mask` (all if `None`); `None` if the
/// image is smaller than the 11×11 window or no window counts.
pub fn ssim(a: ImageRef, b: ImageRef, mask: Option<&[bool]>) -> Option<f64> {
    check_same_size(&a, &b);
    if a.width < WINDOW || a.height < WINDOW {
        return None;
    }
    let w = gaussian_window();
    let half = WINDOW / 2;
    let (mut sum, mut n) = (0.0, 0usize);
    for cy in half..a.height - half {
        for cx in half..a.width - half {
            if mask.is_some_and(|m| !m[cy * a.width + cx]) {
                continue;
            }
            let (mut mx, mut my, mut xx, mut yy, mut xy) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for (wy, row) in w.iter().enumerate() {
                for (wx, &k) in row.iter().enumerate() {
                    let (x, y) = (cx + wx - half, cy + wy - half);
                    let (p, q) = (a.at(x, y), b.at(x, y));
                    mx += k * p;
                    my += k * q;
                    xx += k * p * p;
                    yy += k * q * q;
                    xy += k * p * q;
                }
            }
            let (vx, vy, cxy) = (xx - mx * mx, yy - my * my, xy - mx * my);
            sum += ((2.0 * mx * my + C1) * (2.0 * cxy + C2)) / ((mx * mx + my * my + C1) * (vx + vy + C2));
            n += 1;
        }
    }
    (n > 0).then(|| sum / n as f64)
}

/// FLIP's viewing condition, in pixels per degree of visual angle: the FLIP paper's default, a
/// 0.7 m wide 3840-pixel monitor seen from 0.7 m (spec gtao-raymarch-hybrid §6.4).
pub const FLIP_PIXELS_PER_DEGREE: f32 = nv_flip::DEFAULT_PIXELS_PER_DEGREE;

/// The grey level an AO value is displayed with: `round(clamp(v, 0, 1) · 255)`, as aokit's PNGs
/// store it.
pub fn display_grey(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// LDR-FLIP's per-pixel error map of `test` against `reference` (each value in [0, 1]; 0 where
/// a viewer flipping between the two images sees no difference). Both images are judged as
/// displayed: every AO value becomes the sRGB grey level [`display_grey`], the PNG aokit writes
/// (spec gtao-raymarch-hybrid §6.4). Computed by NVIDIA's reference implementation (the
/// `nv-flip` crate) at [`FLIP_PIXELS_PER_DEGREE`].
pub fn flip_map(reference: ImageRef, test: ImageRef) -> Vec<f32> {
    check_same_size(&reference, &test);
    let rgb = |img: &ImageRef| -> nv_flip::FlipImageRgb8 {
        let bytes: Vec<u8> = img.pixels.iter().flat_map(|&v| [display_grey(v); 3]).collect();
        nv_flip::FlipImageRgb8::with_data(img.width as u32, img.height as u32, &bytes)
    };
    if reference.pixels.is_empty() {
        return Vec::new();
    }
    nv_flip::flip(rgb(&reference), rgb(&test), FLIP_PIXELS_PER_DEGREE).to_vec()
}

/// Mean LDR-FLIP error of `test` against `reference` ([`flip_map`]) over the pixels where `mask`
/// (if any) is true; `None` if none counts. The mean is the FLIP paper's recommended single
/// number (spec gtao-raymarch-hybrid §6.4).
pub fn flip(reference: ImageRef, test: ImageRef, mask: Option<&[bool]>) -> Option<f64> {
    masked_mean(&flip_map(reference, test), mask)
}

/// The mean of a per-pixel map over the pixels where `mask` (if any, as long as the map) is
/// true; `None` if none counts.
pub fn masked_mean(map: &[f32], mask: Option<&[bool]>) -> Option<f64> {
    if let Some(m) = mask {
        assert_eq!(m.len(), map.len(), "mask and map differ in length");
    }
    let (mut sum, mut n) = (0.0f64, 0usize);
    for (i, &e) in map.iter().enumerate() {
        if mask.is_none_or(|m| m[i]) {
            sum += e as f64;
            n += 1;
        }
    }
    (n > 0).then(|| sum / n as f64)
}
