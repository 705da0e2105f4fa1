//! `aokit`: render ambient occlusion for a scene on the CPU or on Vulkan.

use aokit::cli::SceneArgs;
use aokit::cli::TechniqueArgs;
use aokit::frame::Frame;
use aokit::output::{crop_inner, write_bent_png, write_exr, write_png};
use aokit::render::{CpuRenderer, Renderer, VulkanRenderer};
use aokit::report::{BenchResult, CompareReport, CompareSetup};
use aokit::scene::Scene;
use aokit::scene::builtin;
use aokit::technique::Describe;
use aokit_cpu::GBufferImage;
use aokit_shaders::graph::RtMode;
use aokit_vulkan::GpuOptions;
use clap::{Parser, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "aokit", version, about = "Real-time ambient-occlusion kernels, on Vulkan and on the CPU")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render an AO image of a scene.
    Render(RenderArgs),
    /// Render several techniques on one G-buffer and compare them with a reference: MSE, PSNR,
    /// SSIM, rays, time per pass; optional JSON and HTML report.
    Compare(CompareArgs),
    /// Time a technique over K frames after a warm-up: median/min/max per pass, Mpixel/s.
    Bench(BenchArgs),
    /// The scaling study: the scene instanced 1, 4, 16, 64 times on a grid (same camera), per-pass
    /// times of VAO, Ray-SD and the raster SD map.
    Scaling(ScalingArgs),
    /// Write a frame's G-buffer (as engine images and in aokit's layout), camera and scene as plain
    /// files for consumers without Rust (formats: docs/export.md).
    Export(ExportArgs),
    /// Write a static WebGPU page (plain JS modules) that runs the screen-space techniques in a
    /// browser on the exported G-buffer, with cpu-sim's AO as its reference (docs/web.md).
    Web(WebArgs),
    /// Render a camera path (orbit or dolly) frame after frame, with and without temporal
    /// accumulation: temporal instability and MSE against the ground truth per technique, an
    /// animated PNG to look at (docs/temporal.md).
    Path(PathArgs),
    /// Trace the ground truth's AO rays and the G-buffer's primary rays of a frame through
    /// cpu-sim's BVH on N threads: M rays/s, occluded fraction; `--dump DIR` writes the triangles
    /// and rays as .npy for another tracer (bench/embree_rays.py: Embree).
    Rays(aokit::rays::RaysArgs),
    /// Print the Vulkan device aokit would use and its ray-tracing extensions.
    Info {
        /// Enable the Khronos validation layer.
        #[arg(long)]
        validation: bool,
    },
    /// List the built-in scenes and their camera presets.
    Scenes,
    /// List the techniques and their settings (key, accepted values, default, flag).
    Techniques,
    /// Search a technique's number settings against the 512-spp ground truth (Nelder–Mead),
    /// cross-validated over scenes: prints the tuned settings and the gain on held-back scenes.
    Tune(aokit::tune::TuneArgs),
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum Backend {
    Cpu,
    Vulkan,
}

/// Scene, camera and AO parameters shared by every command.
#[derive(clap::Args)]
#[command(allow_negative_numbers = true)]
struct FrameArgs {
    #[command(flatten)]
    view: SceneArgs,
    #[arg(long, value_enum, default_value = "cpu")]
    backend: Backend,
    /// G-buffer guard band in pixels on every side.
    #[arg(long, default_value_t = 64)]
    guard: u32,
    /// Enable the Khronos validation layer (Vulkan back-end); validation messages fail the run.
    #[arg(long)]
    validation: bool,
    /// How the Vulkan back-end runs ray-traced passes: ray-tracing pipelines (raygen, miss,
    /// any-hit; default) or compute kernels with ray queries (VK_KHR_ray_query).
    #[arg(long, value_parser = RtMode::NAMES)]
    rt_mode: Option<String>,
}

#[derive(clap::Args)]
struct RenderArgs {
    #[command(flatten)]
    frame: FrameArgs,
    #[command(flatten)]
    options: TechniqueArgs,
    /// A technique of `aokit techniques`, optionally with `:key=value` settings.
    #[arg(long, default_value = "vao")]
    technique: String,
    /// Skip the bilateral blur.
    #[arg(long)]
    no_blur: bool,
    /// Output PNG (8-bit grey, 1 = unoccluded = white).
    #[arg(long, default_value = "ao.png")]
    out: PathBuf,
    /// Also write the raw float AO as OpenEXR.
    #[arg(long)]
    exr: Option<PathBuf>,
    /// Also write the bent normals (RGB PNG: rgb = view-space normal ·0.5 + 0.5; needs a
    /// technique that outputs them: gtao with --gtao-bent-normals on).
    #[arg(long, value_name = "PNG")]
    bent_out: Option<PathBuf>,
}

#[derive(clap::Args)]
struct CompareArgs {
    #[command(flatten)]
    frame: FrameArgs,
    #[command(flatten)]
    options: TechniqueArgs,
    /// Comma-separated techniques to compare, each optionally with `:key=value` settings (e.g.
    /// `raysd:sd-layers=8`).
    #[arg(long, default_value = "vao,raysd,raysvao")]
    techniques: String,
    /// The reference technique (raysvao or groundtruth).
    #[arg(long, default_value = "raysvao")]
    reference: String,
    /// Write the machine-readable report here.
    #[arg(long)]
    json: Option<PathBuf>,
    /// Write a self-contained HTML page with the images into this folder.
    #[arg(long)]
    html: Option<PathBuf>,
    /// Folder for the PNGs (AO, signed differences, refinement heatmap, ray intervals, SD
    /// layers); default: the --html folder, else `compare-out`.
    #[arg(long)]
    images: Option<PathBuf>,
}

#[derive(clap::Args)]
struct BenchArgs {
    #[command(flatten)]
    frame: FrameArgs,
    #[command(flatten)]
    options: TechniqueArgs,
    #[arg(long, default_value = "vao")]
    technique: String,
    /// Timed frames after the warm-up.
    #[arg(long, default_value_t = 10)]
    frames: u32,
    /// Untimed warm-up frames.
    #[arg(long, default_value_t = 2)]
    warmup: u32,
    /// Write the results as JSON here.
    #[arg(long)]
    json: Option<PathBuf>,
}

#[derive(clap::Args)]
struct ScalingArgs {
    #[command(flatten)]
    frame: FrameArgs,
    #[command(flatten)]
    options: TechniqueArgs,
    /// Instance counts (squares).
    #[arg(long, default_value = "1,4,16,64")]
    copies: String,
    /// Techniques to time.
    #[arg(long, default_value = "vao,raysd,sdsvao")]
    techniques: String,
    /// Timed frames per point after one warm-up frame.
    #[arg(long, default_value_t = 3)]
    frames: u32,
    /// Write the results as JSON here.
    #[arg(long)]
    json: Option<PathBuf>,
}

#[derive(clap::Args)]
struct PathArgs {
    #[command(flatten)]
    frame: FrameArgs,
    #[command(flatten)]
    options: TechniqueArgs,
    /// Comma-separated techniques, each optionally with `:key=value` settings, or `all` (every
    /// registered technique but the reference).
    #[arg(long, visible_alias = "techniques", default_value = "gtao")]
    technique: String,
    /// The camera path: `orbit` (around the camera's target, about its up axis) or `dolly`
    /// (toward the target).
    #[arg(long, default_value = "orbit")]
    path: String,
    /// Frames of the path (at least 2).
    #[arg(long, default_value_t = 60)]
    frames: u32,
    /// Step per frame: degrees of orbit [0.25], or the fraction of the eye–target distance a
    /// dolly moves [0.005].
    #[arg(long)]
    step: Option<f32>,
    /// Temporal accumulation: `off`, `on` or `both` (each technique twice).
    #[arg(long, default_value = "both")]
    temporal: String,
    /// The current frame's weight α of the accumulation's exponential blend, in (0, 1].
    #[arg(long, default_value_t = 0.1)]
    temporal_alpha: f32,
    /// Relative depth tolerance ε of the accumulation's history test and of the instability's
    /// "valid in both frames", in (0, 1].
    #[arg(long, default_value_t = aokit_shaders::temporal::settings::DEPTH_TOLERANCE)]
    temporal_depth_tolerance: f32,
    /// The techniques' noise over the frames: `animated` (frame index t) or `static` (0).
    #[arg(long, default_value = "animated")]
    noise: String,
    /// The reference (MSE, and its own instability as the floor), optionally with settings.
    #[arg(long, default_value = "groundtruth")]
    reference: String,
    /// Animated PNG of the final AO; with several runs one file per run, the run's label
    /// appended to the name (`anim-gtao.png`, `anim-gtao-temporal.png`, `anim-groundtruth.png`).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Frames per second of the animated PNG.
    #[arg(long, default_value_t = 30)]
    fps: u16,
    /// Write the machine-readable report here.
    #[arg(long)]
    json: Option<PathBuf>,
}

#[derive(clap::Args)]
struct ExportArgs {
    #[command(flatten)]
    frame: FrameArgs,
    /// Folder to write into (created if missing).
    #[arg(long)]
    out: PathBuf,
}

#[derive(clap::Args)]
struct WebArgs {
    #[command(flatten)]
    frame: FrameArgs,
    /// Folder to write the page into (created if missing); serve it over HTTP.
    #[arg(long)]
    out: PathBuf,
}

/// Load the scene and resolve the camera and AO parameters.
fn resolve(args: &FrameArgs) -> Result<(Scene, Frame), String> {
    args.view.resolve(args.guard)
}

/// The back-end the user picked.
fn renderer(args: &FrameArgs, scene: &Scene) -> Result<Renderer, String> {
    let mode = rt_mode(args)?;
    match args.backend {
        Backend::Cpu => Ok(Renderer::Cpu(CpuRenderer::new(scene))),
        Backend::Vulkan => {
            let renderer = VulkanRenderer::new(&GpuOptions { validation: args.validation, ..Default::default() })
                .map_err(|e| e.to_string())?;
            renderer.set_rt_mode(mode);
            Ok(Renderer::Vulkan(renderer))
        }
    }
}

/// `--rt-mode`: only the Vulkan back-end has two ways to trace (cpu-sim hands every candidate
/// of its BVH to the same any-hit decision either way).
fn rt_mode(args: &FrameArgs) -> Result<RtMode, String> {
    match (&args.rt_mode, args.backend) {
        (None, _) => Ok(RtMode::Pipeline),
        (Some(mode), Backend::Vulkan) => RtMode::parse(mode),
        (Some(mode), Backend::Cpu) => Err(format!(
            "--rt-mode {mode} selects how the Vulkan back-end traces (--backend vulkan); cpu-sim traces through its BVH"
        )),
    }
}

/// Fail when the validation layer said anything.
fn check_validation(renderer: &Renderer) -> Result<(), String> {
    let messages = renderer.validation_messages();
    if messages.is_empty() {
        return Ok(());
    }
    Err(format!("validation layer reported {} message(s):\n{}", messages.len(), messages.join("\n")))
}

/// A progress bar over G-buffer and pass rows (CPU back-end).
fn progress_bar(message: String, rows: u64) -> ProgressBar {
    let bar = ProgressBar::new(rows).with_style(
        ProgressStyle::with_template("{spinner} {msg} [{bar:40}] {pos}/{len} rows ({eta})").expect("valid template"),
    );
    bar.set_message(message);
    bar
}

fn passes_json(passes: &[(&str, f64)]) -> serde_json::Value {
    passes.iter().map(|(n, ms)| serde_json::json!({"name": n, "ms": ms})).collect::<Vec<_>>().into()
}

fn render(args: RenderArgs) -> Result<(), String> {
    let technique = args.options.technique(&args.technique)?;
    let (scene, frame) = resolve(&args.frame)?;
    let renderer = renderer(&args.frame, &scene)?;
    let rows = 2 * frame.camera.view.size().y as u64;
    let bar = progress_bar(format!("{} G-buffer + {}", renderer.backend_name(), technique.name()), rows);
    let progress = |n| bar.inc(n);
    let (run, _) = renderer.frame(&scene, &frame, &technique, &progress, true).map_err(|e| e.to_string())?;
    bar.finish_and_clear();
    check_validation(&renderer)?;
    let view = frame.camera.view;
    if let Some(path) = &args.bent_out {
        if run.bent_normals.is_empty() {
            return Err(format!(
                "--bent-out: {} wrote no bent normals (gtao writes them with --gtao-bent-normals on)",
                technique.name()
            ));
        }
        let inner = crop_inner(&view, &run.bent_normals);
        write_bent_png(path, frame.inner.x, frame.inner.y, &inner).map_err(|e| e.to_string())?;
    }
    let full = if args.no_blur { &run.ao } else { &run.ao_final };
    let ao = crop_inner(&view, full);
    // Written atomically; the errors name the path.
    write_png(&args.out, frame.inner.x, frame.inner.y, &ao).map_err(|e| e.to_string())?;
    if let Some(exr) = &args.exr {
        write_exr(exr, frame.inner.x, frame.inner.y, &ao).map_err(|e| e.to_string())?;
    }
    let mut line = frame.describe();
    line["scene"] = scene.name.clone().into();
    line["triangles"] = scene.triangles.len().into();
    line["technique"] = technique.name().into();
    line["options"] = technique.describe();
    line["backend"] = renderer.backend_name().into();
    line["device"] = renderer.device_name().into();
    line["passes_ms"] = passes_json(&run.passes);
    if let Some(ms) = run.frame_ms {
        line["frame_ms"] = ms.into();
    }
    line["rays"] = run.rays.into();
    line["refined_samples"] = run.refined_samples.into();
    line["mean_ao"] = (ao.iter().map(|&a| a as f64).sum::<f64>() / ao.len() as f64).into();
    line["out"] = args.out.display().to_string().into();
    if let Some(path) = &args.bent_out {
        line["bent_out"] = path.display().to_string().into();
    }
    println!("{line}");
    Ok(())
}

fn compare(args: CompareArgs) -> Result<(), String> {
    let names: Vec<&str> = args.techniques.split(',').map(str::trim).filter(|s| !s.is_empty()).collect();
    if names.is_empty() {
        return Err("--techniques is empty".into());
    }
    let mut techniques = args.options.techniques(&[&names[..], &[args.reference.as_str()]].concat())?;
    let reference = techniques.pop().expect("the reference is the last");
    let (scene, frame) = resolve(&args.frame)?;
    let renderer = renderer(&args.frame, &scene)?;
    let rows = frame.camera.view.size().y as u64 * (2 + techniques.len() as u64);
    let bar = progress_bar(format!("{}: compare on {}", renderer.backend_name(), scene.name), rows);
    let progress = |n| bar.inc(n);
    let (gbuffer, gbuffer_ms) = renderer.gbuffer(&scene, &frame, &progress).map_err(|e| e.to_string())?;
    let reference_run = renderer.run(&scene, &frame, &gbuffer, &reference, &progress).map_err(|e| e.to_string())?;
    let mut runs = Vec::new();
    for t in &techniques {
        runs.push((t.clone(), renderer.run(&scene, &frame, &gbuffer, t, &progress).map_err(|e| e.to_string())?));
    }
    bar.finish_and_clear();
    check_validation(&renderer)?;
    let device = renderer.device_name();
    let setup = CompareSetup { scene: &scene.name, backend: renderer.backend_name(), device: &device, gbuffer_ms };
    let report = CompareReport::new(setup, &frame, (reference, &reference_run), &runs);
    println!("{}", report.table());
    if let Some(path) = &args.json {
        let text = serde_json::to_string_pretty(&report.json()).expect("serializable");
        aokit::output::write_atomic_bytes(path, text.as_bytes()).map_err(|e| e.to_string())?;
    }
    let images = args.images.clone().or(args.html.clone()).unwrap_or_else(|| PathBuf::from("compare-out"));
    report.write_images(&images, &frame, &gbuffer).map_err(|e| format!("{}: {e}", images.display()))?;
    if let Some(dir) = &args.html {
        let page = report.write_html(dir, &images).map_err(|e| format!("{}: {e}", dir.display()))?;
        eprintln!("wrote {}", page.display());
    }
    Ok(())
}

fn bench(args: BenchArgs) -> Result<(), String> {
    if args.frames == 0 {
        return Err("--frames must be at least 1".into());
    }
    let technique = args.options.technique(&args.technique)?;
    let (scene, frame) = resolve(&args.frame)?;
    let renderer = renderer(&args.frame, &scene)?;
    let total = args.warmup + args.frames;
    let bar = ProgressBar::new(total as u64)
        .with_style(ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} frames").expect("valid template"));
    bar.set_message(format!("bench {} on {}", technique.name(), renderer.backend_name()));
    let mut frames = Vec::new();
    // Per frame: the technique's command buffer from submit to fence, and its pass timestamps.
    let (mut frame_ms, mut gpu_ms) = (Vec::new(), Vec::new());
    for k in 0..total {
        let (run, _) =
            renderer.frame(&scene, &frame, &technique, &aokit_cpu::no_progress, false).map_err(|e| e.to_string())?;
        if k >= args.warmup {
            // The acceleration structure is built once per scene, outside the frames.
            let passes: Vec<_> = run.passes.iter().copied().filter(|p| p.0 != "accel_build").collect();
            if let Some(ms) = run.frame_ms {
                frame_ms.push(ms);
                gpu_ms.push(passes.iter().map(|p| p.1).sum());
            }
            frames.push(passes);
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    check_validation(&renderer)?;
    let result = BenchResult::new(&frames, frame.inner);
    let json = serde_json::json!({
        "scene": scene.name, "backend": renderer.backend_name(), "device": renderer.device_name(),
        "technique": technique.name(), "options": technique.describe(),
        "width": frame.inner.x, "height": frame.inner.y, "target": [frame.camera.view.res.x, frame.camera.view.res.y],
        "warmup": args.warmup, "frames": args.frames, "threads": rayon::current_num_threads(),
        "passes": result.json(),
        "frame_ms": (!frame_ms.is_empty()).then(|| aokit::report::median(&mut frame_ms.clone())),
        "gpu_ms": (!gpu_ms.is_empty()).then(|| aokit::report::median(&mut gpu_ms.clone())),
    });
    println!("{}", result.table());
    if !frame_ms.is_empty() {
        println!("{:<8} {:>10} {:>10}", "frame", "frame_ms", "gpu_ms");
        for (i, (f, g)) in frame_ms.iter().zip(&gpu_ms).enumerate() {
            println!("{i:<8} {f:>10.2} {g:>10.2}");
        }
    }
    println!("{json}");
    if let Some(path) = &args.json {
        let text = serde_json::to_string_pretty(&json).expect("serializable");
        aokit::output::write_atomic_bytes(path, text.as_bytes()).map_err(|e| e.to_string())?;
    }
    Ok(())
}

fn scaling(args: ScalingArgs) -> Result<(), String> {
    let copies: Vec<u32> = args
        .copies
        .split(',')
        .map(|c| c.trim().parse::<u32>().map_err(|e| format!("--copies '{c}': {e}")))
        .collect::<Result<_, _>>()?;
    let names: Vec<&str> = args.techniques.split(',').map(str::trim).collect();
    let techniques = args.options.techniques(&names)?;
    if args.frames == 0 {
        return Err("--frames must be at least 1".into());
    }
    let (scene, frame) = resolve(&args.frame)?;
    let mut rows = Vec::new();
    println!("{:>6} {:>10} {:<10} {:>10}  passes (median ms)", "copies", "triangles", "technique", "total ms");
    for &k in &copies {
        let big = scene.instanced_grid(k)?;
        let renderer = renderer(&args.frame, &big)?;
        let (gbuffer, _) = renderer.gbuffer(&big, &frame, &aokit_cpu::no_progress).map_err(|e| e.to_string())?;
        for t in &techniques {
            let mut frames = Vec::new();
            for i in 0..=args.frames {
                let run =
                    renderer.run(&big, &frame, &gbuffer, t, &aokit_cpu::no_progress).map_err(|e| e.to_string())?;
                if i > 0 {
                    frames.push(run.passes.into_iter().filter(|p| p.0 != "accel_build").collect::<Vec<_>>());
                }
            }
            let stats = BenchResult::new(&frames, frame.inner);
            let total = stats.passes.iter().find(|p| p.0 == "total").map_or(0.0, |p| p.1);
            let passes: Vec<_> =
                stats.passes.iter().filter(|p| p.0 != "total").map(|p| format!("{} {:.1}", p.0, p.1)).collect();
            println!("{k:>6} {:>10} {:<10} {total:>10.1}  {}", big.triangles.len(), t.label(), passes.join(", "));
            rows.push(serde_json::json!({
                "copies": k, "triangles": big.triangles.len(), "technique": t.name(), "options": t.describe(),
                "passes": stats.json(), "total_ms": total,
            }));
        }
        check_validation(&renderer)?;
    }
    let json = serde_json::json!({
        "scene": scene.name, "backend": format!("{:?}", args.frame.backend).to_lowercase(),
        "width": frame.inner.x, "height": frame.inner.y, "frames": args.frames, "results": rows,
    });
    if let Some(path) = &args.json {
        let text = serde_json::to_string_pretty(&json).expect("serializable");
        aokit::output::write_atomic_bytes(path, text.as_bytes()).map_err(|e| e.to_string())?;
    }
    Ok(())
}

fn path(args: PathArgs) -> Result<(), String> {
    use aokit::path::{
        Measure, Noise, PathInputs, PathKind, PathReport, PathResult, PathSpec, path_frames, run_path, suffixed,
        write_apng,
    };
    use aokit_shaders::temporal::settings::TemporalSettings;
    let kind = PathKind::parse(&args.path)?;
    let spec = PathSpec { kind, frames: args.frames, step: args.step.unwrap_or(kind.default_step()) };
    spec.validate()?;
    let noise = Noise::parse(&args.noise)?;
    let modes: &[bool] = match args.temporal.as_str() {
        "off" => &[false],
        "on" => &[true],
        "both" => &[false, true],
        other => return Err(format!("--temporal {other}: expected off, on or both")),
    };
    let temporal = TemporalSettings { alpha: args.temporal_alpha, depth_tolerance: args.temporal_depth_tolerance };
    // The library names the setting; the command line names its flags.
    temporal.validate().map_err(|e| {
        e.replace("temporal alpha", "--temporal-alpha")
            .replace("temporal depth tolerance", "--temporal-depth-tolerance")
    })?;
    if let Some(out) = &args.out
        && !out.extension().is_some_and(|e| e.eq_ignore_ascii_case("png"))
    {
        return Err(format!("--out {}: aokit writes an animated PNG (APNG): give a .png path", out.display()));
    }
    let reference_name = args.reference.split(':').next().unwrap_or_default();
    let names: Vec<&str> = match args.technique.trim() {
        "all" => aokit::technique::TECHNIQUES.iter().map(|t| t.name()).filter(|n| *n != reference_name).collect(),
        list => list.split(',').map(str::trim).filter(|s| !s.is_empty()).collect(),
    };
    if names.is_empty() {
        return Err("--technique is empty".into());
    }
    let mut techniques = args.options.techniques(&[&names[..], &[args.reference.as_str()]].concat())?;
    let reference = techniques.pop().expect("the reference is the last");
    let (scene, base) = resolve(&args.frame)?;
    let renderer = renderer(&args.frame, &scene)?;
    let frames_off = path_frames(&base, &spec, noise, None);
    let frames_on = path_frames(&base, &spec, noise, Some(temporal));
    let runs = 2 + (techniques.len() * modes.len()) as u64;
    let bar = ProgressBar::new(runs * spec.frames as u64).with_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} frames ({eta})").expect("valid template"),
    );
    bar.set_message(format!("{} G-buffers", renderer.backend_name()));
    let mut gbuffers = Vec::new();
    for f in &frames_off {
        gbuffers.push(renderer.gbuffer(&scene, f, &aokit_cpu::no_progress).map_err(|e| e.to_string())?.0);
        bar.inc(1);
    }
    let inputs = |frames| PathInputs { renderer: &renderer, scene: &scene, frames, gbuffers: &gbuffers };
    let tolerance = temporal.depth_tolerance;
    let measure = Measure { reference: None, tolerance, images: args.out.is_some(), keep_ao: true };
    let tick = || bar.inc(1);
    bar.set_message(format!("{} (reference)", reference.label()));
    let (reference_run, reference_ao) =
        run_path(inputs(&frames_off), &reference, measure, &aokit_cpu::no_progress, &tick)?;
    let reference = PathResult { technique: reference, temporal: false, run: reference_run };
    let mut results = Vec::new();
    for t in &techniques {
        for &on in modes {
            bar.set_message(format!("{}{}", t.label(), if on { " +temporal" } else { "" }));
            let frames = if on { &frames_on } else { &frames_off };
            let measure = Measure { reference: Some(&reference_ao), keep_ao: false, ..measure };
            let (run, _) = run_path(inputs(frames), t, measure, &aokit_cpu::no_progress, &tick)?;
            results.push(PathResult { technique: t.clone(), temporal: on, run });
        }
    }
    bar.finish_and_clear();
    check_validation(&renderer)?;
    let device = renderer.device_name();
    let report = PathReport {
        scene: &scene.name,
        backend: renderer.backend_name(),
        device: &device,
        frame: &base,
        spec,
        noise,
        temporal,
        tolerance,
        reference: &reference,
        results: &results,
    };
    print!("{}", report.table());
    if let Some(path) = &args.json {
        let text = serde_json::to_string_pretty(&report.json()).expect("serializable");
        aokit::output::write_atomic_bytes(path, text.as_bytes()).map_err(|e| e.to_string())?;
    }
    if let Some(out) = &args.out {
        let single = results.len() == 1;
        for res in std::iter::once(&reference).chain(&results) {
            let is_reference = std::ptr::eq(res, &reference);
            if single && is_reference {
                continue;
            }
            let name = format!("{}{}", res.technique.label(), if res.temporal { "-temporal" } else { "" });
            let name: String =
                name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '-' { c } else { '_' }).collect();
            let file = if single { out.clone() } else { suffixed(out, &name) };
            write_apng(&file, base.inner.x, base.inner.y, &res.run.images, args.fps).map_err(|e| e.to_string())?;
            eprintln!("wrote {}", file.display());
        }
    }
    Ok(())
}

/// The frame and its G-buffer on the chosen back-end, for commands that write them out (export,
/// web); `command` names the command in the `--rt-mode` refusal.
fn frame_gbuffer(args: &FrameArgs, command: &str) -> Result<(Scene, Frame, GBufferImage, &'static str), String> {
    if args.rt_mode.is_some() {
        return Err(format!("--rt-mode is not read by {command} (it traces no AO rays)"));
    }
    let (scene, frame) = resolve(args)?;
    let renderer = renderer(args, &scene)?;
    let rows = frame.camera.view.size().y as u64;
    let bar = progress_bar(format!("{} G-buffer", renderer.backend_name()), rows);
    let progress = |n| bar.inc(n);
    let (gbuffer, _) = renderer.gbuffer(&scene, &frame, &progress).map_err(|e| e.to_string())?;
    bar.finish_and_clear();
    check_validation(&renderer)?;
    Ok((scene, frame, gbuffer, renderer.backend_name()))
}

fn export(args: ExportArgs) -> Result<(), String> {
    let (scene, frame, gbuffer, backend) = frame_gbuffer(&args.frame, "export")?;
    let json = aokit::export::write(&args.out, &scene, &frame, &gbuffer, backend)
        .map_err(|e| format!("{}: {e}", args.out.display()))?;
    println!("{json}");
    Ok(())
}

fn web(args: WebArgs) -> Result<(), String> {
    let (scene, frame, gbuffer, backend) = frame_gbuffer(&args.frame, "web")?;
    // The page's references: cpu-sim on this G-buffer, whatever the back-end.
    let json = aokit::web::write(&args.out, &scene, &frame, &gbuffer, backend, &aokit_cpu::no_progress)
        .map_err(|e| format!("{}: {e}", args.out.display()))?;
    let names: Vec<_> = json["techniques"].as_array().into_iter().flatten().map(|t| t["name"].clone()).collect();
    let line = serde_json::json!({
        "format": json["format"], "out": args.out.display().to_string(), "techniques": names, "skipped": json["skipped"],
    });
    println!("{line}");
    Ok(())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render(args) => render(args),
        Command::Compare(args) => compare(args),
        Command::Bench(args) => bench(args),
        Command::Scaling(args) => scaling(args),
        Command::Export(args) => export(args),
        Command::Web(args) => web(args),
        Command::Path(args) => path(args),
        Command::Tune(args) => aokit::tune::tune_command(args),
        Command::Rays(args) => aokit::rays::rays_command(args),
        Command::Info { validation } => aokit_vulkan::Gpu::new(&GpuOptions { validation, ..Default::default() })
            .map_err(|e| e.to_string())
            .map(|gpu| {
                let info = gpu.info();
                println!("{}", serde_json::to_string(info).expect("serializable"));
                eprintln!("device: {} ({}, Vulkan {})", info.name, info.device_type, info.api_version);
                for (ext, has) in &info.ray_tracing_extensions {
                    eprintln!("  {ext}: {}", if *has { "yes" } else { "no" });
                }
            }),
        Command::Techniques => {
            print!("{}", aokit::cli::list_techniques());
            Ok(())
        }
        Command::Scenes => {
            for s in builtin::builtin_scenes() {
                let cams: Vec<_> = s.cameras.iter().map(|c| c.name).collect();
                println!("{:8} {} — cameras: {}; radius {}", s.name, s.description, cams.join(", "), s.radius);
            }
            Ok(())
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
