//! Nothing is lost when a run fails half-way: every output goes to a temporary file in the same
//! directory and is renamed over the destination (`aokit::output::write_atomic`), so a run killed
//! (SIGKILL, or SIGXFSZ in the middle of a write) or failing leaves the old file byte for byte or
//! a complete new one, never a truncated one; a normal run leaves no temporary file behind.
//!
//! A ground-truth render of sponza on the CPU (a couple of seconds) writes a PNG and an EXR over
//! old ones; it is killed at fixed delays (loading, tracing), in the middle of the PNG's and of
//! the EXR's write (stopped once its temporary file holds bytes, confirmed unfinished, then
//! SIGKILLed; asserted to have happened), and by
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

/// The temporary file of `name` in `dir` once bytes have reached it (its write has begun):
/// (file name, length).
fn temp_with_bytes(dir: &Path, name: &str) -> Option<(String, u64)> {
    for e in std::fs::read_dir(dir).ok()?.flatten() {
        let n = e.file_name().to_string_lossy().into_owned();
        if aokit::output::is_temp_name(&n)
            && n.starts_with(&format!(".{name}."))
            && let Ok(m) = e.metadata()
            && m.len() > 0
        {
            return Some((n, m.len()));
        }
    }
    None
}

const SIGKILL: i32 = 9;
/// Linux's SIGSTOP (x86, ARM, RISC-V).
const SIGSTOP: i32 = 19;

unsafe extern "C" {
    /// libc's `kill(2)` (std links libc; the test crate has no libc dependency).
    fn kill(pid: i32, sig: i32) -> i32;
}

fn signal(pid: i32, sig: i32) {
    // SAFETY: kill(2) with a child's pid and a signal number has no memory effects.
    let rc = unsafe { kill(pid, sig) };
    assert_eq!(rc, 0, "kill({pid}, {sig}): {}", std::io::Error::last_os_error());
}

/// Wait until `pid` is in the stopped state (/proc/<pid>/stat field 3 is `T`), or gone.
fn wait_stopped(pid: i32) {
    let start = Instant::now();
    loop {
        let Ok(stat) = std::fs::read_to_string(format!("/proc/{pid}/stat")) else { return };
        let state = stat.rsplit_once(')').and_then(|(_, rest)| rest.split_whitespace().next());
        if matches!(state, Some("T" | "t" | "Z" | "X")) {
            return;
        }
        assert!(start.elapsed() < Duration::from_secs(10), "pid {pid} did not stop: {stat}");
        std::thread::sleep(Duration::from_micros(20));
    }
}

#[test]
fn sigkill_leaves_old_or_complete_new_files() {
    use std::os::unix::process::ExitStatusExt;
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
    // Mid-write, deterministically: poll for the output's temporary file holding bytes (its
    // write has begun), stop the run there (SIGSTOP, so it cannot finish the write while we
    // look), confirm the temporary file is still there and the destination still the old file
    // (the write has not completed), and only then SIGKILL it. A run that slips past the window
    // (the write done between poll and stop) is not counted and the attempt is repeated; the
    // test fails unless the kill lands mid-write for each output within `ATTEMPTS` runs.
    const ATTEMPTS: usize = 8;
    for (name, old_bytes) in [("out.png", old_png()), ("out.exr", old_exr())] {
        let mut caught = None;
        let mut log = Vec::new();
        for attempt in 1..=ATTEMPTS {
            reset(&dir);
            let mut child = spawn(&dir);
            let pid = child.id() as i32;
            let start = Instant::now();
            let stopped = loop {
                if let Some((temp, len)) = temp_with_bytes(&dir, name) {
                    signal(pid, SIGSTOP);
                    wait_stopped(pid);
                    break Some((temp, len));
                }
                if child.try_wait().unwrap().is_some() {
                    break None;
                }
                assert!(start.elapsed() < Duration::from_secs(120), "the render did not finish");
                std::thread::sleep(Duration::from_micros(50));
            };
            // Stopped (or exited): nothing changes in `dir` from here until the kill.
            let mid_write = stopped.as_ref().and_then(|(temp, _)| {
                let len = std::fs::metadata(dir.join(temp)).ok()?.len();
                (std::fs::read(dir.join(name)).ok()? == old_bytes).then_some(len)
            });
            let _ = child.kill();
            let status = child.wait().unwrap();
            let when = match (&stopped, mid_write) {
                (Some((temp, _)), Some(len)) => format!("SIGKILL while writing {name} ({temp}: {len} bytes)"),
                (Some((temp, len)), None) => format!("{name}: {temp} ({len} bytes) seen, but the write completed"),
                (None, _) => format!("{name}: the run finished before its write was seen"),
            };
            let state = outputs(&dir, &when);
            log.push(format!("attempt {attempt}: {when}: {state:?} (exit {status})"));
            if let Some(len) = mid_write {
                assert_eq!(status.signal(), Some(SIGKILL), "{when}: the run must die by SIGKILL ({status})");
                let png = if name == "out.exr" { State::New } else { State::Old };
                assert_eq!(state, (png, State::Old), "{when}");
                let temps: Vec<String> =
                    entries(&dir).into_iter().filter(|n| aokit::output::is_temp_name(n) && n.contains(name)).collect();
                assert_eq!(temps.len(), 1, "{when}: the killed write's temporary file stays: {temps:?}");
                let full = if name == "out.png" { r.png.len() } else { r.exr.len() } as u64;
                assert!(len > 0 && len <= full, "{when}: a partial write of the {full}-byte output");
                caught = Some(len);
                break;
            }
        }
        eprintln!("{}", log.join("\n"));
        assert!(caught.is_some(), "{name}: no run was killed in the middle of its write:\n{}", log.join("\n"));
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
