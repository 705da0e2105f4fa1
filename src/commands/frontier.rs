//! `aokit frontier`: every technique at every preset against the 512-spp ground truth on several
//! scenes — MSE, SSIM, FLIP and time — with the Pareto-optimal points; a Markdown table, JSON and
//! one log–log plot per scene (`aokit::frontier`).

use super::progress_bar;
use aokit::cli::TechniqueArgs;
use aokit::frontier::{self, Candidate, Setup};
use aokit::tune::{DeviceArgs, Inputs, Metric, TuneSet, load_scenes, scene_names};
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
    #[command(flatten)]
    device: DeviceArgs,
    /// Comma-separated techniques with optional `:key=value` settings, instead of every
    /// technique at every preset and the tuned settings.
    #[arg(long)]
    techniques: Option<String>,
    /// Leave out the settings `aokit tune` recommended (`aokit::frontier::TUNED`) from the
    /// default list.
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
}

/// Run the command.
pub fn run(args: FrontierArgs) -> Result<(), String> {
    if args.frames == 0 {
        return Err("--frames must be at least 1".into());
    }
    let names = scene_names(&args.scenes)?;
    // Settings flags apply to the listed techniques and the reference together (as in `compare`);
    // the default list sets every preset itself, so it takes none.
    let (reference, candidates, described) = match &args.techniques {
        Some(_) if args.no_tuned => return Err("--no-tuned applies to the default list, not to --techniques".into()),
        Some(list) => {
            let specs: Vec<&str> = list.split(',').map(str::trim).filter(|s| !s.is_empty()).collect();
            if specs.is_empty() {
                return Err("--techniques is empty".into());
            }
            let mut techniques = args.options.techniques(&[&specs[..], &[args.reference.as_str()]].concat())?;
            let reference = techniques.pop().expect("the reference is the last");
            let reference = aokit::technique::reference_at_full_resolution(reference, &args.reference);
            (reference, Candidate::labelled(techniques), format!("the techniques `{}`", specs.join(",")))
        }
        None => {
            if !args.options.given.0.is_empty() {
                return Err("settings flags need --techniques (the default list sets every preset itself); give the \
                            reference's settings as groundtruth:key=value"
                    .into());
            }
            let reference = args.options.technique(&args.reference)?;
            let candidates = frontier::candidates(reference.name(), !args.no_tuned)?;
            let described = if args.no_tuned {
                "every technique at every quality preset"
            } else {
                "every technique at every quality preset, and the settings `aokit tune` recommended (`-tuned`, \
                 docs/tuning.md)"
            };
            (reference, candidates, described.to_string())
        }
    };
    let device = args.device.device()?;
    let scenes = load_scenes(&names, args.width, args.height, args.guard, args.exponent)?;
    let clock = Instant::now();
    let cache = args.device.cache();
    eprintln!(
        "preparing {} scene(s): cpu-sim G-buffers and {} references (a 512-spp reference takes about 10 s per \
         camera at 960×540 on 2 cores; cached afterwards)",
        names.len(),
        reference.name()
    );
    let set =
        TuneSet::new(device, Inputs::Cpu, scenes, reference, Metric::Mse, cache, &mut |line| eprintln!("  {line}"))?;
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
    let wall = format!("wall {:.0} s", clock.elapsed().as_secs_f64());
    let setup = Setup {
        backend: set.device.name().to_string(),
        device: set.device.device_name(),
        width: args.width,
        height: args.height,
        guard: args.guard,
        exponent: args.exponent,
        reference: aokit::tune::spec(&set.reference),
        frames: args.frames,
        candidates: described,
        note: if args.note.is_empty() { wall } else { format!("{}; {wall}", args.note) },
    };
    std::fs::create_dir_all(&args.out).map_err(|e| format!("{}: {e}", args.out.display()))?;
    let write = |name: String, bytes: &[u8]| {
        let path = args.out.join(name);
        aokit::output::write_atomic_bytes(&path, bytes).map_err(|e| format!("{}: {e}", path.display()))
    };
    for scene in &scenes {
        if let Some(svg) = frontier::svg(scene, &setup.backend, &setup.reference) {
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
