//! The CPU's lane drivers (SIMD across pixels, `CPU_LANES` per call, `aokit_shaders::common::lanes`)
//! against the same kernels run one pixel at a time, as the GPU runs them. Where the lanes use
//! only IEEE-exact operations (add, mul, div, sqrt, compares) the two must agree bit for bit:
//! VAO, SVAO pass 1, the ray march and XeGTAO's denoiser. The blur's weights, XeGTAO's slices
//! and VBAO's sectors use `wide`'s exp2/sin/cos/acos/ln/pow polynomials, a few ulp from libm's,
//! and the lanes' inverse square root (`vrsqrtps` and a Newton step, within 4 ulp): the blur
//! agrees within 1e-6, XeGTAO's and VBAO's 8-bit terms may differ by one step in a few pixels.

mod common;

use aokit::render::CpuRenderer;
use aokit_cpu::no_progress;
use aokit_shaders::blur::{BlurParams, blur_pixel};
use aokit_shaders::common::atomics::AtomicU32Buffer;
use aokit_shaders::common::float_order::{RAY_MAX_CLEAR, RAY_MIN_CLEAR};
use aokit_shaders::common::gbuffer_read::GBufferSlices;
use aokit_shaders::glam::{UVec2, uvec2};
use aokit_shaders::gtao::{GtaoParams, denoise_pixel, gtao_pixel};
use aokit_shaders::raymarch::raymarch_pixel;
use aokit_shaders::raymarch::settings::RaymarchSettings;
use aokit_shaders::svao::{Secondary, pass1_pixel};
use aokit_shaders::vao::vao_pixel;
use std::sync::atomic::AtomicU32;

/// Every inner pixel of the frame's full target, row-major.
fn inner_pixels(view: &aokit_shaders::common::ViewParams) -> Vec<UVec2> {
    let size = view.size();
    let g = view.guard;
    (g..size.y - g).flat_map(|y| (g..size.x - g).map(move |x| uvec2(x, y))).collect()
}

#[test]
fn exact_kernels_agree_bit_for_bit_with_one_pixel_at_a_time() {
    // 157 wide: rows end with a partial run of lanes.
    let (scene, frame) = common::builtin_frame("sponza", 157, 90, 16);
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &no_progress);
    let view = frame.camera.view;
    let gbuffer = GBufferSlices { depth: &g.depth, normals: &g.normals, width: view.size().x };
    let pixels = inner_pixels(&view);
    let bits = |v: f32| v.to_bits();

    let vao = frame.vao_params();
    let lanes = aokit_cpu::run_vao(&vao, &g.depth, &g.normals, &no_progress);
    let occluded = pixels.iter().filter(|&&p| lanes[view.index(p)] < 0.99).count();
    assert!(occluded > pixels.len() / 4, "the test image must be mostly occluded, {occluded} pixels are");
    for &p in &pixels {
        assert_eq!(bits(lanes[view.index(p)]), bits(vao_pixel(&gbuffer, &vao, p)), "VAO at {p}");
    }

    let blur = BlurParams { direction: uvec2(1, 0), ..frame.blur_params() };
    let lanes_blur = aokit_cpu::screen::run_blur_direction(&blur, &lanes, &g.depth);
    for &p in &pixels {
        let (a, b) = (lanes_blur[view.index(p)], blur_pixel(&blur, &lanes, &g.depth, p));
        assert!((a - b).abs() <= 1e-6, "blur at {p}: lanes {a} vs one pixel {b}");
    }

    let svao = aokit::technique::SdOptions::default().frame(&frame.desc(), Secondary::StochasticDepth).params;
    let pass1 = aokit_cpu::svao::run_pass1(&svao, &g.depth, &g.normals, &[], &no_progress);
    let texels = (svao.sd_size().x * svao.sd_size().y) as usize;
    let ray_min: Vec<AtomicU32> = (0..texels).map(|_| AtomicU32::new(RAY_MIN_CLEAR)).collect();
    let ray_max: Vec<AtomicU32> = (0..texels).map(|_| AtomicU32::new(RAY_MAX_CLEAR)).collect();
    let mut flagged = 0;
    for &p in &pixels {
        let (mut lo, mut hi) = (ray_min.as_slice(), ray_max.as_slice());
        let one = pass1_pixel(&gbuffer, &[], &svao, p, &mut lo, &mut hi);
        assert_eq!(bits(pass1.ao[view.index(p)]), bits(one.ao), "SVAO pass 1 AO at {p}");
        assert_eq!(pass1.mask[view.index(p)], one.mask, "SVAO pass 1 mask at {p}");
        flagged += one.mask.count_ones();
    }
    assert!(flagged > 100, "pass 1 must flag samples to compare the intervals, flagged {flagged}");
    let (mut lo, mut hi) = (ray_min.as_slice(), ray_max.as_slice());
    for q in 0..texels {
        assert_eq!(pass1.ray_min[q], lo.atomic_min(q, u32::MAX), "ray_min at SD texel {q}");
        assert_eq!(pass1.ray_max[q], hi.atomic_max(q, 0), "ray_max at SD texel {q}");
    }

    let settings = RaymarchSettings::default();
    let (params, kernel) = (settings.params(&frame.desc()), settings.kernel());
    let (ao, terms, edges) = aokit_cpu::raymarch::run_raymarch(&params, &g.depth, &g.normals, &kernel);
    for &p in &pixels {
        let one = raymarch_pixel(&params, &g.depth, &g.normals, &kernel, p);
        let i = view.index(p);
        assert_eq!((bits(ao[i]), terms[i], edges[i]), (bits(one.ao), one.term, one.edges), "ray march at {p}");
    }
}

#[test]
fn xegtao_lanes_match_one_pixel_at_a_time_within_one_step() {
    let (scene, frame) = common::builtin_frame("sponza", 157, 90, 16);
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &no_progress);
    let view = frame.camera.view;
    let params: GtaoParams = frame.gtao_params(&Default::default());
    let mips = aokit_cpu::gtao::run_prefilter(&params, &g.depth);
    let (terms, edges) = aokit_cpu::gtao::run_main(&params, &mips, &g.normals);
    let size = view.size();
    let (mut differ, mut total) = (0, 0);
    for p in (0..size.y).flat_map(|y| (0..size.x).map(move |x| uvec2(x, y))) {
        let one = gtao_pixel(&params, &mips, &g.normals, p);
        let i = view.index(p);
        assert_eq!(edges[i], one.edges, "edges at {p}");
        assert!(terms[i].abs_diff(one.term) <= 1, "term at {p}: lanes {} vs one pixel {}", terms[i], one.term);
        differ += (terms[i] != one.term) as u32;
        total += 1;
    }
    // wide's polynomials are within a few ulp: a one-step difference needs a value within a few
    // ulp of a rounding boundary of the 8-bit term.
    assert!(differ * 100 <= total, "{differ} of {total} terms differ");

    // The denoiser uses exact operations only: its lanes agree bit for bit, borders included,
    // in an earlier pass (terms for the next pass) and in the last (rescaled terms, visibility).
    let params = GtaoParams { denoise_passes: 2, ..params };
    let mut current = terms.clone();
    for pass in 0..2 {
        let p = GtaoParams { pass, ..params };
        let (mut next, mut ao) = (vec![0; current.len()], vec![0.0; current.len()]);
        aokit_cpu::gtao::denoise_into(&p, &current, &edges, &mut next, &mut ao);
        let mut changed = 0;
        for q in (0..size.y).flat_map(|y| (0..size.x).map(move |x| uvec2(x, y))) {
            let one = denoise_pixel(&p, &current, &edges, q);
            let i = view.index(q);
            assert_eq!(next[i], one.term, "denoise pass {pass} term at {q}");
            if one.last {
                assert_eq!(ao[i].to_bits(), one.visibility.to_bits(), "denoise visibility at {q}");
            }
            changed += (next[i] != current[i]) as u32;
        }
        assert!(changed * 10 > total, "pass {pass} must filter: {changed} of {total} terms changed");
        current = next;
    }
}

#[test]
fn vbao_lanes_match_one_pixel_at_a_time_within_one_step() {
    use aokit_shaders::vbao::settings::VbaoSettings;
    use aokit_shaders::vbao::{RULE_PAPER, RULE_TOUCH, WEIGHT_COSINE_BLENDER, WEIGHT_COSINE_EXACT, WEIGHT_UNIFORM};
    let (scene, frame) = common::builtin_frame("sponza", 157, 90, 16);
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &no_progress);
    let size = frame.camera.view.size();
    let base = VbaoSettings::default().params(&frame.desc());
    let mips = aokit_cpu::gtao::run_prefilter(&base.gtao, &g.depth);
    // Every weighting, and both sector rules: wide's acos/sin/cos/ln/pow and the lanes' inverse
    // square root (vrsqrtps plus a Newton step, whose last bits differ between CPUs) are a few
    // ulp from libm's and from 1/√x, so an 8-bit rounding or a sector boundary may flip in a few
    // pixels. A flipped sector moves one slice's visibility by 1/32: the term by at most
    // ⌈255 / (32 · slices)⌉ steps (3 for 3 slices). Measured: at most one step on the earlier CI
    // hosts, two at one pixel of 14130 on an Intel Xeon with AVX-512 (2026-12-05).
    for (weighting, rule) in
        [(WEIGHT_UNIFORM, RULE_PAPER), (WEIGHT_COSINE_BLENDER, RULE_TOUCH), (WEIGHT_COSINE_EXACT, RULE_PAPER)]
    {
        let params = aokit_shaders::vbao::VbaoParams { weighting, sector_rule: rule, ..base };
        let sector_flip = 255u32.div_ceil(aokit_shaders::vbao::kernel::SECTORS * params.gtao.slices);
        let (mut terms, mut edges) = (vec![0; (size.x * size.y) as usize], vec![0; (size.x * size.y) as usize]);
        aokit_cpu::gtao::run_vbao_into(&params, &mips, &g.normals, &mut terms, &mut edges);
        let (mut differ, mut occluded, mut total) = (0, 0, 0);
        for p in (0..size.y).flat_map(|y| (0..size.x).map(move |x| uvec2(x, y))) {
            let one = aokit_shaders::vbao::vbao_pixel(&params, &mips, &g.normals, p);
            let i = (p.y * size.x + p.x) as usize;
            assert_eq!(edges[i], one.edges, "edges at {p}");
            let w = weighting;
            assert!(
                terms[i].abs_diff(one.term) <= sector_flip,
                "weighting {w} at {p}: lanes {} vs one pixel {}",
                terms[i],
                one.term
            );
            differ += (terms[i] != one.term) as u32;
            occluded += (one.term < 160) as u32;
            total += 1;
        }
        assert!(occluded * 10 > total, "weighting {weighting}: the image must be occluded, {occluded} of {total}");
        assert!(differ * 100 <= total, "weighting {weighting}: {differ} of {total} terms differ");
    }
}

/// The lanes' two-instruction clamp (`minps(maxps(x, lo), hi)`) against the compares and
/// selects (`clamp_lanes` on one pixel), bit for bit, on the values where they could part: NaN, ±0, ±∞, the
/// bounds themselves and values next to them, for the bounds the kernels clamp to (sat, the
/// unit interval, MIP levels, +0 to +0).
#[test]
fn lane_clamp_equals_the_scalar_clamp_bit_for_bit() {
    use aokit_shaders::common::lanes::{CPU_LANES, CpuLanes, Lanes};
    use aokit_shaders::common::math::{clamp, clamp_lanes};
    let special = [f32::NAN, -f32::NAN, 0.0, -0.0, f32::INFINITY, f32::NEG_INFINITY, f32::MIN_POSITIVE, -1e-30];
    let mut checked = 0;
    for (lo, hi) in [(0.0f32, 1.0f32), (-1.0, 1.0), (0.0, 5.0), (0.0, 0.0), (-3.5, 1e-3)] {
        let near = |b: f32| [b, f32::from_bits(b.to_bits() + 1), f32::from_bits(b.to_bits().wrapping_sub(1)), -b];
        let xs: Vec<f32> =
            special.iter().copied().chain(near(lo)).chain(near(hi)).chain([0.5, -0.5, 2.0, 7.25]).collect();
        for chunk in xs.chunks(CPU_LANES) {
            let lanes = clamp(CpuLanes::from_lanes(|i| chunk[i % chunk.len()]), lo, hi);
            for (i, &x) in chunk.iter().enumerate() {
                let want = clamp_lanes::<f32>(x, lo, hi);
                assert_eq!(
                    lanes.lane(i).to_bits(),
                    want.to_bits(),
                    "clamp({x:?}, {lo}, {hi}): lanes {:?}, scalar {want:?}",
                    lanes.lane(i)
                );
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 5 * 20, "values × bounds checked");
}

/// The lanes' inverse square root (`vrsqrtps` and one Newton–Raphson step) is within 4 ulp of
/// the correctly rounded 1/√x (computed in f64) at every 251st float from the smallest normal
/// to the largest (about 8.4 M values, every binade; `vrsqrtps`' table differs between CPU
/// makers, the bound is Zen 3's worst, 3 ulp, plus one), and gives the limits
/// at the ends as 1/√x does: ±∞ for ±0, +0 for +∞, NaN for NaN. The kernels take it of squared lengths; 4 ulp
/// is at most 4.8·10⁻⁷ relative, far below the 1/255 step of a stored term.
#[test]
fn lane_inverse_sqrt_is_within_4_ulp_of_the_correctly_rounded_value() {
    use aokit_shaders::common::lanes::{CPU_LANES, CpuLanes, Lanes};
    let xs: Vec<f32> = (f32::MIN_POSITIVE.to_bits()..f32::MAX.to_bits()).step_by(251).map(f32::from_bits).collect();
    assert!(xs.len() > 8_000_000, "{} values", xs.len());
    let mut worst = (0u32, 0.0f32);
    for chunk in xs.chunks(CPU_LANES) {
        let lanes = CpuLanes::from_lanes(|i| chunk[i % chunk.len()]).inverse_sqrt();
        for (i, &x) in chunk.iter().enumerate() {
            let want = (1.0 / (x as f64).sqrt()) as f32;
            let ulps = lanes.lane(i).to_bits().abs_diff(want.to_bits());
            if ulps > worst.0 {
                worst = (ulps, x);
            }
        }
    }
    assert!(worst.0 <= 4, "{} ulp at x = {:e}", worst.0, worst.1);
    let ends =
        CpuLanes::from_lanes(|i| [0.0, -0.0, f32::INFINITY, f32::NAN, 1.0, 4.0, 0.25, 2.0][i % 8]).inverse_sqrt();
    assert_eq!(ends.lane(0), f32::INFINITY);
    assert_eq!(ends.lane(1), f32::NEG_INFINITY, "1/√−0 = 1/−0");
    assert_eq!(ends.lane(2).to_bits(), 0.0f32.to_bits());
    assert!(ends.lane(3).is_nan());
    eprintln!("  worst {} ulp at x = {:e}", worst.0, worst.1);
}
