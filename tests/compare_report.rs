//! `aokit compare`'s report: the JSON contract, metrics that agree with `aokit::metrics`, the PNGs,
//! and the HTML page rendered by headless Chromium (Debian `chromium`; the test fails without it
//! unless the run allows its skip: tests/common/skip.rs).

mod common;

use aokit::metrics::{ImageRef, flip, ssim};
use aokit::render::CpuRenderer;
use aokit::report::{CompareReport, CompareSetup};
use aokit::technique::{SdOptions, Technique};
use aokit_shaders::svao::settings::{RAYSD, RAYSVAO};
use aokit_shaders::vao::settings::VAO;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The report, its frame, and the full-target final AO of the reference and of each technique
/// as the test computed them (not as the report stores them).
fn report(dir: &Path) -> (CompareReport, aokit::frame::Frame, Vec<f32>, Vec<Vec<f32>>) {
    report_of(dir, vec![Technique::new(&VAO, SdOptions::default()), Technique::new(&RAYSD, SdOptions::default())])
}

/// [`report`] of the given techniques.
fn report_of(dir: &Path, techniques: Vec<Technique>) -> (CompareReport, aokit::frame::Frame, Vec<f32>, Vec<Vec<f32>>) {
    let (scene, frame) = common::builtin_frame("sponza", 240, 136, 16);
    let cpu = CpuRenderer::new(&scene);
    let (g, gbuffer_ms) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
    let none = &aokit_cpu::no_progress;
    let reference = Technique::new(&RAYSVAO, SdOptions::default());
    let reference_run = cpu.run(&frame, &g, &reference, none);
    let runs: Vec<_> = techniques
        .into_iter()
        .map(|t| {
            let run = cpu.run(&frame, &g, &t, none);
            (t, run)
        })
        .collect();
    let finals = runs.iter().map(|(_, run)| run.ao_final.clone()).collect();
    let setup = CompareSetup { scene: "sponza", backend: "cpu", device: "test", gbuffer_ms };
    let r = CompareReport::new(setup, &frame, (reference, &reference_run), &runs);
    r.write_images(dir, &frame, &g).unwrap();
    (r, frame, reference_run.ao_final.clone(), finals)
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("aokit-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The JSON carries the contract's fields, and its numbers are the metrics of the cropped final
/// images: MSE and PSNR recomputed here from the technique's and the reference's full-target
/// AO (own crop to the inner 240×136, plain f64 sum, PSNR = 10·log10(1/MSE)); SSIM from
/// `aokit::metrics::ssim` (pinned against scikit-image in tests/metrics.rs) on the same crops.
#[test]
fn compare_json_follows_the_contract_and_matches_the_metrics() {
    let dir = scratch("json");
    let (r, frame, reference_full, finals) = report(&dir);
    let json = r.json();
    assert_eq!(json["scene"], "sponza");
    assert_eq!(json["backend"], "cpu");
    assert_eq!(json["width"], 240);
    assert_eq!(json["height"], 136);
    assert_eq!(json["reference"], "raysvao");
    let results = json["results"].as_array().unwrap();
    assert_eq!(results.len(), 2);
    assert_eq!(finals.len(), 2);
    let view = frame.camera.view;
    let (w, h) = (240usize, 136usize);
    for (full, result) in finals.iter().zip(results) {
        for key in
            ["technique", "options", "mse", "psnr", "ssim", "flip", "rays", "refined_samples", "passes", "total_ms"]
        {
            assert!(result.get(key).is_some(), "missing {key}");
        }
        let (a, reference) = common::inner_pair(&view, full, &reference_full);
        assert_eq!(a.len(), w * h);
        let mut sum = 0.0f64;
        for (x, y) in a.iter().zip(&reference) {
            sum += (*x as f64 - *y as f64).powi(2);
        }
        let expected_mse = sum / (w * h) as f64;
        let expected_psnr = 10.0 * (1.0 / expected_mse).log10();
        let (got_mse, got_psnr) = (result["mse"].as_f64().unwrap(), result["psnr"].as_f64().unwrap());
        assert!(expected_mse > 0.0);
        assert!((got_mse - expected_mse).abs() <= 1e-12 * expected_mse, "MSE {got_mse} vs {expected_mse}");
        assert!((got_psnr - expected_psnr).abs() <= 1e-9, "PSNR {got_psnr} vs {expected_psnr}");
        fn img(w: usize, h: usize, p: &[f32]) -> ImageRef<'_> {
            ImageRef { width: w, height: h, pixels: p }
        }
        let expected_ssim = ssim(img(w, h, &a), img(w, h, &reference), None).unwrap();
        assert!((result["ssim"].as_f64().unwrap() - expected_ssim).abs() <= 1e-12, "SSIM");
        // FLIP of the same crops (pinned against NVIDIA's flip-evaluator in tests/metrics.rs; LDR-FLIP
        // is symmetric, so the order is not what this checks); a visibly different technique is
        // well above 0.
        let expected_flip = flip(img(w, h, &reference), img(w, h, &a), None).unwrap();
        assert!((result["flip"].as_f64().unwrap() - expected_flip).abs() <= 1e-12, "FLIP");
        assert!(expected_flip > 0.01, "FLIP {expected_flip}");
        let passes = result["passes"].as_array().unwrap();
        let total: f64 = passes.iter().map(|p| p["ms"].as_f64().unwrap()).sum();
        assert!((total - result["total_ms"].as_f64().unwrap()).abs() < 1e-9);
        assert!(passes.iter().all(|p| p["name"].is_string()));
    }
    assert_eq!(results[1]["technique"], "raysd");
    assert!(results[1]["rays"].as_u64().unwrap() > 0);
    assert!(results[1]["refined_samples"].as_u64().unwrap() > 0);
    assert!(results[1]["mse"].as_f64().unwrap() < results[0]["mse"].as_f64().unwrap());
    for name in [
        "reference",
        "vao",
        "vao_diff",
        "vao_flip",
        "raysd",
        "raysd_diff",
        "raysd_flip",
        "raysd_refined",
        "raysd_intervals",
        "raysd_sd_layers",
    ] {
        assert!(dir.join(format!("{name}.png")).is_file(), "{name}.png missing");
    }
}

/// `name="value"` of an SVG element's attribute, as a number.
fn attr(element: &str, name: &str) -> f64 {
    let start =
        element.find(&format!(" {name}=\"")).unwrap_or_else(|| panic!("no {name} in {element}")) + name.len() + 3;
    let len = element[start..].find('"').unwrap();
    element[start..start + len].parse().unwrap()
}

/// Every `<tag …>` element of an SVG (the opening tag), and for `text` also its content.
fn elements<'a>(svg: &'a str, tag: &str) -> Vec<(&'a str, String)> {
    let open = format!("<{tag} ");
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find(&open) {
        let end = i + rest[i..].find('>').unwrap() + 1;
        let content = match rest[end..].find(&format!("</{tag}>")) {
            Some(close) if tag == "text" => rest[end..end + close].trim().to_string(),
            _ => String::new(),
        };
        out.push((&rest[i..end], content));
        rest = &rest[end..];
    }
    out
}

/// Least-squares line `y = a + b·x`; returns `(a, b, largest |residual|)`.
fn fit(points: &[(f64, f64)]) -> (f64, f64, f64) {
    let n = points.len() as f64;
    let (mx, my) = (points.iter().map(|p| p.0).sum::<f64>() / n, points.iter().map(|p| p.1).sum::<f64>() / n);
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let b = sxy / sxx;
    let a = my - b * mx;
    let worst = points.iter().map(|p| (p.1 - a - b * p.0).abs()).fold(0.0, f64::max);
    (a, b, worst)
}

/// The HTML report's quality–cost plot (plotters SVG, inline in the page): one `<circle>` per
/// technique, in the table's order, labelled with its name; the pixel positions are affine in
/// ln(total ms) and ln(MSE) of the report's JSON (log–log axes: a least-squares line through
/// all four points leaves at most 1 px, the rounding of plotters' integer coordinates), x grows
/// with time and y falls (up the page) as the MSE grows.
#[test]
fn quality_cost_plot_holds_one_point_per_technique_at_the_json_numbers() {
    let dir = scratch("plot");
    let techniques = vec![
        Technique::new(&VAO, SdOptions::default()),
        Technique::new(&RAYSD, SdOptions::default()),
        Technique::new(&aokit_shaders::svao::settings::HBAO, SdOptions::default()),
        Technique::named("gtao").unwrap(),
    ];
    let (r, _, _, _) = report_of(&dir, techniques);
    let json = r.json();
    let results = json["results"].as_array().unwrap();
    let svg = r.quality_cost_svg().expect("every technique has a positive MSE and time");
    let page = std::fs::read_to_string(r.write_html(&dir, &dir).unwrap()).unwrap();
    assert!(page.contains(&format!("<figure id=\"quality-cost\" class=\"plot\">{svg}")), "the page embeds the plot");
    let circles: Vec<(f64, f64)> =
        elements(&svg, "circle").iter().map(|(e, _)| (attr(e, "cx"), attr(e, "cy"))).collect();
    let texts: Vec<(f64, f64, String)> =
        elements(&svg, "text").into_iter().map(|(e, t)| (attr(e, "x"), attr(e, "y"), t)).collect();
    assert_eq!(circles.len(), results.len(), "one point per technique");
    let (mut xs, mut ys) = (Vec::new(), Vec::new());
    for (&(cx, cy), result) in circles.iter().zip(results) {
        let label = result["label"].as_str().unwrap();
        // Its label sits just right of and above the point.
        let near: Vec<_> =
            texts.iter().filter(|(x, y, _)| (0.0..30.0).contains(&(x - cx)) && (y - cy).abs() < 30.0).collect();
        assert!(near.iter().any(|t| t.2 == label), "no label {label} next to the point at ({cx}, {cy}): {near:?}");
        assert!((0.0..760.0).contains(&cx) && (0.0..480.0).contains(&cy));
        xs.push((result["total_ms"].as_f64().unwrap().ln(), cx));
        ys.push((result["mse"].as_f64().unwrap().ln(), cy));
    }
    let (_, bx, worst_x) = fit(&xs);
    let (_, by, worst_y) = fit(&ys);
    eprintln!("x = a + {bx:.2}·ln ms (worst {worst_x:.2} px), y = c + {by:.2}·ln MSE (worst {worst_y:.2} px)");
    assert!(bx > 0.0 && by < 0.0, "x grows with the time, y up the page with the MSE");
    assert!(worst_x <= 1.0 && worst_y <= 1.0, "not log–log at the JSON's numbers: {worst_x} px, {worst_y} px");
    // The spread of the data covers a real part of the plot (no degenerate axis).
    let spread = |v: &[(f64, f64)]| {
        v.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max) - v.iter().map(|p| p.1).fold(f64::INFINITY, f64::min)
    };
    assert!(spread(&xs) > 100.0 && spread(&ys) > 100.0, "{} {}", spread(&xs), spread(&ys));
}

/// The HTML page, rendered by headless Chromium: its DOM holds the metrics table with the
/// report's numbers, and the screenshot shows the AO images (grey) and the signed differences
/// (red and blue), i.e. the PNGs loaded.
#[test]
fn html_report_renders_in_headless_chromium() {
    let Some(browser) = common::skip::chromium() else { return };
    let dir = scratch("html");
    let (r, _, _, _) = report(&dir);
    let page = r.write_html(&dir, &dir).unwrap();
    let url = format!("file://{}", page.canonicalize().unwrap().display());
    let common_args =
        ["--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--allow-file-access-from-files"];
    let dom = Command::new(browser).args(common_args).arg("--dump-dom").arg(&url).output().unwrap();
    let dom = String::from_utf8_lossy(&dom.stdout);
    assert!(dom.contains("id=\"metrics\""), "metrics table missing from the DOM");
    assert!(dom.contains("id=\"quality-cost\""), "quality–cost plot missing from the DOM");
    assert_eq!(dom.matches("<circle ").count(), r.rows.len(), "one plotted point per technique in the DOM");
    for row in &r.rows {
        assert!(dom.contains(&format!("<td>{}</td>", row.label)), "row {} missing", row.label);
        assert!(dom.contains(&format!("{:.3e}", row.mse)), "MSE of {} missing", row.label);
        assert!(dom.contains(&format!("<td>{:.4}</td>", row.flip)), "FLIP of {} missing", row.label);
        assert!(dom.contains(&format!("{}_flip.png", row.label)), "FLIP map of {} missing", row.label);
    }
    let shot = dir.join("screenshot.png");
    let status = Command::new(browser)
        .args(common_args)
        .arg(format!("--screenshot={}", shot.display()))
        .arg("--window-size=1400,2400")
        .arg(&url)
        .output()
        .unwrap();
    assert!(shot.is_file(), "no screenshot: {}", String::from_utf8_lossy(&status.stderr));
    let img = image::open(&shot).unwrap().to_rgb8();
    let (mut grey, mut red, mut blue) = (0usize, 0usize, 0usize);
    for p in img.pixels() {
        let [r, g, b] = p.0.map(|c| c as i32);
        if (r - g).abs() < 6 && (g - b).abs() < 6 && (60..230).contains(&r) {
            grey += 1;
        }
        if r > 200 && g < 150 && b < 150 {
            red += 1;
        }
        if b > 200 && r < 150 && g < 150 {
            blue += 1;
        }
    }
    let total = (img.width() * img.height()) as usize;
    eprintln!("screenshot {}×{}: grey {grey}, red {red}, blue {blue}", img.width(), img.height());
    assert!(grey > total / 50, "AO images not visible in the screenshot");
    assert!(red + blue > 500, "difference images not visible in the screenshot");
}

/// `aokit bench`'s statistics: median (even and odd counts), min, max per pass and of the
/// per-frame total; Mpixel/s from the median total.
#[test]
fn bench_statistics_are_median_min_max_per_pass() {
    use aokit::report::BenchResult;
    use aokit_shaders::glam::uvec2;
    let frames = vec![
        vec![("a", 1.0), ("b", 10.0)],
        vec![("a", 3.0), ("b", 30.0)],
        vec![("a", 2.0), ("b", 20.0)],
        vec![("a", 7.0), ("b", 5.0)],
    ];
    let r = BenchResult::new(&frames, uvec2(1000, 1000));
    let get = |n: &str| r.passes.iter().find(|p| p.0 == n).map(|p| (p.1, p.2, p.3)).unwrap();
    assert_eq!(get("a"), (2.5, 1.0, 7.0));
    assert_eq!(get("b"), (15.0, 5.0, 30.0));
    // Totals 11, 33, 22, 12 → median 17, min 11, max 33.
    assert_eq!(get("total"), (17.0, 11.0, 33.0));
    assert!((r.mpixels_per_s - 1.0 / 0.017).abs() < 1e-9);
    let odd = BenchResult::new(&frames[..3], uvec2(10, 10));
    assert_eq!(odd.passes[0].1, 2.0);
}
