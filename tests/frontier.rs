//! `aokit frontier`: the Pareto rule on hand cases, the candidate list read from the registry,
//! the scores recomputed independently, the plot's points, the Vulkan back-end scored on
//! cpu-sim's inputs, and the command's files and one-line errors. Small images of the committed
//! Cornell box: nothing is fetched.

mod common;

use aokit::frame::{CameraChoice, FrameRequest};
use aokit::frontier::{Candidate, candidates, measure, pareto_optimal, svg};
use aokit::metrics::{ImageRef, flip, ssim};
use aokit::render::CpuRenderer;
use aokit::technique::Technique;
use aokit::tune::{Device, Inputs, Metric, TuneSet, scene_views};
use std::process::Command;

fn request(width: u32, height: u32) -> FrameRequest {
    FrameRequest {
        width,
        height,
        guard: 16,
        camera: CameraChoice::Auto { fov_deg: 60.0 },
        radius: None,
        exponent: 1.0,
        thickness: 0.0,
    }
}

fn candidate(spec: &str) -> Candidate {
    let technique = Technique::parse(spec).unwrap();
    Candidate { label: technique.label(), technique }
}

/// A point is on the frontier unless another has both a lower MSE and a lower time: equal
/// values do not dominate (the "both lower").
#[test]
fn pareto_optimal_keeps_the_points_nothing_beats_on_both_axes() {
    // (mse, ms): a cheap and bad, b dear and good, c beaten by a on both, d ties a's MSE but is
    // slower, e ties b's time with a worse MSE: ties do not dominate, so only c is off.
    let points = [(4.0, 1.0), (1.0, 9.0), (5.0, 2.0), (4.0, 3.0), (2.0, 9.0)];
    assert_eq!(pareto_optimal(&points), [true, true, false, true, true]);
    // f beats d and e on both axes, not a (slower) nor b (worse MSE).
    let with_f = [(4.0, 1.0), (1.0, 9.0), (5.0, 2.0), (4.0, 3.0), (2.0, 9.0), (1.5, 2.5)];
    assert_eq!(pareto_optimal(&with_f), [true, true, false, false, false, true]);
    assert_eq!(pareto_optimal(&[]), Vec::<bool>::new());
    // A point without a finite MSE or time is never on the frontier.
    assert_eq!(pareto_optimal(&[(f64::NAN, 1.0), (1.0, f64::INFINITY), (2.0, 2.0)]), [false, false, true]);
}

/// The default list: every registered technique but the reference, at each quality preset
/// (`custom` excluded) or at its defaults, then the tuned settings; labels are unique.
#[test]
fn candidates_cover_every_technique_and_preset() {
    let list = candidates("groundtruth", true).unwrap();
    let labels: Vec<&str> = list.iter().map(|c| c.label.as_str()).collect();
    for name in aokit_shaders::techniques::TECHNIQUES.iter().map(|t| t.name()).filter(|n| *n != "groundtruth") {
        assert!(list.iter().any(|c| c.technique.name() == name), "{name} missing");
    }
    assert!(!list.iter().any(|c| c.technique.name() == "groundtruth"), "the reference is not a candidate");
    for t in ["gtao", "vbao"] {
        for p in ["low", "medium", "high", "ultra"] {
            let c = list.iter().find(|c| c.label == format!("{t}-{p}")).unwrap_or_else(|| panic!("{t}-{p} missing"));
            assert_eq!(c.technique.values().iter().find(|(k, _)| *k == "preset").unwrap().1, p);
        }
        assert!(labels.contains(&format!("{t}-tuned").as_str()));
    }
    assert!(!labels.iter().any(|l| l.contains("custom")));
    // Every preset (or default) also at half resolution; the tuned settings at full only.
    let full: Vec<_> = list.iter().filter(|c| !c.label.ends_with("-half") && !c.label.ends_with("-tuned")).collect();
    for c in &full {
        let half = list.iter().find(|h| h.label == format!("{}-half", c.label)).expect("a half-resolution twin");
        assert_eq!(half.technique.resolution(), aokit_shaders::technique::Resolution::half());
        assert_eq!(half.technique.values(), c.technique.values(), "{}: the same settings", c.label);
    }
    assert_eq!(list.iter().filter(|c| c.label.ends_with("-half")).count(), full.len());
    let mut sorted = labels.clone();
    sorted.sort();
    sorted.dedup();
    assert_eq!(sorted.len(), labels.len(), "labels are unique");
    assert_eq!(candidates("groundtruth", false).unwrap().len(), list.len() - aokit::frontier::TUNED.len());
}

/// On a 96×64 Cornell box: each point's MSE, SSIM and FLIP are the metrics of the technique's
/// final AO against the 64-spp ground truth, both rendered here by cpu-sim (own crop, own f64
/// MSE sum); the Pareto flags follow the rule; the reference itself as a candidate scores 0.
#[test]
fn measure_scores_every_candidate_against_the_reference() {
    let req = request(96, 64);
    let reference = Technique::parse("groundtruth:spp=64").unwrap();
    let list = vec![candidate("vao"), candidate("gtao"), candidate("vbao:preset=low"), candidate("groundtruth:spp=64")];
    let scenes = vec![scene_views("cornell", &req).unwrap()];
    let set =
        TuneSet::new(Device::Cpu, Inputs::Device, scenes, reference.clone(), Metric::Mse, None, &mut |_| {}).unwrap();
    let mut heard = Vec::new();
    let frontiers = measure(&set, &list, 2, &mut |scene, p| heard.push((scene.to_string(), p.label.clone()))).unwrap();
    assert_eq!(heard.len(), list.len());
    assert_eq!(frontiers.len(), 1);
    let f = &frontiers[0];
    assert_eq!((f.scene.as_str(), f.cameras.as_slice()), ("cornell", ["front".to_string()].as_slice()));
    assert_eq!(f.points.len(), list.len());
    let (scene, frames) = scene_views("cornell", &req).unwrap();
    let (_, frame) = &frames[0];
    let cpu = CpuRenderer::new(&scene);
    let none = &aokit_cpu::no_progress;
    let (g, _) = cpu.gbuffer(frame, none);
    let gt = cpu.run(frame, &g, &reference, none).ao_final;
    let (w, h) = (96usize, 64usize);
    fn img(v: &[f32]) -> ImageRef<'_> {
        ImageRef { width: 96, height: 64, pixels: v }
    }
    for (p, c) in f.points.iter().zip(&list) {
        let ao = cpu.run(frame, &g, &c.technique, none).ao_final;
        let (a, r) = common::inner_pair(&frame.camera.view, &ao, &gt);
        assert_eq!(a.len(), w * h);
        let own_mse = a.iter().zip(&r).map(|(x, y)| (*x as f64 - *y as f64).powi(2)).sum::<f64>() / (w * h) as f64;
        assert!((p.mse - own_mse).abs() <= 1e-9 * own_mse.max(1e-12), "{}: MSE {} vs {own_mse}", p.label, p.mse);
        assert!((p.ssim - ssim(img(&a), img(&r), None).unwrap()).abs() < 1e-12, "{}: SSIM", p.label);
        assert!((p.flip - flip(img(&r), img(&a), None).unwrap()).abs() < 1e-12, "{}: FLIP", p.label);
        assert!(p.ms > 0.0 && p.ms.is_finite(), "{}: {} ms", p.label, p.ms);
    }
    let exact = &f.points[3];
    assert_eq!((exact.mse, exact.flip, exact.pareto), (0.0, 0.0, true), "the reference against itself");
    assert!(f.points[..3].iter().all(|p| p.mse > 1e-4), "every other technique differs from the ground truth");
    // The flags follow the rule, checked here by the test's own loop over the points.
    for p in &f.points {
        let beaten = f.points.iter().any(|q| q.mse < p.mse && q.ms < p.ms);
        assert_eq!(p.pareto, !beaten, "{}", p.label);
    }
    // The plot: one circle per point with a positive MSE (the exact one cannot be drawn on a log
    // axis), filled for the Pareto points, each labelled.
    let plot = svg(f, "cpu", "groundtruth:spp=64").unwrap();
    let drawn: Vec<_> = f.points.iter().filter(|p| p.mse > 0.0).collect();
    assert_eq!(plot.matches("<circle").count(), drawn.len());
    let filled =
        plot.split("<circle").skip(1).filter(|c| !c.split('>').next().unwrap().contains("fill=\"none\"")).count();
    assert_eq!(filled, drawn.iter().filter(|p| p.pareto).count(), "filled circles = Pareto points");
    for p in &drawn {
        assert!(
            plot.contains(&format!(">{}<", p.label)) || plot.contains(&format!(">\n{}\n<", p.label)),
            "{} unlabelled",
            p.label
        );
    }
}

/// The Vulkan back-end takes cpu-sim's G-buffer and reference but runs the techniques itself: a
/// screen-space technique scores the MSE it scores on the CPU (the kernels agree to within the
/// CPU ≡ Vulkan bars, far below the MSE itself) from an image that is Vulkan's own (not bit for
/// bit cpu-sim's: the two back-ends round differently), and the reference is cpu-sim's.
#[test]
fn vulkan_is_scored_on_cpu_sims_inputs() {
    let Some(vulkan) = common::vulkan() else { return };
    let req = request(96, 64);
    let reference = Technique::parse("groundtruth:spp=64").unwrap();
    let list = vec![candidate("gtao"), candidate("vao")];
    let on = |device| {
        let scenes = vec![scene_views("cornell", &req).unwrap()];
        let set = TuneSet::new(device, Inputs::Cpu, scenes, reference.clone(), Metric::Mse, None, &mut |_| {}).unwrap();
        let f = measure(&set, &list, 1, &mut |_, _| {}).unwrap().remove(0);
        assert!(set.device.validation_messages().is_empty());
        let images: Vec<Vec<f32>> = list.iter().map(|c| set.evaluate(0, 0, &c.technique).unwrap().0).collect();
        (f, set.scenes[0].views[0].reference().to_vec(), images, set.device.name())
    };
    let (cpu, cpu_reference, cpu_images, cpu_name) = on(Device::Cpu);
    let (gpu, gpu_reference, gpu_images, gpu_name) = on(Device::Vulkan(vulkan));
    assert_eq!((cpu_name, gpu_name), ("cpu", "vulkan"));
    assert!(cpu_reference == gpu_reference, "one reference, cpu-sim's");
    for ((c, g), (a, b)) in cpu.points.iter().zip(&gpu.points).zip(cpu_images.iter().zip(&gpu_images)) {
        assert!((c.mse - g.mse).abs() <= 0.01 * c.mse, "{}: MSE cpu {} vs vulkan {}", c.label, c.mse, g.mse);
        assert!((c.flip - g.flip).abs() <= 0.01 * c.flip, "{}: FLIP cpu {} vs vulkan {}", c.label, c.flip, g.flip);
        assert!(a != b, "{}: the Vulkan image is cpu-sim's bit for bit; did Vulkan run it?", c.label);
    }
}

/// The command writes the table, the JSON and one plot per scene; bad input is one line.
#[test]
fn frontier_command_writes_table_json_and_plots() {
    let dir = std::env::temp_dir().join(format!("aokit-frontier-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let aokit = env!("CARGO_BIN_EXE_aokit");
    let out = Command::new(aokit)
        .args(["frontier", "--scenes", "cornell", "--width", "64", "--height", "48", "--guard", "8"])
        .args(["--techniques", "vao,gtao,gtao:preset=low", "--reference", "groundtruth:spp=16", "--frames", "1"])
        .args(["--no-cache", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("frontier_cpu.json")).unwrap()).unwrap();
    assert_eq!(json["backend"], "cpu");
    assert_eq!(json["width"], 64);
    let points = json["scenes"][0]["points"].as_array().unwrap();
    assert_eq!(points.len(), 3);
    for p in points {
        for key in ["label", "technique", "spec", "options", "mse", "ssim", "flip", "ms", "pareto"] {
            assert!(p.get(key).is_some(), "missing {key}");
        }
    }
    assert!(points.iter().any(|p| p["pareto"] == true));
    let table = std::fs::read_to_string(dir.join("frontier_cpu.md")).unwrap();
    assert!(table.contains("![cornell frontier](cornell_cpu.svg)"));
    assert_eq!(table.lines().filter(|l| l.starts_with("| vao") || l.starts_with("| gtao")).count(), 3);
    assert!(std::fs::read_to_string(dir.join("cornell_cpu.svg")).unwrap().starts_with("<svg"));
    for (args, message) in [
        (vec!["--scenes", "nowhere"], "neither a built-in scene"),
        (vec!["--scenes", "cornell,cornell"], "names cornell twice"),
        (vec!["--scenes", "cornell", "--frames", "0"], "--frames must be at least 1"),
        (vec!["--scenes", "cornell", "--techniques", "nope"], "unknown technique 'nope'"),
        (vec!["--scenes", "cornell", "--ao-samples", "8"], "settings flags need --techniques"),
        (vec!["--scenes", "cornell", "--techniques", "vao", "--no-tuned"], "--no-tuned applies to the default list"),
        (vec!["--scenes", "cornell", "--validation"], "--validation enables the Vulkan validation layer"),
    ] {
        let out = Command::new(aokit).arg("frontier").args(&args).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success() && stderr.contains(message), "{args:?}: {stderr}");
        assert_eq!(stderr.trim().lines().count(), 1, "{args:?}: {stderr}");
    }
}
