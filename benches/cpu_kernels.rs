//! CPU kernel throughput on the Sponza G-buffer at 1920×1080 (+64 px guard band = 2048×1208).
//! Team target: one VAO pass ≤ 0.1 s on 2 cores. Run: `cargo bench --bench cpu_kernels`.

use aokit::frame::{CameraChoice, Frame, FrameRequest};
use aokit::render::CpuRenderer;
use aokit::scene::builtin;
use aokit_cpu::no_progress;
use criterion::{Criterion, criterion_group, criterion_main};
use std::time::Duration;

fn kernels(c: &mut Criterion) {
    let b = builtin::find("sponza").unwrap();
    let scene = b.load().unwrap();
    let req = FrameRequest {
        width: 1920,
        height: 1080,
        guard: 64,
        camera: CameraChoice::Preset { name: None, fov_deg: None },
        radius: None,
        exponent: 2.0,
        thickness: 0.0,
    };
    let frame = Frame::resolve(&scene, Some(b), &req).unwrap();
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
    group.finish();
}

criterion_group!(benches, kernels);
criterion_main!(benches);
