//! The CPU executor of a technique's pass graph (`aokit_shaders::graph`): resources are `Vec<u32>`
//! kept across frames, each pass runs its kernel's CPU driver (below), ray-tracing passes go
//! through the BVH with the shared any-hit functions.
//!
//! The executor knows no technique: the order of passes comes from the graph alone, and each
//! pass runs its kernel's CPU driver — the whole-image runner of this crate where one exists
//! ([`cpu_driver`]: fast paths over [`CPU_LANES`](aokit_shaders::common::lanes::CPU_LANES)-pixel lanes and the BVH), else the driver `#[kernel]` generated
//! beside the entry point, which calls the entry point itself once per invocation
//! ([`Kernel::cpu`]). A new screen-space kernel so runs here with no code in this crate.

use crate::gbuffer::Surfaces;
use crate::svao::{HitOrder, Pass1};
use crate::{Progress, SceneBvh};
use aokit_shaders::graph::{Access, Graph, Init, Lifetime, Pass, RAY_COUNT, inputs, ray_count_of};
use aokit_shaders::kernel::{Kernel, KernelIo, Slot};
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
    fn words(&self, slot: u32) -> &[u32] {
        if let Some((_, r)) = self.reads.iter().find(|(s, _)| *s == slot) {
            return r;
        }
        match self.writes.iter().find(|(s, _)| *s == slot) {
            Some((_, Some(w))) => w,
            _ => panic!("pass '{}': slot {slot} is not bound for reading", self.pass.entry()),
        }
    }

    /// The writable words at `slot`, handed out once per pass.
    fn take(&mut self, slot: u32) -> &'a mut [u32] {
        let entry = self.writes.iter_mut().find(|(s, _)| *s == slot);
        entry
            .and_then(|(_, w)| w.take())
            .unwrap_or_else(|| panic!("pass '{}': slot {slot} is not writable", self.pass.entry()))
    }

    /// The buffer bound at `slot` as its declared elements (4-byte aligned ones: `f32`, `u32`,
    /// `Vec2`); read-only, or read-write and not taken yet.
    pub fn read<T: bytemuck::Pod>(&self, slot: Slot<T>) -> &[T] {
        bytemuck::cast_slice(self.words(slot.slot))
    }

    /// The written buffer at `slot` as its declared elements, handed out once per pass.
    pub fn write<T: bytemuck::Pod>(&mut self, slot: Slot<T>) -> &'a mut [T] {
        bytemuck::cast_slice_mut(self.take(slot.slot))
    }

    /// The push constants as the kernel's parameter struct.
    pub fn push<T: bytemuck::Pod>(&self) -> T {
        bytemuck::pod_read_unaligned(&self.pass.push_constants[..size_of::<T>()])
    }

    /// The first record of the buffer at `slot` (parameter records such as `SvaoFrame`).
    pub fn record<T: bytemuck::Pod>(&self, slot: Slot<T>) -> T {
        bytemuck::pod_read_unaligned(&bytemuck::cast_slice::<u32, u8>(self.words(slot.slot))[..size_of::<T>()])
    }

    /// The scene, or a panic naming the pass (the executor checks it before running).
    pub fn scene(&self) -> CpuScene<'a> {
        self.inputs.scene.unwrap_or_else(|| panic!("pass '{}' traces rays but no scene was given", self.pass.entry()))
    }
}

impl KernelIo for PassIo<'_> {
    fn buffers(&mut self, reads: &[u32], writes: &[u32]) -> (&[u8], Vec<&[u32]>, Vec<&mut [u32]>) {
        let read = reads
            .iter()
            .map(|&slot| match self.reads.iter().find(|(s, _)| *s == slot) {
                Some((_, words)) => *words,
                None => panic!("pass '{}': slot {slot} is not bound for reading", self.pass.entry()),
            })
            .collect();
        let mut written: Vec<Option<&mut [u32]>> = writes.iter().map(|_| None).collect();
        for (slot, words) in self.writes.iter_mut() {
            if let Some(i) = writes.iter().position(|s| s == slot) {
                written[i] = words.as_deref_mut();
            }
        }
        let written = written
            .into_iter()
            .zip(writes)
            .map(|(w, slot)| w.unwrap_or_else(|| panic!("pass '{}': slot {slot} is not writable", self.pass.entry())))
            .collect();
        (&self.pass.push_constants, read, written)
    }
}

/// A whole-image CPU runner of a kernel: reads and writes its bindings through [`PassIo`]'s typed
/// slots.
pub type Runner = fn(&mut PassIo);

/// How a pass runs on the CPU.
#[derive(Copy, Clone)]
pub enum CpuDriver {
    /// A runner of this crate.
    Runner(Runner),
    /// The driver generated beside the entry point ([`Kernel::cpu`]).
    Generated(fn(&mut dyn KernelIo, [u32; 2])),
}

/// The kernels this crate runs with its own whole-image runners (lanes, tiles, the BVH). A
/// ray-tracing pass and its ray-query variant are one runner here: the BVH reports every
/// candidate to the same any-hit decision.
static RUNNERS: &[(&Kernel, Runner)] = {
    use aokit_shaders::{
        blur, groundtruth, gtao, halfres, hybrid, rastersd, raymarch, raysd, raysvao, svao, temporal, vao, vbao, vbaosd,
    };
    &[
        (&vao::vao_main::ENTRY, runners::vao),
        (&blur::blur_main::ENTRY, runners::blur),
        (&svao::svao_pass1::ENTRY, runners::svao_pass1),
        (&raysd::rt::raysd_rgen::ENTRY, runners::sd_map),
        (&raysd::rq::raysd_rq::ENTRY, runners::sd_map),
        (&rastersd::rastersd_fs::ENTRY, runners::raster_sd_map),
        (&raysd::raysd_pass2::ENTRY, runners::raysd_pass2),
        (&raysvao::rt::raysvao_rgen::ENTRY, runners::raysvao),
        (&raysvao::rq::raysvao_rq::ENTRY, runners::raysvao),
        (&gtao::gtao_prefilter::ENTRY, runners::gtao_prefilter),
        (&gtao::gtao_normals::ENTRY, runners::gtao_normals),
        (&gtao::gtao_main::ENTRY, runners::gtao_main),
        (&gtao::gtao_denoise::ENTRY, runners::gtao_denoise),
        (&vbao::vbao_main::ENTRY, runners::vbao_main),
        (&vbaosd::vbao_sd_request::ENTRY, runners::vbao_sd_request),
        (&vbaosd::vbao_sd_main::ENTRY, runners::vbao_sd_main),
        (&raymarch::raymarch_main::ENTRY, runners::raymarch),
        (&groundtruth::rt::groundtruth_rgen::ENTRY, runners::ground_truth),
        (&groundtruth::rq::groundtruth_rq::ENTRY, runners::ground_truth),
        (&hybrid::rt::hybrid_rgen::ENTRY, runners::hybrid),
        (&hybrid::rq::hybrid_rq::ENTRY, runners::hybrid),
        (&temporal::temporal_blend::ENTRY, runners::temporal_blend),
        (&halfres::half_downsample::ENTRY, runners::half_downsample),
        (&halfres::half_upsample::ENTRY, runners::half_upsample),
    ]
};

/// How `kernel` runs on the CPU: this crate's runner, else the generated driver; `None` for a
/// kernel with neither (a ray-tracing or raster kernel without a runner).
pub fn cpu_driver(kernel: &Kernel) -> Option<CpuDriver> {
    match RUNNERS.iter().find(|(k, _)| *k == kernel) {
        Some(&(_, run)) => Some(CpuDriver::Runner(run)),
        None => kernel.cpu.map(CpuDriver::Generated),
    }
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
    generated_first: bool,
}

impl CpuExecutor {
    pub fn new() -> Self {
        Self::default()
    }

    /// An executor that runs every kernel with a generated driver ([`Kernel::cpu`]: the entry
    /// point itself, once per invocation) through it rather than through this crate's runner:
    /// slower, and a check that the runners compute what the entry points do.
    pub fn generated_drivers_first() -> Self {
        CpuExecutor { generated_first: true, ..Self::default() }
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
            let generated = pass.kernel.cpu.filter(|_| self.generated_first).map(CpuDriver::Generated);
            let run = generated
                .or_else(|| cpu_driver(pass.kernel))
                .ok_or_else(|| format!("no CPU driver for entry point '{}'", pass.entry()))?;
            let start = Instant::now();
            let invocations = pass.invocations(&graph.view).to_array();
            stats.rays += self.run_pass(pass, inputs, run, invocations)?;
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

    fn run_pass(
        &mut self,
        pass: &Pass,
        inputs: &CpuInputs,
        run: CpuDriver,
        invocations: [u32; 2],
    ) -> Result<u64, String> {
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
                            return Err(format!("pass '{}' traces rays but no scene was given", pass.entry()));
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
            match run {
                CpuDriver::Runner(run) => run(&mut io),
                CpuDriver::Generated(run) => run(&mut io, invocations),
            }
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

/// The whole-image runners (see [`RUNNERS`]): each calls the shader crate's per-pixel functions
/// over whole images (16-pixel lanes, tiles, the BVH) and writes its outputs into the bound
/// resources.
mod runners {
    use super::*;
    use aokit_shaders::gtao::normal_from_depth;
    use aokit_shaders::{
        blur, groundtruth, gtao, halfres, hybrid, rastersd, raymarch, raysd, raysvao, svao, temporal, vao, vbao, vbaosd,
    };

    pub fn vao(io: &mut PassIo) {
        use vao::vao_main::*;
        let params: vao::VaoParams = io.push();
        let out = crate::run_vao(&params, io.read(DEPTH), io.read(NORMALS), io.inputs.progress);
        io.write(AO).copy_from_slice(&out);
    }

    pub fn blur(io: &mut PassIo) {
        use blur::blur_main::*;
        let params: blur::BlurParams = io.push();
        let out = crate::screen::run_blur_direction(&params, io.read(AO_IN), io.read(DEPTH));
        io.write(AO_OUT).copy_from_slice(&out);
    }

    pub fn svao_pass1(io: &mut PassIo) {
        use svao::svao_pass1::*;
        let frame = io.record(FRAME);
        let p = crate::svao::run_pass1(
            &frame.params,
            io.read(DEPTH),
            io.read(NORMALS),
            io.read(DEPTH2),
            io.inputs.progress,
        );
        io.write(AO).copy_from_slice(&p.ao);
        io.write(MASK).copy_from_slice(&p.mask);
        io.write(RAY_MIN).copy_from_slice(&p.ray_min);
        io.write(RAY_MAX).copy_from_slice(&p.ray_max);
    }

    pub fn sd_map(io: &mut PassIo) {
        use raysd::rq::raysd_rq::*;
        let frame = io.record(FRAME);
        let scene = io.scene();
        let pass1 = Pass1 {
            ao: Vec::new(),
            mask: Vec::new(),
            ray_min: io.read(RAY_MIN).to_vec(),
            ray_max: io.read(RAY_MAX).to_vec(),
        };
        let map = crate::svao::run_sd_map(
            scene.bvh,
            scene.surfaces,
            &frame,
            io.read(DEPTH),
            io.read(NORMALS),
            &pass1,
            HitOrder::Traversal,
        );
        io.write(SD_MAP).copy_from_slice(&map.layers);
        io.rays += map.rays;
    }

    /// The raster coverage-mask SD map: every surface on the texel-centre ray is a fragment.
    pub fn raster_sd_map(io: &mut PassIo) {
        use rastersd::rastersd_fs::*;
        let frame = io.record(FRAME);
        let scene = io.scene();
        let pass1 = Pass1 {
            ao: Vec::new(),
            mask: Vec::new(),
            ray_min: io.read(RAY_MIN).to_vec(),
            ray_max: io.read(RAY_MAX).to_vec(),
        };
        let map = crate::svao::run_raster_sd_map(scene.bvh, scene.surfaces, &frame, io.read(DEPTH), &pass1);
        io.write(SD_BITS).copy_from_slice(bytemuck::cast_slice(&map.layers));
        io.rays += map.rays;
    }

    pub fn raysd_pass2(io: &mut PassIo) {
        use raysd::raysd_pass2::*;
        let frame = io.record(FRAME);
        let ao = io.write(AO);
        let gbuffer = (io.read(DEPTH), io.read(NORMALS), io.read(DEPTH2));
        crate::svao::run_pass2_sd_into(&frame.params, gbuffer, ao, io.read(MASK), io.read(SD_MAP));
    }

    pub fn raysvao(io: &mut PassIo) {
        use raysvao::rq::raysvao_rq::*;
        let frame = io.record(FRAME);
        let scene = io.scene();
        let ao = io.write(AO);
        let gbuffer = (io.read(DEPTH), io.read(NORMALS), io.read(DEPTH2));
        let rays = crate::svao::run_raysvao_pass2_into(scene.bvh, scene.surfaces, &frame, gbuffer, ao, io.read(MASK));
        io.rays += rays;
    }

    pub fn gtao_prefilter(io: &mut PassIo) {
        use gtao::gtao_prefilter::*;
        let params: gtao::GtaoParams = io.push();
        let mips = io.write(MIPS);
        crate::gtao::prefilter_pass(&params, io.read(DEPTH), mips);
    }

    pub fn gtao_normals(io: &mut PassIo) {
        use gtao::gtao_normals::*;
        let params: gtao::GtaoParams = io.push();
        let out = crate::gtao::per_pixel(params.view.size(), |p| normal_from_depth(&params, io.read(DEPTH), p));
        io.write(NORMALS).copy_from_slice(&out);
    }

    pub fn gtao_main(io: &mut PassIo) {
        use gtao::gtao_main::*;
        let params: gtao::GtaoParams = io.push();
        let (terms, edges) = (io.write(TERMS), io.write(EDGES));
        crate::gtao::run_main_into(&params, io.read(MIPS), io.read(NORMALS), terms, edges);
    }

    pub fn vbao_main(io: &mut PassIo) {
        use vbao::vbao_main::*;
        let params: vbao::VbaoParams = io.push();
        let (terms, edges) = (io.write(TERMS), io.write(EDGES));
        crate::gtao::run_vbao_into(&params, io.read(MIPS), io.read(NORMALS), terms, edges);
    }

    pub fn vbao_sd_request(io: &mut PassIo) {
        use vbaosd::vbao_sd_request::*;
        let params: vbao::VbaoParams = io.push();
        let frame = io.record(FRAME);
        let (ray_min, ray_max) = (io.write(RAY_MIN), io.write(RAY_MAX));
        crate::gtao::run_vbao_sd_request_into(
            &params,
            &frame.params,
            io.read(MIPS),
            io.read(NORMALS),
            ray_min,
            ray_max,
        );
    }

    pub fn vbao_sd_main(io: &mut PassIo) {
        use vbaosd::vbao_sd_main::*;
        let params: vbao::VbaoParams = io.push();
        let frame = io.record(FRAME);
        let (terms, edges) = (io.write(TERMS), io.write(EDGES));
        let (map, mips, normals) = (io.read(SD_MAP), io.read(MIPS), io.read(NORMALS));
        crate::gtao::run_vbao_sd_into(&params, &frame.params, map, mips, normals, terms, edges);
    }

    pub fn gtao_denoise(io: &mut PassIo) {
        use gtao::gtao_denoise::*;
        let params: gtao::GtaoParams = io.push();
        let (terms, ao) = (io.write(TERMS_OUT), io.write(AO));
        crate::gtao::denoise_into(&params, io.read(TERMS_IN), io.read(EDGES), terms, ao);
    }

    pub fn ground_truth(io: &mut PassIo) {
        use groundtruth::rq::groundtruth_rq::*;
        let frame = io.record(FRAME);
        let scene = io.scene();
        let size = frame.camera.view.size();
        let gbuffer = crate::GBufferImage {
            width: size.x,
            height: size.y,
            depth: io.read(DEPTH).to_vec(),
            normals: io.read(NORMALS).to_vec(),
        };
        let (ao, rays) = crate::run_ground_truth(scene.bvh, scene.surfaces, &frame, &gbuffer, io.inputs.progress);
        io.write(AO).copy_from_slice(&ao);
        io.rays += rays;
    }

    pub fn hybrid(io: &mut PassIo) {
        use hybrid::rq::hybrid_rq::*;
        let frame = io.record(FRAME);
        let scene = io.scene();
        let (ao, terms, edges, rays) =
            crate::hybrid::run_hybrid(scene.bvh, scene.surfaces, &frame, io.read(DEPTH), io.read(NORMALS));
        io.rays += rays;
        io.write(AO).copy_from_slice(&ao);
        io.write(TERMS).copy_from_slice(&terms);
        io.write(EDGES).copy_from_slice(&edges);
    }

    pub fn raymarch(io: &mut PassIo) {
        use raymarch::raymarch_main::*;
        let params: raymarch::RaymarchParams = io.push();
        let kernel = &io.read(KERNEL)[..params.directions as usize];
        let (ao, terms, edges) = crate::raymarch::run_raymarch(&params, io.read(DEPTH), io.read(NORMALS), kernel);
        io.write(AO).copy_from_slice(&ao);
        io.write(TERMS).copy_from_slice(&terms);
        io.write(EDGES).copy_from_slice(&edges);
    }

    /// The half-resolution downsample (`aokit_shaders::halfres`) over the half target,
    /// [`CPU_LANES`](aokit_shaders::common::lanes::CPU_LANES) texels a call.
    pub fn half_downsample(io: &mut PassIo) {
        use aokit_shaders::common::lanes::{CpuLanes, Lanes};
        use halfres::half_downsample::*;
        let params: halfres::HalfParams = io.push();
        let size = params.half.size();
        let (half_depth, half_normals) = (io.write(HALF_DEPTH), io.write(HALF_NORMALS));
        let (depth, normals) = (io.read(DEPTH), io.read(NORMALS));
        let width = params.view.size().x as usize;
        crate::screen::whole_image_lanes2(half_depth, half_normals, size, |first, d, n| {
            let q = crate::screen::lanes_of_run(first, d.len());
            // The blocks' depths straight from their two rows (`block_depths`' order), lanes past
            // the run repeating its last texel as `lanes_of_run` does.
            let row = |dy: usize| &depth[(2 * first.y as usize + dy) * width..][..width];
            let last = d.len() - 1;
            let at =
                |dx: usize, dy: usize| CpuLanes::from_lanes(|i| row(dy)[2 * (first.x as usize + i.min(last)) + dx]);
            let block = [at(0, 0), at(1, 0), at(0, 1), at(1, 1)];
            let (depths, codes) = halfres::half_texel_of_block::<CpuLanes>(&params, normals, q, block);
            for (i, (d, n)) in d.iter_mut().zip(n).enumerate() {
                (*d, *n) = (CpuLanes::lane(depths, i), CpuLanes::index_lane(codes, i));
            }
        });
    }

    /// The half-resolution upsample (`aokit_shaders::halfres`) over the inner image,
    /// [`CPU_LANES`](aokit_shaders::common::lanes::CPU_LANES) pixels a call.
    pub fn half_upsample(io: &mut PassIo) {
        use aokit_shaders::common::lanes::{CpuLanes, Lanes};
        use halfres::half_upsample::*;
        let params: halfres::HalfParams = io.push();
        let (size, g) = (params.view.size(), params.view.guard);
        let out = io.write(AO);
        let (depth, normals, half_depth, half_ao) =
            (io.read(DEPTH), io.read(NORMALS), io.read(HALF_DEPTH), io.read(HALF_AO));
        crate::screen::inner_lanes_into(out, size, g, &crate::no_progress, |first, out| {
            let p = crate::screen::lanes_of_run(first, out.len());
            let ao = halfres::upsample_lanes::<CpuLanes>(&params, depth, normals, half_depth, half_ao, p);
            for (i, v) in out.iter_mut().enumerate() {
                *v = CpuLanes::lane(ao, i);
            }
        });
    }

    /// The temporal accumulation (`aokit_shaders::temporal`) over the full target.
    pub fn temporal_blend(io: &mut PassIo) {
        use temporal::temporal_blend::*;
        let frame = io.record(FRAME);
        let size = frame.camera.view.size();
        let out = io.write(OUT);
        let (depth, ao, history, history_depth) =
            (io.read(DEPTH), io.read(AO), io.read(HISTORY_AO), io.read(HISTORY_DEPTH));
        crate::screen::tiled(out, size.x, 0..size.x, 0..size.y, &crate::no_progress, |p, v| {
            *v = temporal::temporal_pixel(&frame, depth, ao, history, history_depth, p)
        });
    }
}
