//! The raster coverage-mask stochastic depth map (spec svao-raysd §8): the mask statistics, the
//! LUT, and CPU ≡ Vulkan.

mod common;

use aokit::render::CpuRenderer;
use aokit::technique::{SdOptions, Technique};
use aokit_shaders::glam::vec3;
use aokit_shaders::rastersd::{coverage_mask, mask_lut, stratum_start};
use aokit_shaders::svao::settings::{RAYSD, RAYSVAO, SDSVAO};

/// Family-wise significance of the χ² comparisons of a test: a correct implementation fails it
/// with probability at most 0.1 % (Bonferroni over its comparisons), i.e. 99.9 % confidence.
const FAMILY_ALPHA: f64 = 0.001;

/// Spec svao-raysd §8: the N = 4 LUT lists the masks by popcount then value; `I = [0, 1, 5, 11, 15]`.
#[test]
fn lut_and_strata_match_the_spec() {
    let lut: Vec<u32> = (0..16).map(|i| mask_lut(4, i)).collect();
    assert_eq!(lut, [0, 1, 2, 4, 8, 3, 5, 6, 9, 10, 12, 7, 11, 13, 14, 15]);
    assert_eq!((0..5).map(|k| stratum_start(4, k)).collect::<Vec<_>>(), [0, 1, 5, 11, 15]);
    for n in [1u32, 2, 4, 8] {
        let mut all: Vec<u32> = (0..1 << n).map(|i| mask_lut(n, i)).collect();
        all.sort();
        assert_eq!(all, (0..1 << n).collect::<Vec<_>>(), "N = {n}: the LUT is a permutation");
    }
}

/// Coverage statistics over 2·10⁵ random world positions: each sample is kept with probability
/// α = 1.5/N (capped at 1) within 0.01; a fragment keeps Rn ∈ {1, 2} samples about half of the
/// time each (N ≥ 4; within 1 % of the fragments: the spec's Wyman hash is slightly biased —
/// measured 50.8 % Rn = 1, several binomial σ, so no tighter statistical claim is made on it);
/// and every sample is kept equally often.
///
/// The last claim as a proper χ²: given the fragments' popcounts m_f, a mask with m bits is a
/// uniformly random m-subset of the N samples, so the per-sample counts o_k have equal means ō
/// and, orthogonal to (1, …, 1), the covariance Σ_f m_f(N − m_f)/(N(N − 1)) (per fragment
/// Var − Cov of a random m-subset). X = Σ_k (o_k − ō)² / Σ_f m_f(N − m_f)/(N(N − 1)) is χ² with
/// N − 1 degrees of freedom. (Pearson's Σ (o − ō)²/ō is a fraction of X: 1/3 for N = 2, 0.78
/// for N = 4.) Stronger still, within each popcount the masks themselves must be equally
/// likely (a multinomial over the LUT's stratum). The six comparisons (N = 2, 4, 8) share
/// [`FAMILY_ALPHA`].
#[test]
fn coverage_keeps_the_expected_fraction_of_samples() {
    let mut rng = common::rng::Rng::new(99);
    let mut unit = || rng.unit();
    const FRAGMENTS: usize = 200_000;
    let alpha_each = FAMILY_ALPHA / 6.0;
    for n in [1u32, 2, 4, 8] {
        let mut per_sample = vec![0u64; n as usize];
        let mut by_count = vec![0u64; n as usize + 1];
        let mut by_mask = vec![0u64; 1 << n];
        for _ in 0..FRAGMENTS {
            let p = vec3(unit() * 40.0 - 20.0, unit() * 20.0, unit() * 40.0 - 20.0);
            let m = coverage_mask(p, n, 0);
            by_count[m.count_ones() as usize] += 1;
            by_mask[m as usize] += 1;
            for (k, c) in per_sample.iter_mut().enumerate() {
                *c += (m >> k) as u64 & 1;
            }
        }
        let fraction = per_sample.iter().sum::<u64>() as f64 / (FRAGMENTS as f64 * n as f64);
        let alpha = (1.5 / n as f64).min(1.0);
        eprintln!("N = {n}: kept fraction {fraction:.4} (α = {alpha:.4}), popcounts {by_count:?}");
        // Binomial standard error of the mean over 2·10⁵ fragments is < 0.002.
        assert!((fraction - alpha).abs() < 0.01, "N = {n}: kept {fraction}, expected {alpha}");
        if n > 1 {
            let nf = n as f64;
            let mean = per_sample.iter().sum::<u64>() as f64 / nf;
            let variance: f64 =
                by_count.iter().enumerate().map(|(m, &f)| f as f64 * m as f64 * (nf - m as f64)).sum::<f64>()
                    / (nf * (nf - 1.0));
            let chi2: f64 = per_sample.iter().map(|&o| (o as f64 - mean).powi(2) / variance).sum();
            let p_value = common::chi2_p_value(chi2, n as usize - 1);
            eprintln!("N = {n}: per-sample counts {per_sample:?}, χ² = {chi2:.2} ({} df), p = {p_value:.3}", n - 1);
            assert!(
                p_value >= alpha_each,
                "N = {n}: samples not kept equally often, χ² = {chi2:.1}, p = {p_value:.2e}; {per_sample:?}"
            );
            // Within each popcount m, the C(N, m) masks are equally likely: Pearson's χ² of a
            // multinomial, C(N, m) − 1 degrees of freedom per stratum, summed over the strata.
            let (mut chi2, mut df) = (0.0, 0usize);
            for m in 1..n {
                let masks: Vec<u64> =
                    (0..1u32 << n).filter(|k| k.count_ones() == m).map(|k| by_mask[k as usize]).collect();
                let total = masks.iter().sum::<u64>() as f64;
                if total == 0.0 || masks.len() < 2 {
                    continue;
                }
                let e = total / masks.len() as f64;
                assert!(e >= 5.0);
                chi2 += masks.iter().map(|&o| (o as f64 - e).powi(2) / e).sum::<f64>();
                df += masks.len() - 1;
            }
            let p_value = common::chi2_p_value(chi2, df);
            eprintln!("N = {n}: masks within their popcount, χ² = {chi2:.2} ({df} df), p = {p_value:.3}");
            assert!(
                p_value >= alpha_each,
                "N = {n}: masks of equal popcount not equally likely, χ² = {chi2:.1}, p = {p_value:.2e}"
            );
        }
        if n >= 4 {
            let half = FRAGMENTS as f64 / 2.0;
            for k in [1usize, 2] {
                assert!((by_count[k] as f64 - half).abs() < 0.01 * FRAGMENTS as f64, "N = {n}: Rn = {k} count");
            }
        }
    }
}

/// CPU ≡ Vulkan for the raster SD map on the same G-buffer: pass-1 masks identical, pass-2 AO
/// without bias, MSE and fraction within bounds derived from a pass 2 that refines half the
/// flagged samples (fragment positions differ in the last bits, so the hashes differ: statistical);
/// raster SD refines with a worse map than Ray-SD (the paper's claim), validation clean.
#[test]
fn raster_sd_vulkan_agrees_with_cpu() {
    let Some(vk) = common::vulkan() else { return };
    let (scene, frame) = common::builtin_frame("sponza", 320, 180, 32);
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
    let none = &aokit_cpu::no_progress;
    let t = Technique::new(&SDSVAO, SdOptions { raster: true, ..Default::default() });
    let (c, v) = (cpu.run(&frame, &g, &t, none), vk.run(&scene, &frame, &g, &t).unwrap());
    common::assert_validation_clean(&vk);
    let (cm, vm) = (&c.debug.as_ref().unwrap().mask, &v.debug.as_ref().unwrap().mask);
    common::assert_same_len(cm, vm, "pass-1 mask");
    assert!(cm.iter().any(|&m| m != 0), "the view must flag samples");
    assert_eq!(cm, vm);
    let view = frame.camera.view;
    let mse = |a: &[f32], b: &[f32]| common::inner_mse(&view, a, b);
    // The two SD maps are independent samples (fragment positions differ in the last bits, so
    // the coverage hashes differ): pass-2 AO of two correct maps differs by MSE ≈ 1e-4 (99.1 %
    // within 1/255), as much as a pass 2 that misses 1 in 10 flagged samples, so the MSE alone
    // cannot detect small defects. A defect that leaves samples unrefined is a BIAS (refinement
    // only darkens VAO), and independent maps are not: measured mean(Δ) for a pass 2 refining
    // half 4.7e-3 (MSE 1.1e-3, 95.9 % within), missing 1 in 10 9.0e-4 (MSE 2.0e-4, 99.2 %);
    // CPU vs Vulkan 7e-5 (naive standard error 4e-5). Bounds, derived here from the same
    // mutations: |mean(Δ)| ≤ 1/10 of the half effect (≈ 4.6e-4), MSE ≤ 1/5 of the half effect
    // (≈ 2.1e-4: the independent-map floor is 1/10 of it), fraction within ≥ 1 − 1/3 of the half
    // shortfall (≈ 98.7 %).
    let svao = SdOptions { raster: true, ..Default::default() }
        .frame(&frame.desc(), aokit_shaders::svao::Secondary::StochasticDepth);
    let dc = c.debug.as_ref().unwrap();
    let defect = common::pass2_defects(&svao.params, &g, dc, &c.ao);
    let bias = |x: &[f32]| {
        let (a, b) = common::inner_pair(&view, x, &c.ao);
        a.iter().zip(&b).map(|(x, y)| *x as f64 - *y as f64).sum::<f64>() / a.len() as f64
    };
    let half_ao = defect(&|k| k % 2 == 0);
    let (half, half_bias) = (common::agreement::inner(&view, &c.ao, &half_ao), bias(&half_ao));
    let a = common::agreement::inner(&view, &c.ao, &v.ao);
    let gpu_bias = bias(&v.ao);
    let (max_bias, max_mse, min_within) = (half_bias.abs() / 10.0, half.mse / 5.0, 1.0 - (1.0 - half.within) / 3.0);
    let line = format!(
        "{}, mean Δ {gpu_bias:.2e}\n{}, mean Δ {half_bias:.2e}\nbounds: |mean Δ| ≤ {max_bias:.2e}, MSE ≤ {max_mse:.2e}, within ≥ {:.3} %; final AO MSE {:.2e}; SD texels {} vs {}",
        a.line("sdsvao pass-2 AO CPU vs Vulkan"),
        half.line("pass 2 refining half"),
        100.0 * min_within,
        mse(&c.ao_final, &v.ao_final),
        c.rays,
        v.rays
    );
    eprintln!("{line}");
    assert!(half_bias > 1e-3 && half.mse > 1e-4, "the mutation must change the image");
    assert!(gpu_bias.abs() <= max_bias, "{line}\nCPU and Vulkan differ by a bias");
    a.assert_bounds("sdsvao pass-2 AO CPU vs Vulkan", min_within, max_mse);
    assert_eq!(c.rays, v.rays);
    let reference = cpu.run(&frame, &g, &Technique::new(&RAYSVAO, SdOptions::default()), none).ao_final;
    let ray = cpu.run(&frame, &g, &Technique::new(&RAYSD, SdOptions::default()), none).ao_final;
    assert!(mse(&ray, &reference) < mse(&c.ao_final, &reference), "Ray-SD should beat the raster SD map");
}
