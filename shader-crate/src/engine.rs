//! What every engine-facing executor shares (host side): the settings an engine picks
//! ([`AoSettings`]), its depth convention ([`DepthConvention`]), and aokit's camera and frame
//! description derived from the engine's projection and view matrices ([`engine_camera`],
//! [`engine_frame`]). The Vulkan effect (`aokit_vulkan::AoEffect`) and the wgpu effect
//! (`aokit_wgpu::AoEffect`) both build their pass graphs from these, so an engine's frame means
//! the same on either.

use crate::adapters::ImportParams;
use crate::adapters::settings::AdapterSettings;
use crate::adapters::{DEPTH_LINEAR, DEPTH_REVERSED, DEPTH_REVERSED_INFINITE, DEPTH_STANDARD};
use crate::common::alpha::AlphaMaskHeader;
use crate::common::camera::{Camera, ViewParams};
use crate::glam::{Mat4, UVec2, Vec2, vec2};
use crate::graph::{FrameDesc, RtMode};
use crate::technique::Technique;
use crate::temporal::settings::TemporalSettings;

/// The engine's depth convention: what its depth image stores (window depth in `[0, 1]`) and how
/// the projection's planes are read.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum DepthConvention {
    /// 0 at the near plane, 1 at the far plane (e.g. glam's `Mat4::perspective_rh`).
    Standard,
    /// 1 at the near plane, 0 at a finite far plane.
    Reversed,
    /// 1 at the near plane, 0 at infinity (glam's `Mat4::perspective_infinite_reverse_rh`).
    ReversedInfinite,
    /// 0 at the near plane, 1 at the far plane, from an OpenGL-style projection whose clip depth
    /// spans `[−1, 1]` (`glFrustum`, `gluPerspective`) and is stored as the window depth
    /// `0.5·z_ndc + 0.5`: OpenGL with `glDepthRange(0, 1)` (OpenGL 4.6 core specification, section 13.8.1), or
    /// Vulkan with `VK_EXT_depth_clip_control`'s `negativeOneToOne`. The stored values are those
    /// of [`DepthConvention::Standard`]; only the planes are read differently from the matrix.
    /// An infinite far plane is refused.
    NegativeOneToOne,
    /// An `R32_SFLOAT` image holding the linear view depth (distance along −Z), not hardware
    /// depth; the projection still gives the field of view and the far plane.
    Linear,
}

impl DepthConvention {
    /// The adapter's number for it (`aokit_shaders::adapters::depth_convention`), the value of
    /// `ImportParams::depth_convention`.
    pub fn code(self) -> u32 {
        match self {
            DepthConvention::Standard | DepthConvention::NegativeOneToOne => DEPTH_STANDARD,
            DepthConvention::Reversed => DEPTH_REVERSED,
            DepthConvention::ReversedInfinite => DEPTH_REVERSED_INFINITE,
            DepthConvention::Linear => DEPTH_LINEAR,
        }
    }
}

/// Everything that selects what the effect computes. Made with [`AoSettings::new`] and the
/// builder methods; the fields are public for reading and for struct-update syntax.
#[derive(Clone, Debug)]
pub struct AoSettings {
    /// The technique and its settings (presets first: [`Technique::preset`]).
    pub technique: Technique,
    /// World-space AO radius, in the units of the engine's view matrix [0.5].
    pub radius: f32,
    /// Exponent `e` of the final `A^e` \[2\] (XeGTAO applies its own `final-power` instead).
    pub exponent: f32,
    /// Halo thickness τ of the VAO family, world units \[0\].
    pub thickness: f32,
    /// Guard band in pixels around the engine's image \[0\]: aokit's internal target is larger
    /// by `2·guard` and reads the engine's edge texels there.
    pub guard: u32,
    /// Temporal accumulation of the AO over frames (reprojected through the previous view of
    /// the frame's previous view) \[off\].
    pub temporal: Option<TemporalSettings>,
    /// How ray-traced techniques trace: ray-tracing pipelines or ray queries [`None`: pipelines
    /// where the device has them, else ray queries].
    pub rt_mode: Option<RtMode>,
    /// View depth at and beyond which aokit treats a pixel as background [`None`: the
    /// projection's far plane; `1e5 × near` for an infinite projection].
    pub background_depth: Option<f32>,
}

impl AoSettings {
    /// `technique` with the default AO parameters.
    pub fn new(technique: Technique) -> AoSettings {
        AoSettings {
            technique,
            radius: 0.5,
            exponent: 2.0,
            thickness: 0.0,
            guard: 0,
            temporal: None,
            rt_mode: None,
            background_depth: None,
        }
    }

    /// With AO radius `radius` (world units).
    pub fn radius(self, radius: f32) -> AoSettings {
        AoSettings { radius, ..self }
    }

    /// With exponent `exponent`.
    pub fn exponent(self, exponent: f32) -> AoSettings {
        AoSettings { exponent, ..self }
    }

    /// With halo thickness `thickness`.
    pub fn thickness(self, thickness: f32) -> AoSettings {
        AoSettings { thickness, ..self }
    }

    /// With a guard band of `guard` pixels.
    pub fn guard(self, guard: u32) -> AoSettings {
        AoSettings { guard, ..self }
    }

    /// With temporal accumulation.
    pub fn temporal(self, temporal: TemporalSettings) -> AoSettings {
        AoSettings { temporal: Some(temporal), ..self }
    }

    /// With ray-traced passes run as `mode`.
    pub fn rt_mode(self, mode: RtMode) -> AoSettings {
        AoSettings { rt_mode: Some(mode), ..self }
    }

    /// With pixels at and beyond view depth `depth` treated as background.
    pub fn background_depth(self, depth: f32) -> AoSettings {
        AoSettings { background_depth: Some(depth), ..self }
    }

    /// Refuse values out of range, with the reason in one line.
    pub fn check(&self) -> Result<(), String> {
        let positive = |what: &str, v: f32| {
            if v.is_finite() && v > 0.0 { Ok(()) } else { Err(format!("{what} {v}: expected > 0")) }
        };
        positive("radius", self.radius)?;
        positive("exponent", self.exponent)?;
        if let Some(d) = self.background_depth {
            positive("background depth", d)?;
        }
        if !(self.thickness.is_finite() && self.thickness >= 0.0) {
            return Err(format!("thickness {}: expected ≥ 0", self.thickness));
        }
        if self.guard > 512 {
            return Err(format!("guard band {} px: expected ≤ 512", self.guard));
        }
        if let Some(t) = self.temporal {
            t.validate()?;
        }
        Ok(())
    }
}

/// The scene's triangles, for the ray-traced techniques (`AoEffect::build_scene` of
/// `aokit-vulkan` and of `aokit-wgpu`).
#[derive(Copy, Clone, Debug)]
pub struct SceneGeometry<'a> {
    /// World-space positions, three corners per triangle.
    pub positions: &'a [[f32; 3]],
    /// Texture coordinates, three per triangle (what the alpha masks are sampled at).
    pub uvs: &'a [Vec2],
    /// Material index per triangle (into `mask_headers`).
    pub materials: &'a [u32],
    /// Alpha mask per material (`width == 0`: opaque); empty: every material opaque.
    pub mask_headers: &'a [AlphaMaskHeader],
    /// The masks' alpha texels.
    pub mask_texels: &'a [f32],
}

/// aokit's camera of an engine frame and the engine projection's planes.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct EngineCamera {
    /// The camera of aokit's full target (the engine's image plus the guard band).
    pub camera: Camera,
    /// The projection's near plane (view depth).
    pub near: f32,
    /// The projection's far plane (`f32::MAX` for an infinite projection).
    pub far: f32,
}

/// aokit's camera from an engine's `projection` and `view` for images of `size` texels, a guard
/// band of `guard` pixels and depth stored in `convention` (right-handed view space looking down −Z, clip depth `[0, 1]` unless `convention` says otherwise, a symmetric frustum, row 0 of the images at the top of the view).
///
/// A perspective projection maps view depth `z` to clip depth `d = −P₂₂ + P₃₂/z`
/// (`P₂₂ = projection.z_axis.z`, `P₃₂ = projection.w_axis.z`), so `d = 0` and `d = 1` fall at
/// `z = P₃₂/P₂₂` and `z = P₃₂/(1 + P₂₂)`: the near plane is the one that `convention` puts at
/// depth 0 (standard) or 1 (reversed). For [`DepthConvention::NegativeOneToOne`] the planes are
/// where `d = −1` and `1`: `z = P₃₂/(P₂₂ − 1)` and `z = P₃₂/(P₂₂ + 1)`. The field of view is
/// `tan(fov/2) = 1/P₀₀` and `1/|P₁₁|`
/// of the engine's image, widened by the guard band at the same focal length.
pub fn engine_camera(
    projection: Mat4,
    view: Mat4,
    size: UVec2,
    guard: u32,
    convention: DepthConvention,
) -> Result<EngineCamera, String> {
    let bad = |why: String| Err(why);
    let p = projection;
    if !p.is_finite() || !view.is_finite() {
        return bad("the matrices hold NaN or infinity".into());
    }
    if (p.z_axis.w + 1.0).abs() > 1e-6 || p.w_axis.w.abs() > 1e-6 {
        return bad(format!(
            "not a right-handed perspective projection (expected w = −z: P₂₃ = −1, P₃₃ = 0; got {}, {})",
            p.z_axis.w, p.w_axis.w
        ));
    }
    let (sx, sy) = (p.x_axis.x, p.y_axis.y.abs());
    if !(sx > 0.0 && sy > 0.0) {
        return bad(format!("the focal scales P₀₀ = {sx}, |P₁₁| = {sy} must be positive"));
    }
    // The frustum's off-centre terms move the image by P₂₀·w/2 pixels: more than half a pixel
    // is a shifted (or jittered) frustum that aokit's symmetric camera would misplace.
    if (p.z_axis.x * size.x as f32).abs() > 1.0 || (p.z_axis.y * size.y as f32).abs() > 1.0 {
        return bad(format!(
            "the frustum is off-centre by ({}, {}) pixels: pass the symmetric (unjittered) projection",
            0.5 * p.z_axis.x * size.x as f32,
            0.5 * p.z_axis.y * size.y as f32
        ));
    }
    let (p22, p32) = (p.z_axis.z, p.w_axis.z);
    let reversed_matrix = p22 > -0.5; // standard: P₂₂ ≤ −1 (≈ −f/(f − n)); reversed: P₂₂ ≥ 0
    // |P₂₂| below float noise of 0 is the infinite reversed projection.
    let p22 = if p22.abs() < 1e-7 { 0.0 } else { p22 };
    let (near, far) = if convention == DepthConvention::NegativeOneToOne {
        // z_ndc = −P₂₂ + P₃₂/z is −1 at the near plane and 1 at the far plane.
        if p22 >= -1.0 {
            return bad(format!(
                "P₂₂ = {p22}: a NegativeOneToOne projection has P₂₂ = −(f + n)/(f − n) < −1 (an infinite far plane is not supported)"
            ));
        }
        (p32 / (p22 - 1.0), p32 / (p22 + 1.0))
    } else if p22 == 0.0 {
        (p32, f32::MAX)
    } else if reversed_matrix {
        (p32 / (1.0 + p22), p32 / p22)
    } else if p22 == -1.0 {
        (-p32, f32::MAX)
    } else {
        (p32 / p22, p32 / (1.0 + p22))
    };
    if !(near > 0.0 && far > near) {
        return bad(format!("near {near}, far {far} from P₂₂ = {p22}, P₃₂ = {p32}: expected 0 < near < far"));
    }
    let matrix_says = match (reversed_matrix, far == f32::MAX) {
        // The matrix alone cannot tell [−1, 1] from [0, 1] clip depth: trust the frame.
        (false, false) if convention == DepthConvention::NegativeOneToOne => convention,
        (false, false) => DepthConvention::Standard,
        (true, false) => DepthConvention::Reversed,
        (true, true) => DepthConvention::ReversedInfinite,
        (false, true) if convention != DepthConvention::Linear => {
            return bad("standard depth with an infinite far plane is not supported: use reversed Z".into());
        }
        (false, true) => DepthConvention::Linear,
    };
    if convention != DepthConvention::Linear && convention != matrix_says {
        return bad(format!("the frame's depth is {convention:?} but the projection is {matrix_says:?}"));
    }
    let full = size + 2 * guard;
    let tan_inner = vec2(1.0 / sx, 1.0 / sy);
    let tan_half_fov = tan_inner * full.as_vec2() / size.as_vec2();
    let view_params = ViewParams { res: full.as_vec2(), tan_half_fov, near, far, guard, _pad: 0 };
    let camera = Camera { world_to_view: view, view_to_world: view.inverse(), view: view_params };
    Ok(EngineCamera { camera, near, far })
}

/// aokit's frame description for an engine frame, and the adapters' parameters that import its
/// images and export the AO: the camera from the matrices ([`engine_camera`]), the background
/// depth from the settings or the projection's far plane (`1e5 × near` for an infinite one),
/// the previous camera for the temporal reprojection.
pub fn engine_frame(
    settings: &AoSettings,
    size: UVec2,
    projection: Mat4,
    view: Mat4,
    convention: DepthConvention,
    frame_index: u32,
    previous_view: Option<Mat4>,
) -> Result<(FrameDesc, ImportParams), String> {
    let s = settings;
    let derived = engine_camera(projection, view, size, s.guard, convention)?;
    let mut camera = derived.camera;
    let infinite = derived.far == f32::MAX;
    camera.view.far = s.background_depth.unwrap_or(if infinite { derived.near * 1e5 } else { derived.far });
    let previous_camera = previous_view.map(|v| Camera { world_to_view: v, view_to_world: v.inverse(), ..camera });
    let desc = FrameDesc {
        frame_index,
        previous_camera,
        temporal: s.temporal,
        ..FrameDesc::new(camera, s.radius, s.exponent, s.thickness)
    };
    // The builder whose expressions the manifest publishes (`adapters.constants`).
    let engine = AdapterSettings { convention: convention.code(), near: derived.near, far: derived.far };
    Ok((desc, engine.params(&desc)))
}

/// A frame of `settings` at `size` (64×64 when `None`) seen by a nominal camera: which passes a
/// graph has depends on the settings and the size, not on the camera, so an executor checks a
/// technique against its device with this before the first frame.
pub fn probe_frame(settings: &AoSettings, size: Option<UVec2>) -> FrameDesc {
    let s = settings;
    let full = size.unwrap_or(UVec2::splat(64)) + 2 * s.guard;
    let view = ViewParams {
        res: full.as_vec2(),
        tan_half_fov: vec2(1.0, 1.0),
        near: 0.1,
        far: 100.0,
        guard: s.guard,
        _pad: 0,
    };
    let camera = Camera { world_to_view: Mat4::IDENTITY, view_to_world: Mat4::IDENTITY, view };
    FrameDesc { temporal: s.temporal, ..FrameDesc::new(camera, s.radius, s.exponent, s.thickness) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapters::linear_depth;
    use crate::glam::{Vec2, Vec3, Vec4};

    const SIZE: UVec2 = UVec2::new(640, 360);

    /// A Vulkan perspective projection written out (right-handed, looking down −Z, clip depth
    /// in [0, 1], `d = −P₂₂ + P₃₂/z`) that stores depth 0 at view depth `z_at_0` and 1 at
    /// `z_at_1` (either may be infinite), with vertical field of view `fov`.
    fn perspective(fov: f32, aspect: f32, z_at_0: f32, z_at_1: f32) -> Mat4 {
        let sy = 1.0 / (0.5 * fov).tan();
        // d(z) = a + b/z with d(z_at_0) = 0, d(z_at_1) = 1: b = z0·z1/(z0 − z1), a = −b/z0.
        let (p22, p32) = if z_at_0.is_infinite() {
            (0.0, z_at_1) // reversed infinite: d = n/z
        } else if z_at_1.is_infinite() {
            (-1.0, -z_at_0) // standard infinite: d = 1 − n/z
        } else {
            let b = z_at_0 * z_at_1 / (z_at_0 - z_at_1);
            (b / z_at_0, b)
        };
        Mat4::from_cols(
            Vec4::new(sy / aspect, 0.0, 0.0, 0.0),
            Vec4::new(0.0, sy, 0.0, 0.0),
            Vec4::new(0.0, 0.0, p22, -1.0),
            Vec4::new(0.0, 0.0, p32, 0.0),
        )
    }

    /// World → view of a camera at `eye` looking at `target` (right-handed, −Z forward).
    fn look_at(eye: Vec3, target: Vec3) -> Mat4 {
        let f = (target - eye).normalize();
        let r = f.cross(Vec3::Y).normalize();
        let u = r.cross(f);
        Mat4::from_cols(r.extend(0.0), u.extend(0.0), (-f).extend(0.0), eye.extend(1.0)).inverse()
    }

    /// Clip depth of view depth `z` through `p`.
    fn clip_depth(p: Mat4, z: f32) -> f32 {
        let c = p * Vec4::new(0.0, 0.0, -z, 1.0);
        c.z / c.w
    }

    #[test]
    fn every_convention_reads_back_the_view_depth_and_the_field_of_view() {
        let (fov, aspect, n, f) = (1.0f32, 640.0 / 360.0, 0.1, 50.0);
        let cases = [
            (perspective(fov, aspect, n, f), DepthConvention::Standard, f),
            (perspective(fov, aspect, f, n), DepthConvention::Reversed, f),
            (perspective(fov, aspect, f32::INFINITY, n), DepthConvention::ReversedInfinite, f32::MAX),
        ];
        for (p, convention, far) in cases {
            let e = engine_camera(p, Mat4::IDENTITY, SIZE, 0, convention).unwrap();
            assert!((e.near - n).abs() < 1e-6 * n, "{convention:?}: near {}", e.near);
            assert!(
                far == f32::MAX && e.far == far || (e.far - far).abs() < 1e-4 * far,
                "{convention:?}: far {}",
                e.far
            );
            assert!((e.camera.view.tan_half_fov.y - (0.5 * fov).tan()).abs() < 1e-6);
            assert!((e.camera.view.tan_half_fov.x - aspect * (0.5 * fov).tan()).abs() < 1e-5);
            // The adapter's inverse of the convention recovers the depth the matrix stored.
            for z in [0.2f32, 1.0, 7.5, 40.0] {
                let back = linear_depth(clip_depth(p, z), convention.code(), e.near, e.far);
                assert!((back - z).abs() < 2e-4 * z, "{convention:?}: z {z} read back as {back}");
            }
        }
        // OpenGL-style clip depth (gluPerspective's matrix: P₂₂ = (f + n)/(n − f),
        // P₃₂ = 2fn/(n − f)), stored as 0.5·z_ndc + 0.5.
        let mut gl = perspective(fov, aspect, n, f);
        (gl.z_axis.z, gl.w_axis.z) = ((f + n) / (n - f), 2.0 * f * n / (n - f));
        let e = engine_camera(gl, Mat4::IDENTITY, SIZE, 0, DepthConvention::NegativeOneToOne).unwrap();
        assert!((e.near - n).abs() < 1e-6 * n && (e.far - f).abs() < 1e-4 * f, "GL planes {} {}", e.near, e.far);
        for z in [0.2f32, 1.0, 7.5, 40.0] {
            let stored = 0.5 * clip_depth(gl, z) + 0.5;
            let back = linear_depth(stored, DepthConvention::NegativeOneToOne.code(), e.near, e.far);
            assert!((back - z).abs() < 2e-4 * z, "NegativeOneToOne: z {z} read back as {back}");
        }
        // The same matrix read as [0, 1] clip depth gives other planes: the convention matters.
        let as_vulkan = engine_camera(gl, Mat4::IDENTITY, SIZE, 0, DepthConvention::Standard).unwrap();
        assert!((as_vulkan.near - n).abs() > 0.5 * n, "near {} read as Standard", as_vulkan.near);
    }

    #[test]
    fn the_camera_projects_view_points_where_the_matrix_does() {
        let p = perspective(0.9, 640.0 / 360.0, f32::INFINITY, 0.05);
        let view = look_at(Vec3::new(1.0, 2.0, 3.0), Vec3::ZERO);
        for guard in [0, 32] {
            let e = engine_camera(p, view, SIZE, guard, DepthConvention::ReversedInfinite).unwrap();
            for x in [Vec3::new(0.3, -0.2, -2.0), Vec3::new(-1.0, 0.4, -5.0)] {
                let c = p * x.extend(1.0);
                let ndc = c.truncate() / c.w;
                // The matrix's NDC (y up here) as pixels of the engine image (row 0 at the top),
                // then shifted by the guard band into aokit's target.
                let pixel = Vec2::new(0.5 + 0.5 * ndc.x, 0.5 - 0.5 * ndc.y) * SIZE.as_vec2() + guard as f32;
                let ours = e.camera.view.view_to_uv(x) * e.camera.view.res;
                assert!((ours - pixel).length() < 1e-3, "guard {guard}: {ours} vs {pixel}");
            }
            assert_eq!(e.camera.world_to_view, view);
        }
    }

    #[test]
    fn unusable_matrices_are_refused_with_the_reason() {
        let p = perspective(1.0, 1.5, 0.1, 10.0);
        let err = |p, c| engine_camera(p, Mat4::IDENTITY, SIZE, 0, c).unwrap_err().to_string();
        assert!(err(p, DepthConvention::Reversed).contains("is Reversed but the projection is Standard"));
        let orthographic = Mat4::from_scale(Vec3::new(1.0, 1.0, -0.1));
        assert!(err(orthographic, DepthConvention::Standard).contains("perspective"));
        let mut jittered = p;
        jittered.z_axis.x = 4.0 / SIZE.x as f32;
        assert!(err(jittered, DepthConvention::Standard).contains("off-centre"));
        let mut subpixel = p;
        subpixel.z_axis.x = 0.5 / SIZE.x as f32;
        assert!(engine_camera(subpixel, Mat4::IDENTITY, SIZE, 0, DepthConvention::Standard).is_ok());
        assert!(err(perspective(1.0, 1.5, 0.1, f32::INFINITY), DepthConvention::Standard).contains("infinite"));
        assert!(err(Mat4::NAN, DepthConvention::Standard).contains("NaN"));
        assert!(err(perspective(1.0, 1.5, 10.0, 0.1), DepthConvention::NegativeOneToOne).contains("P₂₂"));
    }

    #[test]
    fn settings_out_of_range_are_refused() {
        let t = Technique::named("vao").unwrap();
        assert!(AoSettings::new(t.clone()).radius(0.0).check().is_err());
        assert!(AoSettings::new(t.clone()).exponent(f32::NAN).check().is_err());
        assert!(AoSettings::new(t.clone()).thickness(-1.0).check().is_err());
        assert!(AoSettings::new(t.clone()).guard(4096).check().is_err());
        assert!(AoSettings::new(t).check().is_ok());
    }
}
