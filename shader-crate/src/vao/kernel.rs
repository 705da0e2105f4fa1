//! The VAO kernel math (spec svao-raysd §4). Shared by AO pass 1/2 of later techniques.

// f32 methods (`sqrt`, `abs`, `max`, `powf`) on SPIR-V come from `Lanes`, which implements them
// with `num_traits::Float`.
use crate::common::ViewParams;
use crate::common::gbuffer_read::GBuffer;
use crate::common::lanes::{LaneVec2, LaneVec3, Lanes, select_v3, texel_eq};
use crate::common::math::{clamp_lanes, depth_or_far, is_valid_depth, sat, sign_nonzero};
use crate::common::tables::{
    AO_SAMPLES, HBAO_HALF_CHORDS, HBAO_PDFS, HBAO_RADII, VAO_DIRECTIONS, VAO_HALF_CHORDS, VAO_RADII, kernel_entry,
    rotation_sin_cos,
};
use crate::glam::UVec2;

/// Push constants of the VAO pass.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct VaoParams {
    /// Projection of the full target.
    pub view: ViewParams,
    /// World-space AO radius `R` (spec svao-raysd §2 default 0.2).
    pub radius: f32,
    /// Final exponent (spec svao-raysd §2: 2.0; the papers' figures use 4.0).
    pub exponent: f32,
    /// Thickness `τ` of the halo's constant area (spec svao-raysd §2: 0).
    pub thickness: f32,
    /// Screen-space radius clamp in pixels (spec svao-raysd §4.1: 512).
    pub max_screen_radius: f32,
}

/// Everything svao-raysd §4.1 derives once per shaded pixel (`L = f32`) or per `L::LANES` pixels.
#[derive(Copy, Clone, Debug)]
pub struct PixelFrame<L: Lanes = f32> {
    /// The shaded pixel.
    pub pixel: L::U2,
    /// Pixel centre uv.
    pub uv: L::V2,
    /// Sample radius after the screen clamp (`R_pix`, spec svao-raysd §4.1 step 3).
    pub radius: L,
    /// Screen radius in pixels after the clamp.
    pub screen_radius: L,
    /// View-space position `P`.
    pub position: L::V3,
    /// View normal facing the camera.
    pub normal: L::V3,
    /// `n̂ = −P/|P|`, axis of the sampling sphere.
    pub axis: L::V3,
    /// Tangent frame `t`, `b` of the sampling disc.
    pub tangent: L::V3,
    pub bitangent: L::V3,
    /// Normal in sphere space `(N·t, N·b, N·n̂)`.
    pub normal_sphere: L::V3,
    /// `1/nz(N_o.z)`, the hemisphere-clipping divisor of spec svao-raysd §4.2, hoisted out of the samples.
    pub inv_normal_z: L,
}

/// Per-pixel setup of spec svao-raysd §4.1. `None` means "unshaded" (AO = 1): the depth is unusable or the
/// screen radius is below half a pixel. (The reference has no explicit background test, svao-raysd §15.10;
/// we also treat NaN, ±∞, ≤ 0 and ≥ far as background so broken input never yields NaN.)
#[inline]
pub fn setup_pixel<G: GBuffer>(
    gbuffer: &G,
    view: &ViewParams,
    world_radius: f32,
    max_screen_radius: f32,
    p: UVec2,
) -> Option<PixelFrame> {
    let (shaded, frame) = setup_lanes::<G, f32>(gbuffer, view, world_radius, max_screen_radius, p);
    if shaded { Some(frame) } else { None }
}

/// [`setup_pixel`] of one pixel or of `L::LANES` pixels: whether each is shaded, and the frames
/// (those of unshaded pixels are computed and meaningless).
#[inline]
pub fn setup_lanes<G: GBuffer, L: Lanes>(
    gbuffer: &G,
    view: &ViewParams,
    world_radius: f32,
    max_screen_radius: f32,
    p: L::U2,
) -> (L::Mask, PixelFrame<L>) {
    let uv = view.pixel_uv_lanes::<L>(p);
    let d = gbuffer.linear_depth_lanes::<L>(p);
    // Mean of the x and y pixel radii (svao-raysd §4.1 step 2).
    let t = view.tan_half_fov;
    let rpx = (L::splat(world_radius * view.res.x) / (d * (2.0 * t.x))
        + L::splat(world_radius * view.res.y) / (d * (2.0 * t.y)))
        * 0.5;
    let clamped = rpx.gt(L::splat(max_screen_radius));
    let radius = L::select(clamped, L::splat(world_radius * max_screen_radius) / rpx, L::splat(world_radius));
    let rpx = L::select(clamped, L::splat(max_screen_radius), rpx);
    let shaded = L::and(is_valid_depth(d, view.far), L::not(rpx.lt(L::splat(0.5))));
    let position = view.uv_to_view_lanes::<L>(uv, d);
    let normal = gbuffer.view_normal_lanes::<L>(p);
    let normal = select_v3::<L>(position.dot(normal).gt(L::splat(0.0)), -normal, normal);
    let rot = L::v2_from_lanes(move |i| rotation_sin_cos(L::texel_lane(p, i)));
    let r = L::V3::new(rot.x(), rot.y(), L::splat(0.0));
    let axis = -position / position.length();
    let bitangent = axis.cross(r).normalize();
    let tangent = bitangent.cross(axis);
    let normal_sphere = L::V3::new(normal.dot(tangent), normal.dot(bitangent), normal.dot(axis));
    let frame = PixelFrame {
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
        inv_normal_z: L::splat(1.0) / non_zero(normal_sphere.z()),
    };
    (shaded, frame)
}

/// One VAO line sample (spec svao-raysd §4.2), of one pixel (`L = f32`) or of `L::LANES` pixels.
#[derive(Copy, Clone, Debug)]
pub struct LineSample<L: Lanes = f32> {
    /// False for an invalid sample (less than 10 % of its chord above the tangent plane): it
    /// contributes 0 and is never refined. (A flag rather than `Option`: rust-gpu 0.11 cannot
    /// copy an `Option` whose payload has a `bool` niche.)
    pub valid: L::Mask,
    /// Sphere half-chord `h`.
    pub half_chord: L,
    /// The sample's weight: `2h` for VAO, `0.9·(1 − ρ)^1.5` for HBAO+ (spec svao-raysd §4.2, §4.5).
    pub pdf: L,
    /// Hemisphere-clipped chord end (in object-space z, towards the camera is positive).
    pub sphere_end: L,
    /// View-space sample point `S = P + t·o.x + b·o.y` on the disc.
    pub point: L::V3,
    /// Unsnapped, unclamped uv of the sample point `S`.
    pub uv: L::V2,
    /// Texel of the raster sample (`snap(saturate(uvS))`).
    pub texel: L::U2,
    /// `uvS ∈ [0,1]²`.
    pub in_screen: L::Mask,
    /// Unsnapped screen distance to the pixel in full-res pixels (`ssr`).
    pub screen_distance: L,
    /// The raster sample falls into the shaded pixel itself.
    pub same_pixel: L::Mask,
}

/// `nz(x) = sign(x)·max(|x|, 1e−4)` (spec svao-raysd §4.2; sign(0) = +1).
#[inline]
fn non_zero<L: Lanes>(x: L) -> L {
    sign_nonzero(x) * x.abs().max(L::splat(1.0e-4))
}

/// The VAO kernel (spec svao-raysd §4.2–§4.3).
pub const KERNEL_VAO: u32 = 0;
/// The HBAO+ kernel (spec svao-raysd §4.5).
pub const KERNEL_HBAO: u32 = 1;

/// Build sample `i` of the 8-sample VAO kernel (spec svao-raysd §4.2).
#[inline]
pub fn line_sample<L: Lanes>(frame: &PixelFrame<L>, view: &ViewParams, i: u32) -> LineSample<L> {
    line_sample_of(frame, view, i, AO_SAMPLES, KERNEL_VAO)
}

/// Build sample `i` of the `samples`-sample (8, 16 or 32) `kernel` ([`KERNEL_VAO`] or
/// [`KERNEL_HBAO`]): the kernels share the frame, disc directions `α = (i/N)·2·3.141`,
/// hemisphere clipping, validity and projection, and differ in the radii and weights (spec
/// svao-raysd §4.2, §4.5); every per-sample constant comes from the tables at
/// [`kernel_entry`]`(samples, i)`.
#[inline]
pub fn line_sample_of<L: Lanes>(
    frame: &PixelFrame<L>,
    view: &ViewParams,
    i: u32,
    samples: u32,
    kernel: u32,
) -> LineSample<L> {
    let m = kernel_entry(samples, i);
    let dir = VAO_DIRECTIONS[m];
    let hbao = kernel == KERNEL_HBAO;
    let rho = if hbao { HBAO_RADII[m] } else { VAO_RADII[m] };
    let scale = frame.radius * rho;
    let (ox, oy) = (scale * dir[0], scale * dir[1]);
    let half_chord = frame.radius * if hbao { HBAO_HALF_CHORDS[m] } else { VAO_HALF_CHORDS[m] };
    let pdf = if hbao { L::splat(HBAO_PDFS[m]) } else { half_chord * 2.0 };
    let ns = frame.normal_sphere;
    let zc = -(ox * ns.x() + oy * ns.y()) * frame.inv_normal_z;
    let sphere_end = clamp_lanes(zc, -half_chord, half_chord);
    // (h − end)/(2h) > 0.1, without the division.
    let valid = (half_chord - sphere_end).gt(half_chord * 0.2);
    let s = frame.position + frame.tangent * ox + frame.bitangent * oy;
    let uv = view.view_to_uv_lanes::<L>(s);
    let (zero, one) = (L::splat(0.0), L::splat(1.0));
    let in_screen = L::and(L::and(uv.x().ge(zero), uv.x().le(one)), L::and(uv.y().ge(zero), uv.y().le(one)));
    let texel = view.texel_of_uv_lanes::<L>(uv);
    let d = frame.uv - uv;
    let screen_distance = L::V2::new(d.x() * view.res.x, d.y() * view.res.y).length();
    // Spec svao-raysd §4.2 tests |uv − uvR| < 0.9/res on both axes; both are texel centres, so this holds
    // exactly when the raster sample's texel is the shaded pixel.
    let same_pixel = texel_eq::<L>(texel, frame.pixel);
    LineSample { valid, half_chord, pdf, sphere_end, point: s, uv, texel, in_screen, screen_distance, same_pixel }
}

/// Object-space z of a view point: `oz(D) = dot(D − P, n̂)` (spec svao-raysd §1; larger = closer to the camera).
#[inline]
pub fn object_z<L: Lanes>(frame: &PixelFrame<L>, d: L::V3) -> L {
    (d - frame.position).dot(frame.axis)
}

/// Halo visibility of one depth point at object-space `z` (spec svao-raysd §4.3, SVAO paper §3.3):
/// `v(z) = [max(h − max(end, z), 0) + sat((z − (1+τ)R)/h)·(h − end)] / (2h)`.
#[inline]
pub fn halo_visibility<L: Lanes>(z: L, s: &LineSample<L>, radius: L, thickness: f32) -> L {
    let h = s.half_chord;
    let inv_h = L::splat(1.0) / h;
    let inside = (h - s.sphere_end.max(z)).max(L::splat(0.0));
    let halo = sat((z - radius * (1.0 + thickness)) * inv_h) * (h - s.sphere_end);
    (inside + halo) * (inv_h * 0.5)
}

/// HBAO+ occlusion of one depth point `d` (view space) for sample `s` (spec svao-raysd §4.5):
/// `V = D − P`, `k = sat(N·V/|V| − 0.1)·sat(1 − |V|²/R_g²)` with the UNCLAMPED radius `R_g`,
/// `o = sat(k/pdf)`. Points combine by max; 0 = unoccluded.
#[inline]
pub fn hbao_occlusion<L: Lanes>(frame: &PixelFrame<L>, s: &LineSample<L>, d: L::V3, unclamped_radius: f32) -> L {
    let v = d - frame.position;
    let len2 = v.dot(v);
    let k = sat(frame.normal.dot(v) / len2.sqrt() - 0.1) * sat(-(len2 / (unclamped_radius * unclamped_radius)) + 1.0);
    L::select(len2.gt(L::splat(0.0)), sat(k / s.pdf), L::splat(0.0))
}

/// Visibility of a sample whose raster position falls into the shaded pixel: fully visible,
/// `(h − end)/pdf` (spec svao-raysd §4.2 "same pixel").
#[inline]
pub fn unoccluded_visibility<L: Lanes>(s: &LineSample<L>) -> L {
    (s.half_chord - s.sphere_end) / (s.half_chord * 2.0)
}

/// Object-space z of the depth-buffer surface at the sample's raster texel. Unusable depths read
/// as the far plane (nothing there occludes).
#[inline]
pub fn primary_object_z<G: GBuffer, L: Lanes>(
    gbuffer: &G,
    view: &ViewParams,
    frame: &PixelFrame<L>,
    s: &LineSample<L>,
) -> L {
    object_z(frame, texel_point(view, gbuffer.linear_depth_lanes::<L>(s.texel), s))
}

/// View point of the depth value `d` at the sample's raster texel (unusable depths read as far).
#[inline]
pub fn texel_point<L: Lanes>(view: &ViewParams, d: L, s: &LineSample<L>) -> L::V3 {
    view.uv_to_view_lanes::<L>(view.texel_uv_lanes::<L>(s.texel), depth_or_far(d, view.far))
}

/// Final AO of one pixel with plain VAO on a single depth layer (spec svao-raysd §4, §5 with secondary
/// mode Disabled): `A = (2/8)·Σ v_i`, `AO = sat(A)^exponent`, 1 = unoccluded.
#[inline]
pub fn vao_pixel<G: GBuffer>(gbuffer: &G, params: &VaoParams, p: UVec2) -> f32 {
    match setup_pixel(gbuffer, &params.view, params.radius, params.max_screen_radius, p) {
        Some(frame) => vao_finish(params, vao_visibility_sum(gbuffer, params, &frame)),
        None => 1.0,
    }
}

/// `Σ v_i` over the 8 samples of spec svao-raysd §4.2–§4.3 for one pixel or `L::LANES` pixels: invalid
/// samples add 0, a sample in the shaded pixel itself is unoccluded.
#[inline]
pub fn vao_visibility_sum<G: GBuffer, L: Lanes>(gbuffer: &G, params: &VaoParams, frame: &PixelFrame<L>) -> L {
    let view = &params.view;
    let zero = L::splat(0.0);
    let mut sum = zero;
    let mut i = 0;
    while i < AO_SAMPLES {
        let s = line_sample(frame, view, i);
        let z = primary_object_z(gbuffer, view, frame, &s);
        let v =
            L::select(s.same_pixel, unoccluded_visibility(&s), halo_visibility(z, &s, frame.radius, params.thickness));
        sum = sum + L::select(s.valid, v, zero);
        i += 1;
    }
    sum
}

/// `AO = sat((2/8)·Σ v_i)^exponent` (spec svao-raysd §5).
#[inline]
pub fn vao_finish(params: &VaoParams, sum: f32) -> f32 {
    let a = (2.0 / AO_SAMPLES as f32) * sum;
    Lanes::powf(sat(a), params.exponent)
}
