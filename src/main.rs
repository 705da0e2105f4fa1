//! `aokit`: render ambient occlusion for a scene on the CPU or on Vulkan.

use aokit::cli::SceneArgs;
use aokit::frame::Frame;
use aokit::output::{crop_inner, write_exr, write_png};
use aokit::render::{CpuRenderer, Renderer, VulkanRenderer};
use aokit::report::{BenchResult, CompareReport, CompareSetup};
use aokit::scene::Scene;
use aokit::scene::builtin;
use aokit::technique::{
    GroundTruthSettings, GtaoOptions, GtaoPreset, HybridOptions, RaymarchOptions, SdOptions, Technique,
    TechniqueDefaults,
};
use aokit_shaders::common::tables::JitterTable;
use aokit_vulkan::GpuOptions;
use clap::{Parser, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;
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
    /// Render several techniques on one G-buffer and compare them with a reference: MSE, PSNR,
    /// SSIM, rays, time per pass; optional JSON and HTML report.
    Compare(CompareArgs),
    /// Time a technique over K frames after a warm-up: median/min/max per pass, Mpixel/s.
    Bench(BenchArgs),
    /// The scaling study: the scene instanced 1, 4, 16, 64 times on a grid (same camera), per-pass
    /// times of VAO, Ray-SD and the raster SD map.
    Scaling(ScalingArgs),
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
enum SdRes {
    Full,
    Half,
    Quarter,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum Jitter {
    /// The reference's HEAD table (spec §7.2).
    Scrambled,
    /// The paper-era stratum-centre table.
    Paper,
}

/// Scene, camera and AO parameters shared by every command.
#[derive(clap::Args)]
#[command(allow_negative_numbers = true)]
struct FrameArgs {
    #[command(flatten)]
    view: SceneArgs,
    #[arg(long, value_enum, default_value = "cpu")]
    backend: Backend,
    /// G-buffer guard band in pixels on every side.
    #[arg(long, default_value_t = 64)]
    guard: u32,
    /// Enable the Khronos validation layer (Vulkan back-end); validation messages fail the run.
    #[arg(long)]
    validation: bool,
}

/// Options of the techniques (each applies to the techniques that have it); the numeric defaults
/// are the settings types' own (`Default` beside the kernels).
#[derive(clap::Args)]
struct TechniqueArgs {
    /// Ray-SD map resolution.
    #[arg(long, value_enum, default_value = "quarter")]
    sd_res: SdRes,
    /// Ray-SD layers N (1, 2, 4, 8).
    #[arg(long, default_value_t = SdOptions::default().layers)]
    sd_layers: u32,
    /// Reservoir MAX_COUNT (raised to N when smaller).
    #[arg(long, default_value_t = SdOptions::default().max_count)]
    max_count: u32,
    /// Radius cutoff in pixels: closer samples are never refined (raysd, raysvao).
    #[arg(long, default_value_t = SdOptions::default().cutoff)]
    cutoff: f32,
    /// Trace every SD texel over its full range (no ray-interval optimisation).
    #[arg(long)]
    no_interval: bool,
    /// SD rays through texel centres.
    #[arg(long)]
    no_jitter: bool,
    /// SD jitter table.
    #[arg(long, value_enum, default_value = "scrambled")]
    jitter: Jitter,
    /// SD guard band in full-resolution pixels.
    #[arg(long, default_value_t = SdOptions::default().guard)]
    sd_guard: u32,
    /// Primary depth of vao/raysd/raysvao: the depth buffer, or dual depth (plus a depth-peeled
    /// second layer, spec §11).
    #[arg(long, value_enum, default_value = "single")]
    primary: Primary,
    /// Minimum separation of the peeled second layer (world units).
    #[arg(long, default_value_t = SdOptions::default().peel_separation)]
    peel_separation: f32,
    /// SD map of raysd: ray-traced, or the raster coverage-mask baseline (= --technique sdsvao).
    #[arg(long, value_enum, default_value = "ray")]
    sd_source: SdSource,
    /// AO kernel of vao/raysd: VAO's halo model or HBAO+ (radius × 1.5, spec §4.5).
    #[arg(long, value_enum, default_value = "vao")]
    kernel: Kernel,
    /// Rays per pixel of the ground truth.
    #[arg(long, default_value_t = GroundTruthSettings::default().spp)]
    spp: u32,
    /// Ground truth with uniform instead of cosine-weighted hemisphere sampling.
    #[arg(long)]
    uniform: bool,
    /// XeGTAO quality preset: slices × steps per side 1×2, 2×2, 3×3, 9×3.
    #[arg(long, value_enum, default_value = "high")]
    preset: Preset,
    /// XeGTAO denoise passes (0 off, 1 sharp, 2 medium, 3 soft).
    #[arg(long, default_value_t = GtaoOptions::default().denoise_passes)]
    gtao_denoise: u32,
    /// XeGTAO RadiusMultiplier (effective radius = --radius × this).
    #[arg(long, default_value_t = GtaoOptions::default().radius_multiplier)]
    gtao_radius_multiplier: f32,
    /// XeGTAO FalloffRange (fraction of the radius over which samples fade).
    #[arg(long, default_value_t = GtaoOptions::default().falloff_range)]
    gtao_falloff_range: f32,
    /// XeGTAO SampleDistributionPower.
    #[arg(long, default_value_t = GtaoOptions::default().sample_distribution_power)]
    gtao_sample_power: f32,
    /// XeGTAO ThinOccluderCompensation.
    #[arg(long, default_value_t = GtaoOptions::default().thin_occluder_compensation)]
    gtao_thin_occluder: f32,
    /// XeGTAO FinalValuePower.
    #[arg(long, default_value_t = GtaoOptions::default().final_value_power)]
    gtao_final_power: f32,
    /// XeGTAO DepthMIPSamplingOffset.
    #[arg(long, default_value_t = GtaoOptions::default().depth_mip_sampling_offset)]
    gtao_mip_offset: f32,
    /// XeGTAO normals: the G-buffer's, or derived from depth (pass 0).
    #[arg(long, value_enum, default_value = "gbuffer")]
    gtao_normals: GtaoNormals,
    /// Ray-marched SSAO: directions N (the paper uses 8, 16, 24).
    #[arg(long, default_value_t = RaymarchOptions::default().directions)]
    rm_directions: u32,
    /// Ray-marched SSAO: steps per direction.
    #[arg(long, default_value_t = RaymarchOptions::default().steps)]
    rm_steps: u32,
    /// Ray-marched SSAO: contrast exponent α of Eq. 2.
    #[arg(long, default_value_t = RaymarchOptions::default().alpha)]
    rm_alpha: f32,
    /// Ray-marched SSAO: reading of Eq. 2 (linear: visible distance / R; binary: 0 on a hit).
    #[arg(long, value_enum, default_value = "linear")]
    rm_contribution: RmContribution,
    /// Ray-marched SSAO: Vogel spiral instead of the best-candidate Poisson disk.
    #[arg(long)]
    rm_vogel: bool,
    /// Ray-marched SSAO: XeGTAO denoise passes afterwards.
    #[arg(long, default_value_t = RaymarchOptions::default().denoise_passes)]
    rm_denoise: u32,
    /// Hybrid AO: mixed (1 screen + 1 world ray), world (2 world rays), screen (2 screen rays).
    #[arg(long, value_enum, default_value = "mixed")]
    hybrid_variant: HybridVariant,
    /// Hybrid AO: weight of the world rays (default 2/3 for mixed).
    #[arg(long)]
    world_weight: Option<f32>,
    /// Hybrid AO: XeGTAO denoise passes afterwards.
    #[arg(long, default_value_t = HybridOptions::default().denoise_passes)]
    hybrid_denoise: u32,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum SdSource {
    Ray,
    Raster,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum Kernel {
    Vao,
    Hbao,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum Primary {
    Single,
    Dual,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum RmContribution {
    Linear,
    Binary,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum HybridVariant {
    Mixed,
    World,
    Screen,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum Preset {
    Low,
    Medium,
    High,
    Ultra,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
enum GtaoNormals {
    Gbuffer,
    Depth,
}

impl TechniqueArgs {
    fn gtao_options(&self) -> GtaoOptions {
        GtaoOptions {
            quality: match self.preset {
                Preset::Low => GtaoPreset::Low,
                Preset::Medium => GtaoPreset::Medium,
                Preset::High => GtaoPreset::High,
                Preset::Ultra => GtaoPreset::Ultra,
            },
            denoise_passes: self.gtao_denoise,
            radius_multiplier: self.gtao_radius_multiplier,
            falloff_range: self.gtao_falloff_range,
            sample_distribution_power: self.gtao_sample_power,
            thin_occluder_compensation: self.gtao_thin_occluder,
            final_value_power: self.gtao_final_power,
            depth_mip_sampling_offset: self.gtao_mip_offset,
            normals_from_depth: self.gtao_normals == GtaoNormals::Depth,
        }
    }

    fn sd_options(&self) -> Result<SdOptions, String> {
        let o = SdOptions {
            divisor: match self.sd_res {
                SdRes::Full => 1,
                SdRes::Half => 2,
                SdRes::Quarter => 4,
            },
            layers: self.sd_layers,
            max_count: self.max_count,
            cutoff: self.cutoff,
            interval: !self.no_interval,
            jitter: match (self.no_jitter, self.jitter) {
                (true, _) => JitterTable::None,
                (false, Jitter::Scrambled) => JitterTable::Scrambled,
                (false, Jitter::Paper) => JitterTable::Paper,
            },
            guard: self.sd_guard,
            dual: self.primary == Primary::Dual,
            peel_separation: self.peel_separation,
            hbao: self.kernel == Kernel::Hbao,
            raster: self.sd_source == SdSource::Raster,
        };
        o.validate()?;
        if self.spp == 0 {
            return Err("--spp must be at least 1".into());
        }
        Ok(o)
    }

    fn technique(&self, name: &str) -> Result<Technique, String> {
        let variant = match self.hybrid_variant {
            HybridVariant::Mixed => "mixed",
            HybridVariant::World => "world",
            HybridVariant::Screen => "screen",
        };
        let mut hybrid = HybridOptions { denoise_passes: self.hybrid_denoise, ..HybridOptions::variant(variant)? };
        if let Some(w) = self.world_weight {
            hybrid.world_weight = w;
        }
        let defaults = TechniqueDefaults {
            sd: self.sd_options()?,
            gtao: self.gtao_options(),
            raymarch: RaymarchOptions {
                directions: self.rm_directions,
                steps: self.rm_steps,
                alpha: self.rm_alpha,
                binary: self.rm_contribution == RmContribution::Binary,
                vogel: self.rm_vogel,
                denoise_passes: self.rm_denoise,
            },
            hybrid,
            spp: self.spp,
            uniform: self.uniform,
        };
        Technique::parse(name, &defaults)
    }
}

#[derive(clap::Args)]
struct RenderArgs {
    #[command(flatten)]
    frame: FrameArgs,
    #[command(flatten)]
    options: TechniqueArgs,
    /// vao, hbao, raysd, hbao-sd, sdsvao, raysvao, gtao, raymarch, hybrid or groundtruth.
    #[arg(long, default_value = "vao")]
    technique: String,
    /// Skip the bilateral blur.
    #[arg(long)]
    no_blur: bool,
    /// Output PNG (8-bit grey, 1 = unoccluded = white).
    #[arg(long, default_value = "ao.png")]
    out: PathBuf,
    /// Also write the raw float AO as OpenEXR.
    #[arg(long)]
    exr: Option<PathBuf>,
}

#[derive(clap::Args)]
struct CompareArgs {
    #[command(flatten)]
    frame: FrameArgs,
    #[command(flatten)]
    options: TechniqueArgs,
    /// Comma-separated techniques to compare.
    #[arg(long, default_value = "vao,raysd,raysvao")]
    techniques: String,
    /// The reference technique (raysvao or groundtruth).
    #[arg(long, default_value = "raysvao")]
    reference: String,
    /// Write the machine-readable report here.
    #[arg(long)]
    json: Option<PathBuf>,
    /// Write a self-contained HTML page with the images into this folder.
    #[arg(long)]
    html: Option<PathBuf>,
    /// Folder for the PNGs (AO, signed differences, refinement heatmap, ray intervals, SD
    /// layers); default: the --html folder, else `compare-out`.
    #[arg(long)]
    images: Option<PathBuf>,
}

#[derive(clap::Args)]
struct BenchArgs {
    #[command(flatten)]
    frame: FrameArgs,
    #[command(flatten)]
    options: TechniqueArgs,
    #[arg(long, default_value = "vao")]
    technique: String,
    /// Timed frames after the warm-up.
    #[arg(long, default_value_t = 10)]
    frames: u32,
    /// Untimed warm-up frames.
    #[arg(long, default_value_t = 2)]
    warmup: u32,
    /// Write the results as JSON here.
    #[arg(long)]
    json: Option<PathBuf>,
}

#[derive(clap::Args)]
struct ScalingArgs {
    #[command(flatten)]
    frame: FrameArgs,
    #[command(flatten)]
    options: TechniqueArgs,
    /// Instance counts (squares).
    #[arg(long, default_value = "1,4,16,64")]
    copies: String,
    /// Techniques to time.
    #[arg(long, default_value = "vao,raysd,sdsvao")]
    techniques: String,
    /// Timed frames per point after one warm-up frame.
    #[arg(long, default_value_t = 3)]
    frames: u32,
    /// Write the results as JSON here.
    #[arg(long)]
    json: Option<PathBuf>,
}

/// Load the scene and resolve the camera and AO parameters.
fn resolve(args: &FrameArgs) -> Result<(Scene, Frame), String> {
    args.view.resolve(args.guard)
}

/// The back-end the user picked.
fn renderer(args: &FrameArgs, scene: &Scene) -> Result<Renderer, String> {
    match args.backend {
        Backend::Cpu => Ok(Renderer::Cpu(CpuRenderer::new(scene))),
        Backend::Vulkan => Ok(Renderer::Vulkan(
            VulkanRenderer::new(&GpuOptions { validation: args.validation }).map_err(|e| e.to_string())?,
        )),
    }
}

/// Fail when the validation layer said anything.
fn check_validation(renderer: &Renderer) -> Result<(), String> {
    let messages = renderer.validation_messages();
    if messages.is_empty() {
        return Ok(());
    }
    Err(format!("validation layer reported {} message(s):\n{}", messages.len(), messages.join("\n")))
}

/// A progress bar over G-buffer and pass rows (CPU back-end).
fn progress_bar(message: String, rows: u64) -> ProgressBar {
    let bar = ProgressBar::new(rows).with_style(
        ProgressStyle::with_template("{spinner} {msg} [{bar:40}] {pos}/{len} rows ({eta})").expect("valid template"),
    );
    bar.set_message(message);
    bar
}

fn passes_json(passes: &[(&str, f64)]) -> serde_json::Value {
    passes.iter().map(|(n, ms)| serde_json::json!({"name": n, "ms": ms})).collect::<Vec<_>>().into()
}

fn render(args: RenderArgs) -> Result<(), String> {
    let technique = args.options.technique(&args.technique)?;
    let (scene, frame) = resolve(&args.frame)?;
    let renderer = renderer(&args.frame, &scene)?;
    let rows = 2 * frame.camera.view.size().y as u64;
    let bar = progress_bar(format!("{} G-buffer + {}", renderer.backend_name(), technique.name()), rows);
    let progress = |n| bar.inc(n);
    let (run, _) = renderer.frame(&scene, &frame, &technique, &progress, true).map_err(|e| e.to_string())?;
    bar.finish_and_clear();
    check_validation(&renderer)?;
    let view = frame.camera.view;
    let full = if args.no_blur { &run.ao } else { &run.ao_final };
    let ao = crop_inner(&view, full);
    write_png(&args.out, frame.inner.x, frame.inner.y, &ao).map_err(|e| format!("{}: {e}", args.out.display()))?;
    if let Some(exr) = &args.exr {
        write_exr(exr, frame.inner.x, frame.inner.y, &ao).map_err(|e| format!("{}: {e}", exr.display()))?;
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
    println!("{line}");
    Ok(())
}

fn compare(args: CompareArgs) -> Result<(), String> {
    let names: Vec<&str> = args.techniques.split(',').map(str::trim).filter(|s| !s.is_empty()).collect();
    if names.is_empty() {
        return Err("--techniques is empty".into());
    }
    let techniques = names.iter().map(|n| args.options.technique(n)).collect::<Result<Vec<_>, _>>()?;
    let reference = args.options.technique(&args.reference)?;
    let (scene, frame) = resolve(&args.frame)?;
    let renderer = renderer(&args.frame, &scene)?;
    let rows = frame.camera.view.size().y as u64 * (2 + techniques.len() as u64);
    let bar = progress_bar(format!("{}: compare on {}", renderer.backend_name(), scene.name), rows);
    let progress = |n| bar.inc(n);
    let (gbuffer, gbuffer_ms) = renderer.gbuffer(&scene, &frame, &progress).map_err(|e| e.to_string())?;
    let reference_run = renderer.run(&scene, &frame, &gbuffer, &reference, &progress).map_err(|e| e.to_string())?;
    let mut runs = Vec::new();
    for t in &techniques {
        runs.push((*t, renderer.run(&scene, &frame, &gbuffer, t, &progress).map_err(|e| e.to_string())?));
    }
    bar.finish_and_clear();
    check_validation(&renderer)?;
    let device = renderer.device_name();
    let setup = CompareSetup { scene: &scene.name, backend: renderer.backend_name(), device: &device, gbuffer_ms };
    let report = CompareReport::new(setup, &frame, (reference, &reference_run), &runs, &args.options.sd_options()?);
    println!("{}", report.table());
    if let Some(path) = &args.json {
        std::fs::write(path, serde_json::to_string_pretty(&report.json()).expect("serializable"))
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    let images = args.images.clone().or(args.html.clone()).unwrap_or_else(|| PathBuf::from("compare-out"));
    report.write_images(&images, &frame, &gbuffer).map_err(|e| format!("{}: {e}", images.display()))?;
    if let Some(dir) = &args.html {
        let page = report.write_html(dir, &images).map_err(|e| format!("{}: {e}", dir.display()))?;
        eprintln!("wrote {}", page.display());
    }
    Ok(())
}

fn bench(args: BenchArgs) -> Result<(), String> {
    if args.frames == 0 {
        return Err("--frames must be at least 1".into());
    }
    let technique = args.options.technique(&args.technique)?;
    let (scene, frame) = resolve(&args.frame)?;
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
        std::fs::write(path, serde_json::to_string_pretty(&json).expect("serializable"))
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(())
}

fn scaling(args: ScalingArgs) -> Result<(), String> {
    let copies: Vec<u32> = args
        .copies
        .split(',')
        .map(|c| c.trim().parse::<u32>().map_err(|e| format!("--copies '{c}': {e}")))
        .collect::<Result<_, _>>()?;
    let techniques = args.techniques.split(',').map(|n| args.options.technique(n)).collect::<Result<Vec<_>, _>>()?;
    if args.frames == 0 {
        return Err("--frames must be at least 1".into());
    }
    let (scene, frame) = resolve(&args.frame)?;
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
            println!(
                "{k:>6} {:>10} {:<10} {total:>10.1}  {}",
                big.triangles.len(),
                t.label(&SdOptions::default()),
                passes.join(", ")
            );
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
        std::fs::write(path, serde_json::to_string_pretty(&json).expect("serializable"))
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render(args) => render(args),
        Command::Compare(args) => compare(args),
        Command::Bench(args) => bench(args),
        Command::Scaling(args) => scaling(args),
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
