//! Nothing is lost when a run fails half-way: every output goes to a temporary file in the same
//! directory and is renamed over the destination (`aokit::output::write_atomic`), so a run killed
//! (SIGKILL, or SIGXFSZ in the middle of a write) or failing leaves the old file byte for byte or
//! a complete new one, never a truncated one; a normal run leaves no temporary file behind.
//!
//! A ground-truth render of sponza on the CPU (a couple of seconds) writes a PNG and an EXR over
//! old ones; it is killed at fixed delays (loading, tracing), at the moment the PNG's or the
//! EXR's write is seen starting (a temporary file appears or the destination changes), and by
//! the file-size limit while the PNG or the EXR is being written. A run whose EXR write fails
//! (the limit with SIGXFSZ ignored: EFBIG) reports one line naming the EXR, keeps the old EXR
//! and removes its temporary file.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_aokit");
const WIDTH: u32 = 240;
const HEIGHT: u32 = 180;
const SPP: u32 = 64;

fn render_args(dir: &Path) -> Vec<String> {
    let s = |x: &str| x.to_string();
    vec![
        s("render"),
        s("--backend"),
        s("cpu"),
        s("--scene"),
        s("sponza"),
        s("--technique"),
        s("groundtruth"),
        s("--spp"),
        SPP.to_string(),
        s("--width"),
        WIDTH.to_string(),
        s("--height"),
        HEIGHT.to_string(),
        s("--guard"),
        s("0"),
        s("--out"),
        dir.join("out.png").display().to_string(),
        s("--exr"),
        dir.join("out.exr").display().to_string(),
    ]
}

/// Old outputs: valid images of another size, so "old" and "new" both decode.
fn old_png() -> Vec<u8> {
    let mut out = std::io::Cursor::new(Vec::new());
    image::GrayImage::from_pixel(3, 2, image::Luma([77])).write_to(&mut out, image::ImageFormat::Png).unwrap();
    out.into_inner()
}

fn old_exr() -> Vec<u8> {
    let mut out = std::io::Cursor::new(Vec::new());
    image::Rgb32FImage::from_pixel(3, 2, image::Rgb([0.25; 3]))
        .write_to(&mut out, image::ImageFormat::OpenExr)
        .unwrap();
    out.into_inner()
}

/// A fresh folder holding only the old outputs.
fn reset(dir: &Path) {
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir).unwrap();
    std::fs::write(dir.join("out.png"), old_png()).unwrap();
    std::fs::write(dir.join("out.exr"), old_exr()).unwrap();
}

fn scratch(name: &str) -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("atomic_output-{name}-{}", std::process::id()))
}

fn entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

/// A normal run's outputs (the "new" files) and how long it took.
struct Reference {
    png: Vec<u8>,
    exr: Vec<u8>,
    seconds: f64,
}

/// One normal run over old outputs (shared by the tests; it also fills the scene cache before
/// any run is killed or limited): new, valid outputs and no temporary file left.
fn reference() -> &'static Reference {
    static REFERENCE: OnceLock<Reference> = OnceLock::new();
    REFERENCE.get_or_init(|| {
        let dir = scratch("reference");
        reset(&dir);
        let start = Instant::now();
        let out = Command::new(BIN).args(render_args(&dir)).output().unwrap();
        let seconds = start.elapsed().as_secs_f64();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        assert_eq!(entries(&dir), ["out.exr", "out.png"], "a normal run leaves no temporary file");
        let png = std::fs::read(dir.join("out.png")).unwrap();
        let exr = std::fs::read(dir.join("out.exr")).unwrap();
        check_png(&png).unwrap();
        check_exr(&exr).unwrap();
        eprintln!("reference render: {seconds:.2} s, PNG {} bytes, EXR {} bytes", png.len(), exr.len());
        std::fs::remove_dir_all(&dir).unwrap();
        Reference { png, exr, seconds }
    })
}

fn check_png(bytes: &[u8]) -> Result<(), String> {
    let img = image::load_from_memory_with_format(bytes, image::ImageFormat::Png).map_err(|e| e.to_string())?;
    match (img.width(), img.height()) {
        (WIDTH, HEIGHT) => Ok(()),
        size => Err(format!("PNG of {size:?}")),
    }
}

fn check_exr(bytes: &[u8]) -> Result<(), String> {
    let img = image::load_from_memory_with_format(bytes, image::ImageFormat::OpenExr).map_err(|e| e.to_string())?;
    match (img.width(), img.height()) {
        (WIDTH, HEIGHT) => Ok(()),
        size => Err(format!("EXR of {size:?}")),
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum State {
    Old,
    New,
}

/// The outputs in `dir` are each the old file byte for byte or a complete new one (decoded, and
/// the normal run's bytes: the render is deterministic); anything else in `dir` is a temporary
/// file of a killed run. Returns (PNG, EXR).
fn outputs(dir: &Path, when: &str) -> (State, State) {
    let r = reference();
    let one = |name: &str, old: &[u8], new: &[u8], check: fn(&[u8]) -> Result<(), String>| {
        let bytes = std::fs::read(dir.join(name)).unwrap_or_else(|e| panic!("{when}: {name}: {e}"));
        if bytes == old {
            return State::Old;
        }
        if let Err(e) = check(&bytes) {
            panic!("{when}: {name} is neither the old file nor a valid new one ({} bytes): {e}", bytes.len());
        }
        assert!(bytes == new, "{when}: {name} decodes but differs from a normal run's");
        State::New
    };
    let png = one("out.png", &old_png(), &r.png, check_png);
    let exr = one("out.exr", &old_exr(), &r.exr, check_exr);
    for name in entries(dir) {
        assert!(
            name == "out.png" || name == "out.exr" || aokit::output::is_temp_name(&name),
            "{when}: unexpected file {name}"
        );
    }
    (png, exr)
}

fn spawn(dir: &Path) -> Child {
    Command::new(BIN).args(render_args(dir)).stdout(Stdio::null()).stderr(Stdio::null()).spawn().unwrap()
}

/// Signs that the write of `name` in `dir` began: a temporary file of it, or the destination no
/// longer the old file (its size or modification time changed).
fn write_started(dir: &Path, name: &str, old: &std::fs::Metadata) -> Option<String> {
    let entries = std::fs::read_dir(dir).ok()?;
    for e in entries.flatten() {
        let n = e.file_name().to_string_lossy().into_owned();
        if n != name && n.contains(name) {
            return Some(format!("temporary file {n}"));
        }
    }
    let now = std::fs::metadata(dir.join(name)).ok()?;
    if now.len() != old.len() || now.modified().ok() != old.modified().ok() {
        return Some(format!("{name} changed ({} bytes)", now.len()));
    }
    None
}

#[test]
fn sigkill_leaves_old_or_complete_new_files() {
    let r = reference();
    let dir = scratch("sigkill");
    // Fixed delays: start-up and scene loading, tracing, and near the end (perhaps writing).
    let mut delays = vec![0.0, 0.15, 0.5 * r.seconds, 0.95 * r.seconds, 1.3 * r.seconds];
    delays.iter_mut().for_each(|d| *d = f64::min(*d, 20.0));
    for delay in delays {
        reset(&dir);
        let mut child = spawn(&dir);
        std::thread::sleep(Duration::from_secs_f64(delay));
        let _ = child.kill();
        let status = child.wait().unwrap();
        let when = format!("SIGKILL after {delay:.2} s");
        let state = outputs(&dir, &when);
        eprintln!("{when}: {state:?} (exit {status})");
    }
    // At the moment each output's write is seen starting: the interesting one.
    for name in ["out.png", "out.exr"] {
        reset(&dir);
        let old = std::fs::metadata(dir.join(name)).unwrap();
        let mut child = spawn(&dir);
        let start = Instant::now();
        let seen = loop {
            if let Some(what) = write_started(&dir, name, &old) {
                let _ = child.kill();
                break Some(what);
            }
            if child.try_wait().unwrap().is_some() {
                break None;
            }
            assert!(start.elapsed() < Duration::from_secs(120), "the render did not finish");
            std::thread::sleep(Duration::from_micros(100));
        };
        child.wait().unwrap();
        let when = match &seen {
            Some(what) => format!("SIGKILL at {what}"),
            None => format!("{name}: the run finished before its write was seen"),
        };
        let state = outputs(&dir, &when);
        eprintln!("{when}: {state:?}");
        if seen.is_some() && name == "out.exr" {
            assert_eq!(state.0, State::New, "{when}: the PNG was written before the EXR");
        }
        if seen.is_none() {
            assert_eq!(state, (State::New, State::New), "{when}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Run the render under `ulimit -f` (file size limit in the shell's blocks, 512 or 1024 bytes);
/// with `ignore`, SIGXFSZ is ignored and the over-long write fails with EFBIG instead of
/// killing the run.
fn limited(dir: &Path, blocks: u64, ignore: bool) -> Output {
    let trap = if ignore { "trap '' XFSZ; " } else { "" };
    Command::new("sh")
        .arg("-c")
        .arg(format!("{trap}ulimit -f {blocks} && exec \"$0\" \"$@\""))
        .arg(BIN)
        .args(render_args(dir))
        .output()
        .unwrap()
}

#[test]
fn killed_or_failing_in_the_middle_of_a_write() {
    use std::os::unix::process::ExitStatusExt;
    let r = reference();
    let dir = scratch("fsize");
    // A limit below the PNG: killed by SIGXFSZ while writing it, before the EXR.
    reset(&dir);
    let out = limited(&dir, 2, false);
    assert!(!out.status.success());
    let state = outputs(&dir, "SIGXFSZ while writing the PNG");
    assert_eq!(state, (State::Old, State::Old), "signal {:?}", out.status.signal());
    // Above the PNG (in 512-byte blocks), below the EXR (in 1024-byte blocks): the PNG is
    // replaced, the run is killed while writing the EXR.
    let blocks = r.png.len() as u64 / 512 + 2;
    assert!(blocks * 1024 < r.exr.len() as u64, "no limit between the PNG and the EXR");
    reset(&dir);
    let out = limited(&dir, blocks, false);
    assert!(!out.status.success());
    let state = outputs(&dir, "SIGXFSZ while writing the EXR");
    assert_eq!(state, (State::New, State::Old), "signal {:?}", out.status.signal());
    // The same limit with SIGXFSZ ignored: the EXR's write fails (EFBIG), the run reports one
    // line naming it, the old EXR stays and its temporary file is removed.
    reset(&dir);
    let out = limited(&dir, blocks, true);
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    let stderr = String::from_utf8_lossy(&out.stderr);
    let exr = dir.join("out.exr").display().to_string();
    let error: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error:")).collect();
    assert_eq!(error.len(), 1, "{stderr}");
    assert!(error[0].contains(&exr), "the error names the EXR: {stderr}");
    assert_eq!(stderr.trim_end().lines().last(), Some(error[0]), "one line: {stderr}");
    let state = outputs(&dir, "EFBIG writing the EXR");
    assert_eq!(state, (State::New, State::Old));
    assert_eq!(entries(&dir), ["out.exr", "out.png"], "the failed write's temporary file is removed");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `compare` writes JSON, PNGs and an HTML page over old ones: all replaced, all valid, no
/// temporary file left.
#[test]
fn compare_outputs_replace_old_ones_without_leftovers() {
    let dir = scratch("compare");
    let _ = std::fs::remove_dir_all(&dir);
    let html = dir.join("page");
    std::fs::create_dir_all(&html).unwrap();
    std::fs::write(dir.join("report.json"), "old").unwrap();
    std::fs::write(html.join("index.html"), "old").unwrap();
    std::fs::write(html.join("reference.png"), "old").unwrap();
    let out = Command::new(BIN)
        .args(["compare", "--backend", "cpu", "--scene", "cornell", "--width", "48", "--height", "32", "--guard", "8"])
        .args(["--techniques", "vao", "--reference", "groundtruth:spp=16", "--json"])
        .arg(dir.join("report.json"))
        .arg("--html")
        .arg(&html)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("report.json")).unwrap()).unwrap();
    assert!(json.is_object());
    let page = std::fs::read_to_string(html.join("index.html")).unwrap();
    assert!(page.starts_with("<!DOCTYPE html>") && page.trim_end().ends_with("</html>"));
    for name in entries(&html) {
        assert!(!aokit::output::is_temp_name(&name), "left behind: {name}");
        if name.ends_with(".png") {
            image::open(html.join(&name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        }
    }
    assert_eq!(entries(&dir), ["page", "report.json"]);
    std::fs::remove_dir_all(&dir).unwrap();
}
