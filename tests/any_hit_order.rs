//! cpu-sim's any-hit traversal (`SceneBvh::trace_any_hit`, now on the wide layout)
//! offers the candidates of a ray in exactly the order obvhs' CWBVH traversal did
//! (`trace_any_hit_cwbvh`), so that order-dependent any-hits — the SD map's reservoir —
//! decide as before: on real scenes, every call (distance, triangle, barycentrics) is the same,
//! in the same order, under any mix of IGNORE / ACCEPT / ACCEPT_AND_END answers.

mod common;

use aokit::render::CpuRenderer;
use aokit_cpu::bvh::{AnyHit, PACKET};
use aokit_shaders::glam::{UVec2, Vec2, Vec3};

/// A deterministic answer from the candidate itself: mostly IGNORE, sometimes ACCEPT (the
/// interval shrinks), rarely ACCEPT_AND_END.
fn answer(t: f32, tri: u32, mix: u32) -> AnyHit {
    let h = (t.to_bits() ^ tri.wrapping_mul(0x9E37_79B9)).wrapping_mul(0x85EB_CA6B) >> 24;
    match (h % 16, mix) {
        (_, 0) => AnyHit::Ignore,
        (0..=2, _) => AnyHit::Accept,
        (3, 2) => AnyHit::AcceptAndEnd,
        _ => AnyHit::Ignore,
    }
}

/// A built-in scene's CPU renderer and a 96×64 frame of it (8-pixel guard band).
fn small_frame(name: &str) -> (CpuRenderer, aokit::frame::Frame) {
    let (scene, frame) = common::builtin_frame(name, 96, 64, 8);
    (CpuRenderer::new(&scene), frame)
}

#[test]
fn any_hit_candidates_come_in_obvhs_order_on_real_scenes() {
    for name in ["sponza", "kitchen"] {
        let (cpu, frame) = small_frame(name);
        let bvh = cpu.bvh();
        let camera = &frame.camera;
        let (size, eye) = (camera.view.size(), camera.eye());
        let (mut rays, mut calls, mut accepted) = (0, 0usize, 0usize);
        for y in 0..size.y {
            for x in 0..size.x {
                let d = camera.primary_ray_direction(camera.view.pixel_uv(UVec2::new(x, y)));
                // Camera rays over everything behind a near bound, and AO-length rays from the
                // first surface in a direction bent off the view (incoherent).
                let first = bvh.closest_hit(eye, d, 0.0, f32::INFINITY);
                let bent = (d + Vec3::new(0.3 * ((x % 7) as f32 - 3.0), 0.5, 0.2 * ((y % 5) as f32 - 2.0))).normalize();
                let from = first.map_or(eye, |h| eye + d * (h.t * 0.999));
                for (o, dir, t_min, t_max, mix) in
                    [(eye, d, 0.05, f32::INFINITY, (x + y) % 3), (from, bent, 1e-3, frame.radius * 4.0, (x * y) % 3)]
                {
                    let (mut wide, mut cwbvh) = (Vec::new(), Vec::new());
                    bvh.trace_any_hit(o, dir, t_min, t_max, |t, tri, b| {
                        wide.push((t, tri, b));
                        answer(t, tri, mix)
                    });
                    bvh.trace_any_hit_cwbvh(o, dir, t_min, t_max, |t, tri, b| {
                        cwbvh.push((t, tri, b));
                        answer(t, tri, mix)
                    });
                    assert_eq!(wide, cwbvh, "{name}: ray {o} {dir} ({t_min}, {t_max}), answers {mix}");
                    rays += 1;
                    calls += wide.len();
                    accepted += wide.iter().filter(|&&(t, tri, _)| answer(t, tri, mix) != AnyHit::Ignore).count();
                }
            }
        }
        eprintln!("{name}: {rays} rays, {calls} candidates, {accepted} accepted");
        assert!(calls > 2 * rays && accepted > rays / 10, "{name}: too few candidates to test: {calls}, {accepted}");
    }
}

/// The SD map's own rays (default settings, after AO pass 1) with the reservoir any-hit: every
/// ray offers the same candidates in the same order on both traversals, so every texel's
/// reservoir ends the same; and traced in packets of 8, as the SD map traces them, too. (A 4-lane triangle test instead of obvhs' own decided one edge hit
/// of the kitchen's 73,349 full-resolution SD rays otherwise.)
#[test]
fn sd_rays_see_obvhs_order() {
    use aokit::rays::{sd_rays, svao_pass1};
    use aokit::technique::SdOptions;
    use aokit_shaders::common::alpha::AlphaTables;
    use aokit_shaders::common::any_hit::CandidateHit;
    use aokit_shaders::raysd::SdHits;
    use aokit_shaders::svao::Secondary;
    // The kitchen at full size: its one edge hit that a differently grouped triangle test
    // decided otherwise is there.
    for (name, width, height, guard) in [("sponza", 640, 360, 32), ("kitchen", 1920, 1080, 64)] {
        let (scene, frame) = common::builtin_frame(name, width, height, guard);
        let cpu = CpuRenderer::new(&scene);
        let (bvh, surfaces) = (cpu.bvh(), cpu.surfaces());
        let (gbuffer, _) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
        let sd_frame = SdOptions::default().frame(&frame.desc(), Secondary::StochasticDepth);
        let rays = sd_rays(&sd_frame, &gbuffer, &svao_pass1(&sd_frame, &gbuffer));
        let alpha = AlphaTables {
            uvs: surfaces.uvs.as_flattened(),
            materials: surfaces.materials,
            headers: surfaces.mask_headers,
            texels: surfaces.mask_texels,
        };
        let mut candidates = 0;
        for k in 0..rays.payloads.len() {
            let (d, t_min, t_max) = (rays.directions[k], rays.t_min[k], rays.t_max[k]);
            let (mut a, mut b) = (Vec::new(), Vec::new());
            let mut wide = SdHits { payload: rays.payloads[k], alpha };
            bvh.trace_any_hit(rays.origin, d, t_min, t_max, |t, tri, bary| {
                a.push((t, tri, bary));
                AnyHit::from_decision(wide.decide(t, bary, tri))
            });
            let mut cwbvh = SdHits { payload: rays.payloads[k], alpha };
            bvh.trace_any_hit_cwbvh(rays.origin, d, t_min, t_max, |t, tri, bary| {
                b.push((t, tri, bary));
                AnyHit::from_decision(cwbvh.decide(t, bary, tri))
            });
            assert_eq!(a, b, "{name}: SD ray {k} {d} ({t_min}, {t_max})");
            assert_eq!(wide.payload, cwbvh.payload);
            candidates += a.len();
        }
        // Packets of 8 consecutive rays, as the SD map traces them: each ray's reservoir ends
        // as the lone ray's.
        for (p, first) in (0..rays.payloads.len()).step_by(PACKET).enumerate() {
            let count = (rays.payloads.len() - first).min(PACKET);
            let ray = |k: usize| first + k.min(count - 1);
            let directions = std::array::from_fn(|k| rays.directions[ray(k)]);
            let interval = (&std::array::from_fn(|k| rays.t_min[ray(k)]), &std::array::from_fn(|k| rays.t_max[ray(k)]));
            let mut hits: [SdHits; PACKET] = std::array::from_fn(|k| SdHits { payload: rays.payloads[ray(k)], alpha });
            bvh.trace_any_hit_packet(rays.origin, &directions, interval, count, |k, t, tri, bary| {
                AnyHit::from_decision(hits[k].decide(t, bary, tri))
            });
            for (k, h) in hits.iter().enumerate().take(count) {
                let mut lone = SdHits { payload: rays.payloads[first + k], alpha };
                let (d, t_min, t_max) = (directions[k], interval.0[k], interval.1[k]);
                bvh.trace_any_hit(rays.origin, d, t_min, t_max, |t, tri, bary| {
                    AnyHit::from_decision(lone.decide(t, bary, tri))
                });
                assert_eq!(h.payload, lone.payload, "{name}: packet {p}, SD ray {}", first + k);
            }
        }
        eprintln!("{name}: {} SD rays, {candidates} candidates", rays.payloads.len());
        assert!(rays.payloads.len() > 1000 && candidates > rays.payloads.len() / 2, "{name}: too few to test");
    }
}

/// Packets ([`SceneBvh::trace_any_hit_packet`]) offer each ray exactly the candidates, in the
/// order, and under the same answers as the lone ray (`trace_any_hit`): 8 camera rays of a row
/// (packets across the image's middle mix octants, and split), each over its own interval —
/// some beginning deep in the scene, some short — under any mix of IGNORE / ACCEPT /
/// ACCEPT_AND_END answers, on real scenes.
#[test]
fn packets_offer_each_ray_the_lone_rays_candidates() {
    for name in ["sponza", "kitchen"] {
        let (cpu, frame) = small_frame(name);
        let bvh = cpu.bvh();
        let camera = &frame.camera;
        let (size, eye) = (camera.view.size(), camera.eye());
        let (mut packets, mut mixed, mut calls) = (0, 0, 0usize);
        for y in 0..size.y {
            // Packets start at shifting columns, so some straddle the image's middle.
            for x0 in (y % 5..size.x).step_by(PACKET) {
                let count = ((size.x - x0) as usize).min(PACKET - (y as usize % 3));
                let pixel = |k: usize| UVec2::new(x0 + k.min(count - 1) as u32, y);
                let directions: [Vec3; PACKET] =
                    std::array::from_fn(|k| camera.primary_ray_direction(camera.view.pixel_uv(pixel(k))));
                let first = |k: usize| bvh.closest_hit(eye, directions[k], 0.0, f32::INFINITY).map_or(1.0, |h| h.t);
                // Over everything, from just before the first surface to a little behind it, or
                // a window deep behind it.
                let interval = |k: usize| match (k + y as usize) % 3 {
                    0 => (0.05, f32::INFINITY),
                    1 => (first(k) * 0.98, first(k) * 1.3),
                    _ => (first(k) * 1.1, first(k) * 3.0),
                };
                let t_min = std::array::from_fn(|k| interval(k).0);
                let t_max = std::array::from_fn(|k| interval(k).1);
                let mix = |k: usize| (x0 as usize + k + 2 * y as usize) as u32 % 3;
                let mut got: [Vec<(f32, u32, Vec2)>; PACKET] = Default::default();
                bvh.trace_any_hit_packet(eye, &directions, (&t_min, &t_max), count, |k, t, tri, b| {
                    got[k].push((t, tri, b));
                    answer(t, tri, mix(k))
                });
                for k in 0..count {
                    let mut lone = Vec::new();
                    bvh.trace_any_hit(eye, directions[k], t_min[k], t_max[k], |t, tri, b| {
                        lone.push((t, tri, b));
                        answer(t, tri, mix(k))
                    });
                    assert_eq!(got[k], lone, "{name}: pixel {} ({}, {})", pixel(k), t_min[k], t_max[k]);
                    calls += lone.len();
                }
                let octant = |d: Vec3| (d.x >= 0.0, d.y >= 0.0, d.z >= 0.0);
                mixed += directions[..count].iter().any(|&d| octant(d) != octant(directions[0])) as u32;
                packets += 1;
            }
        }
        eprintln!("{name}: {packets} packets ({mixed} of mixed octants), {calls} candidates");
        assert!(mixed > 0 && calls > 10 * packets as usize, "{name}: too little to test: {mixed}, {calls}");
    }
}

/// The SD map as the renderer traces it (`run_sd_map`: bands of 2×4-texel tiles, packets) holds
/// in every texel exactly the depths of its ray traced alone (`trace_sd` with lone rays), and
/// the far plane (1) where no ray was traced.
#[test]
fn sd_map_of_packets_is_the_map_of_lone_rays() {
    use aokit::rays::{Alpha, Tracer, sd_rays, svao_pass1, trace_sd};
    use aokit::technique::SdOptions;
    use aokit_cpu::svao::{HitOrder, run_sd_map};
    use aokit_shaders::svao::Secondary;
    // 30 SD rows: the last band is cut short.
    let (scene, frame) = common::builtin_frame("sponza", 224, 104, 8);
    let cpu = CpuRenderer::new(&scene);
    let (bvh, surfaces) = (cpu.bvh(), cpu.surfaces());
    let (gbuffer, _) = cpu.gbuffer(&frame, &aokit_cpu::no_progress);
    let sd_frame = SdOptions::default().frame(&frame.desc(), Secondary::StochasticDepth);
    let pass1 = svao_pass1(&sd_frame, &gbuffer);
    let map = run_sd_map(bvh, &surfaces, &sd_frame, &gbuffer.depth, &gbuffer.normals, &pass1, HitOrder::Traversal);
    let rays = sd_rays(&sd_frame, &gbuffer, &pass1);
    let mut lone = rays.payloads.clone();
    trace_sd(bvh, &surfaces, &rays, Alpha::On, Tracer::Wide, &mut lone);
    let n = sd_frame.params.sd_layers as usize;
    let mut expect = vec![1.0f32; map.layers.len()];
    for (k, payload) in lone.iter().enumerate() {
        let i = rays.texels[k] as usize;
        expect[i * n..(i + 1) * n].copy_from_slice(&payload.depth[..n]);
    }
    assert_eq!(sd_frame.params.sd_size().y % 4, 2, "a short last band");
    assert_eq!(map.rays as usize, rays.payloads.len());
    let filled = expect.iter().filter(|&&d| d < 1.0).count();
    assert!(filled > 1000, "too few stored depths to test: {filled}");
    assert!(
        map.layers == expect,
        "{} of {} depths differ",
        map.layers.iter().zip(&expect).filter(|(a, b)| a != b).count(),
        expect.len()
    );
}
