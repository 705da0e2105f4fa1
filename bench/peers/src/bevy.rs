//! `aokit-peers bevy`: aokit's vbao against Bevy 0.20's visibility-bitmask SSAO, both as WGSL
//! through wgpu on one adapter, on one frame (cpu-sim's depth and normals), at one sample count.
//!
//! Bevy's side runs Bevy's own shaders: `bevy_pbr`'s `src/ssao/preprocess_depth.wesl`,
//! `ssao.wesl` and `spatial_denoise.wesl` with what they import from `bevy_render` (`View`,
//! `Globals`, `maths`). Nothing of Bevy is in this repository: the sources are read at run time
//! from the cargo registry, where `cargo fetch --manifest-path bench/peers/bevy/Cargo.toml` puts
//! them and `cargo metadata` finds them (or from `--bevy-src DIR`). [`wesl`] flattens them into
//! plain WGSL as Bevy's shader cache would for this adapter (WESL imports, `@if` conditions on
//! Bevy's shader defs, the `constants` module of its integer defs), and the result is written to
//! a scratch directory only. The bindings mirror Bevy's `SsaoPipelines` (`bevy_pbr/src/ssao/mod.rs`):
//! its bind-group layouts, samplers, texture formats (`R16Float` working depth and AO where the
//! adapter can store to it, as Bevy decides), the Hilbert-index noise LUT, its dispatch sizes.
//! Its inputs are what its prepass would leave: reversed-Z depth of an infinite perspective
//! (`Depth32Float`, ndc = near / view z) and world normals as `n·0.5 + 0.5` in `Rgb10a2Unorm`,
//! with the view at the world origin (world = view space, Bevy's −z forward).
//!
//! aokit's side runs the generated WGSL of `assets/wgsl/` over the Rust graph of
//! `vbao:preset=<the same preset>` (XeGTAO's slices × steps per side equal Bevy's slices ×
//! samples per slice side), binding as `tests/wgsl_wgpu.rs` does: one storage buffer per graph
//! resource, the push constants as a uniform buffer after the last binding.
//!
//! Every dispatch is its own compute pass with GPU timestamps. Rows: the depth MIP chain
//! (aokit's two `gtao_prefilter` dispatches against Bevy's one `preprocess_depth`), the main
//! pass (`vbao_main` against `ssao`), the denoiser (`gtao_denoise` against `spatial_denoise`),
//! and their total.

use crate::common::{self, FrameArgs, Row};
use aokit::technique::Technique;
use aokit_cpu::GBufferImage;
use aokit_shaders::graph::{Graph, Init, PassKind, inputs};
use aokit_shaders::vbao::settings::VbaoSettings;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use wgpu::util::DeviceExt;

/// The Bevy minor version whose shaders this comparison reads (and `bench/peers/bevy/Cargo.toml`
/// pins).
const BEVY_VERSION: &str = "0.20";

/// `aokit-peers bevy`.
#[derive(clap::Args)]
pub struct BevyArgs {
    #[command(flatten)]
    pub frame: FrameArgs,
    /// Quality preset of both sides (slices × samples per slice side): low 1×2, medium 2×2,
    /// high 3×3, ultra 9×3 (Bevy's `ScreenSpaceAmbientOcclusionQualityLevel`, aokit's
    /// `vbao:preset=`).
    #[arg(long, default_value = "high", value_parser = ["low", "medium", "high", "ultra"])]
    pub preset: String,
    /// A directory holding the crate sources `bevy_pbr-0.20.*` and `bevy_render-0.20.*` (e.g. the
    /// cargo registry's `src/index.crates.io-…`). Default: where `cargo metadata` finds them
    /// after `cargo fetch --manifest-path bench/peers/bevy/Cargo.toml`.
    #[arg(long)]
    pub bevy_src: Option<PathBuf>,
    /// Where the flattened Bevy WGSL is written [the temp dir's `aokit-peers-bevy`].
    #[arg(long)]
    pub wgsl_out: Option<PathBuf>,
    /// The near plane of Bevy's camera (its infinite reversed-Z depth is near / view depth; Bevy
    /// biases that depth by 1e-5, so the near plane shifts its result) [Bevy's
    /// `PerspectiveProjection` default, 0.1].
    #[arg(long, default_value_t = 0.1)]
    pub bevy_near: f32,
    /// More of aokit's vbao settings after the preset, as `key=value[:key=value…]` (e.g.
    /// `gate=off`); slices and steps must stay the preset's.
    #[arg(long, value_name = "SETTINGS")]
    pub vbao: Option<String>,
}

/// `(slices, samples per slice side)` of a preset, Bevy's `sample_counts()` and XeGTAO's.
fn preset_counts(preset: &str) -> Result<(u32, u32), String> {
    match preset {
        "low" => Ok((1, 2)),
        "medium" => Ok((2, 2)),
        "high" => Ok((3, 3)),
        "ultra" => Ok((9, 3)),
        _ => Err(format!("--preset {preset}: expected low, medium, high or ultra")),
    }
}

/// Run the comparison and print (and with `--json`, write) the report.
pub fn run(args: BevyArgs) -> Result<(), String> {
    let (slices, steps) = preset_counts(&args.preset)?;
    if !(args.bevy_near.is_finite() && args.bevy_near > 0.0) {
        return Err(format!("--bevy-near {}: must be positive", args.bevy_near));
    }
    let sources = bevy_sources(args.bevy_src.as_deref())?;
    eprintln!("Bevy sources: {} and {}", sources.pbr.display(), sources.render.display());
    let (_scene, frame, gbuffer) = common::frame_and_gbuffer(&args.frame)?;
    let gpu = Gpu::new()?;
    eprintln!("adapter: {}", gpu.name);

    // aokit: vbao at the preset, its graph for the frame.
    let spec = match &args.vbao {
        Some(more) => format!("vbao:preset={}:{more}", args.preset),
        None => format!("vbao:preset={}", args.preset),
    };
    let technique = Technique::parse(&spec).map_err(|e| format!("--vbao: {e}"))?;
    let settings = *technique.settings::<VbaoSettings>().ok_or("vbao's settings are not VbaoSettings")?;
    if (settings.xegtao.slices, settings.xegtao.steps) != (slices, steps) {
        return Err(format!(
            "vbao's preset {} is {}×{}, Bevy's {slices}×{steps}",
            args.preset, settings.xegtao.slices, settings.xegtao.steps
        ));
    }
    let desc = frame.desc();
    let params = settings.params(&desc);
    let graph = technique.graph(&desc)?;
    let aokit = AokitSide::new(&gpu, &graph, &gbuffer)?;

    // Bevy: the same radius (XeGTAO's effective radius, Bevy's default 0.5·1.457 at radius 0.5)
    // and thickness (aokit's T, Bevy's 0.25 at radius 0.5 scaled alike).
    let bevy_settings = BevySettings {
        slices,
        samples_per_slice_side: steps,
        radius: params.gtao.effective_radius(),
        thickness: params.thickness,
        near: args.bevy_near,
    };
    let wgsl_dir = args.wgsl_out.clone().unwrap_or_else(|| std::env::temp_dir().join("aokit-peers-bevy"));
    let bevy = BevySide::new(&gpu, &sources, &bevy_settings, &frame, &gbuffer, &wgsl_dir)?;
    eprintln!("Bevy's flattened WGSL: {}", wgsl_dir.display());

    // Timing: each iteration runs both sides, alternating which goes first.
    let names = ["prefilter (depth MIP chain)", "main", "denoise", "total"];
    let mut rows: Vec<Row> =
        names.iter().map(|n| Row { name: n.to_string(), aokit_ms: Vec::new(), peer_ms: Vec::new() }).collect();
    let total = args.frame.warmup + args.frame.iterations;
    for it in 0..total {
        let run_aokit = || -> Result<[f64; 4], String> {
            let ms = aokit.timer.run(&gpu, &aokit.dispatches)?;
            let sum = |entry: &str| {
                aokit.dispatches.iter().zip(&ms).filter(|(d, _)| d.label == entry).map(|(_, t)| t).sum::<f64>()
            };
            Ok([sum("gtao_prefilter"), sum("vbao_main"), sum("gtao_denoise"), ms.iter().sum()])
        };
        let run_bevy = || -> Result<[f64; 4], String> {
            let ms = bevy.timer.run(&gpu, &bevy.dispatches)?;
            Ok([ms[0], ms[1], ms[2], ms.iter().sum()])
        };
        let (a, b) = if it % 2 == 0 {
            let a = run_aokit()?;
            (a, run_bevy()?)
        } else {
            let b = run_bevy()?;
            (run_aokit()?, b)
        };
        if it >= args.frame.warmup {
            for (k, row) in rows.iter_mut().enumerate() {
                row.aokit_ms.push(a[k]);
                row.peer_ms.push(b[k]);
            }
        }
        eprintln!(
            "iteration {}/{total}{}: aokit {:.3} ms, Bevy {:.3} ms (main {:.3} / {:.3})",
            it + 1,
            if it < args.frame.warmup { " (warm-up)" } else { "" },
            a[3],
            b[3],
            a[1],
            b[1]
        );
    }

    // The images: aokit's main-pass terms as visibility and its final AO; Bevy's noisy and
    // denoised AO.
    let view = frame.camera.view;
    let n = (gbuffer.width * gbuffer.height) as usize;
    let keep: Vec<bool> = gbuffer.depth.iter().map(|&z| z.is_finite() && z < view.far).collect();
    let aokit_final = bytemuck::cast_slice::<u8, f32>(&gpu.read_buffer(&aokit.buffers[graph.output])?).to_vec();
    let aokit_main: Vec<f32> = bytemuck::cast_slice::<u8, u32>(&gpu.read_buffer(&aokit.buffers[aokit.terms])?)
        .iter()
        .map(|&t| (t as f32 * 1.5 / 255.0).min(1.0))
        .collect();
    let bevy_main = gpu.read_r_texture(&bevy.noisy, bevy.format)?;
    let bevy_final = gpu.read_r_texture(&bevy.denoised, bevy.format)?;
    for (what, v) in [("aokit final", &aokit_final), ("aokit main", &aokit_main), ("Bevy main", &bevy_main)] {
        if v.len() != n {
            return Err(format!("{what}: {} pixels where the frame has {n}", v.len()));
        }
    }
    let stats = |v: &[f32]| AoStats::of(v, &keep);
    let (sa_main, sa_final, sb_main, sb_final) =
        (stats(&aokit_main), stats(&aokit_final), stats(&bevy_main), stats(&bevy_final));
    for (what, s) in [("Bevy's main pass", &sb_main), ("Bevy's denoised", &sb_final)] {
        s.check(what)?;
    }
    for (what, s) in [("aokit's main pass", &sa_main), ("aokit's final", &sa_final)] {
        if s.check(what).is_err() {
            eprintln!("warning: {what} AO looks degenerate: {}", s.json());
        }
    }
    if let Some(dir) = &args.frame.images {
        // The final AO as aokit.png and peer.png, the main passes' beside them.
        common::write_images(dir, gbuffer.width, gbuffer.height, &aokit_final, &bevy_final)?;
        for (file, v) in [("aokit_main.png", &aokit_main), ("peer_main.png", &bevy_main)] {
            let bytes: Vec<u8> = v.iter().map(|x| (x.clamp(0.0, 1.0) * 255.0 + 0.5) as u8).collect();
            let path = dir.join(file);
            image::save_buffer(&path, &bytes, gbuffer.width, gbuffer.height, image::ExtendedColorType::L8)
                .map_err(|e| format!("{}: {e}", path.display()))?;
        }
        eprintln!("images: {}", dir.display());
    }
    let keep_px = |i: usize| keep[i];
    let tolerance = 1.0 / 255.0;
    let agreement = serde_json::json!({
        "final": common::agreement(&aokit_final, &bevy_final, keep_px, tolerance),
        "main": common::agreement(&aokit_main, &bevy_main, keep_px, tolerance),
    });
    let count = |entry: &str| aokit.dispatches.iter().filter(|d| d.label == entry).count();
    let report = serde_json::json!({
        "peer": format!("bevy_pbr {} ssao (visibility bitmask)", sources.version),
        "device": gpu.name,
        "scene": args.frame.scene,
        "width": gbuffer.width,
        "height": gbuffer.height,
        "iterations": args.frame.iterations,
        "warmup": args.frame.warmup,
        "samples": {"slices": slices, "steps_per_side": steps},
        "aokit": {
            "technique": spec,
            "settings": serde_json::from_str::<serde_json::Value>(&technique.json()).unwrap_or_default(),
            "dispatches": {"gtao_prefilter": count("gtao_prefilter"), "vbao_main": count("vbao_main"),
                           "gtao_denoise": count("gtao_denoise")},
        },
        "bevy": {
            "quality_level": args.preset,
            "slice_count": slices,
            "samples_per_slice_side": steps,
            "radius": bevy_settings.radius,
            "constant_object_thickness": bevy_settings.thickness,
            "near": bevy_settings.near,
            "working_format": format!("{:?}", bevy.format),
            "shader_defs": bevy.defs,
            "wgsl": wgsl_dir.display().to_string(),
            "sources": [sources.pbr.display().to_string(), sources.render.display().to_string()],
        },
        "passes": rows.iter().map(Row::json).collect::<Vec<_>>(),
        "ao": {
            "aokit_main": sa_main.json(), "aokit_final": sa_final.json(),
            "bevy_main": sb_main.json(), "bevy_final": sb_final.json(),
        },
        "agreement": agreement,
        "note": "Report only: the algorithms differ (aokit's gate at the effective radius, its sector rule and \
                 noise, XeGTAO's 5-level prefilter and edge-aware denoiser, against Bevy's Hilbert/R2 noise, no \
                 gate, its weighted MIP chain and 3×3 bilateral filter), so the images do not agree pixel for \
                 pixel. `final` compares aokit's denoised output with Bevy's spatially denoised one, `main` \
                 aokit's main-pass terms (×1.5/255) with Bevy's noisy AO, over the pixels with geometry. Bevy's \
                 shaders run through wgpu 30 here, as in Bevy 0.20.",
    });
    common::finish(report, args.frame.json.as_ref())
}

// ---------------------------------------------------------------------------------------------
// Bevy's sources
// ---------------------------------------------------------------------------------------------

/// Bevy's crate sources: the roots of `bevy_pbr` and `bevy_render` and `bevy_pbr`'s version.
struct BevySources {
    pbr: PathBuf,
    render: PathBuf,
    version: String,
}

/// Bevy's sources in `dir` (the newest `0.20.x` of each crate there) or, without it, where
/// `cargo metadata` resolves `bench/peers/bevy/Cargo.toml` (offline: `cargo fetch` first).
fn bevy_sources(dir: Option<&Path>) -> Result<BevySources, String> {
    let crates: HashMap<String, (PathBuf, String)> = match dir {
        Some(dir) => {
            let entries = std::fs::read_dir(dir).map_err(|e| format!("--bevy-src {}: {e}", dir.display()))?;
            let mut newest: HashMap<String, (u64, PathBuf, String)> = HashMap::new();
            for entry in entries.flatten() {
                let file = entry.file_name().to_string_lossy().to_string();
                for name in ["bevy_pbr", "bevy_render"] {
                    let prefix = format!("{name}-{BEVY_VERSION}.");
                    let Some(patch) = file.strip_prefix(&prefix).and_then(|p| p.parse::<u64>().ok()) else { continue };
                    if newest.get(name).is_none_or(|(p, _, _)| patch > *p) {
                        let version = format!("{BEVY_VERSION}.{patch}");
                        newest.insert(name.to_string(), (patch, entry.path(), version));
                    }
                }
            }
            newest.into_iter().map(|(k, (_, path, version))| (k, (path, version))).collect()
        }
        None => {
            let manifest = Path::new(env!("CARGO_MANIFEST_DIR")).join("bevy/Cargo.toml");
            let output = std::process::Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
                .args(["metadata", "--format-version", "1", "--offline", "--manifest-path"])
                .arg(&manifest)
                .output()
                .map_err(|e| {
                    format!("cannot run cargo metadata to locate Bevy's sources ({e}); pass --bevy-src DIR")
                })?;
            if !output.status.success() {
                let why = String::from_utf8_lossy(&output.stderr);
                let why = why.lines().find(|l| l.starts_with("error")).unwrap_or("cargo metadata failed").to_string();
                return Err(format!(
                    "Bevy's sources are not in the cargo registry ({why}): run `cargo fetch --manifest-path {}` or \
                     pass --bevy-src DIR",
                    manifest.display()
                ));
            }
            let meta: serde_json::Value =
                serde_json::from_slice(&output.stdout).map_err(|e| format!("cargo metadata's output: {e}"))?;
            let mut found = HashMap::new();
            for p in meta["packages"].as_array().into_iter().flatten() {
                let (Some(name), Some(version), Some(path)) =
                    (p["name"].as_str(), p["version"].as_str(), p["manifest_path"].as_str())
                else {
                    continue;
                };
                if ["bevy_pbr", "bevy_render"].contains(&name) {
                    let root = Path::new(path).parent().unwrap_or(Path::new("/")).to_path_buf();
                    found.insert(name.to_string(), (root, version.to_string()));
                }
            }
            found
        }
    };
    let get = |name: &str| {
        crates.get(name).cloned().ok_or_else(|| match dir {
            Some(d) => format!("--bevy-src {}: no {name}-{BEVY_VERSION}.* in it", d.display()),
            None => format!("cargo metadata lists no {name}; is bench/peers/bevy/Cargo.toml intact?"),
        })
    };
    let ((pbr, version), (render, _)) = (get("bevy_pbr")?, get("bevy_render")?);
    if !version.starts_with(&format!("{BEVY_VERSION}.")) {
        return Err(format!("bevy_pbr {version} where this comparison reads Bevy {BEVY_VERSION}"));
    }
    for file in ["ssao.wesl", "preprocess_depth.wesl", "spatial_denoise.wesl"] {
        if !pbr.join("src/ssao").join(file).is_file() {
            return Err(format!("{}: no src/ssao/{file}", pbr.display()));
        }
    }
    Ok(BevySources { pbr, render, version })
}

// ---------------------------------------------------------------------------------------------
// WESL → WGSL
// ---------------------------------------------------------------------------------------------

/// A small WESL linker for Bevy's SSAO shaders: what Bevy's shader cache (the `wesl` crate with
/// imports and conditional compilation) does to them, enough for these files.
///
/// * Comments are dropped.
/// * `@if(expr)`, `@elif(expr)`, `@else` before a declaration, statement, struct member or
///   `{ … }` block keep or drop it by the flags (`!`, `&&`, `||`, parentheses; absent flags are
///   false); a kept block at module scope contributes its declarations.
/// * `import a::b::{c, d::e};` and qualified names (`constants::SLICE_COUNT`) resolve to
///   declarations of other modules: package `p`'s module `p::x::y` is `<p's src>/x/y.wesl`
///   (or `.wgsl`); `constants` is the module of Bevy's integer shader defs
///   (`const NAME = value;`).
/// * The output is the root module's declarations plus every declaration they reach, by name
///   (unmangled: a name declared by two reached modules is an error).
mod wesl {
    use std::collections::{BTreeMap, HashMap, HashSet, VecDeque};
    use std::path::PathBuf;

    /// Where modules come from and how conditions evaluate.
    pub struct Linker {
        /// Package name → its `src` directory (`bevy_render` → `…/bevy_render-0.20.1/src`).
        pub packages: Vec<(String, PathBuf)>,
        /// `@if` flags (Bevy's shader defs: booleans, and `true` for integer defs).
        pub flags: BTreeMap<String, bool>,
        /// The `constants` module: Bevy's integer shader defs.
        pub constants: BTreeMap<String, String>,
    }

    /// Struct declarations: name → members `(name, type)`.
    pub type Structs = HashMap<String, Vec<(String, String)>>;

    /// A linked shader: the WGSL and the structs it declares.
    pub struct Flat {
        pub wgsl: String,
        pub structs: Structs,
    }

    /// One module-scope declaration (`name` is `None` for directives).
    struct Decl {
        name: Option<String>,
        text: String,
    }

    /// A module after conditional compilation: its declarations and what its names import
    /// (local name → full path of the item).
    struct Module {
        decls: Vec<Decl>,
        imports: HashMap<String, Vec<String>>,
    }

    impl Module {
        fn find(&self, name: &str) -> Option<usize> {
            self.decls.iter().position(|d| d.name.as_deref() == Some(name))
        }
    }

    impl Linker {
        /// Link the module at `root` (e.g. `["bevy_pbr", "ssao", "ssao"]`, read from
        /// `file`).
        pub fn link(&self, root: &[&str], file: &std::path::Path) -> Result<Flat, String> {
            let root: Vec<String> = root.iter().map(|s| s.to_string()).collect();
            let source = std::fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
            let mut modules: HashMap<Vec<String>, Module> = HashMap::new();
            let module = self.process(&source, &root).map_err(|e| format!("{}: {e}", file.display()))?;
            let mut queue: VecDeque<(Vec<String>, usize)> =
                (0..module.decls.len()).map(|i| (root.clone(), i)).collect();
            modules.insert(root.clone(), module);
            let mut seen: HashSet<(Vec<String>, usize)> = HashSet::new();
            let mut order = Vec::new();
            while let Some((m, i)) = queue.pop_front() {
                if !seen.insert((m.clone(), i)) {
                    continue;
                }
                order.push((m.clone(), i));
                let (text, own) = {
                    let d = &modules[&m].decls[i];
                    (d.text.clone(), d.name.clone())
                };
                for ident in references(&text) {
                    if own.as_deref() == Some(ident.as_str()) {
                        continue;
                    }
                    if let Some(j) = modules[&m].find(&ident) {
                        queue.push_back((m.clone(), j));
                        continue;
                    }
                    let Some(path) = modules[&m].imports.get(&ident).cloned() else { continue };
                    let (target, item) = path.split_at(path.len() - 1);
                    if !modules.contains_key(target) {
                        let module = self.load(target)?;
                        modules.insert(target.to_vec(), module);
                    }
                    let j = modules[target]
                        .find(&item[0])
                        .ok_or_else(|| format!("module {} declares no `{}`", target.join("::"), item[0]))?;
                    queue.push_back((target.to_vec(), j));
                }
            }
            let mut wgsl = String::new();
            let mut directives = String::new();
            let mut names: HashMap<String, Vec<String>> = HashMap::new();
            let mut structs = HashMap::new();
            for (m, i) in order {
                let d = &modules[&m].decls[i];
                match &d.name {
                    None => directives += &format!("{}\n", d.text.trim()),
                    Some(name) => {
                        if let Some(other) = names.insert(name.clone(), m.clone())
                            && other != m
                        {
                            return Err(format!(
                                "`{name}` is declared by both {} and {}",
                                other.join("::"),
                                m.join("::")
                            ));
                        }
                        if let Some(members) = struct_members(&d.text) {
                            structs.insert(name.clone(), members);
                        }
                        wgsl += &format!("{}\n\n", tidy(&d.text));
                    }
                }
            }
            Ok(Flat { wgsl: format!("{directives}{wgsl}"), structs })
        }

        /// The module at `path`: the constants module or a package's file.
        fn load(&self, path: &[String]) -> Result<Module, String> {
            if path == ["constants"] {
                let decls = self
                    .constants
                    .iter()
                    .map(|(k, v)| Decl { name: Some(k.clone()), text: format!("const {k} = {v};") })
                    .collect();
                return Ok(Module { decls, imports: HashMap::new() });
            }
            let (package, rest) = path.split_first().ok_or("an empty module path")?;
            let src = &self
                .packages
                .iter()
                .find(|(p, _)| p == package)
                .ok_or_else(|| format!("module {}: unknown package {package}", path.join("::")))?
                .1;
            let stem = src.join(rest.join("/"));
            for ext in ["wesl", "wgsl"] {
                let file = stem.with_extension(ext);
                if let Ok(source) = std::fs::read_to_string(&file) {
                    return self.process(&source, path).map_err(|e| format!("{}: {e}", file.display()));
                }
            }
            Err(format!("module {}: no {}.wesl", path.join("::"), stem.display()))
        }

        /// Comments, conditions, imports, qualified names: `source` as declarations.
        fn process(&self, source: &str, path: &[String]) -> Result<Module, String> {
            let chars: Vec<char> = strip_comments(source)?.chars().collect();
            let chars: Vec<char> = condcomp(&chars, &mut Vec::new(), &self.flags)?.chars().collect();
            let mut module = Module { decls: Vec::new(), imports: HashMap::new() };
            let mut i = 0;
            loop {
                i = skip_ws(&chars, i);
                if i >= chars.len() {
                    break;
                }
                let end = item_end(&chars, i, false).max(i + 1);
                let item: String = chars[i..end].iter().collect();
                i = end;
                let head = head_keyword(&item.chars().collect::<Vec<_>>(), 0);
                match head.as_str() {
                    "import" => parse_import(&item, path, &mut module.imports)?,
                    "enable" | "requires" | "diagnostic" => module.decls.push(Decl { name: None, text: item }),
                    "" if item.trim() == ";" => {}
                    "struct" | "fn" | "var" | "const" | "override" | "alias" => {
                        let name = decl_name(&item).ok_or_else(|| format!("cannot name `{}`", first_line(&item)))?;
                        let text = self.qualified(&item, path, &mut module.imports)?;
                        module.decls.push(Decl { name: Some(name), text });
                    }
                    "const_assert" => {
                        let text = self.qualified(&item, path, &mut module.imports)?;
                        module.decls.push(Decl { name: None, text });
                    }
                    _ => return Err(format!("unexpected `{}` at module scope", first_line(&item))),
                }
            }
            Ok(module)
        }

        /// `item` with each qualified name `a::b::c` replaced by `c`, recording `c`'s full path
        /// among the imports.
        fn qualified(
            &self,
            item: &str,
            path: &[String],
            imports: &mut HashMap<String, Vec<String>>,
        ) -> Result<String, String> {
            let c: Vec<char> = item.chars().collect();
            let mut out = String::new();
            let mut i = 0;
            while i < c.len() {
                if is_ident_start(c[i]) && (i == 0 || !is_ident_char(c[i - 1])) {
                    let mut segments = Vec::new();
                    let mut j = i;
                    loop {
                        let (word, after) = ident_at(&c, j);
                        segments.push(word);
                        if c.get(after) == Some(&':') && c.get(after + 1) == Some(&':') {
                            j = skip_ws(&c, after + 2);
                        } else {
                            j = after;
                            break;
                        }
                    }
                    let last = segments.last().cloned().unwrap_or_default();
                    if segments.len() > 1 {
                        let full = self.absolute(&segments, path, imports)?;
                        if let Some(old) = imports.insert(last.clone(), full.clone())
                            && old != full
                        {
                            return Err(format!("`{last}` names both {} and {}", old.join("::"), full.join("::")));
                        }
                    }
                    out += &last;
                    i = j;
                } else {
                    out.push(c[i]);
                    i += 1;
                }
            }
            Ok(out)
        }

        /// The full path of `segments` written in module `path`.
        fn absolute(
            &self,
            segments: &[String],
            path: &[String],
            imports: &HashMap<String, Vec<String>>,
        ) -> Result<Vec<String>, String> {
            let first = segments[0].as_str();
            if first == "constants" || self.packages.iter().any(|(p, _)| p == first) {
                return Ok(segments.to_vec());
            }
            if first == "package" {
                return Ok(path[..1].iter().chain(&segments[1..]).cloned().collect());
            }
            if first == "super" {
                let ups = segments.iter().take_while(|s| *s == "super").count();
                if ups >= path.len() {
                    return Err(format!("`{}` leaves the package", segments.join("::")));
                }
                return Ok(path[..path.len() - ups].iter().chain(&segments[ups..]).cloned().collect());
            }
            if let Some(module) = imports.get(first) {
                return Ok(module.iter().chain(&segments[1..]).cloned().collect());
            }
            Err(format!("cannot resolve `{}`", segments.join("::")))
        }
    }

    /// `import …;` into `imports` (local name → full path).
    fn parse_import(item: &str, path: &[String], imports: &mut HashMap<String, Vec<String>>) -> Result<(), String> {
        let tokens = import_tokens(item);
        if tokens.first().map(String::as_str) != Some("import") {
            return Err(format!("not an import: {item}"));
        }
        let mut pos = 1;
        let mut paths = Vec::new();
        import_tree(&tokens, &mut pos, Vec::new(), &mut paths)?;
        if tokens.get(pos).map(String::as_str) != Some(";") {
            return Err(format!("cannot read `{}`", item.trim()));
        }
        for p in paths {
            let full = match p[0].as_str() {
                "package" => path[..1].iter().chain(&p[1..]).cloned().collect(),
                "super" => {
                    let ups = p.iter().take_while(|s| *s == "super").count();
                    if ups >= path.len() {
                        return Err(format!("`{}` leaves the package", p.join("::")));
                    }
                    path[..path.len() - ups].iter().chain(&p[ups..]).cloned().collect()
                }
                _ => p.clone(),
            };
            imports.insert(p.last().cloned().unwrap_or_default(), full);
        }
        Ok(())
    }

    /// One import tree (`a::b::{c, d::e}`) after `prefix`.
    fn import_tree(
        tokens: &[String],
        pos: &mut usize,
        prefix: Vec<String>,
        out: &mut Vec<Vec<String>>,
    ) -> Result<(), String> {
        let token = |p: usize| tokens.get(p).map(String::as_str).unwrap_or("");
        if token(*pos) == "{" {
            *pos += 1;
            while token(*pos) != "}" {
                if *pos >= tokens.len() {
                    return Err("an unterminated import list".into());
                }
                import_tree(tokens, pos, prefix.clone(), out)?;
                if token(*pos) == "," {
                    *pos += 1;
                }
            }
            *pos += 1;
            return Ok(());
        }
        let word = token(*pos).to_string();
        if word.is_empty() || !word.chars().all(is_ident_char) {
            return Err(format!("unexpected `{word}` in an import"));
        }
        *pos += 1;
        let mut p = prefix;
        p.push(word);
        match token(*pos) {
            "::" => {
                *pos += 1;
                import_tree(tokens, pos, p, out)
            }
            "as" => Err("import aliases (`as`) are not supported".into()),
            _ => {
                out.push(p);
                Ok(())
            }
        }
    }

    /// Identifiers, `::` and punctuation of an import statement.
    fn import_tokens(item: &str) -> Vec<String> {
        let c: Vec<char> = item.chars().collect();
        let mut tokens = Vec::new();
        let mut i = 0;
        while i < c.len() {
            if c[i].is_whitespace() {
                i += 1;
            } else if is_ident_char(c[i]) {
                let (word, after) = ident_at(&c, i);
                tokens.push(word);
                i = after;
            } else if c[i] == ':' && c.get(i + 1) == Some(&':') {
                tokens.push("::".into());
                i += 2;
            } else {
                tokens.push(c[i].to_string());
                i += 1;
            }
        }
        tokens
    }

    /// `source` without `//` and (nesting) `/* */` comments; line breaks stay.
    fn strip_comments(source: &str) -> Result<String, String> {
        let c: Vec<char> = source.chars().collect();
        let mut out = String::with_capacity(source.len());
        let mut i = 0;
        while i < c.len() {
            if c[i] == '/' && c.get(i + 1) == Some(&'/') {
                while i < c.len() && c[i] != '\n' {
                    i += 1;
                }
            } else if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                let mut depth = 1;
                i += 2;
                while depth > 0 {
                    match (c.get(i), c.get(i + 1)) {
                        (None, _) => return Err("an unterminated block comment".into()),
                        (Some('/'), Some('*')) => (depth, i) = (depth + 1, i + 2),
                        (Some('*'), Some('/')) => (depth, i) = (depth - 1, i + 2),
                        (Some('\n'), _) => (out.push('\n'), i += 1).1,
                        _ => i += 1,
                    }
                }
                out.push(' ');
            } else {
                out.push(c[i]);
                i += 1;
            }
        }
        Ok(out)
    }

    /// Conditional compilation of `c`; `ctx` holds, per open brace around it, whether it is a
    /// struct body (where items end at commas).
    fn condcomp(c: &[char], ctx: &mut Vec<bool>, flags: &BTreeMap<String, bool>) -> Result<String, String> {
        let mut out = String::new();
        // Whether a branch of the current @if chain was taken (Some while @elif/@else follow).
        let mut chain: Option<bool> = None;
        let mut i = 0;
        while i < c.len() {
            if c[i] == '@' {
                let (word, after) = ident_at(c, i + 1);
                if matches!(word.as_str(), "if" | "elif" | "else") {
                    let mut j = after;
                    let cond = if word == "else" {
                        true
                    } else {
                        j = skip_ws(c, j);
                        if c.get(j) != Some(&'(') {
                            return Err(format!("@{word} without a condition"));
                        }
                        let close = matching(c, j)?;
                        let expr: String = c[j + 1..close].iter().collect();
                        j = close + 1;
                        eval(&expr, flags)?
                    };
                    let (take, any) = match word.as_str() {
                        "if" => (cond, cond),
                        _ => {
                            let prev = chain.ok_or_else(|| format!("@{word} without @if before it"))?;
                            (!prev && cond, prev || cond)
                        }
                    };
                    let s = skip_ws(c, j);
                    let e = item_end(c, s, ctx.last() == Some(&true));
                    if take {
                        if c.get(s) == Some(&'{') && ctx.is_empty() {
                            out += &condcomp(&c[s + 1..e - 1], ctx, flags)?;
                        } else {
                            out += &condcomp(&c[s..e], ctx, flags)?;
                        }
                    }
                    i = e;
                    let k = skip_ws(c, i);
                    let next = if c.get(k) == Some(&'@') { ident_at(c, k + 1).0 } else { String::new() };
                    chain = (word != "else" && (next == "elif" || next == "else")).then_some(any);
                    continue;
                }
            }
            match c[i] {
                '{' => ctx.push(ends_with_struct_head(&out)),
                '}' => {
                    ctx.pop();
                }
                _ => {}
            }
            out.push(c[i]);
            i += 1;
        }
        Ok(out)
    }

    /// Whether `text` ends with `struct Name` (a `{` after it opens a struct body).
    fn ends_with_struct_head(text: &str) -> bool {
        let t = text.trim_end();
        let t = t.trim_end_matches(is_ident_char).trim_end();
        t.ends_with("struct") && !t[..t.len() - "struct".len()].ends_with(is_ident_char)
    }

    /// A condition: flags, `true`, `false`, `!`, `&&`, `||`, parentheses.
    fn eval(expr: &str, flags: &BTreeMap<String, bool>) -> Result<bool, String> {
        let c: Vec<char> = expr.chars().collect();
        let mut pos = 0;
        let v = eval_or(&c, &mut pos, flags)?;
        if skip_ws(&c, pos) != c.len() {
            return Err(format!("cannot evaluate condition `{expr}`"));
        }
        Ok(v)
    }

    fn eval_or(c: &[char], pos: &mut usize, flags: &BTreeMap<String, bool>) -> Result<bool, String> {
        let mut v = eval_and(c, pos, flags)?;
        loop {
            *pos = skip_ws(c, *pos);
            if c.get(*pos) == Some(&'|') && c.get(*pos + 1) == Some(&'|') {
                *pos += 2;
                v |= eval_and(c, pos, flags)?;
            } else {
                return Ok(v);
            }
        }
    }

    fn eval_and(c: &[char], pos: &mut usize, flags: &BTreeMap<String, bool>) -> Result<bool, String> {
        let mut v = eval_unary(c, pos, flags)?;
        loop {
            *pos = skip_ws(c, *pos);
            if c.get(*pos) == Some(&'&') && c.get(*pos + 1) == Some(&'&') {
                *pos += 2;
                v &= eval_unary(c, pos, flags)?;
            } else {
                return Ok(v);
            }
        }
    }

    fn eval_unary(c: &[char], pos: &mut usize, flags: &BTreeMap<String, bool>) -> Result<bool, String> {
        *pos = skip_ws(c, *pos);
        match c.get(*pos) {
            Some('!') => {
                *pos += 1;
                Ok(!eval_unary(c, pos, flags)?)
            }
            Some('(') => {
                *pos += 1;
                let v = eval_or(c, pos, flags)?;
                *pos = skip_ws(c, *pos);
                if c.get(*pos) != Some(&')') {
                    return Err("a condition lacks `)`".into());
                }
                *pos += 1;
                Ok(v)
            }
            Some(&ch) if is_ident_start(ch) => {
                let (word, after) = ident_at(c, *pos);
                *pos = after;
                Ok(match word.as_str() {
                    "true" => true,
                    "false" => false,
                    _ => flags.get(&word).copied().unwrap_or(false),
                })
            }
            _ => Err("cannot read a condition".into()),
        }
    }

    /// The end (exclusive) of the item starting at `s`: a `{ … }` block; a declaration or
    /// statement up to its `;` or the closing brace of its body (`fn`, `struct`, `if … else …`,
    /// loops); in a struct body, a member up to its comma. An item never passes the brace that
    /// closes the block around it.
    fn item_end(c: &[char], s: usize, in_struct: bool) -> usize {
        if c.get(s) == Some(&'{') {
            return matching(c, s).map_or(c.len(), |e| e + 1);
        }
        let head = head_keyword(c, s);
        let braced =
            matches!(head.as_str(), "fn" | "struct" | "if" | "for" | "while" | "loop" | "switch" | "continuing");
        let mut depth = 0i32;
        let mut j = s;
        while j < c.len() {
            match c[j] {
                '(' | '[' | '{' => depth += 1,
                ')' | ']' => depth -= 1,
                '}' => {
                    if depth == 0 {
                        return j;
                    }
                    depth -= 1;
                    if depth == 0 && braced {
                        let k = skip_ws(c, j + 1);
                        if head == "if" && ident_at(c, k).0 == "else" {
                            j = k;
                            continue;
                        }
                        if head == "struct" && c.get(k) == Some(&';') {
                            return k + 1;
                        }
                        return j + 1;
                    }
                }
                ';' if depth == 0 => return j + 1,
                ',' if depth == 0 && in_struct => return j + 1,
                _ => {}
            }
            j += 1;
        }
        c.len()
    }

    /// The first word of the item at `s` after its attributes (`@group(0)`, …).
    fn head_keyword(c: &[char], s: usize) -> String {
        let mut k = skip_ws(c, s);
        while c.get(k) == Some(&'@') {
            k = ident_at(c, k + 1).1;
            k = skip_ws(c, k);
            if c.get(k) == Some(&'(') {
                k = matching(c, k).map_or(c.len(), |e| e + 1);
            }
            k = skip_ws(c, k);
        }
        ident_at(c, k).0
    }

    /// The name a module-scope declaration declares.
    fn decl_name(item: &str) -> Option<String> {
        let c: Vec<char> = item.chars().collect();
        let head = head_keyword(&c, 0);
        // Past the attributes and the keyword.
        let mut k = skip_ws(&c, 0);
        while c.get(k) == Some(&'@') {
            k = skip_ws(&c, ident_at(&c, k + 1).1);
            if c.get(k) == Some(&'(') {
                k = matching(&c, k).ok()? + 1;
            }
            k = skip_ws(&c, k);
        }
        k = skip_ws(&c, ident_at(&c, k).1);
        if head == "var" && c.get(k) == Some(&'<') {
            while k < c.len() && c[k] != '>' {
                k += 1;
            }
            k = skip_ws(&c, k + 1);
        }
        let (name, _) = ident_at(&c, k);
        (!name.is_empty()).then_some(name)
    }

    /// The members `(name, type)` of a struct declaration; `None` for other declarations.
    fn struct_members(text: &str) -> Option<Vec<(String, String)>> {
        let c: Vec<char> = text.chars().collect();
        if head_keyword(&c, 0) != "struct" {
            return None;
        }
        let open = c.iter().position(|&ch| ch == '{')?;
        let close = matching(&c, open).ok()?;
        let mut members = Vec::new();
        let mut depth = 0i32;
        let mut start = open + 1;
        for j in open + 1..=close {
            match c[j] {
                '<' | '(' | '[' => depth += 1,
                '>' | ')' | ']' => depth -= 1,
                ',' | '}' if depth == 0 => {
                    let member: String = c[start..j].iter().collect();
                    if let Some((name, ty)) = member.split_once(':') {
                        members.push((name.trim().to_string(), ty.trim().to_string()));
                    }
                    start = j + 1;
                }
                _ => {}
            }
        }
        Some(members)
    }

    /// The identifiers `text` refers to (not member accesses, not attribute names).
    fn references(text: &str) -> Vec<String> {
        let c: Vec<char> = text.chars().collect();
        let mut out = Vec::new();
        let mut i = 0;
        while i < c.len() {
            if is_ident_start(c[i]) && (i == 0 || !is_ident_char(c[i - 1])) {
                let (word, after) = ident_at(&c, i);
                let before = c[..i].iter().rev().find(|ch| !ch.is_whitespace());
                if !matches!(before, Some('.') | Some('@')) {
                    out.push(word);
                }
                i = after;
            } else {
                i += 1;
            }
        }
        out
    }

    /// The index of the bracket closing the one at `open` (`(`, `[` or `{`).
    fn matching(c: &[char], open: usize) -> Result<usize, String> {
        let mut depth = 0;
        for (j, &ch) in c.iter().enumerate().skip(open) {
            match ch {
                '(' | '[' | '{' => depth += 1,
                ')' | ']' | '}' => {
                    depth -= 1;
                    if depth == 0 {
                        return Ok(j);
                    }
                }
                _ => {}
            }
        }
        Err("an unbalanced bracket".into())
    }

    fn skip_ws(c: &[char], mut i: usize) -> usize {
        while i < c.len() && c[i].is_whitespace() {
            i += 1;
        }
        i
    }

    fn is_ident_start(ch: char) -> bool {
        ch.is_ascii_alphabetic() || ch == '_'
    }

    fn is_ident_char(ch: char) -> bool {
        ch.is_ascii_alphanumeric() || ch == '_'
    }

    /// The identifier at `i` (empty if none) and the index after it.
    fn ident_at(c: &[char], i: usize) -> (String, usize) {
        let mut j = i;
        while j < c.len() && is_ident_char(c[j]) {
            j += 1;
        }
        (c[i.min(c.len())..j].iter().collect(), j)
    }

    fn first_line(item: &str) -> &str {
        item.trim().lines().next().unwrap_or("")
    }

    /// A declaration's text without the blank lines comments and conditions left.
    fn tidy(text: &str) -> String {
        text.trim().lines().map(str::trim_end).filter(|l| !l.trim().is_empty()).collect::<Vec<_>>().join("\n")
    }

    #[cfg(test)]
    mod tests {
        use super::*;

        fn flags(on: &[&str]) -> BTreeMap<String, bool> {
            on.iter().map(|f| (f.to_string(), true)).collect()
        }

        fn cc(src: &str, on: &[&str]) -> String {
            let c: Vec<char> = src.chars().collect();
            let out = condcomp(&c, &mut Vec::new(), &flags(on)).unwrap();
            out.split_whitespace().collect::<Vec<_>>().join(" ")
        }

        #[test]
        fn conditions_keep_and_drop_items() {
            let src = "@if(A) @group(0) @binding(3) var a: texture_storage_2d<r16float, write>;\n\
                       @else @group(0) @binding(3) var a: texture_storage_2d<r32float, write>;\nvar b: f32;";
            assert_eq!(
                cc(src, &["A"]),
                "@group(0) @binding(3) var a: texture_storage_2d<r16float, write>; var b: f32;"
            );
            assert_eq!(cc(src, &[]), "@group(0) @binding(3) var a: texture_storage_2d<r32float, write>; var b: f32;");
            let blocks = "@if(A) { var x: f32; }\n@if(!A) { var y: f32; }";
            assert_eq!(cc(blocks, &[]), "var y: f32;");
            let member = "struct G { t: f32, n: u32,\n @if(P) pad: f32\n};";
            assert_eq!(cc(member, &[]), "struct G { t: f32, n: u32, };");
            let stmt =
                "fn f() -> f32 {\n@if(P) return 1.0;\n@elif(Q && !P) return 2.0;\n@else { let z = 3.0; return z; }\n}";
            assert_eq!(cc(stmt, &["Q"]), "fn f() -> f32 { return 2.0; }");
            assert_eq!(cc(stmt, &[]), "fn f() -> f32 { { let z = 3.0; return z; } }");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Uniform layouts (WGSL's host-shareable layout rules)
// ---------------------------------------------------------------------------------------------

/// `(align, size)` of a WGSL type in bytes; `structs` names the struct types.
fn type_layout(ty: &str, structs: &wesl::Structs) -> Result<(usize, usize), String> {
    let ty = ty.trim();
    let vector = |n: usize| match n {
        2 => Ok((8, 8)),
        3 => Ok((16, 12)),
        4 => Ok((16, 16)),
        _ => Err(format!("cannot lay out `{ty}`")),
    };
    let (base, param) = match ty.split_once('<') {
        Some((b, rest)) => (b.trim(), Some(rest.strip_suffix('>').ok_or_else(|| format!("cannot read `{ty}`"))?)),
        None => (ty, None),
    };
    let scalar32 = |p: Option<&str>| p.is_none_or(|p| matches!(p.trim(), "f32" | "u32" | "i32"));
    match base {
        "f32" | "u32" | "i32" => Ok((4, 4)),
        "vec2" | "vec3" | "vec4" if scalar32(param) => vector(base[3..].parse().unwrap_or(0)),
        "vec2f" | "vec3f" | "vec4f" | "vec2u" | "vec3u" | "vec4u" | "vec2i" | "vec3i" | "vec4i" => {
            vector(base[3..4].parse().unwrap_or(0))
        }
        b if b.starts_with("mat") && b.len() >= 6 && scalar32(param) => {
            let (cols, rows) = (b[3..4].parse::<usize>().unwrap_or(0), b[5..6].parse::<usize>().unwrap_or(0));
            let (align, size) = vector(rows)?;
            Ok((align, cols * size.next_multiple_of(align)))
        }
        "array" => {
            let param = param.ok_or_else(|| format!("cannot lay out `{ty}`"))?;
            let (elem, n) = param.rsplit_once(',').ok_or_else(|| format!("`{ty}` has no length"))?;
            let n: usize = n.trim().trim_end_matches('u').parse().map_err(|_| format!("`{ty}`: a length"))?;
            let (align, size) = type_layout(elem, structs)?;
            Ok((align, n * size.next_multiple_of(align)))
        }
        name => struct_layout(name, structs).map(|(align, size, _)| (align, size)),
    }
}

/// `(align, size, members' offsets)` of struct `name`.
fn struct_layout(name: &str, structs: &wesl::Structs) -> Result<(usize, usize, HashMap<String, usize>), String> {
    let members = structs.get(name).ok_or_else(|| format!("no struct or type `{name}` in Bevy's WGSL"))?;
    let (mut offset, mut align) = (0usize, 1usize);
    let mut offsets = HashMap::new();
    for (member, ty) in members {
        if member.starts_with('@') {
            return Err(format!("{name}.{member}: member attributes are not supported"));
        }
        let (a, s) = type_layout(ty, structs)?;
        offset = offset.next_multiple_of(a);
        offsets.insert(member.clone(), offset);
        offset += s;
        align = align.max(a);
    }
    Ok((align, offset.next_multiple_of(align), offsets))
}

/// The bytes of a uniform struct, written member by member (others stay zero).
struct UniformBytes {
    name: String,
    bytes: Vec<u8>,
    offsets: HashMap<String, usize>,
}

impl UniformBytes {
    fn new(name: &str, structs: &wesl::Structs) -> Result<UniformBytes, String> {
        let (_, size, offsets) = struct_layout(name, structs)?;
        Ok(UniformBytes { name: name.into(), bytes: vec![0; size.next_multiple_of(16)], offsets })
    }

    /// Write `values` at member `member`.
    fn set(&mut self, member: &str, values: &[f32]) -> Result<&mut Self, String> {
        let at = *self.offsets.get(member).ok_or_else(|| format!("Bevy's {} has no member {member}", self.name))?;
        for (k, v) in values.iter().enumerate() {
            self.bytes[at + 4 * k..at + 4 * k + 4].copy_from_slice(&v.to_le_bytes());
        }
        Ok(self)
    }
}

// ---------------------------------------------------------------------------------------------
// The device, timing and readback
// ---------------------------------------------------------------------------------------------

/// wgpu's device on the Vulkan adapter, with timestamp queries.
struct Gpu {
    device: wgpu::Device,
    queue: wgpu::Queue,
    adapter: wgpu::Adapter,
    name: String,
}

impl Gpu {
    /// The first Vulkan adapter with `TIMESTAMP_QUERY`, its limits, and the features Bevy would
    /// use here (adapter-specific format features, filterable 32-bit floats) where it has them.
    fn new() -> Result<Gpu, String> {
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::VULKAN,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
            .map_err(|e| format!("no Vulkan adapter for wgpu ({e})"))?;
        let name = adapter.get_info().name;
        if !adapter.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
            return Err(format!("{name} has no timestamp queries (wgpu::Features::TIMESTAMP_QUERY)"));
        }
        let wanted = wgpu::Features::TIMESTAMP_QUERY
            | wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES
            | wgpu::Features::FLOAT32_FILTERABLE;
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("aokit-peers bevy"),
            required_features: adapter.features() & wanted,
            required_limits: adapter.limits(),
            ..Default::default()
        }))
        .map_err(|e| format!("{name}: no device ({e})"))?;
        Ok(Gpu { device, queue, adapter, name })
    }

    /// Run `f` and turn a validation error it causes into `Err` naming `what`.
    fn checked<T>(&self, what: &str, f: impl FnOnce() -> T) -> Result<T, String> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let value = f();
        match pollster::block_on(scope.pop()) {
            None => Ok(value),
            Some(e) => Err(format!("{what}: {e}")),
        }
    }

    /// Submit `encoder` and wait for it.
    fn submit_and_wait(&self, encoder: wgpu::CommandEncoder) -> Result<(), String> {
        self.queue.submit([encoder.finish()]);
        self.device.poll(wgpu::PollType::wait_indefinitely()).map(|_| ()).map_err(|e| format!("device poll: {e}"))
    }

    /// The contents of a mappable buffer.
    fn map_read(&self, buffer: &wgpu::Buffer) -> Result<Vec<u8>, String> {
        buffer.slice(..).map_async(wgpu::MapMode::Read, |r| r.expect("buffer mapped for reading"));
        self.device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| format!("device poll: {e}"))?;
        let bytes = buffer.slice(..).get_mapped_range().map_err(|e| format!("mapped range: {e}"))?.to_vec();
        buffer.unmap();
        Ok(bytes)
    }

    /// The contents of a storage buffer (it must allow `COPY_SRC`).
    fn read_buffer(&self, buffer: &wgpu::Buffer) -> Result<Vec<u8>, String> {
        let readback = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: buffer.size(),
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut encoder = self.device.create_command_encoder(&Default::default());
        encoder.copy_buffer_to_buffer(buffer, 0, &readback, 0, buffer.size());
        self.submit_and_wait(encoder)?;
        self.map_read(&readback)
    }

    /// The red channel of a single-channel float texture (`R16Float` or `R32Float`) as `f32`.
    fn read_r_texture(&self, texture: &wgpu::Texture, format: wgpu::TextureFormat) -> Result<Vec<f32>, String> {
        let texel = match format {
            wgpu::TextureFormat::R16Float => 2,
            wgpu::TextureFormat::R32Float => 4,
            other => return Err(format!("cannot read {other:?} back")),
        };
        let (w, h) = (texture.width(), texture.height());
        let row = (w * texel).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let readback = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("texture readback"),
            size: (row * h) as u64,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut encoder = self.device.create_command_encoder(&Default::default());
        encoder.copy_texture_to_buffer(
            texture.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &readback,
                layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: Some(h) },
            },
            texture.size(),
        );
        self.submit_and_wait(encoder)?;
        let bytes = self.map_read(&readback)?;
        let mut out = Vec::with_capacity((w * h) as usize);
        for y in 0..h as usize {
            let line = &bytes[y * row as usize..][..(w * texel) as usize];
            if texel == 2 {
                out.extend(line.chunks_exact(2).map(|b| f16_to_f32(u16::from_le_bytes([b[0], b[1]]))));
            } else {
                out.extend(line.chunks_exact(4).map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])));
            }
        }
        Ok(out)
    }
}

/// An IEEE half as `f32`.
fn f16_to_f32(h: u16) -> f32 {
    let sign = if h & 0x8000 != 0 { -1.0 } else { 1.0 };
    let (exp, man) = ((h >> 10) & 0x1f, (h & 0x3ff) as f32);
    match exp {
        0 => sign * man * (-24f32).exp2(),
        31 if man == 0.0 => sign * f32::INFINITY,
        31 => f32::NAN,
        e => sign * (1.0 + man / 1024.0) * (e as f32 - 15.0).exp2(),
    }
}

/// One compute dispatch: its pipeline, bind groups (group `k` at index `k`) and workgroups.
struct Dispatch {
    /// The kernel's entry point (aokit) or the pass's name (Bevy).
    label: String,
    pipeline: wgpu::ComputePipeline,
    groups: Vec<wgpu::BindGroup>,
    workgroups: [u32; 2],
}

/// Timestamp queries around each of a side's dispatches.
struct Timer {
    queries: wgpu::QuerySet,
    resolve: wgpu::Buffer,
    readback: wgpu::Buffer,
    /// Nanoseconds per timestamp tick.
    period: f64,
}

impl Timer {
    /// Queries for `passes` dispatches.
    fn new(gpu: &Gpu, passes: usize) -> Timer {
        let count = 2 * passes as u32;
        let size = 8 * count as u64;
        Timer {
            queries: gpu.device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("pass timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count,
            }),
            resolve: gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timestamps"),
                size,
                usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            }),
            readback: gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timestamps readback"),
                size,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
            period: gpu.queue.get_timestamp_period() as f64,
        }
    }

    /// Run `dispatches` in order, each in its own compute pass, in one submission; the GPU time
    /// of each in milliseconds.
    fn run(&self, gpu: &Gpu, dispatches: &[Dispatch]) -> Result<Vec<f64>, String> {
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        for (k, d) in dispatches.iter().enumerate() {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some(&d.label),
                timestamp_writes: Some(wgpu::ComputePassTimestampWrites {
                    query_set: &self.queries,
                    beginning_of_pass_write_index: Some(2 * k as u32),
                    end_of_pass_write_index: Some(2 * k as u32 + 1),
                }),
            });
            pass.set_pipeline(&d.pipeline);
            for (g, group) in d.groups.iter().enumerate() {
                pass.set_bind_group(g as u32, group, &[]);
            }
            pass.dispatch_workgroups(d.workgroups[0], d.workgroups[1], 1);
        }
        let count = 2 * dispatches.len() as u32;
        encoder.resolve_query_set(&self.queries, 0..count, &self.resolve, 0);
        encoder.copy_buffer_to_buffer(&self.resolve, 0, &self.readback, 0, self.resolve.size());
        gpu.submit_and_wait(encoder)?;
        let bytes = gpu.map_read(&self.readback)?;
        let ticks: &[u64] = bytemuck::cast_slice(&bytes);
        Ok(ticks.chunks_exact(2).map(|t| t[1].saturating_sub(t[0]) as f64 * self.period * 1e-6).collect())
    }
}

// ---------------------------------------------------------------------------------------------
// aokit's side
// ---------------------------------------------------------------------------------------------

/// What a generated WGSL module declares: its entry point, workgroup size, the storage
/// bindings it uses and the binding of its constants' uniform.
struct WgslModule {
    source: String,
    entry: String,
    workgroup: [u32; 2],
    bindings: Vec<u32>,
    constants: Option<u32>,
}

impl WgslModule {
    /// Read `assets/wgsl/<entry>.wgsl`.
    fn read(entry: &str) -> Result<WgslModule, String> {
        let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/wgsl").join(format!("{entry}.wgsl"));
        let source = std::fs::read_to_string(&file).map_err(|e| format!("{}: {e}", file.display()))?;
        let mut bindings = Vec::new();
        let mut constants = None;
        let mut pending: Option<u32> = None;
        let (mut entry_point, mut workgroup) = (None, None);
        let mut compute = false;
        for line in source.lines().map(str::trim) {
            if let Some(rest) = line.strip_prefix("@group(0) @binding(") {
                pending = rest.split(')').next().and_then(|b| b.parse().ok());
            } else if let Some(b) = pending.take() {
                if line.starts_with("var<uniform>") {
                    constants = Some(b);
                } else {
                    bindings.push(b);
                }
            }
            if let Some(rest) = line.strip_prefix("@compute @workgroup_size(") {
                let size: Vec<u32> =
                    rest.split(')').next().unwrap_or("").split(',').filter_map(|s| s.trim().parse().ok()).collect();
                workgroup = size.get(..2).map(|s| [s[0], s[1]]);
                compute = true;
            } else if compute && let Some(rest) = line.strip_prefix("fn ") {
                entry_point = rest.split('(').next().map(|s| s.trim().to_string());
                compute = false;
            }
        }
        let what = file.display();
        Ok(WgslModule {
            source,
            entry: entry_point.ok_or_else(|| format!("{what}: no compute entry point"))?,
            workgroup: workgroup.ok_or_else(|| format!("{what}: no workgroup size"))?,
            bindings,
            constants,
        })
    }
}

/// aokit's vbao as WGSL dispatches over storage buffers.
struct AokitSide {
    dispatches: Vec<Dispatch>,
    timer: Timer,
    buffers: HashMap<&'static str, wgpu::Buffer>,
    /// The main pass's AO terms.
    terms: &'static str,
}

impl AokitSide {
    /// The graph's resources (initialized as the graph says), the inputs from `g`, and one
    /// dispatch per pass.
    fn new(gpu: &Gpu, graph: &Graph, g: &GBufferImage) -> Result<AokitSide, String> {
        let device = &gpu.device;
        let usage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST;
        let init = |label: &str, words: &[u32]| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytemuck::cast_slice(if words.is_empty() { &[0u32] } else { words }),
                usage,
            })
        };
        let mut buffers: HashMap<&'static str, wgpu::Buffer> = HashMap::new();
        buffers.insert(inputs::LINEAR_DEPTH, init("linear_depth", bytemuck::cast_slice(&g.depth)));
        buffers.insert(inputs::VIEW_NORMALS, init("view_normals", &g.normals));
        for r in &graph.resources {
            let n = r.len(&graph.view);
            let words = match &r.init {
                Init::Fill(bits) => vec![*bits; n],
                Init::Data(words) if words.len() == n => words.clone(),
                Init::Data(words) => return Err(format!("{}: {} words of data for {n}", r.name, words.len())),
                Init::Undefined => vec![0; n],
            };
            buffers.insert(r.name, init(r.name, &words));
        }
        let mut modules: HashMap<&str, (WgslModule, wgpu::ComputePipeline)> = HashMap::new();
        let mut dispatches = Vec::new();
        let mut terms = None;
        for pass in &graph.passes {
            let entry = pass.entry();
            if pass.kind != PassKind::Compute {
                return Err(format!("vbao's pass {entry} is not a compute pass"));
            }
            if !modules.contains_key(entry) {
                let module = WgslModule::read(entry)?;
                // Specialized as the Vulkan executor does (Bevy's shader has its slice and sample
                // counts as shader defs): `@id(N)` overrides keyed by their ids.
                let specialization = pass.kernel.specialization_for(&pass.push_constants)?;
                let ids: Vec<String> = specialization.iter().map(|(id, _)| id.to_string()).collect();
                let constants: Vec<(&str, f64)> =
                    ids.iter().zip(&specialization).map(|(id, &(_, value))| (id.as_str(), f64::from(value))).collect();
                let pipeline = gpu.checked(&format!("aokit's {entry}.wgsl"), || {
                    let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                        label: Some(entry),
                        source: wgpu::ShaderSource::Wgsl(module.source.as_str().into()),
                    });
                    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                        label: Some(entry),
                        layout: None,
                        module: &shader,
                        entry_point: Some(&module.entry),
                        compilation_options: wgpu::PipelineCompilationOptions {
                            constants: &constants,
                            ..Default::default()
                        },
                        cache: None,
                    })
                })?;
                modules.insert(entry, (module, pipeline));
            }
            let (module, pipeline) = &modules[entry];
            let mut entries: Vec<wgpu::BindGroupEntry> = Vec::new();
            for b in pass.bindings.iter().filter(|b| module.bindings.contains(&b.slot)) {
                let buffer = buffers.get(b.resource).ok_or_else(|| format!("{entry}: no resource {}", b.resource))?;
                entries.push(wgpu::BindGroupEntry { binding: b.slot, resource: buffer.as_entire_binding() });
            }
            let constants;
            if let Some(binding) = module.constants {
                if pass.push_constants.is_empty() {
                    return Err(format!("{entry}: its WGSL reads constants the pass does not give"));
                }
                let mut bytes = pass.push_constants.clone();
                bytes.resize(bytes.len().next_multiple_of(16), 0);
                constants = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("constants"),
                    contents: &bytes,
                    usage: wgpu::BufferUsages::UNIFORM,
                });
                entries.push(wgpu::BindGroupEntry { binding, resource: constants.as_entire_binding() });
            }
            let group = gpu.checked(&format!("aokit's {entry} bindings"), || {
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some(entry),
                    layout: &pipeline.get_bind_group_layout(0),
                    entries: &entries,
                })
            })?;
            if entry == "vbao_main" {
                let slot = pass.kernel.bindings.iter().find(|b| b.name == "terms").map(|b| b.slot);
                terms = slot.and_then(|s| pass.resource(s));
            }
            let n = pass.invocations(&graph.view);
            dispatches.push(Dispatch {
                label: entry.to_string(),
                pipeline: pipeline.clone(),
                groups: vec![group],
                workgroups: [n.x.div_ceil(module.workgroup[0]), n.y.div_ceil(module.workgroup[1])],
            });
        }
        let terms = terms.ok_or("vbao's graph has no vbao_main pass writing `terms`")?;
        let timer = Timer::new(gpu, dispatches.len());
        Ok(AokitSide { dispatches, timer, buffers, terms })
    }
}

// ---------------------------------------------------------------------------------------------
// Bevy's side
// ---------------------------------------------------------------------------------------------

/// Bevy's SSAO settings for the run (`ScreenSpaceAmbientOcclusion` and its quality level).
struct BevySettings {
    slices: u32,
    samples_per_slice_side: u32,
    /// `radius`: the longest sample's distance in view units.
    radius: f32,
    /// `constant_object_thickness`.
    thickness: f32,
    /// The near plane of Bevy's infinite reversed-Z perspective (`PerspectiveProjection::near`).
    near: f32,
}

/// Bevy's three passes with their textures, as `SsaoPipelines` sets them up.
struct BevySide {
    dispatches: Vec<Dispatch>,
    timer: Timer,
    /// The main pass's (noisy) AO and the denoised AO.
    noisy: wgpu::Texture,
    denoised: wgpu::Texture,
    /// The working depth and AO format (`R16Float` where the adapter stores to it).
    format: wgpu::TextureFormat,
    /// The shader defs the shaders were specialized with.
    defs: Vec<String>,
}

/// The Hilbert-curve index of `(x, y)` on a 64×64 grid (the textbook `xy2d`), which Bevy's
/// noise LUT holds.
fn hilbert_index(mut x: u16, mut y: u16) -> u16 {
    const N: u16 = 64;
    let mut index = 0;
    let mut s = N / 2;
    while s > 0 {
        let rx = u16::from(x & s > 0);
        let ry = u16::from(y & s > 0);
        index += s * s * ((3 * rx) ^ ry);
        if ry == 0 {
            if rx == 1 {
                (x, y) = (N - 1 - x, N - 1 - y);
            }
            std::mem::swap(&mut x, &mut y);
        }
        s /= 2;
    }
    index
}

/// Fills Bevy's `Depth32Float` prepass depth from an `R32Float` texture (depth textures take no
/// copies): a full-screen triangle writing `frag_depth`.
/// The prepass depth's stand-in (shared with the tests): a depth pass writing given values.
#[path = "../../../tests/common/depth_pass.rs"]
mod depth_pass;

impl BevySide {
    /// Link Bevy's shaders, build its inputs from the frame and `g`, its textures, pipelines
    /// and bind groups.
    fn new(
        gpu: &Gpu,
        sources: &BevySources,
        settings: &BevySettings,
        frame: &aokit::frame::Frame,
        g: &GBufferImage,
        wgsl_dir: &Path,
    ) -> Result<BevySide, String> {
        let device = &gpu.device;
        let (w, h) = (g.width, g.height);
        let limits = device.limits();
        if limits.max_storage_textures_per_shader_stage < 5 {
            return Err(format!("{}: fewer than 5 storage textures per stage; Bevy disables SSAO", gpu.name));
        }
        // Bevy's choice: R16Float where the adapter can store to it.
        let r16 = gpu.adapter.get_texture_format_features(wgpu::TextureFormat::R16Float);
        let format = if r16.allowed_usages.contains(wgpu::TextureUsages::STORAGE_BINDING)
            && device.features().contains(wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES)
        {
            wgpu::TextureFormat::R16Float
        } else {
            wgpu::TextureFormat::R32Float
        };
        let mut flags = std::collections::BTreeMap::new();
        let mut constants = std::collections::BTreeMap::new();
        flags.insert("USE_R16FLOAT".to_string(), format == wgpu::TextureFormat::R16Float);
        // The global defs of Bevy's pipeline cache.
        let ssbo = limits.max_storage_buffers_per_shader_stage;
        constants.insert("AVAILABLE_STORAGE_BUFFER_BINDINGS".to_string(), ssbo.to_string());
        flags.insert("AVAILABLE_STORAGE_BUFFER_BINDINGS".to_string(), true);
        flags.insert("AVAILABLE_STORAGE_BUFFER_BINDINGS__GE_3".to_string(), ssbo >= 3);
        flags.insert("AVAILABLE_STORAGE_BUFFER_BINDINGS__GE_6".to_string(), ssbo >= 6);
        // The main pass's specialization (no TemporalJitter: TEMPORAL_JITTER off).
        let mut ssao_constants = constants.clone();
        ssao_constants.insert("SLICE_COUNT".to_string(), settings.slices.to_string());
        ssao_constants.insert("SAMPLES_PER_SLICE_SIDE".to_string(), settings.samples_per_slice_side.to_string());
        let mut ssao_flags = flags.clone();
        ssao_flags.insert("SLICE_COUNT".to_string(), true);
        ssao_flags.insert("SAMPLES_PER_SLICE_SIDE".to_string(), true);
        ssao_flags.insert("TEMPORAL_JITTER".to_string(), false);
        let defs: Vec<String> = ssao_flags
            .iter()
            .filter(|(_, on)| **on)
            .map(|(k, _)| match ssao_constants.get(k) {
                Some(v) => format!("{k}={v}"),
                None => k.clone(),
            })
            .collect();
        let packages = vec![
            ("bevy_pbr".to_string(), sources.pbr.join("src")),
            ("bevy_render".to_string(), sources.render.join("src")),
        ];
        std::fs::create_dir_all(wgsl_dir).map_err(|e| format!("{}: {e}", wgsl_dir.display()))?;
        let link = |stem: &str,
                    flags: std::collections::BTreeMap<String, bool>,
                    constants: std::collections::BTreeMap<String, String>|
         -> Result<(String, wesl::Structs), String> {
            let linker = wesl::Linker { packages: packages.clone(), flags, constants };
            let file = sources.pbr.join("src/ssao").join(format!("{stem}.wesl"));
            let flat = linker.link(&["bevy_pbr", "ssao", stem], &file)?;
            let out = wgsl_dir.join(format!("{stem}.wgsl"));
            let text = format!(
                "// Flattened by aokit-peers from {} (Bevy's shader, not aokit's; do not commit).\n\n{}",
                file.display(),
                flat.wgsl
            );
            std::fs::write(&out, text).map_err(|e| format!("{}: {e}", out.display()))?;
            Ok((flat.wgsl, flat.structs))
        };
        let (preprocess_wgsl, _) = link("preprocess_depth", flags.clone(), constants.clone())?;
        let (ssao_wgsl, structs) = link("ssao", ssao_flags, ssao_constants)?;
        let (denoise_wgsl, _) = link("spatial_denoise", flags, constants)?;

        // The inputs: reversed-Z depth of Bevy's infinite perspective, world (= view) normals.
        let view = frame.camera.view;
        let (tx, ty, near) = (view.tan_half_fov.x, view.tan_half_fov.y, settings.near);
        let nearest = g.depth.iter().copied().filter(|&z| z > 0.0).fold(f32::INFINITY, f32::min);
        if nearest < near {
            return Err(format!(
                "the frame has geometry at depth {nearest}, nearer than Bevy's near plane {near}: pass a smaller \
                 --bevy-near"
            ));
        }
        let ndc: Vec<f32> =
            g.depth.iter().map(|&z| if z.is_finite() && z < view.far && z > 0.0 { near / z } else { 0.0 }).collect();
        // The G-buffer's normals are in Bevy's view space already (right-handed, −z forward);
        // as a prepass of front faces would, they face the camera.
        let normals: Vec<u32> = g
            .normals
            .iter()
            .zip(&g.depth)
            .enumerate()
            .map(|(i, (&code, &z))| {
                let n = aokit_shaders::common::normal_codec::decode_normal(code);
                let (u, v) = (((i as u32 % w) as f32 + 0.5) / w as f32, ((i as u32 / w) as f32 + 0.5) / h as f32);
                let to_camera = -aokit_shaders::glam::Vec3::new((2.0 * u - 1.0) * tx * z, (1.0 - 2.0 * v) * ty * z, -z);
                let n = if n.dot(to_camera) < 0.0 { -n } else { n };
                let q = |c: f32| ((c * 0.5 + 0.5).clamp(0.0, 1.0) * 1023.0 + 0.5) as u32;
                q(n.x) | (q(n.y) << 10) | (q(n.z) << 20) | (3 << 30)
            })
            .collect();
        let hilbert: Vec<u16> = (0..64 * 64).map(|i| hilbert_index((i / 64) as u16, (i % 64) as u16)).collect();

        let size = wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 };
        let texture = |label: &str, format, usage, mips: u32| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size,
                mip_level_count: mips,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let with_data = |label: &str, format, size, bytes: &[u8]| {
            device.create_texture_with_data(
                &gpu.queue,
                &wgpu::TextureDescriptor {
                    label: Some(label),
                    size,
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                    view_formats: &[],
                },
                wgpu::util::TextureDataOrder::LayerMajor,
                bytes,
            )
        };
        use wgpu::TextureUsages as U;
        let depth =
            texture("prepass depth", wgpu::TextureFormat::Depth32Float, U::TEXTURE_BINDING | U::RENDER_ATTACHMENT, 1);
        let normal_texture =
            with_data("prepass normals", wgpu::TextureFormat::Rgb10a2Unorm, size, bytemuck::cast_slice(&normals));
        let lut_size = wgpu::Extent3d { width: 64, height: 64, depth_or_array_layers: 1 };
        let hilbert_texture =
            with_data("ssao_hilbert_index_lut", wgpu::TextureFormat::R16Uint, lut_size, bytemuck::cast_slice(&hilbert));
        let storage = U::STORAGE_BINDING | U::TEXTURE_BINDING | U::COPY_SRC;
        let preprocessed = texture("ssao_preprocessed_depth_texture", format, storage, 5);
        let noisy = texture("ssao_noisy_texture", format, storage, 1);
        let denoised = texture("ssao_texture", format, storage, 1);
        let differences = texture("ssao_depth_differences_texture", wgpu::TextureFormat::R32Uint, storage, 1);

        // The prepass depth, once.
        gpu.checked("filling Bevy's prepass depth", || -> Result<(), String> {
            let mut encoder = device.create_command_encoder(&Default::default());
            depth_pass::record(device, &mut encoder, &depth.create_view(&Default::default()), &ndc, w);
            gpu.submit_and_wait(encoder)
        })??;

        // The uniforms: Bevy's `View` at the world origin with its infinite reversed-Z
        // perspective, `Globals` at frame 0, `SsaoSettings`.
        let (w_f, h_f) = (w as f32, h as f32);
        let identity = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
        let clip_from_view =
            [1.0 / tx, 0.0, 0.0, 0.0, 0.0, 1.0 / ty, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, near, 0.0];
        let view_from_clip = [tx, 0.0, 0.0, 0.0, 0.0, ty, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0 / near, 0.0, 0.0, -1.0, 0.0];
        let mut view_uniform = UniformBytes::new("View", &structs)?;
        view_uniform
            .set("clip_from_world", &clip_from_view)?
            .set("unjittered_clip_from_world", &clip_from_view)?
            .set("world_from_clip", &view_from_clip)?
            .set("world_from_view", &identity)?
            .set("view_from_world", &identity)?
            .set("clip_from_view", &clip_from_view)?
            .set("view_from_clip", &view_from_clip)?
            .set("exposure", &[1.0])?
            .set("viewport", &[0.0, 0.0, w_f, h_f])?
            .set("main_pass_viewport", &[0.0, 0.0, w_f, h_f])?;
        let globals = UniformBytes::new("Globals", &structs)?;
        let mut ssao_settings = UniformBytes::new("SsaoSettings", &structs)?;
        ssao_settings.set("radius", &[settings.radius])?.set("thickness", &[settings.thickness])?;
        let uniform = |label: &str, bytes: &[u8]| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytes,
                usage: wgpu::BufferUsages::UNIFORM,
            })
        };
        let view_buffer = uniform("view", &view_uniform.bytes);
        let globals_buffer = uniform("globals", &globals.bytes);
        let settings_buffer = uniform("ssao_settings", &ssao_settings.bytes);

        // Bevy's samplers and bind-group layouts (`SsaoPipelines::from_world`).
        let clamp = |filter| wgpu::SamplerDescriptor {
            min_filter: filter,
            mag_filter: filter,
            mipmap_filter: wgpu::MipmapFilterMode::Nearest,
            address_mode_u: wgpu::AddressMode::ClampToEdge,
            address_mode_v: wgpu::AddressMode::ClampToEdge,
            ..Default::default()
        };
        let point = device.create_sampler(&clamp(wgpu::FilterMode::Nearest));
        let linear = device.create_sampler(&clamp(wgpu::FilterMode::Linear));
        let entry = |binding: u32, ty| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty,
            count: None,
        };
        let texture_2d = |sample_type| wgpu::BindingType::Texture {
            sample_type,
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        };
        let store = |format| wgpu::BindingType::StorageTexture {
            access: wgpu::StorageTextureAccess::WriteOnly,
            format,
            view_dimension: wgpu::TextureViewDimension::D2,
        };
        let uniform_ty = wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        };
        let float = |filterable| wgpu::TextureSampleType::Float { filterable };
        let layout = |label: &str, entries: &[wgpu::BindGroupLayoutEntry]| {
            device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: Some(label), entries })
        };
        let common_layout = layout(
            "ssao_common_bind_group_layout",
            &[
                entry(0, wgpu::BindingType::Sampler(wgpu::SamplerBindingType::NonFiltering)),
                entry(1, wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering)),
                entry(2, uniform_ty),
            ],
        );
        let preprocess_layout = layout(
            "ssao_preprocess_depth_bind_group_layout",
            &[
                entry(0, texture_2d(wgpu::TextureSampleType::Depth)),
                entry(1, store(format)),
                entry(2, store(format)),
                entry(3, store(format)),
                entry(4, store(format)),
                entry(5, store(format)),
            ],
        );
        let ssao_layout = layout(
            "ssao_ssao_bind_group_layout",
            &[
                entry(0, texture_2d(float(true))),
                entry(1, texture_2d(float(false))),
                entry(2, texture_2d(wgpu::TextureSampleType::Uint)),
                entry(3, store(format)),
                entry(4, store(wgpu::TextureFormat::R32Uint)),
                entry(5, uniform_ty),
                entry(6, uniform_ty),
            ],
        );
        let denoise_layout = layout(
            "ssao_spatial_denoise_bind_group_layout",
            &[
                entry(0, texture_2d(float(false))),
                entry(1, texture_2d(wgpu::TextureSampleType::Uint)),
                entry(2, store(format)),
            ],
        );

        let pipeline = |label: &str, wgsl: &str, entry_point: &str, group0: &wgpu::BindGroupLayout| {
            gpu.checked(&format!("Bevy's {label} (flattened WGSL in {})", wgsl_dir.display()), || {
                let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some(label),
                    source: wgpu::ShaderSource::Wgsl(wgsl.into()),
                });
                let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                    label: Some(label),
                    bind_group_layouts: &[Some(group0), Some(&common_layout)],
                    immediate_size: 0,
                });
                device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some(label),
                    layout: Some(&layout),
                    module: &shader,
                    entry_point: Some(entry_point),
                    compilation_options: Default::default(),
                    cache: None,
                })
            })
        };
        let preprocess_pipeline =
            pipeline("preprocess_depth", &preprocess_wgsl, "preprocess_depth", &preprocess_layout)?;
        let ssao_pipeline = pipeline("ssao", &ssao_wgsl, "ssao", &ssao_layout)?;
        let denoise_pipeline = pipeline("spatial_denoise", &denoise_wgsl, "spatial_denoise", &denoise_layout)?;

        let view_of = |t: &wgpu::Texture| t.create_view(&Default::default());
        let mip = |k: u32| {
            preprocessed.create_view(&wgpu::TextureViewDescriptor {
                label: Some("ssao_preprocessed_depth_texture_mip_view"),
                format: Some(format),
                dimension: Some(wgpu::TextureViewDimension::D2),
                base_mip_level: k,
                mip_level_count: Some(1),
                ..Default::default()
            })
        };
        let groups = gpu.checked("Bevy's bind groups", || {
            let group = |label: &str, layout: &wgpu::BindGroupLayout, resources: Vec<wgpu::BindingResource>| {
                let entries: Vec<wgpu::BindGroupEntry> = resources
                    .into_iter()
                    .enumerate()
                    .map(|(k, resource)| wgpu::BindGroupEntry { binding: k as u32, resource })
                    .collect();
                device.create_bind_group(&wgpu::BindGroupDescriptor { label: Some(label), layout, entries: &entries })
            };
            let depth_only = depth.create_view(&wgpu::TextureViewDescriptor {
                aspect: wgpu::TextureAspect::DepthOnly,
                ..Default::default()
            });
            let mips: Vec<wgpu::TextureView> = (0..5).map(mip).collect();
            let tv = wgpu::BindingResource::TextureView;
            let (preprocessed_view, normal_view, lut_view) =
                (view_of(&preprocessed), view_of(&normal_texture), view_of(&hilbert_texture));
            let (noisy_view, denoised_view, differences_view) =
                (view_of(&noisy), view_of(&denoised), view_of(&differences));
            let common = group(
                "ssao_common_bind_group",
                &common_layout,
                vec![
                    wgpu::BindingResource::Sampler(&point),
                    wgpu::BindingResource::Sampler(&linear),
                    view_buffer.as_entire_binding(),
                ],
            );
            let preprocess = group(
                "ssao_preprocess_depth_bind_group",
                &preprocess_layout,
                std::iter::once(tv(&depth_only)).chain(mips.iter().map(tv)).collect(),
            );
            let ssao = group(
                "ssao_ssao_bind_group",
                &ssao_layout,
                vec![
                    tv(&preprocessed_view),
                    tv(&normal_view),
                    tv(&lut_view),
                    tv(&noisy_view),
                    tv(&differences_view),
                    globals_buffer.as_entire_binding(),
                    settings_buffer.as_entire_binding(),
                ],
            );
            let denoise = group(
                "ssao_spatial_denoise_bind_group",
                &denoise_layout,
                vec![tv(&noisy_view), tv(&differences_view), tv(&denoised_view)],
            );
            [common, preprocess, ssao, denoise]
        })?;
        let [common, preprocess, ssao, denoise] = groups;
        // Bevy's dispatches: the depth chain 16×16 pixels per workgroup, the others 8×8.
        let dispatches = vec![
            Dispatch {
                label: "preprocess_depth".into(),
                pipeline: preprocess_pipeline,
                groups: vec![preprocess, common.clone()],
                workgroups: [w.div_ceil(16), h.div_ceil(16)],
            },
            Dispatch {
                label: "ssao".into(),
                pipeline: ssao_pipeline,
                groups: vec![ssao, common.clone()],
                workgroups: [w.div_ceil(8), h.div_ceil(8)],
            },
            Dispatch {
                label: "spatial_denoise".into(),
                pipeline: denoise_pipeline,
                groups: vec![denoise, common],
                workgroups: [w.div_ceil(8), h.div_ceil(8)],
            },
        ];
        let timer = Timer::new(gpu, dispatches.len());
        Ok(BevySide { dispatches, timer, noisy, denoised, format, defs })
    }
}

// ---------------------------------------------------------------------------------------------
// Statistics and images
// ---------------------------------------------------------------------------------------------

/// What an AO image looks like over the pixels with geometry.
struct AoStats {
    mean: f64,
    below_0_9: f64,
    nan: usize,
    pixels: usize,
}

impl AoStats {
    /// Statistics of `v` over the pixels `keep` marks.
    fn of(v: &[f32], keep: &[bool]) -> AoStats {
        let (mut sum, mut below, mut nan, mut n) = (0.0f64, 0usize, 0usize, 0usize);
        for (&x, _) in v.iter().zip(keep).filter(|(_, k)| **k) {
            n += 1;
            if x.is_nan() {
                nan += 1;
                continue;
            }
            sum += x as f64;
            below += usize::from(x < 0.9);
        }
        let valid = (n - nan).max(1) as f64;
        AoStats { mean: sum / valid, below_0_9: below as f64 / valid, nan, pixels: n }
    }

    /// An error unless the image looks like AO: no NaN, neither all white nor all black.
    fn check(&self, what: &str) -> Result<(), String> {
        if self.pixels == 0 {
            return Err(format!("{what}: the frame shows no geometry"));
        }
        if self.nan > 0 || self.mean > 0.999 || self.mean < 0.1 || self.below_0_9 < 0.001 {
            return Err(format!(
                "{what} AO is degenerate (mean {:.4}, {:.2} % below 0.9, {} NaN of {} pixels): a binding or an \
                 input is wrong",
                self.mean,
                100.0 * self.below_0_9,
                self.nan,
                self.pixels
            ));
        }
        Ok(())
    }

    fn json(&self) -> serde_json::Value {
        serde_json::json!({"mean": self.mean, "fraction_below_0_9": self.below_0_9, "nan": self.nan,
                           "pixels": self.pixels})
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn halves_convert() {
        assert_eq!(f16_to_f32(0x3c00), 1.0);
        assert_eq!(f16_to_f32(0xc000), -2.0);
        assert_eq!(f16_to_f32(0x3555), 0.333_251_95);
        assert!(f16_to_f32(0x7e00).is_nan());
    }

    #[test]
    fn hilbert_index_visits_every_cell_once() {
        let mut seen = vec![false; 64 * 64];
        for x in 0..64 {
            for y in 0..64 {
                seen[hilbert_index(x, y) as usize] = true;
            }
        }
        assert!(seen.iter().all(|&s| s));
        assert_eq!(hilbert_index(0, 0), 0);
    }

    #[test]
    fn uniform_layouts_follow_wgsl() {
        let structs: wesl::Structs = [(
            "S".to_string(),
            vec![
                ("m".to_string(), "mat3x3<f32>".to_string()),
                ("a".to_string(), "vec3<f32>".to_string()),
                ("b".to_string(), "f32".to_string()),
                ("c".to_string(), "vec2<f32>".to_string()),
                ("d".to_string(), "array<vec4<f32>, 6>".to_string()),
                ("e".to_string(), "u32".to_string()),
            ],
        )]
        .into();
        let (align, size, offsets) = struct_layout("S", &structs).unwrap();
        assert_eq!(
            (align, offsets["a"], offsets["b"], offsets["c"], offsets["d"], offsets["e"]),
            (16, 48, 60, 64, 80, 176)
        );
        assert_eq!(size, 192);
    }
}
