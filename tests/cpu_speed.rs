//! CPU simulator speed: the CPU-only fast paths must not change a result. The inline
//! floor/ceil equal `f32::floor`/`f32::ceil` bit for bit, `pow(x, 2)` is the exact product, and
//! the tiled pixel loop visits every pixel of its rectangle exactly once and nothing else.

use aokit_cpu::screen::{TILE_COLS, TILE_ROWS, tiled};
use aokit_shaders::common::math::{ceil, floor, frac, pow};
use aokit_shaders::glam::uvec2;
use proptest::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering};

/// The values where a truncating floor goes wrong: signed zeros, halves and near-integers on
/// both sides of 0, the edge 2²³ where every float becomes integral, the i32 range, NaN, ±∞,
/// subnormals.
fn edge_cases() -> Vec<f32> {
    let mut v = vec![
        0.0,
        -0.0,
        0.5,
        -0.5,
        1.0,
        -1.0,
        0.999_999_94,
        -0.999_999_94,
        1.000_000_1,
        -1.000_000_1,
        2.5,
        -2.5,
        8_388_607.5,
        -8_388_607.5,
        8_388_608.0,
        -8_388_608.0,
        8_388_609.0,
        16_777_217.0,
        2_147_483_648.0,
        -2_147_483_648.0,
        3.0e9,
        -3.0e9,
        f32::MAX,
        f32::MIN,
        f32::MIN_POSITIVE,
        -f32::MIN_POSITIVE,
        1.0e-45,
        -1.0e-45,
        f32::INFINITY,
        f32::NEG_INFINITY,
    ];
    for k in -40..=40 {
        let x = k as f32 * 0.25;
        v.extend([x, f32::from_bits(x.to_bits() + 1), f32::from_bits(x.to_bits().wrapping_sub(1))]);
    }
    v
}

fn same_bits(a: f32, b: f32) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

#[test]
fn inline_floor_and_ceil_are_bit_exact_on_edge_cases() {
    for x in edge_cases() {
        assert!(same_bits(floor(x), x.floor()), "floor({x:e}) = {:e}, expected {:e}", floor(x), x.floor());
        assert!(same_bits(ceil(x), x.ceil()), "ceil({x:e}) = {:e}, expected {:e}", ceil(x), x.ceil());
        assert!(same_bits(frac(x), x - x.floor()), "frac({x:e})");
    }
    assert!(floor(f32::NAN).is_nan() && ceil(f32::NAN).is_nan());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4096))]
    /// Any bit pattern (NaNs, subnormals, every exponent).
    #[test]
    fn inline_floor_and_ceil_are_bit_exact_on_any_float(bits in any::<u32>()) {
        let x = f32::from_bits(bits);
        prop_assert!(same_bits(floor(x), x.floor()), "floor({:e})", x);
        prop_assert!(same_bits(ceil(x), x.ceil()), "ceil({:e})", x);
    }

    /// The exact square for p = 2 (within half an ulp of the f64 square), `powf` otherwise.
    #[test]
    fn pow_two_is_the_correctly_rounded_square(x in 0.0f32..4.0, p in 0.5f32..3.0) {
        let sq = (x as f64 * x as f64) as f32;
        prop_assert_eq!(pow(x, 2.0).to_bits(), sq.to_bits());
        if p != 2.0 {
            prop_assert_eq!(pow(x, p).to_bits(), x.powf(p).to_bits());
        }
    }
}

#[test]
fn tiled_visits_each_pixel_of_its_rectangle_once() {
    // Sizes that are not multiples of the tile, a rectangle touching no image edge, and one
    // narrower than a tile.
    for (w, h, xs, ys) in [
        (2 * TILE_COLS + 7, 3 * TILE_ROWS + 5, 3..2 * TILE_COLS + 2, 4..3 * TILE_ROWS + 1),
        (TILE_COLS - 1, TILE_ROWS + 1, 0..TILE_COLS - 1, 0..TILE_ROWS + 1),
        (10, 2 * TILE_ROWS, 2..8, TILE_ROWS..2 * TILE_ROWS),
    ] {
        let mut out = vec![0u32; (w * h) as usize];
        let rows_reported = AtomicU64::new(0);
        let report = |n: u64| {
            rows_reported.fetch_add(n, Ordering::Relaxed);
        };
        tiled(&mut out, w, xs.clone(), ys.clone(), &report, |p, v| {
            // Store the pixel's own index + 1: a pixel written through another's slot, or twice,
            // shows.
            *v += p.y * w + p.x + 1;
        });
        for y in 0..h {
            for x in 0..w {
                let want = if xs.contains(&x) && ys.contains(&y) { y * w + x + 1 } else { 0 };
                assert_eq!(out[(y * w + x) as usize], want, "pixel {:?} of {w}×{h}", uvec2(x, y));
            }
        }
        assert_eq!(rows_reported.load(Ordering::Relaxed), ys.len() as u64, "progress rows of {w}×{h}");
    }
}
