//! The VAO pipeline on either back-end: G-buffer → VAO → bilateral blur.

use crate::frame::Frame;
use crate::scene::Scene;
use crate::technique::{GtaoOptions, RaymarchOptions, SdOptions, SvaoDebug, Technique, TechniqueRun};
use aokit_cpu::svao as svao_cpu;
use aokit_cpu::{GBufferImage, Progress, SceneBvh, Surfaces};
use aokit_shaders::common::alpha::AlphaMaskHeader;
use aokit_shaders::gbuffer::RasterParams;
use aokit_shaders::groundtruth::{GroundTruthFrame, GroundTruthParams};
use aokit_shaders::svao::{Secondary, SvaoFrame};
use aokit_vulkan::{
    Buffer, GBufferVertex, Gpu, GpuError, GpuOptions, GroundTruthPipeline, GtaoOutput, GtaoPasses, RasterGBuffer,
    RasterSdInput, RasterSdPass, SceneAccel, ScreenPasses, ScreenRayOutput, SsaoPipelines, SvaoPipelines,
};
use std::time::Instant;

/// `(pass, milliseconds)` per pass.
pub type PassTimes = Vec<(&'static str, f64)>;

/// Result of one render: the G-buffer it used, AO before and after the blur (full target,
/// guard band = 1), and time per pass.
pub struct Render {
    pub gbuffer: GBufferImage,
    pub ao: Vec<f32>,
    pub ao_blurred: Vec<f32>,
    /// `(pass, milliseconds)`: wall clock on the CPU, timestamp queries on Vulkan.
    pub passes: PassTimes,
}

impl Render {
    /// A render without a blur pass (the ground truth): both AO fields hold `ao`.
    pub fn unblurred(gbuffer: GBufferImage, ao: Vec<f32>, passes: PassTimes) -> Render {
        Render { gbuffer, ao_blurred: ao.clone(), ao, passes }
    }
}

fn ms_since(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// The CPU back-end: ray-cast G-buffer through a BVH, then the kernels over slices.
pub struct CpuRenderer {
    bvh: SceneBvh,
    face_normals: Vec<aokit_shaders::glam::Vec3>,
    uvs: Vec<[aokit_shaders::glam::Vec2; 3]>,
    materials: Vec<u32>,
    masks: (Vec<AlphaMaskHeader>, Vec<f32>),
    pub bvh_build_ms: f64,
}

impl CpuRenderer {
    pub fn new(scene: &Scene) -> Self {
        let t = Instant::now();
        let bvh = SceneBvh::build(&scene.triangles);
        CpuRenderer {
            bvh,
            face_normals: scene.face_normals(),
            uvs: scene.triangle_uvs.clone(),
            materials: scene.triangle_materials.clone(),
            masks: scene.alpha_masks(),
            bvh_build_ms: ms_since(t),
        }
    }

    /// One primary ray per pixel of the full target.
    pub fn gbuffer(&self, frame: &Frame, progress: Progress) -> (GBufferImage, f64) {
        let t = Instant::now();
        let g = aokit_cpu::ray_cast_gbuffer(&self.bvh, &self.surfaces(), &frame.camera, progress);
        (g, ms_since(t))
    }

    /// Ground-truth AO (spec gtao-raymarch-hybrid §5) on a given G-buffer.
    pub fn ground_truth(
        &self,
        frame: &Frame,
        gbuffer: &GBufferImage,
        params: &GroundTruthParams,
        progress: Progress,
    ) -> (Vec<f32>, f64) {
        let t = Instant::now();
        let gt = GroundTruthFrame { camera: frame.camera, params: *params };
        let ao = aokit_cpu::run_ground_truth(&self.bvh, &self.surfaces(), &gt, gbuffer, progress);
        (ao, ms_since(t))
    }

    /// The scene's BVH (for tests and benches that drive the CPU kernels directly).
    pub fn bvh(&self) -> &SceneBvh {
        &self.bvh
    }

    /// Per-triangle surface data (normals, uvs, materials, alpha masks) beside the BVH.
    pub fn surfaces(&self) -> Surfaces<'_> {
        Surfaces {
            face_normals: &self.face_normals,
            uvs: &self.uvs,
            materials: &self.materials,
            mask_headers: &self.masks.0,
            mask_texels: &self.masks.1,
        }
    }

    /// VAO and blur on a given G-buffer.
    pub fn ao(frame: &Frame, gbuffer: GBufferImage, progress: Progress) -> Render {
        let t = Instant::now();
        let ao = aokit_cpu::run_vao(&frame.vao_params(), &gbuffer.depth, &gbuffer.normals, progress);
        let vao_ms = ms_since(t);
        let t = Instant::now();
        let ao_blurred = aokit_cpu::run_blur(&frame.blur_params(), &ao, &gbuffer.depth);
        let passes = vec![("vao", vao_ms), ("blur", ms_since(t))];
        Render { gbuffer, ao, ao_blurred, passes }
    }

    /// The whole pipeline.
    pub fn render(&self, frame: &Frame, progress: Progress) -> Render {
        let (gbuffer, gbuffer_ms) = self.gbuffer(frame, progress);
        let mut r = Self::ao(frame, gbuffer, progress);
        r.passes.insert(0, ("gbuffer", gbuffer_ms));
        r
    }
}

/// De-indexed triangles with their face normals, texture coordinates and materials: the raster
/// pass's vertex stream.
pub fn raster_vertices(scene: &Scene) -> Vec<GBufferVertex> {
    let normals = scene.face_normals();
    let mut out = Vec::with_capacity(3 * scene.triangles.len());
    for (i, (t, n)) in scene.triangles.iter().zip(&normals).enumerate() {
        for (v, uv) in t.iter().zip(scene.triangle_uvs[i]) {
            out.push(GBufferVertex {
                position: [v.x, v.y, v.z, 1.0],
                face_normal: [n.x, n.y, n.z, 0.0],
                uv: uv.to_array(),
                material: scene.triangle_materials[i],
                _pad: 0,
            });
        }
    }
    out
}

/// The Vulkan back-end: raster G-buffer, compute VAO and blur; ray-tracing pipelines and the
/// scene's acceleration structure are made on first use and kept.
pub struct VulkanRenderer {
    pub gpu: Gpu,
    raster: RasterGBuffer,
    screen: ScreenPasses,
    svao: std::cell::OnceCell<SvaoPipelines>,
    gtao_passes: std::cell::OnceCell<GtaoPasses>,
    ssao_pipelines: std::cell::OnceCell<SsaoPipelines>,
    raster_sd: std::cell::OnceCell<RasterSdPass>,
    /// `(scene key, acceleration structure)` of the last scene traced.
    accel: std::cell::RefCell<Option<(usize, SceneAccel)>>,
}

impl VulkanRenderer {
    pub fn new(options: &GpuOptions) -> Result<Self, GpuError> {
        let gpu = Gpu::new(options)?;
        let raster = RasterGBuffer::new(&gpu)?;
        let screen = ScreenPasses::new(&gpu)?;
        Ok(VulkanRenderer {
            gpu,
            raster,
            screen,
            svao: Default::default(),
            gtao_passes: Default::default(),
            ssao_pipelines: Default::default(),
            raster_sd: Default::default(),
            accel: Default::default(),
        })
    }

    /// Rasterize the G-buffer and read it back.
    pub fn gbuffer(&self, scene: &Scene, frame: &Frame) -> Result<(GBufferImage, f64), GpuError> {
        let ((), image, ms) = self.with_raster_gbuffer(scene, frame, |_, _| Ok(()))?;
        Ok((image, ms))
    }

    /// Rasterize the G-buffer, run `pass` on its device buffers (depth, normals), then read it
    /// back and free it. Returns the pass's result, the G-buffer and the raster time in ms.
    fn with_raster_gbuffer<R>(
        &self,
        scene: &Scene,
        frame: &Frame,
        pass: impl FnOnce(&Buffer, &Buffer) -> Result<R, GpuError>,
    ) -> Result<(R, GBufferImage, f64), GpuError> {
        let (depth, normals, ms) = self.raster.render(
            &self.gpu,
            &raster_vertices(scene),
            &scene.alpha_masks(),
            &frame.raster_params(),
            None,
        )?;
        let size = frame.camera.view.size();
        let run = || -> Result<(R, GBufferImage), GpuError> {
            let r = pass(&depth, &normals)?;
            let image = GBufferImage {
                width: size.x,
                height: size.y,
                depth: self.gpu.download(&depth)?,
                normals: self.gpu.download(&normals)?,
            };
            Ok((r, image))
        };
        let out = run();
        self.gpu.free_buffer(depth);
        self.gpu.free_buffer(normals);
        let (r, image) = out?;
        Ok((r, image, ms))
    }

    /// VAO and blur on a given G-buffer (uploaded).
    pub fn ao(&self, frame: &Frame, gbuffer: GBufferImage) -> Result<Render, GpuError> {
        let out = self.with_uploaded_gbuffer(&gbuffer, |depth, normals| {
            self.screen.run(&self.gpu, &frame.vao_params(), &frame.blur_params(), depth, normals)
        })?;
        Ok(Render { gbuffer, ao: out.ao, ao_blurred: out.ao_blurred, passes: out.pass_ms })
    }

    /// Upload a host G-buffer, run `pass` on its device buffers (depth, normals), free them.
    fn with_uploaded_gbuffer<R>(
        &self,
        gbuffer: &GBufferImage,
        pass: impl FnOnce(&Buffer, &Buffer) -> Result<R, GpuError>,
    ) -> Result<R, GpuError> {
        let usage = ash::vk::BufferUsageFlags::STORAGE_BUFFER;
        let depth = self.gpu.upload(&gbuffer.depth, usage)?;
        let out = self.gpu.upload(&gbuffer.normals, usage).and_then(|normals| {
            let r = pass(&depth, &normals);
            self.gpu.free_buffer(normals);
            r
        });
        self.gpu.free_buffer(depth);
        out
    }

    /// Ground truth by Vulkan ray tracing on a given G-buffer (uploaded). Returns the AO
    /// (full target) and `(pass, ms)` for the acceleration-structure build and the trace.
    pub fn ground_truth(
        &self,
        scene: &Scene,
        frame: &Frame,
        gbuffer: &GBufferImage,
        params: &GroundTruthParams,
    ) -> Result<(Vec<f32>, PassTimes), GpuError> {
        let pipeline = GroundTruthPipeline::new(&self.gpu)?;
        let positions: Vec<[f32; 3]> = scene.triangles.iter().flatten().map(|v| v.to_array()).collect();
        let uvs: Vec<_> = scene.triangle_uvs.iter().flatten().copied().collect();
        let accel = SceneAccel::build(&self.gpu, &positions, &uvs, &scene.triangle_materials, &scene.alpha_masks());
        let result = accel.and_then(|accel| {
            let gt = GroundTruthFrame { camera: frame.camera, params: *params };
            let traced = self
                .with_uploaded_gbuffer(gbuffer, |depth, normals| pipeline.run(&self.gpu, &accel, &gt, depth, normals));
            let build_ms = accel.build_ms;
            accel.destroy(&self.gpu);
            let (ao, ms) = traced?;
            Ok((ao, vec![("accel_build", build_ms), ("groundtruth", ms)]))
        });
        pipeline.destroy(&self.gpu);
        result
    }

    /// The whole pipeline, G-buffer kept on the device.
    pub fn render(&self, scene: &Scene, frame: &Frame) -> Result<Render, GpuError> {
        let (out, gbuffer, gbuffer_ms) = self.with_raster_gbuffer(scene, frame, |depth, normals| {
            self.screen.run(&self.gpu, &frame.vao_params(), &frame.blur_params(), depth, normals)
        })?;
        let mut passes = vec![("gbuffer", gbuffer_ms)];
        passes.extend(out.pass_ms);
        Ok(Render { gbuffer, ao: out.ao, ao_blurred: out.ao_blurred, passes })
    }
}

impl Drop for VulkanRenderer {
    fn drop(&mut self) {
        if let Some(p) = self.svao.take() {
            p.destroy(&self.gpu);
        }
        if let Some(p) = self.gtao_passes.take() {
            p.destroy(&self.gpu);
        }
        if let Some(p) = self.ssao_pipelines.take() {
            p.destroy(&self.gpu);
        }
        if let Some(p) = self.raster_sd.take() {
            p.destroy(&self.gpu);
        }
        if let Some((_, a)) = self.accel.take() {
            a.destroy(&self.gpu);
        }
        self.raster.destroy(&self.gpu);
        self.screen.destroy(&self.gpu);
    }
}

impl CpuRenderer {
    /// Run `technique` on a given G-buffer (spec svao-raysd §3 pipeline for the VAO family,
    /// blur included where the technique blurs).
    pub fn run(
        &self,
        frame: &Frame,
        gbuffer: &GBufferImage,
        technique: &Technique,
        progress: Progress,
    ) -> TechniqueRun {
        let (depth, normals) = (&gbuffer.depth[..], &gbuffer.normals[..]);
        let mut passes: PassTimes = Vec::new();
        let mut rays = 0;
        let mut refined_samples = 0;
        let mut interval_sum = None;
        let mut debug = None;
        // Run `f` and record its wall time as pass `name`.
        let mut timed = |name: &'static str, f: &mut dyn FnMut()| {
            let t = Instant::now();
            f();
            passes.push((name, ms_since(t)));
        };
        let mut ao = Vec::new();
        // Techniques that end in XeGTAO's denoiser put its output here; `ao` stays the raw AO.
        let mut denoised = None;
        // The depth-peeled second layer (spec §11) for dual-depth techniques; empty otherwise
        // (never read then).
        let mut depth2 = Vec::new();
        let (dual, separation) = match technique {
            Technique::VaoDual { peel_separation } => (true, *peel_separation),
            Technique::Hbao { dual, peel_separation } => (*dual, *peel_separation),
            Technique::RaySd(o) => (o.dual, o.peel_separation),
            Technique::RaySvao { dual, .. } => (*dual, SdOptions::default().peel_separation),
            _ => (false, 0.0),
        };
        if dual {
            timed("depth_peel", &mut || {
                depth2 =
                    aokit_cpu::ray_cast_second_layer(&self.bvh, &self.surfaces(), &frame.camera, gbuffer, separation)
            });
        }
        let depth2 = &depth2[..];
        match technique {
            Technique::Vao => {
                timed("vao", &mut || ao = aokit_cpu::run_vao(&frame.vao_params(), depth, normals, progress))
            }
            Technique::VaoDual { .. } | Technique::Hbao { .. } => {
                // Pass 1 without a secondary source finalizes every pixel.
                let hbao = matches!(technique, Technique::Hbao { .. });
                let sd = SdOptions { dual, hbao, ..Default::default() };
                let svao = frame.svao_frame(Secondary::Disabled, &sd);
                let name = if hbao { "hbao" } else { "vao" };
                timed(name, &mut || ao = svao_cpu::run_pass1(&svao.params, depth, normals, depth2, progress).ao);
            }
            Technique::GroundTruth { spp, uniform } => {
                let params = frame.ground_truth_params(*spp, *uniform);
                timed("groundtruth", &mut || ao = self.ground_truth(frame, gbuffer, &params, progress).0);
                rays = frame.inner.x as u64 * frame.inner.y as u64 * *spp as u64;
            }
            Technique::RaySd(sd) => {
                let svao = frame.svao_frame(Secondary::StochasticDepth, sd);
                let mut pass1 = None;
                timed("ao_pass1", &mut || {
                    pass1 = Some(svao_cpu::run_pass1(&svao.params, depth, normals, depth2, progress))
                });
                let pass1 = pass1.expect("pass 1 ran");
                let mut map = None;
                if sd.raster {
                    timed("sd_map_raster", &mut || {
                        map = Some(svao_cpu::run_raster_sd_map(&self.bvh, &self.surfaces(), &svao, depth, &pass1))
                    });
                } else {
                    timed("sd_map", &mut || {
                        let order = svao_cpu::HitOrder::Traversal;
                        map = Some(svao_cpu::run_sd_map(
                            &self.bvh,
                            &self.surfaces(),
                            &svao,
                            depth,
                            normals,
                            &pass1,
                            order,
                        ))
                    });
                }
                let map = map.expect("SD map made");
                timed("ao_pass2", &mut || {
                    ao = svao_cpu::run_pass2_sd(&svao.params, depth, normals, depth2, &pass1, &map)
                });
                rays = map.rays;
                if !sd.raster {
                    interval_sum =
                        Some(svao_cpu::sd_ray_stats(&svao, depth, normals, &pass1.ray_min, &pass1.ray_max).1);
                }
                refined_samples = pass1.refined_samples();
                debug = Some(SvaoDebug {
                    ao_pass1: pass1.ao,
                    mask: pass1.mask,
                    ray_min: pass1.ray_min,
                    ray_max: pass1.ray_max,
                    sd_size: svao.params.sd_size(),
                    sd_map: map.layers,
                    layers: svao.params.sd_layers,
                });
            }
            Technique::Gtao(o) => {
                let params = frame.gtao_params(o);
                let mut mips = Vec::new();
                timed("gtao_prefilter", &mut || mips = aokit_cpu::gtao::run_prefilter(&params, depth));
                let mut generated = Vec::new();
                if o.normals_from_depth {
                    timed("gtao_normals", &mut || generated = aokit_cpu::gtao::run_normals(&params, depth));
                }
                let normals = if o.normals_from_depth { &generated[..] } else { normals };
                let (mut terms, mut edges) = (Vec::new(), Vec::new());
                timed("gtao_main", &mut || (terms, edges) = aokit_cpu::gtao::run_main(&params, &mips, normals));
                timed("gtao_denoise", &mut || ao = aokit_cpu::gtao::run_denoise(&params, &terms, &edges));
            }
            Technique::Raymarch(o) => {
                let params = frame.raymarch_params(o);
                let kernel = raymarch_kernel(o);
                let (mut terms, mut edges) = (Vec::new(), Vec::new());
                timed("raymarch", &mut || {
                    (ao, terms, edges) = aokit_cpu::raymarch::run_raymarch(&params, depth, normals, &kernel)
                });
                if o.denoise_passes > 0 {
                    let dp = frame.denoise_params(o.denoise_passes);
                    timed("denoise", &mut || denoised = Some(aokit_cpu::gtao::run_denoise(&dp, &terms, &edges)));
                }
            }
            Technique::Hybrid(o) => {
                let hf = frame.hybrid_frame(o);
                let (mut terms, mut edges) = (Vec::new(), Vec::new());
                timed("hybrid_rays", &mut || {
                    (ao, terms, edges) = aokit_cpu::hybrid::run_hybrid(&self.bvh, &self.surfaces(), &hf, depth, normals)
                });
                rays = (o.screen_rays + o.world_rays) as u64 * frame.inner.x as u64 * frame.inner.y as u64;
                if o.denoise_passes > 0 {
                    let dp = frame.denoise_params(o.denoise_passes);
                    timed("denoise", &mut || denoised = Some(aokit_cpu::gtao::run_denoise(&dp, &terms, &edges)));
                }
            }
            Technique::RaySvao { cutoff, dual } => {
                let options = SdOptions { cutoff: *cutoff, dual: *dual, ..Default::default() };
                let svao = frame.svao_frame(Secondary::Raytraced, &options);
                let mut pass1 = None;
                timed("ao_pass1", &mut || {
                    pass1 = Some(svao_cpu::run_pass1(&svao.params, depth, normals, depth2, progress))
                });
                let pass1 = pass1.expect("pass 1 ran");
                timed("ao_pass2_rays", &mut || {
                    (ao, rays) =
                        svao_cpu::run_raysvao_pass2(&self.bvh, &self.surfaces(), &svao, depth, normals, depth2, &pass1)
                });
                refined_samples = pass1.refined_samples();
                debug = Some(SvaoDebug { ao_pass1: pass1.ao, mask: pass1.mask, ..Default::default() });
            }
        }
        let mut ao_final = denoised.unwrap_or_else(|| ao.clone());
        if technique.blurred() {
            timed("blur", &mut || ao_final = aokit_cpu::run_blur(&frame.blur_params(), &ao, depth));
        }
        TechniqueRun { ao, ao_final, passes, rays, refined_samples, interval_sum, debug }
    }
}

/// The Poisson-disk kernel of a ray-marched SSAO run (spec gtao-raymarch-hybrid §3.3).
fn raymarch_kernel(o: &RaymarchOptions) -> Vec<aokit_shaders::glam::Vec2> {
    let n = o.directions as usize;
    if o.vogel { aokit_shaders::raymarch::kernel::vogel(n) } else { aokit_shaders::raymarch::kernel::best_candidate(n) }
}

/// The pipelines in `cell`, made with `make` on first use.
fn pipeline<T>(cell: &std::cell::OnceCell<T>, make: impl FnOnce() -> Result<T, GpuError>) -> Result<&T, GpuError> {
    if let Some(p) = cell.get() {
        return Ok(p);
    }
    let p = make()?;
    Ok(cell.get_or_init(|| p))
}

/// Identity of a loaded scene for the acceleration-structure cache.
fn scene_key(scene: &Scene) -> usize {
    scene.triangles.as_ptr() as usize ^ scene.triangles.len().rotate_left(32)
}

impl VulkanRenderer {
    /// Run `f` with the scene's acceleration structure, built on first use. Returns the build
    /// time in ms when it was built now.
    fn with_accel<R>(
        &self,
        scene: &Scene,
        f: impl FnOnce(&SceneAccel) -> Result<R, GpuError>,
    ) -> Result<(R, Option<f64>), GpuError> {
        let key = scene_key(scene);
        let mut cache = self.accel.borrow_mut();
        let mut built = None;
        if cache.as_ref().is_none_or(|(k, _)| *k != key) {
            if let Some((_, old)) = cache.take() {
                old.destroy(&self.gpu);
            }
            let positions: Vec<[f32; 3]> = scene.triangles.iter().flatten().map(|v| v.to_array()).collect();
            let uvs: Vec<_> = scene.triangle_uvs.iter().flatten().copied().collect();
            let accel =
                SceneAccel::build(&self.gpu, &positions, &uvs, &scene.triangle_materials, &scene.alpha_masks())?;
            built = Some(accel.build_ms);
            *cache = Some((key, accel));
        }
        let (_, accel) = cache.as_ref().expect("built above");
        Ok((f(accel)?, built))
    }

    /// Run `technique` on a given G-buffer (uploaded).
    pub fn run(
        &self,
        scene: &Scene,
        frame: &Frame,
        gbuffer: &GBufferImage,
        technique: &Technique,
    ) -> Result<TechniqueRun, GpuError> {
        match technique {
            Technique::Vao => {
                let r = self.ao(frame, gbuffer.clone())?;
                Ok(TechniqueRun::plain(r.ao, r.ao_blurred, r.passes))
            }
            Technique::Gtao(o) => {
                let out = self.gtao(frame, gbuffer, o)?;
                Ok(TechniqueRun::plain(out.ao.clone(), out.ao, out.pass_ms))
            }
            Technique::Raymarch(o) => {
                let ssao = self.ssao()?;
                let params = frame.raymarch_params(o);
                let out = self.with_uploaded_gbuffer(gbuffer, |depth, normals| {
                    ssao.raymarch(&self.gpu, &params, depth, normals, &raymarch_kernel(o))
                })?;
                self.finish_screen_rays(frame, out, "raymarch", o.denoise_passes, 0)
            }
            Technique::Hybrid(o) => {
                let ssao = self.ssao()?;
                let hf = frame.hybrid_frame(o);
                let (out, built) = self.with_accel(scene, |accel| {
                    self.with_uploaded_gbuffer(gbuffer, |depth, normals| {
                        ssao.hybrid(&self.gpu, accel, &hf, depth, normals)
                    })
                })?;
                let rays = (o.screen_rays + o.world_rays) as u64 * frame.inner.x as u64 * frame.inner.y as u64;
                let mut run = self.finish_screen_rays(frame, out, "hybrid_rays", o.denoise_passes, rays)?;
                if let Some(ms) = built {
                    run.passes.insert(0, ("accel_build", ms));
                }
                Ok(run)
            }
            Technique::GroundTruth { spp, uniform } => {
                let (ao, passes) =
                    self.ground_truth(scene, frame, gbuffer, &frame.ground_truth_params(*spp, *uniform))?;
                let rays = frame.inner.x as u64 * frame.inner.y as u64 * *spp as u64;
                Ok(TechniqueRun {
                    ao: ao.clone(),
                    ao_final: ao,
                    passes,
                    rays,
                    refined_samples: 0,
                    interval_sum: None,
                    debug: None,
                })
            }
            Technique::RaySd(sd) => {
                let svao = frame.svao_frame(Secondary::StochasticDepth, sd);
                self.run_svao(scene, frame, gbuffer, &svao, sd.raster)
            }
            Technique::RaySvao { cutoff, dual } => {
                let options = SdOptions { cutoff: *cutoff, dual: *dual, ..Default::default() };
                self.run_svao(scene, frame, gbuffer, &frame.svao_frame(Secondary::Raytraced, &options), false)
            }
            Technique::VaoDual { .. } => {
                let options = SdOptions { dual: true, ..Default::default() };
                self.run_svao(scene, frame, gbuffer, &frame.svao_frame(Secondary::Disabled, &options), false)
            }
            Technique::Hbao { dual, .. } => {
                let options = SdOptions { dual: *dual, hbao: true, ..Default::default() };
                self.run_svao(scene, frame, gbuffer, &frame.svao_frame(Secondary::Disabled, &options), false)
            }
        }
    }

    /// The ray-marched SSAO and hybrid pipelines, made on first use.
    fn ssao(&self) -> Result<&SsaoPipelines, GpuError> {
        pipeline(&self.ssao_pipelines, || SsaoPipelines::new(&self.gpu))
    }

    /// The XeGTAO passes, made on first use.
    fn gtao_passes(&self) -> Result<&GtaoPasses, GpuError> {
        pipeline(&self.gtao_passes, || GtaoPasses::new(&self.gpu))
    }

    /// A screen-ray technique's output, through XeGTAO's denoiser when `passes > 0`.
    fn finish_screen_rays(
        &self,
        frame: &Frame,
        out: ScreenRayOutput,
        pass: &'static str,
        passes: u32,
        rays: u64,
    ) -> Result<TechniqueRun, GpuError> {
        let mut times = vec![(pass, out.ms)];
        let mut ao_final = out.ao.clone();
        if passes > 0 {
            let (denoised, ms) =
                self.gtao_passes()?.denoise(&self.gpu, &frame.denoise_params(passes), &out.terms, &out.edges)?;
            times.push(("denoise", ms));
            ao_final = denoised;
        }
        let mut run = TechniqueRun::plain(out.ao, ao_final, times);
        run.rays = rays;
        Ok(run)
    }

    /// Run `f` with the raster SD pass's inputs uploaded (scene vertices, alpha masks), or with
    /// `None` when `pass` is `None`.
    fn with_raster_input<R>(
        &self,
        scene: &Scene,
        frame: &Frame,
        pass: Option<&RasterSdPass>,
        f: impl FnOnce(Option<RasterSdInput>) -> Result<R, GpuError>,
    ) -> Result<R, GpuError> {
        let Some(pass) = pass else { return f(None) };
        let vertices = raster_vertices(scene);
        let masks = scene.alpha_masks();
        let storage = ash::vk::BufferUsageFlags::STORAGE_BUFFER;
        let mut owned = Vec::new();
        let result = (|| {
            owned.push(self.gpu.upload(&vertices, ash::vk::BufferUsageFlags::VERTEX_BUFFER)?);
            owned.push(self.gpu.upload(&masks.0, storage)?);
            owned.push(self.gpu.upload(&masks.1, storage)?);
            f(Some(RasterSdInput {
                pass,
                vertices: &owned[0],
                count: vertices.len() as u32,
                params: frame.raster_params(),
                headers: &owned[1],
                texels: &owned[2],
            }))
        })();
        for b in owned {
            self.gpu.free_buffer(b);
        }
        result
    }

    /// XeGTAO's passes on a given G-buffer (uploaded), with every intermediate buffer.
    pub fn gtao(&self, frame: &Frame, gbuffer: &GBufferImage, options: &GtaoOptions) -> Result<GtaoOutput, GpuError> {
        let passes = self.gtao_passes()?;
        let params = frame.gtao_params(options);
        self.with_uploaded_gbuffer(gbuffer, |depth, normals| {
            passes.run(&self.gpu, &params, depth, (!options.normals_from_depth).then_some(normals))
        })
    }

    /// The stenciled pipeline on Vulkan; `raster_sd`: the SD map from the raster coverage-mask
    /// pass instead of ray tracing.
    fn run_svao(
        &self,
        scene: &Scene,
        frame: &Frame,
        gbuffer: &GBufferImage,
        svao: &SvaoFrame,
        raster_sd: bool,
    ) -> Result<TechniqueRun, GpuError> {
        let pipelines = pipeline(&self.svao, || SvaoPipelines::new(&self.gpu))?;
        let params = &svao.params;
        let traced = params.secondary != Secondary::Disabled as u32 && !raster_sd;
        let raster_pass =
            if raster_sd { Some(pipeline(&self.raster_sd, || RasterSdPass::new(&self.gpu))?) } else { None };
        let separation = SdOptions::default().peel_separation;
        // Pass 1 (and pass 2) on the uploaded G-buffer, with the depth-peeled second layer
        // rasterized against it when dual depth is on. Returns the second layer too.
        let passes_on = |accel: Option<&SceneAccel>| {
            self.with_uploaded_gbuffer(gbuffer, |depth, normals| {
                let peeled = if params.dual != 0 {
                    let raster = RasterParams { peel_separation: separation, ..frame.raster_params() };
                    let (d2, n2, ms) = self.raster.render(
                        &self.gpu,
                        &raster_vertices(scene),
                        &scene.alpha_masks(),
                        &raster,
                        Some(depth),
                    )?;
                    self.gpu.free_buffer(n2);
                    Some((d2, ms))
                } else {
                    None
                };
                let depth2 = peeled.as_ref().map_or(depth, |(d2, _)| d2);
                let run = self.with_raster_input(scene, frame, raster_pass, |raster| {
                    let out = pipelines.run(&self.gpu, accel, svao, [depth, normals, depth2], raster)?;
                    let blurred = self.screen.blur(&self.gpu, &frame.blur_params(), &out.ao, depth)?;
                    Ok((out, blurred))
                });
                let second = match peeled {
                    Some((d2, ms)) => {
                        let host = self.gpu.download::<f32>(&d2);
                        self.gpu.free_buffer(d2);
                        Some((host?, ms))
                    }
                    None => None,
                };
                run.map(|(out, blurred)| (out, blurred, second))
            })
        };
        let ((out, blurred, second), built) =
            if traced { self.with_accel(scene, |accel| passes_on(Some(accel)))? } else { (passes_on(None)?, None) };
        let mut passes = Vec::new();
        if let Some(ms) = built {
            passes.push(("accel_build", ms));
        }
        if let Some((_, ms)) = &second {
            passes.push(("depth_peel", *ms));
        }
        passes.extend(out.pass_ms.iter().copied());
        passes.push(("blur", blurred.1));
        let depth2 = second.map(|(d2, _)| d2).unwrap_or_default();
        let sd = params.secondary == Secondary::StochasticDepth as u32;
        let refined_samples = out.mask.iter().map(|m| m.count_ones() as u64).sum();
        let (rays, interval_sum) = if sd && raster_sd {
            (out.ray_max.iter().filter(|&&m| m != 0).count() as u64, None)
        } else if sd {
            let (rays, sum) =
                aokit_cpu::svao::sd_ray_stats(svao, &gbuffer.depth, &gbuffer.normals, &out.ray_min, &out.ray_max);
            (rays, Some(sum))
        } else {
            let rays = if traced {
                aokit_cpu::svao::count_sample_rays(svao, &gbuffer.depth, &gbuffer.normals, &depth2, &out.mask)
            } else {
                0
            };
            (rays, None)
        };
        let debug = SvaoDebug {
            ao_pass1: out.ao_pass1,
            mask: out.mask,
            ray_min: if sd { out.ray_min } else { Vec::new() },
            ray_max: if sd { out.ray_max } else { Vec::new() },
            sd_size: params.sd_size(),
            sd_map: out.sd_map,
            layers: params.sd_layers,
        };
        Ok(TechniqueRun {
            ao: out.ao,
            ao_final: blurred.0,
            passes,
            rays,
            refined_samples,
            interval_sum,
            debug: Some(debug),
        })
    }
}

/// A back-end chosen at run time (one per process: the size difference does not matter).
#[allow(clippy::large_enum_variant)]
pub enum Renderer {
    Cpu(CpuRenderer),
    Vulkan(VulkanRenderer),
}

impl Renderer {
    pub fn backend_name(&self) -> &'static str {
        match self {
            Renderer::Cpu(_) => "cpu",
            Renderer::Vulkan(_) => "vulkan",
        }
    }

    /// The Vulkan device's name, or the CPU thread count.
    pub fn device_name(&self) -> String {
        match self {
            Renderer::Cpu(_) => format!("CPU, {} threads", rayon::current_num_threads()),
            Renderer::Vulkan(v) => v.gpu.info().name.clone(),
        }
    }

    /// Messages the validation layer reported so far (none on the CPU).
    pub fn validation_messages(&self) -> Vec<String> {
        match self {
            Renderer::Cpu(_) => Vec::new(),
            Renderer::Vulkan(v) => v.gpu.validation_messages(),
        }
    }

    /// The G-buffer: ray cast on the CPU, rasterized on Vulkan. Returns it and its time in ms.
    pub fn gbuffer(&self, scene: &Scene, frame: &Frame, progress: Progress) -> Result<(GBufferImage, f64), GpuError> {
        match self {
            Renderer::Cpu(c) => Ok(c.gbuffer(frame, progress)),
            Renderer::Vulkan(v) => v.gbuffer(scene, frame),
        }
    }

    /// Run a technique on a G-buffer.
    pub fn run(
        &self,
        scene: &Scene,
        frame: &Frame,
        gbuffer: &GBufferImage,
        technique: &Technique,
        progress: Progress,
    ) -> Result<TechniqueRun, GpuError> {
        match self {
            Renderer::Cpu(c) => Ok(c.run(frame, gbuffer, technique, progress)),
            Renderer::Vulkan(v) => v.run(scene, frame, gbuffer, technique),
        }
    }
}
