//! `aokit frontier`: the quality–cost frontier. Every technique at every quality preset (and the
//! settings `aokit tune` found, `docs/tuning.md`) is rendered on every camera of each scene and
//! scored against the 512-spp ground truth (spec gtao-raymarch-hybrid §5) with MSE, SSIM and
//! FLIP (spec gtao-raymarch-hybrid §6.1, §6.2, §6.4), beside its time per frame. A point is **Pareto-optimal** when no
//! other point has both a lower MSE and a lower time; the plot marks those points and joins them
//! into the frontier.
//!
//! The G-buffers (ray-cast) and the references come from cpu-sim for every back-end
//! ([`crate::tune::Inputs::Cpu`]): the techniques read identical G-buffers, and the references
//! are rendered and cached once. The screen-space techniques then score the same on both
//! back-ends to within their CPU ≡ Vulkan agreement; the ray-traced ones trace (or rasterize)
//! the scene on each back-end themselves and may differ a little more.

use crate::metrics::{ImageRef, flip, mse, ssim};
use crate::technique::{Describe, Technique};
use crate::tune::TuneSet;
use std::fmt::Write as _;

/// The settings `aokit tune` recommended at exponent 1 over sponza and the kitchen (all-scenes
/// rows of `docs/tuning.md`'s main table), drawn as `<technique>-tuned` points.
pub const TUNED: [&str; 3] = [
    "gtao:radius-multiplier=2.466:falloff-range=0.5266:sample-power=2.105:final-power=1.42:mip-offset=1.41",
    "vbao:radius-multiplier=1.744:sample-power=2.067:final-power=1.057:mip-offset=2.804:thickness=1.493",
    "raysd:cutoff=0",
];

/// One technique at one setting, as the frontier names it.
#[derive(Clone, Debug)]
pub struct Candidate {
    /// `name` for the defaults, `name-preset` for a preset, `name-tuned` for [`TUNED`].
    pub label: String,
    /// The technique with its settings.
    pub technique: Technique,
}

impl Candidate {
    /// Candidates for techniques given by the user, labelled [`Technique::label`] and numbered
    /// from the second of a repeated label on ([`crate::report::numbered_label`], as `aokit
    /// compare` does).
    pub fn labelled(techniques: Vec<Technique>) -> Vec<Candidate> {
        let mut out: Vec<Candidate> = Vec::new();
        for technique in techniques {
            let label = crate::report::numbered_label(technique.label(), out.iter().map(|c| c.label.as_str()));
            out.push(Candidate { label, technique });
        }
        out
    }
}

/// Every registered technique but the reference: each at every quality preset (its `preset`
/// setting's choices but `custom`), or at its defaults where it has none, at full resolution and
/// at half resolution (`-half`, docs/algorithms/half-resolution.md); then the [`TUNED`] settings
/// (when `tuned`).
pub fn candidates(reference: &str, tuned: bool) -> Result<Vec<Candidate>, String> {
    use aokit_shaders::technique::{Kind, Resolution};
    let mut out = Vec::new();
    for registered in aokit_shaders::techniques::TECHNIQUES {
        let name = registered.name();
        if name == reference {
            continue;
        }
        let t = Technique::named(name)?;
        let presets = t.rows().iter().find(|r| r.key == "preset").map(|r| r.kind);
        match presets {
            Some(Kind::Choice(choices)) => {
                for &preset in choices.iter().filter(|&&c| c != "custom") {
                    out.push(Candidate {
                        label: format!("{name}-{preset}"),
                        technique: Technique::preset(name, preset)?,
                    });
                }
            }
            _ => out.push(Candidate { label: name.to_string(), technique: t }),
        }
    }
    let halves: Vec<Candidate> = out
        .iter()
        .map(|c| Candidate {
            label: format!("{}-half", c.label),
            technique: c.technique.clone().with_resolution(Resolution::half()),
        })
        .collect();
    out.extend(halves);
    if tuned {
        for spec in TUNED {
            let technique = Technique::parse(spec)?;
            out.push(Candidate { label: format!("{}-tuned", technique.name()), technique });
        }
    }
    Ok(out)
}

/// A candidate's scores on one scene: means over the scene's cameras.
#[derive(Clone, Debug)]
pub struct Point {
    /// The candidate's label.
    pub label: String,
    /// `name:key=value…` of the settings that differ from the defaults.
    pub spec: String,
    /// The technique with its settings.
    pub technique: Technique,
    /// MSE against the reference (spec gtao-raymarch-hybrid §6.1).
    pub mse: f64,
    /// SSIM against the reference (spec gtao-raymarch-hybrid §6.2).
    pub ssim: f64,
    /// Mean LDR-FLIP against the reference (spec gtao-raymarch-hybrid §6.4).
    pub flip: f64,
    /// Time per frame in ms: per camera the median over the timed frames of the sum of the
    /// technique's passes (acceleration-structure builds excluded), then the mean over cameras.
    pub ms: f64,
    /// No other point of the scene has both a lower MSE and a lower time ([`pareto_optimal`]).
    pub pareto: bool,
}

/// One scene's frontier.
#[derive(Clone, Debug)]
pub struct SceneFrontier {
    /// The scene's name.
    pub scene: String,
    /// The cameras the scores are averaged over.
    pub cameras: Vec<String>,
    /// The world-space AO radius (the scene's, the same for every camera).
    pub radius: f32,
    /// One point per candidate, in the candidates' order.
    pub points: Vec<Point>,
}

/// For each `(mse, ms)` point: whether it is Pareto-optimal, i.e. finite and no other point has
/// both a lower MSE and a lower time (ties dominate nothing, so equal points are all optimal).
pub fn pareto_optimal(points: &[(f64, f64)]) -> Vec<bool> {
    points
        .iter()
        .map(|&(m, t)| m.is_finite() && t.is_finite() && !points.iter().any(|&(m2, t2)| m2 < m && t2 < t))
        .collect()
}

/// Score every candidate on every scene of `set` (the techniques run on its device, `frames` ≥ 1
/// timed runs per camera after one untimed, whose image is scored); `on_point` hears each
/// finished candidate.
pub fn measure(
    set: &TuneSet,
    candidates: &[Candidate],
    frames: usize,
    on_point: &mut dyn FnMut(&str, &Point),
) -> Result<Vec<SceneFrontier>, String> {
    if frames == 0 {
        return Err("--frames must be at least 1".into());
    }
    let mut out = Vec::new();
    for (s, scene) in set.scenes.iter().enumerate() {
        let mut points = Vec::new();
        for c in candidates {
            let (mut m, mut q, mut f, mut ms) = (0.0, 0.0, 0.0, 0.0);
            for (v, view) in scene.views.iter().enumerate() {
                let (ao, _) = set.evaluate(s, v, &c.technique)?;
                let mut times = Vec::new();
                for _ in 0..frames {
                    times.push(set.evaluate(s, v, &c.technique)?.1);
                }
                let (w, h) = (view.frame.inner.x as usize, view.frame.inner.y as usize);
                let a = ImageRef { width: w, height: h, pixels: &ao };
                let r = ImageRef { width: w, height: h, pixels: view.reference() };
                m += mse(a, r, None).unwrap_or(f64::NAN);
                q += ssim(a, r, None).unwrap_or(f64::NAN);
                f += flip(r, a, None).unwrap_or(f64::NAN);
                ms += crate::report::median(&mut times);
            }
            let n = scene.views.len() as f64;
            let point = Point {
                label: c.label.clone(),
                spec: crate::tune::spec(&c.technique),
                technique: c.technique.clone(),
                mse: m / n,
                ssim: q / n,
                flip: f / n,
                ms: ms / n,
                pareto: false,
            };
            on_point(&scene.name, &point);
            points.push(point);
        }
        let optimal = pareto_optimal(&points.iter().map(|p| (p.mse, p.ms)).collect::<Vec<_>>());
        for (p, o) in points.iter_mut().zip(optimal) {
            p.pareto = o;
        }
        out.push(SceneFrontier {
            scene: scene.name.clone(),
            cameras: scene.views.iter().map(|v| v.camera.clone()).collect(),
            radius: scene.views[0].frame.radius,
            points,
        });
    }
    Ok(out)
}

/// Where and how a frontier was measured (for the table's header and the JSON).
#[derive(Clone, Debug)]
pub struct Setup {
    /// `cpu` or `vulkan`.
    pub backend: String,
    /// The device's name (the CPU's thread count on the CPU).
    pub device: String,
    /// Output width (inner image).
    pub width: u32,
    /// Output height (inner image).
    pub height: u32,
    /// Guard band in pixels on every side.
    pub guard: u32,
    /// AO exponent.
    pub exponent: f32,
    /// The reference's spec (`name:key=value…`).
    pub reference: String,
    /// Timed frames per technique and camera.
    pub frames: usize,
    /// Which points were measured, in words (for the header).
    pub candidates: String,
    /// e.g. the commit and the machine's load, as the caller knows them.
    pub note: String,
}

/// The frontier as Markdown: a header, then per scene a table sorted by time with the Pareto
/// points marked, and the plot (`<scene>_<backend>.svg` beside the file).
pub fn markdown(setup: &Setup, scenes: &[SceneFrontier]) -> String {
    let mut s = format!(
        "# Quality–cost frontier ({backend})\n\nGenerated by `aokit frontier --backend {backend}`: {candidates}, against \
         `{reference}` on every camera of each scene. MSE, SSIM and FLIP (NVIDIA's perceptual difference, LDR, 67 \
         pixels per degree) over the inner image, means over the cameras; time = the sum of the technique's passes \
         per frame (median of {frames} timed frames after one untimed, acceleration-structure builds excluded; \
         wall clock on the CPU, timestamp queries on Vulkan), mean over the cameras. **Pareto** (✓): no other row \
         has both a lower MSE and a lower time. G-buffers (ray-cast) and references are cpu-sim's on every \
         back-end: the screen-space techniques score the same on both to within their CPU ≡ Vulkan agreement, \
         the ray-traced ones trace or rasterize the scene on each back-end and may differ a little more.\n\n\
         - back-end `{backend}`: {device}\n- {w}×{h} + {guard} px guard band, exponent {exponent} (gtao and vbao \
         apply their own final power; docs/tuning.md, \"Which exponent\")\n- {note}\n",
        backend = setup.backend,
        candidates = setup.candidates,
        reference = setup.reference,
        frames = setup.frames,
        device = setup.device,
        w = setup.width,
        h = setup.height,
        guard = setup.guard,
        exponent = setup.exponent,
        note = setup.note,
    );
    for scene in scenes {
        let _ = write!(
            s,
            "\n## {} (camera{} {}; radius {})\n\n![{} frontier]({}_{}.svg)\n\n| technique | settings | MSE | SSIM | FLIP | ms | Pareto |\n|---|---|---|---|---|---|---|\n",
            scene.scene,
            if scene.cameras.len() > 1 { "s" } else { "" },
            scene.cameras.join(", "),
            scene.radius,
            scene.scene,
            scene.scene,
            setup.backend
        );
        let mut rows: Vec<&Point> = scene.points.iter().collect();
        rows.sort_by(|a, b| a.ms.total_cmp(&b.ms));
        for p in rows {
            let _ = writeln!(
                s,
                "| {} | `{}` | {:.3e} | {:.4} | {:.4} | {:.1} | {} |",
                p.label,
                p.spec,
                p.mse,
                p.ssim,
                p.flip,
                p.ms,
                if p.pareto { "✓" } else { "" }
            );
        }
    }
    s
}

/// The frontier as JSON: `{"backend", "device", "width", "height", "guard_band", "exponent",
/// "reference", "frames", "inputs", "note", "scenes": [{"scene", "cameras", "radius", "points": [{"label",
/// "technique", "spec", "options", "mse", "ssim", "flip", "ms", "pareto"}]}]}`.
pub fn json(setup: &Setup, scenes: &[SceneFrontier]) -> serde_json::Value {
    let num = |x: f64| if x.is_finite() { serde_json::json!(x) } else { serde_json::Value::Null };
    serde_json::json!({
        "backend": setup.backend, "device": setup.device, "width": setup.width, "height": setup.height,
        "guard_band": setup.guard, "exponent": setup.exponent, "reference": setup.reference, "frames": setup.frames,
        "inputs": "cpu-sim's ray-cast G-buffers and references on every back-end",
        "note": setup.note,
        "scenes": scenes.iter().map(|s| serde_json::json!({
            "scene": s.scene, "cameras": s.cameras, "radius": s.radius,
            "points": s.points.iter().map(|p| serde_json::json!({
                "label": p.label, "technique": p.technique.name(), "spec": p.spec, "options": p.technique.describe(),
                "mse": num(p.mse), "ssim": num(p.ssim), "flip": num(p.flip), "ms": num(p.ms), "pareto": p.pareto,
            })).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
    })
}

/// The plot's size in pixels.
pub const PLOT_SIZE: (u32, u32) = (900, 600);

/// One scene's frontier as an SVG (plotters): MSE vs time, both logarithmic; Pareto-optimal
/// points filled and joined by the frontier's staircase, the others hollow and grey; every point
/// labelled. Lower left is better. `None` when no point has a positive MSE and time.
pub fn svg(scene: &SceneFrontier, backend: &str, reference: &str) -> Option<String> {
    use plotters::prelude::*;
    let points: Vec<&Point> =
        scene.points.iter().filter(|p| p.mse.is_finite() && p.mse > 0.0 && p.ms.is_finite() && p.ms > 0.0).collect();
    if points.is_empty() {
        return None;
    }
    let x = crate::report::log_range(points.iter().map(|p| p.ms));
    let y = crate::report::log_range(points.iter().map(|p| p.mse));
    let mut frontier: Vec<(f64, f64)> = points.iter().filter(|p| p.pareto).map(|p| (p.ms, p.mse)).collect();
    frontier.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut steps = Vec::new();
    for (i, &(x, y)) in frontier.iter().enumerate() {
        if i > 0 {
            steps.push((x, frontier[i - 1].1));
        }
        steps.push((x, y));
    }
    let mut out = String::new();
    let drawn = (|| -> Result<(), Box<dyn std::error::Error + '_>> {
        let root = SVGBackend::with_string(&mut out, PLOT_SIZE).into_drawing_area();
        root.fill(&WHITE)?;
        let caption = format!("{}: MSE vs {reference} against time per frame ({backend})", scene.scene);
        let mut chart = crate::report::log_log_chart(&root, caption, x, y, "time per frame, ms (log)")?;
        let blue = RGBColor(31, 97, 170);
        chart.draw_series(std::iter::once(PathElement::new(steps, blue.stroke_width(2))))?;
        let grey = RGBColor(150, 150, 150);
        chart.draw_series(points.iter().map(|p| {
            let (style, text) =
                if p.pareto { (blue.filled(), blue.to_rgba()) } else { (grey.stroke_width(1), grey.to_rgba()) };
            EmptyElement::at((p.ms, p.mse))
                + Circle::new((0, 0), 5, style)
                + Text::new(p.label.clone(), (8, -14), ("sans-serif", 13).into_font().color(&text))
        }))?;
        root.present()?;
        Ok(())
    })();
    drawn.ok().map(|()| out)
}
