//! The built-in scenes: real scenes pinned by package version and SHA-256 and fetched through the
//! ordinary package client (cargo), cached under the user's cache directory; the committed
//! Cornell box; and procedural scenes. Credits: `assets/CREDITS.md`.

use super::{Scene, SceneError, procedural};
use aokit_shaders::glam::{Vec3, vec3};
use sha2::{Digest, Sha256};
use std::path::{Path, PathBuf};
use std::process::Command;

/// A file inside a crate published on the registry, pinned by version and hash.
struct CrateFile {
    krate: &'static str,
    version: &'static str,
    path: &'static str,
    sha256: &'static str,
}

/// Where a built-in scene comes from.
enum Source {
    /// An OBJ inside a crate (optionally zstd-compressed, with an optional .mtl beside it).
    Crate {
        file: CrateFile,
        mtl: Option<&'static str>,
    },
    /// An OBJ committed under `assets/scenes/`.
    Committed {
        obj: &'static str,
        sha256: &'static str,
    },
    /// Files inside a Debian package, pinned by version (and the main file by hash), fetched
    /// with `apt-get download` and unpacked with `dpkg --fsys-tarfile | tar`.
    Debian {
        package: &'static str,
        version: &'static str,
        dir: &'static str,
        files: &'static [&'static str],
        sha256: &'static str,
    },
    Procedural(fn() -> Scene),
}

/// A camera that frames the interesting part of a built-in scene.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct CameraPreset {
    pub name: &'static str,
    pub eye: Vec3,
    pub target: Vec3,
    pub up: Vec3,
    /// Vertical field of view of the output image, degrees.
    pub fov_deg: f32,
}

/// A built-in scene: where it comes from, its cameras and its default AO radius.
pub struct BuiltinScene {
    pub name: &'static str,
    pub description: &'static str,
    source: Source,
    /// The first preset is the default.
    pub cameras: &'static [CameraPreset],
    /// Default world-space AO radius.
    pub radius: f32,
}

const UP: Vec3 = vec3(0.0, 1.0, 0.0);

/// Every built-in scene.
pub fn builtin_scenes() -> &'static [BuiltinScene] {
    &BUILTIN
}

static BUILTIN: [BuiltinScene; 5] = [
    BuiltinScene {
        name: "sponza",
        description: "Dabrovic Sponza atrium, 66,450 triangles (crate bvh 0.13.0, media/sponza.obj)",
        source: Source::Crate {
            file: CrateFile {
                krate: "bvh",
                version: "0.13.0",
                path: "media/sponza.obj",
                sha256: "f109270c87e563790153e557890c1029eea4fda4ce360b4164fa8682627bd90d",
            },
            mtl: None,
        },
        cameras: &[
            CameraPreset {
                name: "atrium",
                eye: vec3(-14.0, 2.5, 0.0),
                target: vec3(10.0, 5.0, 0.0),
                up: UP,
                fov_deg: 75.0,
            },
            CameraPreset {
                name: "gallery",
                eye: vec3(12.0, 7.5, 4.5),
                target: vec3(-8.0, 6.0, 4.5),
                up: UP,
                fov_deg: 70.0,
            },
        ],
        radius: 1.0,
    },
    BuiltinScene {
        name: "kitchen",
        description: "kitchen interior, 56,939 triangles (crate obvhs 0.4.0, assets/kitchen.obj.zst)",
        source: Source::Crate {
            file: CrateFile {
                krate: "obvhs",
                version: "0.4.0",
                path: "assets/kitchen.obj.zst",
                sha256: "b6c303004edf3621cf803294bb2b2fe8cc68ec8a1269aba7c198a2e86763d065",
            },
            mtl: Some("assets/kitchen.mtl"),
        },
        cameras: &[CameraPreset {
            name: "corner",
            eye: vec3(3.3, 1.6, 2.3),
            target: vec3(-1.5, 0.9, -2.0),
            up: UP,
            fov_deg: 60.0,
        }],
        radius: 0.25,
    },
    BuiltinScene {
        name: "cornell",
        description: "Cornell box, 34 triangles (Debian embree-tools 3.13.5, Apache-2.0; committed)",
        source: Source::Committed {
            obj: "cornell_box/cornell_box.obj",
            sha256: "1df799353b985e1862a590c6c37814227990e0338220e2e9a575fcd54031a667",
        },
        cameras: &[CameraPreset {
            name: "front",
            eye: vec3(278.0, 273.0, -800.0),
            target: vec3(278.0, 273.0, 0.0),
            up: UP,
            fov_deg: 39.3,
        }],
        radius: 60.0,
    },
    BuiltinScene {
        name: "oak",
        description: "oak tree with alpha-masked leaves, glTF, 555 triangles (opengameart.org \"old oak tree\" by Julius, GPL/CC-BY-SA-3.0; Debian castle-game-engine-doc, fetched with apt-get)",
        source: Source::Debian {
            package: "castle-game-engine-doc",
            version: "7.0~alpha.2+dfsg1-5",
            dir: "./usr/share/doc/castle-game-engine-doc/examples/terrain/data/oak_tree",
            files: &["oaktree.gltf", "oaktree.bin", "oakleaf_light.png", "oakbark.jpg"],
            sha256: "8e39bb0cd2ca9209798cd51176450ef3a853d48d8318a3cb9c21ecbeac1fdc0c",
        },
        cameras: &[CameraPreset {
            name: "crown",
            eye: vec3(0.0, 2.6, 5.5),
            target: vec3(0.0, 2.4, 0.0),
            up: UP,
            fov_deg: 50.0,
        }],
        radius: 0.15,
    },
    BuiltinScene {
        name: "tower",
        description: "procedural tower with a spiral staircase, open on one side (aokit)",
        source: Source::Procedural(procedural::spiral_tower),
        cameras: &[CameraPreset {
            name: "slot",
            eye: vec3(9.0, 4.0, 0.0),
            target: vec3(0.0, 3.5, 0.0),
            up: UP,
            fov_deg: 60.0,
        }],
        radius: 0.6,
    },
];

/// Look up a built-in scene by name.
pub fn find(name: &str) -> Option<&'static BuiltinScene> {
    BUILTIN.iter().find(|s| s.name == name)
}

impl BuiltinScene {
    /// Load the scene, fetching and caching it first if needed.
    pub fn load(&self) -> Result<Scene, SceneError> {
        let mut scene = match &self.source {
            Source::Procedural(make) => make().validated(Path::new(self.name))?,
            Source::Committed { obj, sha256 } => {
                let path = assets_dir().join("scenes").join(obj);
                check_sha256(self.name, &path, sha256)?;
                Scene::load(&path)?
            }
            Source::Crate { file, mtl } => Scene::load(&fetch(self.name, file, *mtl)?)?,
            Source::Debian { package, version, dir, files, sha256 } => {
                Scene::load(&fetch_debian(self.name, package, version, dir, files, sha256)?)?
            }
        };
        scene.name = self.name.to_string();
        Ok(scene)
    }

    /// A camera preset by name.
    pub fn camera(&self, name: &str) -> Option<&CameraPreset> {
        self.cameras.iter().find(|c| c.name == name)
    }
}

/// The repository's `assets/` directory.
pub fn assets_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("assets")
}

/// aokit's cache directory: `$AOKIT_CACHE`, else `$XDG_CACHE_HOME/aokit`, else `~/.cache/aokit`.
pub fn cache_dir() -> PathBuf {
    if let Some(dir) = std::env::var_os("AOKIT_CACHE") {
        return dir.into();
    }
    if let Some(dir) = std::env::var_os("XDG_CACHE_HOME") {
        return Path::new(&dir).join("aokit");
    }
    let home = std::env::var_os("HOME").unwrap_or_else(|| ".".into());
    Path::new(&home).join(".cache").join("aokit")
}

fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes).iter().map(|b| format!("{b:02x}")).collect()
}

fn check_sha256(scene: &str, path: &Path, expected: &str) -> Result<(), SceneError> {
    let bytes = std::fs::read(path).map_err(|source| SceneError::Io { path: path.to_path_buf(), source })?;
    let got = sha256_hex(&bytes);
    if got != expected {
        return Err(SceneError::Fetch {
            scene: scene.into(),
            problem: format!("{} has SHA-256 {got}, expected {expected}", path.display()),
        });
    }
    Ok(())
}

/// Fetch `file` (and its .mtl) with `cargo fetch` into the cache and return the OBJ path, with
/// zstd-compressed files decompressed beside it.
fn fetch(scene: &str, file: &CrateFile, mtl: Option<&str>) -> Result<PathBuf, SceneError> {
    // One fetch at a time in this process; files appear atomically (rename) for other processes.
    static FETCH: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _guard = FETCH.lock().unwrap_or_else(|e| e.into_inner());
    let fail = |problem: String| SceneError::Fetch { scene: scene.into(), problem };
    let dir = cache_dir().join("scenes").join(format!("{}-{}", file.krate, file.version));
    let base = Path::new(file.path).file_name().expect("pinned path has a file name");
    let cached = dir.join(base);
    let obj = match cached.to_string_lossy().strip_suffix(".zst") {
        Some(stem) => PathBuf::from(stem),
        None => cached.clone(),
    };
    if obj.exists() && check_sha256(scene, &cached, file.sha256).is_ok() {
        return Ok(obj);
    }
    let src = crate_source_dir(file).map_err(fail)?;
    std::fs::create_dir_all(&dir).map_err(|e| fail(format!("{}: {e}", dir.display())))?;
    let copy = |from: &str| {
        let bytes =
            std::fs::read(src.join(from)).map_err(|e| fail(format!("reading {from} in {}: {e}", src.display())))?;
        write_atomically(&dir.join(Path::new(from).file_name().expect("file name")), &bytes).map_err(fail)
    };
    copy(file.path)?;
    if let Some(mtl) = mtl {
        copy(mtl)?;
    }
    check_sha256(scene, &cached, file.sha256)?;
    if obj != cached {
        let compressed = std::fs::read(&cached).map_err(|e| fail(e.to_string()))?;
        let mut text = Vec::new();
        let mut decoder =
            ruzstd::decoding::StreamingDecoder::new(&compressed[..]).map_err(|e| fail(format!("zstd: {e}")))?;
        std::io::Read::read_to_end(&mut decoder, &mut text).map_err(|e| fail(format!("zstd: {e}")))?;
        write_atomically(&obj, &text).map_err(fail)?;
    }
    Ok(obj)
}

/// Fetch `files` from `dir` inside Debian package `package=version` into the cache (apt-get
/// download, dpkg --fsys-tarfile | tar) and return the first file's path.
fn fetch_debian(
    scene: &str,
    package: &str,
    version: &str,
    dir: &str,
    files: &[&str],
    sha256: &str,
) -> Result<PathBuf, SceneError> {
    static FETCH: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _guard = FETCH.lock().unwrap_or_else(|e| e.into_inner());
    let fail = |problem: String| SceneError::Fetch { scene: scene.into(), problem };
    let cache = cache_dir().join("scenes").join(format!("{package}-{version}"));
    let main = cache.join(files[0]);
    if files.iter().all(|f| cache.join(f).exists()) && check_sha256(scene, &main, sha256).is_ok() {
        return Ok(main);
    }
    let work = cache_dir().join("fetch").join(format!("{package}-{}", std::process::id()));
    std::fs::create_dir_all(&work).map_err(|e| fail(format!("{}: {e}", work.display())))?;
    let result = (|| -> Result<(), String> {
        let out = Command::new("apt-get")
            .args(["download", &format!("{package}={version}")])
            .current_dir(&work)
            .output()
            .map_err(|e| format!("running apt-get (a Debian system is needed for this scene): {e}"))?;
        if !out.status.success() {
            return Err(format!(
                "apt-get download {package}={version}: {}",
                String::from_utf8_lossy(&out.stderr).trim()
            ));
        }
        let deb = std::fs::read_dir(&work)
            .map_err(|e| e.to_string())?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .find(|p| p.extension().is_some_and(|x| x == "deb"))
            .ok_or("apt-get download left no .deb")?;
        let members: Vec<String> = files.iter().map(|f| format!("{dir}/{f}")).collect();
        let script = format!(
            "dpkg --fsys-tarfile '{}' | tar -x -C '{}' {}",
            deb.display(),
            work.display(),
            members.iter().map(|m| format!("'{m}'")).collect::<Vec<_>>().join(" ")
        );
        let out = Command::new("sh").args(["-c", &script]).output().map_err(|e| e.to_string())?;
        if !out.status.success() {
            return Err(format!("unpacking {}: {}", deb.display(), String::from_utf8_lossy(&out.stderr).trim()));
        }
        std::fs::create_dir_all(&cache).map_err(|e| e.to_string())?;
        for (f, m) in files.iter().zip(&members) {
            let bytes = std::fs::read(work.join(m)).map_err(|e| format!("{m}: {e}"))?;
            write_atomically(&cache.join(f), &bytes)?;
        }
        Ok(())
    })();
    let _ = std::fs::remove_dir_all(&work);
    result.map_err(fail)?;
    check_sha256(scene, &main, sha256)?;
    Ok(main)
}

/// Write through a uniquely named temporary file and rename, so readers never see a partial file.
fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), String> {
    crate::output::write_atomic_bytes(path, bytes).map_err(|e| e.to_string())
}

/// Download the crate with `cargo fetch` through a scratch manifest and return its unpacked
/// source directory (from `cargo metadata`).
fn crate_source_dir(file: &CrateFile) -> Result<PathBuf, String> {
    let project = cache_dir().join("fetch").join(format!("{}-{}", file.krate, file.version));
    std::fs::create_dir_all(project.join("src")).map_err(|e| e.to_string())?;
    let manifest = format!(
        "[package]\nname = \"aokit-scene-fetch\"\nversion = \"0.0.0\"\nedition = \"2021\"\n\n[workspace]\n\n[dependencies]\n{} = \"={}\"\n",
        file.krate, file.version
    );
    write_atomically(&project.join("Cargo.toml"), manifest.as_bytes())?;
    write_atomically(&project.join("src/lib.rs"), b"")?;
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let manifest_path = project.join("Cargo.toml");
    let run = |args: &[&str]| -> Result<Vec<u8>, String> {
        let out = Command::new(&cargo)
            .args(args)
            .arg("--manifest-path")
            .arg(&manifest_path)
            .output()
            .map_err(|e| format!("running `{cargo}`: {e}"))?;
        if !out.status.success() {
            return Err(format!("`cargo {}` failed: {}", args.join(" "), String::from_utf8_lossy(&out.stderr).trim()));
        }
        Ok(out.stdout)
    };
    run(&["fetch", "--quiet"])?;
    let metadata: serde_json::Value =
        serde_json::from_slice(&run(&["metadata", "--format-version", "1"])?).map_err(|e| e.to_string())?;
    let package = metadata["packages"]
        .as_array()
        .and_then(|ps| ps.iter().find(|p| p["name"] == file.krate && p["version"] == file.version))
        .ok_or_else(|| format!("cargo metadata does not list {} {}", file.krate, file.version))?;
    let manifest = package["manifest_path"].as_str().ok_or("no manifest_path in cargo metadata")?;
    Ok(Path::new(manifest).parent().ok_or("manifest has no parent")?.to_path_buf())
}
