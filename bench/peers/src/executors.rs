//! `aokit-peers executors`: the same techniques through aokit's two executors on one frame —
//! `aokit-vulkan`'s (ash, the internal path `AoContext::record` on the G-buffer buffers) and
//! `aokit-wgpu`'s engine API (`AoEffect::record` on the application's textures: linear depth in
//! an `R32Float` texture, RGBA8 normals, an `R32Float` AO texture) — both on the Vulkan driver
//! of this machine (wgpu's Vulkan back-end), alternating which goes first each iteration.
//!
//! Both sides time the technique's pass labels with GPU timestamps (`pass_times` on both); the
//! table's time is their sum, so the wgpu side's import and export adapters are not counted
//! (the ash path has none). Beside it, the wall time from submission to completion of the whole
//! frame (adapters included on the wgpu side). Ray-traced techniques run as ray queries on both
//! sides (the TLAS built by each executor from the same triangles); a technique `aokit-wgpu`
//! refuses is listed with the refusal.

use crate::common::{self, FrameArgs, Row, median};
use aokit::technique::Technique;
use aokit_shaders::common::normal_codec::decode_normal;
use aokit_shaders::glam::{Mat4, Vec4};
use aokit_shaders::graph::RtMode;
use aokit_vulkan::{AoContext, Gpu, GpuInputs, GpuOptions, SceneAccel};
use ash::vk;
use std::path::PathBuf;
use std::rc::Rc;
use std::time::Instant;

/// `aokit-peers executors`.
#[derive(clap::Args)]
pub struct ExecutorsArgs {
    #[command(flatten)]
    pub frame: FrameArgs,
    /// Techniques (with settings, `name[:key=value…]`), comma-separated.
    #[arg(long, default_value = "vao,gtao,vbao,raysd")]
    pub techniques: String,
    /// Run the wgpu side from the WGSL even where the adapter can pass the SPIR-V through.
    #[arg(long)]
    pub wgsl: bool,
    /// Write the table as Markdown here.
    #[arg(long)]
    pub markdown: Option<PathBuf>,
}

/// wgpu's device on the Vulkan back-end with timestamp queries.
fn wgpu_device(wgsl: bool) -> Result<(wgpu::Device, wgpu::Queue, String), String> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::VULKAN,
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    });
    let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
        .map_err(|e| format!("no Vulkan adapter for wgpu: {e}"))?;
    let name = adapter.get_info().name;
    // With the committed SPIR-V passed through, and ray queries, where the adapter can
    // (`--wgsl`: never).
    let spirv = if wgsl { wgpu::Features::empty() } else { adapter.features() & aokit_wgpu::RAY_QUERY_FEATURES };
    let descriptor = wgpu::DeviceDescriptor {
        required_features: wgpu::Features::TIMESTAMP_QUERY | spirv,
        required_limits: adapter.limits(),
        // SAFETY (of the token): ray queries are experimental in wgpu 30.
        experimental_features: unsafe { wgpu::ExperimentalFeatures::enabled() },
        ..Default::default()
    };
    let (device, queue) = pollster::block_on(adapter.request_device(&descriptor)).map_err(|e| e.to_string())?;
    Ok((device, queue, name))
}

/// A 2D texture of `size` with `data` (`bytes_per_texel` each) written in.
fn texture(
    (device, queue): (&wgpu::Device, &wgpu::Queue),
    (w, h): (u32, u32),
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
    data: Option<(&[u8], u32)>,
) -> wgpu::Texture {
    let extent = wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 };
    let t = device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: extent,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: usage | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    if let Some((bytes, texel)) = data {
        let layout = wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(texel * w), rows_per_image: None };
        queue.write_texture(t.as_image_copy(), bytes, layout, extent);
    }
    t
}

pub fn run(args: ExecutorsArgs) -> Result<(), String> {
    let (scene, frame, gbuffer) = common::frame_and_gbuffer(&args.frame)?;
    let tables = scene.corner_tables();
    let geometry = tables.geometry(&scene.triangle_materials);
    let view = frame.camera.view;
    let (w, h) = (view.size().x, view.size().y);
    // The ash side: aokit's internal path on the G-buffer buffers.
    let gpu = Rc::new(Gpu::new(&GpuOptions::default()).map_err(|e| e.to_string())?);
    let depth = gpu.upload(&gbuffer.depth, vk::BufferUsageFlags::STORAGE_BUFFER).map_err(|e| e.to_string())?;
    let normals = gpu.upload(&gbuffer.normals, vk::BufferUsageFlags::STORAGE_BUFFER).map_err(|e| e.to_string())?;
    let masks = (geometry.mask_headers.to_vec(), geometry.mask_texels.to_vec());
    let accel = SceneAccel::build(&gpu, geometry.positions, geometry.uvs, geometry.materials, &masks)
        .map_err(|e| e.to_string())?;
    let inputs = GpuInputs { depth: &depth, normals: &normals, second_depth: None, scene: Some(&accel), raster: None };
    // The wgpu side: the application's textures and matrices.
    let (device, queue, adapter) = wgpu_device(args.wgsl)?;
    let dq = (&device, &queue);
    let sampled = wgpu::TextureUsages::TEXTURE_BINDING;
    let linear =
        texture(dq, (w, h), wgpu::TextureFormat::R32Float, sampled, Some((bytemuck::cast_slice(&gbuffer.depth), 4)));
    let rgba: Vec<u8> = gbuffer
        .normals
        .iter()
        .flat_map(|&n| {
            let c = decode_normal(n) * 0.5 + 0.5;
            [c.x, c.y, c.z, 1.0].map(|v| (v * 255.0).round() as u8)
        })
        .collect();
    let rgba8 = texture(dq, (w, h), wgpu::TextureFormat::Rgba8Unorm, sampled, Some((&rgba, 4)));
    let storage = wgpu::TextureUsages::STORAGE_BINDING;
    let output = texture(dq, (w, h), wgpu::TextureFormat::R32Float, storage, None);
    let views = [&linear, &rgba8, &output].map(|t| t.create_view(&Default::default()));
    // A standard-Z projection of aokit's camera (y flipped: row 0 at the top), which the effect
    // reads back into the same field of view and planes.
    let (n, f, tan) = (view.near, view.far, view.tan_half_fov);
    let projection = Mat4::from_cols(
        Vec4::new(1.0 / tan.x, 0.0, 0.0, 0.0),
        Vec4::new(0.0, -1.0 / tan.y, 0.0, 0.0),
        Vec4::new(0.0, 0.0, f / (n - f), -1.0),
        Vec4::new(0.0, 0.0, n * f / (n - f), 0.0),
    );
    let wgpu_frame = aokit_wgpu::AoFrame::new(
        &views[0],
        aokit_wgpu::DepthConvention::Linear,
        &views[2],
        projection,
        frame.camera.world_to_view,
    )
    .normals(&views[1]);

    let mut results = Vec::new();
    for spec in args.techniques.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let technique = Technique::parse(spec)?;
        // Ray-traced passes as ray queries on both sides (what aokit-wgpu runs).
        let graph = technique.graph(&frame.desc())?.with_rt_mode(RtMode::Query);
        let settings = aokit_wgpu::AoSettings::new(technique.clone())
            .radius(frame.radius)
            .exponent(frame.exponent)
            .thickness(frame.thickness);
        let mut effect = match aokit_wgpu::AoEffect::new(&device, &queue, settings) {
            Ok(effect) => effect,
            Err(e) => {
                eprintln!("{spec}: aokit-wgpu refuses it: {e}");
                results.push(serde_json::json!({ "technique": spec, "refused": e.to_string() }));
                continue;
            }
        };
        effect.resize(w, h).map_err(|e| e.to_string())?;
        let rays =
            if graph.traces_rays() { Some(effect.build_scene(&geometry).map_err(|e| e.to_string())?) } else { None };
        let wgpu_frame = match &rays {
            Some(rays) => wgpu_frame.scene(rays),
            None => wgpu_frame,
        };
        effect.set_timing(true).map_err(|e| e.to_string())?;
        let mut ctx = AoContext::new(gpu.clone());
        let mut row = Row { name: spec.to_string(), aokit_ms: Vec::new(), peer_ms: Vec::new() };
        let (mut wall_wgpu, mut wall_ash, mut wgpu_adapters) = (Vec::new(), Vec::new(), Vec::new());
        let total = args.frame.warmup + args.frame.iterations;
        for k in 0..total {
            let mut times = [0.0; 2];
            let mut walls = [0.0; 2];
            let mut labels = [Vec::new(), Vec::new()];
            let mut adapters_ms = 0.0;
            for side in 0..2 {
                // `aokit_ms`: the wgpu side; `peer_ms`: the ash side.
                if (side == 0) == (k % 2 == 0) {
                    let mut encoder = device.create_command_encoder(&Default::default());
                    effect.record(&mut encoder, &wgpu_frame).map_err(|e| e.to_string())?;
                    let start = Instant::now();
                    queue.submit([encoder.finish()]);
                    device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| e.to_string())?;
                    walls[0] = start.elapsed().as_secs_f64() * 1e3;
                    let mut passes = effect.pass_times().map_err(|e| e.to_string())?;
                    // The graph's labels only (the ash side runs no import or export).
                    let adapters = [aokit_wgpu::IMPORT_LABEL, aokit_wgpu::EXPORT_LABEL];
                    let adapter_ms: f64 = passes.iter().filter(|p| adapters.contains(&p.0)).map(|p| p.1).sum();
                    passes.retain(|p| !adapters.contains(&p.0));
                    times[0] = passes.iter().map(|p| p.1).sum();
                    adapters_ms = adapter_ms;
                    labels[0] = passes;
                } else {
                    let cmd = gpu.begin_one_shot().map_err(|e| e.to_string())?;
                    let recorded = ctx.record(cmd, &graph, &inputs);
                    walls[1] = gpu.finish_one_shot(cmd, recorded.is_ok()).map_err(|e| e.to_string())?;
                    recorded.map_err(|e| e.to_string())?;
                    let passes = ctx.pass_times().map_err(|e| e.to_string())?;
                    times[1] = passes.iter().map(|p| p.1).sum();
                    labels[1] = passes;
                }
            }
            if k >= args.frame.warmup {
                row.aokit_ms.push(times[0]);
                row.peer_ms.push(times[1]);
                wall_wgpu.push(walls[0]);
                wall_ash.push(walls[1]);
                wgpu_adapters.push(adapters_ms);
            }
            let by_label: Vec<String> =
                labels[0].iter().zip(&labels[1]).map(|(a, b)| format!("{} {:.1}/{:.1}", a.0, a.1, b.1)).collect();
            eprintln!(
                "{spec} iteration {}/{total}: wgpu {:.2} ms, ash {:.2} ms (GPU; per label wgpu/ash: {})",
                k + 1,
                times[0],
                times[1],
                by_label.join(", ")
            );
        }
        let wall_ratios: Vec<f64> = wall_wgpu.iter().zip(&wall_ash).map(|(a, b)| a / b).collect();
        results.push(serde_json::json!({
            "technique": spec,
            "wgpu_shaders": if effect.runs_spirv() { "SPIR-V" } else { "WGSL" },
            "wgpu_ms": median(&row.aokit_ms),
            "ash_ms": median(&row.peer_ms),
            "ratio": row.ratio(),
            "wgpu_wall_ms": median(&wall_wgpu),
            "ash_wall_ms": median(&wall_ash),
            "wall_ratio": median(&wall_ratios),
            "wgpu_import_export_ms": median(&wgpu_adapters),
            "wgpu_ms_all": row.aokit_ms,
            "ash_ms_all": row.peer_ms,
        }));
    }
    let report = serde_json::json!({
        "adapter": adapter,
        "scene": args.frame.scene,
        "width": w,
        "height": h,
        "iterations": args.frame.iterations,
        "techniques": results,
    });
    if let Some(path) = &args.markdown {
        std::fs::write(path, markdown(&report)).map_err(|e| format!("{}: {e}", path.display()))?;
    }
    common::finish(report, args.frame.json.as_ref())
}

/// The report as the Markdown table of `bench/EXECUTORS.md`.
fn markdown(report: &serde_json::Value) -> String {
    let mut out = format!(
        "# aokit-wgpu vs aokit-vulkan (ash), same run\n\n`cargo run --release -p aokit-peers -- executors --markdown bench/EXECUTORS.md` (`--wgsl`: the WGSL path) — {} at {}×{}, {} alternating iterations, adapter `{}`.\nGPU: the sum of the technique's pass labels (GPU timestamps on both sides); the wgpu side's texture import and export are timed apart (the ash side, aokit's internal path on buffers, runs none). Wall: submission to completion of the whole frame. Ratios: medians of the per-iteration ratios wgpu / ash.\n\n| technique | wgpu runs | wgpu ms (GPU) | ash ms (GPU) | wgpu / ash | wgpu import + export ms (GPU) | wgpu wall ms | ash wall ms | wall wgpu / ash |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n",
        report["scene"].as_str().unwrap_or(""),
        report["width"],
        report["height"],
        report["iterations"],
        report["adapter"].as_str().unwrap_or(""),
    );
    for t in report["techniques"].as_array().into_iter().flatten() {
        let name = t["technique"].as_str().unwrap_or("");
        if let Some(why) = t["refused"].as_str() {
            out += &format!("| {name} | refused: {why} | | | | | | | |\n");
        } else {
            let v = |k: &str| t[k].as_f64().unwrap_or(f64::NAN);
            out += &format!(
                "| {name} | {} | {:.2} | {:.2} | **{:.3}** | {:.2} | {:.2} | {:.2} | {:.3} |\n",
                t["wgpu_shaders"].as_str().unwrap_or(""),
                v("wgpu_ms"),
                v("ash_ms"),
                v("ratio"),
                v("wgpu_import_export_ms"),
                v("wgpu_wall_ms"),
                v("ash_wall_ms"),
                v("wall_ratio")
            );
        }
    }
    out
}
