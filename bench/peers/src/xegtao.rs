//! aokit's gtao (High preset) against Intel's XeGTAO HLSL, compiled to SPIR-V, on one Vulkan
//! device: same frame, same depth and normals, same settings (XeGTAO's defaults, which are
//! aokit's gtao defaults).
//!
//! aokit runs its internal path (`AoContext::record` on the G-buffer: linear depth and
//! octahedral normals in storage buffers). XeGTAO gets the same G-buffer the way its sample
//! engine feeds it: the depth as a reversed-Z NDC depth texture (from the linear depth with
//! XeGTAO's own unpack constants, `viewZ = mul / (add − ndc)`, so its prefilter recovers the
//! same values), the normals as aokit's octahedral codes in an `R32_UINT` texture (XeGTAO's
//! `LoadNormal` is engine-specific: the SPIR-V decodes aokit's code there, so both sides see the
//! same normals). The SPIR-V's interface is in bench/peers/README.md.

use crate::common::{self, FrameArgs, Row};
use aokit_vulkan::{AoContext, Buffer, Gpu, GpuError, GpuInputs, GpuOptions, Technique};
use ash::vk;
use std::path::PathBuf;
use std::rc::Rc;

/// `aokit-peers xegtao`.
#[derive(clap::Args)]
pub struct XegtaoArgs {
    #[command(flatten)]
    pub frame: FrameArgs,
    /// Folder with XeGTAO's SPIR-V: `CSPrefilterDepths16x16.spv`, `CSGTAOHigh.spv` and
    /// `CSDenoiseLastPass.spv` (bindings in bench/peers/README.md).
    #[arg(long)]
    pub spirv: PathBuf,
}

/// XeGTAO's entry points, in dispatch order, and the names of the compared passes.
const ENTRIES: [&str; 3] = ["CSPrefilterDepths16x16", "CSGTAOHigh", "CSDenoiseLastPass"];
const PASSES: [&str; 3] = ["prefilter", "main", "denoise"];
/// XeGTAO's depth MIP levels (`XE_GTAO_DEPTH_MIP_LEVELS`).
const MIPS: u32 = 5;

/// XeGTAO's `GTAOConstants` (XeGTAO.h), 96 bytes, the members packed as declared.
#[repr(C)]
#[derive(Copy, Clone, bytemuck::Pod, bytemuck::Zeroable)]
struct GtaoConstants {
    viewport_size: [i32; 2],
    viewport_pixel_size: [f32; 2],
    depth_unpack_consts: [f32; 2],
    camera_tan_half_fov: [f32; 2],
    ndc_to_view_mul: [f32; 2],
    ndc_to_view_add: [f32; 2],
    ndc_to_view_mul_x_pixel_size: [f32; 2],
    effect_radius: f32,
    effect_falloff_range: f32,
    radius_multiplier: f32,
    padding0: f32,
    final_value_power: f32,
    denoise_blur_beta: f32,
    sample_distribution_power: f32,
    thin_occluder_compensation: f32,
    depth_mip_sampling_offset: f32,
    noise_index: i32,
}

/// Run the comparison and write the report.
pub fn run(args: XegtaoArgs) -> Result<(), String> {
    let spirv: Vec<Vec<u8>> = ENTRIES
        .iter()
        .map(|e| {
            let path = args.spirv.join(format!("{e}.spv"));
            std::fs::read(&path).map_err(|err| format!("{}: {err} (bench/peers/README.md)", path.display()))
        })
        .collect::<Result<_, _>>()?;
    let (_scene, frame, gbuffer) = common::frame_and_gbuffer(&args.frame)?;
    let gpu = Rc::new(Gpu::new(&GpuOptions::default()).map_err(|e| e.to_string())?);
    let technique = Technique::preset("gtao", "high")?;
    let graph = technique.graph(&frame.desc())?;
    let view = frame.camera.view;
    let (w, h) = (view.size().x, view.size().y);
    let settings = aokit_shaders::gtao::settings::GtaoSettings::default();

    // XeGTAO's constants (XeGTAO.h, GTAOUpdateConstants) for aokit's camera: reversed Z with
    // aokit's near and far planes (its float precision keeps the round trip
    // z → ndc → `mul / (add − ndc)` within a few ulps; standard Z loses ~1e-3 relative at the
    // back of the scene), no TAA (noise index 0), one denoise pass.
    let (near, far) = (view.near, view.far);
    let (mul, add) = (-far * near / (far - near), -near / (far - near));
    let tan = view.tan_half_fov;
    let pixel = [1.0 / w as f32, 1.0 / h as f32];
    let ndc_mul = [2.0 * tan.x, -2.0 * tan.y];
    let constants = GtaoConstants {
        viewport_size: [w as i32, h as i32],
        viewport_pixel_size: pixel,
        depth_unpack_consts: [mul, add],
        camera_tan_half_fov: [tan.x, tan.y],
        ndc_to_view_mul: ndc_mul,
        ndc_to_view_add: [-tan.x, tan.y],
        ndc_to_view_mul_x_pixel_size: [ndc_mul[0] * pixel[0], ndc_mul[1] * pixel[1]],
        effect_radius: frame.radius,
        effect_falloff_range: settings.falloff_range,
        radius_multiplier: settings.radius_multiplier,
        padding0: 0.0,
        final_value_power: settings.final_value_power,
        denoise_blur_beta: 1.2,
        sample_distribution_power: settings.sample_distribution_power,
        thin_occluder_compensation: settings.thin_occluder_compensation,
        depth_mip_sampling_offset: settings.depth_mip_sampling_offset,
        noise_index: 0,
    };
    if settings.denoise_passes != 1 {
        return Err("aokit's gtao default has changed from one denoise pass: match XeGTAO's entry points".into());
    }
    // The same G-buffer for both: NDC depth with XeGTAO's unpack constants; 11:11:10 normals.
    let ndc: Vec<f32> = gbuffer.depth.iter().map(|&z| add - mul / z.min(far)).collect();

    let peer = Xegtao::new(&gpu, &spirv, w, h, &constants, &ndc, &gbuffer.normals).map_err(|e| e.to_string())?;
    let depth = gpu.upload(&gbuffer.depth, vk::BufferUsageFlags::STORAGE_BUFFER).map_err(|e| e.to_string())?;
    let normals = gpu.upload(&gbuffer.normals, vk::BufferUsageFlags::STORAGE_BUFFER).map_err(|e| e.to_string())?;
    let inputs = GpuInputs { depth: &depth, normals: &normals, second_depth: None, scene: None, raster: None };
    let mut ctx = AoContext::new(gpu.clone());

    let mut rows: Vec<Row> = PASSES
        .iter()
        .chain(&["total"])
        .map(|p| Row { name: p.to_string(), aokit_ms: Vec::new(), peer_ms: Vec::new() })
        .collect();
    let mut aokit_passes = Vec::new();
    let total = args.frame.warmup + args.frame.iterations;
    for k in 0..total {
        let aokit_first = k % 2 == 0;
        let mut times = [[0.0; 4]; 2];
        for side in 0..2 {
            let run_aokit = (side == 0) == aokit_first;
            if run_aokit {
                let cmd = gpu.begin_one_shot().map_err(|e| e.to_string())?;
                let recorded = ctx.record(cmd, &graph, &inputs);
                gpu.finish_one_shot(cmd, recorded.is_ok()).map_err(|e| e.to_string())?;
                recorded.map_err(|e| e.to_string())?;
                let passes = ctx.pass_times().map_err(|e| e.to_string())?;
                times[0] = group_aokit(&passes)?;
                aokit_passes = passes;
            } else {
                times[1] = peer.frame(&gpu).map_err(|e| e.to_string())?;
            }
        }
        if k >= args.frame.warmup {
            for (i, row) in rows.iter_mut().enumerate() {
                row.aokit_ms.push(times[0][i]);
                row.peer_ms.push(times[1][i]);
            }
        }
        eprintln!(
            "iteration {}/{total}: aokit {:.2} ms, XeGTAO {:.2} ms{}",
            k + 1,
            times[0][3],
            times[1][3],
            if k < args.frame.warmup { " (warm-up)" } else { "" }
        );
    }

    // Image agreement: aokit's final AO against XeGTAO's final term (8-bit UNORM visibility),
    // over the surfaces (the sky has no AO in either) and over every pixel.
    let ours: Vec<f32> = ctx.download::<f32>(graph.output).map_err(|e| e.to_string())?;
    let theirs = peer.download_final(&gpu).map_err(|e| e.to_string())?;
    if let Some(dir) = &args.frame.images {
        common::write_images(dir, w, h, &ours, &theirs)?;
    }
    let surface = |i: usize| gbuffer.depth[i] < far;
    let every = |_: usize| true;
    let agreement = serde_json::json!({
        "surfaces": common::agreement(&ours, &theirs, surface, 1.0 / 255.0),
        "every_pixel": common::agreement(&ours, &theirs, every, 1.0 / 255.0),
    });
    peer.destroy(&gpu);
    gpu.free_buffer(depth);
    gpu.free_buffer(normals);
    drop(ctx);

    let report = serde_json::json!({
        "peer": "XeGTAO (GameTechDev/XeGTAO) HLSL compiled to SPIR-V: CSPrefilterDepths16x16, CSGTAOHigh, CSDenoiseLastPass",
        "device": gpu.info().name,
        "scene": args.frame.scene,
        "width": w,
        "height": h,
        "iterations": args.frame.iterations,
        "aokit": technique.name(),
        "aokit_passes": aokit_passes.iter().map(|(n, ms)| serde_json::json!({"name": n, "ms": ms})).collect::<Vec<_>>(),
        "passes": rows.iter().map(Row::json).collect::<Vec<_>>(),
        "agreement": agreement,
    });
    common::finish(report, args.frame.json.as_ref())
}

/// aokit's gtao passes summed into XeGTAO's three (prefilter: the MIP levels; main; denoise)
/// and the total, in ms. Fails on a pass it cannot place, so a renamed pass is not dropped.
fn group_aokit(passes: &[(&'static str, f64)]) -> Result<[f64; 4], String> {
    let mut out = [0.0; 4];
    for &(name, ms) in passes {
        let i = if name.contains("prefilter") || name.contains("mip") {
            0
        } else if name.contains("main") {
            1
        } else if name.contains("denoise") {
            2
        } else {
            return Err(format!("aokit's gtao has a pass '{name}' that maps to none of XeGTAO's"));
        };
        out[i] += ms;
        out[3] += ms;
    }
    Ok(out)
}

/// An image with its memory and views: `views[0]` sees every MIP level, `views[1 + m]` level m.
struct Image {
    raw: vk::Image,
    memory: vk::DeviceMemory,
    views: Vec<vk::ImageView>,
}

/// XeGTAO's resources and pipelines on the device.
struct Xegtao {
    images: Vec<Image>,
    sampler: vk::Sampler,
    constants: Buffer,
    set_layouts: Vec<vk::DescriptorSetLayout>,
    layouts: Vec<vk::PipelineLayout>,
    pipelines: Vec<vk::Pipeline>,
    pool: vk::DescriptorPool,
    sets: Vec<vk::DescriptorSet>,
    queries: vk::QueryPool,
    size: (u32, u32),
}

// Indices into `Xegtao::images`.
const RAW_DEPTH: usize = 0;
const WORKING_DEPTH: usize = 1;
const NORMALS: usize = 2;
const AO_TERM: usize = 3;
const EDGES: usize = 4;
const FINAL: usize = 5;

impl Xegtao {
    fn new(
        gpu: &Gpu,
        spirv: &[Vec<u8>],
        w: u32,
        h: u32,
        constants: &GtaoConstants,
        ndc: &[f32],
        normals: &[u32],
    ) -> Result<Xegtao, GpuError> {
        let d = gpu.device();
        let ext = gpu.external();
        let memory_types = unsafe { ext.instance.get_physical_device_memory_properties(ext.physical_device) };
        use vk::ImageUsageFlags as U;
        let storage_sampled = U::STORAGE | U::SAMPLED;
        let specs = [
            (vk::Format::R32_SFLOAT, 1, U::SAMPLED | U::TRANSFER_DST),
            (vk::Format::R32_SFLOAT, MIPS, storage_sampled),
            (vk::Format::R32_UINT, 1, U::SAMPLED | U::TRANSFER_DST),
            (vk::Format::R8_UINT, 1, storage_sampled),
            (vk::Format::R8_UNORM, 1, storage_sampled),
            (vk::Format::R8_UINT, 1, U::STORAGE | U::TRANSFER_SRC),
        ];
        let mut images = Vec::new();
        for (format, mips, usage) in specs {
            images.push(make_image(d, &memory_types, format, w, h, mips, usage)?);
        }
        let sampler_info = vk::SamplerCreateInfo::default()
            .mag_filter(vk::Filter::NEAREST)
            .min_filter(vk::Filter::NEAREST)
            .mipmap_mode(vk::SamplerMipmapMode::NEAREST)
            .address_mode_u(vk::SamplerAddressMode::CLAMP_TO_EDGE)
            .address_mode_v(vk::SamplerAddressMode::CLAMP_TO_EDGE)
            .address_mode_w(vk::SamplerAddressMode::CLAMP_TO_EDGE)
            .max_lod(vk::LOD_CLAMP_NONE);
        let sampler = unsafe { d.create_sampler(&sampler_info, None)? };
        let constants = gpu.upload(std::slice::from_ref(constants), vk::BufferUsageFlags::UNIFORM_BUFFER)?;

        // Per entry point: binding 0 the constants, 1 the sampler, then its images in binding
        // order (sampled, then storage), as bench/peers/README.md lists them.
        use vk::DescriptorType as T;
        let bindings: [Vec<(T, usize, usize)>; 3] = [
            // (type, image, view)
            std::iter::once((T::SAMPLED_IMAGE, RAW_DEPTH, 0))
                .chain((0..MIPS as usize).map(|m| (T::STORAGE_IMAGE, WORKING_DEPTH, 1 + m)))
                .collect(),
            vec![
                (T::SAMPLED_IMAGE, WORKING_DEPTH, 0),
                (T::SAMPLED_IMAGE, NORMALS, 0),
                (T::STORAGE_IMAGE, AO_TERM, 0),
                (T::STORAGE_IMAGE, EDGES, 0),
            ],
            vec![(T::SAMPLED_IMAGE, AO_TERM, 0), (T::SAMPLED_IMAGE, EDGES, 0), (T::STORAGE_IMAGE, FINAL, 0)],
        ];
        let sizes = [
            vk::DescriptorPoolSize { ty: T::UNIFORM_BUFFER, descriptor_count: 3 },
            vk::DescriptorPoolSize { ty: T::SAMPLER, descriptor_count: 3 },
            vk::DescriptorPoolSize { ty: T::SAMPLED_IMAGE, descriptor_count: 8 },
            vk::DescriptorPoolSize { ty: T::STORAGE_IMAGE, descriptor_count: 8 },
        ];
        let pool = unsafe {
            d.create_descriptor_pool(&vk::DescriptorPoolCreateInfo::default().max_sets(3).pool_sizes(&sizes), None)?
        };
        let (mut set_layouts, mut layouts, mut pipelines, mut sets) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for (pass, images_of) in bindings.iter().enumerate() {
            let stage = vk::ShaderStageFlags::COMPUTE;
            let types: Vec<T> =
                [T::UNIFORM_BUFFER, T::SAMPLER].into_iter().chain(images_of.iter().map(|b| b.0)).collect();
            let layout_bindings: Vec<_> = types
                .iter()
                .enumerate()
                .map(|(i, &ty)| {
                    vk::DescriptorSetLayoutBinding::default()
                        .binding(i as u32)
                        .descriptor_type(ty)
                        .descriptor_count(1)
                        .stage_flags(stage)
                })
                .collect();
            let set_layout = unsafe {
                d.create_descriptor_set_layout(
                    &vk::DescriptorSetLayoutCreateInfo::default().bindings(&layout_bindings),
                    None,
                )?
            };
            set_layouts.push(set_layout);
            let layout = unsafe {
                d.create_pipeline_layout(
                    &vk::PipelineLayoutCreateInfo::default().set_layouts(std::slice::from_ref(&set_layout)),
                    None,
                )?
            };
            layouts.push(layout);
            let words = ash::util::read_spv(&mut std::io::Cursor::new(&spirv[pass]))
                .map_err(|e| GpuError::Input(format!("{}.spv is not SPIR-V: {e}", ENTRIES[pass])))?;
            let module = unsafe { d.create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&words), None)? };
            let stage_info = vk::PipelineShaderStageCreateInfo::default().stage(stage).module(module).name(c"main");
            let info = vk::ComputePipelineCreateInfo::default().stage(stage_info).layout(layout);
            let made = unsafe { d.create_compute_pipelines(vk::PipelineCache::null(), &[info], None) };
            unsafe { d.destroy_shader_module(module, None) };
            pipelines.push(made.map_err(|(_, e)| e)?[0]);
            let set = unsafe {
                d.allocate_descriptor_sets(
                    &vk::DescriptorSetAllocateInfo::default()
                        .descriptor_pool(pool)
                        .set_layouts(std::slice::from_ref(&set_layout)),
                )?
            }[0];
            sets.push(set);
            let buffer = [vk::DescriptorBufferInfo { buffer: constants.raw, offset: 0, range: vk::WHOLE_SIZE }];
            let sampler_info = [vk::DescriptorImageInfo { sampler, ..Default::default() }];
            let image_infos: Vec<[vk::DescriptorImageInfo; 1]> = images_of
                .iter()
                .map(|&(_, image, view)| {
                    [vk::DescriptorImageInfo {
                        sampler: vk::Sampler::null(),
                        image_view: images[image].views[view],
                        image_layout: vk::ImageLayout::GENERAL,
                    }]
                })
                .collect();
            let mut writes = vec![
                vk::WriteDescriptorSet::default()
                    .dst_set(set)
                    .dst_binding(0)
                    .descriptor_type(T::UNIFORM_BUFFER)
                    .buffer_info(&buffer),
                vk::WriteDescriptorSet::default()
                    .dst_set(set)
                    .dst_binding(1)
                    .descriptor_type(T::SAMPLER)
                    .image_info(&sampler_info),
            ];
            for (i, info) in image_infos.iter().enumerate() {
                writes.push(
                    vk::WriteDescriptorSet::default()
                        .dst_set(set)
                        .dst_binding(2 + i as u32)
                        .descriptor_type(images_of[i].0)
                        .image_info(info),
                );
            }
            unsafe { d.update_descriptor_sets(&writes, &[]) };
        }
        let queries = unsafe {
            d.create_query_pool(
                &vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(4),
                None,
            )?
        };
        let peer =
            Xegtao { images, sampler, constants, set_layouts, layouts, pipelines, pool, sets, queries, size: (w, h) };
        peer.upload(gpu, ndc, normals)?;
        Ok(peer)
    }

    /// Copy the depth and normals in and move every image to `GENERAL`, where the passes use it.
    fn upload(&self, gpu: &Gpu, ndc: &[f32], normals: &[u32]) -> Result<(), GpuError> {
        let d = gpu.device();
        let staging = [
            gpu.upload(ndc, vk::BufferUsageFlags::TRANSFER_SRC)?,
            gpu.upload(normals, vk::BufferUsageFlags::TRANSFER_SRC)?,
        ];
        let cmd = gpu.begin_one_shot()?;
        let barrier = |image: &Image, old, new| {
            let range = vk::ImageSubresourceRange::default()
                .aspect_mask(vk::ImageAspectFlags::COLOR)
                .level_count(vk::REMAINING_MIP_LEVELS)
                .layer_count(1);
            vk::ImageMemoryBarrier::default()
                .image(image.raw)
                .old_layout(old)
                .new_layout(new)
                .subresource_range(range)
                .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
                .dst_access_mask(
                    vk::AccessFlags::TRANSFER_WRITE | vk::AccessFlags::SHADER_READ | vk::AccessFlags::SHADER_WRITE,
                )
        };
        let (u, dst, general) =
            (vk::ImageLayout::UNDEFINED, vk::ImageLayout::TRANSFER_DST_OPTIMAL, vk::ImageLayout::GENERAL);
        let to_dst = [barrier(&self.images[RAW_DEPTH], u, dst), barrier(&self.images[NORMALS], u, dst)];
        let s = vk::PipelineStageFlags::ALL_COMMANDS;
        unsafe { d.cmd_pipeline_barrier(cmd, s, s, vk::DependencyFlags::empty(), &[], &[], &to_dst) };
        let region = vk::BufferImageCopy::default()
            .image_subresource(
                vk::ImageSubresourceLayers::default().aspect_mask(vk::ImageAspectFlags::COLOR).layer_count(1),
            )
            .image_extent(vk::Extent3D { width: self.size.0, height: self.size.1, depth: 1 });
        unsafe {
            d.cmd_copy_buffer_to_image(cmd, staging[0].raw, self.images[RAW_DEPTH].raw, dst, &[region]);
            d.cmd_copy_buffer_to_image(cmd, staging[1].raw, self.images[NORMALS].raw, dst, &[region]);
        }
        let to_general: Vec<_> = self
            .images
            .iter()
            .enumerate()
            .map(|(i, image)| barrier(image, if i == RAW_DEPTH || i == NORMALS { dst } else { u }, general))
            .collect();
        unsafe { d.cmd_pipeline_barrier(cmd, s, s, vk::DependencyFlags::empty(), &[], &[], &to_general) };
        let done = gpu.finish_one_shot(cmd, true);
        for b in staging {
            gpu.free_buffer(b);
        }
        done.map(|_| ())
    }

    /// One frame of the three passes; returns their GPU times and the total in ms.
    fn frame(&self, gpu: &Gpu) -> Result<[f64; 4], GpuError> {
        let d = gpu.device();
        let (w, h) = self.size;
        // XeGTAO's dispatch sizes: 16×16 pixels per prefilter group, 8×8 per main group, 16×8 per
        // denoise group (two horizontal pixels a thread).
        let groups =
            [(w.div_ceil(16), h.div_ceil(16)), (w.div_ceil(8), h.div_ceil(8)), (w.div_ceil(16), h.div_ceil(8))];
        let cmd = gpu.begin_one_shot()?;
        let stage = vk::PipelineStageFlags::COMPUTE_SHADER;
        unsafe {
            d.cmd_reset_query_pool(cmd, self.queries, 0, 4);
            d.cmd_write_timestamp(cmd, vk::PipelineStageFlags::TOP_OF_PIPE, self.queries, 0);
            for (pass, &(gx, gy)) in groups.iter().enumerate() {
                if pass > 0 {
                    let barrier = vk::MemoryBarrier::default()
                        .src_access_mask(vk::AccessFlags::SHADER_WRITE)
                        .dst_access_mask(vk::AccessFlags::SHADER_READ);
                    d.cmd_pipeline_barrier(cmd, stage, stage, vk::DependencyFlags::empty(), &[barrier], &[], &[]);
                }
                d.cmd_bind_pipeline(cmd, vk::PipelineBindPoint::COMPUTE, self.pipelines[pass]);
                let sets = [self.sets[pass]];
                d.cmd_bind_descriptor_sets(cmd, vk::PipelineBindPoint::COMPUTE, self.layouts[pass], 0, &sets, &[]);
                d.cmd_dispatch(cmd, gx, gy, 1);
                d.cmd_write_timestamp(cmd, stage, self.queries, 1 + pass as u32);
            }
        }
        gpu.finish_one_shot(cmd, true)?;
        let t = gpu.timestamps_ms(self.queries, 4)?;
        Ok([t[1] - t[0], t[2] - t[1], t[3] - t[2], t[3] - t[0]])
    }

    /// The final AO term as visibility in [0, 1] (XeGTAO stores `visibility·255 + ½` as R8_UINT).
    fn download_final(&self, gpu: &Gpu) -> Result<Vec<f32>, GpuError> {
        let (w, h) = self.size;
        let d = gpu.device();
        let readback = gpu.upload(&vec![0u8; (w * h) as usize], vk::BufferUsageFlags::TRANSFER_DST)?;
        let cmd = gpu.begin_one_shot()?;
        let barrier = vk::MemoryBarrier::default()
            .src_access_mask(vk::AccessFlags::SHADER_WRITE)
            .dst_access_mask(vk::AccessFlags::TRANSFER_READ);
        let region = vk::BufferImageCopy::default()
            .image_subresource(
                vk::ImageSubresourceLayers::default().aspect_mask(vk::ImageAspectFlags::COLOR).layer_count(1),
            )
            .image_extent(vk::Extent3D { width: w, height: h, depth: 1 });
        unsafe {
            let (c, t) = (vk::PipelineStageFlags::COMPUTE_SHADER, vk::PipelineStageFlags::TRANSFER);
            d.cmd_pipeline_barrier(cmd, c, t, vk::DependencyFlags::empty(), &[barrier], &[], &[]);
            let general = vk::ImageLayout::GENERAL;
            d.cmd_copy_image_to_buffer(cmd, self.images[FINAL].raw, general, readback.raw, &[region]);
        }
        gpu.finish_one_shot(cmd, true)?;
        let bytes: Vec<u8> = gpu.download(&readback)?;
        gpu.free_buffer(readback);
        Ok(bytes.iter().map(|&b| b as f32 / 255.0).collect())
    }

    fn destroy(self, gpu: &Gpu) {
        let d = gpu.device();
        unsafe {
            let _ = d.device_wait_idle();
            d.destroy_query_pool(self.queries, None);
            d.destroy_descriptor_pool(self.pool, None);
            for p in self.pipelines {
                d.destroy_pipeline(p, None);
            }
            for l in self.layouts {
                d.destroy_pipeline_layout(l, None);
            }
            for l in self.set_layouts {
                d.destroy_descriptor_set_layout(l, None);
            }
            d.destroy_sampler(self.sampler, None);
            for image in self.images {
                for v in image.views {
                    d.destroy_image_view(v, None);
                }
                d.destroy_image(image.raw, None);
                d.free_memory(image.memory, None);
            }
        }
        gpu.free_buffer(self.constants);
    }
}

/// A device-local 2D image with `mips` levels, its memory and views.
fn make_image(
    d: &ash::Device,
    memory_types: &vk::PhysicalDeviceMemoryProperties,
    format: vk::Format,
    w: u32,
    h: u32,
    mips: u32,
    usage: vk::ImageUsageFlags,
) -> Result<Image, GpuError> {
    let info = vk::ImageCreateInfo::default()
        .image_type(vk::ImageType::TYPE_2D)
        .format(format)
        .extent(vk::Extent3D { width: w, height: h, depth: 1 })
        .mip_levels(mips)
        .array_layers(1)
        .samples(vk::SampleCountFlags::TYPE_1)
        .tiling(vk::ImageTiling::OPTIMAL)
        .usage(usage)
        .initial_layout(vk::ImageLayout::UNDEFINED);
    let raw = unsafe { d.create_image(&info, None)? };
    let req = unsafe { d.get_image_memory_requirements(raw) };
    let index = (0..memory_types.memory_type_count)
        .find(|&i| {
            req.memory_type_bits & (1 << i) != 0
                && memory_types.memory_types[i as usize].property_flags.contains(vk::MemoryPropertyFlags::DEVICE_LOCAL)
        })
        .ok_or_else(|| GpuError::Input(format!("no device-local memory for a {format:?} image")))?;
    let memory = unsafe {
        d.allocate_memory(&vk::MemoryAllocateInfo::default().allocation_size(req.size).memory_type_index(index), None)?
    };
    unsafe { d.bind_image_memory(raw, memory, 0)? };
    let view = |base: u32, count: u32| {
        let range = vk::ImageSubresourceRange::default()
            .aspect_mask(vk::ImageAspectFlags::COLOR)
            .base_mip_level(base)
            .level_count(count)
            .layer_count(1);
        let info = vk::ImageViewCreateInfo::default()
            .image(raw)
            .view_type(vk::ImageViewType::TYPE_2D)
            .format(format)
            .subresource_range(range);
        unsafe { d.create_image_view(&info, None) }
    };
    let mut views = vec![view(0, mips)?];
    if mips > 1 {
        for m in 0..mips {
            views.push(view(m, 1)?);
        }
    }
    Ok(Image { raw, memory, views })
}
