//! Temporal behaviour: the frame index in every stochastic technique's noise,
//! the temporal accumulation appended to any technique's graph (CPU and Vulkan), and the
//! temporal-instability metric of `aokit path`.

mod common;

use aokit::frame::Frame;
use aokit::path::{
    FrameImages, Measure, Noise, PathInputs, PathKind, PathSpec, frame_instability, path_frames, run_path,
};
use aokit::render::{CpuRenderer, Renderer};
use aokit::technique::{TECHNIQUES, Technique};
use aokit_cpu::graph::CpuExecutor;
use aokit_cpu::{GBufferImage, no_progress};
use aokit_shaders::common::camera::Camera;
use aokit_shaders::glam::{UVec2, Vec3};
use aokit_shaders::graph::{Access, inputs};
use aokit_shaders::temporal::settings::{DEPTH_TOLERANCE, OUTPUT, TemporalSettings};
use aokit_shaders::temporal::{blend, history_matches, reproject};
use std::process::Command;

/// A camera at `eye` looking down −Z (up +Y) over an inner image of `w×h` with guard `g`.
fn camera_at(eye: Vec3, w: u32, h: u32, g: u32) -> Camera {
    Camera::look_at(eye, eye - Vec3::Z, Vec3::Y, 1.0, UVec2::new(w, h), g, 0.1, 100.0)
}

/// The instability against a known answer: a fronto-parallel plane at depth D, the camera
/// moved sideways by exactly k pixels' worth of world (k·2·D·tx/W), so that the point seen at
/// pixel p in frame 1 was at p + k in frame 0 — every reprojection lands on that texel, the
/// `(w − k)·h` inner pixels whose partner is inner too are valid. A screen-locked column
/// pattern `x mod 2` (noise that does not follow the surface) then flickers by exactly 1 per
/// valid pixel for odd k and 0 for even k; a world-locked one (`(x + k) mod 2` in frame 0) by
/// 0. A previous depth 10 % off fails the depth test at ε = 5 % and passes at ε = 20 %.
#[test]
fn instability_of_a_known_translation() {
    let (w, h, g, depth) = (40u32, 24u32, 4u32, 5.0f32);
    let before = camera_at(Vec3::ZERO, w, h, g);
    let size = before.view.size();
    let pixel = 2.0 * depth * before.view.tan_half_fov.x / before.view.res.x;
    let n = (size.x * size.y) as usize;
    let plane = vec![depth; n];
    let column = |f: &dyn Fn(u32) -> f32| -> Vec<f32> { (0..n).map(|i| f(i as u32 % size.x)).collect() };
    for k in [1u32, 2, 3] {
        let after = camera_at(Vec3::new(k as f32 * pixel, 0.0, 0.0), w, h, g);
        // The reprojection itself: p → p + k, at the plane's depth.
        let r = reproject(&after, &before, UVec2::new(g + 5, g + 7), depth);
        assert!(r.valid);
        assert_eq!(r.pixel, UVec2::new(g + 5 + k, g + 7));
        assert!((r.depth - depth).abs() < 1e-4 * depth, "{}", r.depth);

        let screen = column(&|x| (x % 2) as f32);
        let world_before = column(&|x| ((x + k) % 2) as f32);
        let cur = FrameImages { camera: &after, depth: &plane, ao: &screen };
        let valid = ((w - k) * h) as usize;
        let locked = frame_instability(FrameImages { camera: &before, depth: &plane, ao: &screen }, cur, 0.05);
        assert_eq!((locked.pixels, locked.inner), (valid, (w * h) as usize), "k = {k}");
        assert_eq!(locked.mean_abs, (k % 2) as f64, "k = {k}: screen-locked pattern");
        let world = frame_instability(FrameImages { camera: &before, depth: &plane, ao: &world_before }, cur, 0.05);
        assert_eq!((world.pixels, world.mean_abs), (valid, 0.0), "k = {k}: world-locked pattern");

        // Depth test: the previous frame saw something 10 % farther in its right half.
        let far_right: Vec<f32> =
            (0..n).map(|i| if i as u32 % size.x >= size.x / 2 { 1.1 * depth } else { depth }).collect();
        let prev = FrameImages { camera: &before, depth: &far_right, ao: &screen };
        let kept = (size.x / 2 - g - k) * h; // p + k left of the middle
        assert_eq!(frame_instability(prev, cur, 0.05).pixels, kept as usize, "k = {k}: rejected");
        assert_eq!(frame_instability(prev, cur, 0.2).pixels, valid, "k = {k}: within 20 %");
    }
    // The pieces: a point behind the previous camera or off its image is not valid; the blend.
    let behind = camera_at(Vec3::new(0.0, 0.0, -10.0), w, h, g);
    assert!(!reproject(&before, &behind, UVec2::new(g + 3, g + 3), depth).valid);
    let aside = camera_at(Vec3::new(1000.0, 0.0, 0.0), w, h, g);
    assert!(!reproject(&before, &aside, UVec2::new(g + 3, g + 3), depth).valid);
    assert!(!reproject(&before, &before, UVec2::new(g + 3, g + 3), 100.0).valid, "background");
    assert!(history_matches(5.0, 5.2, 0.05, 100.0) && !history_matches(5.0, 5.3, 0.05, 100.0));
    assert!(!history_matches(5.0, 100.0, 1.0, 100.0), "background in the history");
    assert_eq!(blend(0.25, 0.75, 0.5), 0.5);
}

/// The history is read bilinearly around the reprojected point, over the taps that saw the same
/// surface: a camera moved by ¼ pixel over a plane reads a horizontal ramp `x/64` at `(x + ¼)/64`
/// (weights ¾, ¼); with the right-hand taps' depth 10 % off only the left ones count (weight ¾,
/// value `x/64`); with every tap off, nothing (weight 0). A static camera reads its own texel
/// exactly (the fraction rounds to 1/256).
#[test]
fn the_history_is_filtered_bilinearly_over_the_taps_that_saw_the_surface() {
    use aokit_shaders::temporal::history_bilinear;
    let (w, h, g, depth) = (40u32, 24u32, 4u32, 5.0f32);
    let before = camera_at(Vec3::ZERO, w, h, g);
    let size = before.view.size();
    let n = (size.x * size.y) as usize;
    let pixel = 2.0 * depth * before.view.tan_half_fov.x / before.view.res.x;
    let after = camera_at(Vec3::new(0.25 * pixel, 0.0, 0.0), w, h, g);
    let ramp: Vec<f32> = (0..n).map(|i| (i as u32 % size.x) as f32 / 64.0).collect();
    let plane = vec![depth; n];
    let p = UVec2::new(g + 10, g + 6);
    let r = reproject(&after, &before, p, depth);
    assert!(r.valid && r.pixel == p, "{r:?}");
    let read = |depths: &[f32]| history_bilinear(&before.view, &r, &ramp, depths, 0.05);
    let both = read(&plane);
    assert_eq!(both.x, 1.0);
    assert!((both.y - (p.x as f32 + 0.25) / 64.0).abs() < 1e-5, "{}", both.y);
    let right_off: Vec<f32> = (0..n).map(|i| if i as u32 % size.x > p.x { 1.1 * depth } else { depth }).collect();
    assert_eq!(read(&right_off), aokit_shaders::glam::Vec2::new(0.75, p.x as f32 / 64.0));
    assert_eq!(read(&vec![1.1 * depth; n]).x, 0.0);
    let still = reproject(&before, &before, p, depth);
    assert_eq!(history_bilinear(&before.view, &still, &ramp, &plane, 0.05).y, ramp[before.view.index(p)]);
}

/// The cornell box, small, with its preset camera.
fn cornell() -> (aokit::scene::Scene, Frame) {
    common::builtin_frame("cornell", 64, 48, 8)
}

fn gbuffers(cpu: &CpuRenderer, frames: &[Frame]) -> Vec<GBufferImage> {
    frames.iter().map(|f| cpu.gbuffer(f, &no_progress).0).collect()
}

/// `n` frames that all keep `base`'s camera, each with the previous camera set (a static
/// camera), frame index t or 0.
fn static_frames(base: &Frame, n: u32, animated: bool, temporal: Option<TemporalSettings>) -> Vec<Frame> {
    (0..n)
        .map(|t| Frame {
            frame_index: if animated { t } else { 0 },
            previous_camera: (t > 0).then_some(base.camera),
            temporal,
            ..base.clone()
        })
        .collect()
}

/// A static camera: with a static noise every technique's frames are identical, so the
/// instability is exactly 0 (the known answer); with the frame index animating the noise, the
/// stochastic techniques flicker (> 1e-3 here) while the deterministic VAO stays at 0.
#[test]
fn static_camera_flickers_only_with_animated_noise() {
    let (scene, base) = cornell();
    let renderer = Renderer::Cpu(CpuRenderer::new(&scene));
    let Renderer::Cpu(cpu) = &renderer else { unreachable!() };
    let frames_static = static_frames(&base, 3, false, None);
    let frames_animated = static_frames(&base, 3, true, None);
    let g = gbuffers(cpu, &frames_static);
    for (name, stochastic) in [("gtao", true), ("groundtruth:spp=8", true), ("raymarch", true), ("vao", false)] {
        let t = Technique::parse(name).unwrap();
        let run = |frames| {
            let inputs = PathInputs { renderer: &renderer, scene: &scene, frames, gbuffers: &g };
            let measure = Measure { reference: None, tolerance: DEPTH_TOLERANCE, images: false, keep_ao: false };
            run_path(inputs, &t, measure, &no_progress, &|| ()).unwrap().0
        };
        let (still, moving) = (run(&frames_static), run(&frames_animated));
        assert_eq!(still.instability(), 0.0, "{name}: static noise, static camera");
        assert!(still.valid_fraction() > 0.5, "{name}: {}", still.valid_fraction());
        eprintln!("{name}: animated noise instability {:.5}", moving.instability());
        if stochastic {
            assert!(moving.instability() > 1e-3, "{name}: {}", moving.instability());
        } else {
            assert_eq!(moving.instability(), 0.0, "{name}");
        }
    }
}

/// The frame index reaches every stochastic technique's noise: frame 1 differs from frame 0;
/// frame 0 is the single frame's output bit for bit (`FrameDesc::new`), and frame 64 repeats
/// it (the R2 offsets and rotations have period 64, the SD jitter index 16). The VAO family's
/// 4×4 rotation (spec svao-raysd §4.1.1) and Ray-SVAO's rays are deterministic: unchanged.
#[test]
fn the_frame_index_reaches_every_stochastic_technique() {
    let (scene, base) = common::builtin_frame("tower", 64, 48, 8);
    let cpu = CpuRenderer::new(&scene);
    let (gbuffer, _) = cpu.gbuffer(&base, &no_progress);
    let deterministic = ["vao", "hbao", "raysvao"];
    for t in TECHNIQUES {
        let mut technique = Technique::named(t.name()).unwrap();
        if t.name() == "groundtruth" {
            technique.set("spp", "16").unwrap();
        }
        // The stenciled family refines samples beyond 6 px only, few at this size: all of them.
        if t.keys().contains(&"cutoff") {
            technique.set("cutoff", "0").unwrap();
        }
        let at = |index| cpu.run(&Frame { frame_index: index, ..base.clone() }, &gbuffer, &technique, &no_progress);
        let single = cpu.run(&base, &gbuffer, &technique, &no_progress).ao_final;
        let (zero, one, period) = (at(0).ao_final, at(1).ao_final, at(64).ao_final);
        assert!(zero == single && period == single, "{}: frame 0 and 64 are the single frame", t.name());
        let differ = zero.iter().zip(&one).filter(|(a, b)| a != b).count();
        eprintln!("{}: {differ} pixels differ between frames 0 and 1", t.name());
        if deterministic.contains(&t.name()) {
            assert_eq!(differ, 0, "{}", t.name());
        } else {
            assert!(differ > 0, "{}: no pixel changes with the frame index", t.name());
        }
    }
}

/// Every technique's graph takes the accumulation: validated, the two passes last, binding
/// exactly the slots their modules declare with the modules' access, the output replaced; and
/// without `temporal` the graph is the technique's own.
#[test]
fn the_accumulation_appends_to_every_technique() {
    let (_, base) = cornell();
    let manifest = aokit_contract::manifest::Manifest::committed();
    let on = Frame { temporal: Some(TemporalSettings::default()), previous_camera: Some(base.camera), ..base.clone() };
    for t in TECHNIQUES {
        let technique = Technique::named(t.name()).unwrap();
        let plain = technique.graph(&base.desc()).unwrap();
        let graph = technique.graph(&on.desc()).unwrap();
        graph.validate().unwrap();
        assert_eq!(graph.output, OUTPUT, "{}", t.name());
        assert_eq!(graph.passes[..graph.passes.len() - 2], plain.passes[..], "{}", t.name());
        let [blend, store] = &graph.passes[graph.passes.len() - 2..] else { unreachable!() };
        assert_eq!(blend.resource(2), Some(plain.output), "{}: the blend reads the technique's output", t.name());
        assert_eq!(blend.resource(1), Some(inputs::LINEAR_DEPTH));
        for pass in [blend, store] {
            let module = manifest.modules.iter().find(|m| m.entry_point == pass.entry()).unwrap();
            let mut declared: Vec<_> = module.bindings.iter().map(|b| (b.binding, b.writable)).collect();
            declared.sort();
            let bound: Vec<_> = pass.bindings.iter().map(|b| (b.slot, b.access != Access::Read)).collect();
            assert_eq!(bound, declared, "{}", pass.entry());
            assert!(aokit_cpu::graph::cpu_driver(pass.kernel).is_some(), "{}: no CPU kernel", pass.entry());
        }
    }
    // Out-of-range settings are refused with the setting named.
    let bad = Frame { temporal: Some(TemporalSettings { alpha: 0.0, ..Default::default() }), ..base.clone() };
    let err = Technique::named("vao").unwrap().graph(&bad.desc()).unwrap_err();
    assert!(err.contains("temporal alpha 0"), "{err}");
}

/// The accumulation on the CPU: the first frame (no history) is the technique's output bit for
/// bit, α = 1 keeps the current frame everywhere, a static camera with static noise keeps the
/// image (h + α·(a − h) with h = a), and with animated noise every accumulated pixel is the
/// exponential blend of the frames: after frames a₀, a₁ it is a₀ + α·(a₁ − a₀).
#[test]
fn the_accumulation_blends_the_reprojected_history() {
    let (scene, base) = cornell();
    let cpu = CpuRenderer::new(&scene);
    let technique = Technique::named("gtao").unwrap();
    let (gbuffer, _) = cpu.gbuffer(&base, &no_progress);
    let settings = TemporalSettings::default();
    let plain = |frames: &[Frame]| -> Vec<Vec<f32>> {
        frames.iter().map(|f| cpu.run(f, &gbuffer, &technique, &no_progress).ao_final).collect()
    };
    let accumulated = |frames: &[Frame]| -> Vec<Vec<f32>> {
        let mut executor = CpuExecutor::new();
        frames.iter().map(|f| cpu.run_with(&mut executor, f, &gbuffer, &technique, &no_progress).ao_final).collect()
    };
    let animated = static_frames(&base, 2, true, Some(settings));
    let (a, acc) = (plain(&static_frames(&base, 2, true, None)), accumulated(&animated));
    assert_eq!(acc[0], a[0], "no history on the first frame");
    let view = base.camera.view;
    let mut blended = 0;
    for p in (0..view.size().y).flat_map(|y| (0..view.size().x).map(move |x| UVec2::new(x, y))) {
        let i = view.index(p);
        let expected =
            if view.is_inner(p) && gbuffer.depth[i] < view.far { blend(a[0][i], a[1][i], 0.1) } else { a[1][i] };
        assert_eq!(acc[1][i], expected, "pixel {p}");
        blended += (view.is_inner(p) && a[0][i] != a[1][i]) as usize;
    }
    assert!(blended > 100, "the noise must change between the frames ({blended} pixels)");
    let still = accumulated(&static_frames(&base, 3, false, Some(settings)));
    assert!(still.iter().all(|f| *f == a[0]), "static camera and noise: the image stays");
    let keep = accumulated(&static_frames(&base, 2, true, Some(TemporalSettings { alpha: 1.0, ..settings })));
    assert_eq!(keep[1], a[1], "α = 1 keeps the current frame");
}

/// The accumulation lowers a noisy technique's instability: the ground truth at 2 spp along an
/// orbit, with animated noise, flickers at least 3× less with the accumulation (α = 0.1), and its
/// MSE against a 256-spp ground truth drops too (the history averages the noise away).
#[test]
fn the_accumulation_reduces_the_instability_of_a_noisy_technique() {
    let (scene, base) = cornell();
    let renderer = Renderer::Cpu(CpuRenderer::new(&scene));
    let spec = PathSpec { kind: PathKind::Orbit, frames: 10, step: 0.25 };
    let off = path_frames(&base, &spec, Noise::Animated, None);
    let on = path_frames(&base, &spec, Noise::Animated, Some(TemporalSettings::default()));
    let Renderer::Cpu(cpu) = &renderer else { unreachable!() };
    let g = gbuffers(cpu, &off);
    let run = |frames, technique: &str, reference: Option<&[Vec<f32>]>| {
        let t = Technique::parse(technique).unwrap();
        let inputs = PathInputs { renderer: &renderer, scene: &scene, frames, gbuffers: &g };
        let measure = Measure { reference, tolerance: DEPTH_TOLERANCE, images: false, keep_ao: true };
        run_path(inputs, &t, measure, &no_progress, &|| ()).unwrap()
    };
    let (_, truth) = run(&off, "groundtruth:spp=256", None);
    let (noisy, _) = run(&off, "groundtruth:spp=2", Some(&truth));
    let (smooth, _) = run(&on, "groundtruth:spp=2", Some(&truth));
    eprintln!(
        "2 spp: instability {:.4} → {:.4} with accumulation, MSE {:.4} → {:.4}, valid {:.3}",
        noisy.instability(),
        smooth.instability(),
        noisy.mse(),
        smooth.mse(),
        smooth.valid_fraction()
    );
    assert!(smooth.valid_fraction() > 0.5, "{}", smooth.valid_fraction());
    assert!(smooth.instability() * 3.0 < noisy.instability());
    assert!(smooth.mse() < noisy.mse());
}

/// The accumulation on Vulkan agrees with the CPU: XeGTAO along a 3-frame orbit through one
/// context (the history persists across `run`s) on the CPU's G-buffers; the accumulated last
/// frame agrees within 1/255 on ≥ 99.9 % of the inner pixels, and on both back-ends it differs
/// from the frame without accumulation (the history was used). Validation clean.
#[test]
fn the_accumulation_agrees_between_cpu_and_vulkan() {
    let Some(vk) = common::vulkan() else { return };
    let (scene, base) = common::builtin_frame("sponza", 96, 64, 16);
    let cpu = CpuRenderer::new(&scene);
    let spec = PathSpec { kind: PathKind::Orbit, frames: 3, step: 0.5 };
    let on = path_frames(&base, &spec, Noise::Animated, Some(TemporalSettings::default()));
    let g = gbuffers(&cpu, &on);
    let technique = Technique::named("gtao").unwrap();
    let mut executor = CpuExecutor::new();
    let (mut on_cpu, mut on_gpu) = (Vec::new(), Vec::new());
    for (f, gb) in on.iter().zip(&g) {
        on_cpu = cpu.run_with(&mut executor, f, gb, &technique, &no_progress).ao_final;
        on_gpu = vk.run(&scene, f, gb, &technique).unwrap().ao_final;
    }
    let last = Frame { temporal: None, ..on[2].clone() };
    let plain = cpu.run(&last, &g[2], &technique, &no_progress).ao_final;
    let view = base.camera.view;
    let within = common::inner_within(&view, &on_cpu, &on_gpu, common::agreement::STEP);
    let max = common::inner_max_abs(&view, &on_cpu, &on_gpu);
    let used = 1.0 - common::inner_within(&view, &on_cpu, &plain, common::agreement::STEP);
    let used_gpu = 1.0 - common::inner_within(&view, &on_gpu, &plain, common::agreement::STEP);
    eprintln!(
        "temporal gtao: {:.3} % within 1/255, max {max:.4}; history changed {:.1} % (cpu), {:.1} % (vulkan)",
        100.0 * within,
        100.0 * used,
        100.0 * used_gpu
    );
    assert!(within >= common::agreement::MIN_WITHIN, "{within}");
    assert!(used > 0.2 && used_gpu > 0.2, "{used} {used_gpu}");
    common::assert_validation_clean(&vk);
}

/// `aokit path`: bad input gets one line and exit 1; a small run prints the table, writes the
/// JSON (the reference's row and every technique with and without accumulation) and an APNG.
#[test]
fn path_command_reports_and_refuses_bad_input() {
    let aokit = |args: &[&str]| Command::new(env!("CARGO_BIN_EXE_aokit")).args(args).output().unwrap();
    let base = ["path", "--scene", "cornell", "--width", "32", "--height", "24", "--guard", "4"];
    for (extra, message) in [
        (&["--frames", "0"][..], "--frames 0: a path needs at least 2 frames"),
        (&["--path", "spiral"], "--path spiral: expected orbit or dolly"),
        (&["--temporal", "maybe"], "--temporal maybe: expected off, on or both"),
        (&["--temporal-alpha", "1.5"], "--temporal-alpha 1.5: expected a number in (0, 1]"),
        (&["--noise", "pink"], "--noise pink: expected animated or static"),
        (&["--step", "-1"], "--step -1: expected a finite number > 0"),
        (&["--path", "dolly", "--step", "0.5", "--frames", "3"], "--step 0.5 over 3 frames dollies 100 %"),
        (&["--out", "anim.gif"], "--out anim.gif: aokit writes an animated PNG (APNG): give a .png path"),
        (&["--technique", "nope"], "nope"),
    ] {
        let out = aokit(&[&base[..], extra].concat());
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{extra:?}: {stderr}");
        assert!(stderr.starts_with("error: ") && stderr.lines().count() == 1, "{extra:?}: {stderr}");
        assert!(stderr.contains(message), "{extra:?}: {stderr}");
    }
    let dir = std::env::temp_dir().join(format!("aokit-path-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (json, anim) = (dir.join("path.json"), dir.join("anim.png"));
    let args = ["--frames", "3", "--technique", "vao,gtao", "--reference", "groundtruth:spp=4", "--json"];
    let out = aokit(&[&base[..], &args, &[json.to_str().unwrap(), "--out", anim.to_str().unwrap()]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let report: serde_json::Value = serde_json::from_slice(&std::fs::read(&json).unwrap()).unwrap();
    let labels: Vec<_> = report["results"].as_array().unwrap().iter().map(|r| r["label"].as_str().unwrap()).collect();
    assert_eq!(labels, ["vao", "vao +temporal", "gtao", "gtao +temporal"]);
    assert_eq!(report["reference"]["instability_per_frame"].as_array().unwrap().len(), 2);
    assert!(report["results"][2]["mse"].as_f64().unwrap() > 0.0);
    for name in ["anim-vao.png", "anim-vao-temporal.png", "anim-gtao.png", "anim-gtao-temporal.png"] {
        let bytes = std::fs::read(dir.join(name)).unwrap();
        let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        let reader = decoder.read_info().unwrap();
        let info = reader.info();
        assert_eq!((info.width, info.height), (32, 24), "{name}");
        assert_eq!(info.animation_control.map(|a| a.num_frames), Some(3), "{name}: an APNG of 3 frames");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The frame's rotation of the ray-traced techniques' random numbers: none at frame 0 (so a
/// single frame keeps the original noise bit for bit), 64 distinct rotations with period 64;
/// it reaches the reservoir's slot choice (Ray-SD), the coverage masks (raster SD map) with
/// their expectation α·N = 1.5 kept samples unchanged, and the SD jitter visits all 16 entries
/// of its table over 16 frames.
#[test]
fn frame_rotations_leave_frame_zero_alone_and_move_later_frames() {
    use aokit_shaders::common::noise::{frame_rotation, rotate};
    use aokit_shaders::common::tables::{JitterTable, sd_jitter};
    use aokit_shaders::rastersd::coverage_mask;
    use aokit_shaders::raysd::{NO_SLOT, SdPayload, reservoir_candidate};
    assert_eq!(frame_rotation(0), aokit_shaders::glam::Vec2::ZERO);
    let u = common::rng::noise(10_000, 7);
    assert!(u.iter().all(|&u| rotate(u, 0.0).to_bits() == u.to_bits()));
    let rotations: Vec<_> = (0..64).map(frame_rotation).collect();
    assert!(rotations.iter().all(|r| (0.0..1.0).contains(&r.x) && (0.0..1.0).contains(&r.y)));
    for (i, r) in rotations.iter().enumerate() {
        assert!(rotations[..i].iter().all(|s| s != r), "frame {i} repeats an earlier rotation");
    }
    assert_eq!(frame_rotation(64), frame_rotation(0));
    assert!(u.iter().all(|&u| (0.0..1.0).contains(&rotate(u, rotations[5].x))));

    // Ray-SD: the payload carries the frame's rotation, and the slot choice follows it.
    let mut params: aokit_shaders::svao::SvaoParams = bytemuck::Zeroable::zeroed();
    (params.sd_layers, params.max_count) = (2, 100);
    let payload = |frame| {
        let mut p = SdPayload::new(&aokit_shaders::svao::SvaoParams { noise_frame: frame, ..params }, 0.0, 1.0, 1.0);
        p.count = 6; // past N: the slot is floor(u·count)
        p
    };
    assert_eq!((payload(0).rotation, payload(3).rotation), (0.0, frame_rotation(3).x));
    // The 7th hit (count 6 → 7) takes slot ⌊u·7⌋ and enters the map iff that is < N = 2: each of
    // the `HITS` candidates is kept with p = 2/7, so the kept count is Binomial(HITS, p) for a
    // uniform hash: mean HITS·p, σ = √(HITS·p·(1 − p)). The interval is mean ± 5σ (two-sided
    // false-failure probability 5.7e-7 for a correct reservoir). The defects it must catch are
    // an off-by-one in the count or in N: p = 2/6 (count not incremented) or 2/8 (incremented
    // twice), 1/7 or 3/7. With HITS = 20 000: mean 5714.3, σ = 63.9, interval [5395, 6033];
    // 2/8 gives 5000 ± 61 (6.4 of its σ below the interval), 2/6 gives 6667 ± 67 (9.5 σ above).
    // (The old 1000 hits, σ = 14.3, could not separate 2/7 from 2/6 at any useful confidence.)
    const HITS: usize = 20_000;
    let h = common::rng::noise(2 * HITS, 11);
    let bary = |i: usize| aokit_shaders::glam::Vec2::new(h[2 * i] * 0.5, h[2 * i + 1] * 0.5);
    let slots =
        |frame| -> Vec<u32> { (0..HITS).map(|i| reservoir_candidate(&mut payload(frame), 0.5, bary(i)).0).collect() };
    let (s0, s1) = (slots(0), slots(1));
    let changed = s0.iter().zip(&s1).filter(|(a, b)| a != b).count();
    assert!(changed > HITS / 5, "the rotation changes {changed} of {HITS} slot choices");
    let p = 2.0 / 7.0;
    let (mean, sigma) = (HITS as f64 * p, (HITS as f64 * p * (1.0 - p)).sqrt());
    let (lo, hi) = ((mean - 5.0 * sigma).ceil() as usize, (mean + 5.0 * sigma).floor() as usize);
    for s in [&s0, &s1] {
        let kept = s.iter().filter(|&&s| s != NO_SLOT).count();
        let z = (kept as f64 - mean) / sigma;
        assert!(
            (lo..=hi).contains(&kept),
            "N/count = 2/7 of {HITS} hits enter the map: {kept} kept, expected {mean:.1} ± 5σ = [{lo}, {hi}] (z = {z:.2})"
        );
    }

    // Raster SD: masks change with the frame, the mean kept count stays α·N = 1.5.
    let positions: Vec<Vec3> =
        (0..3000).map(|i| Vec3::new(u[3 * i] * 9.0, u[3 * i + 1] * 7.0, u[3 * i + 2] * 5.0)).collect();
    let masks = |frame| -> Vec<u32> { positions.iter().map(|&p| coverage_mask(p, 4, frame)).collect() };
    let (m0, m1) = (masks(0), masks(1));
    assert!(m0.iter().zip(&m1).filter(|(a, b)| a != b).count() > 1000);
    for m in [&m0, &m1] {
        let mean = m.iter().map(|m| m.count_ones() as f64).sum::<f64>() / m.len() as f64;
        assert!((mean - 1.5).abs() < 0.05, "mean kept samples {mean}");
    }

    // SD jitter: frame 0 is the spec's entry, 16 frames visit every entry once.
    for table in [JitterTable::Scrambled, JitterTable::Paper] {
        let q = UVec2::new(5, 6);
        let seen: Vec<_> = (0..16).map(|f| sd_jitter(q, table as u32, f)).collect();
        assert_eq!(sd_jitter(q, table as u32, 16), seen[0]);
        let all: Vec<_> = (0..16).map(|i| sd_jitter(UVec2::new(i % 4, i / 4), table as u32, 0)).collect();
        assert!(all.iter().all(|j| seen.contains(j)), "{table:?}");
    }
}
