//! The C sample (`examples/c/`): a C11 program that uses nothing of aokit but the committed
//! SPIR-V (`assets/spirv/`) and the generated header (`assets/include/aokit.h`), on the frame files
//! `aokit export` writes. Built with `examples/c/build.sh`, run (with the Khronos validation
//! layer) for vao, gtao and raysd, and its PGM compared with cpu-sim on the same G-buffer.

mod common;

use aokit::render::CpuRenderer;
use aokit::technique::Technique;
use aokit_cpu::graph::{CpuExecutor, CpuInputs, CpuScene};
use aokit_cpu::no_progress;
use std::path::{Path, PathBuf};
use std::process::Command;

// Large enough that the AO radius spans more than raysd's 6-pixel cutoff: the SD map refines
// 14 % of the pixels (at 96×64 nothing is flagged and raysd equals vao).
const WIDTH: u32 = 160;
const HEIGHT: u32 = 112;
const GUARD: u32 = 8;

fn read<T: bytemuck::Pod>(dir: &Path, name: &str) -> Vec<T> {
    let bytes = std::fs::read(dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
    bytemuck::pod_collect_to_vec(&bytes)
}

/// A 16-bit binary PGM (P5, maxval 65535, big-endian) as values in [0, 1].
fn read_pgm(path: &Path) -> (u32, u32, Vec<f32>) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    // Header: "P5", width, height, maxval, each followed by one whitespace byte.
    let mut fields = Vec::new();
    let mut at = 0;
    while fields.len() < 4 {
        while bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        let start = at;
        while !bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        fields.push(String::from_utf8(bytes[start..at].to_vec()).unwrap());
    }
    at += 1;
    assert_eq!((fields[0].as_str(), fields[3].as_str()), ("P5", "65535"), "{}: not a 16-bit P5 PGM", path.display());
    let (w, h): (u32, u32) = (fields[1].parse().unwrap(), fields[2].parse().unwrap());
    let samples = &bytes[at..];
    assert_eq!(samples.len(), 2 * (w * h) as usize, "{}: sample bytes", path.display());
    let values = samples.chunks(2).map(|c| u16::from_be_bytes([c[0], c[1]]) as f32 / 65535.0).collect();
    (w, h, values)
}

/// cc and the Vulkan headers: `true` when they are missing and the run allows the skip.
fn without_c_toolchain() -> bool {
    common::skip::without_tool(common::skip::C_COMPILER, "cc", "apt-get install gcc")
        || (!Path::new("/usr/include/vulkan/vulkan.h").exists()
            && common::skip::cannot_run(
                common::skip::C_COMPILER,
                "no /usr/include/vulkan/vulkan.h (apt-get install libvulkan-dev)",
            ))
}

#[test]
fn c_sample_from_assets_only_agrees_with_cpu_sim() {
    if without_c_toolchain() || common::vulkan().is_none() {
        return;
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = std::env::temp_dir().join(format!("aokit-c-sample-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);

    let out = Command::new(env!("CARGO_BIN_EXE_aokit"))
        .args(["export", "--scene", "cornell"])
        .args(["--width", &WIDTH.to_string(), "--height", &HEIGHT.to_string(), "--guard", &GUARD.to_string()])
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "aokit export: {}", String::from_utf8_lossy(&out.stderr));

    // Built from another directory: build.sh finds its sources and the header itself.
    let build = Command::new("bash").arg(root.join("examples/c/build.sh")).current_dir(&dir).output().unwrap();
    assert!(
        build.status.success(),
        "examples/c/build.sh failed:\n{}{}",
        String::from_utf8_lossy(&build.stdout),
        String::from_utf8_lossy(&build.stderr)
    );
    let sample: PathBuf = root.join("examples/c/build/aokit-c-sample");

    // A bad technique name: one line on stderr, exit status 1.
    let bad = Command::new(&sample).arg(&dir).arg("ssao").arg(dir.join("bad.pgm")).output().unwrap();
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert_eq!(bad.status.code(), Some(1), "bad technique: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "one error line: {stderr}");
    assert!(stderr.contains("ssao"), "{stderr}");

    // The reference: cpu-sim on the exported G-buffer, with the frame `export` resolved.
    let (scene, frame) = common::builtin_frame("cornell", WIDTH, HEIGHT, GUARD);
    assert_eq!(
        std::fs::read(dir.join("camera.bin")).unwrap(),
        bytemuck::bytes_of(&frame.camera),
        "export's camera is the reference frame's"
    );
    let depth: Vec<f32> = read(&dir, "gbuffer_depth.f32");
    let normals: Vec<u32> = read(&dir, "gbuffer_normals.u32");
    let renderer = CpuRenderer::new(&scene);
    let surfaces = renderer.surfaces();

    let mut results = Vec::new();
    for technique in ["vao", "gtao", "raysd"] {
        let pgm = dir.join(format!("{technique}.pgm"));
        let run = Command::new(&sample).arg(&dir).arg(technique).arg(&pgm).env("AOKIT_C_VALIDATION", "1").output();
        let run = run.unwrap();
        assert!(
            run.status.success(),
            "aokit-c-sample {technique} (with validation):\n{}{}",
            String::from_utf8_lossy(&run.stdout),
            String::from_utf8_lossy(&run.stderr)
        );
        let (w, h, got) = read_pgm(&pgm);
        assert_eq!((w, h), (WIDTH, HEIGHT), "{technique}: the inner image");

        let graph = Technique::named(technique).unwrap().graph(&frame.desc()).unwrap();
        let inputs = CpuInputs {
            depth: &depth,
            normals: &normals,
            second_depth: None,
            scene: Some(CpuScene { bvh: renderer.bvh(), surfaces: &surfaces }),
            progress: &no_progress,
        };
        let mut cpu = CpuExecutor::new();
        cpu.run(&graph, &inputs).unwrap();
        let want = aokit::output::crop_inner(&graph.view, cpu.f32(graph.output).unwrap());
        assert_eq!(want.len(), got.len());

        let n = want.len() as f64;
        let within =
            want.iter().zip(&got).filter(|(a, b)| (*a - *b).abs() <= common::agreement::STEP).count() as f64 / n;
        let mse = want.iter().zip(&got).map(|(a, b)| ((a - b) as f64).powi(2)).sum::<f64>() / n;
        let occluded = want.iter().filter(|&&v| v < 0.99).count() as f64 / n;
        eprintln!(
            "{technique}: C sample vs cpu-sim {:.3} % within 1/255, MSE {mse:.2e}, occluded (< 0.99) {:.1} %",
            100.0 * within,
            100.0 * occluded
        );
        assert!(occluded >= 0.05, "{technique}: the reference must show occlusion ({:.1} %)", 100.0 * occluded);
        assert!(
            within >= common::agreement::MIN_WITHIN,
            "{technique}: only {:.3} % within 1/255 (MSE {mse:.2e})",
            100.0 * within
        );
        results.push(got);
    }
    // raysd's ray-query SD map must refine something: the image is not plain VAO's.
    let refined = results[0].iter().zip(&results[2]).filter(|(a, b)| (*a - *b).abs() > common::agreement::STEP).count();
    eprintln!(
        "raysd differs from vao (> 1/255) on {:.1} % of the pixels",
        100.0 * refined as f64 / results[0].len() as f64
    );
    assert!(refined * 100 >= results[0].len(), "raysd must differ from vao on ≥ 1 % of the pixels ({refined})");
    let _ = std::fs::remove_dir_all(&dir);
}
