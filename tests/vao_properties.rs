//! Ring 1–2: properties of the VAO kernel and the blur on the CPU: the halo model's closed form,
//! robustness to broken G-buffers, and analytic scenes.

mod common;

use aokit::frame::{CameraChoice, Frame, FrameRequest};
use aokit::render::CpuRenderer;
use aokit::scene::Scene;
use aokit::scene::procedural::push_quad;
use aokit_cpu::{GBufferImage, no_progress, run_blur, run_vao};
use aokit_shaders::common::camera::Camera;
use aokit_shaders::common::normal_codec::encode_normal;
use aokit_shaders::glam::{UVec2, Vec2, Vec3, uvec2, vec3};
use aokit_shaders::vao::VaoParams;
use aokit_shaders::vao::kernel::{LineSample, halo_visibility};
use proptest::prelude::*;

fn sample(h: f32, end: f32) -> LineSample {
    LineSample {
        valid: true,
        half_chord: h,
        pdf: 2.0 * h,
        sphere_end: end,
        point: Vec3::ZERO,
        uv: Vec2::ZERO,
        texel: UVec2::ZERO,
        in_screen: true,
        screen_distance: 10.0,
        same_pixel: false,
    }
}

#[test]
fn halo_visibility_is_the_piecewise_closed_form() {
    // Spec svao-raysd §4.3 with R = 1, τ = 0.5, h = 0.6, hemisphere end = −0.2: the chord spans
    // [−0.2, 0.6] (length 0.8, pdf 1.2); constant zone (0.6, 1.5]; falloff (1.5, 2.1].
    let (r, tau, h, end) = (1.0, 0.5, 0.6, -0.2);
    let s = sample(h, end);
    let full = 0.8 / 1.2;
    let v = |z: f32| halo_visibility(z, &s, r, tau);
    let close = |a: f32, b: f32| (a - b).abs() < 1e-6;
    assert!(close(v(-5.0), full), "surface far behind: fully visible");
    assert!(close(v(end), full));
    assert!(close(v(0.2), 0.4 / 1.2), "inside the sphere: the visible chord (0.6 − 0.2)/pdf");
    assert!(close(v(h), 0.0));
    assert!(close(v(1.0), 0.0), "constant zone");
    assert!(close(v(1.5), 0.0));
    assert!(close(v(1.8), 0.5 * full), "half-way through the falloff");
    assert!(close(v(2.1), full));
    assert!(close(v(50.0), full), "surface far in front of the sphere: halo gone");
}

fn plane_gbuffer(view: &aokit_shaders::common::ViewParams, depth: f32) -> GBufferImage {
    let size = view.size();
    let n = (size.x * size.y) as usize;
    GBufferImage { width: size.x, height: size.y, depth: vec![depth; n], normals: vec![encode_normal(Vec3::Z); n] }
}

fn params(view: aokit_shaders::common::ViewParams, radius: f32) -> VaoParams {
    VaoParams { view, radius, exponent: 2.0, thickness: 0.0, max_screen_radius: 512.0 }
}

#[test]
fn fronto_parallel_plane_is_nearly_unoccluded() {
    // A plane facing the camera occludes nothing. On the view axis (n̂ ∥ N) every chord is cut
    // exactly at the plane, v_i = ½ and A = (2/8)·8·½ = 1. Off axis the plane is tilted against
    // n̂: the 8 samples' unequal radii no longer cancel and samples with less than 10 % of their
    // chord above the plane are dropped (spec svao-raysd §4.2, §15.2), so A dips a little below 1. The
    // guard band (32 px) covers the screen radius (≈ 26 px) as the spec intends.
    let cam = Camera::look_at(Vec3::ZERO, -Vec3::Z, Vec3::Y, 40f32.to_radians(), uvec2(128, 96), 32, 0.01, 100.0);
    let g = plane_gbuffer(&cam.view, 10.0);
    let mut p = params(cam.view, 2.0);
    p.exponent = 1.0;
    let ao = run_vao(&p, &g.depth, &g.normals, &no_progress);
    let centre = ao[cam.view.index(uvec2(32 + 64, 32 + 48))];
    assert!(centre > 0.995, "on axis: {centre}");
    let inner = aokit::output::crop_inner(&cam.view, &ao);
    let mean = inner.iter().sum::<f32>() / inner.len() as f32;
    let min = inner.iter().copied().fold(1.0, f32::min);
    assert!(mean > 0.97 && min > 0.9, "mean {mean}, min {min}");
}

/// Background pixels (depth at or beyond the far plane, or NaN) are unshaded (AO = 1) even where
/// the screen radius is large, so the `rpx < 0.5` exit (spec svao-raysd §4.1 step 4) cannot be what keeps
/// them at 1: at depth 100 with R = 50 the screen radius is ≈ 22 px (computed here from svao-raysd §4.1
/// step 2). Half the pixels are foreground 40 units in front of the sky, well inside R, so a
/// sky pixel that were shaded would be darkened, which the same geometry with the sky at 99.9
/// (a valid depth, just inside the far plane) confirms.
#[test]
fn sky_pixels_are_unshaded_even_with_a_large_screen_radius() {
    let cam = Camera::look_at(Vec3::ZERO, -Vec3::Z, Vec3::Y, 40f32.to_radians(), uvec2(32, 32), 4, 0.01, 100.0);
    let view = cam.view;
    let radius = 50.0f32;
    // svao-raysd §4.1 step 2 by hand: rpx = R·H/(2·ty·d), ty = tan(20°)·40/32, the same on both axes.
    let ty = (20f64.to_radians()).tan() * 40.0 / 32.0;
    let rpx = radius as f64 * 40.0 / (2.0 * ty * 100.0);
    assert!(rpx > 20.0, "the test needs a screen radius well above half a pixel: {rpx}");
    let shade = |sky: f32| {
        let mut g = plane_gbuffer(&view, 60.0);
        for (i, d) in g.depth.iter_mut().enumerate() {
            let (x, y) = (i as u32 % view.size().x, i as u32 / view.size().x);
            if (x + y) % 2 == 0 {
                *d = sky;
            }
        }
        let ao = run_vao(&params(view, radius), &g.depth, &g.normals, &no_progress);
        let sky_pixels: Vec<f32> = (0..ao.len())
            .filter(|&i| {
                let p = uvec2(i as u32 % view.size().x, i as u32 / view.size().x);
                view.is_inner(p) && (p.x + p.y).is_multiple_of(2)
            })
            .map(|i| ao[i])
            .collect();
        assert_eq!(sky_pixels.len(), 32 * 32 / 2);
        sky_pixels
    };
    // Control: just inside the far plane the same pixels are shaded and clearly occluded.
    let shaded = shade(99.9);
    let mean = shaded.iter().sum::<f32>() / shaded.len() as f32;
    assert!(mean < 0.5, "control: sky pixels at a valid depth should be occluded, mean AO {mean}");
    for sky in [100.0, 150.0, f32::NAN] {
        let ao = shade(sky);
        let bad = ao.iter().filter(|&&a| a != 1.0).count();
        assert_eq!(bad, 0, "depth {sky}: {bad} background pixels shaded, e.g. {:?}", &ao[..4]);
    }
}

/// A screen radius below half a pixel leaves the pixel unshaded (spec svao-raysd §4.1 step 4).
#[test]
fn sub_pixel_radii_are_unshaded() {
    let cam = Camera::look_at(Vec3::ZERO, -Vec3::Z, Vec3::Y, 40f32.to_radians(), uvec2(32, 32), 4, 0.01, 100.0);
    let (depth, radius) = (10.0, 1e-4);
    let mut g = plane_gbuffer(&cam.view, depth);
    // An occluder right next to every pixel that would darken a shaded pixel.
    for (i, d) in g.depth.iter_mut().enumerate() {
        if i % 2 == 0 {
            *d = depth - 0.5 * radius;
        }
    }
    let ao = run_vao(&params(cam.view, radius), &g.depth, &g.normals, &no_progress);
    assert!(ao.iter().all(|&a| a == 1.0));
}

fn crease_scene() -> Scene {
    // Floor y = 0 and a wall x = 0 meeting in a right-angle crease along z.
    let mut s = Scene::default();
    push_quad(&mut s, vec3(0.0, 0.0, 20.0), vec3(20.0, 0.0, 20.0), vec3(20.0, 0.0, -20.0), vec3(0.0, 0.0, -20.0));
    push_quad(&mut s, vec3(0.0, 0.0, -20.0), vec3(0.0, 10.0, -20.0), vec3(0.0, 10.0, 20.0), vec3(0.0, 0.0, 20.0));
    s.validated(std::path::Path::new("crease")).unwrap()
}

#[test]
fn ao_darkens_towards_a_crease() {
    let scene = crease_scene();
    let req = FrameRequest {
        width: 96,
        height: 64,
        guard: 16,
        camera: CameraChoice::Explicit {
            eye: vec3(6.0, 3.0, 0.0),
            target: vec3(0.0, 0.0, 0.0),
            up: Vec3::Y,
            fov_deg: 50.0,
        },
        radius: Some(1.0),
        exponent: 1.0,
        thickness: 0.0,
    };
    let frame = Frame::resolve(&scene, None, &req).unwrap();
    let (g, _) = CpuRenderer::new(&scene).gbuffer(&frame, &no_progress);
    let ao = run_vao(&frame.vao_params(), &g.depth, &g.normals, &no_progress);
    // Walk along the floor away from the crease through the image centre column's world
    // points: project floor points at distance s from the wall.
    let at = |s: f32| {
        let p = frame.camera.world_to_view.transform_point3(vec3(s, 0.0, 0.0));
        let uv = frame.camera.view.view_to_uv(p);
        ao[frame.camera.view.index(frame.camera.view.texel_of_uv(uv))]
    };
    let profile: Vec<f32> = [0.1, 0.3, 0.6, 1.5, 3.0].iter().map(|&s| at(s)).collect();
    assert!(profile[0] < 0.85, "next to the crease: {profile:?}");
    assert!(profile[0] < profile[2] && profile[2] < profile[3] + 1e-3, "monotone: {profile:?}");
    assert!(profile[4] > 0.97, "beyond the radius: {profile:?}");
}

fn any_depth() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(0.0f32),
        Just(-1.0f32),
        Just(1.0e30f32),
        Just(f32::MIN_POSITIVE),
        0.001f32..100.0,
        0.5f32..2.0,
    ]
}

fn any_normal() -> impl Strategy<Value = Vec3> {
    prop_oneof![
        Just(Vec3::ZERO),
        Just(Vec3::NAN),
        Just(Vec3::INFINITY),
        (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0).prop_map(|(x, y, z)| vec3(x, y, z)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn vao_and_blur_stay_finite_in_unit_range(
        depths in prop::collection::vec(any_depth(), 24 * 20),
        normals in prop::collection::vec(any_normal(), 24 * 20),
        radius in prop_oneof![Just(1e-6f32), 0.01f32..5.0, Just(1e6f32)],
        exponent in 0.5f32..4.0,
        fov in 10.0f32..120.0,
    ) {
        let cam = Camera::look_at(Vec3::ZERO, -Vec3::Z, Vec3::Y, fov.to_radians(), uvec2(16, 12), 4, 0.01, 100.0);
        let normals: Vec<u32> = normals.into_iter().map(encode_normal).collect();
        let p = VaoParams { view: cam.view, radius, exponent, thickness: 0.0, max_screen_radius: 512.0 };
        let ao = run_vao(&p, &depths, &normals, &no_progress);
        for (i, a) in ao.iter().enumerate() {
            prop_assert!(a.is_finite() && (0.0..=1.0).contains(a), "pixel {i}: {a}");
        }
        let blur = aokit_shaders::blur::BlurParams { view: cam.view, direction: uvec2(1, 0), sharpness: 16.0, _pad: 0 };
        let blurred = run_blur(&blur, &ao, &depths);
        for (i, a) in blurred.iter().enumerate() {
            prop_assert!(a.is_finite() && (0.0..=1.0).contains(a), "blurred pixel {i}: {a}");
        }
    }
}

fn blur_setup(inner: UVec2) -> (aokit_shaders::common::ViewParams, aokit_shaders::blur::BlurParams) {
    let cam = Camera::look_at(Vec3::ZERO, -Vec3::Z, Vec3::Y, 40f32.to_radians(), inner, 4, 0.01, 100.0);
    let blur = aokit_shaders::blur::BlurParams { view: cam.view, direction: uvec2(1, 0), sharpness: 16.0, _pad: 0 };
    (cam.view, blur)
}

fn variance(v: &[f32]) -> f64 {
    let m = v.iter().map(|&x| x as f64).sum::<f64>() / v.len() as f64;
    v.iter().map(|&x| (x as f64 - m).powi(2)).sum::<f64>() / v.len() as f64
}

/// Inner pixels at least `margin` pixels from the inner image's border.
fn interior(view: &aokit_shaders::common::ViewParams, v: &[f32], margin: u32) -> Vec<f32> {
    let size = view.size();
    let g = view.guard + margin;
    (g..size.y - g)
        .flat_map(|y| (g..size.x - g).map(move |x| (x, y)))
        .map(|(x, y)| v[(y * size.x + x) as usize])
        .collect()
}

/// Spec svao-raysd §12 on a flat depth: a constant stays constant, and white noise is smoothed by the
/// separable Gaussian `w_d = 2^(−0.08·d²)`, d = −4..4. Per pass the variance of i.i.d. noise
/// shrinks by Σw²/(Σw)²: Σw = 1 + 2·(0.94606 + 0.80107 + 0.60709 + 0.41180) = 6.53203,
/// Σw² = 1 + 2·(0.89503 + 0.64171 + 0.36856 + 0.16958) = 5.14976, ratio 0.120694; two passes
/// give 0.120694² = 0.014567. Measured on the pixels ≥ 4 px from the border (no clamping), the
/// sample ratio must lie within ±25 % of that (an identity blur gives 1).
#[test]
fn blur_smooths_noise_on_a_flat_depth() {
    // Large enough that the variance estimate of the correlated output (≈ 1/0.0146 pixels per
    // independent value) is good to a few percent.
    let (view, blur) = blur_setup(uvec2(256, 192));
    let size = view.size();
    let n = (size.x * size.y) as usize;
    let flat = vec![5.0f32; n];
    for a in interior(&view, &run_blur(&blur, &vec![0.4f32; n], &flat), 0) {
        assert!((a - 0.4).abs() < 1e-6, "a constant must stay constant: {a}");
    }
    let input = common::rng::noise(n, 1234);
    let out = run_blur(&blur, &input, &flat);
    let ratio = variance(&interior(&view, &out, 4)) / variance(&interior(&view, &input, 4));
    eprintln!("variance ratio after the blur: {ratio:.5} (i.i.d. prediction 0.01457)");
    assert!((ratio - 0.014567).abs() < 0.25 * 0.014567, "variance ratio {ratio}, expected ≈ 0.0146");
    // The mean is preserved (weights normalized).
    let (mi, mo) = (interior(&view, &input, 4), interior(&view, &out, 4));
    let mean = |v: &[f32]| v.iter().map(|&x| x as f64).sum::<f64>() / v.len() as f64;
    assert!((mean(&mi) - mean(&mo)).abs() < 0.01, "mean {} → {}", mean(&mi), mean(&mo));
}

/// Across a depth discontinuity (depth 5 | depth 50) the weights of the far side vanish
/// (Δ = 45·16·12/5 = 1728, w = 2^(−Δ²) = 0): each side is smoothed with its own noise only, so
/// the output on one side does not change when the other side's AO does, while both sides are
/// still smoothed.
#[test]
fn blur_preserves_depth_edges() {
    let (view, blur) = blur_setup(uvec2(48, 40));
    let size = view.size();
    let n = (size.x * size.y) as usize;
    let mid = size.x / 2;
    let left = |i: usize| (i as u32 % size.x) < mid;
    let depth: Vec<f32> = (0..n).map(|i| if left(i) { 5.0 } else { 50.0 }).collect();
    let noisy = common::rng::noise(n, 99);
    let ao = |other: f32| -> Vec<f32> {
        (0..n).map(|i| if left(i) { 0.3 + 0.2 * noisy[i] } else { other + 0.2 * noisy[i] }).collect()
    };
    let (dark, bright) = (run_blur(&blur, &ao(0.0), &depth), run_blur(&blur, &ao(0.8), &depth));
    let inner_rows = view.guard..size.y - view.guard;
    for y in inner_rows.clone() {
        for x in view.guard..mid {
            let i = (y * size.x + x) as usize;
            assert!((dark[i] - bright[i]).abs() < 1e-6, "pixel ({x},{y}) left of the edge sees the right side");
        }
    }
    // The left column next to the edge is still smoothed along y: its variance drops.
    let column = |v: &[f32], x: u32| inner_rows.clone().map(|y| v[(y * size.x + x) as usize]).collect::<Vec<_>>();
    let (before, after) = (variance(&column(&ao(0.8), mid - 1)), variance(&column(&bright, mid - 1)));
    assert!(after < 0.3 * before, "edge column not smoothed: variance {before} → {after}");
    // And the right side keeps its own level: next to the edge ≈ 0.8 + 0.1, not pulled to 0.4.
    let right_edge = column(&bright, mid);
    let mean = right_edge.iter().sum::<f32>() / right_edge.len() as f32;
    assert!((mean - 0.9).abs() < 0.03, "right side of the edge: mean {mean}");
}

/// One output pixel of one direction against the weighted sum of spec svao-raysd §12 computed by hand.
/// Depths along the direction at offsets −4..4: 9.96 9.95 9.98 9.99 |10.00| 10.03 10.02 10.06
/// 10.20, AO 0.1 0.2 … 0.9. Slopes sL = 0.01, sR = 0.03: s = 0.01 (smaller magnitude); the
/// positive side predicts z0 + 0.01·d, the negative side z0 − 0.01·d. Deviations: −3: −0.02,
/// +1: +0.02, +3: +0.03, +4: +0.16, others 0; Δ = |dev|·16·12/10 = 0.384, 0.384, 0.576, 3.072.
/// Weights 2^(−0.08d² − Δ²): −1: 0.946058, +1: 0.854140, ±2: 0.801070, −3: 0.548113,
/// +3: 0.482374, −4: 0.411796, +4: 0.000594. Result (0.5 + Σ w·a)/(1 + Σ w) = 0.466914
/// (f64 from the decimal inputs; the f32 inputs move it by 1e-7). Checked along x and along y.
#[test]
fn blur_pixel_is_the_cross_bilateral_weighted_sum() {
    let (view, blur) = blur_setup(uvec2(48, 40));
    let size = view.size();
    let n = (size.x * size.y) as usize;
    let z = [9.96f32, 9.95, 9.98, 9.99, 10.0, 10.03, 10.02, 10.06, 10.2];
    let expected = 0.466914f32;
    let c = uvec2(20, 18);
    for dir in [uvec2(1, 0), uvec2(0, 1)] {
        let mut depth = vec![10.0f32; n];
        let mut ao = vec![0.5f32; n];
        for (k, &zk) in z.iter().enumerate() {
            let p = c.as_ivec2() + dir.as_ivec2() * (k as i32 - 4);
            let i = view.index(p.as_uvec2());
            depth[i] = zk;
            ao[i] = (k + 1) as f32 / 10.0;
        }
        let params = aokit_shaders::blur::BlurParams { direction: dir, ..blur };
        let out = aokit_cpu::screen::run_blur_direction(&params, &ao, &depth);
        let got = out[view.index(c)];
        assert!((got - expected).abs() < 2e-6, "direction {dir}: {got} vs hand-computed {expected}");
    }
}

#[test]
fn auto_camera_frames_the_bounds_tightly() {
    use aokit::frame::auto_camera;
    use aokit_shaders::common::camera::Camera;
    let bounds = (vec3(-3.0, 0.0, 1.0), vec3(5.0, 2.0, 4.0));
    let (eye, target) = auto_camera(bounds, 50.0, 16.0 / 9.0);
    let cam = Camera::look_at(eye, target, Vec3::Y, 50f32.to_radians(), uvec2(160, 90), 0, 0.01, 1000.0);
    let mut extent = Vec2::ZERO;
    for i in 0..8 {
        let c = vec3(
            if i & 1 == 0 { bounds.0.x } else { bounds.1.x },
            if i & 2 == 0 { bounds.0.y } else { bounds.1.y },
            if i & 4 == 0 { bounds.0.z } else { bounds.1.z },
        );
        let uv = cam.view.view_to_uv(cam.world_to_view.transform_point3(c));
        assert!(uv.min_element() >= -1e-4 && uv.max_element() <= 1.0 + 1e-4, "corner {c} at {uv}");
        extent = extent.max((uv - 0.5).abs());
    }
    // Tight: some corner touches the left/right or top/bottom edge.
    assert!(extent.max_element() > 0.5 - 1e-3, "{extent}");
}
