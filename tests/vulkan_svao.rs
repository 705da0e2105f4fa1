//! Ray-SD and Ray-SVAO: the SPIR-V (compute + ray-tracing pipelines on Vulkan, validation layer
//! on) against the CPU simulator on the same G-buffer (spec svao-raysd §16: deterministic passes
//! agree to float rounding, hit-order-dependent ones statistically).

mod common;

use aokit::render::CpuRenderer;
use aokit::technique::{SdOptions, Technique, TechniqueRun};
use aokit_shaders::common::gbuffer_read::GBufferSlices;
use aokit_shaders::glam::uvec2;
use aokit_shaders::graph::Refinement;
use aokit_shaders::raysd::sd_ray;
use aokit_shaders::svao::Secondary;
use aokit_shaders::svao::settings::{RAYSD, RAYSVAO};

fn ulps(a: u32, b: u32) -> u32 {
    (a as i64 - b as i64).unsigned_abs() as u32
}

fn debug(run: &TechniqueRun) -> &Refinement {
    run.debug.as_ref().expect("stenciled techniques report their buffers")
}

/// Pass 1 bit-for-bit (within 1 ulp), SD map from the same candidate depths, final AO within
/// MSE 1e-4 — Sponza, ½-resolution SD map, CPU ray-cast G-buffer on both back-ends.
#[test]
fn raysd_vulkan_agrees_with_cpu_sim() {
    let Some(vk) = common::vulkan() else { return };
    let (scene, frame) = common::builtin_frame("sponza", 320, 180, 32);
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
    let options = SdOptions { divisor: 2, ..Default::default() };
    let technique = Technique::new(&RAYSD, options);
    let c = cpu.run(&frame, &g, &technique, &aokit_cpu::no_progress);
    let v = vk.run(&scene, &frame, &g, &technique).expect("Vulkan Ray-SD");
    common::assert_validation_clean(&vk);
    let (dc, dv) = (debug(&c), debug(&v));

    // Pass 1: full-target masks and AO (pass 1 also runs in part of the guard band, spec svao-raysd §5),
    // SD-size interval buffers; every pair must have the same, non-zero length.
    let view = frame.camera.view;
    let pixels = (view.size().x * view.size().y) as usize;
    for (what, a, b) in [("mask", dc.mask.len(), dv.mask.len()), ("pass-1 AO", dc.ao_pass1.len(), dv.ao_pass1.len())] {
        assert_eq!((a, b), (pixels, pixels), "{what}: CPU {a}, Vulkan {b} values for {pixels} pixels");
    }
    common::assert_same_len(&dc.ray_min, &dv.ray_min, "rayMin");
    common::assert_same_len(&dc.ray_max, &dv.ray_max, "rayMax");
    common::assert_same_len(&dc.ray_min, &dc.ray_max, "rayMin/rayMax");
    let mask_equal = dc.mask.iter().zip(&dv.mask).filter(|(a, b)| a == b).count();
    let ao_close = dc.ao_pass1.iter().zip(&dv.ao_pass1).filter(|(a, b)| ulps(a.to_bits(), b.to_bits()) <= 1).count();
    let worst = dc.ao_pass1.iter().zip(&dv.ao_pass1).map(|(a, b)| ulps(a.to_bits(), b.to_bits())).max().unwrap_or(0);
    let worst_masked = dc
        .ao_pass1
        .iter()
        .zip(&dv.ao_pass1)
        .zip(&dc.mask)
        .filter(|(_, m)| **m != 0)
        .map(|((a, b), _)| ulps(a.to_bits(), b.to_bits()))
        .max()
        .unwrap_or(0);
    eprintln!("pass 1 AO: worst {worst} ulp, worst on flagged (UNORM8-stored) pixels {worst_masked} ulp");
    let texels = dc.ray_min.len();
    let min_close = dc.ray_min.iter().zip(&dv.ray_min).filter(|(a, b)| ulps(**a, **b) <= 1).count();
    let max_close = dc.ray_max.iter().zip(&dv.ray_max).filter(|(a, b)| ulps(**a, **b) <= 1).count();
    eprintln!(
        "pass 1: mask equal {mask_equal}/{pixels}, AO ≤1 ulp {ao_close}/{pixels}, rayMin ≤1 ulp {min_close}/{texels}, rayMax ≤1 ulp {max_close}/{texels}"
    );
    assert!(dc.mask.iter().any(|&m| m != 0), "the view must flag samples");
    // Masks and interval buffers: identical / within 1 ulp everywhere. Pass-1 AO of flagged
    // pixels (the UNORM8-stored sum): within 1 ulp. Unflagged pixels are final, through `powf`,
    // which the GPU evaluates as exp2(e·log2 a) with its own approximations: measured ≤ 7 ulp
    // (≈ 4e-7) on lavapipe, so they get 8 ulp.
    assert_eq!(mask_equal, pixels);
    assert_eq!((min_close, max_close), (texels, texels));
    assert!(worst_masked <= 1, "flagged pass-1 AO differs by {worst_masked} ulp");
    assert!(worst <= 8, "pass-1 AO differs by {worst} ulp");

    // SD map: every depth the GPU stored is one of the candidate hits the CPU finds along the
    // same texel ray (on the GPU's own interval buffers), up to intersection rounding.
    let bvh = aokit_cpu::SceneBvh::build(&scene.triangles);
    let svao = options.frame(&frame.desc(), Secondary::StochasticDepth);
    let params = &svao.params;
    let view = &params.vao.view;
    let gb = GBufferSlices { depth: &g.depth, normals: &g.normals, width: g.width };
    let n = params.sd_layers as usize;
    let (mut stored, mut matched) = (0, 0);
    for y in 0..dv.sd_size.y {
        for x in 0..dv.sd_size.x {
            let q = uvec2(x, y);
            let i = params.sd_index(q);
            let ray = sd_ray(&gb, &svao, q, dv.ray_min[i], dv.ray_max[i]);
            let layers = &dv.sd_map[i * n..(i + 1) * n];
            if layers.iter().all(|&z| z >= 1.0) {
                continue;
            }
            assert!(ray.traced(), "texel {q} holds depths but has an empty interval");
            let candidates: Vec<f32> = bvh
                .all_hits(ray.origin, ray.direction, ray.t_min * 0.999, ray.t_max * 1.001)
                .iter()
                .map(|h| ((h.0 * ray.cos_theta - view.near) / (view.far - view.near)).clamp(0.0, 1.0))
                .collect();
            for &z in layers.iter().filter(|&&z| z < 1.0) {
                stored += 1;
                if candidates.iter().any(|&c| (c - z).abs() <= 1e-4 * z.max(1e-3)) {
                    matched += 1;
                }
            }
        }
    }
    eprintln!("SD map: {matched}/{stored} GPU depths match a CPU candidate hit");
    assert!(stored > 100);
    assert!(matched as f64 >= 0.999 * stored as f64);

    let m = common::inner_mse(view, &c.ao_final, &v.ao_final);
    eprintln!("final AO MSE CPU vs Vulkan (inner image): {m:.3e}");
    assert!(m <= 1e-4);
    assert!(v.passes.iter().any(|p| p.0 == "sd_map"));
}

/// Ray-SVAO's result does not depend on hit order (min/max over hits), so both back-ends agree
/// closely: MSE ≤ 1e-5 and 99.5 % of pixels within 1/255.
#[test]
fn raysvao_vulkan_agrees_with_cpu_sim() {
    let Some(vk) = common::vulkan() else { return };
    let (scene, frame) = common::builtin_frame("sponza", 320, 180, 32);
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
    let technique = Technique::new(&RAYSVAO, SdOptions::default());
    let c = cpu.run(&frame, &g, &technique, &aokit_cpu::no_progress);
    let v = vk.run(&scene, &frame, &g, &technique).expect("Vulkan Ray-SVAO");
    common::assert_validation_clean(&vk);
    let view = frame.camera.view;
    let m = common::inner_mse(&view, &c.ao, &v.ao);
    let close = common::inner_within(&view, &c.ao, &v.ao, 1.0 / 255.0);
    eprintln!(
        "Ray-SVAO CPU vs Vulkan (inner image): MSE {m:.3e}, {:.3} % within 1/255; rays {} vs {}",
        100.0 * close,
        c.rays,
        v.rays
    );
    assert!(c.refined_samples > 1000);
    assert!(m <= 1e-5);
    assert!(close >= 0.995);
    let rays = (c.rays as f64 - v.rays as f64).abs();
    assert!(rays <= 0.001 * c.rays as f64, "ray counts differ: {} vs {}", c.rays, v.rays);
}
