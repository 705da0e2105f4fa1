//! A technique as data: the pass graph every executor walks (host side only).
//!
//! A [`Graph`] lists the technique's resources (storage buffers of 32-bit elements, sized from
//! the target) and its passes in order (kernel entry point, which resource each binding slot is
//! and how it is accessed — both as the kernel's signature declares them, [`crate::kernel`](mod@crate::kernel) —
//! the number of invocations, the push constants). The CPU simulator
//! (`aokit_cpu::graph`) calls the kernels' functions for each pass; the Vulkan executor
//! (`aokit_vulkan::AoContext`) records the same passes with barriers derived from the accesses.
//! Neither knows a technique by name, so the order of passes exists exactly once: in the
//! technique's `graph()` beside its kernels.
//!
//! A graph is built per frame from the settings and the camera (cheap: a few small vectors);
//! executors keep resources and pipelines across frames and re-create a resource only when its
//! size changes.

use crate::common::camera::{Camera, ViewParams};
use crate::glam::UVec2;
use crate::kernel::{BindingDecl, EntryBindings, Kernel, Stage};

/// Input resources every technique may bind; the executor provides them.
pub mod inputs {
    /// Linear view depth `f32` per full-target pixel (`>= view.far`: background).
    pub const LINEAR_DEPTH: &str = "linear_depth";
    /// Octahedral-encoded view-space normals `u32` per full-target pixel
    /// (`crate::common::normal_codec`).
    pub const VIEW_NORMALS: &str = "view_normals";
    /// Depth-peeled second layer (`f32` per pixel) of dual-depth techniques (spec svao-raysd
    /// §11); the executor produces it by peeling (raster) or by the next BVH hit (CPU).
    pub const SECOND_DEPTH: &str = "second_depth";
    /// The scene's top-level acceleration structure (ray-tracing passes).
    pub const SCENE_TLAS: &str = "scene_tlas";
    /// Per-triangle corner texture coordinates, materials, alpha-mask headers and texels: what
    /// every any-hit's alpha test reads (`crate::common::alpha`).
    pub const SCENE_UVS: &str = "scene_uvs";
    pub const SCENE_MATERIALS: &str = "scene_materials";
    pub const SCENE_MASK_HEADERS: &str = "scene_mask_headers";
    pub const SCENE_MASK_TEXELS: &str = "scene_mask_texels";
    /// The scene's triangles as the raster passes' vertex stream (de-indexed
    /// `crate::gbuffer`-layout vertices: position, face normal, uv, material).
    pub const SCENE_VERTICES: &str = "scene_vertices";

    /// Every input name.
    pub const ALL: [&str; 9] = [
        LINEAR_DEPTH,
        VIEW_NORMALS,
        SECOND_DEPTH,
        SCENE_TLAS,
        SCENE_UVS,
        SCENE_MATERIALS,
        SCENE_MASK_HEADERS,
        SCENE_MASK_TEXELS,
        SCENE_VERTICES,
    ];
}

/// Element type of a storage buffer.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Elem {
    F32,
    U32,
}

/// What a resource holds at the start of each frame.
#[derive(Clone, Debug, PartialEq)]
pub enum Init {
    /// Every element set to these bits (`1.0f32.to_bits()`, `0`, …) before the first pass.
    Fill(u32),
    /// These words, written before the first pass (parameter records, kernel tables).
    Data(Vec<u32>),
    /// Nothing: a pass writes every element before any pass reads it.
    Undefined,
}

/// Whether a resource is re-initialized every frame or keeps its contents across frames.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Lifetime {
    PerFrame,
    Persistent,
}

/// A 2D extent as a function of the target: what a pass dispatches over and what a resource's
/// texels cover. Evaluates for a view ([`Extent::size`]) and prints as a formula of `W×H` (the
/// full target, inner image plus guard band) and `w×h` (the inner image) ([`Extent::formula`]).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Extent {
    /// The full target `W×H`.
    Full,
    /// The inner image `w×h = (W − 2g)×(H − 2g)`.
    Inner,
    /// `(ceil(W/d) + 2b)×(ceil(H/d) + 2b)`: a reduced-resolution map with its own border of `b`
    /// texels (the SD map and its guard band, spec svao-raysd §3), or, with no border, the
    /// `d×d` blocks of the target a pass dispatches over (gtao's prefilter).
    Reduced { divisor: u32, border: u32 },
    /// `max(1, floor(W/2^k))×max(1, floor(H/2^k))`: MIP level `k` of the full target (spec
    /// gtao-raymarch-hybrid §2.3).
    Mip(u32),
    /// `ceil(W/2)×H`: pairs of horizontally adjacent pixels of the full target (a kernel that
    /// shades two pixels an invocation, as XeGTAO's denoiser).
    Pairs,
    /// `(w/2)×(h/2)`: [`Extent::Inner`] of the half-resolution target (`crate::halfres`).
    HalfInner,
    /// `ceil(W/4)×(H/2)`: [`Extent::Pairs`] of the half-resolution target (`crate::halfres`).
    HalfPairs,
}

impl Extent {
    pub fn size(self, view: &ViewParams) -> UVec2 {
        let full = view.size();
        match self {
            Extent::Full => full,
            Extent::Inner => full - 2 * view.guard,
            Extent::Reduced { divisor, border } => {
                UVec2::new(full.x.div_ceil(divisor), full.y.div_ceil(divisor)) + 2 * border
            }
            Extent::Mip(k) => UVec2::new((full.x >> k).max(1), (full.y >> k).max(1)),
            Extent::Pairs => UVec2::new(full.x.div_ceil(2), full.y),
            Extent::HalfInner => (full - 2 * view.guard) / 2,
            Extent::HalfPairs => UVec2::new(full.x.div_ceil(4), full.y / 2),
        }
    }

    /// The same extent of the half-resolution target `(W/2)×(H/2)` with guard band `g/2` (`W`,
    /// `H`, `g` even; spec half-resolution §1), as an extent of the full target: the full target
    /// is [`Extent::Reduced`] by 2, a reduced map by twice its divisor (`ceil(ceil(W/2)/d) =
    /// ceil(W/2d)`), MIP `k` is MIP `k + 1`. Refused for the half-target forms of the inner
    /// image and of pairs ([`Extent::HalfInner`], [`Extent::HalfPairs`]), which have none.
    pub fn halved(self) -> Result<Extent, String> {
        Ok(match self {
            Extent::Full => Extent::Reduced { divisor: 2, border: 0 },
            Extent::Inner => Extent::HalfInner,
            Extent::Reduced { divisor, border } => Extent::Reduced { divisor: 2 * divisor, border },
            Extent::Mip(k) => Extent::Mip(k + 1),
            Extent::Pairs => Extent::HalfPairs,
            Extent::HalfInner | Extent::HalfPairs => return Err("half resolution applied twice".into()),
        })
    }

    /// `[x, y]` as integer expressions of `W`, `H`, `w`, `h` (the grammar of the manifest's
    /// constants, `assets/README.md` "Expressions").
    pub fn formula(self) -> [String; 2] {
        let of = |v: &str| match self {
            Extent::Full => v.to_string(),
            Extent::Inner => v.to_lowercase(),
            Extent::Reduced { divisor: 1, border: 0 } => v.to_string(),
            Extent::Reduced { divisor: 1, border } => format!("{v} + {}", 2 * border),
            Extent::Reduced { divisor, border: 0 } => format!("div_ceil({v}, {divisor})"),
            Extent::Reduced { divisor, border } => format!("div_ceil({v}, {divisor}) + {}", 2 * border),
            Extent::Mip(0) => v.to_string(),
            Extent::Mip(k) => format!("max(1, div_floor({v}, {}))", 1u32 << k),
            Extent::Pairs if v == "W" => "div_ceil(W, 2)".to_string(),
            Extent::Pairs => v.to_string(),
            Extent::HalfInner => format!("div_floor({}, 2)", v.to_lowercase()),
            Extent::HalfPairs if v == "W" => "div_ceil(W, 4)".to_string(),
            Extent::HalfPairs => format!("div_floor({v}, 2)"),
        };
        [of("W"), of("H")]
    }
}

/// How many 32-bit elements a resource holds, as a function of the target.
#[derive(Clone, Debug, PartialEq)]
pub enum Size {
    /// `per_texel` elements for every texel of `extent`.
    Texels { extent: Extent, per_texel: u32 },
    /// MIP levels `first..first + levels` of the full target packed one after another (`first`
    /// is 1 for a half-resolution graph's chain, whose level 0 is the full target's level 1).
    MipChain { first: u32, levels: u32 },
    /// A fixed number (records, tables).
    Words(usize),
}

impl Size {
    /// One element per texel of the full target.
    pub const TARGET: Size = Size::Texels { extent: Extent::Full, per_texel: 1 };

    pub fn len(&self, view: &ViewParams) -> usize {
        let area = |e: Extent| {
            let s = e.size(view);
            s.x as usize * s.y as usize
        };
        match *self {
            Size::Texels { extent, per_texel } => area(extent) * per_texel as usize,
            Size::MipChain { first, levels } => (first..first + levels).map(|k| area(Extent::Mip(k))).sum(),
            Size::Words(n) => n,
        }
    }

    /// The same size for the half-resolution target (see [`Extent::halved`]).
    pub fn halved(&self) -> Result<Size, String> {
        Ok(match *self {
            Size::Texels { extent, per_texel } => Size::Texels { extent: extent.halved()?, per_texel },
            Size::MipChain { first, levels } => Size::MipChain { first: first + 1, levels },
            Size::Words(n) => Size::Words(n),
        })
    }

    /// The element count as an integer expression of `W`, `H`, `w`, `h` (the grammar of
    /// [`Extent::formula`]).
    pub fn formula(&self) -> String {
        let area = |e: Extent| {
            let [x, y] = e.formula();
            let term = |t: String| if t.contains(" + ") { format!("({t})") } else { t };
            format!("{} * {}", term(x), term(y))
        };
        match *self {
            Size::Texels { extent, per_texel: 1 } => area(extent),
            Size::Texels { extent, per_texel } => format!("{} * {per_texel}", area(extent)),
            Size::MipChain { first, levels } => {
                (first..first + levels).map(|k| area(Extent::Mip(k))).collect::<Vec<_>>().join(" + ")
            }
            Size::Words(n) => n.to_string(),
        }
    }
}

/// One storage buffer of the graph.
#[derive(Clone, Debug, PartialEq)]
pub struct Resource {
    pub name: &'static str,
    pub elem: Elem,
    /// Number of 32-bit elements ([`Resource::len`] for a view).
    pub size: Size,
    pub init: Init,
    pub lifetime: Lifetime,
    /// What it holds, for people and the exported contract.
    pub doc: &'static str,
}

impl Resource {
    /// Number of 32-bit elements for `view`.
    pub fn len(&self, view: &ViewParams) -> usize {
        self.size.len(view)
    }
}

/// How a pass uses a binding.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Access {
    Read,
    Write,
    /// Read and written (accumulation, atomics).
    ReadWrite,
}

impl Access {
    pub fn reads(self) -> bool {
        matches!(self, Access::Read | Access::ReadWrite)
    }
    pub fn writes(self) -> bool {
        matches!(self, Access::Write | Access::ReadWrite)
    }
}

/// Binding `slot` of descriptor set 0 is resource `resource`.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Binding {
    pub slot: u32,
    pub resource: &'static str,
    pub access: Access,
}

/// The kind of pipeline a pass runs.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum PassKind {
    /// A compute shader: the pass's kernel is the compute entry point.
    Compute,
    /// A ray-tracing pipeline: the pass's kernel is the ray-generation shader, with this miss and
    /// any-hit shader (every candidate triangle runs the any-hit; no closest-hit). `query` is the
    /// same pass as a compute kernel with `VK_KHR_ray_query`, whose bindings are those of the
    /// three shaders together; [`Graph::with_rt_mode`] swaps it in.
    RayTracing { miss: &'static Kernel, any_hit: &'static Kernel, query: &'static Kernel },
    /// A raster pass without attachments: `vertex` draws the scene's triangles
    /// ([`inputs::SCENE_VERTICES`]) over a viewport of `invocations` pixels, the pass's kernel is
    /// the fragment shader; the push constants go to the vertex stage.
    Raster { vertex: &'static Kernel },
}

/// How ray-traced passes run on Vulkan.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub enum RtMode {
    /// Ray-tracing pipelines (`VK_KHR_ray_tracing_pipeline`): ray generation, miss and any-hit
    /// shaders with a shader binding table.
    #[default]
    Pipeline,
    /// Compute kernels with ray queries (`VK_KHR_ray_query`): the any-hit decision runs in the
    /// candidate loop (`aokit_shaders::common::any_hit::query_candidates`).
    Query,
}

impl RtMode {
    pub const NAMES: [&'static str; 2] = ["pipeline", "query"];

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }

    pub fn parse(s: &str) -> Result<RtMode, String> {
        match s {
            "pipeline" => Ok(RtMode::Pipeline),
            "query" => Ok(RtMode::Query),
            _ => Err(format!("rt mode {s}: expected pipeline or query")),
        }
    }
}

/// One dispatch (or trace) of a kernel.
#[derive(Clone, Debug, PartialEq)]
pub struct Pass {
    /// Label for timing; consecutive passes with one label are timed as one (e.g. the two blur
    /// directions are `blur`).
    pub label: &'static str,
    /// The entry point (its SPIR-V module, and the CPU simulator's kernel), as its signature
    /// declares it.
    pub kernel: &'static Kernel,
    pub kind: PassKind,
    /// Each slot's resource, with the slot and access the kernel declares (see
    /// [`crate::kernel::EntryBindings`]).
    pub bindings: Vec<Binding>,
    /// Invocations in x and y ([`Pass::invocations`] for a view; compute: rounded up to whole
    /// workgroups; ray tracing: the launch size; raster: the viewport).
    pub dispatch: Extent,
    /// Push-constant bytes (the kernel's `#[repr(C)]` parameter struct); empty when the kernel
    /// reads its parameters from a resource.
    pub push_constants: Vec<u8>,
}

impl Pass {
    /// A compute pass of the kernel whose `Bindings` these are.
    pub fn compute(label: &'static str, bindings: impl EntryBindings, dispatch: Extent, push_constants: &[u8]) -> Pass {
        Pass {
            label,
            kernel: bindings.declaration(),
            kind: PassKind::Compute,
            bindings: bindings.slots(),
            dispatch,
            push_constants: push_constants.to_vec(),
        }
    }

    /// A ray-tracing pass of the shaders `[ray generation, miss, any-hit]` (in that order), bound
    /// as the ray-query variant's `Bindings` say: that compute kernel declares the three shaders'
    /// bindings together, so a ray-traced pass always has one (written `#[kernel(spirv_only)]`).
    /// [`Graph::validate`] checks the stages and that the declarations agree.
    pub fn ray_traced(
        label: &'static str,
        shaders: [&'static Kernel; 3],
        query: impl EntryBindings,
        dispatch: Extent,
    ) -> Pass {
        let [rgen, miss, any_hit] = shaders;
        Pass {
            label,
            kernel: rgen,
            kind: PassKind::RayTracing { miss, any_hit, query: query.declaration() },
            bindings: query.slots(),
            dispatch,
            push_constants: Vec::new(),
        }
    }

    /// A raster pass: `vertex` draws the scene, the fragment kernel's `Bindings` say what it
    /// reads and writes; `push_constants` go to the vertex stage.
    pub fn raster(
        label: &'static str,
        vertex: &'static Kernel,
        fragment: impl EntryBindings,
        dispatch: Extent,
        push_constants: &[u8],
    ) -> Pass {
        Pass {
            label,
            kernel: fragment.declaration(),
            kind: PassKind::Raster { vertex },
            bindings: fragment.slots(),
            dispatch,
            push_constants: push_constants.to_vec(),
        }
    }

    /// The entry point's name.
    pub fn entry(&self) -> &'static str {
        self.kernel.entry
    }

    /// The kernels whose declarations the bindings follow: the kernel itself, the three shaders
    /// of a ray-tracing pass, the vertex and fragment shaders of a raster pass.
    pub fn declared_by(&self) -> Vec<&'static Kernel> {
        match self.kind {
            PassKind::Compute => vec![self.kernel],
            PassKind::RayTracing { miss, any_hit, .. } => vec![self.kernel, miss, any_hit],
            PassKind::Raster { vertex } => vec![vertex, self.kernel],
        }
    }

    /// Each kernel of the pass with the stage its place needs: compute; ray generation, miss,
    /// any-hit and the compute ray-query variant; vertex and fragment.
    fn stages(&self) -> Vec<(&'static Kernel, Stage)> {
        match self.kind {
            PassKind::Compute => vec![(self.kernel, Stage::Compute)],
            PassKind::RayTracing { miss, any_hit, query } => vec![
                (self.kernel, Stage::RayGeneration),
                (miss, Stage::Miss),
                (any_hit, Stage::AnyHit),
                (query, Stage::Compute),
            ],
            PassKind::Raster { vertex } => vec![(vertex, Stage::Vertex), (self.kernel, Stage::Fragment)],
        }
    }

    /// Invocations in x and y for `view`.
    pub fn invocations(&self, view: &ViewParams) -> UVec2 {
        self.dispatch.size(view)
    }

    /// The resource bound at `slot`.
    pub fn resource(&self, slot: u32) -> Option<&'static str> {
        self.bindings.iter().find(|b| b.slot == slot).map(|b| b.resource)
    }

    /// Whether the bindings are exactly what the kernel declares: every declared slot bound
    /// once with its declared access. A ray-tracing pass follows its three shaders together,
    /// which must declare what its ray-query variant declares.
    fn check_declared(&self) -> Result<(), String> {
        for (kernel, stage) in self.stages() {
            if kernel.stage != stage {
                return Err(format!(
                    "pass '{}': {} is a {} kernel where the pass needs a {} one",
                    self.label,
                    kernel.entry,
                    kernel.stage.name(),
                    stage.name()
                ));
            }
        }
        let mut declared: Vec<&BindingDecl> = Vec::new();
        for k in self.declared_by() {
            for d in k.bindings {
                match declared.iter().find(|e| e.slot == d.slot) {
                    Some(e) if e.access != d.access || e.kind != d.kind => {
                        return Err(format!("{}: slot {} is declared differently by two shaders", k.entry, d.slot));
                    }
                    Some(_) => {}
                    None => declared.push(d),
                }
            }
        }
        if let PassKind::RayTracing { query, .. } = self.kind {
            let same = query.bindings.len() == declared.len()
                && query
                    .bindings
                    .iter()
                    .all(|q| declared.iter().any(|d| d.slot == q.slot && d.access == q.access && d.kind == q.kind));
            if !same {
                return Err(format!("{}: its bindings differ from those of the ray-tracing shaders", query.entry));
            }
        }
        for d in &declared {
            match self.bindings.iter().find(|b| b.slot == d.slot) {
                None => return Err(format!("pass '{}' leaves slot {} ({}) unbound", self.entry(), d.slot, d.name)),
                Some(b) if b.access != d.access => {
                    return Err(format!(
                        "pass '{}' binds slot {} ({}) as {:?}; the kernel declares {:?}",
                        self.entry(),
                        d.slot,
                        d.name,
                        b.access,
                        d.access
                    ));
                }
                Some(_) => {}
            }
        }
        if let Some(b) = self.bindings.iter().find(|b| !declared.iter().any(|d| d.slot == b.slot)) {
            return Err(format!("pass '{}' binds slot {}, which the kernel does not declare", self.entry(), b.slot));
        }
        Ok(())
    }
}

/// A technique's resources and passes for one frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Graph {
    pub resources: Vec<Resource>,
    pub passes: Vec<Pass>,
    /// The resource holding the final AO (`f32` per full-target pixel, 1 = unoccluded).
    pub output: &'static str,
    /// The resource holding the AO before denoising/blurring (same layout), for reports.
    pub raw_output: &'static str,
    /// The camera view (full target) the graph was built for.
    pub view: crate::common::camera::ViewParams,
    /// Diagnostic copies for reports: after pass `after`, copy resource `from` into `to` (a
    /// declared resource of the same length).
    pub snapshots: Vec<Snapshot>,
    /// What reports read besides the AO, declared here so that no executor or report names a
    /// technique's buffers.
    pub diagnostics: Diagnostics,
}

/// The diagnostics a graph offers its reports ([`Graph::diagnostics`]).
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub struct Diagnostics {
    /// The resource holding bent normals (RGBA8 in a `u32` per full-target pixel), where the
    /// graph writes them.
    pub bent_normals: Option<&'static str>,
    /// Decodes the stenciled family's refinement buffers after a run.
    pub refinement: Option<RefinementDecoder>,
}

/// A technique's decoder of its refinement buffers, named (graphs compare by the name).
#[derive(Copy, Clone, Debug)]
pub struct RefinementDecoder {
    /// What it decodes, e.g. `svao (traced SD map)`.
    pub name: &'static str,
    /// The decoder.
    pub decode: fn(&Executed) -> Refinement,
}

impl PartialEq for RefinementDecoder {
    fn eq(&self, other: &RefinementDecoder) -> bool {
        self.name == other.name
    }
}

/// A finished graph as a report reads it: a resource's words, and the G-buffer it ran on.
pub struct Executed<'a> {
    /// The words of the graph's resource `name` (`None` where the graph has none of that name).
    pub words: &'a dyn Fn(&str) -> Option<Vec<u32>>,
    /// Linear view depth per full-target pixel.
    pub depth: &'a [f32],
    /// Encoded view normals per full-target pixel.
    pub normals: &'a [u32],
}

impl Executed<'_> {
    /// Resource `name` as `f32`s (empty where the graph has none).
    pub fn f32s(&self, name: &str) -> Vec<f32> {
        (self.words)(name).map(|w| w.into_iter().map(f32::from_bits).collect()).unwrap_or_default()
    }

    /// Resource `name`'s words (empty where the graph has none).
    pub fn u32s(&self, name: &str) -> Vec<u32> {
        (self.words)(name).unwrap_or_default()
    }
}

/// What a stenciled run refined and traced, and its buffers for the report's images.
#[derive(Clone, Debug, Default)]
pub struct Refinement {
    /// Samples flagged for refinement in pass 1.
    pub refined_samples: u64,
    /// Rays the secondary visibility stands for where no ray counter counts them (the raster SD
    /// map counts the SD texels it rasterized).
    pub rays: Option<u64>,
    /// Ray-SD: the summed interval length `Σ (tMax − tMin)` of the SD rays, world units.
    pub interval_sum: Option<f64>,
    /// AO after pass 1 (final where `mask == 0`, the UNORM8-stored sum elsewhere).
    pub ao_pass1: Vec<f32>,
    /// Refinement mask per full-target pixel.
    pub mask: Vec<u32>,
    /// SD-size interval buffers (float bits; 0 = unset), empty without an SD map.
    pub ray_min: Vec<u32>,
    /// See `ray_min`.
    pub ray_max: Vec<u32>,
    /// The SD map's size.
    pub sd_size: crate::glam::UVec2,
    /// SD map: `layers` normalized depths per SD texel.
    pub sd_map: Vec<f32>,
    /// Layers per SD texel.
    pub layers: u32,
}

/// See [`Graph::snapshots`].
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Snapshot {
    pub after: usize,
    pub from: &'static str,
    pub to: &'static str,
}

impl Graph {
    /// The resource called `name`.
    pub fn resource(&self, name: &str) -> Option<&Resource> {
        self.resources.iter().find(|r| r.name == name)
    }

    /// Inputs the passes read (from [`inputs::ALL`]), in first-use order; raster passes read
    /// the scene's vertices too.
    pub fn inputs(&self) -> Vec<&'static str> {
        let mut out = Vec::new();
        for p in &self.passes {
            let vertices = matches!(p.kind, PassKind::Raster { .. }).then_some(inputs::SCENE_VERTICES);
            for name in p.bindings.iter().map(|b| b.resource).chain(vertices) {
                if inputs::ALL.contains(&name) && !out.contains(&name) {
                    out.push(name);
                }
            }
        }
        out
    }

    /// Does any pass trace rays (a ray-tracing pipeline, or a kernel with ray queries: one that
    /// binds the scene's TLAS)?
    pub fn traces_rays(&self) -> bool {
        self.passes.iter().any(|p| p.bindings.iter().any(|b| b.resource == inputs::SCENE_TLAS))
    }

    /// The graph with its ray-traced passes run as `mode` says: unchanged for
    /// [`RtMode::Pipeline`]; for [`RtMode::Query`] every ray-tracing pass becomes the compute
    /// pass of its ray-query variant (same label, bindings and invocations).
    pub fn with_rt_mode(mut self, mode: RtMode) -> Graph {
        if mode == RtMode::Query {
            for pass in &mut self.passes {
                if let PassKind::RayTracing { query, .. } = pass.kind {
                    pass.kernel = query;
                    pass.kind = PassKind::Compute;
                }
            }
        }
        self
    }

    /// The graph for a frame without view normals: XeGTAO's normals-from-depth pass
    /// (`crate::gtao::gtao_normals`, gtao-raymarch-hybrid §2.4) runs first into
    /// [`DERIVED_NORMALS`], and every pass that read [`inputs::VIEW_NORMALS`] reads that instead.
    /// Unchanged when no pass reads normals.
    pub fn with_normals_from_depth(mut self) -> Graph {
        let mut reads = false;
        for b in self.passes.iter_mut().flat_map(|p| &mut p.bindings) {
            if b.resource == inputs::VIEW_NORMALS {
                b.resource = DERIVED_NORMALS;
                reads = true;
            }
        }
        if reads {
            // The normals pass reads only the view of its parameters.
            let params = crate::gtao::GtaoParams { view: self.view, ..bytemuck::Zeroable::zeroed() };
            let bindings =
                crate::gtao::gtao_normals::Bindings { depth: inputs::LINEAR_DEPTH, normals: DERIVED_NORMALS };
            let pass = Pass::compute("normals_from_depth", bindings, Extent::Full, bytemuck::bytes_of(&params));
            self.passes.insert(0, pass);
            self.snapshots.iter_mut().for_each(|s| s.after += 1);
            // The normals pass writes every texel of the target before any pass reads one.
            self.resources.push(Resource {
                init: Init::Undefined,
                ..target_u32(
                    DERIVED_NORMALS,
                    0,
                    "view normals derived from depth for a frame without normals (gtao-raymarch-hybrid §2.4)",
                )
            });
        }
        self
    }

    /// Check the graph's consistency: every bound resource is declared or an input, no input is
    /// written, binding slots are unique per pass, and the outputs exist. Executors call this
    /// once per new graph.
    pub fn validate(&self) -> Result<(), String> {
        self.validate_bindings()
    }

    /// Per pass: whether a memory barrier (shader writes → shader reads and writes) must come
    /// before it — when it reads or overwrites what a pass since the last barrier wrote, or
    /// writes what one read. The GPU executor records exactly these; an engine replaying the
    /// passes needs them too.
    pub fn barriers(&self) -> Vec<bool> {
        let (mut written, mut read): (Vec<&str>, Vec<&str>) = (Vec::new(), Vec::new());
        let mut out = Vec::new();
        for pass in &self.passes {
            let hazard = pass
                .bindings
                .iter()
                .any(|b| written.contains(&b.resource) || (b.access.writes() && read.contains(&b.resource)));
            if hazard {
                written.clear();
                read.clear();
            }
            out.push(hazard);
            for b in &pass.bindings {
                if b.access.writes() {
                    written.push(b.resource);
                }
                if b.access.reads() {
                    read.push(b.resource);
                }
            }
        }
        out
    }

    fn validate_bindings(&self) -> Result<(), String> {
        for (i, r) in self.resources.iter().enumerate() {
            if inputs::ALL.contains(&r.name) || self.resources[..i].iter().any(|s| s.name == r.name) {
                return Err(format!("resource '{}' is declared twice or shadows an input", r.name));
            }
            if let Init::Data(d) = &r.init
                && d.len() > r.len(&self.view)
            {
                return Err(format!(
                    "resource '{}': {} words of data for {} elements",
                    r.name,
                    d.len(),
                    r.len(&self.view)
                ));
            }
        }
        for p in &self.passes {
            p.check_declared()?;
            for (j, b) in p.bindings.iter().enumerate() {
                let input = inputs::ALL.contains(&b.resource);
                if !input && self.resource(b.resource).is_none() {
                    return Err(format!("pass '{}' binds undeclared resource '{}'", p.entry(), b.resource));
                }
                if input && b.access.writes() {
                    return Err(format!("pass '{}' writes input '{}'", p.entry(), b.resource));
                }
                if p.bindings[..j].iter().any(|c| c.slot == b.slot) {
                    return Err(format!("pass '{}' binds slot {} twice", p.entry(), b.slot));
                }
                // A written resource is bound once per pass: the CPU executor hands it to the
                // kernel once, and a second view of it would alias on the GPU.
                let twice = p.bindings[..j]
                    .iter()
                    .any(|c| c.resource == b.resource && (c.access.writes() || b.access.writes()));
                if twice {
                    return Err(format!("pass '{}' binds '{}' twice, writing it", p.entry(), b.resource));
                }
            }
        }
        for s in &self.snapshots {
            let (from, to) = (self.resource(s.from), self.resource(s.to));
            if s.after >= self.passes.len()
                || from.is_none()
                || from.map(|r| r.len(&self.view)) != to.map(|r| r.len(&self.view))
            {
                return Err(format!("snapshot of '{}' into '{}' is not between declared resources", s.from, s.to));
            }
        }
        for out in [self.output, self.raw_output] {
            if self.resource(out).is_none() {
                return Err(format!("output '{out}' is not a declared resource"));
            }
        }
        Ok(())
    }
}

/// What every technique's graph is built from besides its settings: the camera of the full
/// target and the scene-dependent AO parameters.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct FrameDesc {
    pub camera: Camera,
    /// World-space AO radius.
    pub radius: f32,
    /// AO exponent `e` of the final `A^e` (spec svao-raysd §4.3).
    pub exponent: f32,
    /// VAO thickness τ (spec svao-raysd §2, used in svao-raysd §4.3–§4.4).
    pub thickness: f32,
    /// The frame's index in a sequence: every stochastic technique's noise takes it (XeGTAO's
    /// `NoiseIndex`, spec gtao-raymarch-hybrid §1.6; the ray-traced techniques' hashes and
    /// sequences through `crate::common::noise::frame_rotation`). 0 for single frames: frame 0
    /// is the techniques' original noise, bit for bit.
    pub frame_index: u32,
    /// The previous frame's camera, for the temporal accumulation's reprojection; `None` on a
    /// first frame or after a cut (the history restarts).
    pub previous_camera: Option<Camera>,
    /// Temporal accumulation of the final AO (`crate::temporal`), appended to any technique's
    /// graph; `None`: off.
    pub temporal: Option<crate::temporal::settings::TemporalSettings>,
}

impl FrameDesc {
    /// A single frame: index 0, no previous camera, no temporal accumulation.
    pub fn new(camera: Camera, radius: f32, exponent: f32, thickness: f32) -> FrameDesc {
        FrameDesc { camera, radius, exponent, thickness, frame_index: 0, previous_camera: None, temporal: None }
    }

    /// Full target size.
    pub fn size(&self) -> UVec2 {
        self.camera.view.size()
    }

    /// Inner image size (target minus the guard band).
    pub fn inner(&self) -> UVec2 {
        self.size() - 2 * self.camera.view.guard
    }

    /// Pixels of the full target.
    pub fn pixels(&self) -> usize {
        let s = self.size();
        (s.x * s.y) as usize
    }
}

/// A per-frame `f32` image of the full target filled with `value`.
pub fn target_f32(name: &'static str, value: f32, doc: &'static str) -> Resource {
    Resource {
        name,
        elem: Elem::F32,
        size: Size::TARGET,
        init: Init::Fill(value.to_bits()),
        lifetime: Lifetime::PerFrame,
        doc,
    }
}

/// A per-frame `u32` image of the full target filled with `value`.
pub fn target_u32(name: &'static str, value: u32, doc: &'static str) -> Resource {
    Resource { name, elem: Elem::U32, size: Size::TARGET, init: Init::Fill(value), lifetime: Lifetime::PerFrame, doc }
}

/// The resource [`Graph::with_normals_from_depth`] derives the view normals into.
pub const DERIVED_NORMALS: &str = "derived_view_normals";

/// The resource every ray-traced pass adds the rays it traced to.
pub const RAY_COUNT: &str = "ray_count";

/// [`RAY_COUNT`]: a 64-bit count as two `u32` words (low, high), zero at the start of each
/// frame; the kernels add with `crate::common::atomics::count_rays`, the executors report it.
pub fn ray_counter() -> Resource {
    Resource {
        name: RAY_COUNT,
        elem: Elem::U32,
        size: Size::Words(2),
        init: Init::Fill(0),
        lifetime: Lifetime::PerFrame,
        doc: "rays traced this frame, counted by the kernels that trace them: u64 as (low, high) u32 words",
    }
}

/// The rays a frame's [`RAY_COUNT`] words hold.
pub fn ray_count_of(words: &[u32]) -> u64 {
    words.first().copied().unwrap_or(0) as u64 | (words.get(1).copied().unwrap_or(0) as u64) << 32
}

/// A per-frame parameter record (or table) `value` as a one-element storage buffer.
pub fn record<T: bytemuck::Pod>(name: &'static str, values: &[T], doc: &'static str) -> Resource {
    let words: Vec<u32> = bytemuck::cast_slice::<T, u8>(values)
        .chunks(4)
        .map(|c| {
            let mut w = [0u8; 4];
            w[..c.len()].copy_from_slice(c);
            u32::from_le_bytes(w)
        })
        .collect();
    let size = Size::Words(words.len());
    Resource { name, elem: Elem::U32, size, init: Init::Data(words), lifetime: Lifetime::PerFrame, doc }
}
