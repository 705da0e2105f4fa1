//! `aokit bench`: a technique timed over K frames after a warm-up (median/min/max per pass,
//! Mpixel/s).

use super::{FrameArgs, check_validation, renderer, resolve};
use aokit::cli::TechniqueArgs;
use aokit::report::BenchResult;
use aokit::technique::Describe;
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct BenchArgs {
    #[command(flatten)]
    pub frame: FrameArgs,
    #[command(flatten)]
    pub options: TechniqueArgs,
    /// A technique of `aokit techniques`, optionally with `:key=value` settings.
    #[arg(long, default_value = "vao")]
    pub technique: String,
    /// Timed frames after the warm-up.
    #[arg(long, default_value_t = 10)]
    pub frames: u32,
    /// Untimed warm-up frames.
    #[arg(long, default_value_t = 2)]
    pub warmup: u32,
    /// Write the results as JSON here.
    #[arg(long)]
    pub json: Option<PathBuf>,
}

/// Run the command.
pub fn run(args: BenchArgs) -> Result<(), String> {
    if args.frames == 0 {
        return Err("--frames must be at least 1".into());
    }
    let technique = args.options.technique(&args.technique)?;
    let (scene, frame) = resolve(&args.frame)?;
    aokit::technique::check_graphs([&technique], &frame)?;
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
        "traces_rays": technique.graph(&frame.desc()).map(|g| g.traces_rays()).unwrap_or(false),
        "rt_mode": args.frame.rt_mode,
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
