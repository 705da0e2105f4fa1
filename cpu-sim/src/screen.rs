//! Screen-space passes over whole images: each output pixel calls the same per-pixel kernel
//! function that the SPIR-V entry point calls.

use crate::Progress;
use aokit_shaders::blur::{BlurParams, blur_lanes};
use aokit_shaders::common::gbuffer_read::GBufferSlices;
use aokit_shaders::common::lanes::{CPU_LANES, CpuLanes, Lanes};
use aokit_shaders::glam::{UVec2, uvec2};
use aokit_shaders::vao::VaoParams;
use aokit_shaders::vao::kernel::{setup_lanes, vao_finish, vao_visibility_sum};
use rayon::prelude::*;

/// Rows per band of [`tiled`]: the unit of parallel work.
pub const TILE_ROWS: u32 = 16;
/// Columns per tile of [`tiled`]: a band is walked one tile of `TILE_COLS × TILE_ROWS` at a time.
pub const TILE_COLS: u32 = 64;

/// Call `f(pixel, &mut out[pixel])` for every pixel of `xs × ys` of a row-major image `width`
/// wide: bands of [`TILE_ROWS`] rows in parallel, each band walked [`TILE_COLS`] columns at a
/// time, so that what a tile's kernels read around it (`(64 + 2r) × (16 + 2r)` texels for a
/// screen radius `r`) stays in cache instead of `2r` whole rows. Pixels are independent, so the
/// order changes no result. `band_done(rows)` after each band with its rows in `ys`.
pub fn tiled<T: Send>(
    out: &mut [T],
    width: u32,
    xs: core::ops::Range<u32>,
    ys: core::ops::Range<u32>,
    band_done: Progress,
    f: impl Fn(UVec2, &mut T) + Sync,
) {
    tiled_lanes(out, width, xs, ys, 1, band_done, |p, one| f(p, &mut one[0]));
}

/// [`tiled`] for kernels that shade several consecutive pixels of a row per call (SIMD across
/// pixels, [`aokit_shaders::common::lanes`]): `f(first, outputs)` with `outputs` the up to
/// `lanes` pixels of the row from `first` on (fewer at the end of a tile row).
pub fn tiled_lanes<T: Send>(
    out: &mut [T],
    width: u32,
    xs: core::ops::Range<u32>,
    ys: core::ops::Range<u32>,
    lanes: u32,
    band_done: Progress,
    f: impl Fn(UVec2, &mut [T]) + Sync,
) {
    let mut none = vec![(); out.len()];
    tiled_lanes2(out, &mut none, width, xs, ys, lanes, band_done, |p, o, _| f(p, o));
}

/// [`tiled_lanes`] writing two images of the same size at once (a pass with two outputs, such
/// as AO terms and edges), straight into the caller's buffers.
#[allow(clippy::too_many_arguments)]
pub fn tiled_lanes2<A: Send, B: Send>(
    a: &mut [A],
    b: &mut [B],
    width: u32,
    xs: core::ops::Range<u32>,
    ys: core::ops::Range<u32>,
    lanes: u32,
    band_done: Progress,
    f: impl Fn(UVec2, &mut [A], &mut [B]) + Sync,
) {
    assert_eq!(a.len(), b.len(), "both images cover the same pixels");
    let w = width as usize;
    let band = w * TILE_ROWS as usize;
    a.par_chunks_mut(band).zip(b.par_chunks_mut(band)).enumerate().for_each(|(k, (rows_a, rows_b))| {
        let y0 = k as u32 * TILE_ROWS;
        let band_rows = (rows_a.len() / w) as u32;
        let (lo, hi) = (y0.max(ys.start), (y0 + band_rows).min(ys.end));
        if lo >= hi {
            return;
        }
        let mut x0 = xs.start;
        while x0 < xs.end {
            let x1 = (x0 + TILE_COLS).min(xs.end);
            for y in lo..hi {
                let at = ((y - y0) as usize) * w;
                let (row_a, row_b) = (&mut rows_a[at..][..w], &mut rows_b[at..][..w]);
                let mut x = x0;
                while x < x1 {
                    let n = lanes.min(x1 - x);
                    let run = x as usize..(x + n) as usize;
                    f(uvec2(x, y), &mut row_a[run.clone()], &mut row_b[run]);
                    x += n;
                }
            }
            x0 = x1;
        }
        band_done((hi - lo) as u64);
    });
}

/// [`tiled_lanes2`] over every pixel of a `size` image, [`CPU_LANES`] pixels per call, without
/// progress: the whole-target passes with two outputs.
pub fn whole_image_lanes2<A: Send, B: Send>(
    a: &mut [A],
    b: &mut [B],
    size: UVec2,
    f: impl Fn(UVec2, &mut [A], &mut [B]) + Sync,
) {
    tiled_lanes2(a, b, size.x, 0..size.x, 0..size.y, CPU_LANES as u32, &crate::no_progress, f);
}

/// Pixel of lane `i` in a run of `n` ≥ 1 consecutive pixels of a row from `first`: lanes past
/// the run repeat its last pixel (they are computed and discarded, as on a GPU).
#[inline]
pub fn lane_pixel(first: UVec2, i: usize, n: usize) -> UVec2 {
    uvec2(first.x + i.min(n - 1) as u32, first.y)
}

/// The `n` ≥ 1 consecutive pixels of a row from `first` as cpu-sim's lanes ([`CpuLanes`], [`lane_pixel`]).
pub fn lanes_of_run(first: UVec2, n: usize) -> <CpuLanes as Lanes>::U2 {
    <CpuLanes as Lanes>::U2::from_texels(&core::array::from_fn(|i| lane_pixel(first, i, n)))
}

/// Call `kernel(first, out)` for runs of up to [`CPU_LANES`] consecutive inner pixels of a full-target
/// image, in parallel [`tiled_lanes`] bands. Guard-band pixels keep 1.
fn for_inner_lanes(size: UVec2, guard: u32, progress: Progress, kernel: impl Fn(UVec2, &mut [f32]) + Sync) -> Vec<f32> {
    let mut out = vec![1.0; (size.x * size.y) as usize];
    inner_lanes_into(&mut out, size, guard, progress, kernel);
    out
}

/// Call `kernel(first, out)` for runs of up to [`CPU_LANES`] consecutive inner pixels of the
/// caller's full-target image `out`, in parallel [`tiled_lanes`] bands; its guard band is left
/// as it is.
pub fn inner_lanes_into<T: Send>(
    out: &mut [T],
    size: UVec2,
    guard: u32,
    progress: Progress,
    kernel: impl Fn(UVec2, &mut [T]) + Sync,
) {
    let (xs, ys) = (guard..size.x.saturating_sub(guard), guard..size.y.saturating_sub(guard));
    tiled_lanes(out, size.x, xs, ys, CPU_LANES as u32, progress, kernel);
}

/// Plain VAO (spec svao-raysd §4–§5) over the inner image. Returns the full-target AO buffer
/// (guard band = 1).
pub fn run_vao(params: &VaoParams, depth: &[f32], normals: &[u32], progress: Progress) -> Vec<f32> {
    let size = params.view.size();
    let gbuffer = GBufferSlices { depth, normals, width: size.x };
    for_inner_lanes(size, params.view.guard, progress, |p, ao| vao_lanes(&gbuffer, params, p, ao))
}

/// [`aokit_shaders::vao::vao_pixel`] for `ao.len()` ≤ [`CPU_LANES`] consecutive pixels of a row from `first`: the per-pixel
/// setup and final power per lane, the samples on all lanes at once. Missing lanes repeat the
/// last pixel; unshaded pixels (no usable depth) borrow a shaded lane's frame and are
/// discarded.
pub fn vao_lanes(gbuffer: &GBufferSlices, params: &VaoParams, first: UVec2, ao: &mut [f32]) {
    let p = lanes_of_run(first, ao.len());
    let (shaded, frame) = setup_lanes::<_, CpuLanes>(gbuffer, &params.view, params.radius, params.max_screen_radius, p);
    if !CpuLanes::any(shaded) {
        ao.fill(1.0);
        return;
    }
    let sum = vao_visibility_sum(gbuffer, params, &frame);
    for (i, v) in ao.iter_mut().enumerate() {
        *v = if CpuLanes::mask_lane(shaded, i) { vao_finish(params, sum.lane(i)) } else { 1.0 };
    }
}

/// One direction (`params.direction`) of the cross-bilateral blur (spec svao-raysd §12).
/// [`CPU_LANES`] pixels of a row per call of the shader crate's lane-generic blur.
pub fn run_blur_direction(params: &BlurParams, ao: &[f32], depth: &[f32]) -> Vec<f32> {
    for_inner_lanes(params.view.size(), params.view.guard, &crate::no_progress, |p, out| {
        let v: CpuLanes = blur_lanes(params, ao, depth, p);
        for (i, x) in out.iter_mut().enumerate() {
            *x = v.lane(i);
        }
    })
}

/// The two-pass cross-bilateral blur (spec svao-raysd §12): horizontal then vertical.
pub fn run_blur(params: &BlurParams, ao: &[f32], depth: &[f32]) -> Vec<f32> {
    let pass = |direction: UVec2, input: &[f32]| run_blur_direction(&BlurParams { direction, ..*params }, input, depth);
    let horizontal = pass(uvec2(1, 0), ao);
    pass(uvec2(0, 1), &horizontal)
}
