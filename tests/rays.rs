//! `aokit rays` (bench/rays_vs_embree.sh): the dumped files have the documented types
//! and sizes, the dumped AO rays are exactly the ground truth's (per pixel, its AO from the dumped
//! answers equals the ground-truth kernel's), the answers and the reported fractions match an
//! independent brute-force recount over every triangle, and bad input gets a one-line error.

mod common;

use aokit::rays::read_npy;
use aokit::render::CpuRenderer;
use aokit::technique::{SdOptions, Technique};
use aokit_cpu::no_progress;
use aokit_shaders::glam::{DVec3, Vec3};
use aokit_shaders::svao::settings::{RAYSD, RAYSVAO};
use std::path::Path;
use std::process::Command;

const SPP: usize = 16;

fn aokit(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_aokit")).args(args).output().unwrap()
}

/// An `.npy` array of `descr` with `shape`, as its raw little-endian elements.
fn array<T: bytemuck::Pod>(dir: &Path, name: &str, descr: &str, shape: &[usize]) -> Vec<T> {
    let (d, s, data) = read_npy(&dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!((d.as_str(), s.as_slice()), (descr, shape), "{name}: type and shape");
    assert_eq!(data.len(), shape.iter().product::<usize>() * size_of::<T>(), "{name}: payload size");
    bytemuck::pod_collect_to_vec(&data)
}

fn vec3s(flat: &[f32]) -> Vec<Vec3> {
    flat.chunks_exact(3).map(|c| Vec3::new(c[0], c[1], c[2])).collect()
}

/// Nearest hit in `(0, t_max)` of the ray with any triangle, in f64, by the plane of each
/// triangle and three edge tests (not the Möller–Trumbore form the BVH uses); `None` for none.
/// `margin` widens (> 0) or narrows (< 0) the triangles by that fraction of their edge tests, to
/// tell robust answers from grazing ones.
fn brute_force(tris: &[[Vec3; 3]], o: Vec3, d: Vec3, t_max: f32, margin: f64) -> Option<f64> {
    let (o, d) = (o.as_dvec3(), d.as_dvec3());
    let mut best: Option<f64> = None;
    for t in tris {
        let [a, b, c] = t.map(|v| v.as_dvec3());
        let n = (b - a).cross(c - a);
        let denom = n.dot(d);
        if denom == 0.0 {
            continue;
        }
        let s = n.dot(a - o) / denom;
        if !(s > 0.0 && s < t_max as f64) {
            continue;
        }
        let p = o + d * s;
        let edge = |u: DVec3, v: DVec3| (v - u).cross(p - u).dot(n);
        let scale = n.length_squared();
        if [edge(a, b), edge(b, c), edge(c, a)].iter().all(|&e| e >= -margin * scale) {
            best = Some(best.map_or(s, |b: f64| b.min(s)));
        }
    }
    best
}

#[test]
fn dumped_rays_are_the_ground_truths_and_the_answers_recount() {
    let dir = std::env::temp_dir().join(format!("aokit-rays-{}", std::process::id()));
    let spp = SPP.to_string();
    let out = aokit(&[
        "rays",
        "--scene",
        "cornell",
        "--width",
        "160",
        "--height",
        "120",
        "--guard",
        "8",
        "--spp",
        &spp,
        "--repeat",
        "1",
        "--dump",
        dir.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "aokit rays: {}", String::from_utf8_lossy(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON line");
    let file: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("rays.json")).unwrap()).unwrap();
    assert_eq!(json, file, "rays.json holds the printed line");
    assert_eq!(
        (json["format"].as_str(), json["spp"].as_u64(), json["threads"].as_u64()),
        (Some("aokit-rays/1"), Some(16), Some(2))
    );

    // Files: types and sizes from the documented layout.
    let (scene, frame) = common::builtin_frame("cornell", 160, 120, 8);
    let t = scene.triangles.len();
    let tris = vec3s(&array::<f32>(&dir, "triangles.npy", "<f4", &[t, 3, 3]));
    let tris: Vec<[Vec3; 3]> = tris.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
    assert_eq!(tris, scene.triangles);
    let n = json["ao"]["rays"].as_u64().unwrap() as usize;
    let k = json["ao"]["pixels"].as_u64().unwrap() as usize;
    assert_eq!(n, k * SPP, "every pixel that casts rays casts spp of them");
    let origins = vec3s(&array::<f32>(&dir, "ao_origins.npy", "<f4", &[n, 3]));
    let directions = vec3s(&array::<f32>(&dir, "ao_directions.npy", "<f4", &[n, 3]));
    let t_max: Vec<f32> = array(&dir, "ao_tmax.npy", "<f4", &[n]);
    let pixels: Vec<u32> = array(&dir, "ao_pixels.npy", "<u4", &[k, 2]);
    let occluded: Vec<u8> = array(&dir, "ao_occluded.npy", "|u1", &[n]);
    let size = frame.camera.view.size();
    let p = (size.x * size.y) as usize;
    let primary = vec3s(&array::<f32>(&dir, "primary_directions.npy", "<f4", &[p, 3]));
    let hits: Vec<i32> = array(&dir, "primary_hits.npy", "<i4", &[p]);
    let hit_t: Vec<f32> = array(&dir, "primary_t.npy", "<f4", &[p]);
    assert!(t_max.iter().all(|&r| r == frame.radius), "AO rays are as long as the AO radius");
    assert!(directions.iter().all(|d| (d.length() - 1.0).abs() < 1e-5));

    // The rays are the ground truth's: per pixel, the AO from the dumped answers is the
    // ground-truth kernel's, bit for bit, and background pixels cast none.
    let renderer = CpuRenderer::new(&scene);
    let (gbuffer, _) = renderer.gbuffer(&frame, &no_progress);
    let params = frame.ground_truth_params(SPP as u32, false);
    let ao = common::cpu_ground_truth(&renderer, &frame, &gbuffer, &params);
    let view = frame.camera.view;
    for (i, xy) in pixels.chunks_exact(2).enumerate() {
        let index = (xy[1] * size.x + xy[0]) as usize;
        let visible = occluded[i * SPP..(i + 1) * SPP].iter().filter(|&&o| o == 0).count();
        let expect = aokit_shaders::groundtruth::finalize(visible as f32, &params);
        assert_eq!(ao[index], expect, "pixel {xy:?}: the dumped rays' AO is the ground truth's");
        assert!(origins[i * SPP..(i + 1) * SPP].iter().all(|&o| o == origins[i * SPP]), "one origin per pixel");
    }
    let foreground = (view.guard..size.y - view.guard)
        .flat_map(|y| (view.guard..size.x - view.guard).map(move |x| (x, y)))
        .filter(|&(x, y)| gbuffer.depth[(y * size.x + x) as usize] < view.far)
        .count();
    assert_eq!(k, foreground, "every inner pixel with a surface casts rays, no other");

    // Independent recount: brute force over every triangle in f64. Rays whose answer a 1e-6
    // widening or narrowing of the triangles flips graze an edge and may go either way.
    let (mut recount, mut grazing, mut differ) = (0, 0, 0);
    for i in 0..n {
        let wide = brute_force(&tris, origins[i], directions[i], t_max[i], 1e-6).is_some();
        let narrow = brute_force(&tris, origins[i], directions[i], t_max[i], -1e-6).is_some();
        recount += narrow as usize;
        if wide != narrow {
            grazing += 1;
        } else if (occluded[i] != 0) != wide {
            differ += 1;
        }
    }
    assert_eq!(differ, 0, "rays answered otherwise than the brute force ({grazing} grazing of {n})");
    assert!(grazing * 1000 < n, "{grazing} grazing rays of {n}");
    let reported = json["ao"]["occluded_fraction"].as_f64().unwrap();
    let counted = occluded.iter().filter(|&&o| o != 0).count();
    assert_eq!(reported, counted as f64 / n as f64, "the reported fraction is the dumped answers'");
    assert!((reported - recount as f64 / n as f64).abs() <= grazing as f64 / n as f64, "{reported} vs {recount}/{n}");
    assert!(counted > n / 50 && counted < n / 2, "a box occludes some rays, not most: {counted} of {n}");

    // Primary rays: the closest triangle's distance within f32 rounding, misses where the
    // brute force finds nothing.
    let eye: Vec<f32> = json["primary"]["eye"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap() as f32).collect();
    let eye = Vec3::new(eye[0], eye[1], eye[2]);
    let mut hit_count = 0;
    for (j, &d) in primary.iter().enumerate() {
        let expect = brute_force(&tris, eye, d, f32::INFINITY, 0.0);
        match (hits[j], expect) {
            (-1, None) => assert_eq!(hit_t[j], f32::INFINITY),
            (-1, Some(_)) | (_, None) => {
                let (wide, narrow) =
                    (brute_force(&tris, eye, d, f32::INFINITY, 1e-6), brute_force(&tris, eye, d, f32::INFINITY, -1e-6));
                assert_ne!(
                    wide.is_some(),
                    narrow.is_some(),
                    "primary ray {j}: hit {} vs brute force {expect:?}",
                    hits[j]
                );
            }
            (tri, Some(s)) => {
                hit_count += 1;
                assert!(((hit_t[j] as f64) - s).abs() <= 1e-5 * s, "primary ray {j}: t {} vs {s}", hit_t[j]);
                let own = brute_force(&tris[tri as usize..tri as usize + 1], eye, d, f32::INFINITY, 1e-6);
                assert!(
                    own.is_some_and(|t| (t - s).abs() <= 1e-5 * s),
                    "primary ray {j}: triangle {tri} is not hit there"
                );
            }
        }
    }
    assert_eq!(json["primary"]["hits"].as_u64(), Some(hits.iter().filter(|&&h| h >= 0).count() as u64));
    assert!(hit_count > p / 4, "the camera sees the box");

    // The any-hit rays are the techniques' own (default settings): the dumped SD rays are the
    // SD texels the map traces, and their reservoirs end as the map's layers do, bit for bit;
    // Ray-SVAO traces as many rays as the dump holds.
    let s = json["sd"]["rays"].as_u64().unwrap() as usize;
    let layers = json["sd"]["layers"].as_u64().unwrap() as usize;
    let texels: Vec<u32> = array(&dir, "sd_texels.npy", "<u4", &[s]);
    let depth: Vec<f32> = array(&dir, "sd_depth.npy", "<f4", &[s, layers]);
    let count: Vec<u32> = array(&dir, "sd_count.npy", "<u4", &[s]);
    let _ = array::<f32>(&dir, "sd_directions.npy", "<f4", &[s, 3]);
    let _ = array::<f32>(&dir, "sd_interval.npy", "<f4", &[s, 2]);
    let _ = array::<f32>(&dir, "sd_cos.npy", "<f4", &[s]);
    let raysd = Technique::new(&RAYSD, SdOptions::default());
    let run = renderer.run(&frame, &gbuffer, &raysd, &no_progress);
    assert_eq!(run.rays, s as u64, "the SD map traces the dumped rays");
    let map = &run.debug.as_ref().expect("the SD map").sd_map;
    for (k, &q) in texels.iter().enumerate() {
        let q = q as usize;
        let stored: Vec<u32> = map[q * layers..(q + 1) * layers].iter().map(|d| d.to_bits()).collect();
        let dumped: Vec<u32> = depth[k * layers..(k + 1) * layers].iter().map(|d| d.to_bits()).collect();
        assert_eq!(stored, dumped, "SD texel {q}: the dumped reservoir is the map's");
    }
    assert!(s > 100 && count.iter().any(|&c| c > 0), "SD rays that meet surfaces: {s}");
    let v = json["svao"]["rays"].as_u64().unwrap() as usize;
    let state: Vec<f32> = array(&dir, "svao_state.npy", "<f4", &[v, 4]);
    let result: Vec<f32> = array(&dir, "svao_result.npy", "<f4", &[v, 4]);
    let _ = array::<f32>(&dir, "svao_interval.npy", "<f4", &[v, 2]);
    let raysvao = Technique::new(&RAYSVAO, SdOptions::default());
    assert_eq!(
        renderer.run(&frame, &gbuffer, &raysvao, &no_progress).rays,
        v as u64,
        "Ray-SVAO traces the dumped rays"
    );
    assert!(v > 100 && state != result, "Ray-SVAO rays that meet surfaces: {v}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_input_is_one_line() {
    for (args, expect) in [
        (&["--stride", "0"][..], "--stride must be at least 1"),
        (&["--threads", "0"][..], "--threads must be at least 1"),
        (&["--sd-layers", "8"][..], "--sd-layers not read by groundtruth"),
        (&["--copies", "3"][..], "3 copies do not form a square grid"),
    ] {
        let out = aokit(&[&["rays", "--scene", "cornell", "--width", "8", "--height", "8"][..], args].concat());
        assert!(!out.status.success(), "{args:?} must fail");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(expect) && err.trim().lines().count() == 1, "{args:?}: {err}");
    }
}

/// `bench/embree_anyhit.c` gives Embree's intersection filter a C port of the kernels' any-hit
/// decisions (the SD reservoir, `SdHits`; the Ray-SVAO halo, `SampleHits`): on random candidate
/// sequences (random payloads, N, MAX_COUNT, frame rotation, distances and barycentrics) its
/// `--replay` mode ends every ray in the state the Rust kernels end it in, bit for bit.
#[test]
fn embree_harness_any_hit_port_matches_the_kernels() {
    use aokit_cpu::bvh::{AnyHit, replay_any_hit};
    use aokit_shaders::common::alpha::AlphaTables;
    use aokit_shaders::common::any_hit::CandidateHit;
    use aokit_shaders::glam::vec2;
    use aokit_shaders::raysd::{MAX_LAYERS, SdHits, SdPayload};
    use aokit_shaders::raysvao::{SampleHits, SampleRayState};

    if common::skip::without_tool(common::skip::C_COMPILER, "cc", "apt-get install gcc") {
        return;
    }
    let dir = std::env::temp_dir().join(format!("aokit-replay-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let exe = dir.join("embree_anyhit");
    let source = Path::new(env!("CARGO_MANIFEST_DIR")).join("bench/embree_anyhit.c");
    let out = Command::new("cc")
        .args(["-std=c11", "-O2", "-ffp-contract=off", "-DAOKIT_NO_EMBREE", "-o"])
        .arg(&exe)
        .arg(&source)
        .arg("-lm")
        .output()
        .unwrap();
    assert!(out.status.success(), "cc: {}", String::from_utf8_lossy(&out.stderr));

    let mut rng = common::rng::Rng::new(0x1234_5678);
    let mut rnd = move || rng.unit();
    let none = AlphaTables { uvs: &[], materials: &[], headers: &[], texels: &[] };
    let (mut input, mut expect) = (Vec::<u8>::new(), Vec::<u8>::new());
    let (mut accepted, mut ended) = (0, 0);
    for ray in 0..3000 {
        let n = (rnd() * 24.0) as usize;
        let t_halo = 5.0 * rnd();
        let t_const = t_halo + 5.0 * rnd();
        let t_sphere = t_const + 5.0 * rnd();
        let start = SampleRayState { t_halo, t_inside: t_sphere + 30.0 * rnd(), t_const, t_sphere };
        // Candidates anywhere, some exactly on the halo state's bounds, some repeating the one
        // before (the reservoir's z-cull on equal depths).
        let mut hits: Vec<(f32, u32, aokit_shaders::glam::Vec2)> = Vec::new();
        for _ in 0..n {
            let (u, v) = (rnd(), rnd());
            let (u, v) = if u + v > 1.0 { (1.0 - u, 1.0 - v) } else { (u, v) };
            let pick = rnd();
            let t = match (pick * 10.0) as u32 {
                0 => [t_halo, t_const, t_sphere, start.t_inside][(rnd() * 4.0) as usize],
                _ => 0.01 + 40.0 * rnd(),
            };
            match hits.last() {
                Some(&last) if pick > 0.85 => hits.push(last),
                _ => hits.push((t.max(0.01), 7, vec2(u, v))),
            }
        }
        let sd = ray % 2 == 0;
        input.extend_from_slice(&[u32::from(!sd), n as u32].map(u32::to_le_bytes).concat());
        if sd {
            let layers = [1, 2, 4, 8][ray % 4];
            let near = 0.01 + rnd();
            let mut payload = SdPayload {
                depth: [1.0; MAX_LAYERS],
                count: 0,
                layers,
                max_count: layers + (rnd() * 12.0) as u32,
                cos_theta: 0.5 + 0.5 * rnd(),
                near,
                far: near + 5.0 + 50.0 * rnd(),
                rotation: if ray % 3 == 0 { 0.0 } else { rnd() },
            };
            let bytes = |p: &SdPayload| -> Vec<u8> {
                let words: Vec<u32> = p
                    .depth
                    .iter()
                    .map(|d| d.to_bits())
                    .chain([p.count, p.layers, p.max_count])
                    .chain([p.cos_theta, p.near, p.far, p.rotation].map(f32::to_bits))
                    .collect();
                bytemuck::cast_slice(&words).to_vec()
            };
            input.extend(bytes(&payload));
            let mut sd_hits = SdHits { payload, alpha: none };
            replay_any_hit(&hits, 0.0, f32::INFINITY, |t, tri, b| {
                let d = AnyHit::from_decision(sd_hits.decide(t, b, tri));
                accepted += (d != AnyHit::Ignore) as u32;
                d
            });
            payload = sd_hits.payload;
            expect.extend(bytes(&payload));
        } else {
            input.extend_from_slice(bytemuck::bytes_of(&start));
            let mut halo = SampleHits { state: start, alpha: none };
            replay_any_hit(&hits, 0.0, start.t_inside, |t, tri, b| {
                let d = AnyHit::from_decision(halo.decide(t, b, tri));
                ended += (d == AnyHit::AcceptAndEnd) as u32;
                d
            });
            expect.extend_from_slice(bytemuck::bytes_of(&halo.state));
        }
        for (t, _, b) in &hits {
            input.extend_from_slice(&[t.to_bits(), b.x.to_bits(), b.y.to_bits()].map(u32::to_le_bytes).concat());
        }
    }
    assert!(accepted > 100 && ended > 100, "the sequences must reach ACCEPT ({accepted}) and ACCEPT_AND_END ({ended})");
    let (inp, outp) = (dir.join("in.bin"), dir.join("out.bin"));
    std::fs::write(&inp, &input).unwrap();
    let run = Command::new(&exe).arg("--replay").arg(&inp).arg(&outp).output().unwrap();
    assert!(run.status.success(), "--replay: {}", String::from_utf8_lossy(&run.stderr));
    let got = std::fs::read(&outp).unwrap();
    assert_eq!(got.len(), expect.len(), "one final state per record");
    let differ = got.chunks(4).zip(expect.chunks(4)).filter(|(a, b)| a != b).count();
    assert_eq!(differ, 0, "{differ} words of the C port's final states differ from the kernels'");
    std::fs::remove_dir_all(&dir).ok();
}
