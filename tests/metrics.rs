//! MSE / PSNR / SSIM against hand-computed cases and their defining properties.

mod common;

use aokit::metrics::{ImageRef, mse, psnr, ssim};

fn img(width: usize, height: usize, pixels: &[f32]) -> ImageRef<'_> {
    ImageRef { width, height, pixels }
}

#[test]
fn mse_matches_a_naive_double_loop_and_respects_the_mask() {
    let (w, h) = (13, 7);
    let a = common::rng::noise(w * h, 1);
    let b = common::rng::noise(w * h, 2);
    let mut naive = 0.0f64;
    for y in 0..h {
        for x in 0..w {
            let d = a[y * w + x] as f64 - b[y * w + x] as f64;
            naive += d * d;
        }
    }
    naive /= (w * h) as f64;
    assert!((mse(img(w, h, &a), img(w, h, &b), None).unwrap() - naive).abs() < 1e-12);
    // Hand case: a = [0, 1, 0.5, 0.5], b = [0, 0, 0.5, 1] → squared errors 0, 1, 0, 0.25.
    let (p, q) = ([0.0, 1.0, 0.5, 0.5], [0.0, 0.0, 0.5, 1.0]);
    assert_eq!(mse(img(2, 2, &p), img(2, 2, &q), None), Some(1.25 / 4.0));
    assert_eq!(mse(img(2, 2, &p), img(2, 2, &q), Some(&[true, false, true, true])), Some(0.25 / 3.0));
    assert_eq!(mse(img(2, 2, &p), img(2, 2, &q), Some(&[false; 4])), None);
    assert!((psnr(0.01) - 20.0).abs() < 1e-12);
    assert!(psnr(0.0).is_infinite());
}

#[test]
fn ssim_of_an_image_with_itself_is_one_and_ssim_is_symmetric() {
    let (w, h) = (32, 24);
    let a = common::rng::noise(w * h, 7);
    let b: Vec<f32> = a.iter().zip(common::rng::noise(w * h, 9)).map(|(x, n)| 0.7 * x + 0.3 * n).collect();
    assert!((ssim(img(w, h, &a), img(w, h, &a), None).unwrap() - 1.0).abs() < 1e-12);
    let ab = ssim(img(w, h, &a), img(w, h, &b), None).unwrap();
    let ba = ssim(img(w, h, &b), img(w, h, &a), None).unwrap();
    assert!((ab - ba).abs() < 1e-12);
    assert!(ab < 0.99 && ab > 0.0, "{ab}");
    assert_eq!(ssim(img(10, 10, &a[..100]), img(10, 10, &a[..100]), None), None, "smaller than the window");
}

#[test]
fn ssim_of_constant_images_follows_the_closed_form() {
    // Constant images a ≡ 0.2, b ≡ 0.6: variances and covariance vanish, so every window gives
    // SSIM = (2·0.2·0.6 + C1)/(0.2² + 0.6² + C1) with C1 = (0.01·1)².
    let (w, h) = (16, 12);
    let (a, b) = (vec![0.2f32; w * h], vec![0.6f32; w * h]);
    let c1 = 1e-4;
    let (p, q) = (0.2f32 as f64, 0.6f32 as f64);
    let expected = (2.0 * p * q + c1) / (p * p + q * q + c1);
    assert!((ssim(img(w, h, &a), img(w, h, &b), None).unwrap() - expected).abs() < 1e-9);
    // A contrast-only change: a checkerboard vs its half-contrast copy around the same mean 0.5.
    // μx = μy; the window's Gaussian weights give σx² = 4σy² and σxy = 2σy², so
    // SSIM = (2·2σ² + C2)/(4σ² + σ² + C2) with σ² = σy², the same in every window up to edges.
    let cb: Vec<f32> = (0..w * h).map(|i| if (i % w + i / w) % 2 == 0 { 0.9 } else { 0.1 }).collect();
    let half: Vec<f32> = cb.iter().map(|v| 0.5 + 0.5 * (v - 0.5)).collect();
    let s = ssim(img(w, h, &cb), img(w, h, &half), None).unwrap();
    let c2 = 9e-4;
    // σy² for the half-contrast board: weighted variance of ±0.2 around (almost) 0.5 ≈ 0.04.
    let sy2 = 0.04;
    let approx = (4.0 * sy2 + c2) / (5.0 * sy2 + c2);
    assert!((s - approx).abs() < 2e-3, "{s} vs {approx}");
}

/// SSIM of two fixed 24×20 images against an independent implementation. Images (exact in
/// binary): a(x, y) = ((3x + 5y + x·y) mod 17)/16, b(x, y) = ((16·a(x, y) + (x·y + 2x) mod 5)
/// mod 17)/16. Reference value from scikit-image 0.26.0 (Python 3.11.7, numpy 2.4.6):
/// `skimage.metrics.structural_similarity(a, b, gaussian_weights=True, sigma=1.5,
/// use_sample_covariance=False, data_range=1.0)` on float64 arrays of shape (20, 24) — an 11×11
/// Gaussian window (truncate 3.5 → radius 5), K1 = 0.01, K2 = 0.03, the mean over the windows
/// fully inside the image. A plain numpy loop over those (W−10)×(H−10) windows gives the same
/// value to all 16 digits. σ = 1.4 would give 0.58954, σ = 1.6 0.59051, skimage's default 7×7
/// uniform window 0.57667, the sample (N − 1) covariance 0.5911387.
#[test]
fn ssim_matches_scikit_image_on_fixed_images() {
    let (w, h) = (24usize, 20usize);
    let mut a = Vec::with_capacity(w * h);
    let mut b = Vec::with_capacity(w * h);
    for y in 0..h {
        for x in 0..w {
            let ai = (3 * x + 5 * y + x * y) % 17;
            a.push(ai as f32 / 16.0);
            b.push(((ai + (x * y + 2 * x) % 5) % 17) as f32 / 16.0);
        }
    }
    const SKIMAGE: f64 = 0.5911558898884012;
    let got = ssim(img(w, h, &a), img(w, h, &b), None).unwrap();
    assert!((got - SKIMAGE).abs() < 1e-9, "SSIM {got:.16} vs scikit-image {SKIMAGE}");
}
