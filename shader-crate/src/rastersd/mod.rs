//! The raster stochastic depth map baseline (Vermeer et al.'s coverage mask, "Raster-SVAO";
//! spec svao-raysd §8): a second geometry pass at SD resolution whose fragments, behind the
//! first layer and inside the requested interval, keep a random coverage mask with expected
//! fraction α = 1.5/N of the N samples; per sample the nearest kept depth wins (depth test
//! LESS). aokit writes the samples' depths with an atomic min on a storage buffer — the same
//! "nearest wins" as an MSAA depth buffer, with the stencil replaced by an early-out on
//! `rayMax == 0` (spec svao-raysd §8 allows an equivalent early-out).

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use crate::common::float_order::from_ordered_bits;
use crate::common::gbuffer_read::GBuffer;
use crate::common::hash::wyman_hash;
use crate::common::noise::{frame_rotation, rotate};
use crate::glam::{UVec2, Vec3};
use crate::raysd::bilinear_depth;
use crate::svao::SvaoFrame;

/// `hash3(a, b, c) = hash(hash(a, b), c)` (spec svao-raysd §8 step 4).
#[inline]
pub fn hash3(a: f32, b: f32, c: f32) -> f32 {
    wyman_hash(wyman_hash(a, b), c)
}

/// `hash4(a, b, c, d) = hash(hash3(a, b, c), d)`.
#[inline]
pub fn hash4(a: f32, b: f32, c: f32, d: f32) -> f32 {
    wyman_hash(hash3(a, b, c), d)
}

/// Binomial coefficient C(n, k) for small n.
#[inline]
fn binomial(n: u32, k: u32) -> u32 {
    let mut r = 1;
    let mut i = 0;
    while i < k {
        r = r * (n - i) / (i + 1);
        i += 1;
    }
    r
}

/// `I[k] = Σ_{j<k} C(N, j)`: where the masks with popcount k start in the popcount-ordered LUT.
#[inline]
pub fn stratum_start(n: u32, k: u32) -> u32 {
    let mut s = 0;
    let mut j = 0;
    while j < k {
        s += binomial(n, j);
        j += 1;
    }
    s
}

/// `LUT[idx]`: all N-bit masks sorted by popcount, then by value (spec svao-raysd §8; N = 4:
/// `[0, 1,2,4,8, 3,5,6,9,10,12, 7,11,13,14, 15]`).
#[inline]
pub fn mask_lut(n: u32, idx: u32) -> u32 {
    let mut k = 0;
    while k < n && stratum_start(n, k + 1) <= idx {
        k += 1;
    }
    let mut rank = idx - stratum_start(n, k);
    let mut m = 0u32;
    while m < (1 << n) {
        if m.count_ones() == k {
            if rank == 0 {
                return m;
            }
            rank -= 1;
        }
        m += 1;
    }
    (1 << n) - 1
}

/// The fragment's coverage mask (spec svao-raysd §8 step 5): `Rn = floor(α·N + u)` kept samples with
/// `u = hash4(posW, 1.438943289)`, α = 1.5/N; all N when Rn ≥ N, none when Rn = 0, else one of the
/// C(N, Rn) masks with Rn bits, picked by `u2 = hash3(posW.zyx)` from its stratum of the LUT. In
/// frame `frame` of a sequence both hashes are rotated by its `frame_rotation` (frame 0: none).
#[inline]
pub fn coverage_mask(pos_w: Vec3, n: u32, frame: u32) -> u32 {
    let rotation = frame_rotation(frame);
    let u = rotate(hash4(pos_w.x, pos_w.y, pos_w.z, 1.438_943_3), rotation.x);
    let alpha = 1.5 / n as f32;
    let rn = (alpha * n as f32 + u).floor() as u32;
    if rn >= n {
        return (1 << n) - 1;
    }
    if rn == 0 {
        return 0;
    }
    let u2 = rotate(hash3(pos_w.z, pos_w.y, pos_w.x), rotation.y);
    let (lo, hi) = (stratum_start(n, rn) as f32, stratum_start(n, rn + 1) as f32);
    mask_lut(n, (lo + (hi - lo) * u2) as u32)
}

/// One fragment at SD texel `q` (spec svao-raysd §8 steps 2–6, the alpha test done by the caller): linear
/// view depth `d`, world position `pos_w`, camera distance `dist`. Returns the coverage mask
/// (0 = discarded) and the normalized depth `(d − near)/(far − near)` to min into each covered
/// sample. Fragments not farther than the first layer (bilinear primary depth at the texel
/// centre) or outside `[rayMin, rayMax]` are discarded.
#[inline]
pub fn raster_fragment<G: GBuffer>(
    gbuffer: &G,
    frame: &SvaoFrame,
    q: UVec2,
    d: f32,
    pos_w: Vec3,
    dist: f32,
    ray_min: u32,
    ray_max: u32,
) -> (u32, f32) {
    let params = &frame.params;
    let view = &params.vao.view;
    let centre = (q.as_vec2() + 0.5) / params.sd_low_res.as_vec2();
    if d <= bilinear_depth(gbuffer, frame, centre) {
        return (0, 1.0);
    }
    if params.interval != 0
        && ((ray_min != 0 && dist <= from_ordered_bits(ray_min))
            || (ray_max != 0 && dist >= from_ordered_bits(ray_max)))
    {
        return (0, 1.0);
    }
    let z = (d - view.near) / (view.far - view.near);
    (coverage_mask(pos_w, params.sd_layers, params.noise_frame), z)
}

use crate::common::alpha::{AlphaMaskHeader, alpha_test_passes};
use crate::common::atomics::AtomicU32Buffer;
use crate::common::float_order::ordered_bits;
use crate::common::gbuffer_read::DepthSlice;
use crate::glam::{Vec2, Vec4};
use spirv_std::spirv;

/// Fragment shader of the raster SD pass, drawn at SD resolution with the G-buffer's vertex
/// shader: early-out where no SD sample was requested, alpha test, then the covered samples'
/// atomic min of the normalized depth.
#[crate::kernel]
#[spirv(fragment(entry_point_name = "rastersd_fs"))]
pub fn rastersd_fs(
    #[spirv(frag_coord)] frag_coord: Vec4,
    view_position: Vec3,
    #[spirv(flat)] _view_normal: Vec3,
    uv: Vec2,
    #[spirv(flat)] material: u32,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] mask_headers: &[AlphaMaskHeader],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] mask_texels: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] frame: &[SvaoFrame],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] ray_min: &[u32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] ray_max: &[u32],
    #[read_write]
    #[spirv(storage_buffer, descriptor_set = 0, binding = 6)]
    mut sd_bits: &mut [u32],
) {
    let frame = &frame[0];
    let params = &frame.params;
    let size = params.sd_size();
    let q = UVec2::new((frag_coord.x as u32).min(size.x - 1), (frag_coord.y as u32).min(size.y - 1));
    let i = params.sd_index(q);
    if ray_max[i] == 0 || !alpha_test_passes(mask_headers, mask_texels, material, uv) {
        return;
    }
    let gbuffer = DepthSlice { depth, width: params.vao.view.size().x };
    let pos_w = frame.camera.view_to_world.transform_point3(view_position);
    let (mask, z) =
        raster_fragment(&gbuffer, frame, q, -view_position.z, pos_w, view_position.length(), ray_min[i], ray_max[i]);
    let bits = ordered_bits(z);
    let n = params.sd_layers as usize;
    let mut k = 0;
    while k < n {
        if mask & (1 << k) != 0 {
            sd_bits.atomic_min(i * n + k, bits);
        }
        k += 1;
    }
}
