//! Ray-SVAO / RT-VAO (spec svao-raysd §10), the Ray-SD paper's reference: pass 2 traces one
//! ray per flagged sample from the camera through the sample's snapped texel and finds every
//! surface that matters for the halo model on that line — or, with the HBAO+ kernel (svao-raysd §4.5,
//! svao-raysd §10 "HBAO kernel"), the first surface inside the sphere.

#[allow(unused_imports)]
use spirv_std::num_traits::Float;

// The ray-query entry points exist in SPIR-V only (built with the `rq` feature); their
// declarations (`#[kernel(spirv_only)]`) exist on the host too.
#[cfg(any(feature = "rq", not(target_arch = "spirv")))]
pub mod rq;
#[cfg(any(feature = "rt", not(target_arch = "spirv")))]
pub mod rt;

use crate::common::alpha::AlphaTables;
use crate::common::any_hit::CandidateHit;
use crate::common::camera::Camera;
use crate::common::math::sat;
use crate::glam::Vec3;
use crate::svao::pass1::combine;
use crate::svao::{Refined, SvaoParams};
use crate::vao::kernel::{KERNEL_HBAO, LineSample, PixelFrame, halo_visibility, hbao_occlusion};

pub use crate::common::any_hit::{ACCEPT, ACCEPT_AND_END, IGNORE};

/// The running ray distances of one sample's ray (spec svao-raysd §10), also its ray payload. With the
/// HBAO+ kernel the halo branch is switched off (`t_halo` = 0, `t_sphere` = `t_const` = −1: no
/// hit is ignored or treated as lying in front of the sphere), so [`sample_any_hit`] keeps the
/// nearest hit in `t_inside`: svao-raysd §10's first hit on `[T(h), T(sphereEnd)]`.
#[repr(C)]
#[derive(Copy, Clone, Debug, PartialEq)]
#[cfg_attr(not(target_arch = "spirv"), derive(bytemuck::Pod, bytemuck::Zeroable))]
pub struct SampleRayState {
    /// Farthest hit so far in front of the sphere (starts at the falloff start `T((1+τ)R + h)`).
    pub t_halo: f32,
    /// Nearest hit so far inside the sphere (starts at `T(sphereEnd)`).
    pub t_inside: f32,
    /// `T((1+τ)R)`: start of the constant (fully occluding) area.
    pub t_const: f32,
    /// `T(h)`: the sphere's front.
    pub t_sphere: f32,
}

/// A sample's ray: world-space origin and unit direction (and the direction in view space), its
/// interval, its state, and the lateral correction `κ = |S|/|P|` that maps ray distance to
/// object-space z.
#[derive(Copy, Clone, Debug)]
pub struct SampleRay {
    pub origin: Vec3,
    pub direction: Vec3,
    pub view_direction: Vec3,
    pub t_min: f32,
    pub t_max: f32,
    pub state: SampleRayState,
    pub kappa: f32,
}

/// Set up the ray of flagged sample `s` (spec svao-raysd §10): direction through `snap(uvS)` (not clamped),
/// `T(z) = (|P| − z)·κ`; `tMin = max(tHalo, 0)`, `tMax = tInside`, and in screen `tMin` starts
/// `0.01·R` behind the depth-buffer surface. With the HBAO+ kernel the interval is
/// `[max(T(h), 0), T(sphereEnd)]` (same in-screen raise) and the halo branch is off
/// ([`SampleRayState`]).
#[inline]
pub fn sample_ray(
    camera: &Camera,
    params: &SvaoParams,
    frame: &PixelFrame,
    s: &LineSample,
    z_primary: f32,
) -> SampleRay {
    let view = &params.vao.view;
    let r = frame.radius;
    let snapped = ((s.uv * view.res).floor() + 0.5) / view.res;
    let view_direction = view.uv_to_view(snapped, 1.0).normalize();
    let direction = camera.view_to_world.transform_vector3(view_direction).normalize();
    let distance = frame.position.length();
    let kappa = s.point.length() / distance;
    let t = |z: f32| (distance - z) * kappa;
    let falloff_start = (1.0 + params.vao.thickness) * r;
    let (state, t_start) = if params.kernel == KERNEL_HBAO {
        let off = SampleRayState { t_halo: 0.0, t_inside: t(s.sphere_end), t_const: -1.0, t_sphere: -1.0 };
        (off, t(s.half_chord))
    } else {
        let state = SampleRayState {
            t_halo: t(falloff_start + s.half_chord),
            t_inside: t(s.sphere_end),
            t_const: t(falloff_start),
            t_sphere: t(s.half_chord),
        };
        (state, state.t_halo)
    };
    let mut t_min = t_start.max(0.0);
    if s.in_screen {
        t_min = t_min.max(t(z_primary) + 0.01 * r);
    }
    SampleRay { origin: camera.eye(), direction, view_direction, t_min, t_max: state.t_inside, state, kappa }
}

/// The Ray-SVAO any-hit (spec svao-raysd §10) for a hit at `t` that passed the alpha and facing tests:
/// hits nearer than the running `tHalo` do not matter; in front of the sphere a hit pushes
/// `tHalo` back and, inside the constant area, ends the search; inside the sphere the nearest
/// hit is committed.
#[inline]
pub fn sample_any_hit(state: &mut SampleRayState, t: f32) -> u32 {
    if t < state.t_halo {
        return IGNORE;
    }
    if t <= state.t_sphere {
        state.t_halo = state.t_halo.max(t);
        return if t >= state.t_const { ACCEPT_AND_END } else { IGNORE };
    }
    state.t_inside = state.t_inside.min(t);
    ACCEPT
}

/// The Ray-SVAO any-hit over one ray's candidates (spec svao-raysd §10): the alpha test, then
/// [`sample_any_hit`] (every triangle counts as facing the ray: the library traces without
/// culling, svao-raysd §10's "double-sided" case). The any-hit shader and the ray-query loop both run it.
pub struct SampleHits<'a> {
    pub state: SampleRayState,
    pub alpha: AlphaTables<'a>,
}

impl CandidateHit for SampleHits<'_> {
    #[inline]
    fn decide(&mut self, t: f32, bary: crate::glam::Vec2, triangle: u32) -> u32 {
        if !self.alpha.passes(triangle, bary) {
            return IGNORE;
        }
        sample_any_hit(&mut self.state, t)
    }
}

/// Value after the trace (spec svao-raysd §10): VAO `min(v, v(Z(tInside)), vHaloOnly(Z(tHalo)))` with
/// `Z(t) = |P| − t/κ`, `vHaloOnly` the halo (second) term of spec svao-raysd §4.3; HBAO+ `max(v, o)` with
/// `o` the occlusion (svao-raysd §4.5) of the first hit `dir·tFirst` (view space), `v` unchanged on a miss.
/// (The reference evaluates a miss at `tFirst = 0`, the camera itself, which adds occlusion when
/// the camera is within `R` of the pixel (svao-raysd §10); aokit counts a miss as nothing found.)
#[inline]
pub fn sample_visibility(frame: &PixelFrame, s: &LineSample, params: &SvaoParams, ray: &SampleRay, v: f32) -> f32 {
    if params.kernel == KERNEL_HBAO {
        // `t_inside` stays at tMax without a hit.
        if ray.state.t_inside < ray.t_max {
            let hit = ray.view_direction * ray.state.t_inside;
            return combine(params, v, hbao_occlusion(frame, s, hit, params.vao.radius));
        }
        return v;
    }
    let distance = frame.position.length();
    let z = |t: f32| distance - t / ray.kappa;
    let r = frame.radius;
    let tau = params.vao.thickness;
    let inside = halo_visibility(z(ray.state.t_inside), s, r, tau);
    let halo_only = sat((z(ray.state.t_halo) - (1.0 + tau) * r) / s.half_chord) * (s.half_chord - s.sphere_end)
        / (2.0 * s.half_chord);
    v.min(inside).min(halo_only)
}

/// Traces a sample's ray, calling [`sample_any_hit`] for every candidate: `trace_ray` on the
/// GPU, the BVH on the CPU.
pub trait SampleTracer {
    fn trace(&mut self, ray: &mut SampleRay);
}

/// Refine flagged sample `s` by tracing its ray (spec svao-raysd §10): set up, trace when the interval is
/// not empty, evaluate.
#[inline]
pub fn refine_by_ray<T: SampleTracer>(
    camera: &Camera,
    params: &SvaoParams,
    frame: &PixelFrame,
    s: &LineSample,
    v: f32,
    z_primary: f32,
    tracer: &mut T,
) -> Refined {
    let mut ray = sample_ray(camera, params, frame, s, z_primary);
    let mut rays = 0;
    if ray.t_min < ray.t_max {
        tracer.trace(&mut ray);
        rays = 1;
    }
    Refined { v: sample_visibility(frame, s, params, &ray, v), rays }
}
