//! `aokit frontier`: every technique at every preset against the 512-spp ground truth on several
//! scenes — MSE, SSIM, FLIP and time — with the Pareto-optimal points; a Markdown table, JSON and
//! one log–log plot per scene (`aokit::frontier`).

use super::progress_bar;
use aokit::cli::TechniqueArgs;
use aokit::frame::{CameraChoice, FrameRequest};
use aokit::frontier::{self, Candidate, Setup};
use aokit::render::VulkanRenderer;
use aokit::scene::builtin;
use aokit::tune::{Device, Metric, TuneSet, scene_views};
use aokit_shaders::graph::RtMode;
use aokit_vulkan::GpuOptions;
use std::path::PathBuf;
use std::time::Instant;

#[derive(clap::Args)]
#[command(allow_negative_numbers = true)]
pub struct FrontierArgs {
    #[command(flatten)]
    options: TechniqueArgs,
    /// Comma-separated scenes (built-in names or files); built-in scenes use all their camera
    /// presets.
    #[arg(long, default_value = "sponza,kitchen,oak")]
    scenes: String,
    /// Where the techniques run (the G-buffers and the references are cpu-sim's either way).
    #[arg(long, value_parser = ["cpu", "vulkan"], default_value = "cpu")]
    backend: String,
    /// Comma-separated techniques with optional `:key=value` settings, instead of every
    /// technique at every preset and the tuned settings.
    #[arg(long)]
    techniques: Option<String>,
    /// Leave out the settings `aokit tune` recommended (`aokit::frontier::TUNED`).
    #[arg(long)]
    no_tuned: bool,
    /// The reference technique, optionally with `:key=value` settings.
    #[arg(long, default_value = "groundtruth")]
    reference: String,
    /// Output width.
    #[arg(long, default_value_t = 960)]
    width: u32,
    /// Output height.
    #[arg(long, default_value_t = 540)]
    height: u32,
    /// G-buffer guard band in pixels on every side.
    #[arg(long, default_value_t = 64)]
    guard: u32,
    /// AO exponent (1: XeGTAO's protocol, docs/tuning.md "Which exponent").
    #[arg(long, default_value_t = 1.0)]
    exponent: f32,
    /// Timed frames per technique and camera (after one untimed frame); the median counts.
    #[arg(long, default_value_t = 3)]
    frames: usize,
    /// Folder for `frontier_<backend>.md`, `frontier_<backend>.json` and `<scene>_<backend>.svg`.
    #[arg(long, default_value = "frontier-out")]
    out: PathBuf,
    /// A line for the table's header (e.g. the commit and the machine).
    #[arg(long, default_value = "")]
    note: String,
    /// Neither read nor write the reference cache (`<aokit cache>/reference/`).
    #[arg(long)]
    no_cache: bool,
    /// Enable the Khronos validation layer (Vulkan); validation messages fail the run.
    #[arg(long)]
    validation: bool,
    /// How the Vulkan back-end runs ray-traced passes (pipeline or query).
    #[arg(long, value_parser = RtMode::NAMES)]
    rt_mode: Option<String>,
}

/// Run the command.
pub fn run(args: FrontierArgs) -> Result<(), String> {
    if args.frames == 0 {
        return Err("--frames must be at least 1".into());
    }
    let names: Vec<&str> = args.scenes.split(',').map(str::trim).filter(|s| !s.is_empty()).collect();
    if names.is_empty() {
        return Err("--scenes is empty".into());
    }
    if let Some(dup) = names.iter().enumerate().find(|(i, n)| names[..*i].contains(n)).map(|(_, n)| n) {
        return Err(format!("--scenes names {dup} twice"));
    }
    // Settings flags apply to the listed techniques and the reference together (as in `compare`);
    // the default list sets every preset itself, so it takes none.
    let (reference, candidates): (_, Vec<Candidate>) = match &args.techniques {
        Some(list) => {
            let specs: Vec<&str> = list.split(',').map(str::trim).filter(|s| !s.is_empty()).collect();
            if specs.is_empty() {
                return Err("--techniques is empty".into());
            }
            let mut techniques = args.options.techniques(&[&specs[..], &[args.reference.as_str()]].concat())?;
            let reference = techniques.pop().expect("the reference is the last");
            (
                reference,
                techniques.into_iter().map(|technique| Candidate { label: technique.label(), technique }).collect(),
            )
        }
        None => {
            if !args.options.given.0.is_empty() {
                return Err("settings flags need --techniques (the default list sets every preset itself); give the \
                            reference's settings as groundtruth:key=value"
                    .into());
            }
            let reference = args.options.technique(&args.reference)?;
            let candidates = frontier::candidates(reference.name(), !args.no_tuned)?;
            (reference, candidates)
        }
    };
    let device = match (args.backend.as_str(), &args.rt_mode) {
        ("cpu", Some(mode)) => {
            return Err(format!(
                "--rt-mode {mode} selects how the Vulkan back-end traces (--backend vulkan); cpu-sim traces through its BVH"
            ));
        }
        ("cpu", None) => Device::Cpu,
        _ => {
            let mode = args.rt_mode.as_deref().map(RtMode::parse).transpose()?.unwrap_or(RtMode::Pipeline);
            let v = VulkanRenderer::new(&GpuOptions { validation: args.validation, ..Default::default() })
                .map_err(|e| e.to_string())?;
            v.set_rt_mode(mode);
            Device::Vulkan(v)
        }
    };
    let request = FrameRequest {
        width: args.width,
        height: args.height,
        guard: args.guard,
        camera: CameraChoice::Auto { fov_deg: 60.0 },
        radius: None,
        exponent: args.exponent,
        thickness: 0.0,
    };
    let mut scenes = Vec::new();
    for name in &names {
        scenes.push(scene_views(name, &request)?);
    }
    let clock = Instant::now();
    let cache = (!args.no_cache).then(|| builtin::cache_dir().join("reference"));
    eprintln!(
        "preparing {} scene(s): cpu-sim G-buffers and {} references (a 512-spp reference takes about a minute per \
         camera at 960×540 on 2 cores; cached afterwards)",
        names.len(),
        reference.name()
    );
    let set =
        TuneSet::with_cpu_inputs(device, scenes, reference, Metric::Mse, cache, &mut |line| eprintln!("  {line}"))?;
    let bar = progress_bar(format!("{}: frontier", set.device.name()), (set.scenes.len() * candidates.len()) as u64);
    let result = frontier::measure(&set, &candidates, args.frames, &mut |scene, p| {
        bar.println(format!(
            "  {scene} {:<14} MSE {:.3e} SSIM {:.4} FLIP {:.4} {:>9.1} ms",
            p.label, p.mse, p.ssim, p.flip, p.ms
        ));
        bar.inc(1);
    });
    bar.finish_and_clear();
    let scenes = result?;
    let messages = set.device.validation_messages();
    if !messages.is_empty() {
        return Err(format!("validation layer reported {} message(s):\n{}", messages.len(), messages.join("\n")));
    }
    let setup = Setup {
        backend: set.device.name().to_string(),
        device: set.device.device_name(),
        width: args.width,
        height: args.height,
        guard: args.guard,
        exponent: args.exponent,
        reference: aokit::tune::spec(&set.reference),
        frames: args.frames,
        note: if args.note.is_empty() {
            format!("wall {:.0} s", clock.elapsed().as_secs_f64())
        } else {
            format!("{}; wall {:.0} s", args.note, clock.elapsed().as_secs_f64())
        },
    };
    std::fs::create_dir_all(&args.out).map_err(|e| format!("{}: {e}", args.out.display()))?;
    let write = |name: String, bytes: &[u8]| {
        let path = args.out.join(name);
        aokit::output::write_atomic_bytes(&path, bytes).map_err(|e| format!("{}: {e}", path.display()))
    };
    for scene in &scenes {
        if let Some(svg) = frontier::svg(scene, &setup.backend) {
            write(format!("{}_{}.svg", scene.scene, setup.backend), svg.as_bytes())?;
        }
    }
    let table = frontier::markdown(&setup, &scenes);
    write(format!("frontier_{}.md", setup.backend), table.as_bytes())?;
    let json = serde_json::to_string_pretty(&frontier::json(&setup, &scenes)).expect("serializable");
    write(format!("frontier_{}.json", setup.backend), json.as_bytes())?;
    print!("{table}");
    eprintln!("wrote {}/frontier_{}.md (.json, per-scene .svg)", args.out.display(), setup.backend);
    Ok(())
}
