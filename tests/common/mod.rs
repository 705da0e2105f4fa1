//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod agreement;
pub mod depth_pass;
// Written in `agreement` (which other workspaces' tests include on its own, e.g. aokit-bevy's).
pub use agreement::{assert_same_len, inner_pair};
pub mod engine_device;
pub mod rng;
pub mod skip;
pub mod wgpu_adapter;

use aokit::frame::{CameraChoice, Frame, FrameRequest};
use aokit::render::VulkanRenderer;
use aokit::scene::Scene;
use aokit::scene::builtin;
use aokit_shaders::glam::{UVec2, Vec3, uvec2};
use aokit_vulkan::GpuOptions;

/// Open the Vulkan back-end with the Khronos validation layer (core and synchronisation
/// checks). Without a device the test fails, unless the run allows its skip
/// ([`skip::cannot_run`]); `None` then, and the test returns.
pub fn vulkan() -> Option<VulkanRenderer> {
    match VulkanRenderer::new(&GpuOptions { validation: true, ..Default::default() }) {
        Ok(r) => Some(r),
        Err(e) => {
            skip::cannot_run(skip::VULKAN, &format!("no Vulkan device with validation ({e})"));
            None
        }
    }
}

/// A synthetic G-buffer: a fronto-parallel wall at depth 10 with a raised block at depth 9,
/// both facing the camera, an `inner` image (at least 48×40) with a guard band of 8, the frame
/// for it and the VAO/blur parameters.
pub fn step_gbuffer(
    inner: UVec2,
) -> (aokit_shaders::graph::FrameDesc, aokit_shaders::vao::VaoParams, aokit_shaders::blur::BlurParams, Vec<f32>, Vec<u32>)
{
    let guard = 8;
    let camera = aokit_shaders::common::camera::Camera::look_at(
        Vec3::ZERO,
        -Vec3::Z,
        Vec3::Y,
        60f32.to_radians(),
        inner,
        guard,
        0.01,
        100.0,
    );
    let view = camera.view;
    let size = view.size();
    let mut depth = vec![10.0f32; (size.x * size.y) as usize];
    for y in 20..size.y - 20 {
        for x in 24..size.x - 24 {
            depth[(y * size.x + x) as usize] = 9.0;
        }
    }
    let normals = vec![aokit_shaders::common::normal_codec::encode_normal(Vec3::Z); depth.len()];
    let frame = aokit_shaders::graph::FrameDesc::new(camera, 2.0, 2.0, 0.0);
    let vao =
        aokit_shaders::vao::VaoParams { view, radius: 2.0, exponent: 2.0, thickness: 0.0, max_screen_radius: 512.0 };
    let blur = aokit_shaders::blur::BlurParams { view, direction: uvec2(1, 0), sharpness: 16.0, _pad: 0 };
    (frame, vao, blur, depth, normals)
}

/// Pass 2 (spec svao-raysd §9) on the CPU from a run's own pass-1 AO and mask and its SD map
/// `map`, refining only the flagged samples `keep` selects by their running index: `|_| true`
/// reproduces the run's pass-2 AO; leaving every k-th out models a pass 2 that misses 1 in k
/// flagged samples (they keep their pass-1 value) — the defect the SD tests' bounds are
/// derived from.
pub fn pass2_refining(
    params: &aokit_shaders::svao::SvaoParams,
    g: &aokit_cpu::GBufferImage,
    (ao_pass1, mask): (&[f32], &[u32]),
    map: &[f32],
    keep: impl Fn(u64) -> bool,
) -> Vec<f32> {
    use aokit_shaders::common::gbuffer_read::GBufferSlices;
    use aokit_shaders::raysd::SdMapRefine;
    use aokit_shaders::svao::{Refine, Refined, pass2_pixel};
    use aokit_shaders::vao::kernel::{LineSample, PixelFrame};
    struct Some_<'a, F> {
        inner: SdMapRefine<'a>,
        keep: F,
        k: u64,
    }
    impl<F: Fn(u64) -> bool> Refine for Some_<'_, F> {
        fn refine(&mut self, f: &PixelFrame, s: &LineSample, v: f32, z: f32) -> Refined {
            self.k += 1;
            if (self.keep)(self.k) { self.inner.refine(f, s, v, z) } else { Refined { v, rays: 0 } }
        }
    }
    let view = &params.vao.view;
    let size = view.size();
    let gb = GBufferSlices { depth: &g.depth, normals: &g.normals, width: g.width };
    let mut out = ao_pass1.to_vec();
    let mut refine = Some_ { inner: SdMapRefine { map, params }, keep, k: 0 };
    for y in view.guard..size.y - view.guard {
        for x in view.guard..size.x - view.guard {
            let p = uvec2(x, y);
            let i = view.index(p);
            out[i] = pass2_pixel(&gb, &[], params, p, ao_pass1[i], mask[i], &mut refine).ao;
        }
    }
    out
}

/// Pass 2 refined only where `keep` says, on a CPU run's own refinement buffers `d`, after
/// asserting that refining every flagged sample reproduces the run's pass-2 AO `ao` over the
/// inner image: the defect images the SD tests derive their bounds from then differ from `ao`
/// only by the samples left out.
pub fn pass2_defects<'a>(
    params: &'a aokit_shaders::svao::SvaoParams,
    g: &'a aokit_cpu::GBufferImage,
    d: &'a aokit_shaders::graph::Refinement,
    ao: &[f32],
) -> impl Fn(&dyn Fn(u64) -> bool) -> Vec<f32> + 'a {
    let refining = move |keep: &dyn Fn(u64) -> bool| pass2_refining(params, g, (&d.ao_pass1, &d.mask), &d.sd_map, keep);
    let (all, run) = inner_pair(&params.vao.view, &refining(&|_| true), ao);
    assert!(all == run, "pass2_refining must reproduce the CPU's pass 2");
    refining
}

/// Fail on any validation warning or error.
pub fn assert_validation_clean(r: &VulkanRenderer) {
    let messages = r.gpu.validation_messages();
    assert!(messages.is_empty(), "validation layer reported:\n{}", messages.join("\n"));
}

/// A built-in scene (fetched and cached on first use) with its default camera.
pub fn builtin_frame(name: &str, width: u32, height: u32, guard: u32) -> (Scene, Frame) {
    let b = builtin::find(name).expect("built-in scene");
    let scene = b.load().unwrap_or_else(|e| panic!("{e}"));
    let req = FrameRequest {
        width,
        height,
        guard,
        camera: CameraChoice::Preset { name: None, fov_deg: None },
        radius: None,
        exponent: 2.0,
        thickness: 0.0,
    };
    let frame = Frame::resolve(&scene, Some(b), &req).unwrap();
    (scene, frame)
}

/// MSE over equal-length, non-empty slices (f64).
pub fn mse_of(a: &[f32], b: &[f32]) -> f64 {
    assert_same_len(a, b, "mse");
    a.iter().zip(b).map(|(x, y)| (*x as f64 - *y as f64).powi(2)).sum::<f64>() / a.len() as f64
}

/// MSE over the inner image of two full-target buffers.
pub fn inner_mse(view: &aokit_shaders::common::ViewParams, a: &[f32], b: &[f32]) -> f64 {
    let (a, b) = inner_pair(view, a, b);
    mse_of(&a, &b)
}

/// Fraction of equal-length, non-empty slices' elements with `|a − b| ≤ tolerance`.
pub fn fraction_within(a: &[f32], b: &[f32], tolerance: f32) -> f64 {
    assert_same_len(a, b, "fraction within");
    a.iter().zip(b).filter(|(x, y)| (*x - *y).abs() <= tolerance).count() as f64 / a.len() as f64
}

/// Fraction of inner pixels of two full-target buffers with `|a − b| ≤ tolerance`.
pub fn inner_within(view: &aokit_shaders::common::ViewParams, a: &[f32], b: &[f32], tolerance: f32) -> f64 {
    let (a, b) = inner_pair(view, a, b);
    fraction_within(&a, &b, tolerance)
}

/// Largest `|a − b|` over the inner image of two full-target buffers.
pub fn inner_max_abs(view: &aokit_shaders::common::ViewParams, a: &[f32], b: &[f32]) -> f32 {
    let (a, b) = inner_pair(view, a, b);
    a.iter().zip(&b).map(|(x, y)| (x - y).abs()).fold(0.0, f32::max)
}

/// Upper tail `P(X ≥ x)` of the χ² distribution with `df` degrees of freedom: the regularized
/// upper incomplete gamma function `Q(df/2, x/2)` (series below `a + 1`, Lentz continued fraction
/// above; Numerical Recipes §6.2), accurate to ~1e-12 relative for the sizes the tests use.
pub fn chi2_p_value(x: f64, df: usize) -> f64 {
    assert!(df > 0 && x >= 0.0);
    let a = df as f64 / 2.0;
    let x = x / 2.0;
    if x == 0.0 {
        return 1.0;
    }
    let ln_prefix = a * x.ln() - x - ln_gamma(a);
    if x < a + 1.0 {
        // P(a, x) = e^{−x} x^a / Γ(a + 1) · Σ x^n / ((a+1)…(a+n)).
        let (mut term, mut sum, mut ap) = (1.0 / a, 1.0 / a, a);
        for _ in 0..10_000 {
            ap += 1.0;
            term *= x / ap;
            sum += term;
            if term.abs() < sum.abs() * 1e-16 {
                break;
            }
        }
        1.0 - sum * ln_prefix.exp()
    } else {
        let tiny = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..10_000 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            if d.abs() < tiny {
                d = tiny;
            }
            c = b + an / c;
            if c.abs() < tiny {
                c = tiny;
            }
            d = 1.0 / d;
            let delta = d * c;
            h *= delta;
            if (delta - 1.0).abs() < 1e-16 {
                break;
            }
        }
        ln_prefix.exp() * h
    }
}

/// `ln Γ(x)` for x > 0 (Lanczos, g = 7, 9 coefficients; ~1e-15 relative).
fn ln_gamma(x: f64) -> f64 {
    const G: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        // Reflection: Γ(x)Γ(1 − x) = π / sin(πx).
        return (std::f64::consts::PI / (std::f64::consts::PI * x).sin()).ln() - ln_gamma(1.0 - x);
    }
    let x = x - 1.0;
    let mut s = G[0];
    for (i, &g) in G.iter().enumerate().skip(1) {
        s += g / (x + i as f64);
    }
    let t = x + 7.5;
    0.5 * (2.0 * std::f64::consts::PI).ln() + (x + 0.5) * t.ln() - t + s.ln()
}

/// cpu-sim's ground-truth kernel (spec gtao-raymarch-hybrid §5) with `params` on a given
/// G-buffer of `frame`: the AO per full-target pixel.
#[allow(dead_code)]
pub fn cpu_ground_truth(
    cpu: &aokit::render::CpuRenderer,
    frame: &aokit::frame::Frame,
    gbuffer: &aokit_cpu::GBufferImage,
    params: &aokit_shaders::groundtruth::GroundTruthParams,
) -> Vec<f32> {
    let gt = aokit_shaders::groundtruth::GroundTruthFrame {
        camera: frame.camera,
        params: *params,
        ..bytemuck::Zeroable::zeroed()
    };
    aokit_cpu::run_ground_truth(cpu.bvh(), &cpu.surfaces(), &gt, gbuffer, &aokit_cpu::no_progress).0
}

/// The value of the IEEE 754 half-precision number `h`.
pub fn f16_to_f32(h: u16) -> f32 {
    let (sign, exp, mant) = ((h >> 15) as i32, ((h >> 10) & 0x1F) as i32, (h & 0x3FF) as f32);
    let magnitude = match exp {
        0 => mant * 2f32.powi(-24),
        31 => f32::INFINITY,
        e => (1.0 + mant / 1024.0) * 2f32.powi(e - 15),
    };
    if sign == 1 { -magnitude } else { magnitude }
}

/// Half precision of `x` in [0, 1] (round to nearest; the CPU reference reads the stored
/// bits back, so only the stored value matters).
pub fn f32_to_f16(x: f32) -> u16 {
    let x = x as f64;
    if x < 2f64.powi(-14) {
        return (x / 2f64.powi(-24)).round() as u16;
    }
    let e = x.log2().floor() as i32;
    let mant = (x / 2f64.powi(e) * 1024.0).round() as u32 - 1024;
    if mant == 1024 { ((e + 16) as u16) << 10 } else { (((e + 15) as u16) << 10) | mant as u16 }
}
