//! Visibility-bitmask AO (spec vbao): the sector bits, the closed forms of vbao §6 (plane, corner),
//! the thin occluder VBAO exists for, the T → ∞ equivalence with XeGTAO, and CPU ≡ Vulkan; and
//! `vbao-sd` (spec vbao §8): `vbao` without layers, the closed forms with and without them, one
//! flagged sample against hand-placed layers.

mod common;

use aokit::frame::{CameraChoice, Frame, FrameRequest};
use aokit::render::CpuRenderer;
use aokit::scene::Scene;
use aokit::scene::procedural::{push_box, push_quad};
use aokit::technique::{GroundTruthSettings, GtaoOptions, Technique};
use aokit_shaders::glam::{UVec2, Vec3, vec3};
use aokit_shaders::groundtruth::settings::GROUNDTRUTH;
use aokit_shaders::gtao::settings::GTAO;
use aokit_shaders::svao::SvaoFrame;
use aokit_shaders::vbao::settings::{Gate, VBAO, VbaoSettings};
use aokit_shaders::vbao::{RULE_PAPER, RULE_TOUCH, WEIGHT_COSINE_BLENDER, WEIGHT_COSINE_EXACT, WEIGHT_UNIFORM};
use aokit_shaders::vbao::{sector_bits, vbao_pixel};
use aokit_shaders::vbaosd::settings::VBAO_SD;
use aokit_shaders::vbaosd::{request_pixel, vbao_sd_pixel};
use std::f32::consts::PI;

/// The vbao §3 unit tests (Blender's), (lo, hi) → mask, hold under both rules; the rules differ
/// where the interval straddles a sector edge without covering a whole sector.
#[test]
fn sector_bits_match_the_spec_table() {
    let table = [
        ((0.0, 0.0), 0),
        ((0.0, 0.015), 0x1),
        ((0.0, 0.25), 0xFF),
        ((0.25, 0.75), 0x00FF_FF00),
        ((0.75, 1.0), 0xFF00_0000),
        ((0.6, 0.6), 0),
        ((0.0, 1.0), 0xFFFF_FFFF), // clamp(−0.5, 1.5)
    ];
    for rule in [RULE_PAPER, RULE_TOUCH] {
        for ((lo, hi), want) in table {
            assert_eq!(sector_bits(lo, hi, rule), want, "rule {rule}: ({lo}, {hi})");
        }
    }
    // N·lo = 3.9, N·hi = 4.1: the paper's count ⌈0.2⌉ = 1 from bit 3, Touch sets bits 3 and 4.
    assert_eq!(sector_bits(3.9 / 32.0, 4.1 / 32.0, RULE_PAPER), 0x8);
    assert_eq!(sector_bits(3.9 / 32.0, 4.1 / 32.0, RULE_TOUCH), 0x18);
    // A whole mask from any start never shifts by 32 or more (a panic in debug builds).
    assert_eq!(sector_bits(31.5 / 32.0, 1.0, RULE_PAPER), 0x8000_0000);
    assert_eq!(sector_bits(1.0, 1.0, RULE_PAPER), 0);
}

fn frame_for(scene: &Scene, eye: Vec3, target: Vec3, radius: f32, size: (u32, u32), fov_deg: f32) -> Frame {
    let req = FrameRequest {
        width: size.0,
        height: size.1,
        guard: 64,
        camera: CameraChoice::Explicit { eye, target, up: Vec3::Y, fov_deg },
        radius: Some(radius),
        exponent: 1.0,
        thickness: 0.0,
    };
    Frame::resolve(scene, None, &req).unwrap()
}

fn validated(s: Scene, name: &str) -> Scene {
    s.validated(std::path::Path::new(name)).unwrap()
}

/// VBAO's main pass alone (no denoiser), visibility per full-target pixel.
fn main_pass(cpu: &CpuRenderer, frame: &Frame, settings: &VbaoSettings) -> Vec<f32> {
    let (g, _) = cpu.gbuffer(frame, &aokit_cpu::no_progress);
    let params = settings.params(&frame.desc());
    let mips = aokit_cpu::gtao::run_prefilter(&params.gtao, &g.depth);
    aokit_cpu::gtao::per_pixel(frame.camera.view.size(), |p| {
        vbao_pixel(&params, &mips, &g.normals, p).term as f32 * 1.5 / 255.0
    })
}

/// VBAO's main pass at one pixel.
fn main_pass_at(cpu: &CpuRenderer, frame: &Frame, settings: &VbaoSettings, p: UVec2) -> f32 {
    let (g, _) = cpu.gbuffer(frame, &aokit_cpu::no_progress);
    let params = settings.params(&frame.desc());
    let mips = aokit_cpu::gtao::run_prefilter(&params.gtao, &g.depth);
    vbao_pixel(&params, &mips, &g.normals, p).term as f32 * 1.5 / 255.0
}

/// "Dense" sampling of spec vbao §6: many slices and steps, power 1, MIP 0 only.
fn dense(weighting: u32) -> VbaoSettings {
    let mut s = VbaoSettings { weighting, ..Default::default() };
    s.xegtao.slices = 64;
    s.xegtao.steps = 64;
    s.xegtao.sample_distribution_power = 1.0;
    s.xegtao.depth_mip_sampling_offset = 30.0;
    s.xegtao.denoise_passes = 0;
    s
}

/// Spec vbao §6.2: on an infinite plane (head-on and at 45°) every sample lies on the
/// hemisphere's edge and its back point below the plane, so no sector is set: `Uniform` and
/// `CosineBlender` give exactly 1 in every pixel (stored term 170 = 1/1.5·255) with MIP-0
/// sampling, and `CosineExact` gives XeGTAO's unoccluded plane value, 1 up to the projected-
/// normal fudge (≥ 0.95, as XeGTAO's own plane test).
#[test]
fn an_infinite_plane_sets_no_sector() {
    let mut s = Scene::default();
    let big = 1000.0;
    push_quad(&mut s, vec3(-big, 0.0, -big), vec3(-big, 0.0, big), vec3(big, 0.0, big), vec3(big, 0.0, -big));
    let scene = validated(s, "plane");
    let cpu = CpuRenderer::new(&scene);
    for (eye, name) in [(vec3(0.0, 5.0, 0.001), "head-on"), (vec3(0.0, 4.0, 4.0), "45°")] {
        let frame = frame_for(&scene, eye, Vec3::ZERO, 0.5, (96, 64), 50.0);
        let view = frame.camera.view;
        for weighting in [WEIGHT_UNIFORM, WEIGHT_COSINE_BLENDER] {
            let mut settings = VbaoSettings { weighting, ..Default::default() };
            settings.xegtao.depth_mip_sampling_offset = 30.0;
            let vis = main_pass(&cpu, &frame, &settings);
            let inner = aokit::output::crop_inner(&view, &vis);
            let min = inner.iter().copied().fold(f32::MAX, f32::min);
            eprintln!("plane {name}, weighting {weighting}: min visibility {min}");
            assert!(inner.iter().all(|&v| v == 170.0 * 1.5 / 255.0), "plane {name}, weighting {weighting}: {min}");
        }
        let exact = main_pass(&cpu, &frame, &VbaoSettings { weighting: WEIGHT_COSINE_EXACT, ..Default::default() });
        let inner = aokit::output::crop_inner(&view, &exact);
        let min = inner.iter().copied().fold(f32::MAX, f32::min);
        eprintln!("plane {name}, cosine-exact: min {min}");
        assert!(min >= 0.95, "plane {name}, cosine-exact: {min}");
    }
}

/// Spec vbao §6.3, the right-angle corner: floor point P at distance d = kR from an infinite
/// wall facing it, seen from 4R straight above (v = n), gate R_g = R, sampling radius 1.457·R,
/// T ≥ R, dense sampling. `CosineExact` must give the ground truth `1 − (acos k − k√(1−k²))/π`
/// and `Uniform` the N = 32 table (0.6772, 0.8049, 0.9069), each within 0.02: 64 slices over
/// the azimuth integral, 32 steps rounded to whole pixels and 8-bit storage (1.5/255 = 0.006)
/// (measured worst: 0.010, k = 0.5 cosine-exact).
#[test]
fn a_right_angle_corner_matches_the_closed_forms() {
    let radius = 1.0;
    let mut worst = 0.0f32;
    for (k, uniform_32) in [(0.25f32, 0.6772f32), (0.5, 0.8049), (0.75, 0.9069)] {
        let mut s = Scene::default();
        let big = 200.0;
        push_quad(&mut s, vec3(-big, 0.0, -big), vec3(-big, 0.0, big), vec3(big, 0.0, big), vec3(big, 0.0, -big));
        // Wall x = kR facing −x (toward P at the origin).
        let x = k * radius;
        push_quad(&mut s, vec3(x, 0.0, big), vec3(x, big, big), vec3(x, big, -big), vec3(x, 0.0, -big));
        let scene = validated(s, "corner");
        let cpu = CpuRenderer::new(&scene);
        let frame = frame_for(&scene, vec3(0.0, 2.0 * radius, 0.001), Vec3::ZERO, radius, (128, 128), 40.0);
        let view = frame.camera.view;
        let p = view.texel_of_uv(view.view_to_uv(frame.camera.world_to_view.transform_point3(Vec3::ZERO)));
        let truth = 1.0 - (k.acos() - k * (1.0 - k * k).sqrt()) / PI;
        for (weighting, want) in [(WEIGHT_COSINE_EXACT, truth), (WEIGHT_UNIFORM, uniform_32)] {
            let mut settings = dense(weighting);
            settings.gate = Gate::Radius;
            settings.thickness = 2.0;
            let got = main_pass_at(&cpu, &frame, &settings, p);
            eprintln!("corner k = {k}, weighting {weighting}: {got:.4}, closed form {want:.4}");
            worst = worst.max((got - want).abs());
        }
    }
    assert!(worst <= 0.02, "corner: worst |Δ| = {worst}");
}

/// The scene of spec vbao §6.4: a wall (z = 0, facing +z) and a long horizontal pole in front
/// of it, `w` high, `t_p` deep, its back face `g` from the wall; a far camera looks at the wall
/// head-on with a narrow field of view.
fn pole_scene(w: f32, t_p: f32, g: f32) -> Scene {
    let mut s = Scene::default();
    let big = 100.0;
    push_quad(&mut s, vec3(-big, -big, 0.0), vec3(big, -big, 0.0), vec3(big, big, 0.0), vec3(-big, big, 0.0));
    push_box(&mut s, vec3(-big, 0.0, g), vec3(big, w, g + t_p));
    validated(s, "pole")
}

/// The thin occluder VBAO exists for (spec vbao §6.4 geometry with R = 1: w = t_p = 0.1,
/// g = 0.5): on the wall within R/2 of the pole, GTAO (its defaults) darkens the wall as if the
/// pole were a solid block reaching it, VBAO at its defaults (T = 0.5·R) lets the light behind
/// the pole through. Against the 256-spp ground truth (exponent 1), VBAO's mean absolute error
/// there is at most half of GTAO's, and below GTAO's with FinalValuePower 1 (measured: 0.028
/// vs 0.100 and 0.056). Thicker samples darken monotonically toward GTAO's solid block (vbao §6.4).
#[test]
fn behind_a_thin_pole_vbao_errs_at_most_half_as_much_as_gtao() {
    let radius = 1.0;
    let scene = pole_scene(0.1, 0.1, 0.5);
    let cpu = CpuRenderer::new(&scene);
    let frame = frame_for(&scene, vec3(0.3, 0.05, 20.0), vec3(0.3, 0.05, 0.0), radius, (160, 120), 9.0);
    let (g, _) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
    let run = |t: &Technique| cpu.run(&frame, &g, t, &aokit_cpu::no_progress).ao_final;
    let truth = run(&Technique::new(&GROUNDTRUTH, GroundTruthSettings { spp: 256, uniform: false }));
    let gtao = run(&Technique::new(&GTAO, GtaoOptions::default()));
    let gtao_linear = run(&Technique::new(&GTAO, GtaoOptions { final_value_power: 1.0, ..Default::default() }));
    let vbao_at = |thickness: f32| run(&Technique::new(&VBAO, VbaoSettings { thickness, ..Default::default() }));
    let vbao = vbao_at(VbaoSettings::default().thickness);
    // The wall within R/2 of the pole, not the pole itself (its front face is 19.4 from the eye).
    let view = frame.camera.view;
    let region: Vec<usize> = (0..g.depth.len())
        .filter(|&i| {
            let p = UVec2::new(i as u32 % view.size().x, i as u32 / view.size().x);
            let inner = p.x >= view.guard
                && p.y >= view.guard
                && p.x < view.size().x - view.guard
                && p.y < view.size().y - view.guard;
            let world = frame.camera.view_to_world.transform_point3(view.uv_to_view(view.pixel_uv(p), g.depth[i]));
            inner && g.depth[i] > 19.9 && world.y > -0.5 * radius && world.y < 0.1 + 0.5 * radius
        })
        .collect();
    assert!(region.len() > 2000, "{} wall pixels near the pole", region.len());
    let mae = |ao: &[f32]| region.iter().map(|&i| (ao[i] - truth[i]).abs() as f64).sum::<f64>() / region.len() as f64;
    let mean = |ao: &[f32]| region.iter().map(|&i| ao[i] as f64).sum::<f64>() / region.len() as f64;
    let (e_vbao, e_gtao, e_linear) = (mae(&vbao), mae(&gtao), mae(&gtao_linear));
    eprintln!(
        "wall near the pole ({} px): mean truth {:.3}, VBAO {:.3}, GTAO {:.3} (power 1: {:.3}); \
         MAE VBAO {e_vbao:.4}, GTAO {e_gtao:.4} (power 1: {e_linear:.4})",
        region.len(),
        mean(&truth),
        mean(&vbao),
        mean(&gtao),
        mean(&gtao_linear)
    );
    assert!(e_vbao <= 0.5 * e_gtao && e_vbao < e_linear, "VBAO {e_vbao} vs GTAO {e_gtao} / {e_linear}");
    // Thicker samples darken monotonically toward GTAO's solid-block answer (vbao §6.4 table).
    let means: Vec<f64> = [0.1, 0.3, 0.5, 0.7].into_iter().map(|t| mean(&vbao_at(t))).collect();
    eprintln!("VBAO mean near the pole for T = 0.1, 0.3, 0.5, 0.7: {means:.3?}");
    assert!(means.windows(2).all(|m| m[1] < m[0]), "not monotone in T: {means:?}");
}

/// Spec vbao §6.5: with T → ∞ every sample occludes from its front angle to the side's edge,
/// so `CosineExact` VBAO is XeGTAO with a hard cut at R (FalloffRange 0, power 1) up to the
/// sector quantization: per slice at most one sector weight per side (≤ π/32·L), and the
/// fast acos of XeGTAO's horizons (≤ 0.0016 rad here). On Sponza, no pixel differs by more
/// than 2·π/32 + 2·(1.5/255) and the inner mean |Δ| stays below 0.01.
#[test]
fn infinite_thickness_is_xegtao_with_a_hard_cut() {
    let (scene, frame) = common::builtin_frame("sponza", 200, 112, 32);
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
    let base = GtaoOptions { denoise_passes: 0, falloff_range: 0.0, final_value_power: 1.0, ..Default::default() };
    let gtao = cpu.run(&frame, &g, &Technique::new(&GTAO, base), &aokit_cpu::no_progress).ao_final;
    let settings = VbaoSettings {
        xegtao: base,
        thickness: 100.0,
        gate: Gate::Effective,
        weighting: WEIGHT_COSINE_EXACT,
        ..Default::default()
    };
    let vbao = cpu.run(&frame, &g, &Technique::new(&VBAO, settings), &aokit_cpu::no_progress).ao_final;
    let view = frame.camera.view;
    let max = common::inner_max_abs(&view, &gtao, &vbao);
    let (a, b) = common::inner_pair(&view, &gtao, &vbao);
    let mean = a.iter().zip(&b).map(|(x, y)| (x - y).abs() as f64).sum::<f64>() / a.len() as f64;
    eprintln!("T = ∞ VBAO vs XeGTAO (hard cut): max |Δ| {max:.4}, mean |Δ| {mean:.5}");
    assert!(max <= 2.0 * PI / 32.0 + 2.0 * 1.5 / 255.0, "max |Δ| {max}");
    assert!(mean <= 0.01, "mean |Δ| {mean}");
}

/// CPU ≡ Vulkan on Sponza (same CPU G-buffer) for each weighting and both sector rules: the
/// final visibility within one 8-bit step (1/255) on ≥ 99.9 % of the inner image and MSE ≤ 1e-6
/// (the contract's conformance bar). The angles go through `precise_acos`, one operation
/// sequence on both back-ends; with the platforms' own acos (several ulp apart) a horizon on a
/// sector edge flipped a whole sector (1/(32·slices) > 1/255) on 0.1–0.3 % of the pixels.
#[test]
fn vbao_vulkan_agrees_with_cpu() {
    let Some(vk) = common::vulkan() else { return };
    let (scene, frame) = common::builtin_frame("sponza", 320, 180, 32);
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
    let view = frame.camera.view;
    for (weighting, touch) in
        [(WEIGHT_UNIFORM, false), (WEIGHT_COSINE_BLENDER, false), (WEIGHT_COSINE_EXACT, false), (WEIGHT_UNIFORM, true)]
    {
        let t = Technique::new(&VBAO, VbaoSettings { weighting, touch, ..Default::default() });
        let c = cpu.run(&frame, &g, &t, &aokit_cpu::no_progress).ao_final;
        let v = vk.run(&scene, &frame, &g, &t).expect("Vulkan VBAO").ao_final;
        let within = common::inner_within(&view, &c, &v, common::agreement::STEP + 1e-6);
        let mse = common::inner_mse(&view, &c, &v);
        eprintln!("weighting {weighting}, touch {touch}: within one step {:.3} %, MSE {mse:.2e}", 100.0 * within);
        assert!(
            within >= common::agreement::MIN_WITHIN && mse <= common::agreement::MAX_MSE,
            "weighting {weighting}: {within}, {mse}"
        );
    }
    common::assert_validation_clean(&vk);
}

// ---- vbao-sd (spec vbao §8): the samples' occupancy from a ray-traced stochastic depth map.

/// `vbao-sd`'s settings at `vbao`'s values except the weighting (its default is cosine-exact).
fn vbao_sd_like(settings: &VbaoSettings) -> Technique {
    Technique::new(&VBAO_SD, *settings)
}

/// The SD map `vbao-sd` traces for the requests of pixel `p` alone (every pixel when `None`):
/// phase 1 (spec vbao §8.1) on the CPU, then Ray-SD's trace over the requested intervals.
fn sd_map_for(cpu: &CpuRenderer, frame: &Frame, settings: &VbaoSettings, only: Option<UVec2>) -> (Vec<f32>, SvaoFrame) {
    use aokit_shaders::common::float_order::{RAY_MAX_CLEAR, RAY_MIN_CLEAR};
    use aokit_shaders::svao::Secondary;
    let (g, _) = cpu.gbuffer(frame, &aokit_cpu::no_progress);
    let params = settings.params(&frame.desc());
    let sd_frame = settings.sd.frame(&frame.desc(), Secondary::StochasticDepth);
    let mips = aokit_cpu::gtao::run_prefilter(&params.gtao, &g.depth);
    let texels = sd_frame.params.sd_size();
    let n = (texels.x * texels.y) as usize;
    let (mut ray_min, mut ray_max) = (vec![RAY_MIN_CLEAR; n], vec![RAY_MAX_CLEAR; n]);
    let size = frame.camera.view.size();
    let pixels: Vec<UVec2> = match only {
        Some(p) => vec![p],
        None => (0..size.y).flat_map(|y| (0..size.x).map(move |x| UVec2::new(x, y))).collect(),
    };
    for p in pixels {
        request_pixel::<f32, _, _>(
            &params,
            &sd_frame.params,
            &mips,
            &g.normals,
            p,
            &mut &mut ray_min[..],
            &mut &mut ray_max[..],
        );
    }
    let pass1 = aokit_cpu::svao::Pass1 { ao: Vec::new(), mask: Vec::new(), ray_min, ray_max };
    let map = aokit_cpu::svao::run_sd_map(
        cpu.bvh(),
        &cpu.surfaces(),
        &sd_frame,
        &g.depth,
        &g.normals,
        &pass1,
        aokit_cpu::svao::HitOrder::Traversal,
    );
    (map.layers, sd_frame)
}

/// Spec vbao §8.3: where the SD map holds no layer every flagged sample falls back to the
/// constant thickness, so `vbao-sd`'s pixel is `vbao`'s bit for bit (terms and edges) on Sponza,
/// under each weighting. On an infinite plane no sample is flagged: the whole technique
/// requests no SD texel, traces no ray and gives `vbao`'s image.
#[test]
fn without_layers_vbao_sd_is_vbao() {
    let (scene, frame) = common::builtin_frame("sponza", 160, 90, 16);
    let cpu = CpuRenderer::new(&scene);
    let (g, _) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
    let size = frame.camera.view.size();
    for weighting in [WEIGHT_UNIFORM, WEIGHT_COSINE_BLENDER, WEIGHT_COSINE_EXACT] {
        let settings = VbaoSettings { weighting, ..Default::default() };
        let params = settings.params(&frame.desc());
        let sd = settings.sd.frame(&frame.desc(), aokit_shaders::svao::Secondary::StochasticDepth).params;
        let empty = vec![1.0f32; (sd.sd_size().x * sd.sd_size().y * sd.sd_layers) as usize];
        let mips = aokit_cpu::gtao::run_prefilter(&params.gtao, &g.depth);
        let mut checked = 0;
        for y in 0..size.y {
            for x in 0..size.x {
                let p = UVec2::new(x, y);
                let want = vbao_pixel(&params, &mips, &g.normals, p);
                let got = vbao_sd_pixel(&params, &sd, &empty, &mips, &g.normals, p);
                assert_eq!((got.term, got.edges), (want.term, want.edges), "weighting {weighting} at {p}");
                checked += 1;
            }
        }
        assert_eq!(checked, size.x * size.y);
    }

    let mut s = Scene::default();
    let big = 1000.0;
    push_quad(&mut s, vec3(-big, 0.0, -big), vec3(-big, 0.0, big), vec3(big, 0.0, big), vec3(big, 0.0, -big));
    let scene = validated(s, "plane");
    let cpu = CpuRenderer::new(&scene);
    let frame = frame_for(&scene, vec3(0.0, 5.0, 0.001), Vec3::ZERO, 0.5, (96, 64), 50.0);
    let (g, _) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
    let settings = VbaoSettings { weighting: WEIGHT_COSINE_EXACT, ..Default::default() };
    let sd = cpu.run(&frame, &g, &vbao_sd_like(&settings), &aokit_cpu::no_progress);
    let plain = cpu.run(&frame, &g, &Technique::new(&VBAO, settings), &aokit_cpu::no_progress);
    assert_eq!(sd.rays, 0, "a plane flags no sample");
    // vbao runs through its lane runner, vbao-sd through the entry points: within one
    // 8-bit step of each other (the runners' own agreement bar).
    let view = frame.camera.view;
    let within = common::inner_within(&view, &sd.ao_final, &plain.ao_final, common::agreement::STEP + 1e-6);
    assert!(within >= common::agreement::MIN_WITHIN, "plane: vbao-sd vs vbao within one step on {within}");
}

/// Spec vbao §8.3 on the corner of spec vbao §6.3 (k = 0.25, 0.5, 0.75; dense sampling, R_g = R): with a
/// one-sided wall (the floor ending at it) the map has no layer behind the wall (the fallback
/// T = 2R), with a wall 0.5·R thick its back face is the exit of every wall sample. Both must give the closed forms
/// within spec vbao §6.3's 0.02; the thick wall must have layers behind its samples (its back face).
#[test]
fn vbao_sd_corner_matches_the_closed_forms_with_and_without_layers() {
    let radius = 1.0;
    let mut worst = 0.0f32;
    for (k, uniform_32) in [(0.25f32, 0.6772f32), (0.5, 0.8049), (0.75, 0.9069)] {
        for thick in [false, true] {
            let mut s = Scene::default();
            let big = 200.0;
            // The floor ends at the wall: nothing lies behind a one-sided wall.
            let x = k * radius;
            push_quad(&mut s, vec3(-big, 0.0, -big), vec3(-big, 0.0, big), vec3(x, 0.0, big), vec3(x, 0.0, -big));
            if thick {
                push_box(&mut s, vec3(x, 0.0, -big), vec3(x + 0.5 * radius, big, big));
            } else {
                push_quad(&mut s, vec3(x, 0.0, big), vec3(x, big, big), vec3(x, big, -big), vec3(x, 0.0, -big));
            }
            let scene = validated(s, "corner");
            let cpu = CpuRenderer::new(&scene);
            let frame = frame_for(&scene, vec3(0.0, 2.0 * radius, 0.001), Vec3::ZERO, radius, (128, 128), 40.0);
            let view = frame.camera.view;
            let p = view.texel_of_uv(view.view_to_uv(frame.camera.world_to_view.transform_point3(Vec3::ZERO)));
            let truth = 1.0 - (k.acos() - k * (1.0 - k * k).sqrt()) / PI;
            let (g, _) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
            for (weighting, want) in [(WEIGHT_COSINE_EXACT, truth), (WEIGHT_UNIFORM, uniform_32)] {
                let mut settings = dense(weighting);
                settings.gate = Gate::Radius;
                settings.thickness = 2.0;
                let (map, sd) = sd_map_for(&cpu, &frame, &settings, Some(p));
                let layers = map.iter().filter(|&&z| z < 1.0).count();
                assert!(layers > 0 || !thick, "k = {k}: no layer behind the thick wall");
                let params = settings.params(&frame.desc());
                let mips = aokit_cpu::gtao::run_prefilter(&params.gtao, &g.depth);
                let got = vbao_sd_pixel(&params, &sd.params, &map, &mips, &g.normals, p).term as f32 * 1.5 / 255.0;
                eprintln!(
                    "vbao-sd corner k = {k}, thick {thick}, weighting {weighting}: {got:.4}, closed form {want:.4} \
                     ({layers} layers)"
                );
                worst = worst.max((got - want).abs());
            }
        }
    }
    assert!(worst <= 0.02, "vbao-sd corner: worst |Δ| = {worst}");
}

/// Spec vbao §8.2, one flagged sample against hand-placed layers: P on a surface facing the
/// camera, Q 2.4·T (1.2·R) in front of it and to the side, the MIP-0 depth at Q's SD ray equal to
/// Q's (the ray enters Q's surface). With Q's first exit 1.6·T behind it the own segment reaches
/// that exit, and a hidden solid (entry 1.8·T, exit 2·T, still in front of P's plane) adds its
/// own segment; an exit only T/2 behind keeps `vbao`'s slab of T; no layer at all is `vbao`'s
/// sample bit for bit. Each case is
/// the sector bits of those segments ([`interval_bits`] in Q's own slice), and the deep exit sets
/// more sectors than the slab.
#[test]
fn a_flagged_sample_takes_its_segments_from_the_layers() {
    // N = 4 (the default) and N = 8 take different reads and sorts (spec vbao §8.2).
    for layers in [4, 8] {
        flagged_sample_with_layers(layers);
    }
}

fn flagged_sample_with_layers(layers: u32) {
    use aokit_shaders::common::screen_space::view_pos;
    use aokit_shaders::gtao::main_pass::PixelSetup;
    use aokit_shaders::raysd::texel_ray_uv;
    use aokit_shaders::svao::sd_pixel;
    use aokit_shaders::vbao::kernel::{Occupancy, interval_bits, own_slice, sample_bits};
    use aokit_shaders::vbaosd::SdLayers;
    let (_, frame) = common::builtin_frame("sponza", 160, 90, 16);
    let mut settings = VbaoSettings { weighting: WEIGHT_COSINE_EXACT, ..Default::default() };
    settings.sd.layers = layers;
    let params = settings.params(&frame.desc());
    let sd = settings.sd.frame(&frame.desc(), aokit_shaders::svao::Secondary::StochasticDepth).params;
    let view = frame.camera.view;
    let (r, t) = (params.gate_radius, params.thickness);
    // P at the image centre, 5R deep, its normal toward the camera; Q to the right, 2.4·T nearer.
    let depth = 5.0 * r;
    let pos = view_pos(&view, aokit_shaders::glam::vec2(0.5, 0.5), depth);
    let v = (-pos).normalize();
    let px = PixelSetup {
        uv: aokit_shaders::glam::vec2(0.5, 0.5),
        pos,
        v,
        n: v,
        r,
        r_px: 10.0,
        min_s: 0.1,
        xi: aokit_shaders::glam::Vec2::ZERO,
        mip_threshold: 1.0,
    };
    let q = view_pos(&view, aokit_shaders::glam::vec2(0.53, 0.5), depth - 2.4 * t);
    let delta = q - pos;
    assert!(delta.length() < r && delta.dot(v) > 0.1 * delta.length(), "Q is a flagged sample: {delta}");
    let texel = sd_pixel(view.view_to_uv(vec3(q.x, q.y, -q.z)), &sd);
    let uv = texel_ray_uv(texel, &sd);
    let mips = vec![q.z; (view.size().x * view.size().y) as usize * 2];
    let n = sd.sd_layers as usize;
    assert_eq!(n, layers as usize, "the SD map holds N layers");
    let normalized = |d: f32| (d - view.near) / (view.far - view.near);
    let map_with = |layers: &[f32]| {
        let mut map = vec![1.0f32; (sd.sd_size().x * sd.sd_size().y) as usize * n];
        let base = sd.sd_index(texel) * n;
        for (k, &d) in layers.iter().enumerate() {
            map[base + k] = normalized(d);
        }
        map
    };
    let own = own_slice::<f32>(delta, v, v);
    let rule = params.sector_rule;
    let at = |d: f32| view_pos(&view, uv, d) - pos;
    for side in [1.0f32, -1.0] {
        let bits = |map: &[f32]| SdLayers { map, sd: &sd, mips: &mips }.bits(&params, delta, &px, side);
        // Deep exit and a hidden solid (stored out of order: the kernel sorts them).
        let deep = bits(&map_with(&[q.z + 2.0 * t, q.z + 1.6 * t, q.z + 1.8 * t]));
        let want = interval_bits(&own, delta, at(q.z + 1.6 * t), v, side, rule)
            | interval_bits(&own, at(q.z + 1.8 * t), at(q.z + 2.0 * t), v, side, rule);
        assert_eq!(deep, want, "N = {layers}, side {side}: deep exit and hidden solid");
        // A shallow exit: the slab of T.
        let shallow = bits(&map_with(&[q.z + 0.5 * t]));
        let slab = interval_bits(&own, delta, delta - v * t, v, side, rule);
        assert_eq!(shallow, slab, "side {side}: shallow exit");
        // No layer: vbao's sample.
        let none = bits(&map_with(&[]));
        assert_eq!(none, sample_bits::<f32>(delta, v, v, side, t, rule), "side {side}: no layer");
        eprintln!(
            "N = {layers}, side {side}: deep {deep:032b}, slab {slab:032b} ({} vs {} sectors)",
            deep.count_ones(),
            slab.count_ones()
        );
        assert!(deep.count_ones() > slab.count_ones() && deep & slab == slab, "side {side}: the exit widens the slab");
    }
}
