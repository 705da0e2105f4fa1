//! `aokit rays` (issue 14): the rays cpu-sim traces for one frame — the ground truth's AO rays
//! (spec gtao-raymarch-hybrid §5) and the G-buffer's primary rays (spec svao-raysd §1) — as plain
//! arrays, traced through cpu-sim's BVH on a fixed number of threads and timed, and written as
//! `.npy` files so that another tracer (Embree 4 through `bench/embree_rays.py`) traces exactly
//! the same rays. The AO rays are the ones `ground_truth_pixel` casts: it is run with an
//! [`OcclusionQuery`] that records each ray instead of tracing it, so no sampling formula is
//! repeated here.

use crate::scene::Scene;
use aokit_cpu::bvh::Hit;
use aokit_cpu::{GBufferImage, SceneBvh, Surfaces};
use aokit_shaders::common::camera::Camera;
use aokit_shaders::common::gbuffer_read::GBufferSlices;
use aokit_shaders::glam::{UVec2, Vec3, uvec2};
use aokit_shaders::groundtruth::{GroundTruthFrame, OcclusionQuery, ground_truth_pixel};
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
    /// `SceneBvh::occluded` / `closest_hit`: the wide layout, occlusion rays from one origin
    /// sharing an `OriginCut`.
    Scene,
    /// The wide layout, every ray from the root (`occluded_uncached`).
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
    let accept = |tri: u32, b| alpha == Alpha::Off || surfaces.passes_alpha(tri, b);
    out.par_chunks_mut(CHUNK).enumerate().for_each(|(c, chunk)| {
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
/// rayon pool, into `out` (one per ray). `Tracer::Cwbvh` has no alpha test (opaque scenes
/// only).
pub fn trace_primary(
    bvh: &SceneBvh,
    surfaces: &Surfaces,
    (eye, directions): (Vec3, &[Vec3]),
    alpha: Alpha,
    tracer: Tracer,
    out: &mut [Option<Hit>],
) {
    assert_eq!(out.len(), directions.len(), "one answer per ray");
    let masked = alpha == Alpha::On && surfaces.mask_headers.iter().any(|h| h.width > 0);
    out.par_chunks_mut(CHUNK).enumerate().for_each(|(c, chunk)| {
        for (i, o) in chunk.iter_mut().enumerate() {
            let dir = directions[c * CHUNK + i];
            *o = if tracer == Tracer::Cwbvh {
                bvh.closest_hit_cwbvh(eye, dir, 0.0, f32::INFINITY)
            } else if masked {
                bvh.closest_accepted_hit(eye, dir, 0.0, f32::INFINITY, |tri, b| surfaces.passes_alpha(tri, b))
            } else {
                bvh.closest_hit(eye, dir, 0.0, f32::INFINITY)
            };
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

#[cfg(feature = "cli")]
pub use command::{RaysArgs, rays_command};

#[cfg(feature = "cli")]
mod command {
    use super::*;
    use crate::cli::{SceneArgs, TechniqueArgs};
    use crate::technique::GroundTruthSettings;
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
            let mut hits = vec![None; directions.len()];
            let ((), primary_times) = timed(args.repeat, || {
                trace_primary(&bvh, &surfaces, (eye, &directions), alpha, Tracer::Scene, &mut hits)
            });
            // The earlier steps: throughput and how many answers differ from the shipped one.
            let mut steps = serde_json::Map::new();
            for tracer in Tracer::ALL.into_iter().skip(1).filter(|_| args.steps) {
                let mut o = vec![1u8; ao.len()];
                let ((), t) = timed(args.repeat, || trace_occluded(&bvh, &surfaces, &ao, alpha, tracer, &mut o));
                let mut h = vec![None; directions.len()];
                let ((), p) =
                    timed(args.repeat, || trace_primary(&bvh, &surfaces, (eye, &directions), alpha, tracer, &mut h));
                steps.insert(tracer.name().into(), serde_json::json!({
                    "ao": throughput_json(ao.len(), &t),
                    "ao_differ": o.iter().zip(&occluded).filter(|(a, b)| a != b).count(),
                    "primary": throughput_json(directions.len(), &p),
                    "primary_differ": h.iter().zip(&hits).filter(|(a, b)| a.map(|x| x.triangle) != b.map(|x| x.triangle)).count(),
                }));
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
            if args.steps {
                json["steps"] = steps.into();
            }
            if let Some(dir) = &args.dump {
                write_dump(dir, &scene, &ao, &occluded, &directions, &hits)
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
