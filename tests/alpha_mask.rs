//! Alpha-masked (glTF `alphaMode: MASK`) surfaces are cut out of the G-buffer on both back-ends.

mod common;

use aokit::frame::{CameraChoice, Frame, FrameRequest};
use aokit::render::CpuRenderer;
use aokit::scene::procedural::push_quad;
use aokit::scene::{AlphaMask, Material, Scene};
use aokit::technique::{SdOptions, Technique};
use aokit_cpu::{GBufferImage, no_progress};
use aokit_shaders::common::tables::JitterTable;
use aokit_shaders::glam::{Vec2, Vec3, vec2, vec3};
use aokit_shaders::svao::Secondary;
use aokit_shaders::svao::settings::RAYSD;

/// A 2×2 quad at z = 0 whose mask texture is transparent on its left half (u < 0.5), in front
/// of an opaque wall at z = −3, seen from z = 5.
fn masked_scene() -> (Scene, Frame) {
    let mut s = Scene::default();
    push_quad(&mut s, vec3(-1.0, -1.0, 0.0), vec3(1.0, -1.0, 0.0), vec3(1.0, 1.0, 0.0), vec3(-1.0, 1.0, 0.0));
    let uv = |p: Vec3| vec2(0.5 * (p.x + 1.0), 0.5 * (1.0 - p.y));
    s.triangle_uvs = s.triangles.iter().map(|t| t.map(uv)).collect();
    s.triangle_materials = vec![1, 1];
    push_quad(&mut s, vec3(-9.0, -9.0, -3.0), vec3(9.0, -9.0, -3.0), vec3(9.0, 9.0, -3.0), vec3(-9.0, 9.0, -3.0));
    s.triangle_uvs.extend([[Vec2::ZERO; 3]; 2]);
    s.triangle_materials.extend([0, 0]);
    let alpha = (0..64).map(|i| if i % 8 < 4 { 0.1 } else { 0.9 }).collect();
    s.materials = vec![
        Material { name: "wall".into(), alpha_mask: None },
        Material { name: "leaf".into(), alpha_mask: Some(AlphaMask { width: 8, height: 8, alpha, cutoff: 0.5 }) },
    ];
    let scene = s.validated(std::path::Path::new("masked")).unwrap();
    let req = FrameRequest {
        width: 64,
        height: 64,
        guard: 8,
        camera: CameraChoice::Explicit { eye: vec3(0.0, 0.0, 5.0), target: Vec3::ZERO, up: Vec3::Y, fov_deg: 40.0 },
        radius: Some(0.2),
        exponent: 2.0,
        thickness: 0.0,
    };
    let frame = Frame::resolve(&scene, None, &req).unwrap();
    (scene, frame)
}

/// Depth at the quad's left (cut-out) and right (kept) half, on the image's middle row.
fn check(g: &GBufferImage, frame: &Frame, backend: &str) {
    let at = |x: f32| {
        let uv = frame.camera.view.view_to_uv(frame.camera.world_to_view.transform_point3(vec3(x, 0.0, 0.0)));
        g.depth[frame.camera.view.index(frame.camera.view.texel_of_uv(uv))]
    };
    for x in [-0.8, -0.5, -0.2] {
        assert!(
            (at(x) - 8.0).abs() < 1e-3,
            "{backend}: left half at x={x} must show the wall (depth 8), got {}",
            at(x)
        );
    }
    for x in [0.2, 0.5, 0.8] {
        assert!(
            (at(x) - 5.0).abs() < 1e-3,
            "{backend}: right half at x={x} must show the quad (depth 5), got {}",
            at(x)
        );
    }
}

#[test]
fn cpu_rays_skip_cut_out_texels() {
    let (scene, frame) = masked_scene();
    let (g, _) = CpuRenderer::new(&scene).gbuffer(&frame, &no_progress);
    check(&g, &frame, "cpu");
}

#[test]
fn raster_discards_cut_out_fragments() {
    let Some(vk) = common::vulkan() else { return };
    let (scene, frame) = masked_scene();
    let (g, _) = vk.gbuffer(&scene, &frame).unwrap();
    check(&g, &frame, "vulkan");
    let (cpu, _) = CpuRenderer::new(&scene).gbuffer(&frame, &no_progress);
    let same = g.depth.iter().zip(&cpu.depth).filter(|(a, b)| (*a - *b).abs() <= 1e-4 * b.abs()).count();
    assert!(same as f64 >= 0.98 * g.depth.len() as f64, "raster vs rays: {same}/{}", g.depth.len());
    common::assert_validation_clean(&vk);
}

/// The masked scene behind an opaque front wall at z = 1 (view depth 4): the SD map's layers
/// behind the first surface then hold the leaf quad (depth 5) only where its texels are kept,
/// and the back wall (depth 8) everywhere.
fn layered_scene() -> (Scene, Frame) {
    let (mut s, frame) = masked_scene();
    push_quad(&mut s, vec3(-9.0, -9.0, 1.0), vec3(9.0, -9.0, 1.0), vec3(9.0, 9.0, 1.0), vec3(-9.0, 9.0, 1.0));
    s.triangle_uvs.extend([[Vec2::ZERO; 3]; 2]);
    s.triangle_materials.extend([0, 0]);
    (s.validated(std::path::Path::new("layered")).unwrap(), frame)
}

/// Which depths the SD map holds on the leaf's left (cut-out) and right (kept) half.
fn check_sd_layers(map: &[f32], frame: &Frame, options: &SdOptions, backend: &str) {
    let svao = options.frame(&frame.desc(), Secondary::StochasticDepth);
    let p = &svao.params;
    let view = &p.vao.view;
    let n = p.sd_layers as usize;
    let at = |x: f32| -> Vec<f32> {
        let uv = view.view_to_uv(frame.camera.world_to_view.transform_point3(vec3(x, 0.0, 0.0)));
        let i = p.sd_index(aokit_shaders::svao::sd_pixel(uv, p));
        map[i * n..(i + 1) * n].iter().filter(|&&z| z < 1.0).map(|z| z * (view.far - view.near) + view.near).collect()
    };
    for x in [-0.8, -0.5, -0.2] {
        let d = at(x);
        assert!(d.iter().all(|d| (d - 5.0).abs() > 0.05), "{backend}: cut-out leaf stored at x={x}: {d:?}");
        assert!(d.iter().any(|d| (d - 8.0).abs() < 0.05), "{backend}: back wall missing at x={x}: {d:?}");
    }
    for x in [0.2, 0.5, 0.8] {
        let d = at(x);
        assert!(d.iter().any(|d| (d - 5.0).abs() < 0.05), "{backend}: kept leaf missing at x={x}: {d:?}");
    }
}

/// Spec svao-raysd §7.3: the SD any-hit runs the material's alpha test before storing a depth, on both
/// back-ends (full-resolution map, no intervals so every texel traces its whole range).
#[test]
fn sd_map_any_hit_applies_the_alpha_test() {
    let (scene, frame) = layered_scene();
    let options = SdOptions { divisor: 1, interval: false, jitter: JitterTable::None, ..Default::default() };
    let technique = Technique::new(&RAYSD, options);
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &no_progress);
    let c = cpu.run(&frame, &g, &technique, &no_progress);
    check_sd_layers(&c.debug.as_ref().unwrap().sd_map, &frame, &options, "cpu");
    let Some(vk) = common::vulkan() else { return };
    let v = vk.run(&scene, &frame, &g, &technique).unwrap();
    check_sd_layers(&v.debug.as_ref().unwrap().sd_map, &frame, &options, "vulkan");
    common::assert_validation_clean(&vk);
}

/// Every depth the SD map stored on `backend` comes from a candidate hit that survives the
/// alpha test; returns (stored depths, cut-out candidates seen).
fn check_oak_layers(
    renderer: &CpuRenderer,
    frame: &Frame,
    g: &GBufferImage,
    options: &SdOptions,
    map: &[f32],
    backend: &str,
) -> (usize, usize) {
    let bvh = renderer.bvh();
    let surfaces = renderer.surfaces();
    let svao = options.frame(&frame.desc(), Secondary::StochasticDepth);
    let p = &svao.params;
    let view = &p.vao.view;
    let gb =
        aokit_shaders::common::gbuffer_read::GBufferSlices { depth: &g.depth, normals: &g.normals, width: g.width };
    let n = p.sd_layers as usize;
    let sd = p.sd_size();
    let (mut stored, mut cut, mut unexplained) = (0, 0, 0);
    for y in 0..sd.y {
        for x in 0..sd.x {
            let q = aokit_shaders::glam::uvec2(x, y);
            let i = p.sd_index(q);
            let ray = aokit_shaders::raysd::sd_ray(&gb, &svao, q, 0, 0);
            let hits = bvh.all_hits(ray.origin, ray.direction, ray.t_min, ray.t_max);
            let z_of = |t: f32| ((t * ray.cos_theta - view.near) / (view.far - view.near)).clamp(0.0, 1.0);
            cut += hits.iter().filter(|h| !surfaces.passes_alpha(h.1, h.2)).count();
            for &z in map[i * n..(i + 1) * n].iter().filter(|&&z| z < 1.0) {
                stored += 1;
                let explained =
                    hits.iter().any(|h| (z_of(h.0) - z).abs() <= 2e-5 * z.max(1e-3) && surfaces.passes_alpha(h.1, h.2));
                if !explained {
                    unexplained += 1;
                }
            }
        }
    }
    eprintln!(
        "{backend}: {stored} stored depths, {unexplained} not from an alpha-passing hit; {cut} cut-out candidates"
    );
    // GPU barycentrics differ from the CPU's in the last bits: allow a hit on a texel border.
    assert!(
        unexplained as f64 <= 1e-3 * stored as f64,
        "{backend}: {unexplained}/{stored} depths from cut-out leaf texels"
    );
    (stored, cut)
}

/// The alpha-test case of `shared/scenes.md`: the oak tree's leaves (`alphaMode: MASK`, cutoff
/// 0.5). SD rays cross many cut-out leaf texels; none of them may enter the map, on either
/// back-end (full-resolution map, no intervals, N = 8, so every texel traces its whole range).
#[test]
fn sd_map_on_the_oak_tree_never_stores_cut_out_leaf_texels() {
    let (scene, frame) = common::builtin_frame("oak", 240, 180, 16);
    let options = SdOptions { divisor: 1, layers: 8, interval: false, ..Default::default() };
    let technique = Technique::new(&RAYSD, options);
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &no_progress);
    let c = cpu.run(&frame, &g, &technique, &no_progress);
    let (stored, cut) = check_oak_layers(&cpu, &frame, &g, &options, &c.debug.as_ref().unwrap().sd_map, "cpu");
    assert!(stored > 1000 && cut > 1000, "the view must cross leaves: {stored} stored, {cut} cut out");
    let Some(vk) = common::vulkan() else { return };
    let v = vk.run(&scene, &frame, &g, &technique).unwrap();
    let (v_stored, v_cut) = check_oak_layers(&cpu, &frame, &g, &options, &v.debug.as_ref().unwrap().sd_map, "vulkan");
    common::assert_validation_clean(&vk);
    // The Vulkan map is checked as the CPU's was, and used: the same cut-out candidates (they do
    // not depend on the hit order), as many stored depths up to the any-hit order (measured
    // 21974 vs 21999: 1 ‰; bound 1 %), and the AO it yields agrees with cpu-sim's to the
    // exact-agreement bounds (measured 100 % within 1/255, MSE 6e-15; returning VAO instead
    // gives 99.73 %, MSE 1.7e-5, max 86/255).
    assert_eq!(v_cut, cut, "cut-out candidates: Vulkan {v_cut}, CPU {cut}");
    assert!(
        (v_stored as f64 - stored as f64).abs() <= 0.01 * stored as f64,
        "stored depths: Vulkan {v_stored}, CPU {stored}"
    );
    let a = common::agreement::inner(&frame.camera.view, &c.ao, &v.ao);
    eprintln!("{}", a.line("oak Ray-SD pass-2 AO CPU vs Vulkan"));
    a.assert_exact("oak Ray-SD pass-2 AO CPU vs Vulkan");
}
