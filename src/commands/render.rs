//! `aokit render`: one AO image of a scene (PNG, optionally EXR and bent normals) and a JSON line
//! describing the run.

use super::{FrameArgs, check_validation, progress_bar, renderer, resolve};
use aokit::cli::TechniqueArgs;
use aokit::output::{crop_inner, write_bent_png, write_exr, write_png};
use aokit::technique::Describe;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct RenderArgs {
    #[command(flatten)]
    pub frame: FrameArgs,
    #[command(flatten)]
    pub options: TechniqueArgs,
    /// A technique of `aokit techniques`, optionally with `:key=value` settings.
    #[arg(long, default_value = "vao")]
    pub technique: String,
    /// Skip the bilateral blur.
    #[arg(long)]
    pub no_blur: bool,
    /// Output PNG (8-bit grey, 1 = unoccluded = white).
    #[arg(long, default_value = "ao.png")]
    pub out: PathBuf,
    /// Also write the raw float AO as OpenEXR.
    #[arg(long)]
    pub exr: Option<PathBuf>,
    /// Also write the bent normals (RGB PNG: rgb = view-space normal ·0.5 + 0.5; needs a
    /// technique that outputs them: gtao with --gtao-bent-normals on).
    #[arg(long, value_name = "PNG")]
    pub bent_out: Option<PathBuf>,
}

/// Run the command.
pub fn run(args: RenderArgs) -> Result<(), String> {
    let technique = args.options.technique(&args.technique)?;
    let (scene, frame) = resolve(&args.frame)?;
    aokit::technique::check_graphs([&technique], &frame)?;
    if technique.resolution() != aokit_shaders::technique::Resolution::Full {
        // Half resolution keeps only the upsampled final AO (docs/algorithms/half-resolution.md §1).
        if args.no_blur {
            return Err("--no-blur: at half resolution only the upsampled final AO exists".into());
        }
        if args.bent_out.is_some() {
            return Err("--bent-out: at half resolution the technique's bent normals are not upsampled".into());
        }
    }
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

/// `(pass, ms)` as the JSON line's `passes_ms`.
fn passes_json(passes: &[(&str, f64)]) -> serde_json::Value {
    passes.iter().map(|(n, ms)| serde_json::json!({"name": n, "ms": ms})).collect::<Vec<_>>().into()
}
