//! `aokit rays` (CPU rays vs Embree): the rays cpu-sim traces for one frame — the ground truth's AO rays
//! (spec gtao-raymarch-hybrid §5) and the G-buffer's primary rays (spec svao-raysd §1) — as plain
//! arrays, traced through cpu-sim's BVH on a fixed number of threads and timed, and written as
//! `.npy` files so that another tracer (Embree 4 through `bench/embree_rays.py`) traces exactly
//! the same rays. The AO rays are the ones `ground_truth_pixel` casts: it is run with an
//! [`OcclusionQuery`] that records each ray instead of tracing it, so no sampling formula is
//! repeated here.

use crate::scene::Scene;
use aokit_cpu::bvh::{AnyHit, Hit, PACKET, packet_tiles};
use aokit_cpu::svao::{Pass1, SD_TILE, sd_band_order};
use aokit_cpu::{GBufferImage, SceneBvh, Surfaces};
use aokit_shaders::common::alpha::AlphaTables;
use aokit_shaders::common::any_hit::CandidateHit;
use aokit_shaders::common::camera::Camera;
use aokit_shaders::common::gbuffer_read::GBufferSlices;
use aokit_shaders::glam::{UVec2, Vec3, uvec2};
use aokit_shaders::groundtruth::{GroundTruthFrame, OcclusionQuery, ground_truth_pixel};
use aokit_shaders::raysd::{SdHits, SdPayload, sd_ray};
use aokit_shaders::raysvao::{SampleHits, SampleRay, SampleRayState, SampleTracer, refine_by_ray};
use aokit_shaders::svao::{Refine, Refined, SvaoFrame, pass2_pixel};
use aokit_shaders::vao::kernel::{LineSample, PixelFrame};
use rayon::prelude::*;
use std::io::Write;
use std::path::Path;
use std::time::Instant;

/// The format written into `rays.json`.
pub const FORMAT: &str = "aokit-rays/1";

/// Rays as a structure of arrays, in the order they are traced.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AoRays {
    pub origins: Vec<Vec3>,
    /// Unit directions.
    pub directions: Vec<Vec3>,
    /// Each ray covers `t ∈ (0, t_max)`.
    pub t_max: Vec<f32>,
    /// The inner pixels that cast rays, in order; pixel `k` cast rays `k·spp .. (k+1)·spp`
    /// (background pixels cast none and are not listed).
    pub pixels: Vec<UVec2>,
}

impl AoRays {
    pub fn len(&self) -> usize {
        self.origins.len()
    }

    pub fn is_empty(&self) -> bool {
        self.origins.is_empty()
    }
}

/// An [`OcclusionQuery`] that records every ray the ground-truth kernel asks about and answers
/// "not occluded" (the rays a pixel casts do not depend on the answers).
struct Recorder<'a>(&'a mut AoRays);

impl OcclusionQuery for Recorder<'_> {
    fn occluded(&mut self, origin: Vec3, direction: Vec3, t_max: f32) -> bool {
        self.0.origins.push(origin);
        self.0.directions.push(direction);
        self.0.t_max.push(t_max);
        false
    }
}

/// The ground truth's AO rays for the inner pixels `(guard + i·stride, guard + j·stride)` of
/// `gbuffer` (full target), row by row: exactly the rays `aokit_cpu::run_ground_truth` traces
/// for those pixels (stride 1: every pixel).
pub fn ground_truth_rays(frame: &GroundTruthFrame, gbuffer: &GBufferImage, stride: u32) -> AoRays {
    let view = &frame.camera.view;
    let size = view.size();
    let guard = view.guard;
    let slices = GBufferSlices { depth: &gbuffer.depth, normals: &gbuffer.normals, width: size.x };
    let stride = stride.max(1) as usize;
    let rows: Vec<u32> = (guard..size.y - guard).step_by(stride).collect();
    let per_row: Vec<AoRays> = rows
        .par_iter()
        .map(|&y| {
            let mut rays = AoRays::default();
            for x in (guard..size.x - guard).step_by(stride) {
                let before = rays.len();
                ground_truth_pixel(&slices, frame, uvec2(x, y), &mut Recorder(&mut rays));
                if rays.len() > before {
                    rays.pixels.push(uvec2(x, y));
                }
            }
            rays
        })
        .collect();
    let mut all = AoRays::default();
    for r in per_row {
        all.origins.extend(r.origins);
        all.directions.extend(r.directions);
        all.t_max.extend(r.t_max);
        all.pixels.extend(r.pixels);
    }
    all
}

/// The G-buffer's primary ray directions from the eye (`aokit_cpu::ray_cast_gbuffer`'s), one per
/// pixel centre of the full target, row-major.
pub fn primary_directions(camera: &Camera) -> Vec<Vec3> {
    let size = camera.view.size();
    (0..size.y)
        .into_par_iter()
        .flat_map_iter(|y| (0..size.x).map(move |x| camera.primary_ray_direction(camera.view.pixel_uv(uvec2(x, y)))))
        .collect()
}

/// Whether the alpha test takes part (Embree from Python has none: `Off` traces every triangle
/// as opaque).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Alpha {
    On,
    Off,
}

/// Which traversal answers the rays: what the renderers use, or the steps before it (for the
/// record of what each step bought).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Tracer {
    /// `SceneBvh::occluded` / `closest_hits`: the wide layout, occlusion rays from one origin
    /// sharing an `OriginCut`, primary rays as 4×2 packets.
    Scene,
    /// The wide layout, every ray alone from the root (`occluded_uncached` / `closest_hit`).
    Wide,
    /// obvhs' own CWBVH traversal (`occluded_cwbvh` / `closest_hit_cwbvh`).
    Cwbvh,
}

impl Tracer {
    pub const ALL: [Tracer; 3] = [Tracer::Scene, Tracer::Wide, Tracer::Cwbvh];

    pub fn name(self) -> &'static str {
        match self {
            Tracer::Scene => "scene",
            Tracer::Wide => "wide",
            Tracer::Cwbvh => "cwbvh",
        }
    }
}

/// Rays per parallel work item.
const CHUNK: usize = 4096;

/// Trace every AO ray as the ground truth does (`SceneBvh::occluded` over `t ∈ (0, t_max)`,
/// the alpha test as accept, or every triangle opaque) on the current rayon pool, in chunks of
/// consecutive rays, into `out` (one per ray, 1 = occluded).
pub fn trace_occluded(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    rays: &AoRays,
    alpha: Alpha,
    tracer: Tracer,
    out: &mut [u8],
) {
    assert_eq!(out.len(), rays.len(), "one answer per ray");
    let tables = alpha_tables(surfaces, alpha);
    let accept = |tri: u32, b| tables.passes(tri, b);
    out.par_chunks_mut(CHUNK).with_max_len(1).enumerate().for_each(|(c, chunk)| {
        let base = c * CHUNK;
        for (i, o) in chunk.iter_mut().enumerate() {
            let k = base + i;
            let (origin, direction, t_max) = (rays.origins[k], rays.directions[k], rays.t_max[k]);
            let hit = match tracer {
                Tracer::Scene => bvh.occluded(origin, direction, 0.0, t_max, accept),
                Tracer::Wide => bvh.occluded_uncached(origin, direction, 0.0, t_max, accept),
                Tracer::Cwbvh => bvh.occluded_cwbvh(origin, direction, 0.0, t_max, accept),
            };
            *o = hit as u8;
        }
    });
}

/// Closest hit of every primary ray from `eye` over `t ∈ (0, ∞)`, as the G-buffer casts it
/// (alpha-masked triangles tested where `alpha` is on and the scene has masks), on the current
/// rayon pool, into `out` (one per ray). `directions` are row-major rows of `width`:
/// `Tracer::Scene` traces bands of two rows as 4×2 packets (`SceneBvh::closest_hits`, as
/// `aokit_cpu::ray_cast_gbuffer`), `Tracer::Wide` one ray at a time (`closest_hit`),
/// `Tracer::Cwbvh` through obvhs (no alpha test: opaque scenes only). One band (or
/// `CHUNK` rays) per work item: rayon's default splitting of an indexed iterator stops at
/// about four pieces for two threads, and on a frame whose halves cost differently one
/// thread then idles for up to half the run.
pub fn trace_primary(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    (eye, directions, width): (Vec3, &[Vec3], usize),
    alpha: Alpha,
    tracer: Tracer,
    out: &mut [Option<Hit>],
) {
    assert_eq!(out.len(), directions.len(), "one answer per ray");
    assert!(width > 0 && directions.len() % width == 0, "whole rows of {width} rays");
    let masked = alpha == Alpha::On && surfaces.masked();
    let alpha_test = |tri, b| surfaces.passes_alpha(tri, b);
    if tracer == Tracer::Scene {
        let band = 2 * width;
        out.par_chunks_mut(band).with_max_len(1).enumerate().for_each(|(b, chunk)| {
            let dirs = &directions[b * band..b * band + chunk.len()];
            for tile in packet_tiles(width, chunk.len() / width) {
                let packet = tile.map(|i| dirs[i]);
                let hits = if masked {
                    bvh.closest_accepted_hits(eye, &packet, 0.0, f32::INFINITY, alpha_test)
                } else {
                    bvh.closest_hits(eye, &packet, 0.0, f32::INFINITY)
                };
                for (&i, hit) in tile.iter().zip(hits) {
                    chunk[i] = hit;
                }
            }
        });
        return;
    }
    out.par_chunks_mut(CHUNK).with_max_len(1).enumerate().for_each(|(c, chunk)| {
        for (i, o) in chunk.iter_mut().enumerate() {
            let dir = directions[c * CHUNK + i];
            *o = if tracer == Tracer::Cwbvh {
                bvh.closest_hit_cwbvh(eye, dir, 0.0, f32::INFINITY)
            } else if masked {
                bvh.closest_accepted_hit(eye, dir, 0.0, f32::INFINITY, alpha_test)
            } else {
                bvh.closest_hit(eye, dir, 0.0, f32::INFINITY)
            };
        }
    });
}

/// The SD map's rays of one frame (spec svao-raysd §7.1): one per SD texel whose interval
/// pass 1 requested, from the eye, set up by the kernel's `sd_ray`, each with the reservoir's
/// empty payload (`SdPayload::new`: its `cos θ`, `N`, `MAX_COUNT`, near/far, rotation).
#[derive(Clone, Debug, Default)]
pub struct SdRays {
    pub origin: Vec3,
    pub directions: Vec<Vec3>,
    /// Each ray covers `t ∈ (t_min, t_max)`.
    pub t_min: Vec<f32>,
    pub t_max: Vec<f32>,
    pub payloads: Vec<SdPayload>,
    /// The SD texel (`SvaoParams::sd_index`) of each ray.
    pub texels: Vec<u32>,
}

/// Ray-SVAO's rays of one frame (spec svao-raysd §10): one per flagged sample of pass 1, in
/// pass 2's pixel and sample order, from the eye, set up by the kernel's `sample_ray` (through
/// `pass2_pixel` and `refine_by_ray` with a tracer that records instead of tracing).
#[derive(Clone, Debug, Default)]
pub struct SampleRays {
    pub origin: Vec3,
    pub directions: Vec<Vec3>,
    pub t_min: Vec<f32>,
    pub t_max: Vec<f32>,
    /// The halo state each ray starts with.
    pub states: Vec<SampleRayState>,
}

/// AO pass 1 of the stenciled pipeline on `gbuffer` (single depth): the flagged samples and the
/// SD rays' intervals.
pub fn svao_pass1(frame: &SvaoFrame, gbuffer: &GBufferImage) -> Pass1 {
    let far = vec![frame.params.vao.view.far; gbuffer.depth.len()];
    aokit_cpu::svao::run_pass1(&frame.params, &gbuffer.depth, &gbuffer.normals, &far, &aokit_cpu::no_progress)
}

/// The SD rays of `frame` (`Secondary::StochasticDepth`) after `pass1`, in the order the SD map
/// traces them (`aokit_cpu::svao::sd_band_order`): consecutive rays make its packets.
pub fn sd_rays(frame: &SvaoFrame, gbuffer: &GBufferImage, pass1: &Pass1) -> SdRays {
    let params = &frame.params;
    let view = &params.vao.view;
    let sd = params.sd_size();
    let slices = GBufferSlices { depth: &gbuffer.depth, normals: &gbuffer.normals, width: gbuffer.width };
    let mut out = SdRays { origin: frame.camera.eye(), ..Default::default() };
    // Band by band in the order the SD map traces its texels (tiles of SD_TILE).
    let bands = (0..sd.y).step_by(SD_TILE.y as usize);
    for y0 in bands {
        for q in sd_band_order(sd.x, SD_TILE.y.min(sd.y - y0)) {
            let q = q + uvec2(0, y0);
            let i = params.sd_index(q);
            let ray = sd_ray(&slices, frame, q, pass1.ray_min[i], pass1.ray_max[i]);
            if ray.traced() {
                assert_eq!(ray.origin, out.origin, "SD rays start at the eye");
                out.directions.push(ray.direction);
                out.t_min.push(ray.t_min);
                out.t_max.push(ray.t_max);
                out.payloads.push(SdPayload::new(params, view.near, view.far, ray.cos_theta));
                out.texels.push(i as u32);
            }
        }
    }
    out
}

/// A pass-2 source that records each flagged sample's ray (the kernel's `refine_by_ray` sets it
/// up) and traces nothing.
struct SampleRecorder<'a> {
    frame: &'a SvaoFrame,
    rays: SampleRays,
}

impl SampleTracer for SampleRecorder<'_> {
    fn trace(&mut self, ray: &mut SampleRay) {
        assert_eq!(ray.origin, self.rays.origin, "Ray-SVAO rays start at the eye");
        self.rays.directions.push(ray.direction);
        self.rays.t_min.push(ray.t_min);
        self.rays.t_max.push(ray.t_max);
        self.rays.states.push(ray.state);
    }
}

impl Refine for SampleRecorder<'_> {
    fn refine(&mut self, pixel: &PixelFrame, s: &LineSample, v: f32, z_primary: f32) -> Refined {
        let frame = self.frame;
        refine_by_ray(&frame.camera, &frame.params, pixel, s, v, z_primary, self)
    }
}

/// Ray-SVAO's rays of `frame` (`Secondary::Raytraced`) after `pass1`, pixel by pixel.
pub fn sample_rays(frame: &SvaoFrame, gbuffer: &GBufferImage, pass1: &Pass1) -> SampleRays {
    let params = &frame.params;
    let view = &params.vao.view;
    let size = view.size();
    let slices = GBufferSlices { depth: &gbuffer.depth, normals: &gbuffer.normals, width: gbuffer.width };
    let far = vec![view.far; gbuffer.depth.len()];
    let rays = SampleRays { origin: frame.camera.eye(), ..Default::default() };
    let mut recorder = SampleRecorder { frame, rays };
    for y in view.guard..size.y - view.guard {
        for x in view.guard..size.x - view.guard {
            let i = view.index(uvec2(x, y));
            pass2_pixel(&slices, &far, params, uvec2(x, y), pass1.ao[i], pass1.mask[i], &mut recorder);
        }
    }
    recorder.rays
}

/// The alpha tables of `surfaces`, or none (every triangle opaque) with `Alpha::Off`.
fn alpha_tables<'a>(surfaces: &'a Surfaces, alpha: Alpha) -> AlphaTables<'a> {
    match alpha {
        Alpha::On => surfaces.alpha(),
        Alpha::Off => AlphaTables { uvs: &[], materials: &[], headers: &[], texels: &[] },
    }
}

/// Trace one ray through cpu-sim's any-hit traversal (`tracer` picks which), every candidate
/// going to the kernel's `CandidateHit::decide` — the decision the any-hit shader and the
/// ray-query loop make on Vulkan.
fn trace_candidates<H: CandidateHit>(bvh: &SceneBvh, tracer: Tracer, ray: (Vec3, Vec3, f32, f32), hits: &mut H) {
    let (origin, direction, t_min, t_max) = ray;
    let decide = |t: f32, tri: u32, b| AnyHit::from_decision(hits.decide(t, b, tri));
    match tracer {
        Tracer::Cwbvh => bvh.trace_any_hit_cwbvh(origin, direction, t_min, t_max, decide),
        _ => bvh.trace_any_hit(origin, direction, t_min, t_max, decide),
    }
}

/// Trace every SD ray with the reservoir any-hit (`SdHits`, alpha test per `alpha`) on the
/// current rayon pool; `out` gets each ray's final payload (its `N` depths and hit count).
/// `Tracer::Scene` traces packets of 8 consecutive rays (`SceneBvh::trace_any_hit_packet`, as
/// the SD map does), the others one ray at a time.
pub fn trace_sd(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    rays: &SdRays,
    alpha: Alpha,
    tracer: Tracer,
    out: &mut [SdPayload],
) {
    assert_eq!(out.len(), rays.payloads.len(), "one answer per ray");
    let tables = alpha_tables(surfaces, alpha);
    out.par_chunks_mut(CHUNK / 16).with_max_len(1).enumerate().for_each(|(c, chunk)| {
        let first = c * (CHUNK / 16);
        if tracer == Tracer::Scene {
            for (p, packet) in chunk.chunks_mut(PACKET).enumerate() {
                let n = packet.len();
                // Ray `i` of the packet (a short packet repeats its last ray in the unused lanes).
                let ray = |i: usize| first + p * PACKET + i.min(n - 1);
                let pick = |v: &[f32]| std::array::from_fn(|i| v[ray(i)]);
                let directions = std::array::from_fn(|i| rays.directions[ray(i)]);
                let mut hits: [SdHits; PACKET] =
                    std::array::from_fn(|i| SdHits { payload: rays.payloads[ray(i)], alpha: tables });
                let interval = (&pick(&rays.t_min), &pick(&rays.t_max));
                bvh.trace_any_hit_packet(rays.origin, &directions, interval, n, |i, t, tri, b| {
                    AnyHit::from_decision(hits[i].decide(t, b, tri))
                });
                for (o, h) in packet.iter_mut().zip(&hits) {
                    *o = h.payload;
                }
            }
            return;
        }
        for (i, o) in chunk.iter_mut().enumerate() {
            let k = first + i;
            let mut hits = SdHits { payload: rays.payloads[k], alpha: tables };
            trace_candidates(bvh, tracer, (rays.origin, rays.directions[k], rays.t_min[k], rays.t_max[k]), &mut hits);
            *o = hits.payload;
        }
    });
}

/// Trace every Ray-SVAO ray with the halo any-hit (`SampleHits`, alpha test per `alpha`) on
/// the current rayon pool; `out` gets each ray's final state.
pub fn trace_samples(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    rays: &SampleRays,
    alpha: Alpha,
    tracer: Tracer,
    out: &mut [SampleRayState],
) {
    assert_eq!(out.len(), rays.states.len(), "one answer per ray");
    let tables = alpha_tables(surfaces, alpha);
    out.par_chunks_mut(CHUNK / 4).with_max_len(1).enumerate().for_each(|(c, chunk)| {
        for (i, o) in chunk.iter_mut().enumerate() {
            let k = c * (CHUNK / 4) + i;
            let mut hits = SampleHits { state: rays.states[k], alpha: tables };
            trace_candidates(bvh, tracer, (rays.origin, rays.directions[k], rays.t_min[k], rays.t_max[k]), &mut hits);
            *o = hits.state;
        }
    });
}

/// CPU seconds this process has used (user + system, all threads), from `/proc/self/stat`
/// (Linux; `None` elsewhere). Its resolution is a clock tick (10 ms).
pub fn process_cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the command name (which may hold spaces): state is field 3, utime 14, stime 15.
    let fields: Vec<&str> = stat.get(stat.rfind(')')? + 2..)?.split(' ').collect();
    let ticks = fields.get(11)?.parse::<f64>().ok()? + fields.get(12)?.parse::<f64>().ok()?;
    // USER_HZ, fixed at 100 by the Linux ABI.
    Some(ticks / 100.0)
}

/// Wall-clock and CPU seconds of each run of [`timed`].
#[derive(Clone, Debug, Default)]
pub struct Timings {
    pub wall: Vec<f64>,
    /// Empty where the CPU time is unknown.
    pub cpu: Vec<f64>,
}

/// Run `f` `repeats` times (at least once); its last result and the seconds of each run.
pub fn timed<T>(repeats: u32, mut f: impl FnMut() -> T) -> (T, Timings) {
    let mut times = Timings::default();
    let mut result = None;
    for _ in 0..repeats.max(1) {
        let cpu = process_cpu_seconds();
        let t = Instant::now();
        result = Some(f());
        times.wall.push(t.elapsed().as_secs_f64());
        if let (Some(before), Some(after)) = (cpu, process_cpu_seconds()) {
            times.cpu.push(after - before);
        }
    }
    (result.expect("ran at least once"), times)
}

/// `{"runs_s", "min_s", "median_s", "mrays_per_s_best", "mrays_per_s_median", "cpu_s",
/// "mrays_per_cpu_s"}` of `rays` rays traced in each run: M rays per second of the fastest and
/// of the median run, and per CPU second over all runs (what one core does, whatever else the
/// machine runs).
pub fn throughput_json(rays: usize, times: &Timings) -> serde_json::Value {
    let min = times.wall.iter().copied().fold(f64::INFINITY, f64::min);
    let median = crate::report::median(&mut times.wall.clone());
    let cpu: f64 = times.cpu.iter().sum();
    let mut json = serde_json::json!({
        "runs_s": times.wall, "min_s": min, "median_s": median,
        "mrays_per_s_best": rays as f64 / min / 1e6, "mrays_per_s_median": rays as f64 / median / 1e6,
    });
    if times.cpu.len() == times.wall.len() && cpu > 0.0 {
        json["cpu_s"] = times.cpu.clone().into();
        json["mrays_per_cpu_s"] = (rays as f64 * times.cpu.len() as f64 / cpu / 1e6).into();
    }
    json
}

/// A little-endian `.npy` file (format 1.0): `descr` is numpy's type string (`<f4`, `<u4`,
/// `<i4`, `|u1`), `shape` the array's, `data` its C-order bytes.
pub fn write_npy(path: &Path, descr: &str, shape: &[usize], data: &[u8]) -> std::io::Result<()> {
    let dims: Vec<String> = shape.iter().map(|d| d.to_string()).collect();
    let shape = if dims.len() == 1 { format!("({},)", dims[0]) } else { format!("({})", dims.join(", ")) };
    let mut header = format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': {shape}, }}");
    // Magic (6) + version (2) + length (2) + header + '\n', padded to a multiple of 64.
    let total = (10 + header.len() + 1).div_ceil(64) * 64;
    header.push_str(&" ".repeat(total - 10 - header.len() - 1));
    header.push('\n');
    let mut file = std::io::BufWriter::new(std::fs::File::create(path)?);
    file.write_all(b"\x93NUMPY\x01\x00")?;
    file.write_all(&(header.len() as u16).to_le_bytes())?;
    file.write_all(header.as_bytes())?;
    file.write_all(data)?;
    file.into_inner().map_err(|e| e.into_error())?.sync_all()
}

/// The header and payload of a `.npy` file written by [`write_npy`]: `(descr, shape, data)`.
pub fn read_npy(path: &Path) -> std::io::Result<(String, Vec<usize>, Vec<u8>)> {
    let bytes = std::fs::read(path)?;
    let bad = |what: &str| std::io::Error::other(format!("{}: {what}", path.display()));
    if bytes.len() < 10 || &bytes[..8] != b"\x93NUMPY\x01\x00" {
        return Err(bad("not a version 1.0 .npy file"));
    }
    let len = u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
    let header = std::str::from_utf8(bytes.get(10..10 + len).ok_or_else(|| bad("short header"))?)
        .map_err(|_| bad("header is not UTF-8"))?;
    let field = |key: &str| {
        let start = header.find(key).map(|i| i + key.len()).ok_or_else(|| bad(&format!("no {key} in the header")))?;
        Ok::<_, std::io::Error>(&header[start..])
    };
    let descr = field("'descr': '")?.split('\'').next().unwrap_or_default().to_string();
    let shape_text = field("'shape': (")?.split(')').next().unwrap_or_default();
    let shape = shape_text
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| s.parse::<usize>().map_err(|_| bad("bad shape")))
        .collect::<Result<Vec<_>, _>>()?;
    Ok((descr, shape, bytes[10 + len..].to_vec()))
}

/// Write the scene's triangles and the rays into `dir` (created if missing): `triangles.npy`
/// (f32 T×3×3, world-space corners), `ao_origins.npy`, `ao_directions.npy` (f32 N×3),
/// `ao_tmax.npy` (f32 N; every ray covers `t ∈ (0, t_max)`), `ao_pixels.npy` (u32 K×2: the
/// pixels that cast rays, `spp` consecutive rays each), `ao_occluded.npy` (u8 N: cpu-sim's
/// answer, 1 = occluded), `primary_directions.npy` (f32 P×3, from the eye in `rays.json`),
/// `primary_hits.npy` (i32 P: cpu-sim's closest triangle, −1 = miss) and `primary_t.npy`
/// (f32 P: its distance, ∞ = miss).
pub fn write_dump(
    dir: &Path,
    scene: &Scene,
    ao: &AoRays,
    occluded: &[u8],
    primary: &[Vec3],
    hits: &[Option<Hit>],
) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    let f32s = |v: &[Vec3]| -> Vec<f32> { v.iter().flat_map(|p| p.to_array()).collect() };
    let corners: Vec<f32> = scene.triangles.iter().flatten().flat_map(|v| v.to_array()).collect();
    write_npy(&dir.join("triangles.npy"), "<f4", &[scene.triangles.len(), 3, 3], bytemuck::cast_slice(&corners))?;
    let n = ao.len();
    write_npy(&dir.join("ao_origins.npy"), "<f4", &[n, 3], bytemuck::cast_slice(&f32s(&ao.origins)))?;
    write_npy(&dir.join("ao_directions.npy"), "<f4", &[n, 3], bytemuck::cast_slice(&f32s(&ao.directions)))?;
    write_npy(&dir.join("ao_tmax.npy"), "<f4", &[n], bytemuck::cast_slice(&ao.t_max))?;
    let pixels: Vec<u32> = ao.pixels.iter().flat_map(|p| p.to_array()).collect();
    write_npy(&dir.join("ao_pixels.npy"), "<u4", &[ao.pixels.len(), 2], bytemuck::cast_slice(&pixels))?;
    write_npy(&dir.join("ao_occluded.npy"), "|u1", &[n], occluded)?;
    let p = primary.len();
    write_npy(&dir.join("primary_directions.npy"), "<f4", &[p, 3], bytemuck::cast_slice(&f32s(primary)))?;
    let ids: Vec<i32> = hits.iter().map(|h| h.map_or(-1, |h| h.triangle as i32)).collect();
    write_npy(&dir.join("primary_hits.npy"), "<i4", &[p], bytemuck::cast_slice(&ids))?;
    let ts: Vec<f32> = hits.iter().map(|h| h.map_or(f32::INFINITY, |h| h.t)).collect();
    write_npy(&dir.join("primary_t.npy"), "<f4", &[p], bytemuck::cast_slice(&ts))
}

/// Write the any-hit rays and cpu-sim's answers into `dir` (beside [`write_dump`]'s files; all
/// rays start at the eye): `sd_directions.npy` (f32 S×3), `sd_interval.npy` (f32 S×2:
/// `t_min, t_max`, open), `sd_cos.npy` (f32 S: the payload's `cos θ`), `sd_depth.npy` (f32 S×N:
/// cpu-sim's reservoir, 1 = empty), `sd_count.npy` (u32 S: its hit count) and `sd_texels.npy`
/// (u32 S: each ray's SD texel, `SvaoParams::sd_index`);
/// `svao_directions.npy` (f32 V×3), `svao_interval.npy` (f32 V×2), `svao_state.npy` (f32 V×4:
/// the starting `t_halo, t_inside, t_const, t_sphere`) and `svao_result.npy` (f32 V×4:
/// cpu-sim's final state).
pub fn write_any_hit_dump(
    dir: &Path,
    (sd, sd_out, layers): (&SdRays, &[SdPayload], usize),
    (sv, sv_out): (&SampleRays, &[SampleRayState]),
) -> std::io::Result<()> {
    let f32s = |v: &[Vec3]| -> Vec<f32> { v.iter().flat_map(|p| p.to_array()).collect() };
    let pairs = |a: &[f32], b: &[f32]| -> Vec<f32> { a.iter().zip(b).flat_map(|(x, y)| [*x, *y]).collect() };
    let n = sd.payloads.len();
    write_npy(&dir.join("sd_directions.npy"), "<f4", &[n, 3], bytemuck::cast_slice(&f32s(&sd.directions)))?;
    write_npy(&dir.join("sd_interval.npy"), "<f4", &[n, 2], bytemuck::cast_slice(&pairs(&sd.t_min, &sd.t_max)))?;
    let cos: Vec<f32> = sd.payloads.iter().map(|p| p.cos_theta).collect();
    write_npy(&dir.join("sd_cos.npy"), "<f4", &[n], bytemuck::cast_slice(&cos))?;
    let depth: Vec<f32> = sd_out.iter().flat_map(|p| p.depth[..layers].iter().copied()).collect();
    write_npy(&dir.join("sd_depth.npy"), "<f4", &[n, layers], bytemuck::cast_slice(&depth))?;
    let count: Vec<u32> = sd_out.iter().map(|p| p.count).collect();
    write_npy(&dir.join("sd_count.npy"), "<u4", &[n], bytemuck::cast_slice(&count))?;
    write_npy(&dir.join("sd_texels.npy"), "<u4", &[n], bytemuck::cast_slice(&sd.texels))?;
    let v = sv.states.len();
    write_npy(&dir.join("svao_directions.npy"), "<f4", &[v, 3], bytemuck::cast_slice(&f32s(&sv.directions)))?;
    write_npy(&dir.join("svao_interval.npy"), "<f4", &[v, 2], bytemuck::cast_slice(&pairs(&sv.t_min, &sv.t_max)))?;
    write_npy(&dir.join("svao_state.npy"), "<f4", &[v, 4], bytemuck::cast_slice(&sv.states))?;
    write_npy(&dir.join("svao_result.npy"), "<f4", &[v, 4], bytemuck::cast_slice(sv_out))
}

#[cfg(feature = "cli")]
pub use command::{RaysArgs, rays_command};

#[cfg(feature = "cli")]
mod command {
    use super::*;
    use crate::cli::{SceneArgs, TechniqueArgs};
    use crate::technique::{GroundTruthSettings, SdOptions};
    use aokit_shaders::svao::Secondary;
    use std::path::PathBuf;

    /// `aokit rays`: the frame's ground-truth AO rays and primary rays through cpu-sim's BVH.
    #[derive(clap::Args)]
    #[command(allow_negative_numbers = true)]
    pub struct RaysArgs {
        #[command(flatten)]
        view: SceneArgs,
        /// The ground truth's settings (`--spp`, `--uniform`).
        #[command(flatten)]
        options: TechniqueArgs,
        /// G-buffer guard band in pixels on every side (as `aokit render`).
        #[arg(long, default_value_t = 64)]
        guard: u32,
        /// Cast the AO rays of every STRIDE-th inner pixel in x and y (1: every pixel).
        #[arg(long, default_value_t = 1)]
        stride: u32,
        /// The scene instanced K times on a square grid (1, 4, 16, …; as `aokit scaling`), the
        /// camera framing the original.
        #[arg(long, default_value_t = 1)]
        copies: u32,
        /// Threads tracing (a rayon pool of this size).
        #[arg(long, default_value_t = 2)]
        threads: usize,
        /// Timed runs of each traversal (min and median reported).
        #[arg(long, default_value_t = 3)]
        repeat: u32,
        /// Alpha test of masked materials: `on` as the ground truth and the G-buffer, `off` every
        /// triangle opaque (what Embree from Python traces).
        #[arg(long, default_value = "on", value_parser = ["on", "off"])]
        alpha: String,
        /// Also time the earlier traversals (the wide layout without shared cuts; obvhs' CWBVH
        /// traversal), to show what each step bought.
        #[arg(long)]
        steps: bool,
        /// Write the triangles, the rays and cpu-sim's answers into this folder (`.npy` files and
        /// `rays.json`, see `aokit::rays::write_dump`).
        #[arg(long)]
        dump: Option<PathBuf>,
    }

    /// `aokit rays`.
    pub fn rays_command(args: RaysArgs) -> Result<(), String> {
        if args.stride == 0 {
            return Err("--stride must be at least 1".into());
        }
        if args.threads == 0 {
            return Err("--threads must be at least 1".into());
        }
        if args.repeat == 0 {
            return Err("--repeat must be at least 1".into());
        }
        // The rays depend on neither: refuse them rather than accept and ignore them.
        if args.view.exponent != 2.0 || args.view.thickness != 0.0 {
            return Err("--exponent and --thickness do not change the rays; `aokit rays` takes neither".into());
        }
        let technique = args.options.technique("groundtruth")?;
        let settings = *technique.settings::<GroundTruthSettings>().expect("groundtruth reads GroundTruthSettings");
        let alpha = if args.alpha == "on" { Alpha::On } else { Alpha::Off };
        let (scene, frame) = args.view.resolve(args.guard)?;
        let scene = if args.copies == 1 { scene } else { scene.instanced_grid(args.copies)? };
        let pool = rayon::ThreadPoolBuilder::new().num_threads(args.threads).build().map_err(|e| e.to_string())?;
        let json = pool.install(|| {
            let t = Instant::now();
            let bvh = SceneBvh::build(&scene.triangles);
            let build_ms = t.elapsed().as_secs_f64() * 1e3;
            let face_normals = scene.face_normals();
            let (mask_headers, mask_texels) = scene.alpha_masks();
            let masked = mask_headers.iter().filter(|h| h.width > 0).count();
            let surfaces = Surfaces {
                face_normals: &face_normals,
                uvs: &scene.triangle_uvs,
                materials: &scene.triangle_materials,
                mask_headers: &mask_headers,
                mask_texels: &mask_texels,
            };
            let gbuffer = aokit_cpu::ray_cast_gbuffer(&bvh, &surfaces, &frame.camera, &aokit_cpu::no_progress);
            let gt = settings.frame(&frame.desc());
            let t = Instant::now();
            let ao = ground_truth_rays(&gt, &gbuffer, args.stride);
            let generate_ms = t.elapsed().as_secs_f64() * 1e3;
            // Answers are written into buffers allocated (and touched) before the timing.
            let mut occluded = vec![1u8; ao.len()];
            let ((), ao_times) =
                timed(args.repeat, || trace_occluded(&bvh, &surfaces, &ao, alpha, Tracer::Scene, &mut occluded));
            let directions = primary_directions(&frame.camera);
            let eye = frame.camera.eye();
            let width = frame.camera.view.size().x as usize;
            let mut hits = vec![None; directions.len()];
            let ((), primary_times) = timed(args.repeat, || {
                trace_primary(&bvh, &surfaces, (eye, &directions, width), alpha, Tracer::Scene, &mut hits)
            });
            // The SD map's and Ray-SVAO's any-hit rays (default settings) after AO pass 1.
            let sd_frame = SdOptions::default().frame(&frame.desc(), Secondary::StochasticDepth);
            let t = Instant::now();
            let sd = sd_rays(&sd_frame, &gbuffer, &svao_pass1(&sd_frame, &gbuffer));
            let sd_generate_ms = t.elapsed().as_secs_f64() * 1e3;
            let mut sd_out = sd.payloads.clone();
            let ((), sd_times) =
                timed(args.repeat, || trace_sd(&bvh, &surfaces, &sd, alpha, Tracer::Scene, &mut sd_out));
            let sv_frame = SdOptions::default().frame(&frame.desc(), Secondary::Raytraced);
            let t = Instant::now();
            let sv = sample_rays(&sv_frame, &gbuffer, &svao_pass1(&sv_frame, &gbuffer));
            let sv_generate_ms = t.elapsed().as_secs_f64() * 1e3;
            let mut sv_out = sv.states.clone();
            let ((), sv_times) =
                timed(args.repeat, || trace_samples(&bvh, &surfaces, &sv, alpha, Tracer::Scene, &mut sv_out));
            // The earlier steps: throughput and how many answers differ from the shipped one.
            let mut steps = serde_json::Map::new();
            for tracer in Tracer::ALL.into_iter().skip(1).filter(|_| args.steps) {
                let mut o = vec![1u8; ao.len()];
                let ((), t) = timed(args.repeat, || trace_occluded(&bvh, &surfaces, &ao, alpha, tracer, &mut o));
                let mut h = vec![None; directions.len()];
                let primary = (eye, directions.as_slice(), width);
                let ((), p) = timed(args.repeat, || trace_primary(&bvh, &surfaces, primary, alpha, tracer, &mut h));
                let mut step = serde_json::json!({
                    "ao": throughput_json(ao.len(), &t),
                    "ao_differ": o.iter().zip(&occluded).filter(|(a, b)| a != b).count(),
                    "primary": throughput_json(directions.len(), &p),
                    "primary_differ": h.iter().zip(&hits).filter(|(a, b)| a.map(|x| x.triangle) != b.map(|x| x.triangle)).count(),
                });
                // SD rays: packets, single rays on the wide layout, obvhs' traversal.
                let mut d = sd.payloads.clone();
                let ((), t) = timed(args.repeat, || trace_sd(&bvh, &surfaces, &sd, alpha, tracer, &mut d));
                step["sd"] = throughput_json(sd.payloads.len(), &t);
                step["sd_differ"] = d.iter().zip(&sd_out).filter(|(a, b)| a != b).count().into();
                if tracer == Tracer::Cwbvh {
                    // The Ray-SVAO rays have two traversals: the shipped one and obvhs'.
                    let mut v = sv.states.clone();
                    let ((), t) = timed(args.repeat, || trace_samples(&bvh, &surfaces, &sv, alpha, tracer, &mut v));
                    step["svao"] = throughput_json(sv.states.len(), &t);
                    step["svao_differ"] = v.iter().zip(&sv_out).filter(|(a, b)| a != b).count().into();
                }
                steps.insert(tracer.name().into(), step);
            }
            let n_occluded = occluded.iter().filter(|&&o| o != 0).count();
            let n_hits = hits.iter().filter(|h| h.is_some()).count();
            let mut json = frame.describe();
            json["format"] = FORMAT.into();
            json["scene"] = scene.name.clone().into();
            json["triangles"] = scene.triangles.len().into();
            json["masked_materials"] = masked.into();
            json["alpha"] = args.alpha.clone().into();
            json["threads"] = args.threads.into();
            json["spp"] = settings.spp.into();
            json["sampling"] = if settings.uniform { "uniform" } else { "cosine" }.into();
            json["stride"] = args.stride.into();
            json["copies"] = args.copies.into();
            json["bvh_build_ms"] = build_ms.into();
            json["ao"] = serde_json::json!({
                "rays": ao.len(), "pixels": ao.pixels.len(), "t_min": 0.0, "generate_ms": generate_ms,
                "occluded": n_occluded, "occluded_fraction": n_occluded as f64 / ao.len().max(1) as f64,
                "cpu_sim": throughput_json(ao.len(), &ao_times),
            });
            json["primary"] = serde_json::json!({
                "rays": directions.len(), "eye": eye.to_array(), "t_min": 0.0,
                "hits": n_hits, "hit_fraction": n_hits as f64 / directions.len().max(1) as f64,
                "cpu_sim": throughput_json(directions.len(), &primary_times),
            });
            let p = &sd_frame.params;
            json["sd"] = serde_json::json!({
                "rays": sd.payloads.len(), "generate_ms": sd_generate_ms, "origin": sd.origin.to_array(),
                "layers": p.sd_layers, "max_count": p.max_count, "sd_res_divisor": SdOptions::default().divisor,
                "near": p.vao.view.near, "far": p.vao.view.far,
                "rotation": sd.payloads.first().map_or(0.0, |q| q.rotation),
                "cpu_sim": throughput_json(sd.payloads.len(), &sd_times),
            });
            json["svao"] = serde_json::json!({
                "rays": sv.states.len(), "generate_ms": sv_generate_ms, "origin": sv.origin.to_array(),
                "cpu_sim": throughput_json(sv.states.len(), &sv_times),
            });
            if args.steps {
                json["steps"] = steps.into();
            }
            if let Some(dir) = &args.dump {
                write_dump(dir, &scene, &ao, &occluded, &directions, &hits)
                    .and_then(|()| write_any_hit_dump(dir, (&sd, &sd_out, sd_frame.params.sd_layers as usize), (&sv, &sv_out)))
                    .map_err(|e| format!("{}: {e}", dir.display()))?;
                let text = serde_json::to_string_pretty(&json).expect("serializable") + "\n";
                crate::output::write_atomic_bytes(&dir.join("rays.json"), text.as_bytes())
                    .map_err(|e| format!("{}: {e}", dir.display()))?;
            }
            Ok::<_, String>(json)
        })?;
        println!("{json}");
        Ok(())
    }
}
