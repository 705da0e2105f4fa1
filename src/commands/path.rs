//! `aokit path`: a technique along a camera path, with and without temporal accumulation
//! (docs/temporal.md).

use super::{FrameArgs, check_validation, renderer, resolve};
use aokit::cli::TechniqueArgs;
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct PathArgs {
    #[command(flatten)]
    pub frame: FrameArgs,
    #[command(flatten)]
    pub options: TechniqueArgs,
    /// Comma-separated techniques, each optionally with `:key=value` settings, or `all` (every
    /// registered technique but the reference).
    #[arg(long, visible_alias = "techniques", default_value = "gtao")]
    pub technique: String,
    /// The camera path: `orbit` (around the camera's target, about its up axis) or `dolly`
    /// (toward the target).
    #[arg(long, default_value = "orbit")]
    pub path: String,
    /// Frames of the path (at least 2).
    #[arg(long, default_value_t = 60)]
    pub frames: u32,
    /// Step per frame: degrees of orbit [0.25], or the fraction of the eye–target distance a
    /// dolly moves [0.005].
    #[arg(long)]
    pub step: Option<f32>,
    /// Temporal accumulation: `off`, `on` or `both` (each technique twice).
    #[arg(long, default_value = "both")]
    pub temporal: String,
    /// The current frame's weight α of the accumulation's exponential blend, in (0, 1].
    #[arg(long, default_value_t = 0.1)]
    pub temporal_alpha: f32,
    /// Relative depth tolerance ε of the accumulation's history test and of the instability's
    /// "valid in both frames", in (0, 1].
    #[arg(long, default_value_t = aokit_shaders::temporal::settings::DEPTH_TOLERANCE)]
    pub temporal_depth_tolerance: f32,
    /// The techniques' noise over the frames: `animated` (frame index t) or `static` (0).
    #[arg(long, default_value = "animated")]
    pub noise: String,
    /// The reference (MSE, and its own instability as the floor), optionally with settings.
    #[arg(long, default_value = "groundtruth")]
    pub reference: String,
    /// Animated PNG of the final AO; with several runs one file per run, the run's label
    /// appended to the name (`anim-gtao.png`, `anim-gtao-temporal.png`, `anim-groundtruth.png`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Frames per second of the animated PNG.
    #[arg(long, default_value_t = 30)]
    pub fps: u16,
    /// Write the machine-readable report here.
    #[arg(long)]
    pub json: Option<PathBuf>,
}

/// Run the command.
pub fn run(args: PathArgs) -> Result<(), String> {
    use aokit::path::{
        Measure, Noise, PathInputs, PathKind, PathReport, PathResult, PathSpec, path_frames, run_path, suffixed,
        write_apng,
    };
    use aokit_shaders::temporal::settings::TemporalSettings;
    let kind = PathKind::parse(&args.path)?;
    let spec = PathSpec { kind, frames: args.frames, step: args.step.unwrap_or(kind.default_step()) };
    spec.validate()?;
    let noise = Noise::parse(&args.noise)?;
    let modes: &[bool] = match args.temporal.as_str() {
        "off" => &[false],
        "on" => &[true],
        "both" => &[false, true],
        other => return Err(format!("--temporal {other}: expected off, on or both")),
    };
    let temporal = TemporalSettings { alpha: args.temporal_alpha, depth_tolerance: args.temporal_depth_tolerance };
    // The library names the setting; the command line names its flags.
    temporal.validate().map_err(|e| {
        e.replace("temporal alpha", "--temporal-alpha")
            .replace("temporal depth tolerance", "--temporal-depth-tolerance")
    })?;
    if let Some(out) = &args.out
        && !out.extension().is_some_and(|e| e.eq_ignore_ascii_case("png"))
    {
        return Err(format!("--out {}: aokit writes an animated PNG (APNG): give a .png path", out.display()));
    }
    let reference_name = args.reference.split(':').next().unwrap_or_default();
    let names: Vec<&str> = match args.technique.trim() {
        "all" => aokit::technique::TECHNIQUES.iter().map(|t| t.name()).filter(|n| *n != reference_name).collect(),
        list => list.split(',').map(str::trim).filter(|s| !s.is_empty()).collect(),
    };
    if names.is_empty() {
        return Err("--technique is empty".into());
    }
    let mut techniques = args.options.techniques(&[&names[..], &[args.reference.as_str()]].concat())?;
    let reference = techniques.pop().expect("the reference is the last");
    let reference = aokit::technique::reference_at_full_resolution(reference, &args.reference);
    let (scene, base) = resolve(&args.frame)?;
    aokit::technique::check_graphs(techniques.iter().chain([&reference]), &base)?;
    let renderer = renderer(&args.frame, &scene)?;
    let frames_off = path_frames(&base, &spec, noise, None);
    let frames_on = path_frames(&base, &spec, noise, Some(temporal));
    let runs = 2 + (techniques.len() * modes.len()) as u64;
    let bar = ProgressBar::new(runs * spec.frames as u64).with_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} frames ({eta})").expect("valid template"),
    );
    bar.set_message(format!("{} G-buffers", renderer.backend_name()));
    let mut gbuffers = Vec::new();
    for f in &frames_off {
        gbuffers.push(renderer.gbuffer(&scene, f, &aokit_cpu::no_progress).map_err(|e| e.to_string())?.0);
        bar.inc(1);
    }
    let inputs = |frames| PathInputs { renderer: &renderer, scene: &scene, frames, gbuffers: &gbuffers };
    let tolerance = temporal.depth_tolerance;
    let measure = Measure { reference: None, tolerance, images: args.out.is_some(), keep_ao: true };
    let tick = || bar.inc(1);
    bar.set_message(format!("{} (reference)", reference.label()));
    let (reference_run, reference_ao) =
        run_path(inputs(&frames_off), &reference, measure, &aokit_cpu::no_progress, &tick)?;
    let reference = PathResult { technique: reference, temporal: false, run: reference_run };
    let mut results = Vec::new();
    for t in &techniques {
        for &on in modes {
            bar.set_message(format!("{}{}", t.label(), if on { " +temporal" } else { "" }));
            let frames = if on { &frames_on } else { &frames_off };
            let measure = Measure { reference: Some(&reference_ao), keep_ao: false, ..measure };
            let (run, _) = run_path(inputs(frames), t, measure, &aokit_cpu::no_progress, &tick)?;
            results.push(PathResult { technique: t.clone(), temporal: on, run });
        }
    }
    bar.finish_and_clear();
    check_validation(&renderer)?;
    let device = renderer.device_name();
    let report = PathReport {
        scene: &scene.name,
        backend: renderer.backend_name(),
        device: &device,
        frame: &base,
        spec,
        noise,
        temporal,
        tolerance,
        reference: &reference,
        results: &results,
    };
    print!("{}", report.table());
    if let Some(path) = &args.json {
        let text = serde_json::to_string_pretty(&report.json()).expect("serializable");
        aokit::output::write_atomic_bytes(path, text.as_bytes()).map_err(|e| e.to_string())?;
    }
    if let Some(out) = &args.out {
        let single = results.len() == 1;
        for res in std::iter::once(&reference).chain(&results) {
            let is_reference = std::ptr::eq(res, &reference);
            if single && is_reference {
                continue;
            }
            let name = format!("{}{}", res.technique.label(), if res.temporal { "-temporal" } else { "" });
            let name: String =
                name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '-' { c } else { '_' }).collect();
            let file = if single { out.clone() } else { suffixed(out, &name) };
            write_apng(&file, base.inner.x, base.inner.y, &res.run.images, args.fps).map_err(|e| e.to_string())?;
            eprintln!("wrote {}", file.display());
        }
    }
    Ok(())
}
