//! aokit on a wgpu device: ambient occlusion as one effect on the application's own
//! `wgpu::Device` and `Queue`, in the four verbs of the Vulkan effect (`aokit_vulkan::AoEffect`)
//! — [`AoEffect::new`], [`AoEffect::resize`], [`AoEffect::set_settings`] and
//! [`AoEffect::record`] — with the same [`AoSettings`] (a [`Technique`] at one of its presets
//! first).
//!
//! The application hands its depth texture with its convention, optionally its view-space
//! normals, the AO output texture, and its projection and view matrices ([`AoFrame`]); the
//! effect derives aokit's camera from the matrices exactly as the Vulkan effect does
//! (`aokit_shaders::engine`), walks the technique's pass graph — the same declarations the CPU
//! simulator and the Vulkan executor walk; this crate knows no technique — and records every
//! pass into the application's `CommandEncoder`: no submit, no wait, no read-back. Pipelines,
//! buffers and bind groups are made once and reused; a buffer is re-made only when its size
//! changes.
//!
//! ```no_run
//! use aokit_wgpu::glam::Mat4;
//! use aokit_wgpu::{AoEffect, AoFrame, AoSettings, DepthConvention, Technique};
//!
//! // Once: a technique at one of its presets, on the application's device and queue.
//! fn setup(device: &wgpu::Device, queue: &wgpu::Queue) -> Result<AoEffect, Box<dyn std::error::Error>> {
//!     let settings = AoSettings::new(Technique::preset("gtao", "high")?).radius(0.5);
//!     let mut ao = AoEffect::new(device, queue, settings)?;
//!     ao.resize(1920, 1080)?;
//!     Ok(ao)
//! }
//!
//! // Every frame, after the depth pass, into the application's encoder (which it then
//! // submits). `depth`: a Depth32Float view; `ao`: an R32Float view with STORAGE_BINDING.
//! fn frame(
//!     ao: &mut AoEffect,
//!     encoder: &mut wgpu::CommandEncoder,
//!     (depth, output): (&wgpu::TextureView, &wgpu::TextureView),
//!     (projection, view): (Mat4, Mat4),
//! ) -> Result<(), aokit_wgpu::AoError> {
//!     ao.record(encoder, &AoFrame::new(depth, DepthConvention::ReversedInfinite, output, projection, view))
//! }
//! ```
//!
//! # What a technique needs from the adapter
//!
//! The screen-space techniques (`vao`, `hbao`, `gtao`, `vbao`, `raymarch`, with their
//! denoisers and temporal accumulation) run from the committed WGSL (`assets/wgsl/`, embedded
//! here) within WebGPU's default limits, so they run on any wgpu back-end, the browser's
//! WebGPU included. On wgpu's Vulkan back-end with [`SPIRV_FEATURES`] (and the adapter's
//! `max_immediate_size`) they run the committed SPIR-V itself, as `aokit-vulkan` does, the
//! texture import and export included ([`AoEffect::runs_spirv`]). The ray-traced techniques (`raysd`, `hbao-sd`, `hybrid`,
//! `raysvao`, `groundtruth`) run there too with [`RAY_QUERY_FEATURES`] and the adapter's limits,
//! as compute passes with ray queries over the acceleration structure of
//! [`AoEffect::build_scene`] ([`AoEffect::runs_ray_queries`]); elsewhere `AoEffect::new`
//! refuses them on one line, as it refuses the techniques that rasterize the scene themselves
//! and the dual-depth ones on every device (use `aokit-vulkan`).
//!
//! # Textures
//!
//! * **Depth** ([`AoFrame::depth`]): a 2D view of the application's size (one mip level, one
//!   layer; the depth aspect of a depth-stencil format) from a texture with
//!   `TEXTURE_BINDING` usage: `Depth32Float` (or `Depth16Unorm`, `Depth24Plus`…) in
//!   [`AoFrame::depth_convention`], or `R32Float` holding linear view depth
//!   ([`DepthConvention::Linear`]). It is bound as an unfilterable float texture.
//! * **Normals** ([`AoFrame::normals`], optional): any float-readable format holding the
//!   view-space normal `n·0.5 + 0.5` in RGB; without them the technique derives normals from
//!   depth (XeGTAO's normals pass).
//! * **Output** ([`AoFrame::output`]): a 2D view of the application's size from a texture with
//!   `STORAGE_BINDING` usage, `R32Float` (and, where the effect runs SPIR-V, `R16Float` or
//!   `R8Unorm`, whose storage needs the adapter's format features); 1 = unoccluded.
//!
//! wgpu orders the passes after the application's earlier use of these textures and before
//! its later use by itself: no barrier to write.
//!
//! # Views, frames, history
//!
//! Use one `AoEffect` per camera view: an effect keeps one view's buffers (the temporal
//! accumulation's history among them) and re-makes them when the size changes. Temporal
//! accumulation runs when the settings ask for it (`AoSettings::temporal`) and each frame gives
//! its index and the previous view ([`AoFrame::temporal`]). Frames may be recorded ahead of
//! their submission in any number; submit them in the order they were recorded. The graph is
//! rebuilt (a few small vectors) when the camera or the frame index changes; pipelines, buffers
//! and bind groups are kept.
#![warn(missing_docs)]

pub use aokit_shaders::engine::{AoSettings, DepthConvention};
pub use aokit_shaders::glam;
pub use aokit_shaders::technique::{Resolution, Technique};
pub use aokit_shaders::temporal::settings::TemporalSettings;

use aokit_shaders::adapters::ImportParams;
use aokit_shaders::engine::{engine_frame, probe_frame};
use aokit_shaders::glam::{Mat4, UVec2};
use aokit_shaders::graph::{FrameDesc, Graph, Init, Lifetime, PassKind, RtMode, inputs};
use aokit_shaders::kernel::{BindingKind, Kernel};
use std::collections::HashMap;

/// The committed WGSL and SPIR-V, embedded by the build script.
mod modules {
    include!(concat!(env!("OUT_DIR"), "/modules.rs"));

    /// The WGSL module of entry point `entry`.
    pub fn wgsl(entry: &str) -> Option<&'static str> {
        WGSL.iter().find(|(name, _)| *name == entry).map(|m| m.1)
    }

    /// The SPIR-V module of entry point `entry`, as words, with each specialization constant's
    /// default set to its value in `specialization` (`(SpecId, value)`): what a Vulkan driver
    /// does with `VkSpecializationInfo`, done here because wgpu passes a module through as is.
    pub fn spirv(entry: &str, specialization: &[(u32, u32)]) -> Option<Vec<u32>> {
        let bytes = SPIRV.iter().find(|(name, _)| *name == entry)?.1;
        let mut words: Vec<u32> = bytes.chunks_exact(4).map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]])).collect();
        specialize(&mut words, specialization);
        Some(words)
    }

    /// Set the defaults of the 32-bit `OpSpecConstant`s whose `SpecId` decoration `values`
    /// lists (SPIR-V 1.6 §3.3.12 / §3.32.4: `OpDecorate %x SpecId n` is opcode 71 with decoration
    /// 1; `OpSpecConstant %type %x value` is opcode 50). Other instructions are left alone.
    fn specialize(words: &mut [u32], values: &[(u32, u32)]) {
        const OP_DECORATE: u32 = 71;
        const SPEC_ID: u32 = 1;
        const OP_SPEC_CONSTANT: u32 = 50;
        let instructions = |words: &[u32]| {
            let mut at = 5; // after the header
            let mut all = Vec::new();
            while at < words.len() {
                let count = (words[at] >> 16) as usize;
                all.push((at, words[at] & 0xffff, count));
                at += count.max(1);
            }
            all
        };
        let ids: Vec<(u32, u32)> = instructions(words)
            .into_iter()
            .filter(|&(at, op, count)| op == OP_DECORATE && count >= 4 && words[at + 2] == SPEC_ID)
            .filter_map(|(at, _, _)| {
                let value = values.iter().find(|(id, _)| *id == words[at + 3])?.1;
                Some((words[at + 1], value))
            })
            .collect();
        for (at, op, count) in instructions(words) {
            if op == OP_SPEC_CONSTANT
                && count == 4
                && let Some((_, value)) = ids.iter().find(|(result, _)| *result == words[at + 2])
            {
                words[at + 3] = *value;
            }
        }
    }
}

/// The device features with which the effect runs the committed SPIR-V itself on wgpu's Vulkan
/// back-end ([`AoEffect::runs_spirv`]): passed through as is, its push constants as immediates.
/// Request them where the adapter has them (`adapter.features() & SPIRV_FEATURES`).
pub const SPIRV_FEATURES: wgpu::Features = wgpu::Features::PASSTHROUGH_SHADERS.union(wgpu::Features::IMMEDIATES);

/// The device features with which the effect also runs the ray-traced techniques, through the
/// committed ray-query SPIR-V (`*_rq`) and an acceleration structure built with wgpu's BLAS/TLAS
/// API ([`AoEffect::runs_ray_queries`], [`AoEffect::build_scene`]).
pub const RAY_QUERY_FEATURES: wgpu::Features = SPIRV_FEATURES.union(wgpu::Features::EXPERIMENTAL_RAY_QUERY);

/// The scene's inputs a ray-traced pass binds, all provided by an [`AoScene`].
const SCENE_INPUTS: [&str; 5] = [
    inputs::SCENE_TLAS,
    inputs::SCENE_UVS,
    inputs::SCENE_MATERIALS,
    inputs::SCENE_MASK_HEADERS,
    inputs::SCENE_MASK_TEXELS,
];

/// The [`AoEffect::pass_times`] label of the texture import (depth, and normals where given).
pub const IMPORT_LABEL: &str = "import";
/// The [`AoEffect::pass_times`] label of the AO export into the output texture.
pub const EXPORT_LABEL: &str = "export";

/// The adapters' workgroup: `threads(8, 8)` in `aokit_shaders::adapters`.
const ADAPTER_GROUP: u32 = 8;

/// Why the effect could not be made or a frame could not be recorded. When `record` returns an
/// error nothing was recorded into the encoder.
#[derive(Debug, thiserror::Error)]
pub enum AoError {
    /// The settings are out of range, or name a technique or setting that does not exist.
    #[error("settings: {0}")]
    Settings(String),
    /// The projection or view matrix cannot be the camera of a depth image aokit reads.
    #[error("projection: {0}")]
    Projection(String),
    /// `record` before the first `resize`.
    #[error("the effect has no size yet: call AoEffect::resize(width, height) before the first record")]
    NotResized,
    /// The technique needs something this crate cannot run (ray tracing, raster passes), or the
    /// frame's textures are not what the effect reads and writes.
    #[error("frame: {0}")]
    Frame(String),
}

/// One frame of the application: its textures, its camera and its place in a sequence. Made
/// with [`AoFrame::new`] and the builder methods.
#[derive(Copy, Clone, Debug)]
pub struct AoFrame<'a> {
    /// The depth view (hardware depth in `depth_convention`, or linear depth); see the crate
    /// documentation for formats and usages.
    pub depth: &'a wgpu::TextureView,
    /// What `depth` stores.
    pub depth_convention: DepthConvention,
    /// View-space normals `n·0.5 + 0.5` in RGB; `None`: derived from depth.
    pub normals: Option<&'a wgpu::TextureView>,
    /// Where the AO goes: an `R32Float` view with storage usage (`R16Float`, `R8Unorm` too where
    /// the effect runs SPIR-V); 1 = unoccluded.
    pub output: &'a wgpu::TextureView,
    /// The projection the depth was rendered with: right-handed view space looking down −Z,
    /// clip depth `[0, 1]`, symmetric frustum (pass the unjittered matrix), row 0 of the
    /// textures at the top of the view.
    pub projection: Mat4,
    /// World → view.
    pub view: Mat4,
    /// The frame's index in a sequence: every stochastic technique's noise takes it \[0\].
    pub frame_index: u32,
    /// The previous frame's world → view, for the temporal accumulation's reprojection; `None`
    /// on a first frame or after a cut.
    pub previous_view: Option<Mat4>,
    /// The scene, for techniques that trace rays ([`AoEffect::build_scene`]).
    pub scene: Option<&'a AoScene>,
}

impl<'a> AoFrame<'a> {
    /// A frame of `depth` (in `depth_convention`) into `output`, seen through `projection` and
    /// `view`; normals derived from depth, frame index 0, no previous view, no scene.
    pub fn new(
        depth: &'a wgpu::TextureView,
        depth_convention: DepthConvention,
        output: &'a wgpu::TextureView,
        projection: Mat4,
        view: Mat4,
    ) -> AoFrame<'a> {
        AoFrame {
            depth,
            depth_convention,
            normals: None,
            output,
            projection,
            view,
            frame_index: 0,
            previous_view: None,
            scene: None,
        }
    }

    /// With the scene for ray-traced techniques.
    pub fn scene(self, scene: &'a AoScene) -> AoFrame<'a> {
        AoFrame { scene: Some(scene), ..self }
    }

    /// With the application's view-space normals.
    pub fn normals(self, normals: &'a wgpu::TextureView) -> AoFrame<'a> {
        AoFrame { normals: Some(normals), ..self }
    }

    /// As frame `index` of a sequence whose previous frame was seen through `previous_view`.
    pub fn temporal(self, index: u32, previous_view: Option<Mat4>) -> AoFrame<'a> {
        AoFrame { frame_index: index, previous_view, ..self }
    }
}

pub use aokit_shaders::engine::SceneGeometry;

/// The scene on the device for ray queries: a BLAS of its triangles, a TLAS of one instance of
/// it, and the tables the any-hit alpha test reads (`aokit_shaders::common::alpha`). Made by
/// [`AoEffect::build_scene`]; wgpu keeps it alive while frames that use it run.
pub struct AoScene {
    tlas: wgpu::Tlas,
    /// `uvs`, `materials`, `mask_headers`, `mask_texels`, in the order of [`SCENE_INPUTS`]' last four.
    tables: [wgpu::Buffer; 4],
    /// Distinguishes scenes in the kept bind groups.
    id: u64,
    _blas: wgpu::Blas,
}

impl std::fmt::Debug for AoScene {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("AoScene").field("id", &self.id).finish_non_exhaustive()
    }
}

impl AoScene {
    /// The resource bound for scene input `name`.
    fn resource(&self, name: &str) -> wgpu::BindingResource<'_> {
        match SCENE_INPUTS.iter().position(|&n| n == name) {
            Some(0) => wgpu::BindingResource::AccelerationStructure(&self.tlas),
            Some(i) => self.tables[i - 1].as_entire_binding(),
            None => unreachable!("{name} is no scene input"),
        }
    }
}

/// A storage buffer of the graph (or an imported input) on the device.
struct DeviceBuffer {
    buffer: wgpu::Buffer,
    /// Its length in 32-bit elements.
    len: usize,
    /// What it was made for: its `Init::Fill` bits (`None`: no fill), kept in `AoEffect::fills`.
    fill: Option<u32>,
}

/// A compute pipeline, its bind-group layout (set 0) and the bindings its WGSL declares.
struct Pipeline {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    bindings: WgslBindings,
    /// The committed SPIR-V passed through: push constants as wgpu immediates.
    immediates: bool,
}

/// The bindings of group 0 a WGSL module declares.
#[derive(Clone, Debug, Default, PartialEq)]
struct WgslBindings {
    /// Storage buffers and textures.
    resources: Vec<u32>,
    /// The uniform buffer the push constants moved to (`None`: the kernel has none).
    constants: Option<u32>,
}

/// A pipeline: the entry point and its specialization (`(SpecId, value)`, the WGSL overrides).
type PipelineKey = (&'static str, Vec<(u32, u32)>);

/// The export adapter of each output format: its entry point and whether it has WGSL (the
/// others run only from SPIR-V, [`AoEffect::runs_spirv`]).
const EXPORTS: [(wgpu::TextureFormat, &str, bool); 3] = [
    (wgpu::TextureFormat::R32Float, "export_ao_r32f", true),
    (wgpu::TextureFormat::R16Float, "export_ao_r16f", false),
    (wgpu::TextureFormat::R8Unorm, "export_ao_r8", false),
];

/// Where a pass's constants and a resource's initial words lie in a frame's constant buffer.
#[derive(Clone, Debug, PartialEq)]
struct ConstantsLayout {
    /// Per graph pass: `(offset, size)` of its push constants, `None` without any.
    passes: Vec<Option<(u64, u64)>>,
    /// Per graph resource with [`Init::Data`]: `(offset, size)` of its words.
    data: Vec<Option<(u64, u64)>>,
    /// The bytes in all (the adapters' parameters first, at offset 0).
    bytes: Vec<u8>,
}

/// The constant buffer (the passes' push constants and the resources' initial words, copied in
/// by each frame's own commands) and the bind groups that bind it.
#[derive(Default)]
struct ConstantsBinding {
    buffer: Option<wgpu::Buffer>,
    /// The graph passes' bind groups and what they were made for.
    bound: Option<(BindKey, Vec<wgpu::BindGroup>)>,
}

/// What the bind groups depend on: the buffers' generation and, per pass, its pipeline
/// (a layout wgpu derives belongs to its pipeline alone), bindings and constants' place.
#[derive(Clone, PartialEq)]
struct BindKey {
    generation: u64,
    /// The scene bound ([`AoScene::id`]), if any pass binds one.
    scene: Option<u64>,
    passes: Vec<PassBinding>,
}

/// A pass's pipeline, `(slot, resource)` bindings and constants' `(offset, size)`.
type PassBinding = (PipelineKey, Vec<(u32, &'static str)>, Option<(u64, u64)>);

/// GPU timestamps at the beginning and end of each label's compute pass ([`AoEffect::set_timing`]).
struct Timing {
    queries: wgpu::QuerySet,
    /// Labels the query set has room for.
    capacity: usize,
    resolve: wgpu::Buffer,
    readback: wgpu::Buffer,
    /// The labels of the last recorded frame, in order.
    labels: Vec<&'static str>,
    /// A recorded frame's timestamps wait to be read ([`AoEffect::pass_times`]).
    pending: bool,
}

impl Timing {
    /// Room for `labels` labels' timestamps.
    fn ensure(&mut self, device: &wgpu::Device, labels: usize) {
        if labels > self.capacity {
            *self = Timing::new(device, labels.next_power_of_two());
        }
    }

    fn new(device: &wgpu::Device, capacity: usize) -> Timing {
        let stamps = 2 * capacity.max(1) as u32;
        let buffer = |usage| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("aokit timestamps"),
                size: 8 * u64::from(stamps),
                usage,
                mapped_at_creation: false,
            })
        };
        Timing {
            queries: device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("aokit timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count: stamps,
            }),
            capacity: capacity.max(1),
            resolve: buffer(wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC),
            readback: buffer(wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST),
            labels: Vec::new(),
            pending: false,
        }
    }
}

/// The graph built for the last frame and what it was built from.
struct BuiltGraph {
    desc: FrameDesc,
    /// Whether the frame gave normals (without them the graph derives them from depth first).
    normals: bool,
    graph: Graph,
}

/// Ambient occlusion on the application's wgpu device (see the crate documentation).
pub struct AoEffect {
    device: wgpu::Device,
    queue: wgpu::Queue,
    settings: AoSettings,
    size: Option<UVec2>,
    built: Option<BuiltGraph>,
    modules: HashMap<&'static str, wgpu::ShaderModule>,
    pipelines: HashMap<PipelineKey, Pipeline>,
    buffers: HashMap<&'static str, DeviceBuffer>,
    /// Per `Init::Fill` resource with non-zero bits: a buffer holding its initial contents.
    fills: HashMap<&'static str, wgpu::Buffer>,
    /// Bumped whenever a buffer is re-made: the bind groups made before bind stale buffers.
    generation: u64,
    constants: ConstantsBinding,
    timing: Option<Timing>,
}

impl std::fmt::Debug for AoEffect {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("AoEffect").field("settings", &self.settings).field("size", &self.size).finish_non_exhaustive()
    }
}

impl AoEffect {
    /// The effect on the application's `device` and `queue` running `settings`. A technique
    /// the effect cannot run on `device` (ray tracing without ray queries, raster passes) is
    /// refused here, not at the first `record`. The queue is where [`AoEffect::build_scene`]
    /// submits the acceleration-structure build; frames go into the application's encoders.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, settings: AoSettings) -> Result<AoEffect, AoError> {
        settings.check().map_err(AoError::Settings)?;
        let effect = AoEffect {
            device: device.clone(),
            queue: queue.clone(),
            settings,
            size: None,
            built: None,
            modules: HashMap::new(),
            pipelines: HashMap::new(),
            buffers: HashMap::new(),
            fills: HashMap::new(),
            generation: 0,
            constants: ConstantsBinding::default(),
            timing: None,
        };
        effect.check_graph(&effect.settings, &probe_frame(&effect.settings, None))?;
        Ok(effect)
    }

    /// Set the size of the application's textures (depth, normals, output) in texels. Call it
    /// before the first frame and whenever their size changes (new views of the same size need
    /// nothing: each frame binds the views it is given).
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), AoError> {
        if width == 0 || height == 0 || width > 16384 || height > 16384 {
            return Err(AoError::Settings(format!("image size {width}×{height}: expected 1…16384 per side")));
        }
        self.size = Some(UVec2::new(width, height));
        self.built = None;
        Ok(())
    }

    /// Replace the settings; the next frame runs them. Settings this crate cannot run are
    /// refused (and the old ones kept).
    pub fn set_settings(&mut self, settings: AoSettings) -> Result<(), AoError> {
        settings.check().map_err(AoError::Settings)?;
        self.check_graph(&settings, &probe_frame(&settings, self.size))?;
        self.settings = settings;
        self.built = None;
        Ok(())
    }

    /// The graph of `settings` for `desc` (ray-traced passes as ray queries), refused where this
    /// effect cannot run it on its device.
    fn check_graph(&self, settings: &AoSettings, desc: &FrameDesc) -> Result<Graph, AoError> {
        let technique = &settings.technique;
        let name = technique.name();
        let graph = technique.graph(desc).map_err(AoError::Settings)?.with_rt_mode(RtMode::Query);
        graph.validate().map_err(AoError::Settings)?;
        let refuse = |why: &str| Err(AoError::Frame(format!("{name} {why} (use aokit-vulkan)")));
        if settings.rt_mode == Some(RtMode::Pipeline) && graph.traces_rays() {
            return refuse("with ray-tracing pipelines: aokit-wgpu traces with ray queries only");
        }
        if graph.traces_rays() && !self.runs_ray_queries() {
            return refuse(
                "traces rays: aokit-wgpu traces them with ray queries on wgpu's Vulkan back-end, on a device made with RAY_QUERY_FEATURES and the adapter's limits",
            );
        }
        if graph.passes.iter().any(|p| p.kind != PassKind::Compute) {
            return refuse("rasterizes the scene itself: aokit-wgpu runs no raster pass");
        }
        let readable = |i: &&str| [inputs::LINEAR_DEPTH, inputs::VIEW_NORMALS].contains(i) || SCENE_INPUTS.contains(i);
        if let Some(input) = graph.inputs().iter().find(|i| !readable(i)) {
            return refuse(&format!("reads {input}, which aokit-wgpu does not take"));
        }
        let runs =
            |entry: &str| modules::wgsl(entry).is_some() || self.runs_spirv() && modules::spirv(entry, &[]).is_some();
        if let Some(p) = graph.passes.iter().find(|p| !runs(p.entry())) {
            return refuse(&format!("has a pass this device cannot run ({}: no WGSL)", p.entry()));
        }
        if let Some(r) = graph.resources.iter().find(|r| inputs::ALL.contains(&r.name)) {
            return Err(AoError::Settings(format!("{name} declares a resource named like an input: {}", r.name)));
        }
        Ok(graph)
    }

    /// Refuse textures the adapters cannot read or write, with the reason (wgpu would otherwise
    /// report a validation error at the submission).
    fn check_textures(&self, frame: &AoFrame, size: UVec2) -> Result<(), AoError> {
        let extent = |t: &wgpu::Texture| UVec2::new(t.width(), t.height());
        let output = frame.output.texture();
        if self.export_entry(output.format()).is_none()
            || !output.usage().contains(wgpu::TextureUsages::STORAGE_BINDING)
        {
            let formats: Vec<_> = EXPORTS.iter().filter(|e| self.export_entry(e.0).is_some()).map(|e| e.0).collect();
            return Err(AoError::Frame(format!(
                "the output is {:?} with {:?}: expected one of {formats:?} with STORAGE_BINDING",
                output.format(),
                output.usage()
            )));
        }
        let depth = frame.depth.texture().format();
        let linear = frame.depth_convention == DepthConvention::Linear;
        if linear != (depth == wgpu::TextureFormat::R32Float) || !linear && !depth.is_depth_stencil_format() {
            return Err(AoError::Frame(format!(
                "the depth texture is {depth:?} with {:?}: expected a depth format, or R32Float with DepthConvention::Linear",
                frame.depth_convention
            )));
        }
        if let Some(normals) = frame.normals {
            let format = normals.texture().format();
            let float = matches!(format.sample_type(None, None), Some(wgpu::TextureSampleType::Float { .. }));
            if !float {
                return Err(AoError::Frame(format!(
                    "the normal texture is {format:?}: expected a float-readable format"
                )));
            }
        }
        let inputs = std::iter::once(("depth", frame.depth)).chain(frame.normals.map(|n| ("normals", n)));
        for (what, view) in std::iter::once(("output", frame.output)).chain(inputs) {
            let texture = view.texture();
            if extent(texture) != size {
                return Err(AoError::Frame(format!(
                    "the {what} texture is {}×{}, the effect {}×{}: call AoEffect::resize",
                    texture.width(),
                    texture.height(),
                    size.x,
                    size.y
                )));
            }
            if texture.sample_count() != 1 {
                return Err(AoError::Frame(format!(
                    "the {what} texture is multisampled ({}×): resolve it first",
                    texture.sample_count()
                )));
            }
            if what != "output" && !texture.usage().contains(wgpu::TextureUsages::TEXTURE_BINDING) {
                return Err(AoError::Frame(format!("the {what} texture lacks TEXTURE_BINDING usage")));
            }
        }
        Ok(())
    }

    /// The export adapter that writes `format`: `R32Float` on every path, `R16Float` and
    /// `R8Unorm` where the effect runs SPIR-V.
    fn export_entry(&self, format: wgpu::TextureFormat) -> Option<&'static str> {
        let (_, entry, wgsl) = EXPORTS.iter().find(|e| e.0 == format)?;
        (*wgsl || self.runs_spirv()).then_some(*entry)
    }

    /// Does the effect run the ray-traced techniques (ray queries in the committed SPIR-V)? It
    /// does where it runs the SPIR-V ([`AoEffect::runs_spirv`]) on a device made with
    /// [`RAY_QUERY_FEATURES`] and limits that hold every ray-query kernel's buffers and one
    /// BLAS, TLAS instance and acceleration structure binding (request the adapter's limits).
    pub fn runs_ray_queries(&self) -> bool {
        let tracing = |k: &&&Kernel| k.bindings.iter().any(|b| b.kind == BindingKind::AccelerationStructure);
        let buffers = |k: &&Kernel| k.bindings.iter().filter(|b| b.kind == BindingKind::StorageBuffer).count() as u32;
        let needed = Kernel::all().iter().filter(tracing).map(buffers).max().unwrap_or(0);
        let limits = self.device.limits();
        self.runs_spirv()
            && self.device.features().contains(RAY_QUERY_FEATURES)
            && limits.max_storage_buffers_per_shader_stage >= needed
            && limits.max_acceleration_structures_per_shader_stage >= 1
            && limits.max_blas_geometry_count >= 1
            && limits.max_tlas_instance_count >= 1
    }

    /// Build the acceleration structure of `geometry` for the ray-traced techniques (a BLAS of
    /// its triangles, a TLAS of one instance) and upload the alpha-test tables; submitted to the
    /// effect's queue at once (frames submitted after it see it built). Needs
    /// [`AoEffect::runs_ray_queries`].
    pub fn build_scene(&mut self, geometry: &SceneGeometry) -> Result<AoScene, AoError> {
        if !self.runs_ray_queries() {
            return Err(AoError::Frame(
                "build_scene needs ray queries: a Vulkan device made with RAY_QUERY_FEATURES and the adapter's limits"
                    .into(),
            ));
        }
        let g = geometry;
        let triangles = g.positions.len() / 3;
        if triangles == 0
            || !g.positions.len().is_multiple_of(3)
            || g.uvs.len() != g.positions.len()
            || g.materials.len() != triangles
        {
            return Err(AoError::Frame(format!(
                "ray-tracing scene: {} corners, {} uvs, {} materials (expected 3 corners and 3 uvs per triangle, one material)",
                g.positions.len(),
                g.uvs.len(),
                g.materials.len()
            )));
        }
        let most = self.device.limits().max_blas_primitive_count as usize;
        if triangles > most {
            return Err(AoError::Frame(format!(
                "ray-tracing scene: {triangles} triangles, the device's BLAS holds {most}"
            )));
        }
        use wgpu::util::DeviceExt;
        let device = &self.device;
        let buffer = |label: &str, bytes: &[u8], usage: wgpu::BufferUsages| {
            // A binding is never empty: a table without entries is one zero word.
            let contents = if bytes.is_empty() { &[0u8; 4][..] } else { bytes };
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some(label), contents, usage })
        };
        let vertices =
            buffer("aokit scene vertices", bytemuck::cast_slice(g.positions), wgpu::BufferUsages::BLAS_INPUT);
        let masked = g.mask_headers.iter().any(|h| h.width > 0);
        // The any-hit alpha test runs only on triangles not flagged opaque.
        let flags = if masked {
            wgpu::AccelerationStructureGeometryFlags::empty()
        } else {
            wgpu::AccelerationStructureGeometryFlags::OPAQUE
        };
        let size = wgpu::BlasTriangleGeometrySizeDescriptor {
            vertex_format: wgpu::VertexFormat::Float32x3,
            vertex_count: g.positions.len() as u32,
            index_format: None,
            index_count: None,
            flags,
        };
        let blas = device.create_blas(
            &wgpu::CreateBlasDescriptor {
                label: Some("aokit scene"),
                flags: wgpu::AccelerationStructureFlags::PREFER_FAST_TRACE,
                update_mode: wgpu::AccelerationStructureUpdateMode::Build,
            },
            wgpu::BlasGeometrySizeDescriptors::Triangles { descriptors: vec![size.clone()] },
        );
        let mut tlas = device.create_tlas(&wgpu::CreateTlasDescriptor {
            label: Some("aokit scene"),
            max_instances: 1,
            flags: wgpu::AccelerationStructureFlags::PREFER_FAST_TRACE,
            update_mode: wgpu::AccelerationStructureUpdateMode::Build,
        });
        // One instance, identity transform, custom index 0: the any-hit reads triangle
        // `InstanceCustomIndex + PrimitiveId` of the tables (as aokit-vulkan's TLAS).
        let identity = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0];
        tlas[0] = Some(wgpu::TlasInstance::new(&blas, identity, 0, 0xff));
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("aokit scene") });
        let geometry = wgpu::BlasTriangleGeometry {
            size: &size,
            vertex_buffer: &vertices,
            first_vertex: 0,
            vertex_stride: 12,
            index_buffer: None,
            first_index: None,
            transform_buffer: None,
            transform_buffer_offset: None,
        };
        let entry =
            wgpu::BlasBuildEntry { blas: &blas, geometry: wgpu::BlasGeometries::TriangleGeometries(vec![geometry]) };
        encoder.build_acceleration_structures(std::iter::once(&entry), std::iter::once(&tlas));
        self.queue.submit([encoder.finish()]);
        let storage = wgpu::BufferUsages::STORAGE;
        let tables = [
            buffer("aokit scene uvs", bytemuck::cast_slice(g.uvs), storage),
            buffer("aokit scene materials", bytemuck::cast_slice(g.materials), storage),
            buffer("aokit scene mask headers", bytemuck::cast_slice(g.mask_headers), storage),
            buffer("aokit scene mask texels", bytemuck::cast_slice(g.mask_texels), storage),
        ];
        // Unique across effects: a scene built by another effect never matches kept bind groups.
        static SCENES: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
        let id = SCENES.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
        Ok(AoScene { tlas, tables, id, _blas: blas })
    }

    /// Does the effect run the committed SPIR-V itself (the same modules as `aokit-vulkan`)
    /// rather than the WGSL? It does on wgpu's Vulkan back-end when the device was made with
    /// [`SPIRV_FEATURES`] and a `max_immediate_size` that holds every kernel's push constants
    /// (request the adapter's: `Limits { max_immediate_size: adapter.limits().max_immediate_size,
    /// .. }`). The texture import and export run from it too.
    pub fn runs_spirv(&self) -> bool {
        let largest = Kernel::all().iter().map(|k| k.push_constant_bytes().next_multiple_of(4)).max().unwrap_or(0);
        self.device.features().contains(SPIRV_FEATURES)
            && self.device.adapter_info().backend == wgpu::Backend::Vulkan
            && self.device.limits().max_immediate_size >= largest
    }

    /// Does the technique trace rays at the current size and settings (then every frame needs
    /// [`AoFrame::scene`], from [`AoEffect::build_scene`])?
    pub fn traces_rays(&self) -> Result<bool, AoError> {
        let size = self.size.ok_or(AoError::NotResized)?;
        let s = &self.settings;
        Ok(s.technique.graph(&probe_frame(s, Some(size))).map_err(AoError::Settings)?.traces_rays())
    }

    /// The settings in use.
    pub fn settings(&self) -> &AoSettings {
        &self.settings
    }

    /// Time each pass label of the frames recorded from now on with GPU timestamps (`on`), or
    /// stop. Needs a device made with `Features::TIMESTAMP_QUERY`. Timed frames record one
    /// compute pass per label instead of one in all.
    pub fn set_timing(&mut self, on: bool) -> Result<(), AoError> {
        if !on {
            self.timing = None;
        } else if !self.device.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
            return Err(AoError::Frame("timing needs a device with Features::TIMESTAMP_QUERY".into()));
        } else if self.timing.is_none() {
            self.timing = Some(Timing::new(&self.device, 8));
        }
        Ok(())
    }

    /// `(pass label, ms)` of the last recorded frame (with [`AoEffect::set_timing`] on): the
    /// texture import ([`IMPORT_LABEL`]), the graph's labels, the export ([`EXPORT_LABEL`]); once:
    /// call it after that frame's submission and before the next `record`. It waits for the
    /// device to finish everything submitted (`Device::poll`), so it is for profiling, not for
    /// every frame of a shipped application; on the web, where polling does not wait, it fails.
    pub fn pass_times(&mut self) -> Result<Vec<(&'static str, f64)>, AoError> {
        let timing =
            self.timing.as_mut().ok_or_else(|| AoError::Frame("timing is off: AoEffect::set_timing(true)".into()))?;
        if !std::mem::take(&mut timing.pending) {
            return Err(AoError::Frame("no timed frame to read: record (and submit) one first".into()));
        }
        let bytes = 16 * timing.labels.len() as u64;
        if bytes == 0 {
            return Ok(Vec::new());
        }
        let slice = timing.readback.slice(..bytes);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        let waited = self.device.poll(wgpu::PollType::wait_indefinitely());
        let ticks: Result<Vec<u64>, String> = match waited {
            Ok(_) => slice.get_mapped_range().map(|m| bytemuck::cast_slice(&m).to_vec()).map_err(|e| e.to_string()),
            Err(e) => Err(e.to_string()),
        };
        // Unmapped whatever happened: the next timed frame copies into it.
        timing.readback.unmap();
        let ticks = ticks.map_err(|e| AoError::Frame(format!("reading the timestamps: {e}")))?;
        let period = f64::from(self.queue.get_timestamp_period());
        Ok(timing
            .labels
            .iter()
            .zip(ticks.chunks(2))
            .map(|(&label, t)| (label, t[1].wrapping_sub(t[0]) as f64 * period * 1e-6))
            .collect())
    }

    /// Record one frame into `encoder`: import the depth (and normals), run the technique's
    /// passes, export the AO into `frame.output`. Everything the frame needs is written by its
    /// own commands (its constants are copied in from a small buffer made for it), so any number
    /// of frames may be recorded before they are submitted, as long as they are submitted in the
    /// order they were recorded.
    pub fn record(&mut self, encoder: &mut wgpu::CommandEncoder, frame: &AoFrame) -> Result<(), AoError> {
        let size = self.size.ok_or(AoError::NotResized)?;
        let (desc, import) = engine_frame(
            &self.settings,
            size,
            frame.projection,
            frame.view,
            frame.depth_convention,
            frame.frame_index,
            frame.previous_view,
        )
        .map_err(AoError::Projection)?;
        self.check_textures(frame, size)?;
        let normals = frame.normals.is_some();
        let built = match self.built.take() {
            Some(b) if b.desc == desc && b.normals == normals => b,
            _ => {
                let graph = self.check_graph(&self.settings, &desc)?;
                // Without the application's normals, the graph derives them from depth first.
                let mut graph = if normals { graph } else { graph.with_normals_from_depth() };
                // Diagnostic copies are for reports, not application frames.
                graph.snapshots.clear();
                BuiltGraph { desc, normals, graph }
            }
        };
        let recorded = self.record_graph(encoder, frame, &built.graph, &import);
        self.built = Some(built);
        recorded
    }

    /// [`AoEffect::record`] of `graph` with the adapters' parameters `import`.
    fn record_graph(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        frame: &AoFrame,
        graph: &Graph,
        import: &ImportParams,
    ) -> Result<(), AoError> {
        // What can fail does so before anything is recorded.
        if graph.traces_rays() && frame.scene.is_none() {
            let name = self.settings.technique.name();
            return Err(AoError::Frame(format!(
                "{name} traces rays: give the scene (AoEffect::build_scene, AoFrame::scene)"
            )));
        }
        // Every buffer within the device's limits (wgpu would panic on a larger one).
        let limits = self.device.limits();
        let most = limits.max_storage_buffer_binding_size.min(limits.max_buffer_size);
        let pixels = u64::from(graph.view.size().x) * u64::from(graph.view.size().y);
        let largest = graph.resources.iter().map(|r| r.len(&graph.view) as u64).max().unwrap_or(0).max(pixels);
        if 4 * largest > most {
            let full = graph.view.size();
            return Err(AoError::Frame(format!(
                "a {}×{} target needs storage buffers of {} bytes; the device allows {most} (request larger limits or a smaller size)",
                full.x,
                full.y,
                4 * largest
            )));
        }
        let export = self.export_entry(frame.output.texture().format()).expect("checked by check_textures");
        let keys = self.prepare_pipelines(graph, export)?;
        let made = self.ensure_buffers(graph);
        let alignment = u64::from(self.device.limits().min_uniform_buffer_offset_alignment);
        let layout = constants_layout(graph, import, alignment);
        self.ensure_constants(&layout);
        let constants = self.constants.buffer.clone().expect("made above");
        // This frame's constants, copied in by its own commands: a frame recorded later cannot
        // overwrite them before this one ran (`Queue::write_buffer` would land before every
        // command of the next submission).
        let staging = wgpu::util::DeviceExt::create_buffer_init(
            &self.device,
            &wgpu::util::BufferInitDescriptor {
                label: Some("aokit frame constants"),
                contents: &layout.bytes,
                usage: wgpu::BufferUsages::COPY_SRC,
            },
        );
        encoder.copy_buffer_to_buffer(&staging, 0, &constants, 0, layout.bytes.len() as u64);
        // Each resource's initial contents, in the encoder: ordered after the previous frame.
        for (r, data) in graph.resources.iter().zip(&layout.data) {
            if r.lifetime == Lifetime::Persistent && !made.contains(&r.name) {
                continue;
            }
            let buffer = &self.buffers[r.name].buffer;
            match (&r.init, data) {
                (Init::Fill(0), _) => encoder.clear_buffer(buffer, 0, None),
                (Init::Fill(_), _) => encoder.copy_buffer_to_buffer(&self.fills[r.name], 0, buffer, 0, buffer.size()),
                (Init::Data(_), Some((offset, bytes))) => {
                    encoder.copy_buffer_to_buffer(&constants, *offset, buffer, 0, *bytes)
                }
                _ => {}
            }
        }
        self.ensure_bind_groups((graph, frame.scene.filter(|_| graph.traces_rays())), &keys, &layout);
        let adapters = self.adapter_bind_groups(&constants, frame, (graph.output, export));
        // Consecutive passes with one label are timed as one (as the Vulkan executor does).
        let mut spans: Vec<(&'static str, std::ops::Range<usize>)> = Vec::new();
        for (i, p) in graph.passes.iter().enumerate() {
            match spans.last_mut() {
                Some((label, range)) if *label == p.label => range.end = i + 1,
                _ => spans.push((p.label, i..i + 1)),
            }
        }
        if let Some(timing) = &mut self.timing {
            timing.ensure(&self.device, spans.len() + 2);
            let labels = spans.iter().map(|s| s.0);
            timing.labels = std::iter::once(IMPORT_LABEL).chain(labels).chain([EXPORT_LABEL]).collect();
            timing.pending = true;
        }
        let groups = &self.constants.bound.as_ref().expect("made above").1;
        let dispatch = |pass: &mut wgpu::ComputePass, i: usize| {
            let p = &graph.passes[i];
            let invocations = p.invocations(&graph.view);
            let threads = p.kernel.threads;
            let pipeline = &self.pipelines[&keys[i]];
            pass.set_pipeline(&pipeline.pipeline);
            pass.set_bind_group(0, &groups[i], &[]);
            if pipeline.immediates && !p.push_constants.is_empty() {
                let mut bytes = p.push_constants.clone();
                bytes.resize(bytes.len().next_multiple_of(4), 0);
                pass.set_immediates(0, &bytes);
            }
            pass.dispatch_workgroups(invocations.x.div_ceil(threads[0]), invocations.y.div_ceil(threads[1]), 1);
        };
        let adapter = |pass: &mut wgpu::ComputePass, entry: &'static str, group: &wgpu::BindGroup, size: UVec2| {
            let pipeline = &self.pipelines[&(entry, Vec::new())];
            pass.set_pipeline(&pipeline.pipeline);
            pass.set_bind_group(0, group, &[]);
            if pipeline.immediates {
                pass.set_immediates(0, bytemuck::bytes_of(import));
            }
            pass.dispatch_workgroups(size.x.div_ceil(ADAPTER_GROUP), size.y.div_ceil(ADAPTER_GROUP), 1);
        };
        let begin = |encoder: &mut wgpu::CommandEncoder, stamps: Option<u32>| {
            let timestamp_writes = stamps.zip(self.timing.as_ref()).map(|(k, t)| wgpu::ComputePassTimestampWrites {
                query_set: &t.queries,
                beginning_of_pass_write_index: Some(2 * k),
                end_of_pass_write_index: Some(2 * k + 1),
            });
            encoder
                .begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some("aokit"), timestamp_writes })
                .forget_lifetime()
        };
        let (full, engine) = (import.view.size(), import.engine_size);
        let mut pass = begin(encoder, self.timing.as_ref().map(|_| 0));
        adapter(&mut pass, "import_depth", &adapters[0], full);
        if let Some(group) = adapters.get(2) {
            adapter(&mut pass, "import_normals", group, full);
        }
        if let Some(timing) = &self.timing {
            // One compute pass per label, its timestamps at its beginning and end: the import,
            // each of the graph's labels, the export.
            drop(pass);
            for (k, (_, range)) in spans.iter().enumerate() {
                let mut pass = begin(encoder, Some(k as u32 + 1));
                range.clone().for_each(|i| dispatch(&mut pass, i));
            }
            pass = begin(encoder, Some(spans.len() as u32 + 1));
            adapter(&mut pass, export, &adapters[1], engine);
            drop(pass);
            let stamps = 2 * timing.labels.len() as u32;
            encoder.resolve_query_set(&timing.queries, 0..stamps, &timing.resolve, 0);
            encoder.copy_buffer_to_buffer(&timing.resolve, 0, &timing.readback, 0, 8 * u64::from(stamps));
        } else {
            (0..graph.passes.len()).for_each(|i| dispatch(&mut pass, i));
            adapter(&mut pass, export, &adapters[1], engine);
        }
        Ok(())
    }

    /// Every pipeline `graph` and the adapters need, made where missing; returns each pass's
    /// pipeline key.
    fn prepare_pipelines(&mut self, graph: &Graph, export: &'static str) -> Result<Vec<PipelineKey>, AoError> {
        let adapters = ["import_depth", "import_normals", export].map(|entry| {
            let kernel = Kernel::find(entry).expect("the adapters are kernels");
            (kernel, Vec::new())
        });
        let passes = graph.passes.iter().map(|p| (p.kernel, p.push_constants.clone()));
        let mut keys = Vec::new();
        for (i, (kernel, push)) in adapters.into_iter().chain(passes).enumerate() {
            let key = pipeline_key(kernel, &push)?;
            if !self.pipelines.contains_key(&key) {
                let pipeline = self.make_pipeline(kernel, &key.1)?;
                self.pipelines.insert(key.clone(), pipeline);
            }
            if i >= 3 {
                keys.push(key);
            }
        }
        Ok(keys)
    }

    /// The compute pipeline of `kernel` with the WGSL overrides `specialization`, with the
    /// layout wgpu derives from the WGSL.
    fn make_pipeline(&mut self, kernel: &'static Kernel, specialization: &[(u32, u32)]) -> Result<Pipeline, AoError> {
        if let Some(pipeline) = self.spirv_pipeline(kernel, specialization) {
            return Ok(pipeline);
        }
        let source = modules::wgsl(kernel.entry).ok_or_else(|| {
            AoError::Frame(format!("pass {} has no WGSL module: aokit-wgpu cannot run it", kernel.entry))
        })?;
        let device = &self.device;
        // wgpu's own runtime checks stay on: trusting the modules (`create_shader_module_trusted`)
        // measured no faster on lavapipe (gtao 1.14–1.21 vs 1.21 of the ash time, vao 1.14–1.15
        // vs 1.14–1.18, 1920×1080, two runs each).
        let module = self.modules.entry(kernel.entry).or_insert_with(|| {
            device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(kernel.entry),
                source: wgpu::ShaderSource::Wgsl(source.into()),
            })
        });
        let ids: Vec<(String, f64)> = specialization.iter().map(|(id, v)| (id.to_string(), f64::from(*v))).collect();
        let constants: Vec<(&str, f64)> = ids.iter().map(|(id, v)| (id.as_str(), *v)).collect();
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(kernel.entry),
            layout: None,
            module,
            entry_point: None,
            compilation_options: wgpu::PipelineCompilationOptions { constants: &constants, ..Default::default() },
            cache: None,
        });
        let layout = pipeline.get_bind_group_layout(0);
        Ok(Pipeline { pipeline, layout, bindings: wgsl_bindings(source), immediates: false })
    }

    /// The pipeline of `kernel` from the committed SPIR-V itself (specialized, its push
    /// constants as immediates, the layout its declaration gives), where the effect runs SPIR-V
    /// ([`AoEffect::runs_spirv`]); else `None` (the WGSL path).
    fn spirv_pipeline(&self, kernel: &'static Kernel, specialization: &[(u32, u32)]) -> Option<Pipeline> {
        let device = &self.device;
        let push = kernel.push_constant_bytes().next_multiple_of(4);
        let usable = self.runs_spirv();
        if !usable {
            return None;
        }
        let words = modules::spirv(kernel.entry, specialization)?;
        let [x, y, z] = kernel.threads;
        let descriptor = wgpu::ShaderModuleDescriptorPassthrough {
            label: Some(kernel.entry),
            entry_points: vec![wgpu::PassthroughShaderEntryPoint {
                name: kernel.entry.into(),
                workgroup_size: (x, y, z),
            }]
            .into(),
            spirv: Some(words.into()),
            ..Default::default()
        };
        // SAFETY: the module is one of the committed SPIR-V modules that aokit-vulkan runs on
        // Vulkan (validated by spirv-val in tests/spirv_assets.rs), with only its specialization
        // constants' defaults changed to the values aokit-vulkan specializes it with; the layout
        // below is its kernel's declaration, which tests/pass_graph.rs checks against the
        // module's reflection.
        let module = unsafe { device.create_shader_module_passthrough(descriptor) };
        let entries: Vec<wgpu::BindGroupLayoutEntry> = kernel
            .bindings
            .iter()
            .map(|b| wgpu::BindGroupLayoutEntry {
                binding: b.slot,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: match b.kind {
                    BindingKind::AccelerationStructure => {
                        wgpu::BindingType::AccelerationStructure { vertex_return: false }
                    }
                    // The adapters: the application's texture read (`sampled`) or the AO written
                    // in the format the declaration names.
                    BindingKind::Image if b.rust_type.contains("sampled=false") => wgpu::BindingType::StorageTexture {
                        access: wgpu::StorageTextureAccess::WriteOnly,
                        format: EXPORTS
                            .iter()
                            .find(|e| b.rust_type.contains(&format!("format={}", &e.1["export_ao_".len()..])))
                            .map_or(wgpu::TextureFormat::R32Float, |e| e.0),
                        view_dimension: wgpu::TextureViewDimension::D2,
                    },
                    BindingKind::Image => wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: false },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    _ => wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Storage { read_only: !b.access.writes() },
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                },
                count: None,
            })
            .collect();
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some(kernel.entry),
            entries: &entries,
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(kernel.entry),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: push,
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(kernel.entry),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some(kernel.entry),
            compilation_options: Default::default(),
            cache: None,
        });
        let bindings = WgslBindings { resources: kernel.bindings.iter().map(|b| b.slot).collect(), constants: None };
        Some(Pipeline { pipeline, layout, bindings, immediates: true })
    }

    /// The graph's buffers (and the imported depth and normals) at their sizes for its view,
    /// made or re-made where missing or resized; returns the names of those made.
    fn ensure_buffers(&mut self, graph: &Graph) -> Vec<&'static str> {
        let pixels = graph.view.size().x as usize * graph.view.size().y as usize;
        let wanted = graph
            .resources
            .iter()
            .map(|r| (r.name, r.len(&graph.view), &r.init))
            .chain([inputs::LINEAR_DEPTH, inputs::VIEW_NORMALS].map(|name| (name, pixels, &Init::Undefined)));
        let mut made = Vec::new();
        for (name, len, init) in wanted {
            let fill = if let Init::Fill(bits) = *init { Some(bits) } else { None };
            if self.buffers.get(name).is_some_and(|b| b.len == len && b.fill == fill) {
                continue;
            }
            let buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(name),
                size: 4 * len.max(1) as u64,
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            });
            if let Init::Fill(bits) = *init
                && bits != 0
            {
                let words = vec![bits; len.max(1)];
                let fill = wgpu::util::DeviceExt::create_buffer_init(
                    &self.device,
                    &wgpu::util::BufferInitDescriptor {
                        label: Some(name),
                        contents: bytemuck::cast_slice(&words),
                        usage: wgpu::BufferUsages::COPY_SRC,
                    },
                );
                self.fills.insert(name, fill);
            }
            self.buffers.insert(name, DeviceBuffer { buffer, len, fill });
            made.push(name);
        }
        if !made.is_empty() {
            self.generation += 1;
        }
        made
    }

    /// The constant buffer, re-made when `layout` outgrows it.
    fn ensure_constants(&mut self, layout: &ConstantsLayout) {
        let size = layout.bytes.len() as u64;
        let s = &mut self.constants;
        if s.buffer.as_ref().is_none_or(|b| b.size() < size) {
            s.buffer = Some(self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("aokit constants"),
                size: size.next_power_of_two().max(256),
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }));
            s.bound = None;
        }
    }

    /// The bind groups of the graph's passes, re-made when the buffers, the passes, the scene
    /// or the constants' places changed.
    fn ensure_bind_groups(
        &mut self,
        (graph, scene): (&Graph, Option<&AoScene>),
        keys: &[PipelineKey],
        layout: &ConstantsLayout,
    ) {
        let key = BindKey {
            generation: self.generation,
            scene: scene.map(|s| s.id),
            passes: graph
                .passes
                .iter()
                .zip(keys)
                .zip(&layout.passes)
                .map(|((p, k), c)| (k.clone(), p.bindings.iter().map(|b| (b.slot, b.resource)).collect(), *c))
                .collect(),
        };
        if self.constants.bound.as_ref().is_some_and(|(k, _)| *k == key) {
            return;
        }
        let constants = self.constants.buffer.as_ref().expect("made before");
        let groups = graph
            .passes
            .iter()
            .zip(keys)
            .zip(&layout.passes)
            .map(|((p, k), c)| {
                let pipeline = &self.pipelines[k];
                let mut entries: Vec<wgpu::BindGroupEntry> = p
                    .bindings
                    .iter()
                    .filter(|b| pipeline.bindings.resources.contains(&b.slot))
                    .map(|b| wgpu::BindGroupEntry {
                        binding: b.slot,
                        resource: match scene {
                            Some(scene) if SCENE_INPUTS.contains(&b.resource) => scene.resource(b.resource),
                            _ => self.buffers[b.resource].buffer.as_entire_binding(),
                        },
                    })
                    .collect();
                if let (Some(binding), Some((offset, size))) = (pipeline.bindings.constants, c) {
                    entries.push(uniform_entry(binding, constants, *offset, *size));
                }
                self.device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some(p.entry()),
                    layout: &pipeline.layout,
                    entries: &entries,
                })
            })
            .collect();
        self.constants.bound = Some((key, groups));
    }

    /// The adapters' bind groups for this frame's textures: import depth, export, and import
    /// normals where the frame gives them (made every frame: they bind the application's
    /// views, which it may replace at any time).
    fn adapter_bind_groups(
        &self,
        constants: &wgpu::Buffer,
        frame: &AoFrame,
        (output, export): (&'static str, &'static str),
    ) -> Vec<wgpu::BindGroup> {
        let params = std::mem::size_of::<ImportParams>() as u64;
        let group = |entry: &'static str, texture: &wgpu::TextureView, buffer: &'static str| {
            let pipeline = &self.pipelines[&(entry, Vec::new())];
            // import_*: texture 0, buffer 1; export: buffer 0, texture 1; constants at 2.
            let (texture_slot, buffer_slot) = if entry == export { (1, 0) } else { (0, 1) };
            let mut entries = vec![
                wgpu::BindGroupEntry { binding: texture_slot, resource: wgpu::BindingResource::TextureView(texture) },
                wgpu::BindGroupEntry {
                    binding: buffer_slot,
                    resource: self.buffers[buffer].buffer.as_entire_binding(),
                },
            ];
            // From WGSL the parameters are a uniform buffer; from SPIR-V, immediates.
            if let Some(slot) = pipeline.bindings.constants {
                entries.push(uniform_entry(slot, constants, 0, params));
            }
            self.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some(entry),
                layout: &pipeline.layout,
                entries: &entries,
            })
        };
        let mut groups = vec![group("import_depth", frame.depth, inputs::LINEAR_DEPTH)];
        groups.push(group(export, frame.output, output));
        if let Some(normals) = frame.normals {
            groups.push(group("import_normals", normals, inputs::VIEW_NORMALS));
        }
        groups
    }
}

/// `pass`'s pipeline key: its entry point and specialization for its push constants.
fn pipeline_key(kernel: &'static Kernel, push: &[u8]) -> Result<PipelineKey, AoError> {
    Ok((kernel.entry, kernel.specialization_for(push).map_err(AoError::Settings)?))
}

/// Where each pass's push constants and each resource's initial words go in a frame's constant
/// buffer: the adapters' parameters at 0, then each at the next multiple of `alignment` (the
/// device's uniform offset alignment), each padded to 16 bytes (a uniform struct's size).
fn constants_layout(graph: &Graph, import: &ImportParams, alignment: u64) -> ConstantsLayout {
    let mut bytes = bytemuck::bytes_of(import).to_vec();
    let mut place = |data: &[u8]| {
        bytes.resize((bytes.len() as u64).next_multiple_of(alignment) as usize, 0);
        let offset = bytes.len() as u64;
        bytes.extend_from_slice(data);
        bytes.resize(bytes.len().next_multiple_of(16), 0);
        (offset, (data.len() as u64).next_multiple_of(4))
    };
    let passes =
        graph.passes.iter().map(|p| (!p.push_constants.is_empty()).then(|| place(&p.push_constants))).collect();
    let data = graph
        .resources
        .iter()
        .map(|r| match &r.init {
            Init::Data(words) => Some(place(bytemuck::cast_slice(words))),
            _ => None,
        })
        .collect();
    bytes.resize(bytes.len().next_multiple_of(16), 0);
    ConstantsLayout { passes, data, bytes }
}

/// A uniform binding of `size` bytes (rounded up to a uniform struct's 16) at `offset`.
fn uniform_entry(binding: u32, buffer: &wgpu::Buffer, offset: u64, size: u64) -> wgpu::BindGroupEntry<'_> {
    wgpu::BindGroupEntry {
        binding,
        resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
            buffer,
            offset,
            size: std::num::NonZeroU64::new(size.next_multiple_of(16)),
        }),
    }
}

/// The group-0 bindings of a generated WGSL module: `@group(0) @binding(N)` before each
/// resource's `var`, the uniform one being the push constants' (`aokit_contract::wgsl`).
fn wgsl_bindings(source: &str) -> WgslBindings {
    let mut found = WgslBindings::default();
    let mut lines = source.lines();
    while let Some(line) = lines.next() {
        let Some(rest) = line.trim().strip_prefix("@group(0) @binding(") else { continue };
        let Some(binding) = rest.split(')').next().and_then(|n| n.parse().ok()) else { continue };
        let declaration = lines.next().unwrap_or_default();
        if declaration.trim_start().starts_with("var<uniform>") {
            found.constants = Some(binding);
        } else {
            found.resources.push(binding);
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `(SpecId, default)` of every 32-bit `OpSpecConstant` of `words`.
    fn spec_defaults(words: &[u32]) -> Vec<(u32, u32)> {
        let mut at = 5;
        let (mut ids, mut constants) = (Vec::new(), Vec::new());
        while at < words.len() {
            let (op, count) = (words[at] & 0xffff, (words[at] >> 16) as usize);
            if op == 71 && count >= 4 && words[at + 2] == 1 {
                ids.push((words[at + 1], words[at + 3]));
            } else if op == 50 && count == 4 {
                constants.push((words[at + 2], words[at + 3]));
            }
            at += count.max(1);
        }
        let mut out: Vec<(u32, u32)> = ids
            .iter()
            .filter_map(|(target, id)| constants.iter().find(|c| c.0 == *target).map(|c| (*id, c.1)))
            .collect();
        out.sort();
        out
    }

    #[test]
    fn specialization_sets_exactly_the_listed_spec_constants() {
        let kernel = Kernel::find("gtao_main").unwrap();
        let original = modules::spirv("gtao_main", &[]).unwrap();
        let before = spec_defaults(&original);
        assert_eq!(before.len(), kernel.specialization.len(), "{before:?}");
        assert!(before.iter().all(|c| c.1 == 0), "{before:?}");
        let values = [(0, 1), (4, 7)];
        let patched = modules::spirv("gtao_main", &values).unwrap();
        let after = spec_defaults(&patched);
        for (id, value) in after {
            let want = values.iter().find(|v| v.0 == id).map_or(0, |v| v.1);
            assert_eq!(value, want, "SpecId {id}");
        }
        // Nothing else changed.
        let changed = original.iter().zip(&patched).filter(|(a, b)| a != b).count();
        assert_eq!((changed, original.len()), (2, patched.len()));
    }
}
