//! The CPU executor of a technique's pass graph (`aokit_shaders::graph`): resources are `Vec<u32>`
//! kept across frames, each pass calls the kernel functions of its entry point over whole
//! images, ray-tracing passes go through the BVH with the shared any-hit functions.
//!
//! The executor knows kernels (one line per entry point in [`kernel`]), never techniques: the
//! order of passes comes from the graph alone.

use crate::gbuffer::Surfaces;
use crate::svao::{HitOrder, Pass1, SdMap};
use crate::{Progress, SceneBvh};
use aokit_shaders::glam::Vec2;
use aokit_shaders::graph::{Access, Graph, Init, Lifetime, Pass, RAY_COUNT, inputs, ray_count_of};
use std::collections::HashMap;
use std::time::Instant;

/// The scene for ray-tracing passes.
#[derive(Copy, Clone)]
pub struct CpuScene<'a> {
    pub bvh: &'a SceneBvh,
    pub surfaces: &'a Surfaces<'a>,
}

/// What a frame reads besides the graph's own resources.
#[derive(Copy, Clone)]
pub struct CpuInputs<'a> {
    /// Linear depth and encoded normals of the full target.
    pub depth: &'a [f32],
    pub normals: &'a [u32],
    /// The depth-peeled second layer, for dual-depth graphs.
    pub second_depth: Option<&'a [f32]>,
    /// The scene, for graphs that trace rays.
    pub scene: Option<CpuScene<'a>>,
    pub progress: Progress<'a>,
}

/// A kernel's view of its bindings during one pass.
pub struct PassIo<'a> {
    pub pass: &'a Pass,
    reads: Vec<(u32, &'a [u32])>,
    writes: Vec<(u32, Option<&'a mut [u32]>)>,
    pub inputs: &'a CpuInputs<'a>,
    /// Rays traced by this pass (ray-tracing kernels add theirs).
    pub rays: u64,
}

impl<'a> PassIo<'a> {
    /// The words bound at `slot` (read-only or read-write bindings that were not taken yet).
    pub fn words(&self, slot: u32) -> &[u32] {
        if let Some((_, r)) = self.reads.iter().find(|(s, _)| *s == slot) {
            return r;
        }
        match self.writes.iter().find(|(s, _)| *s == slot) {
            Some((_, Some(w))) => w,
            _ => panic!("pass '{}': slot {slot} is not bound for reading", self.pass.entry),
        }
    }

    pub fn f32(&self, slot: u32) -> &[f32] {
        bytemuck::cast_slice(self.words(slot))
    }

    /// The writable words at `slot`, handed out once per pass.
    pub fn take(&mut self, slot: u32) -> &'a mut [u32] {
        let entry = self.writes.iter_mut().find(|(s, _)| *s == slot);
        entry
            .and_then(|(_, w)| w.take())
            .unwrap_or_else(|| panic!("pass '{}': slot {slot} is not writable", self.pass.entry))
    }

    pub fn take_f32(&mut self, slot: u32) -> &'a mut [f32] {
        bytemuck::cast_slice_mut(self.take(slot))
    }

    /// The push constants as the kernel's parameter struct.
    pub fn push<T: bytemuck::Pod>(&self) -> T {
        bytemuck::pod_read_unaligned(&self.pass.push_constants[..size_of::<T>()])
    }

    /// The first record of the buffer at `slot` (parameter records such as `SvaoFrame`).
    pub fn record<T: bytemuck::Pod>(&self, slot: u32) -> T {
        bytemuck::pod_read_unaligned(&bytemuck::cast_slice::<u32, u8>(self.words(slot))[..size_of::<T>()])
    }

    /// The scene, or a panic naming the pass (the executor checks it before running).
    pub fn scene(&self) -> CpuScene<'a> {
        self.inputs.scene.unwrap_or_else(|| panic!("pass '{}' traces rays but no scene was given", self.pass.entry))
    }
}

/// A kernel on the CPU: reads and writes its bindings through [`PassIo`].
pub type CpuKernel = fn(&mut PassIo);

/// The CPU kernel of each entry point.
pub fn kernel(entry: &str) -> Option<CpuKernel> {
    Some(match entry {
        "vao_main" => kernels::vao,
        "blur_main" => kernels::blur,
        "svao_pass1" => kernels::svao_pass1,
        // A ray-tracing pass and its ray-query variant are one kernel on the CPU: the BVH reports
        // every candidate to the same any-hit decision.
        "raysd_rgen" | "raysd_rq" => kernels::sd_map,
        "rastersd_fs" => kernels::raster_sd_map,
        "raysd_pass2" => kernels::raysd_pass2,
        "raysvao_rgen" | "raysvao_rq" => kernels::raysvao,
        "gtao_prefilter" => kernels::gtao_prefilter,
        "gtao_normals" => kernels::gtao_normals,
        "gtao_main" => kernels::gtao_main,
        "gtao_denoise" => kernels::gtao_denoise,
        "vbao_main" => kernels::vbao_main,
        "raymarch_main" => kernels::raymarch,
        "groundtruth_rgen" | "groundtruth_rq" => kernels::ground_truth,
        "hybrid_rgen" | "hybrid_rq" => kernels::hybrid,
        "temporal_blend" => kernels::temporal_blend,
        "temporal_store" => kernels::temporal_store,
        _ => return None,
    })
}

/// What one frame of a graph produced.
#[derive(Clone, Debug, Default)]
pub struct FrameStats {
    /// `(label, ms)` per run of consecutive passes with one label, wall clock.
    pub pass_ms: Vec<(&'static str, f64)>,
    /// Rays traced.
    pub rays: u64,
}

/// Runs pass graphs on the CPU; resources persist across frames (re-made when their size
/// changes, re-initialized every frame unless persistent).
#[derive(Default)]
pub struct CpuExecutor {
    resources: HashMap<&'static str, Vec<u32>>,
}

impl CpuExecutor {
    pub fn new() -> Self {
        Self::default()
    }

    /// The contents of resource `name` after the last frame.
    pub fn words(&self, name: &str) -> Option<&[u32]> {
        self.resources.get(name).map(|v| &v[..])
    }

    /// Resource `name` as `f32`.
    pub fn f32(&self, name: &str) -> Option<&[f32]> {
        self.words(name).map(bytemuck::cast_slice)
    }

    /// Run every pass of `graph` in order.
    pub fn run(&mut self, graph: &Graph, inputs: &CpuInputs) -> Result<FrameStats, String> {
        graph.validate()?;
        for r in &graph.resources {
            let len = r.len(&graph.view);
            let fresh = self.resources.get(r.name).is_none_or(|v| v.len() != len);
            if fresh || r.lifetime == Lifetime::PerFrame {
                let v = self.resources.entry(r.name).or_default();
                v.clear();
                match &r.init {
                    Init::Fill(bits) => v.resize(len, *bits),
                    Init::Data(words) => {
                        v.extend_from_slice(words);
                        v.resize(len, 0);
                    }
                    Init::Undefined => v.resize(len, 0),
                }
            }
        }
        let pixels = inputs.depth.len();
        if inputs.normals.len() != pixels {
            return Err(format!("normals hold {} pixels, depth {pixels}", inputs.normals.len()));
        }
        let mut stats = FrameStats::default();
        for (i, pass) in graph.passes.iter().enumerate() {
            let run = kernel(pass.entry).ok_or_else(|| format!("no CPU kernel for entry point '{}'", pass.entry))?;
            let start = Instant::now();
            stats.rays += self.run_pass(pass, inputs, run)?;
            let ms = start.elapsed().as_secs_f64() * 1e3;
            match stats.pass_ms.last_mut() {
                Some((label, total)) if *label == pass.label => *total += ms,
                _ => stats.pass_ms.push((pass.label, ms)),
            }
            for snap in graph.snapshots.iter().filter(|s| s.after == i) {
                let copy = self.resources[snap.from].clone();
                self.resources.insert(snap.to, copy);
            }
        }
        Ok(stats)
    }

    fn run_pass(&mut self, pass: &Pass, inputs: &CpuInputs, run: CpuKernel) -> Result<u64, String> {
        // Written resources leave the map for the pass, so reads can borrow the rest.
        let mut taken: Vec<(&'static str, Vec<u32>)> = Vec::new();
        for b in pass.bindings.iter().filter(|b| b.access.writes()) {
            let v =
                self.resources.remove(b.resource).ok_or_else(|| format!("'{}' bound twice for writing", b.resource))?;
            taken.push((b.resource, v));
        }
        let result = (|| {
            let mut reads = Vec::new();
            for b in pass.bindings.iter().filter(|b| b.access == Access::Read) {
                let words: &[u32] = match b.resource {
                    inputs::LINEAR_DEPTH => bytemuck::cast_slice(inputs.depth),
                    inputs::VIEW_NORMALS => inputs.normals,
                    inputs::SECOND_DEPTH => bytemuck::cast_slice(
                        inputs.second_depth.ok_or("the graph reads a second depth layer; none was given")?,
                    ),
                    // The scene's buffers are the BVH's surfaces on the CPU.
                    name if inputs::ALL.contains(&name) => {
                        if inputs.scene.is_none() {
                            return Err(format!("pass '{}' traces rays but no scene was given", pass.entry));
                        }
                        &[]
                    }
                    name => self.resources.get(name).map(|v| &v[..]).ok_or_else(|| format!("'{name}' is missing"))?,
                };
                reads.push((b.slot, words));
            }
            let writes = pass
                .bindings
                .iter()
                .filter(|b| b.access.writes())
                .zip(taken.iter_mut())
                .map(|(b, (_, v))| (b.slot, Some(&mut v[..])))
                .collect();
            let mut io = PassIo { pass, reads, writes, inputs, rays: 0 };
            run(&mut io);
            // The ray counter, as the GPU kernels keep it (`common::atomics::count_rays`).
            if let Some(b) = pass.bindings.iter().find(|b| b.resource == RAY_COUNT) {
                let words = io.take(b.slot);
                let total = ray_count_of(words) + io.rays;
                words[..2].copy_from_slice(&[total as u32, (total >> 32) as u32]);
            }
            Ok(io.rays)
        })();
        for (name, v) in taken {
            self.resources.insert(name, v);
        }
        result
    }
}

/// The kernels, one per entry point: each calls the shader crate's functions (through the
/// whole-image runners of this crate) and writes its outputs into the bound resources.
mod kernels {
    use super::*;
    use aokit_shaders::blur::BlurParams;
    use aokit_shaders::groundtruth::GroundTruthFrame;
    use aokit_shaders::gtao::{GtaoParams, mip_offset, mip_size, normal_from_depth, prefilter_texel};
    use aokit_shaders::hybrid::HybridFrame;
    use aokit_shaders::raymarch::RaymarchParams;
    use aokit_shaders::svao::SvaoFrame;
    use aokit_shaders::vao::VaoParams;
    use aokit_shaders::vbao::VbaoParams;

    pub fn vao(io: &mut PassIo) {
        let params: VaoParams = io.push();
        let out = crate::run_vao(&params, io.f32(0), io.words(1), io.inputs.progress);
        io.take_f32(2).copy_from_slice(&out);
    }

    pub fn blur(io: &mut PassIo) {
        let params: BlurParams = io.push();
        let out = crate::screen::run_blur_direction(&params, io.f32(0), io.f32(1));
        io.take_f32(2).copy_from_slice(&out);
    }

    pub fn svao_pass1(io: &mut PassIo) {
        let frame: SvaoFrame = io.record(0);
        let p = crate::svao::run_pass1(&frame.params, io.f32(1), io.words(2), io.f32(7), io.inputs.progress);
        io.take_f32(3).copy_from_slice(&p.ao);
        io.take(4).copy_from_slice(&p.mask);
        io.take(5).copy_from_slice(&p.ray_min);
        io.take(6).copy_from_slice(&p.ray_max);
    }

    pub fn sd_map(io: &mut PassIo) {
        let frame: SvaoFrame = io.record(0);
        let scene = io.scene();
        let pass1 =
            Pass1 { ao: Vec::new(), mask: Vec::new(), ray_min: io.words(4).to_vec(), ray_max: io.words(5).to_vec() };
        let map = crate::svao::run_sd_map(
            scene.bvh,
            scene.surfaces,
            &frame,
            io.f32(2),
            io.words(3),
            &pass1,
            HitOrder::Traversal,
        );
        io.take_f32(6).copy_from_slice(&map.layers);
        io.rays += map.rays;
    }

    /// The raster coverage-mask SD map: every surface on the texel-centre ray is a fragment.
    pub fn raster_sd_map(io: &mut PassIo) {
        let frame: SvaoFrame = io.record(2);
        let scene = io.scene();
        let pass1 =
            Pass1 { ao: Vec::new(), mask: Vec::new(), ray_min: io.words(4).to_vec(), ray_max: io.words(5).to_vec() };
        let map = crate::svao::run_raster_sd_map(scene.bvh, scene.surfaces, &frame, io.f32(3), &pass1);
        io.take_f32(6).copy_from_slice(&map.layers);
        io.rays += map.rays;
    }

    /// Pass 1's AO and mask as the CPU runners take them.
    fn pass1(io: &PassIo, ao: &[u32], mask: u32) -> Pass1 {
        Pass1 {
            ao: bytemuck::cast_slice(ao).to_vec(),
            mask: io.words(mask).to_vec(),
            ray_min: Vec::new(),
            ray_max: Vec::new(),
        }
    }

    pub fn raysd_pass2(io: &mut PassIo) {
        let frame: SvaoFrame = io.record(0);
        let ao = io.take(3);
        let map = SdMap { layers: io.f32(5).to_vec(), rays: 0 };
        let out = crate::svao::run_pass2_sd(&frame.params, io.f32(1), io.words(2), io.f32(6), &pass1(io, ao, 4), &map);
        ao.copy_from_slice(bytemuck::cast_slice(&out));
    }

    pub fn raysvao(io: &mut PassIo) {
        let frame: SvaoFrame = io.record(0);
        let scene = io.scene();
        let ao = io.take(4);
        let p1 = pass1(io, ao, 5);
        let (out, rays) =
            crate::svao::run_raysvao_pass2(scene.bvh, scene.surfaces, &frame, io.f32(2), io.words(3), io.f32(10), &p1);
        ao.copy_from_slice(bytemuck::cast_slice(&out));
        io.rays += rays;
    }

    pub fn gtao_prefilter(io: &mut PassIo) {
        let params: GtaoParams = io.push();
        let full = params.view.size();
        let size = mip_size(full, params.pass);
        // This level is written in place; it reads only the levels before it.
        let (before, level) = io.take_f32(1).split_at_mut(mip_offset(full, params.pass));
        let level = &mut level[..(size.x * size.y) as usize];
        let depth = io.f32(0);
        crate::screen::tiled(level, size.x, 0..size.x, 0..size.y, &crate::no_progress, |t, v| {
            *v = prefilter_texel(&params, depth, before, t)
        });
    }

    pub fn gtao_normals(io: &mut PassIo) {
        let params: GtaoParams = io.push();
        let out = crate::gtao::per_pixel(params.view.size(), |p| normal_from_depth(&params, io.f32(0), p));
        io.take(1).copy_from_slice(&out);
    }

    pub fn gtao_main(io: &mut PassIo) {
        let params: GtaoParams = io.push();
        let (terms, edges) = (io.take(2), io.take(3));
        crate::gtao::run_main_into(&params, io.f32(0), io.words(1), terms, edges);
    }

    pub fn vbao_main(io: &mut PassIo) {
        let params: VbaoParams = io.push();
        let (terms, edges) = (io.take(2), io.take(3));
        crate::gtao::run_vbao_into(&params, io.f32(0), io.words(1), terms, edges);
    }

    pub fn gtao_denoise(io: &mut PassIo) {
        let params: GtaoParams = io.push();
        let (terms, ao) = (io.take(2), io.take_f32(3));
        crate::gtao::denoise_into(&params, io.words(0), io.words(1), terms, ao);
    }

    pub fn ground_truth(io: &mut PassIo) {
        let frame: GroundTruthFrame = io.record(0);
        let scene = io.scene();
        let size = frame.camera.view.size();
        let gbuffer = crate::GBufferImage {
            width: size.x,
            height: size.y,
            depth: io.f32(2).to_vec(),
            normals: io.words(3).to_vec(),
        };
        let (ao, rays) = crate::run_ground_truth(scene.bvh, scene.surfaces, &frame, &gbuffer, io.inputs.progress);
        io.take_f32(4).copy_from_slice(&ao);
        io.rays += rays;
    }

    pub fn hybrid(io: &mut PassIo) {
        let frame: HybridFrame = io.record(0);
        let scene = io.scene();
        let (ao, terms, edges, rays) =
            crate::hybrid::run_hybrid(scene.bvh, scene.surfaces, &frame, io.f32(2), io.words(3));
        io.rays += rays;
        io.take_f32(4).copy_from_slice(&ao);
        io.take(9).copy_from_slice(&terms);
        io.take(10).copy_from_slice(&edges);
    }

    pub fn raymarch(io: &mut PassIo) {
        let params: RaymarchParams = io.push();
        let kernel: &[Vec2] = &bytemuck::cast_slice::<u32, Vec2>(io.words(2))[..params.directions as usize];
        let (ao, terms, edges) = crate::raymarch::run_raymarch(&params, io.f32(0), io.words(1), kernel);
        io.take_f32(3).copy_from_slice(&ao);
        io.take(4).copy_from_slice(&terms);
        io.take(5).copy_from_slice(&edges);
    }

    /// The temporal accumulation (`aokit_shaders::temporal`) over the full target.
    pub fn temporal_blend(io: &mut PassIo) {
        let frame: aokit_shaders::temporal::TemporalFrame = io.record(0);
        let size = frame.camera.view.size();
        let out = io.take_f32(5);
        let (depth, ao, history, history_depth) = (io.f32(1), io.f32(2), io.f32(3), io.f32(4));
        crate::screen::tiled(out, size.x, 0..size.x, 0..size.y, &crate::no_progress, |p, v| {
            *v = aokit_shaders::temporal::temporal_pixel(&frame, depth, ao, history, history_depth, p)
        });
    }

    /// The history for the next frame: the accumulated AO and this frame's depth.
    pub fn temporal_store(io: &mut PassIo) {
        let (history, history_depth) = (io.take_f32(3), io.take_f32(4));
        history.copy_from_slice(io.f32(2));
        history_depth.copy_from_slice(io.f32(1));
    }
}
