//! `aokit`: render ambient occlusion for a scene on the CPU or on Vulkan.

use aokit::frame::{CameraChoice, Frame, FrameRequest};
use aokit::output::{crop_inner, write_exr, write_png};
use aokit::render::{CpuRenderer, Render, VulkanRenderer};
use aokit::scene::Scene;
use aokit::scene::builtin::{self, BuiltinScene};
use aokit_shaders::glam::Vec3;
use aokit_shaders::groundtruth::GroundTruthParams;
use aokit_vulkan::GpuOptions;
use clap::{Parser, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::{Path, PathBuf};
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
    /// Print the Vulkan device aokit would use and its ray-tracing extensions.
    Info {
        /// Enable the Khronos validation layer.
        #[arg(long)]
        validation: bool,
    },
    /// List the built-in scenes and their camera presets.
    Scenes,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum Backend {
    Cpu,
    Vulkan,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum Technique {
    /// Volumetric AO on a single depth layer (spec svao-raysd §4–§5) + bilateral blur.
    Vao,
    /// World-space ray-traced AO, cosine-weighted, `--spp` rays per pixel (the reference).
    #[value(name = "groundtruth")]
    GroundTruth,
}

fn parse_vec3(s: &str) -> Result<Vec3, String> {
    let parts: Vec<f32> =
        s.split(',').map(|p| p.trim().parse::<f32>().map_err(|e| format!("'{p}': {e}"))).collect::<Result<_, _>>()?;
    match parts[..] {
        [x, y, z] => Ok(Vec3::new(x, y, z)),
        _ => Err(format!("expected x,y,z, got '{s}'")),
    }
}

#[derive(clap::Args)]
#[command(allow_negative_numbers = true)]
struct RenderArgs {
    /// Built-in scene name (see `aokit scenes`) or a path to .obj/.gltf/.glb/.ply[.gz].
    #[arg(long)]
    scene: String,
    #[arg(long, value_enum, default_value = "vao")]
    technique: Technique,
    #[arg(long, value_enum, default_value = "cpu")]
    backend: Backend,
    /// Output width in pixels (the guard band is added around it).
    #[arg(long, default_value_t = 1920)]
    width: u32,
    #[arg(long, default_value_t = 1080)]
    height: u32,
    /// G-buffer guard band in pixels on every side.
    #[arg(long, default_value_t = 64)]
    guard: u32,
    /// Camera preset of a built-in scene, or `auto` to frame the scene's bounds.
    #[arg(long)]
    camera: Option<String>,
    /// Explicit camera position (x,y,z); needs --target.
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true, requires = "target")]
    eye: Option<Vec3>,
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true, requires = "eye")]
    target: Option<Vec3>,
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true, default_value = "0,1,0")]
    up: Vec3,
    /// Vertical field of view of the output image in degrees.
    #[arg(long)]
    fov: Option<f32>,
    /// World-space AO radius (default: per built-in scene, else 2 % of the bounding-box diagonal).
    #[arg(long)]
    radius: Option<f32>,
    /// AO exponent (spec default 2; the papers' figures use 4).
    #[arg(long, default_value_t = 2.0)]
    exponent: f32,
    /// Halo thickness τ (spec §4.3).
    #[arg(long, default_value_t = 0.0)]
    thickness: f32,
    /// Rays per pixel of `--technique groundtruth`.
    #[arg(long, default_value_t = 512)]
    spp: u32,
    /// Ground truth with uniform instead of cosine-weighted hemisphere sampling.
    #[arg(long)]
    uniform: bool,
    /// Skip the bilateral blur.
    #[arg(long)]
    no_blur: bool,
    /// Output PNG (8-bit grey, 1 = unoccluded = white).
    #[arg(long, default_value = "ao.png")]
    out: PathBuf,
    /// Also write the raw float AO as OpenEXR.
    #[arg(long)]
    exr: Option<PathBuf>,
    /// Enable the Khronos validation layer (Vulkan back-end); validation messages fail the run.
    #[arg(long)]
    validation: bool,
}

fn load_scene(spec: &str) -> Result<(Scene, Option<&'static BuiltinScene>), String> {
    if let Some(b) = builtin::find(spec) {
        return Ok((b.load().map_err(|e| e.to_string())?, Some(b)));
    }
    let path = Path::new(spec);
    if !path.exists() {
        let names: Vec<_> = builtin::builtin_scenes().iter().map(|s| s.name).collect();
        return Err(format!("'{spec}' is neither a built-in scene ({}) nor an existing file", names.join(", ")));
    }
    Ok((Scene::load(path).map_err(|e| e.to_string())?, None))
}

fn render(args: RenderArgs) -> Result<(), String> {
    let (scene, builtin) = load_scene(&args.scene)?;
    let fov_default = builtin.map_or(60.0, |b| b.cameras[0].fov_deg);
    let camera = match (&args.eye, &args.target, args.camera.as_deref()) {
        (Some(eye), Some(target), _) => {
            CameraChoice::Explicit { eye: *eye, target: *target, up: args.up, fov_deg: args.fov.unwrap_or(fov_default) }
        }
        (_, _, Some("auto")) => CameraChoice::Auto { fov_deg: args.fov.unwrap_or(60.0) },
        (_, _, None) if builtin.is_none() => CameraChoice::Auto { fov_deg: args.fov.unwrap_or(60.0) },
        (_, _, name) => CameraChoice::Preset { name: name.map(str::to_string), fov_deg: args.fov },
    };
    let request = FrameRequest {
        width: args.width,
        height: args.height,
        guard: args.guard,
        camera,
        radius: args.radius,
        exponent: args.exponent,
        thickness: args.thickness,
    };
    let frame = Frame::resolve(&scene, builtin, &request).map_err(|e| e.to_string())?;
    if args.technique == Technique::GroundTruth && args.spp == 0 {
        return Err("--spp must be at least 1".into());
    }
    let gt_params = GroundTruthParams {
        radius: frame.radius,
        exponent: frame.exponent,
        samples: args.spp,
        uniform: args.uniform as u32,
    };
    let (result, device) = match args.backend {
        Backend::Cpu => {
            let renderer = CpuRenderer::new(&scene);
            let rows = frame.camera.view.size().y as u64 + frame.inner.y as u64;
            let bar = ProgressBar::new(rows).with_style(
                ProgressStyle::with_template("{spinner} {msg} [{bar:40}] {pos}/{len} rows ({eta})")
                    .expect("valid template"),
            );
            let r = match args.technique {
                Technique::Vao => {
                    bar.set_message("CPU G-buffer + VAO");
                    renderer.render(&frame, &|n| bar.inc(n))
                }
                Technique::GroundTruth => {
                    bar.set_message(format!("CPU G-buffer + ground truth, {} spp", args.spp));
                    let (gbuffer, gbuffer_ms) = renderer.gbuffer(&frame, &|n| bar.inc(n));
                    let (ao, ms) = renderer.ground_truth(&frame, &gbuffer, &gt_params, &|n| bar.inc(n));
                    let passes = vec![("gbuffer", gbuffer_ms), ("groundtruth", ms)];
                    Render::unblurred(gbuffer, ao, passes)
                }
            };
            bar.finish_and_clear();
            (r, "cpu".to_string())
        }
        Backend::Vulkan => {
            let renderer =
                VulkanRenderer::new(&GpuOptions { validation: args.validation }).map_err(|e| e.to_string())?;
            let r = match args.technique {
                Technique::Vao => renderer.render(&scene, &frame).map_err(|e| e.to_string())?,
                Technique::GroundTruth => {
                    let (gbuffer, gbuffer_ms) = renderer.gbuffer(&scene, &frame).map_err(|e| e.to_string())?;
                    let (ao, mut passes) =
                        renderer.ground_truth(&scene, &frame, &gbuffer, &gt_params).map_err(|e| e.to_string())?;
                    passes.insert(0, ("gbuffer", gbuffer_ms));
                    Render::unblurred(gbuffer, ao, passes)
                }
            };
            let messages = renderer.gpu.validation_messages();
            if !messages.is_empty() {
                return Err(format!(
                    "validation layer reported {} message(s):\n{}",
                    messages.len(),
                    messages.join("\n")
                ));
            }
            (r, renderer.gpu.info().name.clone())
        }
    };
    let view = frame.camera.view;
    let full = if args.no_blur { &result.ao } else { &result.ao_blurred };
    let ao = crop_inner(&view, full);
    write_png(&args.out, frame.inner.x, frame.inner.y, &ao).map_err(|e| format!("{}: {e}", args.out.display()))?;
    if let Some(exr) = &args.exr {
        write_exr(exr, frame.inner.x, frame.inner.y, &ao).map_err(|e| format!("{}: {e}", exr.display()))?;
    }
    let mut line = frame.describe();
    line["scene"] = scene.name.clone().into();
    line["triangles"] = scene.triangles.len().into();
    line["technique"] = args.technique.to_possible_value().expect("named").get_name().into();
    if args.technique == Technique::GroundTruth {
        line["spp"] = args.spp.into();
    }
    line["backend"] = format!("{:?}", args.backend).to_lowercase().into();
    line["device"] = device.into();
    line["passes_ms"] =
        result.passes.iter().map(|(n, ms)| serde_json::json!({"name": n, "ms": ms})).collect::<Vec<_>>().into();
    line["mean_ao"] = (ao.iter().map(|&a| a as f64).sum::<f64>() / ao.len() as f64).into();
    line["out"] = args.out.display().to_string().into();
    println!("{line}");
    Ok(())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render(args) => render(args),
        Command::Info { validation } => {
            aokit_vulkan::Gpu::new(&GpuOptions { validation }).map_err(|e| e.to_string()).map(|gpu| {
                let info = gpu.info();
                println!("{}", serde_json::to_string(info).expect("serializable"));
                eprintln!("device: {} ({}, Vulkan {})", info.name, info.device_type, info.api_version);
                for (ext, has) in &info.ray_tracing_extensions {
                    eprintln!("  {ext}: {}", if *has { "yes" } else { "no" });
                }
            })
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
