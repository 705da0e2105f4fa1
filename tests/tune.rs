//! `aokit tune`: the parameter space read from the settings rows, Nelder–Mead finding a known
//! optimum, the cross-validation scoring the held-back scene, the reference cache, and the
//! command's one-line errors. Small images of the committed/procedural scenes (cornell, tower):
//! nothing is fetched, every test runs in seconds.

mod common;

use aokit::frame::{CameraChoice, FrameRequest};
use aokit::render::CpuRenderer;
use aokit::technique::{Describe, Technique};
use aokit::tune::{Device, Inputs, Metric, TuneSet, parameters, scene_views, spec};
use aokit_shaders::technique::Kind;
use std::path::PathBuf;
use std::process::Command;

fn request(width: u32, height: u32, guard: u32) -> FrameRequest {
    FrameRequest {
        width,
        height,
        guard,
        camera: CameraChoice::Auto { fov_deg: 60.0 },
        radius: None,
        exponent: 2.0,
        thickness: 0.0,
    }
}

fn technique(spec: &str) -> Technique {
    Technique::parse(spec).unwrap()
}

/// A tune set on the CPU without the disk cache.
fn set(scenes: &[&str], reference: &str, req: &FrameRequest, metric: Metric) -> TuneSet {
    let scenes = scenes.iter().map(|s| scene_views(s, req).unwrap()).collect();
    TuneSet::new(Device::Cpu, Inputs::Device, scenes, technique(reference), metric, None, &mut |_| {}).unwrap()
}

/// MSE over the inner image of `t` against `reference` on `scene`'s cameras (mean), rendered
/// here with the CPU renderer and summed in f64 by the test's own helpers, not the tuner's.
fn independent_mse(scene: &str, req: &FrameRequest, t: &Technique, reference: &Technique) -> f64 {
    let (s, frames) = scene_views(scene, req).unwrap();
    let cpu = CpuRenderer::new(&s);
    let none = &aokit_cpu::no_progress;
    let mut sum = 0.0;
    for (_, frame) in &frames {
        let (g, _) = cpu.gbuffer(frame, none);
        let a = cpu.run(frame, &g, t, none).ao_final;
        let b = cpu.run(frame, &g, reference, none).ao_final;
        sum += common::inner_mse(&frame.camera.view, &a, &b);
    }
    sum / frames.len() as f64
}

fn value(t: &Technique, key: &str) -> f64 {
    t.describe()[key.replace('-', "_")].as_f64().unwrap()
}

/// By default the tuner searches exactly the technique's `Number` rows that change its pass
/// graph, over their declared ranges (unbounded ones over [min, max(4·start, min+1)]); `--keys`
/// narrows, extends to counts, and refuses choices, unknown keys and settings without effect.
#[test]
fn parameters_are_the_settings_rows() {
    let req = request(64, 48, 8);
    let (_, frames) = scene_views("cornell", &req).unwrap();
    let desc = frames[0].1.desc();

    let gtao = technique("gtao");
    let params = parameters(&gtao, None, &desc).unwrap();
    let numbers: Vec<_> = gtao.rows().into_iter().filter(|r| matches!(r.kind, Kind::Number { .. })).collect();
    assert!(numbers.len() >= 2);
    assert_eq!(params.iter().map(|p| p.key).collect::<Vec<_>>(), numbers.iter().map(|r| r.key).collect::<Vec<_>>());
    for (p, row) in params.iter().zip(&numbers) {
        let Kind::Number { min, max } = row.kind else { unreachable!() };
        assert_eq!((p.lo, p.hi), (min as f64, max as f64), "{}", p.key);
        assert!(!p.integer);
        assert_eq!(p.start, row.default, "{}", p.key);
    }
    let rm = params.iter().find(|p| p.key == "radius-multiplier").unwrap();
    // The start's own text at the start; 4 significant digits elsewhere; clamped to the box.
    assert_eq!(rm.text((1.457 - 0.3) / 2.7), "1.457");
    assert_eq!(rm.text(0.5), "1.65");
    assert_eq!(rm.text(1.0 / 3.0), "1.2");
    assert_eq!(rm.text(-4.0), "0.3");
    assert_eq!(rm.text(7.0), "3");

    // raysd: `cutoff` (pixels, unbounded: [0, 4·6]); `peel-separation` acts only on dual depth.
    let raysd = parameters(&technique("raysd"), None, &desc).unwrap();
    assert_eq!(raysd.iter().map(|p| (p.key, p.lo, p.hi)).collect::<Vec<_>>(), [("cutoff", 0.0, 24.0)]);
    let dual = parameters(&technique("raysd:primary=dual"), None, &desc).unwrap();
    assert_eq!(dual.iter().map(|p| p.key).collect::<Vec<_>>(), ["cutoff", "peel-separation"]);

    // --keys: a narrower range, a count (rounded), and the refusals.
    let keys = parameters(&gtao, Some("falloff-range=0.2..0.8,steps"), &desc).unwrap();
    assert_eq!((keys[0].key, keys[0].lo, keys[0].hi), ("falloff-range", 0.2, 0.8));
    assert_eq!(keys[0].text(0.5), "0.5");
    assert!(keys[1].integer);
    let Some(Kind::Count { min, max }) = gtao.rows().iter().find(|r| r.key == "steps").map(|r| r.kind) else {
        panic!("gtao's steps is a count")
    };
    assert_eq!((keys[1].lo, keys[1].hi), (min as f64, max as f64));
    assert_eq!(keys[1].text(0.51), (min as f64 + 0.51 * (max - min) as f64).round().to_string());
    let err = |t: &str, k: Option<&str>| parameters(&technique(t), k, &desc).unwrap_err();
    assert!(err("gtao", Some("preset")).contains("is a choice"), "{}", err("gtao", Some("preset")));
    assert!(err("gtao", Some("nope")).contains("has no setting 'nope'"));
    assert!(err("gtao", Some("falloff-range=0.5..2")).contains("inside 0–1"));
    assert!(err("raysd", Some("peel-separation")).contains("does not change the output"));
    assert!(err("groundtruth", None).contains("no continuous"), "{}", err("groundtruth", None));
    assert!(parameters(&technique("groundtruth"), Some("spp=1..64"), &desc).unwrap()[0].integer);
}

/// Against an image rendered by the same technique with other settings, the optimum is those
/// settings with MSE 0: Nelder–Mead finds radius multiplier 2.2 and falloff range 0.3 from
/// XeGTAO's defaults (1.457, 0.615) within 40 renders, to 0.02, with an MSE below 1e-5 (the
/// start's is ~8e-3), and the reported MSE is the one the test recomputes itself.
#[test]
fn nelder_mead_finds_a_known_optimum() {
    let req = request(96, 64, 16);
    let target = "gtao:radius-multiplier=2.2:falloff-range=0.3";
    let set = set(&["cornell"], target, &req, Metric::Mse);
    let start = technique("gtao");
    let params =
        parameters(&start, Some("radius-multiplier,falloff-range"), &set.scenes[0].views[0].frame.desc()).unwrap();
    let mut heard = 0;
    let tuned = set.tune(&[0], &start, &params, 40, &mut |_, _| heard += 1).unwrap();
    eprintln!(
        "{} after {} renders ({}): MSE {:.3e} from {:.3e}",
        spec(&tuned.technique),
        tuned.evaluations.len(),
        tuned.stop,
        tuned.loss,
        tuned.baseline_loss
    );
    assert_eq!(heard, tuned.evaluations.len());
    assert!(tuned.evaluations.len() <= 40);
    assert_eq!(tuned.evaluations[0].values, ["1.457", "0.615"], "the first render is the start");
    assert_eq!(tuned.baseline_loss, tuned.evaluations[0].loss);
    // The result is the best setting rendered, not merely the last.
    let best = tuned.evaluations.iter().min_by(|a, b| a.loss.total_cmp(&b.loss)).unwrap();
    assert_eq!((&tuned.values, tuned.loss), (&best.values, best.loss));
    assert_eq!(
        tuned.values,
        [value(&tuned.technique, "radius-multiplier"), value(&tuned.technique, "falloff-range")]
            .map(|v| (v as f32).to_string())
    );
    let (rm, fr) = (value(&tuned.technique, "radius-multiplier"), value(&tuned.technique, "falloff-range"));
    assert!((rm - 2.2).abs() <= 0.02 && (fr - 0.3).abs() <= 0.02, "found {rm}, {fr}");
    assert!(tuned.baseline_loss > 1e-3, "the start is far from the target: {}", tuned.baseline_loss);
    assert!(tuned.loss < 1e-5, "MSE at the optimum {}", tuned.loss);
    let own = independent_mse("cornell", &req, &tuned.technique, &technique(target));
    assert!((own - tuned.loss).abs() <= 1e-9 * own.max(1e-12), "tuner {} vs recomputed {own}", tuned.loss);
    // The printed settings paste back into a technique with the same values.
    let pasted = technique(&spec(&tuned.technique));
    assert_eq!(pasted.describe(), tuned.technique.describe());
}

/// The same search on the Vulkan back-end (rasterized G-buffer, the graphs through
/// `AoContext`) under the validation layer: the optimum is found and no message is reported.
#[test]
fn nelder_mead_finds_a_known_optimum_on_vulkan() {
    let Some(vulkan) = common::vulkan() else { return };
    let req = request(96, 64, 16);
    let target = "gtao:radius-multiplier=2.2:falloff-range=0.3";
    let scenes = vec![scene_views("cornell", &req).unwrap()];
    let set =
        TuneSet::new(Device::Vulkan(vulkan), Inputs::Device, scenes, technique(target), Metric::Mse, None, &mut |_| {})
            .unwrap();
    let start = technique("gtao");
    let params =
        parameters(&start, Some("radius-multiplier,falloff-range"), &set.scenes[0].views[0].frame.desc()).unwrap();
    let tuned = set.tune(&[0], &start, &params, 40, &mut |_, _| {}).unwrap();
    let (rm, fr) = (value(&tuned.technique, "radius-multiplier"), value(&tuned.technique, "falloff-range"));
    assert!((rm - 2.2).abs() <= 0.02 && (fr - 0.3).abs() <= 0.02, "found {rm}, {fr}");
    assert!(tuned.loss < 1e-5 && tuned.baseline_loss > 1e-3, "{} from {}", tuned.loss, tuned.baseline_loss);
    let messages = set.device.validation_messages();
    assert!(messages.is_empty(), "validation layer reported:\n{}", messages.join("\n"));
}

/// Two scenes: each fold tunes on one and scores the other as held back; the held-back numbers
/// are the MSE of the start and of the fold's tuned settings on that scene, recomputed here.
/// The reference is gtao at radius multiplier 2.2 on both scenes, so tuning on either must
/// improve the other; the search on every scene holds nothing back.
#[test]
fn cross_validation_reports_the_held_back_scene() {
    let req = request(80, 56, 16);
    let target = "gtao:radius-multiplier=2.2";
    let set = set(&["cornell", "tower"], target, &req, Metric::Mse);
    let start = technique("gtao");
    let params = parameters(&start, Some("radius-multiplier"), &set.scenes[0].views[0].frame.desc()).unwrap();
    let study = set.study(&start, &params, 16, &mut |_, _, _| {}).unwrap();
    let names = ["cornell", "tower"];
    assert_eq!(study.folds.len(), 2);
    for (held, fold) in study.folds.iter().enumerate() {
        let tuned_on = names[1 - held];
        assert_eq!(fold.tuned_on, [tuned_on]);
        assert_eq!(fold.held_back.as_deref(), Some(names[held]));
        assert_eq!(fold.scores.len(), 2);
        for s in &fold.scores {
            assert_eq!(s.held_back, s.scene == names[held], "{}", s.scene);
            let own_start = independent_mse(&s.scene, &req, &start, &technique(target));
            let own_tuned = independent_mse(&s.scene, &req, &fold.result.technique, &technique(target));
            assert!((s.baseline.mse - own_start).abs() <= 1e-9 * own_start, "{}: start", s.scene);
            assert!((s.tuned.mse - own_tuned).abs() <= 1e-9 * own_tuned.max(1e-12), "{}: tuned", s.scene);
            assert!(
                s.tuned.mse < 0.2 * s.baseline.mse,
                "{} ({}) did not improve: {:?}",
                s.scene,
                if s.held_back { "held back" } else { "tuning" },
                s
            );
            assert!(s.baseline.ssim.is_some() && s.tuned.ssim.is_some());
            if !s.held_back {
                assert!((s.tuned.mse - fold.result.loss).abs() <= 1e-12, "the tuning scene's MSE is the search's loss");
            }
        }
    }
    assert_eq!(study.held_back_improved(Metric::Mse), (2, 2));
    assert_eq!(study.all.tuned_on, names);
    assert_eq!(study.all.held_back, None);
    assert!(study.all.scores.iter().all(|s| !s.held_back));
}

/// A built-in scene is scored on every camera preset (sponza: atrium and gallery), as their
/// mean: the tuner's MSE is the mean of the per-camera MSEs recomputed here.
#[test]
fn scores_are_the_mean_over_the_cameras() {
    let req = request(64, 40, 8);
    let target = "gtao:falloff-range=0.2";
    let set = set(&["sponza"], target, &req, Metric::Mse);
    let cameras: Vec<_> = set.scenes[0].views.iter().map(|v| v.camera.as_str()).collect();
    assert_eq!(cameras, ["atrium", "gallery"]);
    let t = technique("gtao");
    let got = set.scores(0, &t, false).unwrap();
    assert_eq!(got.ssim, None, "SSIM only when asked for");
    let own = independent_mse("sponza", &req, &t, &technique(target));
    assert!((got.mse - own).abs() <= 1e-9 * own, "{} vs {own}", got.mse);
    assert_eq!(set.loss(&[0], &t).unwrap(), got.mse);
}

/// SSIM as the metric: the loss is 1 − SSIM, minimised towards 0 at the known optimum.
#[test]
fn ssim_metric_minimises_one_minus_ssim() {
    let req = request(64, 48, 16);
    let set = set(&["cornell"], "gtao:falloff-range=0.2", &req, Metric::Ssim);
    let start = technique("gtao");
    let params = parameters(&start, Some("falloff-range"), &set.scenes[0].views[0].frame.desc()).unwrap();
    let tuned = set.tune(&[0], &start, &params, 20, &mut |_, _| {}).unwrap();
    let s = set.scores(0, &tuned.technique, true).unwrap();
    assert!((tuned.loss - (1.0 - s.ssim.unwrap())).abs() < 1e-12);
    assert!(tuned.loss < 0.01 * tuned.baseline_loss, "{} vs {}", tuned.loss, tuned.baseline_loss);
    assert!((value(&tuned.technique, "falloff-range") - 0.2).abs() <= 0.02);
}

/// The reference is rendered once and then read from the disk cache; a different exponent
/// (another image) misses it.
#[test]
fn reference_cache_is_keyed_by_the_frame() {
    let dir = std::env::temp_dir().join(format!("aokit-tune-cache-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let make = |req: &FrameRequest| {
        let scenes = vec![scene_views("cornell", req).unwrap()];
        TuneSet::new(
            Device::Cpu,
            Inputs::Device,
            scenes,
            technique("groundtruth:spp=8"),
            Metric::Mse,
            Some(dir.clone()),
            &mut |_| {},
        )
        .unwrap()
    };
    let req = request(48, 32, 8);
    let first = make(&req);
    assert!(first.scenes[0].views[0].reference_ms.is_some(), "rendered the first time");
    let second = make(&req);
    assert!(second.scenes[0].views[0].reference_ms.is_none(), "read from the cache the second time");
    // Same reference image: a technique scores the same against both.
    let t = technique("gtao");
    assert_eq!(first.scores(0, &t, false).unwrap().mse, second.scores(0, &t, false).unwrap().mse);
    let other = make(&FrameRequest { exponent: 1.0, ..req });
    assert!(other.scenes[0].views[0].reference_ms.is_some(), "another exponent is another reference");
    assert_eq!(
        std::fs::read_dir(&dir)
            .unwrap()
            .filter(|e| e.as_ref().unwrap().path().extension().is_some_and(|x| x == "f32"))
            .count(),
        2
    );
    let _ = std::fs::remove_dir_all(&dir);
}

fn aokit(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_aokit")).args(args).output().unwrap();
    (out.status.success(), String::from_utf8_lossy(&out.stdout).into(), String::from_utf8_lossy(&out.stderr).into())
}

/// The command: a single-scene run is labelled as such and writes its JSON; bad input fails
/// with one line.
#[test]
fn tune_command_reports_and_refuses_bad_input() {
    let json: PathBuf = std::env::temp_dir().join(format!("aokit-tune-{}.json", std::process::id()));
    let tiny = ["--width", "48", "--height", "32", "--guard", "8", "--no-cache"];
    let mut args =
        vec!["tune", "--technique", "gtao", "--keys", "radius-multiplier", "--budget", "6", "--scenes", "cornell"];
    args.extend(tiny);
    args.extend(["--reference", "groundtruth:spp=8", "--json", json.to_str().unwrap()]);
    let (ok, stdout, stderr) = aokit(&args);
    assert!(ok, "{stderr}");
    assert!(stdout.contains("single scene: no held-back scene"), "{stdout}");
    assert!(stdout.contains("tuned: gtao"), "{stdout}");
    let report: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let _ = std::fs::remove_file(&json);
    assert_eq!(report["folds"].as_array().unwrap().len(), 0);
    assert_eq!(report["all"]["tuned_on"], serde_json::json!(["cornell"]));
    assert!(report["all"]["evaluations"].as_u64().unwrap() <= 6);
    assert_eq!(report["recommended"], serde_json::Value::Null, "no recommendation without a held-back scene");

    let refused = |extra: &[&str], expect: &str| {
        let mut args = vec!["tune"];
        args.extend(extra);
        args.extend(tiny);
        if !extra.contains(&"--scenes") {
            args.extend(["--scenes", "cornell"]);
        }
        let (ok, _, stderr) = aokit(&args);
        assert!(!ok, "{extra:?} was accepted");
        let lines: Vec<_> = stderr
            .lines()
            .filter(|l| !l.trim().is_empty() && !l.starts_with("preparing") && !l.starts_with("  "))
            .collect();
        assert_eq!(lines.len(), 1, "{extra:?}: {stderr}");
        assert!(lines[0].starts_with("error: ") && lines[0].contains(expect), "{extra:?}: {stderr}");
    };
    refused(&["--technique", "nosuch"], "unknown technique 'nosuch'");
    refused(&["--technique", "gtao", "--budget", "0"], "--budget must be at least 1");
    refused(&["--technique", "gtao", "--budget", "3"], "too small");
    refused(&["--technique", "groundtruth"], "also the reference");
    refused(&["--technique", "groundtruth:spp=64"], "no continuous");
    refused(&["--technique", "gtao", "--keys", "preset"], "is a choice");
    refused(&["--technique", "gtao", "--scenes", "cornell,cornell"], "twice");
    refused(&["--technique", "gtao", "--rt-mode", "query"], "--rt-mode");
}
