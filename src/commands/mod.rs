//! The `aokit` commands, one module each; what they share: the scene, camera and back-end
//! arguments and the back-end they select.

pub mod bench;
pub mod compare;
pub mod export;
pub mod frontier;
pub mod info;
pub mod path;
pub mod render;
pub mod scaling;
pub mod web;

use aokit::cli::SceneArgs;
use aokit::frame::Frame;
use aokit::render::{CpuRenderer, Renderer, VulkanRenderer};
use aokit::scene::Scene;
use aokit_cpu::GBufferImage;
use aokit_shaders::graph::RtMode;
use aokit_vulkan::GpuOptions;
use clap::ValueEnum;
use indicatif::{ProgressBar, ProgressStyle};

/// Where the kernels run.
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum Backend {
    Cpu,
    Vulkan,
}

/// Scene, camera and AO parameters shared by every command.
#[derive(clap::Args)]
#[command(allow_negative_numbers = true)]
pub struct FrameArgs {
    #[command(flatten)]
    pub view: SceneArgs,
    #[arg(long, value_enum, default_value = "cpu")]
    pub backend: Backend,
    /// G-buffer guard band in pixels on every side.
    #[arg(long, default_value_t = 64)]
    pub guard: u32,
    /// Enable the Khronos validation layer (Vulkan back-end); validation messages fail the run.
    #[arg(long)]
    pub validation: bool,
    /// How the Vulkan back-end runs ray-traced passes: ray-tracing pipelines (raygen, miss,
    /// any-hit; default) or compute kernels with ray queries (VK_KHR_ray_query).
    #[arg(long, value_parser = RtMode::NAMES)]
    pub rt_mode: Option<String>,
}

/// Load the scene and resolve the camera and AO parameters.
pub fn resolve(args: &FrameArgs) -> Result<(Scene, Frame), String> {
    args.view.resolve(args.guard)
}

/// The back-end the user picked.
pub fn renderer(args: &FrameArgs, scene: &Scene) -> Result<Renderer, String> {
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
pub fn rt_mode(args: &FrameArgs) -> Result<RtMode, String> {
    match (&args.rt_mode, args.backend) {
        (None, _) => Ok(RtMode::Pipeline),
        (Some(mode), Backend::Vulkan) => RtMode::parse(mode),
        (Some(mode), Backend::Cpu) => Err(format!(
            "--rt-mode {mode} selects how the Vulkan back-end traces (--backend vulkan); cpu-sim traces through its BVH"
        )),
    }
}

/// Fail when the validation layer said anything.
pub fn check_validation(renderer: &Renderer) -> Result<(), String> {
    let messages = renderer.validation_messages();
    if messages.is_empty() {
        return Ok(());
    }
    Err(format!("validation layer reported {} message(s):\n{}", messages.len(), messages.join("\n")))
}

/// A progress bar over G-buffer and pass rows (CPU back-end).
pub fn progress_bar(message: String, rows: u64) -> ProgressBar {
    let bar = ProgressBar::new(rows).with_style(
        ProgressStyle::with_template("{spinner} {msg} [{bar:40}] {pos}/{len} rows ({eta})").expect("valid template"),
    );
    bar.set_message(message);
    bar
}

/// The frame and its G-buffer on the chosen back-end, for commands that write them out (export,
/// web); `command` names the command in the `--rt-mode` refusal.
pub fn frame_gbuffer(args: &FrameArgs, command: &str) -> Result<(Scene, Frame, GBufferImage, &'static str), String> {
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
