//! `aokit scaling`: per-pass times as the scene is instanced 1, 4, 16, 64 times on a grid.

use super::{FrameArgs, check_validation, renderer, resolve};
use aokit::cli::TechniqueArgs;
use aokit::report::BenchResult;
use aokit::technique::Describe;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct ScalingArgs {
    #[command(flatten)]
    pub frame: FrameArgs,
    #[command(flatten)]
    pub options: TechniqueArgs,
    /// Instance counts (squares).
    #[arg(long, default_value = "1,4,16,64")]
    pub copies: String,
    /// Techniques to time.
    #[arg(long, default_value = "vao,raysd,sdsvao")]
    pub techniques: String,
    /// Timed frames per point after one warm-up frame.
    #[arg(long, default_value_t = 3)]
    pub frames: u32,
    /// Write the results as JSON here.
    #[arg(long)]
    pub json: Option<PathBuf>,
}

/// Run the command.
pub fn run(args: ScalingArgs) -> Result<(), String> {
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
    aokit::technique::check_graphs(&techniques, &frame)?;
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
