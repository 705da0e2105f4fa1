//! Exhaustive CPU tests of the kernels' primitives (`aokit_shaders`): every input of a domain
//! small enough to enumerate — all 2³² f32 bit patterns, every normal code, every f32 of a
//! packing's range, every pair of the sector grid, every choice of the reservoir — checked
//! against values derived here from the definitions: IEEE 754 binary32 rules evaluated in f64,
//! exact integer and rational arithmetic, the spec's formulas. An expectation never comes from
//! calling the function under test. `kernel_math.rs`, `vbao.rs` and `raysd.rs` sample the same
//! functions at random; these tests leave no input of their domains out.
//!
//! Times in the doc comments: wall clock on the 2-core test machine, `[profile.test]`
//! (opt-level 2, x86-64-v3), rayon on both cores,
//! `cargo test --test exhaustive -- --nocapture --test-threads=1` (each test prints its time).

use aokit_shaders::common::atomics::{AtomicU32Buffer, count_rays};
use aokit_shaders::common::denoise_terms::{
    EdgeWeights, pack_bent_normal, pack_bent_term, pack_edges, store_term, unpack_bent_term, unpack_edges,
};
use aokit_shaders::common::float_order::{RAY_MAX_CLEAR, RAY_MIN_CLEAR, from_ordered_bits, ordered_bits};
use aokit_shaders::common::hash::wyman_hash;
use aokit_shaders::common::lanes::{CPU_LANES, CpuLanes, Lanes};
use aokit_shaders::common::math::f32_to_u32_bits;
use aokit_shaders::common::noise::rotate;
use aokit_shaders::common::normal_codec::{decode_normal, decode_normal_lanes, encode_normal};
use aokit_shaders::glam::{Vec3, vec2, vec3, vec4};
use aokit_shaders::raysd::{MAX_LAYERS, NO_SLOT, SdPayload, reservoir_any_hit, reservoir_slot};
use aokit_shaders::svao::unorm8;
use aokit_shaders::vbao::kernel::{SECTORS, sector_bits, sector_bits_lanes, sector_coordinate};
use aokit_shaders::vbao::{RULE_PAPER, RULE_TOUCH};
use rayon::prelude::*;
use std::cmp::Ordering;
use std::collections::HashMap;
use std::sync::atomic::AtomicU32;
use std::time::Instant;

// ---------------------------------------------------------------------------------------------
// Sweeps: a range of u64 keys cut into chunks of 2^20, each folded into a `Tally` on rayon's
// threads. A failing check is counted and the one with the smallest key is reported, so a
// broken kernel gives one readable message instead of a billion.

#[derive(Default)]
struct Tally {
    failed: u64,
    first: Option<(u64, String)>,
    /// Test-specific counters (categories, deviations from the real-number definition).
    counts: [u64; 8],
    /// Test-specific maxima with the key where they occur.
    worst: [(f64, u64); 4],
}

impl Tally {
    #[inline(always)]
    fn check(&mut self, key: u64, ok: bool, why: impl FnOnce() -> String) {
        if !ok {
            self.fail(key, why);
        }
    }

    #[cold]
    #[inline(never)]
    fn fail(&mut self, key: u64, why: impl FnOnce() -> String) {
        self.failed += 1;
        if self.first.as_ref().is_none_or(|(k, _)| key < *k) {
            self.first = Some((key, why()));
        }
    }

    #[inline(always)]
    fn note(&mut self, i: usize, value: f64, key: u64) {
        if value > self.worst[i].0 {
            self.worst[i] = (value, key);
        }
    }

    fn merge(mut self, o: Tally) -> Tally {
        self.failed += o.failed;
        if let Some((k, why)) = o.first
            && self.first.as_ref().is_none_or(|(mine, _)| k < *mine)
        {
            self.first = Some((k, why));
        }
        for i in 0..self.counts.len() {
            self.counts[i] += o.counts[i];
        }
        for i in 0..self.worst.len() {
            if o.worst[i].0 > self.worst[i].0 {
                self.worst[i] = o.worst[i];
            }
        }
        self
    }

    fn assert_clean(&self, what: &str) {
        assert!(
            self.failed == 0,
            "{what}: {} checks failed; the first (smallest input): {}",
            self.failed,
            self.first.as_ref().map_or("?", |(_, why)| why.as_str())
        );
    }
}

const CHUNK: u64 = 1 << 20;

/// `body(start, end, tally)` over `[lo, hi]` (inclusive) in chunks of [`CHUNK`], in parallel.
fn sweep(lo: u64, hi: u64, body: impl Fn(u64, u64, &mut Tally) + Sync) -> Tally {
    let chunks = (hi - lo) / CHUNK + 1;
    (0..chunks)
        .into_par_iter()
        .map(|c| {
            let start = lo + c * CHUNK;
            let end = (start + CHUNK).min(hi + 1);
            let mut t = Tally::default();
            body(start, end, &mut t);
            t
        })
        .reduce(Tally::default, Tally::merge)
}

fn report(name: &str, start: Instant, domain: &str) {
    eprintln!("{name}: {domain} in {:.1} s", start.elapsed().as_secs_f64());
}

// ---------------------------------------------------------------------------------------------
// Binary32 arithmetic from its definition: the exact result rounded to nearest-even. A product
// of two f32 is exact in f64; a sum or quotient in f64 has 53 ≥ 2·24 + 2 bits, so rounding it
// again to f32 gives the correctly rounded binary32 result (Figueroa 1995).

fn mul32(a: f32, b: f32) -> f32 {
    (a as f64 * b as f64) as f32
}
fn add32(a: f32, b: f32) -> f32 {
    (a as f64 + b as f64) as f32
}
fn sub32(a: f32, b: f32) -> f32 {
    (a as f64 - b as f64) as f32
}
fn div32(a: f32, b: f32) -> f32 {
    (a as f64 / b as f64) as f32
}

/// HLSL `saturate` as the kernels define it (`common::math::sat`): NaN and −0 → +0.
fn sat_ref(x: f32) -> f32 {
    if x.is_nan() || x <= 0.0 {
        0.0
    } else if x >= 1.0 {
        1.0
    } else {
        x
    }
}

/// The unit in the last place of binary32 at |x| (normal range).
fn ulp32(x: f64) -> f64 {
    let e = x.abs().max(f32::MIN_POSITIVE as f64).log2().floor();
    (e - 23.0).exp2()
}

/// Every f32 of [−1, 1] by index: 0..=0x3F80_0000 are +0 … 1, the next 0x3F80_0001 are −0 … −1.
const SIGNED_UNIT_LAST: u64 = 2 * 0x3F80_0000 + 1;
fn signed_unit(i: u64) -> f32 {
    if i <= 0x3F80_0000 { f32::from_bits(i as u32) } else { f32::from_bits(0x8000_0000 | (i - 0x3F80_0001) as u32) }
}

// =============================================================================================
// 1. Float order (spec svao-raysd §5, §16) and the atomics on it.

/// Rank `r` in the IEEE 754 total order (`f32::total_cmp`) → bit pattern: ranks 0 … 2³¹−1 are
/// the patterns with the sign bit, descending from 0xFFFF_FFFF (−NaN with the largest payload)
/// to 0x8000_0000 (−0); ranks 2³¹ … 2³²−1 the others, ascending from +0 to 0x7FFF_FFFF (+NaN).
fn bits_at_rank(r: u64) -> u32 {
    if r < 1 << 31 { u32::MAX - r as u32 } else { (r - (1 << 31)) as u32 }
}

/// `ordered_bits` and `from_ordered_bits` over all 2³² f32 bit patterns, visited in IEEE total
/// order (−NaNs, −∞, negatives, −0, +0, denormals, normals, +∞, +NaNs).
///
/// The behaviour asserted, as the code and its doc define it: a positive x (denormals
/// included — nothing is flushed — and +∞) maps to its own bit pattern; every other pattern
/// (NaN of either sign, −0, +0, negatives, −∞) maps to 0, the bits of +0.0. Hence, for every x
/// and its successor y in total order with neither NaN: ordered(x) < ordered(y) when y > 0, and
/// ordered(x) = ordered(y) = 0 when y ≤ 0 — the map is monotone, strictly on the positives.
/// `from_ordered_bits` inverts it on its image [0, 0x7F80_0000] (back to x for positive x, to
/// +0.0 for the rest). Category counts: 16 777 214 NaNs, 2 139 095 042 non-positive,
/// 2 139 095 040 positive patterns.
///
/// Domain 2³² patterns; measured 11 s.
#[test]
fn ordered_bits_over_every_f32() {
    let start = Instant::now();
    assert_eq!(RAY_MIN_CLEAR, f32::MAX.to_bits(), "rayMin clears to the bits of FLT_MAX (spec svao-raysd §6)");
    assert_eq!(RAY_MAX_CLEAR, 0.0f32.to_bits(), "rayMax clears to 0 (spec svao-raysd §6)");
    let t = sweep(0, u32::MAX as u64, |a, b, t| {
        // The predecessor in total order (for rank 0 none: the first check of monotonicity is
        // skipped by starting from its own value).
        let first = f32::from_bits(bits_at_rank(a.max(1) - 1));
        let (mut px, mut po) = (first, ordered_bits(first));
        let (mut nans, mut positives) = (0u64, 0u64);
        for r in a..b {
            let bits = bits_at_rank(r);
            let x = f32::from_bits(bits);
            let o = ordered_bits(x);
            let back = from_ordered_bits(o).to_bits();
            let positive = x > 0.0;
            let nan = x.is_nan();
            nans += nan as u64;
            positives += positive as u64;
            let want = if positive { bits } else { 0 };
            let in_order = r == 0 || px.total_cmp(&x) == Ordering::Less;
            let monotone = px.is_nan() || nan || r == 0 || if positive { po < o } else { po == o };
            let ok = (o == want) & (back == want) & in_order & monotone;
            t.check(r, ok, || {
                format!(
                    "x = {x:e} ({bits:#010x}), predecessor {px:e}: ordered_bits {o:#010x} (expected {want:#010x}), \
                     from_ordered_bits {back:#010x}, after {po:#010x}; in total order {in_order}, monotone {monotone}"
                )
            });
            (px, po) = (x, o);
        }
        t.counts[0] += nans;
        t.counts[2] += positives;
        t.counts[1] += (b - a) - nans - positives;
    });
    t.assert_clean("ordered_bits");
    assert_eq!(t.counts[..3], [16_777_214, 2_139_095_042, 2_139_095_040], "NaN / non-positive / positive patterns");
    report("ordered_bits_over_every_f32", start, "2^32 patterns");
}

/// A bijection of u32 pairing each pattern with another (rotate, xor), so every value meets
/// a partner of every kind (NaN, negative, denormal, …) somewhere in the sweep.
fn partner(x: u32) -> u32 {
    x.rotate_left(13) ^ 0x9E37_79B9
}

/// What the ray-interval atomics keep of a float (spec svao-raysd §16: clamp before the
/// atomics): c(v) = v if v > 0, else +0 (NaN too); and IEEE min/max of such values.
fn clamped(v: f32) -> f32 {
    if v > 0.0 { v } else { 0.0 }
}
fn fmin(a: f32, b: f32) -> f32 {
    if b < a { b } else { a }
}
fn fmax(a: f32, b: f32) -> f32 {
    if b > a { b } else { a }
}

/// Atomic min/max on ordered bits (spec svao-raysd §5) through `&mut [u32]`'s
/// `AtomicU32Buffer` (the SPIR-V path's native twin) over all 2³² patterns x, each against the
/// stored value of its [`partner`] y (so every pattern is once the new value and once the stored
/// one): the slot ends as the ordered bits of the IEEE min/max of c(x), c(y) ([`clamped`]) and
/// the previous value is returned. `count_rays` (a 64-bit ray counter in two words) adds every
/// partner n to every low word x exactly, carrying into the high word.
///
/// Domain 2³² patterns; measured 31 s.
#[test]
fn atomic_min_max_through_ordered_bits_over_every_f32() {
    let start = Instant::now();
    let t = sweep(0, u32::MAX as u64, |a, b, t| {
        for k in a..b {
            let xb = k as u32;
            let yb = partner(xb);
            let (x, y) = (f32::from_bits(xb), f32::from_bits(yb));
            let (cx, cy) = (clamped(x), clamped(y));
            let mut slot = [ordered_bits(y); 2];
            let mut buf: &mut [u32] = &mut slot;
            let prev_min = buf.atomic_min(0, ordered_bits(x));
            let prev_max = buf.atomic_max(1, ordered_bits(x));
            let (want_min, want_max) = (fmin(cx, cy).to_bits(), fmax(cx, cy).to_bits());
            let (got_min, got_max) = (from_ordered_bits(slot[0]).to_bits(), from_ordered_bits(slot[1]).to_bits());
            let mut counter = [xb, 7];
            let mut buf: &mut [u32] = &mut counter;
            count_rays(&mut buf, yb);
            let sum = (7u64 << 32) + xb as u64 + yb as u64;
            let ok = (got_min == want_min)
                & (got_max == want_max)
                & (from_ordered_bits(prev_min).to_bits() == cy.to_bits())
                & (prev_max == prev_min)
                & (counter[0] == sum as u32)
                & (counter[1] == (sum >> 32) as u32);
            t.check(k, ok, || {
                format!(
                    "x = {x:e}, stored y = {y:e}: min {got_min:#x}, max {got_max:#x}, IEEE {want_min:#x}, \
                     {want_max:#x}; returned {prev_min:#x}/{prev_max:#x}; count_rays({xb:#x} + {yb:#x}) left \
                     {counter:x?}, expected {sum:#x}"
                )
            });
        }
    });
    t.assert_clean("atomic min/max on ordered bits");
    report("atomic_min_max_through_ordered_bits_over_every_f32", start, "2^32 patterns");
}

/// The CPU simulator's `&[AtomicU32]` `AtomicU32Buffer` (`fetch_min`/`fetch_max`) folds every
/// one of the 2³² patterns' ordered bits into a rayMin/rayMax pair cleared as the spec says
/// (one pair per chunk of 2²⁰ patterns): each call returns the running IEEE min/max of the
/// clamped floats before it, and each pair ends at the chunk's IEEE min/max.
///
/// Domain 2³² patterns; measured 17 s.
#[test]
fn atomic_u32_slots_fold_every_f32() {
    use std::sync::atomic::Ordering::Relaxed;
    let start = Instant::now();
    let t = sweep(0, u32::MAX as u64, |a, b, t| {
        let pair = [AtomicU32::new(RAY_MIN_CLEAR), AtomicU32::new(RAY_MAX_CLEAR)];
        let (mut lo, mut hi) = (f32::MAX, 0.0f32);
        for k in a..b {
            let x = f32::from_bits(partner(k as u32));
            let mut slots: &[AtomicU32] = &pair;
            let prev_min = slots.atomic_min(0, ordered_bits(x));
            let prev_max = slots.atomic_max(1, ordered_bits(x));
            let ok = (from_ordered_bits(prev_min).to_bits() == lo.to_bits())
                & (from_ordered_bits(prev_max).to_bits() == hi.to_bits());
            t.check(k, ok, || {
                format!("folding {x:e}: returned {prev_min:#x}/{prev_max:#x}, running min/max {lo:e}/{hi:e}")
            });
            let c = clamped(x);
            (lo, hi) = (fmin(lo, c), fmax(hi, c));
        }
        let got = [pair[0].load(Relaxed), pair[1].load(Relaxed)].map(|o| from_ordered_bits(o).to_bits());
        t.check(a, got == [lo.to_bits(), hi.to_bits()], || {
            format!("chunk at {a:#x}: the slots hold {got:x?}, IEEE min/max {lo:e}/{hi:e}")
        });
    });
    t.assert_clean("AtomicU32 slots");
    report("atomic_u32_slots_fold_every_f32", start, "2^32 patterns");
}

// =============================================================================================
// 2. Octahedral normal codec (spec svao-raysd §1).

/// A code's snorm8 byte as the spec reads it: sign-extended, with −128 read as −127
/// (`max(b/127, −1)`).
fn snorm_byte(b: u32) -> i32 {
    (b as u8 as i8 as i32).max(-127)
}

/// The octahedral point of a 16-bit code, ×127, in integers: |x| + |y| + |z| = 127, the lower
/// hemisphere (|bx| + |by| > 127) unfolded with `(127 − |by|)·sgn(bx), (127 − |bx|)·sgn(by)`,
/// sgn(0) = +1.
fn oct_point(code: u32) -> [i32; 3] {
    let (x, y) = (snorm_byte(code & 0xFF), snorm_byte((code >> 8) & 0xFF));
    let z = 127 - x.abs() - y.abs();
    if z >= 0 {
        [x, y, z]
    } else {
        let s = |v: i32| if v < 0 { -1 } else { 1 };
        [(127 - y.abs()) * s(x), (127 - x.abs()) * s(y), z]
    }
}

/// The decoded direction of a 16-bit code: [`oct_point`] normalised in f64.
fn decode_ref(code: u32) -> [f64; 3] {
    let p = oct_point(code).map(|c| c as f64);
    let l = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
    p.map(|c| c / l)
}

/// The code the encoder writes for the direction of a 16-bit code, from the codec's
/// construction. The encoder clamps to [−1, 1] before rounding, so it writes no byte −128
/// (0x80; read as −127). Its fold takes sgn(±0) = +1: on the lower hemisphere a point with
/// |by| = 127 decodes to x = ±0 (its bx sign is lost) and is encoded with bx > 0, likewise
/// |bx| = 127 with by > 0 — the fold edge codes (−k, ±127) and (±127, −k), k ≥ 1, are
/// duplicates of (k, ±127) and (±127, k); the four −Z codes (±127, ±127) all become
/// (127, 127). Elsewhere the map is one to one. Canonical = equal to its own image:
/// 255² − 507 = 64 518 of the 65 536 16-bit codes.
fn canonical(code: u32) -> u32 {
    let (x0, y0) = (snorm_byte(code & 0xFF), snorm_byte((code >> 8) & 0xFF));
    let (mut x, mut y) = (x0, y0);
    if x0.abs() + y0.abs() > 127 {
        if y0.abs() == 127 && x0 < 0 {
            x = -x0;
        }
        if x0.abs() == 127 && y0 < 0 {
            y = -y0;
        }
    }
    (x as u8 as u32) | ((y as u8 as u32) << 8)
}

/// Decoding error allowed per component against [`decode_ref`], from binary32 rounding
/// (ε = 2⁻²⁴, half an ulp of 1): b/127 is rounded once, z = 1 − |x| − |y| and the unfold
/// 1 − |y| add ≤ 2ε absolute each, so the unnormalised point is within 4ε per component
/// (|Δ| ≤ 4√3·ε); its length is ≥ 1/√3, so the direction is within 12ε; normalising (three
/// squares, two sums, sqrt, reciprocal, product: ≤ 5ε relative) brings it to 17ε. Allowed 24ε.
const DECODE_TOL: f64 = 24.0 / (1u64 << 24) as f64;
/// |‖decode‖ − 1| allowed: the last two roundings (reciprocal length, product) of ≤ ε each per
/// component plus the length's own ≤ 3ε: 5ε, allowed 6ε.
const LENGTH_TOL: f64 = 6.0 / (1u64 << 24) as f64;

/// `decode_normal` and `encode_normal` over the codes `code(i)`, i ∈ [0, n): every decoded
/// vector is finite, of unit length within [`LENGTH_TOL`], within [`DECODE_TOL`] of the exact
/// direction of its code (bits 0–15), and `encode ∘ decode` gives that code's [`canonical`]
/// form. Returns the number of non-canonical codes met.
fn normal_codec_sweep(n: u64, code: impl Fn(u64) -> u32 + Sync) -> u64 {
    let reference: Vec<[f64; 3]> = (0..1u32 << 16).map(decode_ref).collect();
    let canon: Vec<u32> = (0..1u32 << 16).map(canonical).collect();
    assert_eq!((0..1u32 << 16).filter(|&c| canon[c as usize] != c).count(), 1018, "non-canonical 16-bit codes");
    for c in 0..1u32 << 16 {
        let k = canon[c as usize];
        assert_eq!(canon[k as usize], k, "{c:#06x} → {k:#06x} is not canonical");
        assert_eq!(reference[k as usize], reference[c as usize], "{c:#06x} and its canonical {k:#06x} differ");
    }
    let t = sweep(0, n - 1, |a, b, t| {
        let mut non_canonical = 0;
        for i in a..b {
            let code = code(i);
            let code16 = (code & 0xFFFF) as usize;
            let v = decode_normal(code);
            let r = &reference[code16];
            let d = [v.x as f64, v.y as f64, v.z as f64];
            let err = (d[0] - r[0]).abs().max((d[1] - r[1]).abs()).max((d[2] - r[2]).abs());
            // |‖d‖ − 1| from ‖d‖² − 1 = (‖d‖ − 1)(‖d‖ + 1), without a square root per code.
            let len_err = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - 1.0).abs() / 2.0;
            t.note(0, err, code as u64);
            t.note(1, len_err, code as u64);
            let e = encode_normal(v);
            let want = canon[code16];
            non_canonical += (want != code) as u64;
            let ok = v.is_finite() & (err <= DECODE_TOL) & (len_err <= LENGTH_TOL) & (e == want);
            t.check(code as u64, ok, || {
                format!(
                    "decode({code:#010x}) = {v:?}: {err:.2e} from {r:?}, |len − 1| = {len_err:.2e}; \
                     encode(decode) = {e:#06x}, canonical {want:#06x}"
                )
            });
        }
        t.counts[0] += non_canonical;
    });
    t.assert_clean("normal codec");
    eprintln!(
        "  max component error {:.2e} (allowed {DECODE_TOL:.2e}), max |len − 1| {:.2e} (allowed {LENGTH_TOL:.2e}); \
         {} non-canonical codes",
        t.worst[0].0, t.worst[1].0, t.counts[0]
    );
    t.counts[0]
}

/// [`normal_codec_sweep`] over every 16-bit code (the G-buffer's R16Uint normal, spec
/// svao-raysd §1) and each of them again with each one of the 16 bits above (the decoder reads
/// bits 0–15 only) and with all of them set. The identity on the 64 518 canonical codes;
/// non-canonical: 1 018 of the 16-bit codes (511 with a byte 0x80, 507 fold duplicates) and
/// every code with a bit above 15, each mapped to a canonical code whose exact direction is
/// the same (asserted on the 2¹⁶ codes in exact arithmetic). All 2³² u32 codes:
/// [`normal_codec_over_every_u32_code`].
///
/// Domain 2¹⁶ × 18 codes; measured 0.1 s.
#[test]
fn normal_codec_over_every_code() {
    let start = Instant::now();
    let high = |i: u64| match i >> 16 {
        0 => 0,
        17 => 0xFFFF,
        b => 1 << (b - 1),
    };
    let non_canonical = normal_codec_sweep(18 << 16, |i| (high(i) << 16) | (i as u32 & 0xFFFF));
    assert_eq!(non_canonical, 1018 + 17 * 65_536);
    report("normal_codec_over_every_code", start, "2^16 × 18 codes");
}

/// [`normal_codec_sweep`] over all 2³² u32 codes: 4 294 902 778 non-canonical (every code but
/// the 64 518 canonical 16-bit ones).
///
/// Domain 2³² codes; measured 68 s (136 s of CPU), hence ignored by default: run with
/// `cargo test --test exhaustive -- --ignored`.
#[test]
#[ignore = "68 s on 2 cores; normal_codec_over_every_code covers every 16-bit code and every high bit"]
fn normal_codec_over_every_u32_code() {
    let start = Instant::now();
    assert_eq!(normal_codec_sweep(1 << 32, |i| i as u32), (1u64 << 32) - 64_518);
    report("normal_codec_over_every_u32_code", start, "2^32 codes");
}

/// The octahedral decoder as it was written before it became generic over lanes (a scalar
/// sign extension through `i32` and a branch for the lower hemisphere): the reference the
/// branch-free decoder must equal bit for bit.
fn decode_normal_scalar_reference(code: u32) -> Vec3 {
    let unsnorm8 = |byte: u32| ((((byte << 24) as i32) >> 24) as f32 / 127.0).max(-1.0);
    let sign = |v: f32| if v < 0.0 { -1.0 } else { 1.0 };
    let (mut x, mut y) = (unsnorm8(code & 0xFF), unsnorm8((code >> 8) & 0xFF));
    let z = 1.0 - x.abs() - y.abs();
    if z < 0.0 {
        (x, y) = ((1.0 - y.abs()) * sign(x), (1.0 - x.abs()) * sign(y));
    }
    vec3(x, y, z).normalize()
}

/// The decoder the kernels read the G-buffer with, one code (`decode_normal`) and
/// [`CPU_LANES`] (`decode_normal_lanes::<CpuLanes>`, cpu-sim's lanes), against the scalar reference above, bit
/// for bit: every 16-bit code in every lane position, with high bits set in half of the lanes
/// (ignored).
///
/// Domain 2¹⁶ codes × 16 lane positions; measured 0.1 s.
#[test]
fn normal_decoder_scalar_and_lanes_equal_the_reference_for_every_code() {
    let start = Instant::now();
    let mut checked = 0u32;
    for c in (0..1u32 << 16).step_by(CPU_LANES) {
        for rot in 0..CPU_LANES {
            let codes: [u32; CPU_LANES] = core::array::from_fn(|i| {
                let code = c + ((i + rot) % CPU_LANES) as u32;
                if i % 2 == 1 { code | 0xABCD_0000 } else { code }
            });
            let lanes = decode_normal_lanes::<CpuLanes>(<CpuLanes as Lanes>::Index::new(codes.map(|k| k as i32)));
            for (i, &code) in codes.iter().enumerate() {
                let want = decode_normal_scalar_reference(code & 0xFFFF).to_array().map(f32::to_bits);
                let one = decode_normal(code).to_array().map(f32::to_bits);
                let got = [lanes.x.lane(i), lanes.y.lane(i), lanes.z.lane(i)].map(f32::to_bits);
                assert_eq!(one, want, "decode_normal({code:#010x})");
                assert_eq!(got, want, "code {code:#010x} in lane {i}");
                checked += 1;
            }
        }
    }
    assert_eq!(checked, (CPU_LANES as u32) << 16, "codes × lane positions checked");
    report(
        "normal_decoder_scalar_and_lanes_equal_the_reference_for_every_code",
        start,
        &format!("2^16 codes × {CPU_LANES} lanes"),
    );
}

/// `f32_to_u32_bits` (the SPIR-V form of `f32_to_u32`: ⌊x⌋ + 2²³ read as bits) against Rust's
/// `as u32` on every float of [0, 2²³), +0 to the largest float below 2²³.
///
/// Domain 0x4B00_0000 floats (1.26·10⁹); measured about 2 s.
#[test]
fn f32_to_u32_bits_equals_the_cast_on_every_float_of_its_range() {
    let start = Instant::now();
    let t = sweep(0, 0x4AFF_FFFF, |a, b, t| {
        for bits in a..b {
            let x = f32::from_bits(bits as u32);
            let got = f32_to_u32_bits(x);
            t.check(bits, got == x as u32, || format!("f32_to_u32_bits({x:?}) = {got}, as u32 = {}", x as u32));
        }
    });
    t.assert_clean("f32_to_u32_bits");
    report("f32_to_u32_bits_equals_the_cast_on_every_float_of_its_range", start, "0x4B000000 floats");
}

/// The octahedral codec's worst angular error over a Fibonacci sphere of 2²⁶ ≈ 6.7·10⁷
/// directions is within the bound derived from its quantisation step, and near it.
///
/// The bound: `encode` maps n to p ∈ [−1, 1]² with o(p) = n/‖n‖₁ on the L1 unit sphere and
/// rounds each coordinate to the nearest multiple of 1/127 (snorm8, half away from zero):
/// |δx|, |δy| ≤ h = 1/254. `decode` takes p' to o(p') = (p', 1 − |x| − |y|), unfolded below the
/// diamond by (x, y) ↦ (±(1 − |y|), ±(1 − |x|)): piecewise linear and continuous, each piece
/// moving o by (±δ, ±δ', ∓δ ∓ δ') up to a swap, so ‖o(p) − o(p')‖₂ ≤ √(h² + h² + (2h)²) = √6·h.
/// Points of the L1 sphere have ‖o‖₂ ≥ 1/√3, so sin θ ≤ √6·h·√3 and θ ≤ asin(√18/254) =
/// 0.016 704 rad (+10⁻⁶ for the binary32 arithmetic). It is nearly attained at the octant
/// centres, o = (1, 1, 1)/3 with δ = (h, h): Δo = h·(1, 1, −2) is perpendicular to o.
/// Observed: 0.016 671 rad, 0.998 of the bound.
///
/// Domain 2²⁶ directions; measured 4 s.
#[test]
fn normal_codec_error_over_a_dense_sphere_is_within_the_quantisation_bound() {
    let start = Instant::now();
    const M: u64 = 1 << 26;
    let bound = (18f64.sqrt() / 254.0).asin() + 1e-6;
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let t = sweep(0, M - 1, |a, b, t| {
        for i in a..b {
            let z = 1.0 - (2 * i + 1) as f64 / M as f64;
            let r = (1.0 - z * z).sqrt();
            let (s, c) = (i as f64 * golden).sin_cos();
            let n = vec3((r * c) as f32, (r * s) as f32, z as f32);
            let d = decode_normal(encode_normal(n));
            let unit = |v: Vec3| {
                let v = [v.x as f64, v.y as f64, v.z as f64];
                let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
                v.map(|c| c / l)
            };
            let (a, b) = (unit(n), unit(d));
            let chord = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
            let angle = 2.0 * (chord / 2.0).asin();
            t.note(0, angle, i);
            t.check(i, angle <= bound, || format!("n = {n:?}: decode(encode(n)) = {d:?}, {angle:.6} rad > {bound:.6}"));
        }
    });
    t.assert_clean("normal codec error");
    let (worst, at) = t.worst[0];
    eprintln!("  worst {worst:.6} rad at point {at}, bound {bound:.6} rad ({:.3} of it)", worst / bound);
    assert!(worst >= bound / 2.0, "the bound is not tight: worst {worst:.6} rad < half of {bound:.6}");
    report("normal_codec_error_over_a_dense_sphere", start, "2^26 directions");
}

// =============================================================================================
// 3. Unorm/snorm packings: XeGTAO's denoiser inputs (spec gtao-raymarch-hybrid §2.6), SVAO's
// UNORM8 store (svao-raysd §5) and the normal codec's snorm8 (svao-raysd §1).
//
// Each packed code is compared with the definition evaluated under binary32 rules (what the
// shaders compute) and, separately, with the definition in real numbers: they may differ only
// where the real value lies within a few binary32 ulps of a rounding threshold, by one code;
// those cases are counted and printed.

/// Checks `got` against the binary32 reference `want32` and the real-number reference
/// `want_real` whose pre-rounding value is `t_real` (thresholds at half-integers).
#[inline]
fn check_code(t: &mut Tally, key: u64, got: u32, want32: u32, want_real: u32, t_real: f64, what: impl Fn() -> String) {
    t.check(key, got == want32, || format!("{}: {got}, binary32 definition {want32}", what()));
    if want32 != want_real {
        t.counts[7] += 1;
        let threshold = (want32.max(want_real)) as f64 - 0.5;
        let near = (t_real - threshold).abs() <= 4.0 * ulp32(t_real);
        t.check(key, want32.abs_diff(want_real) == 1 && near, || {
            format!("{}: binary32 {want32} vs real {want_real} (value {t_real}) far from a threshold", what())
        });
    }
}

/// XeGTAO's packed edges (spec gtao-raymarch-hybrid §2.6.1): `q = round(sat(e)·2.9)` per
/// 2-bit field, `64·qL + 16·qR + 4·qT + qB`. Every f32 e ∈ [+0, 1] in all four fields at
/// once (code 85·q) through the scalar and cpu-sim's lanes (`CpuLanes`: `round_ties_even`,
/// the scalar a floor-based round half to even), against q = round_half_even(e ⊗ 2.9f32);
/// −0, negatives, >1, ±∞ and NaN saturate. Every one of the 256 codes: `unpack_edges` gives
/// each field k as the correctly rounded k/3 (scalar and lanes), and packing it back gives the
/// code. Real-number deviations (exact 2.9): 2 weights.
///
/// Domain 1 065 353 217 f32 + 256 codes; measured 6 s.
#[test]
fn pack_edges_over_every_weight_and_code() {
    let start = Instant::now();
    let q32 = |e: f32| mul32(sat_ref(e), 2.9).to_bits();
    let round_q = |bits: u32| (f32::from_bits(bits) as f64).round_ties_even() as u32;
    let t = sweep(0, 0x3F80_0000, |a, b, t| {
        let mut k = a;
        while k < b {
            let n = (b - k).min(CPU_LANES as u64);
            let xs: [f32; CPU_LANES] = std::array::from_fn(|i| f32::from_bits((k + (i as u64).min(n - 1)) as u32));
            let lanes = CpuLanes::from_lanes(|i| xs[i]);
            let packed = pack_edges::<CpuLanes>(EdgeWeights { l: lanes, r: lanes, t: lanes, b: lanes });
            for (i, &e) in xs.iter().enumerate().take(n as usize) {
                let key = k + i as u64;
                let want = round_q(q32(e));
                let real = {
                    // Real numbers: e·2.9 = e·29/10 against 0.5, 1.5, 2.5 (e·29 exact in f64; no
                    // f32 e makes e·29 a multiple of 5, so no ties).
                    let t29 = e as f64 * 29.0;
                    [5.0, 15.0, 25.0].iter().filter(|&&th| t29 > th).count() as u32
                };
                let got = pack_edges::<f32>(EdgeWeights { l: e, r: e, t: e, b: e });
                t.check(key, got == 85 * want, || format!("pack_edges(all {e:e}) = {got:#x}, expected 85·{want}"));
                let got_lane = CpuLanes::index_lane(packed, i);
                t.check(key, got_lane == 85 * want, || format!("pack_edges::<CpuLanes>(all {e:e}) = {got_lane:#x}"));
                check_code(t, key, got & 3, want, real, e as f64 * 2.9, || format!("q({e:e})"));
            }
            k += n;
        }
    });
    t.assert_clean("pack_edges");
    for e in [-0.0, -1e-30, -1.0, 1.5, f32::INFINITY, f32::NEG_INFINITY, f32::NAN] {
        let want = if e > 1.0 { 3 * 85 } else { 0 };
        assert_eq!(pack_edges::<f32>(EdgeWeights { l: e, r: e, t: e, b: e }), want, "pack_edges({e})");
    }
    for code in 0..256u32 {
        let fields = [(code >> 6) & 3, (code >> 4) & 3, (code >> 2) & 3, code & 3];
        let want = fields.map(|k| (k as f64 / 3.0) as f32);
        let e = unpack_edges::<f32>(code);
        assert_eq!([e.l, e.r, e.t, e.b], want, "unpack_edges({code:#04x})");
        assert_eq!(pack_edges::<f32>(e), code, "pack_edges(unpack_edges({code:#04x}))");
        let lanes = unpack_edges::<CpuLanes>(CpuLanes::index_splat(code));
        let got = [lanes.l, lanes.r, lanes.t, lanes.b].map(|v| v.lane(3));
        assert_eq!(got, want, "unpack_edges::<CpuLanes>({code:#04x})");
        assert_eq!(CpuLanes::index_lane(pack_edges::<CpuLanes>(lanes), 5), code, "lanes: pack(unpack({code:#04x}))");
    }
    eprintln!("  {} weights round differently in real numbers (exact 2.9)", t.counts[7]);
    report("pack_edges_over_every_weight_and_code", start, "1 065 353 217 f32 + 256 codes");
}

/// The stored AO term `uint(sat(vis/1.5)·255 + 0.5)` (spec gtao-raymarch-hybrid §2.6.4) for
/// every f32 vis ∈ [+0, 1.5] against the binary32 evaluation of the definition (every step
/// rounded to nearest-even, then truncated), and the real-number round half up of 170·vis
/// (117 differ, each at a threshold); beyond 1.5, −0, negatives, ±∞ and NaN saturate. Every code k: the
/// denoiser reads it back as vis = 1.5·(k/255) (binary32), which stores k again.
///
/// Domain 1 069 547 521 f32; measured 3 s.
#[test]
fn store_term_over_every_f32_of_0_to_1_5() {
    let start = Instant::now();
    let t = sweep(0, 1.5f32.to_bits() as u64, |a, b, t| {
        for k in a..b {
            let vis = f32::from_bits(k as u32);
            let want = add32(mul32(sat_ref(div32(vis, 1.5)), 255.0), 0.5) as u32;
            let t_real = vis as f64 * 170.0 + 0.5;
            let got = store_term(vis);
            check_code(t, k, got, want, t_real.floor() as u32, t_real - 0.5, || format!("store_term({vis:e})"));
        }
    });
    t.assert_clean("store_term");
    for vis in [-0.0, -1.0, 1.6, f32::INFINITY, f32::NEG_INFINITY, f32::NAN] {
        assert_eq!(store_term(vis), if vis > 1.5 { 255 } else { 0 }, "store_term({vis})");
    }
    for k in 0..=255u32 {
        let vis = mul32(1.5, div32(k as f32, 255.0));
        assert_eq!(store_term(vis), k, "store_term(1.5·{k}/255)");
    }
    eprintln!("  {} values round differently in real numbers", t.counts[7]);
    report("store_term_over_every_f32_of_0_to_1_5", start, "1 069 547 521 f32");
}

/// `uint(sat(x)·255 + 0.5)` under binary32 rules.
fn unorm8_code32(x: f32) -> u32 {
    add32(mul32(sat_ref(x), 255.0), 0.5) as u32
}

/// The RGBA8 packing of a term with a bent normal (spec gtao-raymarch-hybrid §2.6.5):
/// `pack_bent_term` for every f32 x ∈ [+0, 1] in all four channels: q·0x0101_0101, q the
/// binary32 `uint(sat(x)·255 + 0.5)` (real-number round half up of 255·x: 128 differ, each
/// at a threshold); −0, negatives, >1, ±∞ and NaN saturate.
///
/// Domain 1 065 353 217 f32; measured 3 s.
#[test]
fn pack_bent_term_over_every_f32_of_0_to_1() {
    let start = Instant::now();
    let t = sweep(0, 0x3F80_0000, |a, b, t| {
        for k in a..b {
            let x = f32::from_bits(k as u32);
            let want = unorm8_code32(x);
            let t_real = x as f64 * 255.0 + 0.5;
            let got = pack_bent_term(vec4(x, x, x, x));
            t.check(k, got == want * 0x0101_0101, || format!("pack_bent_term(all {x:e}) = {got:#010x}, q = {want}"));
            check_code(t, k, got & 0xFF, want, t_real.floor() as u32, t_real - 0.5, || format!("q({x:e})"));
        }
    });
    t.assert_clean("pack_bent_term");
    eprintln!("  {} values round differently in real numbers", t.counts[7]);
    for x in [-0.0, -1.0, 1.5, f32::INFINITY, f32::NEG_INFINITY, f32::NAN] {
        assert_eq!(pack_bent_term(vec4(x, x, x, x)), if x > 1.0 { u32::MAX } else { 0 }, "pack_bent_term({x})");
    }
    report("pack_bent_term_over_every_f32_of_0_to_1", start, "1 065 353 217 f32");
}

/// Every one of the 2³² RGBA8 words: `unpack_bent_term` gives each byte b as the correctly
/// rounded b/255 in its channel (r in the low byte), and `pack_bent_term` of that gives the
/// word back.
///
/// Domain 2³² words; measured 37 s.
#[test]
fn unpack_bent_term_over_every_word() {
    let start = Instant::now();
    let table: Vec<f32> = (0..256).map(|b| (b as f64 / 255.0) as f32).collect();
    let t = sweep(0, u32::MAX as u64, |a, b, t| {
        for word in a..b {
            let word = word as u32;
            let c = unpack_bent_term(word);
            let want = [0, 8, 16, 24].map(|s| table[((word >> s) & 0xFF) as usize]);
            let back = pack_bent_term(c);
            t.check(word as u64, (c.to_array() == want) & (back == word), || {
                format!("unpack_bent_term({word:#010x}) = {c:?} (expected {want:?}), packed back {back:#010x}")
            });
        }
    });
    t.assert_clean("unpack_bent_term ∘ pack_bent_term");
    report("unpack_bent_term_over_every_word", start, "2^32 words");
}

/// `pack_bent_normal(n, a)`: rgb = n·0.5 + 0.5, packed as `pack_bent_term`. Every f32
/// c ∈ [−1, 1] (both zeros) in all three components and a = c too: each channel is the
/// binary32 `uint(sat(c ⊗ 0.5 ⊕ 0.5)·255 + 0.5)` (a: `uint(sat(c)·255 + 0.5)`); the real
/// definition, floor(127.5·(c + 1) + 0.5) = 128 + ⌊255c/2⌋ clamped (255c exact), differs by
/// one code for 855 638 720 c: the 855 638 016 negatives of magnitude ≤ 2⁻²⁵, which vanish in
/// 0.5 ⊕ c/2 (code 128, really 127), and 704 at a threshold.
///
/// Domain 2 130 706 434 f32; measured 20 s.
#[test]
fn pack_bent_normal_over_every_f32_of_minus_1_to_1() {
    let start = Instant::now();
    let t = sweep(0, SIGNED_UNIT_LAST, |a, b, t| {
        for k in a..b {
            let c = signed_unit(k);
            let q = unorm8_code32(add32(mul32(c, 0.5), 0.5));
            let want = q | (q << 8) | (q << 16) | (unorm8_code32(c) << 24);
            let got = pack_bent_normal(vec3(c, c, c), c);
            t.check(k, got == want, || format!("pack_bent_normal(all {c:e}) = {got:#010x}, expected {want:#010x}"));
            let m = c as f64 * 255.0;
            let real = (128.0 + (m / 2.0).floor()).clamp(0.0, 255.0) as u32;
            // A negative c of magnitude ≤ 2⁻²⁵ vanishes in 0.5 ⊕ c/2 = 0.5 (code 128; really 127).
            t.counts[6] += (c < 0.0 && c >= -(-25f32).exp2()) as u64;
            check_code(t, k, got & 0xFF, q, real, (c as f64 + 1.0) * 127.5, || format!("n = {c:e}"));
        }
    });
    t.assert_clean("pack_bent_normal");
    eprintln!(
        "  {} components round differently in real numbers: {} tiny negatives absorbed by ⊕ 0.5, {} at a threshold",
        t.counts[7],
        t.counts[6],
        t.counts[7] - t.counts[6]
    );
    report("pack_bent_normal_over_every_f32_of_minus_1_to_1", start, "2 130 706 434 f32");
}

/// SVAO's UNORM8 store of a flagged pixel's AO, `round(sat(A)·255)/255` (spec svao-raysd §5,
/// Rust's round = half away from zero), for every f32 A ∈ [+0, 1] against the binary32
/// evaluation, and the real-number code round(255·A) (127 differ, each at a threshold); every code's
/// value k/255 (correctly rounded) is a fixed point.
///
/// Domain 1 065 353 217 f32; measured 3 s.
#[test]
fn unorm8_over_every_f32_of_0_to_1() {
    let start = Instant::now();
    let t = sweep(0, 0x3F80_0000, |a, b, t| {
        for k in a..b {
            let x = f32::from_bits(k as u32);
            let code = (mul32(sat_ref(x), 255.0) as f64).round();
            let want = div32(code as f32, 255.0);
            let got = unorm8(x);
            t.check(k, got.to_bits() == want.to_bits(), || format!("unorm8({x:e}) = {got:e}, expected {want:e}"));
            let t_real = x as f64 * 255.0 + 0.5;
            check_code(t, k, code as u32, code as u32, t_real.floor() as u32, t_real - 0.5, || {
                format!("unorm8({x:e})")
            });
        }
    });
    t.assert_clean("unorm8");
    for k in 0..=255u32 {
        let v = div32(k as f32, 255.0);
        assert_eq!(unorm8(v).to_bits(), v.to_bits(), "unorm8({k}/255)");
    }
    eprintln!("  {} values round differently in real numbers", t.counts[7]);
    report("unorm8_over_every_f32_of_0_to_1", start, "1 065 353 217 f32");
}

/// The normal codec's snorm8 (spec svao-raysd §1, `trunc(c·127 ± 0.5)`), reached through
/// `encode_normal` on the upper hemisphere: for every f32 c ∈ [−1, 1], n = (c, 0, 1 − |c|) and
/// (0, c, 1 − |c|) encode p = c/‖n‖₁ (binary32: ‖n‖₁ = (|c| ⊕ 0) ⊕ (1 ⊖ |c|), p = c ⊘ ‖n‖₁) as
/// trunc(p ⊗ 127 ⊕ ±0.5) in the x byte and in the y byte (the other 0). The real definition,
/// round half away of 127·c, differs by one code for 128 c, each at a threshold.
///
/// Domain 2 130 706 434 f32 × 2 bytes; measured 19 s.
#[test]
fn snorm8_of_the_normal_codec_over_every_f32_of_minus_1_to_1() {
    let start = Instant::now();
    let t = sweep(0, SIGNED_UNIT_LAST, |a, b, t| {
        for k in a..b {
            let c = signed_unit(k);
            let z = sub32(1.0, c.abs());
            let l1 = add32(add32(c.abs(), 0.0), z);
            let p = div32(c, l1);
            let s = if p < 0.0 { -0.5 } else { 0.5 };
            let q = add32(mul32(p.clamp(-1.0, 1.0), 127.0), s) as i32;
            let want = (q as u32) & 0xFF;
            let got_x = encode_normal(vec3(c, 0.0, z));
            let got_y = encode_normal(vec3(0.0, c, z));
            t.check(k, got_x == want && got_y == want << 8, || {
                format!("encode((±){c:e}, 1 − |c|): {got_x:#06x} / {got_y:#06x}, expected byte {want:#04x}")
            });
            let m = (c as f64 * 127.0).abs();
            let real = ((m + 0.5).floor() as i32 * if c < 0.0 { -1 } else { 1 }) as u32 & 0xFF;
            if want != real {
                t.counts[7] += 1;
                let near =
                    (m - ((m + 0.5).floor() - 0.5)).abs().min((m - ((m + 0.5).floor() + 0.5)).abs()) <= 4.0 * ulp32(m);
                t.check(k, (q - (real as u8 as i8 as i32)).abs() == 1 && near, || {
                    format!("snorm8({c:e}): binary32 {want:#04x}, real {real:#04x}, far from a threshold")
                });
            }
        }
    });
    t.assert_clean("snorm8");
    eprintln!("  {} values round differently in real numbers", t.counts[7]);
    report("snorm8_of_the_normal_codec_over_every_f32_of_minus_1_to_1", start, "2 130 706 434 f32");
}

// =============================================================================================
// 4. VBAO sector bits (spec vbao §2.4, §3).

/// The spec's sector rules (vbao §3), N = 32, for 0 ≤ lo, hi ≤ 1: `Paper`: start = ⌊N·lo⌋,
/// count = ⌈N·(hi − lo)⌉ with hi − lo in binary32 as every source computes it, bits =
/// `((count ≥ 32 ? 0xFFFF_FFFF : (1≪count) − 1) ≪ start)` in u64 cut to 32 bits (a shift of 32
/// or more gives 0), none for count ≤ 0. `Touch`: the bits [⌊N·lo⌋, min(⌈N·hi⌉, N)) when
/// hi > lo, else none. N·x is exact in f64 (and in f32: a power of two).
fn sector_ref(lo: f32, hi: f32, rule: u32) -> u32 {
    const N: f64 = 32.0;
    let start = (N * lo as f64).floor();
    if rule == RULE_TOUCH {
        if hi <= lo {
            return 0;
        }
        let end = (N * hi as f64).ceil().min(N);
        if end <= start {
            return 0;
        }
        (((1u64 << end as u32) - (1u64 << start as u32)) & 0xFFFF_FFFF) as u32
    } else {
        let count = (N * sub32(hi, lo) as f64).ceil();
        if count <= 0.0 {
            return 0;
        }
        let ones: u64 = if count >= 32.0 { 0xFFFF_FFFF } else { (1u64 << count as u32) - 1 };
        if start >= 64.0 { 0 } else { ((ones << start as u32) & 0xFFFF_FFFF) as u32 }
    }
}

/// The grid: every multiple of 2⁻¹⁴ in [0, 1] (512 per sector), each sector edge's two f32
/// neighbours, and the smallest denormal, the smallest normal and the largest f32 below 1.
fn sector_grid() -> Vec<f32> {
    let mut g: Vec<f32> = (0..=1 << 14).map(|j| j as f32 / (1 << 14) as f32).collect();
    for k in 0..=32 {
        let e = k as f32 / 32.0;
        g.extend([e.next_down(), e.next_up()].into_iter().filter(|v| (0.0..=1.0).contains(v)));
    }
    g.extend([f32::from_bits(1), f32::MIN_POSITIVE, 1f32.next_down()]);
    g.sort_by(f32::total_cmp);
    g.dedup();
    g
}

/// `sector_bits` (scalar) and `sector_bits_lanes::<CpuLanes>` for both rules over every ordered
/// and unordered pair (lo, hi) of [`sector_grid`] (16 450 values, 270.6 M pairs), against
/// [`sector_ref`]; the spec's table (vbao §3) is among them. N = 32 sectors (`SECTORS`).
///
/// Domain 16 450² pairs × 2 rules × (scalar, lanes); measured 4 s.
#[test]
fn sector_bits_over_every_pair_of_the_sector_grid() {
    let start = Instant::now();
    assert_eq!(SECTORS, 32, "vbao §3: N = 32");
    assert_ne!(RULE_PAPER, RULE_TOUCH);
    let g = sector_grid();
    assert_eq!(g.len(), 16_450);
    let n = g.len() as u64;
    let t = (0..n as usize)
        .into_par_iter()
        .map(|i| {
            let mut t = Tally::default();
            let lo = g[i];
            for rule in [RULE_PAPER, RULE_TOUCH] {
                for j0 in (0..g.len()).step_by(CPU_LANES) {
                    let his: [f32; CPU_LANES] = std::array::from_fn(|k| g[(j0 + k).min(g.len() - 1)]);
                    let lanes =
                        sector_bits_lanes::<CpuLanes>(CpuLanes::splat(lo), CpuLanes::from_lanes(|k| his[k]), rule);
                    for (k, &hi) in his.iter().enumerate().take(g.len() - j0) {
                        let key = ((i * g.len() + j0 + k) * 2) as u64 + rule as u64;
                        let want = sector_ref(lo, hi, rule);
                        let got = sector_bits(lo, hi, rule);
                        t.check(key, got == want, || {
                            format!("rule {rule}: sector_bits({lo:e}, {hi:e}) = {got:#010x}, spec {want:#010x}")
                        });
                        let lane = CpuLanes::index_lane(lanes, k);
                        t.check(key, lane == got, || {
                            format!("rule {rule}: lanes ({lo:e}, {hi:e}) = {lane:#010x}, scalar {got:#010x}")
                        });
                    }
                }
            }
            t
        })
        .reduce(Tally::default, Tally::merge);
    t.assert_clean("sector bits on the grid");
    report("sector_bits_over_every_pair_of_the_sector_grid", start, "16450^2 pairs × 2 rules");
}

/// `sector_bits` (scalar) for every f32 x ∈ [+0, 1] in the pairs (x, 1) — every start
/// ⌊32x⌋, every Paper count ⌈32·(1 ⊖ x)⌉ —, (0, x) — every Touch end ⌈32x⌉, every Paper count
/// ⌈32x⌉ — and (x, x) — the empty interval —, both rules, against [`sector_ref`]. (cpu-sim's lane
/// version is compared on the grid, [`sector_bits_over_every_pair_of_the_sector_grid`].)
///
/// Domain 1 065 353 217 f32 × 3 pairs × 2 rules; measured 16 s.
#[test]
fn sector_bits_over_every_f32_of_0_to_1() {
    let start = Instant::now();
    let t = sweep(0, 0x3F80_0000, |a, b, t| {
        for k in a..b {
            let x = f32::from_bits(k as u32);
            for (lo, hi) in [(x, 1.0), (0.0, x), (x, x)] {
                for rule in [RULE_PAPER, RULE_TOUCH] {
                    let want = sector_ref(lo, hi, rule);
                    let got = sector_bits(lo, hi, rule);
                    t.check(k, got == want, || {
                        format!("rule {rule}: sector_bits({lo:e}, {hi:e}) = {got:#010x}, spec {want:#010x}")
                    });
                }
            }
        }
    });
    t.assert_clean("sector bits over [0, 1]");
    report("sector_bits_over_every_f32_of_0_to_1", start, "1 065 353 217 f32 × 3 pairs × 2 rules");
}

/// `sector_coordinate(θ, γ) = sat((θ − γ + π/2)/π)` (spec vbao §2.4) at every f32 θ within
/// 4 096 ulps of each of the 33 sector edges θ_k = γ − π/2 + kπ/32 (k = 0 … 32; k = 0 and 32
/// are the clamps), for 9 slice normals γ: within 2⁻²² of the real-number value
/// (binary32: θ ⊖ γ and ⊕ π/2 err ≤ 2⁻²³ each for magnitudes < 4, 0.64·2⁻²³ after the product
/// by 1/π; 1/π's rounding times a numerator up to π, π/2's rounding and the product's add
/// < 1.5·2⁻²⁴, so < 1.4·2⁻²³ in all), exactly 0 and 1 beyond the clamps, monotone in θ,
/// and cpu-sim's lane version equals the scalar one. It prints how many θ fall in a sector other
/// than the real-number one (5 008, all within the 2⁻²² band of an edge).
///
/// Domain 9 γ × 33 edges × 8 193 θ = 2.4 M; measured 0.1 s.
#[test]
fn sector_coordinate_at_every_f32_near_the_sector_edges() {
    let start = Instant::now();
    let gammas = [0.0f32, 0.3, -0.3, 1.2, -1.2, 1.5, -1.5, 0.049, -std::f32::consts::FRAC_PI_4];
    let tol = (-22f64).exp2();
    let pi = std::f64::consts::PI;
    let cases: Vec<(f32, u32)> = gammas.iter().flat_map(|&g| (0..=32).map(move |k| (g, k))).collect();
    let t = cases
        .par_iter()
        .map(|&(gamma, k)| {
            let mut t = Tally::default();
            let edge = gamma as f64 - pi / 2.0 + k as f64 * pi / 32.0;
            let mut theta = edge as f32;
            for _ in 0..4096 {
                theta = theta.next_down();
            }
            let mut prev = -1.0f32;
            let thetas: Vec<f32> = (0..8193)
                .scan(theta, |th, _| {
                    let v = *th;
                    *th = th.next_up();
                    Some(v)
                })
                .collect();
            for c in thetas.chunks(CPU_LANES) {
                let lanes = sector_coordinate::<CpuLanes>(
                    CpuLanes::from_lanes(|i| c[i.min(c.len() - 1)]),
                    CpuLanes::splat(gamma),
                );
                for (i, &th) in c.iter().enumerate() {
                    let key = (k as u64) << 32 | th.to_bits() as u64;
                    let x = sector_coordinate::<f32>(th, gamma);
                    let real = (th as f64 - gamma as f64 + pi / 2.0) / pi;
                    let clamped = real.clamp(0.0, 1.0);
                    let ok = if real <= -tol {
                        x == 0.0
                    } else if real >= 1.0 + tol {
                        x == 1.0
                    } else {
                        (x as f64 - clamped).abs() <= tol
                    };
                    t.check(key, ok, || format!("sector_coordinate({th:e}, {gamma}) = {x:e}, real {real:e}"));
                    t.check(key, x >= prev, || format!("not monotone at θ = {th:e}, γ = {gamma}: {x:e} < {prev:e}"));
                    t.check(key, lanes.lane(i).to_bits() == x.to_bits(), || format!("lanes differ at θ = {th:e}"));
                    if (32.0 * x as f64).floor().min(31.0) != (32.0 * clamped).floor().min(31.0) {
                        t.counts[0] += 1;
                    }
                    prev = x;
                }
            }
            t
        })
        .reduce(Tally::default, Tally::merge);
    t.assert_clean("sector_coordinate");
    eprintln!("  {} of 2 433 321 θ land in a sector other than the real-number one", t.counts[0]);
    report("sector_coordinate_at_every_f32_near_the_sector_edges", start, "2.4 M angles");
}

// =============================================================================================
// 5. The stochastic depth map's reservoir any-hit (spec svao-raysd §7.3).
//
// The any-hit's random number is u = rotate(hash(b1, b2), r) = frac(hash + r) with the frame
// rotation r = `SdPayload::rotation`. At the barycentrics (0, 0) the Wyman–McGuire hash is
// frac(10⁴·sin 0·(0.1 + |sin 0|)) = 0, so u = r exactly: the rotation feeds the reservoir any
// u. Only ⌊u·count⌋ matters, so with u uniform each slot j ∈ [0, count) has probability
// 1/count: one representative u per slot ((j + ½)/count) enumerates every outcome, equally
// likely; `reservoir_slot_quantises_every_u` shows that every f32 u lands where
// ⌊u·count⌋ puts it.

/// Every f32 u ∈ [+0, 1) and every count c = 2 … 6 at which the reservoir draws a slot (N = c −
/// 1 layers, the c-th candidate): `reservoir_slot` returns trunc(u ⊗ c) (binary32 product) when
/// it is < N and `NO_SLOT` otherwise; that is the real ⌊u·c⌋ except where u·c rounds up to an
/// integer: one u, 0x3F55_5555 = 0.833 333 31 at c = 6 (6u = 5 − 2⁻²³ rounds to 5), lands in
/// slot 5 (rejected with N = 5) instead of 4 — a shift of 2⁻²⁴ of probability. Also:
/// rotate(hash(0, 0), u) = u for every u.
///
/// Domain 1 065 353 216 f32 × 5 counts; measured 12 s.
#[test]
fn reservoir_slot_quantises_every_u() {
    let start = Instant::now();
    assert_eq!(wyman_hash(0.0, 0.0).to_bits(), 0, "hash(0, 0) = frac(0) = +0");
    let t = sweep(0, 0x3F7F_FFFF, |a, b, t| {
        let h = wyman_hash(0.0, 0.0);
        let mut payloads: [SdPayload; 5] = std::array::from_fn(|i| SdPayload {
            depth: [1.0; MAX_LAYERS],
            count: 0,
            layers: i as u32 + 1,
            max_count: u32::MAX,
            cos_theta: 1.0,
            near: 0.0,
            far: 1.0,
            rotation: 0.0,
        });
        for k in a..b {
            let u = f32::from_bits(k as u32);
            let r = rotate(h, u);
            t.check(k, r.to_bits() == u.to_bits(), || format!("rotate(hash(0, 0), {u:e}) = {r:e}"));
            for (i, p) in payloads.iter_mut().enumerate() {
                let c = i as u32 + 2;
                p.count = c - 1;
                let slot = reservoir_slot(p, u, 0.5);
                let j32 = mul32(u, c as f32) as u32;
                let want = if j32 < c - 1 { j32 } else { NO_SLOT };
                t.check(k, (slot == want) & (p.count == c), || {
                    format!("reservoir_slot(u = {u:e}, count {c}) = {slot}, expected {want}")
                });
                let exact = (u as f64 * c as f64).floor() as u32;
                if exact != j32 {
                    t.counts[c as usize] += 1;
                    t.worst[0] = (u as f64, c as u64);
                }
            }
        }
    });
    t.assert_clean("reservoir slot quantisation");
    eprintln!(
        "  u whose binary32 u·c rounds into the next slot, c = 2…6: {:?} (u = {:e} at c = {})",
        &t.counts[2..=6],
        t.worst[0].0,
        t.worst[0].1
    );
    assert_eq!(t.counts[2..=6], [0, 0, 0, 0, 1], "u·c rounding up to an integer");
    report("reservoir_slot_quantises_every_u", start, "1 065 353 216 f32 × 5 counts");
}

/// All permutations of 0..k.
fn permutations(k: usize) -> Vec<Vec<usize>> {
    if k == 0 {
        return vec![vec![]];
    }
    let mut out = Vec::new();
    for p in permutations(k - 1) {
        for i in 0..=p.len() {
            let mut q = p.clone();
            q.insert(i, k - 1);
            out.push(q);
        }
    }
    out
}

/// Exact non-negative rationals.
#[derive(Copy, Clone, Debug, PartialEq)]
struct Q(u128, u128);
impl Q {
    fn new(n: u128, d: u128) -> Q {
        fn gcd(a: u128, b: u128) -> u128 {
            if b == 0 { a } else { gcd(b, a % b) }
        }
        let g = gcd(n, d).max(1);
        Q(n / g, d / g)
    }
    fn add(self, o: Q) -> Q {
        Q::new(self.0 * o.1 + o.0 * self.1, self.1 * o.1)
    }
    fn mul(self, o: Q) -> Q {
        Q::new(self.0 * o.0, self.1 * o.1)
    }
    fn one_minus(self) -> Q {
        Q::new(self.1 - self.0, self.1)
    }
}

fn binomial(n: u64, k: u64) -> u64 {
    (0..k).fold(1, |acc, i| acc * (n - i) / (i + 1))
}

/// The reservoir any-hit (spec svao-raysd §7.3) over every order of K distinct candidate
/// depths, every reservoir choice and every alpha-test outcome, for N ∈ {1, 2, 3, 4, 8}
/// layers and K = 1 … 6 candidates: per (N, K) K! orders × K!/N! equally likely slot choices
/// (candidate i > N draws ⌊u·i⌋ ∈ [0, i)) × 2^K alpha outcomes, with MAX_COUNT running through
/// 0 … K + 1. Asserted, each derived from the spec, not from the code:
///
/// * every run: candidate i ≤ N takes slot i − 1, a later one its drawn slot if < N; the final
///   layer j is the nearest of the candidates that took slot j and passed the alpha test (1.0,
///   far, if none) — z-cull keeps the nearer sample; the alpha test runs exactly for the
///   candidates that took a slot and are nearer than what it holds then; the any-hit ACCEPTs
///   iff count ≥ MAX_COUNT; the count ends at K;
/// * the distribution (alpha passing): candidate i survives with probability
///   Σ_j p_i(j)·Π_{k nearer than i} (1 − p_k(j)), p_i(j) = [j = i − 1] for i ≤ N and 1/i for
///   i > N, exactly (rational arithmetic against the counts over the K!/N! choices);
/// * far to near (z-cull never fires): Algorithm R — every N-subset of the candidates is the
///   survivor set equally often, each candidate kept with probability N/K (K ≥ N);
/// * order: the result is NOT independent of the candidate order, as the spec says ("Which hits
///   survive depends on the order in which any-hit is called"): the nearest candidate survives
///   with probability min(1, N/i) when it arrives i-th — certainly among the first N, N/K last.
///
/// Domain Σ over (N, K) of K!·(K!/N!)·2^K = 57 532 282 any-hit sequences; measured 4 s.
#[test]
fn reservoir_any_hit_over_every_order_choice_and_alpha_outcome() {
    let start = Instant::now();
    let mut runs = 0u64;
    for layers in [1usize, 2, 3, 4, 8] {
        for k in 1..=6usize {
            // Slot choices: candidate i (1-based) > N draws from i values.
            let radices: Vec<usize> = (1..=k).map(|i| if i > layers { i } else { 1 }).collect();
            let total: usize = radices.iter().product();
            let depth_of = |rank: usize| (rank + 1) as f32 / 8.0;
            let perms = permutations(k);
            let per_order: Vec<(Tally, Vec<u64>, HashMap<u32, u64>)> = perms
                .par_iter()
                .map(|order| {
                    let mut t = Tally::default();
                    let mut survived = vec![0u64; k]; // by depth rank, alpha all passing
                    let mut subsets: HashMap<u32, u64> = HashMap::new(); // survivor set by arrival
                    for alpha in 0..1u32 << k {
                        let max_count = alpha % (k as u32 + 2);
                        for choice in 0..total {
                            // Decode the mixed-radix choice: slot drawn by each candidate.
                            let mut rest = choice;
                            let slots: Vec<usize> = (0..k)
                                .map(|i| {
                                    let r = radices[i];
                                    let s = rest % r;
                                    rest /= r;
                                    if i < layers { i } else { s }
                                })
                                .collect();
                            // Reference: the spec's any-hit, slot by slot.
                            let mut held = vec![1.0f32; layers];
                            let mut want_calls = 0u32;
                            for i in 0..k {
                                let (s, z) = (slots[i], depth_of(order[i]));
                                if s < layers && z < held[s] {
                                    want_calls |= 1 << i;
                                    if alpha >> i & 1 == 1 {
                                        held[s] = z;
                                    }
                                }
                            }
                            // The kernel.
                            let mut p = SdPayload {
                                depth: [1.0; MAX_LAYERS],
                                count: 0,
                                layers: layers as u32,
                                max_count,
                                cos_theta: 1.0,
                                near: 0.0,
                                far: 1.0,
                                rotation: 0.0,
                            };
                            let mut calls = 0u32;
                            let mut accepts = 0u32;
                            for i in 0..k {
                                let count = i + 1;
                                p.rotation = if count > layers {
                                    ((slots[i] as f64 + 0.5) / count as f64) as f32
                                } else {
                                    0.999 // unused: the first N candidates take slot count − 1
                                };
                                let accept = reservoir_any_hit(&mut p, depth_of(order[i]), vec2(0.0, 0.0), || {
                                    calls |= 1 << i;
                                    alpha >> i & 1 == 1
                                });
                                accepts |= (accept as u32) << i;
                            }
                            let want_accepts = (0..k).filter(|&i| i as u32 + 1 >= max_count).fold(0, |m, i| m | 1 << i);
                            let key = choice as u64;
                            t.check(key, p.depth[..layers] == held[..] && p.depth[layers..].iter().all(|&d| d == 1.0), || {
                                format!(
                                    "N={layers} K={k} order {order:?} slots {slots:?} alpha {alpha:b}: layers {:?}, spec {held:?}",
                                    &p.depth[..layers]
                                )
                            });
                            t.check(key, calls == want_calls, || {
                                format!("N={layers} K={k} order {order:?} slots {slots:?}: alpha tests {calls:b}, spec {want_calls:b}")
                            });
                            t.check(key, accepts == want_accepts && p.count == k as u32, || {
                                format!("N={layers} K={k} MAX_COUNT {max_count}: accepts {accepts:b}, spec {want_accepts:b}; count {}", p.count)
                            });
                            if alpha == (1 << k) - 1 {
                                let mut set = 0u32;
                                for (i, &rank) in order.iter().enumerate() {
                                    if p.depth[..layers].contains(&depth_of(rank)) {
                                        survived[rank] += 1;
                                        set |= 1 << i;
                                    }
                                }
                                *subsets.entry(set).or_default() += 1;
                            }
                        }
                    }
                    (t, survived, subsets)
                })
                .collect();
            runs += ((perms.len() * total) as u64) << k;
            for (order, (t, survived, subsets)) in perms.iter().zip(&per_order) {
                t.assert_clean(&format!("reservoir N={layers} K={k}"));
                // Survival probability of each candidate (by arrival i, 1-based) from the spec.
                let p_slot = |i: usize, j: usize| -> Q {
                    if i <= layers {
                        Q::new((j == i - 1) as u128, 1)
                    } else if j < layers {
                        Q::new(1, i as u128)
                    } else {
                        Q::new(0, 1)
                    }
                };
                for i in 1..=k {
                    let mut p = Q::new(0, 1);
                    for j in 0..layers {
                        let mut term = p_slot(i, j);
                        for m in 1..=k {
                            if order[m - 1] < order[i - 1] {
                                term = term.mul(p_slot(m, j).one_minus());
                            }
                        }
                        p = p.add(term);
                    }
                    let got = survived[order[i - 1]];
                    assert_eq!(
                        got as u128 * p.1,
                        p.0 * total as u128,
                        "N={layers} K={k} order {order:?}: candidate {i} survives {got}/{total}, spec {}/{}",
                        p.0,
                        p.1
                    );
                    if order[i - 1] == 0 {
                        // The nearest: min(1, N/i).
                        assert_eq!(p, Q::new(layers.min(i) as u128, i as u128), "nearest at arrival {i}");
                    }
                }
                // Far to near: Algorithm R.
                if order.iter().enumerate().all(|(i, &r)| r == k - 1 - i) {
                    let kept = layers.min(k) as u64;
                    let sets = binomial(k as u64, kept);
                    assert_eq!(subsets.len() as u64, sets, "N={layers} K={k}: survivor sets {subsets:?}");
                    for (set, &n) in subsets {
                        assert_eq!(set.count_ones() as u64, kept);
                        assert_eq!(n * sets, total as u64, "N={layers} K={k}: set {set:b} kept {n} of {total} times");
                    }
                }
            }
            if k > layers {
                // Order dependence: nearest first vs nearest last.
                let first = per_order.iter().zip(&perms).find(|(_, o)| o[0] == 0).unwrap().0.1[0];
                let last = per_order.iter().zip(&perms).find(|(_, o)| o[k - 1] == 0).unwrap().0.1[0];
                assert!(first == total as u64 && last * k as u64 == (layers * total) as u64, "N={layers} K={k}");
            }
        }
    }
    assert_eq!(runs, 57_532_282, "sequences enumerated");
    report("reservoir_any_hit_over_every_order_choice_and_alpha_outcome", start, &format!("{runs} sequences"));
}
