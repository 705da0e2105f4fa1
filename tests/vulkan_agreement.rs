//! Ring 3: the SPIR-V on a Vulkan device (lavapipe in CI) against cpu-sim on the same inputs,
//! every test under the Khronos validation layer.

mod common;

use aokit::output::crop_inner;
use aokit::render::CpuRenderer;
use aokit_cpu::no_progress;

/// Fractions of inner pixels whose |cpu − gpu| is within 1/255 and the largest difference.
fn compare(view: &aokit_shaders::common::ViewParams, a: &[f32], b: &[f32]) -> (f64, f32) {
    let (a, b) = (crop_inner(view, a), crop_inner(view, b));
    let within = a.iter().zip(&b).filter(|(x, y)| (*x - *y).abs() <= 1.0 / 255.0).count();
    let max = a.iter().zip(&b).map(|(x, y)| (x - y).abs()).fold(0.0, f32::max);
    (within as f64 / a.len() as f64, max)
}

#[test]
fn vao_spirv_agrees_with_cpu_sim_on_the_same_gbuffer() {
    let Some(vk) = common::vulkan() else { return };
    let (scene, frame) = common::builtin_frame("sponza", 256, 256, 64);
    let cpu = CpuRenderer::new(&scene);
    let (gbuffer, _) = cpu.gbuffer(&frame, &no_progress);
    let on_cpu = CpuRenderer::ao(&frame, gbuffer.clone(), &no_progress);
    let on_gpu = vk.ao(&frame, gbuffer).unwrap();
    let view = frame.camera.view;
    // The image must actually contain occlusion for the comparison to mean something.
    let inner = crop_inner(&view, &on_cpu.ao);
    let occluded = inner.iter().filter(|&&a| a < 0.9).count();
    assert!(occluded > inner.len() / 50, "only {occluded} occluded pixels");
    for (name, a, b) in [("vao", &on_cpu.ao, &on_gpu.ao), ("vao+blur", &on_cpu.ao_blurred, &on_gpu.ao_blurred)] {
        let (within, max) = compare(&view, a, b);
        eprintln!("{name}: {:.4} % within 1/255, max |Δ| = {max:.2e} ({:.3}/255)", 100.0 * within, max * 255.0);
        assert!(within >= 0.999, "{name}: only {:.3} % within 1/255", 100.0 * within);
        assert!(max <= 4.0 / 255.0, "{name}: max difference {max}");
    }
    common::assert_validation_clean(&vk);
}

#[test]
fn raster_gbuffer_matches_ray_cast_gbuffer() {
    let Some(vk) = common::vulkan() else { return };
    let (scene, frame) = common::builtin_frame("sponza", 256, 256, 64);
    let (raster, _) = vk.gbuffer(&scene, &frame).unwrap();
    let (rays, _) = CpuRenderer::new(&scene).gbuffer(&frame, &no_progress);
    let far = frame.camera.view.far;
    let n = raster.depth.len();
    let close = raster.depth.iter().zip(&rays.depth).filter(|(a, b)| ((*a - *b) / b.max(1e-6)).abs() <= 1e-4).count();
    let background_agrees = raster.depth.iter().zip(&rays.depth).filter(|(a, b)| (**a == far) == (**b == far)).count();
    let normals_agree = raster.normals.iter().zip(&rays.normals).filter(|(a, b)| a == b).count();
    eprintln!(
        "depth within 1e-4 relative: {:.3} %; background agrees: {:.3} %; identical normal codes: {:.3} %",
        100.0 * close as f64 / n as f64,
        100.0 * background_agrees as f64 / n as f64,
        100.0 * normals_agree as f64 / n as f64
    );
    assert!(close as f64 >= 0.99 * n as f64, "depth agreement {close}/{n}");
    assert!(normals_agree as f64 >= 0.98 * n as f64, "normal agreement {normals_agree}/{n}");
    common::assert_validation_clean(&vk);
}

#[test]
fn full_vulkan_pipeline_matches_cpu_pipeline_on_the_tower() {
    let Some(vk) = common::vulkan() else { return };
    let (scene, frame) = common::builtin_frame("tower", 160, 120, 32);
    let gpu = vk.render(&scene, &frame).unwrap();
    let cpu = CpuRenderer::new(&scene).render(&frame, &no_progress);
    let (within, max) = compare(&frame.camera.view, &cpu.ao_blurred, &gpu.ao_blurred);
    eprintln!("tower end to end: {:.3} % within 1/255, max {max:.3}", 100.0 * within);
    // Different G-buffers (raster vs rays) differ at silhouettes; the bulk must agree.
    assert!(within >= 0.97, "only {:.3} % within 1/255", 100.0 * within);
    assert_eq!(gpu.passes.iter().map(|p| p.0).collect::<Vec<_>>(), ["gbuffer", "vao", "blur"]);
    assert!(gpu.passes.iter().all(|p| p.1 > 0.0 && p.1.is_finite()));
    common::assert_validation_clean(&vk);
}

#[test]
fn device_reports_ray_tracing_extensions() {
    let Some(vk) = common::vulkan() else { return };
    let info = vk.gpu.info();
    assert!(!info.name.is_empty());
    let names: Vec<_> = info.ray_tracing_extensions.iter().map(|e| e.0.as_str()).collect();
    assert_eq!(
        names,
        [
            "VK_KHR_acceleration_structure",
            "VK_KHR_ray_tracing_pipeline",
            "VK_KHR_ray_query",
            "VK_KHR_deferred_host_operations"
        ]
    );
    common::assert_validation_clean(&vk);
}

#[test]
fn validation_messages_are_captured() {
    // Proves the other tests' "validation clean" is not vacuous.
    let Some(vk) = common::vulkan() else { return };
    assert!(vk.gpu.validation_messages().is_empty());
    vk.gpu.provoke_validation_error().unwrap();
    let messages = vk.gpu.validation_messages();
    assert!(messages.iter().any(|m| m.contains("anisotropy")), "{messages:?}");
}

#[test]
fn ground_truth_ray_tracing_agrees_with_the_cpu_bvh() {
    let Some(vk) = common::vulkan() else { return };
    if !vk.gpu.has_ray_tracing() {
        panic!("device '{}' has no ray-tracing pipelines", vk.gpu.info().name);
    }
    use aokit_shaders::groundtruth::GroundTruthParams;
    for name in ["tower", "sponza"] {
        let (scene, frame) = common::builtin_frame(name, 96, 64, 16);
        let cpu = CpuRenderer::new(&scene);
        let (gbuffer, _) = cpu.gbuffer(&frame, &no_progress);
        let params = GroundTruthParams { radius: frame.radius, exponent: 1.0, samples: 64, uniform: 0 };
        let (on_cpu, _) = cpu.ground_truth(&frame, &gbuffer, &params, &no_progress);
        let (on_gpu, passes) = vk.ground_truth(&scene, &frame, &gbuffer, &params).unwrap();
        let view = frame.camera.view;
        let (a, b) = (crop_inner(&view, &on_cpu), crop_inner(&view, &on_gpu));
        // Same count of visible rays (AO differs by less than half a ray's 1/64).
        let identical = a.iter().zip(&b).filter(|(x, y)| (*x - *y).abs() < 0.5 / 64.0).count() as f64 / a.len() as f64;
        let mean_abs = a.iter().zip(&b).map(|(x, y)| (x - y).abs() as f64).sum::<f64>() / a.len() as f64;
        let mean_ao = a.iter().map(|&x| x as f64).sum::<f64>() / a.len() as f64;
        eprintln!(
            "{name}: same visible-ray count {:.3} %, mean |Δ| {mean_abs:.2e}, mean AO {mean_ao:.3}, {passes:?}",
            100.0 * identical
        );
        // Same sample sequence and ray origins: only rays grazing an edge may decide differently.
        assert!(mean_ao < 0.97, "{name}: the view must contain occlusion");
        assert!(identical > 0.99, "{name}: {identical}");
        assert!(mean_abs < 2e-3, "{name}: {mean_abs}");
    }
    common::assert_validation_clean(&vk);
}
