//! Ring 1: the kernel math of `aokit-shaders`, checked against values computed independently
//! here (f64, from the spec's formulas), never copied from the implementation.

use aokit_shaders::common::ViewParams;
use aokit_shaders::common::camera::Camera;
use aokit_shaders::common::float_order::{from_ordered_bits, ordered_bits};
use aokit_shaders::common::hash::wyman_hash;
use aokit_shaders::common::normal_codec::{decode_normal, encode_normal};
use aokit_shaders::common::tables::{
    JitterTable, SD_JITTER_PAPER, SD_JITTER_SCRAMBLED, VAO_RADII, rotation_angle, sd_jitter,
};
use aokit_shaders::glam::{UVec2, Vec3, uvec2, vec2, vec3};
use proptest::prelude::*;

/// The spec's 3.141 (svao-raysd §1), written here independently of the kernel's constant.
#[allow(clippy::approx_constant)]
const SPEC_PI: f64 = 3.141;

fn view() -> ViewParams {
    Camera::look_at(Vec3::ZERO, vec3(0.0, 0.0, -1.0), Vec3::Y, 60f32.to_radians(), uvec2(320, 200), 16, 0.1, 100.0).view
}

/// Base-2 radical inverse (Van der Corput), computed independently.
fn van_der_corput(mut i: u32) -> f64 {
    let (mut x, mut f) = (0.0, 0.5);
    while i > 0 {
        x += f * (i & 1) as f64;
        i >>= 1;
        f *= 0.5;
    }
    x
}

#[test]
fn vao_radii_follow_inversion_sampling_of_the_chord_pdf() {
    // Spec svao-raysd §4.2: ρ_i = sqrt(1 − ψ_i^(2/3)), ψ_i = VdC(8 + i); the table is rounded to 6 decimals.
    let expected_psi = [1.0, 9.0, 5.0, 13.0, 3.0, 11.0, 7.0, 15.0].map(|k| k / 16.0);
    for i in 0..8 {
        let psi = van_der_corput(8 + i as u32);
        assert_eq!(psi, expected_psi[i]);
        let rho = (1.0 - psi.powf(2.0 / 3.0)).sqrt();
        assert!((VAO_RADII[i] as f64 - rho).abs() < 1e-6, "radius {i}: {} vs {rho}", VAO_RADII[i]);
    }
}

/// HBAO+ kernel tables (spec svao-raysd §4.5): radii ρ_i = 2·asin(ψ_i^1.25)/π with
/// ψ_i = VdC(8 + i), half-chords sqrt(1 − ρ_i²) (hemisphere clipping as for VAO) and weights
/// pdf_i = 0.9·(1 − ρ_i)^1.5, each recomputed in f64 here; the tables are f32, so within 1e-7.
/// The spec's listed radii (svao-raysd §4.2 table, 17 digits) are checked too.
#[test]
fn hbao_tables_follow_their_formulas() {
    use aokit_shaders::common::tables::{HBAO_HALF_CHORDS, HBAO_PDFS, HBAO_RADII};
    let listed = [
        0.019897607325877215,
        0.3239192018939078,
        0.15013283288204182,
        0.5608856339193332,
        0.07874804859295396,
        0.4306374970658152,
        0.23159241868180838,
        0.74770696488701,
    ];
    for i in 0..8 {
        let psi = van_der_corput(8 + i as u32);
        let rho = 2.0 * psi.powf(1.25).asin() / std::f64::consts::PI;
        assert!((rho - listed[i]).abs() < 1e-15, "spec table, radius {i}: {rho} vs {}", listed[i]);
        let half_chord = (1.0 - rho * rho).sqrt();
        let pdf = 0.9 * (1.0 - rho).powf(1.5);
        for (name, table, want) in [
            ("radius", HBAO_RADII[i], rho),
            ("half-chord", HBAO_HALF_CHORDS[i], half_chord),
            ("pdf", HBAO_PDFS[i], pdf),
        ] {
            assert!((table as f64 - want).abs() < 1e-7, "HBAO {name} {i}: table {table} vs formula {want}");
        }
    }
}

#[test]
fn rotation_table_matches_spec_angles() {
    // Spec svao-raysd §4.1.1: Bayer ranks k, texel floor(k·255/16), ξ = texel/255·2·3.141.
    let ranks = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];
    let listed = [
        [0.000000, 3.128682, 0.763694, 3.917012],
        [4.705341, 1.552024, 5.493671, 2.340353],
        [1.157859, 4.311176, 0.369529, 3.522847],
        [5.887835, 2.734518, 5.099506, 1.946188],
    ];
    for y in 0..4u32 {
        for x in 0..4u32 {
            let k = ranks[y as usize][x as usize] as f64;
            let xi = ((k * 255.0 / 16.0).floor() / 255.0) * 2.0 * SPEC_PI;
            assert!((xi - listed[y as usize][x as usize]).abs() < 1e-6);
            // Periodic in 4 pixels, including inside the guard band.
            for (dx, dy) in [(0, 0), (4, 0), (0, 8), (64, 64)] {
                let got = rotation_angle(uvec2(x + dx, y + dy)) as f64;
                assert!((got - xi).abs() < 2e-6, "({x},{y})+({dx},{dy}): {got} vs {xi}");
            }
        }
    }
}

/// Every column and row of the 16×16 sub-grid of a 4×4-pixel block is hit exactly once.
fn assert_latin_hypercube(table: &[[f32; 2]; 16]) {
    let mut cols = [0; 16];
    let mut rows = [0; 16];
    for y in 0..4 {
        for x in 0..4 {
            let j = table[y * 4 + x];
            assert!((0.0..1.0).contains(&j[0]) && (0.0..1.0).contains(&j[1]));
            cols[((x as f32 + j[0]) * 4.0).floor() as usize] += 1;
            rows[((y as f32 + j[1]) * 4.0).floor() as usize] += 1;
        }
    }
    assert_eq!(cols, [1; 16], "columns");
    assert_eq!(rows, [1; 16], "rows");
}

#[test]
fn sd_jitter_tables_are_latin_hypercubes() {
    assert_latin_hypercube(&SD_JITTER_SCRAMBLED);
    assert_latin_hypercube(&SD_JITTER_PAPER);
    // Lookup uses (q.y mod 4)·4 + (q.x mod 4).
    assert_eq!(
        sd_jitter(uvec2(5, 6), JitterTable::Scrambled as u32, 0),
        vec2(SD_JITTER_SCRAMBLED[9][0], SD_JITTER_SCRAMBLED[9][1])
    );
    assert_eq!(sd_jitter(uvec2(5, 6), JitterTable::None as u32, 0), vec2(0.5, 0.5));
    // Spec svao-raysd §7.2 lists idx 13 = (0.44085410237312317, 0.011881716549396515).
    assert_eq!(SD_JITTER_SCRAMBLED[13], [0.440_854_1_f64 as f32, 0.011_881_717_f64 as f32]);
}

#[test]
fn wyman_hash_matches_f64_formula_and_is_uniform() {
    // The 1e4 scale amplifies f32 rounding of the sine arguments to ~1e-2 absolute error, so
    // the f64 formula must agree on the circle for nearly all inputs: a wrong constant or
    // operand order would agree within 0.05 for only ~10 % of them.
    let mut rng = 0x2545F491u64;
    let mut next = || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 40) as f64 / (1u64 << 24) as f64
    };
    let mut bins = [0u32; 16];
    let n = 160_000;
    let mut close = 0;
    for _ in 0..n {
        let (u, v) = ((next() as f32) as f64, (next() as f32) as f64);
        let x = 1e4 * (17.0 * u + 0.1 * v).sin() * (0.1 + (13.0 * v + u).sin().abs());
        let expected = x - x.floor();
        let got = wyman_hash(u as f32, v as f32) as f64;
        assert!((0.0..1.0).contains(&got));
        let d = (got - expected).abs();
        close += (d.min(1.0 - d) < 0.05) as u32;
        bins[(got * 16.0) as usize] += 1;
    }
    assert!(close as f64 > 0.99 * n as f64, "only {close} of {n} within 0.05 of the f64 formula");
    // χ² with 15 degrees of freedom; 37.7 is the p = 0.001 critical value.
    let e = n as f64 / 16.0;
    let chi2: f64 = bins.iter().map(|&b| (b as f64 - e).powi(2) / e).sum();
    assert!(chi2 < 37.7, "χ² = {chi2}, bins {bins:?}");
}

#[test]
fn ordered_bits_handles_the_edges() {
    assert_eq!(ordered_bits(-0.0), 0);
    assert_eq!(ordered_bits(-1.0), 0);
    assert_eq!(ordered_bits(f32::NAN), 0);
    assert_eq!(ordered_bits(f32::MAX), 0x7F7F_FFFF);
    assert_eq!(ordered_bits(f32::from_bits(1)), 1); // smallest denormal
    assert_eq!(from_ordered_bits(ordered_bits(3.5)), 3.5);
}

fn non_negative() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(0.0f32),
        Just(f32::MAX),
        Just(f32::MIN_POSITIVE),
        (1u32..0x0080_0000).prop_map(f32::from_bits), // denormals
        (0.0f32..f32::MAX),
        (0.0f32..10.0),
    ]
}

proptest! {
    #[test]
    fn ordered_bits_preserve_order(a in non_negative(), b in non_negative()) {
        prop_assert_eq!(a < b, ordered_bits(a) < ordered_bits(b));
        prop_assert_eq!(a == b, ordered_bits(a) == ordered_bits(b));
    }

    #[test]
    fn uv_view_roundtrip(u in 0.0f32..1.0, v in 0.0f32..1.0, d in 0.2f32..90.0) {
        let view = view();
        let x = view.uv_to_view(vec2(u, v), d);
        prop_assert!((x.z + d).abs() <= 1e-6 * d);
        let back = view.view_to_uv(x);
        prop_assert!((back - vec2(u, v)).abs().max_element() < 1e-5);
    }

    #[test]
    fn normal_codec_roundtrip(x in -1.0f32..1.0, y in -1.0f32..1.0, z in -1.0f32..1.0) {
        let n = vec3(x, y, z);
        prop_assume!(n.length() > 1e-3);
        let back = decode_normal(encode_normal(n));
        prop_assert!((back.length() - 1.0).abs() < 1e-5);
        // snorm8 octahedral: worst-case angular error a little under 1°.
        prop_assert!(back.dot(n.normalize()) > 0.9997, "{n:?} -> {back:?}");
    }
}

#[test]
fn normal_codec_reference_bytes() {
    // Spec svao-raysd §1 worked by hand: +Z → p = (0, 0) → bytes (0, 0).
    assert_eq!(encode_normal(vec3(0.0, 0.0, 1.0)), 0);
    // +X: p = (1, 0) → 127 in byte 0.
    assert_eq!(encode_normal(vec3(1.0, 0.0, 0.0)), 127);
    // −Y: p = (0, −1) → −127 = 0x81 in byte 1.
    assert_eq!(encode_normal(vec3(0.0, -1.0, 0.0)), 0x81 << 8);
    // −Z: p = (0, 0) wrapped → (1·sign(0), 1·sign(0)) = (1, 1) → (127, 127).
    assert_eq!(encode_normal(vec3(0.0, 0.0, -1.0)), 127 | (127 << 8));
    assert_eq!(decode_normal(127 | (127 << 8)), vec3(0.0, 0.0, -1.0));
    // Degenerate input (zero, NaN) encodes as +Z instead of poisoning the kernel.
    assert_eq!(decode_normal(encode_normal(Vec3::ZERO)), Vec3::Z);
    assert_eq!(decode_normal(encode_normal(Vec3::NAN)), Vec3::Z);
}

#[test]
fn guard_band_widens_the_frustum_at_the_same_focal_length() {
    // 1920×1080 with g = 64 → 2048×1208 (spec svao-raysd §1); tan of the half fov scales with pixels.
    let cam = Camera::look_at(Vec3::ZERO, -Vec3::Z, Vec3::Y, 60f32.to_radians(), uvec2(1920, 1080), 64, 0.1, 100.0);
    assert_eq!(cam.view.size(), uvec2(2048, 1208));
    let ty = (30f64.to_radians()).tan() * 1208.0 / 1080.0;
    assert!((cam.view.tan_half_fov.y as f64 - ty).abs() < 1e-6);
    assert!((cam.view.tan_half_fov.x as f64 - ty * 2048.0 / 1208.0).abs() < 1e-6);
    // The inner image's top edge (pixel row 64) is at the 30° half-angle.
    let uv_top = 64.0 / 1208.0;
    let dir = cam.primary_ray_direction(vec2(0.5, uv_top));
    let angle = dir.y.atan2(-dir.z) as f64;
    assert!((angle - 30f64.to_radians()).abs() < 1e-5, "{angle}");
    assert!(
        cam.view.is_inner(uvec2(64, 64))
            && !cam.view.is_inner(uvec2(63, 64))
            && !cam.view.is_inner(UVec2::new(1984, 100))
    );
}

#[test]
fn linear_depth_of_a_hit_is_the_view_z() {
    let cam = Camera::look_at(vec3(1.0, 2.0, 3.0), vec3(4.0, 0.0, -2.0), Vec3::Y, 1.0, uvec2(64, 48), 8, 0.1, 100.0);
    for uv in [vec2(0.1, 0.2), vec2(0.5, 0.5), vec2(0.9, 0.7)] {
        let dir = cam.primary_ray_direction(uv);
        let t = 7.5;
        let point = cam.eye() + dir * t;
        let view_z = cam.world_to_view.transform_point3(point).z;
        assert!((cam.linear_depth_of_hit(dir, t) + view_z).abs() < 1e-4);
        // And the point reprojects to the same uv.
        let back = cam.view.view_to_uv(cam.world_to_view.transform_point3(point));
        assert!((back - uv).abs().max_element() < 1e-5);
    }
}

#[test]
fn precomputed_trigonometry_matches_the_formulas() {
    use aokit_shaders::common::tables::{ROTATION_SIN_COS, VAO_DIRECTIONS, VAO_HALF_CHORDS};
    for i in 0..8 {
        let alpha = (i as f64 / 8.0) * 2.0 * SPEC_PI;
        assert!((VAO_DIRECTIONS[i][0] as f64 - alpha.sin()).abs() < 1e-7);
        assert!((VAO_DIRECTIONS[i][1] as f64 - alpha.cos()).abs() < 1e-7);
        let rho = VAO_RADII[i] as f64;
        assert!((VAO_HALF_CHORDS[i] as f64 - (1.0 - rho * rho).sqrt()).abs() < 1e-7);
    }
    for y in 0..4u32 {
        for x in 0..4u32 {
            let xi = rotation_angle(uvec2(x, y)) as f64;
            let [s, c] = ROTATION_SIN_COS[y as usize][x as usize];
            assert!((s as f64 - xi.sin()).abs() < 1e-6 && (c as f64 - xi.cos()).abs() < 1e-6, "({x},{y})");
        }
    }
}

#[test]
fn atomic_min_max_on_ordered_bits_reproduce_f32_min_max_under_contention() {
    use aokit_shaders::common::atomics::AtomicU32Buffer;
    use aokit_shaders::common::float_order::{RAY_MAX_CLEAR, RAY_MIN_CLEAR};
    use std::sync::atomic::{AtomicU32, Ordering};
    let slots = [AtomicU32::new(RAY_MIN_CLEAR), AtomicU32::new(RAY_MAX_CLEAR)];
    let values: Vec<f32> = (0..40_000u32).map(|i| ((i.wrapping_mul(2_654_435_761) >> 8) as f32) * 1e-3).collect();
    std::thread::scope(|s| {
        for chunk in values.chunks(10_000) {
            let slots = &slots;
            s.spawn(move || {
                let mut buf: &[AtomicU32] = slots;
                for &v in chunk {
                    buf.atomic_min(0, ordered_bits(v));
                    buf.atomic_max(1, ordered_bits(v));
                }
            });
        }
    });
    let min = values.iter().copied().fold(f32::INFINITY, f32::min);
    let max = values.iter().copied().fold(0.0, f32::max);
    assert_eq!(from_ordered_bits(slots[0].load(Ordering::Relaxed)), min);
    assert_eq!(from_ordered_bits(slots[1].load(Ordering::Relaxed)), max);
}

/// VBAO's `precise_acos` (A&S 4.4.46, one fixed operation sequence for every back-end) is
/// within 5·10⁻⁷ rad of the true acos at every one of 2²¹ + 1 evenly spaced points of [−1, 1]
/// and at ±1, ±0 and the smallest normals: 2·10⁻⁸ rad of method error plus binary32 rounding
/// (about two ulp of a result up to π; a sector of VBAO's 32 is 0.098 rad, so this moves a
/// sector edge by 5·10⁻⁶ of a sector);
/// the scalar version and cpu-sim's lanes agree bit for bit.
#[test]
fn precise_acos_is_within_5e7_rad_everywhere_and_lanes_agree() {
    use aokit_shaders::common::lanes::{CPU_LANES, CpuLanes, Lanes};
    use aokit_shaders::common::math::precise_acos;
    let n = 1u32 << 21;
    let mut worst = (0.0f64, 0.0f32);
    let mut points: Vec<f32> = (0..=n).map(|i| -1.0 + 2.0 * i as f32 / n as f32).collect();
    points.extend([-1.0, -0.0, 0.0, 1.0, f32::MIN_POSITIVE, -f32::MIN_POSITIVE, 1.0 - f32::EPSILON]);
    for &x in &points {
        let e = (precise_acos(x) as f64 - (x as f64).acos()).abs();
        if e > worst.0 {
            worst = (e, x);
        }
    }
    assert!(worst.0 <= 5e-7, "max error {:.2e} rad at x = {}", worst.0, worst.1);
    for chunk in points.chunks_exact(CPU_LANES).step_by(97) {
        let lanes = precise_acos(CpuLanes::from_lanes(|i| chunk[i]));
        for (i, &x) in chunk.iter().enumerate() {
            assert_eq!(lanes.lane(i).to_bits(), precise_acos(x).to_bits(), "x = {x}");
        }
    }
}
