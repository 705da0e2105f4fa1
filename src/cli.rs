//! Command-line pieces shared by the `aokit` tool and the examples (feature `cli`): the scene,
//! camera and AO-parameter flags and their resolution into a [`Frame`].

use crate::frame::{CameraChoice, Frame, FrameRequest};
use crate::scene::Scene;
use crate::scene::builtin::{self, BuiltinScene};
use aokit_shaders::glam::Vec3;
use std::path::Path;

/// The scene, the output size, the camera and the AO parameters (`aokit render`'s flags).
#[derive(clap::Args, Clone, Debug)]
#[command(allow_negative_numbers = true)]
pub struct SceneArgs {
    /// Built-in scene name (see `aokit scenes`) or a path to .obj/.gltf/.glb/.ply[.gz].
    #[arg(long)]
    pub scene: String,
    /// Output width in pixels (the guard band is added around it).
    #[arg(long, default_value_t = 1920)]
    pub width: u32,
    #[arg(long, default_value_t = 1080)]
    pub height: u32,
    /// Camera preset of a built-in scene, or `auto` to frame the scene's bounds.
    #[arg(long)]
    pub camera: Option<String>,
    /// Explicit camera position (x,y,z); needs --target.
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true, requires = "target")]
    pub eye: Option<Vec3>,
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true, requires = "eye")]
    pub target: Option<Vec3>,
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true, default_value = "0,1,0")]
    pub up: Vec3,
    /// Vertical field of view of the output image in degrees.
    #[arg(long)]
    pub fov: Option<f32>,
    /// World-space AO radius (default: per built-in scene, else 2 % of the bounding-box diagonal).
    #[arg(long)]
    pub radius: Option<f32>,
    /// AO exponent (spec default 2; the papers' figures use 4).
    #[arg(long, default_value_t = 2.0)]
    pub exponent: f32,
    /// Halo thickness τ (spec svao-raysd §4.3).
    #[arg(long, default_value_t = 0.0)]
    pub thickness: f32,
}

/// `x,y,z` as a vector.
pub fn parse_vec3(s: &str) -> Result<Vec3, String> {
    let parts: Vec<f32> =
        s.split(',').map(|p| p.trim().parse::<f32>().map_err(|e| format!("'{p}': {e}"))).collect::<Result<_, _>>()?;
    match parts[..] {
        [x, y, z] => Ok(Vec3::new(x, y, z)),
        _ => Err(format!("expected x,y,z, got '{s}'")),
    }
}

/// A built-in scene by name, or a scene file.
pub fn load_scene(spec: &str) -> Result<(Scene, Option<&'static BuiltinScene>), String> {
    if let Some(b) = builtin::find(spec) {
        return Ok((b.load().map_err(|e| e.to_string())?, Some(b)));
    }
    let path = Path::new(spec);
    if !path.exists() {
        let names: Vec<_> = builtin::builtin_scenes().iter().map(|s| s.name).collect();
        return Err(format!("'{spec}' is neither a built-in scene ({}) nor an existing file", names.join(", ")));
    }
    Ok((Scene::load(path).map_err(|e| e.to_string())?, None))
}

impl SceneArgs {
    /// Load the scene and resolve the camera and AO parameters with a guard band of `guard`
    /// pixels.
    pub fn resolve(&self, guard: u32) -> Result<(Scene, Frame), String> {
        let (scene, builtin) = load_scene(&self.scene)?;
        let fov_default = builtin.map_or(60.0, |b| b.cameras[0].fov_deg);
        let camera = match (&self.eye, &self.target, self.camera.as_deref()) {
            (Some(eye), Some(target), _) => CameraChoice::Explicit {
                eye: *eye,
                target: *target,
                up: self.up,
                fov_deg: self.fov.unwrap_or(fov_default),
            },
            (_, _, Some("auto")) => CameraChoice::Auto { fov_deg: self.fov.unwrap_or(60.0) },
            (_, _, None) if builtin.is_none() => CameraChoice::Auto { fov_deg: self.fov.unwrap_or(60.0) },
            (_, _, name) => CameraChoice::Preset { name: name.map(str::to_string), fov_deg: self.fov },
        };
        let request = FrameRequest {
            width: self.width,
            height: self.height,
            guard,
            camera,
            radius: self.radius,
            exponent: self.exponent,
            thickness: self.thickness,
        };
        let frame = Frame::resolve(&scene, builtin, &request).map_err(|e| e.to_string())?;
        Ok((scene, frame))
    }
}
