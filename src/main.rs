//! `aokit`: render ambient occlusion for a scene on the CPU or on Vulkan.

mod commands;

use clap::{Parser, Subcommand};
use commands::{bench, compare, export, frontier, info, path, render, scaling, web};
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
    Render(render::RenderArgs),
    /// Render several techniques on one G-buffer and compare them with a reference: MSE, PSNR,
    /// SSIM, rays, time per pass; optional JSON and HTML report.
    Compare(compare::CompareArgs),
    /// Time a technique over K frames after a warm-up: median/min/max per pass, Mpixel/s.
    Bench(bench::BenchArgs),
    /// The scaling study: the scene instanced 1, 4, 16, 64 times on a grid (same camera), per-pass
    /// times of VAO, Ray-SD and the raster SD map.
    Scaling(scaling::ScalingArgs),
    /// Write a frame's G-buffer (as engine images and in aokit's layout), camera and scene as plain
    /// files for consumers without Rust (formats: docs/export.md).
    Export(export::ExportArgs),
    /// Write a static WebGPU page (plain JS modules) that runs the screen-space techniques in a
    /// browser on the exported G-buffer, with cpu-sim's AO as its reference (docs/web.md).
    Web(web::WebArgs),
    /// Render a camera path (orbit or dolly) frame after frame, with and without temporal
    /// accumulation: temporal instability and MSE against the ground truth per technique, an
    /// animated PNG to look at (docs/temporal.md).
    Path(path::PathArgs),
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
    /// The quality–cost frontier: every technique at every preset against the 512-spp ground
    /// truth on several scenes (MSE, SSIM, FLIP, time), Pareto-optimal points marked; a table,
    /// JSON and a log–log plot per scene.
    Frontier(frontier::FrontierArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render(args) => render::run(args),
        Command::Compare(args) => compare::run(args),
        Command::Bench(args) => bench::run(args),
        Command::Scaling(args) => scaling::run(args),
        Command::Export(args) => export::run(args),
        Command::Web(args) => web::run(args),
        Command::Path(args) => path::run(args),
        Command::Tune(args) => aokit::tune::tune_command(args),
        Command::Frontier(args) => frontier::run(args),
        Command::Rays(args) => aokit::rays::rays_command(args),
        Command::Info { validation } => info::info(validation),
        Command::Techniques => info::techniques(),
        Command::Scenes => info::scenes(),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
