//! Temporal accumulation of any technique's final AO (engines resolve noise over time; spec gtao-raymarch-hybrid
//! §4.1 "temporal", extended from its static-camera running mean to a moving camera): every
//! pixel of the current frame is carried back into the previous frame through its depth — world
//! position from the current depth, into the previous camera's view, onto the previous image —
//! and, where the previous frame saw the same surface there (its stored depth agrees), blended
//! with the previous frame's accumulated AO by an exponential moving average; elsewhere the
//! history restarts from the current frame.
//!
//! The same reprojection and the same depth test measure temporal instability on the host
//! (`aokit::path`), so "valid in both frames" means one thing.

#[cfg(not(target_arch = "spirv"))]
pub mod settings;

use crate::common::camera::{Camera, ViewParams};
use crate::common::math::is_valid_depth;
use crate::glam::{UVec2, UVec3, Vec2};
use spirv_std::spirv;

/// Everything the accumulation reads besides the images: a storage-buffer record (two cameras
/// exceed the guaranteed push-constant space).
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
#[cfg_attr(not(target_arch = "spirv"), derive(aokit_contract_derive::Layout))]
pub struct TemporalFrame {
    /// This frame's camera.
    pub camera: Camera,
    /// The previous frame's camera: the one the history (AO and depth) was rendered with.
    pub previous: Camera,
    /// Weight α of the current frame in the exponential blend `h + α·(a − h)` (1 = no history).
    pub alpha: f32,
    /// Relative depth tolerance ε of the history test `|d_stored − d_expected| ≤ ε·d_expected`.
    pub depth_tolerance: f32,
    /// 1 when the history buffers hold the previous frame (same target size); 0 on a first
    /// frame, after a cut or a resize: every pixel restarts from the current frame.
    pub history: u32,
    pub _pad: u32,
}

/// Where a pixel of the current frame was in the previous frame.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Reprojection {
    /// False for background, a point behind the previous camera's near plane or outside the
    /// previous inner image.
    pub valid: bool,
    /// The previous frame's pixel (full-target coordinates) holding the point: the nearest
    /// texel, `floor(position)`.
    pub pixel: UVec2,
    /// The point's continuous position on the previous target, in pixels (texel centres at
    /// `k + 0.5`), for [`history_bilinear`].
    pub position: Vec2,
    /// The point's linear depth in the previous view: what the previous depth buffer holds at
    /// `pixel` if it saw the same surface.
    pub depth: f32,
}

/// Reproject pixel `p` of linear depth `d` (spec svao-raysd §1 conventions): view position
/// `X = uv→view(pixel_uv(p), d)` of `camera`, world `W = view_to_world·X`, previous view
/// `X' = previous.world_to_view·W`, position `view→uv(X')·res'` on the previous target; valid
/// when its texel `floor(position)` lies in the previous inner image and `−X'.z` beyond the
/// previous near plane.
#[inline]
pub fn reproject(camera: &Camera, previous: &Camera, p: UVec2, d: f32) -> Reprojection {
    let invalid = Reprojection { valid: false, pixel: UVec2::ZERO, position: Vec2::ZERO, depth: 0.0 };
    let view = &camera.view;
    if !is_valid_depth(d, view.far) {
        return invalid;
    }
    let world = camera.view_to_world.transform_point3(view.uv_to_view(view.pixel_uv(p), d));
    let x = previous.world_to_view.transform_point3(world);
    let depth = -x.z;
    if depth.is_nan() || depth <= previous.view.near {
        return invalid;
    }
    let t = previous.view.view_to_uv(x) * previous.view.res;
    if !(t.x >= 0.0 && t.y >= 0.0 && t.x < previous.view.res.x && t.y < previous.view.res.y) {
        return invalid;
    }
    let pixel = UVec2::new(t.x as u32, t.y as u32);
    if !previous.view.is_inner(pixel) {
        return invalid;
    }
    Reprojection { valid: true, pixel, position: t, depth }
}

/// The depth test of reverse reprojection caching (Nehab, Sander, Lawrence, Tatarchuk, Isidoro,
/// "Accelerating Real-Time Shading with Reverse Reprojection Caching", Graphics Hardware 2007:
/// a cached value is reused only where the cached depth matches the reprojected one), with a
/// relative tolerance: the previous frame saw the same surface at the reprojected pixel when its
/// stored depth is a surface and `|stored − expected| ≤ ε·expected`.
#[inline]
pub fn history_matches(expected: f32, stored: f32, tolerance: f32, far: f32) -> bool {
    is_valid_depth(stored, far) && (stored - expected).abs() <= tolerance * expected
}

/// The history at a reprojected point: the previous frame's accumulated AO filtered bilinearly
/// over the 2×2 texels around `r.position` (weights `(1 − f)`/`f` per axis, the fraction `f`
/// rounded to 1/256 as texture units do, so a static camera reads its own texel exactly),
/// keeping only the taps inside the previous inner image whose stored depth
/// [`history_matches`] `r.depth`, renormalized. Returns `(weight kept, value)`; weight 0: no
/// tap saw this surface. Bilinear rather than nearest, because re-sampling the history to the
/// nearest texel every frame duplicates and drops texel columns under sub-pixel motion (visible
/// streaks, measured on Sponza: docs/temporal.md).
#[inline]
pub fn history_bilinear(
    previous: &ViewParams,
    r: &Reprojection,
    history_ao: &[f32],
    history_depth: &[f32],
    tolerance: f32,
) -> Vec2 {
    let s = r.position - 0.5;
    let base = s.floor();
    let f = ((s - base) * 256.0 + 0.5).floor() / 256.0;
    let (mut sum, mut weights) = (0.0, 0.0);
    let mut k: i32 = 0;
    while k < 4 {
        let (dx, dy) = (k & 1, k >> 1);
        let (x, y) = (base.x as i32 + dx, base.y as i32 + dy);
        let w = (if dx == 0 { 1.0 - f.x } else { f.x }) * (if dy == 0 { 1.0 - f.y } else { f.y });
        if w > 0.0 && x >= 0 && y >= 0 {
            let q = UVec2::new(x as u32, y as u32);
            if previous.is_inner(q) {
                let j = previous.index(q);
                if history_matches(r.depth, history_depth[j], tolerance, previous.far) {
                    sum += w * history_ao[j];
                    weights += w;
                }
            }
        }
        k += 1;
    }
    if weights > 0.0 { Vec2::new(weights, sum / weights) } else { Vec2::ZERO }
}

/// Exponential blend of the history `h` with the current value `a`: `h + α·(a − h)`.
#[inline]
pub fn blend(history: f32, current: f32, alpha: f32) -> f32 {
    history + alpha * (current - history)
}

/// The accumulated AO of pixel `p`: [`blend`] of the history at [`reproject`]'s position
/// ([`history_bilinear`]) with the current AO; the current AO where there is no history, outside
/// the inner image, or where the reprojection or every tap's depth test fails (the history
/// restarts there).
#[inline]
pub fn temporal_pixel(
    frame: &TemporalFrame,
    depth: &[f32],
    ao: &[f32],
    history_ao: &[f32],
    history_depth: &[f32],
    p: UVec2,
) -> f32 {
    let view = &frame.camera.view;
    let i = view.index(p);
    let current = ao[i];
    if frame.history == 0 || !view.is_inner(p) {
        return current;
    }
    let r = reproject(&frame.camera, &frame.previous, p, depth[i]);
    if !r.valid {
        return current;
    }
    let h = history_bilinear(&frame.previous.view, &r, history_ao, history_depth, frame.depth_tolerance);
    if h.x <= 0.0 {
        return current;
    }
    blend(h.y, current, frame.alpha)
}

/// The accumulation, one invocation per pixel of the full target: `out = temporal_pixel(…)`.
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "temporal_blend"))]
pub fn temporal_blend(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[TemporalFrame],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] ao: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] history_ao: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] history_depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 5)] out: &mut [f32],
) {
    let frame = &frame[0];
    let size = frame.camera.view.size();
    let p = id.truncate();
    if p.x >= size.x || p.y >= size.y {
        return;
    }
    out[frame.camera.view.index(p)] = temporal_pixel(frame, depth, ao, history_ao, history_depth, p);
}

/// The history for the next frame, one invocation per pixel of the full target: the accumulated
/// AO and this frame's depth. A pass of its own: the blend reads history at other pixels.
#[crate::kernel]
#[spirv(compute(threads(8, 8), entry_point_name = "temporal_store"))]
pub fn temporal_store(
    #[spirv(global_invocation_id)] id: UVec3,
    #[spirv(storage_buffer, descriptor_set = 0, binding = 0)] frame: &[TemporalFrame],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 1)] depth: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 2)] accumulated: &[f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 3)] history_ao: &mut [f32],
    #[spirv(storage_buffer, descriptor_set = 0, binding = 4)] history_depth: &mut [f32],
) {
    let view = &frame[0].camera.view;
    let size = view.size();
    let p = id.truncate();
    if p.x >= size.x || p.y >= size.y {
        return;
    }
    let i = view.index(p);
    history_ao[i] = accumulated[i];
    history_depth[i] = depth[i];
}
