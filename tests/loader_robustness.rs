//! No byte sequence crashes a scene loader: mutated bytes of real scene files (the fuzz
//! seeds under `fuzz/seeds/`: the Cornell box, cut-down Sponza and kitchen, the oak tree, as OBJ
//! (+MTL), PLY ascii/binary/gzip, glTF and GLB) are fed to every loader, and each load must
//!
//! * return (a panic fails the test: `catch_unwind`) within a CPU-time budget of its thread;
//! * allocate no more than a small multiple of the bytes it was given: a count claimed by a
//!   header is checked against the bytes present before anything is allocated for it (measured
//!   with a per-thread counting allocator);
//! * on failure, give a one-line message that names the file and says what is wrong.
//!
//! The mutations: truncation at many points, bit flips, numbers in the text replaced by huge,
//! negative, NaN and infinite values (PLY `element vertex 10000000000`, an OBJ face index 2³¹,
//! a glTF accessor count 10⁹, …), 32-bit fields overwritten with huge counts, spliced bytes;
//! and a list of hand-made bad files (huge headers, indices out of range, NaN/Inf coordinates,
//! zero-area triangles, node cycles, instancing bombs, image bombs). The random part is a
//! proptest with a fixed seed, so every run tries the same cases.

use aokit::scene::{Scene, SceneError, SceneFormat, no_side_files};
use proptest::prelude::*;
use proptest::sample::Index;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::io::{self, Write};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::time::Duration;

// ---------------------------------------------------------------------------------------------
// Per-thread allocation accounting (tests run on several threads).

struct Counting;

thread_local! {
    static LIVE: Cell<isize> = const { Cell::new(0) };
    static PEAK: Cell<isize> = const { Cell::new(0) };
}

fn note(delta: isize) {
    let _ = LIVE.try_with(|live| {
        let now = live.get() + delta;
        live.set(now);
        let _ = PEAK.try_with(|peak| peak.set(peak.get().max(now)));
    });
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            note(layout.size() as isize);
        }
        p
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            note(layout.size() as isize);
        }
        p
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) };
        note(-(layout.size() as isize));
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            note(new_size as isize - layout.size() as isize);
        }
        p
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Run `f`, returning its result and the most bytes it had allocated at once (this thread).
fn peak_allocation<T>(f: impl FnOnce() -> T) -> (T, usize) {
    let base = LIVE.with(Cell::get);
    PEAK.with(|p| p.set(base));
    let out = f();
    (out, (PEAK.with(Cell::get) - base).max(0) as usize)
}

// ---------------------------------------------------------------------------------------------
// Per-thread CPU time. A wall-clock bound fails whenever the shared test machine stalls the
// thread (2 cores, other builds and tests), so a load's cost is the CPU time its own thread
// spent; the loaders start no threads.

/// CPU time (user + system) the calling thread has run: the first field of
/// `/proc/thread-self/schedstat` (nanoseconds on the CPU), or where that is missing (a kernel
/// without scheduler statistics) fields 14 and 15 of `/proc/thread-self/stat` (proc(5)), in
/// USER_HZ ticks of 10 ms, each rounded down (a difference may be off by 20 ms). `None` without
/// procfs: no budget is checked there.
fn thread_cpu_time() -> Option<Duration> {
    if let Ok(schedstat) = std::fs::read_to_string("/proc/thread-self/schedstat")
        && let Some(ns) = schedstat.split_whitespace().next().and_then(|f| f.parse().ok())
    {
        return Some(Duration::from_nanos(ns));
    }
    let stat = std::fs::read_to_string("/proc/thread-self/stat").ok()?;
    // Field 2, the command name, is in parentheses and may hold spaces: count after the last ')'.
    let fields: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
    let ticks: u64 = fields.get(11)?.parse::<u64>().ok()? + fields.get(12)?.parse::<u64>().ok()?;
    Some(Duration::from_millis(ticks * 10))
}

/// CPU-time budget of one load. Measured (schedstat, on the 2-core test machine,
/// `[profile.test]`): the costliest of the ~17 000 loads of this file (every seed, truncation,
/// mutation and hand-made file) runs 4 ms on its thread, most under 1 ms. The budget is over
/// 100 times that (and 25 times the 20 ms error of the tick-based fallback), so only a load
/// doing far more work than any of today's (a quadratic parse, an endless read) exceeds it,
/// however busy the machine.
const CPU_BUDGET: Duration = Duration::from_millis(500);

/// Run `f` and assert it stayed within [`CPU_BUDGET`] of this thread's CPU time.
fn within_cpu_budget<T>(what: &str, f: impl FnOnce() -> T) -> T {
    let before = thread_cpu_time();
    let out = f();
    if let (Some(before), Some(after)) = (before, thread_cpu_time()) {
        let used = after.saturating_sub(before);
        assert!(used <= CPU_BUDGET, "{what} used {used:?} of CPU time (budget {CPU_BUDGET:?})");
    }
    out
}

// ---------------------------------------------------------------------------------------------
// The real files.

#[derive(Clone, Debug)]
struct Seed {
    /// File name, as errors must show it.
    name: String,
    format: SceneFormat,
    bytes: Vec<u8>,
    /// The .mtl an OBJ's `mtllib` reads.
    mtl: Option<Vec<u8>>,
}

const MTL_SEPARATOR: &[u8] = b"\0MTL\0";

fn seeds_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/seeds")
}

/// The fuzz seeds (gzip seeds decompressed: the mutations go to the PLY inside, and the loader
/// is handed the mutated PLY gzip-compressed again).
fn seeds() -> Vec<Seed> {
    let mut out = Vec::new();
    for (dir, format) in [
        ("obj", SceneFormat::Obj),
        ("ply", SceneFormat::Ply),
        ("ply_gz", SceneFormat::PlyGz),
        ("gltf", SceneFormat::Gltf),
    ] {
        let mut entries: Vec<_> =
            std::fs::read_dir(seeds_dir().join(dir)).expect("fuzz/seeds").map(|e| e.unwrap().path()).collect();
        entries.sort();
        for path in entries {
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            let mut bytes = std::fs::read(&path).unwrap();
            let mut mtl = None;
            if let Some(at) = bytes.windows(MTL_SEPARATOR.len()).position(|w| w == MTL_SEPARATOR) {
                mtl = Some(bytes[at + MTL_SEPARATOR.len()..].to_vec());
                bytes.truncate(at);
            }
            if format == SceneFormat::PlyGz {
                let mut plain = Vec::new();
                io::Read::read_to_end(&mut flate2::read::GzDecoder::new(&bytes[..]), &mut plain).unwrap();
                bytes = plain;
            }
            out.push(Seed { name, format, bytes, mtl });
        }
    }
    assert!(out.len() >= 12, "expected the fuzz seeds of every loader, found {}", out.len());
    out
}

fn gzip(bytes: &[u8]) -> Vec<u8> {
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    gz.write_all(bytes).unwrap();
    gz.finish().unwrap()
}

// ---------------------------------------------------------------------------------------------
// One load, checked.

/// Allocation allowed for a load of `len` bytes: a fixed allowance plus a multiple of the input
/// (the parsers' own structures, the scene's 64 bytes per triangle).
fn allocation_bound(len: usize) -> usize {
    (8 << 20) + 96 * len
}

/// Load `bytes` as `seed`'s format and check the outcome; returns the scene or the message.
fn load(seed: &Seed, bytes: &[u8], case: &str) -> Result<Scene, String> {
    let name = Path::new(&seed.name);
    let mtl = seed.mtl.clone();
    let side = move |_: &Path| mtl.clone().ok_or_else(|| io::Error::from(io::ErrorKind::NotFound));
    let input = if seed.format == SceneFormat::PlyGz { gzip(bytes) } else { bytes.to_vec() };
    let (result, peak) = within_cpu_budget(&format!("{}: {case}", seed.name), || {
        peak_allocation(|| catch_unwind(AssertUnwindSafe(|| Scene::from_bytes(seed.format, name, &input, &side))))
    });
    let result = result.unwrap_or_else(|_| panic!("{}: the loader panicked on {case}", seed.name));
    let bound = allocation_bound(bytes.len().max(input.len()));
    assert!(peak <= bound, "{}: {case} allocated {peak} bytes at once for {} input bytes", seed.name, bytes.len());
    result.map_err(|e| check_message(&e, &seed.name, case))
}

fn check_message(e: &SceneError, name: &str, case: &str) -> String {
    let message = e.to_string();
    assert!(!message.contains(['\n', '\r']), "{name}: {case}: the message is not one line: {message:?}");
    assert!(message.contains(name), "{name}: {case}: the message does not name the file: {message}");
    let problem = message.split_once(name).map_or("", |(_, rest)| rest).trim_start_matches(':').trim();
    assert!(problem.len() >= 8, "{name}: {case}: the message does not say what is wrong: {message}");
    message
}

// ---------------------------------------------------------------------------------------------
// Mutations.

/// Replacements for numbers in text: huge counts and indices, negatives, NaN and infinities.
const NUMBERS: &[&str] = &[
    "0",
    "-1",
    "1",
    "2147483648",
    "-2147483649",
    "4294967296",
    "10000000000",
    "1000000000",
    "10000000",
    "18446744073709551616",
    "1e308",
    "-1e39",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "1e-45",
];

/// 32-bit values written over binary fields (counts, lengths, offsets).
const WORDS: &[u32] = &[0, 1, 0x7fff_ffff, 0x8000_0000, 0xffff_ffff, 1_000_000_000, 10_000_000, 0x7fc0_0000];

#[derive(Clone, Debug)]
enum Mutation {
    Truncate(Index),
    FlipBits(Vec<(Index, u8)>),
    /// Replace the i-th number of the text with `NUMBERS[j]`.
    Numbers(Vec<(Index, Index)>),
    /// Overwrite four bytes (little and big endian) with one of `WORDS`.
    Word {
        at: Index,
        word: Index,
        big_endian: bool,
    },
    Splice {
        at: Index,
        remove: usize,
        insert: Vec<u8>,
    },
    /// Copy a chunk of the file elsewhere (repeated structure, duplicated headers).
    Duplicate {
        from: Index,
        len: usize,
        to: Index,
    },
}

fn number_spans(bytes: &[u8]) -> Vec<(usize, usize)> {
    let mut spans = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let numeric = |b: u8| b.is_ascii_digit() || b == b'.' || b == b'e' || b == b'E';
        let starts =
            bytes[i].is_ascii_digit() || (bytes[i] == b'-' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit));
        if starts && (i == 0 || !bytes[i - 1].is_ascii_alphanumeric()) {
            let mut j = i + 1;
            while j < bytes.len() && (numeric(bytes[j]) || (bytes[j] == b'-' && matches!(bytes[j - 1], b'e' | b'E'))) {
                j += 1;
            }
            spans.push((i, j));
            i = j;
        } else {
            i += 1;
        }
    }
    spans
}

fn apply(m: &Mutation, bytes: &[u8]) -> Vec<u8> {
    let mut out = bytes.to_vec();
    if out.is_empty() {
        return out;
    }
    match m {
        Mutation::Truncate(at) => out.truncate(at.index(bytes.len())),
        Mutation::FlipBits(flips) => {
            for (at, bit) in flips {
                out[at.index(bytes.len())] ^= 1 << (bit % 8);
            }
        }
        Mutation::Numbers(replacements) => {
            let spans = number_spans(bytes);
            if spans.is_empty() {
                return out;
            }
            let mut chosen: Vec<(usize, usize, &str)> = replacements
                .iter()
                .map(|(i, j)| {
                    let (a, b) = spans[i.index(spans.len())];
                    (a, b, NUMBERS[j.index(NUMBERS.len())])
                })
                .collect();
            chosen.sort_by_key(|c| std::cmp::Reverse(c.0));
            chosen.dedup_by_key(|c| c.0);
            for (a, b, s) in chosen {
                out.splice(a..b, s.bytes());
            }
        }
        Mutation::Word { at, word, big_endian } => {
            let w = WORDS[word.index(WORDS.len())];
            let b = if *big_endian { w.to_be_bytes() } else { w.to_le_bytes() };
            let at = at.index(bytes.len());
            for (k, byte) in b.iter().enumerate() {
                if let Some(slot) = out.get_mut(at + k) {
                    *slot = *byte;
                }
            }
        }
        Mutation::Splice { at, remove, insert } => {
            let at = at.index(bytes.len());
            let end = (at + remove).min(bytes.len());
            out.splice(at..end, insert.iter().copied());
        }
        Mutation::Duplicate { from, len, to } => {
            let from = from.index(bytes.len());
            let chunk = bytes[from..(from + len).min(bytes.len())].to_vec();
            let to = to.index(bytes.len());
            out.splice(to..to, chunk);
        }
    }
    out
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        1 => any::<Index>().prop_map(Mutation::Truncate),
        1 => prop::collection::vec((any::<Index>(), any::<u8>()), 1..8).prop_map(Mutation::FlipBits),
        2 => prop::collection::vec((any::<Index>(), any::<Index>()), 1..4).prop_map(Mutation::Numbers),
        1 => (any::<Index>(), any::<Index>(), any::<bool>()).prop_map(|(at, word, big_endian)| Mutation::Word {
            at,
            word,
            big_endian
        }),
        1 => (any::<Index>(), 0usize..64, prop::collection::vec(any::<u8>(), 0..32))
            .prop_map(|(at, remove, insert)| Mutation::Splice { at, remove, insert }),
        1 => (any::<Index>(), 1usize..512, any::<Index>()).prop_map(|(from, len, to)| Mutation::Duplicate { from, len, to }),
    ]
}

// ---------------------------------------------------------------------------------------------
// The tests.

#[test]
fn the_seeds_load() {
    for seed in seeds() {
        let scene = load(&seed, &seed.bytes, "the unmodified file").unwrap_or_else(|e| panic!("{e}"));
        assert!(!scene.triangles.is_empty());
    }
}

/// Every seed cut at up to 400 points (every point of the small ones).
#[test]
fn truncation_at_many_points() {
    let mut cases = 0;
    for seed in seeds() {
        let n = seed.bytes.len();
        let step = n.div_ceil(400).max(1);
        for at in (0..n).step_by(step).chain([n - 1]) {
            let _ = load(&seed, &seed.bytes[..at], &format!("truncation at {at} of {n}"));
            cases += 1;
        }
    }
    eprintln!("truncation: {cases} cases");
}

const CASES: u32 = 10_000;

/// Random mutations of random seeds, from a fixed RNG seed (the same cases every run).
#[test]
fn mutated_real_files() {
    let seeds = seeds();
    let config = Config { cases: CASES, failure_persistence: None, ..Config::default() };
    let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &[12; 32]);
    let mut runner = TestRunner::new_with_rng(config, rng);
    let loaded = std::sync::atomic::AtomicUsize::new(0);
    let result = runner.run(&(any::<Index>(), prop::collection::vec(mutation(), 1..4)), |(seed, mutations)| {
        let seed = &seeds[seed.index(seeds.len())];
        let mut bytes = seed.bytes.clone();
        for m in &mutations {
            bytes = apply(m, &bytes);
        }
        if load(seed, &bytes, &format!("{mutations:?}")).is_ok() {
            loaded.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    eprintln!("mutations: {CASES} cases, {} still loaded", loaded.into_inner());
}

fn seed(format: SceneFormat, name: &str, bytes: impl Into<Vec<u8>>) -> Seed {
    Seed { name: name.into(), format, bytes: bytes.into(), mtl: None }
}

fn must_fail(format: SceneFormat, name: &str, bytes: impl Into<Vec<u8>>, expect: &str) -> String {
    let s = seed(format, name, bytes);
    let message = load(&s, &s.bytes, "a hand-made bad file").map(|_| ()).expect_err(name);
    assert!(message.contains(expect), "{name}: expected '{expect}' in: {message}");
    message
}

const PLY_XYZ: &str = "property float x\nproperty float y\nproperty float z\n";

#[test]
fn huge_counts_are_refused_before_allocating() {
    use SceneFormat::*;
    // PLY: counts far beyond the bytes present, ascii and binary, vertex and face.
    for format in ["ascii", "binary_little_endian", "binary_big_endian"] {
        let header = format!(
            "ply\nformat {format} 1.0\nelement vertex 10000000000\n{PLY_XYZ}element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n"
        );
        must_fail(Ply, "huge_vertex.ply", header.clone(), "declares 10000000000 'vertex' elements");
        must_fail(PlyGz, "huge_vertex.ply.gz", header, "declares 10000000000 'vertex' elements");
        let header = format!(
            "ply\nformat {format} 1.0\nelement vertex 3\n{PLY_XYZ}element face 10000000\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n{}",
            "\n".repeat(64)
        );
        must_fail(Ply, "ten_million_faces.ply", header, "declares 10000000 'face' elements");
        // An element without properties takes no bytes in a binary file: still one byte each.
        let header = format!(
            "ply\nformat {format} 1.0\nelement nothing 4000000000\nelement vertex 0\n{PLY_XYZ}element face 0\nproperty list uchar int vertex_indices\nend_header\n"
        );
        must_fail(Ply, "empty_elements.ply", header, "'nothing' elements");
    }
    // Header numbers beyond u64 (ply-rs's grammar would panic on them).
    let huge = format!("ply\nformat ascii 1.0\nelement vertex 18446744073709551616\n{PLY_XYZ}end_header\n");
    must_fail(Ply, "u64_overflow.ply", huge, "too large");
    must_fail(Ply, "version_overflow.ply", "ply\nformat ascii 99999999999999999999.0\nend_header\n", "too large");
    // A list whose count claims four billion entries (binary) or three billion (ascii).
    let mut b = format!("ply\nformat binary_little_endian 1.0\nelement vertex 3\n{PLY_XYZ}element face 1\nproperty list uint int vertex_indices\nend_header\n").into_bytes();
    for v in [[0f32, 0., 0.], [1., 0., 0.], [0., 1., 0.]] {
        b.extend(v.iter().flat_map(|c| c.to_le_bytes()));
    }
    b.extend(u32::MAX.to_le_bytes());
    b.extend([0u8; 12]);
    must_fail(Ply, "huge_list.ply", b, "truncated");
    let a = format!(
        "ply\nformat ascii 1.0\nelement vertex 3\n{PLY_XYZ}element face 1\nproperty list uint int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3000000000 0 1 2\n"
    );
    must_fail(Ply, "huge_list_ascii.ply", a, "huge_list_ascii.ply");

    // OBJ: face indices at 2^31 and beyond, relative indices before the first vertex.
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    must_fail(Obj, "index_2_31.obj", format!("{obj}f 1 2 2147483648\n"), "out of range");
    must_fail(Obj, "index_2_63.obj", format!("{obj}f 1 2 9223372036854775807\n"), "out of range");
    must_fail(Obj, "index_neg.obj", format!("{obj}f 1 2 -2147483649\n"), "before the first");
    must_fail(Obj, "uv_neg.obj", format!("{obj}vt 0 0\nf 1/-5 2/1 3/1\n"), "before the first");
    must_fail(Obj, "normal_huge.obj", format!("{obj}vn 0 0 1\nf 1//4611686018427387904 2//1 3//1\n"), "out of range");
    must_fail(Obj, "index_oob.obj", format!("{obj}f 1 2 4\n"), "out of bounds");

    // glTF: accessor counts of 10^9 with and without a buffer view, sparse, stride, count 0.
    let gl = |accessor: &str| tri_gltf(accessor);
    let pos = r#""bufferView":0,"componentType":5126,"type":"VEC3","min":[0,0,0],"max":[1,1,0]"#;
    must_fail(Gltf, "count_1e9.gltf", gl(&format!(r#"{{{pos},"count":1000000000}}"#)), "claim 333333333 triangles");
    must_fail(Gltf, "count_1e6.gltf", gl(&format!(r#"{{{pos},"count":1000000}}"#)), "overrun");
    // Without a buffer view an accessor must be sparse (gltf-json checks); its implicit zeros
    // may not outnumber the bytes of the buffers.
    must_fail(
        Gltf,
        "count_1e9_zeros.gltf",
        gl(r#"{"componentType":5126,"type":"VEC3","min":[0,0,0],"max":[1,1,0],"count":1000000000}"#),
        "bufferView",
    );
    let zeros = gl(r#"{"componentType":5126,"type":"VEC3","min":[0,0,0],"max":[1,1,0],"count":1000000000,"sparse":{"count":1,"indices":{"bufferView":0,"componentType":5125},"values":{"bufferView":0}}},
                      {"bufferView":0,"componentType":5121,"type":"SCALAR","count":3}"#)
    .replace(r#""attributes":{"POSITION":0}"#, r#""attributes":{"POSITION":0},"indices":1"#);
    must_fail(Gltf, "sparse_zeros_1e9.gltf", zeros, "without a buffer view");
    must_fail(
        Gltf,
        "sparse_1e9.gltf",
        gl(
            r#"{"componentType":5126,"type":"VEC3","min":[0,0,0],"max":[1,1,0],"count":3,"sparse":{"count":1000000000,"indices":{"bufferView":0,"componentType":5125},"values":{"bufferView":0}}}"#,
        ),
        "sparse count",
    );
    must_fail(Gltf, "count_0.gltf", gl(&format!(r#"{{{pos},"count":0}}"#)), "count 0");
    must_fail(Gltf, "count_2_64.gltf", gl(&format!(r#"{{{pos},"count":18446744073709551615}}"#)), "triangles");
    must_fail(
        Gltf,
        "offset_2_63.gltf",
        gl(&format!(r#"{{{pos},"count":3,"byteOffset":9223372036854775807}}"#)),
        "overrun",
    );
    must_fail(
        Gltf,
        "u8_positions.gltf",
        gl(r#"{"bufferView":0,"componentType":5121,"type":"SCALAR","count":3,"min":[0,0,0],"max":[1,1,0]}"#),
        "VEC3",
    );
    let strided = tri_gltf_with(
        r#"{"bufferView":0,"componentType":5126,"type":"VEC3","min":[0,0,0],"max":[1,1,0],"count":3}"#,
        r#","byteStride":4"#,
    );
    must_fail(Gltf, "stride_4.gltf", strided, "byteStride");
    // A GLB whose header length is shorter than the header, and one claiming 4 GiB.
    let mut glb = b"glTF".to_vec();
    glb.extend(2u32.to_le_bytes());
    glb.extend(4u32.to_le_bytes());
    must_fail(Gltf, "short.glb", glb.clone(), "GLB header");
    glb.truncate(8);
    glb.extend(u32::MAX.to_le_bytes());
    glb.extend(16u32.to_le_bytes());
    glb.extend(b"JSON{}");
    must_fail(Gltf, "claims_4gib.glb", glb, "claims_4gib.glb");
}

/// A one-triangle glTF with `accessor` as its POSITION and the buffer (36 bytes) inline.
fn tri_gltf(accessor: &str) -> String {
    tri_gltf_with(accessor, "")
}

fn tri_gltf_with(accessor: &str, view_extra: &str) -> String {
    let bin: Vec<u8> = [0f32, 0., 0., 1., 0., 0., 0., 1., 0.].iter().flat_map(|c| c.to_le_bytes()).collect();
    format!(
        r#"{{"asset":{{"version":"2.0"}},"scenes":[{{"nodes":[0]}}],"nodes":[{{"mesh":0}}],
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
        "buffers":[{{"byteLength":36,"uri":"data:application/octet-stream;base64,{}"}}],
        "bufferViews":[{{"buffer":0,"byteLength":36{view_extra}}}],
        "accessors":[{accessor}]}}"#,
        base64(&bin)
    )
}

fn base64(bytes: &[u8]) -> String {
    const T: &[u8] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::new();
    for chunk in bytes.chunks(3) {
        let b = [chunk[0], *chunk.get(1).unwrap_or(&0), *chunk.get(2).unwrap_or(&0)];
        let n = (b[0] as u32) << 16 | (b[1] as u32) << 8 | b[2] as u32;
        for k in 0..4 {
            out.push(if k <= chunk.len() { T[(n >> (18 - 6 * k) & 63) as usize] as char } else { '=' });
        }
    }
    out
}

#[test]
fn bad_geometry_and_structure() {
    use SceneFormat::*;
    // NaN and infinite coordinates in every format.
    must_fail(Obj, "nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "non-finite");
    must_fail(Obj, "inf.obj", "v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "non-finite");
    let ply = |coord: &str| {
        format!(
            "ply\nformat ascii 1.0\nelement vertex 3\n{PLY_XYZ}element face 1\nproperty list uchar int vertex_indices\nend_header\n{coord} 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
        )
    };
    // (ascii PLY has no NaN spelling: "nan" is a parse error; 1e39 overflows f32)
    must_fail(Ply, "nan_ascii.ply", ply("nan"), "line 10");
    must_fail(Ply, "inf.ply", ply("1e39"), "non-finite");
    must_fail(PlyGz, "inf.ply.gz", ply("-1e39"), "non-finite");
    let mut nan_ply = format!("ply\nformat binary_big_endian 1.0\nelement vertex 3\n{PLY_XYZ}element face 1\nproperty list uchar int vertex_indices\nend_header\n").into_bytes();
    for c in [f32::NAN, 0., 0., 1., 0., 0., 0., 1., 0.] {
        nan_ply.extend(c.to_be_bytes());
    }
    nan_ply.push(3);
    nan_ply.extend([0i32, 1, 2].iter().flat_map(|i| i.to_be_bytes()));
    must_fail(Ply, "nan.ply", nan_ply, "non-finite");
    let nan_bin: Vec<u8> = [f32::NAN, 0., 0., 1., 0., 0., 0., 1., 0.].iter().flat_map(|c| c.to_le_bytes()).collect();
    let nan_gltf =
        tri_gltf(r#"{"bufferView":0,"componentType":5126,"type":"VEC3","min":[0,0,0],"max":[1,1,0],"count":3}"#)
            .replace(&base64(&tri_bin()), &base64(&nan_bin));
    must_fail(Gltf, "nan.gltf", nan_gltf, "non-finite");
    // A NaN in a node's transform.
    let t = tri_gltf(r#"{"bufferView":0,"componentType":5126,"type":"VEC3","min":[0,0,0],"max":[1,1,0],"count":3}"#)
        .replace(r#""nodes":[{"mesh":0}]"#, r#""nodes":[{"mesh":0,"scale":[1e39,1,1]}]"#);
    must_fail(Gltf, "inf_scale.gltf", t, "non-finite");

    // Indices out of range.
    must_fail(Ply, "bad_face.ply", ply("0").replace("3 0 1 2", "3 0 1 3"), "vertex 3");
    must_fail(Ply, "neg_face.ply", ply("0").replace("3 0 1 2", "3 0 1 -1"), "vertex -1");
    // Indices read from the float bytes at offset 12: 1.0f32 is index 1065353216.
    let indexed =
        tri_gltf(r#"{"bufferView":0,"componentType":5126,"type":"VEC3","min":[0,0,0],"max":[1,1,0],"count":3}"#)
            .replace(r#""attributes":{"POSITION":0}"#, r#""attributes":{"POSITION":1},"indices":0"#)
            .replace(
                r#""accessors":["#,
                r#""accessors":[{"bufferView":0,"byteOffset":12,"componentType":5125,"type":"SCALAR","count":3},"#,
            );
    must_fail(Gltf, "index_oob.gltf", indexed, "out of 3 vertices");

    // Zero-area triangles load (they occlude nothing; AO must cope).
    for (format, name, bytes) in [
        (Obj, "degenerate.obj", b"v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 1\n".to_vec()),
        (Ply, "degenerate.ply", ply("2").replace("1 0 0\n0 1 0", "1 0 0\n0 0 0").into_bytes()),
    ] {
        let s = seed(format, name, bytes);
        let scene = load(&s, &s.bytes, "zero-area triangles").unwrap();
        assert!(scene.face_normals().iter().all(|n| *n == aokit_shaders::glam::Vec3::ZERO));
    }

    // Empty and nearly empty files.
    for (format, name) in [(Obj, "empty.obj"), (Ply, "empty.ply"), (PlyGz, "empty.ply.gz"), (Gltf, "empty.gltf")] {
        let s = seed(format, name, Vec::new());
        load(&s, &[], "an empty file").expect_err(name);
    }
    // A plain file named .ply.gz, gzip of nothing.
    let s = seed(Ply, "fake.ply.gz", ply("0"));
    let message = Scene::from_bytes(PlyGz, Path::new("fake.ply.gz"), &s.bytes, &no_side_files).unwrap_err();
    assert!(check_message(&message, "fake.ply.gz", "fake gzip").contains("gzip"));

    // glTF node hierarchies that are not trees: a cycle, a shared child, a doubled root.
    let base = tri_gltf(r#"{"bufferView":0,"componentType":5126,"type":"VEC3","min":[0,0,0],"max":[1,1,0],"count":3}"#);
    let cycle = base.replace(r#""nodes":[{"mesh":0}]"#, r#""nodes":[{"mesh":0,"children":[1]},{"children":[0]}]"#);
    must_fail(Gltf, "cycle.gltf", cycle, "not a tree");
    let shared = base
        .replace(r#""scenes":[{"nodes":[0]}]"#, r#""scenes":[{"nodes":[1,2]}]"#)
        .replace(r#""nodes":[{"mesh":0}]"#, r#""nodes":[{"mesh":0},{"children":[0]},{"children":[0]}]"#);
    must_fail(Gltf, "shared.gltf", shared, "not a tree");

    // An instancing bomb: 2000 nodes × 3000 triangles from a few kilobytes.
    let mut bin = tri_bin();
    bin.extend((0..9000).flat_map(|i: u32| ((i % 3) as u16).to_le_bytes()));
    let nodes: Vec<String> = (0..2000).map(|_| r#"{"mesh":0}"#.to_string()).collect();
    let roots: Vec<String> = (0..2000).map(|i| i.to_string()).collect();
    let bomb = format!(
        r#"{{"asset":{{"version":"2.0"}},"scenes":[{{"nodes":[{}]}}],"nodes":[{}],
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"indices":1}}]}}],
        "buffers":[{{"byteLength":{},"uri":"data:application/octet-stream;base64,{}"}}],
        "bufferViews":[{{"buffer":0,"byteLength":36}},{{"buffer":0,"byteOffset":36,"byteLength":18000}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"type":"VEC3","min":[0,0,0],"max":[1,1,0],"count":3}},{{"bufferView":1,"componentType":5123,"type":"SCALAR","count":9000}}]}}"#,
        roots.join(","),
        nodes.join(","),
        bin.len(),
        base64(&bin)
    );
    must_fail(Gltf, "bomb.gltf", bomb, "claim 6000000 triangles");

    // An image bomb: a PNG header claiming 30000×30000 RGBA behind an alpha-masked material.
    let mut png = Vec::new();
    image::DynamicImage::ImageRgba8(image::RgbaImage::new(1, 1))
        .write_to(&mut io::Cursor::new(&mut png), image::ImageFormat::Png)
        .unwrap();
    png[16..20].copy_from_slice(&30000u32.to_be_bytes());
    png[20..24].copy_from_slice(&30000u32.to_be_bytes());
    let mut crc = flate2::Crc::new();
    crc.update(&png[12..29]); // the IHDR chunk's type and data
    png[29..33].copy_from_slice(&crc.sum().to_be_bytes());
    let masked = base
        .replace(r#""meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}]"#, r#""meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"materials":[{"alphaMode":"MASK","pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],"textures":[{"source":0}],"images":[{"uri":"data:image/png;base64,PNG"}]"#)
        .replace("PNG", &base64(&png));
    must_fail(Gltf, "image_bomb.gltf", masked.clone(), "image 0");
    // Images the gltf crate's `Image::source()` would unwrap on (found by the fuzzer): a buffer
    // view without a mimeType, and neither a buffer view nor a URI.
    let uri = format!(r#"{{"uri":"data:image/png;base64,{}"}}"#, base64(&png));
    let no_mime = masked.replace(&uri, r#"{"bufferView":0}"#);
    must_fail(Gltf, "image_no_mime.gltf", no_mime, "image 0: unsupported image encoding");
    let nothing = masked.replace(&uri, "{}");
    must_fail(Gltf, "image_nothing.gltf", nothing, "neither a bufferView nor a uri");
}

fn tri_bin() -> Vec<u8> {
    [0f32, 0., 0., 1., 0., 0., 0., 1., 0.].iter().flat_map(|c| c.to_le_bytes()).collect()
}

/// Through the file system: what `aokit render --scene FILE` sees.
#[test]
fn files_on_disk() {
    let dir = std::env::temp_dir().join(format!("aokit-robustness-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let check = |name: &str, bytes: Option<&[u8]>, expect: &str| {
        let path = dir.join(name);
        if let Some(bytes) = bytes {
            std::fs::write(&path, bytes).unwrap();
        }
        let e = Scene::load(&path).expect_err(name);
        let message = check_message(&e, &path.display().to_string(), name);
        assert!(message.contains(expect), "{name}: expected '{expect}' in: {message}");
    };
    let ply = std::fs::read(seeds_dir().join("ply/cornell_le.ply")).unwrap();
    check("truncated.ply", Some(&ply[..ply.len() - 20]), "the data ends inside 'face' element");
    check("half.ply", Some(&ply[..ply.len() / 2]), "PLY");
    let ascii = std::fs::read(seeds_dir().join("ply/cornell_ascii.ply")).unwrap();
    check("truncated_ascii.ply", Some(&ascii[..ascii.len() - 40]), "PLY");
    check("empty.obj", Some(b""), "no triangles");
    std::fs::create_dir_all(dir.join("folder.obj")).unwrap();
    check("folder.obj", None, "is a directory");
    check("missing.ply", None, "No such file");
    // An OBJ whose mtllib is a device: not read, the default material is used.
    std::fs::write(dir.join("devmtl.obj"), b"mtllib /dev/zero\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let scene = within_cpu_budget("devmtl.obj", || Scene::load(&dir.join("devmtl.obj"))).unwrap();
    assert_eq!(scene.materials.len(), 1);
    // A glTF whose buffer is a device: an error, not an endless read.
    let zero = tri_gltf(r#"{"bufferView":0,"componentType":5126,"type":"VEC3","min":[0,0,0],"max":[1,1,0],"count":3}"#)
        .replace(&format!("data:application/octet-stream;base64,{}", base64(&tri_bin())), "file:///dev/zero");
    std::fs::write(dir.join("devzero.gltf"), zero).unwrap();
    let e = within_cpu_budget("devzero.gltf", || Scene::load(&dir.join("devzero.gltf"))).unwrap_err();
    assert!(e.to_string().contains("not a regular file"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}
