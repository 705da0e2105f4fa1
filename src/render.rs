//! A technique on either back-end: the G-buffer (ray cast on the CPU, rasterized on Vulkan),
//! then the technique's pass graph through cpu-sim's executor or aokit-vulkan's, read back as a
//! [`TechniqueRun`] with what the graph's diagnostics declare.

use crate::frame::Frame;
use crate::scene::Scene;
use crate::technique::{Technique, TechniqueRun};
use aokit_cpu::graph::{CpuExecutor, CpuInputs, CpuScene};
use aokit_cpu::{GBufferImage, Progress, SceneBvh, Surfaces};
use aokit_shaders::common::alpha::AlphaMaskHeader;
use aokit_shaders::graph::{Executed, Graph, RAY_COUNT, RtMode, ray_count_of};
use aokit_shaders::technique::Resolution;
use aokit_vulkan::{AoContext, GpuInputs};
use aokit_vulkan::{
    Buffer, GBufferVertex, Gpu, GpuError, GpuOptions, RasterFrame, RasterGBuffer, RasterScene, SceneAccel,
};
use std::cell::RefCell;
use std::rc::Rc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

/// `(pass, milliseconds)` per pass.
pub type PassTimes = Vec<(&'static str, f64)>;

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

/// The Vulkan back-end: the raster G-buffer, and every technique's pass graph through one
/// `AoContext` (pipelines and resources made on first use and kept); the scene's acceleration
/// structure is built on first use and kept.
pub struct VulkanRenderer {
    pub gpu: Rc<Gpu>,
    /// Runs the techniques' pass graphs.
    ctx: RefCell<AoContext<Rc<Gpu>>>,
    /// Acceleration-structure build time of the last graph frame, when it built one.
    last_accel_build: std::cell::Cell<Option<f64>>,
    /// Submit-to-fence wall time of the last graph frame.
    last_frame_ms: std::cell::Cell<Option<f64>>,
    /// `(scene key, raster resources)` of the GPU-resident frames.
    raster_frame: RefCell<Option<(usize, RasterFrame)>>,
    raster: RasterGBuffer,
    /// `(scene key, acceleration structure)` of the last scene traced.
    accel: std::cell::RefCell<Option<(usize, SceneAccel)>>,
    /// How ray-traced passes run: ray-tracing pipelines or ray queries.
    rt_mode: std::cell::Cell<RtMode>,
}

impl VulkanRenderer {
    pub fn gpu(&self) -> &Gpu {
        &self.gpu
    }

    pub fn new(options: &GpuOptions) -> Result<Self, GpuError> {
        let gpu = Rc::new(Gpu::new(options)?);
        let raster = RasterGBuffer::new(&gpu)?;
        Ok(VulkanRenderer {
            ctx: RefCell::new(AoContext::new(gpu.clone())),
            last_accel_build: Default::default(),
            last_frame_ms: Default::default(),
            raster_frame: Default::default(),
            gpu,
            raster,
            accel: Default::default(),
            rt_mode: Default::default(),
        })
    }

    /// Run ray-traced passes as ray-tracing pipelines (the default) or ray-query kernels.
    pub fn set_rt_mode(&self, mode: RtMode) {
        self.rt_mode.set(mode);
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
            &frame.raster_params(0.0),
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
}

impl Drop for VulkanRenderer {
    fn drop(&mut self) {
        if let Some((_, a)) = self.accel.take() {
            a.destroy(&self.gpu);
        }
        if let Some((_, f)) = self.raster_frame.take() {
            f.destroy(&self.gpu);
        }
        self.raster.destroy(&self.gpu);
    }
}

impl CpuRenderer {
    /// Run `technique` on a given G-buffer: its pass graph through the CPU executor (the
    /// depth-peeled second layer first where the technique reads one).
    pub fn run(
        &self,
        frame: &Frame,
        gbuffer: &GBufferImage,
        technique: &Technique,
        progress: Progress,
    ) -> TechniqueRun {
        self.run_with(&mut CpuExecutor::new(), frame, gbuffer, technique, progress)
    }

    /// [`CpuRenderer::run`] through `executor`, whose persistent resources (the temporal
    /// accumulation's history) carry over from the frames it ran before.
    pub fn run_with(
        &self,
        executor: &mut CpuExecutor,
        frame: &Frame,
        gbuffer: &GBufferImage,
        technique: &Technique,
        progress: Progress,
    ) -> TechniqueRun {
        let graph = technique.graph(&frame.desc()).expect("every technique has a pass graph");
        let mut passes: PassTimes = Vec::new();
        let mut depth2 = Vec::new();
        if let Some(separation) = technique.second_layer() {
            let t = Instant::now();
            depth2 = aokit_cpu::ray_cast_second_layer(&self.bvh, &self.surfaces(), &frame.camera, gbuffer, separation);
            passes.push(("depth_peel", ms_since(t)));
        }
        let surfaces = self.surfaces();
        // A run advances the caller's bar by the target's rows, whatever its passes report: the
        // passes that report count the rows of their own target (a half-resolution row stands
        // for two of the frame's, and the guard band's rows are not reported), the rest report
        // none; what is missing is reported when the graph is done.
        let target_rows = frame.camera.view.size().y as u64;
        let rows_per_row = match technique.resolution() {
            Resolution::Full => 1,
            Resolution::Half(_) => 2,
        };
        let reported = AtomicU64::new(0);
        let full_rows = |rows: u64| {
            let before = reported.fetch_add(rows * rows_per_row, Ordering::Relaxed);
            progress((rows * rows_per_row).min(target_rows.saturating_sub(before)));
        };
        let inputs = CpuInputs {
            depth: &gbuffer.depth,
            normals: &gbuffer.normals,
            second_depth: technique.second_layer().map(|_| &depth2[..]),
            scene: Some(CpuScene { bvh: &self.bvh, surfaces: &surfaces }),
            progress: &full_rows,
        };
        let stats = executor.run(&graph, &inputs).expect("the CPU executor runs every graph kernel");
        progress(target_rows.saturating_sub(reported.into_inner()));
        passes.extend(stats.pass_ms);
        let read = |name: &str| executor.words(name).map(|w| w.to_vec());
        let run = graph_run(&graph, passes, &read, gbuffer);
        debug_assert!(!graph.traces_rays() || run.rays == stats.rays, "the ray counter is the executor's count");
        run
    }
}

/// A technique's result from the resources of an executed graph (`read` returns a resource's
/// words): raw and final AO, the rays the kernels counted as they traced them ([`RAY_COUNT`]),
/// and what the graph's [`Diagnostics`](aokit_shaders::graph::Diagnostics) declare.
fn graph_run(
    graph: &Graph,
    passes: PassTimes,
    read: &dyn Fn(&str) -> Option<Vec<u32>>,
    gbuffer: &GBufferImage,
) -> TechniqueRun {
    // Only the graph's own resources: an executor may still hold another technique's.
    let read = |name: &str| graph.resource(name).and_then(|_| read(name));
    let run = Executed { words: &read, depth: &gbuffer.depth, normals: &gbuffer.normals };
    let mut result = TechniqueRun::plain(run.f32s(graph.raw_output), run.f32s(graph.output), passes);
    if let Some(words) = read(RAY_COUNT) {
        result.rays = ray_count_of(&words);
    }
    if let Some(name) = graph.diagnostics.bent_normals {
        result.bent_normals = run.u32s(name);
    }
    if let Some(decoder) = graph.diagnostics.refinement {
        let refinement = (decoder.decode)(&run);
        result.refined_samples = refinement.refined_samples;
        result.interval_sum = refinement.interval_sum;
        if let Some(rays) = refinement.rays {
            result.rays = rays;
        }
        result.debug = Some(refinement);
    }
    result
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
            let t = scene.corner_tables();
            let accel = SceneAccel::build(&self.gpu, &t.positions, &t.uvs, &scene.triangle_materials, &t.masks)?;
            built = Some(accel.build_ms);
            *cache = Some((key, accel));
        }
        let (_, accel) = cache.as_ref().expect("built above");
        Ok((f(accel)?, built))
    }

    /// Run `technique` on a given G-buffer (uploaded): its pass graph through the context.
    pub fn run(
        &self,
        scene: &Scene,
        frame: &Frame,
        gbuffer: &GBufferImage,
        technique: &Technique,
    ) -> Result<TechniqueRun, GpuError> {
        let graph = technique.graph(&frame.desc()).expect("every technique has a pass graph");
        let mut run = self.run_graph(scene, frame, gbuffer, technique, &graph)?;
        if let Some(ms) = self.last_accel_build.take() {
            run.passes.insert(0, ("accel_build", ms));
        }
        Ok(run)
    }

    /// One GPU-resident frame: the raster G-buffer (and the peeled second layer where the
    /// technique reads one) and the technique's pass graph recorded into ONE command buffer,
    /// submitted once; the only download is the final AO. With `details`, afterwards (outside
    /// the frame) also the G-buffer and the graph's buffers for statistics and reports.
    /// `TechniqueRun::frame_ms` is the wall time from submit to fence; its passes are the
    /// timestamps of the raster passes and of the graph's passes.
    pub fn frame(
        &self,
        scene: &Scene,
        frame: &Frame,
        technique: &Technique,
        details: bool,
    ) -> Result<(TechniqueRun, Option<GBufferImage>), GpuError> {
        let graph = technique.graph(&frame.desc()).expect("every technique has a pass graph");
        let graph = graph.with_rt_mode(self.rt_mode.get());
        // Before any GPU work: the raster G-buffer and the acceleration structure come first.
        aokit_vulkan::check_device(&self.gpu, &graph)?;
        let key = scene_key(scene);
        let size = frame.camera.view.size();
        let mut cache = self.raster_frame.borrow_mut();
        if cache.as_ref().is_none_or(|(k, f)| *k != key || f.size() != size) {
            if let Some((_, old)) = cache.take() {
                unsafe { self.gpu.device().device_wait_idle()? };
                old.destroy(&self.gpu);
            }
            let rf = self.raster.frame_resources(&self.gpu, &raster_vertices(scene), &scene.alpha_masks(), size)?;
            *cache = Some((key, rf));
            self.ctx.borrow_mut().invalidate_bindings();
        }
        let (_, rf) = cache.as_ref().expect("made above");
        let separation = technique.second_layer();
        let record = |accel: Option<&SceneAccel>| -> Result<f64, GpuError> {
            let cmd = self.gpu.begin_one_shot()?;
            let params = frame.raster_params(separation.unwrap_or(0.0));
            self.raster.record(&self.gpu, cmd, rf, &params, separation.is_some());
            let (depth, normals) = rf.gbuffer();
            let inputs = GpuInputs {
                depth,
                normals,
                second_depth: separation.map(|_| rf.second_depth()),
                scene: accel,
                raster: Some(rf.scene()),
            };
            let recorded = self.ctx.borrow_mut().record(cmd, &graph, &inputs);
            let waited = self.gpu.finish_one_shot(cmd, recorded.is_ok());
            recorded?;
            waited
        };
        let frame_ms = if graph.traces_rays() {
            let (ms, built) = self.with_accel(scene, |accel| record(Some(accel)))?;
            self.last_accel_build.set(built);
            ms
        } else {
            record(None)?
        };
        let ctx = self.ctx.borrow();
        let mut passes = rf.pass_times(&self.gpu)?;
        passes.extend(ctx.pass_times()?);
        let (mut run, gbuffer) = if details {
            let (depth, normals) = rf.gbuffer();
            let (depth, normals) = (self.gpu.download(depth)?, self.gpu.download(normals)?);
            let gbuffer = GBufferImage { width: size.x, height: size.y, depth, normals };
            let read = |name: &str| ctx.download::<u32>(name).ok();
            (graph_run(&graph, passes, &read, &gbuffer), Some(gbuffer))
        } else {
            (TechniqueRun::plain(Vec::new(), ctx.download::<f32>(graph.output)?, passes), None)
        };
        run.frame_ms = Some(frame_ms);
        Ok((run, gbuffer))
    }

    /// One frame of `graph` as a technique's run.
    fn run_graph(
        &self,
        scene: &Scene,
        frame: &Frame,
        gbuffer: &GBufferImage,
        technique: &Technique,
        graph: &Graph,
    ) -> Result<TechniqueRun, GpuError> {
        let graph = &graph.clone().with_rt_mode(self.rt_mode.get());
        aokit_vulkan::check_device(&self.gpu, graph)?;
        self.graph_frame(Some(scene), frame, gbuffer, technique, graph, |ctx, passes| {
            let read = |name: &str| ctx.download::<u32>(name).ok();
            let mut run = graph_run(graph, passes, &read, gbuffer);
            run.frame_ms = self.last_frame_ms.get();
            run
        })
    }

    /// One frame of `graph` on the uploaded G-buffer (and the peeled second layer, rasterized
    /// against it, where the technique reads one); `finish` reads what it needs from the context
    /// with the pass times and the second layer.
    fn graph_frame<R>(
        &self,
        scene: Option<&Scene>,
        frame: &Frame,
        gbuffer: &GBufferImage,
        technique: &Technique,
        graph: &Graph,
        finish: impl FnOnce(&AoContext<Rc<Gpu>>, PassTimes) -> R,
    ) -> Result<R, GpuError> {
        let needs_vertices = graph.inputs().contains(&aokit_shaders::graph::inputs::SCENE_VERTICES);
        let needs_scene = graph.traces_rays() || needs_vertices || technique.second_layer().is_some();
        let empty = Scene::default();
        let scene = match scene {
            Some(s) => s,
            None if needs_scene => return Err(GpuError::Input(format!("{} needs the scene", technique.name()))),
            None => &empty,
        };
        let mut finish = Some(finish);
        let mut frame_on = |accel: Option<&SceneAccel>| {
            self.with_uploaded_gbuffer(gbuffer, |depth, normals| {
                let mut passes = Vec::new();
                let peeled = match technique.second_layer() {
                    Some(separation) => {
                        let params = frame.raster_params(separation);
                        let (d2, n2, ms) = self.raster.render(
                            self.gpu(),
                            &raster_vertices(scene),
                            &scene.alpha_masks(),
                            &params,
                            Some(depth),
                        )?;
                        self.gpu().free_buffer(n2);
                        passes.push(("depth_peel", ms));
                        Some(d2)
                    }
                    None => None,
                };
                let mut ctx = self.ctx.borrow_mut();
                let ran = self.with_raster_scene(scene, needs_vertices, |raster| {
                    let inputs = GpuInputs { depth, normals, second_depth: peeled.as_ref(), scene: accel, raster };
                    let ms = ctx.run(graph, &inputs)?;
                    self.last_frame_ms.set(Some(ms));
                    ctx.pass_times()
                });
                // The inputs are freed below; a later buffer may take their handles.
                ctx.invalidate_bindings();
                if let Some(d2) = peeled {
                    self.gpu().free_buffer(d2);
                }
                let mut times = ran?;
                times.splice(0..0, passes);
                Ok((finish.take().expect("one frame"))(&ctx, times))
            })
        };
        if !graph.traces_rays() {
            return frame_on(None);
        }
        // The build time is reported by `accel_build_ms` where a report wants it.
        let (out, built) = self.with_accel(scene, |accel| frame_on(Some(accel)))?;
        self.last_accel_build.set(built);
        Ok(out)
    }

    /// Run `f` with the scene uploaded for raster passes (vertices, alpha masks) when `needed`,
    /// else with `None`.
    fn with_raster_scene<R>(
        &self,
        scene: &Scene,
        needed: bool,
        f: impl FnOnce(Option<RasterScene>) -> Result<R, GpuError>,
    ) -> Result<R, GpuError> {
        if !needed {
            return f(None);
        }
        let vertices = raster_vertices(scene);
        let masks = scene.alpha_masks();
        let storage = ash::vk::BufferUsageFlags::STORAGE_BUFFER;
        let mut owned = Vec::new();
        let result = (|| {
            owned.push(self.gpu.upload(&vertices, ash::vk::BufferUsageFlags::VERTEX_BUFFER)?);
            owned.push(self.gpu.upload(&masks.0, storage)?);
            owned.push(self.gpu.upload(&masks.1, storage)?);
            f(Some(RasterScene {
                vertices: &owned[0],
                vertex_count: vertices.len() as u32,
                mask_headers: &owned[1],
                mask_texels: &owned[2],
            }))
        })();
        for b in owned {
            self.gpu.free_buffer(b);
        }
        result
    }

    /// `technique`'s graph on a given G-buffer (uploaded; a technique that needs no scene), and
    /// afterwards the words of each of its resources `names` (for per-pass comparisons) with the
    /// pass times.
    pub fn resources_after(
        &self,
        frame: &Frame,
        gbuffer: &GBufferImage,
        technique: &Technique,
        names: &[&str],
    ) -> Result<(Vec<Vec<u32>>, PassTimes), GpuError> {
        let graph = technique.graph(&frame.desc()).map_err(GpuError::Input)?;
        for name in names {
            if graph.resource(name).is_none() {
                return Err(GpuError::Input(format!("{} has no resource '{name}'", technique.name())));
            }
        }
        self.graph_frame(None, frame, gbuffer, technique, &graph, |ctx, pass_ms| {
            let words: Result<Vec<_>, GpuError> = names.iter().map(|name| ctx.download::<u32>(name)).collect();
            Ok((words?, pass_ms))
        })?
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

    /// One frame from the scene: the G-buffer and the technique, its passes led by `gbuffer`
    /// (and `depth_peel`). Vulkan: GPU-resident, one command buffer ([`VulkanRenderer::frame`];
    /// without `details` only the final AO comes back). CPU: the ray-cast G-buffer, then the
    /// graph. Returns the G-buffer with `details`.
    pub fn frame(
        &self,
        scene: &Scene,
        frame: &Frame,
        technique: &Technique,
        progress: Progress,
        details: bool,
    ) -> Result<(TechniqueRun, Option<GBufferImage>), GpuError> {
        match self {
            Renderer::Cpu(c) => {
                let (gbuffer, ms) = c.gbuffer(frame, progress);
                let mut run = c.run(frame, &gbuffer, technique, progress);
                run.passes.insert(0, ("gbuffer", ms));
                Ok((run, details.then_some(gbuffer)))
            }
            Renderer::Vulkan(v) => v.frame(scene, frame, technique, details),
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
