//! What both comparisons share: the frame and its G-buffer, the timing statistics, the report.

use aokit::frame::{CameraChoice, Frame, FrameRequest};
use aokit::render::CpuRenderer;
use aokit::scene::{Scene, builtin};
use aokit_cpu::GBufferImage;
use std::path::PathBuf;

/// The frame both sides render: a built-in scene's preset camera at `width` × `height`, without
/// a guard band (the peers have none: both sides run over the same pixels).
#[derive(clap::Args, Clone, Debug)]
pub struct FrameArgs {
    /// A built-in scene (`aokit scenes`).
    #[arg(long, default_value = "sponza")]
    pub scene: String,
    #[arg(long, default_value_t = 1920)]
    pub width: u32,
    #[arg(long, default_value_t = 1080)]
    pub height: u32,
    /// Timed iterations (each runs both sides once, alternating which goes first).
    #[arg(long, default_value_t = 9)]
    pub iterations: u32,
    /// Untimed iterations first.
    #[arg(long, default_value_t = 2)]
    pub warmup: u32,
    /// Write the results as JSON here.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write both sides' final AO as PNG into this folder (`aokit.png`, `peer.png`).
    #[arg(long)]
    pub images: Option<PathBuf>,
}

/// The scene, its frame and cpu-sim's G-buffer of it (linear view depth, octahedral normals).
pub fn frame_and_gbuffer(args: &FrameArgs) -> Result<(Scene, Frame, GBufferImage), String> {
    if args.width < 16 || args.height < 16 || args.iterations == 0 {
        return Err("--width and --height must be at least 16 and --iterations at least 1".into());
    }
    let b = builtin::find(&args.scene).ok_or_else(|| format!("'{}' is not a built-in scene", args.scene))?;
    let scene = b.load().map_err(|e| e.to_string())?;
    let req = FrameRequest {
        width: args.width,
        height: args.height,
        guard: 0,
        camera: CameraChoice::Preset { name: None, fov_deg: None },
        radius: None,
        exponent: 2.0,
        thickness: 0.0,
    };
    let frame = Frame::resolve(&scene, Some(b), &req).map_err(|e| e.to_string())?;
    eprintln!("G-buffer of {} at {}×{} (cpu-sim)…", args.scene, args.width, args.height);
    let (gbuffer, _) = CpuRenderer::new(&scene).gbuffer(&frame, &aokit_cpu::no_progress);
    Ok((scene, frame, gbuffer))
}

/// The median of `values` (which must not be empty).
pub fn median(values: &[f64]) -> f64 {
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 { v[n / 2] } else { 0.5 * (v[n / 2 - 1] + v[n / 2]) }
}

/// One row of a side-by-side table: per-iteration times of both sides (ms) and the median of
/// the per-iteration ratios aokit / peer.
pub struct Row {
    pub name: String,
    pub aokit_ms: Vec<f64>,
    pub peer_ms: Vec<f64>,
}

impl Row {
    pub fn ratio(&self) -> f64 {
        let ratios: Vec<f64> = self.aokit_ms.iter().zip(&self.peer_ms).map(|(a, p)| a / p).collect();
        median(&ratios)
    }

    pub fn json(&self) -> serde_json::Value {
        serde_json::json!({
            "pass": self.name,
            "aokit_ms": median(&self.aokit_ms),
            "peer_ms": median(&self.peer_ms),
            "ratio": self.ratio(),
            "aokit_ms_all": self.aokit_ms,
            "peer_ms_all": self.peer_ms,
        })
    }
}

/// Agreement of two AO images over the pixels `keep` selects: the fraction within `tolerance`,
/// the MSE and the largest difference.
pub fn agreement(a: &[f32], b: &[f32], keep: impl Fn(usize) -> bool, tolerance: f32) -> serde_json::Value {
    assert_eq!(a.len(), b.len(), "both images cover the same pixels");
    let (mut n, mut within, mut sq, mut max) = (0usize, 0usize, 0.0f64, 0.0f32);
    for i in (0..a.len()).filter(|&i| keep(i)) {
        let d = (a[i] - b[i]).abs();
        n += 1;
        within += (d <= tolerance) as usize;
        sq += (d as f64) * (d as f64);
        max = max.max(d);
    }
    serde_json::json!({
        "pixels": n,
        "within": tolerance,
        "fraction_within": within as f64 / n.max(1) as f64,
        "mse": sq / n.max(1) as f64,
        "max_abs": max,
    })
}

/// Print `report` and write it to `path`.
pub fn finish(report: serde_json::Value, path: Option<&PathBuf>) -> Result<(), String> {
    let text = serde_json::to_string_pretty(&report).expect("serializable");
    println!("{text}");
    if let Some(path) = path {
        std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(())
}

/// Write both sides' AO (`w` × `h`, visibility in [0, 1]) as 8-bit grey PNGs into `dir`.
pub fn write_images(dir: &std::path::Path, w: u32, h: u32, aokit: &[f32], peer: &[f32]) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for (name, ao) in [("aokit.png", aokit), ("peer.png", peer)] {
        let bytes: Vec<u8> = ao.iter().map(|&v| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8).collect();
        let path = dir.join(name);
        image::save_buffer(&path, &bytes, w, h, image::ExtendedColorType::L8)
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(())
}
