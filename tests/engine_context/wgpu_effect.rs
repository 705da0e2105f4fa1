//! The wgpu effect (`aokit_wgpu::AoEffect`) driven as a wgpu application would drive it, on the
//! same engine arrays and matrices as the Vulkan effect's tests above: the application renders
//! its Depth32Float depth in a render pass (a full-screen triangle writing `frag_depth`), uploads
//! RGBA8 normals, owns an R32Float AO texture, and records the effect into its own encoder.
//! Every screen-space technique through it agrees with cpu-sim on the same arrays (import →
//! `CpuExecutor` → export, `cpu_reference`) within the WGSL conformance bar of
//! `common::agreement` (≥ 99.9 % of the pixels within 1/255, MSE ≤ 1e-6, both asserted), at
//! two sizes (a resize between them) and with four frames recorded before any is submitted
//! (frame indices 0 to 3: gtao's, vbao's and raymarch's noise differs between them, so a frame
//! reading another's constants fails), once from the WGSL and once with the committed SPIR-V
//! passed through (`SPIRV_FEATURES`).

use super::*;

/// Frames recorded before the first is submitted.
const FRAMES_AHEAD: u32 = 4;
use aokit_wgpu::AoEffect as WgpuEffect;
use aokit_wgpu::AoFrame as WgpuFrame;

/// wgpu's device on the Vulkan back-end (lavapipe here), with the features that let the effect
/// pass the committed SPIR-V through (`spirv`) or without (the WGSL path); `None` when there is
/// none and the run allows the skip.
fn wgpu_device(spirv: bool) -> Option<(wgpu::Device, wgpu::Queue)> {
    let adapter = common::wgpu_adapter::vulkan()?;
    // WebGPU's default limits (what a browser gives), with timestamps where the adapter has them.
    // Storage R16Float and R8Unorm textures (adapter-specific format features) on both: the
    // SPIR-V path writes them, the WGSL path must refuse them for their format.
    let formats = wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES;
    if !adapter.features().contains(formats) {
        common::skip::cannot_run(common::skip::VULKAN, "the Vulkan adapter lacks storage R16Float/R8Unorm");
        return None;
    }
    let mut required_features = formats | (adapter.features() & wgpu::Features::TIMESTAMP_QUERY);
    if spirv {
        let needed = aokit_wgpu::SPIRV_FEATURES;
        if !adapter.features().contains(needed) {
            common::skip::cannot_run(common::skip::VULKAN, &format!("the Vulkan adapter lacks {needed:?}"));
            return None;
        }
        required_features |= needed;
    }
    // WebGPU's default limits, but room for the largest push constants as immediates.
    let required_limits = wgpu::Limits {
        max_immediate_size: if spirv { adapter.limits().max_immediate_size } else { 0 },
        ..Default::default()
    };
    let descriptor = wgpu::DeviceDescriptor { required_features, required_limits, ..Default::default() };
    Some(pollster::block_on(adapter.request_device(&descriptor)).unwrap())
}

/// The application's textures: depth rendered from `g.depth`, RGBA8 normals, the AO output.
struct AppTextures {
    depth: wgpu::TextureView,
    normals: wgpu::TextureView,
    output: wgpu::Texture,
    output_view: wgpu::TextureView,
}

/// Render `g`'s hardware depth into a Depth32Float texture the way an application's depth pass
/// does, and upload its normals.
fn app_textures(device: &wgpu::Device, queue: &wgpu::Queue, g: &EngineGBuffer) -> AppTextures {
    let size = g.size;
    let extent = wgpu::Extent3d { width: size.x, height: size.y, depth_or_array_layers: 1 };
    let texture = |format, usage| {
        device.create_texture(&wgpu::TextureDescriptor {
            label: None,
            size: extent,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage,
            view_formats: &[],
        })
    };
    let depth = texture(
        wgpu::TextureFormat::Depth32Float,
        wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
    );
    let depth_view = depth.create_view(&Default::default());
    let mut encoder = device.create_command_encoder(&Default::default());
    common::depth_pass::record(device, &mut encoder, &depth_view, &g.depth, size.x);
    queue.submit([encoder.finish()]);
    let normals =
        texture(wgpu::TextureFormat::Rgba8Unorm, wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST);
    queue.write_texture(
        normals.as_image_copy(),
        &g.normal_bytes,
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(4 * size.x), rows_per_image: None },
        extent,
    );
    let output =
        texture(wgpu::TextureFormat::R32Float, wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC);
    AppTextures {
        depth: depth_view,
        normals: normals.create_view(&Default::default()),
        output_view: output.create_view(&Default::default()),
        output,
    }
}

/// Bytes per texel of the AO formats the tests write.
fn texel_bytes(format: wgpu::TextureFormat) -> u32 {
    match format {
        wgpu::TextureFormat::R32Float => 4,
        wgpu::TextureFormat::R16Float => 2,
        wgpu::TextureFormat::R8Unorm => 1,
        other => unreachable!("AO format {other:?}"),
    }
}

/// Copy the AO texture `output` into a new read-back buffer (rows padded to 256 bytes).
fn copy_output(device: &wgpu::Device, encoder: &mut wgpu::CommandEncoder, output: &wgpu::Texture) -> wgpu::Buffer {
    let row = (texel_bytes(output.format()) * output.width()).next_multiple_of(256);
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("AO read-back"),
        size: u64::from(row * output.height()),
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    encoder.copy_texture_to_buffer(
        output.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: None },
        },
        output.size(),
    );
    buffer
}

/// The read-back buffer's AO (of texture `output`), rows unpadded, as `f32`.
fn read_output(device: &wgpu::Device, buffer: &wgpu::Buffer, output: &wgpu::Texture) -> Vec<f32> {
    buffer.slice(..).map_async(wgpu::MapMode::Read, |r| r.expect("mapped"));
    device.poll(wgpu::PollType::wait_indefinitely()).unwrap();
    let bytes = buffer.slice(..).get_mapped_range().expect("mapped range").to_vec();
    let texel = texel_bytes(output.format()) as usize;
    let row = (texel as u32 * output.width()).next_multiple_of(256) as usize;
    let width = output.width() as usize;
    bytes
        .chunks(row)
        .flat_map(|r| {
            r[..texel * width].chunks(texel).map(|t| match t.len() {
                4 => f32::from_le_bytes([t[0], t[1], t[2], t[3]]),
                2 => common::f16_to_f32(u16::from_le_bytes([t[0], t[1]])),
                _ => f32::from(t[0]) / 255.0,
            })
        })
        .collect()
}

#[test]
fn wgpu_effect_frames_agree_with_cpu_sim() {
    // From the WGSL (any wgpu back-end), then from the committed SPIR-V passed through.
    for spirv in [false, true] {
        let Some((device, queue)) = wgpu_device(spirv) else { return };
        effect_frames(&device, &queue, spirv);
    }
}

/// The frames of `wgpu_effect_frames_agree_with_cpu_sim` on `device`, whose effect must run the
/// SPIR-V itself exactly when `spirv`.
fn effect_frames(device: &wgpu::Device, queue: &wgpu::Queue, spirv: bool) {
    let (device, queue) = (device.clone(), queue.clone());
    let start = Instant::now();
    let path = if spirv { "SPIR-V" } else { "WGSL" };
    let convention = DepthConvention::ReversedInfinite;
    let specs = [
        "vao",
        "hbao",
        "gtao:preset=high",
        "gtao:preset=ultra:denoise=0",
        "vbao",
        "raymarch",
        "gtao:resolution=half",
        "vao:resolution=half-nearest",
    ];
    let first = Technique::parse(specs[0]).unwrap();
    let (_, frame) = common::builtin_frame("sponza", 160, 96, 16);
    let mut effect = WgpuEffect::new(&device, &queue, effect_settings(&first, &frame)).unwrap();
    assert_eq!(effect.runs_spirv(), spirv);
    let mut report = Vec::new();
    // Two sizes: the second frame set runs after a resize (every buffer re-made).
    for (width, height, with_normals) in [(160, 96, true), (120, 72, false)] {
        let (scene, frame) = common::builtin_frame("sponza", width, height, 16);
        let view = frame.camera.view;
        let renderer = CpuRenderer::new(&scene);
        let (gbuffer, _) = renderer.gbuffer(&frame, &no_progress);
        let v = engine_view(&frame, convention);
        let g = EngineGBuffer { params: v.params, ..engine_gbuffer(&view, &gbuffer, EngineFormats::d32(convention)) };
        let textures = app_textures(&device, &queue, &g);
        effect.resize(g.size.x, g.size.y).unwrap();
        for spec in specs {
            let technique = Technique::parse(spec).unwrap();
            effect.set_settings(effect_settings(&technique, &frame)).unwrap();
            // Four frames recorded (frame indices 0 to 3) before any is submitted.
            let mut encoders = Vec::new();
            for index in 0..FRAMES_AHEAD {
                let mut ao_frame =
                    WgpuFrame::new(&textures.depth, convention, &textures.output_view, v.projection, v.world_to_view)
                        .temporal(index, None);
                if with_normals {
                    ao_frame = ao_frame.normals(&textures.normals);
                }
                let mut encoder = device.create_command_encoder(&Default::default());
                effect.record(&mut encoder, &ao_frame).unwrap();
                let readback = copy_output(&device, &mut encoder, &textures.output);
                encoders.push((index, encoder, readback));
            }
            let readbacks: Vec<_> = encoders
                .into_iter()
                .map(|(index, encoder, readback)| {
                    queue.submit([encoder.finish()]);
                    (index, readback)
                })
                .collect();
            for (index, readback) in readbacks {
                let on_wgpu = read_output(&device, &readback, &textures.output);
                let desc = FrameDesc {
                    frame_index: index,
                    ..FrameDesc::new(v.camera, frame.radius, frame.exponent, frame.thickness)
                };
                let graph = technique.graph(&desc).unwrap();
                let on_cpu = cpu_reference(&renderer, &graph, &g, with_normals);
                assert_eq!(
                    (on_cpu.ao.len(), on_wgpu.len()),
                    ((width * height) as usize, (width * height) as usize),
                    "{spec}: lengths"
                );
                let a = common::agreement::of(&on_cpu.ao, &on_wgpu);
                let normals = if with_normals { "RGBA8 normals" } else { "normals from depth" };
                let line = format!(
                    "{path}: {spec} {width}×{height} frame {index} ({normals}): {:.3} % within 1/255, max |Δ| {:.2}/255, MSE {:.2e}, occluded {:.1} %",
                    100.0 * a.within,
                    255.0 * a.max,
                    a.mse,
                    100.0 * a.occluded
                );
                eprintln!("wgpu effect vs cpu-sim: {line}");
                assert!(a.occluded >= 0.02, "{line}: too little occlusion to compare");
                assert!(a.within >= common::agreement::MIN_WITHIN && a.mse <= common::agreement::MAX_MSE, "{line}");
                report.push(line);
            }
        }
    }
    // A timed frame (one compute pass per label) gives the same AO, and a time per label (the
    // frame gives no normals: the graph derives them first).
    let (scene, frame) = common::builtin_frame("sponza", 120, 72, 16);
    let renderer = CpuRenderer::new(&scene);
    let (gbuffer, _) = renderer.gbuffer(&frame, &no_progress);
    let v = engine_view(&frame, convention);
    let g = EngineGBuffer {
        params: v.params,
        ..engine_gbuffer(&frame.camera.view, &gbuffer, EngineFormats::d32(convention))
    };
    let textures = app_textures(&device, &queue, &g);
    let technique = Technique::parse("gtao").unwrap();
    effect.set_settings(effect_settings(&technique, &frame)).unwrap();
    let ao_frame = WgpuFrame::new(&textures.depth, convention, &textures.output_view, v.projection, v.world_to_view);
    let run = |effect: &mut WgpuEffect| {
        let mut encoder = device.create_command_encoder(&Default::default());
        effect.record(&mut encoder, &ao_frame).unwrap();
        let readback = copy_output(&device, &mut encoder, &textures.output);
        queue.submit([encoder.finish()]);
        read_output(&device, &readback, &textures.output)
    };
    let untimed = run(&mut effect);
    if device.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
        effect.set_timing(true).unwrap();
        let timed = run(&mut effect);
        assert!(timed == untimed, "a timed frame differs from the untimed one");
        let times = effect.pass_times().unwrap();
        let mut labels: Vec<&str> =
            technique.graph(&frame.desc()).unwrap().with_normals_from_depth().passes.iter().map(|p| p.label).collect();
        labels.dedup();
        labels.insert(0, aokit_wgpu::IMPORT_LABEL);
        labels.push(aokit_wgpu::EXPORT_LABEL);
        assert_eq!(times.iter().map(|t| t.0).collect::<Vec<_>>(), labels);
        assert!(times.iter().all(|t| t.1 > 0.0 && t.1 < 1e4), "{times:?}");
        eprintln!("{path}: timed gtao frame: {times:?}");
    } else {
        let e = effect.set_timing(true).expect_err("timing without TIMESTAMP_QUERY").to_string();
        assert!(e.contains("TIMESTAMP_QUERY"), "{e}");
    }
    // The other AO formats: R16Float and R8Unorm from SPIR-V (their export kernels have no
    // WGSL), against cpu-sim's export stored in the same format; refused on the WGSL path.
    effect.set_timing(false).unwrap();
    let desc = FrameDesc::new(v.camera, frame.radius, frame.exponent, frame.thickness);
    let on_cpu = cpu_reference(&renderer, &technique.graph(&desc).unwrap(), &g, false).ao;
    for format in [wgpu::TextureFormat::R16Float, wgpu::TextureFormat::R8Unorm] {
        let storage = wgpu::TextureUsages::STORAGE_BINDING;
        let output = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("AO"),
            size: textures.output.size(),
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage: storage | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let view = output.create_view(&Default::default());
        let ao_frame = WgpuFrame::new(&textures.depth, convention, &view, v.projection, v.world_to_view);
        let mut encoder = device.create_command_encoder(&Default::default());
        if !spirv {
            let e = effect.record(&mut encoder, &ao_frame).expect_err("an R16F/R8 output from WGSL").to_string();
            assert!(e.contains(&format!("{format:?}")) && e.contains("R32Float") && !e.contains('\n'), "{e}");
            continue;
        }
        effect.record(&mut encoder, &ao_frame).unwrap();
        let readback = copy_output(&device, &mut encoder, &output);
        queue.submit([encoder.finish()]);
        let on_wgpu = read_output(&device, &readback, &output);
        let stored: Vec<f32> = on_cpu
            .iter()
            .map(|&a| match format {
                wgpu::TextureFormat::R16Float => common::f16_to_f32(common::f32_to_f16(a)),
                _ => (a * 255.0).round() / 255.0,
            })
            .collect();
        let a = common::agreement::of(&stored, &on_wgpu);
        let line = format!("{path}: gtao into {format:?}: {:.3} % within 1/255, MSE {:.2e}", 100.0 * a.within, a.mse);
        eprintln!("{line}");
        assert!(a.within >= common::agreement::MIN_WITHIN && a.mse <= common::agreement::MAX_MSE, "{line}");
    }
    // What it cannot run is refused on one line naming the technique, before any frame.
    for name in ["raysd", "groundtruth", "sdsvao"] {
        let settings = effect_settings(&Technique::named(name).unwrap(), &frame);
        let e = WgpuEffect::new(&device, &queue, settings).expect_err(name).to_string();
        assert!(e.contains(name) && e.contains("aokit-vulkan") && !e.contains('\n'), "{e}");
    }
    eprintln!("wgpu_effect_frames_agree_with_cpu_sim ({path}): {:.1} s", start.elapsed().as_secs_f64());
    assert_eq!(report.len(), 2 * FRAMES_AHEAD as usize * specs.len());
}

/// The ray-traced techniques through the wgpu effect (ray queries in the committed SPIR-V, the
/// acceleration structure built with wgpu's BLAS/TLAS API) on the frame of
/// `ray_queries_on_an_engine_device_agree_with_the_pipelines_and_cpu_sim`: they must agree with
/// the Vulkan effect's ray queries on that frame like two runs of one kernel (≥ 99.9 % within
/// 1/255, MSE ≤ 1e-6: the same SPIR-V on the same driver, over a TLAS of the same triangles),
/// and the ground truth with cpu-sim (`check_agreement`). Every ray-traced technique runs: raysd,
/// the ground truth, hbao-sd, hybrid, raysvao and vbao-sd. A device without ray queries refuses them on
/// one line.
#[test]
fn wgpu_ray_queries_agree_with_the_vulkan_effect_and_cpu_sim() {
    // The first two also against cpu-sim (on the Vulkan side, `check_frame`; the ground truth
    // here too); the others against the Vulkan effect only.
    let specs = ["raysd", "groundtruth:spp=16", "hbao-sd", "hybrid", "raysvao", "vbao-sd"];
    let Some(mut on_vulkan) = ray_traced_frames(RayTracing::QueriesOnly, &specs[..2], true) else { return };
    let Some(others) = ray_traced_frames(RayTracing::QueriesOnly, &specs[2..], false) else { return };
    on_vulkan.extend(others);
    let Some(adapter) = common::wgpu_adapter::vulkan() else { return };
    if !adapter.features().contains(aokit_wgpu::RAY_QUERY_FEATURES) {
        common::skip::cannot_run(common::skip::VULKAN, "the Vulkan adapter lacks wgpu's ray queries or passthrough");
        return;
    }
    let descriptor = wgpu::DeviceDescriptor {
        required_features: aokit_wgpu::RAY_QUERY_FEATURES,
        required_limits: adapter.limits(),
        // SAFETY (of the token): ray queries are experimental in wgpu 30.
        experimental_features: unsafe { wgpu::ExperimentalFeatures::enabled() },
        ..Default::default()
    };
    let (device, queue) = pollster::block_on(adapter.request_device(&descriptor)).unwrap();
    let (scene, frame) = common::builtin_frame("sponza", 96, 64, 12);
    let view = frame.camera.view;
    let renderer = CpuRenderer::new(&scene);
    let (gbuffer, _) = renderer.gbuffer(&frame, &no_progress);
    let v = engine_view(&frame, DepthConvention::Reversed);
    let g = EngineGBuffer { params: v.params, ..engine_gbuffer(&view, &gbuffer, EngineFormats::d32(v.convention)) };
    let textures = app_textures(&device, &queue, &g);
    let first = Technique::parse(specs[0]).unwrap();
    let mut effect = WgpuEffect::new(&device, &queue, effect_settings(&first, &frame)).unwrap();
    assert!(effect.runs_ray_queries());
    effect.resize(g.size.x, g.size.y).unwrap();
    let rays = effect.build_scene(&scene.corner_tables().geometry(&scene.triangle_materials)).unwrap();
    for (spec, vulkan) in specs.iter().zip(&on_vulkan) {
        let technique = Technique::parse(spec).unwrap();
        effect.set_settings(effect_settings(&technique, &frame)).unwrap();
        let ao_frame =
            WgpuFrame::new(&textures.depth, v.convention, &textures.output_view, v.projection, v.world_to_view)
                .normals(&textures.normals);
        // Without the scene: refused before anything is recorded.
        let mut encoder = device.create_command_encoder(&Default::default());
        let e = effect.record(&mut encoder, &ao_frame).expect_err("a ray-traced frame without the scene").to_string();
        assert!(e.contains("build_scene") && !e.contains('\n'), "{e}");
        effect.record(&mut encoder, &ao_frame.scene(&rays)).unwrap();
        let readback = copy_output(&device, &mut encoder, &textures.output);
        queue.submit([encoder.finish()]);
        let on_wgpu = read_output(&device, &readback, &textures.output);
        let a = common::agreement::of(vulkan, &on_wgpu);
        let line = format!(
            "{spec}: wgpu ray queries vs the Vulkan effect's: {:.3} % within 1/255, max |Δ| {:.2}/255, MSE {:.2e}, occluded {:.1} %",
            100.0 * a.within,
            255.0 * a.max,
            a.mse,
            100.0 * a.occluded
        );
        eprintln!("{line}");
        assert!(a.occluded >= 0.02, "{line}: too little occlusion to compare");
        assert!(a.within >= common::agreement::MIN_WITHIN && a.mse <= common::agreement::MAX_MSE, "{line}");
        if spec.starts_with("groundtruth") {
            let desc = FrameDesc::new(v.camera, frame.radius, frame.exponent, frame.thickness);
            let graph = technique.graph(&desc).unwrap();
            let on_cpu = cpu_reference(&renderer, &graph, &g, true);
            check_agreement(&format!("{spec} through aokit-wgpu"), &on_cpu.ao, &on_wgpu);
        }
    }
    // A device without ray queries refuses them on one line, naming what it needs.
    let (plain, plain_queue) = wgpu_device(false).expect("the adapter above");
    let e =
        WgpuEffect::new(&plain, &plain_queue, effect_settings(&first, &frame)).expect_err("no ray queries").to_string();
    assert!(e.contains("raysd") && e.contains("RAY_QUERY_FEATURES") && !e.contains('\n'), "{e}");
}
