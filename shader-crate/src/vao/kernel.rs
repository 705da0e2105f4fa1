//! The VAO kernel math (spec svao-raysd §4). Shared by AO pass 1/2 of later techniques.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

use crate::common::ViewParams;
use crate::common::gbuffer_read::GBuffer;
use crate::common::math::{clamp, is_valid_depth, sat, sign_nonzero};
use crate::common::tables::{
    AO_SAMPLES, HBAO_HALF_CHORDS, HBAO_PDFS, HBAO_RADII, VAO_DIRECTIONS, VAO_HALF_CHORDS, VAO_RADII, kernel_entry,
    rotation_sin_cos,
};
use crate::glam::{UVec2, Vec2, Vec3, vec2, vec3};

/// Push constants of the VAO pass.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct VaoParams {
    /// Projection of the full target.
    pub view: ViewParams,
    /// World-space AO radius `R` (spec §2 default 0.2).
    pub radius: f32,
    /// Final exponent (spec §2: 2.0; the papers' figures use 4.0).
    pub exponent: f32,
    /// Thickness `τ` of the halo's constant area (spec §2: 0).
    pub thickness: f32,
    /// Screen-space radius clamp in pixels (spec §4.1: 512).
    pub max_screen_radius: f32,
}

/// Everything §4.1 derives once per shaded pixel.
#[derive(Copy, Clone, Debug)]
pub struct PixelFrame {
    /// The shaded pixel.
    pub pixel: UVec2,
    /// Pixel centre uv.
    pub uv: Vec2,
    /// Sample radius after the screen clamp (`R_pix`, spec §4.1 step 3).
    pub radius: f32,
    /// Screen radius in pixels after the clamp.
    pub screen_radius: f32,
    /// View-space position `P`.
    pub position: Vec3,
    /// View normal facing the camera.
    pub normal: Vec3,
    /// `n̂ = −P/|P|`, axis of the sampling sphere.
    pub axis: Vec3,
    /// Tangent frame `t`, `b` of the sampling disc.
    pub tangent: Vec3,
    pub bitangent: Vec3,
    /// Normal in sphere space `(N·t, N·b, N·n̂)`.
    pub normal_sphere: Vec3,
    /// `1/nz(N_o.z)`, the hemisphere-clipping divisor of spec §4.2, hoisted out of the samples.
    pub inv_normal_z: f32,
}

/// Per-pixel setup of spec §4.1. `None` means "unshaded" (AO = 1): the depth is unusable or the
/// screen radius is below half a pixel. (The reference has no explicit background test, §15.10;
/// we also treat NaN, ±∞, ≤ 0 and ≥ far as background so broken input never yields NaN.)
#[inline]
pub fn setup_pixel<G: GBuffer>(
    gbuffer: &G,
    view: &ViewParams,
    world_radius: f32,
    max_screen_radius: f32,
    p: UVec2,
) -> Option<PixelFrame> {
    let uv = view.pixel_uv(p);
    let d = gbuffer.linear_depth(p);
    if !is_valid_depth(d, view.far) {
        return None;
    }
    // Mean of the x and y pixel radii (§4.1 step 2).
    let t = view.tan_half_fov;
    let mut rpx = 0.5 * (world_radius * view.res.x / (2.0 * t.x * d) + world_radius * view.res.y / (2.0 * t.y * d));
    let mut radius = world_radius;
    if rpx > max_screen_radius {
        radius = world_radius * max_screen_radius / rpx;
        rpx = max_screen_radius;
    }
    if rpx < 0.5 {
        return None;
    }
    let position = view.uv_to_view(uv, d);
    let mut normal = gbuffer.view_normal(p);
    if position.dot(normal) > 0.0 {
        normal = -normal;
    }
    let rot = rotation_sin_cos(p);
    let r = vec3(rot.x, rot.y, 0.0);
    let axis = -position / position.length();
    let bitangent = axis.cross(r).normalize();
    let tangent = bitangent.cross(axis);
    let normal_sphere = vec3(normal.dot(tangent), normal.dot(bitangent), normal.dot(axis));
    Some(PixelFrame {
        pixel: p,
        uv,
        radius,
        screen_radius: rpx,
        position,
        normal,
        axis,
        tangent,
        bitangent,
        normal_sphere,
        inv_normal_z: 1.0 / non_zero(normal_sphere.z),
    })
}

/// One VAO line sample (spec §4.2).
#[derive(Copy, Clone, Debug)]
pub struct LineSample {
    /// False for an invalid sample (less than 10 % of its chord above the tangent plane): it
    /// contributes 0 and is never refined. (A flag rather than `Option`: rust-gpu 0.11 cannot
    /// copy an `Option` whose payload has a `bool` niche.)
    pub valid: bool,
    /// Sphere half-chord `h`.
    pub half_chord: f32,
    /// The sample's weight: `2h` for VAO, `0.9·(1 − ρ)^1.5` for HBAO+ (spec §4.2, §4.5).
    pub pdf: f32,
    /// Hemisphere-clipped chord end (in object-space z, towards the camera is positive).
    pub sphere_end: f32,
    /// View-space sample point `S = P + t·o.x + b·o.y` on the disc.
    pub point: Vec3,
    /// Unsnapped, unclamped uv of the sample point `S`.
    pub uv: Vec2,
    /// Texel of the raster sample (`snap(saturate(uvS))`).
    pub texel: UVec2,
    /// `uvS ∈ [0,1]²`.
    pub in_screen: bool,
    /// Unsnapped screen distance to the pixel in full-res pixels (`ssr`).
    pub screen_distance: f32,
    /// The raster sample falls into the shaded pixel itself.
    pub same_pixel: bool,
}

/// `nz(x) = sign(x)·max(|x|, 1e−4)` (spec §4.2).
#[inline]
fn non_zero(x: f32) -> f32 {
    sign_nonzero(x) * x.abs().max(1.0e-4)
}

/// The VAO kernel (spec §4.2–§4.3).
pub const KERNEL_VAO: u32 = 0;
/// The HBAO+ kernel (spec §4.5).
pub const KERNEL_HBAO: u32 = 1;

/// Build sample `i` of the 8-sample VAO kernel (spec §4.2).
#[inline]
pub fn line_sample(frame: &PixelFrame, view: &ViewParams, i: u32) -> LineSample {
    line_sample_of(frame, view, i, AO_SAMPLES, KERNEL_VAO)
}

/// Build sample `i` of the `samples`-sample (8, 16 or 32) `kernel` ([`KERNEL_VAO`] or
/// [`KERNEL_HBAO`]): the kernels share the frame, disc directions `α = (i/N)·2·3.141`,
/// hemisphere clipping, validity and projection, and differ in the radii and weights (spec
/// §4.2, §4.5); every per-sample constant comes from the tables at
/// [`kernel_entry`]`(samples, i)`.
#[inline]
pub fn line_sample_of(frame: &PixelFrame, view: &ViewParams, i: u32, samples: u32, kernel: u32) -> LineSample {
    let m = kernel_entry(samples, i);
    let dir = VAO_DIRECTIONS[m];
    let hbao = kernel == KERNEL_HBAO;
    let rho = if hbao { HBAO_RADII[m] } else { VAO_RADII[m] };
    let offset = rho * frame.radius * vec2(dir[0], dir[1]);
    let half_chord = if hbao { HBAO_HALF_CHORDS[m] } else { VAO_HALF_CHORDS[m] } * frame.radius;
    let pdf = if hbao { HBAO_PDFS[m] } else { 2.0 * half_chord };
    let zc = -offset.dot(vec2(frame.normal_sphere.x, frame.normal_sphere.y)) * frame.inv_normal_z;
    let sphere_end = clamp(zc, -half_chord, half_chord);
    // (h − end)/(2h) > 0.1, without the division.
    let valid = half_chord - sphere_end > 0.2 * half_chord;
    let s = frame.position + frame.tangent * offset.x + frame.bitangent * offset.y;
    let uv = view.view_to_uv(s);
    let in_screen = uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0;
    let texel = view.texel_of_uv(uv);
    let screen_distance = ((frame.uv - uv) * view.res).length();
    // Spec §4.2 tests |uv − uvR| < 0.9/res on both axes; both are texel centres, so this holds
    // exactly when the raster sample's texel is the shaded pixel.
    let same_pixel = texel.x == frame.pixel.x && texel.y == frame.pixel.y;
    LineSample { valid, half_chord, pdf, sphere_end, point: s, uv, texel, in_screen, screen_distance, same_pixel }
}

/// Object-space z of a view point: `oz(D) = dot(D − P, n̂)` (spec §1; larger = closer to the camera).
#[inline]
pub fn object_z(frame: &PixelFrame, d: Vec3) -> f32 {
    (d - frame.position).dot(frame.axis)
}

/// Halo visibility of one depth point at object-space `z` (spec §4.3, SVAO paper §3.3):
/// `v(z) = [max(h − max(end, z), 0) + sat((z − (1+τ)R)/h)·(h − end)] / (2h)`.
#[inline]
pub fn halo_visibility(z: f32, s: &LineSample, radius: f32, thickness: f32) -> f32 {
    let h = s.half_chord;
    let inv_h = 1.0 / h;
    let inside = (h - s.sphere_end.max(z)).max(0.0);
    let halo = sat((z - (1.0 + thickness) * radius) * inv_h) * (h - s.sphere_end);
    (inside + halo) * (0.5 * inv_h)
}

/// HBAO+ occlusion of one depth point `d` (view space) for sample `s` (spec §4.5):
/// `V = D − P`, `k = sat(N·V/|V| − 0.1)·sat(1 − |V|²/R_g²)` with the UNCLAMPED radius `R_g`,
/// `o = sat(k/pdf)`. Points combine by max; 0 = unoccluded.
#[inline]
pub fn hbao_occlusion(frame: &PixelFrame, s: &LineSample, d: Vec3, unclamped_radius: f32) -> f32 {
    let v = d - frame.position;
    let len2 = v.dot(v);
    if len2 <= 0.0 {
        return 0.0;
    }
    let k = sat(frame.normal.dot(v) / len2.sqrt() - 0.1) * sat(1.0 - len2 / (unclamped_radius * unclamped_radius));
    sat(k / s.pdf)
}

/// Visibility of a sample whose raster position falls into the shaded pixel: fully visible,
/// `(h − end)/pdf` (spec §4.2 "same pixel").
#[inline]
pub fn unoccluded_visibility(s: &LineSample) -> f32 {
    (s.half_chord - s.sphere_end) / (2.0 * s.half_chord)
}

/// Object-space z of the depth-buffer surface at the sample's raster texel. Unusable depths read
/// as the far plane (nothing there occludes).
#[inline]
pub fn primary_object_z<G: GBuffer>(gbuffer: &G, view: &ViewParams, frame: &PixelFrame, s: &LineSample) -> f32 {
    let mut d = gbuffer.linear_depth(s.texel);
    if !is_valid_depth(d, view.far) {
        d = view.far;
    }
    object_z(frame, view.uv_to_view(view.texel_uv(s.texel), d))
}

/// Final AO of one pixel with plain VAO on a single depth layer (spec §4, §5 with secondary
/// mode Disabled): `A = (2/8)·Σ v_i`, `AO = sat(A)^exponent`, 1 = unoccluded.
#[inline]
pub fn vao_pixel<G: GBuffer>(gbuffer: &G, params: &VaoParams, p: UVec2) -> f32 {
    let view = &params.view;
    let frame = match setup_pixel(gbuffer, view, params.radius, params.max_screen_radius, p) {
        Some(f) => f,
        None => return 1.0,
    };
    let mut sum = 0.0;
    let mut i = 0;
    while i < AO_SAMPLES {
        let s = line_sample(&frame, view, i);
        if s.valid {
            sum += if s.same_pixel {
                unoccluded_visibility(&s)
            } else {
                let z = primary_object_z(gbuffer, view, &frame, &s);
                halo_visibility(z, &s, frame.radius, params.thickness)
            };
        }
        i += 1;
    }
    let a = (2.0 / AO_SAMPLES as f32) * sum;
    sat(a).powf(params.exponent)
}
