//! Engine adapters (`aokit_shaders::adapters`): CPU oracle tests of the pure functions —
//! projections built here in f64 and their hardware depth recovered, background, the normal
//! codec, guard-band clamping, the export's inner image — then the Vulkan entry points against
//! `aokit_cpu::adapters` under the Khronos validation layer.

mod common;

use aokit_cpu::adapters as cpu;
use aokit_shaders::adapters::{
    BACKGROUND_DEPTH, DEPTH_LINEAR, DEPTH_REVERSED, DEPTH_REVERSED_INFINITE, DEPTH_STANDARD, ImportParams,
    import_depth_pixel, import_normal, linear_depth,
};
use aokit_shaders::common::ViewParams;
use aokit_shaders::common::math::is_valid_depth;
use aokit_shaders::common::normal_codec::{decode_normal, encode_normal};
use aokit_shaders::glam::{UVec2, Vec3, uvec2, vec2};

/// Unit roundoff of f32 (round to nearest): every correctly rounded operation and every
/// f64 → f32 conversion has a relative error of at most `U`.
const U: f64 = 1.0 / (1u64 << 24) as f64;

/// The engine's near/far planes, exactly representable in f32, so the only errors are the
/// rounding of the stored depth and the f32 arithmetic of `linear_depth`.
const NEAR: f64 = 0.1f32 as f64;
const FAR: f64 = 1000.0;

/// Projection matrices (rows; column vectors, `clip = P·(x, y, z, 1)`) for a right-handed view
/// space looking down −Z. `gl`: OpenGL's z_ndc ∈ [−1, 1] (window depth `0.5·z_ndc + 0.5`).
#[derive(Copy, Clone, Debug)]
enum Projection {
    /// Vulkan/D3D z_ndc ∈ [0, 1], 0 at near.
    Standard,
    /// OpenGL `glFrustum`/`gluPerspective`, z_ndc ∈ [−1, 1], window depth via glDepthRange(0, 1).
    OpenGl,
    /// Reversed Z: 1 at near, 0 at far.
    Reversed,
    /// Reversed Z with the far plane at infinity.
    ReversedInfinite,
}

impl Projection {
    fn matrix(self, n: f64, f: f64) -> [[f64; 4]; 4] {
        let (sx, sy) = (1.2, 1.7); // any focal lengths: depth does not depend on them
        let (a, b) = match self {
            Projection::Standard => (f / (n - f), n * f / (n - f)),
            Projection::OpenGl => (-(f + n) / (f - n), -2.0 * f * n / (f - n)),
            Projection::Reversed => (n / (f - n), n * f / (f - n)),
            Projection::ReversedInfinite => (0.0, n),
        };
        [[sx, 0.0, 0.0, 0.0], [0.0, sy, 0.0, 0.0], [0.0, 0.0, a, b], [0.0, 0.0, -1.0, 0.0]]
    }

    fn convention(self) -> u32 {
        match self {
            Projection::Standard | Projection::OpenGl => DEPTH_STANDARD,
            Projection::Reversed => DEPTH_REVERSED,
            Projection::ReversedInfinite => DEPTH_REVERSED_INFINITE,
        }
    }

    /// The depth-buffer value (f64) of the view-space point `x`.
    fn hardware_depth(self, x: [f64; 3], n: f64, f: f64) -> f64 {
        let m = self.matrix(n, f);
        let clip: Vec<f64> = m.iter().map(|r| r[0] * x[0] + r[1] * x[1] + r[2] * x[2] + r[3]).collect();
        let ndc = clip[2] / clip[3];
        if let Projection::OpenGl = self { 0.5 * ndc + 0.5 } else { ndc }
    }

    /// Relative error bound of `linear_depth` for a point at view depth `z`.
    ///
    /// Standard: `z = n·f / D` with `D = f − d·(f − n)`. The stored `d` is rounded (|δd| ≤ U·d)
    /// and `f − n`, `d·(f − n)` and the subtraction each round once. Since
    /// `d·(f − n) = f − D = D·(z/n − 1)`, an absolute error `e·d·(f − n)` becomes a relative error
    /// `e·(z/n − 1)` of `D`: to first order |δD/D| ≤ 3U·(z/n − 1) + U, and the product `n·f` and
    /// the division add 2U: rel ≤ U·(3·z/n + 3) — we allow U·(4·z/n + 4).
    /// Reversed: `D = n + d·(f − n)` adds positive terms: rel ≤ U (stored d) + 3U (D) + 2U = 6U;
    /// we allow 8U. Reversed infinite: `z = n/d`: U (stored d) + U (division); we allow 4U.
    fn bound(self, z: f64, n: f64) -> f64 {
        match self {
            Projection::Standard | Projection::OpenGl => U * (4.0 * z / n + 4.0),
            Projection::Reversed => 8.0 * U,
            Projection::ReversedInfinite => 4.0 * U,
        }
    }
}

/// View depths log-spaced over [n, z_max), plus `n` itself.
fn depths(n: f64, z_max: f64, count: usize) -> Vec<f64> {
    (0..count).map(|k| n * (z_max / n).powf(k as f64 / count as f64)).collect()
}

#[test]
fn linear_depth_recovers_projected_view_depths() {
    let projections = [
        (Projection::Standard, FAR),
        (Projection::OpenGl, FAR),
        (Projection::Reversed, FAR),
        // No far plane: depths far beyond FAR.
        (Projection::ReversedInfinite, 1e6),
    ];
    for (projection, z_max) in projections {
        let mut worst: f64 = 0.0; // largest (error / bound)
        for (k, z) in depths(NEAR, z_max, 4000).into_iter().enumerate() {
            // A point off the axis: depth depends on z alone.
            let x = [0.3 * z * ((k % 7) as f64 - 3.0) / 3.0, -0.2 * z, -z];
            let d = projection.hardware_depth(x, NEAR, FAR);
            let d32 = d as f32; // what a D32_SFLOAT depth buffer stores
            let got = linear_depth(d32, projection.convention(), NEAR as f32, FAR as f32) as f64;
            let rel = (got - z).abs() / z;
            let bound = projection.bound(z, NEAR);
            assert!(rel <= bound, "{projection:?}: z = {z}, d = {d32}: got {got}, rel error {rel:.3e} > {bound:.3e}");
            worst = worst.max(rel / bound);
        }
        eprintln!("{projection:?}: largest error = {:.2} of the bound", worst);
    }
}

#[test]
fn linear_depth_reads_linear_images_unchanged() {
    for z in depths(NEAR, FAR, 1000) {
        let z32 = z as f32;
        assert_eq!(linear_depth(z32, DEPTH_LINEAR, NEAR as f32, FAR as f32), z32);
    }
}

#[test]
fn background_maps_to_background() {
    let (n, f) = (NEAR as f32, FAR as f32);
    let cases: [(u32, &[f32]); 4] = [
        (DEPTH_STANDARD, &[1.0, 1.5, f32::INFINITY, f32::NAN]),
        (DEPTH_REVERSED, &[0.0, -0.0, -1e-3, f32::NEG_INFINITY, f32::NAN]),
        (DEPTH_REVERSED_INFINITE, &[0.0, -0.0, -1e-3, f32::NAN]),
        (DEPTH_LINEAR, &[0.0, -1.0, f, 2.0 * f, f32::INFINITY, f32::NAN]),
    ];
    let view = view_params(uvec2(4, 4), 0, 900.0);
    for (convention, values) in cases {
        for &hw in values {
            assert_eq!(linear_depth(hw, convention, n, f), BACKGROUND_DEPTH, "convention {convention}, {hw}");
            let params = ImportParams { depth_convention: convention, ..import_params(view, uvec2(4, 4), n, f) };
            let imported = import_depth_pixel(&params, |_| hw, uvec2(1, 2));
            assert_eq!(imported, view.far, "background is written as view.far");
            assert!(!is_valid_depth(imported, view.far));
        }
    }
    // Every far plane aokit may use treats BACKGROUND_DEPTH as background, and so does an
    // unknown convention.
    assert!(!is_valid_depth(BACKGROUND_DEPTH, f32::MAX));
    assert_eq!(linear_depth(0.5, 7, n, f), BACKGROUND_DEPTH);
    // The last representable depths before the cleared value are still surfaces.
    let below_one = 1.0f32 - f32::EPSILON / 2.0;
    for (convention, hw) in [(DEPTH_STANDARD, below_one), (DEPTH_REVERSED, f32::MIN_POSITIVE)] {
        let z = linear_depth(hw, convention, n, f);
        assert!(z > 0.0 && z <= 1.001 * f, "convention {convention}: {hw} → {z}");
    }
}

/// `count` unit vectors spread over the sphere (Fibonacci lattice) plus the axes and a few
/// directions on the octahedron's folds.
fn unit_normals(count: usize) -> Vec<Vec3> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let mut out: Vec<Vec3> = (0..count)
        .map(|i| {
            let y = 1.0 - 2.0 * (i as f64 + 0.5) / count as f64;
            let r = (1.0 - y * y).sqrt();
            let phi = golden * i as f64;
            Vec3::new((r * phi.cos()) as f32, y as f32, (r * phi.sin()) as f32)
        })
        .collect();
    for v in
        [Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X, -Vec3::Y, -Vec3::Z, Vec3::new(1.0, 1.0, 0.0), Vec3::new(1.0, -1.0, -1.0)]
    {
        out.push(v.normalize());
    }
    out
}

fn angle(a: Vec3, b: Vec3) -> f32 {
    a.normalize().dot(b.normalize()).clamp(-1.0, 1.0).acos()
}

fn snorm8_pair(code: u32) -> [i32; 2] {
    [(code & 0xFF) as u8 as i8 as i32, ((code >> 8) & 0xFF) as u8 as i8 as i32]
}

#[test]
fn imported_normals_match_the_octahedral_codec() {
    let normals = unit_normals(20_000);
    // The codec's own quantization error on this set.
    let theta_q = normals.iter().map(|&n| angle(decode_normal(encode_normal(n)), n)).fold(0.0, f32::max);
    // RGB = n·0.5 + 0.5 in f32 (an RGBA16F/32F image): the code of n itself, up to one snorm8
    // step where `2c − 1` rounds across a quantization boundary.
    let mut identical = 0;
    for &n in &normals {
        let code = import_normal(n * 0.5 + Vec3::splat(0.5));
        let want = encode_normal(n);
        identical += usize::from(code == want);
        let (a, b) = (snorm8_pair(code), snorm8_pair(want));
        assert!(
            (a[0] - b[0]).abs() <= 1 && (a[1] - b[1]).abs() <= 1,
            "{n}: code {code:#06x}, encode_normal {want:#06x}"
        );
    }
    let share = identical as f64 / normals.len() as f64;
    eprintln!("float RGB: {:.3} % identical codes; codec quantization θ_q = {theta_q:.5} rad", 100.0 * share);
    assert!(share >= 0.99, "only {:.3} % identical", 100.0 * share);
    // RGB8 unorm: each channel rounds by ≤ 0.5/255, so `2c − 1` moves each component by ≤ 1/255,
    // the vector by ≤ √3/255 and its direction by ≤ asin(√3/255); encoding adds θ_q (the codec
    // is scale-invariant). 10 % margin on θ_q, which was measured on a finite set.
    let bound = 1.1 * theta_q + (3f32.sqrt() / 255.0).asin();
    let mut worst: f32 = 0.0;
    for &n in &normals {
        let rgb8 = (n * 0.5 + Vec3::splat(0.5)).map(|c| (c * 255.0).round() / 255.0);
        let err = angle(decode_normal(import_normal(rgb8)), n);
        assert!(err <= bound, "{n}: {err} rad > {bound}");
        worst = worst.max(err);
    }
    eprintln!("RGB8: largest angle {worst:.5} rad (bound {bound:.5})");
}

fn view_params(inner: UVec2, guard: u32, far: f32) -> ViewParams {
    let full = inner + 2 * guard;
    ViewParams { res: full.as_vec2(), tan_half_fov: vec2(0.6, 0.45), near: 0.1, far, guard, _pad: 0 }
}

fn import_params(view: ViewParams, engine: UVec2, near: f32, far: f32) -> ImportParams {
    ImportParams { view, engine_size: engine, depth_convention: DEPTH_LINEAR, near, far, _pad: 0 }
}

#[test]
fn guard_band_clamps_to_the_nearest_edge_texel() {
    let (w, h, g) = (5i64, 4i64, 3u32);
    for guard in [g, 0] {
        let view = view_params(uvec2(5, 4), guard, 500.0);
        let params = import_params(view, uvec2(5, 4), 0.1, 1000.0);
        // Distinct depths and normals per engine texel.
        let engine_depth: Vec<f32> = (0..w * h).map(|i| 1.0 + i as f32).collect();
        let rgb: Vec<[f32; 3]> = (0..w * h).map(|i| [i as f32 / 20.0, 1.0 - i as f32 / 20.0, 0.8]).collect();
        let depth = cpu::import_depth(&params, &engine_depth);
        let normals = cpu::import_normals(&params, &rgb);
        let full = view.size();
        assert_eq!(depth.len(), (full.x * full.y) as usize);
        for py in 0..full.y as i64 {
            for px in 0..full.x as i64 {
                let x = (px - guard as i64).clamp(0, w - 1);
                let y = (py - guard as i64).clamp(0, h - 1);
                let (e, i) = ((y * w + x) as usize, (py * full.x as i64 + px) as usize);
                assert_eq!(depth[i], engine_depth[e], "pixel ({px}, {py}), guard {guard}");
                assert_eq!(normals[i], import_normal(Vec3::from(rgb[e])), "pixel ({px}, {py}), guard {guard}");
            }
        }
    }
}

#[test]
fn export_writes_the_inner_image_clamped() {
    let (inner, guard) = (uvec2(6, 5), 2);
    let view = view_params(inner, guard, 500.0);
    let params = import_params(view, inner, 0.1, 1000.0);
    let full = view.size();
    // Guard band: a sentinel that must never appear; inner: −0.5…1.5 and a NaN.
    let mut ao = vec![0.777f32; (full.x * full.y) as usize];
    let mut k = 0;
    for y in guard..guard + inner.y {
        for x in guard..guard + inner.x {
            ao[(y * full.x + x) as usize] = if k == 7 { f32::NAN } else { -0.5 + 2.0 * k as f32 / 29.0 };
            k += 1;
        }
    }
    let out = cpu::export_ao(&params, &ao);
    assert_eq!(out.len(), (inner.x * inner.y) as usize);
    for (k, &v) in out.iter().enumerate() {
        let want = if k == 7 { 0.0 } else { (-0.5 + 2.0 * k as f32 / 29.0).clamp(0.0, 1.0) };
        assert_eq!(v, want, "texel {k}");
    }
    assert!(!out.contains(&0.777));
}

/// SPIR-V `ImageFormat` of the module's (single) storage image and its entry point's name
/// (SPIR-V spec §2.3 physical layout; OpEntryPoint = 15, OpTypeImage = 25).
fn storage_image_format(bytes: &[u8]) -> (String, Vec<u32>) {
    let w: Vec<u32> = bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect();
    let (mut name, mut formats, mut i) = (String::new(), Vec::new(), 5);
    while i < w.len() {
        let (count, op) = ((w[i] >> 16) as usize, w[i] & 0xFFFF);
        let args = &w[i + 1..i + count];
        match op {
            15 => {
                name = args[2..].iter().flat_map(|x| x.to_le_bytes()).take_while(|&b| b != 0).map(char::from).collect()
            }
            // result, sampled type, dim, depth, arrayed, MS, sampled (2 = storage), format
            25 if args[6] == 2 => formats.push(args[7]),
            _ => {}
        }
        i += count;
    }
    (name, formats)
}

#[test]
fn each_export_format_has_the_entry_point_of_its_spirv_format() {
    use aokit_vulkan::Adapters;
    use ash::vk;
    // SPIR-V ImageFormat enumerants R32f = 3, R16f = 9, R8 = 15 and their Vulkan formats (Vulkan
    // spec, "Compatibility Between SPIR-V Image Formats and Vulkan Formats").
    let want = [(vk::Format::R32_SFLOAT, 3), (vk::Format::R16_SFLOAT, 9), (vk::Format::R8_UNORM, 15)];
    assert_eq!(Adapters::EXPORT_FORMATS.len(), want.len());
    for ((format, entry, spirv), (vk_format, spirv_format)) in Adapters::EXPORT_FORMATS.into_iter().zip(want) {
        assert_eq!(format, vk_format);
        let (name, formats) = storage_image_format(spirv);
        assert_eq!(name, entry.to_str().unwrap());
        assert_eq!(formats, [spirv_format], "{name}");
    }
}

// ---------------------------------------------------------------------------------------------
// Vulkan: the entry points against aokit_cpu::adapters.

mod vulkan {
    use super::*;
    use crate::common;
    use aokit_vulkan::{Adapters, AoImage, EngineImage, Image2d};
    use ash::vk;

    /// Stored depth of engine texel `i` for `projection` (`None`: linear) and its view depth:
    /// depths log-spaced over [near, 0.95·far] in a scrambled order, every 11th texel background.
    fn engine_depth(projection: Option<Projection>, i: usize) -> f32 {
        if i % 11 == 5 {
            return match projection.map(Projection::convention) {
                Some(DEPTH_STANDARD) => 1.0,
                Some(_) => 0.0,
                None if i.is_multiple_of(2) => 0.0,
                None => 2.0 * FAR as f32,
            };
        }
        let t = ((i * 7919) % 1000) as f64 / 1000.0;
        let z = NEAR * (0.95 * FAR / NEAR).powf(t);
        match projection {
            Some(p) => p.hardware_depth([0.0, 0.0, -z], NEAR, FAR) as f32,
            None => z as f32,
        }
    }

    #[test]
    fn adapters_on_vulkan_agree_with_cpu_sim() {
        let Some(vulkan) = common::vulkan() else { return };
        let gpu = vulkan.gpu();
        let adapters = Adapters::new(gpu).unwrap();
        // Not multiples of the 8×8 workgroup; view.far below the engine's far plane.
        let (inner, guard) = (uvec2(37, 29), 4);
        let view = view_params(inner, guard, 900.0);
        let full = view.size();
        let (texels, pixels) = ((inner.x * inner.y) as usize, (full.x * full.y) as usize);
        let base = import_params(view, inner, NEAR as f32, FAR as f32);
        let inputs = [
            (DEPTH_STANDARD, Some(Projection::Standard)),
            (DEPTH_REVERSED, Some(Projection::Reversed)),
            (DEPTH_REVERSED_INFINITE, Some(Projection::ReversedInfinite)),
            (DEPTH_LINEAR, None),
        ];
        let usage = vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST;
        let depth_layout = vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL;
        let shader_read = vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL;
        let mut images: Vec<(Vec<f32>, Image2d, vk::ImageLayout)> = Vec::new();
        for (_, projection) in inputs {
            let values: Vec<f32> = (0..texels).map(|i| engine_depth(projection, i)).collect();
            // A depth buffer is a depth attachment (which its read-only layout requires).
            let (format, layout, usage) = match projection {
                Some(_) => {
                    (vk::Format::D32_SFLOAT, depth_layout, usage | vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT)
                }
                None => (vk::Format::R32_SFLOAT, shader_read, usage),
            };
            let image = gpu.create_image_2d(format, inner.x, inner.y, usage).unwrap();
            gpu.upload_image(&image, bytemuck::cast_slice(&values), layout).unwrap();
            images.push((values, image, layout));
        }
        let normals = unit_normals(texels - 8);
        let rgba8: Vec<u8> = normals
            .iter()
            .flat_map(|n| {
                let c = (*n * 0.5 + Vec3::splat(0.5)) * 255.0;
                [c.x.round() as u8, c.y.round() as u8, c.z.round() as u8, 255]
            })
            .collect();
        let normal_image = gpu.create_image_2d(vk::Format::R8G8B8A8_UNORM, inner.x, inner.y, usage).unwrap();
        gpu.upload_image(&normal_image, &rgba8, shader_read).unwrap();
        let rgb: Vec<[f32; 3]> =
            rgba8.chunks(4).map(|c| [c[0] as f32 / 255.0, c[1] as f32 / 255.0, c[2] as f32 / 255.0]).collect();
        // AO: −0.5…1.5 over the target (no NaN: Vulkan leaves NaN handling to the implementation).
        let ao: Vec<f32> = (0..pixels).map(|i| -0.5 + 2.0 * ((i * 104_729) % 4096) as f32 / 4095.0).collect();
        let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
        let ao_src = gpu.upload(&ao, storage).unwrap();
        let ao_buf = gpu.upload(&vec![0.5f32; pixels], storage).unwrap();
        let depth_out: Vec<_> = inputs.iter().map(|_| gpu.upload(&vec![-1.0f32; pixels], storage).unwrap()).collect();
        let normals_out = gpu.upload(&vec![0u32; pixels], storage).unwrap();
        let formats = [vk::Format::R32_SFLOAT, vk::Format::R16_SFLOAT, vk::Format::R8_UNORM];
        let out_usage = vk::ImageUsageFlags::STORAGE | vk::ImageUsageFlags::TRANSFER_SRC;
        let outputs: Vec<Image2d> =
            formats.iter().map(|&f| gpu.create_image_2d(f, inner.x, inner.y, out_usage).unwrap()).collect();
        let pool = adapters.create_descriptor_pool(gpu, (inputs.len() + formats.len()) as u32).unwrap();

        // Rejected before anything is recorded.
        gpu.run_commands(|cb| {
            let bad = ImportParams { depth_convention: 9, ..base };
            let depth = EngineImage { view: images[0].1.view, layout: depth_layout };
            assert!(adapters.record_import(gpu, cb, pool, &bad, (depth, &depth_out[0]), None).is_err());
            let rgba = AoImage { view: outputs[0].view, format: vk::Format::R8G8B8A8_UNORM };
            assert!(adapters.record_export(gpu, cb, pool, &base, &ao_buf, rgba).is_err());
        })
        .unwrap();

        // One command buffer: the four imports, a copy into the AO buffer, the three exports.
        gpu.run_commands(|cb| {
            for o in &outputs {
                gpu.record_image_layout(cb, o, vk::ImageLayout::UNDEFINED, vk::ImageLayout::GENERAL);
            }
            for (k, ((convention, _), (_, image, layout))) in inputs.iter().zip(&images).enumerate() {
                let params = ImportParams { depth_convention: *convention, ..base };
                let depth = EngineImage { view: image.view, layout: *layout };
                let normal =
                    (k == 0).then_some((EngineImage { view: normal_image.view, layout: shader_read }, &normals_out));
                adapters.record_import(gpu, cb, pool, &params, (depth, &depth_out[k]), normal).unwrap();
            }
            gpu.record_copy_buffer(cb, &ao_src, &ao_buf);
            for (o, &f) in outputs.iter().zip(&formats) {
                adapters.record_export(gpu, cb, pool, &base, &ao_buf, AoImage { view: o.view, format: f }).unwrap();
            }
        })
        .unwrap();

        // Depth: SPIR-V lets `a·b + c` contract into an fma and Vulkan allows 2.5 ulp divisions,
        // so the GPU may differ from the CPU by a few roundings of each operation, amplified by
        // the condition number of the formula: κ = z·(f − n)/(n·f) for standard depth (the
        // cancellation in f − d·(f − n)), 0 for the others. Tolerance 8U·(1 + κ) relative; the
        // linear convention is a copy and must be exact.
        for (k, (convention, projection)) in inputs.iter().enumerate() {
            let params = ImportParams { depth_convention: *convention, ..base };
            let want = cpu::import_depth(&params, &images[k].0);
            let got: Vec<f32> = gpu.download(&depth_out[k]).unwrap();
            let (mut exact, mut background, mut worst) = (0, 0, 0.0f64);
            for (&g, &w) in got.iter().zip(&want) {
                let (g, w) = (g as f64, w as f64);
                let kappa = if *convention == DEPTH_STANDARD { w * (FAR - NEAR) / (NEAR * FAR) } else { 0.0 };
                let tol = if projection.is_none() { 0.0 } else { 8.0 * U * (1.0 + kappa) };
                let rel = (g - w).abs() / w;
                assert!(rel <= tol, "convention {convention}: gpu {g} cpu {w} (rel {rel:.3e} > {tol:.3e})");
                exact += usize::from(g == w);
                background += usize::from(w == view.far as f64);
                worst = worst.max(if tol > 0.0 { rel / tol } else { 0.0 });
            }
            eprintln!(
                "depth convention {convention}: {exact}/{pixels} bit-identical, {background} background, largest error {worst:.3} of the tolerance"
            );
            assert!(background > pixels / 20 && background < pixels / 4, "background count {background}");
        }
        let want = cpu::import_normals(&base, &rgb);
        let got: Vec<u32> = gpu.download(&normals_out).unwrap();
        let identical = got.iter().zip(&want).filter(|(a, b)| a == b).count();
        eprintln!("normals: {identical}/{pixels} identical codes");
        assert!(identical as f64 >= 0.999 * pixels as f64, "only {identical}/{pixels} identical normal codes");

        let want = cpu::export_ao(&base, &ao);
        let r32: Vec<f32> =
            bytemuck::cast_slice(&gpu.download_image(&outputs[0], vk::ImageLayout::GENERAL, 4).unwrap()).to_vec();
        assert_eq!(r32, want, "r32f export is exact");
        let r16 = gpu.download_image(&outputs[1], vk::ImageLayout::GENERAL, 2).unwrap();
        let mut worst16: f32 = 0.0;
        for (k, (h, &w)) in r16.chunks(2).zip(&want).enumerate() {
            let v = common::f16_to_f32(u16::from_le_bytes([h[0], h[1]]));
            // One half-precision ulp (2^-10 relative; rounding may go either way), 2^-24 below
            // the normal range.
            let tol = (w * 2f32.powi(-10)).max(2f32.powi(-24));
            assert!((v - w).abs() <= tol, "r16f texel {k}: {v} vs {w}");
            worst16 = worst16.max((v - w).abs());
        }
        let r8 = gpu.download_image(&outputs[2], vk::ImageLayout::GENERAL, 1).unwrap();
        let mut nearest = 0;
        for (k, (&b, &w)) in r8.iter().zip(&want).enumerate() {
            assert!((b as f32 / 255.0 - w).abs() <= 1.0 / 255.0, "r8 texel {k}: {b} vs {w}");
            nearest += usize::from(b as f32 == (w * 255.0).round());
        }
        eprintln!("export: r32f exact; r16f largest |Δ| {worst16:.2e}; r8 {nearest}/{texels} round to nearest");

        adapters.destroy_descriptor_pool(gpu, pool);
        for b in depth_out.into_iter().chain([normals_out, ao_src, ao_buf]) {
            gpu.free_buffer(b);
        }
        for image in images.into_iter().map(|i| i.1).chain(outputs).chain([normal_image]) {
            gpu.free_image(image);
        }
        adapters.destroy(gpu);
        common::assert_validation_clean(&vulkan);
    }

    /// The other engine formats through the import: a D16 depth buffer (each convention but
    /// linear) and RGBA16F and A2B10G10R10 normal images, against cpu-sim's import of the values
    /// the sampler returns (the stored texels decoded). Same tolerances as above: depth within
    /// 8U·(1 + κ), normal codes ≥ 99.9 % identical (a one-ulp difference in the unit-vector
    /// normalisation may flip a code at a rounding boundary).
    #[test]
    fn d16_depth_and_half_and_10_bit_normals_agree_with_cpu_sim() {
        let Some(vulkan) = common::vulkan() else { return };
        let gpu = vulkan.gpu();
        let adapters = Adapters::new(gpu).unwrap();
        let (inner, guard) = (uvec2(37, 29), 4);
        let view = view_params(inner, guard, 900.0);
        let full = view.size();
        let (texels, pixels) = ((inner.x * inner.y) as usize, (full.x * full.y) as usize);
        let base = import_params(view, inner, NEAR as f32, FAR as f32);
        let usage = vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST;
        let depth_usage = usage | vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT;
        let depth_layout = vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL;
        let shader_read = vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL;
        let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
        let conventions = [
            (DEPTH_STANDARD, Projection::Standard),
            (DEPTH_REVERSED, Projection::Reversed),
            (DEPTH_REVERSED_INFINITE, Projection::ReversedInfinite),
        ];
        let mut depth_images = Vec::new();
        for &(_, projection) in &conventions {
            let stored: Vec<u16> =
                (0..texels).map(|i| (engine_depth(Some(projection), i) as f64 * 65535.0).round() as u16).collect();
            let image = gpu.create_image_2d(vk::Format::D16_UNORM, inner.x, inner.y, depth_usage).unwrap();
            gpu.upload_image(&image, bytemuck::cast_slice(&stored), depth_layout).unwrap();
            let sampled: Vec<f32> = stored.iter().map(|&d| d as f32 / 65535.0).collect();
            depth_images.push((sampled, image));
        }
        let normals = unit_normals(texels - 8);
        let half: Vec<u16> = normals
            .iter()
            .flat_map(|n| {
                let c = *n * 0.5 + Vec3::splat(0.5);
                [common::f32_to_f16(c.x), common::f32_to_f16(c.y), common::f32_to_f16(c.z), common::f32_to_f16(1.0)]
            })
            .collect();
        let half_rgb: Vec<[f32; 3]> = half
            .chunks(4)
            .map(|c| [common::f16_to_f32(c[0]), common::f16_to_f32(c[1]), common::f16_to_f32(c[2])])
            .collect();
        let ten: Vec<u32> = normals
            .iter()
            .map(|n| {
                let c = (*n * 0.5 + Vec3::splat(0.5)) * 1023.0;
                (c.x.round() as u32) | ((c.y.round() as u32) << 10) | ((c.z.round() as u32) << 20) | (3 << 30)
            })
            .collect();
        let ten_rgb: Vec<[f32; 3]> = ten
            .iter()
            .map(|&w| {
                [(w & 1023) as f32 / 1023.0, ((w >> 10) & 1023) as f32 / 1023.0, ((w >> 20) & 1023) as f32 / 1023.0]
            })
            .collect();
        let half_image = gpu.create_image_2d(vk::Format::R16G16B16A16_SFLOAT, inner.x, inner.y, usage).unwrap();
        gpu.upload_image(&half_image, bytemuck::cast_slice(&half), shader_read).unwrap();
        let ten_image = gpu.create_image_2d(vk::Format::A2B10G10R10_UNORM_PACK32, inner.x, inner.y, usage).unwrap();
        gpu.upload_image(&ten_image, bytemuck::cast_slice(&ten), shader_read).unwrap();
        let depth_out: Vec<_> =
            conventions.iter().map(|_| gpu.upload(&vec![-1.0f32; pixels], storage).unwrap()).collect();
        let normals_out: Vec<_> = (0..2).map(|_| gpu.upload(&vec![0u32; pixels], storage).unwrap()).collect();
        let pool = adapters.create_descriptor_pool(gpu, conventions.len() as u32).unwrap();
        gpu.run_commands(|cb| {
            for (k, (convention, _)) in conventions.iter().enumerate() {
                let params = ImportParams { depth_convention: *convention, ..base };
                let depth = EngineImage { view: depth_images[k].1.view, layout: depth_layout };
                let normal_image =
                    [&half_image, &ten_image].get(k).map(|i| EngineImage { view: i.view, layout: shader_read });
                let normal = normal_image.map(|n| (n, &normals_out[k]));
                adapters.record_import(gpu, cb, pool, &params, (depth, &depth_out[k]), normal).unwrap();
            }
        })
        .unwrap();
        for (k, (convention, _)) in conventions.iter().enumerate() {
            let params = ImportParams { depth_convention: *convention, ..base };
            let want = cpu::import_depth(&params, &depth_images[k].0);
            let got: Vec<f32> = gpu.download(&depth_out[k]).unwrap();
            common::assert_same_len(&got, &want, "D16 import");
            for (&g, &w) in got.iter().zip(&want) {
                let (g, w) = (g as f64, w as f64);
                let kappa = if *convention == DEPTH_STANDARD { w * (FAR - NEAR) / (NEAR * FAR) } else { 0.0 };
                let tol = 8.0 * U * (1.0 + kappa);
                assert!((g - w).abs() / w <= tol, "D16, convention {convention}: gpu {g} cpu {w}");
            }
        }
        for (k, (name, rgb)) in [("RGBA16F", &half_rgb), ("A2B10G10R10", &ten_rgb)].into_iter().enumerate() {
            let want = cpu::import_normals(&base, rgb);
            let got: Vec<u32> = gpu.download(&normals_out[k]).unwrap();
            common::assert_same_len(&got, &want, name);
            let identical = got.iter().zip(&want).filter(|(a, b)| a == b).count();
            eprintln!("{name} normals: {identical}/{pixels} identical codes");
            assert!(identical as f64 >= 0.999 * pixels as f64, "{name}: only {identical}/{pixels} identical codes");
        }
        adapters.destroy_descriptor_pool(gpu, pool);
        for b in depth_out.into_iter().chain(normals_out) {
            gpu.free_buffer(b);
        }
        for image in depth_images.into_iter().map(|d| d.1).chain([half_image, ten_image]) {
            gpu.free_image(image);
        }
        adapters.destroy(gpu);
        common::assert_validation_clean(&vulkan);
    }
}
