//! `aokit-peers`: aokit's passes timed side by side with the reference implementations' own
//! shaders on the same device, same frame, same settings (docs/benchmarks.md, bench/PEERS.md).
//!
//! * `aokit-peers xegtao --spirv DIR`: aokit's gtao (High) against Intel's XeGTAO HLSL compiled
//!   to SPIR-V (DIR holds it; bench/peers/README.md says what it must contain), through ash on
//!   one Vulkan device.
//! * `aokit-peers bevy`: aokit's vbao against Bevy's visibility-bitmask SSAO WGSL, both through
//!   wgpu on one adapter.
//! * `aokit-peers executors`: aokit's two executors, `aokit-wgpu` and `aokit-vulkan` (ash), on
//!   the same techniques and frame.
//!
//! Each iteration runs both sides, alternating which goes first; every pass is timed with GPU
//! timestamps, and the table gives the median of the per-iteration ratios aokit / peer.

mod bevy;
mod common;
mod executors;
mod xegtao;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(name = "aokit-peers", about = "aokit vs the reference implementations' own shaders, same device")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// aokit's gtao against XeGTAO's HLSL (compiled to SPIR-V) on one Vulkan device.
    Xegtao(xegtao::XegtaoArgs),
    /// aokit's vbao against Bevy's visibility-bitmask SSAO WGSL through wgpu.
    Bevy(bevy::BevyArgs),
    /// The same techniques through aokit-wgpu and aokit-vulkan (ash) on one device.
    Executors(executors::ExecutorsArgs),
}

fn main() {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Xegtao(args) => xegtao::run(args),
        Command::Bevy(args) => bevy::run(args),
        Command::Executors(args) => executors::run(args),
    };
    if let Err(e) = result {
        eprintln!("aokit-peers: {e}");
        std::process::exit(1);
    }
}
