//! A technique as data: the pass graph every executor walks (host side only).
//!
//! A [`Graph`] lists the technique's resources (storage buffers of 32-bit elements, sized from
//! the target) and its passes in order (kernel entry point, which resource each binding slot is
//! and how it is accessed, the number of invocations, the push constants). The CPU simulator
//! (`aokit_cpu::graph`) calls the kernels' functions for each pass; the Vulkan executor
//! (`aokit_vulkan::AoContext`) records the same passes with barriers derived from the accesses.
//! Neither knows a technique by name, so the order of passes exists exactly once: in the
//! technique's `graph()` beside its kernels.
//!
//! A graph is built per frame from the settings and the camera (cheap: a few small vectors);
//! executors keep resources and pipelines across frames and re-create a resource only when its
//! size changes.

use crate::common::camera::Camera;
use crate::glam::UVec2;

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

/// One storage buffer of the graph.
#[derive(Clone, Debug, PartialEq)]
pub struct Resource {
    pub name: &'static str,
    pub elem: Elem,
    /// Number of 32-bit elements.
    pub len: usize,
    pub init: Init,
    pub lifetime: Lifetime,
    /// What it holds, for people and the exported contract.
    pub doc: &'static str,
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
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum PassKind {
    /// A compute shader: `entry` is the compute entry point.
    Compute,
    /// A ray-tracing pipeline: `entry` is the ray-generation shader, with this miss and any-hit
    /// shader (every candidate triangle runs the any-hit; no closest-hit).
    RayTracing { miss: &'static str, any_hit: &'static str },
    /// A raster pass without attachments: `vertex` draws the scene's triangles
    /// ([`inputs::SCENE_VERTICES`]) over a viewport of `invocations` pixels, `entry` is the
    /// fragment shader; the push constants go to the vertex stage.
    Raster { vertex: &'static str },
}

/// One dispatch (or trace) of a kernel.
#[derive(Clone, Debug, PartialEq)]
pub struct Pass {
    /// Label for timing; consecutive passes with one label are timed as one (e.g. the two blur
    /// directions are `blur`).
    pub label: &'static str,
    /// Kernel entry point (SPIR-V module name, and the CPU simulator's kernel).
    pub entry: &'static str,
    pub kind: PassKind,
    pub bindings: Vec<Binding>,
    /// Invocations in x and y (compute: rounded up to whole workgroups; ray tracing: the launch
    /// size).
    pub invocations: UVec2,
    /// Push-constant bytes (the kernel's `#[repr(C)]` parameter struct); empty when the kernel
    /// reads its parameters from a resource.
    pub push_constants: Vec<u8>,
}

impl Pass {
    /// A compute pass.
    pub fn compute(
        label: &'static str,
        entry: &'static str,
        bindings: &[(&'static str, Access)],
        invocations: UVec2,
        push_constants: &[u8],
    ) -> Pass {
        Pass {
            label,
            entry,
            kind: PassKind::Compute,
            bindings: slots(bindings),
            invocations,
            push_constants: push_constants.to_vec(),
        }
    }

    /// The resource bound at `slot`.
    pub fn resource(&self, slot: u32) -> Option<&'static str> {
        self.bindings.iter().find(|b| b.slot == slot).map(|b| b.resource)
    }
}

/// Bindings numbered 0, 1, 2, … in order.
pub fn slots(bindings: &[(&'static str, Access)]) -> Vec<Binding> {
    bindings.iter().enumerate().map(|(i, &(resource, access))| Binding { slot: i as u32, resource, access }).collect()
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

    /// Does any pass trace rays?
    pub fn traces_rays(&self) -> bool {
        self.passes.iter().any(|p| matches!(p.kind, PassKind::RayTracing { .. }))
    }

    /// Check the graph's consistency: every bound resource is declared or an input, no input is
    /// written, binding slots are unique per pass, and the outputs exist. Executors call this
    /// once per new graph.
    pub fn validate(&self) -> Result<(), String> {
        for (i, r) in self.resources.iter().enumerate() {
            if inputs::ALL.contains(&r.name) || self.resources[..i].iter().any(|s| s.name == r.name) {
                return Err(format!("resource '{}' is declared twice or shadows an input", r.name));
            }
            if let Init::Data(d) = &r.init
                && d.len() > r.len
            {
                return Err(format!("resource '{}': {} words of data for {} elements", r.name, d.len(), r.len));
            }
        }
        for p in &self.passes {
            for (j, b) in p.bindings.iter().enumerate() {
                let input = inputs::ALL.contains(&b.resource);
                if !input && self.resource(b.resource).is_none() {
                    return Err(format!("pass '{}' binds undeclared resource '{}'", p.entry, b.resource));
                }
                if input && b.access.writes() {
                    return Err(format!("pass '{}' writes input '{}'", p.entry, b.resource));
                }
                if p.bindings[..j].iter().any(|c| c.slot == b.slot) {
                    return Err(format!("pass '{}' binds slot {} twice", p.entry, b.slot));
                }
                // A written resource is bound once per pass: the CPU executor hands it to the
                // kernel once, and a second view of it would alias on the GPU.
                let twice = p.bindings[..j]
                    .iter()
                    .any(|c| c.resource == b.resource && (c.access.writes() || b.access.writes()));
                if twice {
                    return Err(format!("pass '{}' binds '{}' twice, writing it", p.entry, b.resource));
                }
            }
        }
        for s in &self.snapshots {
            let (from, to) = (self.resource(s.from), self.resource(s.to));
            if s.after >= self.passes.len() || from.is_none() || from.map(|r| r.len) != to.map(|r| r.len) {
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
    /// VAO thickness τ (spec svao-raysd §2, used in §4.3–§4.4).
    pub thickness: f32,
}

impl FrameDesc {
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
pub fn target_f32(frame: &FrameDesc, name: &'static str, value: f32, doc: &'static str) -> Resource {
    Resource {
        name,
        elem: Elem::F32,
        len: frame.pixels(),
        init: Init::Fill(value.to_bits()),
        lifetime: Lifetime::PerFrame,
        doc,
    }
}

/// A per-frame `u32` image of the full target filled with `value`.
pub fn target_u32(frame: &FrameDesc, name: &'static str, value: u32, doc: &'static str) -> Resource {
    Resource { name, elem: Elem::U32, len: frame.pixels(), init: Init::Fill(value), lifetime: Lifetime::PerFrame, doc }
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
    Resource { name, elem: Elem::U32, len: words.len(), init: Init::Data(words), lifetime: Lifetime::PerFrame, doc }
}
