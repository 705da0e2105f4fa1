//! The GPU-resident executor of a technique's pass graph (`aokit_shaders::graph`).
//!
//! An [`AoContext`] owns the pipelines (made on first use from the committed SPIR-V, one per
//! entry point) and the graph's resources (device-local storage buffers, re-made only when their
//! size changes). [`AoContext::record`] records one frame — resource initialisation, every pass
//! with the barriers its reads and writes need, timestamps — into the CALLER's command buffer:
//! no host transfer, no submit, no wait. It knows kernels and bindings, never techniques.
//!
//! Synchronisation contract:
//! - `record` starts with a barrier that orders it after all earlier work on the queue (so a
//!   frame may be recorded while the previous one is in flight on the same queue) and ends with a
//!   barrier that makes the outputs visible to later compute, fragment and transfer reads.
//! - Buffers, descriptor pools and query pools replaced because of a size or binding change are
//!   released [`FRAMES_IN_FLIGHT`] `record` calls later: before recording frame F + 3 the caller
//!   must have waited for frame F (the usual ring of at most three frames in flight, one `record`
//!   per frame). Everything else lives until the context is dropped, and the caller must make sure
//!   the device finished the context's work before dropping it.

use crate::adapters::{Adapters, AoImage, EngineImage};
use crate::compute::{ComputeKernel, memory_barrier};
use crate::descriptors::{Descriptor, KeptSets};
use crate::gbuffer::AttachmentlessPass;
use crate::raytracing::{RtPipeline, SceneAccel};
use crate::{Buffer, Gpu, GpuError, modules};
use aokit_shaders::adapters::ImportParams;
use aokit_shaders::common::ViewParams;
use aokit_shaders::graph::{Graph, Init, Lifetime, Pass, PassKind, RtMode, Size, inputs};
use ash::vk;
use ash::vk::Handle;
use gpu_allocator::MemoryLocation;
use std::borrow::Borrow;
use std::collections::HashMap;
use std::ffi::CString;

/// Frames that may be in flight: what a frame replaced (a buffer re-made at another size, a
/// descriptor pool) is freed this many `record` calls later, so before recording frame F + 3 the
/// engine must have waited for frame F.
pub const FRAMES_IN_FLIGHT: u64 = 3;

/// An engine's frame (see `crate::adapters` for formats, usages and layouts): its depth image
/// (hardware depth in `import.depth_convention` with `import.near`/`import.far`, or linear), an
/// optional view-space normal image (`n·0.5 + 0.5` in RGB; without it, normals are derived from
/// depth by XeGTAO's pass 0), the AO output image, and `import`, whose `view` must be the graph's
/// camera view (`FrameDesc::camera.view`) and `engine_size` the images' size.
#[derive(Copy, Clone)]
pub struct EngineFrame<'a> {
    /// The engine's depth image.
    pub depth: EngineImage,
    /// The engine's view-space normals, if it has them.
    pub normals: Option<EngineImage>,
    /// The depth-peeled second layer (spec svao-raysd §11), for the dual-depth techniques: the
    /// nearest surface at least the technique's peel separation (view depth) behind `depth`,
    /// in the same format and convention, cleared (background) where there is none.
    pub second_depth: Option<EngineImage>,
    /// Where the AO goes.
    pub output: AoImage,
    /// How the adapter reads the engine's depth (convention, planes, size).
    pub import: ImportParams,
    /// The scene's acceleration structure, for graphs that trace rays.
    pub scene: Option<&'a SceneAccel>,
}

/// The context's buffer an engine frame's depth is imported into (linear view depth `f32` per
/// full-target pixel, the guard band clamped to the edge texels): read it with the context's
/// `download` (feature `harness`) to see what aokit made of the engine's depth.
pub const ENGINE_DEPTH: &str = "engine_linear_depth";
/// The context's buffer an engine frame's normals are imported into (octahedral `u32` codes per
/// full-target pixel).
pub const ENGINE_NORMALS: &str = "engine_view_normals";
const ENGINE_SECOND_DEPTH: &str = "engine_second_depth";

/// What a frame reads besides the graph's own resources: the G-buffer in aokit's internal layout
/// (full target, linear `f32` depth, encoded `u32` normals) and, for some graphs, the peeled
/// second layer and the scene.
#[derive(Copy, Clone)]
pub struct GpuInputs<'a> {
    /// Linear view depth, `f32` per pixel of the full target.
    pub depth: &'a Buffer,
    /// Octahedral view normals, `u32` per pixel.
    pub normals: &'a Buffer,
    /// The depth-peeled second layer, for the dual-depth techniques.
    pub second_depth: Option<&'a Buffer>,
    /// The acceleration structure, for graphs that trace rays.
    pub scene: Option<&'a SceneAccel>,
    /// The scene for raster passes (the raster SD map).
    pub raster: Option<RasterScene<'a>>,
}

/// The scene as raster passes draw it: the de-indexed vertex stream (`GBufferVertex`) and the
/// alpha masks (headers, texels) their fragment shaders test.
#[derive(Copy, Clone)]
pub struct RasterScene<'a> {
    /// [`GBufferVertex`](crate::GBufferVertex) records, three per triangle.
    pub vertices: &'a Buffer,
    /// How many vertices `vertices` holds.
    pub vertex_count: u32,
    /// Alpha-mask header per material.
    pub mask_headers: &'a Buffer,
    /// The masks' texels.
    pub mask_texels: &'a Buffer,
}

/// Can `gpu` run `graph`? Its ray-traced passes (pipelines or ray queries, as the graph has
/// them) need the extensions, and every buffer a pass binds — its resources, and the G-buffer
/// inputs over the full target — must fit the device's `maxStorageBufferRange`. Checked before
/// anything is recorded (callers check it before their own GPU work, e.g. a raster G-buffer);
/// the error names what is missing or too big.
pub fn check_device(gpu: &Gpu, graph: &Graph) -> Result<(), GpuError> {
    let view = &graph.view;
    let full = view.size();
    let inputs = (4 * full.x as u64 * full.y as u64, "the G-buffer inputs (4 bytes per full-target pixel)");
    let resources = graph.resources.iter().map(|r| (4 * r.len(view) as u64, r.name));
    let max = gpu.max_storage_buffer_range;
    if let Some((bytes, name)) = resources.chain([inputs]).find(|(bytes, _)| *bytes > max) {
        return Err(GpuError::Missing(format!(
            "a {}×{} target needs {} MiB for {name}, more than '{}' binds in one storage buffer (maxStorageBufferRange {} MiB): render a smaller image",
            full.x,
            full.y,
            bytes >> 20,
            gpu.info().name,
            max >> 20
        )));
    }
    if !graph.traces_rays() {
        return Ok(());
    }
    let pipelines = graph.passes.iter().any(|p| matches!(p.kind, PassKind::RayTracing { .. }));
    gpu.require_rays(if pipelines { RtMode::Pipeline } else { RtMode::Query })
}

/// A pipeline's identity: the entry point and its specialization constants' `(SpecId, value)`.
type PipelineKey = (&'static str, Vec<(u32, u32)>);

/// The pipeline `pass` runs on: its entry point, specialized with what its push constants say
/// (`Kernel::specialization_for`).
fn pipeline_key(pass: &Pass) -> Result<PipelineKey, GpuError> {
    let specialization = pass.kernel.specialization_for(&pass.push_constants).map_err(GpuError::Input)?;
    Ok((pass.entry(), specialization))
}

/// Set 0 of `pass`'s pipeline: at least `slots` bindings (the module's), the scene's TLAS an
/// acceleration structure, every other binding a storage buffer.
fn descriptor_types(pass: &Pass, slots: u32) -> Vec<vk::DescriptorType> {
    let count = pass.bindings.iter().map(|b| b.slot + 1).fold(slots, u32::max);
    (0..count)
        .map(|slot| match pass.resource(slot) {
            Some(inputs::SCENE_TLAS) => vk::DescriptorType::ACCELERATION_STRUCTURE_KHR,
            _ => vk::DescriptorType::STORAGE_BUFFER,
        })
        .collect()
}

enum Pipeline {
    Compute { kernel: ComputeKernel, workgroup: [u32; 3] },
    RayTracing(RtPipeline),
    Raster(AttachmentlessPass),
}

/// A resource on the device.
struct DeviceResource {
    buffer: Buffer,
    len: usize,
}

/// What a graph's descriptor sets bind: each pass's entry point and `(slot, buffer)` pairs, then
/// the scene's identity and the raster vertex buffer where given.
#[derive(Clone, PartialEq)]
struct SetKey {
    entries: Vec<&'static str>,
    buffers: Vec<(u32, vk::Buffer)>,
}

/// Descriptor sets of one graph with one set of bound buffers.
struct BoundSets {
    key: SetKey,
    pool: vk::DescriptorPool,
    sets: Vec<vk::DescriptorSet>,
    /// The frame that last recorded with them (the least recently used are dropped first).
    used: u64,
}

/// Descriptor sets kept for this many graphs/bindings (e.g. techniques alternating through one
/// context, or an engine's double-buffered images) before the least recently used are retired.
const KEPT_SETS: usize = 8;
/// Adapter descriptor sets kept (import depth, import normals and export per set of engine
/// images: room for a few double- or triple-buffered images).
const KEPT_ADAPTER_SETS: usize = 16;

/// Pass timings of the last recorded frame.
struct Timing {
    pool: vk::QueryPool,
    capacity: u32,
    labels: Vec<&'static str>,
}

/// Runs pass graphs on one Vulkan device (see the module documentation).
pub struct AoContext<G: Borrow<Gpu> = Gpu> {
    owner: G,
    /// Per entry point and specialization ([`pipeline_key`]).
    pipelines: HashMap<PipelineKey, Pipeline>,
    /// Boxed: a frame's inputs may point into an entry while others are inserted.
    resources: HashMap<&'static str, Box<DeviceResource>>,
    /// Descriptor sets per graph and bindings, most recently used last.
    bound: Vec<BoundSets>,
    /// Descriptor pools made for graphs so far.
    bound_made: u64,
    timing: Option<Timing>,
    /// The adapter pipelines, made on the first engine frame, and their descriptor sets, kept
    /// per bound images and buffers.
    adapters: Option<Adapters>,
    adapter_sets: KeptSets,
    /// `(last frame that may use it, buffer or pool)` waiting to be freed: tagged with the
    /// latest `record` count when retired (the frame being recorded, or the last one recorded
    /// between frames), an upper bound on the frames whose commands use it.
    retired: Vec<(u64, Retired)>,
    frame: u64,
    #[cfg(feature = "testing")]
    sabotage: Sabotage,
    #[cfg(feature = "testing")]
    free_audit: Option<FreeAudit>,
}

/// A test's use-after-free check (feature `testing`): called before each retired buffer or pool
/// is freed with the last frame (1-based `record` count) whose commands may use it (an upper
/// bound: the latest frame recorded when it was retired).
#[cfg(feature = "testing")]
pub type FreeAudit = Box<dyn FnMut(u64) + Send>;

/// Deliberate defects for aokit's own tests (feature `testing`): they show that the validation
/// layer and the tests catch what they claim to catch. Never set outside a test.
#[cfg(feature = "testing")]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sabotage {
    /// Leave out the barrier the graph puts before this pass (its index in `graph.passes`):
    /// the pass then reads what the previous one writes without a dependency, a hazard the
    /// synchronisation validation must report.
    pub omit_barrier_before: Option<usize>,
    /// Free what a `record` replaces (a buffer re-made at another size, a descriptor pool) at
    /// once, instead of [`FRAMES_IN_FLIGHT`] frames later: the frame before, possibly still
    /// pending, used it. A use-after-free check must catch it.
    pub free_retired_at_once: bool,
}

enum Retired {
    Buffer(Buffer),
    Pool(vk::DescriptorPool),
    Queries(vk::QueryPool),
}

impl<G: Borrow<Gpu>> AoContext<G> {
    /// A context on `gpu` (made headless with [`Gpu::new`] or from the caller's device; an
    /// `Rc<Gpu>` or `&Gpu` shares it with other users).
    pub fn new(gpu: G) -> AoContext<G> {
        AoContext {
            owner: gpu,
            pipelines: HashMap::new(),
            resources: HashMap::new(),
            bound: Vec::new(),
            bound_made: 0,
            timing: None,
            adapters: None,
            adapter_sets: KeptSets::new(KEPT_ADAPTER_SETS),
            retired: Vec::new(),
            frame: 0,
            #[cfg(feature = "testing")]
            sabotage: Sabotage::default(),
            #[cfg(feature = "testing")]
            free_audit: None,
        }
    }

    /// Record the next frames with `sabotage`'s defects (see [`Sabotage`]).
    #[cfg(feature = "testing")]
    pub fn sabotage(&mut self, sabotage: Sabotage) {
        self.sabotage = sabotage;
    }

    /// Call `audit` before each retired resource is freed (see [`FreeAudit`]).
    #[cfg(feature = "testing")]
    pub fn audit_frees(&mut self, audit: FreeAudit) {
        self.free_audit = Some(audit);
    }

    /// Does the sabotage leave out the barrier before pass `i`?
    fn omits_barrier_before(&self, _i: usize) -> bool {
        #[cfg(feature = "testing")]
        if self.sabotage.omit_barrier_before == Some(_i) {
            return true;
        }
        false
    }

    /// The device it runs on.
    pub fn gpu(&self) -> &Gpu {
        self.owner.borrow()
    }

    /// The stages passes run in: compute, fragment where the queue has graphics, ray tracing
    /// where the device has it.
    fn shader_stages(&self) -> vk::PipelineStageFlags {
        let mut stages = vk::PipelineStageFlags::COMPUTE_SHADER;
        if self.gpu().has_graphics_queue() {
            stages |= vk::PipelineStageFlags::FRAGMENT_SHADER;
        }
        if self.gpu().has_ray_tracing() {
            stages |= vk::PipelineStageFlags::RAY_TRACING_SHADER_KHR;
        }
        stages
    }

    fn spirv(entry: &str) -> Result<&'static [u8], GpuError> {
        modules::of(entry).ok_or_else(|| GpuError::Input(format!("no SPIR-V module for entry point '{entry}'")))
    }

    /// The pipeline of `pass` (`key`: its [`pipeline_key`]), made on first use.
    fn ensure_pipeline(&mut self, pass: &Pass, key: &PipelineKey) -> Result<(), GpuError> {
        if self.pipelines.contains_key(key) {
            return Ok(());
        }
        let kernel = pass.kernel;
        let slots = kernel.slot_count();
        if let Some((name, _)) = kernel.push_constants.filter(|_| kernel.push_constant_bytes() == 0) {
            return Err(GpuError::Input(format!(
                "'{}': push constants {name} have no shared-struct layout (derive Layout)",
                kernel.entry
            )));
        }
        let pipeline = match pass.kind {
            PassKind::Compute => {
                let entry = CString::new(pass.entry()).expect("entry names have no NUL");
                let types = descriptor_types(pass, slots);
                let spirv = Self::spirv(pass.entry())?;
                if types.contains(&vk::DescriptorType::ACCELERATION_STRUCTURE_KHR) && !self.gpu().has_ray_query() {
                    return Err(GpuError::NoDevice(format!(
                        "ray queries: '{}' lacks VK_KHR_ray_query / VK_KHR_acceleration_structure / bufferDeviceAddress (pass '{}'; RtMode::Pipeline uses ray-tracing pipelines instead)",
                        self.gpu().info().name,
                        pass.entry()
                    )));
                }
                let compute =
                    ComputeKernel::new(self.gpu(), spirv, &entry, &types, kernel.push_constant_bytes(), &key.1)?;
                Pipeline::Compute { kernel: compute, workgroup: kernel.threads }
            }
            PassKind::RayTracing { miss, any_hit, .. } => {
                let names = [pass.entry(), miss.entry, any_hit.entry]
                    .map(|n| CString::new(n).expect("entry names have no NUL"));
                let shaders = [
                    (Self::spirv(pass.entry())?, names[0].as_c_str()),
                    (Self::spirv(miss.entry)?, names[1].as_c_str()),
                    (Self::spirv(any_hit.entry)?, names[2].as_c_str()),
                ];
                Pipeline::RayTracing(RtPipeline::new(self.gpu(), shaders, descriptor_types(pass, slots))?)
            }
            // The raster pipeline state graphs declare: no attachments, dynamic viewport.
            PassKind::Raster { vertex } => {
                let names = [vertex.entry, pass.entry()].map(|n| CString::new(n).expect("entry names have no NUL"));
                let push = vertex.push_constant_bytes();
                Pipeline::Raster(AttachmentlessPass::new(
                    self.gpu(),
                    (Self::spirv(vertex.entry)?, names[0].as_c_str()),
                    (Self::spirv(pass.entry())?, names[1].as_c_str()),
                    slots,
                    push,
                )?)
            }
        };
        self.pipelines.insert(key.clone(), pipeline);
        Ok(())
    }

    /// Make or re-make the graph's buffers (sizes as declared); returns the names made now.
    fn ensure_resources(&mut self, graph: &Graph) -> Result<Vec<&'static str>, GpuError> {
        self.ensure_named(&graph.resources, &graph.view)
    }

    /// Make or re-make these buffers; returns the names made now.
    fn ensure_named(
        &mut self,
        resources: &[aokit_shaders::graph::Resource],
        view: &ViewParams,
    ) -> Result<Vec<&'static str>, GpuError> {
        let mut made = Vec::new();
        for r in resources {
            let len = r.len(view);
            if self.resources.get(r.name).is_some_and(|d| d.len == len) {
                continue;
            }
            let usage = vk::BufferUsageFlags::STORAGE_BUFFER
                | vk::BufferUsageFlags::TRANSFER_DST
                | vk::BufferUsageFlags::TRANSFER_SRC;
            let buffer = self.gpu().create_buffer(4 * len as u64, usage, MemoryLocation::GpuOnly)?;
            if let Some(old) = self.resources.insert(r.name, Box::new(DeviceResource { buffer, len })) {
                // Sets that bind the old buffer go with it (its handle may be reused).
                let (stale, kept) = std::mem::take(&mut self.bound)
                    .into_iter()
                    .partition(|b| b.key.buffers.iter().any(|(_, raw)| *raw == old.buffer.raw));
                self.bound = kept;
                for b in stale {
                    self.retired.push((self.frame, Retired::Pool(b.pool)));
                }
                self.adapter_sets.forget(old.buffer.raw.as_raw());
                let evicted = std::mem::take(&mut self.adapter_sets.evicted);
                self.retired.extend(evicted.into_iter().map(|pool| (self.frame, Retired::Pool(pool))));
                self.retired.push((self.frame, Retired::Buffer(old.buffer)));
            }
            made.push(r.name);
        }
        Ok(made)
    }

    /// The device buffer of resource `name` after the frames recorded so far.
    pub fn buffer(&self, name: &str) -> Option<&Buffer> {
        self.resources.get(name).map(|r| &r.buffer)
    }

    /// Read resource `name` back (submits a copy and waits: for tools and tests, not frames).
    pub fn download<T: bytemuck::Pod>(&self, name: &str) -> Result<Vec<T>, GpuError> {
        let r = self.resources.get(name).ok_or_else(|| GpuError::Input(format!("no resource '{name}'")))?;
        let mut out = self.gpu().download::<T>(&r.buffer)?;
        out.truncate(4 * r.len / size_of::<T>());
        Ok(out)
    }

    /// Record one frame of `graph` into `cmd` (a primary command buffer in the recording state,
    /// from a pool of the context's queue family). See the module documentation for the
    /// synchronisation contract.
    pub fn record(&mut self, cmd: vk::CommandBuffer, graph: &Graph, inputs: &GpuInputs) -> Result<(), GpuError> {
        let pipelines = self.check_and_prepare(graph)?;
        self.record_prepared(cmd, graph, &pipelines, inputs)
    }

    /// What can fail short of running out of memory, before anything is recorded: the graph's
    /// consistency, the device's features, every pass's pipeline. Returns each pass's
    /// [`pipeline_key`], computed once a frame.
    fn check_and_prepare(&mut self, graph: &Graph) -> Result<Vec<PipelineKey>, GpuError> {
        graph.validate().map_err(GpuError::Input)?;
        check_device(self.gpu(), graph)?;
        let keys = graph.passes.iter().map(pipeline_key).collect::<Result<Vec<_>, _>>()?;
        for (pass, key) in graph.passes.iter().zip(&keys) {
            self.ensure_pipeline(pass, key)?;
        }
        Ok(keys)
    }

    /// [`AoContext::record`] of a graph [`AoContext::check_and_prepare`] accepted (`pipelines`:
    /// what it returned).
    fn record_prepared(
        &mut self,
        cmd: vk::CommandBuffer,
        graph: &Graph,
        pipelines: &[PipelineKey],
        inputs: &GpuInputs,
    ) -> Result<(), GpuError> {
        self.frame += 1;
        self.release_retired();
        let made = self.ensure_resources(graph)?;
        let key = self.set_key(graph, inputs)?;
        let bound = self.ensure_sets(graph, pipelines, key, inputs)?;
        self.ensure_timing(graph)?;
        let stages = self.shader_stages();
        let d = &self.gpu().device;
        let timing = self.timing.as_ref().expect("made above");
        unsafe {
            d.cmd_reset_query_pool(cmd, timing.pool, 0, timing.capacity);
        }
        // Order after earlier work on the queue (the previous frame may still read these).
        let transfer = vk::PipelineStageFlags::TRANSFER;
        memory_barrier(self.gpu(), cmd, transfer | stages, transfer | stages);
        // BOTTOM_OF_PIPE: the stamp waits for all earlier commands (e.g. a raster G-buffer
        // recorded before this frame), so no label absorbs their tail.
        unsafe { d.cmd_write_timestamp(cmd, vk::PipelineStageFlags::BOTTOM_OF_PIPE, timing.pool, 0) };
        for r in &graph.resources {
            if r.lifetime == Lifetime::Persistent && !made.contains(&r.name) {
                continue;
            }
            let raw = self.resources[r.name].buffer.raw;
            match &r.init {
                Init::Fill(bits) => unsafe { d.cmd_fill_buffer(cmd, raw, 0, vk::WHOLE_SIZE, *bits) },
                Init::Data(words) => {
                    // vkCmdUpdateBuffer takes at most 65536 bytes at a time.
                    for (i, chunk) in words.chunks(16384).enumerate() {
                        unsafe { d.cmd_update_buffer(cmd, raw, (i * 65536) as u64, bytemuck::cast_slice(chunk)) };
                    }
                }
                Init::Undefined => {}
            }
        }
        // The fills and updates are visible to the passes and to the snapshots' copies.
        memory_barrier(self.gpu(), cmd, transfer, transfer | stages);
        // Barriers from the accesses: a pass waits for earlier writes it reads or overwrites
        // and for earlier reads of what it writes.
        let barriers = graph.barriers();
        let mut stamp = 0;
        let sets = &self.bound[bound].sets;
        for (i, pass) in graph.passes.iter().enumerate() {
            if barriers[i] && !self.omits_barrier_before(i) {
                memory_barrier(self.gpu(), cmd, stages, stages);
            }
            let invocations = pass.invocations(&graph.view);
            match &self.pipelines[&pipelines[i]] {
                Pipeline::Compute { kernel, workgroup } => {
                    let groups = [invocations.x.div_ceil(workgroup[0]), invocations.y.div_ceil(workgroup[1]), 1];
                    kernel.record_set(self.gpu(), cmd, sets[i], &pass.push_constants, groups);
                }
                Pipeline::RayTracing(p) => p.record_trace(self.gpu(), cmd, sets[i], invocations.x, invocations.y)?,
                Pipeline::Raster(p) => {
                    let scene = inputs.raster.expect("checked by bound_buffers");
                    p.record(
                        self.gpu(),
                        cmd,
                        sets[i],
                        (scene.vertices, scene.vertex_count),
                        &pass.push_constants,
                        invocations,
                    );
                }
            }
            for snap in graph.snapshots.iter().filter(|s| s.after == i) {
                memory_barrier(self.gpu(), cmd, stages, transfer);
                let (from, to) = (&self.resources[snap.from].buffer, &self.resources[snap.to].buffer);
                let region = [vk::BufferCopy::default().size(from.size.min(to.size))];
                unsafe { d.cmd_copy_buffer(cmd, from.raw, to.raw, &region) };
                memory_barrier(self.gpu(), cmd, transfer, stages);
            }
            let last_of_label = graph.passes.get(i + 1).is_none_or(|next| next.label != pass.label);
            if last_of_label {
                stamp += 1;
                // After every earlier command of any stage (a label may span pass kinds).
                unsafe { d.cmd_write_timestamp(cmd, vk::PipelineStageFlags::BOTTOM_OF_PIPE, timing.pool, stamp) };
            }
        }
        memory_barrier(self.gpu(), cmd, transfer | stages, transfer | stages);
        #[cfg(feature = "testing")]
        if self.sabotage.free_retired_at_once {
            self.release_retired_after(0);
        }
        Ok(())
    }

    /// Record one frame of `graph` on the engine's images into `cmd`: import the depth (and
    /// normals, or derive them from depth) into aokit's internal layout, run the graph, export
    /// `graph.output` into `frame.output`. Same contract as [`AoContext::record`]; the images'
    /// layouts and barriers are the caller's (see `crate::adapters`). The adapters' descriptor
    /// sets are kept per image views: after destroying a view an earlier frame used (e.g. on a
    /// resize), call [`AoContext::invalidate_bindings`] before the next frame, since a new view
    /// may get the old handle.
    pub fn record_engine(
        &mut self,
        cmd: vk::CommandBuffer,
        graph: &Graph,
        frame: &EngineFrame,
    ) -> Result<(), GpuError> {
        let reserved = [ENGINE_DEPTH, ENGINE_NORMALS, ENGINE_SECOND_DEPTH];
        if graph.resources.iter().any(|r| reserved.contains(&r.name)) {
            return Err(GpuError::Input(format!("the graph declares a resource named one of {reserved:?}")));
        }
        let second = match (graph.inputs().contains(&inputs::SECOND_DEPTH), frame.second_depth) {
            (true, None) => {
                return Err(GpuError::Input(
                    "the graph reads a depth-peeled second layer (a dual-depth technique): give EngineFrame::second_depth"
                        .into(),
                ));
            }
            (reads, image) => image.filter(|_| reads),
        };
        if frame.import.view != graph.view {
            return Err(GpuError::Input("EngineFrame::import.view differs from the graph's camera view".into()));
        }
        if !Adapters::EXPORT_FORMATS.iter().any(|e| e.0 == frame.output.format) {
            let formats: Vec<_> = Adapters::EXPORT_FORMATS.iter().map(|e| e.0).collect();
            return Err(GpuError::Input(format!(
                "AO output format {:?}: expected one of {formats:?}",
                frame.output.format
            )));
        }
        // Without the engine's normals, the graph derives them from depth first.
        let mut full = if frame.normals.is_none() { graph.clone().with_normals_from_depth() } else { graph.clone() };
        // Diagnostic copies are for reports, not engine frames.
        full.snapshots.clear();
        // What can fail short of running out of memory fails here, before anything is recorded
        // (once per frame: the graph's own recording below does not check it again).
        let pipelines = self.check_and_prepare(&full)?;
        if self.adapters.is_none() {
            self.adapters = Some(Adapters::new(self.gpu())?);
        }
        let internal = [ENGINE_DEPTH, ENGINE_NORMALS, ENGINE_SECOND_DEPTH].map(|name| aokit_shaders::graph::Resource {
            name,
            elem: aokit_shaders::graph::Elem::U32,
            size: Size::TARGET,
            init: Init::Undefined,
            lifetime: Lifetime::PerFrame,
            doc: "",
        });
        self.ensure_named(&internal[..if second.is_some() { 3 } else { 2 }], &frame.import.view)?;
        // The frame `record` is about to count (for the kept sets' least-recently-used order).
        self.adapter_sets.frame = self.frame + 1;
        let adapters = self.adapters.as_ref().expect("made above");
        let (depth, normals) = (&self.resources[ENGINE_DEPTH].buffer, &self.resources[ENGINE_NORMALS].buffer);
        let normal_input = frame.normals.map(|image| (image, normals));
        let gpu = self.owner.borrow();
        adapters.record_import_from(
            gpu,
            cmd,
            &mut self.adapter_sets,
            &frame.import,
            (frame.depth, depth),
            normal_input,
        )?;
        if let Some(image) = second {
            let buffer = &self.resources[ENGINE_SECOND_DEPTH].buffer;
            let sets = &mut self.adapter_sets;
            adapters.record_import_from(gpu, cmd, sets, &frame.import, (image, buffer), None)?;
        }
        let (depth, normals) = (&self.resources[ENGINE_DEPTH].buffer, &self.resources[ENGINE_NORMALS].buffer);
        let second_depth = second.map(|_| &self.resources[ENGINE_SECOND_DEPTH].buffer as *const Buffer);
        // SAFETY of the aliasing below: the resources are boxed (inserting others does not move
        // them) and `record` does not replace these: the imported buffers are not in
        // `full.resources`, so `ensure_resources` never re-makes them.
        let (depth, normals): (*const Buffer, *const Buffer) = (depth, normals);
        let inputs = GpuInputs {
            depth: unsafe { &*depth },
            normals: unsafe { &*normals },
            second_depth: second_depth.map(|b| unsafe { &*b }),
            scene: frame.scene,
            raster: None,
        };
        self.record_prepared(cmd, &full, &pipelines, &inputs)?;
        let adapters = self.adapters.as_ref().expect("made above");
        let ao = &self.resources[graph.output].buffer;
        let gpu = self.owner.borrow();
        adapters.record_export_from(gpu, cmd, &mut self.adapter_sets, &frame.import, ao, frame.output)?;
        let evicted = std::mem::take(&mut self.adapter_sets.evicted);
        self.retired.extend(evicted.into_iter().map(|pool| (self.frame, Retired::Pool(pool))));
        Ok(())
    }

    /// Forget the descriptor sets, so the next frame writes new ones: call it after destroying an
    /// input buffer, engine image view or TLAS that an earlier frame bound (a new object may
    /// reuse its handle).
    pub fn invalidate_bindings(&mut self) {
        for old in std::mem::take(&mut self.bound) {
            self.retired.push((self.frame, Retired::Pool(old.pool)));
        }
        self.adapter_sets.clear();
        let evicted = std::mem::take(&mut self.adapter_sets.evicted);
        self.retired.extend(evicted.into_iter().map(|pool| (self.frame, Retired::Pool(pool))));
    }

    /// Descriptor pools this context has made so far (graphs' and adapters'): constant over frames
    /// that re-record graphs and images it has seen recently.
    #[cfg(feature = "testing")]
    pub fn descriptor_pools_made(&self) -> u64 {
        self.bound_made + self.adapter_sets.made
    }

    /// `(label, ms)` of the last recorded frame, once the device finished it (waits for its
    /// timestamps; the pool is shared by the frames, so call it before recording the next one).
    pub fn pass_times(&self) -> Result<Vec<(&'static str, f64)>, GpuError> {
        let Some(t) = &self.timing else { return Ok(Vec::new()) };
        let stamps = self.gpu().timestamps_ms(t.pool, t.labels.len() + 1)?;
        Ok(t.labels.iter().enumerate().map(|(i, &label)| (label, stamps[i + 1] - stamps[i])).collect())
    }

    /// Record `graph` into a command buffer of the context's own, submit it and wait (the CLI's
    /// and tests' one-shot frame). Returns the wall time from submit to fence in ms.
    pub fn run(&mut self, graph: &Graph, inputs: &GpuInputs) -> Result<f64, GpuError> {
        let cmd = self.gpu().begin_one_shot()?;
        let recorded = self.record(cmd, graph, inputs);
        let waited = self.gpu().finish_one_shot(cmd, recorded.is_ok());
        recorded?;
        waited
    }

    /// What the graph's descriptor sets bind for these inputs.
    fn set_key(&self, graph: &Graph, inputs: &GpuInputs) -> Result<SetKey, GpuError> {
        let mut buffers = Vec::new();
        for pass in &graph.passes {
            for b in &pass.bindings {
                let buffer = self.input_or_resource(b.resource, inputs)?.map_or(vk::Buffer::null(), |b| b.raw);
                buffers.push((b.slot, buffer));
            }
        }
        if let Some(scene) = inputs.scene {
            buffers.push((u32::MAX, vk::Buffer::from_raw(scene.identity())));
        }
        if let Some(raster) = inputs.raster {
            buffers.push((u32::MAX, raster.vertices.raw));
        } else if graph.inputs().contains(&inputs::SCENE_VERTICES) {
            // Checked before anything is recorded into the caller's command buffer.
            return Err(GpuError::Input("a raster pass needs the scene's vertices (GpuInputs::raster)".into()));
        }
        Ok(SetKey { entries: graph.passes.iter().map(|p| p.entry()).collect(), buffers })
    }

    /// The buffer bound for `name`; `None` for the TLAS.
    fn input_or_resource<'a>(&'a self, name: &str, inputs: &GpuInputs<'a>) -> Result<Option<&'a Buffer>, GpuError> {
        let missing = |what: &str| GpuError::Input(format!("the graph reads {what}, which was not given"));
        Ok(Some(match name {
            inputs::LINEAR_DEPTH => inputs.depth,
            inputs::VIEW_NORMALS => inputs.normals,
            inputs::SECOND_DEPTH => inputs.second_depth.ok_or_else(|| missing("a second depth layer"))?,
            inputs::SCENE_TLAS => {
                inputs.scene.ok_or_else(|| missing("the scene"))?;
                return Ok(None);
            }
            inputs::SCENE_MASK_HEADERS if inputs.raster.is_some() => inputs.raster.expect("checked").mask_headers,
            inputs::SCENE_MASK_TEXELS if inputs.raster.is_some() => inputs.raster.expect("checked").mask_texels,
            inputs::SCENE_VERTICES => inputs.raster.ok_or_else(|| missing("the scene's vertices"))?.vertices,
            name if inputs::ALL.contains(&name) => {
                let scene = inputs.scene.ok_or_else(|| missing("the scene"))?;
                scene.alpha_buffer(name).expect("every scene input other than the TLAS is an alpha buffer")
            }
            name => &self.resources.get(name).ok_or_else(|| GpuError::Input(format!("no resource '{name}'")))?.buffer,
        }))
    }

    /// The index in `bound` of descriptor sets for the graph with these bindings: kept ones, or
    /// new ones (retiring the least recently used beyond [`KEPT_SETS`]).
    fn ensure_sets(
        &mut self,
        graph: &Graph,
        pipelines: &[PipelineKey],
        key: SetKey,
        inputs: &GpuInputs,
    ) -> Result<usize, GpuError> {
        if let Some(i) = self.bound.iter().position(|b| b.key == key) {
            self.bound[i].used = self.frame;
            return Ok(i);
        }
        let mut counts: HashMap<vk::DescriptorType, u32> = HashMap::new();
        for pass in &graph.passes {
            for b in &pass.bindings {
                let ty = if b.resource == inputs::SCENE_TLAS {
                    vk::DescriptorType::ACCELERATION_STRUCTURE_KHR
                } else {
                    vk::DescriptorType::STORAGE_BUFFER
                };
                *counts.entry(ty).or_default() += 1;
            }
        }
        let sizes: Vec<_> =
            counts.iter().map(|(&ty, &n)| vk::DescriptorPoolSize::default().ty(ty).descriptor_count(n)).collect();
        let info = vk::DescriptorPoolCreateInfo::default().max_sets(graph.passes.len() as u32).pool_sizes(&sizes);
        let pool = unsafe { self.gpu().device.create_descriptor_pool(&info, None)? };
        let sets = self.write_sets(graph, pipelines, pool, inputs);
        let sets = match sets {
            Ok(sets) => sets,
            Err(e) => {
                unsafe { self.gpu().device.destroy_descriptor_pool(pool, None) };
                return Err(e);
            }
        };
        if self.bound.len() >= KEPT_SETS {
            let oldest = (0..self.bound.len()).min_by_key(|&i| self.bound[i].used).expect("not empty");
            let old = self.bound.remove(oldest);
            self.retired.push((self.frame, Retired::Pool(old.pool)));
        }
        self.bound.push(BoundSets { key, pool, sets, used: self.frame });
        self.bound_made += 1;
        Ok(self.bound.len() - 1)
    }

    /// One descriptor set per pass from `pool`, binding each slot's buffer (or the TLAS);
    /// `pipelines`: each pass's [`pipeline_key`].
    fn write_sets(
        &self,
        graph: &Graph,
        pipelines: &[PipelineKey],
        pool: vk::DescriptorPool,
        inputs: &GpuInputs,
    ) -> Result<Vec<vk::DescriptorSet>, GpuError> {
        let mut sets = Vec::new();
        for (pass, pipeline) in graph.passes.iter().zip(pipelines) {
            let (layout, count) = match &self.pipelines[pipeline] {
                Pipeline::Compute { kernel, .. } => (kernel.set_layout(), kernel.bindings()),
                Pipeline::RayTracing(p) => (p.set_layout, p.bindings.len() as u32),
                Pipeline::Raster(p) => (p.set_layout, p.bindings),
            };
            let mut descriptors = Vec::new();
            for slot in 0..count {
                let name = pass.resource(slot).ok_or_else(|| {
                    GpuError::Input(format!("pass '{}' leaves binding {slot} of its module unbound", pass.entry()))
                })?;
                descriptors.push(match self.input_or_resource(name, inputs)? {
                    Some(buffer) => Descriptor::Storage(buffer),
                    None => inputs.scene.expect("checked").tlas_descriptor(),
                });
            }
            sets.push(self.gpu().descriptor_set(pool, layout, &descriptors)?);
        }
        Ok(sets)
    }

    /// A timestamp query pool with room for the graph's labels.
    fn ensure_timing(&mut self, graph: &Graph) -> Result<(), GpuError> {
        let mut labels: Vec<&'static str> = Vec::new();
        for pass in &graph.passes {
            if labels.last() != Some(&pass.label) {
                labels.push(pass.label);
            }
        }
        let needed = labels.len() as u32 + 1;
        if let Some(t) = &mut self.timing
            && t.capacity >= needed
        {
            t.labels = labels;
            return Ok(());
        }
        let info = vk::QueryPoolCreateInfo::default().query_type(vk::QueryType::TIMESTAMP).query_count(needed);
        let pool = unsafe { self.gpu().device.create_query_pool(&info, None)? };
        if let Some(old) = self.timing.replace(Timing { pool, capacity: needed, labels }) {
            // Frames in flight may still write the old pool: retire it like buffers.
            self.retired.push((self.frame, Retired::Queries(old.pool)));
        }
        Ok(())
    }

    /// Free what was retired [`FRAMES_IN_FLIGHT`] or more `record` calls ago.
    fn release_retired(&mut self) {
        self.release_retired_after(FRAMES_IN_FLIGHT);
    }

    /// Free what frames `frames` or more `record` calls ago were the last to use: before
    /// recording frame F + 3 the caller waited for frame F (the module's contract).
    fn release_retired_after(&mut self, frames: u64) {
        let frame = self.frame;
        let (done, keep): (Vec<_>, Vec<_>) =
            std::mem::take(&mut self.retired).into_iter().partition(|(f, _)| f + frames <= frame);
        self.retired = keep;
        for (_last_use, r) in done {
            #[cfg(feature = "testing")]
            if let Some(audit) = self.free_audit.as_mut() {
                audit(_last_use);
            }
            self.free(r);
        }
    }

    fn free(&self, r: Retired) {
        match r {
            Retired::Buffer(b) => self.gpu().free_buffer(b),
            Retired::Pool(p) => unsafe { self.gpu().device.destroy_descriptor_pool(p, None) },
            Retired::Queries(q) => unsafe { self.gpu().device.destroy_query_pool(q, None) },
        }
    }
}

impl<G: Borrow<Gpu>> Drop for AoContext<G> {
    fn drop(&mut self) {
        if let Some(a) = self.adapters.take() {
            a.destroy(self.gpu());
        }
        for pool in self.adapter_sets.drain() {
            self.free(Retired::Pool(pool));
        }
        for (_, r) in std::mem::take(&mut self.retired) {
            self.free(r);
        }
        for b in std::mem::take(&mut self.bound) {
            self.free(Retired::Pool(b.pool));
        }
        if let Some(t) = self.timing.take() {
            self.free(Retired::Queries(t.pool));
        }
        for (_, r) in std::mem::take(&mut self.resources) {
            self.gpu().free_buffer(r.buffer);
        }
        for (_, p) in std::mem::take(&mut self.pipelines) {
            match p {
                Pipeline::Compute { kernel, .. } => kernel.destroy(self.gpu()),
                Pipeline::RayTracing(p) => p.destroy(self.gpu()),
                Pipeline::Raster(p) => p.destroy(self.gpu()),
            }
        }
    }
}

impl Gpu {
    /// A primary command buffer from the Gpu's own pool, recording (for tools and tests that
    /// record frames themselves; finish it with [`Gpu::finish_one_shot`]).
    pub fn begin_one_shot(&self) -> Result<vk::CommandBuffer, GpuError> {
        let info = vk::CommandBufferAllocateInfo::default()
            .command_pool(self.pool)
            .level(vk::CommandBufferLevel::PRIMARY)
            .command_buffer_count(1);
        let cmd = unsafe { self.device.allocate_command_buffers(&info)? }[0];
        let begin = vk::CommandBufferBeginInfo::default().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
        if let Err(e) = unsafe { self.device.begin_command_buffer(cmd, &begin) } {
            unsafe { self.device.free_command_buffers(self.pool, &[cmd]) };
            return Err(e.into());
        }
        Ok(cmd)
    }

    /// End `cmd`, submit it when `submit` (else just free it), wait, free it. Returns the wall
    /// time from submit to the fence in ms.
    pub fn finish_one_shot(&self, cmd: vk::CommandBuffer, submit: bool) -> Result<f64, GpuError> {
        let d = &self.device;
        let cmds = [cmd];
        let result = (|| unsafe {
            d.end_command_buffer(cmd)?;
            if !submit {
                return Ok(0.0);
            }
            let fence = d.create_fence(&vk::FenceCreateInfo::default(), None)?;
            let start = std::time::Instant::now();
            let waited = d
                .queue_submit(self.queue, &[vk::SubmitInfo::default().command_buffers(&cmds)], fence)
                .and_then(|_| d.wait_for_fences(&[fence], true, u64::MAX));
            let ms = start.elapsed().as_secs_f64() * 1e3;
            d.destroy_fence(fence, None);
            waited?;
            Ok(ms)
        })();
        unsafe { d.free_command_buffers(self.pool, &cmds) };
        result
    }
}
