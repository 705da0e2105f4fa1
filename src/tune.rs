//! `aokit tune`: a technique's settings searched against a reference image (the 512-spp ground
//! truth, spec gtao-raymarch-hybrid §5) with argmin's Nelder–Mead, and cross-validated over
//! scenes.
//!
//! XeGTAO's own auto-tune (spec gtao-raymarch-hybrid §2.8) is a grid search with narrowing passes
//! over RadiusMultiplier and FalloffRange, minimising the mean MSE over every preset camera. Here:
//!
//! - **Parameters** come from the technique's settings rows (`aokit_shaders::technique::Setting`):
//!   by default every `Number` row that changes the technique's pass graph at the given settings
//!   (a row that does not, e.g. `peel-separation` on single depth, cannot change the image);
//!   `--keys` picks rows instead, `Count` rows included (rounded), optionally with a narrower
//!   range `key=lo..hi`. A row without an upper bound (`≥ min`) is searched over
//!   `[min, max(4 × start, min + 1)]`. Choices are **fixed**: set them on the technique
//!   (`gtao:preset=ultra`) and tune once per value.
//! - **Search**: Nelder–Mead (argmin) in normalised coordinates `x ∈ [0, 1]^d`, clamped to the
//!   box; value = min + x·(max − min), rounded to 4 significant digits (counts: to an integer),
//!   so the printed `technique:key=value` reproduces the evaluated image exactly. The first
//!   simplex is the starting settings plus a step of ¼ of each range. The budget is the number
//!   of distinct settings rendered; repeats (rounding, clamping) are memoised and free.
//! - **Objective**: per camera, the metric over the inner image of the technique's final AO
//!   against the reference's (MSE, or 1 − SSIM; spec gtao-raymarch-hybrid §6.1, §6.2), averaged
//!   over the scene's cameras, then over the tuning scenes.
//! - **Cross-validation** (two or more scenes): leave one scene out, tune on the others, score
//!   the held-back scene with the starting and the tuned settings; then tune on every scene for
//!   the recommended settings. With one scene the gain is in-sample only, and says so.
//! - The reference per scene and camera is rendered once; it is cached on disk under
//!   `<aokit cache>/reference/` keyed by everything it depends on (back-end, device, scene
//!   contents, camera, size, guard band, radius, exponent, reference settings, shader sources).

use crate::frame::{CameraChoice, Frame, FrameRequest};
use crate::metrics::{ImageRef, mse, ssim};
use crate::output::crop_inner;
use crate::render::{CpuRenderer, VulkanRenderer};
use crate::scene::Scene;
use crate::scene::builtin;
use crate::technique::{Describe, Technique};
use aokit_cpu::GBufferImage;
use aokit_shaders::graph::FrameDesc;
use aokit_shaders::technique::Kind;
use argmin::core::{CostFunction, Executor, State};
use argmin::solver::neldermead::NelderMead;
use sha2::{Digest, Sha256};
use std::cell::RefCell;
use std::collections::HashMap;
use std::path::PathBuf;
use std::time::Instant;

/// The image metric a search minimises.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Metric {
    /// Mean squared error (spec gtao-raymarch-hybrid §6.1).
    Mse,
    /// SSIM (spec gtao-raymarch-hybrid §6.2); the loss is 1 − SSIM.
    Ssim,
}

impl Metric {
    pub const NAMES: [&'static str; 2] = ["mse", "ssim"];

    pub fn parse(s: &str) -> Result<Metric, String> {
        match s {
            "mse" => Ok(Metric::Mse),
            "ssim" => Ok(Metric::Ssim),
            _ => Err(format!("--metric {s}: expected mse or ssim")),
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Metric::Mse => "mse",
            Metric::Ssim => "ssim",
        }
    }

    /// What the search minimises: the MSE, or 1 − SSIM (0 for identical images either way).
    pub fn loss(self, s: &Scores) -> f64 {
        match self {
            Metric::Mse => s.mse,
            Metric::Ssim => 1.0 - s.ssim.unwrap_or(f64::NAN),
        }
    }
}

/// Metrics of a technique against the reference, averaged over a scene's cameras.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Scores {
    pub mse: f64,
    /// Computed when the metric is SSIM or a report asks for both.
    pub ssim: Option<f64>,
    /// The technique's time per frame (sum of its passes, wall clock on the CPU, timestamps on
    /// Vulkan; the acceleration-structure build excluded), ms: tuning for quality alone may buy
    /// it with time.
    pub ms: f64,
}

/// One searched setting.
#[derive(Clone, Debug)]
pub struct Param {
    pub key: &'static str,
    /// A `Count` row: values are rounded to integers.
    pub integer: bool,
    /// The searched range (inside the row's declared range).
    pub lo: f64,
    pub hi: f64,
    /// The starting settings' value, as the technique states it.
    pub start: String,
    /// The start in normalised coordinates (clamped into the range).
    start_x: f64,
}

impl Param {
    /// The value at normalised coordinate `x` (clamped to [0, 1]) as the text the setting is
    /// given: the start's own text at the start, an integer for counts, else 4 significant
    /// digits kept inside the range.
    pub fn text(&self, x: f64) -> String {
        let x = x.clamp(0.0, 1.0);
        if x == self.start_x && (self.lo..=self.hi).contains(&self.start.parse::<f64>().unwrap_or(f64::NAN)) {
            return self.start.clone();
        }
        let v = self.lo + x * (self.hi - self.lo);
        if self.integer {
            return (v.round() as u64).to_string();
        }
        let text = significant(v, 4);
        match text.parse::<f64>() {
            Ok(r) if r > self.hi => (self.hi as f32).to_string(),
            Ok(r) if r < self.lo => (self.lo as f32).to_string(),
            _ => text,
        }
    }

    /// The normalised coordinate of a value.
    fn x_of(&self, v: f64) -> f64 {
        ((v - self.lo) / (self.hi - self.lo)).clamp(0.0, 1.0)
    }

    /// `key lo–hi [start]`.
    pub fn describe(&self) -> String {
        format!("{} {}–{} [{}]", self.key, trim(self.lo), trim(self.hi), self.start)
    }
}

/// `v` with `digits` significant digits, trailing zeros trimmed.
fn significant(v: f64, digits: i32) -> String {
    if v == 0.0 || !v.is_finite() {
        return "0".into();
    }
    let decimals = (digits - 1 - v.abs().log10().floor() as i32).max(0) as usize;
    trim_text(format!("{v:.decimals$}"))
}

fn trim(v: f64) -> String {
    trim_text(format!("{}", v as f32))
}

fn trim_text(s: String) -> String {
    if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s }
}

/// The graph and second layer as comparable text: equal text, equal image.
fn effect(t: &Technique, frame: &FrameDesc) -> String {
    format!("{:?} {:?}", t.graph(frame), t.second_layer())
}

/// The setting's current value as text (numbers as the settings rows print them).
fn current(t: &Technique, key: &str) -> String {
    let v = &t.describe()[key.replace('-', "_")];
    v.as_str().map_or_else(|| v.to_string(), str::to_string)
}

/// The settings to search: `keys` (`k1,k2=lo..hi,…`) or, without it, every `Number` row of the
/// technique that changes its pass graph at `frame`.
pub fn parameters(technique: &Technique, keys: Option<&str>, frame: &FrameDesc) -> Result<Vec<Param>, String> {
    let rows = technique.rows();
    let name = technique.name();
    let all_keys = || rows.iter().map(|r| r.key).collect::<Vec<_>>().join(", ");
    // A row as a parameter: its declared range (an unbounded one capped), or `range` inside it.
    let make = |row: &aokit_shaders::technique::Row, range: Option<(f64, f64)>| -> Result<Param, String> {
        let (min, max, integer, unbounded) = match row.kind {
            Kind::Number { min, max } => (min as f64, max as f64, false, max == f32::MAX),
            Kind::Count { min, max } => (min as f64, max as f64, true, max == u32::MAX),
            Kind::Choice(names) => {
                return Err(format!(
                    "{name}: {} is a choice ({}): choices are not searched; fix it on the technique, e.g. \
                     --technique {name}:{}={}, and tune once per value",
                    row.key,
                    names.join("|"),
                    row.key,
                    names.last().unwrap_or(&"")
                ));
            }
        };
        let start = current(technique, row.key);
        let s: f64 = start.parse().map_err(|_| format!("{name}: {} is not a number ({start})", row.key))?;
        let max = if unbounded { (4.0 * s).max(min + 1.0) } else { max };
        let (lo, hi) = match range {
            None => (min, max),
            Some((lo, hi)) => {
                // In f32, as the rows declare their bounds.
                let declared_max = if unbounded { f32::INFINITY } else { max as f32 };
                if !(lo as f32 >= min as f32 && hi as f32 <= declared_max && lo < hi) {
                    return Err(format!(
                        "{name}: {} range {}..{}: expected min < max inside {}",
                        row.key,
                        trim(lo),
                        trim(hi),
                        row.kind.accepted()
                    ));
                }
                (lo, hi)
            }
        };
        if integer && hi - lo < 1.0 {
            return Err(format!("{name}: {} range {}..{} holds one whole number", row.key, trim(lo), trim(hi)));
        }
        let mut p = Param { key: row.key, integer, lo, hi, start, start_x: 0.0 };
        p.start_x = p.x_of(s);
        Ok(p)
    };
    // Does the row change the graph anywhere in its range (at the other settings as given)?
    let acts = |p: &Param| -> bool {
        let base = effect(technique, frame);
        [0.0, 1.0].iter().any(|&x| {
            let mut t = technique.clone();
            t.set(p.key, &p.text(x)).is_ok() && effect(&t, frame) != base
        })
    };
    let Some(keys) = keys else {
        let mut params = Vec::new();
        for row in rows.iter().filter(|r| matches!(r.kind, Kind::Number { .. })) {
            let p = make(row, None)?;
            if acts(&p) {
                params.push(p);
            }
        }
        if params.is_empty() {
            return Err(format!(
                "{name} has no continuous (number) setting that changes its output at these settings; \
                 name whole-number settings with --keys (it has: {})",
                all_keys()
            ));
        }
        return Ok(params);
    };
    let mut params: Vec<Param> = Vec::new();
    for item in keys.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let (key, range) = match item.split_once('=') {
            None => (item, None),
            Some((key, range)) => {
                let (lo, hi) = range
                    .split_once("..")
                    .and_then(|(lo, hi)| Some((lo.trim().parse::<f64>().ok()?, hi.trim().parse::<f64>().ok()?)))
                    .ok_or_else(|| format!("--keys {item}: expected key or key=lo..hi"))?;
                (key.trim(), Some((lo, hi)))
            }
        };
        let row = rows
            .iter()
            .find(|r| r.key == key)
            .ok_or_else(|| format!("{name} has no setting '{key}' (it has {})", all_keys()))?;
        if params.iter().any(|p| p.key == key) {
            return Err(format!("--keys names {key} twice"));
        }
        let p = make(row, range)?;
        if !acts(&p) {
            return Err(format!(
                "{name}: {key} does not change the output at these settings (e.g. a dual-depth setting on \
                 single depth); fix the settings it depends on first"
            ));
        }
        params.push(p);
    }
    if params.is_empty() {
        return Err("--keys is empty".into());
    }
    Ok(params)
}

/// Where the techniques run.
#[allow(clippy::large_enum_variant)]
pub enum Device {
    Cpu,
    Vulkan(VulkanRenderer),
}

impl Device {
    pub fn name(&self) -> &'static str {
        match self {
            Device::Cpu => "cpu",
            Device::Vulkan(_) => "vulkan",
        }
    }

    /// The Vulkan device's name, or the CPU thread count.
    pub fn device_name(&self) -> String {
        match self {
            Device::Cpu => format!("CPU, {} threads", rayon::current_num_threads()),
            Device::Vulkan(v) => v.gpu.info().name.clone(),
        }
    }

    /// Validation messages so far (none on the CPU).
    pub fn validation_messages(&self) -> Vec<String> {
        match self {
            Device::Cpu => Vec::new(),
            Device::Vulkan(v) => v.gpu.validation_messages(),
        }
    }
}

/// One camera of a scene: its frame, G-buffer and the reference's final AO (inner image).
pub struct View {
    pub camera: String,
    pub frame: Frame,
    gbuffer: GBufferImage,
    reference: Vec<f32>,
    /// Time to render the reference, ms; `None`: read from the cache.
    pub reference_ms: Option<f64>,
}

impl View {
    /// The reference's final AO over the inner image.
    pub fn reference(&self) -> &[f32] {
        &self.reference
    }
}

/// A scene with every camera the tuner scores.
pub struct TuneScene {
    pub name: String,
    scene: Scene,
    cpu: Option<CpuRenderer>,
    pub views: Vec<View>,
}

/// A built-in scene with all its camera presets, or a scene file with the automatic camera, at
/// the size, guard band and exponent of `request` (its camera is replaced; its radius is the
/// scene's default when `None`).
pub fn scene_views(spec: &str, request: &FrameRequest) -> Result<(Scene, Vec<(String, Frame)>), String> {
    let (scene, cameras): (Scene, Vec<(String, CameraChoice)>) = match builtin::find(spec) {
        Some(b) => (
            b.load().map_err(|e| e.to_string())?,
            b.cameras
                .iter()
                .map(|c| (c.name.to_string(), CameraChoice::Preset { name: Some(c.name.into()), fov_deg: None }))
                .collect(),
        ),
        None => {
            let path = std::path::Path::new(spec);
            if !path.exists() {
                let names: Vec<_> = builtin::builtin_scenes().iter().map(|s| s.name).collect();
                return Err(format!(
                    "'{spec}' is neither a built-in scene ({}) nor an existing file",
                    names.join(", ")
                ));
            }
            let scene = Scene::load(path).map_err(|e| e.to_string())?;
            (scene, vec![("auto".into(), CameraChoice::Auto { fov_deg: 60.0 })])
        }
    };
    let b = builtin::find(spec);
    let frames = cameras
        .into_iter()
        .map(|(name, camera)| {
            let req = FrameRequest { camera, ..request.clone() };
            Frame::resolve(&scene, b, &req).map(|f| (name, f)).map_err(|e| format!("{spec}: {e}"))
        })
        .collect::<Result<_, _>>()?;
    Ok((scene, frames))
}

/// A scene with its cameras' names and frames ([`scene_views`]).
pub type SceneViews = (Scene, Vec<(String, Frame)>);

/// The comma-separated scene list of a `--scenes` flag: none empty, none twice.
pub fn scene_names(spec: &str) -> Result<Vec<&str>, String> {
    let names: Vec<&str> = spec.split(',').map(str::trim).filter(|s| !s.is_empty()).collect();
    if names.is_empty() {
        return Err("--scenes is empty".into());
    }
    if let Some(dup) = names.iter().enumerate().find(|(i, n)| names[..*i].contains(n)).map(|(_, n)| n) {
        return Err(format!("--scenes names {dup} twice"));
    }
    Ok(names)
}

/// Every camera of each named scene ([`scene_views`]) at `width`×`height` + `guard`, AO
/// exponent `exponent`; refused where two names load the same scene (their outputs would
/// collide).
pub fn load_scenes(
    names: &[&str],
    width: u32,
    height: u32,
    guard: u32,
    exponent: f32,
) -> Result<Vec<SceneViews>, String> {
    let request = FrameRequest {
        width,
        height,
        guard,
        camera: CameraChoice::Auto { fov_deg: 60.0 },
        radius: None,
        exponent,
        thickness: 0.0,
    };
    let mut scenes: Vec<SceneViews> = Vec::new();
    for name in names {
        let loaded = scene_views(name, &request)?;
        if let Some((other, _)) = scenes.iter().find(|(s, _)| s.name == loaded.0.name) {
            return Err(format!("--scenes: {name} is scene '{}' again", other.name));
        }
        scenes.push(loaded);
    }
    Ok(scenes)
}

/// The device of `--backend cpu|vulkan`, `--rt-mode` and `--validation`; the last two are
/// refused on the CPU, which has neither.
pub fn device_of(backend: &str, rt_mode: Option<&str>, validation: bool) -> Result<Device, String> {
    use aokit_shaders::graph::RtMode;
    match (backend, rt_mode) {
        ("cpu", Some(mode)) => Err(format!(
            "--rt-mode {mode} selects how the Vulkan back-end traces (--backend vulkan); cpu-sim traces through its BVH"
        )),
        ("cpu", None) if validation => {
            Err("--validation enables the Vulkan validation layer (--backend vulkan); cpu-sim has none".into())
        }
        ("cpu", None) => Ok(Device::Cpu),
        ("vulkan", _) => {
            let mode = rt_mode.map(RtMode::parse).transpose()?.unwrap_or(RtMode::Pipeline);
            let v = VulkanRenderer::new(&aokit_vulkan::GpuOptions { validation, ..Default::default() })
                .map_err(|e| e.to_string())?;
            v.set_rt_mode(mode);
            Ok(Device::Vulkan(v))
        }
        (other, _) => Err(format!("--backend {other}: expected cpu or vulkan")),
    }
}

/// Where a [`TuneSet`]'s G-buffers and references come from.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Inputs {
    /// The set's device: the rasterized G-buffer and the reference rendered on Vulkan, or
    /// cpu-sim's on the CPU.
    Device,
    /// cpu-sim's ray-cast G-buffers and references whatever the device; the techniques still
    /// run on the device, on those same G-buffers (uploaded on Vulkan). Every back-end is
    /// then scored against one reference from the same inputs, and an expensive reference (the
    /// 512-spp ground truth) is rendered and cached once for all back-ends.
    Cpu,
}

/// Scenes, their cameras, G-buffers and reference images, on one device: what every objective
/// evaluation renders against.
pub struct TuneSet {
    pub device: Device,
    pub scenes: Vec<TuneScene>,
    pub reference: Technique,
    pub metric: Metric,
    /// Where the G-buffers and references come from.
    inputs: Inputs,
}

/// SHA-256 of bytes, hex.
fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes).iter().map(|b| format!("{b:02x}")).collect()
}

/// A scene's geometry, texture coordinates, materials and alpha masks, hashed.
fn scene_hash(scene: &Scene) -> String {
    let mut h = Sha256::new();
    for t in &scene.triangles {
        for v in t {
            h.update(bytemuck::cast_slice(&v.to_array()));
        }
    }
    for t in &scene.triangle_uvs {
        for v in t {
            h.update(bytemuck::cast_slice(&v.to_array()));
        }
    }
    h.update(bytemuck::cast_slice(&scene.triangle_materials));
    let (headers, texels) = scene.alpha_masks();
    h.update(format!("{headers:?}").as_bytes());
    h.update(bytemuck::cast_slice(&texels));
    h.finalize().iter().map(|b| format!("{b:02x}")).collect()
}

impl TuneSet {
    /// Load the scenes' G-buffers and render (or read from `cache`) the reference for every
    /// camera, both on `device` or both on cpu-sim ([`Inputs`]); `log` hears one line per
    /// reference image.
    pub fn new(
        device: Device,
        inputs: Inputs,
        scenes: Vec<(Scene, Vec<(String, Frame)>)>,
        reference: Technique,
        metric: Metric,
        cache: Option<PathBuf>,
        log: &mut dyn FnMut(&str),
    ) -> Result<TuneSet, String> {
        TuneSet { device, scenes: Vec::new(), reference, metric, inputs }.load(scenes, cache, log)
    }

    /// Whether the G-buffers and references are cpu-sim's.
    fn inputs_on_cpu(&self) -> bool {
        self.inputs == Inputs::Cpu || matches!(self.device, Device::Cpu)
    }

    fn load(
        mut self,
        scenes: Vec<(Scene, Vec<(String, Frame)>)>,
        cache: Option<PathBuf>,
        log: &mut dyn FnMut(&str),
    ) -> Result<TuneSet, String> {
        let set = &mut self;
        let metric = set.metric;
        for (scene, frames) in scenes {
            let cpu = set.inputs_on_cpu().then(|| CpuRenderer::new(&scene));
            let hash = cache.as_ref().map(|_| scene_hash(&scene));
            let mut ts = TuneScene { name: scene.name.clone(), scene, cpu, views: Vec::new() };
            for (camera, frame) in frames {
                if metric == Metric::Ssim && (frame.inner.x < 11 || frame.inner.y < 11) {
                    return Err(format!(
                        "--metric ssim needs at least 11×11 pixels, got {}×{}",
                        frame.inner.x, frame.inner.y
                    ));
                }
                let gbuffer = match (&set.device, &ts.cpu) {
                    (Device::Vulkan(v), _) if !set.inputs_on_cpu() => {
                        v.gbuffer(&ts.scene, &frame).map_err(|e| e.to_string())?.0
                    }
                    (_, Some(cpu)) => cpu.gbuffer(&frame, &aokit_cpu::no_progress).0,
                    (_, None) => unreachable!("CPU scenes and cpu-sim inputs have a renderer"),
                };
                let key = hash.as_ref().map(|h| set.cache_key(h, &ts.name, &frame));
                let file =
                    cache.as_ref().zip(key.as_ref()).map(|(dir, key)| dir.join(&sha256_hex(key.as_bytes())[..32]));
                let n = (frame.inner.x * frame.inner.y) as usize;
                let cached =
                    file.as_ref().and_then(|f| std::fs::read(f.with_extension("f32")).ok()).and_then(|bytes| {
                        (bytes.len() == 4 * n).then(|| {
                            bytes.chunks_exact(4).map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect()
                        })
                    });
                let (reference_ao, reference_ms) = match cached {
                    Some(ao) => (ao, None),
                    None => {
                        let t = Instant::now();
                        let (ao, _) = set.render_on(set.inputs_on_cpu(), &ts, &frame, &gbuffer, &set.reference)?;
                        let ms = t.elapsed().as_secs_f64() * 1e3;
                        if let (Some(file), Some(key)) = (&file, &key) {
                            let bytes: Vec<u8> = ao.iter().flat_map(|v| v.to_le_bytes()).collect();
                            let write = std::fs::create_dir_all(file.parent().expect("in the cache folder"))
                                .and_then(|_| {
                                    crate::output::write_atomic_bytes(&file.with_extension("json"), key.as_bytes())
                                })
                                .and_then(|_| crate::output::write_atomic_bytes(&file.with_extension("f32"), &bytes));
                            if let Err(e) = write {
                                log(&format!("warning: reference cache {}: {e}", file.display()));
                            }
                        }
                        (ao, Some(ms))
                    }
                };
                log(&match reference_ms {
                    Some(ms) => format!("reference {}/{camera}: rendered in {:.1} s", ts.name, ms / 1e3),
                    None => format!("reference {}/{camera}: from the cache", ts.name),
                });
                ts.views.push(View { camera, frame, gbuffer, reference: reference_ao, reference_ms });
            }
            set.scenes.push(ts);
        }
        Ok(self)
    }

    /// Everything the reference image depends on, as text.
    fn cache_key(&self, scene_hash: &str, scene: &str, frame: &Frame) -> String {
        serde_json::json!({
            "format": "aokit-reference/1",
            "backend": if self.inputs_on_cpu() { "cpu" } else { self.device.name() },
            "device": if self.inputs_on_cpu() { "CPU".to_string() } else { self.device.device_name().split(',').next().unwrap_or_default().to_string() },
            "scene": scene,
            "scene_sha256": scene_hash,
            "frame": frame.describe(),
            "reference": self.reference.name(),
            "options": self.reference.describe(),
            "shader_manifest_sha256": sha256_hex(aokit_contract::MANIFEST_JSON.as_bytes()),
            "aokit": env!("CARGO_PKG_VERSION"),
        })
        .to_string()
    }

    /// A technique's final AO over the inner image of one camera, and its time in ms.
    fn render(
        &self,
        scene: &TuneScene,
        frame: &Frame,
        gbuffer: &GBufferImage,
        t: &Technique,
    ) -> Result<(Vec<f32>, f64), String> {
        self.render_on(false, scene, frame, gbuffer, t)
    }

    /// [`TuneSet::render`] on cpu-sim when `on_cpu`, else on the set's device.
    fn render_on(
        &self,
        on_cpu: bool,
        scene: &TuneScene,
        frame: &Frame,
        gbuffer: &GBufferImage,
        t: &Technique,
    ) -> Result<(Vec<f32>, f64), String> {
        let run = match (&self.device, &scene.cpu) {
            (Device::Vulkan(v), _) if !on_cpu => v.run(&scene.scene, frame, gbuffer, t).map_err(|e| e.to_string())?,
            (_, Some(cpu)) => cpu.run(frame, gbuffer, t, &aokit_cpu::no_progress),
            (_, None) => unreachable!("CPU scenes and cpu-sim inputs have a renderer"),
        };
        let ms = run.passes.iter().filter(|p| p.0 != "accel_build").map(|p| p.1).sum();
        Ok((crop_inner(&frame.camera.view, &run.ao_final), ms))
    }

    /// A technique's final AO over the inner image of camera `view` of scene `scene`, and its
    /// time in ms (the sum of its passes, acceleration-structure builds excluded), on the set's
    /// device. Panics where `scene` or `view` is out of range.
    pub fn evaluate(&self, scene: usize, view: usize, t: &Technique) -> Result<(Vec<f32>, f64), String> {
        let s = &self.scenes[scene];
        let v = &s.views[view];
        self.render(s, &v.frame, &v.gbuffer, t)
    }

    /// The technique's metrics on scene `scene`, averaged over its cameras (SSIM too when the
    /// metric is SSIM or `both`).
    pub fn scores(&self, scene: usize, t: &Technique, both: bool) -> Result<Scores, String> {
        let s = &self.scenes[scene];
        let (mut m, mut q, mut time) = (0.0, 0.0, 0.0);
        let want_ssim = both || self.metric == Metric::Ssim;
        for v in &s.views {
            let (ao, ms) = self.render(s, &v.frame, &v.gbuffer, t)?;
            time += ms;
            let (w, h) = (v.frame.inner.x as usize, v.frame.inner.y as usize);
            let a = ImageRef { width: w, height: h, pixels: &ao };
            let b = ImageRef { width: w, height: h, pixels: &v.reference };
            m += mse(a, b, None).expect("a non-empty image");
            if want_ssim {
                q += ssim(a, b, None).unwrap_or(f64::NAN);
            }
        }
        let n = s.views.len() as f64;
        Ok(Scores { mse: m / n, ssim: want_ssim.then_some(q / n), ms: time / n })
    }

    /// The loss on `scenes`: the metric's loss per scene (mean over its cameras), averaged over
    /// the scenes, so that every scene weighs the same whatever its camera count.
    pub fn loss(&self, scenes: &[usize], t: &Technique) -> Result<f64, String> {
        let mut sum = 0.0;
        for &s in scenes {
            sum += self.metric.loss(&self.scores(s, t, false)?);
        }
        Ok(sum / scenes.len() as f64)
    }

    /// Nelder–Mead over `params` from `start`, on `scenes`, for at most `budget` distinct
    /// settings; `on_eval` hears every new evaluation with the best loss so far.
    pub fn tune(
        &self,
        scenes: &[usize],
        start: &Technique,
        params: &[Param],
        budget: usize,
        on_eval: &mut dyn FnMut(&Evaluation, f64),
    ) -> Result<Tuned, String> {
        let d = params.len();
        let x0: Vec<f64> = params.iter().map(|p| p.start_x).collect();
        // The first simplex: the start and a step of ¼ range (at least one whole number) along
        // each axis, backwards where forwards leaves the box.
        let mut simplex = vec![x0.clone()];
        for (i, p) in params.iter().enumerate() {
            let step = if p.integer { (1.0 / (p.hi - p.lo)).clamp(0.25, 1.0) } else { 0.25 };
            let mut x = x0.clone();
            x[i] = if x0[i] + step <= 1.0 { x0[i] + step } else { x0[i] - step };
            simplex.push(x);
        }
        let texts = |x: &[f64]| -> Vec<String> { params.iter().zip(x).map(|(p, &x)| p.text(x)).collect() };
        let start_values: Vec<String> = params.iter().map(|p| p.start.clone()).collect();
        let mut first: Vec<Vec<String>> = vec![start_values.clone()];
        for x in &simplex {
            let t = texts(x);
            if !first.contains(&t) {
                first.push(t);
            }
        }
        if budget < first.len() {
            return Err(format!(
                "--budget {budget} is too small for {d} setting(s): the start and Nelder–Mead's first simplex \
                 take {} evaluations",
                first.len()
            ));
        }
        let search = RefCell::new(Search {
            memo: HashMap::new(),
            evaluations: Vec::new(),
            refused: 0,
            budget_spent: false,
            failure: None,
            on_eval,
        });
        let objective = Objective { set: self, scenes, start, params, budget, search: &search };
        // The start as given (outside a narrowed range it is not a vertex of the simplex).
        objective.evaluate(&start_values).map_err(|e| e.to_string())?;
        let solver = NelderMead::new(simplex);
        let run = Executor::new(objective, solver).configure(|s| s.max_iters(50 * budget as u64 + 100)).run();
        let stop = match run {
            Ok(r) => match r.state().get_termination_reason() {
                Some(reason) => reason.to_string(),
                None => "stopped".into(),
            },
            Err(_) if search.borrow().budget_spent => "budget spent".into(),
            Err(e) => return Err(search.borrow_mut().failure.take().unwrap_or_else(|| e.to_string())),
        };
        let search = search.into_inner();
        let baseline_loss = search.memo[&start_values];
        let best = search.evaluations.iter().min_by(|a, b| a.loss.total_cmp(&b.loss)).expect("the start was evaluated");
        let mut technique = start.clone();
        for (p, v) in params.iter().zip(&best.values) {
            technique.set(p.key, v).expect("evaluated settings are valid");
        }
        Ok(Tuned {
            values: best.values.clone(),
            loss: best.loss,
            technique,
            baseline_loss,
            evaluations: search.evaluations,
            refused: search.refused,
            stop,
        })
    }
}

/// One rendered setting of a search.
#[derive(Clone, Debug)]
pub struct Evaluation {
    /// The searched settings' values, in parameter order.
    pub values: Vec<String>,
    pub loss: f64,
    /// Wall time of the evaluation's renders and metrics.
    pub ms: f64,
}

/// A finished search.
#[derive(Clone, Debug)]
pub struct Tuned {
    /// The starting technique with the best values.
    pub technique: Technique,
    pub values: Vec<String>,
    pub loss: f64,
    /// The loss of the starting settings.
    pub baseline_loss: f64,
    /// Every distinct setting rendered, in order.
    pub evaluations: Vec<Evaluation>,
    /// Points whose settings the technique refused (e.g. a layer count that is no power of two);
    /// they are not rendered and count as a loss of [`REFUSED_LOSS`].
    pub refused: usize,
    /// Why the search stopped: "budget spent", or argmin's termination reason.
    pub stop: String,
}

/// The loss of settings the technique refuses: above any real MSE or 1 − SSIM (≤ 2).
pub const REFUSED_LOSS: f64 = 1e3;

struct Search<'a> {
    memo: HashMap<Vec<String>, f64>,
    evaluations: Vec<Evaluation>,
    refused: usize,
    budget_spent: bool,
    failure: Option<String>,
    on_eval: &'a mut dyn FnMut(&Evaluation, f64),
}

/// The objective argmin minimises (shared state behind a `RefCell`: argmin owns the cost
/// function and calls it through `&self`).
struct Objective<'a, 'b> {
    set: &'a TuneSet,
    scenes: &'a [usize],
    start: &'a Technique,
    params: &'a [Param],
    budget: usize,
    search: &'a RefCell<Search<'b>>,
}

impl Objective<'_, '_> {
    fn evaluate(&self, values: &[String]) -> Result<f64, argmin::core::Error> {
        let mut search = self.search.borrow_mut();
        if let Some(&loss) = search.memo.get(values) {
            return Ok(loss);
        }
        let mut t = self.start.clone();
        for (p, v) in self.params.iter().zip(values) {
            if t.set(p.key, v).is_err() {
                search.refused += 1;
                search.memo.insert(values.to_vec(), REFUSED_LOSS);
                return Ok(REFUSED_LOSS);
            }
        }
        if search.evaluations.len() >= self.budget {
            search.budget_spent = true;
            return Err(argmin::core::Error::msg("the evaluation budget is spent"));
        }
        let clock = Instant::now();
        let loss = match self.set.loss(self.scenes, &t) {
            Ok(l) => l,
            Err(e) => {
                search.failure = Some(e.clone());
                return Err(argmin::core::Error::msg(e));
            }
        };
        let e = Evaluation { values: values.to_vec(), loss, ms: clock.elapsed().as_secs_f64() * 1e3 };
        search.memo.insert(values.to_vec(), loss);
        search.evaluations.push(e.clone());
        let best = search.evaluations.iter().map(|e| e.loss).fold(f64::INFINITY, f64::min);
        (search.on_eval)(&e, best);
        Ok(loss)
    }
}

impl CostFunction for Objective<'_, '_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, x: &Vec<f64>) -> Result<f64, argmin::core::Error> {
        let values: Vec<String> = self.params.iter().zip(x).map(|(p, &x)| p.text(x)).collect();
        self.evaluate(&values)
    }
}

/// A technique as `name:key=value…` with every setting that differs from the registry's
/// defaults (and its resolution when not full), to paste into `--technique`/`--techniques`.
pub fn spec(t: &Technique) -> String {
    let defaults = Technique::named(t.name()).expect("a registered technique");
    let mut s = t.name().to_string();
    for row in t.rows() {
        let v = current(t, row.key);
        if v != current(&defaults, row.key) {
            s += &format!(":{}={v}", row.key);
        }
    }
    if t.resolution() != aokit_shaders::technique::Resolution::Full {
        s += &format!(":{}={}", aokit_shaders::technique::RESOLUTION_KEY, t.resolution().name());
    }
    s
}

/// A scene's metrics with the starting and the tuned settings.
#[derive(Clone, Debug)]
pub struct SceneScores {
    pub scene: String,
    /// Not among the scenes the settings were tuned on.
    pub held_back: bool,
    pub baseline: Scores,
    pub tuned: Scores,
}

/// One search and its scores on every scene.
#[derive(Clone, Debug)]
pub struct Fold {
    pub tuned_on: Vec<String>,
    pub held_back: Option<String>,
    pub result: Tuned,
    pub scores: Vec<SceneScores>,
    pub wall_s: f64,
}

/// Leave-one-out folds (two or more scenes) and the search on every scene.
#[derive(Clone, Debug)]
pub struct Study {
    pub folds: Vec<Fold>,
    pub all: Fold,
}

impl Study {
    /// Folds whose held-back scene improved (lower loss with the tuned settings), of all folds.
    pub fn held_back_improved(&self, metric: Metric) -> (usize, usize) {
        let better = |f: &Fold| {
            f.scores.iter().filter(|s| s.held_back).all(|s| metric.loss(&s.tuned) < metric.loss(&s.baseline))
        };
        (self.folds.iter().filter(|f| better(f)).count(), self.folds.len())
    }
}

/// The relative loss reduction, percent (positive = better).
pub fn gain(baseline: f64, tuned: f64) -> f64 {
    100.0 * (baseline - tuned) / baseline
}

impl TuneSet {
    /// Cross-validation: with two or more scenes, per scene a search on the others scored on it
    /// (held back); then a search on every scene. With one scene only the latter (in-sample).
    /// `on_eval` hears `(fold label, evaluation, best loss)`.
    pub fn study(
        &self,
        start: &Technique,
        params: &[Param],
        budget: usize,
        on_eval: &mut dyn FnMut(&str, &Evaluation, f64),
    ) -> Result<Study, String> {
        let n = self.scenes.len();
        // Warm-up, untimed: the first frame of a technique makes its pipelines (Vulkan).
        self.scores(0, start, false)?;
        let mut baseline = Vec::new();
        for s in 0..n {
            baseline.push(self.scores(s, start, true)?);
        }
        let mut fold = |tuned_on: Vec<usize>, label: &str| -> Result<Fold, String> {
            let clock = Instant::now();
            let result = self.tune(&tuned_on, start, params, budget, &mut |e, best| on_eval(label, e, best))?;
            let mut scores = Vec::new();
            for (s, &baseline) in baseline.iter().enumerate() {
                scores.push(SceneScores {
                    scene: self.scenes[s].name.clone(),
                    held_back: !tuned_on.contains(&s),
                    baseline,
                    tuned: self.scores(s, &result.technique, true)?,
                });
            }
            let names = |v: &[usize]| v.iter().map(|&s| self.scenes[s].name.clone()).collect::<Vec<_>>();
            let held: Vec<usize> = (0..n).filter(|s| !tuned_on.contains(s)).collect();
            Ok(Fold {
                tuned_on: names(&tuned_on),
                held_back: names(&held).first().cloned(),
                result,
                scores,
                wall_s: clock.elapsed().as_secs_f64(),
            })
        };
        let mut folds = Vec::new();
        if n >= 2 {
            for held in 0..n {
                let label = format!("fold {}/{n}", held + 1);
                folds.push(fold((0..n).filter(|&s| s != held).collect(), &label)?);
            }
        }
        let all = fold((0..n).collect(), "all scenes")?;
        Ok(Study { folds, all })
    }
}

#[cfg(feature = "cli")]
pub use command::{DeviceArgs, TuneArgs, tune_command};

#[cfg(feature = "cli")]
mod command {
    use super::*;
    use crate::cli::TechniqueArgs;
    use aokit_shaders::graph::RtMode;

    /// Where `tune` and `frontier` run and whether they cache their references.
    #[derive(clap::Args)]
    pub struct DeviceArgs {
        /// Where the techniques run (`tune`: the reference too; `frontier`: the G-buffers and
        /// references are cpu-sim's either way).
        #[arg(long, value_parser = ["cpu", "vulkan"], default_value = "cpu")]
        pub backend: String,
        /// Neither read nor write the reference cache (`<aokit cache>/reference/`).
        #[arg(long)]
        pub no_cache: bool,
        /// Enable the Khronos validation layer (--backend vulkan); validation messages fail the
        /// run.
        #[arg(long)]
        pub validation: bool,
        /// How the Vulkan back-end runs ray-traced passes (pipeline or query).
        #[arg(long, value_parser = RtMode::NAMES)]
        pub rt_mode: Option<String>,
    }

    impl DeviceArgs {
        /// The device ([`device_of`]).
        pub fn device(&self) -> Result<Device, String> {
            device_of(&self.backend, self.rt_mode.as_deref(), self.validation)
        }

        /// The reference cache's folder, unless `--no-cache`.
        pub fn cache(&self) -> Option<PathBuf> {
            (!self.no_cache).then(|| builtin::cache_dir().join("reference"))
        }
    }

    /// `aokit tune`'s flags.
    #[derive(clap::Args)]
    #[command(allow_negative_numbers = true)]
    pub struct TuneArgs {
        #[command(flatten)]
        options: TechniqueArgs,
        /// The technique to tune, optionally with fixed `:key=value` settings (choices are fixed,
        /// not searched: e.g. `gtao:preset=ultra`).
        #[arg(long)]
        technique: String,
        /// Comma-separated scenes (built-in names or files); with two or more, each is held back
        /// once (leave-one-out cross-validation). Built-in scenes use all their camera presets.
        #[arg(long, default_value = "sponza,kitchen")]
        scenes: String,
        /// The metric minimised (mean over cameras): mse, or ssim (the loss is 1 − SSIM).
        #[arg(long, default_value = "mse", value_parser = Metric::NAMES)]
        metric: String,
        /// Distinct settings rendered per search (Nelder–Mead's objective evaluations).
        #[arg(long, default_value_t = 60)]
        budget: usize,
        /// Settings to search, comma-separated, each optionally with a range (default: every number
        /// setting that changes the output), e.g. `radius-multiplier=0.9..2,falloff-range`.
        #[arg(long)]
        keys: Option<String>,
        /// The reference image's technique, optionally with `:key=value` settings.
        #[arg(long, default_value = "groundtruth")]
        reference: String,
        /// Output width (the tuner's default is small: the 512-spp ground truth is the cost).
        #[arg(long, default_value_t = 480)]
        width: u32,
        #[arg(long, default_value_t = 270)]
        height: u32,
        /// G-buffer guard band in pixels on every side.
        #[arg(long, default_value_t = 64)]
        guard: u32,
        /// AO exponent (as `render`/`compare`; the ground truth is V^exponent).
        #[arg(long, default_value_t = 2.0)]
        exponent: f32,
        #[command(flatten)]
        device: DeviceArgs,
        /// Write the results as JSON here.
        #[arg(long)]
        json: Option<PathBuf>,
    }

    fn fold_text(label: &str, f: &Fold) -> String {
        let held = match &f.held_back {
            Some(h) => format!(", held back {h}"),
            None if f.scores.iter().all(|s| !s.held_back) && f.scores.len() == 1 => {
                " (single scene: no held-back scene, the gain is in-sample only)".into()
            }
            None => String::new(),
        };
        let mut s = format!(
            "{label} — tuned on {}{held}: {} evaluations ({}{}), {:.1} s\n  tuned: {}\n",
            f.tuned_on.join(", "),
            f.result.evaluations.len(),
            f.result.stop,
            if f.result.refused > 0 { format!(", {} refused points", f.result.refused) } else { String::new() },
            f.wall_s,
            spec(&f.result.technique)
        );
        s += &format!(
            "  {:<12} {:<10} {:>11} {:>11} {:>8}   {:>9} {:>9} {:>8}   {:>9} {:>9}\n",
            "scene", "role", "MSE start", "MSE tuned", "gain", "SSIM st.", "SSIM tu.", "gain", "ms start", "ms tuned"
        );
        for sc in &f.scores {
            let ssim_loss = |s: &Scores| Metric::Ssim.loss(s);
            s += &format!(
                "  {:<12} {:<10} {:>11.4e} {:>11.4e} {:>7.1}%   {:>9.5} {:>9.5} {:>7.1}%   {:>9.1} {:>9.1}\n",
                sc.scene,
                if sc.held_back { "held back" } else { "tuning" },
                sc.baseline.mse,
                sc.tuned.mse,
                gain(sc.baseline.mse, sc.tuned.mse),
                sc.baseline.ssim.unwrap_or(f64::NAN),
                sc.tuned.ssim.unwrap_or(f64::NAN),
                gain(ssim_loss(&sc.baseline), ssim_loss(&sc.tuned)),
                sc.baseline.ms,
                sc.tuned.ms,
            );
        }
        s
    }

    fn scores_json(s: &Scores) -> serde_json::Value {
        serde_json::json!({"mse": s.mse, "ssim": s.ssim, "ms": s.ms})
    }

    fn fold_json(params: &[Param], metric: Metric, f: &Fold) -> serde_json::Value {
        serde_json::json!({
            "tuned_on": f.tuned_on, "held_back": f.held_back,
            "tuned": spec(&f.result.technique),
            "values": params.iter().zip(&f.result.values).map(|(p, v)| (p.key.to_string(), v.parse::<f64>().map_or(serde_json::Value::Null, |x| x.into()))).collect::<serde_json::Map<_, _>>(),
            "loss": f.result.loss, "start_loss": f.result.baseline_loss,
            "evaluations": f.result.evaluations.len(), "refused": f.result.refused, "stop": f.result.stop,
            "wall_s": f.wall_s,
            "scores": f.scores.iter().map(|s| serde_json::json!({
                "scene": s.scene, "held_back": s.held_back,
                "start": scores_json(&s.baseline), "tuned": scores_json(&s.tuned),
                "gain_percent": gain(metric.loss(&s.baseline), metric.loss(&s.tuned)),
            })).collect::<Vec<_>>(),
            "history": f.result.evaluations.iter().map(|e| serde_json::json!({"values": e.values, "loss": e.loss, "ms": e.ms})).collect::<Vec<_>>(),
        })
    }

    /// `aokit tune`.
    pub fn tune_command(args: TuneArgs) -> Result<(), String> {
        let metric = Metric::parse(&args.metric)?;
        if args.budget == 0 {
            return Err("--budget must be at least 1".into());
        }
        let mut techniques = args.options.techniques(&[args.technique.as_str(), args.reference.as_str()])?;
        let reference = techniques.pop().expect("two techniques");
        let reference = crate::technique::reference_at_full_resolution(reference, &args.reference);
        let technique = techniques.pop().expect("two techniques");
        if technique.name() == reference.name() && technique.describe() == reference.describe() {
            return Err(format!("{} is also the reference: nothing to tune against", spec(&technique)));
        }
        let names = scene_names(&args.scenes)?;
        let device = args.device.device()?;
        let scenes = load_scenes(&names, args.width, args.height, args.guard, args.exponent)?;
        let params = parameters(&technique, args.keys.as_deref(), &scenes[0].1[0].1.desc())?;
        let clock = Instant::now();
        let cache = args.device.cache();
        eprintln!("preparing {} scene(s): G-buffers and {} reference images", names.len(), reference.name());
        let set =
            TuneSet::new(device, Inputs::Device, scenes, reference, metric, cache, &mut |line| eprintln!("  {line}"))?;
        let reference_s = clock.elapsed().as_secs_f64();
        let mut header = format!(
            "aokit tune: {} against {} ({}) on {} ({}), {}×{} + {} px guard band, metric {} (loss {}; mean over \
             cameras, then scenes), budget {} evaluations per search\n",
            spec(&technique),
            spec(&set.reference),
            set.reference.describe(),
            set.device.name(),
            set.device.device_name(),
            args.width,
            args.height,
            args.guard,
            metric.name(),
            if metric == Metric::Mse { "MSE" } else { "1 − SSIM" },
            args.budget
        );
        for s in &set.scenes {
            let cams: Vec<_> = s.views.iter().map(|v| v.camera.as_str()).collect();
            header +=
                &format!("  scene {}: camera(s) {}; radius {}\n", s.name, cams.join(", "), s.views[0].frame.radius);
        }
        header += &format!(
            "  searched (Nelder–Mead in [0,1]^{}, clamped; 4 significant digits): {}\n  references ready in {:.1} s\n",
            params.len(),
            params.iter().map(Param::describe).collect::<Vec<_>>().join(", "),
            reference_s
        );
        header += "  gain: relative reduction of the MSE and of 1 − SSIM (positive = closer to the reference); ms: the \
                   technique's time per frame, mean over cameras\n";
        print!("{header}");
        let study = set.study(&technique, &params, args.budget, &mut |label, e, best| {
            eprintln!(
                "  [{label}] {}: loss {:.4e} (best {:.4e}, {:.0} ms)",
                params.iter().zip(&e.values).map(|(p, v)| format!("{}={v}", p.key)).collect::<Vec<_>>().join(" "),
                e.loss,
                best,
                e.ms
            );
        })?;
        let messages = set.device.validation_messages();
        if !messages.is_empty() {
            return Err(format!("validation layer reported {} message(s):\n{}", messages.len(), messages.join("\n")));
        }
        for (i, f) in study.folds.iter().enumerate() {
            print!("{}", fold_text(&format!("fold {}/{}", i + 1, study.folds.len()), f));
        }
        print!("{}", fold_text("all scenes", &study.all));
        let (improved, folds) = study.held_back_improved(metric);
        let recommended = spec(&study.all.result.technique);
        let verdict = if folds == 0 {
            "single scene: no held-back scene, so no evidence that the tuned settings generalise".to_string()
        } else if improved == folds {
            format!(
                "the held-back scene improved in {improved}/{folds} folds: the tuned settings generalise; recommended: {recommended}"
            )
        } else {
            format!("the held-back scene improved in only {improved}/{folds} folds: keep the defaults")
        };
        println!("verdict: {verdict}\ntotal {:.1} s", clock.elapsed().as_secs_f64());
        if let Some(path) = &args.json {
            let json = serde_json::json!({
                "technique": spec(&technique), "reference": spec(&set.reference), "reference_options": set.reference.describe(),
                "backend": set.device.name(), "device": set.device.device_name(),
                "width": args.width, "height": args.height, "guard_band": args.guard, "exponent": args.exponent,
                "metric": metric.name(), "budget": args.budget,
                "parameters": params.iter().map(|p| serde_json::json!({"key": p.key, "min": p.lo, "max": p.hi, "start": p.start, "integer": p.integer})).collect::<Vec<_>>(),
                "scenes": set.scenes.iter().map(|s| serde_json::json!({
                    "name": s.name, "cameras": s.views.iter().map(|v| v.camera.clone()).collect::<Vec<_>>(),
                    "reference_ms": s.views.iter().map(|v| v.reference_ms).collect::<Vec<_>>(),
                })).collect::<Vec<_>>(),
                "folds": study.folds.iter().map(|f| fold_json(&params, metric, f)).collect::<Vec<_>>(),
                "all": fold_json(&params, metric, &study.all),
                "held_back_improved": [improved, folds],
                "recommended": (folds > 0 && improved == folds).then_some(recommended),
                "wall_s": clock.elapsed().as_secs_f64(),
            });
            let text = serde_json::to_string_pretty(&json).expect("serializable");
            crate::output::write_atomic_bytes(path, text.as_bytes()).map_err(|e| e.to_string())?;
        }
        Ok(())
    }
}
