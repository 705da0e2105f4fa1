//! `aokit compare`: several techniques on one G-buffer against a reference — MSE, PSNR, SSIM, rays,
//! time per pass; JSON, images and an HTML page.

use super::{FrameArgs, check_validation, progress_bar, renderer, resolve};
use aokit::cli::TechniqueArgs;
use aokit::report::{CompareReport, CompareSetup};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct CompareArgs {
    #[command(flatten)]
    pub frame: FrameArgs,
    #[command(flatten)]
    pub options: TechniqueArgs,
    /// Comma-separated techniques to compare, each optionally with `:key=value` settings (e.g.
    /// `raysd:sd-layers=8`).
    #[arg(long, default_value = "vao,raysd,raysvao")]
    pub techniques: String,
    /// The reference technique (raysvao or groundtruth).
    #[arg(long, default_value = "raysvao")]
    pub reference: String,
    /// Write the machine-readable report here.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write a self-contained HTML page with the images into this folder.
    #[arg(long)]
    pub html: Option<PathBuf>,
    /// Folder for the PNGs (AO, signed differences, refinement heatmap, ray intervals, SD
    /// layers); default: the --html folder, else `compare-out`.
    #[arg(long)]
    pub images: Option<PathBuf>,
}

/// Run the command.
pub fn run(args: CompareArgs) -> Result<(), String> {
    let names: Vec<&str> = args.techniques.split(',').map(str::trim).filter(|s| !s.is_empty()).collect();
    if names.is_empty() {
        return Err("--techniques is empty".into());
    }
    let mut techniques = args.options.techniques(&[&names[..], &[args.reference.as_str()]].concat())?;
    let reference = techniques.pop().expect("the reference is the last");
    let reference = aokit::technique::reference_at_full_resolution(reference, &args.reference);
    let (scene, frame) = resolve(&args.frame)?;
    aokit::technique::check_graphs(techniques.iter().chain([&reference]), &frame)?;
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
