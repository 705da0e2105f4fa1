//! Scenes: triangle soups loaded from OBJ (+MTL), glTF 2.0 and PLY files, the built-in scenes
//! fetched through the package clients, and procedural test scenes.

pub mod builtin;
mod gltf_file;
mod obj_file;
mod ply_file;
pub mod procedural;

use aokit_shaders::common::alpha::AlphaMaskHeader;
use aokit_shaders::glam::{Vec2, Vec3};
use std::fmt;
use std::io::{self, Read};
use std::path::{Path, PathBuf};

/// Why a scene could not be loaded. Every variant names the file, and the message
/// ([`Display`](fmt::Display)) is always one line: line breaks and control characters in the
/// parsers' messages are folded, and overlong messages are shortened.
#[derive(Debug)]
pub enum SceneError {
    Io { path: PathBuf, source: std::io::Error },
    Malformed { path: PathBuf, format: &'static str, problem: String },
    UnknownFormat { path: PathBuf },
    Empty { path: PathBuf },
    NonFinite { path: PathBuf, index: usize, value: [f32; 3] },
    Fetch { scene: String, problem: String },
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = match self {
            SceneError::Io { path, source } => format!("{}: {source}", path.display()),
            SceneError::Malformed { path, format, problem } => {
                format!("{}: malformed {format} file: {problem}", path.display())
            }
            SceneError::UnknownFormat { path } => {
                format!("{}: unsupported scene format (expected .obj, .gltf, .glb, .ply or .ply.gz)", path.display())
            }
            SceneError::Empty { path } => format!("{}: the scene has no triangles", path.display()),
            SceneError::NonFinite { path, index, value } => {
                format!("{}: vertex {index} has a non-finite coordinate {value:?}", path.display())
            }
            SceneError::Fetch { scene, problem } => format!("cannot fetch built-in scene '{scene}': {problem}"),
        };
        f.write_str(&one_line(&text))
    }
}

impl std::error::Error for SceneError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            SceneError::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}

impl SceneError {
    fn malformed(path: &Path, format: &'static str, problem: impl ToString) -> Self {
        SceneError::Malformed { path: path.to_path_buf(), format, problem: problem.to_string() }
    }
}

/// The longest message [`SceneError`] prints, in characters.
const MAX_MESSAGE_CHARS: usize = 400;

/// `text` on one line: runs of whitespace that contain a line break become "; ", other control
/// characters are escaped, and the result is cut at [`MAX_MESSAGE_CHARS`].
fn one_line(text: &str) -> String {
    let mut out = String::with_capacity(text.len().min(MAX_MESSAGE_CHARS + 8));
    let mut chars = text.trim().chars().peekable();
    let mut count = 0;
    while let Some(c) = chars.next() {
        if count >= MAX_MESSAGE_CHARS {
            out.push('…');
            break;
        }
        if c.is_whitespace() {
            let mut line_break = c == '\n' || c == '\r';
            while let Some(&n) = chars.peek().filter(|n| n.is_whitespace()) {
                line_break |= n == '\n' || n == '\r';
                chars.next();
            }
            if line_break {
                // "problem.\n\tdetail" reads as "problem; detail".
                while out.ends_with(['.', ':', ';', ' ']) {
                    out.pop();
                }
                out.push_str("; ");
            } else {
                out.push(' ');
            }
        } else if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
        count += 1;
    }
    let kept = out.trim_end_matches([';', ' ']).len();
    out.truncate(kept);
    out
}

/// The scene file formats [`Scene::from_bytes`] parses.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum SceneFormat {
    /// Wavefront OBJ; `mtllib` files are read through the side-file reader.
    Obj,
    /// glTF 2.0: JSON (`.gltf`) or binary (`.glb`), told apart by the `glTF` magic.
    Gltf,
    /// PLY, ascii or binary.
    Ply,
    /// Gzip-compressed PLY.
    PlyGz,
}

impl SceneFormat {
    /// The format a file name's extension names (case-insensitive): `.obj`, `.gltf`, `.glb`,
    /// `.ply` or `.ply.gz`.
    pub fn from_path(path: &Path) -> Option<SceneFormat> {
        let name = path.file_name()?.to_string_lossy().to_ascii_lowercase();
        if name.ends_with(".obj") {
            Some(SceneFormat::Obj)
        } else if name.ends_with(".gltf") || name.ends_with(".glb") {
            Some(SceneFormat::Gltf)
        } else if name.ends_with(".ply") {
            Some(SceneFormat::Ply)
        } else if name.ends_with(".ply.gz") {
            Some(SceneFormat::PlyGz)
        } else {
            None
        }
    }
}

/// Reads a file a scene refers to (an OBJ's `mtllib`, a glTF's external buffers and images) by
/// the name written in the scene: [`Scene::load`] resolves it against the scene's folder.
pub type SideFiles<'a> = &'a dyn Fn(&Path) -> io::Result<Vec<u8>>;

/// A [`SideFiles`] reader for scenes held in memory that have no files beside them: every
/// referenced file is "not found" (a missing .mtl is not fatal; a missing glTF buffer is).
pub fn no_side_files(name: &Path) -> io::Result<Vec<u8>> {
    Err(io::Error::new(io::ErrorKind::NotFound, format!("{} is not available", name.display())))
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
    /// Load a scene file, choosing the parser by extension ([`SceneFormat::from_path`]).
    /// Files the scene refers to are read from its folder.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        let format = SceneFormat::from_path(path).ok_or_else(|| SceneError::UnknownFormat { path: path.into() })?;
        let bytes = read_file(path)?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Scene::from_bytes(format, path, &bytes, &|name: &Path| read_regular_file(&dir.join(name)))
    }

    /// Parse a scene held in memory: what [`Scene::load`] does after reading the file. `path`
    /// only names the scene in errors (and in [`Scene::name`]); the files the scene refers to are
    /// asked of `side_files` ([`no_side_files`] when there are none). Any byte sequence gives
    /// either a validated scene or an error: counts in headers are checked against the bytes
    /// present before anything is allocated for them.
    pub fn from_bytes(
        format: SceneFormat,
        path: &Path,
        bytes: &[u8],
        side_files: SideFiles,
    ) -> Result<Scene, SceneError> {
        let scene = match format {
            SceneFormat::Obj => obj_file::load_bytes(path, bytes, side_files)?,
            SceneFormat::Gltf => gltf_file::load_bytes(path, bytes, side_files)?,
            SceneFormat::Ply => ply_file::load_bytes(path, bytes)?,
            SceneFormat::PlyGz => ply_file::load_gz_bytes(path, bytes)?,
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
    /// the Ray-SD paper): the original stays where it is, the others are shifted by
    /// whole multiples of 1.25 × its extent, so a camera framing the original sees the same
    /// image as long as the copies stay out of view. `copies` must be a square (1, 4, 16, 64…).
    pub fn instanced_grid(&self, copies: u32) -> Result<Scene, String> {
        let side = (copies as f64).sqrt().round() as i32;
        if side < 1 || side as u64 * side as u64 != copies as u64 {
            return Err(format!("{copies} copies do not form a square grid (use 1, 4, 16, 64, …)"));
        }
        // Refuse before allocating what the machine cannot hold (an abort otherwise): the
        // triangles, their tables, the CPU BVH and a Vulkan BLAS take about this much each.
        const BYTES_PER_TRIANGLE: u64 = 400;
        let triangles = self.triangles.len() as u64 * copies as u64;
        let needed = triangles * BYTES_PER_TRIANGLE;
        if let Some(available) = available_memory()
            && needed > available
        {
            return Err(format!(
                "{copies} copies of {} ({triangles} triangles) need about {} MiB, more than the {} MiB of memory available",
                self.name,
                needed >> 20,
                available >> 20
            ));
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

    /// The per-corner tables the GPU's acceleration structure is built from (positions and uvs,
    /// three per triangle) with the packed alpha masks ([`Scene::alpha_masks`]).
    pub fn corner_tables(&self) -> CornerTables {
        CornerTables {
            positions: self.triangles.iter().flatten().map(|v| v.to_array()).collect(),
            uvs: self.triangle_uvs.iter().flatten().copied().collect(),
            masks: self.alpha_masks(),
        }
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

/// Read a scene file; directories, devices and pipes are refused (a `/dev/zero` would never end).
fn read_file(path: &Path) -> Result<Vec<u8>, SceneError> {
    read_regular_file(path).map_err(|source| SceneError::Io { path: path.to_path_buf(), source })
}

fn read_regular_file(path: &Path) -> io::Result<Vec<u8>> {
    // stat before opening: opening a named pipe would block.
    let meta = std::fs::metadata(path)?;
    if meta.is_dir() {
        return Err(io::Error::new(io::ErrorKind::IsADirectory, "is a directory, not a scene file"));
    }
    if !meta.is_file() {
        return Err(io::Error::new(io::ErrorKind::InvalidInput, "not a regular file"));
    }
    let mut file = std::fs::File::open(path)?;
    let mut bytes = Vec::with_capacity(meta.len().try_into().unwrap_or(0));
    file.read_to_end(&mut bytes)?;
    Ok(bytes)
}

/// `MemAvailable` of `/proc/meminfo` in bytes (Linux); `None` where it cannot be read.
fn available_memory() -> Option<u64> {
    let info = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = info.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// A scene's triangles as the Vulkan back-end's ray tracing takes them ([`Scene::corner_tables`]).
#[derive(Clone, Debug)]
pub struct CornerTables {
    /// World-space positions, three corners per triangle.
    pub positions: Vec<[f32; 3]>,
    /// Texture coordinates, three per triangle.
    pub uvs: Vec<Vec2>,
    /// The packed alpha masks: headers per material, texels.
    pub masks: (Vec<AlphaMaskHeader>, Vec<f32>),
}

impl CornerTables {
    /// The tables with the scene's per-triangle `materials` as the engine API's geometry.
    pub fn geometry<'a>(&'a self, materials: &'a [u32]) -> aokit_vulkan::SceneGeometry<'a> {
        aokit_vulkan::SceneGeometry {
            positions: &self.positions,
            uvs: &self.uvs,
            materials,
            mask_headers: &self.masks.0,
            mask_texels: &self.masks.1,
        }
    }
}
