//! Reports: `aokit compare` (metrics vs a reference, JSON contract, PNGs, HTML page) and
//! `aokit bench` (per-pass statistics over frames).

use crate::frame::Frame;
use crate::metrics::{ImageRef, flip_map, masked_mean, mse, psnr, ssim};
use crate::output::crop_inner;
use crate::technique::{Describe, Technique, TechniqueRun};
use aokit_cpu::GBufferImage;
use image::{Rgb, RgbImage};
use std::io;
use std::path::{Path, PathBuf};

/// Metrics and costs of one technique against the reference.
#[derive(Clone, Debug)]
pub struct CompareRow {
    /// File-name-safe unique label (name plus non-default options, numbered if repeated).
    pub label: String,
    pub technique: Technique,
    pub mse: f64,
    pub psnr: f64,
    pub ssim: Option<f64>,
    /// Mean LDR-FLIP against the reference ([`crate::metrics::flip`]).
    pub flip: f64,
    /// FLIP's per-pixel error map (inner image).
    pub flip_map: Vec<f32>,
    pub rays: u64,
    pub refined_samples: u64,
    pub passes: Vec<(&'static str, f64)>,
    pub total_ms: f64,
    /// Final AO over the inner image.
    pub ao: Vec<f32>,
    pub run: TechniqueRun,
}

impl CompareRow {
    /// The table cells shared by the text and HTML tables: label, MSE, PSNR, SSIM, FLIP, rays,
    /// refined samples, summed SD-ray interval, total ms, passes.
    pub fn cells(&self) -> [String; 10] {
        let passes: Vec<_> = self.passes.iter().map(|(n, ms)| format!("{n} {ms:.1}")).collect();
        [
            self.label.clone(),
            format!("{:.3e}", self.mse),
            format!("{:.2}", self.psnr),
            self.ssim.map_or("-".into(), |v| format!("{v:.4}")),
            format!("{:.4}", self.flip),
            self.rays.to_string(),
            self.refined_samples.to_string(),
            self.run.interval_sum.map_or("-".into(), |v| format!("{v:.4e}")),
            format!("{:.1}", self.total_ms),
            passes.join(", "),
        ]
    }
}

/// Where a comparison ran.
#[derive(Copy, Clone, Debug)]
pub struct CompareSetup<'a> {
    pub scene: &'a str,
    pub backend: &'a str,
    pub device: &'a str,
    /// Time of the shared G-buffer pass.
    pub gbuffer_ms: f64,
}

/// One `aokit compare` run.
pub struct CompareReport {
    pub scene: String,
    pub backend: String,
    pub device: String,
    pub width: u32,
    pub height: u32,
    pub gbuffer_ms: f64,
    pub reference: Technique,
    pub reference_ao: Vec<f32>,
    pub reference_run: TechniqueRun,
    pub rows: Vec<CompareRow>,
}

impl CompareReport {
    /// Metrics over the inner image (guard band excluded) of the final (post-blur where the
    /// technique blurs) AO of every technique against the reference's final AO.
    pub fn new(
        setup: CompareSetup,
        frame: &Frame,
        (reference, reference_run): (Technique, &TechniqueRun),
        runs: &[(Technique, TechniqueRun)],
    ) -> CompareReport {
        let view = frame.camera.view;
        let (w, h) = (frame.inner.x as usize, frame.inner.y as usize);
        let reference_ao = crop_inner(&view, &reference_run.ao_final);
        let reference_img = ImageRef { width: w, height: h, pixels: &reference_ao };
        let mut rows = Vec::new();
        for (technique, run) in runs {
            let ao = crop_inner(&view, &run.ao_final);
            let img = ImageRef { width: w, height: h, pixels: &ao };
            let m = mse(img, reference_img, None).unwrap_or(f64::NAN);
            let flip_map = flip_map(reference_img, img);
            let flip = masked_mean(&flip_map, None).unwrap_or(f64::NAN);
            let label = numbered_label(technique.label(), rows.iter().map(|r: &CompareRow| r.label.as_str()));
            rows.push(CompareRow {
                label,
                technique: technique.clone(),
                mse: m,
                psnr: psnr(m),
                ssim: ssim(img, reference_img, None),
                flip,
                flip_map,
                rays: run.rays,
                refined_samples: run.refined_samples,
                passes: run.passes.clone(),
                total_ms: run.total_ms(),
                ao,
                run: run.clone(),
            });
        }
        CompareReport {
            scene: setup.scene.to_string(),
            backend: setup.backend.to_string(),
            device: setup.device.to_string(),
            width: frame.inner.x,
            height: frame.inner.y,
            gbuffer_ms: setup.gbuffer_ms,
            reference,
            reference_ao,
            reference_run: reference_run.clone(),
            rows,
        }
    }

    /// The machine-readable contract:
    /// `{"scene", "backend", "width", "height", "reference", "results": [{"technique", "options",
    /// "mse", "psnr", "ssim", "flip", "rays", "refined_samples", "passes": [{"name", "ms"}],
    /// "total_ms"}]}`.
    pub fn json(&self) -> serde_json::Value {
        let results: Vec<_> = self
            .rows
            .iter()
            .map(|r| {
                serde_json::json!({
                    "technique": r.technique.name(),
                    "label": r.label,
                    "options": r.technique.describe(),
                    "mse": r.mse, "psnr": finite_or_null(r.psnr), "ssim": r.ssim, "flip": r.flip,
                    "rays": r.rays, "refined_samples": r.refined_samples,
                    "ray_interval_sum": r.run.interval_sum,
                    "passes": r.passes.iter().map(|(n, ms)| serde_json::json!({"name": n, "ms": ms})).collect::<Vec<_>>(),
                    "total_ms": r.total_ms,
                })
            })
            .collect();
        serde_json::json!({
            "scene": self.scene, "backend": self.backend, "device": self.device,
            "width": self.width, "height": self.height,
            "reference": self.reference.name(), "reference_options": self.reference.describe(),
            "reference_total_ms": self.reference_run.total_ms(),
            "reference_rays": self.reference_run.rays,
            "reference_passes": self.reference_run.passes.iter().map(|(n, ms)| serde_json::json!({"name": n, "ms": ms})).collect::<Vec<_>>(),
            "gbuffer_ms": self.gbuffer_ms,
            "metrics_on": "final AO (after the bilateral blur for vao/raysd/raysvao), inner image",
            "results": results,
        })
    }

    /// A plain-text table, one row per technique.
    pub fn table(&self) -> String {
        let mut s = format!(
            "{} on {} ({}), {}×{}, reference {}\n{:<24} {:>11} {:>7} {:>7} {:>7} {:>11} {:>10} {:>11} {:>10}  passes (ms)\n",
            self.scene,
            self.backend,
            self.device,
            self.width,
            self.height,
            self.reference.name(),
            "technique",
            "MSE",
            "PSNR",
            "SSIM",
            "FLIP",
            "rays",
            "refined",
            "Σ interval",
            "total ms"
        );
        let reference: Vec<_> = self.reference_run.passes.iter().map(|(n, ms)| format!("{n} {ms:.1}")).collect();
        s += &format!(
            "{:<24} {:>11} {:>7} {:>7} {:>7} {:>11} {:>10} {:>11} {:>10.1}  {}\n",
            format!("({})", self.reference.name()),
            "reference",
            "",
            "",
            "",
            self.reference_run.rays,
            self.reference_run.refined_samples,
            "",
            self.reference_run.total_ms(),
            reference.join(", ")
        );
        for r in &self.rows {
            let [label, mse, psnr, ssim, flip, rays, refined, interval, total, passes] = r.cells();
            s += &format!(
                "{label:<24} {mse:>11} {psnr:>7} {ssim:>7} {flip:>7} {rays:>11} {refined:>10} {interval:>11} {total:>10}  {passes}\n"
            );
        }
        s
    }

    /// PNGs into `dir`: per technique the AO, the signed difference to the reference, FLIP's
    /// error map (magma: black = no visible difference, yellow-white = 1), and for
    /// the stenciled techniques the refined-samples heatmap, the ray-interval lengths and the
    /// SD-map layers; the reference AO too.
    pub fn write_images(&self, dir: &Path, frame: &Frame, gbuffer: &GBufferImage) -> io::Result<()> {
        std::fs::create_dir_all(dir)?;
        let (w, h) = (self.width, self.height);
        save(grey(w, h, &self.reference_ao), &dir.join("reference.png"))?;
        for r in &self.rows {
            save(grey(w, h, &r.ao), &dir.join(format!("{}.png", r.label)))?;
            save(signed_difference(w, h, &r.ao, &self.reference_ao), &dir.join(format!("{}_diff.png", r.label)))?;
            save(flip_heatmap(w, h, &r.flip_map), &dir.join(format!("{}_flip.png", r.label)))?;
            if let Some(debug) = &r.run.debug {
                let view = frame.camera.view;
                let counts: Vec<f32> =
                    crop_inner(&view, &debug.mask.iter().map(|m| m.count_ones() as f32).collect::<Vec<_>>());
                save(heatmap(w, h, &counts, 8.0), &dir.join(format!("{}_refined.png", r.label)))?;
                if !debug.ray_max.is_empty() {
                    let s = debug.sd_size;
                    save(
                        interval_lengths(s.x, s.y, &debug.ray_min, &debug.ray_max),
                        &dir.join(format!("{}_intervals.png", r.label)),
                    )?;
                }
                if !debug.sd_map.is_empty() {
                    save(sd_layers(debug, frame, gbuffer), &dir.join(format!("{}_sd_layers.png", r.label)))?;
                }
            }
        }
        Ok(())
    }

    /// A self-contained HTML page in `dir` that shows the PNGs from `images` side by side with
    /// the metrics table. Returns the page's path.
    pub fn write_html(&self, dir: &Path, images: &Path) -> io::Result<PathBuf> {
        std::fs::create_dir_all(dir)?;
        let rel = |name: &str| -> String {
            let p = images.join(name);
            let abs_dir = std::fs::canonicalize(dir).unwrap_or_else(|_| dir.to_path_buf());
            let abs = std::fs::canonicalize(&p).unwrap_or(p);
            abs.strip_prefix(&abs_dir).map(|r| r.display().to_string()).unwrap_or_else(|_| abs.display().to_string())
        };
        let mut rows = String::new();
        for r in &self.rows {
            let cells: Vec<String> = r.cells().iter().map(|c| format!("<td>{}</td>", html_escape(c))).collect();
            rows += &format!("<tr>{}</tr>\n", cells.concat());
        }
        let mut figures = format!(
            "<figure><img src=\"{}\" alt=\"reference\"><figcaption>reference: {}</figcaption></figure>\n",
            rel("reference.png"),
            self.reference.name()
        );
        let mut diffs = String::new();
        let mut flips = String::new();
        let mut extras = String::new();
        for r in &self.rows {
            figures += &format!(
                "<figure><img src=\"{}\" alt=\"{l}\"><figcaption>{l}</figcaption></figure>\n",
                rel(&format!("{}.png", r.label)),
                l = r.label
            );
            diffs += &format!(
                "<figure><img src=\"{}\" alt=\"{l} − reference\"><figcaption>{l} − reference</figcaption></figure>\n",
                rel(&format!("{}_diff.png", r.label)),
                l = r.label
            );
            flips += &format!(
                "<figure><img src=\"{}\" alt=\"{l} FLIP\"><figcaption>{l}: FLIP {f:.4}</figcaption></figure>\n",
                rel(&format!("{}_flip.png", r.label)),
                l = r.label,
                f = r.flip
            );
            for (suffix, what) in [
                ("refined", "refined samples per pixel (0–8)"),
                ("intervals", "ray-interval length per SD texel"),
                ("sd_layers", "SD-map layers, one colour per slot"),
            ] {
                let name = format!("{}_{suffix}.png", r.label);
                if images.join(&name).exists() {
                    extras += &format!(
                        "<figure><img src=\"{}\" alt=\"{l} {what}\"><figcaption>{l}: {what}</figcaption></figure>\n",
                        rel(&name),
                        l = r.label
                    );
                }
            }
        }
        let page = format!(
            r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>aokit compare — {scene}</title>
<style>
body {{ font-family: sans-serif; margin: 1.5em; background: #fafafa; color: #222; }}
table {{ border-collapse: collapse; margin-bottom: 1.5em; }}
th, td {{ border: 1px solid #bbb; padding: 0.3em 0.6em; text-align: right; }}
th:first-child, td:first-child {{ text-align: left; }}
.row {{ display: flex; flex-wrap: wrap; gap: 0.8em; }}
figure {{ margin: 0; flex: 1 1 30%; min-width: 280px; }}
img {{ width: 100%; image-rendering: pixelated; border: 1px solid #ccc; }}
figcaption {{ font-size: 0.9em; text-align: center; }}
</style></head><body>
<h1>aokit compare: {scene}</h1>
<p id="setup">Back-end <b>{backend}</b> ({device}), {w}×{h}, reference <b>{reference}</b>. Metrics on the final AO over the inner image. Difference images: red = brighter than the reference, blue = darker, full colour at |Δ| ≥ 0.25.</p>
<table id="metrics"><tr><th>technique</th><th>MSE</th><th>PSNR (dB)</th><th>SSIM</th><th>FLIP</th><th>rays</th><th>refined samples</th><th>Σ SD-ray interval</th><th>total ms</th><th>passes (ms)</th></tr>
{rows}</table>
<h2>Quality vs cost</h2>{plot}
<h2>AO</h2><div class="row">{figures}</div>
<h2>Signed difference to the reference</h2><div class="row">{diffs}</div>
<h2>FLIP error maps</h2><p>NVIDIA's FLIP (LDR, 67 pixels per degree) of each AO image against the reference, both as displayed grey levels: black = no visible difference, bright = clearly visible.</p><div class="row">{flips}</div>
<h2>Refinement, intervals, SD map</h2><div class="row">{extras}</div>
</body></html>
"#,
            scene = html_escape(&self.scene),
            backend = self.backend,
            device = html_escape(&self.device),
            w = self.width,
            h = self.height,
            reference = self.reference.name(),
            plot = self.quality_cost_figure(),
        );
        let path = dir.join("index.html");
        crate::output::write_atomic_bytes(&path, page.as_bytes())?;
        Ok(path)
    }
}

/// One technique on the quality–cost plot: its report label, total ms and MSE (the JSON's
/// `label`, `total_ms`, `mse`).
#[derive(Clone, Debug, PartialEq)]
pub struct PlotPoint {
    pub label: String,
    pub total_ms: f64,
    pub mse: f64,
}

/// The quality–cost plot's size in pixels.
pub const PLOT_SIZE: (u32, u32) = (760, 480);

impl CompareReport {
    /// The techniques a log–log plot can show (finite, positive MSE and time), in row order,
    /// and the labels of those it cannot (e.g. MSE 0: identical to the reference).
    pub fn plot_points(&self) -> (Vec<PlotPoint>, Vec<String>) {
        let (mut shown, mut left_out) = (Vec::new(), Vec::new());
        for r in &self.rows {
            if r.mse.is_finite() && r.mse > 0.0 && r.total_ms.is_finite() && r.total_ms > 0.0 {
                shown.push(PlotPoint { label: r.label.clone(), total_ms: r.total_ms, mse: r.mse });
            } else {
                left_out.push(r.label.clone());
            }
        }
        (shown, left_out)
    }

    /// The quality–cost plot as SVG (plotters): per technique its MSE against the reference vs
    /// its total ms, both axes logarithmic, one labelled point per technique (drawn in row
    /// order, a `<circle>` each); lower left is better. `None` when no technique has a
    /// positive MSE and time.
    pub fn quality_cost_svg(&self) -> Option<String> {
        use plotters::prelude::*;
        let (points, _) = self.plot_points();
        if points.is_empty() {
            return None;
        }
        let x = log_range(points.iter().map(|p| p.total_ms));
        let y = log_range(points.iter().map(|p| p.mse));
        let mut svg = String::new();
        let drawn = (|| -> Result<(), Box<dyn std::error::Error + '_>> {
            let root = SVGBackend::with_string(&mut svg, PLOT_SIZE).into_drawing_area();
            root.fill(&WHITE)?;
            let caption = format!("{}: MSE vs {} vs total time ({})", self.scene, self.reference.name(), self.backend);
            let mut chart = log_log_chart(&root, caption, x, y, "total ms (log)")?;
            chart.draw_series(points.iter().enumerate().map(|(i, p)| {
                let colour = Palette99::pick(i).to_rgba();
                EmptyElement::at((p.total_ms, p.mse))
                    + Circle::new((0, 0), 5, colour.filled())
                    + Text::new(p.label.clone(), (8, -16), ("sans-serif", 14).into_font())
            }))?;
            root.present()?;
            Ok(())
        })();
        drawn.ok().map(|()| svg)
    }

    /// The plot inside a `<figure id="quality-cost">` with a caption naming the techniques it
    /// cannot show.
    fn quality_cost_figure(&self) -> String {
        let (_, left_out) = self.plot_points();
        let note = if left_out.is_empty() {
            String::new()
        } else {
            format!(" Not drawn (MSE or time not positive): {}.", html_escape(&left_out.join(", ")))
        };
        match self.quality_cost_svg() {
            Some(svg) => format!(
                "<figure id=\"quality-cost\" class=\"plot\">{svg}<figcaption>MSE against the reference vs total time per \
                 technique, log–log; lower left is better.{note}</figcaption></figure>"
            ),
            None => format!("<p id=\"quality-cost\">No technique to plot.{note}</p>"),
        }
    }
}

/// `base`, or `base-N` when `taken` (the labels given so far) already holds `base` or `base-…`:
/// N counts them, from 2 on (`gtao`, `gtao-2`), so repeated techniques keep distinct labels and
/// file names.
pub fn numbered_label<'a>(base: String, taken: impl Iterator<Item = &'a str>) -> String {
    let n = taken.filter(|l| *l == base || l.starts_with(&format!("{base}-"))).count();
    if n == 0 { base } else { format!("{base}-{}", n + 1) }
}

/// A logarithmic axis range around positive `values`: padded by a quarter decade each side
/// (×/÷ 2 around values within a factor 1.5).
pub(crate) fn log_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, 0.0f64), |(lo, hi), x| (lo.min(x), hi.max(x)));
    let pad = if hi / lo < 1.5 { 2.0 } else { 10f64.powf(0.25) };
    (lo / pad, hi * pad)
}

/// A chart with logarithmic x and y axes.
pub(crate) type LogLogChart<'a, DB> = plotters::prelude::ChartContext<
    'a,
    DB,
    plotters::prelude::Cartesian2d<plotters::prelude::LogCoord<f64>, plotters::prelude::LogCoord<f64>>,
>;

/// The log–log chart of the reports' plots (MSE on y against a time on x): caption, axes,
/// light grid, labels.
pub(crate) fn log_log_chart<'a, DB: plotters::prelude::DrawingBackend>(
    root: &'a plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    caption: String,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
    x_desc: &str,
) -> Result<LogLogChart<'a, DB>, String> {
    use plotters::prelude::*;
    let mut chart = ChartBuilder::on(root)
        .caption(caption, ("sans-serif", 18))
        .margin(16)
        .x_label_area_size(44)
        .y_label_area_size(76)
        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc("MSE (log)")
        .axis_desc_style(("sans-serif", 15))
        .x_labels(8)
        .y_labels(8)
        .light_line_style(RGBColor(236, 236, 236))
        .x_label_formatter(&|v| if *v >= 10.0 { format!("{v:.0}") } else { format!("{v:.2}") })
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()
        .map_err(|e| e.to_string())?;
    Ok(chart)
}

fn finite_or_null(x: f64) -> serde_json::Value {
    if x.is_finite() { x.into() } else { serde_json::Value::Null }
}

fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

fn save(img: RgbImage, path: &Path) -> io::Result<()> {
    crate::output::save_image(&img, path)
}

fn grey(w: u32, h: u32, v: &[f32]) -> RgbImage {
    RgbImage::from_fn(w, h, |x, y| {
        let g = crate::metrics::display_grey(v[(y * w + x) as usize]);
        Rgb([g, g, g])
    })
}

/// FLIP's error map in NVIDIA's magma colour map (black at 0, light yellow at 1).
pub fn flip_heatmap(w: u32, h: u32, map: &[f32]) -> RgbImage {
    let coloured = nv_flip::FlipImageFloat::with_data(w, h, map).apply_color_lut(&nv_flip::magma_lut());
    RgbImage::from_raw(w, h, coloured.to_vec()).expect("w·h RGB texels")
}

/// Signed difference `a − b`: red where `a` is brighter, blue where darker, white at 0, full
/// colour at |Δ| ≥ 0.25.
pub fn signed_difference(w: u32, h: u32, a: &[f32], b: &[f32]) -> RgbImage {
    RgbImage::from_fn(w, h, |x, y| {
        let i = (y * w + x) as usize;
        let d = ((a[i] - b[i]) / 0.25).clamp(-1.0, 1.0);
        let fade = (255.0 * (1.0 - d.abs())).round() as u8;
        if d >= 0.0 { Rgb([255, fade, fade]) } else { Rgb([fade, fade, 255]) }
    })
}

/// A perceptually ordered ramp (black → blue → magenta → orange → yellow) of `t` ∈ [0, 1].
fn ramp(t: f32) -> Rgb<u8> {
    const STOPS: [[f32; 3]; 5] =
        [[0.0, 0.0, 0.0], [0.15, 0.1, 0.6], [0.7, 0.15, 0.55], [0.98, 0.5, 0.1], [1.0, 1.0, 0.6]];
    let t = t.clamp(0.0, 1.0) * (STOPS.len() - 1) as f32;
    let i = (t as usize).min(STOPS.len() - 2);
    let f = t - i as f32;
    let c = |k: usize| ((STOPS[i][k] * (1.0 - f) + STOPS[i + 1][k] * f) * 255.0).round() as u8;
    Rgb([c(0), c(1), c(2)])
}

/// Heatmap of `v / max`.
fn heatmap(w: u32, h: u32, v: &[f32], max: f32) -> RgbImage {
    RgbImage::from_fn(w, h, |x, y| ramp(v[(y * w + x) as usize] / max))
}

/// Ray-interval length `rayMax − rayMin` per SD texel (0 = unset → black), scaled to the
/// image's 99th percentile.
fn interval_lengths(w: u32, h: u32, ray_min: &[u32], ray_max: &[u32]) -> RgbImage {
    let lengths: Vec<f32> = ray_min
        .iter()
        .zip(ray_max)
        .map(|(&lo, &hi)| {
            if hi == 0 {
                return 0.0;
            }
            let lo = if lo == aokit_shaders::common::float_order::RAY_MIN_CLEAR { 0.0 } else { f32::from_bits(lo) };
            (f32::from_bits(hi) - lo).max(0.0)
        })
        .collect();
    let mut sorted: Vec<f32> = lengths.iter().copied().filter(|&l| l > 0.0).collect();
    sorted.sort_by(f32::total_cmp);
    let scale = sorted.get(sorted.len() * 99 / 100).copied().unwrap_or(1.0).max(1e-6);
    RgbImage::from_fn(w, h, |x, y| {
        let l = lengths[(y * w + x) as usize];
        if l > 0.0 { ramp(0.15 + 0.85 * l / scale) } else { Rgb([0, 0, 0]) }
    })
}

/// The SD map's layers side by side, each tinted with its slot's colour; brightness falls with
/// linear depth over the G-buffer's depth range; empty texels are black.
fn sd_layers(debug: &aokit_shaders::graph::Refinement, frame: &Frame, gbuffer: &GBufferImage) -> RgbImage {
    const COLOURS: [[f32; 3]; 8] = [
        [1.0, 0.3, 0.3],
        [0.3, 1.0, 0.3],
        [0.35, 0.5, 1.0],
        [1.0, 0.9, 0.3],
        [1.0, 0.4, 1.0],
        [0.3, 1.0, 1.0],
        [1.0, 0.6, 0.2],
        [0.8, 0.8, 0.8],
    ];
    let view = frame.camera.view;
    let (near, far) = (view.near, view.far);
    let max_depth = gbuffer.depth.iter().copied().filter(|&d| d < far).fold(near, f32::max);
    let (w, h, n) = (debug.sd_size.x, debug.sd_size.y, debug.layers);
    RgbImage::from_fn(w * n, h, |x, y| {
        let (slot, sx) = (x / w, x % w);
        let z = debug.sd_map[((y * w + sx) * n + slot) as usize];
        if z >= 1.0 {
            return Rgb([0, 0, 0]);
        }
        let d = z * (far - near) + near;
        let b = 1.0 - 0.8 * ((d - near) / (max_depth - near).max(1e-6)).clamp(0.0, 1.0);
        let c = COLOURS[slot as usize % COLOURS.len()];
        Rgb([(c[0] * b * 255.0) as u8, (c[1] * b * 255.0) as u8, (c[2] * b * 255.0) as u8])
    })
}

/// Per-pass timing statistics of `aokit bench`.
pub struct BenchResult {
    /// `(pass, median, min, max)` in ms, in pass order, then `total`.
    pub passes: Vec<(String, f64, f64, f64)>,
    /// Output megapixels per second at the median total time.
    pub mpixels_per_s: f64,
}

/// Median of `v` (sorts it).
pub fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 { v[n / 2] } else { 0.5 * (v[n / 2 - 1] + v[n / 2]) }
}

impl BenchResult {
    /// Statistics over frames, each a list of `(pass, ms)`; the inner image size gives Mpixel/s.
    pub fn new(frames: &[Vec<(&'static str, f64)>], inner: aokit_shaders::glam::UVec2) -> BenchResult {
        let mut names: Vec<&str> = Vec::new();
        for f in frames {
            for (n, _) in f {
                if !names.contains(n) {
                    names.push(n);
                }
            }
        }
        let stats = |mut v: Vec<f64>| {
            let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            (median(&mut v), lo, hi)
        };
        let mut passes = Vec::new();
        for n in names {
            let v: Vec<f64> = frames.iter().filter_map(|f| f.iter().find(|(m, _)| *m == n).map(|p| p.1)).collect();
            let (m, lo, hi) = stats(v);
            passes.push((n.to_string(), m, lo, hi));
        }
        let totals: Vec<f64> = frames.iter().map(|f| f.iter().map(|p| p.1).sum()).collect();
        let (m, lo, hi) = stats(totals);
        passes.push(("total".to_string(), m, lo, hi));
        let mpixels_per_s = inner.x as f64 * inner.y as f64 / (m * 1e-3) / 1e6;
        BenchResult { passes, mpixels_per_s }
    }

    pub fn json(&self) -> serde_json::Value {
        let mut v: Vec<_> = self
            .passes
            .iter()
            .map(|(n, m, lo, hi)| serde_json::json!({"name": n, "median_ms": m, "min_ms": lo, "max_ms": hi}))
            .collect();
        v.push(serde_json::json!({"name": "throughput", "mpixels_per_s": self.mpixels_per_s}));
        v.into()
    }

    pub fn table(&self) -> String {
        let mut s = format!("{:<14} {:>10} {:>10} {:>10}\n", "pass", "median ms", "min ms", "max ms");
        for (n, m, lo, hi) in &self.passes {
            s += &format!("{n:<14} {m:>10.2} {lo:>10.2} {hi:>10.2}\n");
        }
        s += &format!("{:.2} Mpixel/s (inner image at the median total)", self.mpixels_per_s);
        s
    }
}
