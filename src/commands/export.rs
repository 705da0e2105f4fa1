//! `aokit export`: a frame's G-buffer, camera and scene as plain files (docs/export.md).

use super::{FrameArgs, frame_gbuffer};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct ExportArgs {
    #[command(flatten)]
    pub frame: FrameArgs,
    /// Folder to write into (created if missing).
    #[arg(long)]
    pub out: PathBuf,
}

/// Run the command.
pub fn run(args: ExportArgs) -> Result<(), String> {
    let (scene, frame, gbuffer, backend) = frame_gbuffer(&args.frame, "export")?;
    let json = aokit::export::write(&args.out, &scene, &frame, &gbuffer, backend)
        .map_err(|e| format!("{}: {e}", args.out.display()))?;
    println!("{json}");
    Ok(())
}
