//! Packet traversal: camera rays traced as 4×2 packets (`SceneBvh::closest_hits`,
//! what the CPU G-buffer casts) get, ray by ray, the same triangle and the same distance as the
//! single-ray traversal (`closest_hit`), on real scenes, with and without the alpha test; and the
//! G-buffer cast with packets is the single-ray G-buffer bit for bit.

mod common;

use aokit::render::CpuRenderer;
use aokit_cpu::bvh::{Hit, PACKET};
use aokit_cpu::no_progress;
use aokit_shaders::common::normal_codec::encode_normal;
use aokit_shaders::glam::{UVec2, Vec3};

/// Every pixel's single-ray hit and the hits of packets of `(x0 + i % 4, y0 + i / 4)` for tiles
/// at every offset of the 4×2 grid (so every pixel is traced in several packet positions).
/// Returns (pixels, hits, differing rays).
fn compare(name: &str, width: u32, height: u32) -> (usize, usize, Vec<String>) {
    let (scene, frame) = common::builtin_frame(name, width, height, 16);
    let cpu = CpuRenderer::new(&scene);
    let (bvh, surfaces) = (cpu.bvh(), cpu.surfaces());
    let masked = surfaces.mask_headers.iter().any(|h| h.width > 0);
    let camera = &frame.camera;
    let size = camera.view.size();
    let eye = camera.eye();
    let dir = |x: u32, y: u32| camera.primary_ray_direction(camera.view.pixel_uv(UVec2::new(x, y)));
    let single = |d: Vec3| {
        if masked {
            bvh.closest_accepted_hit(eye, d, 0.0, f32::INFINITY, |t, b| surfaces.passes_alpha(t, b))
        } else {
            bvh.closest_hit(eye, d, 0.0, f32::INFINITY)
        }
    };
    let expect: Vec<Option<Hit>> =
        (0..size.y).flat_map(|y| (0..size.x).map(move |x| (x, y))).map(|(x, y)| single(dir(x, y))).collect();
    let mut differ = Vec::new();
    for (ox, oy) in [(0, 0), (1, 1), (2, 0), (3, 1)] {
        for y0 in (oy..size.y - 1).step_by(2) {
            for x0 in (ox..size.x - 3).step_by(4) {
                let pixels: [(u32, u32); PACKET] = std::array::from_fn(|i| (x0 + i as u32 % 4, y0 + i as u32 / 4));
                let dirs = pixels.map(|(x, y)| dir(x, y));
                let got = if masked {
                    bvh.closest_accepted_hits(eye, &dirs, 0.0, f32::INFINITY, |t, b| surfaces.passes_alpha(t, b))
                } else {
                    bvh.closest_hits(eye, &dirs, 0.0, f32::INFINITY)
                };
                for (i, &(x, y)) in pixels.iter().enumerate() {
                    let e = expect[(y * size.x + x) as usize];
                    if got[i] != e {
                        differ.push(format!(
                            "{name} pixel ({x}, {y}) at tile ({x0}, {y0}): packet {:?}, single {e:?}",
                            got[i]
                        ));
                    }
                }
            }
        }
    }
    // The G-buffer (packets over two-row bands) against the single-ray hits.
    let (g, _) = cpu.gbuffer(&frame, &no_progress);
    let far = camera.view.far;
    for y in 0..size.y {
        for x in 0..size.x {
            let i = (y * size.x + x) as usize;
            let (mut depth, mut normal) = (far, 0);
            if let Some(h) = expect[i] {
                let d = camera.linear_depth_of_hit(dir(x, y), h.t);
                if d < far {
                    depth = d;
                    normal = encode_normal(
                        camera.world_to_view.transform_vector3(surfaces.face_normals[h.triangle as usize]),
                    );
                }
            }
            if (g.depth[i].to_bits(), g.normals[i]) != (depth.to_bits(), normal) {
                differ.push(format!(
                    "{name} G-buffer pixel ({x}, {y}): {} / {} vs single ray {depth} / {normal}",
                    g.depth[i], g.normals[i]
                ));
            }
        }
    }
    (expect.len(), expect.iter().filter(|h| h.is_some()).count(), differ)
}

#[test]
fn packets_hit_what_single_rays_hit_on_real_scenes() {
    // Sponza and the kitchen (opaque), the oak tree (alpha-masked leaves: the accepting packet).
    for (name, width, height, min_hit) in
        [("sponza", 192, 108, 0.9), ("kitchen", 192, 108, 0.9), ("oak", 160, 120, 0.2)]
    {
        let (pixels, hits, differ) = compare(name, width, height);
        eprintln!("{name}: {pixels} pixels, {hits} hit, {} differ", differ.len());
        assert!(differ.is_empty(), "{} rays differ, e.g.\n{}", differ.len(), differ[..differ.len().min(10)].join("\n"));
        assert!(hits as f64 >= min_hit * pixels as f64, "{name}: the camera must see the scene: {hits} of {pixels}");
    }
}
