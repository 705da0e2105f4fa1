//! `aokit web`: the static WebGPU page of the screen-space techniques (docs/web.md).

use super::{FrameArgs, frame_gbuffer};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct WebArgs {
    #[command(flatten)]
    pub frame: FrameArgs,
    /// Folder to write the page into (created if missing); serve it over HTTP.
    #[arg(long)]
    pub out: PathBuf,
}

/// Run the command.
pub fn run(args: WebArgs) -> Result<(), String> {
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
