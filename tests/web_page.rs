//! `aokit web`'s page in a real browser: the page is written for sponza and kitchen at 96×64 (guard 8),
//! served from this test's thread (std::net), and opened in headless Chromium with WebGPU on
//! SwiftShader. With `?test=1` the page runs every screen-space technique at its defaults (and
//! the configurations of `ALSO`) and POSTs the inner AO it read back from the GPU and the
//! constants it computed; this test compares the AO with cpu-sim on the same exported G-buffer
//! (the page's own reference files too) and the constants with the graph's push constants, then
//! checks the screenshot Chromium took once the page was done. Debian `chromium`; the test
//! fails without it unless the run allows its skip (tests/common/skip.rs).

mod common;

use aokit::output::crop_inner;
use aokit::technique::Technique;
use aokit_cpu::graph::{CpuExecutor, CpuInputs};
use aokit_shaders::common::camera::Camera;
use aokit_shaders::graph::FrameDesc;
use std::collections::HashMap;
use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Non-default configurations the page also runs, through its own controls (presets, graph
/// variants, table contents): `technique:key=value…` as `aokit render --technique` takes them.
/// At least three per technique the browser runs, one of them changing the graph where a
/// setting the browser can run does (hbao's only graph-changing setting, dual depth, needs a
/// second layer the export does not hold).
const ALSO: [&str; 16] = [
    "vao:kernel=hbao",
    "vao:ao-samples=16",
    "vao:kernel=hbao:ao-samples=32",
    "hbao:ao-samples=16",
    "hbao:ao-samples=32",
    "hbao:peel-separation=0.2:ao-samples=16",
    "gtao:preset=low:denoise=2",
    "gtao:preset=ultra:normals=depth",
    "gtao:bent-normals=on:denoise=0:falloff-range=0.3",
    "vbao:denoise=0",
    "vbao:normals=depth:sectors=touch",
    "vbao:weighting=cosine-exact:gate=radius:thickness=0.3",
    "raymarch:directions=8:kernel=vogel:denoise=1",
    "raymarch:directions=24:steps=4:contribution=binary",
    "raymarch:alpha=2:denoise=3",
    "raymarch:directions=61:kernel=vogel",
];

/// The scenes the page runs on.
const SCENES: [&str; 2] = ["sponza", "kitchen"];

fn is_root() -> bool {
    std::fs::read_to_string("/proc/self/status")
        .is_ok_and(|s| s.lines().any(|l| l.starts_with("Uid:") && l.split_whitespace().nth(1) == Some("0")))
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("aokit-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// What the page sent.
#[derive(Default)]
struct Received {
    results: HashMap<String, Vec<u8>>,
    constants: HashMap<String, String>,
    /// Per spec: `{resource: hex}` of the data words the page computed.
    data: HashMap<String, String>,
    failed: HashMap<String, String>,
    done: Option<String>,
    error: Option<String>,
}

/// One HTTP request: method, path (without the query), body.
fn read_request(stream: &mut TcpStream) -> Option<(String, String, Vec<u8>)> {
    stream.set_nonblocking(false).ok()?;
    stream.set_read_timeout(Some(Duration::from_secs(10))).ok()?;
    let mut data = Vec::new();
    let mut buf = [0u8; 65536];
    let header_end = loop {
        if let Some(i) = data.windows(4).position(|w| w == b"\r\n\r\n") {
            break i + 4;
        }
        let n = stream.read(&mut buf).ok()?;
        if n == 0 {
            return None;
        }
        data.extend_from_slice(&buf[..n]);
    };
    let head = String::from_utf8_lossy(&data[..header_end]).to_string();
    let mut first = head.lines().next()?.split_whitespace();
    let (method, target) = (first.next()?.to_string(), first.next()?.to_string());
    let length: usize = head
        .lines()
        .find_map(|l| l.split_once(':').filter(|(k, _)| k.eq_ignore_ascii_case("content-length")))
        .map_or(0, |(_, v)| v.trim().parse().unwrap_or(0));
    let mut body = data[header_end..].to_vec();
    while body.len() < length {
        let n = stream.read(&mut buf).ok()?;
        if n == 0 {
            break;
        }
        body.extend_from_slice(&buf[..n]);
    }
    let path = target.split('?').next().unwrap_or("/").to_string();
    Some((method, path, body))
}

fn respond(mut stream: TcpStream, status: &str, content_type: &str, body: &[u8]) {
    let head = format!(
        "HTTP/1.1 {status}\r\nContent-Type: {content_type}\r\nContent-Length: {}\r\nCache-Control: no-store\r\nConnection: close\r\n\r\n",
        body.len()
    );
    let _ = stream.write_all(head.as_bytes()).and_then(|_| stream.write_all(body));
}

/// A 1×1 GIF: the answer to the page's load-holding image.
const GIF: &[u8] = &[
    0x47, 0x49, 0x46, 0x38, 0x39, 0x61, 1, 0, 1, 0, 0x80, 0, 0, 0, 0, 0, 0xff, 0xff, 0xff, 0x21, 0xf9, 4, 1, 0, 0, 0,
    0, 0x2c, 0, 0, 0, 0, 1, 0, 1, 0, 0, 2, 2, 0x44, 1, 0, 0x3b,
];

fn serve_one(dir: &Path, mut stream: TcpStream, got: &mut Received, held: &mut Vec<TcpStream>) {
    let Some((method, path, body)) = read_request(&mut stream) else { return };
    let ok = |s: TcpStream| respond(s, "200 OK", "text/plain", b"ok");
    match (method.as_str(), path.as_str()) {
        ("GET", "/hold") => held.push(stream),
        ("POST", "/done") => {
            got.done = Some(String::from_utf8_lossy(&body).to_string());
            ok(stream);
        }
        ("POST", "/error") => {
            got.error = Some(String::from_utf8_lossy(&body).to_string());
            ok(stream);
        }
        ("POST", p) if p.starts_with("/result/") => {
            got.results.insert(decode(&p["/result/".len()..]), body);
            ok(stream);
        }
        ("POST", p) if p.starts_with("/failed/") => {
            got.failed.insert(decode(&p["/failed/".len()..]), String::from_utf8_lossy(&body).to_string());
            ok(stream);
        }
        ("POST", p) if p.starts_with("/data/") => {
            got.data.insert(decode(&p["/data/".len()..]), String::from_utf8_lossy(&body).to_string());
            ok(stream);
        }
        ("POST", p) if p.starts_with("/constants/") => {
            got.constants.insert(decode(&p["/constants/".len()..]), String::from_utf8_lossy(&body).to_string());
            ok(stream);
        }
        ("GET", p) => {
            let rel = p.trim_start_matches('/');
            let rel = if rel.is_empty() { "index.html" } else { rel };
            let file = dir.join(decode(rel));
            let inside = !rel.split('/').any(|c| c == "..");
            match std::fs::read(&file) {
                Ok(bytes) if inside => {
                    let mime = match file.extension().and_then(|e| e.to_str()) {
                        Some("html") => "text/html; charset=utf-8",
                        Some("js") => "text/javascript",
                        Some("json") => "application/json",
                        Some("wgsl") => "text/plain; charset=utf-8",
                        _ => "application/octet-stream",
                    };
                    respond(stream, "200 OK", mime, &bytes);
                }
                _ => respond(stream, "404 Not Found", "text/plain", b"not found"),
            }
        }
        _ => respond(stream, "405 Method Not Allowed", "text/plain", b""),
    }
}

/// `%xx` escapes of a URL path.
fn decode(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%'
            && i + 2 < b.len()
            && let Ok(v) = u8::from_str_radix(&s[i + 1..i + 3], 16)
        {
            out.push(v);
            i += 3;
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    String::from_utf8_lossy(&out).to_string()
}

fn words<T: bytemuck::Pod>(path: &Path) -> Vec<T> {
    bytemuck::pod_collect_to_vec(&std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display())))
}

#[test]
fn web_page_runs_the_screen_space_techniques_in_chromium_and_agrees_with_cpu_sim() {
    let Some(browser) = common::skip::chromium() else { return };
    for scene in SCENES {
        run_page(browser, scene);
    }
}

/// The page on `scene` at 96×64 (guard 8): every technique at its defaults and [`ALSO`].
fn run_page(browser: &str, scene: &str) {
    let start = Instant::now();
    let dir = scratch(&format!("web-{scene}"));
    let site = dir.join("site");
    let out = Command::new(env!("CARGO_BIN_EXE_aokit"))
        .args(["web", "--scene", scene, "--width", "96", "--height", "64", "--guard", "8", "--out"])
        .arg(&site)
        .output()
        .unwrap();
    assert!(out.status.success(), "aokit web failed: {}", String::from_utf8_lossy(&out.stderr));
    let written = start.elapsed();

    // The frame and G-buffer the page runs on, from the files it loads.
    let export: serde_json::Value = serde_json::from_slice(&std::fs::read(site.join("export.json")).unwrap()).unwrap();
    let camera: Camera = bytemuck::pod_read_unaligned(&std::fs::read(site.join("camera.bin")).unwrap());
    let number = |k: &str| export[k].as_f64().unwrap() as f32;
    let desc = FrameDesc::new(camera, number("radius"), number("exponent"), number("thickness"));
    let depth: Vec<f32> = words(&site.join("gbuffer_depth.f32"));
    let normals: Vec<u32> = words(&site.join("gbuffer_normals.u32"));
    let web: serde_json::Value = serde_json::from_slice(&std::fs::read(site.join("web.json")).unwrap()).unwrap();
    let names: Vec<String> =
        web["techniques"].as_array().unwrap().iter().map(|t| t["name"].as_str().unwrap().to_string()).collect();
    for t in ["vao", "gtao", "raymarch"] {
        assert!(names.iter().any(|n| n == t), "web.json lacks {t}: {names:?}");
    }

    // Serve the folder and open the page.
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    listener.set_nonblocking(true).unwrap();
    let port = listener.local_addr().unwrap().port();
    let shot = dir.join("screenshot.png");
    let url = format!("http://127.0.0.1:{port}/index.html?test=1&also={}", ALSO.join(","));
    let log = std::fs::File::create(dir.join("chromium.log")).unwrap();
    let mut cmd = Command::new(browser);
    cmd.args([
        "--headless=new",
        "--enable-unsafe-webgpu",
        "--use-webgpu-adapter=swiftshader",
        "--hide-scrollbars",
        "--no-first-run",
        "--window-size=1200,760",
    ]);
    if is_root() {
        cmd.arg("--no-sandbox");
    }
    let mut child = cmd
        .arg(format!("--user-data-dir={}", dir.join("profile").display()))
        .arg(format!("--screenshot={}", shot.display()))
        .arg(&url)
        .stdout(Stdio::null())
        .stderr(log)
        .spawn()
        .unwrap();
    let mut got = Received::default();
    let mut held = Vec::new();
    let deadline = Instant::now() + Duration::from_secs(90);
    let exited = loop {
        match listener.accept() {
            Ok((stream, _)) => serve_one(&site, stream, &mut got, &mut held),
            Err(e) if e.kind() == std::io::ErrorKind::WouldBlock => std::thread::sleep(Duration::from_millis(5)),
            Err(e) => panic!("accept: {e}"),
        }
        if got.done.is_some() || got.error.is_some() {
            for s in held.drain(..) {
                respond(s, "200 OK", "image/gif", GIF);
            }
        }
        if let Some(status) = child.try_wait().unwrap() {
            break Some(status);
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
    };
    let browser_time = start.elapsed() - written;
    eprintln!("{scene}: aokit web {:.1} s, browser {:.1} s", written.as_secs_f64(), browser_time.as_secs_f64());
    // Chromium's profile is large; the page, the log and the screenshot stay.
    let _ = std::fs::remove_dir_all(dir.join("profile"));
    let chromium_log = std::fs::read_to_string(dir.join("chromium.log")).unwrap_or_default();
    let tail: String = chromium_log.lines().filter(|l| !l.contains("dbus")).take(40).collect::<Vec<_>>().join("\n");
    assert!(got.error.is_none(), "the page failed: {}", got.error.unwrap());
    assert!(exited.is_some(), "Chromium did not finish within 90 s; the page sent {:?}\n{tail}", got.results.keys());
    let adapter = got.done.clone().unwrap_or_else(|| panic!("the page never reported done\n{tail}"));

    // The page's AO against cpu-sim on the same G-buffer, and its constants against the graph's.
    let runs: Vec<String> = names.iter().cloned().chain(ALSO.iter().map(|s| s.to_string())).collect();
    let mut failures = Vec::new();
    for spec in &runs {
        let technique = Technique::parse(spec).unwrap();
        let graph = technique.graph(&desc).unwrap();
        let mut cpu = CpuExecutor::new();
        let inputs = CpuInputs {
            depth: &depth,
            normals: &normals,
            second_depth: None,
            scene: None,
            progress: &aokit_cpu::no_progress,
        };
        cpu.run(&graph, &inputs).unwrap();
        let reference = crop_inner(&graph.view, cpu.f32(graph.output).unwrap());
        if !spec.contains(':') {
            let written: Vec<f32> = words(&site.join(format!("reference/{spec}.f32")));
            assert_eq!(written, reference, "{spec}: aokit web's reference is not cpu-sim's AO");
        }
        let Some(bytes) = got.results.get(spec.as_str()) else {
            let why = got.failed.get(spec.as_str()).map_or("no result from the page", |s| s.as_str());
            let why = why.lines().next().unwrap_or_default();
            failures.push(format!("{scene} {spec}: {why}"));
            continue;
        };
        let page: Vec<f32> = bytemuck::pod_collect_to_vec(bytes);
        assert_eq!(page.len(), reference.len(), "{spec}: the page sent {} pixels", page.len());
        let n = page.len() as f64;
        let within =
            page.iter().zip(&reference).filter(|(a, b)| (*a - *b).abs() <= common::agreement::STEP).count() as f64 / n;
        let mse = page.iter().zip(&reference).map(|(a, b)| ((a - b) as f64).powi(2)).sum::<f64>() / n;
        let max = page.iter().zip(&reference).map(|(a, b)| (a - b).abs()).fold(0.0f32, f32::max);
        let occluded = reference.iter().filter(|&&v| v < 0.9).count() as f64 / n;
        eprintln!(
            "{scene:8} {spec:52} browser vs cpu-sim: {:7.3} % within 1/255, max |Δ| {max:.2e}, MSE {mse:.2e}, reference occluded {:.1} %",
            100.0 * within,
            100.0 * occluded
        );
        if occluded <= 0.02 {
            failures.push(format!("{spec}: the reference is (nearly) white: {:.2} % occluded", 100.0 * occluded));
        }
        // What the page computed from the manifest — every push-constant block and every data
        // resource's words — is checked byte for byte below; the AO then differs from cpu-sim
        // only by SwiftShader's arithmetic (its trigonometry and division are not binary32
        // exact: the same WGSL on lavapipe through wgpu agrees to the conformance bar,
        // tests/wgsl_wgpu.rs). The bar here catches a wrong pass, binding or buffer (a blur in
        // the wrong direction or a missing denoise pass moves the MSE above 1e-4 on these
        // scenes), not SwiftShader's flipped march steps (MSE up to 2.4e-5 measured).
        if mse > 5e-5 {
            failures.push(format!("{scene} {spec}: {:.3} % within 1/255, MSE {mse:.2e}", 100.0 * within));
        }
        let sent: serde_json::Value = serde_json::from_str(&got.data[spec.as_str()]).unwrap();
        for r in &graph.resources {
            let aokit_shaders::graph::Init::Data(words) = &r.init else { continue };
            let hex: String = words.iter().flat_map(|w| w.to_le_bytes()).map(|b| format!("{b:02x}")).collect();
            if sent[r.name] != hex.as_str() {
                failures.push(format!("{scene} {spec}: data {}\n  page {}\n  rust {hex}", r.name, sent[r.name]));
            }
        }
        // The constants the page computed in JS, byte for byte those of the Rust graph.
        let sent: serde_json::Value = serde_json::from_str(&got.constants[spec.as_str()]).unwrap();
        let sent = sent.as_array().unwrap();
        assert_eq!(sent.len(), graph.passes.len(), "{spec}: pass count");
        for (i, (pass, s)) in graph.passes.iter().zip(sent).enumerate() {
            let hex: String = pass.push_constants.iter().map(|b| format!("{b:02x}")).collect();
            assert_eq!(s["entry"], pass.entry(), "{spec}: pass {i}");
            if s["hex"] != hex.as_str() {
                failures.push(format!(
                    "{spec}: pass {i} ({}) constants\n  page {}\n  rust {hex}",
                    pass.entry(),
                    s["hex"]
                ));
            }
        }
    }

    assert!(failures.is_empty(), "{}", failures.join("\n"));

    // The screenshot Chromium took once the page had sent everything: the AO on its canvas.
    let img = image::open(&shot).unwrap_or_else(|e| panic!("{}: {e}\n{tail}", shot.display())).to_rgb8();
    let (mut grey, mut colours) = (0usize, std::collections::HashSet::new());
    for p in img.pixels() {
        let [r, g, b] = p.0.map(i32::from);
        if (r - g).abs() < 4 && (g - b).abs() < 4 && (40..225).contains(&r) {
            grey += 1;
        }
        colours.insert(p.0);
    }
    let total = (img.width() * img.height()) as usize;
    eprintln!(
        "adapter {adapter}; screenshot {} {}×{}: {:.1} % mid-grey, {} colours; aokit web {:.1} s, browser {:.1} s",
        shot.display(),
        img.width(),
        img.height(),
        100.0 * grey as f64 / total as f64,
        colours.len(),
        written.as_secs_f64(),
        browser_time.as_secs_f64()
    );
    assert!(grey > total / 10, "the AO is not visible in the screenshot ({grey} of {total} pixels mid-grey)");
    assert!(colours.len() > 64, "the screenshot is (nearly) blank: {} colours", colours.len());
}
