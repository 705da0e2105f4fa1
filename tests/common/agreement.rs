//! The agreement statistics and tolerances every back-end comparison uses (CPU ≡ Vulkan, the
//! engine path, wgpu, the WebGPU page, the C sample, the Bevy plugin), written once. Self-contained
//! (it needs only `aokit-shaders`), so another workspace's tests can include it by path.
#![allow(dead_code)]

/// One step of an 8-bit AO output: the quantum an engine's R8 target can show.
pub const STEP: f32 = 1.0 / 255.0;
/// Deterministic kernels: at least this fraction of inner pixels within one [`STEP`] (a one-ulp
/// difference in a rounding flips a value across a step boundary in a few pixels, no more).
pub const MIN_WITHIN: f64 = 0.999;
/// Deterministic kernels: the MSE a handful of one-step flips gives is ~1e-8; a wrong term, a
/// missing pass or one misplaced tap in a 64×64 block gives ≥ 1e-5. Bound in between.
pub const MAX_MSE: f64 = 1e-6;

/// How two AO images of equal, non-empty length agree.
#[derive(Clone, Copy, Debug)]
pub struct Agreement {
    /// Values compared.
    pub n: usize,
    /// Fraction with `|a − b| ≤ STEP`.
    pub within: f64,
    /// Mean squared difference.
    pub mse: f64,
    /// Largest `|a − b|`.
    pub max: f32,
    /// Fraction of `a` below 0.9 (is there occlusion to compare?).
    pub occluded: f64,
}

/// The statistics of `a` against `b`; lengths must match and be non-zero.
pub fn of(a: &[f32], b: &[f32]) -> Agreement {
    assert_same_len(a, b, "agreement");
    let n = a.len();
    let (mut within, mut sum, mut max, mut occluded) = (0usize, 0.0f64, 0.0f32, 0usize);
    for (x, y) in a.iter().zip(b) {
        let d = (x - y).abs();
        within += usize::from(d <= STEP);
        sum += (d as f64).powi(2);
        max = max.max(if d.is_nan() { f32::INFINITY } else { d });
        occluded += usize::from(*x < 0.9);
    }
    Agreement { n, within: within as f64 / n as f64, mse: sum / n as f64, max, occluded: occluded as f64 / n as f64 }
}

/// The statistics over the inner image of two full-target buffers.
pub fn inner(view: &aokit_shaders::common::ViewParams, a: &[f32], b: &[f32]) -> Agreement {
    let (a, b) = inner_pair(view, a, b);
    of(&a, &b)
}

impl Agreement {
    /// One line for the test's log and its failure messages.
    pub fn line(&self, label: &str) -> String {
        format!(
            "{label}: {:.3} % of {} within 1/255, MSE {:.2e}, max |Δ| {:.2}/255, occluded {:.1} %",
            100.0 * self.within,
            self.n,
            self.mse,
            255.0 * self.max,
            100.0 * self.occluded
        )
    }

    /// Assert the deterministic-kernel agreement: ≥ [`MIN_WITHIN`] within a step AND MSE ≤
    /// [`MAX_MSE`].
    pub fn assert_exact(&self, label: &str) {
        self.assert_bounds(label, MIN_WITHIN, MAX_MSE);
    }

    /// Assert both a fraction within one step and an MSE bound (state where they come from).
    pub fn assert_bounds(&self, label: &str, min_within: f64, max_mse: f64) {
        let line = self.line(label);
        assert!(self.within >= min_within, "{line}: fewer than {:.3} % within 1/255", 100.0 * min_within);
        assert!(self.mse <= max_mse, "{line}: MSE above {max_mse:.1e}");
    }
}

/// The inner image `[g, W−g) × [g, H−g)` of two full-target buffers, for agreement statistics.
/// Both must hold exactly one value per pixel of the full target, so a short or empty read-back
/// fails here instead of zipping to nothing, and the guard band (1 on both sides for AO) is cut
/// away so it cannot dilute an MSE or a fraction of agreeing pixels.
pub fn inner_pair<T: Copy>(view: &aokit_shaders::common::ViewParams, a: &[T], b: &[T]) -> (Vec<T>, Vec<T>) {
    let size = view.size();
    let full = (size.x * size.y) as usize;
    assert!(full > 0, "empty target");
    assert_eq!(a.len(), full, "first buffer holds {} values for a {}×{} target", a.len(), size.x, size.y);
    assert_eq!(b.len(), full, "second buffer holds {} values for a {}×{} target", b.len(), size.x, size.y);
    let g = view.guard;
    assert!(2 * g < size.x && 2 * g < size.y, "guard band {g} leaves no inner image");
    let crop = |v: &[T]| -> Vec<T> {
        let mut out = Vec::with_capacity(((size.x - 2 * g) * (size.y - 2 * g)) as usize);
        for y in g..size.y - g {
            let row = (y * size.x) as usize;
            out.extend_from_slice(&v[row + g as usize..row + (size.x - g) as usize]);
        }
        out
    };
    (crop(a), crop(b))
}

/// Two buffers that are compared element by element without an image layout (MIP chains, SD
/// texels, interval buffers): equal, non-zero lengths.
pub fn assert_same_len<T, U>(a: &[T], b: &[U], what: &str) {
    assert!(!a.is_empty(), "{what}: first buffer is empty");
    assert_eq!(a.len(), b.len(), "{what}: buffer lengths differ");
}
