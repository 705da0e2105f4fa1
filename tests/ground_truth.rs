//! Ground-truth AO: sampling math against closed forms, an analytic scene, and convergence.

mod common;

use aokit::frame::{CameraChoice, Frame, FrameRequest};
use aokit::output::crop_inner;
use aokit::render::CpuRenderer;
use aokit::scene::Scene;
use aokit::scene::procedural::push_quad;
use aokit_cpu::no_progress;
use aokit_shaders::glam::{Vec3, uvec2, vec3};
use aokit_shaders::groundtruth::{GroundTruthParams, basis, hemisphere_direction, sample_2d};
use proptest::prelude::*;

proptest! {
    #[test]
    fn basis_is_orthonormal(x in -1.0f32..1.0, y in -1.0f32..1.0, z in -1.0f32..1.0) {
        let n = vec3(x, y, z);
        prop_assume!(n.length() > 1e-2);
        let n = n.normalize();
        let (t, b) = basis(n);
        for (u, v) in [(t, b), (t, n), (b, n)] {
            prop_assert!(u.dot(v).abs() < 1e-5);
        }
        prop_assert!((t.length() - 1.0).abs() < 1e-5 && (b.length() - 1.0).abs() < 1e-5);
        prop_assert!((t.cross(b) - n).length() < 1e-4, "right-handed");
    }
}

#[test]
fn r2_sequence_matches_the_closed_form() {
    // g is the real root of x³ = x + 1; R2 is frac(0.5 + k·(1/g, 1/g²)) (Roberts 2018).
    let mut g = 1.0f64;
    for _ in 0..60 {
        g = (1.0 + g).cbrt();
    }
    let pixel = uvec2(3, 5);
    let shift = sample_2d(0, pixel) - 0.5; // k = 0 is 0.5 + shift
    for k in [1u32, 2, 3, 10, 100, 511] {
        let expected = [(0.5 + k as f64 / g).fract(), (0.5 + k as f64 / (g * g)).fract()];
        let got = sample_2d(k, pixel) - shift;
        for axis in 0..2 {
            let d = (got[axis] as f64 - expected[axis]).rem_euclid(1.0);
            assert!(d.min(1.0 - d) < 1e-4, "k={k} axis {axis}: {got} vs {expected:?}");
        }
    }
}

#[test]
fn cosine_weighted_directions_have_the_right_moments() {
    // For pdf cos θ/π: E[cos θ] = 2/3, E[cos² θ] = 1/2, and E[sin θ cos φ] = 0.
    let n = vec3(0.3, -0.5, 0.8).normalize();
    let (t, _) = basis(n);
    let count = 4096;
    let (mut c1, mut c2, mut lateral) = (0.0, 0.0, 0.0);
    for k in 0..count {
        let d = hemisphere_direction(n, sample_2d(k, uvec2(1, 2)), false);
        assert!((d.length() - 1.0).abs() < 1e-5 && d.dot(n) >= 0.0);
        c1 += d.dot(n) as f64;
        c2 += (d.dot(n) as f64).powi(2);
        lateral += d.dot(t) as f64;
    }
    let n = count as f64;
    assert!((c1 / n - 2.0 / 3.0).abs() < 2e-3, "{}", c1 / n);
    assert!((c2 / n - 0.5).abs() < 2e-3, "{}", c2 / n);
    assert!((lateral / n).abs() < 5e-3);
}

/// Camera looking down at a floor (y = 0) under a parallel ceiling at y = `gap`, both 2 km wide.
fn slab(gap: f32) -> (Scene, Frame) {
    let mut s = Scene::default();
    let l = 1000.0;
    push_quad(&mut s, vec3(-l, 0.0, l), vec3(l, 0.0, l), vec3(l, 0.0, -l), vec3(-l, 0.0, -l));
    push_quad(&mut s, vec3(-l, gap, -l), vec3(l, gap, -l), vec3(l, gap, l), vec3(-l, gap, l));
    let scene = s.validated(std::path::Path::new("slab")).unwrap();
    let req = FrameRequest {
        width: 24,
        height: 16,
        guard: 0,
        camera: CameraChoice::Explicit {
            eye: vec3(0.0, 0.8 * gap, 0.0),
            target: vec3(0.3, 0.0, 0.1),
            up: Vec3::Z,
            fov_deg: 40.0,
        },
        radius: Some(1.0),
        exponent: 1.0,
        thickness: 0.0,
    };
    let frame = Frame::resolve(&scene, None, &req).unwrap();
    (scene, frame)
}

#[test]
fn floor_under_a_ceiling_matches_the_closed_form() {
    // A ray leaving the floor at angle θ hits the ceiling at distance gap/cos θ, so it is
    // occluded iff cos θ > gap/R. Under the cosine-weighted measure that has probability
    // 1 − (gap/R)², leaving AO = (gap/R)² (for gap < R).
    for (gap, uniform) in [(0.5f32, 0), (0.8, 0), (0.5, 1)] {
        let (scene, frame) = slab(gap);
        let cpu = CpuRenderer::new(&scene);
        let (g, _) = cpu.gbuffer(&frame, &no_progress);
        let params = GroundTruthParams { radius: 1.0, exponent: 1.0, samples: 512, uniform };
        let ao = common::cpu_ground_truth(&cpu, &frame, &g, &params);
        let inner = crop_inner(&frame.camera.view, &ao);
        let mean = inner.iter().map(|&a| a as f64).sum::<f64>() / inner.len() as f64;
        let expected = (gap as f64).powi(2);
        assert!((mean - expected).abs() < 1e-3, "gap {gap}, uniform {uniform}: {mean} vs {expected}");
    }
}

#[test]
fn cornell_box_converges_by_512_samples() {
    let b = aokit::scene::builtin::find("cornell").unwrap();
    let scene = b.load().unwrap();
    let req = FrameRequest {
        width: 48,
        height: 48,
        guard: 0,
        camera: CameraChoice::Preset { name: None, fov_deg: None },
        radius: None,
        exponent: 1.0,
        thickness: 0.0,
    };
    let frame = Frame::resolve(&scene, Some(b), &req).unwrap();
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &no_progress);
    let run = |samples| {
        let params = GroundTruthParams { radius: frame.radius, exponent: 1.0, samples, uniform: 0 };
        common::cpu_ground_truth(&cpu, &frame, &g, &params)
    };
    let (a, b) = (run(512), run(4096));
    let view = frame.camera.view;
    let mse = common::inner_mse(&view, &a, &b);
    let (_, b) = common::inner_pair(&view, &a, &b);
    let n = b.len();
    let occluded = b.iter().filter(|&&v| v < 0.95).count();
    eprintln!("Cornell 48×48: MSE(512, 4096 spp) = {mse:.2e}; {occluded} of {n} pixels below 0.95");
    assert!(occluded > n / 20, "the view must contain occlusion");
    assert!(mse < 2e-4, "{mse}");
}
