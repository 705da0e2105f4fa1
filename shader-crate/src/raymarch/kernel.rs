//! The Poisson-disk kernel (spec gtao-raymarch-hybrid §3.3), built once on the host in f64 and
//! uploaded as f32: best-candidate sampling with PCG32, or a Vogel spiral.

use crate::glam::{Vec2, vec2};

/// PCG32 (O'Neill's `pcg32_srandom_r` / `pcg32_random_r`).
struct Pcg32 {
    state: u64,
    inc: u64,
}

impl Pcg32 {
    fn new(initstate: u64, initseq: u64) -> Self {
        let mut rng = Pcg32 { state: 0, inc: (initseq << 1) | 1 };
        rng.next_u32();
        rng.state = rng.state.wrapping_add(initstate);
        rng.next_u32();
        rng
    }

    fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.state = old.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(self.inc);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rot = (old >> 59) as u32;
        xorshifted.rotate_right(rot)
    }

    fn unit(&mut self) -> f64 {
        self.next_u32() as f64 / 4_294_967_296.0
    }
}

/// Best-candidate Poisson disk of `n` points in the unit disk (spec gtao-raymarch-hybrid §3.3): point i keeps the
/// best of `32·max(i, 1)` uniform candidates `(√u₁ cos 2πu₂, √u₁ sin 2πu₂)` by distance to the
/// accepted points; ties keep the first. PCG32 seeded with the spec's initstate/initseq.
pub fn best_candidate(n: usize) -> Vec<Vec2> {
    let mut rng = Pcg32::new(0x853c_49e6_748f_ea9b, 0xda3e_39cb_94b9_5bdb);
    let mut points: Vec<(f64, f64)> = Vec::with_capacity(n);
    for i in 0..n {
        let mut best = (0.0, 0.0);
        let mut best_distance = -1.0;
        for _ in 0..32 * i.max(1) {
            let (u1, u2) = (rng.unit(), rng.unit());
            let r = u1.sqrt();
            let c = (r * (2.0 * std::f64::consts::PI * u2).cos(), r * (2.0 * std::f64::consts::PI * u2).sin());
            let d = points.iter().map(|p| (p.0 - c.0).hypot(p.1 - c.1)).fold(f64::INFINITY, f64::min);
            if d > best_distance {
                best_distance = d;
                best = c;
            }
        }
        points.push(best);
    }
    points.into_iter().map(|(x, y)| vec2(x as f32, y as f32)).collect()
}

/// Vogel spiral: `p_i = √((i+½)/N)·(cos iγ, sin iγ)`, γ = π(3 − √5) (spec gtao-raymarch-hybrid §3.3).
pub fn vogel(n: usize) -> Vec<Vec2> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let r = ((i as f64 + 0.5) / n as f64).sqrt();
            let a = i as f64 * golden;
            vec2((r * a.cos()) as f32, (r * a.sin()) as f32)
        })
        .collect()
}
