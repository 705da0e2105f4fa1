//! Resolving what the user asked for — camera, image size, guard band, AO radius — into the
//! kernels' parameter structs.

use crate::scene::Scene;
use crate::scene::builtin::BuiltinScene;
use aokit_shaders::blur::BlurParams;
use aokit_shaders::common::camera::Camera;
use aokit_shaders::gbuffer::RasterParams;
use aokit_shaders::glam::{UVec2, Vec3, uvec2, vec3};
use aokit_shaders::graph::FrameDesc;
use aokit_shaders::vao::VaoParams;

/// How the camera is chosen.
#[derive(Clone, Debug, PartialEq)]
pub enum CameraChoice {
    /// A built-in scene's preset (`name: None`: its first), optionally with another field of view.
    Preset {
        name: Option<String>,
        fov_deg: Option<f32>,
    },
    /// Frame the scene's bounding box.
    Auto {
        fov_deg: f32,
    },
    Explicit {
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        fov_deg: f32,
    },
}

/// Everything a render needs besides the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameRequest {
    /// Output (inner) image size.
    pub width: u32,
    pub height: u32,
    /// G-buffer guard band in pixels (spec svao-raysd §1: 64).
    pub guard: u32,
    pub camera: CameraChoice,
    /// World-space AO radius; `None`: the scene's default.
    pub radius: Option<f32>,
    pub exponent: f32,
    pub thickness: f32,
}

/// The resolved frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub camera: Camera,
    pub eye: Vec3,
    pub target: Vec3,
    pub up: Vec3,
    pub fov_deg: f32,
    pub radius: f32,
    pub exponent: f32,
    pub thickness: f32,
    pub inner: UVec2,
    /// The frame's place in a sequence (`aokit::path`): its index (the techniques' noise), the
    /// previous frame's camera and the temporal accumulation ([`FrameDesc`]'s fields of the
    /// same names). A single frame: 0, `None`, `None`.
    pub frame_index: u32,
    pub previous_camera: Option<Camera>,
    pub temporal: Option<aokit_shaders::temporal::settings::TemporalSettings>,
}

/// Why a frame request is unusable.
#[derive(Debug, thiserror::Error)]
pub enum FrameError {
    #[error("image size must be at least 1×1, got {0}×{1}")]
    ZeroSize(u32, u32),
    #[error("image size {0}×{1} plus guard band {2} exceeds 16384 pixels per side")]
    TooLarge(u32, u32, u32),
    #[error("{0} must be finite and positive, got {1}")]
    NotPositive(&'static str, f32),
    #[error("field of view must be in (0°, 180°), got {0}°")]
    Fov(f32),
    #[error("eye and target coincide, or up is parallel to the view direction")]
    DegenerateCamera,
    #[error("scene '{scene}' has no camera preset '{name}' (presets: {presets})")]
    UnknownPreset { scene: String, name: String, presets: String },
    #[error("camera presets exist only for built-in scenes; use --camera auto or --eye/--target")]
    NoPresets,
}

/// Fraction of the bounding-box diagonal used as the AO radius of scenes without a default.
pub const DEFAULT_RADIUS_FRACTION: f32 = 0.02;

/// Camera `auto`: look at the bounding-box centre from the (+x, +y, +z) diagonal, from the
/// smallest distance at which all eight corners of the box project inside the image, so the
/// geometry fills it.
pub fn auto_camera(bounds: (Vec3, Vec3), fov_deg: f32, aspect: f32) -> (Vec3, Vec3) {
    let center = 0.5 * (bounds.0 + bounds.1);
    let back = vec3(1.0, 0.6, 1.0).normalize(); // from the centre towards the eye
    let right = Vec3::Y.cross(back).normalize();
    let up = back.cross(right);
    let ty = (0.5 * fov_deg.to_radians()).tan();
    let tx = ty * aspect;
    let mut distance = 0.0f32;
    for i in 0..8 {
        let corner = vec3(
            if i & 1 == 0 { bounds.0.x } else { bounds.1.x },
            if i & 2 == 0 { bounds.0.y } else { bounds.1.y },
            if i & 4 == 0 { bounds.0.z } else { bounds.1.z },
        ) - center;
        // The corner sits at view depth `distance − corner·back`; it is inside the frustum when
        // its lateral offsets are within depth·tan of the half angles.
        let toward = corner.dot(back);
        distance = distance.max(toward + corner.dot(right).abs() / tx).max(toward + corner.dot(up).abs() / ty);
    }
    let distance = distance.max(1e-3 * (bounds.1 - bounds.0).length().max(f32::MIN_POSITIVE));
    (center + back * distance, center)
}

impl Frame {
    /// Resolve a request against a scene (and its built-in description, if any).
    pub fn resolve(scene: &Scene, builtin: Option<&BuiltinScene>, req: &FrameRequest) -> Result<Frame, FrameError> {
        if req.width == 0 || req.height == 0 {
            return Err(FrameError::ZeroSize(req.width, req.height));
        }
        // In u64: a guard band near u32::MAX must not wrap past the check.
        if req.width.max(req.height) as u64 + 2 * req.guard as u64 > 16384 {
            return Err(FrameError::TooLarge(req.width, req.height, req.guard));
        }
        let bounds = scene.bounds();
        let diagonal = (bounds.1 - bounds.0).length().max(f32::MIN_POSITIVE);
        let aspect = req.width as f32 / req.height as f32;
        let up_y = vec3(0.0, 1.0, 0.0);
        let (eye, target, up, fov_deg) = match &req.camera {
            CameraChoice::Explicit { eye, target, up, fov_deg } => (*eye, *target, *up, *fov_deg),
            CameraChoice::Auto { fov_deg } => {
                let (eye, target) = auto_camera(bounds, *fov_deg, aspect);
                (eye, target, up_y, *fov_deg)
            }
            CameraChoice::Preset { name, fov_deg } => {
                let Some(b) = builtin else { return Err(FrameError::NoPresets) };
                let preset = match name {
                    None => &b.cameras[0],
                    Some(n) => b.camera(n).ok_or_else(|| FrameError::UnknownPreset {
                        scene: b.name.into(),
                        name: n.clone(),
                        presets: b.cameras.iter().map(|c| c.name).collect::<Vec<_>>().join(", "),
                    })?,
                };
                (preset.eye, preset.target, preset.up, fov_deg.unwrap_or(preset.fov_deg))
            }
        };
        if !(fov_deg > 0.0 && fov_deg < 180.0) {
            return Err(FrameError::Fov(fov_deg));
        }
        let forward = target - eye;
        if !eye.is_finite()
            || !target.is_finite()
            || forward.length() == 0.0
            || forward.cross(up).length() <= 1e-6 * forward.length() * up.length()
        {
            return Err(FrameError::DegenerateCamera);
        }
        let radius = req.radius.or(builtin.map(|b| b.radius)).unwrap_or(DEFAULT_RADIUS_FRACTION * diagonal);
        for (what, v) in [("AO radius", radius), ("exponent", req.exponent)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(FrameError::NotPositive(what, v));
            }
        }
        if !(req.thickness.is_finite() && req.thickness >= 0.0) {
            return Err(FrameError::NotPositive("thickness", req.thickness));
        }
        // Far beyond anything visible: background depth = far marks "no surface".
        let center = 0.5 * (bounds.0 + bounds.1);
        let far = 2.0 * ((eye - center).length() + diagonal);
        let near = 1e-4 * far;
        let inner = uvec2(req.width, req.height);
        let camera = Camera::look_at(eye, target, up, fov_deg.to_radians(), inner, req.guard, near, far);
        Ok(Frame {
            camera,
            eye,
            target,
            up,
            fov_deg,
            radius,
            exponent: req.exponent,
            thickness: req.thickness,
            inner,
            frame_index: 0,
            previous_camera: None,
            temporal: None,
        })
    }

    /// What the techniques' graphs are built from.
    pub fn desc(&self) -> FrameDesc {
        FrameDesc {
            frame_index: self.frame_index,
            previous_camera: self.previous_camera,
            temporal: self.temporal,
            ..FrameDesc::new(self.camera, self.radius, self.exponent, self.thickness)
        }
    }

    /// Push constants of the VAO pass (spec svao-raysd §2 defaults: 512 px screen clamp).
    pub fn vao_params(&self) -> VaoParams {
        aokit_shaders::vao::settings::vao_params(&self.desc())
    }

    /// Push constants of the horizontal blur (spec svao-raysd §12: sharpness 16).
    pub fn blur_params(&self) -> BlurParams {
        aokit_shaders::blur::graph::blur_params(&self.desc(), uvec2(1, 0))
    }

    /// Push constants of the raster G-buffer pass; `peel_separation`: the minimum distance of
    /// the depth-peeled second layer beyond the first (peeling passes only).
    pub fn raster_params(&self, peel_separation: f32) -> RasterParams {
        RasterParams {
            world_to_view: self.camera.world_to_view,
            view: self.camera.view,
            peel_separation,
            _pad0: 0,
            _pad1: 0,
            _pad2: 0,
        }
    }

    /// One-line JSON description printed by `aokit render`.
    pub fn describe(&self) -> serde_json::Value {
        let v = |x: Vec3| [x.x, x.y, x.z];
        let full = self.camera.view.size();
        serde_json::json!({
            "camera": {"eye": v(self.eye), "target": v(self.target), "up": v(self.up), "fov_y_deg": self.fov_deg,
                       "fov_y": self.fov_deg.to_radians(), "near": self.camera.view.near, "far": self.camera.view.far},
            "radius": self.radius,
            "exponent": self.exponent,
            "thickness": self.thickness,
            "image": [self.inner.x, self.inner.y],
            "guard_band": self.camera.view.guard,
            "target_size": [full.x, full.y],
        })
    }
}
