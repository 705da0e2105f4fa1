//! Camera paths and temporal stability (`aokit path`): a sequence of frames
//! along an orbit around the camera's target or a dolly toward it, every technique rendered
//! frame after frame (its noise taking the frame index, optionally with the temporal
//! accumulation of `aokit_shaders::temporal`), and per technique
//!
//! - **temporal instability**: per frame t ≥ 1 the mean of `|AO_t(p) − AO_{t−1}(q)|` over the
//!   inner pixels `p` valid in both frames, `q` = `p` reprojected into frame t − 1 with the
//!   accumulation's own reprojection and depth test (`aokit_shaders::temporal::{reproject,
//!   history_matches}`), then the mean over the frames; the ground truth's own instability on
//!   the same path is the floor a perfect technique would still show (its Monte-Carlo noise and
//!   the nearest-texel reprojection);
//! - **MSE** against the ground truth of the same frame (inner image, as `aokit compare`),
//!   averaged over the frames.

use crate::frame::Frame;
use crate::output::crop_inner;
use crate::render::Renderer;
use crate::scene::Scene;
use crate::technique::{Describe, Technique};
use aokit_cpu::graph::CpuExecutor;
use aokit_cpu::{GBufferImage, Progress};
use aokit_shaders::common::camera::Camera;
use aokit_shaders::glam::{Mat3, UVec2, Vec3};
use aokit_shaders::temporal::settings::TemporalSettings;
use aokit_shaders::temporal::{history_matches, reproject};
use rayon::prelude::*;
use std::path::Path;

/// How the camera moves.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum PathKind {
    /// The eye circles the target about the camera's up axis, centred on the starting eye:
    /// frame t is rotated by `step·(t − (N−1)/2)` degrees.
    Orbit,
    /// The eye moves straight toward the target: frame t is at `target + (eye − target)·(1 −
    /// step·t)`.
    Dolly,
}

impl PathKind {
    pub const NAMES: [&'static str; 2] = ["orbit", "dolly"];

    pub fn parse(s: &str) -> Result<PathKind, String> {
        match s {
            "orbit" => Ok(PathKind::Orbit),
            "dolly" => Ok(PathKind::Dolly),
            _ => Err(format!("--path {s}: expected orbit or dolly")),
        }
    }

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }

    /// The default step per frame: 0.25° of orbit (≈ 1 px of motion at 640×360 on the built-in
    /// scenes' presets), or 0.5 % of the eye–target distance of dolly.
    pub fn default_step(self) -> f32 {
        match self {
            PathKind::Orbit => 0.25,
            PathKind::Dolly => 0.005,
        }
    }
}

/// A camera path: its kind, its frame count and the step per frame (degrees for an orbit, a
/// fraction of the eye–target distance for a dolly).
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct PathSpec {
    pub kind: PathKind,
    pub frames: u32,
    pub step: f32,
}

impl PathSpec {
    /// At least two frames (instability compares consecutive ones), a finite positive step, and
    /// a dolly that stops short of the target.
    pub fn validate(&self) -> Result<(), String> {
        if self.frames < 2 {
            return Err(format!(
                "--frames {}: a path needs at least 2 frames (instability compares consecutive frames)",
                self.frames
            ));
        }
        if !(self.step.is_finite() && self.step > 0.0) {
            return Err(format!("--step {}: expected a finite number > 0", self.step));
        }
        let travel = self.step as f64 * (self.frames - 1) as f64;
        if self.kind == PathKind::Dolly && travel >= 1.0 {
            return Err(format!(
                "--step {} over {} frames dollies {:.0} % of the way to the target: the path must stop short of it (step·(frames−1) < 1)",
                self.step,
                self.frames,
                100.0 * travel
            ));
        }
        Ok(())
    }

    /// The eye of frame `t` for a camera at `eye` looking at `target` with `up`.
    pub fn eye(&self, eye: Vec3, target: Vec3, up: Vec3, t: u32) -> Vec3 {
        match self.kind {
            PathKind::Orbit => {
                let degrees = self.step * (t as f32 - 0.5 * (self.frames - 1) as f32);
                target + Mat3::from_axis_angle(up.normalize(), degrees.to_radians()) * (eye - target)
            }
            PathKind::Dolly => target + (eye - target) * (1.0 - self.step * t as f32),
        }
    }
}

/// Which noise the frames get.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Noise {
    /// Frame t has frame index t (as an engine with temporal accumulation runs its AO).
    Animated,
    /// Every frame has index 0 (a fixed noise pattern on the screen).
    Static,
}

impl Noise {
    pub const NAMES: [&'static str; 2] = ["animated", "static"];

    pub fn parse(s: &str) -> Result<Noise, String> {
        match s {
            "animated" => Ok(Noise::Animated),
            "static" => Ok(Noise::Static),
            _ => Err(format!("--noise {s}: expected animated or static")),
        }
    }

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }
}

/// The frames of `spec` starting from `base` (same target, up, field of view, near and far
/// planes): each with its frame index (by `noise`), the previous frame's camera (none for the
/// first) and `temporal`.
pub fn path_frames(base: &Frame, spec: &PathSpec, noise: Noise, temporal: Option<TemporalSettings>) -> Vec<Frame> {
    let view = base.camera.view;
    let mut frames: Vec<Frame> = Vec::with_capacity(spec.frames as usize);
    for t in 0..spec.frames {
        let eye = spec.eye(base.eye, base.target, base.up, t);
        let camera = Camera::look_at(
            eye,
            base.target,
            base.up,
            base.fov_deg.to_radians(),
            base.inner,
            view.guard,
            view.near,
            view.far,
        );
        let previous_camera = frames.last().map(|f| f.camera);
        let frame_index = match noise {
            Noise::Animated => t,
            Noise::Static => 0,
        };
        frames.push(Frame { camera, eye, frame_index, previous_camera, temporal, ..base.clone() });
    }
    frames
}

/// One frame's instability: the mean `|AO_t(p) − AO_{t−1}(q)|` over the `pixels` inner pixels
/// valid in both frames, of `inner` inner pixels.
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub struct FrameInstability {
    pub mean_abs: f64,
    pub pixels: usize,
    pub inner: usize,
}

/// A frame as the instability reads it: its camera, linear depth and AO (full target).
#[derive(Copy, Clone)]
pub struct FrameImages<'a> {
    pub camera: &'a Camera,
    pub depth: &'a [f32],
    pub ao: &'a [f32],
}

/// The instability of `current` against `previous`: every inner pixel `p` of `current` is
/// carried into `previous` by [`reproject`] (its depth, both cameras); it counts where that
/// lands inside the previous inner image and [`history_matches`] the previous depth there within
/// the relative `tolerance` — the temporal accumulation's test — and contributes
/// `|AO_t(p) − AO_{t−1}(q)|`.
pub fn frame_instability(previous: FrameImages, current: FrameImages, tolerance: f32) -> FrameInstability {
    let view = current.camera.view;
    let size = view.size();
    let far = previous.camera.view.far;
    let rows: Vec<(f64, usize)> = (view.guard..size.y - view.guard)
        .into_par_iter()
        .map(|y| {
            let (mut sum, mut n) = (0.0f64, 0usize);
            for x in view.guard..size.x - view.guard {
                let p = UVec2::new(x, y);
                let i = view.index(p);
                let r = reproject(current.camera, previous.camera, p, current.depth[i]);
                if !r.valid {
                    continue;
                }
                let j = previous.camera.view.index(r.pixel);
                if history_matches(r.depth, previous.depth[j], tolerance, far) {
                    sum += (current.ao[i] as f64 - previous.ao[j] as f64).abs();
                    n += 1;
                }
            }
            (sum, n)
        })
        .collect();
    let (sum, pixels) = rows.iter().fold((0.0, 0), |(s, n), (rs, rn)| (s + rs, n + rn));
    let inner = ((size.x - 2 * view.guard) * (size.y - 2 * view.guard)) as usize;
    FrameInstability { mean_abs: if pixels > 0 { sum / pixels as f64 } else { 0.0 }, pixels, inner }
}

/// A technique's run along a path.
#[derive(Clone, Debug, Default)]
pub struct PathRun {
    /// Frames 1… (frame 0 has no predecessor).
    pub instability: Vec<FrameInstability>,
    /// Per frame, MSE against the reference's AO of the same frame (inner image); empty without
    /// a reference.
    pub mse: Vec<f64>,
    /// Per frame, the technique's passes in ms (wall clock on the CPU, timestamps on Vulkan;
    /// the acceleration-structure build left out).
    pub ms: Vec<f64>,
    /// Per frame, the final AO of the inner image in 8 bits (when asked for, for the animation).
    pub images: Vec<Vec<u8>>,
}

impl PathRun {
    /// The instability averaged over the frames that have valid pixels.
    pub fn instability(&self) -> f64 {
        let counted: Vec<f64> = self.instability.iter().filter(|f| f.pixels > 0).map(|f| f.mean_abs).collect();
        if counted.is_empty() { f64::NAN } else { counted.iter().sum::<f64>() / counted.len() as f64 }
    }

    /// The fraction of inner pixels valid in both frames, over all frame pairs.
    pub fn valid_fraction(&self) -> f64 {
        let (n, of) = self.instability.iter().fold((0, 0), |(n, of), f| (n + f.pixels, of + f.inner));
        if of > 0 { n as f64 / of as f64 } else { 0.0 }
    }

    /// The mean MSE over the frames (NaN without a reference).
    pub fn mse(&self) -> f64 {
        if self.mse.is_empty() { f64::NAN } else { self.mse.iter().sum::<f64>() / self.mse.len() as f64 }
    }

    /// The median ms per frame.
    pub fn median_ms(&self) -> f64 {
        if self.ms.is_empty() {
            return f64::NAN;
        }
        crate::report::median(&mut self.ms.clone())
    }
}

/// What [`run_path`] renders on: the back-end, the scene, the path's frames and their
/// G-buffers (one per frame, from [`Renderer::gbuffer`]).
#[derive(Copy, Clone)]
pub struct PathInputs<'a> {
    pub renderer: &'a Renderer,
    pub scene: &'a Scene,
    pub frames: &'a [Frame],
    pub gbuffers: &'a [GBufferImage],
}

/// What [`run_path`] measures and keeps.
#[derive(Copy, Clone)]
pub struct Measure<'a> {
    /// Per frame, the reference's final AO (full target) to take the MSE against.
    pub reference: Option<&'a [Vec<f32>]>,
    /// The instability's relative depth tolerance ([`frame_instability`]).
    pub tolerance: f32,
    /// Keep every frame's final AO in 8 bits ([`PathRun::images`]).
    pub images: bool,
    /// Return every frame's final AO (full target).
    pub keep_ao: bool,
}

/// Render `technique` on every frame of the path in order — on the CPU through one executor,
/// on Vulkan through the renderer's context, so the temporal history carries from frame to
/// frame — and measure it as `measure` says. Returns the run and, with `measure.keep_ao`, every
/// frame's final AO (full target) for later comparisons. `on_frame` is called after each frame.
pub fn run_path(
    inputs: PathInputs,
    technique: &Technique,
    measure: Measure,
    progress: Progress,
    on_frame: &dyn Fn(),
) -> Result<(PathRun, Vec<Vec<f32>>), String> {
    let Measure { reference, tolerance, images, keep_ao } = measure;
    let mut executor = CpuExecutor::new();
    let mut run = PathRun::default();
    let mut kept = Vec::new();
    let mut previous: Option<Vec<f32>> = None;
    for (t, (frame, gbuffer)) in inputs.frames.iter().zip(inputs.gbuffers).enumerate() {
        let result = match inputs.renderer {
            Renderer::Cpu(c) => c.run_with(&mut executor, frame, gbuffer, technique, progress),
            Renderer::Vulkan(v) => v.run(inputs.scene, frame, gbuffer, technique).map_err(|e| e.to_string())?,
        };
        let ao = result.ao_final;
        let view = frame.camera.view;
        run.ms.push(result.passes.iter().filter(|p| p.0 != "accel_build").map(|p| p.1).sum());
        if let Some(prev) = &previous {
            let before = &inputs.frames[t - 1];
            let a = FrameImages { camera: &before.camera, depth: &inputs.gbuffers[t - 1].depth, ao: prev };
            let b = FrameImages { camera: &frame.camera, depth: &gbuffer.depth, ao: &ao };
            run.instability.push(frame_instability(a, b, tolerance));
        }
        if let Some(reference) = reference {
            let (a, b) = (crop_inner(&view, &ao), crop_inner(&view, &reference[t]));
            let image = |pixels| crate::metrics::ImageRef {
                width: frame.inner.x as usize,
                height: frame.inner.y as usize,
                pixels,
            };
            run.mse.push(crate::metrics::mse(image(&a), image(&b), None).unwrap_or(f64::NAN));
        }
        if images {
            run.images
                .push(crop_inner(&view, &ao).iter().map(|&a| (a.clamp(0.0, 1.0) * 255.0).round() as u8).collect());
        }
        if keep_ao {
            kept.push(ao.clone());
        }
        previous = Some(ao);
        on_frame();
    }
    Ok((run, kept))
}

/// An animated PNG (APNG, grey 8-bit, looping) of `frames` (`width×height` bytes each) at
/// `fps` frames per second, written atomically.
pub fn write_apng(path: &Path, width: u32, height: u32, frames: &[Vec<u8>], fps: u16) -> std::io::Result<()> {
    let io = |e: png::EncodingError| std::io::Error::other(e.to_string());
    crate::output::write_atomic(path, |w| {
        let mut encoder = png::Encoder::new(w, width, height);
        encoder.set_color(png::ColorType::Grayscale);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.set_animated(frames.len() as u32, 0).map_err(io)?;
        encoder.set_frame_delay(1, fps.max(1)).map_err(io)?;
        let mut writer = encoder.write_header().map_err(io)?;
        for f in frames {
            writer.write_image_data(f).map_err(io)?;
        }
        writer.finish().map_err(io)
    })
}

/// `path` with `-suffix` before its extension (`anim.png` → `anim-gtao.png`).
pub fn suffixed(path: &Path, suffix: &str) -> std::path::PathBuf {
    let stem = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    let ext = path.extension().map(|e| format!(".{}", e.to_string_lossy())).unwrap_or_default();
    path.with_file_name(format!("{stem}-{suffix}{ext}"))
}

/// One row of a path report: a technique, with or without the temporal accumulation, and its run.
pub struct PathResult {
    pub technique: Technique,
    pub temporal: bool,
    pub run: PathRun,
}

impl PathResult {
    /// The technique's label, `+temporal` with the accumulation.
    pub fn label(&self) -> String {
        if self.temporal { format!("{} +temporal", self.technique.label()) } else { self.technique.label() }
    }
}

/// What `aokit path` prints and writes.
pub struct PathReport<'a> {
    pub scene: &'a str,
    pub backend: &'a str,
    pub device: &'a str,
    pub frame: &'a Frame,
    pub spec: PathSpec,
    pub noise: Noise,
    pub temporal: TemporalSettings,
    /// The instability metric's relative depth tolerance.
    pub tolerance: f32,
    /// The reference (the ground truth): its run is the instability floor.
    pub reference: &'a PathResult,
    pub results: &'a [PathResult],
}

impl PathReport<'_> {
    /// The table: per row the instability, its ratio to the reference's (the floor), the mean
    /// MSE against the reference, the fraction of pixels valid in both frames, ms per frame.
    pub fn table(&self) -> String {
        let floor = self.reference.run.instability();
        let mut out = format!(
            "{} {} frames, {} noise, {}×{}, {} ({}); temporal α {}, depth tolerance {}\n",
            self.spec.kind.name(),
            self.spec.frames,
            self.noise.name(),
            self.frame.inner.x,
            self.frame.inner.y,
            self.backend,
            self.device,
            self.temporal.alpha,
            self.tolerance
        );
        out += &format!(
            "{:<34} {:>12} {:>8} {:>12} {:>8} {:>10}\n",
            "technique", "instability", "× floor", "MSE vs ref", "valid %", "ms/frame"
        );
        let row = |label: String, r: &PathRun, mse: String| {
            format!(
                "{label:<34} {:>12.5} {:>8.2} {mse:>12} {:>8.1} {:>10.1}\n",
                r.instability(),
                r.instability() / floor,
                100.0 * r.valid_fraction(),
                r.median_ms()
            )
        };
        out += &row(format!("{} (floor)", self.reference.label()), &self.reference.run, "—".into());
        for res in self.results {
            out += &row(res.label(), &res.run, format!("{:.3e}", res.run.mse()));
        }
        out
    }

    /// The machine-readable report.
    pub fn json(&self) -> serde_json::Value {
        let floor = self.reference.run.instability();
        let number = |v: f64| if v.is_finite() { serde_json::json!(v) } else { serde_json::Value::Null };
        let result = |res: &PathResult| {
            serde_json::json!({
                "technique": res.technique.name(),
                "label": res.label(),
                "options": res.technique.describe(),
                "temporal": res.temporal,
                "instability": number(res.run.instability()),
                "instability_over_floor": number(res.run.instability() / floor),
                "instability_per_frame": res.run.instability.iter().map(|f| f.mean_abs).collect::<Vec<_>>(),
                "valid_fraction": res.run.valid_fraction(),
                "mse": number(res.run.mse()),
                "mse_per_frame": res.run.mse,
                "median_ms": number(res.run.median_ms()),
            })
        };
        let v = |x: Vec3| [x.x, x.y, x.z];
        serde_json::json!({
            "scene": self.scene,
            "backend": self.backend,
            "device": self.device,
            "width": self.frame.inner.x,
            "height": self.frame.inner.y,
            "guard_band": self.frame.camera.view.guard,
            "radius": self.frame.radius,
            "exponent": self.frame.exponent,
            "camera": {"eye": v(self.frame.eye), "target": v(self.frame.target), "up": v(self.frame.up), "fov_y_deg": self.frame.fov_deg},
            "path": {"kind": self.spec.kind.name(), "frames": self.spec.frames, "step": self.spec.step,
                     "step_unit": match self.spec.kind { PathKind::Orbit => "degrees per frame", PathKind::Dolly => "fraction of the eye–target distance per frame" }},
            "noise": self.noise.name(),
            "temporal": {"alpha": self.temporal.alpha, "depth_tolerance": self.temporal.depth_tolerance},
            "instability_depth_tolerance": self.tolerance,
            "reference": result(self.reference),
            "results": self.results.iter().map(result).collect::<Vec<_>>(),
        })
    }
}
