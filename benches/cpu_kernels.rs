//! CPU kernel throughput on the Sponza G-buffer at 1920×1080 (+64 px guard band = 2048×1208).
//! Team targets: one VAO pass ≤ 0.1 s on 2 cores; ≥ 5 M incoherent AO rays/s. Also the Ray-SD
//! passes and the reservoir any-hit. Then every pass of every technique's graph at 960×540 (+64)
//! in Mpixel/s of the inner image, timed by the CPU executor itself (to compare with lavapipe), and the ray
//! tracer in M rays/s (`rays/...`). Run: `cargo bench --bench cpu_kernels` (filter:
//! `-- passes/gtao`).

use aokit::cli::TechniqueArgs;
use aokit::frame::{CameraChoice, Frame, FrameRequest};
use aokit::render::CpuRenderer;
use aokit::scene::builtin;
use aokit::technique::SdOptions;
use aokit_cpu::no_progress;
use aokit_cpu::svao as svao_cpu;
use aokit_shaders::glam::vec2;
use aokit_shaders::raysd::{MAX_LAYERS, SdPayload, reservoir_any_hit};
use aokit_shaders::svao::Secondary;
use criterion::{Criterion, SamplingMode, Throughput, criterion_group, criterion_main};
use std::time::Duration;

/// Sponza's preset camera over `width × height` plus the 64 px guard band.
fn sponza_frame(scene: &aokit::scene::Scene, width: u32, height: u32) -> Frame {
    let req = FrameRequest {
        width,
        height,
        guard: 64,
        camera: CameraChoice::Preset { name: None, fov_deg: None },
        radius: None,
        exponent: 2.0,
        thickness: 0.0,
    };
    Frame::resolve(scene, builtin::find("sponza"), &req).unwrap()
}

fn kernels(c: &mut Criterion) {
    let b = builtin::find("sponza").unwrap();
    let scene = b.load().unwrap();
    let frame = sponza_frame(&scene, 1920, 1080);
    let renderer = CpuRenderer::new(&scene);
    let (g, _) = renderer.gbuffer(&frame, &no_progress);
    let vao = frame.vao_params();
    let mut group = c.benchmark_group("sponza_2048x1208");
    group.sample_size(10).measurement_time(Duration::from_secs(8));
    group.bench_function("gbuffer_primary_rays", |bench| bench.iter(|| renderer.gbuffer(&frame, &no_progress)));
    group.bench_function("vao_pass", |bench| {
        bench.iter(|| aokit_cpu::run_vao(&vao, &g.depth, &g.normals, &no_progress))
    });
    let ao = aokit_cpu::run_vao(&vao, &g.depth, &g.normals, &no_progress);
    group.bench_function("blur_two_passes", |bench| {
        bench.iter(|| aokit_cpu::run_blur(&frame.blur_params(), &ao, &g.depth))
    });
    // Ray-SD (¼ map, N = 4): pass 1, the SD map (reservoir any-hit over the BVH), pass 2.
    let svao = SdOptions::default().frame(&frame.desc(), Secondary::StochasticDepth);
    group.bench_function("svao_pass1", |bench| {
        bench.iter(|| svao_cpu::run_pass1(&svao.params, &g.depth, &g.normals, &[], &no_progress))
    });
    let pass1 = svao_cpu::run_pass1(&svao.params, &g.depth, &g.normals, &[], &no_progress);
    let bvh = renderer.bvh();
    let surfaces = renderer.surfaces();
    let map = svao_cpu::run_sd_map(bvh, &surfaces, &svao, &g.depth, &g.normals, &pass1, svao_cpu::HitOrder::Traversal);
    group.throughput(Throughput::Elements(map.rays));
    group.bench_function("raysd_sd_map_rays", |bench| {
        bench.iter(|| {
            svao_cpu::run_sd_map(bvh, &surfaces, &svao, &g.depth, &g.normals, &pass1, svao_cpu::HitOrder::Traversal)
        })
    });
    group.throughput(Throughput::Elements(pass1.refined_samples()));
    group.bench_function("raysd_pass2_refined_samples", |bench| {
        bench.iter(|| svao_cpu::run_pass2_sd(&svao.params, &g.depth, &g.normals, &[], &pass1, &map))
    });
    // Ground-truth AO rays per second (4 spp over the inner image).
    let gt = frame.ground_truth_params(4, false);
    group.throughput(Throughput::Elements(4 * frame.inner.x as u64 * frame.inner.y as u64));
    group.bench_function("groundtruth_ao_rays", |bench| {
        let gt = aokit_shaders::groundtruth::GroundTruthFrame {
            camera: frame.camera,
            params: gt,
            ..bytemuck::Zeroable::zeroed()
        };
        bench.iter(|| aokit_cpu::run_ground_truth(renderer.bvh(), &renderer.surfaces(), &gt, &g, &no_progress))
    });
    group.finish();

    // The reservoir any-hit alone: 16-hit streams into an N = 4 payload.
    let mut micro = c.benchmark_group("reservoir_any_hit");
    micro.throughput(Throughput::Elements(16 * 1024));
    micro.bench_function("hits", |bench| {
        bench.iter(|| {
            let mut kept = 0u32;
            for stream in 0..1024u32 {
                let mut p = SdPayload {
                    depth: [1.0; MAX_LAYERS],
                    count: 0,
                    layers: 4,
                    max_count: u32::MAX,
                    cos_theta: 1.0,
                    near: 0.0,
                    far: 1.0,
                    rotation: 0.0,
                };
                for k in 0..16u32 {
                    let t = ((stream * 16 + k) as f32 * 0.618_034).fract();
                    let b = vec2(t, (t * 7.0).fract());
                    reservoir_any_hit(&mut p, t, b, || true);
                }
                kept += p.count;
            }
            std::hint::black_box(kept)
        })
    });
    micro.finish();
}

/// Every pass of each technique's graph, one benchmark per pass: each iteration runs the
/// technique's frame on the CPU and counts the pass's own wall time as the executor measured it.
fn passes(c: &mut Criterion) {
    let b = builtin::find("sponza").unwrap();
    let scene = b.load().unwrap();
    let frame = sponza_frame(&scene, 960, 540);
    let renderer = CpuRenderer::new(&scene);
    let (g, _) = renderer.gbuffer(&frame, &no_progress);
    let mut group = c.benchmark_group("passes");
    group.sample_size(10).sampling_mode(SamplingMode::Flat).measurement_time(Duration::from_secs(4));
    group.throughput(Throughput::Elements(frame.inner.x as u64 * frame.inner.y as u64));
    for name in ["vao", "sdsvao", "raysd", "gtao", "vbao", "raymarch", "hybrid"] {
        let technique = TechniqueArgs::default().technique(name).unwrap();
        let run = renderer.run(&frame, &g, &technique, &no_progress);
        for &(pass, _) in run.passes.iter().filter(|p| p.0 != "accel_build") {
            group.bench_function(format!("{name}/{pass}"), |bench| {
                bench.iter_custom(|iters| {
                    (0..iters)
                        .map(|_| {
                            let run = renderer.run(&frame, &g, &technique, &no_progress);
                            let ms: f64 = run.passes.iter().filter(|p| p.0 == pass).map(|p| p.1).sum();
                            Duration::from_secs_f64(ms / 1e3)
                        })
                        .sum()
                })
            });
        }
    }
    group.finish();
}

/// Ray throughput in M rays/s on the rays `aokit rays` records (as bench/rays_vs_embree.sh): the G-buffer's
/// primary rays as 4×2 packets and one at a time, and Ray-SVAO's any-hit rays (the SD map's
/// are `sponza_2048x1208/raysd_sd_map_rays`).
fn rays(c: &mut Criterion) {
    use aokit::rays::{Alpha, Tracer, primary_directions, sample_rays, svao_pass1, trace_primary, trace_samples};
    let b = builtin::find("sponza").unwrap();
    let scene = b.load().unwrap();
    let frame = sponza_frame(&scene, 1920, 1080);
    let renderer = CpuRenderer::new(&scene);
    let (g, _) = renderer.gbuffer(&frame, &no_progress);
    let (bvh, surfaces) = (renderer.bvh(), renderer.surfaces());
    let mut group = c.benchmark_group("rays");
    group.sample_size(10).measurement_time(Duration::from_secs(6));
    let directions = primary_directions(&frame.camera);
    let width = frame.camera.view.size().x as usize;
    let mut hits = vec![None; directions.len()];
    group.throughput(Throughput::Elements(directions.len() as u64));
    for tracer in [Tracer::Scene, Tracer::Wide] {
        let name = if tracer == Tracer::Scene { "primary_packets" } else { "primary_single" };
        group.bench_function(name, |bench| {
            bench.iter(|| {
                let rays = (frame.camera.eye(), directions.as_slice(), width);
                trace_primary(bvh, &surfaces, rays, Alpha::On, tracer, &mut hits)
            })
        });
    }
    let svao = SdOptions::default().frame(&frame.desc(), Secondary::Raytraced);
    let samples = sample_rays(&svao, &g, &svao_pass1(&svao, &g));
    let mut states = samples.states.clone();
    group.throughput(Throughput::Elements(samples.states.len() as u64));
    group.bench_function("raysvao_any_hit", |bench| {
        bench.iter(|| trace_samples(bvh, &surfaces, &samples, Alpha::On, Tracer::Scene, &mut states))
    });
    group.finish();
}

criterion_group!(benches, kernels, passes, rays);
criterion_main!(benches);
