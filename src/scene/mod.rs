//! Scenes: triangle soups loaded from OBJ (+MTL), glTF 2.0 and PLY files, the built-in scenes
//! fetched through the package clients, and procedural test scenes.

pub mod builtin;
mod gltf_file;
mod obj_file;
mod ply_file;
pub mod procedural;

use aokit_shaders::common::alpha::AlphaMaskHeader;
use aokit_shaders::glam::{Vec2, Vec3};
use std::path::{Path, PathBuf};

/// Why a scene could not be loaded. Every variant names the file.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    #[error("{path}: {source}")]
    Io { path: PathBuf, source: std::io::Error },
    #[error("{path}: malformed {format} file: {problem}")]
    Malformed { path: PathBuf, format: &'static str, problem: String },
    #[error("{path}: unsupported scene format (expected .obj, .gltf, .glb, .ply or .ply.gz)")]
    UnknownFormat { path: PathBuf },
    #[error("{path}: the scene has no triangles")]
    Empty { path: PathBuf },
    #[error("{path}: vertex {index} has a non-finite coordinate {value:?}")]
    NonFinite { path: PathBuf, index: usize, value: [f32; 3] },
    #[error("cannot fetch built-in scene '{scene}': {problem}")]
    Fetch { scene: String, problem: String },
}

impl SceneError {
    fn malformed(path: &Path, format: &'static str, problem: impl ToString) -> Self {
        SceneError::Malformed { path: path.to_path_buf(), format, problem: problem.to_string() }
    }
}

/// An alpha mask (glTF `alphaMode: MASK`): texels with alpha below `cutoff` are cut out.
#[derive(Clone, Debug, PartialEq)]
pub struct AlphaMask {
    pub width: u32,
    pub height: u32,
    /// Row-major alpha in [0, 1].
    pub alpha: Vec<f32>,
    pub cutoff: f32,
}

/// A material as far as AO cares: its name and optional alpha mask.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Material {
    pub name: String,
    pub alpha_mask: Option<AlphaMask>,
}

/// A world-space triangle soup.
#[derive(Clone, Debug, Default)]
pub struct Scene {
    pub name: String,
    pub triangles: Vec<[Vec3; 3]>,
    /// Per triangle: index into `materials`.
    pub triangle_materials: Vec<u32>,
    /// Per triangle: texture coordinates of its corners (zero where the file has none).
    pub triangle_uvs: Vec<[Vec2; 3]>,
    pub materials: Vec<Material>,
}

impl Scene {
    /// Load a scene file, choosing the parser by extension.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let lower = name.to_ascii_lowercase();
        let scene = if lower.ends_with(".obj") {
            obj_file::load(path)?
        } else if lower.ends_with(".gltf") || lower.ends_with(".glb") {
            gltf_file::load(path)?
        } else if lower.ends_with(".ply") || lower.ends_with(".ply.gz") {
            ply_file::load(path)?
        } else {
            return Err(SceneError::UnknownFormat { path: path.to_path_buf() });
        };
        scene.validated(path)
    }

    /// Reject empty scenes and non-finite vertices; fill missing per-triangle attributes.
    pub fn validated(mut self, path: &Path) -> Result<Scene, SceneError> {
        if self.triangles.is_empty() {
            return Err(SceneError::Empty { path: path.to_path_buf() });
        }
        for (i, t) in self.triangles.iter().enumerate() {
            for (k, v) in t.iter().enumerate() {
                if !v.is_finite() {
                    return Err(SceneError::NonFinite {
                        path: path.to_path_buf(),
                        index: 3 * i + k,
                        value: v.to_array(),
                    });
                }
            }
        }
        if self.materials.is_empty() {
            self.materials.push(Material::default());
        }
        self.triangle_materials.resize(self.triangles.len(), 0);
        let material_count = self.materials.len() as u32;
        for m in &mut self.triangle_materials {
            if *m >= material_count {
                *m = 0;
            }
        }
        self.triangle_uvs.resize(self.triangles.len(), [Vec2::ZERO; 3]);
        Ok(self)
    }

    /// Axis-aligned bounds `(min, max)`.
    /// `copies` instances of the scene on a square grid in the x–z plane (the scaling study of
    /// spec svao-raysd / issue 6): the original stays where it is, the others are shifted by
    /// whole multiples of 1.25 × its extent, so a camera framing the original sees the same
    /// image as long as the copies stay out of view. `copies` must be a square (1, 4, 16, 64…).
    pub fn instanced_grid(&self, copies: u32) -> Result<Scene, String> {
        let side = (copies as f64).sqrt().round() as i32;
        if side < 1 || (side * side) as u32 != copies {
            return Err(format!("{copies} copies do not form a square grid (use 1, 4, 16, 64, …)"));
        }
        let (lo, hi) = self.bounds();
        let step = (hi - lo) * 1.25;
        let mut out =
            Scene { name: format!("{}×{copies}", self.name), materials: self.materials.clone(), ..Default::default() };
        let start = -(side / 2);
        for i in start..start + side {
            for j in start..start + side {
                let offset = Vec3::new(i as f32 * step.x, 0.0, j as f32 * step.z);
                out.triangles.extend(self.triangles.iter().map(|t| t.map(|v| v + offset)));
                out.triangle_materials.extend_from_slice(&self.triangle_materials);
                out.triangle_uvs.extend_from_slice(&self.triangle_uvs);
            }
        }
        Ok(out)
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        let mut lo = Vec3::splat(f32::INFINITY);
        let mut hi = Vec3::splat(f32::NEG_INFINITY);
        for v in self.triangles.iter().flatten() {
            lo = lo.min(*v);
            hi = hi.max(*v);
        }
        (lo, hi)
    }

    /// Alpha masks packed for the kernels: one header per material (width 0 = opaque) and all
    /// mask texels concatenated. Never empty, so they bind as storage buffers.
    pub fn alpha_masks(&self) -> (Vec<AlphaMaskHeader>, Vec<f32>) {
        let mut texels = Vec::new();
        let mut headers: Vec<AlphaMaskHeader> = self
            .materials
            .iter()
            .map(|m| match &m.alpha_mask {
                Some(mask) => {
                    let header = AlphaMaskHeader {
                        offset: texels.len() as u32,
                        width: mask.width,
                        height: mask.height,
                        cutoff: mask.cutoff,
                    };
                    texels.extend_from_slice(&mask.alpha);
                    header
                }
                None => AlphaMaskHeader::default(),
            })
            .collect();
        if headers.is_empty() {
            headers.push(AlphaMaskHeader::default());
        }
        if texels.is_empty() {
            texels.push(1.0);
        }
        (headers, texels)
    }

    /// World-space unit face normals `normalize((v1 − v0) × (v2 − v0))`; zero for degenerate
    /// triangles.
    pub fn face_normals(&self) -> Vec<Vec3> {
        self.triangles.iter().map(|t| (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero()).collect()
    }
}

fn read_file(path: &Path) -> Result<Vec<u8>, SceneError> {
    std::fs::read(path).map_err(|source| SceneError::Io { path: path.to_path_buf(), source })
}
